(** * DuffCount.v — the computed p and q of Duff's forward differences under
    the kappa model.

    §18.5 of docs/float.md, Duff's method (Duff.v, src/duff.rs) in the model of
    FloatModelK.v / Profiles.v: from the unit inputs Na, Nb, L read into the
    format ([Profiles.vap]: each component within k_in of the exact),
    1 <= n <= 2^24 and a pixel i <= n (exact integers), bounds of |p^_i - p_i|
    and |q^_i - q_i|, p_i = N_i.L, q_i = N_i.N_i, N_i = Na + (i/n)(Nb - Na)
    ([Span.p], [Span.q] at x = i, = A i + B and C i^2 + D i + E:
    [Duff.eq_5_7_duff_recurrence_exact]), for
    - the set-up of Horner's closed form (PhongCount.v): k_j = (Nb_j - Na_j)/n
      (a rounded subtraction, then one division [Profiles.kcomp_ok], or a
      reciprocal 1/n and a product [PhongCount.krecip_ok]); A = k.L, B = Na.L,
      C = k.k, D = 2 (k.Na) (the x2 exact), E = Na.Na, each dot product in any
      order, each product rounded or fused ([fdot_ok]);
    - then Duff's loop ([duff_run]): p_0 = B, q_0 = E, dq_0 = (C + D),
      d2q = (C + C) (a rounded addition: covers 2C exact), and for j < n
        p_{j+1} = (p_j + A),  q_{j+1} = (q_j + dq_j),  dq_{j+1} = (dq_j + d2q),
      each a rounded addition (k_add), possibly rounded differently at every
      step.
    With K1 >= 1 bounding k_in, k_add, k_mul, and kd = k_div (one division)
    or kd = (1 + 2^-20) k_mul + k_div + 2^-36 (reciprocal then product):
        |p^_i - p_i| <= (17.02 K1 + 2.02 kd + 1.001 i k_add) u,
        |q^_i - q_i| <= (65.05 K1 + 12.04 kd + 3.004 i k_add) u
    ([duff_div_generic], [duff_recip_generic]), for every i <= n.
    Corollaries for symmetric Phong (src/symmetric_phong.rs: q walked by Duff's
    recurrence only to h = floor(n/2), pixel i using the q walked min(i, n - i)
    steps, as q(x) = q(n - x) for unit Na, Nb, [Symmetry.sec_4_q_is_symmetric]):
    the same bound for p^_i, and for the q^ used at pixel i
        |q^_{min(i, n-i)} - q_i| <= (65.05 K1 + 12.04 kd + 3.004 min(i, n-i) k_add) u
    ([symmetric_phong_div_generic], [symmetric_phong_recip_generic]).  The loop
    terms: each p-addition has a result within 1.001 in size (1.001 i k_add u);
    each q-addition within 1.002 and each dq-addition within 4.0025/n (its
    error reaches q_i multiplied by at most i - 1 <= n: i (i-1)/2 times
    4.0025/n <= 2.00125 i), together (1.002 + 2.00125) i k_add u <= 3.004 i k_add u.
    The set-up terms: for p, B^ - B + (i/n)(n A^ - n A) (K_pa, K_a:
    17.012 K1 + 2.011 kd); for q, with e = D^/2 the computed k.Na, the loop
    starts from q_0 + i dq_0 + i(i-1)/2 d2q, whose difference to q_i is
      (E^ - E) + (i/n)^2 (n^2 C^ - n^2 C) + 2 (i/n) (n e - n D/2)
      + i (dq_0 - (C^ + 2e)) + i(i-1)/2 (d2q - (C^ + C^))
    (K_pa, K_c, K_d0 each once: 57.042 K1 + 12.031 kd; the roundings of dq_0
    and d2q at most 8.0001 k_add u <= 8.0001 K1 u).
    The absolute term eta of every operation is absorbed (model_ok: eta 2^84 <= u,
    n <= 2^24).  Size conditions: model_ok M K with K1 <= K, 1 <= k_div,
    n k_add u <= 2^-11 (as the Euler loops of Profiles.v), and for the
    reciprocal forms kd u <= 2^-21. *)

From Coq Require Import Reals Lra Lia.
From PhongApprox Require Import Span FloatModel Float FloatModelK Profiles PhongCount PhongCountD.
From PhongApprox Require Symmetry.
Open Scope R_scope.

(** ** The loop of p: P_{j+1} = (P_j + fa), P_0 = fb *)

