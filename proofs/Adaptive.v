(** * Adaptive.v — §5 "Adaptive shading", paper eqs. 23-24. *)

Require Import Reals Lra Lia.
From PhongApprox Require Import Span Euler.
Open Scope R_scope.

(** Gouraud along the span: G(i) = p_a + i dp with dp = (p_b - p_a)/n. *)
Definition dp (s : span) : R := (pb s - pa s) / INR (n s).
Definition gouraud (s : span) (i : nat) : R := pa s + INR i * dp s.

(** eq. 23 and the step actually used: m' = trunc(m) + 1 = (n + 1)/2 (nat). *)
Definition m_real (s : span) : R := (dp s - t0 s) / ds s.
Definition m_step (m : nat) : nat := ((m + 1) / 2)%nat.

(** eq. 24: delta = m' dp - (m' t0 + (m'^2 - m')/2 ds). *)
Definition delta (s : span) : R :=
  let m := INR (m_step (n s)) in m * dp s - (m * t0 s + (m ^ 2 - m) / 2 * ds s).

(** 8-bit level of an intensity: floor(255 v) (Int_part is floor on R). *)
Definition level (v : R) : Z := Int_part (255 * v).

(** ** Helpers *)

Lemma Int_part_bounds : forall r, IZR (Int_part r) <= r < IZR (Int_part r) + 1.
Proof. intros r. destruct (base_Int_part r). split; lra. Qed.

Lemma Int_part_eq : forall r z, IZR z <= r < IZR z + 1 -> Int_part r = z.
Proof.
  intros r z [H1 H2]. unfold Int_part.
  rewrite <- (up_tech r z); [lia | exact H1 | rewrite plus_IZR; simpl; lra].
Qed.

Lemma ds_nonzero_n : forall s, ds s <> 0 -> (0 < n s)%nat.
Proof.
  intros s H. destruct (Nat.eq_dec (n s) 0) as [H0 | H0]; [| lia].
  exfalso. apply H. unfold ds. rewrite H0. simpl INR. unfold Rdiv.
  rewrite Rinv_0. ring.
Qed.

