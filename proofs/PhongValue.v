(** * PhongValue.v — the computed value p/sqrt q of Phong under the kappa model.

    §18.4 of docs/float.md: from computed p^ (|p^ - p| <= ep) and q^
    (|q^ - q| <= eq), the value is [p^ / sqrt q^] or [p^ * (1 / sqrt q^)],
    each operation (square root, division or reciprocal, product) within its
    kappa bound [ap1 (k u) eta] of the exact result on its computed operands
    ([FloatModelK.ap1]).

    With B = ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) (sqrt qmin + sqrt (qmin - eq))),
    gamma_w = w u / (1 - w u) and eps = eta / sqrt (qmin - eq):
      [phong_value_real]   |p^/sqrt q^ - p/sqrt q| <= B                  (§18.4's first step);
      [phong_value_div]    p^ / s:          B (1 + gamma_w) + gamma_w + 2 (1 + B) eps + eta,
                           w = ks + kd;
      [phong_value_recip]  p^ * (1 / s):    B (1 + gamma_w) + gamma_w + 2 (1 + B) eps
                                            + (1 + ep) eta (1 + km u) + eta,  w = ks + kd + km;
      [phong_value_either] either form, the [phong_value_recip] bound.
    Size conditions: 2 eq <= qmin, w u <= 2^-10, 1024 eta <= sqrt (qmin - eq),
    and |p| <= 1 for the reciprocal form (|p^| <= 1 + ep multiplies the
    reciprocal's eta).  The doc's formula B (1 + gamma_3) + gamma_3 + eta has
    no eps term: the square root's eta, relative to sqrt q^ >= sqrt (qmin - eq),
    is eps, and it enters like a rounding, (w u + eps)/(1 - w u - eps) <=
    gamma_w + 2 eps ([pv_gamma]); it is that 2 (1 + B) eps, and for the
    reciprocal form the reciprocal's eta times |p^|, that the doc leaves out. *)

From Coq Require Import Reals Lra.
From PhongApprox Require Import FloatModelK.
Open Scope R_scope.

(** ** Helpers *)

Lemma pv_abs_le : forall x a, Rabs x <= a -> - a <= x <= a.
Proof. intros x a H. unfold Rabs in H. destruct (Rcase_abs x); lra. Qed.

Lemma pv_div_abs : forall x y, 0 < y -> Rabs (x / y) = Rabs x / y.
Proof.
  intros x y Hy. unfold Rdiv. rewrite Rabs_mult, Rabs_inv, (Rabs_pos_eq y) by lra.
  reflexivity.
Qed.

Lemma pv_div_le : forall x y a b, 0 <= x <= a -> 0 < b <= y -> x / y <= a / b.
Proof.
  intros x y a b Hx Hb. unfold Rdiv. apply Rmult_le_compat; try lra.
  - left. apply Rinv_0_lt_compat. lra.
  - apply Rinv_le_contravar; lra.
Qed.

Lemma pv_div_le_iff : forall x y a, 0 < y -> x <= a * y -> x / y <= a.
Proof.
  intros x y a Hy H. unfold Rdiv. apply (Rmult_le_reg_r y); [lra|].
  rewrite Rmult_assoc, Rinv_l, Rmult_1_r by lra. exact H.
Qed.

(** ** 1. The real-analysis step *)

Theorem phong_value_real : forall p q ph qh qmin ep eq,
  0 < qmin -> qmin <= q -> Rabs p <= sqrt q ->
  Rabs (ph - p) <= ep -> Rabs (qh - q) <= eq ->
  0 <= ep -> 0 <= eq -> 2 * eq <= qmin ->
  Rabs (ph / sqrt qh - p / sqrt q) <=
    ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq))).
