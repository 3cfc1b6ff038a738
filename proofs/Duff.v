(** * Duff.v — Duff's forward-difference recurrence, paper eqs. 5-7. *)

Require Import Reals Lra Lia.
From PhongApprox Require Import Span.
Open Scope R_scope.

(** State (p_i, q_i, dq_i) of the recurrence. *)
Record dstate := mkD { d_p : R ; d_q : R ; d_dq : R }.

(** eqs. 5-7 with p_0 = B, dp = A, q_0 = E, dq_0 = C + D, d2q = 2 C:
    p_{i+1} = p_i + A ; q_{i+1} = q_i + dq_i ; dq_{i+1} = dq_i + 2 C. *)
Fixpoint duff (A B C D E : R) (i : nat) : dstate :=
  match i with
  | O => mkD B E (C + D)
  | S j => let st := duff A B C D E j in
           mkD (d_p st + A) (d_q st + d_dq st) (d_dq st + 2 * C)
  end.

(** The recurrence instantiated with a span's coefficients. *)
Definition duff_span (s : span) (i : nat) : dstate :=
  duff (A s) (B s) (C s) (D s) (E s) i.

(* Note: Stated for arbitrary coefficients A..E, every i. *)
(** Paper eqs. 5-7: Duff's recurrence gives p_i = A i + B, q_i = C i^2 + D i + E
    (and dq_i = C (2i + 1) + D) exactly. *)
Theorem eq_5_7_duff_recurrence_exact : forall (A B C D E : R) (i : nat),
  d_p (duff A B C D E i) = A * INR i + B
  /\ d_q (duff A B C D E i) = C * INR i ^ 2 + D * INR i + E
  /\ d_dq (duff A B C D E i) = C * (2 * INR i + 1) + D.
Proof.
  intros A B C D E i. induction i as [| i [H1 [H2 H3]]].
  - cbn [duff d_p d_q d_dq INR]. repeat split; ring.
  - cbn [duff d_p d_q d_dq]. rewrite H1, H2, H3, S_INR. repeat split; ring.
Qed.

(* Note: First forward difference C (2x+1) + D, = C + D at x = 0; second difference 2 C. *)
(** Paper §2.1 after eq. 7: "dq_0 = C + D and d^2q = 2C" are the forward differences
    of q(x) = C x^2 + D x + E. *)
Theorem eq_7_duff_dq0_and_d2q : forall (C D E x : R),
  let qf := fun y => C * y ^ 2 + D * y + E in
  qf (x + 1) - qf x = C * (2 * x + 1) + D
  /\ qf 1 - qf 0 = C + D
  /\ (qf (x + 2) - qf (x + 1)) - (qf (x + 1) - qf x) = 2 * C.
Proof. intros C D E x qf. unfold qf. repeat split; ring. Qed.

(** Paper §2.1: Duff's p_i, q_i are N(i).L and N(i).N(i), so "I_d = p/sqrt q" is
    the Phong value at pixel i. *)
Theorem eq_5_7_duff_computes_phong : forall (s : span) (i : nat),
  d_p (duff_span s i) = dot (N s (INR i)) (L s)
  /\ d_q (duff_span s i) = dot (N s (INR i)) (N s (INR i))
  /\ d_p (duff_span s i) / sqrt (d_q (duff_span s i)) = phong s (INR i).
Proof.
  intros s i. unfold duff_span.
  destruct (eq_5_7_duff_recurrence_exact (A s) (B s) (C s) (D s) (E s) i)
    as [H1 [H2 _]].
  rewrite H1, H2, eq_2_p_is_linear, eq_3_q_is_quadratic.
  split; [reflexivity | split; [reflexivity |]]. unfold phong, p, q. reflexivity.
Qed.
