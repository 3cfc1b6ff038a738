(** * PhongCount.v — the computed p and q of Phong under the kappa model.

    §18.4 of docs/float.md, first half (PhongValue.v is the second): from the
    unit inputs Na, Nb, L read into the format ([Profiles.vap]: each component
    within k_in of the exact), n >= 1 and a pixel i <= n (exact integers),
    bounds of |p^ - p_i| and |q^ - q_i|, p_i = N_i.L, q_i = N_i.N_i,
    N_i = Na + (i/n)(Nb - Na) ([Span.p], [Span.q] at x = i), for
    - Horner's closed form ([horner_ok]): k_j = (Nb_j - Na_j) / n (a rounded
      subtraction, then one division [Profiles.kcomp_ok], or a reciprocal
      1/n and a product [krecip_ok]); A = k.L, B = Na.L, C = k.k,
      D = 2 (k.Na) (the x2 exact), E = Na.Na, each dot product in any order,
      each product rounded or fused ([fdot_ok]); p^ = (A i) + B,
      q^ = ((C i + D) i) + E, each product and sum rounded (a fused product
      is the case of an exact product);
    - the per-pixel normal ([pixel_ok]): N_j = na_j + (i k_j), then
      p^ = N.l, q^ = N.N;
    - the lerp ([lerp_ok]): t^ = i/n (one division, or i (1/n)),
      N_j = ((1 - t^) na_j) + (t^ nb_j), then p^ = N.l, q^ = N.N.
    With K1 >= 1, k_in, k_add, k_mul and kd = k_div (one division) or
    kd = (1 + 2^-20) k_mul + k_div + 2^-36 (reciprocal then product):
      Horner:            |p^ - p_i| <= (20.03 K1 + 2.02 kd) u,
                         |q^ - q_i| <= (78.11 K1 + 12.04 kd) u;
      per-pixel, lerp:   |p^ - p_i| <= (14.04 K1 + 2.04 kd) u,
                         |q^ - q_i| <= (23.06 K1 + 4.06 kd) u.
    The absolute term eta of every operation is absorbed (model_ok: eta 2^84 <= u,
    n <= 2^24).  Size conditions: model_ok M K with K1 <= K, 1 <= k_div, and for
    the reciprocal forms kd u <= 2^-21.  The set-up errors of A, B, C, D, E are
    Profiles.K_a, K_pa, K_c, K_d0 (E = K_pa on the span with L := Na). *)

From Coq Require Import Reals Lra Lia.
From PhongApprox Require Import Span FloatModel Float FloatModelK Profiles.
Open Scope R_scope.

(** ** Real-arithmetic steps *)

Lemma hc_t : forall m i, 1 <= m -> 0 <= i <= m -> 0 <= i / m <= 1.
Proof.
  intros m i Hm Hi. split.
  - apply Rmult_le_pos; [lra | left; apply Rinv_0_lt_compat; lra].
  - apply (Rmult_le_reg_r m); [lra|]. unfold Rdiv. rewrite Rmult_assoc, Rinv_l by lra. lra.
Qed.

Lemma hc_scale : forall t X, 0 <= t <= 1 -> Rabs (t * X) <= Rabs X.
Proof.
  intros t X Ht. rewrite Rabs_mult, Rabs_pos_eq by lra.
  pose proof (Rabs_pos X). nra.
Qed.

(** p^ = (A i) + B. *)
Lemma hp_abs : forall v eta m i fA fB a b cA cB x ph,
  small_ok v eta -> 1 <= m <= 16777216 -> 0 <= i <= m ->
  Rabs (m * fA - a) <= cA -> Rabs (fB - b) <= cB -> 0 <= cA <= / 1000 -> 0 <= cB <= / 1000 ->
  Rabs a <= 2 -> Rabs (b + i / m * a) <= 1 ->
  ap1 v eta x (fA * i) -> ap1 v eta ph (x + fB) ->
  Rabs (ph - (b + i / m * a)) <= cA + cB + 301 / 100 * v.
Proof.
  intros v eta m i fA fB a b cA cB x ph Hv Hm Hi HA HB HcA HcB Ha Hp Hx Hph.
  unfold ap1 in Hx, Hph.
  pose proof (v_pos v eta Hv). pose proof (v_small v eta Hv).
  pose proof (e_pos v eta Hv). pose proof (e_small v eta Hv).
  pose proof (hc_t m i ltac:(lra) Hi) as Ht.
  assert (EA : fA * i = i / m * (m * fA)) by (field; lra).
  assert (B1 : Rabs (fA * i) <= 2 + cA).
  { rewrite EA. eapply Rle_trans; [apply hc_scale; exact Ht|].
    pose proof (abs_near _ _ _ HA). lra. }
  assert (E1 : Rabs (x - fA * i) <= v * (2 + cA) + eta).
  { assert (v * Rabs (fA * i) <= v * (2 + cA)) by (apply Rmult_le_compat_l; lra). lra. }
  assert (E0 : Rabs (fA * i - i / m * a) <= cA).
  { replace (fA * i - i / m * a) with (i / m * (m * fA - a)) by (field; lra).
    eapply Rle_trans; [apply hc_scale; exact Ht|]. exact HA. }
  assert (S1 : Rabs (x + fB) <= 1 + cA + cB + (v * (2 + cA) + eta)).
  { replace (x + fB) with ((b + i / m * a) + (x - fA * i) + (fA * i - i / m * a) + (fB - b))
      by ring.
    eapply Rle_trans; [apply tri4|]. lra. }
  assert (S2 : 1 + cA + cB + (v * (2 + cA) + eta) <= 1004 / 1000).
  { assert (v * (2 + cA) <= / 2097152 * 3) by (apply Rmult_le_compat; lra). lra. }
  assert (E2 : Rabs (ph - (x + fB)) <= v * (1004 / 1000) + eta).
  { assert (v * Rabs (x + fB) <= v * (1004 / 1000)) by (apply Rmult_le_compat_l; lra). lra. }
  replace (ph - (b + i / m * a))
    with ((ph - (x + fB)) + (x - fA * i) + (fA * i - i / m * a) + (fB - b)) by ring.
  eapply Rle_trans; [apply tri4|].
  assert (v * (2 + cA) <= v * (2 + / 1000)) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

(** q^ = ((C i + D) i) + E, D = 2 e exactly. *)
Lemma hq_abs : forall v eta m i fC e fE c dd ee cC cD cE y1 y2 y3 qh,
  small_ok v eta -> 1 <= m <= 16777216 -> 0 <= i <= m ->
  Rabs (m * m * fC - c) <= cC -> Rabs (m * e - dd) <= cD -> Rabs (fE - ee) <= cE ->
  0 <= cC <= / 1000 -> 0 <= cD <= / 1000 -> 0 <= cE <= / 1000 ->
  Rabs c <= 4 -> Rabs dd <= 2 ->
  Rabs (ee + 2 * (i / m) * dd + (i / m) * (i / m) * c) <= 1 ->
  ap1 v eta y1 (fC * i) -> ap1 v eta y2 (y1 + 2 * e) -> ap1 v eta y3 (y2 * i) ->
  ap1 v eta qh (y3 + fE) ->
  Rabs (qh - (ee + 2 * (i / m) * dd + (i / m) * (i / m) * c))
    <= cE + cC + 2 * cD + 2106 / 100 * v.
