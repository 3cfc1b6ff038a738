(** * SkipFloat.v — the float form of the skip test (src/skip/float.rs).

    Skip.v proves the exact decision sound; the float form decides in binary64
    alone. Every quantity is an interval [lo, hi]; an interval operation rounds
    each endpoint candidate to nearest and steps one float outward
    ([next_down], [next_up]), then takes the smallest of the stepped-down and the
    largest of the stepped-up candidates. Here the two steps are any functions
    [dn], [up] with [dn x <= x <= up x] (the Section [Enclosure]); binary64 is
    [dn64], [up64]: Flocq's [pred] and [succ] of [round radix2 (FLT_exp (-1074) 53)
    rnd x] for any valid rounding [rnd] (so round to nearest with any tie rule),
    which enclose x by Flocq's [pred_round_le_id] and [succ_round_ge_id].

    The model is total: where the Rust meets a result that is not finite, or a
    divisor interval that holds 0, it answers "do not skip", which needs no
    proof, and while every result is finite the float operations are Flocq's
    roundings of the real ones. Every division of the model is by an interval
    that the code has checked to exclude 0 ([mem_div] needs it). The two places
    where the code gives up on a value ([q.lo <= 0], [root <= 0]) are modelled
    ([phong_loop] returns [None]).

    - [phong_max] (Phong, Duff, symmetric Phong): the bound F of
      f(u) = p(u)/√q(u) on the segment N(u) = N_a + u (N_b − N_a), u ∈ [0, 1]
      ([seg_f]); [phong_max_sound]: f(u) <= F at every u ∈ [0, 1]. The largest f
      is at 0, at 1 or at the root −L₀/L₁ of L (Skip.v's [f_cands]); where L₁'s
      interval excludes 0, L₁ ≠ 0, so q = |N|² > 0 everywhere ([seg_q_pos]) and the
      root's interval holds the root; elsewhere [0, 1] itself is a candidate.
    - [quadratic_max] (corrected Euler, Euler, Gouraud): the bound of
      v(t) = p_a + t s_0 + t (t − 1)/2 ds on [0, n] with the exact set-up values
      [setup], from the candidates 0, n and t_v (Skip.v's [v_cands]);
      [quadratic_max_sound].
    - [squared_max] (the squared method, value sign(p)·√max(0, g)): g's set-up
      (SquaredSpan::new's formulas) in intervals ([isqsetup], [None] where a
      divisor's interval holds 0) from the exact values [sqsetup_exact], the
      bound G of its quadratic g(t) = g_a + t t_0 + t (t − 1)/2 ds on [0, n] by
      [quad_top], then the root rounded up, [up (sqrt G)] (0 where G <= 0);
      [squared_max_sound]: √max(0, g(t)) <= F at every t ∈ [0, n].
    - [below_one]: 255·K_s·(F + e)^s·(1 + u)^(2s+2) < 1 evaluated upward, the
      powers by repeated squaring ([pow_up]); [below_one_sound].

    The theorems [float_skip_sound] and [float_quadratic_skip_sound] are the two
    decisions at binary64: where the code skips, every value within e of the
    method's exact value at any point of the span has
    255·K_s·max(0, v)^s·(1 + u)^(2s+2) < 1. [float_squared_skip_sound] is the
    squared method's: every value at most √max(0, g) + e (so every value within
    e of sign(p)·√max(0, g)) has the same. *)

From Coq Require Import Reals Lra Lia Psatz List.
From Flocq Require Import Core.
From PhongApprox Require Import Skip.
Import ListNotations.
Open Scope R_scope.

(** ** Intervals and 3-vectors *)

Record Ivl := mkI { lo : R; hi : R }.

Definition mem (x : R) (X : Ivl) : Prop := lo X <= x <= hi X.

(** [I::pt]. *)
Definition ipt (x : R) : Ivl := mkI x x.

Definition Rltb (x y : R) : bool := if Rlt_dec x y then true else false.
Definition Rleb (x y : R) : bool := if Rle_dec x y then true else false.

Lemma Rltb_true x y : Rltb x y = true -> x < y.
Proof. unfold Rltb. destruct (Rlt_dec x y); congruence. Qed.
Lemma Rltb_false x y : Rltb x y = false -> y <= x.
Proof. unfold Rltb. destruct (Rlt_dec x y); [congruence | lra]. Qed.
Lemma Rleb_false x y : Rleb x y = false -> y < x.
Proof. unfold Rleb. destruct (Rle_dec x y); [congruence | lra]. Qed.

(** [o.lo > 0 || o.hi < 0]: the test before a division ([I::div]) and on L₁. *)
Definition excl0 (X : Ivl) : bool := Rltb 0 (lo X) || Rltb (hi X) 0.

Lemma excl0_true X : excl0 X = true -> 0 < lo X \/ hi X < 0.
Proof.
  unfold excl0. intros H. apply Bool.orb_true_iff in H.
  destruct H as [H | H]; apply Rltb_true in H; auto.
Qed.

Lemma excl0_mem X x : excl0 X = true -> mem x X -> x <> 0.
Proof. intros H [H1 H2]. apply excl0_true in H. lra. Qed.

(** [I::meet]: the intersection with [a, b], [None] where empty (max and min of
    floats are exact). *)
Definition imeet (X : Ivl) (a b : R) : option Ivl :=
  if Rleb (Rmax (lo X) a) (Rmin (hi X) b)
  then Some (mkI (Rmax (lo X) a) (Rmin (hi X) b)) else None.

Lemma mem_meet X a b x :
  mem x X -> a <= x <= b -> exists Y, imeet X a b = Some Y /\ mem x Y.
Proof.
  intros [H1 H2] Hab. unfold imeet, mem.
  assert (Rmax (lo X) a <= x) by (apply Rmax_lub; lra).
  assert (x <= Rmin (hi X) b) by (apply Rmin_glb; lra).
  destruct (Rleb _ _) eqn:E.
  - eexists. split; [reflexivity | simpl; lra].
  - apply Rleb_false in E. lra.
Qed.

Record V3 (T : Type) := mkV { cx : T; cy : T; cz : T }.
Arguments mkV {T}. Arguments cx {T}. Arguments cy {T}. Arguments cz {T}.

Definition dot3 (x y : V3 R) : R := cx x * cx y + cy x * cy y + cz x * cz y.
Definition vsub3 (x y : V3 R) : V3 R := mkV (cx x - cx y) (cy x - cy y) (cz x - cz y).
Definition vdiv3 (x : V3 R) (n : R) : V3 R := mkV (cx x / n) (cy x / n) (cz x / n).

(** [vec]: the float inputs as point intervals. *)
Definition vpt (x : V3 R) : V3 Ivl := mkV (ipt (cx x)) (ipt (cy x)) (ipt (cz x)).

Definition memv (x : V3 R) (X : V3 Ivl) : Prop :=
  mem (cx x) (cx X) /\ mem (cy x) (cy X) /\ mem (cz x) (cz X).

Lemma mem_pt x : mem x (ipt x).
Proof. unfold mem, ipt; simpl; lra. Qed.

Lemma memv_pt x : memv x (vpt x).
Proof. repeat split; simpl; lra. Qed.

(** ** Products and quotients lie between the corner values *)

Lemma lin_r k a b x :
  a <= x <= b -> (a * k <= x * k <= b * k) \/ (b * k <= x * k <= a * k).
Proof.
  intros H. destruct (Rle_dec 0 k).
  - left. split; apply Rmult_le_compat_r; lra.
  - right. split; nra.
Qed.

Lemma lin_l k a b x :
  a <= x <= b -> (k * a <= k * x <= k * b) \/ (k * b <= k * x <= k * a).
Proof. rewrite !(Rmult_comm k). apply lin_r. Qed.

Lemma corners a b c d x y :
  a <= x <= b -> c <= y <= d ->
  (a * c <= x * y \/ a * d <= x * y \/ b * c <= x * y \/ b * d <= x * y) /\
  (x * y <= a * c \/ x * y <= a * d \/ x * y <= b * c \/ x * y <= b * d).
Proof.
  intros Hx Hy.
  pose proof (lin_r y a b x Hx). pose proof (lin_l a c d y Hy).
  pose proof (lin_l b c d y Hy). lra.
Qed.

Lemma inv_between c d y :
  (0 < c \/ d < 0) -> c <= y <= d -> / d <= / y <= / c.
Proof.
  intros [Hc | Hd] Hy.
  - split; apply Rinv_le_contravar; lra.
  - assert (E : forall z, z < 0 -> / z = - / - z)
      by (intros z Hz; field; lra).
    rewrite (E d), (E y), (E c) by lra.
    assert (/ - c <= / - y) by (apply Rinv_le_contravar; lra).
    assert (/ - y <= / - d) by (apply Rinv_le_contravar; lra).
    lra.
Qed.

(** ** The interval operations, for any enclosing steps [dn], [up] *)

Section Enclosure.

Context (dn up : R -> R).
Context (Hdn : forall x, dn x <= x) (Hup : forall x, x <= up x).

(** [hull] of two or four candidates: Rust folds [min] of the [next_down]s and
    [max] of the [next_up]s from +∞ and −∞. *)
Definition hull2 (c1 c2 : R) : Ivl := mkI (Rmin (dn c1) (dn c2)) (Rmax (up c1) (up c2)).
Definition hull4 (c1 c2 c3 c4 : R) : Ivl :=
  mkI (Rmin (Rmin (Rmin (dn c1) (dn c2)) (dn c3)) (dn c4))
      (Rmax (Rmax (Rmax (up c1) (up c2)) (up c3)) (up c4)).

Definition iadd (X Y : Ivl) : Ivl := hull2 (lo X + lo Y) (hi X + hi Y).
Definition isub (X Y : Ivl) : Ivl := hull2 (lo X - hi Y) (hi X - lo Y).
Definition imul (X Y : Ivl) : Ivl :=
  hull4 (lo X * lo Y) (lo X * hi Y) (hi X * lo Y) (hi X * hi Y).
Definition idiv (X Y : Ivl) : Ivl :=
  hull4 (lo X / lo Y) (lo X / hi Y) (hi X / lo Y) (hi X / hi Y).

Definition idot (X Y : V3 Ivl) : Ivl :=
  iadd (iadd (imul (cx X) (cx Y)) (imul (cy X) (cy Y))) (imul (cz X) (cz Y)).
Definition ivsub (X Y : V3 Ivl) : V3 Ivl :=
  mkV (isub (cx X) (cx Y)) (isub (cy X) (cy Y)) (isub (cz X) (cz Y)).
Definition ivdiv (X : V3 Ivl) (N : Ivl) : V3 Ivl :=
  mkV (idiv (cx X) N) (idiv (cy X) N) (idiv (cz X) N).

Lemma hull2_mem c1 c2 z : (c1 <= z \/ c2 <= z) -> (z <= c1 \/ z <= c2) -> mem z (hull2 c1 c2).
Proof.
  intros H1 H2. pose proof (Hdn c1). pose proof (Hdn c2).
  pose proof (Hup c1). pose proof (Hup c2).
  unfold mem, hull2; simpl. split.
  - unfold Rmin. repeat destruct Rle_dec; lra.
  - unfold Rmax. repeat destruct Rle_dec; lra.
Qed.

Lemma hull4_mem c1 c2 c3 c4 z :
  (c1 <= z \/ c2 <= z \/ c3 <= z \/ c4 <= z) ->
  (z <= c1 \/ z <= c2 \/ z <= c3 \/ z <= c4) -> mem z (hull4 c1 c2 c3 c4).
Proof.
  intros H1 H2. pose proof (Hdn c1). pose proof (Hdn c2).
  pose proof (Hdn c3). pose proof (Hdn c4).
  pose proof (Hup c1). pose proof (Hup c2). pose proof (Hup c3). pose proof (Hup c4).
  unfold mem, hull4; simpl. split.
  - pose proof (Rmin_l (Rmin (Rmin (dn c1) (dn c2)) (dn c3)) (dn c4)).
    pose proof (Rmin_r (Rmin (Rmin (dn c1) (dn c2)) (dn c3)) (dn c4)).
    pose proof (Rmin_l (Rmin (dn c1) (dn c2)) (dn c3)).
    pose proof (Rmin_r (Rmin (dn c1) (dn c2)) (dn c3)).
    pose proof (Rmin_l (dn c1) (dn c2)). pose proof (Rmin_r (dn c1) (dn c2)). lra.
  - pose proof (Rmax_l (Rmax (Rmax (up c1) (up c2)) (up c3)) (up c4)).
    pose proof (Rmax_r (Rmax (Rmax (up c1) (up c2)) (up c3)) (up c4)).
    pose proof (Rmax_l (Rmax (up c1) (up c2)) (up c3)).
    pose proof (Rmax_r (Rmax (up c1) (up c2)) (up c3)).
    pose proof (Rmax_l (up c1) (up c2)). pose proof (Rmax_r (up c1) (up c2)). lra.
Qed.

Lemma mem_add x y X Y : mem x X -> mem y Y -> mem (x + y) (iadd X Y).
Proof. intros [] []. apply hull2_mem; lra. Qed.

Lemma mem_sub x y X Y : mem x X -> mem y Y -> mem (x - y) (isub X Y).
Proof. intros [] []. apply hull2_mem; lra. Qed.

Lemma mem_mul x y X Y : mem x X -> mem y Y -> mem (x * y) (imul X Y).
Proof.
  intros Hx Hy. destruct (corners _ _ _ _ x y Hx Hy). apply hull4_mem; assumption.
Qed.

Lemma mem_div x y X Y :
  mem x X -> mem y Y -> (0 < lo Y \/ hi Y < 0) -> mem (x / y) (idiv X Y).
Proof.
  intros Hx Hy H0.
  pose proof (inv_between _ _ _ H0 Hy) as Hi.
  destruct (corners _ _ _ _ x (/ y) Hx Hi).
  apply hull4_mem; unfold Rdiv; lra.
Qed.

Lemma mem_vsub x y X Y : memv x X -> memv y Y -> memv (vsub3 x y) (ivsub X Y).
Proof.
  intros (H1 & H2 & H3) (G1 & G2 & G3).
  repeat split; simpl; apply mem_sub; assumption.
Qed.

Lemma mem_vdiv x n X N :
  memv x X -> mem n N -> (0 < lo N \/ hi N < 0) -> memv (vdiv3 x n) (ivdiv X N).
Proof.
  intros (H1 & H2 & H3) Hn H0.
  repeat split; simpl; apply mem_div; assumption.
Qed.

Lemma mem_dot x y X Y : memv x X -> memv y Y -> mem (dot3 x y) (idot X Y).
Proof.
  intros (H1 & H2 & H3) (G1 & G2 & G3). unfold dot3, idot.
  repeat apply mem_add; apply mem_mul; assumption.
Qed.

(** ** Phong: [phong_max] *)

(** The loop over the candidates U of [phong_max]: P = B + U·A',
    Q = E + U·D' + (U·U)·C', give up where Q.lo <= 0; where P.hi > 0,
    root = next_down(√Q.lo) (give up where root <= 0) and the bound
    (P.hi / root).hi. *)
Fixpoint phong_loop (a b c d e : Ivl) (best : R) (us : list Ivl) : option R :=
  match us with
  | [] => Some best
  | U :: us' =>
      let P := iadd b (imul U a) in
      let Q := iadd (iadd e (imul U d)) (imul (imul U U) c) in
      if Rleb (lo Q) 0 then None
      else if Rltb 0 (hi P) then
        let root := dn (sqrt (lo Q)) in
        if Rleb root 0 then None
        else phong_loop a b c d e (Rmax best (hi (idiv (ipt (hi P)) (ipt root)))) us'
      else phong_loop a b c d e best us'
  end.

(** The candidates: [0, 0], [1, 1], and −L₀/L₁ met with [0, 1] (none where empty)
    where L₁'s interval excludes 0, else [0, 1]. *)
Definition phong_cands (l0 l1 : Ivl) : list Ivl :=
  ipt 0 :: ipt 1 ::
    (if excl0 l1 then
       match imeet (idiv (isub (ipt 0) l0) l1) 0 1 with Some r => [r] | None => [] end
     else [mkI 0 1]).

(** [phong_max]: A' = Δ·H, B = N_a·H, C' = Δ·Δ, D' = (Δ·N_a)·2, E = N_a·N_a,
    L₀ = A'E − (B D')·½, L₁ = (A' D')·½ − B C' (Δ = N_b − N_a). *)
Definition phong_max (na nb h : V3 R) : option R :=
  let NA := vpt na in
  let dN := ivsub (vpt nb) NA in
  let H := vpt h in
  let a := idot dN H in
  let b := idot NA H in
  let c := idot dN dN in
  let d := imul (idot dN NA) (ipt 2) in
  let e := idot NA NA in
  let half := ipt (/ 2) in
  let l0 := isub (imul a e) (imul (imul b d) half) in
  let l1 := isub (imul (imul a d) half) (imul b c) in
  phong_loop a b c d e 0 (phong_cands l0 l1).

End Enclosure.

(** ** The exact Phong values on the segment *)

(** f(u) = p(u)/√q(u) with Skip.v's p, q, f at the exact coefficients of the
    exact inputs. *)
Definition seg_f (na nb h : V3 R) (u : R) : R :=
  let d := vsub3 nb na in
  f (dot3 d h) (dot3 na h) (dot3 d d) (dot3 d na * 2) (dot3 na na) u.

(** It is N(u)·H / |N(u)| with N(u) = N_a + u (N_b − N_a). *)
Lemma seg_f_normal na nb h u :
  let N := mkV (cx na + u * (cx nb - cx na)) (cy na + u * (cy nb - cy na))
               (cz na + u * (cz nb - cz na)) in
  seg_f na nb h u = dot3 N h / sqrt (dot3 N N).
Proof.
  unfold seg_f, f, p, q, dot3, vsub3; simpl. f_equal; [| f_equal]; ring.
Qed.

(** At u = t/n it is Skip.v's f in the pixel parameter t, k = (N_b − N_a)/n:
    pixel i of the span is u = i/n. *)
Lemma seg_f_steps na nb h n t :
  n <> 0 ->
  let k := vdiv3 (vsub3 nb na) n in
  seg_f na nb h (t / n) = f (dot3 k h) (dot3 na h) (dot3 k k) (2 * dot3 k na) (dot3 na na) t.
Proof.
  intros Hn. unfold seg_f, f, p, q, dot3, vdiv3, vsub3; simpl.
  f_equal; [| f_equal]; field; exact Hn.
Qed.

(** q(u) = |N(u)|² vanishes only where N(u) = 0, and then L₁ = 0: where L₁ ≠ 0,
    q > 0 everywhere. *)
Lemma seg_q_pos na nb h u :
  let d := vsub3 nb na in
  dot3 d h * (dot3 d na * 2) / 2 - dot3 na h * dot3 d d <> 0 ->
  0 < q (dot3 d d) (dot3 d na * 2) (dot3 na na) u.
Proof.
  destruct na as [a0 a1 a2], nb as [b0 b1 b2], h as [h0 h1 h2].
  unfold vsub3, dot3, q; simpl. intros HL.
  set (d0 := b0 - a0) in *. set (d1 := b1 - a1) in *. set (d2 := b2 - a2) in *.
  set (w0 := a0 + u * d0). set (w1 := a1 + u * d1). set (w2 := a2 + u * d2).
  assert (Eq : a0 * a0 + a1 * a1 + a2 * a2 + (d0 * a0 + d1 * a1 + d2 * a2) * 2 * u
               + (d0 * d0 + d1 * d1 + d2 * d2) * u ^ 2 = w0 * w0 + w1 * w1 + w2 * w2)
    by (unfold w0, w1, w2; ring).
  assert (EL : (d0 * h0 + d1 * h1 + d2 * h2) * ((d0 * a0 + d1 * a1 + d2 * a2) * 2) / 2
               - (a0 * h0 + a1 * h1 + a2 * h2) * (d0 * d0 + d1 * d1 + d2 * d2)
               = (d0 * h0 + d1 * h1 + d2 * h2) * (d0 * w0 + d1 * w1 + d2 * w2)
                 - (w0 * h0 + w1 * h1 + w2 * h2) * (d0 * d0 + d1 * d1 + d2 * d2))
    by (unfold w0, w1, w2; field).
  clearbody w0 w1 w2.
  destruct (Rle_dec (w0 * w0 + w1 * w1 + w2 * w2) 0) as [Hle | Hlt]; [| lra].
  exfalso. apply HL.
  assert (w0 = 0) by nra. assert (w1 = 0) by nra. assert (w2 = 0) by nra.
  subst w0 w1 w2. rewrite EL. ring.
Qed.

(** ** The quadratic recurrences: exact set-up *)

Inductive Valued := Gouraud | Euler | CorrectedEuler.

(** n(n − 1)/2: the Rust's [(m * (m - 1) / 2) as f64], exact for an integer
    1 <= n <= 2^24. *)
Definition tri (n : R) : R := n * (n - 1) / 2.

(** The exact (p_a, s_0, ds) of [Span::setup] (eqs. 2–3, 10–17), operation for
    operation as [qsetup]: k = (N_b − N_a)/n, A = k·L, p_a = N_a·L, C = k·k,
    D = 2 (k·N_a), p_b = N_b·L, dq_b = 2 n C + D, di_a = A − (p_a/2) D,
    di_b = A − (p_b/2) dq_b, ds = (di_b − di_a)/n. *)
Definition setup (w : Valued) (na nb l : V3 R) (n : R) : R * R * R :=
  let k := vdiv3 (vsub3 nb na) n in
  let a := dot3 k l in
  let pa := dot3 na l in
  let c := dot3 k k in
  let d := 2 * dot3 k na in
  let pb := dot3 nb l in
  let dqb := 2 * n * c + d in
  let dia := a - pa / 2 * d in
  let dib := a - pb / 2 * dqb in
  let ds := (dib - dia) / n in
  match w with
  | Gouraud => (pa, (pb - pa) / n, 0)
  | Euler => (pa, dia, ds)
  | CorrectedEuler =>
      let pn := pa + n * dia + tri n * ds in
      (pa, dia - (pn - pb) / n, ds)
  end.

(** ** The squared method: exact set-up *)

(** The exact (g_a, t_0, ds) of [SquaredSpan::new]'s formulas, operation for
    operation as [isqsetup]: k = (N_b − N_a)/n, A = k·L, B = N_a·L, C = k·k,
    D = 2 (k·N_a), E = N_a·N_a, p_b = N_b·L, q_b = N_b·N_b, dq_b = 2 n C + D;
    g = p²/q at each end, g' = p (2 A q − p q')/(q q) at each end,
    ds = (dg_b − dg_a)/n, g_n = g_a + n dg_a + tri(n) ds, t_0 = dg_a − (g_n − g_b)/n. *)
Definition sqsetup_exact (na nb l : V3 R) (n : R) : R * R * R :=
  let k := vdiv3 (vsub3 nb na) n in
  let a := dot3 k l in
  let b := dot3 na l in
  let c := dot3 k k in
  let d := 2 * dot3 k na in
  let e := dot3 na na in
  let pb := dot3 nb l in
  let qb := dot3 nb nb in
  let dqb := 2 * n * c + d in
  let ga := b * b / e in
  let gb := pb * pb / qb in
  let dga := b * (2 * a * e - b * d) / (e * e) in
  let dgb := pb * (2 * a * qb - pb * dqb) / (qb * qb) in
  let ds := (dgb - dga) / n in
  let gn := ga + n * dga + tri n * ds in
  (ga, dga - (gn - gb) / n, ds).

(** ** The decisions, for any enclosing steps *)

Section Decision.

Context (dn up : R -> R).
Context (Hdn : forall x, dn x <= x) (Hup : forall x, x <= up x).

Local Notation iadd := (iadd dn up).
Local Notation isub := (isub dn up).
Local Notation imul := (imul dn up).
Local Notation idiv := (idiv dn up).
Local Notation idot := (idot dn up).
Local Notation ivsub := (ivsub dn up).
Local Notation ivdiv := (ivdiv dn up).
Local Notation mem_add := (mem_add dn up Hdn Hup).
Local Notation mem_sub := (mem_sub dn up Hdn Hup).
Local Notation mem_mul := (mem_mul dn up Hdn Hup).
Local Notation mem_div := (mem_div dn up Hdn Hup).
Local Notation mem_dot := (mem_dot dn up Hdn Hup).
Local Notation mem_vsub := (mem_vsub dn up Hdn Hup).
Local Notation mem_vdiv := (mem_vdiv dn up Hdn Hup).

(** *** Phong *)

Lemma phong_loop_sound A B C D E a b c d e best us F :
  mem A a -> mem B b -> mem C c -> mem D d -> mem E e -> 0 <= best ->
  phong_loop dn up a b c d e best us = Some F ->
  best <= F /\ forall U, In U us -> forall u, mem u U ->
    0 < q C D E u /\ f A B C D E u <= F.
Proof.
  intros Ha Hb Hc Hd He. revert best.
  induction us as [| U us IH]; intros best Hbest Hs.
  { cbn in Hs. injection Hs as <-. split; [lra | intros U []]. }
  cbn [phong_loop] in Hs.
  assert (HP : forall u, mem u U -> mem (p A B u) (iadd b (imul U a))).
  { intros u Hu. unfold p. rewrite (Rmult_comm A). apply mem_add; [exact Hb |].
    apply mem_mul; assumption. }
  assert (HQ : forall u, mem u U -> mem (q C D E u) (iadd (iadd e (imul U d)) (imul (imul U U) c))).
  { intros u Hu. unfold q. replace (C * u ^ 2) with (u * u * C) by ring.
    rewrite (Rmult_comm D). apply mem_add; [apply mem_add |]; [exact He | |];
      repeat apply mem_mul; assumption. }
  set (P := iadd b (imul U a)) in *.
  set (Q := iadd (iadd e (imul U d)) (imul (imul U U) c)) in *.
  destruct (Rleb (lo Q) 0) eqn:EQ; [discriminate |]. apply Rleb_false in EQ.
  assert (Hq : forall u, mem u U -> 0 < q C D E u)
    by (intros u Hu; destruct (HQ u Hu); lra).
  (* where P.hi <= 0, f <= 0 <= best on U *)
  assert (Hneg : forall G, hi P <= 0 -> best <= G -> forall u, mem u U -> f A B C D E u <= G).
  { intros G HPh HG u Hu. destruct (HP u Hu) as [_ Hp]. specialize (Hq u Hu).
    assert (0 < sqrt (q C D E u)) by (apply sqrt_lt_R0; lra).
    unfold f. assert (p A B u / sqrt (q C D E u) <= 0); [| lra].
    unfold Rdiv. assert (0 < / sqrt (q C D E u)) by (apply Rinv_0_lt_compat; lra). nra. }
  destruct (Rltb 0 (hi P)) eqn:EP.
  - apply Rltb_true in EP.
    set (root := dn (sqrt (lo Q))) in Hs.
    destruct (Rleb root 0) eqn:ER; [discriminate |]. apply Rleb_false in ER.
    set (G := Rmax best (hi (idiv (ipt (hi P)) (ipt root)))) in Hs.
    assert (HG0 : best <= G) by exact (Rmax_l _ _).
    destruct (IH G ltac:(lra) Hs) as [HGF Hrest].
    split; [lra |]. intros U' [<- | Hin]; [| apply Hrest; assumption].
    intros u Hu. split; [apply Hq, Hu |].
    (* f u = p/√q <= P.hi/√q <= P.hi/√Q.lo <= P.hi/root <= (P.hi/root).hi *)
    destruct (HP u Hu) as [_ Hp]. destruct (HQ u Hu) as [HQl _].
    assert (Hr1 : root <= sqrt (lo Q)) by exact (Hdn _).
    assert (Hr2 : sqrt (lo Q) <= sqrt (q C D E u)) by (apply sqrt_le_1_alt; lra).
    assert (Hdiv : mem (hi P / root) (idiv (ipt (hi P)) (ipt root)))
      by (apply mem_div; [apply mem_pt | apply mem_pt | left; simpl; lra]).
    assert (HGd : hi (idiv (ipt (hi P)) (ipt root)) <= G) by exact (Rmax_r _ _).
    assert (f A B C D E u <= hi P / root); [| destruct Hdiv; lra].
    unfold f, Rdiv.
    assert (0 < / sqrt (q C D E u)) by (apply Rinv_0_lt_compat; lra).
    assert (/ sqrt (q C D E u) <= / root) by (apply Rinv_le_contravar; lra).
    apply Rle_trans with (hi P * / sqrt (q C D E u)).
    + apply Rmult_le_compat_r; lra.
    + apply Rmult_le_compat_l; lra.
  - apply Rltb_false in EP.
    destruct (IH best Hbest Hs) as [HbF Hrest].
    split; [exact HbF |]. intros U' [<- | Hin]; [| apply Hrest; assumption].
    intros u Hu. split; [apply Hq, Hu | apply (Hneg F); assumption].
Qed.

(** [phong_max] bounds f on [0, 1] (and q > 0 there). *)
Lemma phong_max_sound na nb h F :
  phong_max dn up na nb h = Some F ->
  0 <= F /\ forall u, 0 <= u <= 1 ->
    0 < q (dot3 (vsub3 nb na) (vsub3 nb na)) (dot3 (vsub3 nb na) na * 2) (dot3 na na) u /\
    seg_f na nb h u <= F.
Proof.
  intros Hs. unfold phong_max in Hs. cbv zeta in Hs. unfold seg_f. cbv zeta.
  set (dv := vsub3 nb na).
  set (A := dot3 dv h). set (B := dot3 na h). set (C := dot3 dv dv).
  set (D := dot3 dv na * 2). set (E := dot3 na na).
  set (dN := ivsub (vpt nb) (vpt na)) in Hs.
  assert (HdN : memv dv dN) by (apply mem_vsub; apply memv_pt).
  set (a := idot dN (vpt h)) in Hs. set (b := idot (vpt na) (vpt h)) in Hs.
  set (c := idot dN dN) in Hs. set (d := imul (idot dN (vpt na)) (ipt 2)) in Hs.
  set (e := idot (vpt na) (vpt na)) in Hs.
  assert (Ha : mem A a) by (apply mem_dot; [exact HdN | apply memv_pt]).
  assert (Hb : mem B b) by (apply mem_dot; apply memv_pt).
  assert (Hc : mem C c) by (apply mem_dot; exact HdN).
  assert (Hd : mem D d)
    by (apply mem_mul; [apply mem_dot; [exact HdN | apply memv_pt] | apply mem_pt]).
  assert (He : mem E e) by (apply mem_dot; apply memv_pt).
  set (l0 := isub (imul a e) (imul (imul b d) (ipt (/ 2)))) in Hs.
  set (l1 := isub (imul (imul a d) (ipt (/ 2))) (imul b c)) in Hs.
  assert (Hl0 : mem (A * E - B * D * / 2) l0)
    by (apply mem_sub; [apply mem_mul; assumption |
                        apply mem_mul; [apply mem_mul; assumption | apply mem_pt]]).
  assert (Hl1 : mem (A * D * / 2 - B * C) l1)
    by (apply mem_sub; [apply mem_mul; [apply mem_mul; assumption | apply mem_pt] |
                        apply mem_mul; assumption]).
  destruct (phong_loop_sound A B C D E a b c d e 0 _ F Ha Hb Hc Hd He
              (Rle_refl 0) Hs) as [HF Hcand].
  split; [exact HF |]. intros u Hu.
  assert (Hin0 : In (ipt 0) (phong_cands dn up l0 l1))
    by (unfold phong_cands; left; reflexivity).
  assert (Hin1 : In (ipt 1) (phong_cands dn up l0 l1))
    by (unfold phong_cands; right; left; reflexivity).
  destruct (excl0 l1) eqn:EL.
  - (* L₁ ≠ 0: q > 0 everywhere; f u is at most f at 0, 1 or t* *)
    assert (HL1 : A * D / 2 - B * C <> 0) by exact (excl0_mem l1 _ EL Hl1).
    assert (Hq : forall x, 0 < q C D E x) by (intros x; apply (seg_q_pos na nb h x HL1)).
    split; [apply Hq |].
    destruct (f_cands A B C D E 1 u (fun x _ => Hq x) Hu) as [H0 | [H1 | (_ & Hts & Hle)]].
    + apply Rle_trans with (1 := H0), (proj2 (Hcand _ Hin0 0 (mem_pt 0))).
    + apply Rle_trans with (1 := H1), (proj2 (Hcand _ Hin1 1 (mem_pt 1))).
    + assert (Hts' : 0 <= tstar A B C D E <= 1) by lra.
      assert (Hr : mem (tstar A B C D E) (idiv (isub (ipt 0) l0) l1)).
      { replace (tstar A B C D E) with ((0 - (A * E - B * D * / 2)) / (A * D * / 2 - B * C))
          by (unfold tstar, Rdiv; ring).
        apply mem_div; [apply mem_sub; [apply mem_pt | exact Hl0] | exact Hl1 |].
        apply excl0_true, EL. }
      destruct (mem_meet _ 0 1 _ Hr Hts') as [r [Hm Hmr]].
      assert (Hinr : In r (phong_cands dn up l0 l1))
        by (unfold phong_cands; rewrite EL, Hm; right; right; left; reflexivity).
      apply Rle_trans with (1 := Hle), (proj2 (Hcand r Hinr _ Hmr)).
  - (* L₁ may be 0: [0, 1] itself is a candidate *)
    assert (Hin : In (mkI 0 1) (phong_cands dn up l0 l1))
      by (unfold phong_cands; rewrite EL; right; right; left; reflexivity).
    apply (Hcand _ Hin). exact Hu.
Qed.

(** The same bound as max(0, p(u))/√q(u) <= F. *)
Lemma phong_max_bound na nb h F :
  phong_max dn up na nb h = Some F ->
  forall u, 0 <= u <= 1 ->
    let d := vsub3 nb na in
    Rmax 0 (p (dot3 d h) (dot3 na h) u) / sqrt (q (dot3 d d) (dot3 d na * 2) (dot3 na na) u)
      <= F.
Proof.
  intros Hs u Hu d. destruct (phong_max_sound na nb h F Hs) as [HF Hall].
  destruct (Hall u Hu) as [Hq Hf]. unfold seg_f, f in Hf. fold d in Hf |- *.
  unfold Rmax. destruct (Rle_dec 0 _); [exact Hf |]. unfold Rdiv. rewrite Rmult_0_l. exact HF.
Qed.

(** *** The quadratic recurrences *)

(** The set-up in intervals (eqs. 2–3, 10–17), as [quadratic_max] computes it. *)
Definition qsetup (w : Valued) (na nb l : V3 R) (n : R) : Ivl * Ivl * Ivl :=
  let NA := vpt na in
  let NB := vpt nb in
  let Lv := vpt l in
  let N := ipt n in
  let two := ipt 2 in
  let k := ivdiv (ivsub NB NA) N in
  let a := idot k Lv in
  let pa := idot NA Lv in
  let c := idot k k in
  let d := imul two (idot k NA) in
  let pb := idot NB Lv in
  let dqb := iadd (imul (imul two N) c) d in
  let dia := isub a (imul (idiv pa two) d) in
  let dib := isub a (imul (idiv pb two) dqb) in
  let ds := idiv (isub dib dia) N in
  match w with
  | Gouraud => (pa, idiv (isub pb pa) N, ipt 0)
  | Euler => (pa, dia, ds)
  | CorrectedEuler =>
      let pn := iadd (iadd pa (imul N dia)) (imul (ipt (tri n)) ds) in
      (pa, isub dia (idiv (isub pn pb) N), ds)
  end.

(** v(T) = p_a + T·s_0 + ((T·(T − 1))·½)·ds. *)
Definition iv (PA S0 DS T : Ivl) : Ivl :=
  iadd (iadd PA (imul T S0)) (imul (imul (imul T (isub T (ipt 1))) (ipt (/ 2))) DS).

(** The candidates [0, 0], [n, n], and 1/2 − s_0/ds met with [0, n] where
    ds.hi < 0, or [0, n] where ds.lo < 0 <= ds.hi; the bound is the largest v.hi,
    from 0. *)
Definition quad_cands (S0 DS : Ivl) (n : R) : list Ivl :=
  let N := ipt n in
  ipt 0 :: N ::
    (if Rltb (hi DS) 0 then
       match imeet (isub (ipt (/ 2)) (idiv S0 DS)) 0 (hi N) with
       | Some T => [T] | None => [] end
     else if Rltb (lo DS) 0 then [mkI 0 (hi N)] else []).

Definition quad_top (PA S0 DS : Ivl) (n : R) : R :=
  fold_left (fun best T => Rmax best (hi (iv PA S0 DS T))) (quad_cands S0 DS n) 0.

Definition quadratic_max (w : Valued) (na nb l : V3 R) (n : R) : R :=
  let '(PA, S0, DS) := qsetup w na nb l n in quad_top PA S0 DS n.

(** Corrected Euler's start t_0 = s_0 − (p_n − p_b)/n with p_n = p_a + n s_0 + tri(n) ds
    (eq. 17), in intervals: shared by [qsetup] and [isqsetup]. *)
Lemma mem_ce_t0 n pa s0 ds pb PA S0 DS PB :
  0 < n -> mem pa PA -> mem s0 S0 -> mem ds DS -> mem pb PB ->
  mem (s0 - (pa + n * s0 + tri n * ds - pb) / n)
    (isub S0 (idiv (isub (iadd (iadd PA (imul (ipt n) S0)) (imul (ipt (tri n)) DS)) PB) (ipt n))).
Proof.
  intros Hn Hpa Hs0 Hds Hpb.
  apply mem_sub; [exact Hs0 |]. apply mem_div; [| apply mem_pt | left; exact Hn].
  apply mem_sub; [| exact Hpb].
  repeat apply mem_add; try apply mem_mul; try apply mem_pt; assumption.
Qed.

Lemma qsetup_sound w na nb l n pa s0 ds PA S0 DS :
  0 < n -> setup w na nb l n = (pa, s0, ds) -> qsetup w na nb l n = (PA, S0, DS) ->
  mem pa PA /\ mem s0 S0 /\ mem ds DS.
Proof.
  intros Hn Hs HS. unfold setup in Hs. unfold qsetup in HS. cbv zeta in Hs, HS.
  assert (HN : 0 < lo (ipt n) \/ hi (ipt n) < 0) by (left; exact Hn).
  assert (H2 : 0 < lo (ipt 2) \/ hi (ipt 2) < 0) by (left; simpl; lra).
  assert (Hk : memv (vdiv3 (vsub3 nb na) n) (ivdiv (ivsub (vpt nb) (vpt na)) (ipt n)))
    by (apply mem_vdiv; [apply mem_vsub; apply memv_pt | apply mem_pt | exact HN]).
  set (k := vdiv3 (vsub3 nb na) n) in *.
  set (K := ivdiv (ivsub (vpt nb) (vpt na)) (ipt n)) in *.
  assert (Hpa : mem (dot3 na l) (idot (vpt na) (vpt l))) by (apply mem_dot; apply memv_pt).
  assert (Hpb : mem (dot3 nb l) (idot (vpt nb) (vpt l))) by (apply mem_dot; apply memv_pt).
  assert (Ha : mem (dot3 k l) (idot K (vpt l))) by (apply mem_dot; [exact Hk | apply memv_pt]).
  assert (Hc : mem (dot3 k k) (idot K K)) by (apply mem_dot; exact Hk).
  assert (Hd : mem (2 * dot3 k na) (imul (ipt 2) (idot K (vpt na))))
    by (apply mem_mul; [apply mem_pt | apply mem_dot; [exact Hk | apply memv_pt]]).
  set (PAi := idot (vpt na) (vpt l)) in *. set (PBi := idot (vpt nb) (vpt l)) in *.
  set (Ai := idot K (vpt l)) in *. set (Ci := idot K K) in *.
  set (Di := imul (ipt 2) (idot K (vpt na))) in *.
  assert (Hdqb : mem (2 * n * dot3 k k + 2 * dot3 k na)
                   (iadd (imul (imul (ipt 2) (ipt n)) Ci) Di))
    by (apply mem_add; [repeat apply mem_mul; try apply mem_pt; exact Hc | exact Hd]).
  assert (Hdia : mem (dot3 k l - dot3 na l / 2 * (2 * dot3 k na))
                   (isub Ai (imul (idiv PAi (ipt 2)) Di)))
    by (apply mem_sub; [exact Ha | apply mem_mul; [apply mem_div; try apply mem_pt |]; assumption]).
  assert (Hdib : mem (dot3 k l - dot3 nb l / 2 * (2 * n * dot3 k k + 2 * dot3 k na))
                   (isub Ai (imul (idiv PBi (ipt 2))
                                   (iadd (imul (imul (ipt 2) (ipt n)) Ci) Di))))
    by (apply mem_sub; [exact Ha | apply mem_mul; [apply mem_div; try apply mem_pt |]; assumption]).
  set (dia := dot3 k l - dot3 na l / 2 * (2 * dot3 k na)) in *.
  set (dib := dot3 k l - dot3 nb l / 2 * (2 * n * dot3 k k + 2 * dot3 k na)) in *.
  set (DIA := isub Ai (imul (idiv PAi (ipt 2)) Di)) in *.
  set (DIB := isub Ai (imul (idiv PBi (ipt 2)) (iadd (imul (imul (ipt 2) (ipt n)) Ci) Di))) in *.
  assert (Hds : mem ((dib - dia) / n) (idiv (isub DIB DIA) (ipt n)))
    by (apply mem_div; [apply mem_sub; assumption | apply mem_pt | exact HN]).
  destruct w; injection Hs as <- <- <-; injection HS as <- <- <-.
  - split; [exact Hpa | split; [| apply mem_pt]].
    apply mem_div; [apply mem_sub; assumption | apply mem_pt | exact HN].
  - split; [exact Hpa | split; assumption].
  - split; [exact Hpa | split; [apply mem_ce_t0; assumption | exact Hds]].
Qed.

Lemma fold_max_ge (g : Ivl -> R) cands b0 :
  b0 <= fold_left (fun best T => Rmax best (g T)) cands b0 /\
  forall T, In T cands -> g T <= fold_left (fun best T => Rmax best (g T)) cands b0.
Proof.
  revert b0. induction cands as [| T0 cands IH]; intros b0; simpl.
  { split; [lra | intros T []]. }
  destruct (IH (Rmax b0 (g T0))) as [H1 H2].
  pose proof (Rmax_l b0 (g T0)). pose proof (Rmax_r b0 (g T0)).
  split; [lra |]. intros T [<- | Hin]; [lra | apply H2, Hin].
Qed.

Lemma mem_iv pa s0 ds PA S0 DS t T :
  mem pa PA -> mem s0 S0 -> mem ds DS -> mem t T -> mem (v pa s0 ds t) (iv PA S0 DS T).
Proof.
  intros Hp Hs Hd Ht. unfold v, Rdiv, iv.
  apply mem_add; [apply mem_add; [exact Hp | apply mem_mul; assumption] |].
  repeat apply mem_mul; try assumption; try apply mem_pt.
  apply mem_sub; [exact Ht | apply mem_pt].
Qed.

Lemma quad_top_sound pa s0 ds PA S0 DS n :
  0 < n -> mem pa PA -> mem s0 S0 -> mem ds DS ->
  0 <= quad_top PA S0 DS n /\
  forall t, 0 <= t <= n -> v pa s0 ds t <= quad_top PA S0 DS n.
Proof.
  intros Hn Hp Hs Hd. unfold quad_top.
  destruct (fold_max_ge (fun T => hi (iv PA S0 DS T)) (quad_cands S0 DS n) 0)
    as [H0 Hall].
  set (top := fold_left _ _ 0) in *.
  assert (Hc : forall c T, In T (quad_cands S0 DS n) -> mem c T -> v pa s0 ds c <= top).
  { intros c T Hin Hm. destruct (mem_iv pa s0 ds PA S0 DS c T Hp Hs Hd Hm).
    specialize (Hall T Hin). cbv beta in Hall. lra. }
  split; [exact H0 |]. intros t Ht.
  destruct (v_cands pa s0 ds n t Ht) as [H | [H | (Hds & Htv & H)]];
    apply Rle_trans with (1 := H).
  - apply (Hc 0 (ipt 0)); [unfold quad_cands; left; reflexivity | apply mem_pt].
  - apply (Hc n (ipt n)); [unfold quad_cands; right; left; reflexivity | apply mem_pt].
  - assert (Htv' : 0 <= tv s0 ds <= n) by lra.
    destruct (Rltb (hi DS) 0) eqn:E1.
    + pose proof (Rltb_true _ _ E1) as E1'.
      assert (Hm : mem (tv s0 ds) (isub (ipt (/ 2)) (idiv S0 DS)))
        by (apply mem_sub; [apply mem_pt | apply mem_div; [exact Hs | exact Hd | right; exact E1']]).
      destruct (mem_meet _ 0 (hi (ipt n)) _ Hm Htv') as [T [HT HmT]].
      apply (Hc _ T); [| exact HmT].
      unfold quad_cands; cbv zeta. rewrite E1, HT. right; right; left; reflexivity.
    + assert (E2 : Rltb (lo DS) 0 = true)
        by (unfold Rltb; destruct (Rlt_dec (lo DS) 0); [reflexivity | destruct Hd; lra]).
      apply (Hc _ (mkI 0 n)); [| exact Htv'].
      unfold quad_cands; cbv zeta. rewrite E1, E2. right; right; left; reflexivity.
Qed.

(** [quadratic_max] bounds v on [0, n], v at the exact set-up values. *)
Lemma quadratic_max_sound w na nb l n pa s0 ds :
  0 < n -> setup w na nb l n = (pa, s0, ds) ->
  0 <= quadratic_max w na nb l n /\
  forall t, 0 <= t <= n -> v pa s0 ds t <= quadratic_max w na nb l n.
Proof.
  intros Hn Hs. unfold quadratic_max.
  destruct (qsetup w na nb l n) as [[PA S0] DS] eqn:HS.
  destruct (qsetup_sound w na nb l n pa s0 ds PA S0 DS Hn Hs HS) as (H1 & H2 & H3).
  apply quad_top_sound; assumption.
Qed.

(** *** The squared method *)

(** The closure [slope] of [squared_max]: g' = p·(2A·q − p·q')/(q·q) as
    ((P·((2·A)·Q − P·DQ)) / (Q·Q)). *)
Definition islope (A P Q DQ : Ivl) : Ivl :=
  idiv (imul P (isub (imul (imul (ipt 2) A) Q) (imul P DQ))) (imul Q Q).

(** The set-up of [squared_max] in intervals, [None] where a divisor's interval
    (E, q_b, E·E, q_b·q_b, in the Rust's order) holds 0. *)
Definition isqsetup (na nb l : V3 R) (n : R) : option (Ivl * Ivl * Ivl) :=
  let NA := vpt na in
  let NB := vpt nb in
  let H := vpt l in
  let N := ipt n in
  let two := ipt 2 in
  let k := ivdiv (ivsub NB NA) N in
  let a := idot k H in
  let b := idot NA H in
  let c := idot k k in
  let d := imul two (idot k NA) in
  let e := idot NA NA in
  let pb := idot NB H in
  let qb := idot NB NB in
  let dqb := iadd (imul (imul two N) c) d in
  if negb (excl0 e) then None else
  let ga := idiv (imul b b) e in
  if negb (excl0 qb) then None else
  let gb := idiv (imul pb pb) qb in
  if negb (excl0 (imul e e)) then None else
  let dga := islope a b e d in
  if negb (excl0 (imul qb qb)) then None else
  let dgb := islope a pb qb dqb in
  let ds := idiv (isub dgb dga) N in
  let gn := iadd (iadd ga (imul N dga)) (imul (ipt (tri n)) ds) in
  Some (ga, isub dga (idiv (isub gn gb) N), ds).

(** [squared_max]: G = [quad_top] of the set-up; the bound is next_up of the
    root rounded to nearest, [up (sqrt G)], where G > 0, else 0. *)
Definition squared_max (na nb l : V3 R) (n : R) : option R :=
  match isqsetup na nb l n with
  | None => None
  | Some (GA, T0, DS) =>
      let G := quad_top GA T0 DS n in
      Some (if Rltb 0 G then up (sqrt G) else 0)
  end.

Lemma mem_slope a p q dq A P Q DQ :
  mem a A -> mem p P -> mem q Q -> mem dq DQ -> excl0 (imul Q Q) = true ->
  mem (p * (2 * a * q - p * dq) / (q * q)) (islope A P Q DQ).
Proof.
  intros Ha Hp Hq Hdq H0. unfold islope.
  assert (Hqq : mem (q * q) (imul Q Q)) by (apply mem_mul; assumption).
  apply mem_div; [| exact Hqq | apply excl0_true, H0].
  apply mem_mul; [exact Hp |]. apply mem_sub; [| apply mem_mul; assumption].
  repeat apply mem_mul; try assumption. apply mem_pt.
Qed.

Lemma isqsetup_sound na nb l n ga t0 ds GA T0 DS :
  0 < n -> sqsetup_exact na nb l n = (ga, t0, ds) ->
  isqsetup na nb l n = Some (GA, T0, DS) ->
  mem ga GA /\ mem t0 T0 /\ mem ds DS.
Proof.
  intros Hn Hs HS. unfold sqsetup_exact in Hs. unfold isqsetup in HS. cbv zeta in Hs, HS.
  assert (HN : 0 < lo (ipt n) \/ hi (ipt n) < 0) by (left; exact Hn).
  assert (Hk : memv (vdiv3 (vsub3 nb na) n) (ivdiv (ivsub (vpt nb) (vpt na)) (ipt n)))
    by (apply mem_vdiv; [apply mem_vsub; apply memv_pt | apply mem_pt | exact HN]).
  set (k := vdiv3 (vsub3 nb na) n) in *.
  set (K := ivdiv (ivsub (vpt nb) (vpt na)) (ipt n)) in *.
  assert (Ha : mem (dot3 k l) (idot K (vpt l))) by (apply mem_dot; [exact Hk | apply memv_pt]).
  assert (Hb : mem (dot3 na l) (idot (vpt na) (vpt l))) by (apply mem_dot; apply memv_pt).
  assert (Hc : mem (dot3 k k) (idot K K)) by (apply mem_dot; exact Hk).
  assert (Hd : mem (2 * dot3 k na) (imul (ipt 2) (idot K (vpt na))))
    by (apply mem_mul; [apply mem_pt | apply mem_dot; [exact Hk | apply memv_pt]]).
  assert (He : mem (dot3 na na) (idot (vpt na) (vpt na))) by (apply mem_dot; apply memv_pt).
  assert (Hpb : mem (dot3 nb l) (idot (vpt nb) (vpt l))) by (apply mem_dot; apply memv_pt).
  assert (Hqb : mem (dot3 nb nb) (idot (vpt nb) (vpt nb))) by (apply mem_dot; apply memv_pt).
  set (a := dot3 k l) in *. set (b := dot3 na l) in *. set (c := dot3 k k) in *.
  set (d := 2 * dot3 k na) in *. set (e := dot3 na na) in *.
  set (pb := dot3 nb l) in *. set (qb := dot3 nb nb) in *.
  set (Ai := idot K (vpt l)) in *. set (Bi := idot (vpt na) (vpt l)) in *.
  set (Ci := idot K K) in *. set (Di := imul (ipt 2) (idot K (vpt na))) in *.
  set (Ei := idot (vpt na) (vpt na)) in *. set (PBi := idot (vpt nb) (vpt l)) in *.
  set (QBi := idot (vpt nb) (vpt nb)) in *.
  assert (Hdqb : mem (2 * n * c + d) (iadd (imul (imul (ipt 2) (ipt n)) Ci) Di))
    by (apply mem_add; [repeat apply mem_mul; try apply mem_pt; exact Hc | exact Hd]).
  set (DQBi := iadd (imul (imul (ipt 2) (ipt n)) Ci) Di) in *.
  destruct (excl0 Ei) eqn:E1; [| discriminate].
  destruct (excl0 QBi) eqn:E2; [| discriminate].
  destruct (excl0 (imul Ei Ei)) eqn:E3; [| discriminate].
  destruct (excl0 (imul QBi QBi)) eqn:E4; [| discriminate].
  cbn [negb] in HS.
  assert (Hga : mem (b * b / e) (idiv (imul Bi Bi) Ei))
    by (apply mem_div; [apply mem_mul; assumption | exact He | apply excl0_true, E1]).
  assert (Hgb : mem (pb * pb / qb) (idiv (imul PBi PBi) QBi))
    by (apply mem_div; [apply mem_mul; assumption | exact Hqb | apply excl0_true, E2]).
  assert (Hdga : mem (b * (2 * a * e - b * d) / (e * e)) (islope Ai Bi Ei Di))
    by (apply mem_slope; assumption).
  assert (Hdgb : mem (pb * (2 * a * qb - pb * (2 * n * c + d)) / (qb * qb))
                   (islope Ai PBi QBi DQBi))
    by (apply mem_slope; assumption).
  set (ga' := b * b / e) in *. set (gb' := pb * pb / qb) in *.
  set (dga := b * (2 * a * e - b * d) / (e * e)) in *.
  set (dgb := pb * (2 * a * qb - pb * (2 * n * c + d)) / (qb * qb)) in *.
  assert (Hds : mem ((dgb - dga) / n) (idiv (isub (islope Ai PBi QBi DQBi) (islope Ai Bi Ei Di)) (ipt n)))
    by (apply mem_div; [apply mem_sub; assumption | apply mem_pt | exact HN]).
  injection Hs as <- <- <-. injection HS as <- <- <-.
  split; [exact Hga | split; [apply mem_ce_t0; assumption | exact Hds]].
Qed.

(** [squared_max] bounds √max(0, g) on [0, n], g = v at the exact set-up values. *)
Lemma squared_max_sound na nb l n ga t0 ds F :
  0 < n -> sqsetup_exact na nb l n = (ga, t0, ds) -> squared_max na nb l n = Some F ->
  0 <= F /\ forall t, 0 <= t <= n -> sqrt (Rmax 0 (v ga t0 ds t)) <= F.
Proof.
  intros Hn Hs HF. unfold squared_max in HF.
  destruct (isqsetup na nb l n) as [[[GA T0] DS] |] eqn:HS; [| discriminate].
  destruct (isqsetup_sound na nb l n ga t0 ds GA T0 DS Hn Hs HS) as (H1 & H2 & H3).
  destruct (quad_top_sound ga t0 ds GA T0 DS n Hn H1 H2 H3) as [HG Hall].
  set (G := quad_top GA T0 DS n) in *. cbv zeta in HF.
  destruct (Rltb 0 G) eqn:EG; injection HF as <-.
  - pose proof (Hup (sqrt G)) as Hr. pose proof (sqrt_pos G).
    split; [lra |]. intros t Ht.
    apply Rle_trans with (sqrt G); [| exact Hr].
    apply sqrt_le_1_alt. apply Rmax_lub; [exact HG | apply Hall, Ht].
  - apply Rltb_false in EG.
    split; [lra |]. intros t Ht.
    replace (Rmax 0 (v ga t0 ds t)) with 0; [rewrite sqrt_0; lra |].
    symmetry. apply Rle_antisym; [apply Rmax_lub; [lra | specialize (Hall t Ht); lra] | apply Rmax_l].
Qed.

End Decision.

(** ** [below_one]: the final inequality in upward rounding *)

Section Below.

Context (up : R -> R) (Hup : forall x, x <= up x).

(** The loop of [pow] from the bit pattern of the exponent: where [left] is odd,
    acc = up(acc·base); then [left] halves and, while it is not 0,
    base = up(base·base). *)
Fixpoint pow_up_pos (acc base : R) (k : positive) : R :=
  match k with
  | xH => up (acc * base)
  | xO k' => pow_up_pos acc (up (base * base)) k'
  | xI k' => pow_up_pos (up (acc * base)) (up (base * base)) k'
  end.

Definition pow_up (x : R) (k : N) : R :=
  match k with N0 => 1 | Npos k => pow_up_pos 1 x k end.

(** [below_one]: up(up(up(255·K_s)·pow(up(F + e), s))·pow(up(1 + u), 2s + 2)) < 1.
    The Rust also requires the total to be finite. A finite total means every
    step was finite: every factor is positive (a [next_up] of a value >= 0), so an
    infinite one would make the total infinite. *)
Definition below_one (F e ks uu : R) (s : nat) : Prop :=
  up (up (up (255 * ks) * pow_up (up (F + e)) (N.of_nat s))
      * pow_up (up (1 + uu)) (N.of_nat (2 * s + 2))) < 1.

Lemma pow_up_pos_ge acc base k :
  0 <= acc -> 0 <= base -> acc * base ^ Pos.to_nat k <= pow_up_pos acc base k.
Proof.
  revert acc base. induction k as [k IH | k IH |]; intros acc base Ha Hb; cbn [pow_up_pos].
  - rewrite Pos2Nat.inj_xI.
    assert (Hb2 : base * base <= up (base * base)) by apply Hup.
    assert (Hab : acc * base <= up (acc * base)) by apply Hup.
    assert (0 <= base * base) by nra. assert (0 <= acc * base) by nra.
    eapply Rle_trans; [| apply IH; lra].
    assert (E : base ^ (2 * Pos.to_nat k) = (base * base) ^ Pos.to_nat k)
      by (rewrite pow_mult; f_equal; ring).
    change (base ^ S (2 * Pos.to_nat k)) with (base * base ^ (2 * Pos.to_nat k)).
    rewrite E, <- Rmult_assoc.
    apply Rmult_le_compat; try lra; try (apply pow_le; lra).
    apply pow_incr; lra.
  - rewrite Pos2Nat.inj_xO.
    assert (Hb2 : base * base <= up (base * base)) by apply Hup.
    assert (0 <= base * base) by nra.
    eapply Rle_trans; [| apply IH; lra].
    rewrite pow_mult. replace (base ^ 2) with (base * base) by ring.
    apply Rmult_le_compat_l; [lra |]. apply pow_incr; lra.
  - rewrite Pos2Nat.inj_1, pow_1. apply Hup.
Qed.

Lemma pow_up_ge x s : 0 <= x -> x ^ s <= pow_up x (N.of_nat s).
Proof.
  intros Hx. destruct s as [| s]; cbn [N.of_nat pow_up]; [simpl; lra |].
  pose proof (pow_up_pos_ge 1 x (Pos.of_succ_nat s) ltac:(lra) Hx) as H.
  rewrite SuccNat2Pos.id_succ, Rmult_1_l in H. exact H.
Qed.

(** Where [below_one] holds at F, every v within e of any x <= F passes. *)
Lemma below_one_sound F e ks uu s :
  0 <= F -> 0 <= ks -> 0 <= e -> 0 <= uu -> below_one F e ks uu s ->
  forall x y, x <= F -> Rabs (y - x) <= e ->
  255 * ks * Rmax 0 y ^ s * (1 + uu) ^ (2 * s + 2) < 1.
Proof.
  intros HF Hk He Hu Hb x y Hx Hy. unfold below_one in Hb.
  assert (Hy' : y - x <= e) by (apply Rle_trans with (Rabs (y - x)); [apply Rle_abs | exact Hy]).
  set (m := Rmax 0 y).
  assert (Hm0 : 0 <= m) by apply Rmax_l.
  pose proof (Hup (F + e)) as HFe.
  assert (Hm : m <= up (F + e))
    by (apply Rle_trans with (F + e); [apply Rmax_lub; lra | exact HFe]).
  assert (H1 : m ^ s <= pow_up (up (F + e)) (N.of_nat s))
    by (apply Rle_trans with (up (F + e) ^ s);
        [apply pow_incr; lra | apply pow_up_ge; lra]).
  pose proof (Hup (1 + uu)) as Hw.
  assert (H2 : (1 + uu) ^ (2 * s + 2) <= pow_up (up (1 + uu)) (N.of_nat (2 * s + 2)))
    by (apply Rle_trans with (up (1 + uu) ^ (2 * s + 2));
        [apply pow_incr; lra | apply pow_up_ge; lra]).
  pose proof (Hup (255 * ks)) as HK.
  assert (0 <= m ^ s) by (apply pow_le; lra).
  assert (0 <= (1 + uu) ^ (2 * s + 2)) by (apply pow_le; lra).
  set (K1 := up (up (255 * ks) * pow_up (up (F + e)) (N.of_nat s))) in *.
  set (P2 := pow_up (up (1 + uu)) (N.of_nat (2 * s + 2))) in *.
  assert (H3 : 255 * ks * m ^ s <= K1).
  { apply Rle_trans with (up (255 * ks) * pow_up (up (F + e)) (N.of_nat s)); [| apply Hup].
    apply Rmult_le_compat; lra. }
  assert (255 * ks * m ^ s * (1 + uu) ^ (2 * s + 2) <= up (K1 * P2)); [| lra].
  apply Rle_trans with (K1 * P2); [| apply Hup].
  apply Rmult_le_compat; try lra. apply Rmult_le_pos; lra.
Qed.

End Below.

(** ** The two decisions for any enclosing steps *)

Lemma skip_sound_gen (dn up : R -> R) :
  (forall x, dn x <= x) -> (forall x, x <= up x) ->
  forall na nb h F ks e uu s,
  phong_max dn up na nb h = Some F -> below_one up F e ks uu s ->
  0 <= ks -> 0 <= e -> 0 <= uu ->
  forall u x, 0 <= u <= 1 -> Rabs (x - seg_f na nb h u) <= e ->
  255 * ks * Rmax 0 x ^ s * (1 + uu) ^ (2 * s + 2) < 1.
Proof.
  intros Hdn Hup na nb h F ks e uu s Hs Hb Hk He Hu u x Hu1 Hx.
  destruct (phong_max_sound dn up Hdn Hup na nb h F Hs) as [HF Hall].
  apply (below_one_sound up Hup F e ks uu s HF Hk He Hu Hb (seg_f na nb h u) x);
    [apply Hall, Hu1 | exact Hx].
Qed.

Lemma quadratic_skip_sound_gen (dn up : R -> R) :
  (forall x, dn x <= x) -> (forall x, x <= up x) ->
  forall w na nb l n ks e uu s pa s0 ds,
  0 < n -> setup w na nb l n = (pa, s0, ds) ->
  below_one up (quadratic_max dn up w na nb l n) e ks uu s ->
  0 <= ks -> 0 <= e -> 0 <= uu ->
  forall t x, 0 <= t <= n -> Rabs (x - v pa s0 ds t) <= e ->
  255 * ks * Rmax 0 x ^ s * (1 + uu) ^ (2 * s + 2) < 1.
Proof.
  intros Hdn Hup w na nb l n ks e uu s pa s0 ds Hn Hs Hb Hk He Hu t x Ht Hx.
  destruct (quadratic_max_sound dn up Hdn Hup w na nb l n pa s0 ds Hn Hs) as [HF Hall].
  apply (below_one_sound up Hup _ e ks uu s HF Hk He Hu Hb (v pa s0 ds t) x);
    [apply Hall, Ht | exact Hx].
Qed.

Lemma squared_skip_sound_gen (dn up : R -> R) :
  (forall x, dn x <= x) -> (forall x, x <= up x) ->
  forall na nb l n ks e uu F s ga t0 ds,
  0 < n -> sqsetup_exact na nb l n = (ga, t0, ds) ->
  squared_max dn up na nb l n = Some F -> below_one up F e ks uu s ->
  0 <= ks -> 0 <= e -> 0 <= uu ->
  forall t x, 0 <= t <= n -> x <= sqrt (Rmax 0 (v ga t0 ds t)) + e ->
  255 * ks * Rmax 0 x ^ s * (1 + uu) ^ (2 * s + 2) < 1.
Proof.
  intros Hdn Hup na nb l n ks e uu F s ga t0 ds Hn Hs HF Hb Hk He Hu t x Ht Hx.
  destruct (squared_max_sound dn up Hdn Hup na nb l n ga t0 ds F Hn Hs HF) as [HF0 Hall].
  pose proof (Hall t Ht) as Hg.
  (* x is within e of min(x, F) <= F *)
  apply (below_one_sound up Hup F e ks uu s HF0 Hk He Hu Hb (Rmin x F) x);
    [apply Rmin_r |].
  unfold Rmin. destruct (Rle_dec x F).
  - rewrite Rminus_diag_eq, Rabs_R0 by reflexivity. exact He.
  - rewrite Rabs_right by lra. lra.
Qed.

(** ** binary64 *)

Definition fexp64 : Z -> Z := FLT_exp (-1074) 53.

(** [next_down] and [next_up] of the rounded result. *)
Definition dn64 (rnd : R -> Z) (x : R) : R :=
  pred radix2 fexp64 (round radix2 fexp64 rnd x).
Definition up64 (rnd : R -> Z) (x : R) : R :=
  succ radix2 fexp64 (round radix2 fexp64 rnd x).

Lemma dn64_le rnd : Valid_rnd rnd -> forall x, dn64 rnd x <= x.
Proof.
  intros Hr x. assert (Prec_gt_0 53) by (unfold Prec_gt_0; lia).
  apply pred_round_le_id; typeclasses eauto.
Qed.

Lemma up64_ge rnd : Valid_rnd rnd -> forall x, x <= up64 rnd x.
Proof.
  intros Hr x. assert (Prec_gt_0 53) by (unfold Prec_gt_0; lia).
  apply succ_round_ge_id; typeclasses eauto.
Qed.

(** The Phong decision at binary64 (for round to nearest with ties to even,
    [rnd] = [ZnearestE], and any other valid rounding). *)
Theorem float_skip_sound : forall (rnd : R -> Z), Valid_rnd rnd ->
  forall (na nb h : V3 R) (F ks e uu : R) (s : nat),
  phong_max (dn64 rnd) (up64 rnd) na nb h = Some F ->
  below_one (up64 rnd) F e ks uu s ->
  0 <= ks -> 0 <= e -> 0 <= uu ->
  forall u x, 0 <= u <= 1 -> Rabs (x - seg_f na nb h u) <= e ->
  255 * ks * Rmax 0 x ^ s * (1 + uu) ^ (2 * s + 2) < 1.
Proof.
  intros rnd Hr. apply skip_sound_gen; [apply dn64_le | apply up64_ge]; exact Hr.
Qed.

(** The quadratic decision at binary64, for each of the three set-ups. *)
Theorem float_quadratic_skip_sound : forall (rnd : R -> Z), Valid_rnd rnd ->
  forall (w : Valued) (na nb l : V3 R) (n ks e uu : R) (s : nat) (pa s0 ds : R),
  0 < n -> setup w na nb l n = (pa, s0, ds) ->
  below_one (up64 rnd) (quadratic_max (dn64 rnd) (up64 rnd) w na nb l n) e ks uu s ->
  0 <= ks -> 0 <= e -> 0 <= uu ->
  forall t x, 0 <= t <= n -> Rabs (x - v pa s0 ds t) <= e ->
  255 * ks * Rmax 0 x ^ s * (1 + uu) ^ (2 * s + 2) < 1.
Proof.
  intros rnd Hr. apply quadratic_skip_sound_gen; [apply dn64_le | apply up64_ge]; exact Hr.
Qed.

(** The squared decision at binary64: every value at most e above √max(0, g). *)
Theorem float_squared_skip_sound : forall (rnd : R -> Z), Valid_rnd rnd ->
  forall (na nb l : V3 R) (n ks e uu F : R) (s : nat) (ga t0 ds : R),
  0 < n -> sqsetup_exact na nb l n = (ga, t0, ds) ->
  squared_max (dn64 rnd) (up64 rnd) na nb l n = Some F ->
  below_one (up64 rnd) F e ks uu s ->
  0 <= ks -> 0 <= e -> 0 <= uu ->
  forall t x, 0 <= t <= n -> x <= sqrt (Rmax 0 (v ga t0 ds t)) + e ->
  255 * ks * Rmax 0 x ^ s * (1 + uu) ^ (2 * s + 2) < 1.
Proof.
  intros rnd Hr. apply squared_skip_sound_gen; [apply dn64_le | apply up64_ge]; exact Hr.
Qed.
