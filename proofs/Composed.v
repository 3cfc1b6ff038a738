(** * Composed.v — Phong's bound under a profile, composed from the count
    theorems and the value step, as src/tolerance/profile/phong.rs
    [phong_bound] computes it (and src/tolerance/profile/counts.rs
    [duff_bound], [symmetric_phong_bound] for Duff and symmetric Phong).

    [phong_bound] takes, for each of the three forms of p^ and q^ (Horner's
    closed form, the per-pixel normal, the lerp; the division by n done as a
    rounded division or as a rounded reciprocal then a product), the smaller of
    the two count theorems' bounds (PhongCount.v for any unit normals,
    PhongCountD.v with dd >= |Nb - Na|), then the largest over the forms
    (e_p, e_q), then the value step [PhongValue.phong_value_either] with those
    e_p, e_q, and adds normalize-then-dot's term
    ([PhongNormalize.phong_normalize_dot_unit]).  Here:
    - [phong_composed]: whichever of the six form/division combinations
      computed p^, q^ ([phong_form_ok]), any EP, EQ at least the smaller of the
      two theorems' bounds of every combination ([phong_errors_ok]: Rust's
      min per form, then max over forms, is such an EP, EQ) bound
      |p^ - p_i| and |q^ - q_i|, so phong_value_either's bound with ep := EP,
      eq := EQ holds for the computed value p^/s or p^ (1/s).  The value step's
      conditions |p_i| <= sqrt q_i and |p_i| <= 1 are proved here (unit Na,
      Nb, L, i <= n), not assumed.
    - [phong_composed_normalize]: the same for normalize-then-dot, the normal
      computed by the per-pixel or the lerp form ([normal_form_ok]), EP, EQ
      covering those two forms ([pl_errors_ok]); its p is the exact N^.l
      ([PhongNormalize.pixel_ok_exact_dot], [lerp_ok_exact_dot]).
    - [duff_composed], [symmetric_phong_composed]: Duff's walk and symmetric
      Phong ([DuffCount.v]) with EP, EQ covering both ways of /n after SP >= i
      steps of p and SQ steps of q (SQ >= i for Duff, SQ >= min(i, n - i) for
      symmetric Phong), then phong_value_either.
    The count bounds are written with the theorems' own constants:
    [kd_recip M] is the reciprocal forms' kd,
    (1 + 2^-20) k_mul + k_div + 2^-36.  Only [Theorem]s of the other files are
    used. *)

From Coq Require Import Reals Lra Lia.
From PhongApprox Require Import Span FloatModel Float FloatModelK Profiles PhongValue
  PhongCountD PhongCount PhongNormalize DuffCount Symmetry.
Open Scope R_scope.

(** ** The bounds of the count theorems, in units of u *)

(** kd of the reciprocal forms (1/n rounded, then a product). *)
Definition kd_recip (M : fmodel) : R := (1 + / 1048576) * k_mul M + k_div M + / 68719476736.

(** PhongCount.v (any unit normals) and PhongCountD.v (dd >= |Nb - Na|). *)
Definition horner_p (K1 kd : R) : R := 2003 / 100 * K1 + 202 / 100 * kd.
Definition horner_q (K1 kd : R) : R := 7811 / 100 * K1 + 1204 / 100 * kd.
Definition horner_pd (K1 kd dd : R) : R :=
  (804 / 100 + 601 / 100 * dd) * K1 + (3 / 100 + 101 / 100 * dd) * kd.
Definition horner_qd (K1 kd dd : R) : R :=
  (1013 / 100 + 1803 / 100 * dd + 801 / 100 * dd * dd) * K1
  + (7 / 100 + 202 / 100 * dd + 201 / 100 * dd * dd) * kd.

Definition pixel_p (K1 kd : R) : R := 1404 / 100 * K1 + 204 / 100 * kd.
Definition pixel_q (K1 kd : R) : R := 2306 / 100 * K1 + 406 / 100 * kd.
Definition pixel_pd (K1 kd dd : R) : R :=
  (602 / 100 + 201 / 100 * dd) * K1 + (2 / 100 + 101 / 100 * dd) * kd.
Definition pixel_qd (K1 kd dd : R) : R :=
  (702 / 100 + 401 / 100 * dd + 0 * dd * dd) * K1
  + (2 / 100 + 201 / 100 * dd + 0 * dd * dd) * kd.

Definition lerp_p (K1 kd : R) : R := 1404 / 100 * K1 + 204 / 100 * kd.
Definition lerp_q (K1 kd : R) : R := 2306 / 100 * K1 + 406 / 100 * kd.
Definition lerp_pd (K1 kd dd : R) : R :=
  (802 / 100 + 0 * dd) * K1 + (2 / 100 + 101 / 100 * dd) * kd.
Definition lerp_qd (K1 kd dd : R) : R :=
  (1102 / 100 + 0 * dd + 0 * dd * dd) * K1
  + (2 / 100 + 201 / 100 * dd + 0 * dd * dd) * kd.

(** EP, EQ are at least the smaller of the two theorems' bounds of the form,
    for both ways of /n (kd = k_div or kd_recip). *)
