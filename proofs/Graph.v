(** * Graph.v — a running error bound for straight-line float programs.

    A program is a list of nodes [g 0], [g 1], ..., [g (N-1)]; node j applies
    one operation to inputs or to earlier nodes (operands have indices < j):
    reading an input [In i] (the exact real [X i], rounded into the format),
    a constant [Cst c] held exactly, [Add], [Sub], [Mul], [Div], [DivE] (a
    division either way: one rounded division, or a rounded reciprocal 1/b
    followed by a rounded product, each within the node's unit), [Sqrt],
    [Rsqrt] (1 / sqrt, e.g. GPU inverseSqrt) and [Sum l], a sum of several
    nodes in ANY order: any binary tree of additions over any permutation of
    its terms ([sum_exec]).

    Exact values [x j] apply each operation to the exact values of the
    operands ([exact_op]).  An execution [y] is any assignment of values in
    which every node is within FloatModelK's bound [ap1 v eta] of its
    operation applied to the COMPUTED operands ([exec_op]), with its own unit
    v = kappa u ([nv]) and its own absolute term eta ([neta]); so each
    operation may round differently (direction, mode, flushing), and an
    exact operation (the product inside a fused multiply-add) is allowed too.
    The absolute term is per node because of the ulp model (the last
    section): an operation specified in ulps of its exact result (IEEE round
    to nearest 1/2 ulp, a faithful GPU rounding 1 ulp, a GPU division 2.5
    ulp, inverseSqrt 2 ulp) whose exact result x has |x| <= M is within
    k ulp(M), i.e. [ap1 0 (k * ulp M)]: such a node may take v = 0 and
    eta = k ulp(M) where that is smaller than its relative bound
    ([rn_half_ulp_model], [faithful_ulp_model]).

    A certificate gives per node an interval [lo j, hi j], an error bound
    [E j] and, for square roots, a positive lower bound [S j] of the root of
    the exact operand and (for [Sqrt]) a lower bound [T j >= 0] of the root
    of the computed operand, so that
        |sqrt y_a - sqrt x_a| = |y_a - x_a| / (sqrt y_a + sqrt x_a)
                              <= E a / (S j + T j).
    [DivE] takes the [Div] interval rule; its error rule covers both ways:
    with d the [Div] bound on |y_a / y_b - x_a / x_b| and Q = |y_a / y_b|
    <= m + d, the reciprocal-then-product way is within
        Q v (2 + v) + (1 + v) |y_a| eta + eta
    of y_a / y_b, where |y_a| <= mag (lo a) (hi a) + E a.
    It is checked node by node by the local rules [iv_ok] (interval
    arithmetic) and [err_ok] (first-order error propagation made rigorous:
    every product of errors is kept).  [graph_sound] says: if every node is
    well formed and its certificate satisfies the local rules, then for EVERY
    execution, every exact value lies in its interval and every computed value
    is within [E j] of the exact one:

        lo j <= x j <= hi j   /\   |y j - x j| <= E j.

    The sum rule rests on [sum_exec_err]: a sum of k computed terms t_i in any
    order, each addition of two nonzero partial sums with unit v, and an addition of
    a zero moving the other operand by ez at most (a float plus 0 is that float, or
    0 where a subnormal is flushed), with nz of the terms nonzero, is within
        ((1+v)^(nz-1) - 1) sum |t_i| + (nz-1) (1+v)^(nz-1) eta
          + (k-1) (1+v)^(nz-1) ez
    of the exact sum: at most nz - 1 of its additions round.  The rule counts as
    nonzero every term not known to be zero ([live]). *)

From Coq Require Import Reals Lra Lia List Permutation.
From Flocq Require Import Core.
From PhongApprox Require Import FloatModelK.
Import ListNotations.
Open Scope R_scope.

(** ** The language *)

(** Operations. Operands are indices of earlier nodes. *)
Inductive op : Type :=
| In (i : nat)          (* input i: an exact real X i, read (rounded) into the format *)
| Cst (c : R)           (* a constant the format holds exactly: no rounding *)
| Add (a b : nat)
| Sub (a b : nat)
| Mul (a b : nat)
| Div (a b : nat)
| DivE (a b : nat)      (* a division either way: y a / y b, or a reciprocal r of y b then y a * r *)
| Sqrt (a : nat)
| Rsqrt (a : nat)       (* 1 / sqrt, e.g. GPU inverseSqrt *)
| Sum (l : list nat).   (* a sum of several nodes in ANY order: any binary tree of additions over any permutation *)

(** A node: its operation, the unit v = kappa u of its rounding and its absolute term eta
    (for Sum, of each of its additions), and for Sum the most an addition of an exact
    zero may move the other operand ([nez]: 0 where no flushing, the flush threshold
    where a subnormal may be flushed to zero). *)
Record node := Node { nop : op; nv : R; neta : R; nez : R }.

(** Operands come before the node; a Sum has at least one term. *)
Definition op_wf (o : op) (j : nat) : Prop :=
  match o with
  | In _ | Cst _ => True
  | Add a b | Sub a b | Mul a b | Div a b | DivE a b => (a < j)%nat /\ (b < j)%nat
  | Sqrt a | Rsqrt a => (a < j)%nat
  | Sum l => l <> [] /\ Forall (fun a => (a < j)%nat) l
  end.

(** The exact value of a node from the exact inputs X and the exact values x of earlier nodes. *)
Definition exact_op (X x : nat -> R) (o : op) : R :=
  match o with
  | In i => X i
  | Cst c => c
  | Add a b => x a + x b
  | Sub a b => x a - x b
  | Mul a b => x a * x b
  | Div a b => x a / x b
  | DivE a b => x a / x b
  | Sqrt a => sqrt (x a)
  | Rsqrt a => / sqrt (x a)
  | Sum l => fold_right Rplus 0 (map x l)
  end.

(** Sums in any order: any binary tree of additions over any permutation of the terms,
    each addition of two nonzero partial sums within ap1 v eta of their exact sum, and
    an addition of an exact zero returning the other operand — or 0 where that operand
    is at most ez in magnitude (a subnormal flushed): a float plus 0 is that float,
    [exact_op_model]. *)
Inductive sum_exec (v eta ez : R) : list R -> R -> Prop :=
| sum_one : forall t, sum_exec v eta ez [t] t
| sum_split : forall l l1 l2 r1 r2 y,
    Permutation l (l1 ++ l2) -> l1 <> [] -> l2 <> [] ->
    sum_exec v eta ez l1 r1 -> sum_exec v eta ez l2 r2 ->
    (r1 <> 0 -> r2 <> 0 -> ap1 v eta y (r1 + r2)) ->
    (r1 = 0 -> y = r2 \/ (Rabs r2 <= ez /\ y = 0)) ->
    (r2 = 0 -> y = r1 \/ (Rabs r1 <= ez /\ y = 0)) ->
    sum_exec v eta ez l y.

(** The number of nonzero values of a list. *)
Definition nzc (ts : list R) : nat :=
  length (filter (fun t => if Req_EM_T t 0 then false else true) ts).

(** What an execution may compute at a node: within ap1 (nv node) (neta node) of the exact operation on the COMPUTED operands y.
    A fused multiply-add is covered: its product is exact, which ap1 allows for any v >= 0. *)
Definition exec_op (X y : nat -> R) (g : node) (yj : R) : Prop :=
  let v := nv g in
  match nop g with
  | In i => ap1 v (neta g) yj (X i)
  | Cst c => yj = c
  | Add a b => ap1 v (neta g) yj (y a + y b)
  | Sub a b => ap1 v (neta g) yj (y a - y b)
  | Mul a b => ap1 v (neta g) yj (y a * y b)
  | Div a b => ap1 v (neta g) yj (y a / y b)
  | DivE a b => ap1 v (neta g) yj (y a / y b) \/ (exists r, ap1 v (neta g) r (/ y b) /\ ap1 v (neta g) yj (y a * r))
  | Sqrt a => ap1 v (neta g) yj (sqrt (y a))
  | Rsqrt a => ap1 v (neta g) yj (/ sqrt (y a))
  | Sum l => sum_exec v (neta g) (nez g) (map y l) yj
  end.

(** ** The certificate *)

(** An interval [lo j, hi j] of the exact value, an error bound E j, and for
    Sqrt/Rsqrt a positive lower bound S j of the root (of the exact operand)
    and for Sqrt a lower bound T j >= 0 of the root of the computed operand. *)
Definition mag (lo hi : R) : R := Rmax (Rabs lo) (Rabs hi).

Definition sumR (f : nat -> R) (l : list nat) : R := fold_right Rplus 0 (map f l).

(** The interval rules. *)
Definition iv_ok (g : nat -> node) (X lo hi S : nat -> R) (j : nat) : Prop :=
  lo j <= hi j /\
  match nop (g j) with
  | In i => lo j <= X i <= hi j
  | Cst c => lo j <= c <= hi j
  | Add a b => lo j <= lo a + lo b /\ hi a + hi b <= hi j
  | Sub a b => lo j <= lo a - hi b /\ hi a - lo b <= hi j
  | Mul a b => Forall (fun p => lo j <= p <= hi j)
                 [lo a * lo b; lo a * hi b; hi a * lo b; hi a * hi b]
  | Div a b | DivE a b => (0 < lo b \/ hi b < 0) /\
               Forall (fun p => lo j <= p <= hi j)
                 [lo a / lo b; lo a / hi b; hi a / lo b; hi a / hi b]
  | Sqrt a => 0 < S j /\ S j * S j <= lo a /\ lo j <= S j /\ 0 <= hi j /\ hi a <= hi j * hi j
  | Rsqrt a => 0 < S j /\ S j * S j <= lo a /\ 0 < lo j /\ lo j * lo j * hi a <= 1 /\ 1 <= hi j * S j
  | Sum l => lo j <= sumR lo l /\ sumR hi l <= hi j
  end.

(** A term that may be nonzero: one whose interval is not [0, 0] with no error (such a
    term is exactly 0 in every execution, and adding it rounds nothing). *)
Definition live (lo hi E : nat -> R) (i : nat) : bool :=
  if Req_EM_T (Rabs (lo i) + Rabs (hi i) + E i) 0 then false else true.

(** The error rules: E j bounds |y j - x j| given the operands' bounds.
    For Rsqrt, [E a <= lo a - S j * S j] makes both the exact and the
    computed operand at least S j ^ 2 > 0.  For Sqrt,
    [T j * T j <= lo a - E a] makes the computed operand at least T j ^ 2. *)
Definition err_ok (g : nat -> node) (lo hi E S T : nat -> R) (j : nat) : Prop :=
  let v := nv (g j) in
  let eta := neta (g j) in
  let m := mag (lo j) (hi j) in
  0 <= E j /\
  match nop (g j) with
  | In _ => v * m + eta <= E j
  | Cst _ => True
  | Add a b | Sub a b => E a + E b + v * (m + E a + E b) + eta <= E j
  | Mul a b =>
      let d := mag (lo a) (hi a) * E b + mag (lo b) (hi b) * E a + E a * E b in
      d + v * (m + d) + eta <= E j
  | Div a b =>
      let lb := Rmin (Rabs (lo b)) (Rabs (hi b)) in
      E b < lb /\
      let d := (E a + m * E b) / (lb - E b) in
      d + v * (m + d) + eta <= E j
  | DivE a b =>
      let lb := Rmin (Rabs (lo b)) (Rabs (hi b)) in
      E b < lb /\
      let d := (E a + m * E b) / (lb - E b) in
      d + v * (m + d) + eta <= E j /\
      d + v * (2 + v) * (m + d) + (1 + v) * (mag (lo a) (hi a) + E a) * eta + eta <= E j
  | Sqrt a =>
      E a <= S j * S j /\ 0 <= T j /\ T j * T j <= lo a - E a /\
      let d := E a / (S j + T j) in
      d + v * (m + d) + eta <= E j
  | Rsqrt a =>
      E a <= lo a - S j * S j /\
      let d := E a / (2 * (S j * S j * S j)) in
      d + v * (m + d) + eta <= E j
  | Sum l =>
      let k := length l in
      let m := (length (filter (live lo hi E) l) - 1)%nat in
      let w := (1 + v) ^ m in
      0 <= nez (g j) /\
      sumR E l + (w - 1) * sumR (fun i => mag (lo i) (hi i) + E i) l
        + INR m * w * eta + INR (k - 1) * w * nez (g j) <= E j
  end.

(** ** Real-number lemmas *)

Lemma mag_ge : forall lo hi x, lo <= x <= hi -> Rabs x <= mag lo hi.
Proof.
  intros lo hi x Hx. unfold mag.
  pose proof (Rmax_l (Rabs lo) (Rabs hi)). pose proof (Rmax_r (Rabs lo) (Rabs hi)).
  destruct (Rle_or_lt 0 x).
  - rewrite Rabs_pos_eq by lra. pose proof (Rle_abs hi). lra.
  - rewrite Rabs_left by lra. pose proof (Rle_abs (- lo)). rewrite Rabs_Ropp in *. lra.
Qed.

(** One rounded operation: z is the operation on the computed operands, within d of the
    exact value xj, and yj is within ap1 of z. *)
Lemma ap1_step : forall v eta yj z xj d m, 0 <= v -> ap1 v eta yj z ->
  Rabs (z - xj) <= d -> Rabs xj <= m -> Rabs (yj - xj) <= d + v * (m + d) + eta.
Proof.
  unfold ap1. intros v eta yj z xj d m Hv Hy Hz Hm.
  assert (Hzm : Rabs z <= m + d) by (pose proof (Rabs_triang_inv z xj); lra).
  assert (v * Rabs z <= v * (m + d)) by (apply Rmult_le_compat_l; lra).
  replace (yj - xj) with ((yj - z) + (z - xj)) by ring.
  pose proof (Rabs_triang (yj - z) (z - xj)). lra.
Qed.

Lemma add_err : forall xa xb ya yb Ea Eb, Rabs (ya - xa) <= Ea -> Rabs (yb - xb) <= Eb ->
  Rabs ((ya + yb) - (xa + xb)) <= Ea + Eb.
Proof.
  intros. replace ((ya + yb) - (xa + xb)) with ((ya - xa) + (yb - xb)) by ring.
  pose proof (Rabs_triang (ya - xa) (yb - xb)). lra.
Qed.

Lemma sub_err : forall xa xb ya yb Ea Eb, Rabs (ya - xa) <= Ea -> Rabs (yb - xb) <= Eb ->
  Rabs ((ya - yb) - (xa - xb)) <= Ea + Eb.
Proof.
  intros. replace ((ya - yb) - (xa - xb)) with ((ya - xa) + - (yb - xb)) by ring.
  pose proof (Rabs_triang (ya - xa) (- (yb - xb))). rewrite Rabs_Ropp in *. lra.
Qed.

Lemma mul_err : forall xa xb ya yb Ea Eb ma mb,
  Rabs (ya - xa) <= Ea -> Rabs (yb - xb) <= Eb -> Rabs xa <= ma -> Rabs xb <= mb ->
  Rabs (ya * yb - xa * xb) <= ma * Eb + mb * Ea + Ea * Eb.
Proof.
  intros xa xb ya yb Ea Eb ma mb Ha Hb Hma Hmb.
  replace (ya * yb - xa * xb) with (xa * (yb - xb) + xb * (ya - xa) + (ya - xa) * (yb - xb))
    by ring.
  pose proof (Rabs_triang (xa * (yb - xb) + xb * (ya - xa)) ((ya - xa) * (yb - xb))).
  pose proof (Rabs_triang (xa * (yb - xb)) (xb * (ya - xa))).
  rewrite !Rabs_mult in *.
  assert (Rabs xa * Rabs (yb - xb) <= ma * Eb) by (apply Rmult_le_compat; auto using Rabs_pos).
  assert (Rabs xb * Rabs (ya - xa) <= mb * Ea) by (apply Rmult_le_compat; auto using Rabs_pos).
  assert (Rabs (ya - xa) * Rabs (yb - xb) <= Ea * Eb)
    by (apply Rmult_le_compat; auto using Rabs_pos).
  lra.
Qed.

(** Products of intervals: x y lies between the extremes of the four corners. *)
Lemma lin_between : forall c a1 a2 x L H, a1 <= x <= a2 ->
  L <= c * a1 <= H -> L <= c * a2 <= H -> L <= c * x <= H.
Proof.
  intros c a1 a2 x L H Hx H1 H2. destruct (Rle_or_lt 0 c).
  - assert (c * a1 <= c * x) by (apply Rmult_le_compat_l; lra).
    assert (c * x <= c * a2) by (apply Rmult_le_compat_l; lra). lra.
  - assert (c * x <= c * a1) by (apply Rmult_le_compat_neg_l; lra).
    assert (c * a2 <= c * x) by (apply Rmult_le_compat_neg_l; lra). lra.
Qed.

Lemma mul_between : forall a1 a2 b1 b2 x y L H, a1 <= x <= a2 -> b1 <= y <= b2 ->
  L <= a1 * b1 <= H -> L <= a1 * b2 <= H -> L <= a2 * b1 <= H -> L <= a2 * b2 <= H ->
  L <= x * y <= H.
Proof.
  intros a1 a2 b1 b2 x y L H Hx Hy H11 H12 H21 H22.
  assert (L <= a1 * y <= H) by (apply (lin_between a1 b1 b2); auto).
  assert (L <= a2 * y <= H) by (apply (lin_between a2 b1 b2); auto).
  rewrite Rmult_comm. apply (lin_between y a1 a2); [auto | rewrite Rmult_comm; auto ..].
Qed.

Lemma Forall4 : forall (P : R -> Prop) a b c d, Forall P [a; b; c; d] ->
  P a /\ P b /\ P c /\ P d.
Proof. intros P a b c d H. rewrite !Forall_cons_iff in H. tauto. Qed.

(** A sign-definite divisor interval: 1/x_b lies in [1/hi b, 1/lo b], |x_b| >= lb. *)
Lemma inv_between : forall lb hb xb, lb <= xb <= hb -> (0 < lb \/ hb < 0) ->
  / hb <= / xb <= / lb.
Proof.
  intros lb hb xb Hx [Hp | Hn].
  - split; apply Rinv_le_contravar; lra.
  - assert (/ - xb <= / - hb) by (apply Rinv_le_contravar; lra).
    assert (/ - lb <= / - xb) by (apply Rinv_le_contravar; lra).
    rewrite !Rinv_opp in *. lra.
Qed.

Lemma div_lb : forall lb hb xb, lb <= xb <= hb -> (0 < lb \/ hb < 0) ->
  Rmin (Rabs lb) (Rabs hb) <= Rabs xb.
Proof.
  intros lb hb xb Hx [Hp | Hn].
  - pose proof (Rmin_l (Rabs lb) (Rabs hb)).
    rewrite (Rabs_pos_eq lb), (Rabs_pos_eq xb) in * by lra. lra.
  - pose proof (Rmin_r (Rabs lb) (Rabs hb)).
    rewrite (Rabs_left hb), (Rabs_left xb) in * by lra. lra.
Qed.

Lemma div_between : forall la ha lb hb xa xb L H, la <= xa <= ha -> lb <= xb <= hb ->
  (0 < lb \/ hb < 0) -> Forall (fun p => L <= p <= H) [la / lb; la / hb; ha / lb; ha / hb] ->
  L <= xa / xb <= H.
Proof.
  intros la ha lb hb xa xb L H Ha Hb Hs HF.
  apply Forall4 in HF. unfold Rdiv in *.
  apply (mul_between la ha (/ hb) (/ lb)); try tauto. now apply inv_between.
Qed.

Lemma div_err : forall xa xb ya yb Ea Eb m lbd,
  lbd <= Rabs xb -> Eb < lbd -> Rabs (ya - xa) <= Ea -> Rabs (yb - xb) <= Eb ->
  Rabs (xa / xb) <= m -> Rabs (ya / yb - xa / xb) <= (Ea + m * Eb) / (lbd - Eb).
Proof.
  intros xa xb ya yb Ea Eb m lbd Hl HE Ha Hb Hm.
  assert (Hyb : lbd - Eb <= Rabs yb).
  { pose proof (Rabs_triang_inv xb yb). rewrite Rabs_minus_sym in Hb. lra. }
  assert (Hxb : xb <> 0) by (intro Hz; rewrite Hz, Rabs_R0 in Hl; pose proof (Rabs_pos (yb - xb)); lra).
  assert (Hyb0 : yb <> 0) by (intro Hz; rewrite Hz, Rabs_R0 in Hyb; pose proof (Rabs_pos (yb - xb)); lra).
  replace (ya / yb - xa / xb) with (((ya - xa) - xa / xb * (yb - xb)) * / yb)
    by (field; split; assumption).
  rewrite Rabs_mult, Rabs_inv.
  assert (Hn : Rabs ((ya - xa) - xa / xb * (yb - xb)) <= Ea + m * Eb).
  { pose proof (Rabs_triang (ya - xa) (- (xa / xb * (yb - xb)))).
    rewrite Rabs_Ropp, Rabs_mult in H.
    assert (Rabs (xa / xb) * Rabs (yb - xb) <= m * Eb)
      by (apply Rmult_le_compat; auto using Rabs_pos).
    unfold Rminus at 1. lra. }
  unfold Rdiv. apply Rmult_le_compat; auto using Rabs_pos.
  - left. apply Rinv_0_lt_compat. pose proof (Rabs_pos (yb - xb)). lra.
  - apply Rinv_le_contravar; [pose proof (Rabs_pos (yb - xb)) |]; lra.
Qed.

(** The second way of DivE: a rounded reciprocal r of yb, then a rounded product ya * r. *)
Lemma recip_err : forall v eta ya yb r y q p, 0 <= v -> 0 <= eta -> yb <> 0 ->
  ap1 v eta r (/ yb) -> ap1 v eta y (ya * r) -> Rabs (ya / yb) <= q -> Rabs ya <= p ->
  Rabs (y - ya / yb) <= v * (2 + v) * q + (1 + v) * p * eta + eta.
Proof.
  unfold ap1. intros v eta ya yb r y q p Hv He Hb Hr Hy Hq Hp.
  assert (HA : Rabs ya * Rabs (/ yb) = Rabs (ya / yb)) by (unfold Rdiv; now rewrite Rabs_mult).
  assert (H1 : Rabs (ya * r - ya / yb) <= v * Rabs (ya / yb) + Rabs ya * eta).
  { replace (ya * r - ya / yb) with (ya * (r - / yb)) by (field; exact Hb).
    rewrite Rabs_mult. pose proof (Rabs_pos ya).
    assert (Rabs ya * Rabs (r - / yb) <= Rabs ya * (v * Rabs (/ yb) + eta))
      by (apply Rmult_le_compat_l; lra).
    rewrite <- HA. lra. }
  assert (H2 : Rabs (ya * r) <= (1 + v) * Rabs (ya / yb) + Rabs ya * eta)
    by (pose proof (Rabs_triang_inv (ya * r) (ya / yb)); lra).
  assert (v * Rabs (ya * r) <= v * ((1 + v) * Rabs (ya / yb) + Rabs ya * eta))
    by (apply Rmult_le_compat_l; lra).
  replace (y - ya / yb) with ((y - ya * r) + (ya * r - ya / yb)) by ring.
  pose proof (Rabs_triang (y - ya * r) (ya * r - ya / yb)).
  assert (v * (2 + v) * Rabs (ya / yb) <= v * (2 + v) * q) by (apply Rmult_le_compat_l; nra).
  assert ((1 + v) * Rabs ya * eta <= (1 + v) * p * eta)
    by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_l; lra]).
  lra.
