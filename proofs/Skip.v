(** * Skip.v — a scan-line test that no pixel of a span reaches specular level 1.

    The quantiser maps x to level floor(255 x), so a pixel is at level 0 exactly
    when 255 x < 1. Before shading a span's specular term Ks·max(0, x)^s
    (Ks ≥ 0, s ≥ 1 a natural number), the renderer may decide that every pixel
    of the span is at level 0 and skip the term. This file proves that decision
    sound for two kinds of base value x along the span, t ∈ [0, n]:

    - Phong's, f(t) = p(t)/√q(t), p(t) = B + A t, q(t) = E + D t + C t²
      (q > 0 on [0, n]). f'(t) = L(t)/q(t)^(3/2) with the affine
      L(t) = (A E − B D/2) + t (A D/2 − B C), so the largest f on [0, n] is at
      0, at n or at the root t* of L when it lies inside. The decision tests
      these candidates by the square-root-free inequality
      (255 Ks)² p^(2s) < q^s, or p ≤ 0 (theorems [phong_skip_sound],
      [phong_skip_levels]).
    - The quadratic recurrences, v(t) = p_a + t s0 + t (t − 1)/2 · ds: corrected
      Euler (eq. 17, s0 = t0), Euler (s0 = di_a) and Gouraud (ds = 0). For
      ds < 0 the largest v is at the vertex t_v = 1/2 − s0/ds, otherwise at an
      end (theorems [quadratic_skip_sound], [quadratic_skip_levels]).

    The Rust decision (src/skip.rs) evaluates exactly these candidate
    inequalities ([ok], [okv] at the candidates of [skip_phong],
    [skip_quadratic]) in exact rationals. *)

From Coq Require Import Reals Lra Lia Psatz.
From Coquelicot Require Import Coquelicot.
Open Scope R_scope.

(** ** Phong *)

Definition p (A B t : R) : R := B + A * t.
Definition q (C D E t : R) : R := E + D * t + C * t ^ 2.
Definition f (A B C D E t : R) : R := p A B t / sqrt (q C D E t).

(** The numerator of f' = L / q^(3/2): A·q − p·q'/2. *)
Definition L (A B C D E t : R) : R := (A * E - B * D / 2) + t * (A * D / 2 - B * C).

(** The root of L (meaningful when A·D/2 − B·C ≠ 0). *)
Definition tstar (A B C D E : R) : R := - (A * E - B * D / 2) / (A * D / 2 - B * C).

(** One candidate x passes when no positive specular base can reach level 1
    there: p(x) ≤ 0, or 255·Ks·(p/√q)^s < 1 squared, without the root. *)
Definition ok (A B C D E Ks : R) (s : nat) (x : R) : Prop :=
  p A B x <= 0 \/ (255 * Ks) ^ 2 * p A B x ^ (2 * s) < q C D E x ^ s.

(** The decision: both ends, and t* when L has a root strictly inside (the
    implication reads: if A·D/2 − B·C ≠ 0 and 0 < t* < n then ok t*, else
    True). *)
Definition skip_phong (A B C D E n Ks : R) (s : nat) : Prop :=
  ok A B C D E Ks s 0 /\ ok A B C D E Ks s n /\
  (A * D / 2 - B * C <> 0 /\ 0 < tstar A B C D E < n -> ok A B C D E Ks s (tstar A B C D E)).

Lemma f_derive A B C D E x :
  0 < q C D E x ->
  derivable_pt_lim (f A B C D E) x (L A B C D E x / (q C D E x * sqrt (q C D E x))).
Proof.
  intros Hq. apply is_derive_Reals. unfold f, p, q in *.
  assert (Hr : sqrt (E + D * x + C * x ^ 2) * sqrt (E + D * x + C * x ^ 2)
               = E + D * x + C * x ^ 2) by (apply sqrt_sqrt; lra).
  assert (Hpos : 0 < sqrt (E + D * x + C * x ^ 2)) by (apply sqrt_lt_R0; lra).
  auto_derive.
  - replace (x * (x * 1)) with (x ^ 2) by ring. split; [lra | split; [lra | exact I]].
  - replace (x * (x * 1)) with (x ^ 2) by ring.
    set (r := sqrt (E + D * x + C * x ^ 2)) in *. clearbody r.
    rewrite <- Hr.
    replace (L A B C D E x) with (A * (r * r) - (B + A * x) * (D + 2 * C * x) / 2)
      by (rewrite Hr; unfold L; field).
    field. lra.
Qed.

