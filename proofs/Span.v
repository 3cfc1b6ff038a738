(** * Span.v — the scan-line set-up of Hast, Barrera & Bengtsson,
    "Approximated Phong Shading by using the Euler Method".

    Vectors are component triples over [R]; a span (scan line) goes from the
    normal [Na] to the normal [Nb] in [n] pixel steps under the light [L].
    Division is Coq's total real division ([/ 0 = 0]); whenever a statement
    below carries no [0 < n] hypothesis it has been checked to hold for
    [n = 0] as well under that convention (so it is a strictly stronger
    statement than the one with [n >= 1]). *)

Require Import Reals Lra Lia.
Open Scope R_scope.

(** ** Vectors *)

Record vec := mkV { vx : R ; vy : R ; vz : R }.

Definition dot (u v : vec) : R := vx u * vx v + vy u * vy v + vz u * vz v.
Definition vadd (u v : vec) : vec := mkV (vx u + vx v) (vy u + vy v) (vz u + vz v).
Definition vsub (u v : vec) : vec := mkV (vx u - vx v) (vy u - vy v) (vz u - vz v).
Definition vscale (a : R) (v : vec) : vec := mkV (a * vx v) (a * vy v) (a * vz v).

(** [is_unit v] : [v . v = 1]. *)
Definition is_unit (v : vec) : Prop := dot v v = 1.

(** ** The span *)

Record span := mkSpan { Na : vec ; Nb : vec ; L : vec ; n : nat }.

(** k = (Nb - Na)/n ;  N(x) = Na + x k *)
Definition k (s : span) : vec := vscale (/ INR (n s)) (vsub (Nb s) (Na s)).
Definition N (s : span) (x : R) : vec := vadd (Na s) (vscale x (k s)).

(** eqs. 2-3: A = k.L, B = Na.L, C = k.k, D = 2 k.Na, E = Na.Na *)
Definition A (s : span) : R := dot (k s) (L s).
Definition B (s : span) : R := dot (Na s) (L s).
Definition C (s : span) : R := dot (k s) (k s).
Definition D (s : span) : R := 2 * dot (k s) (Na s).
Definition E (s : span) : R := dot (Na s) (Na s).

(** eq. 4: p(x) = A x + B, q(x) = C x^2 + D x + E, Phong value p / sqrt q *)
Definition p (s : span) (x : R) : R := A s * x + B s.
Definition q (s : span) (x : R) : R := C s * x ^ 2 + D s * x + E s.
Definition phong (s : span) (x : R) : R := p s x / sqrt (q s x).

(** edge values and derivatives, eqs. 10-11 *)
Definition pa (s : span) : R := dot (Na s) (L s).
Definition pb (s : span) : R := dot (Nb s) (L s).
Definition dqa (s : span) : R := D s.
Definition dqb (s : span) : R := 2 * INR (n s) * C s + D s.
Definition dia (s : span) : R := A s - pa s / 2 * dqa s.
Definition dib (s : span) : R := A s - pb s / 2 * dqb s.
Definition ds (s : span) : R := (dib s - dia s) / INR (n s).

Ltac expand :=
  unfold p, q, phong, pa, pb, dqa, dqb, dia, dib, ds, A, B, C, D, E, N, k,
         is_unit, dot, vadd, vsub, vscale in *;
  cbn [vx vy vz] in *.

(** Case split on [n = 0]; in the zero case [/ INR n] becomes [0]. *)
Ltac split_n s :=
  let H0 := fresh "Hn" in
  destruct (Nat.eq_dec (n s) 0) as [H0 | H0];
  [ rewrite ?H0 in *; change (INR 0) with 0 in *; rewrite ?Rinv_0 in *
  | apply not_0_INR in H0 ].

Lemma INR_2 : INR 2 = 2.
Proof. simpl. ring. Qed.
Lemma INR_3 : INR 3 = 3.
Proof. simpl. ring. Qed.

(** Shared by Angle.v and FastSetup.v. *)
Lemma INR_n_neq_0 : forall s, (0 < n s)%nat -> INR (n s) <> 0.
Proof. intros s H. apply not_0_INR. lia. Qed.
Lemma dot_vscale_l : forall (a : R) (u v : vec), dot (vscale a u) v = a * dot u v.
Proof. intros. unfold dot, vscale; cbn [vx vy vz]. ring. Qed.
Lemma dot_vscale_r : forall (a : R) (u v : vec), dot u (vscale a v) = a * dot u v.
Proof. intros. unfold dot, vscale; cbn [vx vy vz]. ring. Qed.
Lemma dot_vadd_r : forall u v w, dot u (vadd v w) = dot u v + dot u w.
Proof. intros. unfold dot, vadd; cbn [vx vy vz]. ring. Qed.