Proof.
  intros p q ph qh qmin ep eq Hqm Hq Hp Hep Heq Hep0 Heq0 H2.
  pose proof (pv_abs_le _ _ Heq) as Hqh.
  assert (Ha : 0 < sqrt (qmin - eq)) by (apply sqrt_lt_R0; lra).
  assert (Hat : sqrt (qmin - eq) <= sqrt qh) by (apply sqrt_le_1_alt; lra).
  assert (Hsm : sqrt qmin <= sqrt q) by (apply sqrt_le_1_alt; lra).
  assert (Hsm0 : 0 < sqrt qmin) by (apply sqrt_lt_R0; lra).
  assert (Hs2 : sqrt q * sqrt q = q) by (apply sqrt_sqrt; lra).
  assert (Ht2 : sqrt qh * sqrt qh = qh) by (apply sqrt_sqrt; lra).
  set (s := sqrt q) in *. set (t := sqrt qh) in *. set (a := sqrt (qmin - eq)) in *.
  set (sm := sqrt qmin) in *.
  assert (Hid : ph / t - p / s = (ph - p) / t + (p / s) * ((q - qh) / (t * (s + t)))).
  { rewrite <- Hs2, <- Ht2. field. lra. }
  rewrite Hid.
  eapply Rle_trans; [apply Rabs_triang|].
  rewrite Rabs_mult, pv_div_abs, pv_div_abs, pv_div_abs by nra.
  assert (H1 : Rabs (ph - p) / t <= ep / a)
    by (apply pv_div_le; [split; [apply Rabs_pos|lra] | lra]).
  assert (H3 : Rabs p / s <= 1) by (apply pv_div_le_iff; lra).
  assert (H4 : Rabs (q - qh) / (t * (s + t)) <= eq / (a * (sm + a))).
  { apply pv_div_le; [split; [apply Rabs_pos|rewrite Rabs_minus_sym; lra] |].
    split; [nra|]. apply Rmult_le_compat; lra. }
  assert (H5 : 0 <= Rabs (q - qh) / (t * (s + t))).
  { apply Rmult_le_pos; [apply Rabs_pos|]. left; apply Rinv_0_lt_compat; nra. }
  assert (H6 : 0 <= Rabs p / s).
  { apply Rmult_le_pos; [apply Rabs_pos|]. left; apply Rinv_0_lt_compat; nra. }
  nra.
Qed.

