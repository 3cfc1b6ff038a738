(** * FastSetup.v — a cheap per-row set-up for corrected Euler and Phong, forward
    differences down a polygon edge, and one Newton step for 1/sqrt.

    Hast, Barrera & Bengtsson, "Approximated Phong Shading by using the Euler
    Method". With unit edge normals every quantity of a span reduces to three
    numbers: c = Na . Nb, p_a and p_b (see ClosedForms.v). This file shows what
    a renderer needs to compute per span and per row, and that the shortcuts
    are exact:
    - corrected Euler at pixel i is Gouraud plus a parabola in i whose height
      is (1 - c)(p_a + p_b)/2, so it can be evaluated with no Euler set-up at all;
    - the Phong coefficients A, B, C, D, E of eqs. 2-3 in terms of (c, p_a, p_b, n);
    - if the normal at the left end of a span is U (not normalised) and the
      right end is U + m n1, then U . L, U . n1 and U . U are enough to get
      p_a, p_b and c after normalising both ends;
    - for a normal field F(x, y) = n1 x + n2 y + n3 over a triangle, the four
      numbers F . L, F . n1, F . n2, F . F can be carried down an edge by
      additions only (forward differences), for any sequence of x moves per
      row, and they equal the direct evaluation at every row;
    - one Newton step r (3 - q r^2)/2 on an approximation r = (1 + e)/sqrt q of
      1/sqrt q leaves relative error -(3/2 e^2 + 1/2 e^3), at most 7/4 e^2 in
      size when |e| <= 1/2: the error is squared.
    Division is Coq's total real division ([/ 0 = 0]), as in Span.v. *)

Require Import Reals Lra Lia Psatz List.
From PhongApprox Require Import Span Euler ClosedForms.
Open Scope R_scope.

(** ** Helpers *)

Lemma C_unit : forall s : span, is_unit (Na s) -> is_unit (Nb s) ->
  (1 <= n s)%nat ->
  C s = 2 * (1 - dot (Na s) (Nb s)) / INR (n s) ^ 2.
Proof.
  intros s Ha Hb Hn. pose proof (INR_n_neq_0 s Hn) as Hn'.
  apply (Rmult_eq_reg_l (INR (n s))); [| exact Hn'].
  rewrite nC_expand. unfold is_unit in Ha, Hb. rewrite Ha, Hb.
  field. exact Hn'.
Qed.

Lemma inv_sqrt_sq : forall x : R, 0 < x -> / sqrt x * (/ sqrt x * x) = 1.
Proof.
  intros x Hx. pose proof (sqrt_lt_R0 x Hx) as Hs.
  pose proof (sqrt_sqrt x (Rlt_le 0 x Hx)) as Hss.
  set (r := sqrt x) in *. clearbody r. subst x. field. lra.
Qed.

(** ** Claims: the span set-up in (c, p_a, p_b, n) *)

(* Note: Unit Na, Nb and n >= 1; every i (not only 0 <= i <= n). *)
(** Paper eqs. 11-17: corrected Euler (started at t_0 with step ds) is Gouraud plus a
    parabola vanishing at both edges, with ds = -(1 - c)(p_a + p_b)/n^2 and
    t_0 = (p_b - p_a)/n - (n - 1)/2 ds. *)
Theorem fast_rows_ce_from_span_invariants : forall (s : span) (i : nat),
  is_unit (Na s) -> is_unit (Nb s) -> (1 <= n s)%nat ->
  ceuler s i = pa s + INR i * (pb s - pa s) / INR (n s)
    + (1 - dot (Na s) (Nb s)) * (pa s + pb s) * INR i * (INR (n s) - INR i)
      / (2 * INR (n s) ^ 2).
Proof.
  intros s i Ha Hb Hn. pose proof (INR_n_neq_0 s Hn) as Hn'.
  rewrite ceuler_closed_form, (t0_closed_form s ltac:(lia)), (ds_unit s Ha Hb).
  field. exact Hn'.
Qed.

(* Note: Unit Na, Nb and n >= 1 (only C needs n >= 1 and unit Nb; A, B, D, E hold
   for every n, D and E with unit Na only). *)
(** Paper eqs. 2-3: the Phong coefficients A = k . L, B = Na . L, C = k . k,
    D = 2 k . Na, E = Na . Na in terms of c = Na . Nb, p_a, p_b and n. *)
Theorem fast_rows_phong_from_span_invariants : forall s : span,
  is_unit (Na s) -> is_unit (Nb s) -> (1 <= n s)%nat ->
  A s = (pb s - pa s) / INR (n s)
  /\ B s = pa s
  /\ C s = 2 * (1 - dot (Na s) (Nb s)) / INR (n s) ^ 2
  /\ D s = - 2 * (1 - dot (Na s) (Nb s)) / INR (n s)
  /\ E s = 1.
Proof.
  intros s Ha Hb Hn. split; [exact (A_pa_pb s) |].
  split; [reflexivity |]. split; [exact (C_unit s Ha Hb Hn) |].
  split; [exact (D_unit s Ha) | exact Ha].
Qed.

(* Note: Any vectors U, n1, L and any real m; the normalisation parts need U . U > 0
   (and Ub . Ub > 0 for the right end). *)
(** Per row, a span whose left-end normal is U and right-end normal Ub = U + m n1
    needs only U . L, U . n1 and U . U: they give Ub . L, U . Ub and Ub . Ub, and
    normalising the ends divides by the square roots of U . U and Ub . Ub. *)
Theorem fast_rows_field_span_identities : forall (U n1 Lv : vec) (m : R),
  let Ub := vadd U (vscale m n1) in
  dot Ub Lv = dot U Lv + m * dot n1 Lv
  /\ dot U Ub = dot U U + m * dot U n1
  /\ dot Ub Ub = dot U U + 2 * m * dot U n1 + m ^ 2 * dot n1 n1
  /\ (0 < dot U U ->
      is_unit (vscale (/ sqrt (dot U U)) U)
      /\ dot (vscale (/ sqrt (dot U U)) U) Lv = dot U Lv / sqrt (dot U U))
  /\ (0 < dot U U -> 0 < dot Ub Ub ->
      dot (vscale (/ sqrt (dot U U)) U) (vscale (/ sqrt (dot Ub Ub)) Ub)
      = dot U Ub / (sqrt (dot U U) * sqrt (dot Ub Ub))).
Proof.
  intros U n1 Lv m Ub.
  assert (E1 : dot Ub Lv = dot U Lv + m * dot n1 Lv
               /\ dot U Ub = dot U U + m * dot U n1
               /\ dot Ub Ub = dot U U + 2 * m * dot U n1 + m ^ 2 * dot n1 n1).
  { unfold Ub. destruct U as [u1 u2 u3], n1 as [a1 a2 a3], Lv as [l1 l2 l3].
    unfold dot, vadd, vscale; cbn [vx vy vz]. repeat split; ring. }
  destruct E1 as [E1 [E2 E3]]. do 3 (split; [assumption |]). split.
  - intros HU. split.
    + unfold is_unit. rewrite dot_vscale_l, dot_vscale_r. apply inv_sqrt_sq. exact HU.
    + rewrite dot_vscale_l. unfold Rdiv. ring.
  - intros HU HUb. pose proof (sqrt_lt_R0 _ HU) as H1.
    pose proof (sqrt_lt_R0 _ HUb) as H2.
    rewrite dot_vscale_l, dot_vscale_r. field. split; lra.
Qed.

(** ** Forward differences down a polygon edge *)

(** The normal field over a polygon: F(x, y) = n1 x + n2 y + n3. *)
Definition nfield (n1 n2 n3 : vec) (x y : R) : vec :=
  vadd (vadd (vscale x n1) (vscale y n2)) n3.

(** The per-row state carried down an edge: s = F . L, g = F . n1, h = F . n2,
    q = F . F. *)
Record edge_state := mkState { st_s : R ; st_g : R ; st_h : R ; st_q : R }.

(** The state evaluated directly at the point (x, y). *)
Definition state_at (n1 n2 n3 Lv : vec) (x y : R) : edge_state :=
  let F := nfield n1 n2 n3 x y in
  mkState (dot F Lv) (dot F n1) (dot F n2) (dot F F).

(** One row down the edge, from (x, y) to (x + dx, y + 1), by additions of
    constants of the triangle (and the products dx g, dx^2, which are constants
    too when dx is the same on every row). *)
Definition step (n1 n2 Lv : vec) (dx : R) (st : edge_state) : edge_state :=
  mkState
    (st_s st + dx * dot n1 Lv + dot n2 Lv)
    (st_g st + dx * dot n1 n1 + dot n1 n2)
    (st_h st + dx * dot n1 n2 + dot n2 n2)
    (st_q st + 2 * (dx * st_g st + st_h st)
       + dx ^ 2 * dot n1 n1 + 2 * dx * dot n1 n2 + dot n2 n2).

(** [steps] applies [step] for each x move of [dxs], first element first. *)
Definition steps (n1 n2 Lv : vec) (dxs : list R) (st : edge_state) : edge_state :=
  fold_left (fun acc dx => step n1 n2 Lv dx acc) dxs st.

Lemma step_state_at : forall (n1 n2 n3 Lv : vec) (x y dx : R),
  step n1 n2 Lv dx (state_at n1 n2 n3 Lv x y) = state_at n1 n2 n3 Lv (x + dx) (y + 1).
Proof.
  intros [a1 a2 a3] [b1 b2 b3] [c1 c2 c3] [l1 l2 l3] x y dx.
  unfold step, state_at, nfield, dot, vadd, vscale; cbn [vx vy vz st_s st_g st_h st_q].
  f_equal; ring.
Qed.

(* Note: Any vectors n1, n2, n3, L, any start (x0, y0) and any list of real x moves
   (integer or not, of any sign); exact, no rounding model. *)
(** Forward differences down a polygon's edge reproduce the direct evaluation of
    F . L, F . n1, F . n2 and F . F at every row. *)
Theorem edge_stepped_setup_exact : forall (n1 n2 n3 Lv : vec) (x0 y0 : R) (dxs : list R),
  steps n1 n2 Lv dxs (state_at n1 n2 n3 Lv x0 y0)
  = state_at n1 n2 n3 Lv (x0 + fold_right Rplus 0 dxs) (y0 + INR (length dxs)).
Proof.
  intros n1 n2 n3 Lv x0 y0 dxs. revert x0 y0.
  induction dxs as [| dx dxs IH]; intros x0 y0.
  - cbn [steps fold_left fold_right length INR].
    rewrite !Rplus_0_r. reflexivity.
  - unfold steps. cbn [fold_left fold_right length].
    fold (steps n1 n2 Lv dxs (step n1 n2 Lv dx (state_at n1 n2 n3 Lv x0 y0))).
    rewrite step_state_at, IH, S_INR. f_equal; ring.
Qed.

(** ** One Newton step for the reciprocal square root *)

Lemma newton_identity : forall t e : R, 0 < t ->
  (1 + e) / t * (3 - t * t * ((1 + e) / t) ^ 2) / 2
  = (1 - 3 / 2 * e ^ 2 - 1 / 2 * e ^ 3) / t.
Proof. intros t e Ht. field. lra. Qed.

(* Note: Any q > 0 and any relative error e (exact identity); the bound needs
   |e| <= 1/2 (then 3/2 + e/2 lies in [5/4, 7/4]). *)
(** One Newton step r (3 - q r^2)/2 on r = (1 + e)/sqrt q, an approximation of
    1/sqrt q with relative error e, gives relative error -(3/2 e^2 + 1/2 e^3):
    the error is squared. *)
Theorem rsqrt_newton_step_error : forall q e : R, 0 < q ->
  let r := (1 + e) / sqrt q in
  r * (3 - q * r ^ 2) / 2 = (1 - 3 / 2 * e ^ 2 - 1 / 2 * e ^ 3) / sqrt q
  /\ (Rabs e <= 1 / 2 -> Rabs (3 / 2 * e ^ 2 + 1 / 2 * e ^ 3) <= 7 / 4 * e ^ 2).
Proof.
  intros q e Hq r. split.
  - unfold r. pose proof (sqrt_lt_R0 q Hq) as Hs.
    rewrite <- (newton_identity (sqrt q) e Hs).
    rewrite (sqrt_sqrt q (Rlt_le 0 q Hq)). reflexivity.
  - intros He. assert (He' : - (1 / 2) <= e <= 1 / 2).
    { unfold Rabs in He. destruct (Rcase_abs e); lra. }
    pose proof (pow2_ge_0 e) as He2.
    assert (H3 : 3 / 2 * e ^ 2 + 1 / 2 * e ^ 3 = e ^ 2 * (3 / 2 + e / 2)) by field.
    rewrite H3, Rabs_mult, (Rabs_pos_eq (e ^ 2) He2), Rabs_pos_eq by lra.
    rewrite (Rmult_comm (7 / 4)). apply Rmult_le_compat_l; lra.
Qed.
