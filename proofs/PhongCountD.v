(** * PhongCountD.v — the bounds of PhongCount.v parametrized by the span's distance.

    With dd >= |Nb - Na| (Euclidean norm of the exact difference, through
    dot (Nb - Na) (Nb - Na) <= dd^2, 0 <= dd <= 2), the errors of every
    rounding after the inputs act on the difference Nb - Na as one quantity and
    scale with dd (Cauchy-Schwarz: sum |D_j| |X_j| <= dd |X|), while the inputs'
    own roundings (1 - t) Na_j e_a + t Nb_j e_b are bounded by the mixtures
    M_j = (1 - t) |Na_j| + t |Nb_j| (sum M_j |X_j| <= 1 for |X| <= 1).
    Same hypotheses and models as PhongCount.v (kd = k_div, or for the
    reciprocal forms kd = (1 + 2^-20) k_mul + k_div + 2^-36), plus
    0 <= dd <= 2 and dot (Nb - Na) (Nb - Na) <= dd^2:
      Horner:  |p^ - p_i| <= ((8.04 + 6.01 dd) K1 + (0.03 + 1.01 dd) kd) u,
               |q^ - q_i| <= ((10.13 + 18.03 dd + 8.01 dd^2) K1
                              + (0.07 + 2.02 dd + 2.01 dd^2) kd) u;
      per-pixel: |p^ - p_i| <= ((6.02 + 2.01 dd) K1 + (0.02 + 1.01 dd) kd) u,
               |q^ - q_i| <= ((7.02 + 4.01 dd) K1 + (0.02 + 2.01 dd) kd) u;
      lerp:    |p^ - p_i| <= (8.02 K1 + (0.02 + 1.01 dd) kd) u,
               |q^ - q_i| <= (11.02 K1 + (0.02 + 2.01 dd) kd) u.
    The checker takes the minimum of these bounds and the d-free ones.
    The relations ([horner_ok], [pixel_ok], [lerp_ok], [krecip_ok], ...) and
    the steps shared with PhongCount.v, DuffCount.v and PhongNormalize.v come
    first; PhongCount.v's per-pixel and lerp bounds are these at dd = 2, and
    its Horner core is [horner_core] here. *)

From Coq Require Import Reals Lra Lia.
From PhongApprox Require Import Span FloatModel Float FloatModelK Profiles.
Open Scope R_scope.

(** ** Real-arithmetic steps *)

Lemma hc_scale : forall t X, 0 <= t <= 1 -> Rabs (t * X) <= Rabs X.
Proof.
  intros t X Ht. rewrite Rabs_mult, Rabs_pos_eq by lra.
  pose proof (Rabs_pos X). nra.
Qed.

Lemma dot_sq0 : forall a, 0 <= dot a a.
Proof. intros a. unfold dot. repeat apply Rplus_le_le_0_compat; apply Rle_0_sqr. Qed.

Lemma abs3 : forall X, 0 <= Rabs (vx X) /\ 0 <= Rabs (vy X) /\ 0 <= Rabs (vz X).
Proof. intros X. repeat split; apply Rabs_pos. Qed.

(** One rounding y of x scaled by lam >= 0: |lam (y - x)| <= v B + lam eta for |lam x| <= B. *)
Lemma ap_lam : forall v eta lam y x B, 0 <= v -> 0 <= lam -> ap1 v eta y x ->
  Rabs (lam * x) <= B -> Rabs (lam * (y - x)) <= v * B + lam * eta.
Proof.
  intros v eta lam y x B Hv Hl H HB. unfold ap1 in H.
  rewrite Rabs_mult, Rabs_pos_eq in * by lra.
  assert (lam * Rabs (y - x) <= lam * (v * Rabs x + eta)) by (apply Rmult_le_compat_l; lra).
  assert (v * (lam * Rabs x) <= v * B) by (apply Rmult_le_compat_l; lra). lra.
Qed.

(** ** The exact p_i, q_i and their sizes *)

Lemma hc_p_form : forall s x, (n s <> 0)%nat ->
  p s x = pa s + x / INR (n s) * dot (vsub (Nb s) (Na s)) (L s).
Proof.
  intros s x Hn. apply not_0_INR in Hn. unfold p, A, B, pa, k, dot, vscale, vsub; cbn [vx vy vz].
  field. exact Hn.
Qed.

Lemma hc_q_form : forall s x, (n s <> 0)%nat ->
  q s x = dot (Na s) (Na s) + 2 * (x / INR (n s)) * dot (vsub (Nb s) (Na s)) (Na s)
          + (x / INR (n s)) * (x / INR (n s)) * dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)).
Proof.
  intros s x Hn. apply not_0_INR in Hn. unfold q, C, D, E, k, dot, vscale, vsub; cbn [vx vy vz].
  field. exact Hn.
Qed.

Lemma hc_p_le1 : forall s t, is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> 0 <= t <= 1 ->
  Rabs (pa s + t * dot (vsub (Nb s) (Na s)) (L s)) <= 1.
Proof.
  intros s t Ha Hb Hl Ht.
  assert (X : Rabs (dot (Na s) (L s)) <= 1)
    by (eapply Rle_trans; [apply dot_abs | apply unit_pair; assumption]).
  assert (Y : Rabs (dot (Nb s) (L s)) <= 1)
    by (eapply Rle_trans; [apply dot_abs | apply unit_pair; assumption]).
  replace (pa s + t * dot (vsub (Nb s) (Na s)) (L s))
    with ((1 - t) * dot (Na s) (L s) + t * dot (Nb s) (L s))
    by (unfold pa, dot, vsub; cbn [vx vy vz]; ring).
  eapply Rle_trans; [apply Rabs_triang|].
  rewrite !Rabs_mult, (Rabs_pos_eq (1 - t)), (Rabs_pos_eq t) by lra. nra.
Qed.

Lemma hc_q_le1 : forall s t, is_unit (Na s) -> is_unit (Nb s) -> 0 <= t <= 1 ->
  Rabs (dot (Na s) (Na s) + 2 * t * dot (vsub (Nb s) (Na s)) (Na s)
        + t * t * dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))) <= 1.
Proof.
  intros s t Ha Hb Ht.
  assert (X : Rabs (dot (Na s) (Nb s)) <= 1)
    by (eapply Rle_trans; [apply dot_abs | apply unit_pair; assumption]).
  assert (E : dot (Na s) (Na s) + 2 * t * dot (vsub (Nb s) (Na s)) (Na s)
        + t * t * dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))
        = (1 - t) * (1 - t) * dot (Na s) (Na s) + t * t * dot (Nb s) (Nb s)
          + 2 * t * (1 - t) * dot (Na s) (Nb s))
    by (unfold dot, vsub; cbn [vx vy vz]; ring).
  rewrite E. unfold is_unit in Ha, Hb. rewrite Ha, Hb.
  set (r := dot (Na s) (Nb s)) in *.
  assert (R : - 1 <= r <= 1) by (unfold Rabs in X; destruct (Rcase_abs r); lra).
  assert (P : 0 <= 2 * t * (1 - t)) by nra.
  apply Rabs_le. split; nra.
Qed.

Lemma hc_sizes : forall s, is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  Rabs (dot (vsub (Nb s) (Na s)) (L s)) <= 2 /\
  Rabs (dot (vsub (Nb s) (Na s)) (Na s)) <= 2 /\
  Rabs (dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))) <= 4.
Proof.
  intros s Ha Hb Hl. split; [|split].
  - eapply Rle_trans; [apply dot_abs | apply diff_pair; assumption].
  - eapply Rle_trans; [apply dot_abs | apply diff_pair; assumption].
  - pose proof (diff_sq _ _ Ha Hb). pose proof (dot_sq0 (vsub (Nb s) (Na s))).
    rewrite Rabs_pos_eq; lra.
Qed.

(** ** A division as a reciprocal then a product *)

Lemma recip_ap1 : forall (u eta kd km m x r y : R),
  0 < u <= / 2097152 -> 0 <= eta -> eta * 19342813113834066795298816 <= u ->
  0 <= kd -> kd * u <= / 2097152 -> 0 <= km -> 1 <= m <= 16777216 ->
  ap1 (kd * u) eta r (1 / m) -> ap1 (km * u) eta y (x * r) ->
  ap1 (((1 + / 1048576) * km + kd + / 68719476736) * u) eta y (x / m).
Proof.
  intros u eta kd km m x r y Hu He He2 Hkd Hkdu Hkm Hm Hr Hy. unfold ap1 in *.
  assert (Im2 : / 16777216 <= / m) by (apply Rinv_le_contravar; lra).
  replace (1 / m) with (/ m) in Hr by (field; lra).
  rewrite (Rabs_pos_eq (/ m)) in Hr by lra.
  set (dd := (kd + / 68719476736) * u).
  assert (R1 : Rabs (r - / m) <= dd * / m).
  { assert (eta <= / 68719476736 * u * / m).
    { assert (/ 68719476736 * u * / 16777216 <= / 68719476736 * u * / m)
        by (apply Rmult_le_compat_l; nra). lra. }
    unfold dd. lra. }
  assert (Hdd : 0 <= dd <= / 1048576) by (unfold dd; split; [nra | lra]).
  assert (X1 : Rabs (x * r - x / m) <= dd * Rabs (x / m)).
  { replace (x * r - x / m) with (x * (r - / m)) by (field; lra).
    replace (x / m) with (x * / m) by (field; lra).
    rewrite !Rabs_mult, (Rabs_pos_eq (/ m)) by lra.
    replace (dd * (Rabs x * / m)) with (Rabs x * (dd * / m)) by ring.
    apply Rmult_le_compat_l; [apply Rabs_pos | exact R1]. }
  assert (X2 : Rabs (x * r) <= (1 + dd) * Rabs (x / m)).
  { pose proof (abs_near _ _ _ X1). lra. }
  assert (X3 : km * u * Rabs (x * r) <= km * u * ((1 + dd) * Rabs (x / m)))
    by (apply Rmult_le_compat_l; nra).
  assert (X4 : km * u * (dd * Rabs (x / m)) <= km * u * (/ 1048576 * Rabs (x / m))).
  { apply Rmult_le_compat_l; [nra|]. apply Rmult_le_compat_r; [apply Rabs_pos | lra]. }
  replace (y - x / m) with ((y - x * r) + (x * r - x / m)) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  assert (E : ((1 + / 1048576) * km + kd + / 68719476736) * u * Rabs (x / m)
              = km * u * Rabs (x / m) + km * u * (/ 1048576 * Rabs (x / m))
                + dd * Rabs (x / m)) by (unfold dd; ring).
  rewrite E. nra.
Qed.

(** ** The computation as a relation, for a model M *)

(** k_j as a rounded subtraction, a reciprocal 1/m (a division) and a product. *)
Definition krecip_ok (M : fmodel) (m kj a b : R) : Prop :=
  exists t r, ap_add M t (b - a) /\ ap_div M r (1 / m) /\ ap_mul M kj (t * r).