Definition horner_errors_ok (M : fmodel) (K1 dd EP EQ : R) : Prop :=
  forall kd, kd = k_div M \/ kd = kd_recip M ->
    Rmin (horner_p K1 kd) (horner_pd K1 kd dd) * m_u M <= EP /\
    Rmin (horner_q K1 kd) (horner_qd K1 kd dd) * m_u M <= EQ.

Definition pixel_errors_ok (M : fmodel) (K1 dd EP EQ : R) : Prop :=
  forall kd, kd = k_div M \/ kd = kd_recip M ->
    Rmin (pixel_p K1 kd) (pixel_pd K1 kd dd) * m_u M <= EP /\
    Rmin (pixel_q K1 kd) (pixel_qd K1 kd dd) * m_u M <= EQ.

Definition lerp_errors_ok (M : fmodel) (K1 dd EP EQ : R) : Prop :=
  forall kd, kd = k_div M \/ kd = kd_recip M ->
    Rmin (lerp_p K1 kd) (lerp_pd K1 kd dd) * m_u M <= EP /\
    Rmin (lerp_q K1 kd) (lerp_qd K1 kd dd) * m_u M <= EQ.

(** The per-pixel and lerp forms (those normalize-then-dot is applied to). *)
Definition pl_errors_ok (M : fmodel) (K1 dd EP EQ : R) : Prop :=
  pixel_errors_ok M K1 dd EP EQ /\ lerp_errors_ok M K1 dd EP EQ.

(** All three forms: EP, EQ at least the largest over the forms of the smaller
    of the two theorems (Rust's [PhongCounts::errors], then the max). *)
Definition phong_errors_ok (M : fmodel) (K1 dd EP EQ : R) : Prop :=
  horner_errors_ok M K1 dd EP EQ /\ pl_errors_ok M K1 dd EP EQ.

(** ** The six ways of computing p^ and q^ (the count theorems' hypotheses) *)

(** k = (Nb - Na)/n component by component: a rounded division, or 1/n then a product. *)
Definition kdiv3_ok (M : fmodel) (s : span) (kk na nb : vec) : Prop :=
  kcomp_ok M (INR (n s)) (vx kk) (vx na) (vx nb) /\
  kcomp_ok M (INR (n s)) (vy kk) (vy na) (vy nb) /\
  kcomp_ok M (INR (n s)) (vz kk) (vz na) (vz nb).

Definition krecip3_ok (M : fmodel) (s : span) (kk na nb : vec) : Prop :=
  krecip_ok M (INR (n s)) (vx kk) (vx na) (vx nb) /\
  krecip_ok M (INR (n s)) (vy kk) (vy na) (vy nb) /\
  krecip_ok M (INR (n s)) (vz kk) (vz na) (vz nb).

Definition phong_form_ok (M : fmodel) (s : span) (na nb l : vec) (i : nat) (ph qh : R)
  : Prop :=
  (exists kk, kdiv3_ok M s kk na nb /\ horner_ok M i na l kk ph qh) \/
  (exists kk, krecip3_ok M s kk na nb /\ horner_ok M i na l kk ph qh) \/
  (exists kk, kdiv3_ok M s kk na nb /\ pixel_ok M i na l kk ph qh) \/
  (exists kk, krecip3_ok M s kk na nb /\ pixel_ok M i na l kk ph qh) \/
  (exists th, ap_div M th (INR i / INR (n s)) /\ lerp_ok M th na nb l ph qh) \/
  (exists r th, ap_div M r (1 / INR (n s)) /\ ap_mul M th (INR i * r) /\
                lerp_ok M th na nb l ph qh).

(** The computed normal nh at the pixel i: per-pixel (na + i k) or lerp, either
    way of /n. *)
Definition ncomp3_ok (M : fmodel) (i : nat) (nh na kk : vec) : Prop :=
  ncomp_ok M i (vx nh) (vx na) (vx kk) /\ ncomp_ok M i (vy nh) (vy na) (vy kk) /\
  ncomp_ok M i (vz nh) (vz na) (vz kk).

Definition lcomp3_ok (M : fmodel) (th : R) (nh na nb : vec) : Prop :=
  lcomp_ok M th (vx nh) (vx na) (vx nb) /\ lcomp_ok M th (vy nh) (vy na) (vy nb) /\
  lcomp_ok M th (vz nh) (vz na) (vz nb).

Definition normal_form_ok (M : fmodel) (s : span) (na nb : vec) (i : nat) (nh : vec)
  : Prop :=
  (exists kk, kdiv3_ok M s kk na nb /\ ncomp3_ok M i nh na kk) \/
  (exists kk, krecip3_ok M s kk na nb /\ ncomp3_ok M i nh na kk) \/
  (exists th, ap_div M th (INR i / INR (n s)) /\ lcomp3_ok M th nh na nb) \/
  (exists r th, ap_div M r (1 / INR (n s)) /\ ap_mul M th (INR i * r) /\
                lcomp3_ok M th nh na nb).

(** ** Helpers *)

(** The smaller of two valid bounds is a valid bound. *)
Lemma cz_min : forall x a b u e, 0 <= u -> x <= a * u -> x <= b * u -> Rmin a b * u <= e ->
  x <= e.
Proof.
  intros x a b u e Hu Ha Hb H. unfold Rmin in H. destruct (Rle_dec a b); lra.
Qed.

Lemma cz_cs : forall a b : vec, dot a b * dot a b <= dot a a * dot b b.
Proof.
  intros a b. unfold dot.
  pose proof (Rle_0_sqr (vx a * vy b - vy a * vx b)).
  pose proof (Rle_0_sqr (vx a * vz b - vz a * vx b)).
  pose proof (Rle_0_sqr (vy a * vz b - vz a * vy b)). unfold Rsqr in *. nra.
Qed.

(** q_i <= 1 at a pixel i <= n of a span with unit Na, Nb. *)
Lemma cz_q_le_1 : forall (s : span) (i : nat), is_unit (Na s) -> is_unit (Nb s) ->
  (1 <= n s)%nat -> (i <= n s)%nat -> q s (INR i) <= 1.
Proof.
  intros s i Ha Hb Hn Hi.
  assert (Hn0 : 0 < INR (n s)) by (apply lt_0_INR; lia).
  assert (Hin : INR i <= INR (n s)) by (apply le_INR; lia).
  pose proof (pos_INR i) as Hi0.
  set (t := INR i / INR (n s)).
  assert (Ht : 0 <= t <= 1).
  { unfold t, Rdiv. split.
    - apply Rmult_le_pos; [lra | left; apply Rinv_0_lt_compat; lra].
    - apply (Rmult_le_reg_r (INR (n s))); [lra|].
      rewrite Rmult_assoc, Rinv_l by lra. lra. }
  assert (E1 : q s (INR i) = dot (Na s) (Na s)
            + 2 * t * (dot (Na s) (Nb s) - dot (Na s) (Na s))
            + t * t * (dot (Nb s) (Nb s) - 2 * dot (Na s) (Nb s) + dot (Na s) (Na s))).
  { unfold t, q, C, D, E, k, dot, vscale, vsub; cbn [vx vy vz]. field. lra. }
  assert (E2 : dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))
             = dot (Nb s) (Nb s) - 2 * dot (Na s) (Nb s) + dot (Na s) (Na s)).
  { unfold dot, vsub; cbn [vx vy vz]. ring. }
  assert (E3 : 0 <= dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))).
  { unfold dot. pose proof (Rle_0_sqr (vx (vsub (Nb s) (Na s)))).
    pose proof (Rle_0_sqr (vy (vsub (Nb s) (Na s)))).
    pose proof (Rle_0_sqr (vz (vsub (Nb s) (Na s)))). unfold Rsqr in *. lra. }
  unfold is_unit in Ha, Hb. rewrite Ha, Hb in E1, E2.
  assert (0 <= t * (1 - t)) by nra.
  assert (0 <= t * (1 - t) * (1 - dot (Na s) (Nb s))) by (apply Rmult_le_pos; lra).
  nra.
