(** * FloatModelK.v — a floating-point model for a CLASS of implementations.

    [FloatModel.v] fixes one rounding function and one evaluation order.
    Here a computed value is only known to be within the per-operation bound
    of the exact result of its operation on the computed operands:

        approx k u eta y x   :=   |y - x| <= k u |x| + eta

    (y is the computed value, x the exact result of the operation applied to
    the computed operands).  Every operation may round differently (another
    direction, another mode, flushing or not), so nothing is assumed about a
    rounding function: a computation is a relation between the inputs and
    every value an implementation may produce.  A model ([fmodel]) gives the
    unit roundoff u, the absolute term eta (underflow, flushing of subnormal
    results to zero) and one factor per operation class:
      k_in  : reading an input (the exact reals Na, Nb, L rounded to the format);
      k_add : addition and subtraction;
      k_mul : multiplication;
      k_div : division, or a reciprocal followed by a multiplication.
    An operation done exactly (a product inside a fused multiply-add, an
    intermediate kept in a wider format) satisfies [approx] for every k, so
    fused multiply-adds are covered wherever a product feeds an addition.

    Three-term sums: [sum3_rel ua eta q1 q2 q3 y] holds when y is
    ((q_i + q_j) + q_k) for SOME permutation (i, j, k) of (1, 2, 3), each of
    the two additions within its [approx] bound; addition of reals being
    commutative, this is every association and every order of the three
    terms.  A dot product [fdot_rel] is such a sum of three products, each
    product rounded (k_mul) or exact (fused).  The one fact about them used
    later is [fdot_err]:

        |y - a.b| <= (um + 2 ua)(1 + 2^-19) (|a1 b1| + |a2 b2| + |a3 b3|) + 8 eta

    for every order and every fusion (um = k_mul u, ua = k_add u).

    Size conditions ([model_ok M K]): K >= 1 bounds every k, K u <= 2^-21,
    eta 2^84 <= u.  They hold for binary32 and binary64 with k up to 8 for
    binary32 (2^3 2^-24 = 2^-21), e.g. k = 5 for a 2.5-ulp division.

    The section [V] redoes FloatModel.v's forward-error library for any
    relation bounded by one unit v (every k u <= v), [fdot_abs] is the
    weighted dot-product lemma with absolute weights, and [gseq_err],
    [cseq_err] are the loops (Gouraud, corrected Euler) with a possibly
    different rounding at every step (FloatModel.v's loops [gloop], [floop]
    are their case w = u, as in Float.v).  The product and dot-product steps shared with
    FloatModel.v are its [comp_prod_abs] and [fdot_core]. *)

From Coq Require Import Reals Lra Lia.
From Flocq Require Import Core Relative.
From PhongApprox Require Import Span FloatModel.
Open Scope R_scope.

(** ** The model *)

(** One operation with error unit v: |y - x| <= v |x| + eta. *)
Definition ap1 (v eta y x : R) : Prop := Rabs (y - x) <= v * Rabs x + eta.

(** The same with v = k u. *)
Definition approx (k u eta y x : R) : Prop := ap1 (k * u) eta y x.

Record fmodel := mkModel {
  m_u : R; m_eta : R; k_in : R; k_add : R; k_mul : R; k_div : R }.

Definition ap_in (M : fmodel) : R -> R -> Prop := approx (k_in M) (m_u M) (m_eta M).
Definition ap_add (M : fmodel) : R -> R -> Prop := approx (k_add M) (m_u M) (m_eta M).
Definition ap_mul (M : fmodel) : R -> R -> Prop := approx (k_mul M) (m_u M) (m_eta M).
Definition ap_div (M : fmodel) : R -> R -> Prop := approx (k_div M) (m_u M) (m_eta M).

(** Size conditions; K is any common bound of the four factors. *)
Definition model_ok (M : fmodel) (K : R) : Prop :=
  0 < m_u M /\ 0 <= m_eta M /\ m_eta M * 19342813113834066795298816 <= m_u M /\
  0 <= k_in M <= K /\ 0 <= k_add M <= K /\ 0 <= k_mul M <= K /\ 0 <= k_div M <= K /\
  1 <= K /\ K * m_u M <= / 2097152.