(** Horner's closed form from the computed na, l, k, at the pixel i. *)
Definition horner_ok (M : fmodel) (i : nat) (na l kk : vec) (ph qh : R) : Prop :=
  exists fa fb fc e fe,
    fdot_ok M kk l fa /\ fdot_ok M na l fb /\ fdot_ok M kk kk fc /\
    fdot_ok M kk na e /\ fdot_ok M na na fe /\
    (exists x, ap_mul M x (fa * INR i) /\ ap_add M ph (x + fb)) /\
    (exists y1 y2 y3, ap_mul M y1 (fc * INR i) /\ ap_add M y2 (y1 + 2 * e) /\
                      ap_mul M y3 (y2 * INR i) /\ ap_add M qh (y3 + fe)).

Lemma hm_small_d : forall M K kd, model_ok M K -> 1 <= kd -> kd * m_u M <= / 2097152 ->
  small_ok (kd * m_u M) (m_eta M).
Proof.
  intros M K kd HM H1 H2. pose proof HM as (U1 & U2 & U3 & _).
  repeat split; try lra.
  - apply Rmult_lt_0_compat; lra.
  - assert (m_u M <= kd * m_u M) by (rewrite <- (Rmult_1_l (m_u M)) at 1;
      apply Rmult_le_compat_r; lra). lra.
Qed.

Lemma hm_small : forall M K K1, model_ok M K -> 1 <= K1 <= K -> small_ok (K1 * m_u M) (m_eta M).
Proof.
  intros M K K1 HM HK. pose proof HM as (H1 & _ & _ & _ & _ & _ & _ & _ & H9).
  apply (hm_small_d M K K1 HM); [lra |].
  assert (K1 * m_u M <= K * m_u M) by (apply Rmult_le_compat_r; lra). lra.
Qed.

Lemma hm_ap : forall M k K1 y x, 0 < m_u M -> k <= K1 ->
  approx k (m_u M) (m_eta M) y x -> ap1 (K1 * m_u M) (m_eta M) y x.
Proof.
  intros M k K1 y x Hu Hk H. eapply ap1_mono; [|exact H].
  apply Rmult_le_compat_r; lra.
Qed.

Lemma hm_vap : forall M K1 vh w, 0 < m_u M -> k_in M <= K1 ->
  vap M vh w -> vap1 (K1 * m_u M) (m_eta M) vh w.
Proof.
  intros M K1 vh w Hu Hk [A1 [A2 A3]].
  repeat split; eapply hm_ap; eassumption.
Qed.

Lemma hm_fdot : forall M K1 a b y, 0 < m_u M -> k_add M <= K1 -> k_mul M <= K1 ->
  fdot_ok M a b y -> fdot_rel (K1 * m_u M) (K1 * m_u M) (m_eta M) a b y.
Proof.
  intros M K1 a b y Hu Ha Hm H. unfold fdot_ok in H.
  eapply fdot_mono; [| | exact H]; apply Rmult_le_compat_r; lra.
Qed.

(** ** The per-pixel normal: N_j = na_j + (i k_j), p^ = N.l, q^ = N.N *)

Definition wb16 (w : vec) : Prop :=
  0 <= vx w <= 16 /\ 0 <= vy w <= 16 /\ 0 <= vz w <= 16.

(** The exact normal N_i = Na + t (Nb - Na), 0 <= t <= 1. *)
Definition nrm (s : span) (t : R) : vec := vadd (Na s) (vscale t (vsub (Nb s) (Na s))).

Lemma pp_ni : forall s t, is_unit (Na s) -> is_unit (Nb s) -> 0 <= t <= 1 ->
  vbounded (nrm s t) 1 /\
  (forall X, is_unit X ->
     Rabs (vx (nrm s t)) * Rabs (vx X) + Rabs (vy (nrm s t)) * Rabs (vy X)
     + Rabs (vz (nrm s t)) * Rabs (vz X) <= 1) /\
  Rabs (vx (nrm s t)) * Rabs (vx (nrm s t)) + Rabs (vy (nrm s t)) * Rabs (vy (nrm s t))
     + Rabs (vz (nrm s t)) * Rabs (vz (nrm s t)) <= 1.
Proof.
  intros s t Ha Hb Ht.
  assert (Q : dot (nrm s t) (nrm s t) <= 1).
  { pose proof (hc_q_le1 s t Ha Hb Ht) as H.
    replace (dot (nrm s t) (nrm s t)) with (dot (Na s) (Na s)
        + 2 * t * dot (vsub (Nb s) (Na s)) (Na s)
        + t * t * dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)))
      by (unfold nrm, dot, vadd, vscale, vsub; cbn [vx vy vz]; ring).
    unfold Rabs in H. destruct (Rcase_abs _); lra. }
  destruct (unit_bounded _ Ha) as [A1 [A2 A3]].
  destruct (unit_bounded _ Hb) as [B1 [B2 B3]].
  assert (C : forall a b, Rabs a <= 1 -> Rabs b <= 1 -> Rabs (a + t * (b - a)) <= 1).
  { intros a b H1 H2. replace (a + t * (b - a)) with ((1 - t) * a + t * b) by ring.
    eapply Rle_trans; [apply Rabs_triang|].
    rewrite !Rabs_mult, (Rabs_pos_eq (1 - t)), (Rabs_pos_eq t) by lra.
    pose proof (Rabs_pos a). pose proof (Rabs_pos b). nra. }
  split; [|split].
  - unfold vbounded, nrm, vadd, vscale, vsub; cbn [vx vy vz]. repeat split; apply C; assumption.
  - intros X HX. unfold is_unit in HX.
    pose proof (amgm1 (vx (nrm s t)) (vx X)). pose proof (amgm1 (vy (nrm s t)) (vy X)).
    pose proof (amgm1 (vz (nrm s t)) (vz X)). unfold dot in Q, HX. lra.
  - rewrite !abs_sq. unfold dot in Q. lra.
Qed.

Lemma pp_p_form : forall s i, (n s <> 0)%nat ->
  p s (INR i) = dot (nrm s (INR i / INR (n s))) (L s).
Proof.
  intros s i Hn. rewrite hc_p_form by exact Hn.
  unfold nrm, pa, dot, vadd, vscale, vsub; cbn [vx vy vz]. ring.
Qed.

Lemma pp_q_form : forall s i, (n s <> 0)%nat ->
  q s (INR i) = dot (nrm s (INR i / INR (n s))) (nrm s (INR i / INR (n s))).
Proof.
  intros s i Hn. rewrite hc_q_form by exact Hn.
  unfold nrm, dot, vadd, vscale, vsub; cbn [vx vy vz]. ring.
Qed.

(** The per-pixel normal from the computed na, k at the pixel i (each product
    i k_j rounded, or exact when fused into the sum), then p^ = N.l, q^ = N.N. *)
Definition ncomp_ok (M : fmodel) (i : nat) (nj naj kj : R) : Prop :=
  exists z, ap_mul M z (INR i * kj) /\ ap_add M nj (naj + z).

Definition pixel_ok (M : fmodel) (i : nat) (na l kk : vec) (ph qh : R) : Prop :=
  exists nh, ncomp_ok M i (vx nh) (vx na) (vx kk) /\ ncomp_ok M i (vy nh) (vy na) (vy kk) /\
    ncomp_ok M i (vz nh) (vz na) (vz kk) /\ fdot_ok M nh l ph /\ fdot_ok M nh nh qh.

(** The lerp with the model's operations: t^ within ap1 (kd u) of i/n, then
    w = 1 - t^ (a subtraction), (w na_j) + (t^ nb_j), each product rounded or fused. *)
Definition lcomp_ok (M : fmodel) (th nj naj nbj : R) : Prop :=
  exists w a b, ap_add M w (1 - th) /\ ap_mul M a (w * naj) /\ ap_mul M b (th * nbj)
                /\ ap_add M nj (a + b).

Definition lerp_ok (M : fmodel) (th : R) (na nb l : vec) (ph qh : R) : Prop :=
  exists nh, lcomp_ok M th (vx nh) (vx na) (vx nb) /\ lcomp_ok M th (vy nh) (vy na) (vy nb) /\
    lcomp_ok M th (vz nh) (vz na) (vz nb) /\ fdot_ok M nh l ph /\ fdot_ok M nh nh qh.

(** ** Cauchy-Schwarz on absolute values *)

Lemma nd_sq_le : forall x y, 0 <= x -> 0 <= y -> x * x <= y * y -> x <= y.
Proof. intros x y Hx Hy H. nra. Qed.

(** Cauchy-Schwarz with absolute values. *)
Lemma nd_cs : forall a b : vec,
  (Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b) + Rabs (vz a) * Rabs (vz b))
  * (Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b) + Rabs (vz a) * Rabs (vz b))
  <= dot a a * dot b b.
Proof.
  intros a b. unfold dot.
  rewrite <- (abs_sq (vx a)), <- (abs_sq (vy a)), <- (abs_sq (vz a)),
          <- (abs_sq (vx b)), <- (abs_sq (vy b)), <- (abs_sq (vz b)).
  set (x1 := Rabs (vx a)). set (x2 := Rabs (vy a)). set (x3 := Rabs (vz a)).
  set (y1 := Rabs (vx b)). set (y2 := Rabs (vy b)). set (y3 := Rabs (vz b)).
  pose proof (Rle_0_sqr (x1 * y2 - x2 * y1)). pose proof (Rle_0_sqr (x1 * y3 - x3 * y1)).
  pose proof (Rle_0_sqr (x2 * y3 - x3 * y2)). unfold Rsqr in *. nra.
Qed.

Lemma cs_abs : forall (a b : vec) (A : R), 0 <= A -> dot a a <= A * A -> dot b b <= 1 ->
  Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b) + Rabs (vz a) * Rabs (vz b) <= A.
Proof.
  intros a b A HA Ha Hb. pose proof (dot_sq0 a). pose proof (dot_sq0 b).
  apply nd_sq_le; [repeat apply Rplus_le_le_0_compat; apply Rmult_le_pos; apply Rabs_pos | lra |].
  eapply Rle_trans; [apply nd_cs|]. replace (A * A) with (A * A * 1) by ring.
  apply Rmult_le_compat; lra.
Qed.

Lemma mix_le : forall t a b, 0 <= t <= 1 -> a <= 1 -> b <= 1 -> (1 - t) * a + t * b <= 1.
Proof. intros t a b Ht Ha Hb. nra. Qed.

(** Mixture weights: c1 M_j + c2 |D_j| + 2^-15. *)
Definition wM (a b : vec) (t c1 c2 : R) : vec :=
  mkV (c1 * ((1 - t) * Rabs (vx a) + t * Rabs (vx b)) + c2 * Rabs (vx b - vx a) + / 32768)
      (c1 * ((1 - t) * Rabs (vy a) + t * Rabs (vy b)) + c2 * Rabs (vy b - vy a) + / 32768)
      (c1 * ((1 - t) * Rabs (vz a) + t * Rabs (vz b)) + c2 * Rabs (vz b - vz a) + / 32768).

(** The inputs of a component mixed with weights 1 - t, t: the mixture
    Mj = (1 - t)|a0| + t|b0| <= 1, the inputs' errors within v Mj + eta, the
    exact value within Mj, the computed difference within |b0 - a0| + 2^-19. *)
Lemma mix_in : forall v eta t a0 b0 ra rb, small_ok v eta -> 0 <= t <= 1 ->
  Rabs a0 <= 1 -> Rabs b0 <= 1 -> ap1 v eta ra a0 -> ap1 v eta rb b0 ->
  0 <= (1 - t) * Rabs a0 + t * Rabs b0 <= 1 /\
  Rabs ((1 - t) * (ra - a0) + t * (rb - b0)) <= v * ((1 - t) * Rabs a0 + t * Rabs b0) + eta /\
  Rabs (a0 + t * (b0 - a0)) <= (1 - t) * Rabs a0 + t * Rabs b0 /\
  Rabs (rb - ra) <= Rabs (b0 - a0) + / 524288.
