(** * Fixed.v — the Gouraud and corrected-Euler loops in fixed point.

    In fixed point with [f] fractional bits an addition is exact (while it does
    not saturate), so the loop of eqs. 16-17 ([p += t; t += ds]) run on set-up
    values rounded to the grid 2^-f is the exact recurrence on the rounded
    values, and its error is the set-up's error carried along the span. Rounded
    to nearest, each set-up value is off by at most h = 2^-(f+1).

    Tests of the same names: tests/lowp.rs. Derivation and table:
    docs/float.md, "Low precision". Code: src/fixed_span.rs. *)

Require Import Reals Lra Lia.
From PhongApprox Require Import Span Euler.
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
    with (ep + INR i * es + (INR i ^ 2 - INR i) / 2 * ed) by ring.
  pose proof (pos_INR i) as Hi. pose proof (tri_nonneg i) as Ht.
  set (T := (INR i ^ 2 - INR i) / 2) in *.
  eapply Rle_trans; [apply Rabs_triang |].
  eapply Rle_trans; [apply Rplus_le_compat_r, Rabs_triang |].
  rewrite !Rabs_mult, (Rabs_right (INR i)), (Rabs_right T) by lra.
  apply Rle_trans with (h + INR i * h + T * h).
  - apply Rplus_le_compat; [apply Rplus_le_compat |]; try assumption.
    + apply Rmult_le_compat_l; assumption.
    + apply Rmult_le_compat_l; assumption.
  - lra.
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
  replace (g0 + eg + INR i * (dg + ed) - (g0 + INR i * dg)) with (eg + INR i * ed) by ring.
  pose proof (pos_INR i) as Hi.
  eapply Rle_trans; [apply Rabs_triang |].
  rewrite Rabs_mult, (Rabs_right (INR i)) by lra.
  apply Rle_trans with (h + INR i * h).
  - apply Rplus_le_compat; [assumption | apply Rmult_le_compat_l; assumption].
  - lra.
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
  - apply Rmult_le_reg_l with F; [lra |].
    rewrite <- Rmult_assoc, Rinv_r by lra.
    rewrite Rmult_1_l.
    replace (F * / 510) with (F / 510) by (unfold Rdiv; ring).
    apply Rmult_le_reg_l with 510; [lra |].
    replace (510 * (F / 510)) with F by (field; lra). lra.
Qed.
