(** * Related.v — claims of the related-work methods (Bishop & Weimer, Seiler,
    Kuijk & Blake, Ouyang & Maynard, Mortensen's vertex angles).

    Code: [src/related/*.rs]; tests of the same names: [tests/related.rs];
    discussion: [docs/comparison.md]. *)

From Coquelicot Require Import Coquelicot.
Require Import Reals Lra Lia.
From PhongApprox Require Import Euler.
Open Scope R_scope.

(** ** Forward differences of quadratics

    [forward_differences] in [src/related/triangle.rs] runs
    [I += dI; dI += ddI]: Euler's recurrence of eqs. 12-13 ([euler_p],
    Euler.v) with [p_0 = I], [s_0 = dI], [ds = ddI]. *)

(** [A x^2 + B x y + C y^2 + D x + E y + F]: Seiler's [Quadratic] (fields
    [a..f]) and Bishop & Weimer's [Taylor] with
    [(A, B, C, D, E, F) = (T5, T4, T3, T2, T1, T0)]. *)
Definition quad2 (A B C D E F x y : R) : R :=
  A * x ^ 2 + B * x * y + C * y ^ 2 + D * x + E * y + F.

(* Note: Any coefficients, any row y, any start x0, every pixel j. *)
(** Bishop & Weimer: "two additions per pixel" along a scan line give the
    second-order Taylor polynomial exactly, starting from
    [dI = T5 (2 x0 + 1) + T4 y + T2] and [ddI = 2 T5] ([Taylor::shade_row]). *)
Theorem bishop_weimer_forward_differences_are_exact :
  forall (T0 T1 T2 T3 T4 T5 x0 y : R) (j : nat),
  euler_p (quad2 T5 T4 T3 T2 T1 T0 x0 y) (T5 * (2 * x0 + 1) + T4 * y + T2)
    (2 * T5) j
  = quad2 T5 T4 T3 T2 T1 T0 (x0 + INR j) y.
Proof. intros. rewrite eq_14_euler_closed_form. unfold quad2. field. Qed.

(* Note: Any coefficients, any row y, any start x0, every pixel j. *)
(** Seiler: the six-point quadratic, written as [A x^2 + ... + F], is evaluated
    exactly by forward differences along a row ([Quadratic::shade_row]). *)
Theorem seiler_forward_differences_are_exact :
  forall (A B C D E F x0 y : R) (j : nat),
  euler_p (quad2 A B C D E F x0 y) (A * (2 * x0 + 1) + B * y + D) (2 * A) j
  = quad2 A B C D E F (x0 + INR j) y.
Proof. intros. apply bishop_weimer_forward_differences_are_exact. Qed.

(** ** Bishop & Weimer along one span *)

(** The span's Phong curve with unit [N_a] ([E = 1]), eqs. 2-4. *)
Definition bw_f (A B C D x : R) : R :=
  (A * x + B) / sqrt (C * x ^ 2 + D * x + 1).

(** Its derivative, eq. 9 with [E = 1]. *)
Definition bw_df (A B C D x : R) : R :=
  / sqrt (C * x ^ 2 + D * x + 1)
  * (A - (A * x + B) / (2 * (C * x ^ 2 + D * x + 1)) * (2 * C * x + D)).

(* Note: E = 1 (unit N_a); bw_df is the derivative of bw_f wherever q > 0,
   which holds on a neighbourhood of 0 since q(0) = 1. *)
(** Bishop & Weimer's scan-line case, expanded about the span's left edge:
    "[B + (A - BD/2) x + (3BD^2/8 - BC/2 - AD/2) x^2]" — the value, the first
    derivative and half the second derivative at 0 ([Taylor::from_span_at]). *)
Theorem bishop_weimer_scanline_special_case : forall A B C D : R,
  bw_f A B C D 0 = B
  /\ (forall x, 0 < C * x ^ 2 + D * x + 1 -> is_derive (bw_f A B C D) x (bw_df A B C D x))
  /\ bw_df A B C D 0 = A - B * D / 2
  /\ is_derive (bw_df A B C D) 0
       (2 * (3 * B * D ^ 2 / 8 - B * C / 2 - A * D / 2)).
Proof.
  intros A B C D.
  assert (H0 : C * 0 ^ 2 + D * 0 + 1 = 1) by ring.
  split; [| split; [| split]].
  - unfold bw_f. rewrite H0, sqrt_1. field.
  - intros x Hq. unfold bw_f, bw_df.
    assert (Hs : sqrt (C * x ^ 2 + D * x + 1) <> 0)
      by (apply Rgt_not_eq, sqrt_lt_R0; exact Hq).
    assert (Hsq : sqrt (C * x ^ 2 + D * x + 1) * sqrt (C * x ^ 2 + D * x + 1)
                  = C * x ^ 2 + D * x + 1) by (apply sqrt_sqrt; lra).
    auto_derive.
    + simpl. repeat split; [lra | exact Hs].
    + simpl.
      replace (C * (x * (x * 1)) + D * x + 1) with (C * x ^ 2 + D * x + 1) by ring.
      set (Q := C * x ^ 2 + D * x + 1) in *. set (S := sqrt Q) in *.
      rewrite <- Hsq. field. exact Hs.
  - unfold bw_df. rewrite H0, sqrt_1. field.
  - unfold bw_df. auto_derive; simpl; replace (C * (0 * (0 * 1)) + D * 0 + 1) with 1 by ring;
      rewrite sqrt_1; [repeat split; lra | field].
Qed.

(** ** Seiler's six-point quadratic *)

(** The six-node Lagrange element in barycentric coordinates [l1], [l2],
    [l3 = 1 - l1 - l2]: vertex values [v1 v2 v3], edge-midpoint values [m12 m23
    m31] ([Quadratic::from_six]). *)
Definition seiler (v1 v2 v3 m12 m23 m31 l1 l2 : R) : R :=
  let l3 := 1 - l1 - l2 in
  v1 * l1 * (2 * l1 - 1) + v2 * l2 * (2 * l2 - 1) + v3 * l3 * (2 * l3 - 1)
  + 4 * m12 * l1 * l2 + 4 * m23 * l2 * l3 + 4 * m31 * l3 * l1.

(* Note: Any six values. *)
(** Seiler: the quadratic "takes the exact intensity at the three vertices and the
    three edge midpoints". *)
Theorem seiler_is_exact_at_the_six_points : forall v1 v2 v3 m12 m23 m31 : R,
  seiler v1 v2 v3 m12 m23 m31 1 0 = v1
  /\ seiler v1 v2 v3 m12 m23 m31 0 1 = v2
  /\ seiler v1 v2 v3 m12 m23 m31 0 0 = v3
  /\ seiler v1 v2 v3 m12 m23 m31 (1 / 2) (1 / 2) = m12
  /\ seiler v1 v2 v3 m12 m23 m31 0 (1 / 2) = m23
  /\ seiler v1 v2 v3 m12 m23 m31 (1 / 2) 0 = m31.
Proof.
  intros. unfold seiler. repeat split; field.
Qed.

(* Note: Any triangle (x_i, y_i), any quadratic g in screen coordinates, any point
   l1 P1 + l2 P2 + (1 - l1 - l2) P3 of the plane. *)
(** The six-point quadratic of a quadratic [g] is [g] everywhere: fed [g] at the
    vertices and edge midpoints, it returns [g] at every point of the plane. *)
Theorem seiler_reproduces_quadratics :
  forall (A B C D E F x1 y1 x2 y2 x3 y3 l1 l2 : R),
  let g := fun x y => quad2 A B C D E F x y in
  let l3 := 1 - l1 - l2 in
  seiler (g x1 y1) (g x2 y2) (g x3 y3)
    (g ((x1 + x2) / 2) ((y1 + y2) / 2))
    (g ((x2 + x3) / 2) ((y2 + y3) / 2))
    (g ((x3 + x1) / 2) ((y3 + y1) / 2)) l1 l2
  = g (l1 * x1 + l2 * x2 + l3 * x3) (l1 * y1 + l2 * y2 + l3 * y3).
Proof.
  intros. unfold g, l3, seiler, quad2. field.
Qed.

(** ** Kuijk & Blake: the Chebyshev recurrence *)

(** [N(kΔ)·L = (u·L) cos(kΔ) + (w·L) sin(kΔ)] ([spherical::at]). *)
Definition sph (uL wL d : R) (k : nat) : R := uL * cos (INR k * d) + wL * sin (INR k * d).

(** [(I_k, I_{k+1})] after [k] steps of [I_{k+1} = 2 cos Δ I_k - I_{k-1}]
    ([spherical::shade]). *)
Fixpoint cheb (i0 i1 c : R) (k : nat) : R * R :=
  match k with
  | O => (i0, i1)
  | S j => let (a, b) := cheb i0 i1 c j in (b, 2 * c * b - a)
  end.

Lemma sph_step : forall uL wL d k,
  sph uL wL d (S (S k)) = 2 * cos d * sph uL wL d (S k) - sph uL wL d k.
Proof.
  intros. unfold sph.
  replace (INR (S (S k)) * d) with (INR (S k) * d + d)
    by (rewrite (S_INR (S k)); ring).
  replace (INR k * d) with (INR (S k) * d - d) by (rewrite S_INR; ring).
  rewrite cos_plus, sin_plus, cos_minus, sin_minus. ring.
Qed.

(* Note: Any u·L, w·L and step Δ; every pixel k. *)
(** Kuijk & Blake: "one multiplication and one subtraction per pixel", the
    recurrence [I_{k+1} = 2 cos Δ I_k - I_{k-1}] from [I_0 = u·L],
    [I_1 = (u·L) cos Δ + (w·L) sin Δ], gives the sinusoid exactly. *)
Theorem spherical_recurrence_matches_closed_form : forall (uL wL d : R) (k : nat),
  fst (cheb uL (uL * cos d + wL * sin d) (cos d) k) = sph uL wL d k.
Proof.
  intros uL wL d k.
  assert (Hpair : forall j, cheb uL (uL * cos d + wL * sin d) (cos d) j
                            = (sph uL wL d j, sph uL wL d (S j))).
  { induction j as [| j IH].
    - unfold sph. simpl. rewrite Rmult_0_l, Rmult_1_l, cos_0, sin_0. f_equal; ring.
    - simpl. rewrite IH. f_equal. symmetry. apply sph_step. }
  rewrite Hpair. reflexivity.
Qed.

(* Note: u, w orthonormal, N_a = u, N_b = cos Ω u + sin Ω w, 0 <= Ω < π; then
   N_a·L = u·L, N_b·L = cos Ω (u·L) + sin Ω (w·L), |N_a + N_b|^2 = 2 + 2 cos Ω. *)
(** Spherical interpolation equals Phong's normalized linear interpolation at the
    middle of the span: [(N_a + N_b)/|N_a + N_b| · L = N(Ω/2)·L]. The same fact
    makes binary interpolation exact at the whole span's midpoint
    ([binary_exact_at_ends_and_whole_span_midpoint]). *)
Theorem spherical_equals_phong_at_the_middle : forall uL wL W : R,
  0 <= W < PI ->
  (uL + (cos W * uL + sin W * wL)) / sqrt (2 + 2 * cos W)
  = uL * cos (W / 2) + wL * sin (W / 2).
Proof.
  intros uL wL W [H0 Hpi].
  set (h := W / 2).
  assert (HW : W = 2 * h) by (unfold h; field).
  assert (Hc : 0 < cos h) by (apply cos_gt_0; unfold h; lra).
  assert (Hq : 2 + 2 * cos W = (2 * cos h) ^ 2).
  { rewrite HW, cos_2a_cos. ring. }
  rewrite Hq, sqrt_pow2 by lra.
  rewrite HW, cos_2a_cos, sin_2a. field. lra.
Qed.

(** ** Mortensen's vertex angles *)

(* Note: Any barycentric l1, l2 and any common vertex angle a. *)
(** The failure case of interpolating the vertex angles over the polygon: when
    the three vertex angles are equal, every pixel gets their cosine — the
    polygon is flat whatever its normals. *)
Theorem vertex_angle_equal_angles_give_a_flat_polygon : forall a l1 l2 : R,
  cos (l1 * a + l2 * a + (1 - l1 - l2) * a) = cos a.
Proof.
  intros. f_equal. ring.
Qed.