Qed.

Lemma sqrt_ge : forall S xa, 0 < S -> S * S <= xa -> S <= sqrt xa.
Proof.
  intros S xa HS Hx. rewrite <- (sqrt_square S) by lra. now apply sqrt_le_1_alt.
Qed.

(** T j bounds the root of the computed operand from below: sqrt y_a >= T j >= 0. *)
Lemma sqrt_err : forall xa ya Ea S T, 0 < S -> S * S <= xa -> 0 <= T -> T * T <= ya ->
  Rabs (ya - xa) <= Ea -> Rabs (sqrt ya - sqrt xa) <= Ea / (S + T).
Proof.
  intros xa ya Ea S T HS Hx HT Hy Ha.
  assert (HSx := sqrt_ge S xa HS Hx).
  assert (HTy : T <= sqrt ya) by (rewrite <- (sqrt_square T) by lra; now apply sqrt_le_1_alt).
  assert (0 <= xa) by nra. assert (0 <= ya) by nra.
  assert (Heq : (sqrt ya - sqrt xa) * (sqrt ya + sqrt xa) = ya - xa).
  { transitivity (sqrt ya * sqrt ya - sqrt xa * sqrt xa); [ring|].
    rewrite !sqrt_sqrt by lra. reflexivity. }
  assert (Habs : Rabs (sqrt ya - sqrt xa) * (sqrt ya + sqrt xa) = Rabs (ya - xa)).
  { rewrite <- Heq, Rabs_mult, (Rabs_pos_eq (sqrt ya + sqrt xa)) by lra. reflexivity. }
  apply Rmult_le_reg_r with (S + T); [lra|]. unfold Rdiv.
  rewrite Rmult_assoc, Rinv_l, Rmult_1_r by lra.
  pose proof (Rabs_pos (sqrt ya - sqrt xa)).
  assert (Rabs (sqrt ya - sqrt xa) * (S + T) <= Rabs (sqrt ya - sqrt xa) * (sqrt ya + sqrt xa))
    by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