(** ** 2. The value's own operations *)

(** From the error of x = p^/sqrt q^ to the error of the value. *)
Lemma pv_core : forall x v z B g E0,
  Rabs (x - v) <= B -> Rabs v <= 1 -> Rabs (z - x) <= g * Rabs x + E0 -> 0 <= g ->
  Rabs (z - v) <= B * (1 + g) + g + E0.
Proof.
  intros x v z B g E0 H1 H2 H3 Hg.
  assert (Hx : Rabs x <= 1 + B).
  { replace x with ((x - v) + v) by ring. pose proof (Rabs_triang (x - v) v). lra. }
  replace (z - v) with ((z - x) + (x - v)) by ring.
  pose proof (Rabs_triang (z - x) (x - v)). nra.
Qed.

(** The computed square root, relative: the eta becomes eps t with eta <= eps t. *)
Lemma pv_sqrt_rel : forall v eta eps t s,
  0 < t -> eta <= eps * t -> ap1 v eta s t -> Rabs (s - t) <= (v + eps) * t.
Proof.
  intros v eta eps t s Ht He H. unfold ap1 in H. rewrite (Rabs_pos_eq t) in H by lra. lra.
Qed.

Lemma pv_ratio : forall c s t, 0 < t -> 0 <= c < 1 -> Rabs (s - t) <= c * t ->
  0 < s /\ 0 < t / s /\ t / s <= / (1 - c) /\ Rabs (t / s - 1) <= c * / (1 - c).
Proof.
  intros c s t Ht Hc H. pose proof (pv_abs_le _ _ H) as Hs.
  assert (Hs0 : 0 < s) by nra.
  assert (Hic : / (1 - c) * (1 - c) = 1) by (field; lra).
  assert (Hic0 : 0 < / (1 - c)) by (apply Rinv_0_lt_compat; lra).
  assert (Hr : t / s <= / (1 - c)).
  { apply pv_div_le_iff; [lra|]. nra. }
  assert (Hr0 : 0 < t / s) by (unfold Rdiv; apply Rmult_lt_0_compat; [lra|apply Rinv_0_lt_compat; lra]).
  repeat split; try lra.
  replace (t / s - 1) with ((t - s) / s) by (field; lra).
  rewrite pv_div_abs, Rabs_minus_sym by lra.
  apply Rle_trans with (c * (t / s)).
  - unfold Rdiv. rewrite <- Rmult_assoc. apply Rmult_le_compat_r; [left; apply Rinv_0_lt_compat; lra|lra].
  - apply Rmult_le_compat_l; lra.
Qed.

(** p^ / s, then a division within a. *)
Lemma pv_div_step : forall a c eta ph s t vh,
  0 < t -> 0 <= c < 1 -> Rabs (s - t) <= c * t -> 0 <= a ->
  ap1 a eta vh (ph / s) ->
  Rabs (vh - ph / t) <= (a + c) / (1 - c) * Rabs (ph / t) + eta.
Proof.
  intros a c eta ph s t vh Ht Hc Hst Ha H. unfold ap1 in H.
  destruct (pv_ratio c s t Ht Hc Hst) as (Hs & Hr0 & Hr & Hr1).
  set (x := ph / t) in *. set (rho := t / s) in *.
  assert (E1 : ph / s = x * rho) by (unfold x, rho; field; lra).
  rewrite E1 in H. rewrite Rabs_mult, (Rabs_pos_eq rho) in H by lra.
  replace (vh - x) with ((vh - x * rho) + x * (rho - 1)) by ring.
  pose proof (Rabs_triang (vh - x * rho) (x * (rho - 1))).
  rewrite Rabs_mult in *. pose proof (Rabs_pos x).
  assert (Rabs x * Rabs (rho - 1) <= Rabs x * (c * / (1 - c))) by (apply Rmult_le_compat_l; lra).
  assert (a * (Rabs x * rho) <= a * (Rabs x * / (1 - c))) by (apply Rmult_le_compat_l; [lra|apply Rmult_le_compat_l; lra]).
  unfold Rdiv. nra.
Qed.

(** p^ * r with r within a of 1 / s, the product within b. *)
Lemma pv_recip_step : forall a b c eta P ph s t r vh,
  0 < t -> 0 <= c -> Rabs (s - t) <= c * t -> 0 <= a -> 0 <= b -> a + b + c < 1 ->
  0 <= eta -> Rabs ph <= P ->
  ap1 a eta r (1 / s) -> ap1 b eta vh (ph * r) ->
  Rabs (vh - ph / t) <= (a + b + c) / (1 - (a + b + c)) * Rabs (ph / t) + (P * eta * (1 + b) + eta).
Proof.
  intros a b c eta P ph s t r vh Ht Hc Hst Ha Hb Hsum He HP Hr Hv. unfold ap1 in Hr, Hv.
  destruct (pv_ratio c s t Ht ltac:(lra) Hst) as (Hs & Hr0 & Hrho & Hr1).
  set (x := ph / t) in *. set (rho := t / s) in *. set (ic := / (1 - c)) in *.
  assert (Hic : ic * (1 - c) = 1) by (unfold ic; field; lra).
  assert (E1 : ph / s = x * rho) by (unfold x, rho; field; lra).
  assert (E2 : Rabs (1 / s) = 1 / s) by (apply Rabs_pos_eq; unfold Rdiv; rewrite Rmult_1_l; left; apply Rinv_0_lt_compat; lra).
  rewrite E2 in Hr.
  assert (Hax : Rabs (ph / s) = Rabs x * rho) by (rewrite E1, Rabs_mult, (Rabs_pos_eq rho) by lra; reflexivity).
  (* |p^ r - p^/s| <= a |x| rho + |p^| eta *)
  assert (D1 : Rabs (ph * r - ph / s) <= a * (Rabs x * rho) + P * eta).
  { replace (ph * r - ph / s) with (ph * (r - 1 / s)) by (field; lra).
    rewrite Rabs_mult.
    assert (Rabs ph * Rabs (r - 1 / s) <= Rabs ph * (a * (1 / s) + eta))
      by (apply Rmult_le_compat_l; [apply Rabs_pos|lra]).
    assert (Rabs ph * (1 / s) = Rabs (ph / s)) by (rewrite pv_div_abs by lra; field; lra).
    assert (Rabs ph * eta <= P * eta) by (apply Rmult_le_compat_r; lra).
    nra. }
  assert (D2 : Rabs (ph * r) <= Rabs x * rho * (1 + a) + P * eta).
  { replace (ph * r) with ((ph * r - ph / s) + ph / s) by ring.
    pose proof (Rabs_triang (ph * r - ph / s) (ph / s)). nra. }
  assert (D3 : Rabs (ph / s - x) <= Rabs x * (c * ic)).
  { rewrite E1. replace (x * rho - x) with (x * (rho - 1)) by ring.
    rewrite Rabs_mult. apply Rmult_le_compat_l; [apply Rabs_pos|lra]. }
  assert (D4 : Rabs (vh - x) <= Rabs x * (rho * (a + b * (1 + a)) + c * ic) + (P * eta * (1 + b) + eta)).
  { replace (vh - x) with ((vh - ph * r) + (ph * r - ph / s) + (ph / s - x)) by ring.
    pose proof (Rabs_triang (vh - ph * r + (ph * r - ph / s)) (ph / s - x)).
    pose proof (Rabs_triang (vh - ph * r) (ph * r - ph / s)).
    assert (b * Rabs (ph * r) <= b * (Rabs x * rho * (1 + a) + P * eta)) by (apply Rmult_le_compat_l; lra).
    nra. }
  (* rho (a + b (1 + a)) + c ic <= ic (a + b + a b + c) <= (a + b + c) / (1 - (a + b + c)) *)
  assert (Hic0 : 0 < ic) by (unfold ic; apply Rinv_0_lt_compat; lra).
  assert (F1 : rho * (a + b * (1 + a)) + c * ic <= ic * (a + b + a * b + c)).
  { assert (rho * (a + b * (1 + a)) <= ic * (a + b * (1 + a))) by (apply Rmult_le_compat_r; nra). nra. }
  assert (F2 : ic * (a + b + a * b + c) <= (a + b + c) / (1 - (a + b + c))).
  { (* (a+b+ab+c)(1-a-b-c) <= (a+b+c)(1-c) *)
    assert (K : (a + b + a * b + c) * (1 - (a + b + c)) <= (a + b + c) * (1 - c)).
    { pose proof (Rmult_le_pos a a Ha Ha). pose proof (Rmult_le_pos b b Hb Hb).
      pose proof (Rmult_le_pos a b Ha Hb). pose proof (Rmult_le_pos c a Hc Ha).
      pose proof (Rmult_le_pos c b Hc Hb).
      assert (0 <= a * b * (a + b + c)) by (apply Rmult_le_pos; nra).
      nra. }
    replace (ic * (a + b + a * b + c))
      with ((a + b + a * b + c) * (1 - (a + b + c)) / ((1 - c) * (1 - (a + b + c))))
      by (unfold ic; field; lra).
    replace ((a + b + c) / (1 - (a + b + c)))
      with ((a + b + c) * (1 - c) / ((1 - c) * (1 - (a + b + c)))) by (field; lra).
    unfold Rdiv. apply Rmult_le_compat_r; [| exact K].
    left. apply Rinv_0_lt_compat, Rmult_lt_0_compat; lra. }
  pose proof (Rabs_pos x).
  assert (Rabs x * (rho * (a + b * (1 + a)) + c * ic) <= Rabs x * ((a + b + c) / (1 - (a + b + c))))
    by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

(** (x + e)/(1 - x - e) <= x/(1 - x) + 2 e for small x, e. *)
Lemma pv_gamma : forall x e, 0 <= x <= / 1024 -> 0 <= e <= / 1024 ->
  (x + e) / (1 - (x + e)) <= x / (1 - x) + 2 * e.
Proof.
  intros x e Hx He. apply pv_div_le_iff; [lra|].
  set (y := x / (1 - x)).
  assert (Hy : y * (1 - x) = x) by (unfold y; field; lra).
  assert (Hy2 : y <= 2 * x) by nra.
  assert (Hy0 : 0 <= y) by nra.
  nra.
Qed.

Lemma pv_finish : forall B g gam eps E0 z x v,
  Rabs (x - v) <= B -> Rabs v <= 1 -> Rabs (z - x) <= g * Rabs x + E0 ->
  0 <= g <= gam + 2 * eps -> 0 <= B ->
  Rabs (z - v) <= B * (1 + gam) + gam + (2 * (1 + B) * eps + E0).
Proof.
  intros B g gam eps E0 z x v H1 H2 H3 Hg HB.
  pose proof (pv_core x v z B g E0 H1 H2 H3 (proj1 Hg)). nra.
Qed.

(** The common set-up: x = p^/sqrt q^ is within B of v, |v| <= 1, and the
    computed square root is within (ks u + eps) sqrt q^ with eps = eta / sqrt (qmin - eq). *)
Lemma pv_setup : forall u eta ks p q ph qh qmin ep eq s,
  0 < qmin -> qmin <= q -> Rabs p <= sqrt q ->
  Rabs (ph - p) <= ep -> Rabs (qh - q) <= eq -> 0 <= ep -> 0 <= eq -> 2 * eq <= qmin ->
  0 <= eta -> 1024 * eta <= sqrt (qmin - eq) ->
  ap1 (ks * u) eta s (sqrt qh) ->
  0 < sqrt qh /\ Rabs (p / sqrt q) <= 1 /\
  0 <= eta / sqrt (qmin - eq) <= / 1024 /\
  Rabs (s - sqrt qh) <= (ks * u + eta / sqrt (qmin - eq)) * sqrt qh /\
  0 <= ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq))).
