(** * Derivative.v — the derivative of the Phong curve, paper eqs. 9-11
    (uses Coquelicot's [is_derive]). *)

From Coquelicot Require Import Coquelicot.
Require Import Reals Lra Lia.
From PhongApprox Require Import Span.
Open Scope R_scope.

Lemma is_derive_eq : forall (f : R -> R) (x l l' : R),
  is_derive f x l -> l = l' -> is_derive f x l'.
Proof. intros f x l l' H <-. exact H. Qed.

Lemma phong_derive_raw : forall s x, 0 < q s x ->
  is_derive (phong s) x
    ((A s * sqrt (q s x) - p s x * ((2 * C s * x + D s) / (2 * sqrt (q s x))))
       / (sqrt (q s x) * sqrt (q s x))).
Proof.
  intros s x Hq. unfold phong, p, q in *.
  assert (Hs : sqrt (C s * x ^ 2 + D s * x + E s) <> 0)
    by (apply Rgt_not_eq, sqrt_lt_R0; exact Hq).
  auto_derive.
  - simpl in Hs |- *. repeat split; [lra | exact Hs].
  - simpl in Hs |- *. field. exact Hs.
Qed.

(* Note: Wherever q(x) > 0; dp/dx = A and dq/dx = 2 C x + D. *)
(** Paper eq. 9: "di = d/dx (p / sqrt q) = (1 / sqrt q) (dp/dx - p/(2q) dq/dx)". *)
Theorem eq_9_derivative : forall (s : span) (x : R), 0 < q s x ->
  is_derive (phong s) x
    (/ sqrt (q s x) * (A s - p s x / (2 * q s x) * (2 * C s * x + D s))).
Proof.
  intros s x Hq.
  assert (Hs : sqrt (q s x) <> 0) by (apply Rgt_not_eq, sqrt_lt_R0; exact Hq).
  assert (Hsq : sqrt (q s x) * sqrt (q s x) = q s x) by (apply sqrt_sqrt; lra).
  eapply is_derive_eq; [apply phong_derive_raw; exact Hq |].
  remember (sqrt (q s x)) as S. rewrite <- Hsq. field. exact Hs.
Qed.

(* Note: Any span. *)
(** Paper eqs. 10-11: "dp_a = dp_b = A", "dq_a = D", "dq_b = 2nC + D" are the
    derivatives of p and q at x = 0 and x = n. *)
Theorem eq_10_11_dp_dq_at_edges : forall s : span,
  is_derive (p s) 0 (A s) /\ is_derive (p s) (INR (n s)) (A s)
  /\ is_derive (q s) 0 (dqa s) /\ is_derive (q s) (INR (n s)) (dqb s).
Proof.
  intros s. unfold dqa, dqb.
  assert (Hp : forall x, is_derive (p s) x (A s)).
  { intros x. apply (is_derive_ext (fun t => A s * t + B s)); [reflexivity |].
    auto_derive; [exact I | ring]. }
  assert (Hq : forall x, is_derive (q s) x (2 * C s * x + D s)).
  { intros x. apply (is_derive_ext (fun t => C s * t ^ 2 + D s * t + E s));
      [reflexivity |].
    auto_derive; [exact I | ring]. }
  split; [apply Hp | split; [apply Hp | split]]; (eapply is_derive_eq; [apply Hq | ring]).
Qed.

(* Note: Needs unit Na, Nb and n >= 1. *)
(** Paper eqs. 10-11: "q = 1 on the edges, therefore the derivatives at the edges are"
    di_a = A - p_a/2 dq_a and di_b = A - p_b/2 dq_b (eq. 9 at x = 0 and x = n). *)
Theorem eq_10_11_edge_derivatives : forall s : span,
  (0 < n s)%nat -> is_unit (Na s) -> is_unit (Nb s) ->
  is_derive (phong s) 0 (dia s) /\ is_derive (phong s) (INR (n s)) (dib s).
Proof.
  intros s Hn Ha Hb.
  pose proof (INR_n_neq_0 s Hn) as Hn'.
  destruct (eq_10_q_is_one_on_edges s Ha Hb) as [H0 H1].
  split; (eapply is_derive_eq; [apply eq_9_derivative; lra |]).
  - rewrite H0, sqrt_1. unfold dia, dqa, pa, p, B. field.
  - rewrite H1, sqrt_1. unfold dib, dqb, pb, p, A, B, C, D, k, dot, vscale, vsub.
    cbn [vx vy vz]. field. exact Hn'.
Qed.
