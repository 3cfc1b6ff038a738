(** * Fixed.v — the span units in fixed point: the Gouraud, Euler and
    corrected-Euler loops, the adaptive decision and Duff's value.

    In fixed point with [f] fractional bits an addition is exact (while it does
    not saturate), so the loop of eqs. 16-17 ([p += t; t += ds]) run on set-up
    values rounded to the grid 2^-f is the exact recurrence on the rounded
    values, and its error is the set-up's error carried along the span. Rounded
    to nearest, each set-up value is off by at most h = 2^-(f+1).

    Proved: the loops' errors ([fixed_point_gouraud_error],
    [fixed_point_euler_error], [fixed_point_corrected_euler_error],
    [fixed_point_half_level_bits]); the adaptive unit's delta, computed exactly
    from rounded dp, t0, ds ([fixed_point_adaptive_delta_error]), and its
    decision, the exact one outside a band ([fixed_point_adaptive_decision]);
    Duff's p/sqrt q from a truncated integer square root and a truncated divider
    ([fixed_point_duff_error]), on the unit's loops ([fixed_point_duff_unit_error]).

    Tests of the same names: tests/lowp.rs. Derivation and table:
    docs/float.md, "Low precision". Code: src/fixed_span.rs,
    src/tolerance/profile.rs (fixed_bound). Contract: docs/float.md §14 and
    docs/conformance.md, Hardware. *)

Require Import Reals Lra Lia.
From PhongApprox Require Import Span Euler PhongValue.
Open Scope R_scope.

(** Gouraud (fence) shading as its loop: g_0 = p_a, g_(i+1) = g_i + dp. *)
Fixpoint fence (g0 dg : R) (i : nat) : R :=
  match i with
  | O => g0
  | S j => fence g0 dg j + dg
  end.

Lemma fence_closed_form : forall g0 dg i, fence g0 dg i = g0 + INR i * dg.
Proof.
  intros g0 dg i. induction i as [| i IH].
  - cbn. ring.
  - cbn [fence]. rewrite IH, S_INR. ring.
Qed.

Lemma tri_nonneg : forall i : nat, 0 <= (INR i ^ 2 - INR i) / 2.
Proof.
  intros [| i].
  - cbn. lra.
  - rewrite S_INR. pose proof (pos_INR i). nra.
Qed.

(** |a x + b y + c z| <= h (a + b + c) for a, b, c >= 0 and |x|, |y|, |z| <= h. *)
Lemma lin3_err : forall a b c x y z h, 0 <= a -> 0 <= b -> 0 <= c ->
  Rabs x <= h -> Rabs y <= h -> Rabs z <= h -> Rabs (a * x + b * y + c * z) <= h * (a + b + c).
Proof.
  intros a b c x y z h Ha Hb Hc Hx Hy Hz.
  eapply Rle_trans; [apply Rabs_triang |].
  eapply Rle_trans; [apply Rplus_le_compat_r, Rabs_triang |].
  rewrite !Rabs_mult, (Rabs_pos_eq a), (Rabs_pos_eq b), (Rabs_pos_eq c) by lra.
  pose proof (Rmult_le_compat_l a _ _ Ha Hx). pose proof (Rmult_le_compat_l b _ _ Hb Hy).
  pose proof (Rmult_le_compat_l c _ _ Hc Hz). lra.
Qed.

(** The corrected-Euler loop (any start slope, so plain Euler too) on set-up
    values each off by at most [h] stays within [h (1 + i + i(i-1)/2)] of the
    loop on the exact values, at pixel [i]. *)
Theorem fixed_point_corrected_euler_error :
  forall (p0 s0 d ep es ed h : R) (i : nat),
  Rabs ep <= h -> Rabs es <= h -> Rabs ed <= h ->
  Rabs (euler_p (p0 + ep) (s0 + es) (d + ed) i - euler_p p0 s0 d i)
    <= h * (1 + INR i + (INR i ^ 2 - INR i) / 2).
Proof.
  intros p0 s0 d ep es ed h i Hp Hs Hd.
  rewrite !eq_14_euler_closed_form.
  replace (p0 + ep + INR i * (s0 + es) + (INR i ^ 2 - INR i) / 2 * (d + ed) -
           (p0 + INR i * s0 + (INR i ^ 2 - INR i) / 2 * d))
    with (1 * ep + INR i * es + (INR i ^ 2 - INR i) / 2 * ed) by ring.
  apply lin3_err; try assumption; [lra | apply pos_INR | apply tri_nonneg].
Qed.