Lemma sqrt_between : forall la ha xa L H S, la <= xa <= ha -> 0 < S -> S * S <= la ->
  L <= S -> 0 <= H -> ha <= H * H -> L <= sqrt xa <= H.
Proof.
  intros la ha xa L H S Hx HS HSl HL HH Hh. split.
  - pose proof (sqrt_ge S xa HS). lra.
  - rewrite <- (sqrt_square H) by lra. apply sqrt_le_1_alt. lra.
Qed.

Lemma rsqrt_err : forall xa ya Ea S, 0 < S -> S * S <= xa -> S * S <= ya ->
  Rabs (ya - xa) <= Ea -> Rabs (/ sqrt ya - / sqrt xa) <= Ea / (2 * (S * S * S)).
Proof.
  intros xa ya Ea S HS Hx Hy Ha.
  pose proof (sqrt_ge S xa HS Hx) as Hp. pose proof (sqrt_ge S ya HS Hy) as Hq.
  pose proof (Rmult_le_pos S S ltac:(lra) ltac:(lra)).
  set (p := sqrt xa) in *. set (q := sqrt ya) in *.
  assert (Heq : (/ q - / p) * (p * q * (p + q)) = xa - ya).
  { transitivity (p * p - q * q); [field; split; lra|].
    unfold p, q. rewrite !sqrt_sqrt by lra. reflexivity. }
  assert (Habs : Rabs (/ q - / p) * (p * q * (p + q)) = Rabs (ya - xa)).
  { rewrite (Rabs_minus_sym ya xa), <- Heq, Rabs_mult, (Rabs_pos_eq (p * q * (p + q))).
    - reflexivity.
    - apply Rmult_le_pos; [apply Rmult_le_pos|]; lra. }
  assert (HS2 : S * S <= p * q) by (apply Rmult_le_compat; lra).
  assert (HS3 : S * S * (2 * S) <= p * q * (p + q))
    by (apply Rmult_le_compat; lra).
  assert (HS3p : 0 < S * S * S) by (repeat apply Rmult_lt_0_compat; lra).
  apply Rmult_le_reg_r with (2 * (S * S * S)); [lra|]. unfold Rdiv.
  rewrite (Rmult_assoc Ea), Rinv_l, Rmult_1_r by lra.
  pose proof (Rabs_pos (/ q - / p)).
  assert (Rabs (/ q - / p) * (S * S * (2 * S)) <= Rabs (/ q - / p) * (p * q * (p + q)))
    by (apply Rmult_le_compat_l; lra).
  replace (Rabs (/ q - / p) * (2 * (S * S * S)))
    with (Rabs (/ q - / p) * (S * S * (2 * S))) by ring.
  lra.