Proof.
  intros v eta t a0 b0 ra rb Hv Ht Ha0 Hb0 Hra Hrb. small_facts Hv. unfold ap1 in Hra, Hrb.
  pose proof (Rabs_pos a0). pose proof (Rabs_pos b0).
  assert (v * Rabs a0 <= v) by (pose proof (Rmult_le_compat_l v _ _ ltac:(lra) Ha0); lra).
  assert (v * Rabs b0 <= v) by (pose proof (Rmult_le_compat_l v _ _ ltac:(lra) Hb0); lra).
  split; [split; [apply Rplus_le_le_0_compat; apply Rmult_le_pos; lra | apply mix_le; lra]|].
  split; [|split].
  - eapply Rle_trans; [apply Rabs_triang|].
    rewrite !Rabs_mult, (Rabs_pos_eq (1 - t)), (Rabs_pos_eq t) by lra.
    assert ((1 - t) * Rabs (ra - a0) <= (1 - t) * (v * Rabs a0 + eta))
      by (apply Rmult_le_compat_l; lra).
    assert (t * Rabs (rb - b0) <= t * (v * Rabs b0 + eta)) by (apply Rmult_le_compat_l; lra).
    lra.
  - replace (a0 + t * (b0 - a0)) with ((1 - t) * a0 + t * b0) by ring.
    eapply Rle_trans; [apply Rabs_triang|].
    rewrite !Rabs_mult, (Rabs_pos_eq (1 - t)), (Rabs_pos_eq t) by lra. lra.
  - replace (rb - ra) with ((b0 - a0) + (rb - b0) - (ra - a0)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp.
    eapply Rle_trans; [apply Rplus_le_compat_r, Rabs_triang|]. lra.
Qed.

(** The last rounding y of x, x within E <= c of X, |X| <= Mj. *)
Lemma mix_out : forall v eta X x y Mj E c, 0 <= v -> ap1 v eta y x -> Rabs X <= Mj ->
  Rabs (x - X) <= E -> E <= c -> Rabs (y - X) <= E + v * Mj + c * v + eta.
Proof.
  intros v eta X x y Mj E c Hv Hy HX Hx Hc. unfold ap1 in Hy.
  pose proof (abs_near _ _ _ Hx).
  assert (v * Rabs x <= v * (Mj + c)) by (apply Rmult_le_compat_l; lra).
  replace (y - X) with ((y - x) + (x - X)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.

(** ** One component of the per-pixel normal, with the mixture weights *)

Lemma pd_comp : forall v d eta m i a0 b0 ra rb tt kj z nj,
  small_ok v eta -> small_ok d eta -> 1 <= m <= 16777216 -> 0 <= i <= m ->
  Rabs a0 <= 1 -> Rabs b0 <= 1 ->
  ap1 v eta ra a0 -> ap1 v eta rb b0 -> ap1 v eta tt (rb - ra) -> ap1 d eta kj (tt / m) ->
  ap1 v eta z (i * kj) -> ap1 v eta nj (ra + z) ->
  Rabs (nj - (a0 + i / m * (b0 - a0))) <=
    v * (2 * ((1 - i / m) * Rabs a0 + i / m * Rabs b0) + 2001 / 1000 * Rabs (b0 - a0) + / 32768)
    + d * (0 * ((1 - i / m) * Rabs a0 + i / m * Rabs b0) + 1001 / 1000 * Rabs (b0 - a0)
           + / 32768).
Proof.
  intros v d eta m i a0 b0 ra rb tt kj z nj Hv Hd Hm Hi Ha0 Hb0 Hra Hrb Htt Hkj Hz Hnj.
  small_facts Hv. v_facts Hd.
  pose proof (theta_rng m i ltac:(lra) Hi) as Ht.
  set (t := i / m) in *.
  destruct (mix_in v eta t a0 b0 ra rb Hv Ht Ha0 Hb0 Hra Hrb) as (HM & AB & Nn & R1).
  set (D := b0 - a0) in *.
  pose proof (Rabs_pos D).
  assert (HD2 : Rabs D <= 2) by (unfold D; pose proof (absdiff b0 a0); lra).
  set (Mj := (1 - t) * Rabs a0 + t * Rabs b0) in *.
  assert (Me : m * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  assert (HI : i = t * m) by (unfold t; field; lra).
  unfold ap1 in Hra, Hrb, Htt, Hkj, Hz, Hnj.
  (* the subtraction *)
  assert (G : Rabs (tt - (rb - ra)) <= v * Rabs D + / 524288 * v + eta).
  { assert (v * Rabs (rb - ra) <= v * (Rabs D + / 524288)) by (apply Rmult_le_compat_l; lra).
    lra. }
  assert (T1 : Rabs tt <= Rabs D + / 262144).
  { pose proof (abs_near _ _ _ G). assert (v * Rabs D <= / 2097152 * 2)
      by (apply Rmult_le_compat; lra). lra. }
  (* the division, times i *)
  assert (Dm : Rabs (i * kj - t * tt) <= d * Rabs tt + m * eta).
  { replace (i * kj - t * tt) with (i * (kj - tt / m)) by (rewrite HI; field; lra).
    assert (B : Rabs (i * (tt / m)) <= Rabs tt).
    { replace (i * (tt / m)) with (t * tt) by (rewrite HI; field; lra). apply hc_scale, Ht. }
    pose proof (ap_lam d eta i _ _ _ ltac:(lra) ltac:(lra) Hkj B).
    assert (i * eta <= m * eta) by (apply Rmult_le_compat_r; lra). lra. }
  assert (DT : d * Rabs tt <= d * (Rabs D + / 262144)) by (apply Rmult_le_compat_l; lra).
  assert (Ik : Rabs (i * kj) <= Rabs D + / 131072).
  { replace (i * kj) with (t * tt + (i * kj - t * tt)) by ring.
    eapply Rle_trans; [apply Rabs_triang|].
    assert (Rabs (t * tt) <= Rabs tt) by (apply hc_scale; exact Ht).
    assert (d * (Rabs D + / 262144) <= / 2097152 * (2 + / 262144))
      by (apply Rmult_le_compat; lra). lra. }
  (* the product i k_j *)
  assert (Z : Rabs (z - i * kj) <= v * Rabs D + / 131072 * v + eta).
  { assert (v * Rabs (i * kj) <= v * (Rabs D + / 131072)) by (apply Rmult_le_compat_l; lra).
    lra. }
  (* the sum *)
  assert (EN : ra + z - (a0 + t * D)
               = ((1 - t) * (ra - a0) + t * (rb - b0)) + t * (tt - (rb - ra))
                 + (i * kj - t * tt) + (z - i * kj)) by (unfold D; ring).
  assert (TG : Rabs (t * (tt - (rb - ra))) <= v * Rabs D + / 524288 * v + eta)
    by (eapply Rle_trans; [apply hc_scale; exact Ht | exact G]).
  assert (E1 : Rabs (ra + z - (a0 + t * D))
               <= v * Mj + 2 * (v * Rabs D) + d * Rabs D + / 98304 * v + / 131072 * d
                  + 16777220 * eta).
  { rewrite EN. eapply Rle_trans; [apply tri4|]. lra. }
  assert (VS : v * Mj + 2 * (v * Rabs D) + d * Rabs D <= / 2097152 * 7).
  { assert (v * Mj <= / 2097152 * 1) by (apply Rmult_le_compat; lra).
    assert (v * Rabs D <= / 2097152 * 2) by (apply Rmult_le_compat; lra).
    assert (d * Rabs D <= / 2097152 * 2) by (apply Rmult_le_compat; lra). lra. }
  eapply Rle_trans; [apply (mix_out v eta _ _ _ _ _ (/ 65536) ltac:(lra) Hnj Nn E1); lra|].
  assert (0 <= v * Rabs D) by (apply Rmult_le_pos; lra).
  assert (0 <= d * Rabs D) by (apply Rmult_le_pos; lra).
  fold Mj. lra.
Qed.

Lemma prod_le : forall X Y x y, Rabs X <= x -> Rabs Y <= y -> Rabs (X * Y) <= x * y.
Proof.
  intros X Y x y HX HY. rewrite Rabs_mult.
  apply Rmult_le_compat; try apply Rabs_pos; assumption.
Qed.

(** ** One component of the lerp, with the mixture weights *)

Lemma ld_comp : forall v d eta m i a0 b0 ra rb th w y1 y2 nj,
  small_ok v eta -> small_ok d eta -> 1 <= m <= 16777216 -> 0 <= i <= m ->
  Rabs a0 <= 1 -> Rabs b0 <= 1 ->
  ap1 v eta nj (y1 + y2) -> ap1 v eta y1 (w * ra) -> ap1 v eta y2 (th * rb) ->
  ap1 v eta w (1 - th) -> ap1 d eta th (i / m) -> ap1 v eta ra a0 -> ap1 v eta rb b0 ->
  Rabs (nj - (a0 + i / m * (b0 - a0))) <=
    v * (4 * ((1 - i / m) * Rabs a0 + i / m * Rabs b0) + 0 * Rabs (b0 - a0) + / 32768)
    + d * (0 * ((1 - i / m) * Rabs a0 + i / m * Rabs b0) + 1001 / 1000 * Rabs (b0 - a0)
           + / 32768).
Proof.
  intros v d eta m i a0 b0 ra rb th w y1 y2 nj Hv Hd Hm Hi Ha0 Hb0 Hnj Hy1 Hy2 Hw Hth Hra Hrb.
  small_facts Hv. v_facts Hd.
  pose proof (Rabs_pos a0). pose proof (Rabs_pos b0).
  pose proof (theta_rng m i ltac:(lra) Hi) as Ht.
  set (t := i / m) in *.
  destruct (mix_in v eta t a0 b0 ra rb Hv Ht Ha0 Hb0 Hra Hrb) as (HM & AB & Nn & Rd).
  set (D := b0 - a0) in *.
  pose proof (Rabs_pos D).
  assert (HD2 : Rabs D <= 2) by (unfold D; pose proof (absdiff b0 a0); lra).
  set (Mj := (1 - t) * Rabs a0 + t * Rabs b0) in *.
  unfold ap1 in Hra, Hrb, Hth, Hw, Hy1, Hy2, Hnj.
  rewrite (Rabs_pos_eq t) in Hth by lra.
  assert (A1 : v * Rabs a0 <= v) by (pose proof (Rmult_le_compat_l v _ _ ltac:(lra) Ha0); lra).
  assert (B1 : v * Rabs b0 <= v) by (pose proof (Rmult_le_compat_l v _ _ ltac:(lra) Hb0); lra).
  assert (E1 : eta * Rabs a0 <= eta) by (pose proof (Rmult_le_compat_l eta _ _ ltac:(lra) Ha0); lra).
  assert (P1 : 0 <= v * t) by (apply Rmult_le_pos; lra).
  assert (P2 : v * t <= v) by (pose proof (Rmult_le_compat_l v t 1 ltac:(lra) ltac:(lra)); lra).
  assert (P3 : d * t <= d) by (pose proof (Rmult_le_compat_l d t 1 ltac:(lra) ltac:(lra)); lra).
  assert (P5 : d * t * Rabs D <= d * Rabs D)
    by (apply Rmult_le_compat_r; [apply Rabs_pos | lra]).
  assert (P10 : 0 <= d * Rabs D) by (apply Rmult_le_pos; lra).
  assert (P11 : eta * Rabs D <= eta * 2) by (apply Rmult_le_compat_l; lra).
  assert (P12 : d * Rabs D <= / 2097152 * 2) by (apply Rmult_le_compat; lra).
  (* t^ and 1 - t^ *)
  assert (Tau : Rabs (th - t) <= d * t + eta) by lra.
  assert (W1 : Rabs (1 - th) <= (1 - t) + d * t + eta).
  { replace (1 - th) with ((1 - t) - (th - t)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp, (Rabs_pos_eq (1 - t)) by lra. lra. }
  assert (Om : Rabs (w - (1 - th)) <= v * (1 - t) + / 1048576 * v + eta).
  { assert (v * Rabs (1 - th) <= v * ((1 - t) + d * t + eta)) by (apply Rmult_le_compat_l; lra).
    assert (v * (d * t + eta) <= v * / 1048576) by (apply Rmult_le_compat_l; lra). lra. }
  assert (Ra : Rabs ra <= Rabs a0 + / 1048576).
  { pose proof (abs_near _ _ _ Hra). lra. }
  assert (Rb : Rabs rb <= Rabs b0 + / 1048576).
  { pose proof (abs_near _ _ _ Hrb). lra. }
  (* the pieces *)
  assert (X1 : Rabs ((w - (1 - th)) * ra) <= v * ((1 - t) * Rabs a0) + / 131072 * v + 2 * eta).
  { eapply Rle_trans; [apply (prod_le _ _ _ _ Om Ra)|]. lra. }
  assert (X2 : Rabs ((th - t) * (rb - ra)) <= d * Rabs D + / 262144 * d + 3 * eta).
  { eapply Rle_trans; [apply (prod_le _ _ _ _ Tau Rd)|]. lra. }
  assert (Wb : Rabs w <= (1 - t) + / 524288).
  { replace w with ((1 - t) + (w - (1 - th)) - (th - t)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp.
    eapply Rle_trans; [apply Rplus_le_compat_r, Rabs_triang|].
    rewrite (Rabs_pos_eq (1 - t)) by lra. lra. }
  assert (Thb : Rabs th <= t + / 524288).
  { replace th with (t + (th - t)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite (Rabs_pos_eq t) by lra. lra. }
  assert (X3 : Rabs (y1 - w * ra) <= v * ((1 - t) * Rabs a0) + / 262144 * v + eta).
  { pose proof (prod_le _ _ _ _ Wb Ra) as Q.
    assert (v * Rabs (w * ra) <= v * (((1 - t) + / 524288) * (Rabs a0 + / 1048576)))
      by (apply Rmult_le_compat_l; lra). lra. }
  assert (X4 : Rabs (y2 - th * rb) <= v * (t * Rabs b0) + / 262144 * v + eta).
  { pose proof (prod_le _ _ _ _ Thb Rb) as Q.
    assert (v * Rabs (th * rb) <= v * ((t + / 524288) * (Rabs b0 + / 1048576)))
      by (apply Rmult_le_compat_l; lra). lra. }
  assert (EN : y1 + y2 - (a0 + t * D)
               = (y1 - w * ra) + (y2 - th * rb) + ((1 - t) * (ra - a0) + t * (rb - b0))
                 + (w - (1 - th)) * ra + (th - t) * (rb - ra)) by (unfold D; ring).
  assert (HMa : v * Mj = v * ((1 - t) * Rabs a0) + v * (t * Rabs b0)) by (unfold Mj; ring).
  assert (F1 : Rabs (y1 + y2 - (a0 + t * D))
               <= 2 * (v * ((1 - t) * Rabs a0)) + v * (t * Rabs b0) + v * Mj + d * Rabs D
                  + / 65536 * v + / 262144 * d + 8 * eta).
  { rewrite EN. eapply Rle_trans; [apply tri5|]. lra. }
  assert (VM : v * Mj <= v) by (pose proof (Rmult_le_compat_l v _ _ ltac:(lra) (proj2 HM)); lra).
  assert (V1 : v * ((1 - t) * Rabs a0) <= v * Mj).
  { apply Rmult_le_compat_l; [lra|]. unfold Mj.
    pose proof (Rmult_le_pos t (Rabs b0) ltac:(lra) ltac:(lra)). lra. }
  assert (V2 : v * (t * Rabs b0) <= v * Mj).
  { apply Rmult_le_compat_l; [lra|]. unfold Mj.
    pose proof (Rmult_le_pos (1 - t) (Rabs a0) ltac:(lra) ltac:(lra)). lra. }
  eapply Rle_trans; [apply (mix_out v eta _ _ _ _ _ (/ 262144) ltac:(lra) Hnj Nn F1); lra|].
  fold Mj. lra.
Qed.

(** ** The dot products of a computed normal within the mixture weights *)

(** The weights of a read-in unit vector and of none. *)
Lemma wb16_in : forall X, is_unit X -> wb16 (Float.wIn X) /\ wb16 vzero.
Proof.
  intros X HX. destruct (unit_bounded _ HX) as [X1 [X2 X3]]. pose proof (abs3 X).
  unfold wb16, Float.wIn, vzero; cbn [vx vy vz]. repeat split; lra.
Qed.

Lemma wM_sum : forall (a b X : vec) (t c1 c2 dd : R), 0 <= t <= 1 -> 0 <= c1 -> 0 <= c2 ->
  Rabs (vx a) * Rabs (vx X) + Rabs (vy a) * Rabs (vy X) + Rabs (vz a) * Rabs (vz X) <= 1 ->
  Rabs (vx b) * Rabs (vx X) + Rabs (vy b) * Rabs (vy X) + Rabs (vz b) * Rabs (vz X) <= 1 ->
  Rabs (vx (vsub b a)) * Rabs (vx X) + Rabs (vy (vsub b a)) * Rabs (vy X)
    + Rabs (vz (vsub b a)) * Rabs (vz X) <= dd ->
  vbounded X 1 ->
  vx (wM a b t c1 c2) * Rabs (vx X) + vy (wM a b t c1 c2) * Rabs (vy X)
    + vz (wM a b t c1 c2) * Rabs (vz X) <= c1 + c2 * dd + 3 / 32768.
Proof.
  intros a b X t c1 c2 dd Ht H1 H2 HA HB HD [X1 [X2 X3]].
  unfold vsub in HD; cbn [vx vy vz] in HD. unfold wM; cbn [vx vy vz].
  set (SA := Rabs (vx a) * Rabs (vx X) + Rabs (vy a) * Rabs (vy X) + Rabs (vz a) * Rabs (vz X))
    in *.
  set (SB := Rabs (vx b) * Rabs (vx X) + Rabs (vy b) * Rabs (vy X) + Rabs (vz b) * Rabs (vz X))
    in *.
  set (SD := Rabs (vx b - vx a) * Rabs (vx X) + Rabs (vy b - vy a) * Rabs (vy X)
             + Rabs (vz b - vz a) * Rabs (vz X)) in *.
  assert (M1 : c1 * ((1 - t) * SA + t * SB) <= c1 * 1)
    by (apply Rmult_le_compat_l; [lra | apply mix_le; lra]).
  assert (M2 : c2 * SD <= c2 * dd) by (apply Rmult_le_compat_l; lra).
  unfold SA, SB, SD in *. lra.
Qed.

Lemma wM_wb16 : forall (a b : vec) (t c1 c2 : R), 0 <= t <= 1 -> 0 <= c1 <= 4 -> 0 <= c2 <= 3 ->
  vbounded a 1 -> vbounded b 1 -> wb16 (wM a b t c1 c2).
Proof.
  intros a b t c1 c2 Ht Hc1 Hc2 [A1 [A2 A3]] [B1 [B2 B3]].
  assert (G : forall x y, Rabs x <= 1 -> Rabs y <= 1 ->
    0 <= c1 * ((1 - t) * Rabs x + t * Rabs y) + c2 * Rabs (y - x) + / 32768 <= 16).
  { intros x y Hx Hy. pose proof (Rabs_pos x). pose proof (Rabs_pos y).
    pose proof (Rabs_pos (y - x)). pose proof (absdiff y x).
    assert (0 <= (1 - t) * Rabs x + t * Rabs y <= 1).
    { split; [apply Rplus_le_le_0_compat; apply Rmult_le_pos; lra | apply mix_le; lra]. }
    assert (0 <= c1 * ((1 - t) * Rabs x + t * Rabs y) <= 4 * 1)
      by (split; [apply Rmult_le_pos | apply Rmult_le_compat]; lra).
    assert (0 <= c2 * Rabs (y - x) <= 3 * 2)
      by (split; [apply Rmult_le_pos | apply Rmult_le_compat]; lra).
    lra. }
  unfold wb16, wM; cbn [vx vy vz]. repeat split; apply G; assumption.
Qed.

Lemma pd_tail : forall (v d eta : R) (s : span) (nh l : vec) (t ph qh dd c1 c2 c3 : R),
  small_ok v eta -> small_ok d eta ->
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> 0 <= t <= 1 ->
  0 <= dd -> dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd ->
  0 <= c1 <= 4 -> 0 <= c2 <= 3 -> 0 <= c3 <= 3 ->
  vap1 v eta l (L s) ->
  vapprox 1 1 nh (nrm s t) (vlin v d (wM (Na s) (Nb s) t c1 c2) (wM (Na s) (Nb s) t 0 c3)) ->
  fdot_rel v v eta nh l ph -> fdot_rel v v eta nh nh qh ->
  Rabs (ph - dot (nrm s t) (L s)) <= (c1 + c2 * dd + 402 / 100) * v + (c3 * dd + 2 / 100) * d /\
  Rabs (qh - dot (nrm s t) (nrm s t))
    <= (2 * c1 + 2 * c2 * dd + 302 / 100) * v + (2 * c3 * dd + 2 / 100) * d.
Proof.
  intros v d eta s nh l t ph qh dd c1 c2 c3 Hv Hd Ha Hb Hl Ht Hdd HD Hc1 Hc2 Hc3 Inl VN Hp Hq.
  destruct (pp_ni s t Ha Hb Ht) as [NB [NX NN]].
  assert (Q : dot (nrm s t) (nrm s t) <= 1).
  { unfold dot. rewrite <- (abs_sq (vx (nrm s t))), <- (abs_sq (vy (nrm s t))),
      <- (abs_sq (vz (nrm s t))). lra. }
  pose proof (NX _ Hl) as NL. pose proof (NX _ Ha) as NA. pose proof (NX _ Hb) as NBb.
  pose proof (unit_pair _ _ Ha Hl) as AL. pose proof (unit_pair _ _ Hb Hl) as BL.
  pose proof (cs_abs _ _ dd Hdd HD (Req_le _ _ Hl)) as DL.
  pose proof (cs_abs _ _ dd Hdd HD Q) as DN.
  destruct (unit_bounded _ Hl) as [L1 [L2 L3]].
  destruct NB as [N1 [N2 N3]].
  pose proof (wM_wb16 _ _ t c1 c2 Ht Hc1 Hc2 (unit_bounded _ Ha) (unit_bounded _ Hb)) as Wv.
  pose proof (wM_wb16 _ _ t 0 c3 Ht ltac:(lra) Hc3 (unit_bounded _ Ha) (unit_bounded _ Hb)) as Wd.
  destruct (wb16_in _ Hl) as [WL W0].
  assert (NB1 : vbounded (nrm s t) 1) by (repeat split; assumption).
  (* the weighted sums against L and against N *)
  pose proof (wM_sum _ _ _ t c1 c2 dd Ht ltac:(lra) ltac:(lra) AL BL DL (unit_bounded _ Hl)) as SL1.
  pose proof (wM_sum _ _ _ t 0 c3 dd Ht ltac:(lra) ltac:(lra) AL BL DL (unit_bounded _ Hl)) as SL2.
  assert (NA' : Rabs (vx (Na s)) * Rabs (vx (nrm s t)) + Rabs (vy (Na s)) * Rabs (vy (nrm s t))
                + Rabs (vz (Na s)) * Rabs (vz (nrm s t)) <= 1) by lra.
  assert (NB' : Rabs (vx (Nb s)) * Rabs (vx (nrm s t)) + Rabs (vy (Nb s)) * Rabs (vy (nrm s t))
                + Rabs (vz (Nb s)) * Rabs (vz (nrm s t)) <= 1) by lra.
  pose proof (wM_sum _ _ _ t c1 c2 dd Ht ltac:(lra) ltac:(lra) NA' NB' DN NB1) as SN1.
  pose proof (wM_sum _ _ _ t 0 c3 dd Ht ltac:(lra) ltac:(lra) NA' NB' DN NB1) as SN2.
  split.
  - pose proof (dot_w v d eta 1 16 (/ 100) 1 1 ph (c1 + c2 * dd + 402 / 100) (c3 * dd + 2 / 100)
      nh l (nrm s t) (L s) _ _ _ _ Hv Hd ltac:(lra) ltac:(lra) Hp ltac:(lra) ltac:(lra) ltac:(lra) VN
      (K_in_vec v d eta Hv _ _ Inl) (vb12 _ NB1) (vb12 _ (unit_bounded _ Hl)) Wv Wd WL W0) as HD2.
    rewrite !Rmult_1_l in HD2. apply HD2; [lra | lra | |].
    + unfold wsum0, Float.wIn; cbn [vx vy vz]. lra.
    + unfold wsum0, vzero; cbn [vx vy vz]. lra.
  - pose proof (dot_w v d eta 1 16 (/ 100) 1 1 qh (2 * c1 + 2 * c2 * dd + 302 / 100) (2 * c3 * dd + 2 / 100)
      nh nh (nrm s t) (nrm s t) _ _ _ _ Hv Hd ltac:(lra) ltac:(lra) Hq ltac:(lra) ltac:(lra) ltac:(lra) VN VN
      (vb12 _ NB1) (vb12 _ NB1) Wv Wd Wv Wd) as HD2.
    rewrite !Rmult_1_l in HD2. apply HD2; [lra | lra | |].
    + unfold wsum0; cbn [vx vy vz]. lra.
    + unfold wsum0; cbn [vx vy vz]. lra.
Qed.

(** The span's distance: dd >= |Nb - Na|. *)
Definition Ddist (s : span) (dd : R) : Prop :=
  0 <= dd <= 2 /\ dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd.

(** ** Horner's closed form, and every form on the set-up of k (section HK) *)

(** p^ = (A i) + B, with |a| <= Da (Da = dd, a = D.L). *)
Lemma hp_abs_d : forall v eta m i fA fB a b cA cB x ph Da,
  small_ok v eta -> 1 <= m <= 16777216 -> 0 <= i <= m ->
  Rabs (m * fA - a) <= cA -> Rabs (fB - b) <= cB -> 0 <= cA <= / 1000 -> 0 <= cB <= / 1000 ->
  0 <= Da <= 2 -> Rabs a <= Da -> Rabs (b + i / m * a) <= 1 ->
  ap1 v eta x (fA * i) -> ap1 v eta ph (x + fB) ->
  Rabs (ph - (b + i / m * a)) <= cA + cB + (101 / 100 + Da) * v.
Proof.
  intros v eta m i fA fB a b cA cB x ph Da Hv Hm Hi HA HB HcA HcB HDa Ha Hp Hx Hph.
  unfold ap1 in Hx, Hph.
  small_facts Hv.
  pose proof (theta_rng m i ltac:(lra) Hi) as Ht.
  assert (EA : fA * i = i / m * (m * fA)) by (field; lra).
  assert (B1 : Rabs (fA * i) <= Da + cA).
  { rewrite EA. eapply Rle_trans; [apply hc_scale; exact Ht|].
    pose proof (abs_near _ _ _ HA). lra. }
  assert (E1 : Rabs (x - fA * i) <= v * (Da + cA) + eta).
  { assert (v * Rabs (fA * i) <= v * (Da + cA)) by (apply Rmult_le_compat_l; lra). lra. }
  assert (E0 : Rabs (fA * i - i / m * a) <= cA).
  { replace (fA * i - i / m * a) with (i / m * (m * fA - a)) by (field; lra).
    eapply Rle_trans; [apply hc_scale; exact Ht|]. exact HA. }
  assert (V1 : v * (Da + cA) <= / 2097152 * 3) by (apply Rmult_le_compat; lra).
  assert (S1 : Rabs (x + fB) <= 1004 / 1000).
  { replace (x + fB) with ((b + i / m * a) + (x - fA * i) + (fA * i - i / m * a) + (fB - b))
      by ring.
    eapply Rle_trans; [apply tri4|]. lra. }
  assert (E2 : Rabs (ph - (x + fB)) <= v * (1004 / 1000) + eta).
  { assert (v * Rabs (x + fB) <= v * (1004 / 1000)) by (apply Rmult_le_compat_l; lra). lra. }
  replace (ph - (b + i / m * a))
    with ((ph - (x + fB)) + (x - fA * i) + (fA * i - i / m * a) + (fB - b)) by ring.
  eapply Rle_trans; [apply tri4|].
  assert (v * cA <= v * / 1000) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

(** q^ = ((C i + D) i) + E, D = 2 e exactly, with |c| <= C2 (= dd^2), |dd| <= D1 (= dd). *)
Lemma hq_abs_d : forall v eta m i fC e fE c dd ee cC cD cE y1 y2 y3 qh C2 D1,
  small_ok v eta -> 1 <= m <= 16777216 -> 0 <= i <= m ->
  Rabs (m * m * fC - c) <= cC -> Rabs (m * e - dd) <= cD -> Rabs (fE - ee) <= cE ->
  0 <= cC <= / 1000 -> 0 <= cD <= / 1000 -> 0 <= cE <= / 1000 ->
  0 <= C2 <= 4 -> 0 <= D1 <= 2 -> Rabs c <= C2 -> Rabs dd <= D1 ->
  Rabs (ee + 2 * (i / m) * dd + (i / m) * (i / m) * c) <= 1 ->
  ap1 v eta y1 (fC * i) -> ap1 v eta y2 (y1 + 2 * e) -> ap1 v eta y3 (y2 * i) ->
  ap1 v eta qh (y3 + fE) ->
  Rabs (qh - (ee + 2 * (i / m) * dd + (i / m) * (i / m) * c))
    <= cE + cC + 2 * cD + (106 / 100 + 4 * D1 + 3 * C2) * v.
Proof.
  intros v eta m i fC e fE c dd ee cC cD cE y1 y2 y3 qh C2 D1 Hv Hm Hi HC HD HE HcC HcD HcE
    HC2 HD1 Hc Hd Hq H1 H2 H3 H4.
  unfold ap1 in H1, H2, H3, H4.
  small_facts Hv.
  pose proof (theta_rng m i ltac:(lra) Hi) as Ht.
  set (t := i / m) in *.
  assert (Ei : i = t * m) by (unfold t; field; lra).
  assert (Me : m * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  set (S2b := C2 + 2 * D1 + / 100).
  assert (VS : v * S2b <= / 2097152 * (8 + 1 / 100))
    by (apply Rmult_le_compat; unfold S2b; lra).
  assert (VC : v * (C2 + cC) <= / 2097152 * (4 + / 1000)) by (apply Rmult_le_compat; lra).
  assert (F1 : Rabs (m * y1 - t * (m * m * fC)) <= v * (C2 + cC) + m * eta).
  { replace (m * y1 - t * (m * m * fC)) with (m * (y1 - fC * i)) by (rewrite Ei; ring).
    apply ap_lam; [lra | lra | exact H1 |].
    replace (m * (fC * i)) with (t * (m * m * fC)) by (rewrite Ei; ring).
    eapply Rle_trans; [apply hc_scale; exact Ht|]. pose proof (abs_near _ _ _ HC). lra. }
  assert (F0 : Rabs (t * (m * m * fC) - t * c) <= cC).
  { replace (t * (m * m * fC) - t * c) with (t * (m * m * fC - c)) by ring.
    eapply Rle_trans; [apply hc_scale; exact Ht|]. exact HC. }
  assert (Tc : Rabs (t * c) <= C2) by (eapply Rle_trans; [apply hc_scale; exact Ht|]; lra).
  assert (S2 : Rabs (m * y1 + 2 * (m * e)) <= S2b).
  { replace (m * y1 + 2 * (m * e))
      with (t * c + 2 * dd + (m * y1 - t * (m * m * fC)) + (t * (m * m * fC) - t * c)
            + 2 * (m * e - dd)) by ring.
    assert (Rabs (2 * dd) <= 2 * D1) by (rewrite Rabs_mult, (Rabs_pos_eq 2) by lra; lra).
    assert (Rabs (2 * (m * e - dd)) <= 2 * cD)
      by (rewrite Rabs_mult, (Rabs_pos_eq 2) by lra; lra).
    eapply Rle_trans; [apply tri5|]. unfold S2b. lra. }
  assert (F2 : Rabs (m * y2 - m * (y1 + 2 * e)) <= v * S2b + m * eta).
  { rewrite <- Rmult_minus_distr_l. apply ap_lam; [lra | lra | exact H2 |].
    replace (m * (y1 + 2 * e)) with (m * y1 + 2 * (m * e)) by ring. exact S2. }
  assert (S3 : Rabs (m * y2) <= S2b + / 100).
  { replace (m * y2) with ((m * y1 + 2 * (m * e)) + (m * y2 - m * (y1 + 2 * e))) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra. }
  assert (F3 : Rabs (y3 - y2 * i) <= v * (S2b + / 100) + eta).
  { assert (Rabs (y2 * i) <= S2b + / 100).
    { replace (y2 * i) with (t * (m * y2)) by (rewrite Ei; ring).
      eapply Rle_trans; [apply hc_scale; exact Ht|]. exact S3. }
    assert (v * Rabs (y2 * i) <= v * (S2b + / 100)) by (apply Rmult_le_compat_l; lra). lra. }
  set (Q := ee + 2 * t * dd + t * t * c) in *.
  assert (Eq : y3 + fE - Q = (y3 - y2 * i) + t * (m * y2 - m * (y1 + 2 * e))
                 + t * (m * y1 - t * (m * m * fC)) + t * (t * (m * m * fC) - t * c)
                 + 2 * t * (m * e - dd) + (fE - ee)).
  { unfold Q. rewrite Ei. ring. }
  assert (Rt1 : Rabs (t * (m * y2 - m * (y1 + 2 * e))) <= v * S2b + m * eta)
    by (eapply Rle_trans; [apply hc_scale; exact Ht | exact F2]).
  assert (Rt2 : Rabs (t * (m * y1 - t * (m * m * fC))) <= v * (C2 + cC) + m * eta)
    by (eapply Rle_trans; [apply hc_scale; exact Ht | exact F1]).
  assert (Rt3 : Rabs (t * (t * (m * m * fC) - t * c)) <= cC)
    by (eapply Rle_trans; [apply hc_scale; exact Ht | exact F0]).
  assert (Rt4 : Rabs (2 * t * (m * e - dd)) <= 2 * cD).
  { replace (2 * t * (m * e - dd)) with (t * (2 * (m * e - dd))) by ring.
    eapply Rle_trans; [apply hc_scale; exact Ht|].
    rewrite Rabs_mult, (Rabs_pos_eq 2) by lra. lra. }
  assert (G : Rabs (y3 + fE - Q) <= cE + cC + 2 * cD
                + (v * S2b + v * (S2b + / 100) + v * (C2 + cC) + 3 * 16777216 * eta)).
  { rewrite Eq. eapply Rle_trans; [apply tri6|]. lra. }
  assert (S4 : Rabs (y3 + fE) <= 1005 / 1000).
  { replace (y3 + fE) with (Q + (y3 + fE - Q)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra. }
  assert (F4 : Rabs (qh - (y3 + fE)) <= v * (1005 / 1000) + eta).
  { assert (v * Rabs (y3 + fE) <= v * (1005 / 1000)) by (apply Rmult_le_compat_l; lra). lra. }
  replace (qh - Q) with ((qh - (y3 + fE)) + (y3 + fE - Q)) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  assert (v * cC <= v * / 1000) by (apply Rmult_le_compat_l; lra).
  unfold S2b in *. lra.
Qed.

(** One component of n k: |n k_j - D_j| <= v (|a_j| + |b_j| + 1.001 |D_j|) + d 1.001 |D_j|. *)
Lemma hk_comp : forall v d eta m a0 b0 ra rb tt kj,
  small_ok v eta -> small_ok d eta -> 1 <= m <= 16777216 ->
  Rabs a0 <= 1 -> Rabs b0 <= 1 ->
  ap1 v eta ra a0 -> ap1 v eta rb b0 -> ap1 v eta tt (rb - ra) -> ap1 d eta kj (tt / m) ->
  Rabs (m * kj - (b0 - a0)) <=
    v * (Rabs a0 + Rabs b0 + 1001 / 1000 * Rabs (b0 - a0) + / 32768)
    + d * (1001 / 1000 * Rabs (b0 - a0) + / 32768).
Proof.
  intros v d eta m a0 b0 ra rb tt kj Hv Hd Hm Ha0 Hb0 Hra Hrb Htt Hkj.
  small_facts Hv. v_facts Hd.
  set (D := b0 - a0) in *.
  pose proof (Rabs_pos D).
  assert (HD2 : Rabs D <= 2) by (unfold D; pose proof (absdiff b0 a0); lra).
  assert (Me : m * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  unfold ap1 in Hra, Hrb, Htt, Hkj.
  assert (A1 : v * Rabs a0 <= v) by (pose proof (Rmult_le_compat_l v _ _ ltac:(lra) Ha0); lra).
  assert (B1 : v * Rabs b0 <= v) by (pose proof (Rmult_le_compat_l v _ _ ltac:(lra) Hb0); lra).
  assert (R1 : Rabs (rb - ra) <= Rabs D + / 524288).
  { replace (rb - ra) with (D + (rb - b0) - (ra - a0)) by (unfold D; ring).
    eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp.
    eapply Rle_trans; [apply Rplus_le_compat_r, Rabs_triang|]. lra. }
  assert (G : Rabs (tt - (rb - ra)) <= v * Rabs D + / 524288 * v + eta).
  { assert (v * Rabs (rb - ra) <= v * (Rabs D + / 524288)) by (apply Rmult_le_compat_l; lra).
    lra. }
  assert (T1 : Rabs tt <= Rabs D + / 262144).
  { pose proof (abs_near _ _ _ G). assert (v * Rabs D <= / 2097152 * 2)
      by (apply Rmult_le_compat; lra). lra. }
  assert (Dm : Rabs (m * kj - tt) <= d * Rabs tt + m * eta).
  { replace (m * kj - tt) with (m * (kj - tt / m)) by (field; lra).
    apply ap_lam; [lra | lra | exact Hkj |].
    replace (m * (tt / m)) with tt by (field; lra). lra. }
  assert (DT : d * Rabs tt <= d * (Rabs D + / 262144)) by (apply Rmult_le_compat_l; lra).
  replace (m * kj - D) with ((m * kj - tt) + (tt - (rb - ra)) + (rb - b0) - (ra - a0))
    by (unfold D; ring).
  eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp.
  eapply Rle_trans; [apply Rplus_le_compat_r, tri3|].
  assert (0 <= v * Rabs D) by (apply Rmult_le_pos; lra).
  assert (0 <= d * Rabs D) by (apply Rmult_le_pos; lra).
  lra.
Qed.

Section HK.
Context (v d eta dd : R) (Hv : small_ok v eta) (Hdv : small_ok d eta) (s : span)
        (HDd : Ddist s dd) (Ha : is_unit (Na s)) (Hb : is_unit (Nb s))
        (Hn1 : (1 <= n s)%nat) (Hn2 : INR (n s) <= 16777216)
        (na nb kk : vec) (Ina : vap1 v eta na (Na s)) (Inb : vap1 v eta nb (Nb s))
        (tx ty tz : R)
        (Htx : ap1 v eta tx (vx nb - vx na)) (Hkx : ap1 d eta (vx kk) (tx / INR (n s)))
        (Hty : ap1 v eta ty (vy nb - vy na)) (Hky : ap1 d eta (vy kk) (ty / INR (n s)))
        (Htz : ap1 v eta tz (vz nb - vz na)) (Hkz : ap1 d eta (vz kk) (tz / INR (n s))).

Local Notation Dl := (vsub (Nb s) (Na s)).

(** The weights of n k: |a_j| + |b_j| = 2 ((1 - 1/2) |a_j| + 1/2 |b_j|). *)
Lemma hk_vec : vapprox 1 (INR (n s)) kk Dl
  (vlin v d (wM (Na s) (Nb s) (1 / 2) 2 (1001 / 1000)) (wM (Na s) (Nb s) 0 0 (1001 / 1000))).
Proof.
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  destruct (unit_bounded _ Ha) as [A1 [A2 A3]].
  destruct (unit_bounded _ Hb) as [B1 [B2 B3]].
  destruct Ina as [I1 [I2 I3]]. destruct Inb as [J1 [J2 J3]].
  unfold vapprox, vlin, wM, vsub; cbn [vx vy vz]. rewrite !Rmult_1_l.
  repeat split; (eapply Rle_trans; [eapply (hk_comp v d eta); eassumption | lra]).
Qed.

Lemma hk_wb : wb16 (wM (Na s) (Nb s) (1 / 2) 2 (1001 / 1000))
  /\ wb16 (wM (Na s) (Nb s) 0 0 (1001 / 1000)).
Proof. split; apply wM_wb16; try lra; apply unit_bounded; assumption. Qed.

(** n (k.X) for a unit X read as xh: the set-ups A (X = L) and D/2 (X = Na). *)
Lemma kx_dot : forall (xh X : vec) (y : R), is_unit X -> vap1 v eta xh X ->
  fdot_rel v v eta kk xh y ->
  Rabs (INR (n s) * y - dot Dl X) <= (202 / 100 + 501 / 100 * dd) * v
                                     + (2 / 100 + 101 / 100 * dd) * d.
Proof.
  intros xh X y HX IX Hy. destruct HDd as [Hdd HD].
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  destruct hk_wb as [W1 W2].
  destruct (wb16_in _ HX) as [WX W0].
  pose proof (cs_abs _ _ dd ltac:(lra) HD (Req_le _ _ HX)) as DX.
  pose proof (unit_pair _ _ Ha HX) as AX. pose proof (unit_pair _ _ Hb HX) as BX.
  pose proof (diff_bounded _ _ Ha Hb) as [D1 [D2 D3]].
  destruct (unit_bounded _ HX) as [X1 [X2 X3]].
  pose proof (dot_w v d eta dd 16 (/ 100) (INR (n s)) 1 y (202 / 100 + 501 / 100 * dd)
    (2 / 100 + 101 / 100 * dd) kk xh Dl X _ _ _ _ Hv Hdv ltac:(lra) ltac:(lra) Hy ltac:(lra) ltac:(lra) ltac:(lra)
    hk_vec (K_in_vec v d eta Hv _ _ IX) (diff_bounded _ _ Ha Hb) (vb12 _ (unit_bounded _ HX))
    W1 W2 WX W0 DX ltac:(lra)) as HD2.
  rewrite Rmult_1_r in HD2. apply HD2.
  - unfold wsum0, wM, Float.wIn; unfold vsub in *; cbn [vx vy vz] in *. lra.
  - unfold wsum0, wM, vzero; unfold vsub in *; cbn [vx vy vz] in *. lra.
Qed.

(** n^2 (k.k): the set-up C. *)
Lemma kk_dot : forall (y : R), fdot_rel v v eta kk kk y ->
  Rabs (INR (n s) * INR (n s) * y - dot Dl Dl)
    <= (2 / 100 + 401 / 100 * dd + 501 / 100 * dd * dd) * v
       + (2 / 100 + 0 * dd + 201 / 100 * dd * dd) * d.
Proof.
  intros y Hy. destruct HDd as [Hdd HD].
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  destruct hk_wb as [W1 W2].
  pose proof (cs_abs _ _ dd ltac:(lra) HD (Req_le _ _ Ha)) as DA.
  pose proof (cs_abs _ _ dd ltac:(lra) HD (Req_le _ _ Hb)) as DB.
  assert (DD : Rabs (vx Dl) * Rabs (vx Dl) + Rabs (vy Dl) * Rabs (vy Dl)
               + Rabs (vz Dl) * Rabs (vz Dl) <= dd * dd).
  { rewrite !abs_sq. exact HD. }
  pose proof (diff_bounded _ _ Ha Hb) as [D1 [D2 D3]].
  assert (dd * dd <= 4) by nra.
  assert (0 <= dd * dd) by nra.
  pose proof (dot_w v d eta (dd * dd) 16 (/ 100) (INR (n s)) (INR (n s)) y
    (2 / 100 + 401 / 100 * dd + 501 / 100 * dd * dd) (2 / 100 + 0 * dd + 201 / 100 * dd * dd)
    kk kk Dl Dl _ _ _ _ Hv Hdv ltac:(lra) ltac:(lra) Hy ltac:(lra) ltac:(lra) ltac:(nra)
    hk_vec hk_vec (diff_bounded _ _ Ha Hb) (diff_bounded _ _ Ha Hb)
    W1 W2 W1 W2 DD ltac:(lra)) as HD2.
  apply HD2.
  - unfold wsum0, wM; unfold vsub in *; cbn [vx vy vz] in *. lra.
  - unfold wsum0, wM; unfold vsub in *; cbn [vx vy vz] in *. lra.
Qed.

(** The pixel's ranges: n <> 0, 1 <= n <= 2^24, 0 <= i <= n, 0 <= i/n <= 1. *)
Lemma hk_pix : forall i : nat, (i <= n s)%nat ->
  (n s <> 0)%nat /\ 1 <= INR (n s) <= 16777216 /\ 0 <= INR i <= INR (n s)
  /\ 0 <= INR i / INR (n s) <= 1.
Proof.
  intros i Hi.
  assert (Hm : 1 <= INR (n s) <= 16777216) by (split; [apply (le_INR 1); exact Hn1 | exact Hn2]).
  assert (Hii : 0 <= INR i <= INR (n s)) by (split; [apply pos_INR | apply le_INR; exact Hi]).
  repeat split; try lia; try lra; apply theta_rng; lra.
Qed.

(** The two dot products of a computed normal nh within the mixture weights
    (c1, c2 for v; 1.001 for d) of N(i/n): [pd_tail] at p(i), q(i), left: the
    components of nh, with the sizes of the inputs. *)
Local Ltac nrm_pre l nh i Hi :=
  destruct (hk_pix i Hi) as (Hn0 & Hm & Hii & Ht); pose proof HDd as [[Hdd _] HD];
  destruct (unit_bounded _ Ha) as [A1 [A2 A3]];
  destruct (unit_bounded _ Hb) as [B1 [B2 B3]];
  pose proof Ina as [Ia1 [Ia2 Ia3]]; pose proof Inb as [Ib1 [Ib2 Ib3]];
  rewrite pp_p_form, pp_q_form by exact Hn0;
  eapply (pd_tail v d eta s nh l); try eassumption; try lra;
  unfold vapprox, vlin, wM, nrm, vadd, vscale, vsub; cbn [vx vy vz]; rewrite !Rmult_1_l.

(** The per-pixel normal, the lerp and Horner's closed form on the section's
    set-up. *)
Lemma pd_core : forall (l nh : vec) (i : nat) (zx zy zz ph qh : R),
  is_unit (L s) -> (i <= n s)%nat -> vap1 v eta l (L s) ->
  ap1 v eta zx (INR i * vx kk) -> ap1 v eta (vx nh) (vx na + zx) ->
  ap1 v eta zy (INR i * vy kk) -> ap1 v eta (vy nh) (vy na + zy) ->
  ap1 v eta zz (INR i * vz kk) -> ap1 v eta (vz nh) (vz na + zz) ->
  fdot_rel v v eta nh l ph -> fdot_rel v v eta nh nh qh ->
  Rabs (ph - p s (INR i)) <= (2 + 2001 / 1000 * dd + 402 / 100) * v
                             + (1001 / 1000 * dd + 2 / 100) * d /\
  Rabs (qh - q s (INR i)) <= (2 * 2 + 2 * (2001 / 1000) * dd + 302 / 100) * v
                             + (2 * (1001 / 1000) * dd + 2 / 100) * d.
Proof.
  intros l nh i zx zy zz ph qh Hl Hi Inl Hzx Hnx Hzy Hny Hzz Hnz Hp Hq.
  nrm_pre l nh i Hi. repeat split; eapply pd_comp; eassumption.
Qed.

Lemma ld_core : forall (l nh : vec) (i : nat) (th wx wy wz ax ay az bx by_ bz ph qh : R),
  is_unit (L s) -> (i <= n s)%nat -> vap1 v eta l (L s) ->
  ap1 d eta th (INR i / INR (n s)) ->
  fdot_rel v v eta nh l ph -> fdot_rel v v eta nh nh qh ->
  ap1 v eta (vx nh) (ax + bx) -> ap1 v eta bx (th * vx nb) -> ap1 v eta ax (wx * vx na) ->
  ap1 v eta wx (1 - th) ->
  ap1 v eta (vy nh) (ay + by_) -> ap1 v eta by_ (th * vy nb) -> ap1 v eta ay (wy * vy na) ->
  ap1 v eta wy (1 - th) ->
  ap1 v eta (vz nh) (az + bz) -> ap1 v eta bz (th * vz nb) -> ap1 v eta az (wz * vz na) ->
  ap1 v eta wz (1 - th) ->
  Rabs (ph - p s (INR i)) <= (4 + 0 * dd + 402 / 100) * v + (1001 / 1000 * dd + 2 / 100) * d /\
  Rabs (qh - q s (INR i)) <= (2 * 4 + 2 * 0 * dd + 302 / 100) * v
                             + (2 * (1001 / 1000) * dd + 2 / 100) * d.
Proof.
  intros l nh i th wx wy wz ax ay az bx by_ bz ph qh Hl Hi Inl Hth Hp Hq
    Hnx Hbx Hax Hwx Hny Hby Hay Hwy Hnz Hbz Haz Hwz.
  nrm_pre l nh i Hi. repeat split; eapply ld_comp; eassumption.
Qed.

(** Horner's p^ and q^ ([hp_abs_d], [hq_abs_d]) with |D.L|, |D.Na| <= da and |D.D| <= c2. *)
Local Ltac horner_fin da c2 :=
  split;
  [ rewrite hc_p_form by lia; eapply Rle_trans;
    [ eapply hp_abs_d with (v := v) (m := INR (n s)) (Da := da); try eassumption; try lra;
      apply hc_p_le1; assumption
    | lra ]
  | rewrite hc_q_form by lia; eapply Rle_trans;
    [ eapply hq_abs_d with (v := v) (m := INR (n s)) (C2 := c2) (D1 := da); try eassumption;
      try lra; apply hc_q_le1; assumption
    | lra ] ].

Lemma horner_core_d : forall (l : vec) (fa fb fc e fe : R) (i : nat) (x ph y1 y2 y3 qh : R),
  is_unit (L s) -> (i <= n s)%nat -> vap1 v eta l (L s) ->
  fdot_rel v v eta kk l fa -> fdot_rel v v eta na l fb -> fdot_rel v v eta kk kk fc ->
  fdot_rel v v eta kk na e -> fdot_rel v v eta na na fe ->
  ap1 v eta x (fa * INR i) -> ap1 v eta ph (x + fb) ->
  ap1 v eta y1 (fc * INR i) -> ap1 v eta y2 (y1 + 2 * e) -> ap1 v eta y3 (y2 * INR i) ->
  ap1 v eta qh (y3 + fe) ->
  Rabs (ph - p s (INR i)) <= (804 / 100 + 601 / 100 * dd) * v + (3 / 100 + 101 / 100 * dd) * d /\
  Rabs (qh - q s (INR i)) <= (1013 / 100 + 1803 / 100 * dd + 801 / 100 * dd * dd) * v
                             + (7 / 100 + 202 / 100 * dd + 201 / 100 * dd * dd) * d.
Proof.
  intros l fa fb fc e fe i x ph y1 y2 y3 qh Hl Hi Inl Hfa Hfb Hfc Hfe0 Hfe Hx Hph Hy1 Hy2 Hy3 Hqh.
  v_facts Hv. v_facts Hdv.
  pose proof HDd as [Hdd HD]. destruct (hk_pix i Hi) as (Hn0 & Hm & Hii & Ht).
  pose proof (kx_dot l (L s) fa Hl Inl Hfa) as CA.
  pose proof (K_pa v d eta Hv Hdv s Ha Hb Hl na l fb Ina Inl Hfb) as CB.
  pose proof (kk_dot fc Hfc) as CC.
  pose proof (kx_dot na (Na s) e Ha Ina Hfe0) as CD.
  pose proof (K_pa v d eta Hv Hdv (mkSpan (Na s) (Nb s) (Na s) (n s)) Ha Hb Ha na na fe
                Ina Ina Hfe) as CE.
  unfold pa in CE; cbn [Na Nb L] in CE.
  assert (VD : v * dd <= v * 2) by (apply Rmult_le_compat_l; lra).
  assert (DD : d * dd <= d * 2) by (apply Rmult_le_compat_l; lra).
  assert (V0 : 0 <= v * dd) by (apply Rmult_le_pos; lra).
  assert (D0 : 0 <= d * dd) by (apply Rmult_le_pos; lra).
  assert (Q0 : 0 <= dd * dd <= 4) by (split; nra).
  assert (VDD : v * (dd * dd) <= v * 4) by (apply Rmult_le_compat_l; lra).
  assert (DDD : d * (dd * dd) <= d * 4) by (apply Rmult_le_compat_l; lra).
  assert (V1 : 0 <= v * (dd * dd)) by (apply Rmult_le_pos; lra).
  assert (D1 : 0 <= d * (dd * dd)) by (apply Rmult_le_pos; lra).
  assert (SL : Rabs (dot (vsub (Nb s) (Na s)) (L s)) <= dd)
    by (eapply Rle_trans; [apply dot_abs | apply cs_abs; [lra | exact HD | right; exact Hl]]).
  assert (SA : Rabs (dot (vsub (Nb s) (Na s)) (Na s)) <= dd)
    by (eapply Rle_trans; [apply dot_abs | apply cs_abs; [lra | exact HD | right; exact Ha]]).
  assert (SC : Rabs (dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s))) <= dd * dd)
    by (rewrite Rabs_pos_eq; [exact HD | apply dot_sq0]).
  horner_fin dd (dd * dd).
Qed.

(** Horner's closed form with the dd-free set-up errors of Profiles.v (K_a,
    K_pa, K_c, K_d0): the bounds of PhongCount.v. *)
Lemma horner_core : forall (l : vec) (fa fb fc e fe : R) (i : nat) (x ph y1 y2 y3 qh : R),
  is_unit (L s) -> (i <= n s)%nat -> vap1 v eta l (L s) ->
  fdot_rel v v eta kk l fa -> fdot_rel v v eta na l fb -> fdot_rel v v eta kk kk fc ->
  fdot_rel v v eta kk na e -> fdot_rel v v eta na na fe ->
  ap1 v eta x (fa * INR i) -> ap1 v eta ph (x + fb) ->
  ap1 v eta y1 (fc * INR i) -> ap1 v eta y2 (y1 + 2 * e) -> ap1 v eta y3 (y2 * INR i) ->
  ap1 v eta qh (y3 + fe) ->
  Rabs (ph - p s (INR i)) <= 2003 / 100 * v + 202 / 100 * d /\
  Rabs (qh - q s (INR i)) <= 7811 / 100 * v + 1204 / 100 * d.
Proof.
  intros l fa fb fc e fe i x ph y1 y2 y3 qh Hl Hi Inl Hfa Hfb Hfc Hfe0 Hfe Hx Hph Hy1 Hy2 Hy3 Hqh.
  v_facts Hv. v_facts Hdv. destruct (hk_pix i Hi) as (_ & Hm & Hii & Ht).
  destruct (hc_sizes s Ha Hb Hl) as [Sa [Sd Sc]].
  pose proof (K_a v d eta Hv Hdv s Ha Hb Hl Hn1 Hn2 na nb l kk fa Ina Inb Inl
                tx ty tz Htx Hkx Hty Hky Htz Hkz Hfa) as CA.
  pose proof (K_pa v d eta Hv Hdv s Ha Hb Hl na l fb Ina Inl Hfb) as CB.
  pose proof (K_c v d eta Hv Hdv s Ha Hb Hl Hn1 Hn2 na nb kk fc Ina Inb
                tx ty tz Htx Hkx Hty Hky Htz Hkz Hfc) as CC.
  pose proof (K_d0 v d eta Hv Hdv s Ha Hb Hl Hn1 Hn2 na nb kk Ina Inb
                tx ty tz Htx Hkx Hty Hky Htz Hkz e Hfe0) as CD.
  pose proof (K_pa v d eta Hv Hdv (mkSpan (Na s) (Nb s) (Na s) (n s)) Ha Hb Ha na na fe
                Ina Ina Hfe) as CE.
  unfold pa in CE; cbn [Na Nb L] in CE.
  horner_fin 2 4.
Qed.

End HK.

(** ** With the model's operations *)

(** A core's bound A v + B d at v = K1 u, d = kd u within (a K1 + b kd) u. *)
Lemma lin_le : forall u K1 kd A B a b, 0 <= u -> 0 <= K1 -> 0 <= kd -> A <= a -> B <= b ->
  A * (K1 * u) + B * (kd * u) <= (a * K1 + b * kd) * u.
Proof.
  intros u K1 kd A B a b Hu HK Hk Ha Hb.
  assert (0 <= (a - A) * K1 * u) by (repeat apply Rmult_le_pos; lra).
  assert (0 <= (b - B) * kd * u) by (repeat apply Rmult_le_pos; lra). lra.
Qed.

(** Every input, addition, product and dot product of the model within unit
    K1 u ([hm_vap], [hm_ap], [hm_fdot]). *)
Ltac hm_lift M K1 :=
  let Hu := fresh "Hu" in
  assert (Hu : 0 < m_u M) by (eapply model_u; eassumption);
  repeat match goal with
  | Hk : k_in M <= K1, H : vap M _ _ |- _ => apply (hm_vap M K1 _ _ Hu Hk) in H
  | Hk : k_add M <= K1, H : ap_add M _ _ |- _ => apply (hm_ap M _ K1 _ _ Hu Hk) in H
  | Hk : k_mul M <= K1, H : ap_mul M _ _ |- _ => apply (hm_ap M _ K1 _ _ Hu Hk) in H
  | Ha : k_add M <= K1, Hm : k_mul M <= K1, H : fdot_ok M _ _ _ |- _ =>
      apply (hm_fdot M K1 _ _ _ Hu Ha Hm) in H
  end.

Lemma conj_le : forall a b x y x' y' : R,
  a <= x' /\ b <= y' -> x' <= x -> y' <= y -> a <= x /\ b <= y.
Proof. intros a b x y x' y' [H1 H2] H3 H4. split; lra. Qed.

Lemma div_setup : forall (M : fmodel) (K : R), model_ok M K -> k_div M * m_u M <= / 2097152.
Proof.
  intros M K HM. pose proof HM as (_ & _ & _ & _ & _ & _ & [_ Hdk] & _ & H9).
  assert (k_div M * m_u M <= K * m_u M)
    by (apply Rmult_le_compat_r; [left; apply (model_u M K HM) | exact Hdk]). lra.
Qed.

(** The reciprocal's unit kd = (1 + 2^-20) k_mul + k_div + 2^-36 as in PhongCount.v. *)
Lemma recip_setup : forall (M : fmodel) (K : R), model_ok M K ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  1 <= k_div M ->
  (forall (m x r y : R), 1 <= m <= 16777216 -> ap_div M r (1 / m) -> ap_mul M y (x * r) ->
     ap1 (((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M) (m_eta M) y (x / m)) /\
  1 <= (1 + / 1048576) * k_mul M + k_div M + / 68719476736.
Proof.
  intros M K HM Hkd Hdiv.
  pose proof HM as (U1 & U2 & U3 & _ & _ & [Km0 _] & [Kd0 Kd1] & K8 & K9).
  assert (Hu : 0 < m_u M <= / 2097152).
  { split; [exact U1|]. assert (m_u M <= K * m_u M) by (rewrite <- (Rmult_1_l (m_u M)) at 1;
      apply Rmult_le_compat_r; lra). lra. }
  pose proof (div_setup M K HM) as Hdu.
  split.
  - intros m x r y Hm Hr Hy. apply (recip_ap1 _ _ (k_div M) (k_mul M) _ _ r); assumption.
  - pose proof (Rmult_le_pos (1 + / 1048576) (k_mul M)); lra.
Qed.

(** A theorem from its [core] on units v = K1 u, d = kd u, its k_j (or t) by
    [kcomp_ok] (one division, kd = k_div) or [krecip_ok] (reciprocal then
    product, kd from [recip_setup]): the relations taken apart, the operations
    lifted to unit K1 u ([hm_lift]), the bounds of [core] within the theorem's. *)
Ltac kd_model core :=
  intros;
  match goal with HM : model_ok ?M ?K |- _ =>
    pose proof (div_setup M K HM); pose proof (model_u M K HM) end;
  try match goal with H : 0 <= ?dd <= 2, H2 : dot (vsub (Nb ?s) (Na ?s)) _ <= ?dd * ?dd |- _ =>
    assert (Ddist s dd) by (split; assumption) end;
  unfold horner_ok, pixel_ok, ncomp_ok, lerp_ok, lcomp_ok, kcomp_ok, krecip_ok in *;
  repeat match goal with
  | H : exists _, _ |- _ => destruct H
  | H : _ /\ _ |- _ => destruct H
  end;
  try match goal with
  | HM : model_ok ?M ?K, Hdiv : 1 <= k_div ?M,
    Hkd : ((1 + / 1048576) * k_mul ?M + k_div ?M + / 68719476736) * m_u ?M <= / 2097152 |- _ =>
      let R := fresh "R" in destruct (recip_setup M K HM Hkd Hdiv) as [R ?];
      repeat match goal with Hr : ap_div M ?r (1 / ?m), Hy : ap_mul M ?y (?x * ?r) |- _ =>
        apply (R m x r y ltac:(split; [apply (le_INR 1) |]; assumption) Hr) in Hy end
  end;
  let fin K1 kd :=
    match goal with HM : model_ok ?M ?K |- _ =>
      pose proof (hm_small M K K1 HM ltac:(split; assumption));
      pose proof (hm_small_d M K kd HM ltac:(assumption) ltac:(assumption));
      assert (0 <= k_add M * m_u M <= K1 * m_u M)
        by (pose proof HM as (_ & _ & _ & _ & [? _] & _); split;
            [apply Rmult_le_pos | apply Rmult_le_compat_r]; lra);
      hm_lift M K1;
      eapply conj_le; [eapply (core (K1 * m_u M) (kd * m_u M) (m_eta M)); eassumption | |];
      first [right; ring | apply lin_le; lra]
    end in
  match goal with
  | |- _ <= (_ * ?K1 + _ * ?kd) * _ /\ _ => fin K1 kd
  | |- _ <= (_ * ?K1 + _ * ?kd + _) * _ /\ _ => fin K1 kd
  end.

(** Phong, per-pixel normal, one division, with the span's distance dd >= |Nb - Na|. *)
Theorem phong_pixel_div_dist : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh dd : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  0 <= dd <= 2 -> dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  kcomp_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  kcomp_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  kcomp_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  pixel_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= ((602 / 100 + 201 / 100 * dd) * K1
                              + (2 / 100 + 101 / 100 * dd) * k_div M) * m_u M /\
  Rabs (qh - q s (INR i)) <= ((702 / 100 + 401 / 100 * dd + 0 * dd * dd) * K1
                              + (2 / 100 + 201 / 100 * dd + 0 * dd * dd) * k_div M) * m_u M.
Proof. kd_model pd_core. Qed.

(** The same with k_j = (Nb_j - Na_j) * r, r = 1/n a rounded division. *)
Theorem phong_pixel_recip_dist : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh dd : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  0 <= dd <= 2 -> dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  krecip_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  krecip_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  krecip_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  pixel_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= ((602 / 100 + 201 / 100 * dd) * K1
      + (2 / 100 + 101 / 100 * dd) * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736))
      * m_u M /\
  Rabs (qh - q s (INR i)) <= ((702 / 100 + 401 / 100 * dd + 0 * dd * dd) * K1
      + (2 / 100 + 201 / 100 * dd + 0 * dd * dd)
        * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M.
Proof. kd_model pd_core. Qed.

(** Phong, lerp, t = i/n one rounded division, with the span's distance. *)
Theorem phong_lerp_div_dist : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l : vec) (i : nat) (th ph qh dd : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  0 <= dd <= 2 -> dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  ap_div M th (INR i / INR (n s)) ->
  lerp_ok M th na nb l ph qh ->
  Rabs (ph - p s (INR i)) <= ((802 / 100 + 0 * dd) * K1
                              + (2 / 100 + 101 / 100 * dd) * k_div M) * m_u M /\
  Rabs (qh - q s (INR i)) <= ((1102 / 100 + 0 * dd + 0 * dd * dd) * K1
                              + (2 / 100 + 201 / 100 * dd + 0 * dd * dd) * k_div M) * m_u M.
Proof. kd_model ld_core. Qed.

(** The same with t = i * r, r = 1/n a rounded division. *)
Theorem phong_lerp_recip_dist : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l : vec) (i : nat) (r th ph qh dd : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  0 <= dd <= 2 -> dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  ap_div M r (1 / INR (n s)) -> ap_mul M th (INR i * r) ->
  lerp_ok M th na nb l ph qh ->
  Rabs (ph - p s (INR i)) <= ((802 / 100 + 0 * dd) * K1
      + (2 / 100 + 101 / 100 * dd) * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736))
      * m_u M /\
  Rabs (qh - q s (INR i)) <= ((1102 / 100 + 0 * dd + 0 * dd * dd) * K1
      + (2 / 100 + 201 / 100 * dd + 0 * dd * dd)
        * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M.
Proof. kd_model ld_core. Qed.

(** Phong, Horner's closed form, one division, with the span's distance dd >= |Nb - Na|. *)
Theorem phong_horner_div_dist : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh dd : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  0 <= dd <= 2 -> dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  kcomp_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  kcomp_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  kcomp_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  horner_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= ((804 / 100 + 601 / 100 * dd) * K1
                              + (3 / 100 + 101 / 100 * dd) * k_div M) * m_u M /\
  Rabs (qh - q s (INR i)) <= ((1013 / 100 + 1803 / 100 * dd + 801 / 100 * dd * dd) * K1
                              + (7 / 100 + 202 / 100 * dd + 201 / 100 * dd * dd) * k_div M)
                             * m_u M.
Proof. kd_model horner_core_d. Qed.

(** The same with k_j = (Nb_j - Na_j) * r, r = 1/n a rounded division. *)
Theorem phong_horner_recip_dist : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh dd : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  0 <= dd <= 2 -> dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  krecip_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  krecip_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  krecip_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  horner_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= ((804 / 100 + 601 / 100 * dd) * K1
      + (3 / 100 + 101 / 100 * dd) * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736))
      * m_u M /\
  Rabs (qh - q s (INR i)) <= ((1013 / 100 + 1803 / 100 * dd + 801 / 100 * dd * dd) * K1
      + (7 / 100 + 202 / 100 * dd + 201 / 100 * dd * dd)
        * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M.
Proof. kd_model horner_core_d. Qed.