(** Cauchy-Schwarz (Lagrange's identity) and its unit case (Angle.v, Float.v). *)
Lemma cauchy_schwarz_sq : forall u v, (dot u v) ^ 2 <= dot u u * dot v v.
Proof.
  intros [x1 y1 z1] [x2 y2 z2]. unfold dot; cbn [vx vy vz].
  pose proof (pow2_ge_0 (x1 * y2 - y1 * x2)). pose proof (pow2_ge_0 (x1 * z2 - z1 * x2)).
  pose proof (pow2_ge_0 (y1 * z2 - z1 * y2)). lra.
Qed.

Lemma unit_dot_bounds : forall u v, is_unit u -> is_unit v -> -1 <= dot u v <= 1.
Proof.
  intros u v Hu Hv. pose proof (cauchy_schwarz_sq u v) as H.
  unfold is_unit in Hu, Hv. rewrite Hu, Hv in H. split; nra.
Qed.

Lemma cs3 : forall a b : vec, dot a b * dot a b <= dot a a * dot b b.
Proof.
  intros a b. replace (dot a b * dot a b) with (dot a b ^ 2) by ring. apply cauchy_schwarz_sq.
Qed.

(** ** Example spans *)

(** The span of the Mortensen counterexample (Angular.v), also used to show
    that plain Euler misses p_b (Euler.v):
    Na = (3/5, 0, 4/5), Nb = (-3/5, 0, 4/5), L = (0, 0, 1), n = 2. *)
Definition mortensen_span : span :=
  mkSpan (mkV (3/5) 0 (4/5)) (mkV (-3/5) 0 (4/5)) (mkV 0 0 1) 2.

(** A fact of the set-up (norms, p_a, p_b, di_a, ds) of a concrete span [sp], computed. *)
Ltac span_val sp :=
  unfold ds, dib, dia, dqb, dqa, A, C, D, k, is_unit, pa, pb, sp, dot, vscale, vsub;
  cbn [vx vy vz Na Nb L n]; rewrite ?INR_2; field.

(** ** Helper identities (no hypotheses) *)

Lemma k_dot_sum : forall s,
  dot (k s) (Na s) + dot (k s) (Nb s) = (dot (Nb s) (Nb s) - dot (Na s) (Na s)) / INR (n s).
Proof. intros s. expand. unfold Rdiv. ring. Qed.

Lemma nC_expand : forall s,
  INR (n s) * C s =
  (dot (Nb s) (Nb s) - 2 * dot (Na s) (Nb s) + dot (Na s) (Na s)) / INR (n s).
Proof.
  intros s. unfold C, k. split_n s.
  - unfold dot, vscale; cbn [vx vy vz]. unfold Rdiv. rewrite Rinv_0. ring.
  - unfold dot, vscale, vsub; cbn [vx vy vz]. field. exact Hn.
Qed.

Lemma nC_plus_D : forall s,
  INR (n s) * C s + D s = (dot (Nb s) (Nb s) - dot (Na s) (Na s)) / INR (n s).
Proof.
  intros s. rewrite nC_expand. unfold D, k, dot, vscale, vsub; cbn [vx vy vz].
  unfold Rdiv. ring.
Qed.

Lemma dqb_is_2k_nb : forall s, dqb s = 2 * dot (k s) (Nb s).
Proof.
  intros s. unfold dqb. replace (2 * INR (n s) * C s + D s)
    with (2 * (INR (n s) * C s + D s) - D s) by ring.
  rewrite nC_plus_D. unfold D.
  pose proof (k_dot_sum s) as H. lra.
Qed.

Lemma q_at_n : forall s, q s (INR (n s)) = dot (Nb s) (Nb s) \/ (n s = 0%nat /\ q s (INR (n s)) = E s).
Proof.
  intros s. split_n s.
  - right. split; [reflexivity|]. unfold q. ring.
  - left. unfold q, C, D, E, k, dot, vscale, vsub; cbn [vx vy vz]. field. exact Hn.
Qed.

(** ** Claims *)

(** Paper eq. 2: "N . L = A x + B = p" with N = k x + Na; for every real x. *)
Theorem eq_2_p_is_linear : forall (s : span) (x : R),
  dot (N s x) (L s) = A s * x + B s.
Proof. intros. expand. ring. Qed.

(** Paper eq. 3: "N . N = C x^2 + D x + E = q"; for every real x. *)
Theorem eq_3_q_is_quadratic : forall (s : span) (x : R),
  dot (N s x) (N s x) = C s * x ^ 2 + D s * x + E s.
Proof. intros. expand. ring. Qed.

(** Paper after eq. 3: "Note that E = 1, since m = Na has unit length". *)
Theorem eq_3_e_is_one : forall s : span, is_unit (Na s) -> E s = 1.
Proof. intros s H. exact H. Qed.

(* Note: Holds for every n (for n = 0 both edges are Na). *)
(** Paper eq. 10 / §4: "Note that q = 1 on the edges", "q_a = q_b = 1" (unit Na, Nb). *)
Theorem eq_10_q_is_one_on_edges : forall s : span,
  is_unit (Na s) -> is_unit (Nb s) -> q s 0 = 1 /\ q s (INR (n s)) = 1.
Proof.
  intros s Ha Hb. split.
  - unfold q. unfold is_unit in Ha. unfold E. rewrite Ha. ring.
  - destruct (q_at_n s) as [H | [_ H]]; rewrite H; assumption.
Qed.

(* Note: Needs n >= 1: for n = 0 the right edge is Na, not Nb. *)
(** Paper §3 / eq. 4: with normalised edge normals the intensities on the edges are
    correct: p(0)/sqrt q(0) = p_a and p(n)/sqrt q(n) = p_b. *)
Theorem eq_4_phong_exact_on_edges : forall s : span,
  (0 < n s)%nat -> is_unit (Na s) -> is_unit (Nb s) ->
  phong s 0 = pa s /\ phong s (INR (n s)) = pb s.
Proof.
  intros s Hn Ha Hb. destruct (eq_10_q_is_one_on_edges s Ha Hb) as [H0 H1].
  unfold phong. rewrite H0, H1, sqrt_1. split.
  - unfold p, B, pa. field.
  - unfold p, A, B, pb, k, dot, vscale, vsub; cbn [vx vy vz]. field. exact (INR_n_neq_0 s Hn).
Qed.

(* Note: Only |Na| = |Nb| is needed (unit Na, Nb suffice); any n. *)
(** Paper eq. 18: "Na . k = - Nb . k". *)
Theorem eq_18_na_k_is_minus_nb_k : forall s : span,
  dot (Na s) (Na s) = dot (Nb s) (Nb s) ->
  dot (Na s) (k s) = - dot (Nb s) (k s).
Proof.
  intros s H. pose proof (k_dot_sum s) as K. rewrite H in K.
  replace ((dot (Nb s) (Nb s) - dot (Nb s) (Nb s)) / INR (n s)) with 0 in K
    by (unfold Rdiv; ring).
  unfold dot in *. lra.
Qed.

(* Note: Only |Na| = |Nb| is needed; any n. *)
(** Paper eq. 19: "dq_b = 2 n k^2 - 2 k . Nb" (eq. 18 used in D = 2 k . Na). *)
Theorem eq_19_dqb_via_nb : forall s : span,
  dot (Na s) (Na s) = dot (Nb s) (Nb s) ->
  dqb s = 2 * INR (n s) * C s - 2 * dot (k s) (Nb s).
Proof.
  intros s H. pose proof (eq_18_na_k_is_minus_nb_k s H) as H18.
  unfold dqb, D. unfold dot in *. lra.
Qed.

(* Note: Any n; the second equality alone only needs |Na| = |Nb|. *)
(** Paper eq. 20: "n k^2 = 2 (1 - Na . Nb)/n = 2 k . Nb" (unit Na, Nb). *)
Theorem eq_20_n_k2_is_2k_nb : forall s : span,
  is_unit (Na s) -> is_unit (Nb s) ->
  INR (n s) * C s = 2 * (1 - dot (Na s) (Nb s)) / INR (n s)
  /\ INR (n s) * C s = 2 * dot (k s) (Nb s).
Proof.
  intros s Ha Hb. unfold is_unit in *. rewrite nC_expand, Ha, Hb. split.
  - unfold Rdiv. ring.
  - assert (K : 2 * dot (k s) (Nb s)
                 = 2 * (dot (Nb s) (Nb s) - dot (Na s) (Nb s)) / INR (n s))
      by (unfold k, dot, vscale, vsub; cbn [vx vy vz]; unfold Rdiv; ring).
    rewrite K, Hb. unfold Rdiv. ring.
Qed.

(* Note: TRUE FOR EVERY SPAN, with no assumption at all: the paper derives it from unit normals, but
   2 n C + D = 2 k . (n k + Na) = 2 k . Nb for any Na, Nb, L and any n. *)
(** Paper eq. 21: "dq_b = 4 k . Nb - 2 k . Nb = 2 k . Nb". *)
Theorem eq_21_dqb_is_2k_nb : forall s : span, dqb s = 2 * dot (k s) (Nb s).
Proof. exact dqb_is_2k_nb. Qed.

(* Note: Only |Na| = |Nb| is needed; any n. *)
(** Paper eq. 22 / §3.2: "dq_b = -2 k . Na", i.e. "we will prove that dq_b = -dq_a". *)
Theorem eq_22_dqb_is_minus_dqa : forall s : span,
  dot (Na s) (Na s) = dot (Nb s) (Nb s) -> dqb s = - dqa s.
Proof.
  intros s H. rewrite dqb_is_2k_nb. unfold dqa, D.
  pose proof (eq_18_na_k_is_minus_nb_k s H) as H18. unfold dot in *. lra.
Qed.

(* Note: Only |Na| = |Nb| is needed; any n. *)
(** Paper eqs. 10-11 with eq. 22: ds = (di_b - di_a)/n = D (p_a + p_b)/(2 n). *)
Theorem eq_11_ds_closed_form : forall s : span,
  dot (Na s) (Na s) = dot (Nb s) (Nb s) ->
  ds s = D s * (pa s + pb s) / (2 * INR (n s)).
Proof.
  intros s H. unfold ds, dib, dia. rewrite (eq_22_dqb_is_minus_dqa s H).
  unfold dqa. split_n s.
  - unfold Rdiv. rewrite Rmult_0_r, Rinv_0. ring.
  - field. exact Hn.
Qed.
