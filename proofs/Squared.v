(** * Squared.v — squared corrected Euler: corrected Euler (eqs. 15-17)
    applied to g = p²/q instead of f = p/√q.

    Along a span, t ∈ [0, n], p(t) = B + A t = N(t)·L and
    q(t) = E + D t + C t² = N(t)·N(t) (Skip.v's [p], [q]), so Phong's value is
    f = p/√q and its square is g = p²/q, a rational function with no root.
    The squared method runs corrected Euler's recurrence on g: it starts at
    g_a = g(0), takes the end slopes dg_a = g'(0), dg_b = g'(n),
    sds = (dg_b − dg_a)/n and the corrected start slope
    st0 = corr_t0 n g_a g_b dg_a sds (Euler.v), and steps
    sq_i = euler_p g_a st0 sds i. This file proves:

    - [sq_derivative]: g' = p (2 A q − p (D + 2 C t))/q², i.e.
      (2 p p' q − p² q')/q² with p' = A, q' = D + 2 C t, wherever q ≠ 0;
    - [sq_starts_at_ga], [sq_ends_at_gb]: the values are exact at both ends
      (g(0) and g(n), n ≥ 1), from eq. 17 of Euler.v;
    - [sq_closed_form]: sq_i = g_a + i st0 + i (i − 1)/2 · sds (eq. 14);
    - [sq_unit_setup]: with unit normals at both ends (E = q(0) = 1,
      q(n) = 1) the end slopes are dg_a = 2 p_a di_a and dg_b = 2 p_b di_b,
      di the derivative of p/√q at the ends (eqs. 10-11): twice p times
      corrected Euler's slopes;
    - [sq_specular_even], [sq_specular_odd]: the specular power of f from g:
      f^(2m) = g^m, and f^(2m+1) = g^m √g where p ≥ 0;
    - [sq_nonneg_value]: g ≥ 0 where q > 0, and √g = |p|/√q (the diffuse
      term |N·L|/|N| per pixel is √g);
    - [sq_root_holder], [sq_root_lipschitz], [sq_signed_value_error]: the
      error of the signed root sign(p)·√max(0, g), to bound a float
      implementation's value sign(p̃)·fl(√max(0, g̃)) against the exact value:
      |√max(0,x) − √max(0,y)| ≤ √|x − y| (Hölder) and ≤ |x − y|/√y for y > 0
      (Lipschitz), turning the errors of g and p from the operation graphs
      (Graph.v's [graph_sound]) and the root's rounding k·√x + eta into a
      bound on the value, tight when the error of p is below |p|;
    - [sq_shader_root_rounding]: the root computed as 1/inverseSqrt(x), x the
      computed max(0, g) ≤ 9, under a float model with relative error k·u and
      absolute term eta per operation: writing r = (1 + ρ)/√x,
      |ρ| ≤ kr·u + 3·eta =: a < 1, so |v − √x| ≤ (kd·u + a)/(1 − a)·√x
      + eta' + √xmin, the last term for a flushed operand x < xmin read as 0;
    - [sq_skip_sound]: the skip test: its specular term is
      √max(0, g(t))^s, g the quadratic [v] of Skip.v on the span, and
      [skip_quadratic] on g with 255·Ks² in place of Ks (checking
      (255·Ks)²·g(c)^s < 1 at the candidates c) gives
      255·Ks·√max(0, g(t))^s < 1 for every t ∈ [0, n].

    Code: src/squared_corrected_euler.rs. *)

From Coq Require Import Reals Lra Lia.
From Coquelicot Require Import Coquelicot.
From PhongApprox Require Import Euler Skip.
Open Scope R_scope.

(** g = p²/q and its derivative. *)
Definition g (A B C D E t : R) : R := p A B t ^ 2 / q C D E t.

Definition dg (A B C D E t : R) : R :=
  p A B t * (2 * A * q C D E t - p A B t * (D + 2 * C * t)) / q C D E t ^ 2.

(** The set-up on a span of n steps and the values. *)
Definition ga (A B C D E : R) : R := g A B C D E 0.
Definition gb (A B C D E : R) (n : nat) : R := g A B C D E (INR n).
Definition dga (A B C D E : R) : R := dg A B C D E 0.
Definition dgb (A B C D E : R) (n : nat) : R := dg A B C D E (INR n).
Definition sds (A B C D E : R) (n : nat) : R :=
  (dgb A B C D E n - dga A B C D E) / INR n.
Definition st0 (A B C D E : R) (n : nat) : R :=
  corr_t0 n (ga A B C D E) (gb A B C D E n) (dga A B C D E) (sds A B C D E n).
Definition sq (A B C D E : R) (n i : nat) : R :=
  euler_p (ga A B C D E) (st0 A B C D E n) (sds A B C D E n) i.

(* Note: Any A..E and t with q(t) <> 0. *)
(** g' = (2 p p' q − p² q')/q², p' = A, q' = D + 2 C t. *)
Theorem sq_derivative : forall (A B C D E t : R),
  q C D E t <> 0 -> is_derive (fun x => g A B C D E x) t (dg A B C D E t).
Proof.
  intros A B C D E t Hq. unfold g, dg, p, q in *.
  auto_derive.
  - replace (E + D * t + C * (t * (t * 1))) with (E + D * t + C * t ^ 2) by ring.
    exact Hq.
  - replace (E + D * t + C * (t * (t * 1))) with (E + D * t + C * t ^ 2) by ring.
    field. exact Hq.
Qed.

(* Note: Any A..E, n. *)
(** The first value is g(0). *)
Theorem sq_starts_at_ga : forall (A B C D E : R) (n : nat),
  sq A B C D E n 0 = g A B C D E 0.
Proof.
  intros. unfold sq, st0. apply eq_17_corrected_euler_starts_at_pa.
Qed.

(* Note: Any A..E and n >= 1 (no hypothesis on q). *)
(** The n-th value is g(n). *)
Theorem sq_ends_at_gb : forall (A B C D E : R) (n : nat),
  (0 < n)%nat -> sq A B C D E n n = g A B C D E (INR n).
Proof.
  intros A B C D E n Hn. unfold sq, st0.
  apply (eq_17_corrected_euler_ends_at_pb n _ (gb A B C D E n)). exact Hn.
Qed.

(* Note: Any A..E, n, i. *)
(** eq. 14 for the squared values. *)
Theorem sq_closed_form : forall (A B C D E : R) (n i : nat),
  sq A B C D E n i
  = ga A B C D E + INR i * st0 A B C D E n
    + INR i * (INR i - 1) / 2 * sds A B C D E n.
Proof.
  intros. unfold sq. rewrite eq_14_euler_closed_form. field.
Qed.

(* Note: Unit normals at both ends: E = q(0) = 1 and q(n) = 1; any A..D, n. *)
(** eqs. 10-11: dg_a = 2 p_a di_a, di_a = A − p_a/2 · D, and
    dg_b = 2 p_b di_b, di_b = A − p_b/2 · (2 n C + D). *)
Theorem sq_unit_setup : forall (A B C D E : R) (n : nat),
  E = 1 -> q C D E (INR n) = 1 ->
  let pa := B in
  let pb := p A B (INR n) in
  dga A B C D E = 2 * pa * (A - pa / 2 * D)
  /\ dgb A B C D E n = 2 * pb * (A - pb / 2 * (2 * INR n * C + D)).
Proof.
  intros A B C D E n HE Hqn pa pb. unfold pa, pb, dga, dgb, dg.
  rewrite Hqn. split.
  - unfold p, q. rewrite HE. field.
  - field.
Qed.

Lemma f_sq (A B C D E t : R) : 0 < q C D E t ->
  (p A B t / sqrt (q C D E t)) ^ 2 = g A B C D E t.
Proof.
  intros Hq. unfold g.
  assert (Hs : 0 < sqrt (q C D E t)) by (apply sqrt_lt_R0; exact Hq).
  rewrite <- (sqrt_sqrt (q C D E t)) at 2 by lra. field. lra.
Qed.

(* Note: Any p(t) (no sign condition), q(t) > 0, every m. *)
(** An even specular power of f is a power of g: f^(2m) = g^m. *)
Theorem sq_specular_even : forall (A B C D E t : R) (m : nat),
  0 < q C D E t ->
  (p A B t / sqrt (q C D E t)) ^ (2 * m) = g A B C D E t ^ m.
Proof.
  intros A B C D E t m Hq. rewrite pow_mult, f_sq by exact Hq. reflexivity.
Qed.

(* Note: p(t) >= 0, q(t) > 0, every m. *)
(** An odd specular power: f^(2m+1) = g^m √g. *)
Theorem sq_specular_odd : forall (A B C D E t : R) (m : nat),
  0 <= p A B t -> 0 < q C D E t ->
  (p A B t / sqrt (q C D E t)) ^ (2 * m + 1) = g A B C D E t ^ m * sqrt (g A B C D E t).
Proof.
  intros A B C D E t m Hp Hq.
  assert (Hs : 0 < sqrt (q C D E t)) by (apply sqrt_lt_R0; exact Hq).
  rewrite pow_add, pow_1, sq_specular_even by exact Hq.
  rewrite <- (f_sq A B C D E t Hq), sqrt_pow2; [reflexivity |].
  apply Rdiv_le_0_compat; lra.
Qed.

(* Note: Any p(t), q(t) > 0. *)
(** g ≥ 0 and √g = |p|/√q: the diffuse term |N·L|/|N| is √g. *)
Theorem sq_nonneg_value : forall (A B C D E t : R),
  0 < q C D E t ->
  0 <= g A B C D E t /\ sqrt (g A B C D E t) = Rabs (p A B t) / sqrt (q C D E t).
Proof.
  intros A B C D E t Hq.
  assert (Hs : 0 < sqrt (q C D E t)) by (apply sqrt_lt_R0; exact Hq).
  rewrite <- (f_sq A B C D E t Hq). split.
  - apply pow2_ge_0.
  - rewrite <- Rsqr_pow2, sqrt_Rsqr_abs, Rabs_div by lra.
    rewrite (Rabs_pos_eq (sqrt _)) by lra. reflexivity.
Qed.

(** The root of max(0, x): the float code's √max(0, g̃). *)
Definition sqp (x : R) : R := sqrt (Rmax 0 x).
(** The sign of p times r: r, −r or 0. *)
Definition sgnv (p r : R) : R := if Rlt_dec 0 p then r else if Rlt_dec p 0 then - r else 0.

(** max(0, ·) is 1-Lipschitz. *)
Lemma sq_rmax_lip : forall x y : R, Rabs (Rmax 0 x - Rmax 0 y) <= Rabs (x - y).
Proof.
  intros x y. apply Rabs_le.
  pose proof (Rle_abs (x - y)). pose proof (Rle_abs (- (x - y))).
  rewrite Rabs_Ropp in *.
  unfold Rmax; destruct (Rle_dec 0 x), (Rle_dec 0 y); split; lra.
Qed.

(** √a − √b ≤ √(a − b) for 0 ≤ b ≤ a. *)
Lemma sq_sqrt_diff : forall a b : R, 0 <= b <= a ->
  sqrt a - sqrt b <= sqrt (a - b).
Proof.
  intros a b [Hb Hab].
  assert (Ha : 0 <= a) by lra.
  pose proof (sqrt_le_1_alt b a Hab).
  pose proof (sqrt_pos b). pose proof (sqrt_sqrt a Ha). pose proof (sqrt_sqrt b Hb).
  apply Rsqr_incr_0_var; [| apply sqrt_pos].
  unfold Rsqr. rewrite sqrt_sqrt by lra. nra.
Qed.

(* Note: Any x, y. *)
(** The root of max(0, ·) is 1/2-Hölder: |√max(0,x) − √max(0,y)| ≤ √|x − y|. *)
Theorem sq_root_holder : forall x y : R, Rabs (sqp x - sqp y) <= sqrt (Rabs (x - y)).
Proof.
  intros x y. unfold sqp.
  pose proof (sq_rmax_lip x y) as Hl.
  assert (Hx : 0 <= Rmax 0 x) by apply Rmax_l.
  assert (Hy : 0 <= Rmax 0 y) by apply Rmax_l.
  destruct (Rle_dec (Rmax 0 y) (Rmax 0 x)) as [Hle | Hle].
  - pose proof (sqrt_le_1_alt _ _ Hle).
    rewrite Rabs_pos_eq by lra.
    eapply Rle_trans; [apply sq_sqrt_diff; lra |].
    apply sqrt_le_1_alt. rewrite Rabs_pos_eq in Hl by lra. exact Hl.
  - assert (Hle' : Rmax 0 x <= Rmax 0 y) by lra.
    pose proof (sqrt_le_1_alt _ _ Hle').
    rewrite Rabs_minus_sym, Rabs_pos_eq by lra.
    eapply Rle_trans; [apply sq_sqrt_diff; lra |].
    apply sqrt_le_1_alt. rewrite Rabs_minus_sym, Rabs_pos_eq in Hl by lra. exact Hl.
Qed.

(* Note: Any x, y > 0. *)
(** Away from 0 it is Lipschitz: |√max(0,x) − √y| ≤ |x − y|/√y. *)
Theorem sq_root_lipschitz : forall x y : R, 0 < y -> Rabs (sqp x - sqp y) <= Rabs (x - y) / sqrt y.
Proof.
  intros x y Hy. unfold sqp.
  pose proof (sq_rmax_lip x y).
  rewrite (Rmax_right 0 y) in * by lra.
  set (a := Rmax 0 x) in *.
  assert (Ha : 0 <= a) by apply Rmax_l.
  pose proof (sqrt_lt_R0 y Hy). pose proof (sqrt_pos a).
  pose proof (sqrt_sqrt a Ha). pose proof (sqrt_sqrt y (Rlt_le _ _ Hy)).
  assert (He : sqrt a - sqrt y = (a - y) / (sqrt a + sqrt y)).
  { replace (a - y) with ((sqrt a - sqrt y) * (sqrt a + sqrt y)) by nra.
    field. lra. }
  rewrite He, Rabs_div, (Rabs_pos_eq (sqrt a + sqrt y)) by lra.
  apply Rle_trans with (Rabs (a - y) / sqrt y).
  - unfold Rdiv. apply Rmult_le_compat_l; [apply Rabs_pos |].
    apply Rinv_le_contravar; lra.
  - unfold Rdiv. apply Rmult_le_compat_r; [| exact H].
    left. apply Rinv_0_lt_compat. lra.
Qed.

(* Note: Any g, g̃, p, p̃ with |g̃ − g| ≤ e, |p̃ − p| ≤ ep,
   |√max(0,g̃) − √max(0,g)| ≤ R (e.g. √e, or e/√g for g > 0, from the two
   theorems above), a root r̃ within k·√max(0,g̃) + eta of √max(0,g̃), k ≥ 0. *)
(** The signed value's error: R + k (√max(0,g) + R) + eta when ep < |p| (p̃
    has p's sign), and (1 + k)(√max(0,g) + R) + √max(0,g) + eta always. *)
Theorem sq_signed_value_error : forall (g gt p pt e ep R k eta rt : R),
  Rabs (gt - g) <= e -> Rabs (pt - p) <= ep ->
  Rabs (sqp gt - sqp g) <= R ->
  Rabs (rt - sqp gt) <= k * sqp gt + eta -> 0 <= k ->
  (ep < Rabs p -> Rabs (sgnv pt rt - sgnv p (sqp g)) <= R + k * (sqp g + R) + eta) /\
  Rabs (sgnv pt rt - sgnv p (sqp g)) <= (1 + k) * (sqp g + R) + sqp g + eta.
Proof.
  intros g gt p pt e ep R k eta rt _ Hp HR Hr Hk.
  assert (Hs : 0 <= sqp g) by apply sqrt_pos.
  assert (Hst : 0 <= sqp gt) by apply sqrt_pos.
  assert (Hgt : sqp gt <= sqp g + R) by
    (pose proof (Rle_abs (sqp gt - sqp g)); lra).
  assert (HkR : k * sqp gt <= k * (sqp g + R)) by (apply Rmult_le_compat_l; lra).
  assert (Hrt : Rabs rt <= (1 + k) * (sqp g + R) + eta).
  { pose proof (Rabs_triang_inv rt (sqp gt)). rewrite (Rabs_pos_eq (sqp gt)) in * by lra.
    lra. }
  assert (Hd : Rabs (rt - sqp g) <= R + k * (sqp g + R) + eta).
  { replace (rt - sqp g) with ((rt - sqp gt) + (sqp gt - sqp g)) by ring.
    pose proof (Rabs_triang (rt - sqp gt) (sqp gt - sqp g)). lra. }
  split.
  - intros Hep. unfold sgnv.
    pose proof (Rle_abs (pt - p)). pose proof (Rle_abs (- (pt - p))).
    rewrite Rabs_Ropp in *.
    destruct (Rle_dec 0 p) as [Hp0 | Hp0].
    + rewrite Rabs_pos_eq in Hep by lra.
      destruct (Rlt_dec 0 pt); [| lra]. destruct (Rlt_dec 0 p); [exact Hd | lra].
    + rewrite Rabs_left in Hep by lra.
      destruct (Rlt_dec 0 pt); [lra |]. destruct (Rlt_dec pt 0); [| lra].
      destruct (Rlt_dec 0 p); [lra |]. destruct (Rlt_dec p 0); [| lra].
      replace (- rt - - sqp g) with (- (rt - sqp g)) by ring.
      rewrite Rabs_Ropp. exact Hd.
  - assert (H1 : Rabs (sgnv pt rt) <= Rabs rt).
    { unfold sgnv. destruct (Rlt_dec 0 pt); [lra |].
      destruct (Rlt_dec pt 0); [rewrite Rabs_Ropp; lra |].
      rewrite Rabs_R0. apply Rabs_pos. }
    assert (H2 : Rabs (sgnv p (sqp g)) <= sqp g).
    { unfold sgnv. destruct (Rlt_dec 0 p).
      - rewrite Rabs_pos_eq by lra. lra.
      - destruct (Rlt_dec p 0); [rewrite Rabs_Ropp, Rabs_pos_eq by lra; lra |].
        rewrite Rabs_R0. lra. }
    pose proof (Rabs_triang (sgnv pt rt) (- sgnv p (sqp g))).
    rewrite Rabs_Ropp in *. unfold Rminus. lra.
Qed.

(* Note: Any u, kr, kd, eta, eta', xmin >= 0 with kr u + 3 eta < 1, x = the
   computed max(0, g) in [0, 9], r within kr u/√x + eta of 1/√x and v within
   kd u |1/r| + eta' of 1/r; or, where subnormals are flushed, x < xmin read
   as 0 and v = 0.  (x = 0 with xmin = 0 fits neither case.) *)
(** The root as 1/inverseSqrt(x): with a = kr u + 3 eta,
    |v − √x| <= (kd u + a)/(1 − a) √x + eta' + √xmin. *)
Theorem sq_shader_root_rounding : forall (u kr kd eta eta' xmin x r v : R),
  0 <= u -> 0 <= kr -> 0 <= kd -> 0 <= eta -> 0 <= eta' -> 0 <= xmin ->
  kr * u + 3 * eta < 1 ->
  0 <= x <= 9 ->
  ((x < xmin /\ v = 0) \/
   (0 < x /\
    Rabs (r - / sqrt x) <= kr * u * / sqrt x + eta /\
    Rabs (v - / r) <= kd * u * Rabs (/ r) + eta')) ->
  Rabs (v - sqrt x) <=
    (kd * u + kr * u + 3 * eta) / (1 - kr * u - 3 * eta) * sqrt x + (eta' + sqrt xmin).
Proof.
  intros u kr kd eta eta' xmin x r v Hu Hkr Hkd He He' Hm Ha Hx H.
  pose proof (sqrt_pos x) as Hs0. pose proof (sqrt_pos xmin) as Hm0.
  unfold Rdiv. set (z := / (1 - kr * u - 3 * eta)).
  assert (Hz : 0 < z) by (apply Rinv_0_lt_compat; lra).
  assert (Hk : 0 <= kd * u + kr * u + 3 * eta) by nra.
  assert (Hb : 0 <= (kd * u + kr * u + 3 * eta) * z * sqrt x).
  { apply Rmult_le_pos; [apply Rmult_le_pos |]; lra. }
  destruct H as [[Hlt Hv] | [Hx0 [Hr Hv]]].
  - (* flushed: |0 - √x| = √x <= √xmin *)
    subst v. rewrite Rminus_0_l, Rabs_Ropp, Rabs_pos_eq by lra.
    pose proof (sqrt_le_1_alt x xmin (Rlt_le _ _ Hlt)). lra.
  - (* r = (1 + e)/√x with |e| <= kr u + eta √x <= kr u + 3 eta < 1 *)
    assert (Hs : 0 < sqrt x) by (apply sqrt_lt_R0; lra).
    assert (Hs3 : sqrt x <= 3) by (pose proof (sqrt_sqrt x (proj1 Hx)); nra).
    set (s := sqrt x) in *.
    set (e := r * s - 1).
    assert (He1 : Rabs e <= kr * u + 3 * eta).
    { replace e with (s * (r - / s)) by (unfold e; field; lra).
      rewrite Rabs_mult, (Rabs_pos_eq s) by lra.
      apply Rle_trans with (s * (kr * u * / s + eta)); [apply Rmult_le_compat_l; lra |].
      replace (s * (kr * u * / s + eta)) with (kr * u + eta * s) by (field; lra). nra. }
    assert (He2 : 1 - kr * u - 3 * eta <= 1 + e) by
      (pose proof (Rle_abs (- e)); rewrite Rabs_Ropp in *; lra).
    set (w := / (1 + e)).
    assert (Hw : 0 < w) by (apply Rinv_0_lt_compat; lra).
    assert (Hw1 : w * (1 + e) = 1) by (apply Rinv_l; lra).
    assert (Hwz : w <= z) by (apply Rinv_le_contravar; lra).
    assert (Hrs : r * s = 1 + e) by (unfold e; ring).
    assert (Hr0 : 0 < r) by nra.
    assert (Hir : / r = s * w) by (unfold w; rewrite <- Hrs; field; lra).
    rewrite Hir in Hv. rewrite (Rabs_pos_eq (s * w)) in Hv by (apply Rmult_le_pos; lra).
    (* |/r - √x| = √x |e| w *)
    assert (Hd : Rabs (/ r - s) = s * Rabs e * w).
    { rewrite Hir. replace (s * w - s) with (s * w * (- e)) by nra.
      rewrite !Rabs_mult, Rabs_Ropp, (Rabs_pos_eq s), (Rabs_pos_eq w) by lra. ring. }
    assert (Hm1 : (kd * u + Rabs e) * w <= (kd * u + kr * u + 3 * eta) * z).
    { apply Rmult_le_compat; try lra. pose proof (Rabs_pos e). nra. }
    apply Rmult_le_compat_l with (r := s) in Hm1; [| lra].
    replace (v - s) with ((v - / r) + (/ r - s)) by ring.
    pose proof (Rabs_triang (v - / r) (/ r - s)). rewrite Hd, Hir in *. lra.
Qed.

(** The skip test of the squared method: its specular term is
    max(0, v)^s = √max(0, g)^s with g the quadratic [v] of Skip.v, and the
    test runs [skip_quadratic] on g with 255·Ks² in place of Ks, i.e. checks
    (255·Ks)²·g(c)^s < 1 at the candidates c; then 255·Ks·√max(0, g(t))^s < 1
    on the whole span. *)
Theorem sq_skip_sound : forall ga t0 ds n Ks s,
  0 <= n -> 0 <= Ks -> (1 <= s)%nat ->
  skip_quadratic ga t0 ds n (255 * Ks ^ 2) s ->
  forall t, 0 <= t <= n -> 255 * Ks * sqrt (Rmax 0 (v ga t0 ds t)) ^ s < 1.
Proof.
  intros ga t0 ds n Ks s Hn HK Hs Hskip t Ht.
  assert (HK2 : 0 <= 255 * Ks ^ 2) by nra.
  pose proof (quadratic_skip_sound ga t0 ds n _ s Hn HK2 Hs Hskip t Ht) as H.
  set (M := Rmax 0 (v ga t0 ds t)) in *.
  assert (HM : 0 <= M) by apply Rmax_l.
  assert (Hx : (sqrt M ^ s) ^ 2 = M ^ s).
  { rewrite <- pow_mult, Nat.mul_comm, pow_mult, <- Rsqr_pow2, Rsqr_sqrt; lra. }
  pose proof (pow_le _ s (sqrt_pos M)) as H0.
  set (x := sqrt M ^ s) in *.
  assert (Hy : (255 * Ks * x) ^ 2 < 1) by (rewrite Rpow_mult_distr, Hx; nra).
  assert (0 <= 255 * Ks * x) by (apply Rmult_le_pos; lra). nra.
Qed.