Proof.
  intros v eta m i fC e fE c dd ee cC cD cE y1 y2 y3 qh Hv Hm Hi HC HD HE HcC HcD HcE
    Hc Hd Hq H1 H2 H3 H4.
  unfold ap1 in H1, H2, H3, H4.
  pose proof (v_pos v eta Hv). pose proof (v_small v eta Hv).
  pose proof (e_pos v eta Hv). pose proof (e_small v eta Hv).
  pose proof (hc_t m i ltac:(lra) Hi) as Ht.
  set (t := i / m) in *.
  assert (Ei : i = t * m) by (unfold t; field; lra).
  assert (Me : m * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  (* m y1 against t (m^2 fC) *)
  assert (F1 : Rabs (m * y1 - t * (m * m * fC)) <= v * (4 + cC) + m * eta).
  { replace (m * y1 - t * (m * m * fC)) with (m * (y1 - fC * i)) by (rewrite Ei; ring).
    rewrite Rabs_mult, (Rabs_pos_eq m) by lra.
    assert (G : m * Rabs (fC * i) <= 4 + cC).
    { replace (m * Rabs (fC * i)) with (Rabs (t * (m * m * fC)))
        by (rewrite Ei, !Rabs_mult, (Rabs_pos_eq m), (Rabs_pos_eq t) by lra; ring).
      eapply Rle_trans; [apply hc_scale; exact Ht|]. pose proof (abs_near _ _ _ HC). lra. }
    assert (m * Rabs (y1 - fC * i) <= m * (v * Rabs (fC * i) + eta))
      by (apply Rmult_le_compat_l; lra).
    assert (v * (m * Rabs (fC * i)) <= v * (4 + cC)) by (apply Rmult_le_compat_l; lra).
    assert (m * (v * Rabs (fC * i) + eta) = v * (m * Rabs (fC * i)) + m * eta) by ring.
    lra. }
  assert (F0 : Rabs (t * (m * m * fC) - t * c) <= cC).
  { replace (t * (m * m * fC) - t * c) with (t * (m * m * fC - c)) by ring.
    eapply Rle_trans; [apply hc_scale; exact Ht|]. exact HC. }
  assert (Tc : Rabs (t * c) <= 4) by (eapply Rle_trans; [apply hc_scale; exact Ht|]; lra).
  assert (V1 : v * (4 + cC) <= v * (4 + / 1000)) by (apply Rmult_le_compat_l; lra).
  (* m y2 against m (y1 + 2 e) *)
  assert (S2 : Rabs (m * y1 + 2 * (m * e)) <= 801 / 100).
  { replace (m * y1 + 2 * (m * e))
      with (t * c + 2 * dd + (m * y1 - t * (m * m * fC)) + (t * (m * m * fC) - t * c)
            + 2 * (m * e - dd)) by ring.
    assert (T : forall a1 a2 a3 a4 a5 : R,
      Rabs (a1 + a2 + a3 + a4 + a5) <= Rabs a1 + Rabs a2 + Rabs a3 + Rabs a4 + Rabs a5).
    { intros. repeat (eapply Rle_trans; [apply Rabs_triang | apply Rplus_le_compat_r]); lra. }
    assert (Rabs (2 * dd) <= 4) by (rewrite Rabs_mult, (Rabs_pos_eq 2) by lra; lra).
    assert (Rabs (2 * (m * e - dd)) <= 2 * cD)
      by (rewrite Rabs_mult, (Rabs_pos_eq 2) by lra; lra).
    eapply Rle_trans; [apply T|]. lra. }
  assert (F2 : Rabs (m * y2 - m * (y1 + 2 * e)) <= v * (801 / 100) + m * eta).
  { rewrite <- Rmult_minus_distr_l, Rabs_mult, (Rabs_pos_eq m) by lra.
    assert (m * Rabs (y2 - (y1 + 2 * e)) <= m * (v * Rabs (y1 + 2 * e) + eta))
      by (apply Rmult_le_compat_l; lra).
    assert (R1 : m * Rabs (y1 + 2 * e) = Rabs (m * y1 + 2 * (m * e)))
      by (rewrite <- (Rabs_pos_eq m) at 1 by lra; rewrite <- Rabs_mult; f_equal; ring).
    assert (v * (m * Rabs (y1 + 2 * e)) <= v * (801 / 100))
      by (apply Rmult_le_compat_l; lra).
    assert (m * (v * Rabs (y1 + 2 * e) + eta) = v * (m * Rabs (y1 + 2 * e)) + m * eta) by ring.
    lra. }
  assert (S3 : Rabs (m * y2) <= 802 / 100).
  { replace (m * y2) with ((m * y1 + 2 * (m * e)) + (m * y2 - m * (y1 + 2 * e))) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra. }
  assert (F3 : Rabs (y3 - y2 * i) <= v * (802 / 100) + eta).
  { assert (Rabs (y2 * i) <= 802 / 100).
    { replace (y2 * i) with (t * (m * y2)) by (rewrite Ei; ring).
      eapply Rle_trans; [apply hc_scale; exact Ht|]. exact S3. }
    assert (v * Rabs (y2 * i) <= v * (802 / 100)) by (apply Rmult_le_compat_l; lra). lra. }
  set (Q := ee + 2 * t * dd + t * t * c) in *.
  assert (Eq : y3 + fE - Q = (y3 - y2 * i) + t * (m * y2 - m * (y1 + 2 * e))
                 + t * (m * y1 - t * (m * m * fC)) + t * (t * (m * m * fC) - t * c)
                 + 2 * t * (m * e - dd) + (fE - ee)).
  { unfold Q. rewrite Ei. ring. }
  assert (T6 : forall a1 a2 a3 a4 a5 a6 : R,
    Rabs (a1 + a2 + a3 + a4 + a5 + a6)
      <= Rabs a1 + Rabs a2 + Rabs a3 + Rabs a4 + Rabs a5 + Rabs a6).
  { intros. repeat (eapply Rle_trans; [apply Rabs_triang | apply Rplus_le_compat_r]); lra. }
  assert (Rt1 : Rabs (t * (m * y2 - m * (y1 + 2 * e))) <= v * (801 / 100) + m * eta)
    by (eapply Rle_trans; [apply hc_scale; exact Ht | exact F2]).
  assert (Rt2 : Rabs (t * (m * y1 - t * (m * m * fC))) <= v * (4 + cC) + m * eta)
    by (eapply Rle_trans; [apply hc_scale; exact Ht | exact F1]).
  assert (Rt3 : Rabs (t * (t * (m * m * fC) - t * c)) <= cC)
    by (eapply Rle_trans; [apply hc_scale; exact Ht | exact F0]).
  assert (Rt4 : Rabs (2 * t * (m * e - dd)) <= 2 * cD).
  { replace (2 * t * (m * e - dd)) with (t * (2 * (m * e - dd))) by ring.
    eapply Rle_trans; [apply hc_scale; exact Ht|].
    rewrite Rabs_mult, (Rabs_pos_eq 2) by lra. lra. }
  assert (G : Rabs (y3 + fE - Q) <= cE + cC + 2 * cD + (v * (2004 / 100) + 3 * 16777216 * eta)).
  { rewrite Eq. eapply Rle_trans; [apply T6|]. lra. }
  assert (S4 : Rabs (y3 + fE) <= 1005 / 1000).
  { replace (y3 + fE) with (Q + (y3 + fE - Q)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra. }
  assert (F4 : Rabs (qh - (y3 + fE)) <= v * (1005 / 1000) + eta).
  { assert (v * Rabs (y3 + fE) <= v * (1005 / 1000)) by (apply Rmult_le_compat_l; lra). lra. }
  replace (qh - Q) with ((qh - (y3 + fE)) + (y3 + fE - Q)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.

(** ** The exact p_i, q_i and their sizes *)

Lemma hc_dot_abs : forall a b : vec,
  Rabs (dot a b) <= Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b) + Rabs (vz a) * Rabs (vz b).
Proof. intros a b. unfold dot. rewrite <- !Rabs_mult. apply tri3. Qed.

Lemma hc_p_form : forall s x, (n s <> 0)%nat ->
  p s x = pa s + x / INR (n s) * dot (vsub (Nb s) (Na s)) (L s).
Proof.
  intros s x Hn. apply not_0_INR in Hn. unfold p, A, B, pa, k, dot, vscale, vsub; cbn [vx vy vz].
  field. exact Hn.
Qed.

Lemma hc_q_form : forall s x, (n s <> 0)%nat ->
  q s x = dot (Na s) (Na s) + 2 * (x / INR (n s)) * dot (vsub (Nb s) (Na s)) (Na s)
          + (x / INR (n s)) * (x / INR (n s)) * dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)).
Proof.
  intros s x Hn. apply not_0_INR in Hn. unfold q, C, D, E, k, dot, vscale, vsub; cbn [vx vy vz].
  field. exact Hn.
Qed.

Lemma hc_p_le1 : forall s t, is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> 0 <= t <= 1 ->
  Rabs (pa s + t * dot (vsub (Nb s) (Na s)) (L s)) <= 1.
Proof.
  intros s t Ha Hb Hl Ht.
  assert (X : Rabs (dot (Na s) (L s)) <= 1)
    by (eapply Rle_trans; [apply hc_dot_abs | apply unit_pair; assumption]).
  assert (Y : Rabs (dot (Nb s) (L s)) <= 1)
    by (eapply Rle_trans; [apply hc_dot_abs | apply unit_pair; assumption]).
  replace (pa s + t * dot (vsub (Nb s) (Na s)) (L s))
    with ((1 - t) * dot (Na s) (L s) + t * dot (Nb s) (L s))
    by (unfold pa, dot, vsub; cbn [vx vy vz]; ring).
  eapply Rle_trans; [apply Rabs_triang|].
  rewrite !Rabs_mult, (Rabs_pos_eq (1 - t)), (Rabs_pos_eq t) by lra. nra.
Qed.

Lemma hc_q_le1 : forall s t, is_unit (Na s) -> is_unit (Nb s) -> 0 <= t <= 1 ->
  Rabs (dot (Na s) (Na s) + 2 * t * dot (vsub (Nb s) (Na s)) (Na s)
        + t * t * dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))) <= 1.
Proof.
  intros s t Ha Hb Ht.
  assert (X : Rabs (dot (Na s) (Nb s)) <= 1)
    by (eapply Rle_trans; [apply hc_dot_abs | apply unit_pair; assumption]).
  assert (E : dot (Na s) (Na s) + 2 * t * dot (vsub (Nb s) (Na s)) (Na s)
        + t * t * dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))
        = (1 - t) * (1 - t) * dot (Na s) (Na s) + t * t * dot (Nb s) (Nb s)
          + 2 * t * (1 - t) * dot (Na s) (Nb s))
    by (unfold dot, vsub; cbn [vx vy vz]; ring).
  rewrite E. unfold is_unit in Ha, Hb. rewrite Ha, Hb.
  set (r := dot (Na s) (Nb s)) in *.
  assert (R : - 1 <= r <= 1) by (unfold Rabs in X; destruct (Rcase_abs r); lra).
  assert (P : 0 <= 2 * t * (1 - t)) by nra.
  apply Rabs_le. split; nra.
Qed.

Lemma hc_sizes : forall s, is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  Rabs (dot (vsub (Nb s) (Na s)) (L s)) <= 2 /\
  Rabs (dot (vsub (Nb s) (Na s)) (Na s)) <= 2 /\
  Rabs (dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))) <= 4.
Proof.
  intros s Ha Hb Hl. split; [|split].
  - eapply Rle_trans; [apply hc_dot_abs | apply diff_pair; assumption].
  - eapply Rle_trans; [apply hc_dot_abs | apply diff_pair; assumption].
  - pose proof (diff_sq _ _ Ha Hb).
    assert (0 <= dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))).
    { unfold dot. pose proof (Rle_0_sqr (vx (vsub (Nb s) (Na s)))).
      pose proof (Rle_0_sqr (vy (vsub (Nb s) (Na s)))).
      pose proof (Rle_0_sqr (vz (vsub (Nb s) (Na s)))). unfold Rsqr in *. lra. }
    rewrite Rabs_pos_eq; lra.
Qed.