Proof.
  intros u eta ks p q ph qh qmin ep eq s Hqm Hq Hp Hep Heq Hep0 Heq0 H2 He He2 Hs.
  pose proof (phong_value_real p q ph qh qmin ep eq Hqm Hq Hp Hep Heq Hep0 Heq0 H2) as HB.
  pose proof (pv_abs_le _ _ Heq) as Hqh.
  assert (Ha : 0 < sqrt (qmin - eq)) by (apply sqrt_lt_R0; lra).
  assert (Hat : sqrt (qmin - eq) <= sqrt qh) by (apply sqrt_le_1_alt; lra).
  assert (Hsq : 0 < sqrt q) by (apply sqrt_lt_R0; lra).
  assert (Heps0 : 0 <= eta / sqrt (qmin - eq))
    by (unfold Rdiv; apply Rmult_le_pos; [lra|left; apply Rinv_0_lt_compat; lra]).
  assert (Heps : eta / sqrt (qmin - eq) <= / 1024) by (apply pv_div_le_iff; lra).
  assert (Het : eta <= eta / sqrt (qmin - eq) * sqrt qh).
  { apply Rle_trans with (eta / sqrt (qmin - eq) * sqrt (qmin - eq)).
    - right. field. lra.
    - apply Rmult_le_compat_l; lra. }
  repeat split; try lra.
  - rewrite pv_div_abs by lra. apply pv_div_le_iff; lra.
  - apply (pv_sqrt_rel (ks * u) eta); [lra|exact Het|exact Hs].
  - pose proof (Rabs_pos (ph / sqrt qh - p / sqrt q)). lra.