(** The Gouraud loop on a start value and slope each off by at most [h] stays
    within [h (1 + i)] at pixel [i]. *)
Theorem fixed_point_gouraud_error :
  forall (g0 dg eg ed h : R) (i : nat),
  Rabs eg <= h -> Rabs ed <= h ->
  Rabs (fence (g0 + eg) (dg + ed) i - fence g0 dg i) <= h * (1 + INR i).
Proof.
  intros g0 dg eg ed h i Hg Hd.
  rewrite !fence_closed_form.
  replace (g0 + eg + INR i * (dg + ed) - (g0 + INR i * dg)) with (1 * eg + INR i * ed + 0 * 0)
    by ring.
  replace (h * (1 + INR i)) with (h * (1 + INR i + 0)) by ring. pose proof (Rabs_pos eg).
  apply lin3_err; try assumption; try lra; [apply pos_INR | rewrite Rabs_R0; lra].
Qed.

(** The table of docs/float.md: with [f] fractional bits, [h = 2^-(f+1)], and
    [2^(f+1) >= 255 (n^2 + n + 2)], corrected Euler stays within half an 8-bit
    level (1/510) of its exact run at every pixel of a span of [n] steps. *)
Theorem fixed_point_half_level_bits :
  forall (p0 s0 d ep es ed two_f1 : R) (n i : nat),
  0 < two_f1 -> 255 * (INR n ^ 2 + INR n + 2) <= two_f1 -> (i <= n)%nat ->
  Rabs ep <= / two_f1 -> Rabs es <= / two_f1 -> Rabs ed <= / two_f1 ->
  Rabs (euler_p (p0 + ep) (s0 + es) (d + ed) i - euler_p p0 s0 d i) <= / 510.
Proof.
  intros p0 s0 d ep es ed F n i HF Hbits Hin Hp Hs Hd.
  eapply Rle_trans; [apply (fixed_point_corrected_euler_error _ _ _ _ _ _ _ i Hp Hs Hd) |].
  apply le_INR in Hin. pose proof (pos_INR i) as Hi.
  assert (Hsum : 1 + INR i + (INR i ^ 2 - INR i) / 2 <= (INR n ^ 2 + INR n + 2) / 2) by nra.
  assert (Hpos : 0 <= 1 + INR i + (INR i ^ 2 - INR i) / 2) by (pose proof (tri_nonneg i); lra).
  apply Rle_trans with (/ F * ((INR n ^ 2 + INR n + 2) / 2)).
  - apply Rmult_le_compat_l; [left; apply Rinv_0_lt_compat; lra | lra].
  - replace (/ 510) with (/ F * (F / 510)) by (field; lra).
    apply Rmult_le_compat_l; [left; apply Rinv_0_lt_compat |]; lra.
Qed.


(** Plain Euler's loop (eqs. 12-13, start slope di_a) on set-up values each off
    by at most [h] stays within [h (1 + i + i(i-1)/2)] of the loop on the exact
    values, at pixel [i]: the corrected-Euler loop with another start slope. *)
Theorem fixed_point_euler_error :
  forall (p0 s0 d ep es ed h : R) (i : nat),
  Rabs ep <= h -> Rabs es <= h -> Rabs ed <= h ->
  Rabs (euler_p (p0 + ep) (s0 + es) (d + ed) i - euler_p p0 s0 d i)
    <= h * (1 + INR i + (INR i ^ 2 - INR i) / 2).
Proof. exact fixed_point_corrected_euler_error. Qed.

(** ** The adaptive unit *)

