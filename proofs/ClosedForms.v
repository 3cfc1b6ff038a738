(** * ClosedForms.v — closed forms in the edge data, the limit of the Euler error,
    the paper's adaptive procedure composed end to end, the crate's clamped
    quantiser, and the crate's mirrored half-span algorithm.

    Hast, Barrera & Bengtsson, "Approximated Phong Shading by using the Euler
    Method". With unit edge normals every quantity of the set-up reduces to
    three numbers: c = Na . Nb, p_a and p_b. This file adds
    - ds, eps and delta in closed form in (c, p_a, p_b, n) (eqs. 11, 15, 24);
    - the limit of eps as n grows, with its exact 1/n rate (eq. 15);
    - the exact condition under which plain Euler lands on p_b (eq. 15);
    - eqs. 23-24 composed: "truncate it and add 1" applied to m = (d_p - t_0)/ds
      yields exactly [delta], and what happens when ds = 0;
    - the crate's clamped 8-bit quantiser (src/quantize.rs) and the three §5
      level claims of Adaptive.v restated for it;
    - a model of src/symmetric_phong.rs (square roots for the left half only,
      mirrored for the right half) proved equal to Phong at every pixel;
    - eq. 14 as a sum of slopes (the arithmetic series behind the closed form).
    Division is Coq's total real division ([/ 0 = 0]), as in Span.v. *)

Require Import Reals Lra Lia Psatz List.
From PhongApprox Require Import Span Duff Euler Symmetry Adaptive.
From Coquelicot Require Rbar Lim_seq.
Open Scope R_scope.

(** ** Helpers: the set-up in terms of c = Na . Nb, p_a, p_b *)

Lemma A_pa_pb : forall s, A s = (pb s - pa s) / INR (n s).
Proof.
  intros s. unfold A, pa, pb, k, dot, vscale, vsub; cbn [vx vy vz].
  unfold Rdiv. ring.
Qed.

Lemma D_unit : forall s, is_unit (Na s) ->
  D s = - 2 * (1 - dot (Na s) (Nb s)) / INR (n s).
Proof.
  intros s Ha. unfold is_unit in Ha.
  unfold D, k, dot, vscale, vsub in *; cbn [vx vy vz] in *.
  unfold Rdiv. rewrite <- Ha. ring.
Qed.

(** For unit vectors 1 - c = |Na - Nb|^2 / 2 >= 0. *)
Lemma one_minus_c_half_dist : forall u v : vec, is_unit u -> is_unit v ->
  1 - dot u v = dot (vsub u v) (vsub u v) / 2.
Proof.
  intros [x1 y1 z1] [x2 y2 z2] Hu Hv. unfold is_unit, dot, vsub in *.
  cbn [vx vy vz] in *. lra.
Qed.

Lemma one_minus_c_nonneg : forall u v : vec, is_unit u -> is_unit v ->
  0 <= 1 - dot u v.
Proof.
  intros u v Hu Hv. rewrite one_minus_c_half_dist by assumption.
  unfold dot. nra.
Qed.

Lemma unit_c_one_iff_eq : forall u v : vec, is_unit u -> is_unit v ->
  (dot u v = 1 <-> u = v).
Proof.
  intros u v Hu Hv. split.
  - intros Hc. pose proof (one_minus_c_half_dist u v Hu Hv) as H.
    destruct u as [x1 y1 z1], v as [x2 y2 z2].
    unfold dot, vsub in H, Hc; cbn [vx vy vz] in H, Hc.
    pose proof (Rle_0_sqr (x1 - x2)). pose proof (Rle_0_sqr (y1 - y2)).
    pose proof (Rle_0_sqr (z1 - z2)).
    assert (x1 = x2 /\ y1 = y2 /\ z1 = z2) as (-> & -> & ->)
      by (repeat split; apply Rminus_diag_uniq, Rsqr_0_uniq; unfold Rsqr in *; lra).
    reflexivity.
  - intros Heq. rewrite <- Heq. exact Hu.
Qed.

Lemma ds_unit : forall s, is_unit (Na s) -> is_unit (Nb s) ->
  ds s = - (1 - dot (Na s) (Nb s)) * (pa s + pb s) / INR (n s) ^ 2.
Proof.
  intros s Ha Hb.
  assert (H : dot (Na s) (Na s) = dot (Nb s) (Nb s)) by (unfold is_unit in *; lra).
  rewrite (eq_11_ds_closed_form s H), (D_unit s Ha).
  split_n s.
  - unfold Rdiv. rewrite Rmult_0_r, Rinv_0. simpl. rewrite Rmult_0_l, Rinv_0. ring.
  - field. exact Hn.
Qed.

Lemma eps_unit : forall s, (0 < n s)%nat -> is_unit (Na s) -> is_unit (Nb s) ->
  eps s = (1 - dot (Na s) (Nb s))
          * ((pa s - pb s) / 2 + (pa s + pb s) / (2 * INR (n s))).
Proof.
  intros s Hn Ha Hb. pose proof (INR_n_neq_0 s Hn) as Hn'.
  unfold eps, corr_eps. rewrite eq_14_euler_closed_form.
  rewrite (ds_unit s Ha Hb). unfold dia, dqa. rewrite A_pa_pb, (D_unit s Ha).
  field. exact Hn'.
Qed.

Lemma eps_is_euler_minus_pb : forall s, eps s = euler_span s (n s) - pb s.
Proof. intros s. reflexivity. Qed.

(** ** Claims: closed forms *)

(* Note: Unit Na, Nb; EVERY n, including n = 0 (both sides are 0 under Coq's x/0 = 0).
   Only |Na| = 1 enters the value of D; |Na| = |Nb| is what eq. 22 needs. *)
(** Paper eqs. 10-11: "ds = (di_b - di_a)/n", with "q_a = q_b = 1" and eq. 22
    (dq_b = -dq_a), is ds = D (p_a + p_b)/(2 n) = -(1 - Na . Nb)(p_a + p_b)/n^2. *)
Theorem eq_11_ds_unit_closed_form : forall s : span,
  is_unit (Na s) -> is_unit (Nb s) ->
  ds s = - (1 - dot (Na s) (Nb s)) * (pa s + pb s) / INR (n s) ^ 2.
Proof. exact ds_unit. Qed.

(* Note: Unit Na, Nb and n >= 1 (for n = 0, eps = p_a - p_b, which is not the formula). *)
(** Paper eq. 15: "eps = p_n - p_b" with eq. 14 "p_n = p_a + n di_a + (n^2 - n)/2 ds":
    eps = (1 - Na . Nb) ((p_a - p_b)/2 + (p_a + p_b)/(2 n)). *)
Theorem eq_15_eps_closed_form : forall s : span,
  (0 < n s)%nat -> is_unit (Na s) -> is_unit (Nb s) ->
  eps s = (1 - dot (Na s) (Nb s))
          * ((pa s - pb s) / 2 + (pa s + pb s) / (2 * INR (n s))).
Proof. exact eps_unit. Qed.

Lemma eps_rate : forall (na nb l : vec) (m : nat),
  is_unit na -> is_unit nb -> (1 <= m)%nat ->
  eps (mkSpan na nb l m) - (1 - dot na nb) * (dot na l - dot nb l) / 2
  = (1 - dot na nb) * (dot na l + dot nb l) / (2 * INR m).
Proof.
  intros na nb l m Ha Hb Hm.
  assert (Hm' : INR m <> 0) by (apply not_0_INR; lia).
  rewrite (eps_unit (mkSpan na nb l m)) by (cbn; assumption || lia).
  unfold pa, pb; cbn [Na Nb L n]. field. exact Hm'.
Qed.

Lemma eps_rate_abs : forall (na nb l : vec) (m : nat),
  is_unit na -> is_unit nb -> (1 <= m)%nat ->
  Rabs (eps (mkSpan na nb l m) - (1 - dot na nb) * (dot na l - dot nb l) / 2)
  = (1 - dot na nb) * Rabs (dot na l + dot nb l) / (2 * INR m).
Proof.
  intros na nb l m Ha Hb Hm. assert (Hm' : 0 < INR m) by (apply lt_0_INR; lia).
  rewrite (eps_rate na nb l m Ha Hb Hm).
  pose proof (one_minus_c_nonneg na nb Ha Hb) as Hc.
  unfold Rdiv. rewrite !Rabs_mult, (Rabs_pos_eq (1 - dot na nb)), (Rabs_pos_eq (/ _))
    by (try apply Rlt_le, Rinv_0_lt_compat; lra).
  reflexivity.
Qed.

Lemma eps_Un_cv : forall na nb l : vec, is_unit na -> is_unit nb ->
  Un_cv (fun m => eps (mkSpan na nb l m))
        ((1 - dot na nb) * (dot na l - dot nb l) / 2).
Proof.
  intros na nb l Ha Hb e He.
  set (K := (1 - dot na nb) * Rabs (dot na l + dot nb l) / 2).
  assert (HK : 0 <= K).
  { unfold K. pose proof (one_minus_c_nonneg na nb Ha Hb).
    pose proof (Rabs_pos (dot na l + dot nb l)). unfold Rdiv.
    apply Rmult_le_pos; [apply Rmult_le_pos|]; lra. }
  destruct (archimed_cor1 (e / (K + 1))) as [N [HN HN0]].
  { apply Rdiv_lt_0_compat; lra. }
  exists N. intros m Hm. unfold R_dist.
  rewrite (eps_rate_abs na nb l m Ha Hb ltac:(lia)).
  assert (HNp : 0 < INR N) by (apply lt_0_INR; lia).
  assert (HmN : INR N <= INR m) by (apply le_INR; lia).
  replace ((1 - dot na nb) * Rabs (dot na l + dot nb l) / (2 * INR m))
    with (K * / INR m) by (unfold K; field; lra).
  assert (Hinv : / INR m <= / INR N) by (apply Rinv_le_contravar; lra).
  assert (HKe : (K + 1) * / INR N < e).
  { apply (Rmult_lt_compat_l (K + 1)) in HN; [| lra].
    replace ((K + 1) * (e / (K + 1))) with e in HN by (field; lra). exact HN. }
  assert (K * / INR m <= (K + 1) * / INR N).
  { apply Rmult_le_compat; [lra | apply Rlt_le, Rinv_0_lt_compat; lra | lra | exact Hinv]. }
  lra.
Qed.

(* Note: Fixed unit Na, Nb and any L; the sequence is indexed by n; the rate equality
   needs n >= 1 (at n = 0, eps = p_a - p_b). The limit is 0 only when Na = Nb or
   p_a = p_b: plain Euler's end error does NOT vanish for long spans. *)
(** Paper eq. 15: "eps = p_n - p_b" -- for fixed edge normals and light, as n grows
    eps tends to (1 - Na . Nb)(p_a - p_b)/2, and
    |eps - (1 - Na . Nb)(p_a - p_b)/2| = (1 - Na . Nb)|p_a + p_b|/(2 n) exactly. *)
Theorem eq_15_eps_limit : forall na nb l : vec,
  is_unit na -> is_unit nb ->
  (forall m : nat, (1 <= m)%nat ->
     eps (mkSpan na nb l m) - (1 - dot na nb) * (dot na l - dot nb l) / 2
     = (1 - dot na nb) * (dot na l + dot nb l) / (2 * INR m)
     /\ Rabs (eps (mkSpan na nb l m) - (1 - dot na nb) * (dot na l - dot nb l) / 2)
        = (1 - dot na nb) * Rabs (dot na l + dot nb l) / (2 * INR m))
  /\ (forall e : R, 0 < e -> exists N : nat, forall m : nat, (N <= m)%nat ->
        Rabs (eps (mkSpan na nb l m) - (1 - dot na nb) * (dot na l - dot nb l) / 2) < e)
  /\ Lim_seq.is_lim_seq (fun m => eps (mkSpan na nb l m))
       (Rbar.Finite ((1 - dot na nb) * (dot na l - dot nb l) / 2)).
Proof.
  intros na nb l Ha Hb. split; [| split].
  - intros m Hm. split; [exact (eps_rate na nb l m Ha Hb Hm) |].
    exact (eps_rate_abs na nb l m Ha Hb Hm).
  - exact (eps_Un_cv na nb l Ha Hb).
  - apply (proj2 (Lim_seq.is_lim_seq_Reals _ _)). exact (eps_Un_cv na nb l Ha Hb).
Qed.

(* Note: Unit Na, Nb and n >= 1. Na . Nb = 1 holds exactly when Na = Nb (second
   conjunct); the other alternative is a single linear condition on p_a, p_b (e.g.
   n = 1: p_a = 0). So for Na <> Nb plain Euler misses p_b on all but a hyperplane of
   lights. *)
(** Paper §3.1 / eq. 15: "we will end up with another value for p_n than p_b":
    p_n = p_b iff Na . Nb = 1 or n (p_a - p_b) + (p_a + p_b) = 0. *)
Theorem eq_15_euler_misses_pb_general : forall s : span,
  (0 < n s)%nat -> is_unit (Na s) -> is_unit (Nb s) ->
  (euler_span s (n s) = pb s
   <-> dot (Na s) (Nb s) = 1 \/ INR (n s) * (pa s - pb s) + (pa s + pb s) = 0)
  /\ (dot (Na s) (Nb s) = 1 <-> Na s = Nb s).
Proof.
  intros s Hn Ha Hb. split; [| exact (unit_c_one_iff_eq _ _ Ha Hb)].
  pose proof (INR_n_neq_0 s Hn) as Hn'.
  assert (He : (1 - dot (Na s) (Nb s)) * (INR (n s) * (pa s - pb s) + (pa s + pb s))
               = 2 * INR (n s) * (euler_span s (n s) - pb s)).
  { rewrite <- eps_is_euler_minus_pb, (eps_unit s Hn Ha Hb). field. exact Hn'. }
  split.
  - intros H. replace (euler_span s (n s) - pb s) with 0 in He by lra. rewrite Rmult_0_r in He.
    apply Rmult_integral in He. destruct He as [H0 | H0]; [left; lra | right; exact H0].
  - intros H. assert (H0 : 2 * INR (n s) * (euler_span s (n s) - pb s) = 0)
      by (rewrite <- He; destruct H as [-> | ->]; ring).
    apply Rmult_integral in H0. destruct H0; lra.
Qed.

Lemma m_step_even : forall r, m_step (2 * r) = r.
Proof. intros r. destruct (m_step_half (2 * r)) as (H1 & H2 & H3). lia. Qed.

Lemma m_step_odd : forall r, m_step (2 * r + 1) = S r.
Proof. intros r. destruct (m_step_half (2 * r + 1)) as (H1 & H2 & H3). lia. Qed.

(* Note: Unit Na, Nb and n >= 1 (for n = 0, delta = 0). Even n: m' = n/2 and
   m'(n - m') = n^2/4; odd n: m' = (n+1)/2 and m'(n - m') = (n^2 - 1)/4. The span
   length hardly enters: |delta| <= (1 - Na . Nb)|p_a + p_b|/8 for every n. *)
(** Paper eq. 24: "delta = n d_p - (n t_0 + (n^2 - n)/2 ds)" at the step m' of eq. 23,
    with unit normals: delta = -(1 - Na . Nb)(p_a + p_b)/8 for even n and
    -(1 - Na . Nb)(p_a + p_b)/8 * (1 - 1/n^2) for odd n. *)
Theorem eq_24_delta_unit_closed_form : forall s : span,
  (0 < n s)%nat -> is_unit (Na s) -> is_unit (Nb s) ->
  (Nat.even (n s) = true ->
     delta s = - (1 - dot (Na s) (Nb s)) * (pa s + pb s) / 8)
  /\ (Nat.even (n s) = false ->
     delta s = - (1 - dot (Na s) (Nb s)) * (pa s + pb s) / 8
               * (1 - 1 / INR (n s) ^ 2)).
Proof.
  intros s Hn Ha Hb.
  pose proof (proj2 (eq_24_delta_closed_form s) Hn) as Hd.
  rewrite (ds_unit s Ha Hb) in Hd.
  destruct (Nat.Even_or_Odd (n s)) as [[r Hr] | [r Hr]].
  - assert (Hev : Nat.even (n s) = true) by (rewrite Hr, Nat.even_mul; reflexivity).
    split; [| intros H; congruence]. intros _.
    rewrite Hd, Hr, m_step_even. rewrite Hr in Hn.
    assert (Hr' : INR r <> 0) by (apply not_0_INR; lia).
    rewrite mult_INR. simpl (INR 2). field. exact Hr'.
  - assert (Hod : Nat.even (n s) = false).
    { rewrite Hr, Nat.even_add, Nat.even_mul. reflexivity. }
    split; [intros H; congruence |]. intros _.
    rewrite Hd, Hr, m_step_odd.
    rewrite plus_INR, mult_INR, (S_INR r). simpl (INR 2). simpl (INR 1).
    assert (0 <= INR r) by apply pos_INR.
    field. lra.
Qed.

(** ** Claim: eqs. 23-24 composed *)

(** The paper's procedure: m = (d_p - t_0)/ds (eq. 23, [m_real]); "truncate it and
    add 1" (Int_part is floor; m >= 0 whenever ds <> 0, where floor = trunc); then
    eq. 24 at that step. *)
Definition paper_step (s : span) : Z := (Int_part (m_real s) + 1)%Z.
Definition paper_delta (s : span) : R :=
  let m := IZR (paper_step s) in m * dp s - (m * t0 s + (m ^ 2 - m) / 2 * ds s).

Lemma paper_step_ds0 : forall s, ds s = 0 -> paper_step s = 1%Z.
Proof.
  intros s Hds. unfold paper_step, m_real. rewrite Hds. unfold Rdiv.
  rewrite Rinv_0, Rmult_0_r, (Int_part_eq 0 0) by (simpl; lra). reflexivity.
Qed.

(* Note: First conjunct: every span with ds <> 0 (no unit normals needed; ds <> 0
   forces n >= 1). Second: ds = 0 with n >= 1, where the paper's m is undefined:
   then delta = 0 and corrected Euler IS Gouraud at every pixel; Coq's x/0 = 0 makes
   m = 0, the step 1, and the procedure still returns delta. Third: for n = 0 (then
   ds = 0) the procedure returns -di_a instead of delta = 0. *)
(** Paper §5, eqs. 23-24: "n = (d_p - t_0)/d_s" ... "we need to truncate it and add 1"
    ... "delta = n d_p - (n t_0 + (n^2 - n)/2 ds)": the procedure computes exactly
    delta = G(m') - CE(m') with m' = (n + 1)/2. *)
Theorem eq_23_24_paper_step_gives_delta : forall s : span,
  (ds s <> 0 ->
     (0 < n s)%nat /\ m_real s = (INR (n s) - 1) / 2
     /\ paper_step s = Z.of_nat (m_step (n s)) /\ paper_delta s = delta s)
  /\ ((0 < n s)%nat -> ds s = 0 ->
     delta s = 0 /\ (forall i : nat, gouraud s i = ceuler s i)
     /\ paper_step s = 1%Z /\ paper_delta s = delta s)
  /\ (n s = 0%nat -> ds s = 0 /\ delta s = 0 /\ paper_delta s = - dia s).
Proof.
  intros s. split; [| split].
  3: { intros Hn0.
       assert (ds s = 0 /\ dp s = 0 /\ t0 s = dia s) as (Hds & Hdp & Ht0)
         by (unfold ds, dp, t0, corr_t0; rewrite Hn0; simpl INR; unfold Rdiv;
             rewrite Rinv_0; repeat split; ring).
       pose proof (paper_step_ds0 s Hds) as Hst.
       split; [exact Hds | split].
       - unfold delta; cbv zeta. rewrite Hn0. change (m_step 0) with 0%nat. change (INR 0) with 0. field.
       - unfold paper_delta; cbv zeta. rewrite Hst, Hdp, Ht0, Hds. simpl IZR. ring. }
  - intros Hds. pose proof (ds_nonzero_n s Hds) as Hn.
    assert (Hm : m_real s = (INR (n s) - 1) / 2)
      by exact (eq_23_m_is_half_n_minus_1 s Hds).
    assert (Hst : paper_step s = Z.of_nat (m_step (n s))).
    { unfold paper_step. rewrite Hm.
      exact (proj1 (eq_23_truncated_step_is_ceil_half (n s) ltac:(lia))). }
    repeat split; try assumption.
    unfold paper_delta, delta. rewrite Hst, <- INR_IZR_INZ. reflexivity.
  - intros Hn Hds.
    assert (HG : forall i, gouraud s i = ceuler s i).
    { intros i. pose proof (eq_24_gouraud_minus_corrected_euler s i Hn) as H.
      rewrite Hds in H. lra. }
    assert (Hd : delta s = 0).
    { rewrite (proj1 (eq_24_delta_closed_form s)). rewrite HG. ring. }
    pose proof (paper_step_ds0 s Hds) as Hst.
    repeat split; try assumption.
    unfold paper_delta. rewrite Hst, Hd, Hds.
    pose proof (HG 1%nat) as H1. unfold gouraud in H1.
    rewrite ceuler_closed_form, Hds in H1. simpl INR in H1. lra.
Qed.

(** ** The crate's clamped quantiser (src/quantize.rs) *)

(** 0 if v <= 0, 255 if v >= 1, else floor(255 v). *)
Definition clamped_level (v : R) : Z :=
  if Rle_dec v 0 then 0%Z else if Rle_dec 1 v then 255%Z else Int_part (255 * v).

Definition clamp01 (v : R) : R := Rmax 0 (Rmin 1 v).

Lemma level_0 : level 0 = 0%Z.
Proof. unfold level. apply Int_part_eq. simpl. lra. Qed.

Lemma level_1 : level 1 = 255%Z.
Proof. unfold level. apply Int_part_eq. simpl. lra. Qed.

Lemma clamp01_id : forall v : R, 0 <= v <= 1 -> clamp01 v = v.
Proof. intros v Hv. unfold clamp01. rewrite Rmin_right, Rmax_right by lra. reflexivity. Qed.

(** Everywhere, the clamped level is the level of the clamped value. *)
Lemma clamped_level_clamp : forall v : R, clamped_level v = level (clamp01 v).
Proof.
  intros v. unfold clamp01, clamped_level.
  destruct (Rle_dec v 0) as [Hv | Hv]; [| destruct (Rle_dec 1 v) as [Hw | Hw]].
  - rewrite Rmin_right, Rmax_left by lra. symmetry. exact level_0.
  - rewrite Rmin_left, Rmax_right by lra. symmetry. exact level_1.
  - rewrite Rmin_right, Rmax_right by lra. reflexivity.
Qed.

(** On [0, 1] the clamped quantiser is the unclamped one (including v = 1). *)
Lemma clamped_level_is_level : forall v : R, 0 <= v <= 1 -> clamped_level v = level v.
Proof. intros v Hv. rewrite clamped_level_clamp, clamp01_id by exact Hv. reflexivity. Qed.

Lemma level_diff_ge_1 : forall g c : R, Rabs (g - c) * 255 >= 1 -> level g <> level c.
Proof. exact (proj1 eq_24_large_delta_implies_different_levels). Qed.

(* Note: The witnesses 1/255 and 1/255 - 1/1000 both lie in (0, 1), where the clamped
   and unclamped quantisers agree (levels 1 and 0). *)
(** Paper §5: "If |delta * 255 * K_d| < 1.0 then [Gouraud and corrected Euler] would
    give the same result" -- refuted also for the crate's quantiser
    floor(255 clamp(v, 0, 1)) (§6: "multiply our intensity value with 255 and then
    truncate it"). *)
Theorem eq_24_delta_test_does_not_imply_same_clamped_levels :
  ~ (forall g c : R, Rabs (g - c) * 255 < 1 -> clamped_level g = clamped_level c)
  /\ exists g c : R, Rabs (g - c) * 255 < 1 /\ clamped_level g <> clamped_level c.
Proof.
  apply delta_test_refuted; rewrite clamped_level_is_level by lra; unfold level;
    apply Int_part_eq; simpl; split; lra.
Qed.

(* Note: Span Na = (0,3/5,4/5), Nb = (0,8/17,15/17), L = (0,0,1), n = 2, K_d = 1
   (adaptive_span of Adaptive.v): G_1 = 143/170 and CE_1 = 48763/57800 lie in (0, 1),
   so clamping changes nothing: levels 214 and 215 although |delta * 255| ~ 0.63 < 1. *)
(** Paper §5: "If |delta * 255 * K_d| < 1.0 then the diffuse intensity could be
    computed just as well with Gouraud" -- refuted on a concrete unit-normal span
    under the crate's clamped quantiser. *)
Theorem eq_24_delta_test_fails_on_concrete_span_clamped :
  let s := adaptive_span in
  is_unit (Na s) /\ is_unit (Nb s) /\ (0 < n s)%nat
  /\ Rabs (delta s * 255 * 1) < 1
  /\ clamped_level (1 * gouraud s 1) = 214%Z /\ clamped_level (1 * ceuler s 1) = 215%Z
  /\ ~ (forall (s' : span) (Kd : R), (0 < n s')%nat ->
          is_unit (Na s') -> is_unit (Nb s') -> 0 < Kd <= 1 ->
          Rabs (delta s' * 255 * Kd) < 1 ->
          forall i : nat, (i <= n s')%nat ->
          clamped_level (Kd * gouraud s' i) = clamped_level (Kd * ceuler s' i)).
Proof.
  cbv zeta.
  destruct adaptive_span_values as [_ [_ [_ [_ [_ [HG [HC _]]]]]]].
  destruct eq_24_delta_test_fails_on_concrete_span
    as [Ha [Hb [Hn [Hd [HlG [HlC _]]]]]].
  (* Both values lie in [0, 1], where the clamped quantiser is the floor. *)
  rewrite <- clamped_level_is_level in HlG by (rewrite HG; lra).
  rewrite <- clamped_level_is_level in HlC by (rewrite HC; lra).
  repeat split; try assumption.
  intros H. specialize (H adaptive_span 1 Hn Ha Hb ltac:(lra) Hd 1%nat).
  rewrite HlG, HlC in H. assert (H' : (214 = 215)%Z) by (apply H; cbn; lia).
  discriminate H'.
Qed.

(* Note: The converse of the delta test survives clamping only with the values in
   [0, 1] (conjuncts 1 and 3); in general exactly when the CLAMPED values are a level
   apart (conjunct 2). It is FALSE without such a premise: g = 2, c = 1 (both 255),
   g = -1, c = 0 (both 0), and even g = -1, c = 1/1000 with only c in [0, 1]. *)
(** Paper §5, true converse of "If |delta * 255 * K_d| < 1.0 then ..." for the
    crate's quantiser: |g - c| * 255 >= 1 with g, c in [0, 1] implies different
    clamped levels; so |delta * 255 * K_d| >= 1 with K_d G(m'), K_d CE(m') in [0, 1]
    implies that they are quantised differently. *)
Theorem eq_24_large_delta_implies_different_clamped_levels :
  (forall g c : R, 0 <= g <= 1 -> 0 <= c <= 1 ->
     Rabs (g - c) * 255 >= 1 -> clamped_level g <> clamped_level c)
  /\ (forall g c : R, Rabs (clamp01 g - clamp01 c) * 255 >= 1 ->
        clamped_level g <> clamped_level c)
  /\ (forall (s : span) (Kd : R),
        0 <= Kd * gouraud s (m_step (n s)) <= 1 ->
        0 <= Kd * ceuler s (m_step (n s)) <= 1 ->
        Rabs (delta s * 255 * Kd) >= 1 ->
        clamped_level (Kd * gouraud s (m_step (n s)))
        <> clamped_level (Kd * ceuler s (m_step (n s))))
  /\ ~ (forall g c : R, Rabs (g - c) * 255 >= 1 -> clamped_level g <> clamped_level c)
  /\ (Rabs (2 - 1) * 255 >= 1 /\ clamped_level 2 = 255%Z /\ clamped_level 1 = 255%Z)
  /\ (Rabs (-1 - 0) * 255 >= 1 /\ clamped_level (-1) = 0%Z /\ clamped_level 0 = 0%Z)
  /\ (Rabs (-1 - 1 / 1000) * 255 >= 1
      /\ clamped_level (-1) = 0%Z /\ clamped_level (1 / 1000) = 0%Z).
Proof.
  assert (Hclamp : forall g c : R, Rabs (clamp01 g - clamp01 c) * 255 >= 1 ->
                   clamped_level g <> clamped_level c).
  { intros g c H. rewrite !clamped_level_clamp. apply level_diff_ge_1. exact H. }
  assert (Hunit : forall g c : R, 0 <= g <= 1 -> 0 <= c <= 1 ->
                  Rabs (g - c) * 255 >= 1 -> clamped_level g <> clamped_level c).
  { intros g c Hg Hc H. apply Hclamp. rewrite !clamp01_id by assumption. exact H. }
  assert (clamped_level 2 = 255%Z /\ clamped_level 1 = 255%Z /\ clamped_level (-1) = 0%Z
          /\ clamped_level 0 = 0%Z) as (L2 & L1 & Lm1 & L0).
  { unfold clamped_level. repeat split; repeat destruct (Rle_dec _ _);
      try reflexivity; exfalso; lra. }
  assert (Lt : clamped_level (1 / 1000) = 0%Z).
  { rewrite clamped_level_is_level by lra. unfold level. apply Int_part_eq.
    simpl. lra. }
  assert (A1 : Rabs (2 - 1) * 255 >= 1) by (rewrite Rabs_pos_eq; lra).
  assert (A2 : Rabs (-1 - 0) * 255 >= 1) by (rewrite Rabs_left; lra).
  assert (A3 : Rabs (-1 - 1 / 1000) * 255 >= 1) by (rewrite Rabs_left; lra).
  split; [exact Hunit |]. split; [exact Hclamp |]. split.
  - intros s Kd HG HC H. rewrite !clamped_level_is_level by assumption.
    exact (proj2 eq_24_large_delta_implies_different_levels s Kd H).
  - split.
    + intros H. apply (H 2 1 A1). rewrite L2, L1. reflexivity.
    + repeat split; assumption.
Qed.

(** ** Claim: the crate's mirrored half-span algorithm (src/symmetric_phong.rs) *)

(** The p-walk: p_0 = B, p_{i+1} = p_i + A. *)
Fixpoint p_walk (a b : R) (i : nat) : R :=
  match i with
  | O => b
  | S j => p_walk a b j + a
  end.

(** [root] of the crate: sqrt q_j for j = 0 .. n/2 from Duff's recurrence. *)
Definition sym_roots (s : span) : list R :=
  map (fun j => sqrt (d_q (duff_span s j))) (seq 0 (S (n s / 2))).

(** The table index read at pixel i: i on the left half, n - i on the right. *)
Definition sym_index (s : span) (i : nat) : nat :=
  if (i <=? n s / 2)%nat then i else (n s - i)%nat.

(** [out] of the crate: out[i] = p_i / root[index i], i = 0 .. n. *)
Definition sym_shade (s : span) : list R :=
  map (fun i => p_walk (A s) (B s) i / nth (sym_index s i) (sym_roots s) 0)
      (seq 0 (S (n s))).

Lemma p_walk_closed : forall a b i, p_walk a b i = a * INR i + b.
Proof.
  intros a b i. induction i as [| i IH].
  - simpl. ring.
  - cbn [p_walk]. rewrite IH, S_INR. ring.
Qed.

Lemma nth_map_seq : forall (g : nat -> R) (len j : nat) (d : R),
  (j < len)%nat -> nth j (map g (seq 0 len)) d = g j.
Proof.
  intros g len j d Hj.
  rewrite (nth_indep _ d (g 0%nat)) by (rewrite map_length, seq_length; exact Hj).
  rewrite map_nth, seq_nth by exact Hj. reflexivity.
Qed.

Lemma sym_index_le_half : forall s i, (i <= n s)%nat -> (sym_index s i <= n s / 2)%nat.
Proof.
  intros s i Hi. unfold sym_index.
  destruct (Nat.leb_spec i (n s / 2)) as [H | H]; [exact H |].
  destruct (m_step_half (n s)) as (_ & Hd & Hr). lia.
Qed.

(* Note: Only |Na| = |Nb| is needed (the crate's Span::new requires unit normals);
   EVERY n including n = 0, and every pixel 0 <= i <= n; the table index is always
   within the n/2 + 1 computed roots. Even n = 2r: pixel r reads its own root and
   pixels r + 1 .. 2r mirror r - 1 .. 0. Odd n = 2r + 1: pixels r + 1 .. 2r + 1 mirror
   r .. 0, the two middle pixels r and r + 1 sharing root r. *)
(** Paper §4: "we only need to compute sqrt q for the first half of the scan line" and
    "we do not have to compute q for the whole scan line since we can reuse these
    values for the second part": the crate's algorithm returns Phong at every pixel. *)
Theorem sec_4_symmetric_phong_algorithm : forall s : span,
  dot (Na s) (Na s) = dot (Nb s) (Nb s) ->
  length (sym_roots s) = S (n s / 2) /\ length (sym_shade s) = S (n s)
  /\ forall i : nat, (i <= n s)%nat ->
       (sym_index s i <= n s / 2)%nat /\ nth i (sym_shade s) 0 = phong s (INR i).
Proof.
  intros s H. unfold sym_roots, sym_shade.
  rewrite !map_length, !seq_length. split; [reflexivity | split; [reflexivity |]].
  intros i Hi. split; [exact (sym_index_le_half s i Hi) |].
  pose proof (sym_index_le_half s i Hi) as Hix.
  rewrite nth_map_seq by lia. unfold sym_roots. rewrite nth_map_seq by lia.
  rewrite p_walk_closed.
  assert (Hq : d_q (duff_span s (sym_index s i)) = d_q (duff_span s i)).
  { unfold sym_index. destruct (i <=? n s / 2)%nat; [reflexivity |].
    exact (sec_4_duff_q_is_symmetric s i H Hi). }
  rewrite Hq. unfold duff_span.
  rewrite (proj1 (proj2 (eq_5_7_duff_recurrence_exact (A s) (B s) (C s) (D s) (E s) i))).
  reflexivity.
Qed.

(** ** Claim: eq. 14 as a sum of slopes *)

(* Note: Generic in p_0, s_0, ds. m = 0: p_0 (first conjunct; sum_f_R0 f 0 = f 0 is
   one term, so the sum form is stated for m >= 1). The slopes summed are Euler's own
   s_j (eq. 13), which equal s_0 + j ds. *)
(** Paper eq. 14 and after: "p_n = p_a + n di_a + (n^2 - n)/2 ds", from
    "(1 + 2 + 3 + ... + (n-1)) ds = (n^2 - n)/2 ds": p_m = p_0 + sum_{j<m} s_j
    = p_0 + sum_{j<m} (s_0 + j ds) = p_0 + m s_0 + (m^2 - m)/2 ds. *)
Theorem eq_14_euler_sum_of_slopes : forall (p0 s0 d : R) (m : nat),
  euler_p p0 s0 d 0 = p0
  /\ ((1 <= m)%nat ->
      euler_p p0 s0 d m = p0 + sum_f_R0 (fun j => euler_s p0 s0 d j) (m - 1)
      /\ euler_p p0 s0 d m = p0 + sum_f_R0 (fun j => s0 + INR j * d) (m - 1)
      /\ p0 + sum_f_R0 (fun j => s0 + INR j * d) (m - 1)
         = p0 + INR m * s0 + (INR m ^ 2 - INR m) / 2 * d).
Proof.
  intros p0 s0 d m. split; [reflexivity |]. intros Hm.
  assert (Hsl : sum_f_R0 (fun j => euler_s p0 s0 d j) (m - 1)
                = sum_f_R0 (fun j => s0 + INR j * d) (m - 1)).
  { apply sum_eq. intros j _. apply eq_13_slope_closed_form. }
  assert (Hser : p0 + sum_f_R0 (fun j => s0 + INR j * d) (m - 1)
                 = p0 + INR m * s0 + (INR m ^ 2 - INR m) / 2 * d).
  { rewrite sum_plus, sum_cte. rewrite (eq_14_arithmetic_series m d Hm).
    rewrite S_INR, minus_INR by exact Hm. simpl (INR 1). ring. }
  assert (Hp : euler_p p0 s0 d m = p0 + sum_f_R0 (fun j => s0 + INR j * d) (m - 1)).
  { rewrite Hser. apply eq_14_euler_closed_form. }
  split; [rewrite Hsl; exact Hp |]. split; [exact Hp | exact Hser].
Qed.