Lemma dp_loop : forall (v w eta mr fa fb a b cA cB : R) (m i : nat) (P : nat -> R),
  small_ok v eta -> 0 <= w <= v -> mr = INR m -> 1 <= mr <= 16777216 -> mr * w <= / 2048 ->
  Rabs (mr * fa - a) <= cA -> Rabs (fb - b) <= cB -> 0 <= cA -> 0 <= cB ->
  cA + cB <= / 10000 ->
  (forall t, 0 <= t <= 1 -> Rabs (b + t * a) <= 1) ->
  P O = fb -> (forall j, (j < m)%nat -> ap1 w eta (P (S j)) (P j + fa)) ->
  (i <= m)%nat ->
  Rabs (P i - (b + INR i / mr * a)) <= cA + cB + 1001 / 1000 * INR i * w + / 1000000000 * v.
Proof.
  intros v w eta mr fa fb a b cA cB m i P Hv Hw Hmr Hm Hmw HA HB HcA HcB Hc Hab HP0 Hst Hi.
  small_facts Hv.
  assert (Me : mr * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  assert (Gen : forall J : nat, (J <= m)%nat ->
            Rabs (fb + INR J * fa - (b + INR J / mr * a)) <= cA + cB).
  { intros J HJ.
    assert (HJr : 0 <= INR J <= mr)
      by (rewrite Hmr; split; [apply pos_INR | apply le_INR; exact HJ]).
    pose proof (theta_rng mr (INR J) ltac:(lra) HJr) as Ht.
    replace (fb + INR J * fa - (b + INR J / mr * a))
      with ((fb - b) + INR J / mr * (mr * fa - a)) by (field; lra).
    eapply Rle_trans; [apply Rabs_triang|].
    pose proof (hc_scale (INR J / mr) (mr * fa - a) Ht). lra. }
  pose proof (gseq_err w eta P fa m (1001 / 1000) ltac:(lra) ltac:(lra) ltac:(lra) Hst) as G.
  assert (HG : forall j, (j < m)%nat ->
            Rabs (P O + INR (S j) * fa) + INR m * (w * (1001 / 1000) + eta) <= 1001 / 1000).
  { intros j Hj. rewrite HP0, <- Hmr.
    pose proof (Gen (S j) ltac:(lia)) as G1.
    assert (HJr : 0 <= INR (S j) <= mr)
      by (rewrite Hmr; split; [apply pos_INR | apply le_INR; lia]).
    pose proof (theta_rng mr (INR (S j)) ltac:(lra) HJr) as Ht.
    pose proof (Hab _ Ht) as G2.
    pose proof (abs_near _ _ _ G1) as G3.
    lra. }
  specialize (G HG i Hi). rewrite HP0 in G.
  pose proof (Gen i Hi) as G4.
  replace (P i - (b + INR i / mr * a))
    with ((P i - (fb + INR i * fa)) + (fb + INR i * fa - (b + INR i / mr * a))) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  assert (Hir : 0 <= INR i <= mr) by (rewrite Hmr; split; [apply pos_INR | apply le_INR; exact Hi]).
  assert (INR i * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  lra.
Qed.

(** ** The loop of q *)

(** The slope at 0, |m fc + 2 m e| <= 4 + cC + 2 cD, and |m^2 fc| <= 4 + cC. *)
Lemma dq_f0 : forall mr fc e c dd cC cD, 1 <= mr -> 0 <= c <= 4 ->
  Rabs (mr * mr * fc - c) <= cC -> Rabs (mr * e - dd) <= cD ->
  (forall z, 0 <= z <= 2 -> Rabs (c * z + 2 * dd) <= 4) ->
  Rabs (mr * fc + 2 * (mr * e)) <= 4 + cC + 2 * cD /\ Rabs (mr * mr * fc) <= 4 + cC.
Proof.
  intros mr fc e c dd cC cD Hm Hc HC HD Hz.
  assert (Hinv : 0 <= / mr <= 1).
  { split; [left; apply Rinv_0_lt_compat; lra|].
    rewrite <- Rinv_1. apply Rinv_le_contravar; lra. }
  split; [| pose proof (abs_near _ _ _ HC); rewrite (Rabs_pos_eq c) in * by lra; lra].
  replace (mr * fc + 2 * (mr * e))
    with ((c * / mr + 2 * dd) + / mr * (mr * mr * fc - c) + 2 * (mr * e - dd)) by (field; lra).
  eapply Rle_trans; [apply tri3|].
  pose proof (Hz (/ mr) ltac:(lra)).
  pose proof (hc_scale (/ mr) (mr * mr * fc - c) Hinv).
  rewrite (Rabs_mult 2 (mr * e - dd)), (Rabs_pos_eq 2) by lra. lra.
Qed.

(** The ideal value of q_J on the computed E^, dq_0, d2q: E^ + J dq_0 + J(J-1)/2 d2q. *)
Lemma dq_ideal : forall (v eta mr fc e fe c dd ee cC cD cE g0 h : R) (J : nat),
  small_ok v eta -> 1 <= mr <= 16777216 -> INR J <= mr ->
  Rabs (mr * mr * fc - c) <= cC -> Rabs (mr * e - dd) <= cD -> Rabs (fe - ee) <= cE ->
  0 <= cC <= / 50000 -> 0 <= cD <= / 100000 -> 0 <= cE ->
  0 <= c <= 4 -> (forall z, 0 <= z <= 2 -> Rabs (c * z + 2 * dd) <= 4) ->
  ap1 v eta g0 (fc + 2 * e) -> ap1 v eta h (fc + fc) ->
  Rabs (fe + INR J * g0 + INR J * (INR J - 1) / 2 * h
        - (ee + 2 * (INR J / mr) * dd + (INR J / mr) * (INR J / mr) * c))
    <= cE + cC + 2 * cD + 80001 / 10000 * v + / 10000000000 * v.
Proof.
  intros v eta mr fc e fe c dd ee cC cD cE g0 h J Hv Hm HJ HC HD HE HcC HcD HcE Hc Hz
    Hg0 Hh.
  unfold ap1 in Hg0, Hh.
  small_facts Hv.
  set (Jr := INR J) in *.
  assert (J0 : 0 <= Jr) by apply pos_INR.
  assert (J1 : 0 <= Jr * (Jr - 1)).
  { unfold Jr. destruct J as [| J']; [cbn [INR]; lra|].
    rewrite S_INR. pose proof (pos_INR J'). nra. }
  pose proof (theta_rng mr Jr ltac:(lra) ltac:(lra)) as Ht.
  set (t := Jr / mr) in *.
  destruct (dq_f0 mr fc e c dd cC cD ltac:(lra) Hc HC HD Hz) as [F0 F2].
  assert (F1 : Rabs (Jr * (fc + 2 * e)) <= 4 + cC + 2 * cD).
  { replace (Jr * (fc + 2 * e)) with (t * (mr * fc + 2 * (mr * e))) by (unfold t; field; lra).
    eapply Rle_trans; [apply hc_scale; exact Ht | exact F0]. }
  assert (Hmm : 1 <= mr * mr) by nra.
  assert (F3 : Rabs (Jr * (Jr - 1) * fc) <= 4 + cC).
  { pose proof (theta_rng (mr * mr) (Jr * (Jr - 1)) Hmm ltac:(split; nra)) as Ht2.
    replace (Jr * (Jr - 1) * fc) with (Jr * (Jr - 1) / (mr * mr) * (mr * mr * fc))
      by (field; lra).
    eapply Rle_trans; [apply hc_scale; exact Ht2 | exact F2]. }
  assert (E1 : Rabs (Jr * (g0 - (fc + 2 * e))) <= v * (4 + cC + 2 * cD) + Jr * eta)
    by (apply ap_lam; [lra | lra | exact Hg0 | exact F1]).
  assert (E2 : Rabs (Jr * (Jr - 1) / 2 * (h - (fc + fc)))
               <= v * (4 + cC) + Jr * (Jr - 1) / 2 * eta).
  { apply ap_lam; [lra | lra | exact Hh |].
    replace (Jr * (Jr - 1) / 2 * (fc + fc)) with (Jr * (Jr - 1) * fc) by field. exact F3. }
  assert (Htt : 0 <= t * t <= 1) by (split; nra).
  assert (E3 : Rabs (t * t * (mr * mr * fc - c)) <= cC)
    by (eapply Rle_trans; [apply hc_scale; exact Htt | exact HC]).
  assert (E4 : Rabs (2 * t * (mr * e - dd)) <= 2 * cD).
  { replace (2 * t * (mr * e - dd)) with (2 * (t * (mr * e - dd))) by ring.
    rewrite Rabs_mult, (Rabs_pos_eq 2) by lra.
    pose proof (hc_scale t (mr * e - dd) Ht). lra. }
  replace (fe + Jr * g0 + Jr * (Jr - 1) / 2 * h - (ee + 2 * t * dd + t * t * c))
    with ((fe - ee) + Jr * (g0 - (fc + 2 * e)) + Jr * (Jr - 1) / 2 * (h - (fc + fc))
          + t * t * (mr * mr * fc - c) + 2 * t * (mr * e - dd)) by (unfold t; field; lra).
  eapply Rle_trans; [apply tri5|].
  assert (Je : Jr * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  assert (Jq : Jr * (Jr - 1) / 2 <= 281474976710656) by nra.
  assert (Je2 : Jr * (Jr - 1) / 2 * eta <= 281474976710656 * eta)
    by (apply Rmult_le_compat_r; lra).
  assert (Wc : v * (2 * cC + 2 * cD) <= v * / 10000) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

Lemma dq_loop : forall (v w eta mr fc e fe c dd ee cC cD cE h : R) (m i : nat)
  (Q G : nat -> R),
  small_ok v eta -> 0 <= w <= v -> mr = INR m -> 1 <= mr <= 16777216 -> mr * w <= / 2048 ->
  Rabs (mr * mr * fc - c) <= cC -> Rabs (mr * e - dd) <= cD -> Rabs (fe - ee) <= cE ->
  0 <= cC <= / 50000 -> 0 <= cD <= / 100000 -> 0 <= cE <= / 100000 ->
  0 <= c <= 4 -> (forall z, 0 <= z <= 2 -> Rabs (c * z + 2 * dd) <= 4) ->
  (forall t, 0 <= t <= 1 -> Rabs (ee + 2 * t * dd + t * t * c) <= 1) ->
  ap1 v eta (G O) (fc + 2 * e) -> ap1 v eta h (fc + fc) -> Q O = fe ->
  (forall j, (j < m)%nat -> ap1 w eta (Q (S j)) (Q j + G j) /\ ap1 w eta (G (S j)) (G j + h)) ->
  (i <= m)%nat ->
  Rabs (Q i - (ee + 2 * (INR i / mr) * dd + (INR i / mr) * (INR i / mr) * c))
    <= cE + cC + 2 * cD + 80001 / 10000 * v + 3004 / 1000 * INR i * w + / 1000000000 * v.
Proof.
  intros v w eta mr fc e fe c dd ee cC cD cE h m i Q G Hv Hw Hmr Hm Hmw HC HD HE HcC HcD HcE
    Hc Hz Hq Hg0 Hh HQ0 Hst Hi.
  small_facts Hv.
  set (g0 := G O) in *.
  set (Ms := 40025 / 10000 / mr).
  set (Mp := 1002 / 1000).
  assert (HMs : 0 <= Ms)
    by (unfold Ms, Rdiv; apply Rmult_le_pos; [lra | left; apply Rinv_0_lt_compat; lra]).
  assert (Me : mr * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  assert (Hmm : mr * mr <= 281474976710656) by nra.
  assert (Mme : mr * mr * eta <= 281474976710656 * eta) by (apply Rmult_le_compat_r; lra).
  destruct (dq_f0 mr fc e c dd cC cD ltac:(lra) Hc HC HD Hz) as [F0 F2].
  destruct (cseq_err w eta Q G h m Ms Mp ltac:(lra) ltac:(lra) HMs ltac:(unfold Mp; lra) Hst)
    with (i := i) as [_ HQi]; [| | exact Hi |].
  - (* the slopes dq_J, 1 <= J <= m - 1 *)
    intros j Hj. fold g0. rewrite <- Hmr.
    set (Jr := INR (S j)).
    assert (J0 : 1 <= Jr) by (unfold Jr; rewrite S_INR; pose proof (pos_INR j); lra).
    assert (J1 : Jr + 1 <= mr)
      by (unfold Jr; rewrite Hmr, <- S_INR; apply le_INR; lia).
    set (z := (2 * Jr + 1) / mr).
    assert (Hz0 : 0 <= z <= 2).
    { unfold z, Rdiv. split.
      - apply Rmult_le_pos; [lra | left; apply Rinv_0_lt_compat; lra].
      - apply (Rmult_le_reg_r mr); [lra|].
        rewrite Rmult_assoc, Rinv_l by lra. lra. }
    assert (T1 : Rabs (mr * (g0 - (fc + 2 * e))) <= v * (4 + cC + 2 * cD) + mr * eta).
    { apply ap_lam; [lra | lra | exact Hg0 |].
      replace (mr * (fc + 2 * e)) with (mr * fc + 2 * (mr * e)) by ring. exact F0. }
    assert (T2 : Rabs (mr * Jr * (h - (fc + fc))) <= 2 * v * (4 + cC) + mr * mr * eta).
    { assert (Ht : 0 <= Jr / mr <= 1) by (apply theta_rng; [lra | split; lra]).
      assert (B : Rabs (mr * Jr * (fc + fc)) <= 2 * (4 + cC)).
      { replace (mr * Jr * (fc + fc)) with (2 * (Jr / mr * (mr * mr * fc))) by (field; lra).
        rewrite Rabs_mult, (Rabs_pos_eq 2) by lra.
        pose proof (hc_scale _ (mr * mr * fc) Ht). lra. }
      pose proof (ap_lam v eta (mr * Jr) _ _ _ ltac:(lra) ltac:(nra) Hh B).
      assert (mr * Jr * eta <= mr * mr * eta)
        by (apply Rmult_le_compat_r; [lra|]; apply Rmult_le_compat_l; lra).
      lra. }
    assert (T3 : Rabs (c * z + 2 * dd) <= 4) by (apply Hz; exact Hz0).
    assert (T4 : Rabs (z * (mr * mr * fc - c)) <= 2 * cC).
    { rewrite Rabs_mult, (Rabs_pos_eq z) by lra.
      apply Rmult_le_compat; try lra; apply Rabs_pos. }
    assert (T5 : Rabs (2 * (mr * e - dd)) <= 2 * cD)
      by (rewrite Rabs_mult, (Rabs_pos_eq 2) by lra; lra).
    assert (Eq : mr * (g0 + Jr * h)
                 = mr * (g0 - (fc + 2 * e)) + mr * Jr * (h - (fc + fc)) + (c * z + 2 * dd)
                   + z * (mr * mr * fc - c) + 2 * (mr * e - dd)) by (unfold z; field; lra).
    assert (X : Rabs (mr * (g0 + Jr * h))
                <= 4 + v * (12 + 3 * cC + 2 * cD) + 2 * cC + 2 * cD + mr * eta + mr * mr * eta).
    { rewrite Eq. eapply Rle_trans; [apply tri5|]. lra. }
    assert (EA : Rabs (g0 + Jr * h) = Rabs (mr * (g0 + Jr * h)) / mr).
    { rewrite Rabs_mult, (Rabs_pos_eq mr) by lra. field; lra. }
    rewrite EA. unfold Ms. apply div_helper; [lra|].
    assert (mr * (w * (40025 / 10000 / mr) + eta) * mr = 40025 / 10000 * (mr * w) + mr * mr * eta)
      by (field; lra).
    assert (v * (3 * cC + 2 * cD) <= v * / 10000) by (apply Rmult_le_compat_l; lra).
    lra.
  - (* the values q_J, 1 <= J <= m *)
    intros j Hj. fold g0. rewrite HQ0, <- Hmr.
    assert (HJ : INR (S j) <= mr) by (rewrite Hmr; apply le_INR; lia).
    pose proof (dq_ideal v eta mr fc e fe c dd ee cC cD cE g0 h (S j) Hv Hm HJ HC HD HE
                  HcC HcD ltac:(lra) Hc Hz Hg0 Hh) as G1.
    assert (Ht : 0 <= INR (S j) / mr <= 1) by (apply theta_rng; [lra | split; [apply pos_INR | lra]]).
    pose proof (Hq _ Ht) as G2.
    pose proof (abs_near _ _ _ G1) as G3.
    assert (mr * mr / 2 * (w * Ms + eta) = 40025 / 20000 * (mr * w) + mr * mr * eta / 2)
      by (unfold Ms; field; lra).
    unfold Mp in *. lra.
  - (* the end *)
    fold g0 in HQi. rewrite HQ0 in HQi.
    assert (Hir : 0 <= INR i <= mr) by (rewrite Hmr; split; [apply pos_INR | apply le_INR; exact Hi]).
    pose proof (dq_ideal v eta mr fc e fe c dd ee cC cD cE g0 h i Hv Hm ltac:(lra) HC HD HE
                  HcC HcD ltac:(lra) Hc Hz Hg0 Hh) as G1.
    assert (J1 : 0 <= INR i * (INR i - 1)).
    { destruct i as [| i']; [cbn [INR]; lra|].
      rewrite S_INR. pose proof (pos_INR i'). nra. }
    assert (R1 : INR i * (INR i - 1) / mr <= INR i).
    { apply (Rmult_le_reg_r mr); [lra|]. unfold Rdiv.
      rewrite Rmult_assoc, Rinv_l by lra. nra. }
    assert (R2 : INR i * (INR i - 1) / 2 * (w * Ms)
                 = INR i * (INR i - 1) / mr * (40025 / 20000 * w)) by (unfold Ms; field; lra).
    assert (R3 : INR i * (INR i - 1) / mr * (40025 / 20000 * w) <= INR i * (40025 / 20000 * w))
      by (apply Rmult_le_compat_r; lra).
    assert (R4 : INR i * (INR i - 1) / 2 <= 281474976710656).
    { replace (INR i * (INR i - 1)) with (INR i * INR i - INR i) by ring.
      assert (INR i * INR i <= 16777216 * 16777216) by (apply Rmult_le_compat; lra).
      lra. }
    assert (R5 : INR i * (INR i - 1) / 2 * eta <= 281474976710656 * eta)
      by (apply Rmult_le_compat_r; lra).
    assert (R6 : INR i * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
    assert (R7 : INR i * (INR i - 1) / 2 * (w * Ms + eta) + INR i * (w * Mp + eta)
                 = INR i * (INR i - 1) / 2 * (w * Ms) + INR i * (INR i - 1) / 2 * eta
                   + 1002 / 1000 * INR i * w + INR i * eta) by (unfold Mp; ring).
    assert (R8 : 0 <= INR i * w) by (apply Rmult_le_pos; lra).
    replace (Q i - (ee + 2 * (INR i / mr) * dd + INR i / mr * (INR i / mr) * c))
      with ((Q i - (fe + INR i * g0 + INR i * (INR i - 1) / 2 * h))
            + (fe + INR i * g0 + INR i * (INR i - 1) / 2 * h
               - (ee + 2 * (INR i / mr) * dd + INR i / mr * (INR i / mr) * c))) by ring.
    eapply Rle_trans; [apply Rabs_triang|].
    lra.
Qed.

(** ** Unit normals: the exact slopes n dq_x = (2x+1)/n c + 2 dd are within 4 *)

Lemma dc_slope : forall s, is_unit (Na s) -> is_unit (Nb s) -> forall z, 0 <= z <= 2 ->
  Rabs (dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) * z + 2 * dot (vsub (Nb s) (Na s)) (Na s))
    <= 4.
Proof.
  intros s Ha Hb z Hz.
  assert (X : Rabs (dot (Na s) (Nb s)) <= 1)
    by (eapply Rle_trans; [apply dot_abs | apply unit_pair; assumption]).
  assert (E1 : dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))
               = dot (Nb s) (Nb s) - 2 * dot (Na s) (Nb s) + dot (Na s) (Na s))
    by (unfold dot, vsub; cbn [vx vy vz]; ring).
  assert (E2 : dot (vsub (Nb s) (Na s)) (Na s) = dot (Na s) (Nb s) - dot (Na s) (Na s))
    by (unfold dot, vsub; cbn [vx vy vz]; ring).
  rewrite E1, E2. unfold is_unit in Ha, Hb. rewrite Ha, Hb.
  set (r := dot (Na s) (Nb s)) in *.
  assert (R : - 1 <= r <= 1) by (unfold Rabs in X; destruct (Rcase_abs r); lra).
  apply Rabs_le. split; nra.
Qed.

(** ** Duff's method with unit v (inputs, set-up additions and products),
    d (the division) and w (the additions of dq_0, d2q and the loop) *)

Lemma duff_core : forall (v d eta w : R) (s : span) (na nb l kk : vec)
  (tx ty tz fa fb fc e fe h : R) (P Q G : nat -> R),
  small_ok v eta -> small_ok d eta -> 0 <= w <= v ->
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> INR (n s) * w <= / 2048 ->
  vap1 v eta na (Na s) -> vap1 v eta nb (Nb s) -> vap1 v eta l (L s) ->
  ap1 v eta tx (vx nb - vx na) -> ap1 d eta (vx kk) (tx / INR (n s)) ->
  ap1 v eta ty (vy nb - vy na) -> ap1 d eta (vy kk) (ty / INR (n s)) ->
  ap1 v eta tz (vz nb - vz na) -> ap1 d eta (vz kk) (tz / INR (n s)) ->
  fdot_rel v v eta kk l fa -> fdot_rel v v eta na l fb -> fdot_rel v v eta kk kk fc ->
  fdot_rel v v eta kk na e -> fdot_rel v v eta na na fe ->
  P O = fb -> Q O = fe -> ap1 v eta (G O) (fc + 2 * e) -> ap1 v eta h (fc + fc) ->
  (forall j, (j < n s)%nat ->
     ap1 w eta (P (S j)) (P j + fa) /\ ap1 w eta (Q (S j)) (Q j + G j) /\
     ap1 w eta (G (S j)) (G j + h)) ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - p s (INR i)) <= 1702 / 100 * v + 202 / 100 * d + 1001 / 1000 * INR i * w /\
  Rabs (Q i - q s (INR i)) <= 6505 / 100 * v + 1204 / 100 * d + 3004 / 1000 * INR i * w.
Proof.
  intros v d eta w s na nb l kk tx ty tz fa fb fc e fe h P Q G Hv Hd Hw Ha Hb Hl
    Hn1 Hn2 Hnw Ina Inb Inl Htx Hkx Hty Hky Htz Hkz Hfa Hfb Hfc Hfe0 Hfe HP0 HQ0 Hg0 Hh Hst
    i Hi.
  v_facts Hv. v_facts Hd.
  assert (Hn0 : (n s <> 0)%nat) by lia.
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  assert (Hii : 0 <= INR i <= INR (n s)) by (split; [apply pos_INR | apply le_INR; exact Hi]).
  destruct (hc_sizes s Ha Hb Hl) as [Sa [Sd Sc]].
  pose proof (K_a v d eta Hv Hd s Ha Hb Hl Hn1 Hn2 na nb l kk fa Ina Inb Inl
                tx ty tz Htx Hkx Hty Hky Htz Hkz Hfa) as CA.
  pose proof (K_pa v d eta Hv Hd s Ha Hb Hl na l fb Ina Inl Hfb) as CB.
  pose proof (K_c v d eta Hv Hd s Ha Hb Hl Hn1 Hn2 na nb kk fc Ina Inb
                tx ty tz Htx Hkx Hty Hky Htz Hkz Hfc) as CC.
  pose proof (K_d0 v d eta Hv Hd s Ha Hb Hl Hn1 Hn2 na nb kk Ina Inb
                tx ty tz Htx Hkx Hty Hky Htz Hkz e Hfe0) as CD.
  pose proof (K_pa v d eta Hv Hd (mkSpan (Na s) (Nb s) (Na s) (n s)) Ha Hb Ha na na fe
                Ina Ina Hfe) as CE.
  unfold pa in CE; cbn [Na Nb L] in CE.
  pose proof (dl_dd s Ha Hb) as Cc.
  split.
  - rewrite hc_p_form by exact Hn0.
    assert (Hst1 : forall j, (j < n s)%nat -> ap1 w eta (P (S j)) (P j + fa))
      by (intros j Hj; apply (Hst j Hj)).
    pose proof (dp_loop v w eta (INR (n s)) fa fb _ _ _ _ (n s) i P Hv Hw eq_refl Hm Hnw
                  CA CB ltac:(lra) ltac:(lra) ltac:(lra)
                  (fun t Ht => hc_p_le1 s t Ha Hb Hl Ht) HP0 Hst1 Hi) as R.
    eapply Rle_trans; [exact R|]. lra.
  - rewrite hc_q_form by exact Hn0.
    assert (Hst2 : forall j, (j < n s)%nat ->
              ap1 w eta (Q (S j)) (Q j + G j) /\ ap1 w eta (G (S j)) (G j + h))
      by (intros j Hj; split; apply (Hst j Hj)).
    pose proof (dq_loop v w eta (INR (n s)) fc e fe _ _ _ _ _ _ h (n s) i Q G Hv Hw eq_refl Hm
                  Hnw CC CD CE ltac:(lra) ltac:(lra) ltac:(lra) Cc (dc_slope s Ha Hb)
                  (fun t Ht => hc_q_le1 s t Ha Hb Ht) Hg0 Hh HQ0 Hst2 Hi) as R.
    eapply Rle_trans; [exact R|]. lra.
Qed.

(** ** The computation as a relation, for a model M *)

(** Duff's loop from the set-up values fa = A, fb = B, fc = C, e (D = 2 e),
    fe = E: P = p^, Q = q^, G = dq^, every addition within ap_add. *)
Definition duff_run (M : fmodel) (m : nat) (fa fb fc e fe : R) (P Q G : nat -> R) : Prop :=
  P O = fb /\ Q O = fe /\ ap_add M (G O) (fc + 2 * e) /\
  exists h, ap_add M h (fc + fc) /\
    forall j, (j < m)%nat ->
      ap_add M (P (S j)) (P j + fa) /\ ap_add M (Q (S j)) (Q j + G j) /\
      ap_add M (G (S j)) (G j + h).

(** The set-up A, B, C, D = 2e, E from the computed na, l, k (each dot product
    in any order, products rounded or fused), then Duff's loop over m pixels. *)
Definition duff_ok (M : fmodel) (m : nat) (na l kk : vec) (P Q G : nat -> R) : Prop :=
  exists fa fb fc e fe,
    fdot_ok M kk l fa /\ fdot_ok M na l fb /\ fdot_ok M kk kk fc /\
    fdot_ok M kk na e /\ fdot_ok M na na fe /\ duff_run M m fa fb fc e fe P Q G.

(** Duff, k_j = (Nb_j - Na_j) / n with one division: for every i <= n,
    |p^_i - p_i| <= (17.02 K1 + 2.02 k_div + 1.001 i k_add) u,
    |q^_i - q_i| <= (65.05 K1 + 12.04 k_div + 3.004 i k_add) u,
    K1 >= k_in, k_add, k_mul, K1 >= 1, k_div >= 1, n k_add u <= 2^-11
    (and model_ok M K, K >= K1, k_div). *)
Theorem duff_div_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l kk : vec) (P Q G : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> INR (n s) * (k_add M * m_u M) <= / 2048 ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  kcomp_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  kcomp_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  kcomp_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  duff_ok M (n s) na l kk P Q G ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - p s (INR i)) <= (1702 / 100 * K1 + 202 / 100 * k_div M
                               + 1001 / 1000 * INR i * k_add M) * m_u M /\
  Rabs (Q i - q s (INR i)) <= (6505 / 100 * K1 + 1204 / 100 * k_div M
                               + 3004 / 1000 * INR i * k_add M) * m_u M.
Proof. intros; unfold duff_ok, duff_run in *; kd_model duff_core. Qed.

(** The same with k_j = (Nb_j - Na_j) * r, r = 1/n a rounded division:
    k_div is replaced by kd = (1 + 2^-20) k_mul + k_div + 2^-36, kd u <= 2^-21. *)
Theorem duff_recip_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (P Q G : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> INR (n s) * (k_add M * m_u M) <= / 2048 ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  krecip_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  krecip_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  krecip_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  duff_ok M (n s) na l kk P Q G ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - p s (INR i)) <= (1702 / 100 * K1
      + 202 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)
      + 1001 / 1000 * INR i * k_add M) * m_u M /\
  Rabs (Q i - q s (INR i)) <= (6505 / 100 * K1
      + 1204 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)
      + 3004 / 1000 * INR i * k_add M) * m_u M.
Proof. intros; unfold duff_ok, duff_run in *; kd_model duff_core. Qed.

(** ** Symmetric Phong: q walked to h = floor(n/2), reused as q(n - i) = q(i) *)

(** Symmetric Phong from Duff's theorem [lem]: p at i, q at j = min(i, n - i),
    q(n - i) = q(i) for |Na| = |Nb| ([Symmetry.sec_4_q_is_symmetric]). *)
Ltac sym_inst lem :=
  intros;
  match goal with Ha : is_unit (Na ?s), Hb : is_unit (Nb ?s), Hi : (?i <= n ?s)%nat |- _ =>
    assert (Hj : (Nat.min i (n s - i) <= n s)%nat) by lia;
    assert (Eq : q s (INR (Nat.min i (n s - i))) = q s (INR i));
    [ destruct (Nat.min_spec i (n s - i)) as [[_ E] | [_ E]]; rewrite E; [reflexivity|];
      rewrite minus_INR by exact Hi; symmetry; apply Symmetry.sec_4_q_is_symmetric;
      unfold is_unit in Ha, Hb; rewrite Ha, Hb; reflexivity
    | split; [eapply proj1 | rewrite <- Eq; eapply proj2]; eapply lem; eassumption ]
  end.

(** Symmetric Phong (src/symmetric_phong.rs), k_j = (Nb_j - Na_j) / n with one
    division: p is walked as in Duff; q is walked by Duff's recurrence only to
    h = floor(n/2).  The walk of q to h is a prefix of Duff's walk, so the run of
    [duff_ok] covers it; pixel i's q is the one walked min(i, n - i) steps, and
    for unit Na, Nb, q(n - i) = q(i) ([Symmetry.sec_4_q_is_symmetric]).  For every
    i <= n, with j = min(i, n - i):
    |p^_i - p_i| <= (17.02 K1 + 2.02 k_div + 1.001 i k_add) u,
    |q^_j - q_i| <= (65.05 K1 + 12.04 k_div + 3.004 j k_add) u. *)
Theorem symmetric_phong_div_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l kk : vec) (P Q G : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> INR (n s) * (k_add M * m_u M) <= / 2048 ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  kcomp_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  kcomp_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  kcomp_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  duff_ok M (n s) na l kk P Q G ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - p s (INR i)) <= (1702 / 100 * K1 + 202 / 100 * k_div M
                               + 1001 / 1000 * INR i * k_add M) * m_u M /\
  Rabs (Q (Nat.min i (n s - i)) - q s (INR i))
    <= (6505 / 100 * K1 + 1204 / 100 * k_div M
        + 3004 / 1000 * INR (Nat.min i (n s - i)) * k_add M) * m_u M.
Proof. sym_inst duff_div_generic. Qed.

(** The same with k_j = (Nb_j - Na_j) * r, r = 1/n a rounded division:
    k_div is replaced by kd = (1 + 2^-20) k_mul + k_div + 2^-36, kd u <= 2^-21. *)
Theorem symmetric_phong_recip_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (P Q G : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> INR (n s) * (k_add M * m_u M) <= / 2048 ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  krecip_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  krecip_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  krecip_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  duff_ok M (n s) na l kk P Q G ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - p s (INR i)) <= (1702 / 100 * K1
      + 202 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)
      + 1001 / 1000 * INR i * k_add M) * m_u M /\
  Rabs (Q (Nat.min i (n s - i)) - q s (INR i)) <= (6505 / 100 * K1
      + 1204 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)
      + 3004 / 1000 * INR (Nat.min i (n s - i)) * k_add M) * m_u M.
Proof. sym_inst duff_recip_generic. Qed.