(** m' = m/2 + m mod 2 (here and in ClosedForms.v, AdaptiveDelta.v). *)
Lemma m_step_half : forall m,
  (m_step m = m / 2 + m mod 2 /\ m = 2 * (m / 2) + m mod 2 /\ m mod 2 < 2)%nat.
Proof.
  intros m. unfold m_step. pose proof (Nat.div_mod (m + 1) 2 ltac:(lia)).
  pose proof (Nat.div_mod m 2 ltac:(lia)). pose proof (Nat.mod_upper_bound m 2 ltac:(lia)).
  pose proof (Nat.mod_upper_bound (m + 1) 2 ltac:(lia)). lia.
Qed.

Lemma m_step_spec : forall m, (1 <= m)%nat ->
  exists r : nat, (r <= 1)%nat /\ INR m + 1 = 2 * INR (m_step m) + INR r
                  /\ (m_step m <= m)%nat.
Proof.
  intros m Hm. destruct (m_step_half m) as (H1 & H2 & H3).
  exists (1 - m mod 2)%nat. repeat split; [lia | | lia].
  rewrite <- S_INR, <- INR_2, <- mult_INR, <- plus_INR. f_equal. lia.
Qed.

(** The discrete maximisation behind eq. 24: for 0 <= i <= n,
    0 <= i (n - i) <= m' (n - m') with m' = (n+1)/2. *)
Lemma discrete_max : forall m i, (1 <= m)%nat -> (i <= m)%nat ->
  0 <= INR i * (INR m - INR i)
  /\ INR i * (INR m - INR i) <= INR (m_step m) * (INR m - INR (m_step m)).
Proof.
  intros m i Hm Hi. destruct (m_step_spec m Hm) as [r [Hr [Heq Hle]]].
  pose proof (le_INR _ _ Hi) as Hi'. pose proof (pos_INR i) as Hi0.
  split; [nra |].
  assert (Hr' : r = 0%nat \/ r = 1%nat) by lia.
  destruct (le_lt_dec (m_step m) i) as [Hc | Hc].
  - apply le_INR in Hc.
    destruct Hr' as [-> | ->]; simpl INR in Heq; nra.
  - assert (Hc' : (i + 1 <= m_step m)%nat) by lia. apply le_INR in Hc'.
    rewrite plus_INR in Hc'. simpl INR in Hc'.
    destruct Hr' as [-> | ->]; simpl INR in Heq; nra.
Qed.

(** ** Claims *)

(* Note: The stationary point is ALWAYS (n - 1)/2, independent of the span; no unit
   hypothesis; ds <> 0 forces n >= 1 (with Coq's x/0 = 0). *)
(** Paper eq. 23: "n = (d_p - t_0)/d_s", the extreme point of Gouraud minus
    corrected Euler, equals (n - 1)/2. *)
Theorem eq_23_m_is_half_n_minus_1 : forall s : span,
  ds s <> 0 -> (dp s - t0 s) / ds s = (INR (n s) - 1) / 2.
Proof.
  intros s H. pose proof (ds_nonzero_n s H) as Hn.
  pose proof (INR_n_neq_0 s Hn) as Hn'.
  rewrite (t0_closed_form s Hn). unfold dp. field. split; assumption.
Qed.

(* Note: n >= 1; Int_part is floor, = trunc here since (n-1)/2 >= 0. *)
(** Paper §5 after eq. 23: "we need to truncate it and add 1": trunc((n-1)/2) + 1
    = (n + 1)/2 (nat division) = ceil(n/2). *)
Theorem eq_23_truncated_step_is_ceil_half : forall m : nat, (1 <= m)%nat ->
  (Int_part ((INR m - 1) / 2) + 1)%Z = Z.of_nat (m_step m)
  /\ m_step m = (m / 2 + m mod 2)%nat.
Proof.
  intros m Hm. split.
  - destruct (m_step_spec m Hm) as [r [Hr [Heq _]]].
    rewrite (Int_part_eq _ (Z.of_nat (m_step m) - 1)); [lia |].
    rewrite minus_IZR, <- INR_IZR_INZ.
    assert (Hr' : r = 0%nat \/ r = 1%nat) by lia.
    destruct Hr' as [-> | ->]; simpl INR in Heq; split; lra.
  - apply m_step_half.
Qed.

(* Note: Every i; n >= 1. *)
(** Paper §5 (eqs. 23-24): Gouraud minus corrected Euler along the span is
    G(i) - CE_i = ds/2 * i (n - i). *)
Theorem eq_24_gouraud_minus_corrected_euler : forall (s : span) (i : nat),
  (0 < n s)%nat ->
  gouraud s i - ceuler s i = ds s / 2 * INR i * (INR (n s) - INR i).
Proof.
  intros s i Hn. pose proof (INR_n_neq_0 s Hn) as Hn'.
  unfold gouraud. rewrite ceuler_closed_form, (t0_closed_form s Hn). unfold dp.
  field. exact Hn'.
Qed.

(* Note: First part for any n, second for n >= 1. *)
(** Paper eq. 24: "delta = n d_p - (n t_0 + (n^2 - n)/2 ds)" at m' = (n+1)/2 is
    G(m') - CE_{m'} = ds/2 * m' (n - m'). *)
Theorem eq_24_delta_closed_form : forall s : span,
  delta s = gouraud s (m_step (n s)) - ceuler s (m_step (n s))
  /\ ((0 < n s)%nat ->
      delta s = ds s / 2 * INR (m_step (n s)) * (INR (n s) - INR (m_step (n s)))).
Proof.
  intros s.
  assert (H1 : delta s = gouraud s (m_step (n s)) - ceuler s (m_step (n s))).
  { unfold delta, gouraud. rewrite ceuler_closed_form. ring. }
  split; [exact H1 |]. intros Hn. rewrite H1.
  apply eq_24_gouraud_minus_corrected_euler. exact Hn.
Qed.

(* Note: n >= 1; m' = (n+1)/2. *)
(** Paper §5: "The maximum difference between corrected Euler and Gouraud along a scan
    line could be found by" eqs. 23-24: |G(i) - CE_i| <= |delta| for 0 <= i <= n. *)
Theorem eq_24_delta_is_max_difference : forall s : span,
  (0 < n s)%nat ->
  delta s = gouraud s (m_step (n s)) - ceuler s (m_step (n s))
  /\ (forall i : nat, (i <= n s)%nat ->
        Rabs (gouraud s i - ceuler s i) <= Rabs (delta s)).
Proof.
  intros s Hn. destruct (eq_24_delta_closed_form s) as [H1 H2].
  split; [exact H1 |]. intros i Hi.
  destruct (discrete_max (n s) i ltac:(lia) Hi) as [Hpos Hmax].
  rewrite (H2 Hn), (eq_24_gouraud_minus_corrected_euler s i Hn), !Rmult_assoc,
    !(Rabs_mult (ds s / 2)), (Rabs_pos_eq (INR i * _)), (Rabs_pos_eq (INR (m_step _) * _))
    by lra.
  apply Rmult_le_compat_l; [apply Rabs_pos | exact Hmax].
Qed.

(** A quantiser [f] with levels 1 and 0 at 1/255 and 1/255 - 1/1000 refutes the
    delta test (here and in ClosedForms.v). *)
Lemma delta_test_refuted : forall f : R -> Z,
  f (1 / 255) = 1%Z -> f (1 / 255 - 1 / 1000) = 0%Z ->
  ~ (forall g c : R, Rabs (g - c) * 255 < 1 -> f g = f c)
  /\ exists g c : R, Rabs (g - c) * 255 < 1 /\ f g <> f c.
Proof.
  intros f Hg Hc.
  assert (Hd : Rabs (1 / 255 - (1 / 255 - 1 / 1000)) * 255 < 1).
  { rewrite Rabs_pos_eq by lra. lra. }
  split.
  - intros H. specialize (H _ _ Hd). rewrite Hg, Hc in H. discriminate.
  - exists (1 / 255), (1 / 255 - 1 / 1000). split; [exact Hd |].
    rewrite Hg, Hc. discriminate.
Qed.

(* Note: FALSE in general: intensities 1/255 and 1/255 - 1/1000 are closer than 1/255
   but lie on 8-bit levels floor(255 v) = 1 and 0. *)
(** Paper §5: "If |delta * 255 * K_d| < 1.0 then [Gouraud and corrected Euler] would
    give the same result" -- refuted. *)
Theorem eq_24_delta_test_does_not_imply_same_levels :
  ~ (forall g c : R, Rabs (g - c) * 255 < 1 -> level g = level c)
  /\ exists g c : R, Rabs (g - c) * 255 < 1 /\ level g <> level c.
Proof. apply delta_test_refuted; unfold level; apply Int_part_eq; simpl; split; lra. Qed.

(** A concrete span: Na = (0, 3/5, 4/5), Nb = (0, 8/17, 15/17), L = (0,0,1), n = 2. *)
Definition adaptive_span : span :=
  mkSpan (mkV 0 (3/5) (4/5)) (mkV 0 (8/17) (15/17)) (mkV 0 0 1) 2.

Lemma adaptive_span_values :
  let s := adaptive_span in
  pa s = 4/5 /\ pb s = 15/17 /\ dia s = 39/850 /\ ds s = -143/28900
  /\ t0 s = 2523/57800
  /\ gouraud s 1 = 143/170 /\ ceuler s 1 = 48763/57800 /\ delta s = -143/57800.
Proof.
  cbv zeta.
  assert (Hpa : pa adaptive_span = 4/5) by span_val adaptive_span.
  assert (Hpb : pb adaptive_span = 15/17) by span_val adaptive_span.
  assert (Hdia : dia adaptive_span = 39/850) by span_val adaptive_span.
  assert (Hds : ds adaptive_span = -143/28900) by span_val adaptive_span.
  assert (Hn : (0 < n adaptive_span)%nat) by (cbn; lia).
  assert (Ht0 : t0 adaptive_span = 2523/57800).
  { rewrite (t0_closed_form _ Hn), Hpa, Hpb, Hds. cbn [n adaptive_span].
    rewrite INR_2. field. }
  assert (HG : gouraud adaptive_span 1 = 143/170).
  { unfold gouraud, dp. rewrite Hpa, Hpb. cbn [n adaptive_span]. rewrite INR_2.
    simpl INR. field. }
  assert (HC : ceuler adaptive_span 1 = 48763/57800).
  { rewrite ceuler_closed_form, Hpa, Ht0, Hds. simpl INR. field. }
  assert (HD : delta adaptive_span = -143/57800).
  { rewrite (proj1 (eq_24_delta_closed_form _)).
    change (m_step (n adaptive_span)) with 1%nat. rewrite HG, HC. field. }
  repeat split; assumption.
Qed.

(* Note: Span Na = (0,3/5,4/5), Nb = (0,8/17,15/17), L = (0,0,1), n = 2, K_d = 1:
   |delta * 255| = 36465/57800 (about 0.63) < 1, yet at pixel 1 Gouraud = 143/170
   (level 214) and corrected Euler = 48763/57800 (level 215). *)
(** Paper §5: "If |delta * 255 * K_d| < 1.0 then the diffuse intensity could be
    computed just as well with Gouraud" -- refuted on a concrete unit-normal span. *)
Theorem eq_24_delta_test_fails_on_concrete_span :
  let s := adaptive_span in
  is_unit (Na s) /\ is_unit (Nb s) /\ (0 < n s)%nat
  /\ Rabs (delta s * 255 * 1) < 1
  /\ level (1 * gouraud s 1) = 214%Z /\ level (1 * ceuler s 1) = 215%Z
  /\ ~ (forall (s' : span) (Kd : R), (0 < n s')%nat ->
          is_unit (Na s') -> is_unit (Nb s') -> 0 < Kd <= 1 ->
          Rabs (delta s' * 255 * Kd) < 1 ->
          forall i : nat, (i <= n s')%nat ->
          level (Kd * gouraud s' i) = level (Kd * ceuler s' i)).
Proof.
  cbv zeta.
  destruct adaptive_span_values as [_ [_ [_ [_ [_ [HG [HC HD]]]]]]].
  assert (Ha : is_unit (Na adaptive_span)) by span_val adaptive_span.
  assert (Hb : is_unit (Nb adaptive_span)) by span_val adaptive_span.
  assert (Hn : (0 < n adaptive_span)%nat) by (cbn; lia).
  assert (Hd : Rabs (delta adaptive_span * 255 * 1) < 1).
  { rewrite HD. rewrite Rabs_left by lra. lra. }
  assert (HlG : level (1 * gouraud adaptive_span 1) = 214%Z).
  { unfold level. rewrite HG. apply Int_part_eq. split; lra. }
  assert (HlC : level (1 * ceuler adaptive_span 1) = 215%Z).
  { unfold level. rewrite HC. apply Int_part_eq. split; lra. }
  repeat split; try assumption.
  intros H. specialize (H adaptive_span 1 Hn Ha Hb ltac:(lra) Hd 1%nat).
  rewrite HlG, HlC in H. assert (H' : (214 = 215)%Z) by (apply H; cbn; lia).
  discriminate H'.
Qed.

(* Note: No clamping; level v = floor(255 v). *)
(** Paper §5, true converse of the delta test: |g - c| * 255 >= 1 implies different
    8-bit levels; so |delta * 255 * K_d| >= 1 implies K_d G(m'), K_d CE_{m'} differ. *)
Theorem eq_24_large_delta_implies_different_levels :
  (forall g c : R, Rabs (g - c) * 255 >= 1 -> level g <> level c)
  /\ (forall (s : span) (Kd : R), Rabs (delta s * 255 * Kd) >= 1 ->
        level (Kd * gouraud s (m_step (n s))) <> level (Kd * ceuler s (m_step (n s)))).
Proof.
  assert (Hgen : forall g c : R, Rabs (g - c) * 255 >= 1 -> level g <> level c).
  { intros g c H Heq. unfold level in Heq.
    destruct (Int_part_bounds (255 * g)) as [G1 G2].
    destruct (Int_part_bounds (255 * c)) as [C1 C2].
    rewrite Heq in G1, G2.
    unfold Rabs in H. destruct (Rcase_abs (g - c)); lra. }
  split; [exact Hgen |].
  intros s Kd H. apply Hgen.
  rewrite (proj1 (eq_24_delta_closed_form s)) in H.
  replace (Kd * gouraud s (m_step (n s)) - Kd * ceuler s (m_step (n s)))
    with ((gouraud s (m_step (n s)) - ceuler s (m_step (n s))) * Kd) by ring.
  rewrite Rabs_mult. rewrite Rabs_mult, Rabs_mult in H.
  rewrite (Rabs_pos_eq 255) in H by lra. lra.
Qed.