Qed.

(** |p_i| <= sqrt q_i and |p_i| <= 1 for unit Na, Nb, L and i <= n. *)
Lemma cz_p_bounds : forall (s : span) (i : nat), is_unit (Na s) -> is_unit (Nb s) ->
  is_unit (L s) -> (1 <= n s)%nat -> (i <= n s)%nat ->
  Rabs (p s (INR i)) <= sqrt (q s (INR i)) /\ Rabs (p s (INR i)) <= 1 /\
  q s (INR i) <= 1.
Proof.
  intros s i Ha Hb HL Hn Hi.
  pose proof (cz_q_le_1 s i Ha Hb Hn Hi) as Hq1.
  assert (H1 : Rabs (p s (INR i)) <= sqrt (q s (INR i))).
  { unfold p, q. rewrite <- eq_2_p_is_linear, <- eq_3_q_is_quadratic.
    rewrite <- sqrt_Rsqr_abs. apply sqrt_le_1_alt. unfold Rsqr.
    pose proof (cz_cs (N s (INR i)) (L s)) as H. unfold is_unit in HL. rewrite HL in H. lra. }
  assert (H2 : sqrt (q s (INR i)) <= 1).
  { rewrite <- sqrt_1. apply sqrt_le_1_alt. exact Hq1. }
  repeat split; lra.
Qed.

