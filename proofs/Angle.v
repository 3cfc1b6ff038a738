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

From PhongApprox Require Import Span Euler Adaptive ClosedForms.
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
    exists (vscale (/ sqrt (dot V V)) V). unfold is_unit. rewrite <- comb_dot. fold V.
    replace (dot (vscale (/ sqrt (dot V V)) V) (vscale (/ sqrt (dot V V)) V))
      with (/ sqrt (dot V V) * / sqrt (dot V V) * dot V V)
      by (unfold dot, vscale; cbn [vx vy vz]; ring).
    replace (dot V (vscale (/ sqrt (dot V V)) V)) with (/ sqrt (dot V V) * dot V V)
      by (unfold dot, vscale; cbn [vx vy vz]; ring).
    set (r := sqrt (dot V V)) in *. clearbody r. rewrite <- Hss. split; field; lra.
Qed.

(** ** Step 1: the span methods in t *)

Lemma dia_unit : forall s, is_unit (Na s) -> (0 < n s)%nat ->
  dia s = (pb s - pa s + (1 - dot (Na s) (Nb s)) * pa s) / INR (n s).
Proof.
  intros s Ha Hn. pose proof (INR_n_neq_0 s Hn). unfold dia, dqa.
  rewrite (D_unit s Ha). unfold A, pa, pb, k, dot, vscale, vsub; cbn [vx vy vz].
  field. assumption.
Qed.

