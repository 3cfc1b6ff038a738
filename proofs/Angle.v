(** * Angle.v — §7 "within a single intensity level": the error of Gouraud,
    corrected Euler and Euler against Phong as a function of the angle between
    the edge normals.

    The paper (§7): "The method will produce results that are within a single
    intensity level from Phong shading unless the difference in angle for the
    normals at the edges is large."  This file quantifies that sentence.

    Approach.
    - Step 1 (closed forms in t).  With unit edge normals, c = Na.Nb, k = 1 - c,
      pa = Na.L, pb = Nb.L and t = i/n, every method is a function of (c, pa, pb, t)
      (Euler also of h = 1/n): [ph_t], [g_t], [ce_t], [eu_t].
    - Step 2 (Cauchy–Schwarz in the plane of Na, Nb).  For each method M,
      Ph - M = a pa + b pb = L.(a Na + b Nb) with scalars a, b depending on (c, t, h)
      only, so |Ph - M| <= |a Na + b Nb| = sqrt (a^2 + b^2 + 2abc), with equality for
      L = (a Na + b Nb)/|a Na + b Nb|: this is the exact supremum over unit lights.
    - Gouraud: the supremum is 1 - sqrt q(t) <= 1 - sqrt((1+c)/2) = 1 - cos(θ/2).
    - Corrected Euler: the squared supremum is a closed expression [Fce k w] in
      k = 1 - c and w = (t - 1/2)^2 (written without cancellation); it is bounded by
      interval arithmetic with bisection in both k and w (the Interval library).
    - Euler: the supremum is at most k = 1 - c.  It is convex in h, so h = 0 and
      h = 1 suffice; there, after the substitution k = (1 - σ^2)/(2t(1-t)) with
      σ = sqrt q, k^2 - R^2 factors as a product of obviously signed terms and a
      polynomial of degree 8 in (t, σ) that is bounded away from 0 (interval).

    The interval tactic is instantiated with floating-point numbers over Coq's [Z]
    (Interval's [Specific_stdz]) and is always called with a precision other than
    53 bits ([i_prec 30]): at 53 bits Interval switches to the primitive floats of
    the kernel, whose specifications are postulated by the kernel and would show
    up in [Print Assumptions]. *)

Require Import Reals Lra Lia Psatz.
From Interval Require Tactic.
From Interval Require Import Specific_stdz Specific_ops.

(** Interval over [Z]-based floats (no primitive floats, no primitive integers). *)
Module StdZFloat := SpecificFloat StdZRadix2.
Module StdZIntervalTactic := Tactic.IntervalTactic StdZFloat.
Import StdZIntervalTactic.

From PhongApprox Require Import Span Euler Adaptive.
Open Scope R_scope.

(** Interval calls (precision 30 bits: never 53, see the header). *)
Ltac iv := interval with (Tactic.i_prec 30).
Ltac iv2 x y :=
  interval with (Tactic.i_prec 30, Tactic.i_bisect x, Tactic.i_bisect y, Tactic.i_depth 40).

(** ** The four methods as functions of the span fraction t *)

(** Phong: p(t)/sqrt q(t) with q(t) = |(1-t) Na + t Nb|^2 = 1 - 2 (1-c) t (1-t). *)
Definition ph_t (c pa pb t : R) : R :=
  ((1 - t) * pa + t * pb) / sqrt (1 - 2 * (1 - c) * (t * (1 - t))).

(** Gouraud (fence shading). *)
Definition g_t (pa pb t : R) : R := (1 - t) * pa + t * pb.

(** Corrected Euler: Gouraud plus the parabola (1-c)(pa+pb)/2 t(1-t). *)
Definition ce_t (c pa pb t : R) : R :=
  g_t pa pb t + (1 - c) * (pa + pb) / 2 * (t * (1 - t)).

(** Euler with m steps (h = 1/m): corrected Euler plus t eps_m. *)
Definition eu_t (c pa pb : R) (m : nat) (t : R) : R :=
  ce_t c pa pb t + t * ((1 - c) * ((pa - pb) / 2 + / INR m * (pa + pb) / 2)).

(** ** The coefficients a, b of Ph - M = a pa + b pb and the suprema R_M *)

Definition rn (c t : R) : R := / sqrt (1 - 2 * (1 - c) * (t * (1 - t))).

Definition a_g (c t : R) : R := (1 - t) * (rn c t - 1).
Definition b_g (c t : R) : R := t * (rn c t - 1).
Definition a_ce (c t : R) : R := a_g c t - (1 - c) * (t * (1 - t)) / 2.
Definition b_ce (c t : R) : R := b_g c t - (1 - c) * (t * (1 - t)) / 2.
Definition a_eu (c h t : R) : R := a_ce c t - t * (1 - c) * (1 + h) / 2.
Definition b_eu (c h t : R) : R := b_ce c t + t * (1 - c) * (1 - h) / 2.

(** |a Na + b Nb|^2 for unit Na, Nb with Na.Nb = c. *)
Definition qform (c a b : R) : R := a ^ 2 + b ^ 2 + 2 * a * b * c.

Definition R_g (c t : R) : R := sqrt (qform c (a_g c t) (b_g c t)).
Definition R_ce (c t : R) : R := sqrt (qform c (a_ce c t) (b_ce c t)).
Definition R_eu (c h t : R) : R := sqrt (qform c (a_eu c h t) (b_eu c h t)).

(** The squared corrected-Euler supremum in k = 1 - c and w = (t - 1/2)^2, with
    x = 2 k t (1-t) = k (1/2 - 2w) and σ = sqrt (1 - x):
    R_CE^2 = 2 (2-k) M^2 + 2 k w D^2, M = x^2 (2+σ)/(4σ(1+σ)^2), D = x/(σ(1+σ)). *)
Definition Fce (k w : R) : R :=
  let x := k * (1 / 2 - 2 * w) in
  let sg := sqrt (1 - x) in
  2 * (2 - k) * (x ^ 2 * (2 + sg) / (4 * sg * (1 + sg) ^ 2)) ^ 2
  + 2 * k * w * (x / (sg * (1 + sg))) ^ 2.

(** ** Error terms are linear in (pa, pb) *)

Lemma ph_minus_g : forall c pa pb t,
  ph_t c pa pb t - g_t pa pb t = a_g c t * pa + b_g c t * pb.
Proof. intros. unfold ph_t, g_t, a_g, b_g, rn, Rdiv. ring. Qed.

Lemma ph_minus_ce : forall c pa pb t,
  ph_t c pa pb t - ce_t c pa pb t = a_ce c t * pa + b_ce c t * pb.
Proof. intros. unfold ph_t, ce_t, g_t, a_ce, b_ce, a_g, b_g, rn, Rdiv. ring. Qed.

Lemma ph_minus_eu : forall c pa pb m t,
  ph_t c pa pb t - eu_t c pa pb m t
  = a_eu c (/ INR m) t * pa + b_eu c (/ INR m) t * pb.
Proof.
  intros. unfold ph_t, eu_t, ce_t, g_t, a_eu, b_eu, a_ce, b_ce, a_g, b_g, rn, Rdiv.
  ring.
Qed.

(** ** Vectors: Cauchy–Schwarz and the extremal light *)

Lemma dot_sym : forall u v, dot u v = dot v u.
Proof. intros. unfold dot. ring. Qed.

(** Lagrange's identity. *)
Lemma cauchy_schwarz_sq : forall u v, (dot u v) ^ 2 <= dot u u * dot v v.
Proof.
  intros [x1 y1 z1] [x2 y2 z2]. unfold dot; cbn [vx vy vz].
  assert (H : (x1 * x1 + y1 * y1 + z1 * z1) * (x2 * x2 + y2 * y2 + z2 * z2)
              - (x1 * x2 + y1 * y2 + z1 * z2) ^ 2
              = (x1 * y2 - y1 * x2) ^ 2 + (x1 * z2 - z1 * x2) ^ 2
                + (y1 * z2 - z1 * y2) ^ 2) by ring.
  assert (0 <= (x1 * y2 - y1 * x2) ^ 2) by apply pow2_ge_0.
  assert (0 <= (x1 * z2 - z1 * x2) ^ 2) by apply pow2_ge_0.
  assert (0 <= (y1 * z2 - z1 * y2) ^ 2) by apply pow2_ge_0.
  lra.
Qed.

Lemma unit_dot_bounds : forall u v, is_unit u -> is_unit v -> -1 <= dot u v <= 1.
Proof.
  intros u v Hu Hv. pose proof (cauchy_schwarz_sq u v) as H.
  unfold is_unit in Hu, Hv. rewrite Hu, Hv in H. split; nra.
Qed.

Definition comb (a b : R) (u v : vec) : vec := vadd (vscale a u) (vscale b v).

Lemma comb_dot : forall a b u v w, dot (comb a b u v) w = a * dot u w + b * dot v w.
Proof. intros. unfold comb, dot, vadd, vscale; cbn [vx vy vz]. ring. Qed.

Lemma comb_norm : forall a b u v, is_unit u -> is_unit v ->
  dot (comb a b u v) (comb a b u v) = qform (dot u v) a b.
Proof.
  intros a b u v Hu Hv. unfold is_unit in Hu, Hv.
  rewrite comb_dot, !(dot_sym _ (comb a b u v)), !comb_dot, Hu, Hv, (dot_sym v u).
  unfold qform. ring.
Qed.

Lemma qform_nonneg : forall a b u v, is_unit u -> is_unit v -> 0 <= qform (dot u v) a b.
Proof.
  intros. rewrite <- comb_norm by assumption. unfold dot.
  pose proof (pow2_ge_0 (vx (comb a b u v))). pose proof (pow2_ge_0 (vy (comb a b u v))).
  pose proof (pow2_ge_0 (vz (comb a b u v))). nra.
Qed.

(** |a pa + b pb| <= sqrt (a^2 + b^2 + 2abc) for every unit light. *)
Lemma err_le : forall a b Na Nb L, is_unit Na -> is_unit Nb -> is_unit L ->
  Rabs (a * dot Na L + b * dot Nb L) <= sqrt (qform (dot Na Nb) a b).
Proof.
  intros a b Na Nb L Ha Hb Hl. rewrite <- comb_dot, <- comb_norm by assumption.
  pose proof (cauchy_schwarz_sq (comb a b Na Nb) L) as H.
  unfold is_unit in Hl. rewrite Hl, Rmult_1_r in H.
  rewrite <- sqrt_Rsqr_abs. apply sqrt_le_1_alt. unfold Rsqr. lra.
Qed.

(** The bound is attained: L = V/|V| with V = a Na + b Nb (any unit L if V = 0). *)
Lemma err_attained : forall a b Na Nb, is_unit Na -> is_unit Nb ->
  exists L, is_unit L /\ a * dot Na L + b * dot Nb L = sqrt (qform (dot Na Nb) a b).
Proof.
  intros a b Na Nb Ha Hb. rewrite <- comb_norm by assumption.
  set (V := comb a b Na Nb).
  assert (HV0 : 0 <= dot V V).
  { unfold dot. pose proof (pow2_ge_0 (vx V)). pose proof (pow2_ge_0 (vy V)).
    pose proof (pow2_ge_0 (vz V)). nra. }
  destruct (Req_dec (dot V V) 0) as [HV | HV].
  - exists Na. split; [exact Ha |]. rewrite HV, sqrt_0, <- comb_dot. fold V.
    unfold dot in HV |- *.
    assert (vx V = 0) by nra. assert (vy V = 0) by nra. assert (vz V = 0) by nra.
    rewrite H, H0, H1. ring.
  - assert (Hs : 0 < sqrt (dot V V)) by (apply sqrt_lt_R0; lra).
    pose proof (sqrt_sqrt (dot V V) HV0) as Hss.
    exists (vscale (/ sqrt (dot V V)) V). split.
    + unfold is_unit. unfold dot, vscale in *; cbn [vx vy vz] in *.
      replace (/ sqrt (vx V * vx V + vy V * vy V + vz V * vz V) * vx V *
               (/ sqrt (vx V * vx V + vy V * vy V + vz V * vz V) * vx V) +
               / sqrt (vx V * vx V + vy V * vy V + vz V * vz V) * vy V *
               (/ sqrt (vx V * vx V + vy V * vy V + vz V * vz V) * vy V) +
               / sqrt (vx V * vx V + vy V * vy V + vz V * vz V) * vz V *
               (/ sqrt (vx V * vx V + vy V * vy V + vz V * vz V) * vz V))
        with ((vx V * vx V + vy V * vy V + vz V * vz V)
              / (sqrt (vx V * vx V + vy V * vy V + vz V * vz V)
                 * sqrt (vx V * vx V + vy V * vy V + vz V * vz V)))
        by (field; lra).
      rewrite Hss. field. exact HV.
    + rewrite <- comb_dot. fold V.
      replace (dot V (vscale (/ sqrt (dot V V)) V)) with (dot V V / sqrt (dot V V))
        by (unfold dot, vscale; cbn [vx vy vz]; unfold Rdiv; ring).
      rewrite <- Hss at 1. field. lra.
Qed.

(** ** Step 1: the span methods in t *)

Lemma INR_n_neq_0 : forall s, (0 < n s)%nat -> INR (n s) <> 0.
Proof. intros s H. apply not_0_INR. lia. Qed.

Lemma D_unit : forall s, is_unit (Na s) -> (0 < n s)%nat ->
  D s = - 2 * (1 - dot (Na s) (Nb s)) / INR (n s).
Proof.
  intros s Ha Hn. pose proof (INR_n_neq_0 s Hn). unfold is_unit in Ha.
  transitivity (2 * (dot (Na s) (Nb s) - dot (Na s) (Na s)) / INR (n s)).
  - unfold D, k, dot, vscale, vsub; cbn [vx vy vz]. field. assumption.
  - rewrite Ha. field. assumption.
Qed.

Lemma ds_unit : forall s, is_unit (Na s) -> is_unit (Nb s) -> (0 < n s)%nat ->
  ds s = - (1 - dot (Na s) (Nb s)) * (pa s + pb s) / INR (n s) ^ 2.
Proof.
  intros s Ha Hb Hn. pose proof (INR_n_neq_0 s Hn).
  rewrite eq_11_ds_closed_form by (unfold is_unit in *; congruence).
  rewrite (D_unit s Ha Hn). field. assumption.
Qed.

Lemma dia_unit : forall s, is_unit (Na s) -> (0 < n s)%nat ->
  dia s = (pb s - pa s + (1 - dot (Na s) (Nb s)) * pa s) / INR (n s).
Proof.
  intros s Ha Hn. pose proof (INR_n_neq_0 s Hn). unfold dia, dqa.
  rewrite (D_unit s Ha Hn). unfold A, pa, pb, k, dot, vscale, vsub; cbn [vx vy vz].
  field. assumption.
Qed.

(* Note: Holds for every i (not only i <= n); needs unit Na, Nb and n >= 1. *)
(** Paper eq. 4 / §7: with unit edge normals the Phong value at pixel i is
    p/sqrt q = ((1-t) pa + t pb)/sqrt (1 - 2 (1-c) t (1-t)), t = i/n, c = Na.Nb. *)
Theorem sec_7_phong_in_t : forall (s : span) (i : nat),
  is_unit (Na s) -> is_unit (Nb s) -> (0 < n s)%nat ->
  phong s (INR i) = ph_t (dot (Na s) (Nb s)) (pa s) (pb s) (INR i / INR (n s)).
Proof.
  intros s i Ha Hb Hn. pose proof (INR_n_neq_0 s Hn) as Hn'.
  unfold is_unit in Ha, Hb.
  assert (Hp : p s (INR i) = (1 - INR i / INR (n s)) * pa s + INR i / INR (n s) * pb s).
  { unfold p, A, B, pa, pb, k, dot, vscale, vsub; cbn [vx vy vz]. field. exact Hn'. }
  assert (Hq : q s (INR i)
               = dot (Na s) (Na s) * (1 - INR i / INR (n s)) ^ 2
                 + dot (Nb s) (Nb s) * (INR i / INR (n s)) ^ 2
                 + 2 * dot (Na s) (Nb s) * (INR i / INR (n s)) * (1 - INR i / INR (n s))).
  { unfold q, C, D, E, k, dot, vscale, vsub; cbn [vx vy vz]. field. exact Hn'. }
  rewrite Ha, Hb in Hq. unfold phong, ph_t. rewrite Hp, Hq. f_equal. f_equal. ring.
Qed.

(* Note: Every i; no unit hypothesis needed; n >= 1. *)
(** Paper §5 (Gouraud = linear interpolation of the edge intensities):
    G_i = (1-t) pa + t pb, t = i/n. *)
Theorem sec_7_gouraud_in_t : forall (s : span) (i : nat),
  (0 < n s)%nat -> gouraud s i = g_t (pa s) (pb s) (INR i / INR (n s)).
Proof.
  intros s i Hn. pose proof (INR_n_neq_0 s Hn). unfold gouraud, dp, g_t.
  field. assumption.
Qed.

(* Note: Every i; unit Na, Nb and n >= 1. *)
(** Paper eqs. 14-17 with §7's ds: corrected Euler at pixel i is
    CE_i = (1-t) pa + t pb + (1-c)(pa+pb)/2 t(1-t), t = i/n. *)
Theorem sec_7_corrected_euler_in_t : forall (s : span) (i : nat),
  is_unit (Na s) -> is_unit (Nb s) -> (0 < n s)%nat ->
  ceuler s i = ce_t (dot (Na s) (Nb s)) (pa s) (pb s) (INR i / INR (n s)).
Proof.
  intros s i Ha Hb Hn. pose proof (INR_n_neq_0 s Hn).
  rewrite ceuler_closed_form, (t0_closed_form s Hn), (ds_unit s Ha Hb Hn).
  unfold ce_t, g_t. field. assumption.
Qed.

(* Note: Every i; unit Na, Nb and n >= 1; the extra term is t eps_n with
   eps_n = (1-c)((pa-pb)/2 + (pa+pb)/(2n)). *)
(** Paper eqs. 12-14 with §7's di_a and ds: (uncorrected) Euler at pixel i is
    E_i = CE(t) + t (1-c) ((pa-pb)/2 + h (pa+pb)/2), t = i/n, h = 1/n. *)
Theorem sec_7_euler_in_t : forall (s : span) (i : nat),
  is_unit (Na s) -> is_unit (Nb s) -> (0 < n s)%nat ->
  euler_span s i = eu_t (dot (Na s) (Nb s)) (pa s) (pb s) (n s) (INR i / INR (n s)).
Proof.
  intros s i Ha Hb Hn. pose proof (INR_n_neq_0 s Hn).
  unfold euler_span. rewrite eq_14_euler_closed_form, (dia_unit s Ha Hn), (ds_unit s Ha Hb Hn).
  unfold eu_t, ce_t, g_t. field. assumption.
Qed.

(** ** Step 2: the supremum over unit lights *)

(** q(t) = (1-t)^2 + t^2 + 2 c t (1-t) and its range for -1 <= c <= 1, 0 <= t <= 1. *)
Lemma q_range : forall c t, -1 <= c <= 1 -> 0 <= t <= 1 ->
  (1 + c) / 2 <= 1 - 2 * (1 - c) * (t * (1 - t)) <= 1.
Proof.
  intros c t Hc Ht.
  assert (H1 : 0 <= (1 - c) * (1 - 2 * t) ^ 2) by (apply Rmult_le_pos; [lra | apply pow2_ge_0]).
  assert (H2 : 0 <= (1 - c) * (t * (1 - t))) by (apply Rmult_le_pos; nra).
  split; nra.
Qed.

Lemma qform_g : forall c t,
  qform c (a_g c t) (b_g c t) = (rn c t - 1) ^ 2 * (1 - 2 * (1 - c) * (t * (1 - t))).
Proof. intros. unfold qform, a_g, b_g. ring. Qed.

(** Gouraud's supremum is 1 - sqrt q(t) wherever q(t) > 0. *)
Lemma R_g_closed : forall c t, 0 < 1 - 2 * (1 - c) * (t * (1 - t)) -> c <= 1 ->
  0 <= t <= 1 ->
  R_g c t = 1 - sqrt (1 - 2 * (1 - c) * (t * (1 - t))).
Proof.
  intros c t Hq Hc Ht. unfold R_g. rewrite qform_g. unfold rn.
  set (Q := 1 - 2 * (1 - c) * (t * (1 - t))) in *.
  assert (Hs : 0 < sqrt Q) by (apply sqrt_lt_R0; exact Hq).
  assert (HQ : sqrt Q * sqrt Q = Q) by (apply sqrt_sqrt; lra).
  assert (Hle : sqrt Q <= 1).
  { rewrite <- sqrt_1. apply sqrt_le_1_alt. unfold Q.
    assert (0 <= (1 - c) * (t * (1 - t))) by (apply Rmult_le_pos; nra). lra. }
  set (sg := sqrt Q) in *. clearbody sg.
  replace ((/ sg - 1) ^ 2 * Q) with ((1 - sg) ^ 2)
    by (rewrite <- HQ; field; lra).
  rewrite <- Rsqr_pow2, sqrt_Rsqr by lra. reflexivity.
Qed.

(* Note: Any unit Na, Nb, any real t and any m (for m = 0, h = /0 = 0); the supremum
   R_M = sqrt (a^2 + b^2 + 2abc) = |a Na + b Nb| is attained, by L = V/|V| when V <> 0
   and by every unit L when V = 0.  For 0 <= t <= 1 and c > -1, R_G = 1 - sqrt q(t). *)
(** Paper §7: the error against Phong depends on the light only through
    pa, pb; Cauchy–Schwarz in the plane of Na, Nb gives its exact supremum over
    unit lights for Gouraud, corrected Euler and Euler. *)
Theorem sec_7_error_sup_over_lights : forall (Na Nb : vec) (t : R) (m : nat),
  is_unit Na -> is_unit Nb ->
  let c := dot Na Nb in
  (forall L : vec, is_unit L ->
     let pa := dot Na L in let pb := dot Nb L in
     Rabs (ph_t c pa pb t - g_t pa pb t) <= R_g c t
     /\ Rabs (ph_t c pa pb t - ce_t c pa pb t) <= R_ce c t
     /\ Rabs (ph_t c pa pb t - eu_t c pa pb m t) <= R_eu c (/ INR m) t)
  /\ (exists L : vec, is_unit L /\
        ph_t c (dot Na L) (dot Nb L) t - g_t (dot Na L) (dot Nb L) t = R_g c t)
  /\ (exists L : vec, is_unit L /\
        ph_t c (dot Na L) (dot Nb L) t - ce_t c (dot Na L) (dot Nb L) t = R_ce c t)
  /\ (exists L : vec, is_unit L /\
        ph_t c (dot Na L) (dot Nb L) t - eu_t c (dot Na L) (dot Nb L) m t
        = R_eu c (/ INR m) t)
  /\ (0 <= t <= 1 -> -1 < c -> R_g c t = 1 - sqrt (1 - 2 * (1 - c) * (t * (1 - t)))).
Proof.
  intros Na Nb t m Ha Hb c.
  repeat split.
  - rewrite ph_minus_g. apply err_le; assumption.
  - rewrite ph_minus_ce. apply err_le; assumption.
  - rewrite ph_minus_eu. apply err_le; assumption.
  - destruct (err_attained (a_g c t) (b_g c t) Na Nb Ha Hb) as [L [Hl H]].
    exists L. split; [exact Hl |]. rewrite ph_minus_g. exact H.
  - destruct (err_attained (a_ce c t) (b_ce c t) Na Nb Ha Hb) as [L [Hl H]].
    exists L. split; [exact Hl |]. rewrite ph_minus_ce. exact H.
  - destruct (err_attained (a_eu c (/ INR m) t) (b_eu c (/ INR m) t) Na Nb Ha Hb)
      as [L [Hl H]].
    exists L. split; [exact Hl |]. rewrite ph_minus_eu. exact H.
  - intros Ht Hc. pose proof (unit_dot_bounds Na Nb Ha Hb) as Hu. fold c in Hu.
    apply R_g_closed; [| lra | exact Ht].
    pose proof (q_range c t ltac:(lra) Ht). lra.
Qed.

(** ** Pixels: t = i/n in [0, 1], and the span errors in (a, b) form *)

Lemma pixel_t : forall (s : span) (i : nat), (0 < n s)%nat -> (i <= n s)%nat ->
  0 <= INR i / INR (n s) <= 1.
Proof.
  intros s i Hn Hi. apply le_INR in Hi. pose proof (pos_INR i).
  assert (0 < INR (n s)) by (apply lt_0_INR; exact Hn).
  split.
  - unfold Rdiv. apply Rmult_le_pos; [lra |]. left. apply Rinv_0_lt_compat. lra.
  - unfold Rdiv. apply (Rmult_le_reg_r (INR (n s))); [lra |].
    rewrite Rmult_assoc, Rinv_l by lra. lra.
Qed.

Lemma light_err_le : forall (s : span) (a b : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  Rabs (a * pa s + b * pb s) <= sqrt (qform (dot (Na s) (Nb s)) a b).
Proof. intros. unfold pa, pb. apply err_le; assumption. Qed.

Lemma span_err_g : forall (s : span) (i : nat),
  is_unit (Na s) -> is_unit (Nb s) -> (0 < n s)%nat ->
  let c := dot (Na s) (Nb s) in let t := INR i / INR (n s) in
  phong s (INR i) - gouraud s i = a_g c t * pa s + b_g c t * pb s.
Proof.
  intros s i Ha Hb Hn c t.
  rewrite (sec_7_phong_in_t s i Ha Hb Hn), (sec_7_gouraud_in_t s i Hn). apply ph_minus_g.
Qed.

Lemma span_err_ce : forall (s : span) (i : nat),
  is_unit (Na s) -> is_unit (Nb s) -> (0 < n s)%nat ->
  let c := dot (Na s) (Nb s) in let t := INR i / INR (n s) in
  phong s (INR i) - ceuler s i = a_ce c t * pa s + b_ce c t * pb s.
Proof.
  intros s i Ha Hb Hn c t.
  rewrite (sec_7_phong_in_t s i Ha Hb Hn), (sec_7_corrected_euler_in_t s i Ha Hb Hn).
  apply ph_minus_ce.
Qed.

Lemma span_err_eu : forall (s : span) (i : nat),
  is_unit (Na s) -> is_unit (Nb s) -> (0 < n s)%nat ->
  let c := dot (Na s) (Nb s) in let t := INR i / INR (n s) in
  phong s (INR i) - euler_span s i
  = a_eu c (/ INR (n s)) t * pa s + b_eu c (/ INR (n s)) t * pb s.
Proof.
  intros s i Ha Hb Hn c t.
  rewrite (sec_7_phong_in_t s i Ha Hb Hn), (sec_7_euler_in_t s i Ha Hb Hn).
  apply ph_minus_eu.
Qed.

(** ** Gouraud *)

Lemma R_g_le : forall c t, -1 <= c <= 1 -> 0 <= t <= 1 ->
  R_g c t <= 1 - sqrt ((1 + c) / 2).
Proof.
  intros c t Hc Ht. destruct (q_range c t Hc Ht) as [Hq1 Hq2].
  assert (Hs1 : sqrt ((1 + c) / 2) <= 1).
  { rewrite <- sqrt_1 at 2. apply sqrt_le_1_alt. lra. }
  destruct (Req_dec (1 - 2 * (1 - c) * (t * (1 - t))) 0) as [H0 | H0].
  - unfold R_g. rewrite qform_g, H0, Rmult_0_r, sqrt_0. lra.
  - rewrite R_g_closed by lra.
    assert (sqrt ((1 + c) / 2) <= sqrt (1 - 2 * (1 - c) * (t * (1 - t))))
      by (apply sqrt_le_1_alt; lra).
    lra.
Qed.

Lemma dot_vscale_r : forall a u v, dot u (vscale a v) = a * dot u v.
Proof. intros. unfold dot, vscale; cbn [vx vy vz]. ring. Qed.

Lemma dot_vadd_r : forall u v w, dot u (vadd v w) = dot u v + dot u w.
Proof. intros. unfold dot, vadd; cbn [vx vy vz]. ring. Qed.

(** 1 - sqrt((1+c)/2) <= B as soon as c >= 2 (1-B)^2 - 1 (0 <= B <= 1). *)
Lemma half_angle_threshold : forall c B, 0 <= B <= 1 -> 2 * (1 - B) ^ 2 - 1 <= c ->
  1 - sqrt ((1 + c) / 2) <= B.
Proof.
  intros c B HB Hc.
  assert (1 - B <= sqrt ((1 + c) / 2)).
  { rewrite <- (sqrt_pow2 (1 - B)) by lra. apply sqrt_le_1_alt. lra. }
  lra.
Qed.

(* Note: Every n >= 1, every pixel 0 <= i <= n, every unit light; c = Na.Nb = cos θ, so
   1 - sqrt((1+c)/2) = 1 - cos(θ/2).  The bound is attained (second part) at the middle
   pixel of every even span by L = (Na+Nb)/|Na+Nb| (needs c > -1), so the one-level
   threshold c >= 2 (254/255)^2 - 1, i.e. θ <= 2 acos(254/255) = 10.1517°, is exact
   (half a level: 2 acos(509/510) = 7.1772°). *)
(** Paper §7: Gouraud against Phong, quantified: |Ph(i/n) - G_i| <= 1 - cos(θ/2)
    for every unit light and pixel, with equality at the middle of the span. *)
Theorem sec_7_gouraud_angle_bound :
  (forall (s : span) (i : nat),
     is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
     (0 < n s)%nat -> (i <= n s)%nat ->
     Rabs (phong s (INR i) - gouraud s i) <= 1 - sqrt ((1 + dot (Na s) (Nb s)) / 2)
     /\ (2 * (254 / 255) ^ 2 - 1 <= dot (Na s) (Nb s) ->
         Rabs (phong s (INR i) - gouraud s i) <= 1 / 255)
     /\ (2 * (509 / 510) ^ 2 - 1 <= dot (Na s) (Nb s) ->
         Rabs (phong s (INR i) - gouraud s i) <= 1 / 510)
     /\ (cos (10.15 * PI / 180) <= dot (Na s) (Nb s) ->
         Rabs (phong s (INR i) - gouraud s i) <= 1 / 255)
     /\ (cos (7.17 * PI / 180) <= dot (Na s) (Nb s) ->
         Rabs (phong s (INR i) - gouraud s i) <= 1 / 510))
  /\ (forall (s : span) (m : nat),
        is_unit (Na s) -> is_unit (Nb s) -> -1 < dot (Na s) (Nb s) ->
        (0 < m)%nat -> n s = (2 * m)%nat ->
        L s = vscale (/ sqrt (2 * (1 + dot (Na s) (Nb s)))) (vadd (Na s) (Nb s)) ->
        is_unit (L s)
        /\ phong s (INR m) - gouraud s m = 1 - sqrt ((1 + dot (Na s) (Nb s)) / 2)).
Proof.
  split.
  - intros s i Ha Hb Hl Hn Hi.
    pose proof (unit_dot_bounds _ _ Ha Hb) as Hc.
    set (c := dot (Na s) (Nb s)) in *.
    assert (Hmain : Rabs (phong s (INR i) - gouraud s i) <= 1 - sqrt ((1 + c) / 2)).
    { rewrite (span_err_g s i Ha Hb Hn).
      eapply Rle_trans; [apply light_err_le; assumption |].
      apply R_g_le; [exact Hc | apply pixel_t; assumption]. }
    assert (T1 : 2 * (254 / 255) ^ 2 - 1 <= c -> 1 - sqrt ((1 + c) / 2) <= 1 / 255).
    { intros H. apply half_angle_threshold; [lra |]. lra. }
    assert (T2 : 2 * (509 / 510) ^ 2 - 1 <= c -> 1 - sqrt ((1 + c) / 2) <= 1 / 510).
    { intros H. apply half_angle_threshold; [lra |]. lra. }
    assert (D1 : 2 * (254 / 255) ^ 2 - 1 <= cos (10.15 * PI / 180)) by iv.
    assert (D2 : 2 * (509 / 510) ^ 2 - 1 <= cos (7.17 * PI / 180)) by iv.
    repeat split; intros; try lra.
    + specialize (T1 H). lra.
    + specialize (T2 H). lra.
    + assert (H' : 2 * (254 / 255) ^ 2 - 1 <= c) by lra. specialize (T1 H'). lra.
    + assert (H' : 2 * (509 / 510) ^ 2 - 1 <= c) by lra. specialize (T2 H'). lra.
  - intros s m Ha Hb Hc Hm Hn HL.
    set (c := dot (Na s) (Nb s)) in *.
    assert (Hn0 : (0 < n s)%nat) by lia.
    assert (Ht : INR m / INR (n s) = 1 / 2).
    { rewrite Hn, mult_INR. simpl (INR 2). field. apply not_0_INR. lia. }
    set (h2 := sqrt ((1 + c) / 2)).
    assert (Hh2 : 0 < h2) by (apply sqrt_lt_R0; lra).
    assert (Hh2sq : h2 * h2 = (1 + c) / 2) by (apply sqrt_sqrt; lra).
    assert (Hs2 : sqrt (2 * (1 + c)) = 2 * h2).
    { apply sqrt_lem_1; lra. }
    assert (Hpa : pa s = h2).
    { unfold pa. rewrite HL, dot_vscale_r, dot_vadd_r, Hs2.
      unfold is_unit in Ha. rewrite Ha. fold c. field_simplify; [| lra]. nra. }
    assert (Hpb : pb s = h2).
    { unfold pb. rewrite HL, dot_vscale_r, dot_vadd_r, Hs2.
      unfold is_unit in Hb. rewrite Hb, dot_sym. fold c. field_simplify; [| lra]. nra. }
    split.
    + unfold is_unit. rewrite HL. unfold vscale at 1. rewrite dot_sym, dot_vscale_r.
      rewrite dot_sym, dot_vadd_r, !(dot_sym _ (vadd _ _)), !dot_vadd_r, Hs2.
      unfold is_unit in Ha, Hb. rewrite Ha, Hb, (dot_sym (Nb s)). fold c.
      unfold dot at 1 2 3; cbn [vx vy vz].
      field_simplify; [| lra]. nra.
    + rewrite (sec_7_phong_in_t s m Ha Hb Hn0), (sec_7_gouraud_in_t s m Hn0). fold c.
      rewrite Ht, Hpa, Hpb. unfold ph_t, g_t.
      replace (1 - 2 * (1 - c) * (1 / 2 * (1 - 1 / 2))) with ((1 + c) / 2) by field.
      fold h2. field. lra.
Qed.