Qed.

(** ** The value as [p^ / sqrt q^]: a square root within ks, a division within kd. *)
Theorem phong_value_div : forall u eta ks kd p q ph qh qmin ep eq s vh,
  0 < qmin -> qmin <= q -> Rabs p <= sqrt q ->
  Rabs (ph - p) <= ep -> Rabs (qh - q) <= eq -> 0 <= ep -> 0 <= eq -> 2 * eq <= qmin ->
  0 <= u -> 0 <= eta -> 0 <= ks -> 0 <= kd ->
  (ks + kd) * u <= / 1024 -> 1024 * eta <= sqrt (qmin - eq) ->
  ap1 (ks * u) eta s (sqrt qh) ->
  ap1 (kd * u) eta vh (ph / s) ->
  Rabs (vh - p / sqrt q) <=
    (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq))))
      * (1 + (ks + kd) * u / (1 - (ks + kd) * u))
    + (ks + kd) * u / (1 - (ks + kd) * u)
    + (2 * (1 + (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq)))))
         * (eta / sqrt (qmin - eq))
       + eta).
Proof.
  intros u eta ks kd p q ph qh qmin ep eq s vh Hqm Hq Hp Hep Heq Hep0 Heq0 H2 Hu He Hks Hkd Hw He2 Hs Hv.
  pose proof (phong_value_real p q ph qh qmin ep eq Hqm Hq Hp Hep Heq Hep0 Heq0 H2) as HB.
  destruct (pv_setup u eta ks p q ph qh qmin ep eq s Hqm Hq Hp Hep Heq Hep0 Heq0 H2 He He2 Hs)
    as (Ht & Hv1 & Heps & Hst & HB0).
  set (B := ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq)))) in *.
  set (eps := eta / sqrt (qmin - eq)) in *.
  assert (Hku : 0 <= ks * u /\ 0 <= kd * u) by (split; apply Rmult_le_pos; lra).
  assert (Hc : 0 <= ks * u + eps < 1) by nra.
  pose proof (pv_div_step (kd * u) (ks * u + eps) eta ph s (sqrt qh) vh Ht Hc Hst (proj2 Hku) Hv) as Hstep.
  apply (pv_finish B ((kd * u + (ks * u + eps)) / (1 - (ks * u + eps))) _ eps eta vh (ph / sqrt qh));
    try assumption.
  split.
  - unfold Rdiv. apply Rmult_le_pos; [lra|left; apply Rinv_0_lt_compat; lra].
  - apply Rle_trans with (((ks + kd) * u + eps) / (1 - ((ks + kd) * u + eps))).
    + apply pv_div_le; [split; nra|split; nra].
    + apply pv_gamma; split; nra.