Qed.

Lemma rsqrt_between : forall la ha xa L H S, la <= xa <= ha -> 0 < S -> S * S <= la ->
  0 < L -> L * L * ha <= 1 -> 1 <= H * S -> L <= / sqrt xa <= H.
Proof.
  intros la ha xa L H S Hx HS HSl HL HLh HH.
  pose proof (Rmult_le_pos S S ltac:(lra) ltac:(lra)).
  pose proof (sqrt_ge S xa HS ltac:(lra)) as Hp.
  assert (Hsx : sqrt xa * sqrt xa = xa) by (apply sqrt_sqrt; lra).
  split.
  - assert (HL2 : L * L * xa <= L * L * ha)
      by (apply Rmult_le_compat_l; [apply Rmult_le_pos|]; lra).
    assert (Ht : 0 <= L * sqrt xa) by (apply Rmult_le_pos; lra).
    assert (Ht2 : (L * sqrt xa) * (L * sqrt xa) <= 1)
      by (replace ((L * sqrt xa) * (L * sqrt xa)) with (L * L * (sqrt xa * sqrt xa)) by ring;
          rewrite Hsx; lra).
    assert (Ht1 : L * sqrt xa <= 1) by nra.
    apply Rmult_le_reg_r with (sqrt xa); [lra|]. rewrite Rinv_l by lra. exact Ht1.
  - assert (/ sqrt xa <= / S) by (apply Rinv_le_contravar; lra).
    assert (/ S <= H).
    { apply Rmult_le_reg_r with S; [lra|]. rewrite Rinv_l by lra. exact HH. }
    lra.
Qed.

(** ** Sums in any order *)

Lemma fold_app : forall l1 l2,
  fold_right Rplus 0 (l1 ++ l2) = fold_right Rplus 0 l1 + fold_right Rplus 0 l2.
Proof. induction l1 as [|a l1 IH]; simpl; intros; [ring | rewrite IH; ring]. Qed.

Lemma fold_perm : forall l l', Permutation l l' -> fold_right Rplus 0 l = fold_right Rplus 0 l'.
Proof. induction 1; simpl; [reflexivity | congruence | ring | congruence]. Qed.

Lemma fold_abs : forall l, Rabs (fold_right Rplus 0 l) <= fold_right Rplus 0 (map Rabs l).
Proof.
  induction l as [|a l IH]; simpl.
  - rewrite Rabs_R0. lra.
  - pose proof (Rabs_triang a (fold_right Rplus 0 l)). lra.
Qed.

Lemma le_mul_ge1 : forall a w, 0 <= a -> 1 <= w -> a <= a * w.
Proof. intros. nra. Qed.

(** One addition of two nonzero partial sums of n1 + 1 and n2 + 1 rounded additions'
    worth, whose additions of a zero (z1, z2 of them) moved them by ez at most. *)
Lemma sum_step : forall v eta ez (n1 n2 z1 z2 : nat) s1 s2 A1 A2 r1 r2 y,
  0 <= v -> 0 <= eta -> 0 <= ez -> Rabs s1 <= A1 -> Rabs s2 <= A2 ->
  Rabs (r1 - s1) <= ((1 + v) ^ n1 - 1) * A1 + INR n1 * (1 + v) ^ n1 * eta
                    + INR z1 * (1 + v) ^ n1 * ez ->
  Rabs (r2 - s2) <= ((1 + v) ^ n2 - 1) * A2 + INR n2 * (1 + v) ^ n2 * eta
                    + INR z2 * (1 + v) ^ n2 * ez ->
  ap1 v eta y (r1 + r2) ->
  Rabs (y - (s1 + s2)) <= ((1 + v) ^ (n1 + n2 + 1) - 1) * (A1 + A2)
                          + INR (n1 + n2 + 1) * (1 + v) ^ (n1 + n2 + 1) * eta
                          + INR (z1 + z2) * (1 + v) ^ (n1 + n2 + 1) * ez.
Proof.
  intros v eta ez n1 n2 z1 z2 s1 s2 A1 A2 r1 r2 y Hv He Hz H1 H2 E1 E2 Hy. unfold ap1 in Hy.
  assert (Hw : (1 + v) ^ (n1 + n2 + 1) = (1 + v) ^ n1 * (1 + v) ^ n2 * (1 + v))
    by (rewrite !pow_add; ring).
  rewrite Hw, !plus_INR. simpl (INR 1).
  pose proof (pow_R1_Rle (1 + v) n1 ltac:(lra)) as W1.
  pose proof (pow_R1_Rle (1 + v) n2 ltac:(lra)) as W2.
  set (w1 := (1 + v) ^ n1) in *. set (w2 := (1 + v) ^ n2) in *.
  set (W := w1 * w2 * (1 + v)).
  pose proof (pos_INR n1) as N1. pose proof (pos_INR n2) as N2.
  pose proof (pos_INR z1) as Z1. pose proof (pos_INR z2) as Z2.
  pose proof (Rabs_pos s1). pose proof (Rabs_pos s2).
  assert (F1 : (1 + v) * w1 <= W).
  { unfold W. pose proof (le_mul_ge1 ((1 + v) * w1) w2 ltac:(nra) W2). lra. }
  assert (F2 : (1 + v) * w2 <= W).
  { unfold W. pose proof (le_mul_ge1 ((1 + v) * w2) w1 ltac:(nra) W1). lra. }
  assert (F3 : 1 <= W) by (assert (1 <= (1 + v) * w1) by nra; lra).
  set (D1 := Rabs (r1 - s1)) in *. set (D2 := Rabs (r2 - s2)) in *.
  assert (Hr : Rabs (r1 + r2) <= A1 + A2 + D1 + D2).
  { replace (r1 + r2) with ((r1 - s1) + (r2 - s2) + (s1 + s2)) by ring.
    pose proof (Rabs_triang ((r1 - s1) + (r2 - s2)) (s1 + s2)).
    pose proof (Rabs_triang (r1 - s1) (r2 - s2)). pose proof (Rabs_triang s1 s2).
    unfold D1, D2. lra. }
  assert (T0 : Rabs (y - (s1 + s2)) <= v * (A1 + A2) + (1 + v) * (D1 + D2) + eta).
  { replace (y - (s1 + s2)) with ((y - (r1 + r2)) + (r1 - s1) + (r2 - s2)) by ring.
    pose proof (Rabs_triang ((y - (r1 + r2)) + (r1 - s1)) (r2 - s2)).
    pose proof (Rabs_triang (y - (r1 + r2)) (r1 - s1)).
    assert (v * Rabs (r1 + r2) <= v * (A1 + A2 + D1 + D2)) by (apply Rmult_le_compat_l; lra).
    unfold D1, D2 in *. lra. }
  assert (P1 : (1 + v) * D1 <= ((1 + v) * w1 - 1 - v) * A1 + INR n1 * ((1 + v) * w1) * eta
                               + INR z1 * ((1 + v) * w1) * ez).
  { assert ((1 + v) * D1 <= (1 + v) * ((w1 - 1) * A1 + INR n1 * w1 * eta + INR z1 * w1 * ez))
      by (apply Rmult_le_compat_l; lra). nra. }
  assert (P2 : (1 + v) * D2 <= ((1 + v) * w2 - 1 - v) * A2 + INR n2 * ((1 + v) * w2) * eta
                               + INR z2 * ((1 + v) * w2) * ez).
  { assert ((1 + v) * D2 <= (1 + v) * ((w2 - 1) * A2 + INR n2 * w2 * eta + INR z2 * w2 * ez))
      by (apply Rmult_le_compat_l; lra). nra. }
  assert (Q1 : ((1 + v) * w1 - 1) * A1 <= (W - 1) * A1) by (apply Rmult_le_compat_r; lra).
  assert (Q2 : ((1 + v) * w2 - 1) * A2 <= (W - 1) * A2) by (apply Rmult_le_compat_r; lra).
  assert (Q3 : INR n1 * ((1 + v) * w1) * eta <= INR n1 * W * eta)
    by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_l; lra]).
  assert (Q4 : INR n2 * ((1 + v) * w2) * eta <= INR n2 * W * eta)
    by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_l; lra]).
  assert (Q5 : INR z1 * ((1 + v) * w1) * ez <= INR z1 * W * ez)
    by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_l; lra]).
  assert (Q6 : INR z2 * ((1 + v) * w2) * ez <= INR z2 * W * ez)
    by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_l; lra]).
  assert (Q7 : eta <= 1 * W * eta) by nra.
  unfold W in *. nra.
Qed.

Lemma nzc_app : forall l1 l2, nzc (l1 ++ l2) = (nzc l1 + nzc l2)%nat.
Proof. intros. unfold nzc. rewrite filter_app, app_length. reflexivity. Qed.

Lemma nzc_perm : forall l l', Permutation l l' -> nzc l = nzc l'.
Proof.
  induction 1; unfold nzc in *; simpl; repeat destruct Req_EM_T; simpl; lia.
