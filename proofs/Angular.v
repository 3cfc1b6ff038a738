(** * Angular.v — the second source (Mortensen, "linear interpolation of
    angles"): "The angle between the light vector and the normal vector ...
    changes in a linear fashion ... from one edge of the plane to the next
    across each scanline."  Refuted for Phong shading (interpolated normals). *)

Require Import Reals Lra Lia.
From PhongApprox Require Import Span.
Open Scope R_scope.

(** Angle interpolation across the span: cos(alpha_a + i/n (alpha_b - alpha_a))
    with alpha = acos(N.L) at the (unit) edge normals. *)
Definition angle_interp (s : span) (i : nat) : R :=
  cos (acos (pa s) + INR i / INR (n s) * (acos (pb s) - acos (pa s))).

Definition mortensen_span2 : span :=
  mkSpan (mkV 0 0 1) (mkV 1 0 0) (mkV 0 0 1) 3.

Lemma mortensen_phong_1 : phong mortensen_span 1 = 1.
Proof.
  unfold phong, p, q, A, B, C, D, E, k, mortensen_span, dot, vscale, vsub.
  cbn [vx vy vz Na Nb L n]. rewrite INR_2.
  match goal with |- ?a / sqrt ?b = 1 =>
    replace b with ((4/5) * (4/5)) by field;
    replace a with (4/5) by field end.
  rewrite sqrt_square by lra. field.
Qed.

(* Note: Na = (3/5,0,4/5), Nb = (-3/5,0,4/5), L = (0,0,1), n = 2: p_a = p_b = 4/5, so
   angle interpolation is the constant 4/5, but the Phong value at pixel 1 is 1. *)
(** Mortensen: "The angle between the light vector and the normal vector ... changes in
    a linear fashion ... across each scanline" -- refuted (equal end angles). *)
Theorem mortensen_equal_angles_counterexample :
  let s := mortensen_span in
  is_unit (Na s) /\ is_unit (Nb s) /\ pa s = 4/5 /\ pb s = 4/5
  /\ (forall i : nat, angle_interp s i = 4/5)
  /\ phong s 1 = 1 /\ phong s 1 <> angle_interp s 1.
Proof.
  cbv zeta.
  assert (Hpa : pa mortensen_span = 4/5) by span_val mortensen_span.
  assert (Hpb : pb mortensen_span = 4/5) by span_val mortensen_span.
  assert (Hai : forall i : nat, angle_interp mortensen_span i = 4/5).
  { intros i. unfold angle_interp. rewrite Hpa, Hpb.
    replace (acos (4/5) + INR i / INR (n mortensen_span) * (acos (4/5) - acos (4/5)))
      with (acos (4/5)) by ring.
    apply cos_acos. lra. }
  repeat split; try assumption; try span_val mortensen_span.
  - exact mortensen_phong_1.
  - rewrite mortensen_phong_1, Hai. lra.
Qed.

(* Note: On the span above the true angle acos(phong(i)) is acos(4/5), 0, acos(4/5)
   at i = 0, 1, 2: the middle angle is not the average of the end angles. *)
(** Mortensen: the angle between N and L "changes in a linear fashion" -- refuted:
    the true Phong angle is not linear in the pixel index. *)
Theorem mortensen_angle_not_linear :
  let s := mortensen_span in
  acos (phong s 0) = acos (4/5) /\ acos (phong s 2) = acos (4/5)
  /\ acos (phong s 1) = 0
  /\ acos (phong s 1) <> (acos (phong s 0) + acos (phong s 2)) / 2.
Proof.
  cbv zeta.
  assert (Ha : is_unit (Na mortensen_span)) by span_val mortensen_span.
  assert (Hb : is_unit (Nb mortensen_span)) by span_val mortensen_span.
  assert (Hn : (0 < n mortensen_span)%nat) by (cbn; lia).
  destruct (eq_4_phong_exact_on_edges mortensen_span Hn Ha Hb) as [H0 H2].
  assert (Hpa : pa mortensen_span = 4/5) by span_val mortensen_span.
  assert (Hpb : pb mortensen_span = 4/5) by span_val mortensen_span.
  cbn [n mortensen_span] in H2. rewrite INR_2 in H2.
  rewrite H0, H2, Hpa, Hpb, mortensen_phong_1, acos_1.
  pose proof (acos_bound_lt (4/5) ltac:(lra)) as Hpos.
  repeat split; lra.
Qed.

(* Note: Na = L = (0,0,1), Nb = (1,0,0), n = 3 (end angles 0 and pi/2): angle
   interpolation at pixel 1 gives cos(pi/6) = sqrt 3/2, Phong gives (2/3)/sqrt(5/9) = 2/sqrt 5. *)
(** Mortensen: "Angular interpolation is correct in 99% of all possible cases. The only
    cases when it will not be correct is when the angles ... are equal" -- refuted. *)
Theorem mortensen_unequal_angles_counterexample :
  let s := mortensen_span2 in
  is_unit (Na s) /\ is_unit (Nb s) /\ pa s = 1 /\ pb s = 0
  /\ angle_interp s 1 = sqrt 3 / 2
  /\ phong s 1 = (2/3) / sqrt (5/9)
  /\ phong s 1 <> angle_interp s 1.
Proof.
  cbv zeta.
  assert (Hpa : pa mortensen_span2 = 1) by span_val mortensen_span2.
  assert (Hpb : pb mortensen_span2 = 0) by span_val mortensen_span2.
  assert (Hai : angle_interp mortensen_span2 1 = sqrt 3 / 2).
  { unfold angle_interp. rewrite Hpa, Hpb, acos_1, acos_0.
    cbn [n mortensen_span2]. rewrite INR_3.
    replace (0 + INR 1 / 3 * (PI / 2 - 0)) with (PI / 6) by (simpl; field).
    exact cos_PI6. }
  assert (Hph : phong mortensen_span2 1 = (2/3) / sqrt (5/9)).
  { unfold phong, p, q, A, B, C, D, E, k, mortensen_span2, dot, vscale, vsub.
    cbn [vx vy vz Na Nb L n]. rewrite INR_3.
    match goal with |- ?a / sqrt ?b = _ =>
      replace b with (5/9) by field; replace a with (2/3) by field end.
    reflexivity. }
  repeat split; try assumption; [span_val mortensen_span2.. |].
  rewrite Hph, Hai. intros Heq.
  assert (Ha : 0 < sqrt (5/9)) by (apply sqrt_lt_R0; lra).
  assert (Ha2 : sqrt (5/9) * sqrt (5/9) = 5/9) by (apply sqrt_sqrt; lra).
  assert (Hb2 : sqrt 3 * sqrt 3 = 3) by (apply sqrt_sqrt; lra).
  assert (Hab : sqrt (5/9) * sqrt 3 = 4/3).
  { apply (f_equal (fun t => t * sqrt (5/9) * 2)) in Heq.
    field_simplify in Heq; [| lra]. lra. }
  nra.
Qed.