(** The mean value theorem for f on [a, b]: f b − f a = (b − a)·f'(c), with f'(c)'s
    denominator q(c)·√q(c) positive. *)
Lemma f_mvt A B C D E a b :
  a < b -> (forall x, a <= x <= b -> 0 < q C D E x) ->
  exists c, a <= c <= b /\ 0 < q C D E c * sqrt (q C D E c) /\
    f A B C D E b - f A B C D E a =
      L A B C D E c / (q C D E c * sqrt (q C D E c)) * (b - a).
Proof.
  intros Hab Hq.
  destruct (MVT_cor2 (f A B C D E)
              (fun x => L A B C D E x / (q C D E x * sqrt (q C D E x))) a b)
    as [c [Hc Hc']]; [lra | intros c Hc; apply f_derive, Hq; lra |].
  assert (Hqc : 0 < q C D E c) by (apply Hq; lra).
  assert (Hs : 0 < sqrt (q C D E c)) by (apply sqrt_lt_R0; lra).
  exists c; repeat split; try lra; nra.
Qed.

(** f is nondecreasing where L ≥ 0 and nonincreasing where L ≤ 0 (the sign of f' is
    the sign of L since q > 0). *)
Lemma f_up A B C D E a b :
  a <= b -> (forall x, a <= x <= b -> 0 < q C D E x) ->
  (forall x, a <= x <= b -> 0 <= L A B C D E x) -> f A B C D E a <= f A B C D E b.
Proof.
  intros Hab Hq HL. destruct (Req_dec a b) as [<- | Hne]; [lra |].
  destruct (f_mvt A B C D E a b) as [c [Hc [Hd Heq]]]; [lra | exact Hq |].
  assert (0 <= L A B C D E c) by (apply HL; lra).
  assert (0 <= L A B C D E c / (q C D E c * sqrt (q C D E c)))
    by (apply Rdiv_le_0_compat; lra).
  nra.
Qed.

Lemma f_down A B C D E a b :
  a <= b -> (forall x, a <= x <= b -> 0 < q C D E x) ->
  (forall x, a <= x <= b -> L A B C D E x <= 0) -> f A B C D E b <= f A B C D E a.
Proof.
  intros Hab Hq HL. destruct (Req_dec a b) as [<- | Hne]; [lra |].
  destruct (f_mvt A B C D E a b) as [c [Hc [Hd Heq]]]; [lra | exact Hq |].
  assert (0 <= - L A B C D E c) by (enough (L A B C D E c <= 0) by lra; apply HL; lra).
  assert (0 <= - L A B C D E c / (q C D E c * sqrt (q C D E c)))
    by (apply Rdiv_le_0_compat; lra).
  unfold Rdiv in *. nra.
Qed.

(** With A·D/2 − B·C ≠ 0, L(x) = (A·D/2 − B·C)·(x − tstar). *)
Lemma L_root A B C D E x :
  A * D / 2 - B * C <> 0 ->
  L A B C D E x = (A * D / 2 - B * C) * (x - tstar A B C D E).
Proof. intros Hm. unfold L, tstar. field. intros H. apply Hm. lra. Qed.

(** Every f(t), t ∈ [0, n], is at most f at 0, at n or at the root t* of L
    strictly inside (where A·D/2 − B·C ≠ 0). *)
Lemma f_cands A B C D E n t :
  (forall x, 0 <= x <= n -> 0 < q C D E x) -> 0 <= t <= n ->
  f A B C D E t <= f A B C D E 0 \/ f A B C D E t <= f A B C D E n \/
  (A * D / 2 - B * C <> 0 /\ 0 < tstar A B C D E < n /\
   f A B C D E t <= f A B C D E (tstar A B C D E)).
Proof.
  intros Hq Ht.
  assert (Hsub : forall a b, 0 <= a -> b <= n -> forall x, a <= x <= b -> 0 < q C D E x)
    by (intros a b Ha Hb x Hx; apply Hq; lra).
  (* the ends, by the monotonicity on [t, n] or on [0, t] *)
  assert (Up : (forall x, t <= x <= n -> 0 <= L A B C D E x) ->
               f A B C D E t <= f A B C D E n)
    by (intros HL; apply f_up; [lra | apply Hsub; lra | exact HL]).
  assert (Down : (forall x, 0 <= x <= t -> L A B C D E x <= 0) ->
                 f A B C D E t <= f A B C D E 0)
    by (intros HL; apply f_down; [lra | apply Hsub; lra | exact HL]).
  set (m := A * D / 2 - B * C) in *.
  destruct (Req_dec m 0) as [Hm | Hm].
  - (* L is constant *)
    assert (HLc : forall x, L A B C D E x = A * E - B * D / 2)
      by (intros x; unfold L; fold m; rewrite Hm; ring).
    destruct (Rle_dec 0 (A * E - B * D / 2)) as [Hc | Hc].
    + right; left. apply Up. intros x _. rewrite HLc. exact Hc.
    + left. apply Down. intros x _. rewrite HLc. lra.
  - set (ts := tstar A B C D E) in *.
    assert (HL : forall x, L A B C D E x = m * (x - ts)) by (intros x; apply L_root, Hm).
    destruct (Rlt_dec 0 m) as [Hmp | Hmn].
    + (* L < 0 before t*, > 0 after: f has no interior maximum *)
      destruct (Rle_dec ts t) as [Hts | Hts].
      * right; left. apply Up. intros x Hx. rewrite HL. nra.
      * left. apply Down. intros x Hx. rewrite HL. nra.
    + destruct (Rle_dec ts 0) as [Hts0 | Hts0].
      { left. apply Down. intros x Hx. rewrite HL. nra. }
      destruct (Rle_dec n ts) as [Htsn | Htsn].
      { right; left. apply Up. intros x Hx. rewrite HL. nra. }
      (* L > 0 before t*, < 0 after: f is largest at t* *)
      right; right. split; [exact Hm | split; [lra |]].
      destruct (Rle_dec t ts) as [Htt | Htt].
      * apply f_up; [lra | apply Hsub; lra |]. intros x Hx. rewrite HL. nra.
      * apply f_down; [lra | apply Hsub; lra |]. intros x Hx. rewrite HL. nra.
Qed.

(** Every f(t), t ∈ [0, n], is at most f at a candidate that the decision
    tests. *)
Lemma phong_dominated A B C D E n Ks s t :
  (forall x, 0 <= x <= n -> 0 < q C D E x) -> skip_phong A B C D E n Ks s ->
  0 <= t <= n ->
  exists c, 0 <= c <= n /\ ok A B C D E Ks s c /\ f A B C D E t <= f A B C D E c.
Proof.
  intros Hq [H0 [Hn Hs]] Ht.
  destruct (f_cands A B C D E n t Hq Ht) as [H | [H | (Hm & Hts & H)]].
  - exists 0. split; [lra | split; [exact H0 | exact H]].
  - exists n. split; [lra | split; [exact Hn | exact H]].
  - exists (tstar A B C D E). split; [lra | split; [apply Hs; split; assumption | exact H]].
Qed.

(** At a candidate c that passes, every positive y ≤ f(c) has 255·Ks·y^s < 1:
    for p(c) > 0 both 255·Ks·p^s and √q^s are nonnegative, so the squared
    inequality gives 255·Ks·p^s < √q^s. *)
Lemma ok_bound A B C D E Ks s c y :
  0 <= Ks -> 0 < q C D E c -> ok A B C D E Ks s c ->
  0 < y <= f A B C D E c -> 255 * Ks * y ^ s < 1.
Proof.
  intros HK Hq Hok Hy. unfold f in Hy.
  set (P := p A B c) in *. set (Q := q C D E c) in *.
  assert (Hr : sqrt Q * sqrt Q = Q) by (apply sqrt_sqrt; lra).
  assert (Hpos : 0 < sqrt Q) by (apply sqrt_lt_R0; lra).
  set (r := sqrt Q) in *. clearbody r.
  assert (Hi : 0 < / r) by (apply Rinv_0_lt_compat; lra).
  assert (HP : 0 < P).
  { destruct (Rle_dec P 0) as [HP | HP]; [| lra].
    exfalso. unfold Rdiv in Hy. nra. }
  destruct Hok as [Hok | Hok]; [fold P in Hok; lra |]. fold P Q in Hok.
  assert (Hrs : 0 < r ^ s) by (apply pow_lt; lra).
  assert (HPs : 0 <= P ^ s) by (apply pow_le; lra).
  assert (Hsq : (255 * Ks * P ^ s) ^ 2 < (r ^ s) ^ 2).
  { assert (E1 : (255 * Ks * P ^ s) ^ 2 = (255 * Ks) ^ 2 * P ^ (2 * s))
      by (rewrite Rpow_mult_distr, <- pow_mult, Nat.mul_comm; reflexivity).
    assert (E2 : (r ^ s) ^ 2 = Q ^ s)
      by (rewrite <- pow_mult, Nat.mul_comm, pow_mult, <- Hr; f_equal; ring).
    rewrite E1, E2. exact Hok. }
  assert (Hlt : 255 * Ks * P ^ s < r ^ s) by nra.
  assert (Hys : y ^ s <= (P / r) ^ s) by (apply pow_incr; lra).
  unfold Rdiv in Hys. rewrite Rpow_mult_distr, pow_inv in Hys.
  assert (Hi' : 0 < / r ^ s) by (apply Rinv_0_lt_compat; lra).
  assert (255 * Ks * y ^ s <= 255 * Ks * (P ^ s * / r ^ s))
    by (apply Rmult_le_compat_l; lra).
  assert (255 * Ks * (P ^ s * / r ^ s) < 1); [| lra].
  replace (255 * Ks * (P ^ s * / r ^ s)) with ((255 * Ks * P ^ s) * / r ^ s) by ring.
  apply (Rmult_lt_reg_r (r ^ s)); [lra |].
  rewrite Rmult_assoc, Rinv_l, Rmult_1_r, Rmult_1_l; lra.
Qed.

Theorem phong_skip_sound : forall A B C D E n Ks s,
  0 <= n -> 0 <= Ks -> (1 <= s)%nat ->
  (forall t, 0 <= t <= n -> 0 < q C D E t) ->
  skip_phong A B C D E n Ks s ->
  forall t, 0 <= t <= n -> 255 * Ks * Rmax 0 (p A B t / sqrt (q C D E t)) ^ s < 1.
Proof.
  intros A B C D E n Ks s Hn HK Hs Hq Hskip t Ht. fold (f A B C D E t).
  destruct (Rle_dec (f A B C D E t) 0) as [Hf | Hf].
  - rewrite Rmax_left by lra. rewrite pow_i by lia. lra.
  - rewrite Rmax_right by lra.
    destruct (phong_dominated A B C D E n Ks s t Hq Hskip Ht) as [c [Hc [Hok Hle]]].
    apply (ok_bound A B C D E Ks s c); [exact HK | apply Hq, Hc | exact Hok | lra].
Qed.

Theorem phong_skip_levels : forall A B C D E n Ks s,
  0 <= n -> 0 <= Ks -> (1 <= s)%nat ->
  (forall t, 0 <= t <= n -> 0 < q C D E t) ->
  skip_phong A B C D E n Ks s ->
  forall i : nat, INR i <= n ->
  255 * Ks * Rmax 0 (p A B (INR i) / sqrt (q C D E (INR i))) ^ s < 1.
Proof.
  intros. apply (phong_skip_sound A B C D E n); auto. split; [apply pos_INR | auto].
Qed.

(** ** Quadratic recurrences *)

(** Eq. 17's closed form at real t: s0 = t0 for corrected Euler, di_a for
    Euler; Gouraud is ds = 0 with s0 = dp. *)
Definition v (pa s0 ds t : R) : R := pa + t * s0 + t * (t - 1) / 2 * ds.

(** The vertex of v (its maximum when ds < 0). *)
Definition tv (s0 ds : R) : R := / 2 - s0 / ds.

Definition okv (pa s0 ds Ks : R) (s : nat) (x : R) : Prop :=
  v pa s0 ds x <= 0 \/ 255 * Ks * v pa s0 ds x ^ s < 1.

Definition skip_quadratic (pa s0 ds n Ks : R) (s : nat) : Prop :=
  okv pa s0 ds Ks s 0 /\ okv pa s0 ds Ks s n /\
  (ds < 0 /\ 0 < tv s0 ds < n -> okv pa s0 ds Ks s (tv s0 ds)).

(** Every v(t), t ∈ [0, n], is at most v at 0, at n or, for ds < 0, at the
    vertex t_v strictly inside: for ds < 0, v(t) = v(t_v) + ds/2·(t − t_v)²,
    v(t) − v(0) = ds/2·t·(t − 2 t_v) and v(t) − v(n) = ds/2·(t − n)·(t + n − 2 t_v);
    for ds ≥ 0, v is convex: (n − t)·v(0) + t·v(n) − n·v(t) = ds/2·n·t·(n − t) ≥ 0. *)
Lemma v_cands pa s0 ds n t :
  0 <= t <= n ->
  v pa s0 ds t <= v pa s0 ds 0 \/ v pa s0 ds t <= v pa s0 ds n \/
  (ds < 0 /\ 0 < tv s0 ds < n /\ v pa s0 ds t <= v pa s0 ds (tv s0 ds)).
Proof.
  intros Ht.
  destruct (Rlt_dec ds 0) as [Hds | Hds].
  - set (w := tv s0 ds) in *.
    assert (E0 : v pa s0 ds t - v pa s0 ds 0 = ds / 2 * t * (t - 2 * w))
      by (unfold w, tv, v; field; lra).
    assert (En : v pa s0 ds t - v pa s0 ds n = ds / 2 * (t - n) * (t + n - 2 * w))
      by (unfold w, tv, v; field; lra).
    assert (Ew : v pa s0 ds t - v pa s0 ds w = ds / 2 * (t - w) ^ 2)
      by (unfold w, tv, v; field; lra).
    destruct (Rle_dec w 0) as [Hw0 | Hw0].
    { left. assert (0 <= t * (t - 2 * w)) by nra. nra. }
    destruct (Rle_dec n w) as [Hwn | Hwn].
    { right; left. assert (0 <= (t - n) * (t + n - 2 * w)) by nra. nra. }
    right; right. split; [exact Hds | split; [lra |]].
    assert (0 <= (t - w) ^ 2) by apply pow2_ge_0.
    assert (ds / 2 * (t - w) ^ 2 <= 0) by nra. lra.
  - assert (Hc : (n - t) * v pa s0 ds 0 + t * v pa s0 ds n - n * v pa s0 ds t
                 = ds / 2 * n * t * (n - t)) by (unfold v; field).
    assert (Hpos : 0 <= ds / 2 * n * t * (n - t)).
    { assert (0 <= n * t * (n - t)) by (apply Rmult_le_pos; [apply Rmult_le_pos |]; lra).
      assert (0 <= ds / 2) by lra. nra. }
    destruct (Req_dec n 0) as [Hn0 | Hn0].
    { left. replace t with 0 by lra. lra. }
    destruct (Rle_dec (v pa s0 ds 0) (v pa s0 ds n)) as [Hle | Hle].
    + right; left. assert (n * v pa s0 ds t <= n * v pa s0 ds n) by nra.
      apply (Rmult_le_reg_l n); lra.
    + left. assert (n * v pa s0 ds t <= n * v pa s0 ds 0) by nra.
      apply (Rmult_le_reg_l n); lra.
Qed.

(** Every v(t), t ∈ [0, n], is at most v at a tested candidate. *)
Lemma quadratic_dominated pa s0 ds n Ks s t :
  skip_quadratic pa s0 ds n Ks s -> 0 <= t <= n ->
  exists c, 0 <= c <= n /\ okv pa s0 ds Ks s c /\ v pa s0 ds t <= v pa s0 ds c.
Proof.
  intros [H0 [Hn Hv]] Ht.
  destruct (v_cands pa s0 ds n t Ht) as [H | [H | (Hds & Htv & H)]].
  - exists 0. split; [lra | split; [exact H0 | exact H]].
  - exists n. split; [lra | split; [exact Hn | exact H]].
  - exists (tv s0 ds). split; [lra | split; [apply Hv; split; assumption | exact H]].
Qed.

Theorem quadratic_skip_sound : forall pa s0 ds n Ks s,
  0 <= n -> 0 <= Ks -> (1 <= s)%nat ->
  skip_quadratic pa s0 ds n Ks s ->
  forall t, 0 <= t <= n -> 255 * Ks * Rmax 0 (v pa s0 ds t) ^ s < 1.
Proof.
  intros pa s0 ds n Ks s Hn HK Hs Hskip t Ht.
  destruct (Rle_dec (v pa s0 ds t) 0) as [Hf | Hf].
  - rewrite Rmax_left by lra. rewrite pow_i by lia. lra.
  - rewrite Rmax_right by lra.
    destruct (quadratic_dominated pa s0 ds n Ks s t Hskip Ht) as [c [Hc [Hok Hle]]].
    destruct Hok as [Hok | Hok]; [lra |].
    assert (v pa s0 ds t ^ s <= v pa s0 ds c ^ s) by (apply pow_incr; lra).
    assert (255 * Ks * v pa s0 ds t ^ s <= 255 * Ks * v pa s0 ds c ^ s)
      by (apply Rmult_le_compat_l; lra).
    lra.
Qed.

Theorem quadratic_skip_levels : forall pa s0 ds n Ks s,
  0 <= n -> 0 <= Ks -> (1 <= s)%nat ->
  skip_quadratic pa s0 ds n Ks s ->
  forall i : nat, INR i <= n -> 255 * Ks * Rmax 0 (v pa s0 ds (INR i)) ^ s < 1.
Proof.
  intros. apply (quadratic_skip_sound pa s0 ds n); auto. split; [apply pos_INR | auto].
Qed.