(** eq. 24 at the step [k] (the unit's k = ceil(n/2)), with T = (k^2 - k)/2:
    delta = k dp - k t0 - T ds. Computed exactly from [dp], [t0], [ds] each off
    by at most [h], it is off by at most [h (2k + T)]. *)
Theorem fixed_point_adaptive_delta_error :
  forall (k : nat) (dp t0 ds e_dp e_t0 e_ds h : R),
  Rabs e_dp <= h -> Rabs e_t0 <= h -> Rabs e_ds <= h ->
  Rabs ((INR k * (dp + e_dp) - INR k * (t0 + e_t0) - (INR k ^ 2 - INR k) / 2 * (ds + e_ds))
        - (INR k * dp - INR k * t0 - (INR k ^ 2 - INR k) / 2 * ds))
    <= h * (2 * INR k + (INR k ^ 2 - INR k) / 2).
Proof.
  intros k dp t0 ds e_dp e_t0 e_ds h Hp Ht Hd.
  pose proof (pos_INR k) as Hk. pose proof (tri_nonneg k) as HT.
  set (T := (INR k ^ 2 - INR k) / 2) in *.
  replace (INR k * (dp + e_dp) - INR k * (t0 + e_t0) - T * (ds + e_ds)
           - (INR k * dp - INR k * t0 - T * ds))
    with (INR k * e_dp + INR k * (- e_t0) + T * (- e_ds)) by ring.
  replace (h * (2 * INR k + T)) with (h * (INR k + INR k + T)) by ring.
  apply lin3_err; rewrite ?Rabs_Ropp; assumption.
Qed.

(** The unit picks Gouraud iff [255 |dh| < 1] (K_d = 1), on its computed
    [dh] within [e] of the exact delta. Where [255 |delta| < 1 - 255 e] it picks
    Gouraud, and where [255 |delta| > 1 + 255 e] corrected Euler, as the exact
    test does: it may differ from the exact test only in the band
    [|255 |delta| - 1| <= 255 e]. *)
Theorem fixed_point_adaptive_decision :
  forall (delta dh e : R),
  Rabs (dh - delta) <= e ->
  (255 * Rabs delta < 1 - 255 * e -> 255 * Rabs dh < 1) /\
  (1 + 255 * e < 255 * Rabs delta -> ~ (255 * Rabs dh < 1)).
Proof.
  intros delta dh e He.
  pose proof (Rabs_triang (dh - delta) delta) as H1.
  pose proof (Rabs_triang (delta - dh) dh) as H2.
  rewrite Rabs_minus_sym in H2.
  replace (dh - delta + delta) with dh in H1 by ring.
  replace (delta - dh + dh) with delta in H2 by ring.
  split; intros; lra.
Qed.

(** ** Duff's value *)

(** Duff's value p/sqrt q (eqs. 5-7) as the unit computes it: from [ph], [qh]
    within [Ep], [Eq] of p, q, with q >= qmin > Eq and r = sqrt (qmin - Eq)
    > 2h, a square root [sh] truncated below within one unit 2h = 2^-f of
    sqrt qh, and a quotient [vh] within 2h of ph/sh. With |p| <= sqrt q (p = N.L,
    q = N.N, L a unit vector: Cauchy-Schwarz),
    |vh - p/sqrt q| <= (Ep + Eq/(2r) + 2h)/(r - 2h) + 2h.
    (ph/sh - p/sqrt q = (ph - p)/sh + (p/sqrt q)(sqrt q - sh)/sh, and
    |sqrt q - sqrt qh| = |q - qh|/(sqrt q + sqrt qh) <= Eq/(2r).) *)
Theorem fixed_point_duff_error :
  forall (p q ph qh sh vh qmin r Ep Eq h : R),
  qmin <= q -> 0 < qmin - Eq -> r = sqrt (qmin - Eq) -> 0 < r - 2 * h ->
  Rabs p <= sqrt q ->
  Rabs (ph - p) <= Ep -> Rabs (qh - q) <= Eq ->
  sqrt qh - 2 * h < sh <= sqrt qh ->
  Rabs (vh - ph / sh) <= 2 * h ->
  Rabs (vh - p / sqrt q) <= (Ep + Eq / (2 * r) + 2 * h) / (r - 2 * h) + 2 * h.
Proof.
  intros p q ph qh sh vh qmin r Ep Eq h Hq Hm Hr Hr2 Hp Hph Hqh Hsh Hvh.
  pose proof (Rabs_pos (qh - q)) as HEq.
  assert (Hqh' : qmin - Eq <= qh)
    by (unfold Rabs in Hqh; destruct (Rcase_abs (qh - q)); lra).
  assert (H0 : 0 < r) by (rewrite Hr; apply sqrt_lt_R0; lra).
  assert (Ht : r <= sqrt qh) by (rewrite Hr; apply sqrt_le_1_alt; lra).
  assert (Hs : r <= sqrt q) by (rewrite Hr; apply sqrt_le_1_alt; lra).
  assert (Hs2 : sqrt q * sqrt q = q) by (apply sqrt_sqrt; lra).
  assert (Ht2 : sqrt qh * sqrt qh = qh) by (apply sqrt_sqrt; lra).
  set (s := sqrt q) in *. set (t := sqrt qh) in *.
  (* |s - t| <= Eq / (2 r) *)
  assert (Hst : Rabs (s - t) <= Eq / (2 * r)).
  { replace (s - t) with ((q - qh) / (s + t)) by (rewrite <- Hs2, <- Ht2; field; lra).
    rewrite pv_div_abs by lra. apply pv_div_le; [| lra].
    rewrite Rabs_minus_sym. split; [apply Rabs_pos | exact Hqh]. }
  assert (Hssh : Rabs (s - sh) <= Eq / (2 * r) + 2 * h).
  { replace (s - sh) with ((s - t) + (t - sh)) by ring.
    eapply Rle_trans; [apply Rabs_triang |].
    rewrite (Rabs_pos_eq (t - sh)) by lra. lra. }
  assert (Hps : Rabs (p / s) <= 1).
  { rewrite pv_div_abs by lra. apply pv_div_le_iff; lra. }
  (* the exact quotient of the computed operands *)
  assert (Hv : Rabs (ph / sh - p / s) <= (Ep + Eq / (2 * r) + 2 * h) / (r - 2 * h)).
  { replace (ph / sh - p / s) with ((ph - p + p / s * (s - sh)) / sh) by (field; lra).
    rewrite pv_div_abs by lra. apply pv_div_le; [| lra].
    split; [apply Rabs_pos |].
    eapply Rle_trans; [apply Rabs_triang |].
    rewrite Rabs_mult.
    pose proof (Rabs_pos (p / s)). pose proof (Rabs_pos (s - sh)). nra. }
  replace (vh - p / s) with ((vh - ph / sh) + (ph / sh - p / s)) by ring.
  eapply Rle_trans; [apply Rabs_triang |]. lra.
Qed.

(** Duff's unit on set-up values each off by at most [h]: p from the Gouraud
    loop on p0 = B, dp = A; q from the loop q += dq; dq += d2q on q0 = E,
    dq0 = C + D, d2q = 2C (Euler's loop); at pixel [i <= n] they are within
    Ep >= h(1 + n) and Eq >= h(1 + n + n(n-1)/2), and the value within the bound
    of [fixed_point_duff_error]. *)
Theorem fixed_point_duff_unit_error :
  forall (p0 dp q0 dq0 d2q e_p0 e_dp e_q0 e_dq0 e_d2q sh vh qmin r Ep Eq h : R)
    (n i : nat),
  (i <= n)%nat ->
  Rabs e_p0 <= h -> Rabs e_dp <= h ->
  Rabs e_q0 <= h -> Rabs e_dq0 <= h -> Rabs e_d2q <= h ->
  h * (1 + INR n) <= Ep -> h * (1 + INR n + (INR n ^ 2 - INR n) / 2) <= Eq ->
  qmin <= euler_p q0 dq0 d2q i -> 0 < qmin - Eq -> r = sqrt (qmin - Eq) -> 0 < r - 2 * h ->
  Rabs (fence p0 dp i) <= sqrt (euler_p q0 dq0 d2q i) ->
  sqrt (euler_p (q0 + e_q0) (dq0 + e_dq0) (d2q + e_d2q) i) - 2 * h < sh
    <= sqrt (euler_p (q0 + e_q0) (dq0 + e_dq0) (d2q + e_d2q) i) ->
  Rabs (vh - fence (p0 + e_p0) (dp + e_dp) i / sh) <= 2 * h ->
  Rabs (vh - fence p0 dp i / sqrt (euler_p q0 dq0 d2q i))
    <= (Ep + Eq / (2 * r) + 2 * h) / (r - 2 * h) + 2 * h.
Proof.
  intros p0 dp q0 dq0 d2q e_p0 e_dp e_q0 e_dq0 e_d2q sh vh qmin r Ep Eq h n i
    Hin Hp0 Hdp Hq0 Hdq0 Hd2q HEp HEq Hq Hm Hr Hr2 Hp Hsh Hvh.
  apply (fixed_point_duff_error _ _ (fence (p0 + e_p0) (dp + e_dp) i)
           (euler_p (q0 + e_q0) (dq0 + e_dq0) (d2q + e_d2q) i) sh vh qmin r Ep Eq h
           Hq Hm Hr Hr2 Hp); [| | exact Hsh | exact Hvh].
  all: apply le_INR in Hin; pose proof (pos_INR i); pose proof (Rabs_pos e_p0).
  - eapply Rle_trans; [apply fixed_point_gouraud_error; eassumption |].
    eapply Rle_trans; [| exact HEp]. apply Rmult_le_compat_l; lra.
  - eapply Rle_trans; [apply fixed_point_corrected_euler_error; eassumption |].
    eapply Rle_trans; [| exact HEq]. apply Rmult_le_compat_l; [lra | nra].
Qed.