(** Three-term sums in any order: ((q_i + q_j) + q_k), (i, j, k) any permutation. *)
Definition sum3_rel (ua eta q1 q2 q3 y : R) : Prop :=
  exists r,
    (ap1 ua eta r (q1 + q2) /\ ap1 ua eta y (r + q3)) \/
    (ap1 ua eta r (q1 + q3) /\ ap1 ua eta y (r + q2)) \/
    (ap1 ua eta r (q2 + q3) /\ ap1 ua eta y (r + q1)).

(** Dot products: the three products, each rounded or exact (fused), summed in any order. *)
Definition fdot_rel (um ua eta : R) (a b : vec) (y : R) : Prop :=
  exists q1 q2 q3,
    ap1 um eta q1 (vx a * vx b) /\ ap1 um eta q2 (vy a * vy b) /\
    ap1 um eta q3 (vz a * vz b) /\ sum3_rel ua eta q1 q2 q3 y.

Definition sum3 (M : fmodel) : R -> R -> R -> R -> Prop :=
  sum3_rel (k_add M * m_u M) (m_eta M).
Definition fdot_ok (M : fmodel) : vec -> vec -> R -> Prop :=
  fdot_rel (k_mul M * m_u M) (k_add M * m_u M) (m_eta M).

(** ** Basic facts *)

Lemma ap1_exact : forall v eta x, 0 <= v -> 0 <= eta -> ap1 v eta x x.
Proof.
  intros v eta x Hv He. unfold ap1. rewrite Rminus_diag_eq, Rabs_R0 by reflexivity.
  pose proof (Rabs_pos x). pose proof (Rmult_le_pos v (Rabs x) Hv (Rabs_pos x)). lra.
Qed.