(** ** Each form's counts under EP, EQ *)

Section Counts.
Context (M : fmodel) (K K1 dd EP EQ : R) (s : span) (na nb l : vec) (i : nat).
Context (HM : model_ok M K) (HK1 : 1 <= K1 <= K) (Hin : k_in M <= K1)
  (Hadd : k_add M <= K1) (Hmul : k_mul M <= K1) (Hdiv : 1 <= k_div M)
  (Hrec : kd_recip M * m_u M <= / 2097152)
  (Ha : is_unit (Na s)) (Hb : is_unit (Nb s)) (HL : is_unit (L s))
  (Hdd : 0 <= dd <= 2) (Hdist : dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd)
  (Hn1 : (1 <= n s)%nat) (Hn : INR (n s) <= 16777216) (Hi : (i <= n s)%nat)
  (Hva : vap M na (Na s)) (Hvb : vap M nb (Nb s)) (Hvl : vap M l (L s)).

Lemma cz_u : 0 <= m_u M.
Proof. destruct HM as (Hu & _). lra. Qed.

Lemma cz_horner : forall ph qh, horner_errors_ok M K1 dd EP EQ ->
  ((exists kk, kdiv3_ok M s kk na nb /\ horner_ok M i na l kk ph qh) \/
   (exists kk, krecip3_ok M s kk na nb /\ horner_ok M i na l kk ph qh)) ->
  Rabs (ph - p s (INR i)) <= EP /\ Rabs (qh - q s (INR i)) <= EQ.
Proof.
  pose proof cz_u as Hu.
  intros ph qh He [(kk & (Hx & Hy & Hz) & Hh) | (kk & (Hx & Hy & Hz) & Hh)].
  - destruct (He (k_div M) (or_introl eq_refl)) as [HEp HEq].
    destruct (phong_horner_div_generic M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l kk i ph qh
      Ha Hb HL Hn1 Hn Hi Hva Hvb Hvl Hx Hy Hz Hh) as [P1 Q1].
    destruct (phong_horner_div_dist M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l kk i ph qh dd
      Ha Hb HL Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl Hx Hy Hz Hh) as [P2 Q2].
    split; [exact (cz_min _ _ _ _ _ Hu P1 P2 HEp) | exact (cz_min _ _ _ _ _ Hu Q1 Q2 HEq)].
  - destruct (He (kd_recip M) (or_intror eq_refl)) as [HEp HEq].
    destruct (phong_horner_recip_generic M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l kk i
      ph qh Ha Hb HL Hn1 Hn Hi Hva Hvb Hvl Hx Hy Hz Hh) as [P1 Q1].
    destruct (phong_horner_recip_dist M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l kk i
      ph qh dd Ha Hb HL Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl Hx Hy Hz Hh) as [P2 Q2].
    split; [exact (cz_min _ _ _ _ _ Hu P1 P2 HEp) | exact (cz_min _ _ _ _ _ Hu Q1 Q2 HEq)].
Qed.

Lemma cz_pixel : forall ph qh, pixel_errors_ok M K1 dd EP EQ ->
  ((exists kk, kdiv3_ok M s kk na nb /\ pixel_ok M i na l kk ph qh) \/
   (exists kk, krecip3_ok M s kk na nb /\ pixel_ok M i na l kk ph qh)) ->
  Rabs (ph - p s (INR i)) <= EP /\ Rabs (qh - q s (INR i)) <= EQ.
Proof.
  pose proof cz_u as Hu.
  intros ph qh He [(kk & (Hx & Hy & Hz) & Hh) | (kk & (Hx & Hy & Hz) & Hh)].
  - destruct (He (k_div M) (or_introl eq_refl)) as [HEp HEq].
    destruct (phong_pixel_div_generic M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l kk i ph qh
      Ha Hb HL Hn1 Hn Hi Hva Hvb Hvl Hx Hy Hz Hh) as [P1 Q1].
    destruct (phong_pixel_div_dist M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l kk i ph qh dd
      Ha Hb HL Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl Hx Hy Hz Hh) as [P2 Q2].
    split; [exact (cz_min _ _ _ _ _ Hu P1 P2 HEp) | exact (cz_min _ _ _ _ _ Hu Q1 Q2 HEq)].
  - destruct (He (kd_recip M) (or_intror eq_refl)) as [HEp HEq].
    destruct (phong_pixel_recip_generic M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l kk i
      ph qh Ha Hb HL Hn1 Hn Hi Hva Hvb Hvl Hx Hy Hz Hh) as [P1 Q1].
    destruct (phong_pixel_recip_dist M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l kk i
      ph qh dd Ha Hb HL Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl Hx Hy Hz Hh) as [P2 Q2].
    split; [exact (cz_min _ _ _ _ _ Hu P1 P2 HEp) | exact (cz_min _ _ _ _ _ Hu Q1 Q2 HEq)].
Qed.

Lemma cz_lerp : forall ph qh, lerp_errors_ok M K1 dd EP EQ ->
  ((exists th, ap_div M th (INR i / INR (n s)) /\ lerp_ok M th na nb l ph qh) \/
   (exists r th, ap_div M r (1 / INR (n s)) /\ ap_mul M th (INR i * r) /\
                 lerp_ok M th na nb l ph qh)) ->
  Rabs (ph - p s (INR i)) <= EP /\ Rabs (qh - q s (INR i)) <= EQ.
Proof.
  pose proof cz_u as Hu.
  intros ph qh He [(th & Ht & Hh) | (r & th & Hr & Ht & Hh)].
  - destruct (He (k_div M) (or_introl eq_refl)) as [HEp HEq].
    destruct (phong_lerp_div_generic M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l i th ph qh
      Ha Hb HL Hn1 Hn Hi Hva Hvb Hvl Ht Hh) as [P1 Q1].
    destruct (phong_lerp_div_dist M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l i th ph qh dd
      Ha Hb HL Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl Ht Hh) as [P2 Q2].
    split; [exact (cz_min _ _ _ _ _ Hu P1 P2 HEp) | exact (cz_min _ _ _ _ _ Hu Q1 Q2 HEq)].
  - destruct (He (kd_recip M) (or_intror eq_refl)) as [HEp HEq].
    destruct (phong_lerp_recip_generic M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l i r th
      ph qh Ha Hb HL Hn1 Hn Hi Hva Hvb Hvl Hr Ht Hh) as [P1 Q1].
    destruct (phong_lerp_recip_dist M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l i r th
      ph qh dd Ha Hb HL Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl Hr Ht Hh) as [P2 Q2].
    split; [exact (cz_min _ _ _ _ _ Hu P1 P2 HEp) | exact (cz_min _ _ _ _ _ Hu Q1 Q2 HEq)].
Qed.

(** Whichever of the six combinations computed p^, q^. *)
Lemma cz_form : forall ph qh, phong_errors_ok M K1 dd EP EQ ->
  phong_form_ok M s na nb l i ph qh ->
  Rabs (ph - p s (INR i)) <= EP /\ Rabs (qh - q s (INR i)) <= EQ.
Proof.
  intros ph qh (Hh & Hp & Hl) [H | [H | [H | [H | [H | H]]]]].
  - apply cz_horner; [exact Hh | left; exact H].
  - apply cz_horner; [exact Hh | right; exact H].
  - apply cz_pixel; [exact Hp | left; exact H].
  - apply cz_pixel; [exact Hp | right; exact H].
  - apply cz_lerp; [exact Hl | left; exact H].
  - apply cz_lerp; [exact Hl | right; exact H].
Qed.

(** The exact N^.l of the per-pixel or lerp normal, and q^ = N^.N^. *)
Lemma cz_normal : forall nh qh, pl_errors_ok M K1 dd EP EQ ->
  normal_form_ok M s na nb i nh -> fdot_ok M nh nh qh ->
  Rabs (dot nh l - p s (INR i)) <= EP /\ Rabs (qh - q s (INR i)) <= EQ.
Proof.
  intros nh qh (Hp & Hl) [(kk & Hk & Hx & Hy & Hz) | [(kk & Hk & Hx & Hy & Hz)
    | [(th & Ht & Hx & Hy & Hz) | (r & th & Hr & Ht & Hx & Hy & Hz)]]] Hq.
  - apply cz_pixel; [exact Hp | left; exists kk; split; [exact Hk|]].
    exact (pixel_ok_exact_dot M K i na l kk nh qh HM Hx Hy Hz Hq).
  - apply cz_pixel; [exact Hp | right; exists kk; split; [exact Hk|]].
    exact (pixel_ok_exact_dot M K i na l kk nh qh HM Hx Hy Hz Hq).
  - apply cz_lerp; [exact Hl | left; exists th; split; [exact Ht|]].
    exact (lerp_ok_exact_dot M K th na nb l nh qh HM Hx Hy Hz Hq).
  - apply cz_lerp; [exact Hl | right; exists r, th; split; [exact Hr|split; [exact Ht|]]].
    exact (lerp_ok_exact_dot M K th na nb l nh qh HM Hx Hy Hz Hq).
Qed.

End Counts.

(** ** Phong: the counts' min per form, max over forms, then the value step *)

Theorem phong_composed : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  kd_recip M * m_u M <= / 2097152 ->
  forall (s : span) (na nb l : vec) (i : nat) (ph qh dd EP EQ qmin ks kv km sh vh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  0 <= dd <= 2 -> dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  phong_form_ok M s na nb l i ph qh ->
  phong_errors_ok M K1 dd EP EQ ->
  0 < qmin -> qmin <= q s (INR i) -> 2 * EQ <= qmin ->
  0 <= ks -> 0 <= kv -> 0 <= km ->
  (ks + kv + km) * m_u M <= / 1024 -> 1024 * m_eta M <= sqrt (qmin - EQ) ->
  ap1 (ks * m_u M) (m_eta M) sh (sqrt qh) ->
  (ap1 (kv * m_u M) (m_eta M) vh (ph / sh) \/
   exists r, ap1 (kv * m_u M) (m_eta M) r (1 / sh) /\ ap1 (km * m_u M) (m_eta M) vh (ph * r)) ->
  Rabs (vh - p s (INR i) / sqrt (q s (INR i))) <=
    (EP / sqrt (qmin - EQ) + EQ / (sqrt (qmin - EQ) * (sqrt qmin + sqrt (qmin - EQ))))
      * (1 + (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M))
    + (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M)
    + (2 * (1 + (EP / sqrt (qmin - EQ) + EQ / (sqrt (qmin - EQ) * (sqrt qmin + sqrt (qmin - EQ)))))
         * (m_eta M / sqrt (qmin - EQ))
       + ((1 + EP) * m_eta M * (1 + km * m_u M) + m_eta M)).
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l i ph qh dd EP EQ qmin ks kv km sh vh
    Ha Hb HL Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl Hf He Hqm Hq H2 Hks Hkv Hkm Hw He2 Hs Hv.
  destruct (cz_form M K K1 dd EP EQ s na nb l i HM HK1 Hin Hadd Hmul Hdiv Hrec Ha Hb HL
    Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl ph qh He Hf) as [HEp HEq].
  destruct (cz_p_bounds s i Ha Hb HL Hn1 Hi) as (Hp & Hp1 & _).
  pose proof HM as (Hu & Het & _).
  pose proof (Rabs_pos (ph - p s (INR i))). pose proof (Rabs_pos (qh - q s (INR i))).
  apply (phong_value_either (m_u M) (m_eta M) ks kv km (p s (INR i)) (q s (INR i)) ph qh qmin
    EP EQ sh vh); try assumption; lra.
Qed.

(** ** Normalize-then-dot: the per-pixel or lerp normal, then phong_normalize_dot_unit *)

Theorem phong_composed_normalize : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  kd_recip M * m_u M <= / 2097152 ->
  forall (s : span) (na nb l nh w : vec) (i : nat) (qh dd EP EQ qmin ks kv km sh r vh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  0 <= dd <= 2 -> dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  normal_form_ok M s na nb i nh -> fdot_ok M nh nh qh ->
  pl_errors_ok M K1 dd EP EQ ->
  0 < qmin -> qmin <= q s (INR i) -> 2 * EQ <= qmin ->
  0 <= ks -> 0 <= kv -> 0 <= km ->
  (ks + kv + km) * m_u M <= / 1024 -> 1024 * m_eta M <= qmin - EQ ->
  ap1 (ks * m_u M) (m_eta M) sh (sqrt qh) ->
  ap1 (kv * m_u M) (m_eta M) r (1 / sh) ->
  ap1 (km * m_u M) (m_eta M) (vx w) (vx nh * r) ->
  ap1 (km * m_u M) (m_eta M) (vy w) (vy nh * r) ->
  ap1 (km * m_u M) (m_eta M) (vz w) (vz nh * r) ->
  fdot_ok M w l vh ->
  Rabs (vh - p s (INR i) / sqrt (q s (INR i))) <=
    (EP / sqrt (qmin - EQ) + EQ / (sqrt (qmin - EQ) * (sqrt qmin + sqrt (qmin - EQ))))
      * (1 + (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M))
    + (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M)
    + (2 * (1 + (EP / sqrt (qmin - EQ) + EQ / (sqrt (qmin - EQ) * (sqrt qmin + sqrt (qmin - EQ)))))
         * (m_eta M / sqrt (qmin - EQ))
       + ((1 + EP) * m_eta M * (1 + km * m_u M) + m_eta M))
    + (103 / 100 * (1 + k_in M * m_u M + 2 * m_eta M)
         * (km * m_u M + k_mul M * m_u M + 2 * (k_add M * m_u M))
       + 2 * (1 + k_in M * m_u M + 2 * m_eta M) * m_eta M + 8 * m_eta M).
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l nh w i qh dd EP EQ qmin ks kv km sh
    r vh Ha Hb HL Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl Hf Hqh He Hqm Hq H2 Hks Hkv Hkm Hw He2
    Hs Hr Hx Hy Hz Hv.
  destruct (cz_normal M K K1 dd EP EQ s na nb l i HM HK1 Hin Hadd Hmul Hdiv Hrec Ha Hb HL
    Hdd Hdist Hn1 Hn Hi Hva Hvb Hvl nh qh He Hf Hqh) as [HEp HEq].
  destruct (cz_p_bounds s i Ha Hb HL Hn1 Hi) as (Hp & Hp1 & Hq1).
  pose proof HM as (Hu & Het & _ & Hki & Hka & Hkm' & _ & _ & HK).
  pose proof (Rabs_pos (dot nh l - p s (INR i))). pose proof (Rabs_pos (qh - q s (INR i))).
  assert (Hum : 0 <= k_mul M * m_u M <= / 2097152) by (split; nra).
  assert (Hua : 0 <= k_add M * m_u M <= / 2097152) by (split; nra).
  apply (phong_normalize_dot_unit (m_u M) (m_eta M) ks kv km (k_in M) (k_mul M * m_u M)
    (k_add M * m_u M) (p s (INR i)) (q s (INR i)) qmin EP EQ nh l (L s) w qh sh r vh);
    try assumption; lra.
Qed.

(** ** Duff and symmetric Phong: both ways of /n, the walks' steps, then the value step *)

(** DuffCount.v's bounds in units of u after st steps, ka = k_add. *)
Definition duff_p (K1 kd ka st : R) : R := 1702 / 100 * K1 + 202 / 100 * kd + 1001 / 1000 * st * ka.
Definition duff_q (K1 kd ka st : R) : R := 6505 / 100 * K1 + 1204 / 100 * kd + 3004 / 1000 * st * ka.

(** EP covers p after SP steps, EQ covers q after SQ steps, either way of /n
    (Rust's [errors] with the larger kd). *)
Definition duff_errors_ok (M : fmodel) (K1 SP SQ EP EQ : R) : Prop :=
  forall kd, kd = k_div M \/ kd = kd_recip M ->
    duff_p K1 kd (k_add M) SP * m_u M <= EP /\ duff_q K1 kd (k_add M) SQ * m_u M <= EQ.

(** Duff's set-up and walk (P, Q, G: p, q, dq at every step), either way of /n. *)
Definition duff_form_ok (M : fmodel) (s : span) (na nb l : vec) (P Q G : nat -> R) : Prop :=
  (exists kk, kdiv3_ok M s kk na nb /\ duff_ok M (n s) na l kk P Q G) \/
  (exists kk, krecip3_ok M s kk na nb /\ duff_ok M (n s) na l kk P Q G).

(** A bound after st steps is within the one after SP >= st steps. *)
Lemma cz_steps : forall x a c st sp ka u e, 0 <= c -> 0 <= ka -> 0 <= u -> st <= sp ->
  x <= (a + c * st * ka) * u -> (a + c * sp * ka) * u <= e -> x <= e.
Proof.
  intros x a c st sp ka u e Hc Hka Hu Hst H1 H2.
  assert (H0 : 0 <= c * ka * u) by (apply Rmult_le_pos; [apply Rmult_le_pos|]; lra).
  assert (H3 : (c * ka * u) * st <= (c * ka * u) * sp) by (apply Rmult_le_compat_l; lra).
  assert (E1 : (a + c * st * ka) * u = a * u + (c * ka * u) * st) by ring.
  assert (E2 : (a + c * sp * ka) * u = a * u + (c * ka * u) * sp) by ring.
  rewrite E1 in H1. rewrite E2 in H2. lra.
Qed.

Lemma cz_duff : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  kd_recip M * m_u M <= / 2097152 ->
  forall (s : span) (na nb l : vec) (P Q G : nat -> R) (i j : nat) (SP SQ EP EQ : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> INR (n s) * (k_add M * m_u M) <= / 2048 ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  duff_form_ok M s na nb l P Q G -> (i <= n s)%nat -> (j <= n s)%nat ->
  INR i <= SP -> INR j <= SQ -> duff_errors_ok M K1 SP SQ EP EQ ->
  Rabs (P i - p s (INR i)) <= EP /\ Rabs (Q j - q s (INR j)) <= EQ.
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l P Q G i j SP SQ EP EQ
    Ha Hb HL Hn1 Hn Hna Hva Hvb Hvl Hf Hi Hj HSP HSQ He.
  pose proof HM as (Hu & _ & _ & _ & Hka & _).
  destruct Hf as [(kk & (Hx & Hy & Hz) & Hd) | (kk & (Hx & Hy & Hz) & Hd)].
  - destruct (He (k_div M) (or_introl eq_refl)) as [HEp HEq].
    pose proof (duff_div_generic M K K1 HM HK1 Hin Hadd Hmul Hdiv s na nb l kk P Q G
      Ha Hb HL Hn1 Hn Hna Hva Hvb Hvl Hx Hy Hz Hd) as T.
    destruct (T i Hi) as [P1 _]. destruct (T j Hj) as [_ Q1].
    split; [refine (cz_steps _ _ _ _ _ _ _ _ _ _ _ HSP P1 HEp)
           | refine (cz_steps _ _ _ _ _ _ _ _ _ _ _ HSQ Q1 HEq)]; lra.
  - destruct (He (kd_recip M) (or_intror eq_refl)) as [HEp HEq].
    pose proof (duff_recip_generic M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l kk P Q G
      Ha Hb HL Hn1 Hn Hna Hva Hvb Hvl Hx Hy Hz Hd) as T.
    destruct (T i Hi) as [P1 _]. destruct (T j Hj) as [_ Q1].
    split; [refine (cz_steps _ _ _ _ _ _ _ _ _ _ _ HSP P1 HEp)
           | refine (cz_steps _ _ _ _ _ _ _ _ _ _ _ HSQ Q1 HEq)]; lra.
Qed.

(** Duff at the pixel i: p^ = P i, q^ = Q i after i steps (Rust: SP = SQ = n). *)
Theorem duff_composed : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  kd_recip M * m_u M <= / 2097152 ->
  forall (s : span) (na nb l : vec) (P Q G : nat -> R) (i : nat)
         (SP SQ EP EQ qmin ks kv km sh vh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> INR (n s) * (k_add M * m_u M) <= / 2048 ->
  (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  duff_form_ok M s na nb l P Q G ->
  INR i <= SP -> INR i <= SQ -> duff_errors_ok M K1 SP SQ EP EQ ->
  0 < qmin -> qmin <= q s (INR i) -> 2 * EQ <= qmin ->
  0 <= ks -> 0 <= kv -> 0 <= km ->
  (ks + kv + km) * m_u M <= / 1024 -> 1024 * m_eta M <= sqrt (qmin - EQ) ->
  ap1 (ks * m_u M) (m_eta M) sh (sqrt (Q i)) ->
  (ap1 (kv * m_u M) (m_eta M) vh (P i / sh) \/
   exists r, ap1 (kv * m_u M) (m_eta M) r (1 / sh) /\ ap1 (km * m_u M) (m_eta M) vh (P i * r)) ->
  Rabs (vh - p s (INR i) / sqrt (q s (INR i))) <=
    (EP / sqrt (qmin - EQ) + EQ / (sqrt (qmin - EQ) * (sqrt qmin + sqrt (qmin - EQ))))
      * (1 + (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M))
    + (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M)
    + (2 * (1 + (EP / sqrt (qmin - EQ) + EQ / (sqrt (qmin - EQ) * (sqrt qmin + sqrt (qmin - EQ)))))
         * (m_eta M / sqrt (qmin - EQ))
       + ((1 + EP) * m_eta M * (1 + km * m_u M) + m_eta M)).
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l P Q G i SP SQ EP EQ qmin ks kv km
    sh vh Ha Hb HL Hn1 Hn Hna Hi Hva Hvb Hvl Hf HSP HSQ He Hqm Hq H2 Hks Hkv Hkm Hw He2 Hs Hv.
  destruct (cz_duff M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l P Q G i i SP SQ EP EQ
    Ha Hb HL Hn1 Hn Hna Hva Hvb Hvl Hf Hi Hi HSP HSQ He) as [HEp HEq].
  destruct (cz_p_bounds s i Ha Hb HL Hn1 Hi) as (Hp & Hp1 & _).
  pose proof HM as (Hu & Het & _).
  pose proof (Rabs_pos (P i - p s (INR i))). pose proof (Rabs_pos (Q i - q s (INR i))).
  apply (phong_value_either (m_u M) (m_eta M) ks kv km (p s (INR i)) (q s (INR i)) (P i) (Q i)
    qmin EP EQ sh vh); try assumption; lra.
Qed.

(** Symmetric Phong at the pixel i: p^ = P i after i steps, q^ = Q j, j = min(i, n - i),
    q walked j steps (q_j = q_i for unit Na, Nb). *)
Theorem symmetric_phong_composed : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  kd_recip M * m_u M <= / 2097152 ->
  forall (s : span) (na nb l : vec) (P Q G : nat -> R) (i : nat)
         (SP SQ EP EQ qmin ks kv km sh vh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> INR (n s) * (k_add M * m_u M) <= / 2048 ->
  (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  duff_form_ok M s na nb l P Q G ->
  INR i <= SP -> INR (Nat.min i (n s - i)) <= SQ -> duff_errors_ok M K1 SP SQ EP EQ ->
  0 < qmin -> qmin <= q s (INR i) -> 2 * EQ <= qmin ->
  0 <= ks -> 0 <= kv -> 0 <= km ->
  (ks + kv + km) * m_u M <= / 1024 -> 1024 * m_eta M <= sqrt (qmin - EQ) ->
  ap1 (ks * m_u M) (m_eta M) sh (sqrt (Q (Nat.min i (n s - i)))) ->
  (ap1 (kv * m_u M) (m_eta M) vh (P i / sh) \/
   exists r, ap1 (kv * m_u M) (m_eta M) r (1 / sh) /\ ap1 (km * m_u M) (m_eta M) vh (P i * r)) ->
  Rabs (vh - p s (INR i) / sqrt (q s (INR i))) <=
    (EP / sqrt (qmin - EQ) + EQ / (sqrt (qmin - EQ) * (sqrt qmin + sqrt (qmin - EQ))))
      * (1 + (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M))
    + (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M)
    + (2 * (1 + (EP / sqrt (qmin - EQ) + EQ / (sqrt (qmin - EQ) * (sqrt qmin + sqrt (qmin - EQ)))))
         * (m_eta M / sqrt (qmin - EQ))
       + ((1 + EP) * m_eta M * (1 + km * m_u M) + m_eta M)).
Proof.
  intros M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l P Q G i SP SQ EP EQ qmin ks kv km
    sh vh Ha Hb HL Hn1 Hn Hna Hi Hva Hvb Hvl Hf HSP HSQ He Hqm Hq H2 Hks Hkv Hkm Hw He2 Hs Hv.
  set (j := Nat.min i (n s - i)) in *.
  assert (Hj : (j <= n s)%nat) by (unfold j; lia).
  destruct (cz_duff M K K1 HM HK1 Hin Hadd Hmul Hdiv Hrec s na nb l P Q G i j SP SQ EP EQ
    Ha Hb HL Hn1 Hn Hna Hva Hvb Hvl Hf Hi Hj HSP HSQ He) as [HEp HEq].
  assert (Eq : q s (INR j) = q s (INR i)).
  { unfold j. destruct (Nat.le_ge_cases i (n s - i)) as [Hle | Hge].
    - rewrite Nat.min_l by exact Hle. reflexivity.
    - rewrite Nat.min_r by exact Hge. rewrite minus_INR by exact Hi.
      symmetry. apply sec_4_q_is_symmetric. unfold is_unit in Ha, Hb. lra. }
  rewrite Eq in HEq.
  destruct (cz_p_bounds s i Ha Hb HL Hn1 Hi) as (Hp & Hp1 & _).
  pose proof HM as (Hu & Het & _).
  pose proof (Rabs_pos (P i - p s (INR i))). pose proof (Rabs_pos (Q j - q s (INR i))).
  apply (phong_value_either (m_u M) (m_eta M) ks kv km (p s (INR i)) (q s (INR i)) (P i) (Q j)
    qmin EP EQ sh vh); try assumption; lra.
Qed.
