(** * Symmetry.v — §4 "Symmetry of the Normalization". *)

Require Import Reals Lra Lia.
From PhongApprox Require Import Span Duff.
Open Scope R_scope.

(** With |Na| = |Nb|, C n + D = 0 (any n). *)
Lemma Cn_plus_D_zero : forall s,
  dot (Na s) (Na s) = dot (Nb s) (Nb s) -> C s * INR (n s) + D s = 0.
Proof.
  intros s H. pose proof (nC_plus_D s) as K. rewrite H in K.
  replace ((dot (Nb s) (Nb s) - dot (Nb s) (Nb s)) / INR (n s)) with 0 in K
    by (unfold Rdiv; ring).
  lra.
Qed.

Lemma q_diff : forall s x,
  q s x - q s (INR (n s) - x) = (2 * x - INR (n s)) * (C s * INR (n s) + D s).
Proof. intros. unfold q. ring. Qed.

(* Note: Only |Na| = |Nb| is needed (unit Na, Nb suffice); any n. *)
(** Paper §4: q is "a quadratic curve ... with same values at the edges and with the
    extreme point in the middle ... such a curve must be symmetric": q(x) = q(n - x). *)
Theorem sec_4_q_is_symmetric : forall (s : span) (x : R),
  dot (Na s) (Na s) = dot (Nb s) (Nb s) -> q s x = q s (INR (n s) - x).
Proof.
  intros s x H. pose proof (q_diff s x) as K. rewrite (Cn_plus_D_zero s H) in K.
  lra.
Qed.

(* Note: Two readings, both true when |Na| = |Nb| (any n):
   (1) the derivative q'(x) = 2 C x + D vanishes at the real mid point x = n/2;
   (2) Duff's discrete step dq_i = q_{i+1} - q_i = C (2i + 1) + D (eq. 7) vanishes at
       i = (n - 1)/2, half a pixel BEFORE the middle: a pixel index only for odd n
       (for even n no Duff step is exactly 0). *)
(** Paper §4: "dq_b = -dq_a. This means that dq = 0 in the middle of the scan line
    since the derivative of q is a straight line." *)
Theorem sec_4_dq_zero_at_middle : forall s : span,
  dot (Na s) (Na s) = dot (Nb s) (Nb s) ->
  2 * C s * (INR (n s) / 2) + D s = 0
  /\ C s * (2 * ((INR (n s) - 1) / 2) + 1) + D s = 0.
Proof.
  intros s H. pose proof (Cn_plus_D_zero s H) as K. split; rewrite <- K; field.
Qed.

(* Note: |Na| = |Nb|; q(x) = q(n/2) + C (x - n/2)^2 and C = k.k >= 0, so it is a minimum. *)
(** Paper §4: q has "the extreme point in the middle of the scan line". *)
Theorem sec_4_q_minimum_at_middle : forall (s : span) (x : R),
  dot (Na s) (Na s) = dot (Nb s) (Nb s) ->
  q s x = q s (INR (n s) / 2) + C s * (x - INR (n s) / 2) ^ 2
  /\ q s (INR (n s) / 2) <= q s x.
Proof.
  intros s x H. pose proof (Cn_plus_D_zero s H) as K.
  assert (Hc : 0 <= C s) by (unfold C, dot; nra).
  assert (Hid : q s x = q s (INR (n s) / 2) + C s * (x - INR (n s) / 2) ^ 2).
  { unfold q. replace (D s) with (- (C s * INR (n s))) by lra. field. }
  split; [exact Hid |].
  rewrite Hid. assert (0 <= C s * (x - INR (n s) / 2) ^ 2) by (apply Rmult_le_pos; [lra | apply pow2_ge_0]).
  lra.
Qed.

(* Note: Only |Na| = |Nb| is needed. *)
(** Paper §4: "we only need to compute sqrt q for the first half of the scan line":
    p(i)/sqrt q(n - i) = p(i)/sqrt q(i) for every pixel i <= n. *)
Theorem sec_4_symmetric_phong_equals_phong : forall (s : span) (i : nat),
  dot (Na s) (Na s) = dot (Nb s) (Nb s) -> (i <= n s)%nat ->
  p s (INR i) / sqrt (q s (INR (n s - i))) = phong s (INR i).
Proof.
  intros s i H Hi. unfold phong. rewrite minus_INR by exact Hi.
  rewrite <- (sec_4_q_is_symmetric s (INR i) H). reflexivity.
Qed.

(* Note: |Na| = |Nb|; pixels i <= n. *)
(** Paper §4: "we do not have to compute q for the whole scan line since we can
    reuse these values for the second part": Duff's q_{n-i} = q_i. *)
Theorem sec_4_duff_q_is_symmetric : forall (s : span) (i : nat),
  dot (Na s) (Na s) = dot (Nb s) (Nb s) -> (i <= n s)%nat ->
  d_q (duff_span s (n s - i)) = d_q (duff_span s i).
Proof.
  intros s i H Hi. unfold duff_span.
  destruct (eq_5_7_duff_recurrence_exact (A s) (B s) (C s) (D s) (E s) (n s - i))
    as [_ [H1 _]].
  destruct (eq_5_7_duff_recurrence_exact (A s) (B s) (C s) (D s) (E s) i)
    as [_ [H2 _]].
  rewrite H1, H2, minus_INR by exact Hi.
  pose proof (sec_4_q_is_symmetric s (INR i) H) as K. unfold q in K.
  rewrite K. reflexivity.
Qed.
