(** * Squared.v — squared corrected Euler: corrected Euler (eqs. 15-17)
    applied to g = p²/q instead of f = p/√q.

    Along a span, t ∈ [0, n], p(t) = B + A t = N(t)·L and
    q(t) = E + D t + C t² = N(t)·N(t) (Skip.v's [p], [q]), so Phong's value is
    f = p/√q and its square is g = p²/q, a rational function with no root.
    The squared method runs corrected Euler's recurrence on g: it starts at
    g_a = g(0), takes the end slopes dg_a = g'(0), dg_b = g'(n),
    sds = (dg_b − dg_a)/n and the corrected start slope
    st0 = corr_t0 n g_a g_b dg_a sds (Euler.v), and steps
    sq_i = euler_p g_a st0 sds i. This file proves:

    - [sq_derivative]: g' = p (2 A q − p (D + 2 C t))/q², i.e.
      (2 p p' q − p² q')/q² with p' = A, q' = D + 2 C t, wherever q ≠ 0;
    - [sq_starts_at_ga], [sq_ends_at_gb]: the values are exact at both ends
      (g(0) and g(n), n ≥ 1), from eq. 17 of Euler.v;
    - [sq_closed_form]: sq_i = g_a + i st0 + i (i − 1)/2 · sds (eq. 14);
    - [sq_unit_setup]: with unit normals at both ends (E = q(0) = 1,
      q(n) = 1) the end slopes are dg_a = 2 p_a di_a and dg_b = 2 p_b di_b,
      di the derivative of p/√q at the ends (eqs. 10-11): twice p times
      corrected Euler's slopes;
    - [sq_specular_even], [sq_specular_odd]: the specular power of f from g:
      f^(2m) = g^m, and f^(2m+1) = g^m √g where p ≥ 0;
    - [sq_nonneg_value]: g ≥ 0 where q > 0, and √g = |p|/√q (the diffuse
      term |N·L|/|N| per pixel is √g).

    Code: src/squared_corrected_euler.rs. *)

From Coq Require Import Reals Lra Lia.
From Coquelicot Require Import Coquelicot.
From PhongApprox Require Import Euler Skip.
Open Scope R_scope.

(** g = p²/q and its derivative. *)
Definition g (A B C D E t : R) : R := p A B t ^ 2 / q C D E t.

Definition dg (A B C D E t : R) : R :=
  p A B t * (2 * A * q C D E t - p A B t * (D + 2 * C * t)) / q C D E t ^ 2.

(** The set-up on a span of n steps and the values. *)
Definition ga (A B C D E : R) : R := g A B C D E 0.
Definition gb (A B C D E : R) (n : nat) : R := g A B C D E (INR n).
Definition dga (A B C D E : R) : R := dg A B C D E 0.
Definition dgb (A B C D E : R) (n : nat) : R := dg A B C D E (INR n).
Definition sds (A B C D E : R) (n : nat) : R :=
  (dgb A B C D E n - dga A B C D E) / INR n.
Definition st0 (A B C D E : R) (n : nat) : R :=
  corr_t0 n (ga A B C D E) (gb A B C D E n) (dga A B C D E) (sds A B C D E n).
Definition sq (A B C D E : R) (n i : nat) : R :=
  euler_p (ga A B C D E) (st0 A B C D E n) (sds A B C D E n) i.

(* Note: Any A..E and t with q(t) <> 0. *)
(** g' = (2 p p' q − p² q')/q², p' = A, q' = D + 2 C t. *)
Theorem sq_derivative : forall (A B C D E t : R),
  q C D E t <> 0 -> is_derive (fun x => g A B C D E x) t (dg A B C D E t).
Proof.
  intros A B C D E t Hq. unfold g, dg, p, q in *.
  auto_derive.
  - replace (E + D * t + C * (t * (t * 1))) with (E + D * t + C * t ^ 2) by ring.
    exact Hq.
  - replace (E + D * t + C * (t * (t * 1))) with (E + D * t + C * t ^ 2) by ring.
    field. exact Hq.
Qed.

(* Note: Any A..E, n. *)
(** The first value is g(0). *)
Theorem sq_starts_at_ga : forall (A B C D E : R) (n : nat),
  sq A B C D E n 0 = g A B C D E 0.
Proof.
  intros. unfold sq, st0. apply eq_17_corrected_euler_starts_at_pa.
Qed.

(* Note: Any A..E and n >= 1 (no hypothesis on q). *)
(** The n-th value is g(n). *)
Theorem sq_ends_at_gb : forall (A B C D E : R) (n : nat),
  (0 < n)%nat -> sq A B C D E n n = g A B C D E (INR n).
Proof.
  intros A B C D E n Hn. unfold sq, st0.
  apply (eq_17_corrected_euler_ends_at_pb n _ (gb A B C D E n)). exact Hn.
Qed.

(* Note: Any A..E, n, i. *)
(** eq. 14 for the squared values. *)
Theorem sq_closed_form : forall (A B C D E : R) (n i : nat),
  sq A B C D E n i
  = ga A B C D E + INR i * st0 A B C D E n
    + INR i * (INR i - 1) / 2 * sds A B C D E n.
Proof.
  intros. unfold sq. rewrite eq_14_euler_closed_form. field.
Qed.

(* Note: Unit normals at both ends: E = q(0) = 1 and q(n) = 1; any A..D, n. *)
(** eqs. 10-11: dg_a = 2 p_a di_a, di_a = A − p_a/2 · D, and
    dg_b = 2 p_b di_b, di_b = A − p_b/2 · (2 n C + D). *)
Theorem sq_unit_setup : forall (A B C D E : R) (n : nat),
  E = 1 -> q C D E (INR n) = 1 ->
  let pa := B in
  let pb := p A B (INR n) in
  dga A B C D E = 2 * pa * (A - pa / 2 * D)
  /\ dgb A B C D E n = 2 * pb * (A - pb / 2 * (2 * INR n * C + D)).
Proof.
  intros A B C D E n HE Hqn pa pb. unfold pa, pb, dga, dgb, dg.
  rewrite Hqn. split.
  - unfold p, q. rewrite HE. field.
  - field.
Qed.

Lemma f_sq (A B C D E t : R) : 0 < q C D E t ->
  (p A B t / sqrt (q C D E t)) ^ 2 = g A B C D E t.
Proof.
  intros Hq. unfold g.
  assert (Hs : 0 < sqrt (q C D E t)) by (apply sqrt_lt_R0; exact Hq).
  rewrite <- (sqrt_sqrt (q C D E t)) at 2 by lra. field. lra.
Qed.

(* Note: Any p(t) (no sign condition), q(t) > 0, every m. *)
(** An even specular power of f is a power of g: f^(2m) = g^m. *)
Theorem sq_specular_even : forall (A B C D E t : R) (m : nat),
  0 < q C D E t ->
  (p A B t / sqrt (q C D E t)) ^ (2 * m) = g A B C D E t ^ m.
Proof.
  intros A B C D E t m Hq. rewrite pow_mult, f_sq by exact Hq. reflexivity.
Qed.

(* Note: p(t) >= 0, q(t) > 0, every m. *)
(** An odd specular power: f^(2m+1) = g^m √g. *)
Theorem sq_specular_odd : forall (A B C D E t : R) (m : nat),
  0 <= p A B t -> 0 < q C D E t ->
  (p A B t / sqrt (q C D E t)) ^ (2 * m + 1) = g A B C D E t ^ m * sqrt (g A B C D E t).
Proof.
  intros A B C D E t m Hp Hq.
  assert (Hs : 0 < sqrt (q C D E t)) by (apply sqrt_lt_R0; exact Hq).
  rewrite pow_add, pow_1, sq_specular_even by exact Hq.
  rewrite <- (f_sq A B C D E t Hq), sqrt_pow2; [reflexivity |].
  apply Rdiv_le_0_compat; lra.
Qed.

(* Note: Any p(t), q(t) > 0. *)
(** g ≥ 0 and √g = |p|/√q: the diffuse term |N·L|/|N| is √g. *)
Theorem sq_nonneg_value : forall (A B C D E t : R),
  0 < q C D E t ->
  0 <= g A B C D E t /\ sqrt (g A B C D E t) = Rabs (p A B t) / sqrt (q C D E t).
Proof.
  intros A B C D E t Hq.
  assert (Hs : 0 < sqrt (q C D E t)) by (apply sqrt_lt_R0; exact Hq).
  rewrite <- (f_sq A B C D E t Hq). split.
  - apply pow2_ge_0.
  - rewrite <- Rsqr_pow2, sqrt_Rsqr_abs, Rabs_div by lra.
    rewrite (Rabs_pos_eq (sqrt _)) by lra. reflexivity.
Qed.