(* Note: Holds for every i (not only i <= n); needs unit Na, Nb and n >= 1. *)
(** Paper eq. 4 in the setting of §7 (unit edge normals): the Phong value at pixel i is
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

(* Note: Every i; needs neither unit Na nor unit Nb; n >= 1. *)
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
  rewrite ceuler_closed_form, (t0_closed_form s Hn), (ds_unit s Ha Hb).
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
  unfold euler_span. rewrite eq_14_euler_closed_form, (dia_unit s Ha Hn), (ds_unit s Ha Hb).
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

(** r - 1 and r - 1 - x/2 without cancellation, for r = 1/σ, σ = sqrt (1 - x). *)
Lemma r_minus_1 : forall x sg, 0 < sg -> sg * sg = 1 - x ->
  / sg - 1 = x / (sg * (1 + sg)).
Proof. intros x sg H H2. replace x with (1 - sg * sg) by lra. field. lra. Qed.

Lemma r_minus_1_half : forall x sg, 0 < sg -> sg * sg = 1 - x ->
  / sg - 1 - x / 2 = x ^ 2 * (2 + sg) / (2 * sg * (1 + sg) ^ 2).
Proof. intros x sg H H2. replace x with (1 - sg * sg) by lra. field. lra. Qed.

(** The squared supremum of corrected Euler is [Fce (1 - c) ((t - 1/2)^2)]:
    with a = m - d, b = m + d, a^2 + b^2 + 2abc = 2 (1+c) m^2 + 2 (1-c) d^2. *)
Lemma qform_ce_Fce : forall c t, -1 / 2 <= c <= 1 -> 0 <= t <= 1 ->
  qform c (a_ce c t) (b_ce c t) = Fce (1 - c) ((t - 1 / 2) ^ 2).
Proof.
  intros c t Hc Ht.
  assert (Hs : 0 <= t * (1 - t) <= 1 / 4)
    by (pose proof (pow2_ge_0 (t - 1 / 2)); split; nra).
  set (x := 2 * (1 - c) * (t * (1 - t))).
  assert (Hx : 0 <= x <= 3 / 4) by (unfold x; split; nra).
  assert (Hxw : (1 - c) * (1 / 2 - 2 * (t - 1 / 2) ^ 2) = x) by (unfold x; field).
  unfold Fce. cbv zeta. rewrite Hxw.
  unfold qform, a_ce, b_ce, a_g, b_g, rn. fold x.
  assert (Hsg : 0 < sqrt (1 - x)) by (apply sqrt_lt_R0; lra).
  assert (Hsg2 : sqrt (1 - x) * sqrt (1 - x) = 1 - x) by (apply sqrt_sqrt; lra).
  set (sg := sqrt (1 - x)) in *. clearbody sg.
  transitivity (2 * (1 + c) * ((/ sg - 1 - x / 2) / 2) ^ 2
                + 2 * (1 - c) * (t - 1 / 2) ^ 2 * (/ sg - 1) ^ 2).
  { unfold x. field. lra. }
  rewrite (r_minus_1_half x sg Hsg Hsg2), (r_minus_1 x sg Hsg Hsg2).
  field. lra.
Qed.

(* Note: Any unit Na, Nb, any real t and any m (for m = 0, h = /0 = 0); the supremum
   R_M = sqrt (a^2 + b^2 + 2abc) = |a Na + b Nb| is attained, by L = V/|V| when V <> 0
   and by every unit L when V = 0.  For 0 <= t <= 1 and c > -1, R_G = 1 - sqrt q(t);
   for c >= -1/2, R_CE^2 is the closed form [Fce (1-c) ((t-1/2)^2)] used below. *)
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
  /\ (0 <= t <= 1 -> -1 < c -> R_g c t = 1 - sqrt (1 - 2 * (1 - c) * (t * (1 - t))))
  /\ (0 <= t <= 1 -> -1 / 2 <= c -> R_ce c t = sqrt (Fce (1 - c) ((t - 1 / 2) ^ 2))).
Proof.
  intros Na Nb t m Ha Hb c.
  repeat split.
  - rewrite ph_minus_g. apply err_le; assumption.
  - rewrite ph_minus_ce. apply err_le; assumption.
  - rewrite ph_minus_eu. apply err_le; assumption.
  - setoid_rewrite ph_minus_g. apply err_attained; assumption.
  - setoid_rewrite ph_minus_ce. apply err_attained; assumption.
  - setoid_rewrite ph_minus_eu. apply err_attained; assumption.
  - intros Ht Hc. pose proof (unit_dot_bounds Na Nb Ha Hb) as Hu. fold c in Hu.
    apply R_g_closed; [| lra | exact Ht].
    pose proof (q_range c t ltac:(lra) Ht). lra.
  - intros Ht Hc. pose proof (unit_dot_bounds Na Nb Ha Hb) as Hu. fold c in Hu.
    unfold R_ce. rewrite qform_ce_Fce by lra. reflexivity.
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

(** Ph - M in (a, b) form: Gouraud, corrected Euler, Euler. *)
Lemma span_err : forall (s : span) (i : nat),
  is_unit (Na s) -> is_unit (Nb s) -> (0 < n s)%nat ->
  let c := dot (Na s) (Nb s) in let t := INR i / INR (n s) in
  phong s (INR i) - gouraud s i = a_g c t * pa s + b_g c t * pb s
  /\ phong s (INR i) - ceuler s i = a_ce c t * pa s + b_ce c t * pb s
  /\ phong s (INR i) - euler_span s i
     = a_eu c (/ INR (n s)) t * pa s + b_eu c (/ INR (n s)) t * pb s.
Proof.
  intros s i Ha Hb Hn c t.
  rewrite (sec_7_phong_in_t s i Ha Hb Hn), (sec_7_gouraud_in_t s i Hn),
    (sec_7_corrected_euler_in_t s i Ha Hb Hn), (sec_7_euler_in_t s i Ha Hb Hn).
  split; [apply ph_minus_g | split; [apply ph_minus_ce | apply ph_minus_eu]].
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
    { rewrite (proj1 (span_err s i Ha Hb Hn)).
      eapply Rle_trans; [apply light_err_le; assumption |].
      apply R_g_le; [exact Hc | apply pixel_t; assumption]. }
    assert (T : forall B, 0 <= B <= 1 -> 2 * (1 - B) ^ 2 - 1 <= c ->
                Rabs (phong s (INR i) - gouraud s i) <= B)
      by (intros; eapply Rle_trans; [exact Hmain | apply half_angle_threshold; assumption]).
    assert (D1 : 2 * (254 / 255) ^ 2 - 1 <= cos (10.15 * PI / 180)) by iv.
    assert (D2 : 2 * (509 / 510) ^ 2 - 1 <= cos (7.17 * PI / 180)) by iv.
    repeat split; intros; [exact Hmain | apply T; lra ..].
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
    assert (pa s = h2 /\ pb s = h2) as [Hpa Hpb].
    { unfold pa, pb. rewrite HL, !dot_vscale_r, !dot_vadd_r, Hs2.
      unfold is_unit in Ha, Hb. rewrite Ha, Hb, (dot_sym (Nb s)). fold c.
      replace (1 + c) with (2 * (h2 * h2)) by lra. replace (c + 1) with (2 * (h2 * h2)) by lra.
      split; field; lra. }
    split.
    + unfold is_unit. rewrite HL, Hs2.
      assert (E : forall a u v, dot (vscale a (vadd u v)) (vscale a (vadd u v))
                  = a * a * (dot u u + 2 * dot u v + dot v v))
        by (intros; unfold dot, vscale, vadd; cbn [vx vy vz]; ring).
      rewrite E. unfold is_unit in Ha, Hb. rewrite Ha, Hb. fold c.
      replace (1 + 2 * c + 1) with (4 * (h2 * h2)) by lra. field. lra.
    + rewrite (sec_7_phong_in_t s m Ha Hb Hn0), (sec_7_gouraud_in_t s m Hn0). fold c.
      rewrite Ht, Hpa, Hpb. unfold ph_t, g_t.
      replace (1 - 2 * (1 - c) * (1 / 2 * (1 - 1 / 2))) with ((1 + c) / 2) by field.
      fold h2. field. lra.
Qed.

(** ** Corrected Euler *)

(** A pixel bound for corrected Euler from a bound on [Fce] over a box in (k, w). *)
Lemma ce_pixel_bound : forall (s : span) (i : nat) (K B : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (0 < n s)%nat -> (i <= n s)%nat ->
  0 <= B -> K <= 3 / 2 -> 1 - K <= dot (Na s) (Nb s) ->
  (forall k w, 0 <= k <= K -> 0 <= w <= 1 / 4 -> Fce k w <= B ^ 2) ->
  Rabs (phong s (INR i) - ceuler s i) <= B.
Proof.
  intros s i K B Ha Hb Hl Hn Hi HB HK Hc HF.
  rewrite (proj1 (proj2 (span_err s i Ha Hb Hn))).
  eapply Rle_trans; [apply light_err_le; assumption |].
  pose proof (pixel_t s i Hn Hi) as Ht. pose proof (unit_dot_bounds _ _ Ha Hb) as Hu.
  set (c := dot (Na s) (Nb s)) in *. set (t := INR i / INR (n s)) in *.
  rewrite qform_ce_Fce by lra.
  rewrite <- (sqrt_pow2 B HB). apply sqrt_le_1_alt. apply HF; [lra |].
  split; [apply pow2_ge_0 | nra].
Qed.

(** A table row: sup over k in [0, 1 - cos θ], w in [0, 1/4] of R_CE, as B/255
    with B the supremum in 8-bit levels rounded up at the third digit ([Fce k w <=
    (B/255)^2] by interval bisection). *)
Ltac ce_row th :=
  intros ?; apply (ce_pixel_bound _ _ (1 - cos (th * PI / 180))); try assumption;
  [lra | iv | lra | intros k w Hk Hw; unfold Fce; iv2 k w].

(* Note: Every n >= 1, every pixel 0 <= i <= n, every unit light; θ is the angle between
   the edge normals (cos θ <= c).  The bounds are sup over t in [0,1] and over unit
   lights of |Ph - CE|, in 8-bit levels rounded up at the third significant digit
   (computed: 0.0040796, 0.032707, 0.11078, 0.26392, 0.51881, 0.90364, 1.4485, 2.1859,
   3.1511, 4.3830, 7.8215, 12.899, 20.092, 29.948 levels); the worst pixel is off-centre
   (t ~ 0.21-0.38 or mirrored), e.g. t ~ 0.272 at 60°. *)
(** Paper §7: "The method will produce results that are within a single intensity
    level from Phong shading unless the difference in angle for the normals at the
    edges is large" -- the error of corrected Euler as a function of that angle. *)
Theorem sec_7_corrected_euler_angle_table : forall (s : span) (i : nat),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (0 < n s)%nat -> (i <= n s)%nat ->
  let c := dot (Na s) (Nb s) in
  let err := Rabs (phong s (INR i) - ceuler s i) in
  (cos (5 * PI / 180) <= c -> err <= 0.00408 / 255)
  /\ (cos (10 * PI / 180) <= c -> err <= 0.0328 / 255)
  /\ (cos (15 * PI / 180) <= c -> err <= 0.111 / 255)
  /\ (cos (20 * PI / 180) <= c -> err <= 0.264 / 255)
  /\ (cos (25 * PI / 180) <= c -> err <= 0.519 / 255)
  /\ (cos (30 * PI / 180) <= c -> err <= 0.904 / 255)
  /\ (cos (35 * PI / 180) <= c -> err <= 1.45 / 255)
  /\ (cos (40 * PI / 180) <= c -> err <= 2.19 / 255)
  /\ (cos (45 * PI / 180) <= c -> err <= 3.16 / 255)
  /\ (cos (50 * PI / 180) <= c -> err <= 4.39 / 255)
  /\ (cos (60 * PI / 180) <= c -> err <= 7.83 / 255)
  /\ (cos (70 * PI / 180) <= c -> err <= 12.9 / 255)
  /\ (cos (80 * PI / 180) <= c -> err <= 20.1 / 255)
  /\ (cos (90 * PI / 180) <= c -> err <= 30.0 / 255).
Proof.
  intros s i Ha Hb Hl Hn Hi. cbv zeta.
  repeat split.
  - ce_row 5.
  - ce_row 10.
  - ce_row 15.
  - ce_row 20.
  - ce_row 25.
  - ce_row 30.
  - ce_row 35.
  - ce_row 40.
  - ce_row 45.
  - ce_row 50.
  - ce_row 60.
  - ce_row 70.
  - ce_row 80.
  - ce_row 90.
Qed.


(** Sharpness: a concrete span Na = (1,0,0), Nb = (cos θ, sin θ, 0) with the extremal
    light of pixel i, where the error exceeds B. *)
Lemma ce_sharp : forall (th B : R) (i m : nat),
  (0 < m)%nat -> (i <= m)%nat -> 0 <= B -> -1 / 2 <= cos (th * PI / 180) ->
  B ^ 2 < Fce (1 - cos (th * PI / 180)) ((INR i / INR m - 1 / 2) ^ 2) ->
  exists s : span, is_unit (Na s) /\ is_unit (Nb s) /\ is_unit (L s) /\ n s = m
    /\ dot (Na s) (Nb s) = cos (th * PI / 180)
    /\ B < Rabs (phong s (INR i) - ceuler s i).
Proof.
  intros th B i m Hm Him HB Hc HF.
  set (Na0 := mkV 1 0 0).
  set (Nb0 := mkV (cos (th * PI / 180)) (sin (th * PI / 180)) 0).
  assert (Ha : is_unit Na0) by (unfold is_unit, dot, Na0; cbn [vx vy vz]; ring).
  assert (Hb : is_unit Nb0).
  { unfold is_unit, dot, Nb0; cbn [vx vy vz].
    pose proof (sin2_cos2 (th * PI / 180)) as H. unfold Rsqr in H. lra. }
  assert (Hc0 : dot Na0 Nb0 = cos (th * PI / 180))
    by (unfold dot, Na0, Nb0; cbn [vx vy vz]; ring).
  set (c := cos (th * PI / 180)) in *.
  set (t := INR i / INR m).
  destruct (err_attained (a_ce c t) (b_ce c t) Na0 Nb0 Ha Hb) as [L0 [Hl HL]].
  exists (mkSpan Na0 Nb0 L0 m). cbn [Na Nb L n].
  repeat split; try assumption.
  assert (Ht : 0 <= t <= 1) by (apply (pixel_t (mkSpan Na0 Nb0 L0 m)); cbn [n]; assumption).
  pose proof (unit_dot_bounds _ _ Ha Hb) as Hu.
  rewrite (proj1 (proj2 (span_err (mkSpan Na0 Nb0 L0 m) i Ha Hb Hm))). cbn [Na Nb L n].
  rewrite Hc0. fold t. unfold pa, pb. cbn [Na Nb L].
  rewrite HL, Hc0, qform_ce_Fce by lra.
  rewrite Rabs_pos_eq by apply sqrt_pos.
  rewrite <- (sqrt_pow2 B HB). apply sqrt_lt_1_alt. split; [apply pow2_ge_0 | exact HF].
Qed.

(* Note: Every n >= 1, every pixel, every unit light.  Exact thresholds (computed):
   one level up to θ = 31.0121° (c = 0.857059), half a level up to 24.6977°
   (c = 0.908525).  Sharpness is shown on actual pixels: n = 500, i = 113 (t = 0.226)
   at θ = 31.1° (error 1.0087 levels) and n = 50, i = 11 (t = 0.22) at θ = 24.8°
   (1.0126 half-levels), with Na = (1,0,0), Nb = (cos θ, sin θ, 0) and the extremal
   light of that pixel. *)
(** Paper §7: "within a single intensity level from Phong shading unless the
    difference in angle for the normals at the edges is large": corrected Euler is
    within one level (1/255) of Phong at every pixel iff θ is at most about 31°
    (half a level: about 24.7°). *)
Theorem sec_7_corrected_euler_one_level :
  (forall (s : span) (i : nat),
     is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
     (0 < n s)%nat -> (i <= n s)%nat ->
     (cos (31 * PI / 180) <= dot (Na s) (Nb s) ->
      Rabs (phong s (INR i) - ceuler s i) <= 1 / 255)
     /\ (cos (24.6 * PI / 180) <= dot (Na s) (Nb s) ->
         Rabs (phong s (INR i) - ceuler s i) <= 1 / 510))
  /\ (exists s : span, is_unit (Na s) /\ is_unit (Nb s) /\ is_unit (L s)
        /\ n s = 500%nat /\ dot (Na s) (Nb s) = cos (31.1 * PI / 180)
        /\ 1 / 255 < Rabs (phong s (INR 113) - ceuler s 113))
  /\ (exists s : span, is_unit (Na s) /\ is_unit (Nb s) /\ is_unit (L s)
        /\ n s = 50%nat /\ dot (Na s) (Nb s) = cos (24.8 * PI / 180)
        /\ 1 / 510 < Rabs (phong s (INR 11) - ceuler s 11)).
Proof.
  split; [intros s i Ha Hb Hl Hn Hi; split; [ce_row 31 | ce_row 24.6] |].
  split; apply ce_sharp; [lia | lia | lra | iv | | lia | lia | lra | iv |];
    rewrite !INR_IZR_INZ; cbn [Z.of_nat Pos.of_succ_nat Pos.succ]; unfold Fce; iv.
Qed.

(** ** Euler *)

(** After k = (1 - σ^2)/(2 t (1-t)), σ = sqrt q(t), the Euler error at h = 0 and
    h = 1 is governed by these two polynomials (degree 8 in (t, σ)). *)
Definition P0 (t sg : R) : R :=
  sg^4*t^3 - 2*sg^4*t^2 + 2*sg^3*t^4 - 3*sg^3*t^3 - 2*sg^3*t^2 + 4*sg^2*t^4
  - 9*sg^2*t^3 + 2*sg^2*t^2 + 4*sg^2*t - 4*sg^2 + 2*sg*t^4 - 9*sg*t^3
  + 14*sg*t^2 - 4*sg*t - 4*sg - 8*t^4 + 20*t^3 - 12*t^2.

Definition P1 (t sg : R) : R :=
  sg^4*t^2 - 3*sg^4*t + 2*sg^3*t^3 - 5*sg^3*t^2 - 3*sg^3*t + 4*sg^2*t^3
  - 13*sg^2*t^2 + 7*sg^2*t + 4*sg^2 + 2*sg*t^3 - 3*sg*t^2 + 11*sg*t + 4*sg
  - 8*t^3 + 20*t^2 - 4*t.

(** On the region |1 - 2t| <= σ <= 1 (i.e. 0 <= k <= 2), P0 <= -1 and P1 >= 2;
    the region is covered by three boxes. *)
Lemma P0_neg : forall t sg, 0 <= t <= 1 -> 0 <= sg <= 1 ->
  1 - 2 * t <= sg -> 2 * t - 1 <= sg -> P0 t sg < 0.
Proof.
  intros t sg Ht Hs H1 H2. unfold P0.
  destruct (Rle_lt_dec t (1 / 4)) as [Hl | Hl];
    [| destruct (Rle_lt_dec t (3 / 4)) as [Hm | Hm]].
  - assert (Ht' : 0 <= t <= 1 / 4) by lra. assert (Hs' : 1 / 2 <= sg <= 1) by lra.
    iv2 t sg.
  - assert (Ht' : 1 / 4 <= t <= 3 / 4) by lra. iv2 t sg.
  - assert (Ht' : 3 / 4 <= t <= 1) by lra. assert (Hs' : 1 / 2 <= sg <= 1) by lra.
    iv2 t sg.
Qed.

Lemma P1_pos : forall t sg, 0 <= t <= 1 -> 0 <= sg <= 1 ->
  1 - 2 * t <= sg -> 2 * t - 1 <= sg -> 0 < P1 t sg.
Proof.
  intros t sg Ht Hs H1 H2. unfold P1.
  destruct (Rle_lt_dec t (1 / 4)) as [Hl | Hl].
  - assert (Ht' : 0 <= t <= 1 / 4) by lra. assert (Hs' : 1 / 2 <= sg <= 1) by lra.
    iv2 t sg.
  - assert (Ht' : 1 / 4 <= t <= 1) by lra. iv2 t sg.
Qed.

(** The Euler coefficients with r left abstract. *)
Definition A_eu (c r h t : R) : R :=
  (1 - t) * (r - 1) - (1 - c) * (t * (1 - t)) / 2 - t * (1 - c) * (1 + h) / 2.
Definition B_eu (c r h t : R) : R :=
  t * (r - 1) - (1 - c) * (t * (1 - t)) / 2 + t * (1 - c) * (1 - h) / 2.

Lemma a_eu_r : forall c h t, a_eu c h t = A_eu c (rn c t) h t.
Proof. intros. unfold a_eu, a_ce, a_g, A_eu. ring. Qed.
Lemma b_eu_r : forall c h t, b_eu c h t = B_eu c (rn c t) h t.
Proof. intros. unfold b_eu, b_ce, b_g, B_eu. ring. Qed.

(** k^2 - R_E^2 at h = 0 and h = 1, for 0 < t < 1, in the variables (t, σ): it is
    (1-σ)^2 (1+σ-2t) F / (16 σ t^2 d) with F >= 0, d > 0. *)
Lemma eu_sigma_le : forall t sg F d Q K, 0 < t < 1 -> 0 < sg -> 2 * t - 1 <= sg ->
  0 <= F -> 0 < d -> K - Q = (1 - sg) ^ 2 * ((1 + sg - 2 * t) * F) / (16 * sg * t ^ 2 * d) ->
  Q <= K.
Proof.
  intros t sg F d Q K Ht Hs H1 HF Hd E.
  assert (0 < t ^ 2) by (apply pow_lt; lra).
  assert (0 <= (1 - sg) ^ 2 * ((1 + sg - 2 * t) * F) / (16 * sg * t ^ 2 * d)).
  { unfold Rdiv. apply Rmult_le_pos.
    - apply Rmult_le_pos; [apply pow2_ge_0 | apply Rmult_le_pos; lra].
    - left. apply Rinv_0_lt_compat. apply Rmult_lt_0_compat; [| lra].
      apply Rmult_lt_0_compat; lra. }
  lra.
Qed.

Lemma eu_sigma : forall t sg hh, hh = 0 \/ hh = 1 -> 0 < t < 1 -> 0 < sg <= 1 ->
  1 - 2 * t <= sg -> 2 * t - 1 <= sg ->
  let c := 1 - (1 - sg ^ 2) / (2 * (t * (1 - t))) in
  qform c (A_eu c (/ sg) hh t) (B_eu c (/ sg) hh t) <= (1 - c) ^ 2.
Proof.
  intros t sg hh Hh Ht Hs H1 H2 c.
  pose proof (P0_neg t sg ltac:(lra) ltac:(lra) H1 H2).
  pose proof (P1_pos t sg ltac:(lra) ltac:(lra) H1 H2).
  destruct Hh; subst hh; [apply (eu_sigma_le t sg (- P0 t sg) ((1 - t) ^ 3))
    | apply (eu_sigma_le t sg (P1 t sg) ((1 - t) ^ 2))]; try lra; try (apply pow_lt; lra);
    unfold c, qform, A_eu, B_eu, P0, P1; field; repeat split; nra.
Qed.

Lemma rn_edge : forall c t, t = 0 \/ t = 1 -> rn c t = 1.
Proof.
  intros c t Ht. unfold rn.
  replace (1 - 2 * (1 - c) * (t * (1 - t))) with 1 by (destruct Ht; subst; ring).
  rewrite sqrt_1. apply Rinv_1.
Qed.

(** R_E^2 <= k^2 at h = 0 and at h = 1 (every t in [0,1], every c in [-1,1]). *)
Lemma eu_end : forall c t hh, hh = 0 \/ hh = 1 -> -1 <= c <= 1 -> 0 <= t <= 1 ->
  qform c (a_eu c hh t) (b_eu c hh t) <= (1 - c) ^ 2.
Proof.
  intros c t hh Hh Hc Ht. rewrite a_eu_r, b_eu_r.
  destruct (Req_dec t 0) as [H0 | H0]; [| destruct (Req_dec t 1) as [H1 | H1]].
  - rewrite (rn_edge c t (or_introl H0)). subst t. unfold qform, A_eu, B_eu.
    destruct Hh; subst hh; nra.
  - rewrite (rn_edge c t (or_intror H1)). subst t. unfold qform, A_eu, B_eu.
    assert (0 <= (1 - c) ^ 2 * (1 + c)) by (apply Rmult_le_pos; [apply pow2_ge_0 | lra]).
    destruct Hh; subst hh; nra.
  - assert (Ht' : 0 < t < 1) by lra.
    destruct (q_range c t Hc Ht) as [Hq1 Hq2].
    assert (HQ2 : (1 - 2 * t) ^ 2 <= 1 - 2 * (1 - c) * (t * (1 - t)))
      by (assert (0 <= (1 + c) * (t * (1 - t))) by (apply Rmult_le_pos; nra); nra).
    unfold rn.
    set (Q := 1 - 2 * (1 - c) * (t * (1 - t))) in *.
    destruct (Req_dec Q 0) as [HQ | HQ].
    + (* antipodal normals (c = -1) at the middle of the span: q = 0, r = /0 = 0 *)
      assert (Hcm : c = -1) by lra.
      assert (Hth : t = 1 / 2) by (unfold Q in HQ; subst c; nra).
      rewrite HQ, sqrt_0, Rinv_0. subst c t. unfold qform, A_eu, B_eu.
      destruct Hh; subst hh; lra.
    + assert (HQp : 0 < Q) by lra.
      assert (Hsg : 0 < sqrt Q) by (apply sqrt_lt_R0; lra).
      assert (Hsg2 : sqrt Q ^ 2 = Q) by (rewrite <- Rsqr_pow2; apply Rsqr_sqrt; lra).
      assert (Hsg1 : sqrt Q <= 1) by (rewrite <- sqrt_1; apply sqrt_le_1_alt; lra).
      assert (Habs : Rabs (1 - 2 * t) <= sqrt Q).
      { rewrite <- sqrt_Rsqr_abs, Rsqr_pow2. apply sqrt_le_1_alt. exact HQ2. }
      pose proof (Rle_abs (1 - 2 * t)). pose proof (Rle_abs (- (1 - 2 * t))).
      rewrite Rabs_Ropp in *.
      set (sg := sqrt Q) in *. clearbody sg.
      assert (Hc' : c = 1 - (1 - sg ^ 2) / (2 * (t * (1 - t)))).
      { rewrite Hsg2. unfold Q. field. lra. }
      clearbody Q. subst c. apply eu_sigma; lra.
Qed.

(** R_E^2 is convex in h: V_h = V_0 - (t k h / 2)(Na + Nb). *)
Lemma eu_convex : forall c h t, -1 <= c -> 0 <= h <= 1 ->
  qform c (a_eu c h t) (b_eu c h t)
  <= (1 - h) * qform c (a_eu c 0 t) (b_eu c 0 t) + h * qform c (a_eu c 1 t) (b_eu c 1 t).
Proof.
  intros c h t Hc Hh. rewrite !a_eu_r, !b_eu_r.
  set (r := rn c t).
  assert (E : (1 - h) * qform c (A_eu c r 0 t) (B_eu c r 0 t)
              + h * qform c (A_eu c r 1 t) (B_eu c r 1 t)
              - qform c (A_eu c r h t) (B_eu c r h t)
              = 2 * (t * (1 - c) / 2) ^ 2 * (1 + c) * (h * (1 - h)))
    by (unfold qform, A_eu, B_eu; field).
  assert (0 <= 2 * (t * (1 - c) / 2) ^ 2 * (1 + c) * (h * (1 - h))).
  { apply Rmult_le_pos; [| nra]. apply Rmult_le_pos; [| lra].
    pose proof (pow2_ge_0 (t * (1 - c) / 2)). lra. }
  lra.
Qed.

Lemma R_eu_le : forall c h t, -1 <= c <= 1 -> 0 <= h <= 1 -> 0 <= t <= 1 ->
  R_eu c h t <= 1 - c.
Proof.
  intros c h t Hc Hh Ht. unfold R_eu.
  rewrite <- (sqrt_pow2 (1 - c)) by lra. apply sqrt_le_1_alt.
  eapply Rle_trans; [apply eu_convex; lra |].
  pose proof (eu_end c t 0 (or_introl eq_refl) Hc Ht).
  pose proof (eu_end c t 1 (or_intror eq_refl) Hc Ht).
  nra.
Qed.

(* Note: Every n >= 1 (h = 1/n), every pixel 0 <= i <= n, every unit light, every
   pair of unit edge normals (including antipodal ones).  Sharp: equality at n = 1,
   pixel 1, L = Na (E_1 = pb + (1-c) pa).  Hence the exact one-level threshold over all
   spans is c >= 254/255, θ <= acos(254/255) = 5.0759° (half a level: 509/510,
   3.5886°).  Proof: convexity in h reduces to h in {0, 1}; there, with
   k = (1 - σ^2)/(2t(1-t)), k^2 - R_E^2 = (1-σ)^2 (1+σ-2t) (-P0)/(16σt^2(1-t)^3)
   (h = 0) and (1-σ)^2 (1+σ-2t) P1/(16σt^2(1-t)^2) (h = 1). *)
(** Paper §3.1 / §7: uncorrected Euler drifts from Phong; quantified against the angle
    between the edge normals: |Ph(i/n) - E_i| <= 1 - cos θ. *)
Theorem sec_7_euler_angle_bound :
  (forall (s : span) (i : nat),
     is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
     (0 < n s)%nat -> (i <= n s)%nat ->
     Rabs (phong s (INR i) - euler_span s i) <= 1 - dot (Na s) (Nb s)
     /\ (254 / 255 <= dot (Na s) (Nb s) ->
         Rabs (phong s (INR i) - euler_span s i) <= 1 / 255)
     /\ (509 / 510 <= dot (Na s) (Nb s) ->
         Rabs (phong s (INR i) - euler_span s i) <= 1 / 510)
     /\ (cos (5.07 * PI / 180) <= dot (Na s) (Nb s) ->
         Rabs (phong s (INR i) - euler_span s i) <= 1 / 255)
     /\ (cos (3.58 * PI / 180) <= dot (Na s) (Nb s) ->
         Rabs (phong s (INR i) - euler_span s i) <= 1 / 510))
  /\ (forall s : span,
        is_unit (Na s) -> is_unit (Nb s) -> n s = 1%nat -> L s = Na s ->
        phong s (INR 1) - euler_span s 1 = - (1 - dot (Na s) (Nb s))).
Proof.
  split.
  - intros s i Ha Hb Hl Hn Hi.
    pose proof (unit_dot_bounds _ _ Ha Hb) as Hc.
    assert (Hn1 : 1 <= INR (n s)) by (apply (le_INR 1); lia).
    assert (Hh : 0 <= / INR (n s) <= 1).
    { split; [left; apply Rinv_0_lt_compat; lra |].
      rewrite <- Rinv_1. apply Rinv_le_contravar; lra. }
    assert (Hmain : Rabs (phong s (INR i) - euler_span s i) <= 1 - dot (Na s) (Nb s)).
    { rewrite (proj2 (proj2 (span_err s i Ha Hb Hn))).
      eapply Rle_trans; [apply light_err_le; assumption |].
      apply R_eu_le; [exact Hc | exact Hh | apply pixel_t; assumption]. }
    assert (D1 : 254 / 255 <= cos (5.07 * PI / 180)) by iv.
    assert (D2 : 509 / 510 <= cos (3.58 * PI / 180)) by iv.
    repeat split; intros; lra.
  - intros s Ha Hb Hn HL.
    assert (Hn0 : (0 < n s)%nat) by lia.
    rewrite (proj2 (proj2 (span_err s 1 Ha Hb Hn0))). rewrite Hn.
    replace (INR 1 / INR 1) with 1 by (simpl; field).
    replace (/ INR 1) with 1 by (simpl; field).
    rewrite a_eu_r, b_eu_r, rn_edge by auto.
    unfold pa, pb. rewrite HL. unfold is_unit in Ha. rewrite Ha, (dot_sym (Nb s)).
    unfold A_eu, B_eu. field.
Qed.