Qed.

Lemma nzc_zero_sum : forall l, nzc l = 0%nat -> fold_right Rplus 0 l = 0.
Proof.
  induction l as [|a l IH]; simpl; intros H; [reflexivity|]. unfold nzc in H. simpl in H.
  destruct (Req_EM_T a 0) as [Ha | Ha]; [| discriminate]. rewrite Ha, IH; [ring | exact H].
Qed.

Lemma nzc_le_length : forall l, (nzc l <= length l)%nat.
Proof.
  induction l as [|a l IH]; [reflexivity|]. unfold nzc in *. simpl.
  destruct (Req_EM_T a 0); simpl; lia.
Qed.

(** The bound of a sum grows with its exponent. *)
Lemma sum_bound_mono : forall v eta ez (m m' k : nat) A, 0 <= v -> 0 <= eta -> 0 <= ez ->
  0 <= A -> (m <= m')%nat ->
  ((1 + v) ^ m - 1) * A + INR m * (1 + v) ^ m * eta + INR k * (1 + v) ^ m * ez
  <= ((1 + v) ^ m' - 1) * A + INR m * (1 + v) ^ m' * eta + INR k * (1 + v) ^ m' * ez.
Proof.
  intros v eta ez m m' k A Hv He Hz HA Hm.
  assert (Hp : (1 + v) ^ m <= (1 + v) ^ m') by (apply Rle_pow; lra || lia).
  pose proof (pos_INR m). pose proof (pos_INR k).
  assert (((1 + v) ^ m - 1) * A <= ((1 + v) ^ m' - 1) * A) by (apply Rmult_le_compat_r; lra).
  assert (INR m * (1 + v) ^ m * eta <= INR m * (1 + v) ^ m' * eta)
    by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_l; lra]).
  assert (INR k * (1 + v) ^ m * ez <= INR k * (1 + v) ^ m' * ez)
    by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_l; lra]).
  lra.
Qed.

(** The error of a sum of k >= 1 computed terms in any order: with nz of them nonzero,
    at most nz - 1 of its additions round (an addition of a zero moves by ez at most). *)
Lemma sum_exec_err : forall v eta ez, 0 <= v -> 0 <= eta -> 0 <= ez ->
  forall ts y, sum_exec v eta ez ts y ->
  (1 <= length ts)%nat /\ (nzc ts = 0%nat -> y = 0) /\
  Rabs (y - fold_right Rplus 0 ts)
    <= ((1 + v) ^ (nzc ts - 1) - 1) * fold_right Rplus 0 (map Rabs ts)
       + INR (nzc ts - 1) * (1 + v) ^ (nzc ts - 1) * eta
       + INR (length ts - 1) * (1 + v) ^ (nzc ts - 1) * ez.
Proof.
  intros v eta ez Hv He Hz ts y H.
  induction H as [t | l l1 l2 r1 r2 y Hp Hl1 Hl2 Hs1 [Hk1 [Z1 IH1]] Hs2 [Hk2 [Z2 IH2]]
                      Hnz H1z H2z].
  - simpl. split; [lia|]. split.
    + unfold nzc. simpl. destruct (Req_EM_T t 0); [auto | discriminate].
    + replace (t - (t + 0)) with 0 by ring. rewrite Rabs_R0.
      replace (nzc [t] - 1)%nat with 0%nat by (unfold nzc; simpl; destruct Req_EM_T; reflexivity).
      simpl. pose proof (Rabs_pos t). lra.
  - assert (Hlen : length l = (length l1 + length l2)%nat)
      by (rewrite (Permutation_length Hp); apply app_length).
    assert (Hn : nzc l = (nzc l1 + nzc l2)%nat) by (rewrite (nzc_perm _ _ Hp); apply nzc_app).
    rewrite (fold_perm _ _ Hp), (fold_perm _ _ (Permutation_map Rabs Hp)), map_app, !fold_app.
    rewrite Hlen, Hn.
    set (S1 := fold_right Rplus 0 l1) in *. set (S2 := fold_right Rplus 0 l2) in *.
    set (A1 := fold_right Rplus 0 (map Rabs l1)) in *.
    set (A2 := fold_right Rplus 0 (map Rabs l2)) in *.
    assert (HA1 : Rabs S1 <= A1) by apply fold_abs.
    assert (HA2 : Rabs S2 <= A2) by apply fold_abs.
    pose proof (Rabs_pos S1). pose proof (Rabs_pos S2).
    set (n1 := nzc l1) in *. set (n2 := nzc l2) in *.
    set (k1 := length l1) in *. set (k2 := length l2) in *.
    split; [lia|].
    (* The bound of each part, at the whole sum's exponent. *)
    set (m := (n1 + n2 - 1)%nat).
    pose proof (sum_bound_mono v eta ez (n1 - 1) m (k1 - 1) A1 Hv He Hz ltac:(lra) ltac:(lia))
      as M1.
    pose proof (sum_bound_mono v eta ez (n2 - 1) m (k2 - 1) A2 Hv He Hz ltac:(lra) ltac:(lia))
      as M2.
    set (W := (1 + v) ^ m) in *.
    assert (HW : 1 <= W) by (apply pow_R1_Rle; lra).
    assert (Hcount : (INR (n1 - 1) + INR (n2 - 1) <= INR m)).
    { rewrite <- plus_INR. apply le_INR. unfold m. lia. }
    assert (Hk : INR (k1 - 1) + INR (k2 - 1) + 1 <= INR (k1 + k2 - 1)).
    { rewrite <- plus_INR. replace 1 with (INR 1) by reflexivity. rewrite <- plus_INR.
      apply le_INR. lia. }
    assert (Ec : (INR (n1 - 1) + INR (n2 - 1)) * W * eta <= INR m * W * eta)
      by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_r; lra]).
    assert (Zc : (INR (k1 - 1) + INR (k2 - 1) + 1) * W * ez <= INR (k1 + k2 - 1) * W * ez)
      by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_r; lra]).
    assert (EzW : ez <= W * ez) by nra.
    (* One side zero: the addition moves the other by ez at most. *)
    assert (Zero : forall ra rb Sa Sb Ba Bb ya,
      ra = 0 -> (ya = rb \/ (Rabs rb <= ez /\ ya = 0)) ->
      Rabs (ra - Sa) <= Ba -> Rabs (rb - Sb) <= Bb ->
      Rabs (ya - (Sa + Sb)) <= Ba + Bb + ez).
    { intros ra rb Sa Sb Ba Bb ya Hra Hya Ha Hb.
      assert (Hy' : Rabs (ya - rb) <= ez).
      { destruct Hya as [-> | [Hr ->]];
          [rewrite Rminus_diag_eq, Rabs_R0 by reflexivity; lra
          | rewrite Rminus_0_l, Rabs_Ropp; exact Hr]. }
      rewrite Hra, Rminus_0_l, Rabs_Ropp in Ha.
      replace (ya - (Sa + Sb)) with ((ya - rb) + (rb - Sb) + - Sa) by ring.
      pose proof (Rabs_triang ((ya - rb) + (rb - Sb)) (- Sa)). rewrite Rabs_Ropp in H1.
      pose proof (Rabs_triang (ya - rb) (rb - Sb)). lra. }
    destruct (Req_EM_T r1 0) as [R1 | R1].
    + split.
      * intros Hn0. assert (n2 = 0%nat) by lia.
        destruct (H1z R1) as [-> | [_ ->]]; [apply Z2; assumption | reflexivity].
      * pose proof (Zero r1 r2 S1 S2 _ _ y R1 (H1z R1) IH1 IH2) as Hb. lra.
    + destruct (Req_EM_T r2 0) as [R2 | R2].
      * split.
        -- intros Hn0. assert (n1 = 0%nat) by lia. exfalso. apply R1. apply Z1. assumption.
        -- pose proof (Zero r2 r1 S2 S1 _ _ y R2 (H2z R2) IH2 IH1) as Hb.
           rewrite Rplus_comm in Hb. lra.
      * assert (P1 : n1 <> 0%nat) by (intro Hn0; apply R1, Z1, Hn0).
        assert (P2 : n2 <> 0%nat) by (intro Hn0; apply R2, Z2, Hn0).
        split; [intros Hn0; lia|].
        pose proof (sum_step v eta ez (n1 - 1) (n2 - 1) (k1 - 1) (k2 - 1) S1 S2 A1 A2 r1 r2 y
                      Hv He Hz HA1 HA2 IH1 IH2 (Hnz R1 R2)) as Hs.
        replace (n1 - 1 + (n2 - 1) + 1)%nat with m in Hs by (unfold m; lia).
        fold W in Hs.
        assert (INR (k1 - 1 + (k2 - 1)) * W * ez <= INR (k1 + k2 - 1) * W * ez).
        { apply Rmult_le_compat_r; [lra|]. apply Rmult_le_compat_r; [lra|].
          apply le_INR. lia. }
        lra.
Qed.

(** ** Lemmas on sums over node lists *)

Lemma sumR_le : forall f h l, Forall (fun i => f i <= h i) l -> sumR f l <= sumR h l.
Proof.
  intros f h l H. unfold sumR. induction H; simpl; lra.
Qed.

Lemma sumR_diff : forall f h e l, Forall (fun i => Rabs (f i - h i) <= e i) l ->
  Rabs (sumR f l - sumR h l) <= sumR e l.
Proof.
  intros f h e l H. unfold sumR. induction H as [|i l Hi _ IH]; simpl.
  - rewrite Rminus_diag_eq, Rabs_R0 by reflexivity. lra.
  - replace (f i + fold_right Rplus 0 (map f l) - (h i + fold_right Rplus 0 (map h l)))
      with ((f i - h i) + (fold_right Rplus 0 (map f l) - fold_right Rplus 0 (map h l)))
      by ring.
    pose proof (Rabs_triang (f i - h i)
                  (fold_right Rplus 0 (map f l) - fold_right Rplus 0 (map h l))). lra.
Qed.

(** ** The rules, one operation at a time *)

(** A term known to be zero (interval [0, 0], no error) computes 0: the computed terms
    have at most as many nonzero values as there are live terms. *)
Lemma nzc_live : forall (l : list nat) (x y lo hi E : nat -> R),
  Forall (fun i => lo i <= x i <= hi i /\ Rabs (y i - x i) <= E i) l ->
  (nzc (map y l) <= length (filter (live lo hi E) l))%nat.
Proof.
  induction l as [|i l IH]; intros x y lo hi E HF; [unfold nzc; simpl; lia|].
  apply Forall_cons_iff in HF. destruct HF as [[Hi Ei] HF'].
  specialize (IH x y lo hi E HF').
  unfold nzc in *. simpl. unfold live at 1.
  destruct (Req_EM_T (Rabs (lo i) + Rabs (hi i) + E i) 0) as [Hz | Hz]; simpl.
  - assert (Hy : y i = 0).
    { pose proof (Rabs_pos (lo i)). pose proof (Rabs_pos (hi i)).
      pose proof (Rabs_pos (y i - x i)).
      pose proof (Rle_abs (lo i)). pose proof (Rle_abs (hi i)).
      pose proof (Rle_abs (- lo i)). pose proof (Rle_abs (- hi i)). rewrite Rabs_Ropp in *.
      pose proof (Rle_abs (y i - x i)). pose proof (Rle_abs (- (y i - x i))).
      rewrite Rabs_Ropp in *. lra. }
    destruct (Req_EM_T (y i) 0) as [_ | Hn]; [exact IH | contradiction].
  - destruct (Req_EM_T (y i) 0); simpl; lia.
Qed.

(** The rounding of a sum on its computed terms: only the live terms' additions round
    (the sum rule's terms less the operands' errors; also GraphAffine.v's local error). *)
Lemma sum_rounding : forall v eta ez (l : list nat) (x y lo hi E : nat -> R) yj,
  0 <= v -> 0 <= eta -> 0 <= ez ->
  Forall (fun i => lo i <= x i <= hi i /\ Rabs (y i - x i) <= E i) l ->
  sum_exec v eta ez (map y l) yj ->
  Rabs (yj - sumR y l)
    <= ((1 + v) ^ (length (filter (live lo hi E) l) - 1) - 1)
         * sumR (fun i => mag (lo i) (hi i) + E i) l
       + INR (length (filter (live lo hi E) l) - 1)
         * (1 + v) ^ (length (filter (live lo hi E) l) - 1) * eta
       + INR (length l - 1) * (1 + v) ^ (length (filter (live lo hi E) l) - 1) * ez.
Proof.
  intros v eta ez l x y lo hi E yj Hv He Hz HF Hs.
  destruct (sum_exec_err v eta ez Hv He Hz _ _ Hs) as [_ [_ Herr]].
  rewrite map_length, map_map in Herr. change (fold_right Rplus 0 (map y l)) with (sumR y l) in Herr.
  change (fold_right Rplus 0 (map (fun i => Rabs (y i)) l))
    with (sumR (fun i => Rabs (y i)) l) in Herr.
  pose proof (nzc_live l x y lo hi E HF) as Hn.
  set (m := (length (filter (live lo hi E) l) - 1)%nat) in *.
  set (m0 := (nzc (map y l) - 1)%nat) in *.
  assert (Hm : (m0 <= m)%nat) by (unfold m0, m; lia).
  assert (Habs : sumR (fun i => Rabs (y i)) l <= sumR (fun i => mag (lo i) (hi i) + E i) l).
  { apply sumR_le. eapply Forall_impl; [|exact HF]. simpl. intros i [Hi Ei].
    pose proof (mag_ge _ _ _ Hi). pose proof (Rabs_triang_inv (y i) (x i)). lra. }
  assert (Hpos : 0 <= sumR (fun i => Rabs (y i)) l).
  { clear. unfold sumR. induction l as [|i l IH]; simpl; [lra|].
    pose proof (Rabs_pos (y i)). lra. }
  pose proof (sum_bound_mono v eta ez m0 m (length l - 1) _ Hv He Hz Hpos Hm) as Hmono.
  pose proof (pow_R1_Rle (1 + v) m ltac:(lra)).
  assert (((1 + v) ^ m - 1) * sumR (fun i => Rabs (y i)) l
          <= ((1 + v) ^ m - 1) * sumR (fun i => mag (lo i) (hi i) + E i) l)
    by (apply Rmult_le_compat_l; lra).
  assert (INR m0 * (1 + v) ^ m * eta <= INR m * (1 + v) ^ m * eta)
    by (apply Rmult_le_compat_r; [lra | apply Rmult_le_compat_r; [lra | apply le_INR; exact Hm]]).
  lra.
Qed.

Lemma case_sum : forall v eta ez (l : list nat) (x y lo hi E : nat -> R) yj L H Ej,
  0 <= v -> 0 <= eta -> 0 <= ez ->
  Forall (fun i => lo i <= x i <= hi i /\ Rabs (y i - x i) <= E i) l ->
  sum_exec v eta ez (map y l) yj -> L <= sumR lo l -> sumR hi l <= H ->
  sumR E l + ((1 + v) ^ (length (filter (live lo hi E) l) - 1) - 1)
               * sumR (fun i => mag (lo i) (hi i) + E i) l
    + INR (length (filter (live lo hi E) l) - 1)
        * (1 + v) ^ (length (filter (live lo hi E) l) - 1) * eta
    + INR (length l - 1) * (1 + v) ^ (length (filter (live lo hi E) l) - 1) * ez <= Ej ->
  L <= sumR x l <= H /\ Rabs (yj - sumR x l) <= Ej.
Proof.
  intros v eta ez l x y lo hi E yj L H Ej Hv He Hz HF Hs HL HH HE. split.
  - assert (sumR lo l <= sumR x l) by (apply sumR_le; eapply Forall_impl; [|exact HF]; simpl; intros; lra).
    assert (sumR x l <= sumR hi l) by (apply sumR_le; eapply Forall_impl; [|exact HF]; simpl; intros; lra).
    lra.
  - pose proof (sum_rounding v eta ez l x y lo hi E yj Hv He Hz HF Hs) as Hr.
    assert (Hd : Rabs (sumR y l - sumR x l) <= sumR E l)
      by (apply sumR_diff; eapply Forall_impl; [|exact HF]; simpl; tauto).
    replace (yj - sumR x l) with ((yj - sumR y l) + (sumR y l - sumR x l)) by ring.
    pose proof (Rabs_triang (yj - sumR y l) (sumR y l - sumR x l)). lra.
Qed.

(** ** Soundness *)

(** One node, given the claims for all earlier nodes. *)
Lemma node_sound : forall (g : nat -> node) (X : nat -> R) (x y lo hi E S T : nat -> R) j,
  (forall a, (a < j)%nat -> lo a <= x a <= hi a /\ Rabs (y a - x a) <= E a) ->
  op_wf (nop (g j)) j -> 0 <= nv (g j) -> 0 <= neta (g j) ->
  x j = exact_op X x (nop (g j)) -> exec_op X y (g j) (y j) ->
  iv_ok g X lo hi S j -> err_ok g lo hi E S T j ->
  lo j <= x j <= hi j /\ Rabs (y j - x j) <= E j.
Proof.
  intros g X x y lo hi E S T j IH. unfold exec_op, iv_ok, err_ok.
  destruct (g j) as [o v eta ez]. cbn [nop nv neta nez].
  destruct o as [i | c | a b | a b | a b | a b | a b | a | a | l];
    cbn [op_wf exact_op]; intros Hwf Hv He Hx Hy [Hlh Hiv] [HE0 Her]; rewrite Hx.
  - (* In *)
    split; [exact Hiv|].
    pose proof (ap1_step v eta (y j) (X i) (X i) 0 (mag (lo j) (hi j)) Hv Hy).
    rewrite Rminus_diag_eq, Rabs_R0 in H by reflexivity.
    pose proof (H (Rle_refl 0) (mag_ge _ _ _ Hiv)). lra.
  - (* Cst *)
    split; [exact Hiv|]. rewrite Hy, Rminus_diag_eq, Rabs_R0 by reflexivity. exact HE0.
  - (* Add *)
    destruct Hwf as [Ha Hb]. destruct (IH a Ha) as [Ia Ea]. destruct (IH b Hb) as [Ib Eb].
    assert (Hi : lo j <= x a + x b <= hi j) by lra. split; [exact Hi|].
    pose proof (ap1_step v eta (y j) (y a + y b) (x a + x b) (E a + E b) _ Hv Hy
                  (add_err _ _ _ _ _ _ Ea Eb) (mag_ge _ _ _ Hi)). lra.
  - (* Sub *)
    destruct Hwf as [Ha Hb]. destruct (IH a Ha) as [Ia Ea]. destruct (IH b Hb) as [Ib Eb].
    assert (Hi : lo j <= x a - x b <= hi j) by lra. split; [exact Hi|].
    pose proof (ap1_step v eta (y j) (y a - y b) (x a - x b) (E a + E b) _ Hv Hy
                  (sub_err _ _ _ _ _ _ Ea Eb) (mag_ge _ _ _ Hi)). lra.
  - (* Mul *)
    destruct Hwf as [Ha Hb]. destruct (IH a Ha) as [Ia Ea]. destruct (IH b Hb) as [Ib Eb].
    apply Forall4 in Hiv.
    assert (Hi : lo j <= x a * x b <= hi j)
      by (apply (mul_between (lo a) (hi a) (lo b) (hi b)); tauto).
    split; [exact Hi|].
    pose proof (ap1_step v eta (y j) (y a * y b) (x a * x b) _ _ Hv Hy
             (mul_err _ _ _ _ _ _ _ _ Ea Eb (mag_ge _ _ _ Ia) (mag_ge _ _ _ Ib))
             (mag_ge _ _ _ Hi)). lra.
  - (* Div *)
    destruct Hwf as [Ha Hb]. destruct (IH a Ha) as [Ia Ea]. destruct (IH b Hb) as [Ib Eb].
    destruct Hiv as [Hs Hiv]. destruct Her as [Hlb Her].
    assert (Hi : lo j <= x a / x b <= hi j) by (apply (div_between (lo a) (hi a) (lo b) (hi b)); auto).
    split; [exact Hi|].
    pose proof (ap1_step v eta (y j) (y a / y b) (x a / x b) _ _ Hv Hy
             (div_err _ _ _ _ _ _ _ _ (div_lb _ _ _ Ib Hs) Hlb Ea Eb (mag_ge _ _ _ Hi))
             (mag_ge _ _ _ Hi)). lra.
  - (* DivE *)
    destruct Hwf as [Ha Hb]. destruct (IH a Ha) as [Ia Ea]. destruct (IH b Hb) as [Ib Eb].
    destruct Hiv as [Hs Hiv]. destruct Her as (Hlb & Her1 & Her2).
    assert (Hi : lo j <= x a / x b <= hi j) by (apply (div_between (lo a) (hi a) (lo b) (hi b)); auto).
    split; [exact Hi|].
    pose proof (div_lb _ _ _ Ib Hs) as Hl.
    pose proof (div_err _ _ _ _ _ _ _ _ Hl Hlb Ea Eb (mag_ge _ _ _ Hi)) as Hd.
    destruct Hy as [Hy | (r & Hr & Hy)].
    + pose proof (ap1_step v eta (y j) (y a / y b) (x a / x b) _ _ Hv Hy Hd (mag_ge _ _ _ Hi)). lra.
    + assert (Hyb : y b <> 0).
      { intro Hz. pose proof (Rabs_triang_inv (x b) (y b)). rewrite Rabs_minus_sym in Eb.
        rewrite Hz, Rminus_0_r in *. lra. }
      assert (HQ : Rabs (y a / y b) <= mag (lo j) (hi j) + (E a + mag (lo j) (hi j) * E b)
                                        / (Rmin (Rabs (lo b)) (Rabs (hi b)) - E b)).
      { pose proof (Rabs_triang_inv (y a / y b) (x a / x b)). pose proof (mag_ge _ _ _ Hi). lra. }
      assert (HP : Rabs (y a) <= mag (lo a) (hi a) + E a).
      { pose proof (Rabs_triang_inv (y a) (x a)). pose proof (mag_ge _ _ _ Ia). lra. }
      pose proof (recip_err v eta (y a) (y b) r (y j) _ _ Hv He Hyb Hr Hy HQ HP).
      replace (y j - x a / x b) with ((y j - y a / y b) + (y a / y b - x a / x b)) by ring.
      pose proof (Rabs_triang (y j - y a / y b) (y a / y b - x a / x b)). lra.
  - (* Sqrt *)
    destruct (IH a Hwf) as [Ia Ea]. destruct Hiv as (HS & HSl & HL & HH & Hh).
    destruct Her as (HES & HT & HTl & Her).
    assert (Hi : lo j <= sqrt (x a) <= hi j) by (apply (sqrt_between (lo a) (hi a) _ _ _ (S j)); auto).
    split; [exact Hi|].
    assert (Hya : T j * T j <= y a).
    { pose proof (Rabs_triang_inv (x a) (y a)). rewrite Rabs_minus_sym in Ea.
      unfold Rabs in *. destruct Rcase_abs; lra. }
    pose proof (ap1_step v eta (y j) (sqrt (y a)) (sqrt (x a)) _ _ Hv Hy
             (sqrt_err (x a) (y a) (E a) (S j) (T j) HS ltac:(lra) HT Hya Ea) (mag_ge _ _ _ Hi)).
    lra.
  - (* Rsqrt *)
    destruct (IH a Hwf) as [Ia Ea]. destruct Hiv as (HS & HSl & HL & HLh & HH).
    destruct Her as [HES Her].
    assert (Hi : lo j <= / sqrt (x a) <= hi j)
      by (apply (rsqrt_between (lo a) (hi a) _ _ _ (S j)); auto).
    split; [exact Hi|].
    assert (Hya : S j * S j <= y a).
    { pose proof (Rabs_triang_inv (x a) (y a)). rewrite Rabs_minus_sym in Ea.
      unfold Rabs in *. destruct Rcase_abs; lra. }
    pose proof (ap1_step v eta (y j) (/ sqrt (y a)) (/ sqrt (x a)) _ _ Hv Hy
             (rsqrt_err (x a) (y a) (E a) (S j) HS ltac:(lra) Hya Ea) (mag_ge _ _ _ Hi)). lra.
  - (* Sum *)
    destruct Hwf as [_ Hl]. destruct Hiv as [HL HH].
    change (fold_right Rplus 0 (map x l)) with (sumR x l).
    destruct Her as [Hez Her].
    apply (case_sum v eta ez l x y lo hi E); auto.
    eapply Forall_impl; [|exact Hl]. intros a Ha. exact (IH a Ha).
Qed.

Theorem graph_sound :
  forall (g : nat -> node) (N : nat) (X : nat -> R) (x y lo hi E S T : nat -> R),
  (forall j, (j < N)%nat -> op_wf (nop (g j)) j /\ 0 <= nv (g j) /\ 0 <= neta (g j)) ->
  (forall j, (j < N)%nat -> x j = exact_op X x (nop (g j))) ->
  (forall j, (j < N)%nat -> exec_op X y (g j) (y j)) ->
  (forall j, (j < N)%nat -> iv_ok g X lo hi S j /\ err_ok g lo hi E S T j) ->
  forall j, (j < N)%nat -> lo j <= x j <= hi j /\ Rabs (y j - x j) <= E j.
Proof.
  intros g N X x y lo hi E S T Hwf Hx Hy Hc.
  assert (Hall : forall n j, (j < n)%nat -> (j < N)%nat ->
                 lo j <= x j <= hi j /\ Rabs (y j - x j) <= E j).
  { induction n as [|n IHn]; intros j Hjn HjN; [lia|].
    destruct (Hwf j HjN) as (Hw & Hv & He). destruct (Hc j HjN) as [Hi Her].
    apply (node_sound g X x y lo hi E S T j); auto.
    intros a Ha. apply IHn; lia. }
  intros j Hj. exact (Hall (Nat.succ j) j (Nat.lt_succ_diag_r j) Hj).
Qed.

(** ** The ulp model: why a node may take v = 0 and eta = k ulp(M)

    An implementation specifies an operation in ulps of the exact result:
    IEEE round to nearest within 1/2 ulp, a faithful (GPU) rounding within
    1 ulp, a GPU division within 2.5 ulp, inverseSqrt within 2 ulp.  If the
    exact result x satisfies |x| <= M, then ulp x <= ulp M (ulp is monotone
    in |x| for FLT), so such an operation is within k ulp(M), that is
    [ap1 0 (k * ulp M) y x]: the node may take [nv = 0] and
    [neta = k * ulp M] where that is smaller than the relative form.
    Below, in Flocq's terms for an FLT format (radix 2, minimal exponent
    emin, precision prec). *)

(** The shape: an error of at most k ulp(M) is ap1 with v = 0 and eta = k ulp(M). *)
Lemma ulp_model_ap1 : forall (emin prec : Z) (y x k M : R),
  Rabs x <= M -> Rabs (y - x) <= k * ulp radix2 (FLT_exp emin prec) M ->
  ap1 0 (k * ulp radix2 (FLT_exp emin prec) M) y x.
Proof.
  intros emin prec y x k M _ H. unfold ap1. lra.
Qed.

(** ulp is monotone for FLT: |x| <= M gives ulp x <= ulp M. *)
Lemma ulp_FLT_le_bound : forall (emin prec : Z), (0 < prec)%Z -> forall x M : R,
  Rabs x <= M -> ulp radix2 (FLT_exp emin prec) x <= ulp radix2 (FLT_exp emin prec) M.
Proof.
  intros emin prec Hp x M Hx.
  assert (Hpg : Prec_gt_0 prec) by exact Hp.
  apply (ulp_le radix2 (FLT_exp emin prec)).
  pose proof (Rle_abs M). rewrite (Rabs_pos_eq M); [lra |].
  pose proof (Rabs_pos x). lra.
Qed.

(** Round to nearest (any tie-breaking choice): within 1/2 ulp(M). *)
Lemma rn_half_ulp_model : forall (emin prec : Z), (0 < prec)%Z ->
  forall (choice : Z -> bool) (x M : R), Rabs x <= M ->
  Rabs (round radix2 (FLT_exp emin prec) (Znearest choice) x - x)
    <= / 2 * ulp radix2 (FLT_exp emin prec) M.
Proof.
  intros emin prec Hp choice x M Hx.
  assert (Hpg : Prec_gt_0 prec) by exact Hp.
  pose proof (error_le_half_ulp radix2 (FLT_exp emin prec) choice x) as H.
  pose proof (ulp_FLT_le_bound emin prec Hp x M Hx). lra.
Qed.

(** Any rounding (down, up, toward zero, nearest; a faithful rounding is one of
    round-down and round-up): within 1 ulp(M). *)
Lemma faithful_ulp_model : forall (emin prec : Z), (0 < prec)%Z ->
  forall (rnd : R -> Z), Valid_rnd rnd -> forall (x M : R), Rabs x <= M ->
  Rabs (round radix2 (FLT_exp emin prec) rnd x - x) <= ulp radix2 (FLT_exp emin prec) M.
Proof.
  intros emin prec Hp rnd Hrnd x M Hx.
  assert (Hpg : Prec_gt_0 prec) by exact Hp.
  pose proof (error_le_ulp radix2 (FLT_exp emin prec) rnd x) as H.
  pose proof (ulp_FLT_le_bound emin prec Hp x M Hx). lra.
Qed.

(** Hence a node rounding to nearest may take v = 0 and eta = ulp(M) / 2, and any
    rounding v = 0 and eta = ulp(M). *)
Lemma rn_ap1_ulp : forall (emin prec : Z), (0 < prec)%Z ->
  forall (choice : Z -> bool) (x M : R), Rabs x <= M ->
  ap1 0 (/ 2 * ulp radix2 (FLT_exp emin prec) M)
    (round radix2 (FLT_exp emin prec) (Znearest choice) x) x.
Proof.
  intros emin prec Hp choice x M Hx.
  apply (ulp_model_ap1 emin prec _ x (/ 2) M Hx).
  now apply rn_half_ulp_model.
Qed.

Lemma faithful_ap1_ulp : forall (emin prec : Z), (0 < prec)%Z ->
  forall (rnd : R -> Z), Valid_rnd rnd -> forall (x M : R), Rabs x <= M ->
  ap1 0 (1 * ulp radix2 (FLT_exp emin prec) M) (round radix2 (FLT_exp emin prec) rnd x) x.
Proof.
  intros emin prec Hp rnd Hrnd x M Hx.
  apply (ulp_model_ap1 emin prec _ x 1 M Hx). rewrite Rmult_1_l.
  now apply faithful_ulp_model.
Qed.

(** A number the format holds is its own rounding, by any rounding: a node whose
    exact result (on its computed operands) is such a number may take v = 0 and
    eta = 0 (the evaluator's exact inputs and exact operations; the checker takes
    only zero or normal results, which flushing does not move). *)
Lemma exact_op_model : forall (emin prec : Z) (rnd : R -> Z), Valid_rnd rnd ->
  forall x : R, generic_format radix2 (FLT_exp emin prec) x ->
  ap1 0 0 (round radix2 (FLT_exp emin prec) rnd x) x.
Proof.
  intros emin prec rnd Hrnd x Hx. unfold ap1.
  rewrite round_generic by assumption.
  rewrite Rminus_diag_eq, Rabs_R0 by reflexivity. lra.
Qed.

(** ** Inputs read as known numbers

    An implementation that rounds each input to nearest reads the exact input
    X i as a number Xr i the checker knows (its nearest number of the format).
    Its execution is then an execution of the graph on the exact inputs Xr,
    each read exactly (v = 0, eta = 0, [exact_op_model]); a certificate on Xr
    bounds its error from the exact values at Xr, and the intervals of a
    certificate on X hold the exact values at X, so the error from those is at
    most the first bound plus the distance between the two intervals. *)

(** The exact values are an execution: every operation without error. *)
Lemma sum_exec_exact : forall v eta ez, 0 <= v -> 0 <= eta ->
  forall ts, ts <> [] -> sum_exec v eta ez ts (fold_right Rplus 0 ts).
Proof.
  intros v eta ez Hv He ts. induction ts as [|a ts IH]; intros Hne; [congruence|].
  assert (Hz : forall z, ap1 v eta z z).
  { intro z. unfold ap1. rewrite Rminus_diag_eq, Rabs_R0 by reflexivity.
    pose proof (Rabs_pos z). nra. }
  destruct ts as [|b ts].
  - simpl. rewrite Rplus_0_r. constructor.
  - apply (sum_split v eta ez (a :: b :: ts) [a] (b :: ts) a (fold_right Rplus 0 (b :: ts)));
      [apply Permutation_refl | discriminate | discriminate | constructor | | | |].
    + apply IH. discriminate.
    + intros _ _. apply Hz.
    + intros Ha. left. simpl in *. lra.
    + intros Hb. left. simpl in *. lra.
Qed.

Lemma exact_exec : forall (g : nat -> node) (X x : nat -> R) j,
  op_wf (nop (g j)) j -> 0 <= nv (g j) -> 0 <= neta (g j) ->
  x j = exact_op X x (nop (g j)) -> exec_op X x (g j) (x j).
Proof.
  intros g X x j Hwf Hv He Hx.
  assert (Hz : forall z, ap1 (nv (g j)) (neta (g j)) z z).
  { intro z. unfold ap1. rewrite Rminus_diag_eq, Rabs_R0 by reflexivity.
    pose proof (Rabs_pos z). nra. }
  unfold exec_op. rewrite Hx.
  destruct (nop (g j)); simpl; try apply Hz; try reflexivity.
  - left. apply Hz.
  - destruct Hwf as [Hne _].
    apply sum_exec_exact; auto. destruct l; [congruence | discriminate].
Qed.

(** The triangle inequality from the exact value at the inputs as read (in
    [lor, hir]) to the one at the exact inputs (in [lo, hi]). *)
Lemma read_triangle : forall x xr y lo hi lor hir B,
  lo <= x <= hi -> lor <= xr <= hir -> Rabs (y - xr) <= B ->
  Rabs (y - x) <= B + Rmax (hir - lo) (hi - lor).
Proof.
  intros x xr y lo hi lor hir B Hx Hxr Hy.
  assert (Hd : Rabs (xr - x) <= Rmax (hir - lo) (hi - lor)).
  { pose proof (Rmax_l (hir - lo) (hi - lor)). pose proof (Rmax_r (hir - lo) (hi - lor)).
    unfold Rabs. destruct (Rcase_abs (xr - x)); lra. }
  pose proof (Rabs_triang (y - xr) (xr - x)).
  replace (y - xr + (xr - x)) with (y - x) in * by ring. lra.
Qed.

Theorem graph_sound_read :
  forall (g gr : nat -> node) (N : nat) (X Xr : nat -> R)
         (x xr y lo hi E S T lor hir Er Sr Tr : nat -> R),
  (forall j, (j < N)%nat -> nop (gr j) = nop (g j)) ->
  (forall j, (j < N)%nat -> op_wf (nop (g j)) j /\ 0 <= nv (g j) /\ 0 <= neta (g j)) ->
  (forall j, (j < N)%nat -> 0 <= nv (gr j) /\ 0 <= neta (gr j)) ->
  (forall j, (j < N)%nat -> x j = exact_op X x (nop (g j))) ->
  (forall j, (j < N)%nat -> xr j = exact_op Xr xr (nop (g j))) ->
  (forall j, (j < N)%nat -> exec_op Xr y (gr j) (y j)) ->
  (forall j, (j < N)%nat -> iv_ok g X lo hi S j /\ err_ok g lo hi E S T j) ->
  (forall j, (j < N)%nat -> iv_ok gr Xr lor hir Sr j /\ err_ok gr lor hir Er Sr Tr j) ->
  forall j, (j < N)%nat -> Rabs (y j - x j) <= Er j + Rmax (hir j - lo j) (hi j - lor j).
Proof.
  intros g gr N X Xr x xr y lo hi E S T lor hir Er Sr Tr
    Hop Hwf Hwr Hx Hxr Hy Hc Hcr j Hj.
  assert (Hx0 : lo j <= x j <= hi j).
  { apply (graph_sound g N X x x lo hi E S T Hwf Hx); auto.
    intros k Hk. destruct (Hwf k Hk) as (Hw & Hv & He).
    apply exact_exec; auto. }
  assert (Hr : lor j <= xr j <= hir j /\ Rabs (y j - xr j) <= Er j).
  { apply (graph_sound gr N Xr xr y lor hir Er Sr Tr); auto.
    - intros k Hk. rewrite Hop by exact Hk.
      destruct (Hwf k Hk) as (Hw & _). destruct (Hwr k Hk). auto.
    - intros k Hk. rewrite Hop by exact Hk. auto. }
  destruct Hr as [Hxr0 Hyr]. exact (read_triangle _ _ _ _ _ _ _ _ Hx0 Hxr0 Hyr).
Qed.