Qed.

(** ** The value as [p^ * (1 / sqrt q^)]: a square root within ks, a
    reciprocal within kd, a product within km. *)
Theorem phong_value_recip : forall u eta ks kd km p q ph qh qmin ep eq s r vh,
  0 < qmin -> qmin <= q -> Rabs p <= sqrt q -> Rabs p <= 1 ->
  Rabs (ph - p) <= ep -> Rabs (qh - q) <= eq -> 0 <= ep -> 0 <= eq -> 2 * eq <= qmin ->
  0 <= u -> 0 <= eta -> 0 <= ks -> 0 <= kd -> 0 <= km ->
  (ks + kd + km) * u <= / 1024 -> 1024 * eta <= sqrt (qmin - eq) ->
  ap1 (ks * u) eta s (sqrt qh) ->
  ap1 (kd * u) eta r (1 / s) ->
  ap1 (km * u) eta vh (ph * r) ->
  Rabs (vh - p / sqrt q) <=
    (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq))))
      * (1 + (ks + kd + km) * u / (1 - (ks + kd + km) * u))
    + (ks + kd + km) * u / (1 - (ks + kd + km) * u)
    + (2 * (1 + (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq)))))
         * (eta / sqrt (qmin - eq))
       + ((1 + ep) * eta * (1 + km * u) + eta)).