Lemma ap1_mono : forall v v' eta y x, v <= v' -> ap1 v eta y x -> ap1 v' eta y x.
Proof.
  intros v v' eta y x Hv H. unfold ap1 in *.
  assert (v * Rabs x <= v' * Rabs x) by (apply Rmult_le_compat_r; [apply Rabs_pos | exact Hv]).
  lra.
Qed.

Lemma sum3_mono : forall ua ua' eta q1 q2 q3 y, ua <= ua' ->
  sum3_rel ua eta q1 q2 q3 y -> sum3_rel ua' eta q1 q2 q3 y.
Proof.
  intros ua ua' eta q1 q2 q3 y Hu [r [[H1 H2] | [[H1 H2] | [H1 H2]]]]; exists r;
    [left | right; left | right; right]; split; eapply ap1_mono; eassumption.
Qed.

Lemma fdot_mono : forall um ua um' ua' eta a b y, um <= um' -> ua <= ua' ->
  fdot_rel um ua eta a b y -> fdot_rel um' ua' eta a b y.
Proof.
  intros um ua um' ua' eta a b y H1 H2 (q1 & q2 & q3 & A1 & A2 & A3 & A4).
  exists q1, q2, q3. repeat split; try (eapply ap1_mono; eassumption).
  eapply sum3_mono; eassumption.
Qed.

Lemma model_u : forall M K, model_ok M K -> 0 < m_u M.
Proof. intros M K H. apply H. Qed.

(** The units k u of a model are at most K u <= 2^-21. *)
Lemma model_unit : forall M K k, model_ok M K -> 0 <= k <= K ->
  0 <= k * m_u M <= K * m_u M /\ K * m_u M <= / 2097152.
Proof.
  intros M K k (H1 & H2 & H3 & _ & _ & _ & _ & H8 & H9) Hk. split; [split|exact H9].
  - apply Rmult_le_pos; lra.
  - apply Rmult_le_compat_r; lra.
Qed.

(** ** Three-term sums in any order *)

(** Every order of a three-term sum (one order: FloatModel.v's [sum_chain_abs]). *)
Lemma sum3_err : forall um ua eta x1 x2 x3 q1 q2 q3 y,
  0 <= um <= / 2097152 -> 0 <= ua <= / 2097152 -> 0 <= eta ->
  ap1 um eta q1 x1 -> ap1 um eta q2 x2 -> ap1 um eta q3 x3 ->
  sum3_rel ua eta q1 q2 q3 y ->
  Rabs (y - (x1 + x2 + x3)) <=
  (um + 2 * ua) * (1 + / 524288) * (Rabs x1 + Rabs x2 + Rabs x3) + 8 * eta.
Proof.
  intros um ua eta x1 x2 x3 q1 q2 q3 y Hm Ha He H1 H2 H3 [r [[H4 H5] | [[H4 H5] | [H4 H5]]]].
  - eapply sum_chain_abs; eassumption.
  - replace (x1 + x2 + x3) with (x1 + x3 + x2) by ring.
    replace (Rabs x1 + Rabs x2 + Rabs x3) with (Rabs x1 + Rabs x3 + Rabs x2) by ring.
    eapply sum_chain_abs; eassumption.
  - replace (x1 + x2 + x3) with (x2 + x3 + x1) by ring.
    replace (Rabs x1 + Rabs x2 + Rabs x3) with (Rabs x2 + Rabs x3 + Rabs x1) by ring.
    eapply sum_chain_abs; eassumption.
Qed.

(** The dot-product lemma: every evaluation order, every fusion. *)
Lemma fdot_err : forall um ua eta a b y,
  0 <= um <= / 2097152 -> 0 <= ua <= / 2097152 -> 0 <= eta ->
  fdot_rel um ua eta a b y ->
  Rabs (y - dot a b) <=
  (um + 2 * ua) * (1 + / 524288)
    * (Rabs (vx a * vx b) + Rabs (vy a * vy b) + Rabs (vz a * vz b)) + 8 * eta.
Proof.
  intros um ua eta a b y Hm Ha He (q1 & q2 & q3 & H1 & H2 & H3 & H4).
  unfold dot. eapply sum3_err; eassumption.
Qed.

(** ** Error library for one unit v (every k u <= v) *)

Definition small_ok (v eta : R) : Prop :=
  0 < v /\ v <= / 2097152 /\ 0 <= eta /\ eta * 19342813113834066795298816 <= v.

Section V.
Context (v eta : R) (Hv : small_ok v eta).

Lemma v_pos : 0 < v.
Proof. apply Hv. Qed.
Lemma v_small : v <= / 2097152.
Proof. apply Hv. Qed.
Lemma e_pos : 0 <= eta.
Proof. apply Hv. Qed.
Lemma e_small : eta * 19342813113834066795298816 <= v.
Proof. apply Hv. Qed.

(** One operation on a value scaled by lam <= 2^48 (the scale is n or n^2, n <= 2^24). *)
Lemma ap_sc : forall lam y x M, ap1 v eta y x -> 0 <= lam <= 281474976710656 -> Rabs (lam * x) <= M ->
  Rabs (lam * y - lam * x) <= (M + / 68719476736) * v.
Proof.
  intros lam y x M Hx Hl HM.
  pose proof v_pos. pose proof e_small. pose proof e_pos.
  rewrite <- Rmult_minus_distr_l, Rabs_mult, (Rabs_pos_eq lam) by lra.
  unfold ap1 in Hx.
  assert (K1 : lam * Rabs (y - x) <= lam * (v * Rabs x + eta))
    by (apply Rmult_le_compat_l; lra).
  assert (K2 : lam * Rabs x = Rabs (lam * x))
    by (rewrite Rabs_mult, (Rabs_pos_eq lam); lra).
  assert (K3 : lam * eta <= 281474976710656 * eta) by (apply Rmult_le_compat_r; lra).
  assert (K4 : v * (lam * Rabs x) <= v * M) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

Lemma ap_1 : forall y x M, ap1 v eta y x -> Rabs x <= M -> Rabs (y - x) <= (M + / 68719476736) * v.
Proof.
  intros y x M Hx H. pose proof (ap_sc 1 y x M Hx) as H1.
  rewrite !Rmult_1_l in H1. apply H1; [lra | exact H].
Qed.

Lemma ap_step : forall lam y x Y X e M, ap1 v eta y x -> 0 <= lam <= 281474976710656 -> lam * x = Y ->
  Rabs (Y - X) <= e -> Rabs X + e <= M ->
  Rabs (lam * y - X) <= e + (M + / 68719476736) * v.
Proof.
  intros lam y x Y X e M Hy Hl HY He HM.
  assert (HB : Rabs (lam * x) <= M) by (rewrite HY; pose proof (abs_near X Y e He); lra).
  pose proof (ap_sc lam y x M Hy Hl HB) as H.
  replace (lam * y - X) with ((lam * y - lam * x) + (Y - X)) by (rewrite <- HY; ring).
  eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.

Lemma in_comp : forall y x, ap1 v eta y x -> Rabs (y - x) <= v * (Rabs x + / 1073741824).
Proof.
  intros y x H. unfold ap1 in H. pose proof v_pos. pose proof e_small. lra.
Qed.

(** Dot product with unit v for products and additions, in any order. *)
Lemma fdot_v : forall a b y, fdot_rel v v eta a b y ->
  Rabs (y - dot a b) <=
  (3 + / 131072) * v * (Rabs (vx a * vx b) + Rabs (vy a * vy b) + Rabs (vz a * vz b)) + 8 * eta.
Proof.
  intros a b y H. pose proof v_pos. pose proof v_small. pose proof e_pos.
  eapply Rle_trans; [exact (fdot_err v v eta a b y ltac:(lra) ltac:(lra) ltac:(lra) H)|].
  pose proof (Rabs_pos (vx a * vx b)). pose proof (Rabs_pos (vy a * vy b)).
  pose proof (Rabs_pos (vz a * vz b)). nra.
Qed.

End V.

(** The size facts of a unit: 0 < v <= 2^-21 ([v_facts]), and of eta ([small_facts]). *)
Ltac v_facts Hv := match type of Hv with small_ok ?v ?eta =>
  pose proof (v_pos v eta Hv); pose proof (v_small v eta Hv) end.
Ltac small_facts Hv := v_facts Hv; match type of Hv with small_ok ?v ?eta =>
  pose proof (e_pos v eta Hv); pose proof (e_small v eta Hv) end.

(** Weighted error of a computed dot product of two approximated vectors,
    with absolute weights: |lam ah_j - a_j| <= wa_j, |mu bh_j - b_j| <= wb_j,
    every weight at most W. *)
Definition wsum0 (a b wa wb : vec) : R :=
  Rabs (vx a) * vx wb + vx wa * Rabs (vx b) + (Rabs (vy a) * vy wb + vy wa * Rabs (vy b))
  + (Rabs (vz a) * vz wb + vz wa * Rabs (vz b)).
Definition wle (w : vec) (W : R) : Prop :=
  0 <= vx w <= W /\ 0 <= vy w <= W /\ 0 <= vz w <= W.

Section VA.
Context (v eta : R) (Hv : small_ok v eta).

Lemma fdot_abs : forall (lam mu y W : R) (ah bh a b wa wb : vec),
  fdot_rel v v eta ah bh y ->
  0 < lam -> 0 < mu -> lam * mu <= 281474976710656 ->
  vapprox 1 lam ah a wa -> vapprox 1 mu bh b wb ->
  vbounded a 2 -> vbounded b 2 -> wle wa W -> wle wb W ->
  Rabs (lam * mu * y - dot a b) <= wsum0 a b wa wb + 3 * (W * W)
    + (3 + / 131072) * v * (Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b)
                            + Rabs (vz a) * Rabs (vz b) + 12 * W + 3 * (W * W))
    + 8 * (281474976710656 * eta).
Proof.
  intros lam mu y W ah bh a b wa wb Hy. small_facts Hv. intros.
  eapply Rle_trans; [apply (fdot_core ((3 + / 131072) * v) (8 * eta) 281474976710656 lam mu y W
    ah bh a b wa wb); try assumption; try lra; apply (fdot_v v eta Hv _ _ _ Hy)|].
  unfold wsum0. lra.
Qed.

End VA.

(** ** The loops, with a possibly different rounding at every step *)

(** Gouraud: G_{j+1} within w|G_j + d| + eta of G_j + d (FloatModel.v's [gloop]). *)
Lemma gseq_err : forall (w eta : R) (G : nat -> R) (d : R) (m : nat) (Mg : R),
  0 <= w -> 0 <= eta -> 0 <= Mg ->
  (forall j, (j < m)%nat -> ap1 w eta (G (S j)) (G j + d)) ->
  (forall j, (j < m)%nat -> Rabs (G O + INR (S j) * d) + INR m * (w * Mg + eta) <= Mg) ->
  forall i, (i <= m)%nat ->
  Rabs (G i - (G O + INR i * d)) <= INR i * (w * Mg + eta).
Proof.
  intros w eta G d m Mg Hw He HMg Hstep HG i.
  set (g0 := G O) in *.
  induction i as [| i IH]; intros Hi.
  - cbn [INR]. unfold g0. rewrite Rminus_diag_eq, Rabs_R0 by ring. lra.
  - specialize (IH ltac:(lia)). pose proof (Hstep i ltac:(lia)) as St. unfold ap1 in St.
    set (Gh := G i) in *.
    specialize (HG i ltac:(lia)).
    assert (Him : INR (S i) <= INR m) by (apply le_INR; lia).
    assert (Hi0 : 0 <= INR i) by apply pos_INR.
    rewrite S_INR in *.
    assert (Emg : 0 <= w * Mg + eta) by (pose proof (Rmult_le_pos w Mg); lra).
    assert (AG : Rabs (Gh + d) <= Mg).
    { replace (Gh + d) with ((g0 + (INR i + 1) * d) + (Gh - (g0 + INR i * d))) by ring.
      eapply Rle_trans; [apply Rabs_triang|].
      assert (INR i * (w * Mg + eta) <= INR m * (w * Mg + eta))
        by (apply Rmult_le_compat_r; lra).
      lra. }
    assert (RG : Rabs (G (S i) - (Gh + d)) <= w * Mg + eta).
    { eapply Rle_trans; [apply St|]. apply Rplus_le_compat_r, Rmult_le_compat_l; lra. }
    replace (G (S i) - (g0 + (INR i + 1) * d))
      with ((G (S i) - (Gh + d)) + (Gh - (g0 + INR i * d))) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.

(** Corrected Euler: P_{j+1} within w|P_j + Q_j| + eta of P_j + Q_j, and
    Q_{j+1} within w|Q_j + d| + eta of Q_j + d (FloatModel.v's [floop]). *)
Lemma cseq_err : forall (w eta : R) (P Q : nat -> R) (d : R) (m : nat) (Ms Mp : R),
  0 <= w -> 0 <= eta -> 0 <= Ms -> 0 <= Mp ->
  (forall j, (j < m)%nat -> ap1 w eta (P (S j)) (P j + Q j) /\ ap1 w eta (Q (S j)) (Q j + d)) ->
  (forall j, (S j < m)%nat ->
     Rabs (Q O + INR (S j) * d) + INR m * (w * Ms + eta) <= Ms) ->
  (forall j, (j < m)%nat ->
     Rabs (P O + INR (S j) * Q O + INR (S j) * (INR (S j) - 1) / 2 * d)
     + INR m * INR m / 2 * (w * Ms + eta) + INR m * (w * Mp + eta) <= Mp) ->
  forall i, (i <= m)%nat ->
  ((i < m)%nat -> Rabs (Q i - (Q O + INR i * d)) <= INR i * (w * Ms + eta))
  /\ Rabs (P i - (P O + INR i * Q O + INR i * (INR i - 1) / 2 * d))
     <= INR i * (INR i - 1) / 2 * (w * Ms + eta) + INR i * (w * Mp + eta).
Proof.
  intros w eta P Q d m Ms Mp Hw He HMs HMp Hstep HS HP i Hi.
  assert (Ems : 0 <= w * Ms + eta) by (pose proof (Rmult_le_pos w Ms); lra).
  assert (Emp : 0 <= w * Mp + eta) by (pose proof (Rmult_le_pos w Mp); lra).
  (* the slopes: the Gouraud loop on Q *)
  assert (HQ : forall k, (k < m)%nat -> Rabs (Q k - (Q O + INR k * d)) <= INR k * (w * Ms + eta)).
  { intros k Hk. apply (gseq_err w eta Q d (m - 1) Ms Hw He HMs); [| | lia].
    - intros j Hj. apply Hstep. lia.
    - intros j Hj. pose proof (HS j ltac:(lia)).
      assert (INR (m - 1) * (w * Ms + eta) <= INR m * (w * Ms + eta))
        by (apply Rmult_le_compat_r; [lra | apply le_INR; lia]).
      lra. }
  split; [exact (HQ i)|].
  set (p0 := P O) in *. set (s0 := Q O) in *.
  induction i as [| i IH].
  - cbn [INR]. unfold p0. rewrite Rabs_right; lra.
  - pose proof (IH ltac:(lia)) as IP. pose proof (HQ i ltac:(lia)) as IS.
    destruct (Hstep i ltac:(lia)) as [StP _]. unfold ap1 in StP.
    set (Sh := Q i) in *. set (Ph := P i) in *.
    specialize (HP i ltac:(lia)).
    assert (Him : INR (S i) <= INR m) by (apply le_INR; lia).
    assert (Hi0 : 0 <= INR i) by apply pos_INR.
    assert (Him' : INR i <= INR m) by (apply le_INR; lia).
    rewrite S_INR in *.
    assert (AP : Rabs (Ph + Sh) <= Mp).
    { replace (Ph + Sh) with ((p0 + (INR i + 1) * s0 + (INR i + 1) * (INR i + 1 - 1) / 2 * d)
         + (Ph - (p0 + INR i * s0 + INR i * (INR i - 1) / 2 * d))
         + (Sh - (s0 + INR i * d))) by field.
      eapply Rle_trans; [apply Rabs_triang|].
      eapply Rle_trans; [apply Rplus_le_compat_r, Rabs_triang|].
      assert (INR i * (INR i - 1) / 2 + INR i <= INR m * INR m / 2) by nra.
      assert ((INR i * (INR i - 1) / 2 + INR i) * (w * Ms + eta)
                <= INR m * INR m / 2 * (w * Ms + eta)) by (apply Rmult_le_compat_r; lra).
      assert (INR i * (w * Mp + eta) <= INR m * (w * Mp + eta))
        by (apply Rmult_le_compat_r; lra).
      lra. }
    assert (RP : Rabs (P (S i) - (Ph + Sh)) <= w * Mp + eta).
    { eapply Rle_trans; [apply StP|]. apply Rplus_le_compat_r, Rmult_le_compat_l; lra. }
    replace (P (S i) - (p0 + (INR i + 1) * s0 + (INR i + 1) * (INR i + 1 - 1) / 2 * d))
      with ((P (S i) - (Ph + Sh))
            + (Ph - (p0 + INR i * s0 + INR i * (INR i - 1) / 2 * d))
            + (Sh - (s0 + INR i * d))) by field.
    eapply Rle_trans; [apply Rabs_triang|].
    eapply Rle_trans; [apply Rplus_le_compat_r, Rabs_triang|].
    assert (E1 : (INR i + 1) * (INR i + 1 - 1) / 2 * (w * Ms + eta) + (INR i + 1) * (w * Mp + eta)
             = INR i * (INR i - 1) / 2 * (w * Ms + eta) + INR i * (w * Mp + eta)
               + INR i * (w * Ms + eta) + (w * Mp + eta)) by field.
    rewrite E1. lra.
Qed.