(** ** Horner's closed form with unit v (inputs, additions, products) and d (the division) *)

Lemma horner_core : forall (v d eta : R) (s : span) (na nb l kk : vec)
  (tx ty tz fa fb fc e fe : R) (i : nat) (x ph y1 y2 y3 qh : R),
  small_ok v eta -> small_ok d eta ->
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap1 v eta na (Na s) -> vap1 v eta nb (Nb s) -> vap1 v eta l (L s) ->
  ap1 v eta tx (vx nb - vx na) -> ap1 d eta (vx kk) (tx / INR (n s)) ->
  ap1 v eta ty (vy nb - vy na) -> ap1 d eta (vy kk) (ty / INR (n s)) ->
  ap1 v eta tz (vz nb - vz na) -> ap1 d eta (vz kk) (tz / INR (n s)) ->
  fdot_rel v v eta kk l fa -> fdot_rel v v eta na l fb -> fdot_rel v v eta kk kk fc ->
  fdot_rel v v eta kk na e -> fdot_rel v v eta na na fe ->
  ap1 v eta x (fa * INR i) -> ap1 v eta ph (x + fb) ->
  ap1 v eta y1 (fc * INR i) -> ap1 v eta y2 (y1 + 2 * e) -> ap1 v eta y3 (y2 * INR i) ->
  ap1 v eta qh (y3 + fe) ->
  Rabs (ph - p s (INR i)) <= 2003 / 100 * v + 202 / 100 * d /\
  Rabs (qh - q s (INR i)) <= 7811 / 100 * v + 1204 / 100 * d.
Proof.
  intros v d eta s na nb l kk tx ty tz fa fb fc e fe i x ph y1 y2 y3 qh Hv Hd Ha Hb Hl
    Hn1 Hn2 Hi Ina Inb Inl Htx Hkx Hty Hky Htz Hkz Hfa Hfb Hfc Hfe0 Hfe Hx Hph Hy1 Hy2 Hy3 Hqh.
  pose proof (v_pos v eta Hv). pose proof (v_small v eta Hv).
  pose proof (v_pos d eta Hd). pose proof (v_small d eta Hd).
  assert (Hn0 : (n s <> 0)%nat) by lia.
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  assert (Hii : 0 <= INR i <= INR (n s)) by (split; [apply pos_INR | apply le_INR; exact Hi]).
  pose proof (hc_t (INR (n s)) (INR i) ltac:(lra) Hii) as Ht.
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
  split.
  - rewrite hc_p_form by exact Hn0.
    eapply Rle_trans.
    + eapply (hp_abs v eta (INR (n s)) (INR i) fa fb); try eassumption; try lra.
      apply hc_p_le1; assumption.
    + lra.
  - rewrite hc_q_form by exact Hn0.
    eapply Rle_trans.
    + eapply (hq_abs v eta (INR (n s)) (INR i) fc e fe); try eassumption; try lra.
      apply hc_q_le1; assumption.
    + lra.
Qed.

(** ** A division as a reciprocal then a product *)

Lemma recip_ap1 : forall (u eta kd km m x r y : R),
  0 < u <= / 2097152 -> 0 <= eta -> eta * 19342813113834066795298816 <= u ->
  0 <= kd -> kd * u <= / 2097152 -> 0 <= km -> 1 <= m <= 16777216 ->
  ap1 (kd * u) eta r (1 / m) -> ap1 (km * u) eta y (x * r) ->
  ap1 (((1 + / 1048576) * km + kd + / 68719476736) * u) eta y (x / m).
Proof.
  intros u eta kd km m x r y Hu He He2 Hkd Hkdu Hkm Hm Hr Hy. unfold ap1 in *.
  assert (Im : 0 < / m) by (apply Rinv_0_lt_compat; lra).
  assert (Im2 : / 16777216 <= / m) by (apply Rinv_le_contravar; lra).
  replace (1 / m) with (/ m) in Hr by (field; lra).
  rewrite (Rabs_pos_eq (/ m)) in Hr by lra.
  set (dd := (kd + / 68719476736) * u).
  assert (R1 : Rabs (r - / m) <= dd * / m).
  { assert (eta <= / 68719476736 * u * / m).
    { assert (/ 68719476736 * u * / 16777216 <= / 68719476736 * u * / m)
        by (apply Rmult_le_compat_l; nra). lra. }
    unfold dd. lra. }
  assert (Hdd : 0 <= dd <= / 1048576).
  { unfold dd. split; [nra|].
    lra. }
  assert (X1 : Rabs (x * r - x / m) <= dd * Rabs (x / m)).
  { replace (x * r - x / m) with (x * (r - / m)) by (field; lra).
    replace (x / m) with (x * / m) by (field; lra).
    rewrite !Rabs_mult, (Rabs_pos_eq (/ m)) by lra.
    replace (dd * (Rabs x * / m)) with (Rabs x * (dd * / m)) by ring.
    apply Rmult_le_compat_l; [apply Rabs_pos | exact R1]. }
  assert (X2 : Rabs (x * r) <= (1 + dd) * Rabs (x / m)).
  { pose proof (abs_near _ _ _ X1). lra. }
  assert (X3 : km * u * Rabs (x * r) <= km * u * ((1 + dd) * Rabs (x / m)))
    by (apply Rmult_le_compat_l; nra).
  assert (X4 : km * u * (dd * Rabs (x / m)) <= km * u * (/ 1048576 * Rabs (x / m))).
  { apply Rmult_le_compat_l; [nra|]. apply Rmult_le_compat_r; [apply Rabs_pos | lra]. }
  replace (y - x / m) with ((y - x * r) + (x * r - x / m)) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  pose proof (Rabs_pos (x / m)).
  assert (E : ((1 + / 1048576) * km + kd + / 68719476736) * u * Rabs (x / m)
              = km * u * Rabs (x / m) + km * u * (/ 1048576 * Rabs (x / m))
                + dd * Rabs (x / m)) by (unfold dd; ring).
  rewrite E. nra.
Qed.

(** ** The computation as a relation, for a model M *)

(** k_j as a rounded subtraction, a reciprocal 1/m (a division) and a product. *)
Definition krecip_ok (M : fmodel) (m kj a b : R) : Prop :=
  exists t r, ap_add M t (b - a) /\ ap_div M r (1 / m) /\ ap_mul M kj (t * r).

(** Horner's closed form from the computed na, l, k, at the pixel i. *)
Definition horner_ok (M : fmodel) (i : nat) (na l kk : vec) (ph qh : R) : Prop :=
  exists fa fb fc e fe,
    fdot_ok M kk l fa /\ fdot_ok M na l fb /\ fdot_ok M kk kk fc /\
    fdot_ok M kk na e /\ fdot_ok M na na fe /\
    (exists x, ap_mul M x (fa * INR i) /\ ap_add M ph (x + fb)) /\
    (exists y1 y2 y3, ap_mul M y1 (fc * INR i) /\ ap_add M y2 (y1 + 2 * e) /\
                      ap_mul M y3 (y2 * INR i) /\ ap_add M qh (y3 + fe)).

Lemma hm_small : forall M K K1, model_ok M K -> 1 <= K1 <= K -> small_ok (K1 * m_u M) (m_eta M).
Proof.
  intros M K K1 HM HK. pose proof HM as (H1 & H2 & H3 & _ & _ & _ & _ & H8 & H9).
  repeat split; try lra.
  - apply Rmult_lt_0_compat; lra.
  - assert (K1 * m_u M <= K * m_u M) by (apply Rmult_le_compat_r; lra). lra.
  - assert (m_u M <= K1 * m_u M) by (rewrite <- (Rmult_1_l (m_u M)) at 1;
      apply Rmult_le_compat_r; lra). lra.
Qed.

Lemma hm_small_d : forall M K kd, model_ok M K -> 1 <= kd -> kd * m_u M <= / 2097152 ->
  small_ok (kd * m_u M) (m_eta M).
Proof.
  intros M K kd HM H1 H2. pose proof HM as (U1 & U2 & U3 & _).
  repeat split; try lra.
  - apply Rmult_lt_0_compat; lra.
  - assert (m_u M <= kd * m_u M) by (rewrite <- (Rmult_1_l (m_u M)) at 1;
      apply Rmult_le_compat_r; lra). lra.
Qed.

Lemma hm_ap : forall M k K1 y x, 0 < m_u M -> k <= K1 ->
  approx k (m_u M) (m_eta M) y x -> ap1 (K1 * m_u M) (m_eta M) y x.
Proof.
  intros M k K1 y x Hu Hk H. eapply ap1_mono; [|exact H].
  apply Rmult_le_compat_r; lra.
Qed.

Lemma hm_vap : forall M K1 vh w, 0 < m_u M -> k_in M <= K1 ->
  vap M vh w -> vap1 (K1 * m_u M) (m_eta M) vh w.
Proof.
  intros M K1 vh w Hu Hk [A1 [A2 A3]].
  repeat split; eapply hm_ap; eassumption.
Qed.

Lemma hm_fdot : forall M K1 a b y, 0 < m_u M -> k_add M <= K1 -> k_mul M <= K1 ->
  fdot_ok M a b y -> fdot_rel (K1 * m_u M) (K1 * m_u M) (m_eta M) a b y.
Proof.
  intros M K1 a b y Hu Ha Hm H. unfold fdot_ok in H.
  eapply fdot_mono; [| | exact H]; apply Rmult_le_compat_r; lra.
Qed.

(** The core with the model's operations, for any division unit d. *)
Lemma horner_model : forall (M : fmodel) (K K1 kd : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 ->
  1 <= kd -> kd * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R) (tx ty tz : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  ap_add M tx (vx nb - vx na) -> ap1 (kd * m_u M) (m_eta M) (vx kk) (tx / INR (n s)) ->
  ap_add M ty (vy nb - vy na) -> ap1 (kd * m_u M) (m_eta M) (vy kk) (ty / INR (n s)) ->
  ap_add M tz (vz nb - vz na) -> ap1 (kd * m_u M) (m_eta M) (vz kk) (tz / INR (n s)) ->
  horner_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (2003 / 100 * K1 + 202 / 100 * kd) * m_u M /\
  Rabs (qh - q s (INR i)) <= (7811 / 100 * K1 + 1204 / 100 * kd) * m_u M.
Proof.
  intros M K K1 kd HM HK1 Hin Hadd Hmul Hkd1 Hkd2 s na nb l kk i ph qh tx ty tz
    Ha Hb Hl Hn1 Hn2 Hi Ina Inb Inl Htx Hkx Hty Hky Htz Hkz
    (fa & fb & fc & e & fe & Hfa & Hfb & Hfc & Hfe0 & Hfe & (x & Hx & Hph)
     & (y1 & y2 & y3 & Hy1 & Hy2 & Hy3 & Hqh)).
  pose proof (model_u M K HM) as Hu.
  pose proof (hm_small M K K1 HM HK1) as Hv.
  pose proof (hm_small_d M K kd HM Hkd1 Hkd2) as Hd.
  destruct (horner_core (K1 * m_u M) (kd * m_u M) (m_eta M) s na nb l kk tx ty tz fa fb fc e fe
              i x ph y1 y2 y3 qh Hv Hd Ha Hb Hl Hn1 Hn2 Hi
              (hm_vap M K1 _ _ Hu Hin Ina) (hm_vap M K1 _ _ Hu Hin Inb)
              (hm_vap M K1 _ _ Hu Hin Inl)
              (hm_ap M _ K1 _ _ Hu Hadd Htx) Hkx (hm_ap M _ K1 _ _ Hu Hadd Hty) Hky
              (hm_ap M _ K1 _ _ Hu Hadd Htz) Hkz
              (hm_fdot M K1 _ _ _ Hu Hadd Hmul Hfa) (hm_fdot M K1 _ _ _ Hu Hadd Hmul Hfb)
              (hm_fdot M K1 _ _ _ Hu Hadd Hmul Hfc) (hm_fdot M K1 _ _ _ Hu Hadd Hmul Hfe0)
              (hm_fdot M K1 _ _ _ Hu Hadd Hmul Hfe)
              (hm_ap M _ K1 _ _ Hu Hmul Hx) (hm_ap M _ K1 _ _ Hu Hadd Hph)
              (hm_ap M _ K1 _ _ Hu Hmul Hy1) (hm_ap M _ K1 _ _ Hu Hadd Hy2)
              (hm_ap M _ K1 _ _ Hu Hmul Hy3) (hm_ap M _ K1 _ _ Hu Hadd Hqh)) as [P Q].
  split.
  - eapply Rle_trans; [exact P|]. right. ring.
  - eapply Rle_trans; [exact Q|]. right. ring.
Qed.

(** Phong, Horner's closed form, k_j = (Nb_j - Na_j) / n with one division:
    |p^ - p_i| <= (20.03 K1 + 2.02 k_div) u, |q^ - q_i| <= (78.11 K1 + 12.04 k_div) u,
    K1 >= k_in, k_add, k_mul, K1 >= 1, k_div >= 1 (and model_ok M K, K >= K1, k_div). *)
Theorem phong_horner_div_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  kcomp_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  kcomp_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  kcomp_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  horner_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (2003 / 100 * K1 + 202 / 100 * k_div M) * m_u M /\
  Rabs (qh - q s (INR i)) <= (7811 / 100 * K1 + 1204 / 100 * k_div M) * m_u M.
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l kk i ph qh Ha Hb Hl Hn1 Hn2 Hi
    Ina Inb Inl (tx & Htx & Hkx) (ty & Hty & Hky) (tz & Htz & Hkz) H.
  pose proof HM as (_ & _ & _ & _ & _ & _ & [_ Hdk] & _ & H9).
  assert (k_div M * m_u M <= / 2097152).
  { assert (k_div M * m_u M <= K * m_u M)
      by (apply Rmult_le_compat_r; [left; apply (model_u M K HM) | exact Hdk]). lra. }
  eapply (horner_model M K K1 (k_div M) HM HK1 Hin Hadd Hmul Hdiv); eassumption.
Qed.

(** The same with k_j = (Nb_j - Na_j) * r, r = 1/n a rounded division:
    k_div is replaced by kd = (1 + 2^-20) k_mul + k_div + 2^-36, kd u <= 2^-21. *)
Theorem phong_horner_recip_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  krecip_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  krecip_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  krecip_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  horner_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (2003 / 100 * K1
      + 202 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M /\
  Rabs (qh - q s (INR i)) <= (7811 / 100 * K1
      + 1204 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M.
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv Hkd s na nb l kk i ph qh Ha Hb Hl Hn1 Hn2 Hi
    Ina Inb Inl (tx & rx & Htx & Hrx & Hkx) (ty & ry & Hty & Hry & Hky)
    (tz & rz & Htz & Hrz & Hkz) H.
  pose proof HM as (U1 & U2 & U3 & _ & _ & [Km0 _] & [Kd0 Kd1] & K8 & K9).
  assert (Hu : 0 < m_u M <= / 2097152).
  { split; [exact U1|]. assert (m_u M <= K * m_u M) by (rewrite <- (Rmult_1_l (m_u M)) at 1;
      apply Rmult_le_compat_r; lra). lra. }
  assert (Hdu : k_div M * m_u M <= / 2097152).
  { assert (k_div M * m_u M <= K * m_u M) by (apply Rmult_le_compat_r; lra). lra. }
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  set (kd := (1 + / 1048576) * k_mul M + k_div M + / 68719476736) in *.
  assert (Kx : ap1 (kd * m_u M) (m_eta M) (vx kk) (tx / INR (n s)))
    by (unfold kd; apply (recip_ap1 _ _ (k_div M) (k_mul M) _ _ rx); assumption).
  assert (Ky : ap1 (kd * m_u M) (m_eta M) (vy kk) (ty / INR (n s)))
    by (unfold kd; apply (recip_ap1 _ _ (k_div M) (k_mul M) _ _ ry); assumption).
  assert (Kz : ap1 (kd * m_u M) (m_eta M) (vz kk) (tz / INR (n s)))
    by (unfold kd; apply (recip_ap1 _ _ (k_div M) (k_mul M) _ _ rz); assumption).
  assert (Hk1 : 1 <= kd) by (unfold kd; pose proof (Rmult_le_pos (1 + / 1048576) (k_mul M)); lra).
  exact (horner_model M K K1 kd HM HK1 Hin Hadd Hmul Hk1 Hkd s na nb l kk i ph qh tx ty tz
           Ha Hb Hl Hn1 Hn2 Hi Ina Inb Inl Htx Kx Hty Ky Htz Kz H).
Qed.

(** ** The per-pixel normal: N_j = na_j + (i k_j), p^ = N.l, q^ = N.N *)

Definition wb16 (w : vec) : Prop :=
  0 <= vx w <= 16 /\ 0 <= vy w <= 16 /\ 0 <= vz w <= 16.

(** [Profiles.K_dot] with weights up to 16. *)
Lemma pp_dot : forall (v d eta lam mu y Sb Cv Cd : R) (ah bh a0 b0 wa1 wa2 wb1 wb2 : vec),
  small_ok v eta -> small_ok d eta ->
  fdot_rel v v eta ah bh y -> 0 < lam -> 0 < mu -> lam * mu <= 281474976710656 ->
  vapprox 1 lam ah a0 (vlin v d wa1 wa2) -> vapprox 1 mu bh b0 (vlin v d wb1 wb2) ->
  vbounded a0 2 -> vbounded b0 2 -> wb16 wa1 -> wb16 wa2 -> wb16 wb1 -> wb16 wb2 ->
  Rabs (vx a0) * Rabs (vx b0) + Rabs (vy a0) * Rabs (vy b0) + Rabs (vz a0) * Rabs (vz b0) <= Sb ->
  Sb <= 12 ->
  wsum0 a0 b0 wa1 wb1 + 3 * Sb + / 100 <= Cv -> wsum0 a0 b0 wa2 wb2 + / 100 <= Cd ->
  Rabs (lam * mu * y - dot a0 b0) <= Cv * v + Cd * d.
Proof.
  intros v d eta lam mu y Sb Cv Cd ah bh a0 b0 wa1 wa2 wb1 wb2 Hv Hdv Hy Hl Hm Hlm HA HB Ba Bb
    W1 W2 W3 W4 HS HS12 C1 C2.
  pose proof (v_pos v eta Hv). pose proof (v_small v eta Hv).
  pose proof (v_pos d eta Hdv). pose proof (v_small d eta Hdv).
  pose proof (e_pos v eta Hv). pose proof (e_small v eta Hv).
  assert (WL : forall w1 w2, wb16 w1 -> wb16 w2 -> wle (vlin v d w1 w2) (16 * (v + d))).
  { intros w1 w2 [X1 [X2 X3]] [Y1 [Y2 Y3]]. unfold wle, vlin; cbn [vx vy vz].
    repeat split; nra. }
  pose proof (fdot_abs v eta Hv lam mu y (16 * (v + d)) ah bh a0 b0 _ _ Hy Hl Hm Hlm HA HB Ba Bb
                (WL _ _ W1 W2) (WL _ _ W3 W4)) as F.
  assert (E : wsum0 a0 b0 (vlin v d wa1 wa2) (vlin v d wb1 wb2)
              = v * wsum0 a0 b0 wa1 wb1 + d * wsum0 a0 b0 wa2 wb2)
    by (unfold wsum0, vlin; cbn [vx vy vz]; ring).
  rewrite E in F.
  set (S := Rabs (vx a0) * Rabs (vx b0) + Rabs (vy a0) * Rabs (vy b0) + Rabs (vz a0) * Rabs (vz b0))
    in *.
  assert (S0 : 0 <= S).
  { unfold S. pose proof (Rabs_pos (vx a0)). pose proof (Rabs_pos (vy a0)).
    pose proof (Rabs_pos (vz a0)). pose proof (Rabs_pos (vx b0)).
    pose proof (Rabs_pos (vy b0)). pose proof (Rabs_pos (vz b0)). nra. }
  assert (V1 : v * (wsum0 a0 b0 wa1 wb1 + 3 * Sb + / 100) <= v * Cv)
    by (apply Rmult_le_compat_l; lra).
  assert (V2 : d * (wsum0 a0 b0 wa2 wb2 + / 100) <= d * Cd) by (apply Rmult_le_compat_l; lra).
  assert (F1 : v * S <= v * Sb) by (apply Rmult_le_compat_l; lra).
  assert (F2 : v * Sb <= v * 12) by (apply Rmult_le_compat_l; lra).
  assert (F3 : (v + d) * (v + d) <= / 1048576 * (v + d)) by (apply Rmult_le_compat_r; lra).
  assert (F4 : v * (v + d) <= / 2097152 * (v + d)) by (apply Rmult_le_compat_r; lra).
  assert (F5 : v * ((v + d) * (v + d)) <= / 2097152 * (v + d)).
  { assert ((v + d) * (v + d) <= v + d) by lra.
    apply Rmult_le_compat; try lra. apply Rmult_le_pos; lra. }
  assert (F6 : 0 <= v * S) by (apply Rmult_le_pos; lra).
  eapply Rle_trans; [exact F|]. lra.
Qed.

(** One component of the per-pixel normal: input, subtraction, division (unit d),
    product i k_j (rounded or exact), sum. *)
Lemma pp_comp : forall v d eta m i a0 b0 ra rb tt kj z nj,
  small_ok v eta -> small_ok d eta -> 1 <= m <= 16777216 -> 0 <= i <= m ->
  Rabs a0 <= 1 -> Rabs b0 <= 1 ->
  ap1 v eta ra a0 -> ap1 v eta rb b0 -> ap1 v eta tt (rb - ra) -> ap1 d eta kj (tt / m) ->
  ap1 v eta z (i * kj) -> ap1 v eta nj (ra + z) ->
  Rabs (1 * nj - (a0 + i / m * (b0 - a0))) <=
    1 * (v * (501 / 100 * (Rabs a0 + Rabs b0) + / 32768)
         + d * (101 / 100 * (Rabs a0 + Rabs b0) + / 32768)).
Proof.
  intros v d eta m i a0 b0 ra rb tt kj z nj Hv Hd Hm Hi Ha0 Hb0 Hra Hrb Htt Hkj Hz Hnj.
  rewrite !Rmult_1_l.
  pose proof (v_pos v eta Hv). pose proof (v_small v eta Hv).
  pose proof (v_pos d eta Hd). pose proof (v_small d eta Hd).
  pose proof (e_pos v eta Hv). pose proof (e_small v eta Hv).
  pose proof (Rabs_pos a0). pose proof (Rabs_pos b0).
  pose proof (K_comp v d eta Hv Hd m a0 b0 ra rb tt kj Hm Ha0 Hb0 Hra Hrb Htt Hkj) as HK.
  set (S := Rabs a0 + Rabs b0) in *.
  set (ek := v * (2001 / 1000 * S + / 268435456) + d * (1001 / 1000 * S + / 268435456)) in *.
  assert (Hek : 0 <= ek <= / 262144).
  { assert (HS : 0 <= S <= 2) by (unfold S; lra).
    unfold ek. split.
    { pose proof (Rmult_le_pos v (2001 / 1000 * S + / 268435456) ltac:(lra) ltac:(lra)).
      pose proof (Rmult_le_pos d (1001 / 1000 * S + / 268435456) ltac:(lra) ltac:(lra)). lra. }
    assert (v * (2001 / 1000 * S + / 268435456) <= / 2097152 * (2001 / 1000 * 2 + / 268435456))
      by (apply Rmult_le_compat; unfold S in *; lra).
    assert (d * (1001 / 1000 * S + / 268435456) <= / 2097152 * (1001 / 1000 * 2 + / 268435456))
      by (apply Rmult_le_compat; unfold S in *; lra).
    lra. }
  pose proof (hc_t m i ltac:(lra) Hi) as Ht.
  assert (G1 : Rabs (i * kj - i / m * (b0 - a0)) <= ek).
  { replace (i * kj - i / m * (b0 - a0)) with (i / m * (m * kj - (b0 - a0))) by (field; lra).
    eapply Rle_trans; [apply hc_scale; exact Ht | exact HK]. }
  assert (G0 : Rabs (i / m * (b0 - a0)) <= S).
  { eapply Rle_trans; [apply hc_scale; exact Ht|]. pose proof (absdiff b0 a0). unfold S. lra. }
  assert (G2 : Rabs (i * kj) <= S + ek).
  { replace (i * kj) with (i / m * (b0 - a0) + (i * kj - i / m * (b0 - a0))) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra. }
  assert (G3 : Rabs (z - i * kj) <= v * (S + ek) + eta).
  { unfold ap1 in Hz. assert (v * Rabs (i * kj) <= v * (S + ek)) by (apply Rmult_le_compat_l; lra).
    lra. }
  pose proof (in_comp v eta Hv _ _ Hra) as G4.
  assert (G5a : Rabs (a0 + i / m * (b0 - a0)) <= S).
  { replace (a0 + i / m * (b0 - a0)) with ((1 - i / m) * a0 + i / m * b0) by ring.
    eapply Rle_trans; [apply Rabs_triang|].
    rewrite !Rabs_mult, (Rabs_pos_eq (1 - i / m)), (Rabs_pos_eq (i / m)) by lra.
    unfold S. nra. }
  assert (Vek : v * ek <= v * / 262144) by (apply Rmult_le_compat_l; lra).
  assert (VS : v * S <= / 2097152 * 2) by (apply Rmult_le_compat; unfold S in *; lra).
  assert (G5 : Rabs (ra + z) <= S + / 131072).
  { replace (ra + z) with ((a0 + i / m * (b0 - a0)) + (ra - a0) + (z - i * kj)
                            + (i * kj - i / m * (b0 - a0))) by ring.
    eapply Rle_trans; [apply tri4|].
    assert (v * (Rabs a0 + / 1073741824) <= / 2097152 * (1 + / 1073741824))
      by (apply Rmult_le_compat; lra).
    lra. }
  assert (G6 : Rabs (nj - (ra + z)) <= v * (S + / 131072) + eta).
  { unfold ap1 in Hnj. assert (v * Rabs (ra + z) <= v * (S + / 131072))
      by (apply Rmult_le_compat_l; lra). lra. }
  replace (nj - (a0 + i / m * (b0 - a0)))
    with ((nj - (ra + z)) + (z - i * kj) + (ra - a0) + (i * kj - i / m * (b0 - a0))) by ring.
  eapply Rle_trans; [apply tri4|].
  assert (v * Rabs a0 <= v * S) by (apply Rmult_le_compat_l; unfold S; lra).
  assert (0 <= v * S) by (apply Rmult_le_pos; unfold S; lra).
  assert (0 <= d * S) by (apply Rmult_le_pos; unfold S; lra).
  unfold ek in *. lra.
Qed.

(** The exact normal N_i = Na + t (Nb - Na), 0 <= t <= 1. *)
Definition nrm (s : span) (t : R) : vec := vadd (Na s) (vscale t (vsub (Nb s) (Na s))).

Lemma pp_ni : forall s t, is_unit (Na s) -> is_unit (Nb s) -> 0 <= t <= 1 ->
  vbounded (nrm s t) 1 /\
  (forall X, is_unit X ->
     Rabs (vx (nrm s t)) * Rabs (vx X) + Rabs (vy (nrm s t)) * Rabs (vy X)
     + Rabs (vz (nrm s t)) * Rabs (vz X) <= 1) /\
  Rabs (vx (nrm s t)) * Rabs (vx (nrm s t)) + Rabs (vy (nrm s t)) * Rabs (vy (nrm s t))
     + Rabs (vz (nrm s t)) * Rabs (vz (nrm s t)) <= 1.
Proof.
  intros s t Ha Hb Ht.
  assert (Q : dot (nrm s t) (nrm s t) <= 1).
  { pose proof (hc_q_le1 s t Ha Hb Ht) as H.
    replace (dot (nrm s t) (nrm s t)) with (dot (Na s) (Na s)
        + 2 * t * dot (vsub (Nb s) (Na s)) (Na s)
        + t * t * dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)))
      by (unfold nrm, dot, vadd, vscale, vsub; cbn [vx vy vz]; ring).
    unfold Rabs in H. destruct (Rcase_abs _); lra. }
  destruct (unit_bounded _ Ha) as [A1 [A2 A3]].
  destruct (unit_bounded _ Hb) as [B1 [B2 B3]].
  assert (C : forall a b, Rabs a <= 1 -> Rabs b <= 1 -> Rabs (a + t * (b - a)) <= 1).
  { intros a b H1 H2. replace (a + t * (b - a)) with ((1 - t) * a + t * b) by ring.
    eapply Rle_trans; [apply Rabs_triang|].
    rewrite !Rabs_mult, (Rabs_pos_eq (1 - t)), (Rabs_pos_eq t) by lra.
    pose proof (Rabs_pos a). pose proof (Rabs_pos b). nra. }
  split; [|split].
  - unfold vbounded, nrm, vadd, vscale, vsub; cbn [vx vy vz]. repeat split; apply C; assumption.
  - intros X HX. unfold is_unit in HX.
    pose proof (amgm1 (vx (nrm s t)) (vx X)). pose proof (amgm1 (vy (nrm s t)) (vy X)).
    pose proof (amgm1 (vz (nrm s t)) (vz X)). unfold dot in Q, HX. lra.
  - rewrite !abs_sq. unfold dot in Q. lra.
Qed.

Lemma pp_p_form : forall s i, (n s <> 0)%nat ->
  p s (INR i) = dot (nrm s (INR i / INR (n s))) (L s).
Proof.
  intros s i Hn. rewrite hc_p_form by exact Hn.
  unfold nrm, pa, dot, vadd, vscale, vsub; cbn [vx vy vz]. ring.
Qed.

Lemma pp_q_form : forall s i, (n s <> 0)%nat ->
  q s (INR i) = dot (nrm s (INR i / INR (n s))) (nrm s (INR i / INR (n s))).
Proof.
  intros s i Hn. rewrite hc_q_form by exact Hn.
  unfold nrm, dot, vadd, vscale, vsub; cbn [vx vy vz]. ring.
Qed.

Definition wPv (a b : vec) : vec :=
  mkV (501 / 100 * (Rabs (vx a) + Rabs (vx b)) + / 32768)
      (501 / 100 * (Rabs (vy a) + Rabs (vy b)) + / 32768)
      (501 / 100 * (Rabs (vz a) + Rabs (vz b)) + / 32768).
Definition wPd (a b : vec) : vec :=
  mkV (101 / 100 * (Rabs (vx a) + Rabs (vx b)) + / 32768)
      (101 / 100 * (Rabs (vy a) + Rabs (vy b)) + / 32768)
      (101 / 100 * (Rabs (vz a) + Rabs (vz b)) + / 32768).

Lemma pp_core : forall (v d eta : R) (s : span) (na nb l kk nh : vec) (i : nat)
  (tx ty tz zx zy zz ph qh : R),
  small_ok v eta -> small_ok d eta ->
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap1 v eta na (Na s) -> vap1 v eta nb (Nb s) -> vap1 v eta l (L s) ->
  ap1 v eta tx (vx nb - vx na) -> ap1 d eta (vx kk) (tx / INR (n s)) ->
  ap1 v eta ty (vy nb - vy na) -> ap1 d eta (vy kk) (ty / INR (n s)) ->
  ap1 v eta tz (vz nb - vz na) -> ap1 d eta (vz kk) (tz / INR (n s)) ->
  ap1 v eta zx (INR i * vx kk) -> ap1 v eta (vx nh) (vx na + zx) ->
  ap1 v eta zy (INR i * vy kk) -> ap1 v eta (vy nh) (vy na + zy) ->
  ap1 v eta zz (INR i * vz kk) -> ap1 v eta (vz nh) (vz na + zz) ->
  fdot_rel v v eta nh l ph -> fdot_rel v v eta nh nh qh ->
  Rabs (ph - p s (INR i)) <= 1404 / 100 * v + 204 / 100 * d /\
  Rabs (qh - q s (INR i)) <= 2306 / 100 * v + 406 / 100 * d.
Proof.
  intros v d eta s na nb l kk nh i tx ty tz zx zy zz ph qh Hv Hd Ha Hb Hl Hn1 Hn2 Hi
    Ina Inb Inl Htx Hkx Hty Hky Htz Hkz Hzx Hnx Hzy Hny Hzz Hnz Hp Hq.
  assert (Hn0 : (n s <> 0)%nat) by lia.
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  assert (Hii : 0 <= INR i <= INR (n s)) by (split; [apply pos_INR | apply le_INR; exact Hi]).
  pose proof (hc_t (INR (n s)) (INR i) ltac:(lra) Hii) as Ht.
  set (t := INR i / INR (n s)) in *.
  destruct (pp_ni s t Ha Hb Ht) as [NB [NX NN]].
  pose proof (NX _ Hl) as NL. pose proof (NX _ Ha) as NA. pose proof (NX _ Hb) as NBb.
  pose proof (unit_pair _ _ Ha Hl) as AL. pose proof (unit_pair _ _ Hb Hl) as BL.
  destruct (unit_bounded _ Ha) as [A1 [A2 A3]].
  destruct (unit_bounded _ Hb) as [B1 [B2 B3]].
  destruct (unit_bounded _ Hl) as [L1 [L2 L3]].
  destruct NB as [N1 [N2 N3]].
  destruct Ina as [Ia1 [Ia2 Ia3]]. destruct Inb as [Ib1 [Ib2 Ib3]].
  assert (VN : vapprox 1 1 nh (nrm s t) (vlin v d (wPv (Na s) (Nb s)) (wPd (Na s) (Nb s)))).
  { unfold vapprox, vlin, wPv, wPd, nrm, vadd, vscale, vsub; cbn [vx vy vz].
    repeat split; eapply pp_comp; eassumption. }
  assert (WB : forall a b : vec, vbounded a 1 -> vbounded b 1 -> wb16 (wPv a b) /\ wb16 (wPd a b)).
  { intros a b [X1 [X2 X3]] [Y1 [Y2 Y3]]. unfold wb16, wPv, wPd; cbn [vx vy vz].
    pose proof (Rabs_pos (vx a)). pose proof (Rabs_pos (vy a)). pose proof (Rabs_pos (vz a)).
    pose proof (Rabs_pos (vx b)). pose proof (Rabs_pos (vy b)). pose proof (Rabs_pos (vz b)).
    repeat split; lra. }
  destruct (WB (Na s) (Nb s) (unit_bounded _ Ha) (unit_bounded _ Hb)) as [Wv Wd].
  assert (W0 : wb16 vzero) by (unfold wb16, vzero; cbn [vx vy vz]; repeat split; lra).
  assert (WL : wb16 (Float.wIn (L s))).
  { unfold wb16, Float.wIn; cbn [vx vy vz].
    pose proof (Rabs_pos (vx (L s))). pose proof (Rabs_pos (vy (L s))).
    pose proof (Rabs_pos (vz (L s))). repeat split; lra. }
  pose proof (Rabs_pos (vx (Na s))). pose proof (Rabs_pos (vy (Na s))).
  pose proof (Rabs_pos (vz (Na s))). pose proof (Rabs_pos (vx (Nb s))).
  pose proof (Rabs_pos (vy (Nb s))). pose proof (Rabs_pos (vz (Nb s))).
  pose proof (Rabs_pos (vx (L s))). pose proof (Rabs_pos (vy (L s))).
  pose proof (Rabs_pos (vz (L s))). pose proof (Rabs_pos (vx (nrm s t))).
  pose proof (Rabs_pos (vy (nrm s t))). pose proof (Rabs_pos (vz (nrm s t))).
  pose proof (unit_pair _ _ Hb Ha) as BA.
  split.
  - rewrite pp_p_form by exact Hn0. fold t.
    pose proof (pp_dot v d eta 1 1 ph 1 (1404 / 100) (204 / 100) nh l (nrm s t) (L s)
      _ _ _ _ Hv Hd Hp ltac:(lra) ltac:(lra) ltac:(lra) VN (K_in_vec v d eta Hv _ _ Inl)
      (vb12 _ (conj N1 (conj N2 N3))) (vb12 _ (unit_bounded _ Hl)) Wv Wd WL W0) as HD.
    rewrite !Rmult_1_l in HD. apply HD; [lra | lra | |].
    + unfold wsum0, wPv, Float.wIn; cbn [vx vy vz].
      assert (Rabs (vx (nrm s t)) + Rabs (vy (nrm s t)) + Rabs (vz (nrm s t)) <= 3) by lra.
      lra.
    + unfold wsum0, wPd, vzero; cbn [vx vy vz]. lra.
  - rewrite pp_q_form by exact Hn0. fold t.
    pose proof (pp_dot v d eta 1 1 qh 1 (2306 / 100) (406 / 100) nh nh (nrm s t) (nrm s t)
      _ _ _ _ Hv Hd Hq ltac:(lra) ltac:(lra) ltac:(lra) VN VN
      (vb12 _ (conj N1 (conj N2 N3))) (vb12 _ (conj N1 (conj N2 N3))) Wv Wd Wv Wd) as HD.
    rewrite !Rmult_1_l in HD. apply HD; [lra | lra | |].
    + unfold wsum0, wPv; cbn [vx vy vz]. lra.
    + unfold wsum0, wPd; cbn [vx vy vz]. lra.
Qed.

(** The per-pixel normal from the computed na, k at the pixel i (each product
    i k_j rounded, or exact when fused into the sum), then p^ = N.l, q^ = N.N. *)
Definition ncomp_ok (M : fmodel) (i : nat) (nj naj kj : R) : Prop :=
  exists z, ap_mul M z (INR i * kj) /\ ap_add M nj (naj + z).

Definition pixel_ok (M : fmodel) (i : nat) (na l kk : vec) (ph qh : R) : Prop :=
  exists nh, ncomp_ok M i (vx nh) (vx na) (vx kk) /\ ncomp_ok M i (vy nh) (vy na) (vy kk) /\
    ncomp_ok M i (vz nh) (vz na) (vz kk) /\ fdot_ok M nh l ph /\ fdot_ok M nh nh qh.

Lemma pixel_model : forall (M : fmodel) (K K1 kd : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 ->
  1 <= kd -> kd * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R) (tx ty tz : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  ap_add M tx (vx nb - vx na) -> ap1 (kd * m_u M) (m_eta M) (vx kk) (tx / INR (n s)) ->
  ap_add M ty (vy nb - vy na) -> ap1 (kd * m_u M) (m_eta M) (vy kk) (ty / INR (n s)) ->
  ap_add M tz (vz nb - vz na) -> ap1 (kd * m_u M) (m_eta M) (vz kk) (tz / INR (n s)) ->
  pixel_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1 + 204 / 100 * kd) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1 + 406 / 100 * kd) * m_u M.
Proof.
  intros M K K1 kd HM HK1 Hin Hadd Hmul Hkd1 Hkd2 s na nb l kk i ph qh tx ty tz
    Ha Hb Hl Hn1 Hn2 Hi Ina Inb Inl Htx Hkx Hty Hky Htz Hkz
    (nh & (zx & Hzx & Hnx) & (zy & Hzy & Hny) & (zz & Hzz & Hnz) & Hp & Hq).
  pose proof (model_u M K HM) as Hu.
  pose proof (hm_small M K K1 HM HK1) as Hv.
  pose proof (hm_small_d M K kd HM Hkd1 Hkd2) as Hd.
  destruct (pp_core (K1 * m_u M) (kd * m_u M) (m_eta M) s na nb l kk nh i tx ty tz zx zy zz ph qh
              Hv Hd Ha Hb Hl Hn1 Hn2 Hi
              (hm_vap M K1 _ _ Hu Hin Ina) (hm_vap M K1 _ _ Hu Hin Inb)
              (hm_vap M K1 _ _ Hu Hin Inl)
              (hm_ap M _ K1 _ _ Hu Hadd Htx) Hkx (hm_ap M _ K1 _ _ Hu Hadd Hty) Hky
              (hm_ap M _ K1 _ _ Hu Hadd Htz) Hkz
              (hm_ap M _ K1 _ _ Hu Hmul Hzx) (hm_ap M _ K1 _ _ Hu Hadd Hnx)
              (hm_ap M _ K1 _ _ Hu Hmul Hzy) (hm_ap M _ K1 _ _ Hu Hadd Hny)
              (hm_ap M _ K1 _ _ Hu Hmul Hzz) (hm_ap M _ K1 _ _ Hu Hadd Hnz)
              (hm_fdot M K1 _ _ _ Hu Hadd Hmul Hp) (hm_fdot M K1 _ _ _ Hu Hadd Hmul Hq)) as [P Q].
  split.
  - eapply Rle_trans; [exact P|]. right. ring.
  - eapply Rle_trans; [exact Q|]. right. ring.
Qed.

(** Phong, per-pixel normal N_i = na + i k, k_j = (Nb_j - Na_j) / n with one division:
    |p^ - p_i| <= (14.04 K1 + 2.04 k_div) u, |q^ - q_i| <= (23.06 K1 + 4.06 k_div) u. *)
Theorem phong_pixel_div_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  kcomp_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  kcomp_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  kcomp_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  pixel_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1 + 204 / 100 * k_div M) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1 + 406 / 100 * k_div M) * m_u M.
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l kk i ph qh Ha Hb Hl Hn1 Hn2 Hi
    Ina Inb Inl (tx & Htx & Hkx) (ty & Hty & Hky) (tz & Htz & Hkz) H.
  pose proof HM as (_ & _ & _ & _ & _ & _ & [_ Hdk] & _ & H9).
  assert (k_div M * m_u M <= / 2097152).
  { assert (k_div M * m_u M <= K * m_u M)
      by (apply Rmult_le_compat_r; [left; apply (model_u M K HM) | exact Hdk]). lra. }
  eapply (pixel_model M K K1 (k_div M) HM HK1 Hin Hadd Hmul Hdiv); eassumption.
Qed.

(** The same with k_j = (Nb_j - Na_j) * r, r = 1/n a rounded division. *)
Theorem phong_pixel_recip_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  krecip_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  krecip_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  krecip_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  pixel_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1
      + 204 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1
      + 406 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M.
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv Hkd s na nb l kk i ph qh Ha Hb Hl Hn1 Hn2 Hi
    Ina Inb Inl (tx & rx & Htx & Hrx & Hkx) (ty & ry & Hty & Hry & Hky)
    (tz & rz & Htz & Hrz & Hkz) H.
  pose proof HM as (U1 & U2 & U3 & _ & _ & [Km0 _] & [Kd0 Kd1] & K8 & K9).
  assert (Hu : 0 < m_u M <= / 2097152).
  { split; [exact U1|]. assert (m_u M <= K * m_u M) by (rewrite <- (Rmult_1_l (m_u M)) at 1;
      apply Rmult_le_compat_r; lra). lra. }
  assert (Hdu : k_div M * m_u M <= / 2097152).
  { assert (k_div M * m_u M <= K * m_u M) by (apply Rmult_le_compat_r; lra). lra. }
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  set (kd := (1 + / 1048576) * k_mul M + k_div M + / 68719476736) in *.
  assert (Kx : ap1 (kd * m_u M) (m_eta M) (vx kk) (tx / INR (n s)))
    by (unfold kd; apply (recip_ap1 _ _ (k_div M) (k_mul M) _ _ rx); assumption).
  assert (Ky : ap1 (kd * m_u M) (m_eta M) (vy kk) (ty / INR (n s)))
    by (unfold kd; apply (recip_ap1 _ _ (k_div M) (k_mul M) _ _ ry); assumption).
  assert (Kz : ap1 (kd * m_u M) (m_eta M) (vz kk) (tz / INR (n s)))
    by (unfold kd; apply (recip_ap1 _ _ (k_div M) (k_mul M) _ _ rz); assumption).
  assert (Hk1 : 1 <= kd) by (unfold kd; pose proof (Rmult_le_pos (1 + / 1048576) (k_mul M)); lra).
  exact (pixel_model M K K1 kd HM HK1 Hin Hadd Hmul Hk1 Hkd s na nb l kk i ph qh tx ty tz
           Ha Hb Hl Hn1 Hn2 Hi Ina Inb Inl Htx Kx Hty Ky Htz Kz H).
Qed.

(** ** The lerp N_j = ((1 - t) na_j) + (t nb_j), t = i/n rounded *)

Lemma lp_prod : forall X x Y y ex ey, Rabs (X - x) <= ex -> Rabs (Y - y) <= ey ->
  Rabs (X * Y - x * y) <= ex * Rabs Y + Rabs x * ey.
Proof.
  intros X x Y y ex ey H1 H2.
  replace (X * Y - x * y) with ((X - x) * Y + x * (Y - y)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. rewrite !Rabs_mult.
  apply Rplus_le_compat.
  - apply Rmult_le_compat_r; [apply Rabs_pos | exact H1].
  - apply Rmult_le_compat_l; [apply Rabs_pos | exact H2].
Qed.

Lemma lp_comp : forall v d eta m i a0 b0 ra rb th w y1 y2 nj,
  small_ok v eta -> small_ok d eta -> 1 <= m <= 16777216 -> 0 <= i <= m ->
  Rabs a0 <= 1 -> Rabs b0 <= 1 ->
  ap1 v eta ra a0 -> ap1 v eta rb b0 -> ap1 d eta th (i / m) -> ap1 v eta w (1 - th) ->
  ap1 v eta y1 (w * ra) -> ap1 v eta y2 (th * rb) -> ap1 v eta nj (y1 + y2) ->
  Rabs (1 * nj - (a0 + i / m * (b0 - a0))) <=
    1 * (v * (501 / 100 * (Rabs a0 + Rabs b0) + / 32768)
         + d * (101 / 100 * (Rabs a0 + Rabs b0) + / 32768)).
Proof.
  intros v d eta m i a0 b0 ra rb th w y1 y2 nj Hv Hd Hm Hi Ha0 Hb0 Hra Hrb Hth Hw Hy1 Hy2 Hnj.
  rewrite !Rmult_1_l.
  pose proof (v_pos v eta Hv). pose proof (v_small v eta Hv).
  pose proof (v_pos d eta Hd). pose proof (v_small d eta Hd).
  pose proof (e_pos v eta Hv). pose proof (e_small v eta Hv).
  pose proof (Rabs_pos a0). pose proof (Rabs_pos b0).
  pose proof (hc_t m i ltac:(lra) Hi) as Ht.
  set (t := i / m) in *.
  unfold ap1 in Hth, Hw, Hy1, Hy2, Hnj.
  rewrite (Rabs_pos_eq t) in Hth by lra.
  assert (Dt : d * t <= d) by (pose proof (Rmult_le_compat_l d t 1 ltac:(lra) ltac:(lra)); lra).
  assert (Dt0 : 0 <= d * t) by (apply Rmult_le_pos; lra).
  (* 1 - th *)
  assert (W1 : Rabs (1 - th) <= 1 + (d * t + eta)).
  { replace (1 - th) with ((1 - t) - (th - t)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp, Rabs_pos_eq by lra. lra. }
  assert (W2 : v * Rabs (1 - th) <= v * (1 + (d * t + eta))) by (apply Rmult_le_compat_l; lra).
  assert (W3 : v * (d * t + eta) <= v * / 1048576).
  { apply Rmult_le_compat_l; lra. }
  set (EW := v * (1 + / 1048576) + 2 * eta + d * t).
  assert (HW : Rabs (w - (1 - t)) <= EW).
  { replace (w - (1 - t)) with ((w - (1 - th)) + (t - th)) by ring.
    assert (Rabs (t - th) <= d * t + eta) by (rewrite Rabs_minus_sym; lra).
    eapply Rle_trans; [apply Rabs_triang|]. unfold EW. lra. }
  assert (EW0 : 0 <= EW <= / 524288) by (unfold EW; lra).
  pose proof (in_comp v eta Hv _ _ Hra) as HA.
  pose proof (in_comp v eta Hv _ _ Hrb) as HB.
  set (EA := v * (Rabs a0 + / 1073741824)) in *.
  set (EB := v * (Rabs b0 + / 1073741824)) in *.
  assert (EA0 : 0 <= EA <= / 1048576).
  { unfold EA. split; [apply Rmult_le_pos; lra|].
    assert (v * (Rabs a0 + / 1073741824) <= / 2097152 * (1 + / 1073741824))
      by (apply Rmult_le_compat; lra). lra. }
  assert (EB0 : 0 <= EB <= / 1048576).
  { unfold EB. split; [apply Rmult_le_pos; lra|].
    assert (v * (Rabs b0 + / 1073741824) <= / 2097152 * (1 + / 1073741824))
      by (apply Rmult_le_compat; lra). lra. }
  assert (RA : Rabs ra <= Rabs a0 + EA) by (pose proof (abs_near _ _ _ HA); lra).
  assert (RB : Rabs rb <= Rabs b0 + EB) by (pose proof (abs_near _ _ _ HB); lra).
  (* w ra against (1 - t) a0 *)
  assert (P1 : Rabs (w * ra - (1 - t) * a0) <= EW * (Rabs a0 + EA) + EA).
  { eapply Rle_trans; [apply (lp_prod _ _ _ _ _ _ HW HA)|].
    rewrite (Rabs_pos_eq (1 - t)) by lra.
    assert (EW * Rabs ra <= EW * (Rabs a0 + EA)) by (apply Rmult_le_compat_l; lra).
    assert ((1 - t) * EA <= 1 * EA) by (apply Rmult_le_compat_r; lra). lra. }
  assert (P1b : EW * (Rabs a0 + EA) <= v * (1 + / 1048576) * Rabs a0 + d * Rabs a0
                                        + 2 * eta + / 524288 * EA).
  { assert (EW * EA <= / 524288 * EA) by (apply Rmult_le_compat_r; lra).
    assert (d * t * Rabs a0 <= d * Rabs a0) by (apply Rmult_le_compat_r; lra).
    assert (eta * Rabs a0 <= eta * 1) by (apply Rmult_le_compat_l; lra).
    assert (EW * Rabs a0 <= v * (1 + / 1048576) * Rabs a0 + d * Rabs a0 + 2 * eta)
      by (unfold EW; lra).
    replace (EW * (Rabs a0 + EA)) with (EW * Rabs a0 + EW * EA) by ring. lra. }
  assert (Q1 : Rabs ((1 - t) * a0) <= Rabs a0).
  { rewrite Rabs_mult, (Rabs_pos_eq (1 - t)) by lra.
    assert ((1 - t) * Rabs a0 <= 1 * Rabs a0) by (apply Rmult_le_compat_r; lra). lra. }
  assert (Vsm : v * (1 + / 1048576) * Rabs a0 + d * Rabs a0 <= (2 + / 1048576) / 2097152).
  { assert (v * (1 + / 1048576) * Rabs a0 <= / 2097152 * (1 + / 1048576) * 1)
      by (apply Rmult_le_compat; try lra; apply Rmult_le_pos; lra).
    assert (d * Rabs a0 <= / 2097152 * 1) by (apply Rmult_le_compat; lra). lra. }
  assert (P2 : Rabs (y1 - w * ra) <= v * (Rabs a0 + / 131072) + eta).
  { assert (Rabs (w * ra) <= Rabs a0 + / 131072).
    { replace (w * ra) with ((1 - t) * a0 + (w * ra - (1 - t) * a0)) by ring.
      eapply Rle_trans; [apply Rabs_triang|]. lra. }
    assert (v * Rabs (w * ra) <= v * (Rabs a0 + / 131072)) by (apply Rmult_le_compat_l; lra).
    lra. }
  (* th rb against t b0 *)
  assert (HT : Rabs (th - t) <= d * t + eta) by lra.
  assert (P3 : Rabs (th * rb - t * b0) <= (d * t + eta) * (Rabs b0 + EB) + EB).
  { eapply Rle_trans; [apply (lp_prod _ _ _ _ _ _ HT HB)|].
    rewrite (Rabs_pos_eq t) by lra.
    assert ((d * t + eta) * Rabs rb <= (d * t + eta) * (Rabs b0 + EB))
      by (apply Rmult_le_compat_l; lra).
    assert (t * EB <= 1 * EB) by (apply Rmult_le_compat_r; lra). lra. }
  assert (P3b : (d * t + eta) * (Rabs b0 + EB) <= d * Rabs b0 + eta + / 1048576 * EB).
  { assert ((d * t + eta) * EB <= / 1048576 * EB) by (apply Rmult_le_compat_r; lra).
    assert (d * t * Rabs b0 <= d * Rabs b0) by (apply Rmult_le_compat_r; lra).
    assert (eta * Rabs b0 <= eta * 1) by (apply Rmult_le_compat_l; lra). lra. }
  assert (Q3 : Rabs (t * b0) <= Rabs b0).
  { rewrite Rabs_mult, (Rabs_pos_eq t) by lra.
    assert (t * Rabs b0 <= 1 * Rabs b0) by (apply Rmult_le_compat_r; lra). lra. }
  assert (Dsm : d * Rabs b0 <= / 2097152) by (pose proof (Rmult_le_compat d (/ 2097152) (Rabs b0) 1 ltac:(lra) ltac:(lra) ltac:(lra) ltac:(lra)); lra).
  assert (P4 : Rabs (y2 - th * rb) <= v * (Rabs b0 + / 131072) + eta).
  { assert (Rabs (th * rb) <= Rabs b0 + / 131072).
    { replace (th * rb) with (t * b0 + (th * rb - t * b0)) by ring.
      eapply Rle_trans; [apply Rabs_triang|]. lra. }
    assert (v * Rabs (th * rb) <= v * (Rabs b0 + / 131072)) by (apply Rmult_le_compat_l; lra).
    lra. }
  (* the sum *)
  assert (VA : v * (Rabs a0 + / 131072) <= / 2097152 * 2) by (apply Rmult_le_compat; lra).
  assert (VB : v * (Rabs b0 + / 131072) <= / 2097152 * 2) by (apply Rmult_le_compat; lra).
  assert (P5 : Rabs (y1 + y2) <= Rabs a0 + Rabs b0 + / 131072).
  { replace (y1 + y2) with ((1 - t) * a0 + t * b0 + (y1 - w * ra) + (w * ra - (1 - t) * a0)
                            + (y2 - th * rb) + (th * rb - t * b0)) by ring.
    assert (T : forall a1 a2 a3 a4 a5 a6 : R,
      Rabs (a1 + a2 + a3 + a4 + a5 + a6)
        <= Rabs a1 + Rabs a2 + Rabs a3 + Rabs a4 + Rabs a5 + Rabs a6).
    { intros. repeat (eapply Rle_trans; [apply Rabs_triang | apply Rplus_le_compat_r]); lra. }
    eapply Rle_trans; [apply T|]. lra. }
  assert (P6 : Rabs (nj - (y1 + y2)) <= v * (Rabs a0 + Rabs b0 + / 131072) + eta).
  { assert (v * Rabs (y1 + y2) <= v * (Rabs a0 + Rabs b0 + / 131072))
      by (apply Rmult_le_compat_l; lra). lra. }
  replace (nj - (a0 + t * (b0 - a0)))
    with ((nj - (y1 + y2)) + (y1 - w * ra) + (w * ra - (1 - t) * a0)
          + (y2 - th * rb) + (th * rb - t * b0)) by ring.
  assert (T5 : forall a1 a2 a3 a4 a5 : R,
    Rabs (a1 + a2 + a3 + a4 + a5) <= Rabs a1 + Rabs a2 + Rabs a3 + Rabs a4 + Rabs a5).
  { intros. repeat (eapply Rle_trans; [apply Rabs_triang | apply Rplus_le_compat_r]); lra. }
  eapply Rle_trans; [apply T5|].
  assert (0 <= v * Rabs a0) by (apply Rmult_le_pos; lra).
  assert (0 <= v * Rabs b0) by (apply Rmult_le_pos; lra).
  assert (0 <= d * Rabs a0) by (apply Rmult_le_pos; lra).
  assert (0 <= d * Rabs b0) by (apply Rmult_le_pos; lra).
  unfold EA, EB in *. lra.
Qed.

(** The dot products of a computed normal within the weights wPv, wPd of N_i. *)
Lemma pp_tail : forall (v d eta : R) (s : span) (nh l : vec) (t ph qh : R),
  small_ok v eta -> small_ok d eta ->
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> 0 <= t <= 1 ->
  vap1 v eta l (L s) ->
  vapprox 1 1 nh (nrm s t) (vlin v d (wPv (Na s) (Nb s)) (wPd (Na s) (Nb s))) ->
  fdot_rel v v eta nh l ph -> fdot_rel v v eta nh nh qh ->
  Rabs (ph - dot (nrm s t) (L s)) <= 1404 / 100 * v + 204 / 100 * d /\
  Rabs (qh - dot (nrm s t) (nrm s t)) <= 2306 / 100 * v + 406 / 100 * d.
Proof.
  intros v d eta s nh l t ph qh Hv Hd Ha Hb Hl Ht Inl VN Hp Hq.
  destruct (pp_ni s t Ha Hb Ht) as [NB [NX NN]].
  pose proof (NX _ Hl) as NL. pose proof (NX _ Ha) as NA. pose proof (NX _ Hb) as NBb.
  pose proof (unit_pair _ _ Ha Hl) as AL. pose proof (unit_pair _ _ Hb Hl) as BL.
  destruct (unit_bounded _ Ha) as [A1 [A2 A3]].
  destruct (unit_bounded _ Hb) as [B1 [B2 B3]].
  destruct (unit_bounded _ Hl) as [L1 [L2 L3]].
  destruct NB as [N1 [N2 N3]].
  assert (WB : forall a b : vec, vbounded a 1 -> vbounded b 1 -> wb16 (wPv a b) /\ wb16 (wPd a b)).
  { intros a b [X1 [X2 X3]] [Y1 [Y2 Y3]]. unfold wb16, wPv, wPd; cbn [vx vy vz].
    pose proof (Rabs_pos (vx a)). pose proof (Rabs_pos (vy a)). pose proof (Rabs_pos (vz a)).
    pose proof (Rabs_pos (vx b)). pose proof (Rabs_pos (vy b)). pose proof (Rabs_pos (vz b)).
    repeat split; lra. }
  destruct (WB (Na s) (Nb s) (unit_bounded _ Ha) (unit_bounded _ Hb)) as [Wv Wd].
  assert (W0 : wb16 vzero) by (unfold wb16, vzero; cbn [vx vy vz]; repeat split; lra).
  assert (WL : wb16 (Float.wIn (L s))).
  { unfold wb16, Float.wIn; cbn [vx vy vz].
    pose proof (Rabs_pos (vx (L s))). pose proof (Rabs_pos (vy (L s))).
    pose proof (Rabs_pos (vz (L s))). repeat split; lra. }
  pose proof (Rabs_pos (vx (Na s))). pose proof (Rabs_pos (vy (Na s))).
  pose proof (Rabs_pos (vz (Na s))). pose proof (Rabs_pos (vx (Nb s))).
  pose proof (Rabs_pos (vy (Nb s))). pose proof (Rabs_pos (vz (Nb s))).
  pose proof (Rabs_pos (vx (L s))). pose proof (Rabs_pos (vy (L s))).
  pose proof (Rabs_pos (vz (L s))). pose proof (Rabs_pos (vx (nrm s t))).
  pose proof (Rabs_pos (vy (nrm s t))). pose proof (Rabs_pos (vz (nrm s t))).
  split.
  - pose proof (pp_dot v d eta 1 1 ph 1 (1404 / 100) (204 / 100) nh l (nrm s t) (L s)
      _ _ _ _ Hv Hd Hp ltac:(lra) ltac:(lra) ltac:(lra) VN (K_in_vec v d eta Hv _ _ Inl)
      (vb12 _ (conj N1 (conj N2 N3))) (vb12 _ (unit_bounded _ Hl)) Wv Wd WL W0) as HD.
    rewrite !Rmult_1_l in HD. apply HD; [lra | lra | |].
    + unfold wsum0, wPv, Float.wIn; cbn [vx vy vz].
      assert (Rabs (vx (nrm s t)) + Rabs (vy (nrm s t)) + Rabs (vz (nrm s t)) <= 3) by lra.
      lra.
    + unfold wsum0, wPd, vzero; cbn [vx vy vz]. lra.
  - pose proof (pp_dot v d eta 1 1 qh 1 (2306 / 100) (406 / 100) nh nh (nrm s t) (nrm s t)
      _ _ _ _ Hv Hd Hq ltac:(lra) ltac:(lra) ltac:(lra) VN VN
      (vb12 _ (conj N1 (conj N2 N3))) (vb12 _ (conj N1 (conj N2 N3))) Wv Wd Wv Wd) as HD.
    rewrite !Rmult_1_l in HD. apply HD; [lra | lra | |].
    + unfold wsum0, wPv; cbn [vx vy vz]. lra.
    + unfold wsum0, wPd; cbn [vx vy vz]. lra.
Qed.

Lemma lerp_core : forall (v d eta : R) (s : span) (na nb l nh : vec) (i : nat)
  (th wx wy wz ax ay az bx by_ bz ph qh : R),
  small_ok v eta -> small_ok d eta ->
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap1 v eta na (Na s) -> vap1 v eta nb (Nb s) -> vap1 v eta l (L s) ->
  ap1 d eta th (INR i / INR (n s)) ->
  ap1 v eta wx (1 - th) -> ap1 v eta ax (wx * vx na) -> ap1 v eta bx (th * vx nb) ->
  ap1 v eta (vx nh) (ax + bx) ->
  ap1 v eta wy (1 - th) -> ap1 v eta ay (wy * vy na) -> ap1 v eta by_ (th * vy nb) ->
  ap1 v eta (vy nh) (ay + by_) ->
  ap1 v eta wz (1 - th) -> ap1 v eta az (wz * vz na) -> ap1 v eta bz (th * vz nb) ->
  ap1 v eta (vz nh) (az + bz) ->
  fdot_rel v v eta nh l ph -> fdot_rel v v eta nh nh qh ->
  Rabs (ph - p s (INR i)) <= 1404 / 100 * v + 204 / 100 * d /\
  Rabs (qh - q s (INR i)) <= 2306 / 100 * v + 406 / 100 * d.
Proof.
  intros v d eta s na nb l nh i th wx wy wz ax ay az bx by_ bz ph qh Hv Hd Ha Hb Hl Hn1 Hn2 Hi
    Ina Inb Inl Hth Hwx Hax Hbx Hnx Hwy Hay Hby Hny Hwz Haz Hbz Hnz Hp Hq.
  assert (Hn0 : (n s <> 0)%nat) by lia.
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  assert (Hii : 0 <= INR i <= INR (n s)) by (split; [apply pos_INR | apply le_INR; exact Hi]).
  pose proof (hc_t (INR (n s)) (INR i) ltac:(lra) Hii) as Ht.
  destruct (unit_bounded _ Ha) as [A1 [A2 A3]].
  destruct (unit_bounded _ Hb) as [B1 [B2 B3]].
  destruct Ina as [Ia1 [Ia2 Ia3]]. destruct Inb as [Ib1 [Ib2 Ib3]].
  assert (VN : vapprox 1 1 nh (nrm s (INR i / INR (n s)))
                 (vlin v d (wPv (Na s) (Nb s)) (wPd (Na s) (Nb s)))).
  { unfold vapprox, vlin, wPv, wPd, nrm, vadd, vscale, vsub; cbn [vx vy vz].
    repeat split.
    - exact (lp_comp v d eta _ _ _ _ _ _ _ _ _ _ _ Hv Hd Hm Hii A1 B1 Ia1 Ib1 Hth Hwx Hax Hbx Hnx).
    - exact (lp_comp v d eta _ _ _ _ _ _ _ _ _ _ _ Hv Hd Hm Hii A2 B2 Ia2 Ib2 Hth Hwy Hay Hby Hny).
    - exact (lp_comp v d eta _ _ _ _ _ _ _ _ _ _ _ Hv Hd Hm Hii A3 B3 Ia3 Ib3 Hth Hwz Haz Hbz Hnz). }
  rewrite pp_p_form, pp_q_form by exact Hn0.
  exact (pp_tail v d eta s nh l _ ph qh Hv Hd Ha Hb Hl Ht Inl VN Hp Hq).
Qed.

(** The lerp with the model's operations: t^ within ap1 (kd u) of i/n, then
    w = 1 - t^ (a subtraction), (w na_j) + (t^ nb_j), each product rounded or fused. *)
Definition lcomp_ok (M : fmodel) (th nj naj nbj : R) : Prop :=
  exists w a b, ap_add M w (1 - th) /\ ap_mul M a (w * naj) /\ ap_mul M b (th * nbj)
                /\ ap_add M nj (a + b).

Definition lerp_ok (M : fmodel) (th : R) (na nb l : vec) (ph qh : R) : Prop :=
  exists nh, lcomp_ok M th (vx nh) (vx na) (vx nb) /\ lcomp_ok M th (vy nh) (vy na) (vy nb) /\
    lcomp_ok M th (vz nh) (vz na) (vz nb) /\ fdot_ok M nh l ph /\ fdot_ok M nh nh qh.

Lemma lerp_model : forall (M : fmodel) (K K1 kd : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 ->
  1 <= kd -> kd * m_u M <= / 2097152 ->
  forall (s : span) (na nb l : vec) (i : nat) (th ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  ap1 (kd * m_u M) (m_eta M) th (INR i / INR (n s)) ->
  lerp_ok M th na nb l ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1 + 204 / 100 * kd) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1 + 406 / 100 * kd) * m_u M.
Proof.
  intros M K K1 kd HM HK1 Hin Hadd Hmul Hkd1 Hkd2 s na nb l i th ph qh
    Ha Hb Hl Hn1 Hn2 Hi Ina Inb Inl Hth
    (nh & (wx & ax & bx & Hwx & Hax & Hbx & Hnx) & (wy & ay & by_ & Hwy & Hay & Hby & Hny)
     & (wz & az & bz & Hwz & Haz & Hbz & Hnz) & Hp & Hq).
  pose proof (model_u M K HM) as Hu.
  pose proof (hm_small M K K1 HM HK1) as Hv.
  pose proof (hm_small_d M K kd HM Hkd1 Hkd2) as Hd.
  destruct (lerp_core (K1 * m_u M) (kd * m_u M) (m_eta M) s na nb l nh i
              th wx wy wz ax ay az bx by_ bz ph qh Hv Hd Ha Hb Hl Hn1 Hn2 Hi
              (hm_vap M K1 _ _ Hu Hin Ina) (hm_vap M K1 _ _ Hu Hin Inb)
              (hm_vap M K1 _ _ Hu Hin Inl) Hth
              (hm_ap M _ K1 _ _ Hu Hadd Hwx) (hm_ap M _ K1 _ _ Hu Hmul Hax)
              (hm_ap M _ K1 _ _ Hu Hmul Hbx) (hm_ap M _ K1 _ _ Hu Hadd Hnx)
              (hm_ap M _ K1 _ _ Hu Hadd Hwy) (hm_ap M _ K1 _ _ Hu Hmul Hay)
              (hm_ap M _ K1 _ _ Hu Hmul Hby) (hm_ap M _ K1 _ _ Hu Hadd Hny)
              (hm_ap M _ K1 _ _ Hu Hadd Hwz) (hm_ap M _ K1 _ _ Hu Hmul Haz)
              (hm_ap M _ K1 _ _ Hu Hmul Hbz) (hm_ap M _ K1 _ _ Hu Hadd Hnz)
              (hm_fdot M K1 _ _ _ Hu Hadd Hmul Hp) (hm_fdot M K1 _ _ _ Hu Hadd Hmul Hq)) as [P Q].
  split.
  - eapply Rle_trans; [exact P|]. right. ring.
  - eapply Rle_trans; [exact Q|]. right. ring.
Qed.

(** Phong, lerp N_i = ((1 - t) Na) + (t Nb), t = i/n one rounded division:
    |p^ - p_i| <= (14.04 K1 + 2.04 k_div) u, |q^ - q_i| <= (23.06 K1 + 4.06 k_div) u. *)
Theorem phong_lerp_div_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l : vec) (i : nat) (th ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  ap_div M th (INR i / INR (n s)) ->
  lerp_ok M th na nb l ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1 + 204 / 100 * k_div M) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1 + 406 / 100 * k_div M) * m_u M.
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l i th ph qh Ha Hb Hl Hn1 Hn2 Hi
    Ina Inb Inl Hth H.
  pose proof HM as (_ & _ & _ & _ & _ & _ & [_ Hdk] & _ & H9).
  assert (k_div M * m_u M <= / 2097152).
  { assert (k_div M * m_u M <= K * m_u M)
      by (apply Rmult_le_compat_r; [left; apply (model_u M K HM) | exact Hdk]). lra. }
  eapply (lerp_model M K K1 (k_div M) HM HK1 Hin Hadd Hmul Hdiv); eassumption.
Qed.

(** The same with t = i * r, r = 1/n a rounded division. *)
Theorem phong_lerp_recip_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l : vec) (i : nat) (r th ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  ap_div M r (1 / INR (n s)) -> ap_mul M th (INR i * r) ->
  lerp_ok M th na nb l ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1
      + 204 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1
      + 406 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M.
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv Hkd s na nb l i r th ph qh Ha Hb Hl Hn1 Hn2 Hi
    Ina Inb Inl Hr Hth H.
  pose proof HM as (U1 & U2 & U3 & _ & _ & [Km0 _] & [Kd0 Kd1] & K8 & K9).
  assert (Hu : 0 < m_u M <= / 2097152).
  { split; [exact U1|]. assert (m_u M <= K * m_u M) by (rewrite <- (Rmult_1_l (m_u M)) at 1;
      apply Rmult_le_compat_r; lra). lra. }
  assert (Hdu : k_div M * m_u M <= / 2097152).
  { assert (k_div M * m_u M <= K * m_u M) by (apply Rmult_le_compat_r; lra). lra. }
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  set (kd := (1 + / 1048576) * k_mul M + k_div M + / 68719476736) in *.
  assert (Kt : ap1 (kd * m_u M) (m_eta M) th (INR i / INR (n s)))
    by (unfold kd; apply (recip_ap1 _ _ (k_div M) (k_mul M) _ _ r); assumption).
  assert (Hk1 : 1 <= kd) by (unfold kd; pose proof (Rmult_le_pos (1 + / 1048576) (k_mul M)); lra).
  exact (lerp_model M K K1 kd HM HK1 Hin Hadd Hmul Hk1 Hkd s na nb l i th ph qh
           Ha Hb Hl Hn1 Hn2 Hi Ina Inb Inl Kt H).
Qed.