Proof.
  intros u eta ks kd km p q ph qh qmin ep eq s r vh Hqm Hq Hp Hp1 Hep Heq Hep0 Heq0 H2 Hu He Hks Hkd Hkm Hw He2 Hs Hr Hv.
  pose proof (phong_value_real p q ph qh qmin ep eq Hqm Hq Hp Hep Heq Hep0 Heq0 H2) as HB.
  destruct (pv_setup u eta ks p q ph qh qmin ep eq s Hqm Hq Hp Hep Heq Hep0 Heq0 H2 He He2 Hs)
    as (Ht & Hv1 & Heps & Hst & HB0).
  set (B := ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq)))) in *.
  set (eps := eta / sqrt (qmin - eq)) in *.
  assert (Hku : 0 <= ks * u /\ 0 <= kd * u /\ 0 <= km * u) by (repeat split; apply Rmult_le_pos; lra).
  assert (HP : Rabs ph <= 1 + ep).
  { replace ph with ((ph - p) + p) by ring. pose proof (Rabs_triang (ph - p) p). lra. }
  assert (Hsum : kd * u + km * u + (ks * u + eps) < 1) by nra.
  pose proof (pv_recip_step (kd * u) (km * u) (ks * u + eps) eta (1 + ep) ph s (sqrt qh) r vh
    Ht ltac:(lra) Hst (proj1 (proj2 Hku)) (proj2 (proj2 Hku)) Hsum He HP Hr Hv) as Hstep.
  replace (kd * u + km * u + (ks * u + eps)) with ((ks + kd + km) * u + eps) in Hstep by ring.
  apply (pv_finish B (((ks + kd + km) * u + eps) / (1 - ((ks + kd + km) * u + eps))) _ eps _ vh (ph / sqrt qh));
    try assumption.
  split.
  - unfold Rdiv. apply Rmult_le_pos; [nra|left; apply Rinv_0_lt_compat; nra].
  - apply pv_gamma; split; nra.
Qed.

(** ** Either form, one bound (the reciprocal form's, w = ks + kd + km). *)
Theorem phong_value_either : forall u eta ks kd km p q ph qh qmin ep eq s vh,
  0 < qmin -> qmin <= q -> Rabs p <= sqrt q -> Rabs p <= 1 ->
  Rabs (ph - p) <= ep -> Rabs (qh - q) <= eq -> 0 <= ep -> 0 <= eq -> 2 * eq <= qmin ->
  0 <= u -> 0 <= eta -> 0 <= ks -> 0 <= kd -> 0 <= km ->
  (ks + kd + km) * u <= / 1024 -> 1024 * eta <= sqrt (qmin - eq) ->
  ap1 (ks * u) eta s (sqrt qh) ->
  (ap1 (kd * u) eta vh (ph / s) \/
   exists r, ap1 (kd * u) eta r (1 / s) /\ ap1 (km * u) eta vh (ph * r)) ->
  Rabs (vh - p / sqrt q) <=
    (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq))))
      * (1 + (ks + kd + km) * u / (1 - (ks + kd + km) * u))
    + (ks + kd + km) * u / (1 - (ks + kd + km) * u)
    + (2 * (1 + (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq)))))
         * (eta / sqrt (qmin - eq))
       + ((1 + ep) * eta * (1 + km * u) + eta)).
Proof.
  intros u eta ks kd km p q ph qh qmin ep eq s vh Hqm Hq Hp Hp1 Hep Heq Hep0 Heq0 H2 Hu He Hks Hkd Hkm Hw He2 Hs [Hv | (r & Hr & Hv)].
  - assert (Hw2 : (ks + kd) * u <= / 1024) by nra.
    pose proof (phong_value_div u eta ks kd p q ph qh qmin ep eq s vh Hqm Hq Hp Hep Heq Hep0 Heq0 H2
      Hu He Hks Hkd Hw2 He2 Hs Hv) as H.
    destruct (pv_setup u eta ks p q ph qh qmin ep eq s Hqm Hq Hp Hep Heq Hep0 Heq0 H2 He He2 Hs)
      as (_ & _ & Heps & _ & HB0).
    set (B := ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq)))) in *.
    assert (Hg : (ks + kd) * u / (1 - (ks + kd) * u) <= (ks + kd + km) * u / (1 - (ks + kd + km) * u)).
    { apply pv_div_le; split; nra. }
    assert (0 <= (1 + ep) * eta * (1 + km * u)).
    { apply Rmult_le_pos; [apply Rmult_le_pos|]; nra. }
    nra.
  - exact (phong_value_recip u eta ks kd km p q ph qh qmin ep eq s r vh Hqm Hq Hp Hp1 Hep Heq Hep0 Heq0 H2
      Hu He Hks Hkd Hkm Hw He2 Hs Hr Hv).
Qed.
