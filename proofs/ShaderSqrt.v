(** * ShaderSqrt.v — the shader profile's square root, 1/inverseSqrt(x).

    Under the [shader] profile (binary32, u = 2^-24) a square root is
    computed as the reciprocal of inverseSqrt: r = inverseSqrt(x) is within
    2 ulps of 1/sqrt(x), so |r - 1/sqrt x| <= 4u |1/sqrt x| for a result in
    the normal range, and y = 1/r is a GPU division within 2.5 ulps, so
    |y - 1/r| <= 5u |1/r|.  Writing r = (1 + d1)/sqrt x and y = (1 + d2)/r,
    y/sqrt x - 1 = (d2 - d1)/(1 + d1), of size at most 9u/(1 - 4u), which is
    at most (9 + 2^-18) u for every u <= 2^-24: the crate's kappa_sqrt.

    Both results are in the normal range here (eta = 0): the absolute term
    of a flushed subnormal result (the model's eta) is not part of these
    statements. *)

From Coq Require Import Reals Lra.
From PhongApprox Require Import FloatModelK.
Open Scope R_scope.

(** Relative form, for any unit roundoff u <= 2^-24 (binary32: u = 2^-24). *)
Theorem shader_sqrt_recip_rsqrt : forall u x r y,
  0 <= u <= / 16777216 -> 0 < x ->
  Rabs (r - / sqrt x) <= 4 * u * Rabs (/ sqrt x) ->
  Rabs (y - / r) <= 5 * u * Rabs (/ r) ->
  Rabs (y - sqrt x) <= (9 + / 262144) * u * sqrt x.
Proof.
  intros u x r y Hu Hx Hr Hy.
  assert (Hs : 0 < sqrt x) by (apply sqrt_lt_R0; lra).
  set (s := sqrt x) in *.
  assert (Ha : 0 < / s) by (apply Rinv_0_lt_compat; lra).
  rewrite (Rabs_pos_eq (/ s)) in Hr by lra.
  assert (Hr0 : (1 - 4 * u) * / s <= r) by
    (pose proof (Rabs_minus_sym r (/ s)); pose proof (Rle_abs (/ s - r)); lra).
  assert (Hrp : 0 < r) by nra.
  rewrite (Rabs_pos_eq (/ r)) in Hy by (apply Rlt_le, Rinv_0_lt_compat; lra).
  (* /r - s = s (/s - r) / r *)
  assert (E : / r - s = s * (/ s - r) * / r) by (field; lra).
  assert (Hd : Rabs (/ r - s) <= 4 * u * / r).
  { rewrite E, !Rabs_mult, (Rabs_pos_eq s), (Rabs_pos_eq (/ r)) by
      (try apply Rlt_le, Rinv_0_lt_compat; lra).
    rewrite Rabs_minus_sym.
    replace (4 * u * / r) with (s * (4 * u * / s) * / r) by (field; lra).
    apply Rmult_le_compat_r; [apply Rlt_le, Rinv_0_lt_compat; lra |].
    apply Rmult_le_compat_l; lra. }
  (* 1/r <= s/(1 - 4u) *)
  assert (Hinv : / r <= s / (1 - 4 * u)).
  { unfold Rdiv. replace s with (/ / s) at 1 by (field; lra).
    rewrite <- Rinv_mult. apply Rinv_le_contravar; [| lra].
    apply Rmult_lt_0_compat; lra. }
  replace (y - s) with ((y - / r) + (/ r - s)) by ring.
  eapply Rle_trans; [apply Rabs_triang |].
  apply Rle_trans with (9 * u * (s / (1 - 4 * u))).
  { assert (0 <= u * / r) by (apply Rmult_le_pos; [lra |
      apply Rlt_le, Rinv_0_lt_compat; lra]). nra. }
  unfold Rdiv.
  replace (9 * u * (s * / (1 - 4 * u))) with (u * s * (9 / (1 - 4 * u))) by (field; lra).
  replace ((9 + / 262144) * u * s) with (u * s * (9 + / 262144)) by ring.
  apply Rmult_le_compat_l; [apply Rmult_le_pos; lra |].
  apply Rle_trans with (9 * / (1 - 4 * u)); [lra |].
  apply Rmult_le_reg_r with (1 - 4 * u); [lra |].
  rewrite Rmult_assoc, Rinv_l by lra. nra.
Qed.

(** The same in [ap1] form (FloatModelK.v), eta = 0 (normal results). *)
Theorem shader_sqrt_recip_rsqrt_ap1 : forall u x r y,
  0 <= u <= / 16777216 -> 0 < x ->
  ap1 (4 * u) 0 r (/ sqrt x) -> ap1 (5 * u) 0 y (/ r) ->
  ap1 ((9 + / 262144) * u) 0 y (sqrt x).
Proof.
  unfold ap1. intros u x r y Hu Hx Hr Hy. rewrite Rplus_0_r in *.
  rewrite (Rabs_pos_eq (sqrt x)) by apply sqrt_pos.
  apply (shader_sqrt_recip_rsqrt u x r y); assumption.
Qed.
