(** * GraphAffine.v — a first-order error bound that sees dependencies.

    Graph.v's running bound adds, at every operation, the bounds of its
    operands' errors.  Where one rounding reaches a node along two paths with
    opposite signs, it is counted twice although it cancels: corrected Euler's
    set-up t0 = di_a - (p_n - p_b)/n, with p_n = p_a + n di_a + ..., carries the
    rounding of di_a once directly and once through p_n / n.

    Here every node's error is an affine form over the LOCAL errors of the
    nodes before it, delta k = y k - exact_op X y (g k) (the rounding of node k
    on its computed operands):

        y j - x j  =  sum_k fm M j k * delta k  +  rho j,   |rho j| <= R j,

    where fm M j j = 1 (the node's own rounding), fm M j k = M j k for k < j
    (a certificate's coefficients, any reals) and 0 for k > j.  A coefficient
    is carried as a number; the rules charge the difference between it and the
    coefficient the operation propagates, times the bound e k of delta k, to
    the remainder, so a certificate may round its coefficients or drop one
    altogether (a coefficient of 0: its whole term goes to the remainder).
    Propagated coefficients use the exact values only through the intervals
    [lo, hi] of a Graph.v certificate (centre and radius), so every rule is an
    inequality between the certificate's numbers.

    Given a Graph.v certificate (iv_ok, err_ok) for the intervals, the bounds
    E of the local errors' sizes and the roots S, T, the rules are:
    [loc_ok]: e j bounds |delta j| (one rounding on operands of size at most
    |x j| + E j, from FloatModelK's ap1 or the sum and reciprocal lemmas);
    [aff_ok]: the remainder's propagation — Add, Sub, Sum and Mul linearly (Mul
    with the second-order term F a * F b), Div and DivE linearly by a divisor
    known exactly, else (and Sqrt, Rsqrt) as one opaque step bounded by
    Graph.v's rule on the operands' affine bounds F.  [graph_sound_affine]: for
    EVERY execution, |y j - x j| <= sum_k |fm M j k| e k + R j.
    [graph_sound_affine_read] is the same bound from the inputs as read, as
    [graph_sound_read] is [graph_sound]'s. *)

From Coq Require Import Reals Lra Lia List Permutation.
From PhongApprox Require Import FloatModelK Graph.
Import ListNotations.
Open Scope R_scope.

(** ** Forms *)

(** The local error of node k: its computed value less its operation on the computed operands. *)
Definition delta (g : nat -> node) (X y : nat -> R) (k : nat) : R :=
  y k - exact_op X y (nop (g k)).

(** The full coefficient of delta k in node a's form. *)
Definition fm (M : nat -> nat -> R) (a k : nat) : R :=
  if Nat.eqb k a then 1 else if Nat.ltb k a then M a k else 0.

(** The coefficients of node j's form without its own rounding. *)
Definition pm (M : nat -> nat -> R) (j k : nat) : R :=
  if Nat.ltb k j then M j k else 0.

(** The affine bound of node a: sum_k |fm a k| e k + R a. *)
Definition ferr (N : nat) (M : nat -> nat -> R) (R0 e : nat -> R) (a : nat) : R :=
  sumR (fun k => Rabs (fm M a k) * e k) (seq 0 N) + R0 a.

Definition cen (lo hi : nat -> R) (a : nat) : R := (lo a + hi a) / 2.
Definition rad (lo hi : nat -> R) (a : nat) : R := (hi a - lo a) / 2.

(** ** The rules *)

(** e j bounds the local error of node j. *)
Definition loc_ok (g : nat -> node) (lo hi E e : nat -> R) (j : nat) : Prop :=
  let v := nv (g j) in
  let eta := neta (g j) in
  let m := mag (lo j) (hi j) in
  0 <= e j /\
  match nop (g j) with
  | Cst _ => True
  | DivE a b =>
      v * (2 + v) < 1 /\ v * (m + E j) + eta <= (1 - v) * e j /\
      v * (2 + v) * (m + E j) + (1 + v) * (mag (lo a) (hi a) + E a) * eta + eta
        <= (1 - v * (2 + v)) * e j
  | Sum l =>
      let k := length l in
      let m := (length (filter (live lo hi E) l) - 1)%nat in
      let w := (1 + v) ^ m in
      (w - 1) * sumR (fun i => mag (lo i) (hi i) + E i) l + INR m * w * eta
        + INR (k - 1) * w * nez (g j) <= e j
  | _ => v < 1 /\ v * (m + E j) + eta <= (1 - v) * e j
  end.

(** The remainder of node j's form. *)
Definition aff_ok (N : nat) (g : nat -> node) (lo hi E S T : nat -> R)
    (M : nat -> nat -> R) (R0 e : nat -> R) (j : nat) : Prop :=
  let dev c := sumR (fun k => Rabs (c k - pm M j k) * e k) (seq 0 N) in
  let opaque d := d + sumR (fun k => Rabs (pm M j k) * e k) (seq 0 N) <= R0 j in
  let F := ferr N M R0 e in
  match nop (g j) with
  | In _ | Cst _ => opaque 0
  | Add a b => R0 a + R0 b + dev (fun k => fm M a k + fm M b k) <= R0 j
  | Sub a b => R0 a + R0 b + dev (fun k => fm M a k - fm M b k) <= R0 j
  | Mul a b =>
      mag (lo b) (hi b) * R0 a + mag (lo a) (hi a) * R0 b + F a * F b
        + sumR (fun k => (Rabs (cen lo hi b * fm M a k + cen lo hi a * fm M b k - pm M j k)
                          + rad lo hi b * Rabs (fm M a k) + rad lo hi a * Rabs (fm M b k)) * e k)
               (seq 0 N) <= R0 j
  | Div a b | DivE a b =>
      (lo b = hi b /\ E b = 0 /\ R0 a / Rabs (lo b) + dev (fun k => fm M a k / lo b) <= R0 j)
      \/ (let lb := Rmin (Rabs (lo b)) (Rabs (hi b)) in
          F b < lb /\ opaque ((F a + mag (lo j) (hi j) * F b) / (lb - F b)))
      \/ (F b < Rmin (Rabs (lo b)) (Rabs (hi b)) /\
          forall u q, / hi b <= u <= / lo b -> lo j <= q <= hi j ->
            Rabs u * R0 a + Rabs (q * u) * R0 b
            + (F a + Rabs q * F b) * F b * (u * u) / (1 - Rabs u * F b)
            + dev (fun k => u * fm M a k - q * u * fm M b k) <= R0 j)
  | Sqrt a =>
      opaque (F a / (S j + T j))
      \/ (forall s, S j <= s <= hi j ->
            R0 a / (2 * s) + F a * F a / (2 * s * ((s + T j) * (s + T j)))
            + dev (fun k => fm M a k / (2 * s)) <= R0 j)
  | Rsqrt a => opaque (F a / (2 * (S j * S j * S j)))
  | Sum l => sumR R0 l + dev (fun k => sumR (fun t => fm M t k) l) <= R0 j
  end.

(** ** Sums over symbols *)

Lemma sumR_app : forall f l1 l2, sumR f (l1 ++ l2) = sumR f l1 + sumR f l2.
Proof. intros. unfold sumR. rewrite map_app. apply fold_app. Qed.

Lemma sumR_ext : forall f h l, (forall k, f k = h k) -> sumR f l = sumR h l.
Proof. intros f h l H. unfold sumR. induction l; simpl; [reflexivity | rewrite H, IHl; reflexivity]. Qed.

Lemma sumR_lin : forall (c1 c2 : R) (f1 f2 f3 d : nat -> R) l,
  sumR (fun k => (c1 * f1 k + c2 * f2 k - f3 k) * d k) l
  = c1 * sumR (fun k => f1 k * d k) l + c2 * sumR (fun k => f2 k * d k) l
    - sumR (fun k => f3 k * d k) l.
Proof. intros. unfold sumR. induction l; simpl; [ring | rewrite IHl; ring]. Qed.

Lemma sumR_bound : forall (f D : nat -> R) l, Forall (fun k => Rabs (f k) <= D k) l ->
  Rabs (sumR f l) <= sumR D l.
Proof.
  intros f D l H. unfold sumR. induction H as [|k l Hk _ IH]; simpl.
  - rewrite Rabs_R0. lra.
  - pose proof (Rabs_triang (f k) (fold_right Rplus 0 (map f l))). lra.
Qed.

Lemma sumR_plus : forall (f h : nat -> R) l,
  sumR (fun k => f k + h k) l = sumR f l + sumR h l.
Proof. intros. unfold sumR. induction l; simpl; [ring | rewrite IHl; ring]. Qed.

Lemma sumR_swap : forall (F : nat -> nat -> R) (d : nat -> R) lk lt,
  sumR (fun k => sumR (fun t => F t k) lt * d k) lk
  = sumR (fun t => sumR (fun k => F t k * d k) lk) lt.
Proof.
  intros F d lk lt. induction lt as [|t lt IH].
  - unfold sumR at 2. simpl. unfold sumR. simpl.
    induction lk; simpl; [reflexivity | rewrite IHlk; ring].
  - rewrite (sumR_ext _ (fun k => F t k * d k + sumR (fun t0 => F t0 k) lt * d k))
      by (intro k; unfold sumR; simpl; ring).
    rewrite sumR_plus, IH. unfold sumR at 3. simpl. reflexivity.
Qed.

(** A combination with coefficients c - p, bounded termwise. *)
Lemma dev_bound : forall (c p d e D : nat -> R) l,
  Forall (fun k => Rabs (d k) <= e k /\ Rabs (c k - p k) <= D k) l ->
  Rabs (sumR (fun k => (c k - p k) * d k) l) <= sumR (fun k => D k * e k) l.
Proof.
  intros c p d e D l H. apply sumR_bound. eapply Forall_impl; [|exact H].
  intros k [Hd Hc]. simpl. rewrite Rabs_mult. apply Rmult_le_compat; auto using Rabs_pos.
Qed.

(** The sum over seq 0 N of an indicator of j < N times d is d j. *)
Lemma sum_ind : forall (d : nat -> R) N j,
  sumR (fun k => (if Nat.eqb k j then 1 else 0) * d k) (seq 0 N)
  = if Nat.ltb j N then d j else 0.
Proof.
  intros d N j. induction N as [|N IH]; [reflexivity|].
  rewrite seq_S, sumR_app, IH. unfold sumR at 1. cbn [map fold_right]. rewrite Nat.add_0_l.
  destruct (lt_eq_lt_dec j N) as [[Hlt | Heq] | Hgt].
  - replace (Nat.ltb j N) with true by (symmetry; apply Nat.ltb_lt; lia).
    replace (Nat.ltb j (S N)) with true by (symmetry; apply Nat.ltb_lt; lia).
    replace (Nat.eqb N j) with false by (symmetry; apply Nat.eqb_neq; lia). ring.
  - subst. rewrite Nat.ltb_irrefl, Nat.eqb_refl.
    replace (Nat.ltb N (S N)) with true by (symmetry; apply Nat.ltb_lt; lia). ring.
  - replace (Nat.ltb j N) with false by (symmetry; apply Nat.ltb_ge; lia).
    replace (Nat.ltb j (S N)) with false by (symmetry; apply Nat.ltb_ge; lia).
    replace (Nat.eqb N j) with false by (symmetry; apply Nat.eqb_neq; lia). ring.
Qed.

Lemma fm_pm : forall M j k, fm M j k = pm M j k + (if Nat.eqb k j then 1 else 0).
Proof.
  intros. unfold fm, pm. destruct (Nat.eqb k j) eqn:E.
  - apply Nat.eqb_eq in E. subst. rewrite Nat.ltb_irrefl. ring.
  - destruct (Nat.ltb k j); ring.
Qed.

Lemma lin_fm : forall M (d : nat -> R) N j, (j < N)%nat ->
  sumR (fun k => fm M j k * d k) (seq 0 N) = sumR (fun k => pm M j k * d k) (seq 0 N) + d j.
Proof.
  intros M d N j Hj.
  rewrite (sumR_ext _ (fun k => pm M j k * d k + (if Nat.eqb k j then 1 else 0) * d k))
    by (intro k; rewrite fm_pm; ring).
  rewrite sumR_plus, sum_ind.
  replace (Nat.ltb j N) with true by (symmetry; apply Nat.ltb_lt; exact Hj). reflexivity.
Qed.

Lemma fm_zero : forall M a k, (a < k)%nat -> fm M a k = 0.
Proof.
  intros. unfold fm. destruct (Nat.eqb k a) eqn:E; [apply Nat.eqb_eq in E; lia|].
  destruct (Nat.ltb k a) eqn:E2; [apply Nat.ltb_lt in E2; lia | reflexivity].
Qed.

Lemma cen_rad : forall lo hi a x, lo a <= x <= hi a -> Rabs (x - cen lo hi a) <= rad lo hi a.
Proof. intros. unfold cen, rad, Rabs. destruct Rcase_abs; lra. Qed.

(** ** The local errors *)

Lemma loc_ap1 : forall v eta y z Y e, 0 <= v -> v < 1 -> ap1 v eta y z -> Rabs y <= Y ->
  v * Y + eta <= (1 - v) * e -> Rabs (y - z) <= e.
Proof.
  unfold ap1. intros v eta y z Y e Hv Hv1 Hy HY He.
  assert (Hz : Rabs z <= Y + Rabs (y - z)).
  { pose proof (Rabs_triang_inv z y). rewrite Rabs_minus_sym in H. lra. }
  assert (v * Rabs z <= v * (Y + Rabs (y - z))) by (apply Rmult_le_compat_l; lra).
  assert (H1 : (1 - v) * Rabs (y - z) <= (1 - v) * e) by lra.
  apply Rmult_le_reg_l in H1; lra.
Qed.

Lemma local_sound : forall (g : nat -> node) (X x y lo hi E S T e : nat -> R) j,
  (forall a, (a <= j)%nat -> lo a <= x a <= hi a /\ Rabs (y a - x a) <= E a) ->
  op_wf (nop (g j)) j -> 0 <= nv (g j) -> 0 <= neta (g j) ->
  exec_op X y (g j) (y j) -> iv_ok g X lo hi S j -> err_ok g lo hi E S T j ->
  loc_ok g lo hi E e j -> Rabs (delta g X y j) <= e j.
Proof.
  intros g X x y lo hi E S T e j IH Hwf Hv He Hy Hiv Herr [He0 Hloc]. unfold delta.
  destruct (IH j (Nat.le_refl j)) as [Ij Ej].
  assert (HY : Rabs (y j) <= mag (lo j) (hi j) + E j).
  { pose proof (mag_ge _ _ _ Ij). pose proof (Rabs_triang_inv (y j) (x j)). lra. }
  unfold exec_op, loc_ok, err_ok, iv_ok in *. destruct (g j) as [o v eta ez]. cbn [nop nv neta nez] in *.
  destruct o as [i | c | a b | a b | a b | a b | a b | a | a | l]; cbn [exact_op] in *;
    cbv zeta in Hloc;
    try exact (loc_ap1 v eta _ _ _ _ Hv (proj1 Hloc) Hy HY (proj2 Hloc)).
  - (* Cst *) rewrite Hy, Rminus_diag_eq, Rabs_R0 by reflexivity. exact He0.
  - (* DivE *)
    destruct Hloc as (Hv2 & Hl1 & Hl2). destruct Hwf as [Ha Hb].
    destruct Hy as [Hy | (r & Hr & Hy)].
    + apply (loc_ap1 v eta _ _ _ _ Hv ltac:(nra) Hy HY Hl1).
    + destruct (IH a ltac:(lia)) as [Ia Ea]. destruct (IH b ltac:(lia)) as [Ib Eb].
      destruct Herr as [_ (Hlb & _)].
      destruct Hiv as [_ [Hs _]].
      assert (Hyb : y b <> 0).
      { intro Hz. pose proof (div_lb _ _ _ Ib Hs).
        rewrite Hz, Rminus_0_l, Rabs_Ropp in Eb. lra. }
      assert (HP : Rabs (y a) <= mag (lo a) (hi a) + E a).
      { pose proof (mag_ge _ _ _ Ia). pose proof (Rabs_triang_inv (y a) (x a)). lra. }
      set (D := Rabs (y j - y a / y b)).
      assert (HQ : Rabs (y a / y b) <= mag (lo j) (hi j) + E j + D).
      { pose proof (Rabs_triang_inv (y a / y b) (y j)). rewrite Rabs_minus_sym in H.
        unfold D. lra. }
      pose proof (recip_err v eta (y a) (y b) r (y j) _ _ Hv He Hyb Hr Hy HQ HP) as Hd.
      fold D in Hd. set (w := v * (2 + v)) in *.
      assert (H1 : (1 - w) * D <= (1 - w) * e j).
      { assert (w * (mag (lo j) (hi j) + E j + D) = w * (mag (lo j) (hi j) + E j) + w * D) by ring.
        assert ((1 - w) * D = D - w * D) by ring. lra. }
      apply Rmult_le_reg_l in H1; lra.
  - (* Sum *)
    destruct Herr as [_ [Hez _]].
    destruct Hwf as [_ Hl].
    assert (HF : Forall (fun i => lo i <= x i <= hi i /\ Rabs (y i - x i) <= E i) l).
    { eapply Forall_impl; [|exact Hl]. intros i Hi. apply IH. simpl in Hi.
      apply Nat.lt_le_incl. exact Hi. }
    pose proof (sum_rounding v eta ez l x y lo hi E (y j) Hv He Hez HF Hy) as Hr.
    change (fold_right Rplus 0 (map y l)) with (sumR y l). lra.
Qed.

(** ** The remainders *)

Lemma forall_seq : forall (P : nat -> Prop) N, (forall k, (k < N)%nat -> P k) -> Forall P (seq 0 N).
Proof. intros P N H. apply Forall_forall. intros k Hk. apply in_seq in Hk. apply H. lia. Qed.

Lemma lin_dev : forall (c p d e : nat -> R) l, Forall (fun k => Rabs (d k) <= e k) l ->
  Rabs (sumR (fun k => (c k - p k) * d k) l) <= sumR (fun k => Rabs (c k - p k) * e k) l.
Proof.
  intros c p d e l H. apply dev_bound. eapply Forall_impl; [|exact H]. simpl. intros. split; lra.
Qed.

Lemma lin_abs : forall (f d e : nat -> R) l, Forall (fun k => Rabs (d k) <= e k) l ->
  Rabs (sumR (fun k => f k * d k) l) <= sumR (fun k => Rabs (f k) * e k) l.
Proof.
  intros f d e l H. apply sumR_bound. eapply Forall_impl; [|exact H]. simpl. intros k Hk.
  rewrite Rabs_mult. apply Rmult_le_compat_l; [apply Rabs_pos | exact Hk].
Qed.

Lemma sumR_zero : forall (d : nat -> R) l, sumR (fun k => 0 * d k) l = 0.
Proof. intros. unfold sumR. induction l; simpl; [reflexivity | rewrite IHl; ring]. Qed.

Lemma lin_diff : forall (f p d : nat -> R) l,
  sumR (fun k => (f k - p k) * d k) l = sumR (fun k => f k * d k) l - sumR (fun k => p k * d k) l.
Proof. intros. unfold sumR. induction l; simpl; [ring | rewrite IHl; ring]. Qed.

Lemma sumR_rho : forall (y x L : nat -> R) l,
  sumR y l - sumR x l - sumR L l = sumR (fun t => y t - x t - L t) l.
Proof. intros. unfold sumR. induction l; simpl; [ring | rewrite <- IHl; ring]. Qed.

(** The opaque step: |P| <= d gives the remainder d + sum |pm j k| e k. *)
Lemma opaque_step : forall (P d : R) (p dl e : nat -> R) l, Rabs P <= d ->
  Forall (fun k => Rabs (dl k) <= e k) l ->
  Rabs (P - sumR (fun k => p k * dl k) l) <= d + sumR (fun k => Rabs (p k) * e k) l.
Proof.
  intros P d p dl e l HP H. pose proof (lin_abs p dl e l H).
  pose proof (Rabs_triang P (- sumR (fun k => p k * dl k) l)). rewrite Rabs_Ropp in H1.
  unfold Rminus. lra.
Qed.

(** A division, linearly: u = 1/x_b and q = x_a/x_b range over the intervals the
    certificate gives them, the second-order term over |x_b| (|x_b| - F b). *)
Lemma div_lin : forall N (lo hi : nat -> R) M R0 e (d : nat -> R) j a b xa xb ya yb,
  Forall (fun k => Rabs (d k) <= e k) (seq 0 N) ->
  lo b <= xb <= hi b -> (0 < lo b \/ hi b < 0) -> lo j <= xa / xb <= hi j ->
  Rabs (ya - xa - sumR (fun k => fm M a k * d k) (seq 0 N)) <= R0 a ->
  Rabs (yb - xb - sumR (fun k => fm M b k * d k) (seq 0 N)) <= R0 b ->
  Rabs (ya - xa) <= ferr N M R0 e a -> Rabs (yb - xb) <= ferr N M R0 e b ->
  ferr N M R0 e b < Rmin (Rabs (lo b)) (Rabs (hi b)) ->
  (forall u q, / hi b <= u <= / lo b -> lo j <= q <= hi j ->
     Rabs u * R0 a + Rabs (q * u) * R0 b
     + (ferr N M R0 e a + Rabs q * ferr N M R0 e b) * ferr N M R0 e b * (u * u)
       / (1 - Rabs u * ferr N M R0 e b)
     + sumR (fun k => Rabs (u * fm M a k - q * u * fm M b k - pm M j k) * e k) (seq 0 N)
     <= R0 j) ->
  Rabs (ya / yb - xa / xb - sumR (fun k => pm M j k * d k) (seq 0 N)) <= R0 j.
Proof.
  intros N lo hi M R0 e d j a b xa xb ya yb Hds Ib Hs Ij Ra Rb Fa Fb Hlt Hc.
  set (Fa' := ferr N M R0 e a) in *. set (Fb' := ferr N M R0 e b) in *.
  pose proof (div_lb _ _ _ Ib Hs) as Hlb.
  set (X := Rabs xb) in *.
  assert (HX : 0 < X) by (pose proof (Rabs_pos (yb - xb)); lra).
  assert (Hxb : xb <> 0) by (intro Hz; unfold X in HX; rewrite Hz, Rabs_R0 in HX; lra).
  assert (HY : X - Fb' <= Rabs yb).
  { pose proof (Rabs_triang_inv xb yb). rewrite Rabs_minus_sym in Fb. unfold X. lra. }
  assert (Hyb : yb <> 0) by (intro Hz; rewrite Hz, Rabs_R0 in HY; lra).
  set (u := / xb). set (q := xa / xb).
  assert (Hu : / hi b <= u <= / lo b) by (apply inv_between; auto).
  specialize (Hc u q Hu Ij).
  set (La := sumR (fun k => fm M a k * d k) (seq 0 N)) in *.
  set (Lb := sumR (fun k => fm M b k * d k) (seq 0 N)) in *.
  set (Lj := sumR (fun k => pm M j k * d k) (seq 0 N)) in *.
  pose proof (lin_dev (fun k => u * fm M a k - q * u * fm M b k) (pm M j) d e _ Hds) as Hl.
  rewrite lin_diff, (sumR_ext _ (fun k => (u * fm M a k + (- (q * u)) * fm M b k - 0) * d k))
    in Hl by (intro; ring).
  rewrite sumR_lin, sumR_zero in Hl. fold La Lb in Hl.
  set (T2 := ((ya - xa) - q * (yb - xb)) * (yb - xb) / (xb * yb)).
  assert (Hid : ya / yb - q - Lj
                = u * (ya - xa - La) - q * u * (yb - xb - Lb)
                  + (u * La + - (q * u) * Lb - 0 - Lj) - T2).
  { unfold T2, u, q. field. split; assumption. }
  rewrite Hid.
  assert (HT : Rabs T2 <= (Fa' + Rabs q * Fb') * Fb' * (u * u) / (1 - Rabs u * Fb')).
  { assert (Huu : u * u = / X * / X).
    { unfold u, X. rewrite <- Rinv_mult, <- Rinv_mult. f_equal.
      rewrite <- Rabs_mult. symmetry. apply Rabs_pos_eq. nra. }
    assert (Hau : Rabs u = / X) by (unfold u, X; apply Rabs_inv).
    rewrite Huu, Hau.
    replace ((Fa' + Rabs q * Fb') * Fb' * (/ X * / X) / (1 - / X * Fb'))
      with ((Fa' + Rabs q * Fb') * Fb' / (X * (X - Fb'))) by (field; lra).
    unfold T2. unfold Rdiv. rewrite !Rabs_mult, Rabs_inv, Rabs_mult. fold X.
    assert (Hn : Rabs (ya - xa - q * (yb - xb)) <= Fa' + Rabs q * Fb').
    { pose proof (Rabs_triang (ya - xa) (- (q * (yb - xb)))). rewrite Rabs_Ropp, Rabs_mult in H.
      assert (Rabs q * Rabs (yb - xb) <= Rabs q * Fb') by (apply Rmult_le_compat_l; auto using Rabs_pos).
      unfold Rminus at 1. lra. }
    assert (Hd : / (X * Rabs yb) <= / (X * (X - Fb'))).
    { apply Rinv_le_contravar; [apply Rmult_lt_0_compat; lra | apply Rmult_le_compat_l; lra]. }
    apply Rmult_le_compat; [apply Rmult_le_pos; apply Rabs_pos | left; apply Rinv_0_lt_compat;
      apply Rmult_lt_0_compat; [lra | lra] | | exact Hd].
    apply Rmult_le_compat; auto using Rabs_pos. }
  assert (H1 : Rabs (u * (ya - xa - La)) <= Rabs u * R0 a)
    by (rewrite Rabs_mult; apply Rmult_le_compat_l; auto using Rabs_pos).
  assert (H2 : Rabs (q * u * (yb - xb - Lb)) <= Rabs (q * u) * R0 b)
    by (rewrite Rabs_mult; apply Rmult_le_compat_l; auto using Rabs_pos).
  pose proof (Rabs_triang (u * (ya - xa - La) - q * u * (yb - xb - Lb)
                           + (u * La + - (q * u) * Lb - 0 - Lj)) (- T2)).
  pose proof (Rabs_triang (u * (ya - xa - La) - q * u * (yb - xb - Lb))
                          (u * La + - (q * u) * Lb - 0 - Lj)).
  pose proof (Rabs_triang (u * (ya - xa - La)) (- (q * u * (yb - xb - Lb)))).
  rewrite Rabs_Ropp in H, H3.
  replace (u * (ya - xa - La) - q * u * (yb - xb - Lb) + (u * La + - (q * u) * Lb - 0 - Lj) + - T2)
    with (u * (ya - xa - La) - q * u * (yb - xb - Lb) + (u * La + - (q * u) * Lb - 0 - Lj) - T2)
    in H by ring.
  replace (u * (ya - xa - La) + - (q * u * (yb - xb - Lb)))
    with (u * (ya - xa - La) - q * u * (yb - xb - Lb)) in H3 by ring.
  fold Lj in Hl. lra.
Qed.

(** A square root, linearly: s = sqrt x_a ranges over [S j, hi j]. *)
Lemma sqrt_lin : forall N (hij : R) M R0 e (d : nat -> R) j a S T xa ya Fa,
  Forall (fun k => Rabs (d k) <= e k) (seq 0 N) ->
  0 < S -> S * S <= xa -> 0 <= T -> T * T <= ya -> 0 <= hij -> xa <= hij * hij ->
  Rabs (ya - xa - sumR (fun k => fm M a k * d k) (seq 0 N)) <= R0 a ->
  Rabs (ya - xa) <= Fa ->
  (forall s, S <= s <= hij ->
     R0 a / (2 * s) + Fa * Fa / (2 * s * ((s + T) * (s + T)))
     + sumR (fun k => Rabs (fm M a k / (2 * s) - pm M j k) * e k) (seq 0 N) <= R0 j) ->
  Rabs (sqrt ya - sqrt xa - sumR (fun k => pm M j k * d k) (seq 0 N)) <= R0 j.
Proof.
  intros N hij M R0 e d j a S T xa ya Fa Hds HS HSx HT HTy Hh Hxh Ra Fa'' Hc.
  set (s := sqrt xa). set (t := sqrt ya).
  assert (Hs : S <= s) by (apply sqrt_ge; auto).
  assert (Hsh : s <= hij).
  { unfold s. rewrite <- (sqrt_square hij) by exact Hh. apply sqrt_le_1_alt. exact Hxh. }
  assert (Ht : T <= t).
  { destruct (Req_dec T 0) as [Hz | Hz]; [rewrite Hz; apply sqrt_pos|].
    apply sqrt_ge; [lra | exact HTy]. }
  specialize (Hc s (conj Hs Hsh)).
  assert (Hxa : 0 <= xa) by nra. assert (Hya : 0 <= ya) by nra.
  assert (Hss : s * s = xa) by (apply sqrt_sqrt; exact Hxa).
  assert (Htt : t * t = ya) by (apply sqrt_sqrt; exact Hya).
  set (La := sumR (fun k => fm M a k * d k) (seq 0 N)) in *.
  set (Lj := sumR (fun k => pm M j k * d k) (seq 0 N)) in *.
  pose proof (lin_dev (fun k => fm M a k / (2 * s)) (pm M j) d e _ Hds) as Hl.
  rewrite lin_diff, (sumR_ext _ (fun k => (/ (2 * s) * fm M a k + 0 * fm M a k - 0) * d k))
    in Hl by (intro; unfold Rdiv; ring).
  rewrite sumR_lin, sumR_zero in Hl. fold La Lj in Hl.
  set (A := ya - xa) in *.
  set (T2 := A * A / (2 * s * ((s + t) * (s + t)))).
  assert (Hid : t - s - Lj = / (2 * s) * (A - La) + (/ (2 * s) * La + 0 * La - 0 - Lj) - T2).
  { unfold T2, A. rewrite <- Hss, <- Htt. field. lra. }
  rewrite Hid.
  assert (HT2 : Rabs T2 <= Fa * Fa / (2 * s * ((s + T) * (s + T)))).
  { assert (Hp1 : 0 < 2 * s * ((s + t) * (s + t))).
    { apply Rmult_lt_0_compat; [lra|]. apply Rmult_lt_0_compat; lra. }
    assert (Hp2 : 0 < 2 * s * ((s + T) * (s + T))).
    { apply Rmult_lt_0_compat; [lra|]. apply Rmult_lt_0_compat; lra. }
    assert (Hp3 : (s + T) * (s + T) <= (s + t) * (s + t))
      by (apply Rmult_le_compat; lra).
    unfold T2. unfold Rdiv. rewrite Rabs_mult, Rabs_inv.
    rewrite (Rabs_pos_eq (2 * s * ((s + t) * (s + t)))) by lra.
    assert (HA : Rabs (A * A) <= Fa * Fa)
      by (rewrite Rabs_mult; pose proof (Rabs_pos A); apply Rmult_le_compat; lra).
    apply Rmult_le_compat; [apply Rabs_pos | left; apply Rinv_0_lt_compat; lra | exact HA |].
    apply Rinv_le_contravar; [lra|].
    apply Rmult_le_compat_l; lra. }
  assert (H1 : Rabs (/ (2 * s) * (A - La)) <= R0 a / (2 * s)).
  { rewrite Rabs_mult, Rabs_inv, (Rabs_pos_eq (2 * s)) by lra. unfold Rdiv.
    rewrite Rmult_comm. apply Rmult_le_compat_r; [left; apply Rinv_0_lt_compat; lra | exact Ra]. }
  pose proof (Rabs_triang (/ (2 * s) * (A - La) + (/ (2 * s) * La + 0 * La - 0 - Lj)) (- T2)).
  pose proof (Rabs_triang (/ (2 * s) * (A - La)) (/ (2 * s) * La + 0 * La - 0 - Lj)).
  rewrite Rabs_Ropp in H.
  replace (/ (2 * s) * (A - La) + (/ (2 * s) * La + 0 * La - 0 - Lj) + - T2)
    with (/ (2 * s) * (A - La) + (/ (2 * s) * La + 0 * La - 0 - Lj) - T2) in H by ring.
  lra.
Qed.

(** A division (either way: the remainder concerns y a / y b). *)
Lemma div_affine : forall N (lo hi E : nat -> R) M R0 e (d : nat -> R) j a b xa xb ya yb,
  Forall (fun k => Rabs (d k) <= e k) (seq 0 N) ->
  lo a <= xa <= hi a -> lo b <= xb <= hi b -> Rabs (yb - xb) <= E b ->
  (0 < lo b \/ hi b < 0) -> lo j <= xa / xb <= hi j ->
  Rabs (ya - xa - sumR (fun k => fm M a k * d k) (seq 0 N)) <= R0 a ->
  Rabs (ya - xa) <= ferr N M R0 e a -> Rabs (yb - xb) <= ferr N M R0 e b ->
  (lo b = hi b /\ E b = 0 /\
     R0 a / Rabs (lo b) + sumR (fun k => Rabs (fm M a k / lo b - pm M j k) * e k) (seq 0 N)
       <= R0 j)
  \/ (ferr N M R0 e b < Rmin (Rabs (lo b)) (Rabs (hi b)) /\
      (ferr N M R0 e a + mag (lo j) (hi j) * ferr N M R0 e b)
        / (Rmin (Rabs (lo b)) (Rabs (hi b)) - ferr N M R0 e b)
      + sumR (fun k => Rabs (pm M j k) * e k) (seq 0 N) <= R0 j) ->
  Rabs (ya / yb - xa / xb - sumR (fun k => pm M j k * d k) (seq 0 N)) <= R0 j.
Proof.
  intros N lo hi E M R0 e d j a b xa xb ya yb Hds Ia Ib Eb Hs Ij Ra Fa Fb
    [(Hlh & HE & Hc) | (Hlt & Hc)].
  - assert (Hyb : yb = xb).
    { rewrite HE in Eb. pose proof (Rabs_pos (yb - xb)).
      destruct (Req_dec (yb - xb) 0); [lra|]. pose proof (Rabs_pos_lt _ H0). lra. }
    assert (Hxb : xb = lo b) by lra. subst yb. rewrite Hxb in *.
    assert (Hn : lo b <> 0) by (destruct Hs; lra).
    pose proof (lin_dev (fun k => fm M a k / lo b) (pm M j) d e _ Hds) as Hl.
    rewrite (sumR_ext _ (fun k => (/ lo b * fm M a k + 0 * fm M a k - pm M j k) * d k))
      in Hl by (intro; unfold Rdiv; ring).
    rewrite sumR_lin in Hl.
    set (La := sumR (fun k => fm M a k * d k) (seq 0 N)) in *.
    set (Lj := sumR (fun k => pm M j k * d k) (seq 0 N)) in *.
    replace (ya / lo b - xa / lo b - Lj)
      with ((ya - xa - La) * / lo b + (/ lo b * La + 0 * La - Lj)) by (field; exact Hn).
    pose proof (Rabs_triang ((ya - xa - La) * / lo b) (/ lo b * La + 0 * La - Lj)).
    rewrite Rabs_mult, Rabs_inv in H.
    assert (Rabs (ya - xa - La) * / Rabs (lo b) <= R0 a / Rabs (lo b)).
    { unfold Rdiv. apply Rmult_le_compat_r; [|exact Ra].
      left. apply Rinv_0_lt_compat, Rabs_pos_lt, Hn. }
    lra.
  - assert (Hd : Rabs (ya / yb - xa / xb)
                 <= (ferr N M R0 e a + mag (lo j) (hi j) * ferr N M R0 e b)
                    / (Rmin (Rabs (lo b)) (Rabs (hi b)) - ferr N M R0 e b)).
    { apply div_err; [exact (div_lb _ _ _ Ib Hs) | lra | exact Fa | exact Fb |].
      exact (mag_ge _ _ _ Ij). }
    pose proof (opaque_step _ _ (pm M j) d e _ Hd Hds). lra.
Qed.

Lemma node_affine : forall N g X x y lo hi E S T (M : nat -> nat -> R) R0 e j,
  (j < N)%nat ->
  (forall k, (k < N)%nat -> Rabs (delta g X y k) <= e k) ->
  (forall a, (a < N)%nat -> lo a <= x a <= hi a /\ Rabs (y a - x a) <= E a) ->
  (forall a, (a < j)%nat ->
     Rabs (y a - x a - sumR (fun k => fm M a k * delta g X y k) (seq 0 N)) <= R0 a) ->
  op_wf (nop (g j)) j -> x j = exact_op X x (nop (g j)) ->
  iv_ok g X lo hi S j -> err_ok g lo hi E S T j -> aff_ok N g lo hi E S T M R0 e j ->
  Rabs (exact_op X y (nop (g j)) - x j - sumR (fun k => pm M j k * delta g X y k) (seq 0 N))
    <= R0 j.
Proof.
  intros N g X x y lo hi E S T M R0 e j Hj Hd Hold IH Hwf Hx Hiv Herr Haff.
  set (d := delta g X y) in *.
  assert (Hds : Forall (fun k => Rabs (d k) <= e k) (seq 0 N)) by (apply forall_seq; exact Hd).
  set (lin := fun f => sumR (fun k => f k * d k) (seq 0 N)).
  assert (HF : forall a, (a < j)%nat -> Rabs (y a - x a) <= ferr N M R0 e a).
  { intros a Ha. specialize (IH a Ha). pose proof (lin_abs (fm M a) d e _ Hds).
    pose proof (Rabs_triang (y a - x a - sumR (fun k => fm M a k * d k) (seq 0 N))
                  (sumR (fun k => fm M a k * d k) (seq 0 N))).
    replace (y a - x a - sumR (fun k => fm M a k * d k) (seq 0 N)
             + sumR (fun k => fm M a k * d k) (seq 0 N)) with (y a - x a) in H0 by ring.
    unfold ferr. lra. }
  unfold iv_ok, err_ok, aff_ok in *. rewrite Hx.
  destruct (nop (g j)) as [i | c | a b | a b | a b | a b | a b | a | a | l] eqn:Hg;
    cbn [exact_op op_wf] in *; cbv zeta in Haff.
  (* Div and DivE: the same remainder rules, on y a / y b. *)
  6-7: destruct Hwf as [Ha Hb]; destruct (Hold a ltac:(lia)) as [Ia _];
    destruct (Hold b ltac:(lia)) as [Ib Eb]; destruct Hiv as (_ & Hs & Hiv);
    assert (Hq : lo j <= x a / x b <= hi j)
      by (apply (div_between (lo a) (hi a) (lo b) (hi b)); auto);
    destruct Haff as [H | [H | (Hlt & H)]];
    [idtac | idtac | apply (div_lin N lo hi M R0 e d j a b); auto];
    apply (div_affine N lo hi E M R0 e d j a b); auto.
  - (* In *) replace (X i - X i) with 0 by ring.
    pose proof (opaque_step 0 0 (pm M j) d e _ ltac:(rewrite Rabs_R0; lra) Hds). lra.
  - (* Cst *) replace (c - c) with 0 by ring.
    pose proof (opaque_step 0 0 (pm M j) d e _ ltac:(rewrite Rabs_R0; lra) Hds). lra.
  - (* Add *)
    destruct Hwf as [Ha Hb]. pose proof (IH a Ha) as Ra. pose proof (IH b Hb) as Rb.
    pose proof (lin_dev (fun k => fm M a k + fm M b k) (pm M j) d e _ Hds) as Hl.
    rewrite lin_diff, (sumR_ext _ (fun k => fm M a k * d k + fm M b k * d k))
      in Hl by (intro; ring).
    rewrite sumR_plus in Hl.
    set (La := sumR (fun k => fm M a k * d k) (seq 0 N)) in *.
    set (Lb := sumR (fun k => fm M b k * d k) (seq 0 N)) in *.
    set (Lj := sumR (fun k => pm M j k * d k) (seq 0 N)) in *.
    replace (y a + y b - (x a + x b) - Lj)
      with ((y a - x a - La) + (y b - x b - Lb) + (La + Lb - Lj)) by ring.
    pose proof (Rabs_triang (y a - x a - La + (y b - x b - Lb)) (La + Lb - Lj)).
    pose proof (Rabs_triang (y a - x a - La) (y b - x b - Lb)). lra.
  - (* Sub *)
    destruct Hwf as [Ha Hb]. pose proof (IH a Ha) as Ra. pose proof (IH b Hb) as Rb.
    pose proof (lin_dev (fun k => fm M a k - fm M b k) (pm M j) d e _ Hds) as Hl.
    rewrite lin_diff, (sumR_ext _ (fun k => (1 * fm M a k + (-1) * fm M b k - 0) * d k))
      in Hl by (intro; ring).
    rewrite sumR_lin in Hl.
    rewrite sumR_zero in Hl.
    set (La := sumR (fun k => fm M a k * d k) (seq 0 N)) in *.
    set (Lb := sumR (fun k => fm M b k * d k) (seq 0 N)) in *.
    set (Lj := sumR (fun k => pm M j k * d k) (seq 0 N)) in *.
    replace (y a - y b - (x a - x b) - Lj)
      with ((y a - x a - La) - (y b - x b - Lb) + (1 * La + -1 * Lb - 0 - Lj)) by ring.
    pose proof (Rabs_triang (y a - x a - La - (y b - x b - Lb)) (1 * La + -1 * Lb - 0 - Lj)).
    pose proof (Rabs_triang (y a - x a - La) (- (y b - x b - Lb))). rewrite Rabs_Ropp in H0.
    replace (y a - x a - La + - (y b - x b - Lb)) with (y a - x a - La - (y b - x b - Lb))
      in H0 by ring. lra.
  - (* Mul *)
    destruct Hwf as [Ha Hb]. pose proof (IH a Ha) as Ra. pose proof (IH b Hb) as Rb.
    destruct (Hold a ltac:(lia)) as [Ia _]. destruct (Hold b ltac:(lia)) as [Ib _].
    pose proof (HF a Ha) as Fa. pose proof (HF b Hb) as Fb.
    set (c := fun k => x b * fm M a k + x a * fm M b k).
    assert (Hc : Rabs (sumR (fun k => (c k - pm M j k) * d k) (seq 0 N))
       <= sumR (fun k => (Rabs (cen lo hi b * fm M a k + cen lo hi a * fm M b k - pm M j k)
                          + rad lo hi b * Rabs (fm M a k) + rad lo hi a * Rabs (fm M b k)) * e k)
               (seq 0 N)).
    { apply dev_bound. eapply Forall_impl; [|exact Hds]. intros k Hk. split; [exact Hk|].
      unfold c.
      replace (x b * fm M a k + x a * fm M b k - pm M j k)
        with ((cen lo hi b * fm M a k + cen lo hi a * fm M b k - pm M j k)
              + (x b - cen lo hi b) * fm M a k + (x a - cen lo hi a) * fm M b k) by ring.
      pose proof (cen_rad lo hi b (x b) Ib). pose proof (cen_rad lo hi a (x a) Ia).
      pose proof (Rabs_triang ((cen lo hi b * fm M a k + cen lo hi a * fm M b k - pm M j k)
                               + (x b - cen lo hi b) * fm M a k) ((x a - cen lo hi a) * fm M b k)).
      pose proof (Rabs_triang (cen lo hi b * fm M a k + cen lo hi a * fm M b k - pm M j k)
                              ((x b - cen lo hi b) * fm M a k)).
      rewrite !Rabs_mult in *.
      assert (Rabs (x b - cen lo hi b) * Rabs (fm M a k) <= rad lo hi b * Rabs (fm M a k))
        by (apply Rmult_le_compat_r; [apply Rabs_pos | lra]).
      assert (Rabs (x a - cen lo hi a) * Rabs (fm M b k) <= rad lo hi a * Rabs (fm M b k))
        by (apply Rmult_le_compat_r; [apply Rabs_pos | lra]).
      lra. }
    unfold c in Hc. rewrite sumR_lin in Hc.
    set (La := sumR (fun k => fm M a k * d k) (seq 0 N)) in *.
    set (Lb := sumR (fun k => fm M b k * d k) (seq 0 N)) in *.
    set (Lj := sumR (fun k => pm M j k * d k) (seq 0 N)) in *.
    replace (y a * y b - x a * x b - Lj)
      with (x b * (y a - x a - La) + x a * (y b - x b - Lb) + (y a - x a) * (y b - x b)
            + (x b * La + x a * Lb - Lj)) by ring.
    pose proof (mag_ge _ _ _ Ia). pose proof (mag_ge _ _ _ Ib).
    assert (Rabs (x b * (y a - x a - La)) <= mag (lo b) (hi b) * R0 a)
      by (rewrite Rabs_mult; apply Rmult_le_compat; auto using Rabs_pos).
    assert (Rabs (x a * (y b - x b - Lb)) <= mag (lo a) (hi a) * R0 b)
      by (rewrite Rabs_mult; apply Rmult_le_compat; auto using Rabs_pos).
    assert (Rabs ((y a - x a) * (y b - x b)) <= ferr N M R0 e a * ferr N M R0 e b)
      by (rewrite Rabs_mult; apply Rmult_le_compat; auto using Rabs_pos).
    pose proof (Rabs_triang (x b * (y a - x a - La) + x a * (y b - x b - Lb)
                             + (y a - x a) * (y b - x b)) (x b * La + x a * Lb - Lj)).
    pose proof (Rabs_triang (x b * (y a - x a - La) + x a * (y b - x b - Lb))
                            ((y a - x a) * (y b - x b))).
    pose proof (Rabs_triang (x b * (y a - x a - La)) (x a * (y b - x b - Lb))). lra.
  - (* Sqrt *)
    pose proof (IH a Hwf) as Ra. destruct (Hold a ltac:(lia)) as [Ia Ea].
    pose proof (HF a Hwf) as Fa.
    destruct Hiv as (_ & HS & HSl & HL & HH & Hh). destruct Herr as (HE0 & HES & HT & HTl & _).
    assert (Hya : T j * T j <= y a).
    { pose proof (Rle_abs (- (y a - x a))) as Hh0. rewrite Rabs_Ropp in Hh0. lra. }
    destruct Haff as [Haff | Haff].
    + pose proof (sqrt_err (x a) (y a) _ (S j) (T j) HS ltac:(lra) HT Hya Fa) as Hs.
      pose proof (opaque_step _ _ (pm M j) d e _ Hs Hds). lra.
    + apply (sqrt_lin N (hi j) M R0 e d j a (S j) (T j) (x a) (y a) (ferr N M R0 e a));
        auto; lra.
  - (* Rsqrt *)
    pose proof (IH a Hwf) as Ra. destruct (Hold a ltac:(lia)) as [Ia Ea].
    pose proof (HF a Hwf) as Fa.
    destruct Hiv as (_ & HS & HSl & HL & HLh & HH). destruct Herr as (HE0 & HES & _).
    assert (Hya : S j * S j <= y a).
    { pose proof (Rle_abs (- (y a - x a))) as Hh0. rewrite Rabs_Ropp in Hh0. lra. }
    pose proof (rsqrt_err (x a) (y a) _ (S j) HS ltac:(lra) Hya Fa) as Hs.
    pose proof (opaque_step _ _ (pm M j) d e _ Hs Hds). lra.
  - (* Sum *)
    destruct Hwf as [_ Hl].
    change (fold_right Rplus 0 (map y l)) with (sumR y l).
    change (fold_right Rplus 0 (map x l)) with (sumR x l).
    pose proof (lin_dev (fun k => sumR (fun t => fm M t k) l) (pm M j) d e _ Hds) as Hv.
    rewrite lin_diff, sumR_swap in Hv.
    set (Lj := sumR (fun k => pm M j k * d k) (seq 0 N)) in *.
    set (Lt := sumR (fun t => sumR (fun k => fm M t k * d k) (seq 0 N)) l) in *.
    replace (sumR y l - sumR x l - Lj) with ((sumR y l - sumR x l - Lt) + (Lt - Lj)) by ring.
    unfold Lt. rewrite sumR_rho.
    assert (Hr : Rabs (sumR (fun t => y t - x t - sumR (fun k => fm M t k * d k) (seq 0 N)) l)
                 <= sumR R0 l).
    { apply sumR_bound. eapply Forall_impl; [|exact Hl]. intros t Ht. exact (IH t Ht). }
    pose proof (Rabs_triang (sumR (fun t => y t - x t - sumR (fun k => fm M t k * d k) (seq 0 N)) l)
                            (Lt - Lj)). fold Lt in H, Hr |- *. lra.
Qed.

(** ** Soundness *)

Theorem graph_sound_affine :
  forall (g : nat -> node) (N : nat) (X : nat -> R) (x y lo hi E S T e R0 : nat -> R)
         (M : nat -> nat -> R),
  (forall j, (j < N)%nat -> op_wf (nop (g j)) j /\ 0 <= nv (g j) /\ 0 <= neta (g j)) ->
  (forall j, (j < N)%nat -> x j = exact_op X x (nop (g j))) ->
  (forall j, (j < N)%nat -> exec_op X y (g j) (y j)) ->
  (forall j, (j < N)%nat -> iv_ok g X lo hi S j /\ err_ok g lo hi E S T j) ->
  (forall j, (j < N)%nat -> loc_ok g lo hi E e j /\ aff_ok N g lo hi E S T M R0 e j) ->
  forall j, (j < N)%nat -> Rabs (y j - x j) <= ferr N M R0 e j.
Proof.
  intros g N X x y lo hi E S T e R0 M Hwf Hx Hy Hc Ha.
  pose proof (graph_sound g N X x y lo hi E S T Hwf Hx Hy Hc) as Hold.
  assert (Hd : forall k, (k < N)%nat -> Rabs (delta g X y k) <= e k).
  { intros k Hk. destruct (Hwf k Hk) as (Hw & Hv & He). destruct (Hc k Hk) as [Hi Her].
    apply (local_sound g X x y lo hi E S T e k); auto; [intros a Ha'; apply Hold; lia|].
    exact (proj1 (Ha k Hk)). }
  set (d := delta g X y) in *.
  assert (Hds : Forall (fun k => Rabs (d k) <= e k) (seq 0 N)) by (apply forall_seq; exact Hd).
  assert (Hall : forall n j, (j < n)%nat -> (j < N)%nat ->
                 Rabs (y j - x j - sumR (fun k => fm M j k * d k) (seq 0 N)) <= R0 j).
  { induction n as [|n IHn]; intros j Hjn HjN; [lia|].
    destruct (Hwf j HjN) as (Hw & _). destruct (Hc j HjN) as [Hi Her].
    pose proof (node_affine N g X x y lo hi E S T M R0 e j HjN Hd Hold
                  ltac:(intros a Ha'; apply IHn; lia) Hw (Hx j HjN) Hi Her
                  (proj2 (Ha j HjN))) as Hn.
    rewrite lin_fm by exact HjN. fold d in Hn.
    replace (y j - x j - (sumR (fun k => pm M j k * d k) (seq 0 N) + d j))
      with (exact_op X y (nop (g j)) - x j - sumR (fun k => pm M j k * d k) (seq 0 N))
      by (unfold d, delta; ring).
    exact Hn. }
  intros j Hj. pose proof (Hall (Nat.succ j) j (Nat.lt_succ_diag_r j) Hj) as Hr.
  pose proof (lin_abs (fm M j) d e _ Hds).
  pose proof (Rabs_triang (y j - x j - sumR (fun k => fm M j k * d k) (seq 0 N))
                          (sumR (fun k => fm M j k * d k) (seq 0 N))).
  replace (y j - x j - sumR (fun k => fm M j k * d k) (seq 0 N)
           + sumR (fun k => fm M j k * d k) (seq 0 N)) with (y j - x j) in H0 by ring.
  unfold ferr. lra.
Qed.

(** From the inputs as read: the affine bound of an execution on the inputs Xr, plus
    the distance between the two certificates' intervals (as [graph_sound_read]). *)
Theorem graph_sound_affine_read :
  forall (g gr : nat -> node) (N : nat) (X Xr : nat -> R)
         (x xr y lo hi E S T lor hir Er Sr Tr e R0 : nat -> R) (M : nat -> nat -> R),
  (forall j, (j < N)%nat -> nop (gr j) = nop (g j)) ->
  (forall j, (j < N)%nat -> op_wf (nop (g j)) j /\ 0 <= nv (g j) /\ 0 <= neta (g j)) ->
  (forall j, (j < N)%nat -> 0 <= nv (gr j) /\ 0 <= neta (gr j)) ->
  (forall j, (j < N)%nat -> x j = exact_op X x (nop (g j))) ->
  (forall j, (j < N)%nat -> xr j = exact_op Xr xr (nop (g j))) ->
  (forall j, (j < N)%nat -> exec_op Xr y (gr j) (y j)) ->
  (forall j, (j < N)%nat -> iv_ok g X lo hi S j /\ err_ok g lo hi E S T j) ->
  (forall j, (j < N)%nat -> iv_ok gr Xr lor hir Sr j /\ err_ok gr lor hir Er Sr Tr j) ->
  (forall j, (j < N)%nat -> loc_ok gr lor hir Er e j /\ aff_ok N gr lor hir Er Sr Tr M R0 e j) ->
  forall j, (j < N)%nat ->
    Rabs (y j - x j) <= ferr N M R0 e j + Rmax (hir j - lo j) (hi j - lor j).
Proof.
  intros g gr N X Xr x xr y lo hi E S T lor hir Er Sr Tr e R0 M
    Hop Hwf Hwr Hx Hxr Hy Hc Hcr Ha j Hj.
  assert (Hwf' : forall k, (k < N)%nat -> op_wf (nop (gr k)) k /\ 0 <= nv (gr k) /\ 0 <= neta (gr k)).
  { intros k Hk. rewrite Hop by exact Hk. destruct (Hwf k Hk) as (Hw & _). destruct (Hwr k Hk). auto. }
  assert (Hxr' : forall k, (k < N)%nat -> xr k = exact_op Xr xr (nop (gr k))).
  { intros k Hk. rewrite Hop by exact Hk. auto. }
  assert (Hx0 : lo j <= x j <= hi j).
  { apply (graph_sound g N X x x lo hi E S T Hwf Hx); auto.
    intros k Hk. destruct (Hwf k Hk) as (Hw & Hv & He). apply exact_exec; auto. }
  assert (Hxr0 : lor j <= xr j <= hir j)
    by (apply (graph_sound gr N Xr xr y lor hir Er Sr Tr); auto).
  pose proof (graph_sound_affine gr N Xr xr y lor hir Er Sr Tr e R0 M Hwf' Hxr' Hy Hcr Ha j Hj)
    as Hyr.
  exact (read_triangle _ _ _ _ _ _ _ _ Hx0 Hxr0 Hyr).
Qed.
