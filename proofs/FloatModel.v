(** * FloatModel.v — the floating-point model used by Float.v.

    Rounding is Flocq's round-to-nearest-even in the format FLT(emin, prec)
    (radix 2): binary32 is prec = 24, emin = -149, binary64 is prec = 53,
    emin = -1074.  Everything after the first two lemmas only uses the
    "standard model with underflow"

        |rnd x - x| <= u |x| + eta      (u = 2^-prec, eta = 2^(emin-1))

    ([std_model]), proved once from Flocq's [error_N_FLT], together with
    the size conditions [fmt_ok] (u <= 2^-24, eta <= 2^-60 u), which hold
    for every format with prec >= 24 and emin <= -prec - 59, in particular
    for binary32 and binary64.

    The rest is a small forward-error library: rounding a scaled value,
    the three-term dot product [(x + y) + z] with rounded products, and
    the two float loops (corrected Euler, eqs. 16-17, and Gouraud). *)

From Coq Require Import Reals Lra Lia.
From Flocq Require Import Core Relative.
From PhongApprox Require Import Span.
Open Scope R_scope.

(** ** The standard model, from Flocq *)

Definition std_model (rnd : R -> R) (u eta : R) : Prop :=
  forall x : R, Rabs (rnd x - x) <= u * Rabs x + eta.

Lemma flt_std_model : forall emin prec : Z, (0 < prec)%Z ->
  std_model (fun x => round radix2 (FLT_exp emin prec) ZnearestE x)
            (bpow radix2 (- prec)) (bpow radix2 (emin - 1)).
Proof.
  intros emin prec Hp x.
  destruct (error_N_FLT radix2 emin prec Hp (fun z => negb (Z.even z)) x)
    as (e & d & He & Hd & _ & Hr).
  rewrite Hr.
  replace (x * (1 + e) + d - x) with (x * e + d) by ring.
  assert (H1 : / 2 * bpow radix2 (- prec + 1) = bpow radix2 (- prec)).
  { rewrite bpow_plus, bpow_1. simpl (IZR radix2). field. }
  assert (H2 : / 2 * bpow radix2 emin = bpow radix2 (emin - 1)).
  { replace emin with (emin - 1 + 1)%Z at 1 by ring. rewrite bpow_plus, bpow_1.
    simpl (IZR radix2). field. }
  rewrite H1 in He. rewrite H2 in Hd.
  eapply Rle_trans; [apply Rabs_triang|].
  rewrite Rabs_mult.
  apply Rplus_le_compat; [| exact Hd].
  rewrite Rmult_comm. apply Rmult_le_compat_r; [apply Rabs_pos | exact He].
Qed.

(** Size conditions: u <= 2^-24 and eta <= 2^-60 u. *)
Definition fmt_ok (u eta : R) : Prop :=
  0 < u /\ u <= / 16777216 /\ 0 <= eta /\ eta * 1152921504606846976 <= u.

Lemma flt_fmt_ok : forall emin prec : Z, (24 <= prec)%Z -> (emin <= - prec - 59)%Z ->
  fmt_ok (bpow radix2 (- prec)) (bpow radix2 (emin - 1)).
Proof.
  intros emin prec H1 H2. repeat split.
  - apply bpow_gt_0.
  - replace (/ 16777216) with (bpow radix2 (-24)) by (simpl; lra).
    apply bpow_le. lia.
  - apply Rlt_le, bpow_gt_0.
  - replace 1152921504606846976 with (bpow radix2 60) by (simpl; lra).
    rewrite <- bpow_plus. apply bpow_le. lia.
Qed.

(** ** The computations, for any rounding function [rnd] *)

(** Three-term dot product, left to right: rnd (rnd (rnd (x1 y1) + rnd (x2 y2)) + rnd (x3 y3)). *)
Definition fdot (rnd : R -> R) (a b : vec) : R :=
  rnd (rnd (rnd (vx a * vx b) + rnd (vy a * vy b)) + rnd (vz a * vz b)).

(** Corrected Euler loop (state (P, S)): P' = rnd (P + S), S' = rnd (S + d). *)
Fixpoint floop (rnd : R -> R) (p0 s0 d : R) (i : nat) : R * R :=
  match i with
  | O => (p0, s0)
  | S j => let (pj, sj) := floop rnd p0 s0 d j in (rnd (pj + sj), rnd (sj + d))
  end.

(** Gouraud loop: G' = rnd (G + d). *)
Fixpoint gloop (rnd : R -> R) (g0 d : R) (i : nat) : R :=
  match i with
  | O => g0
  | S j => rnd (gloop rnd g0 d j + d)
  end.

Lemma floop_S : forall rnd p0 s0 d i,
  floop rnd p0 s0 d (S i) =
  (rnd (fst (floop rnd p0 s0 d i) + snd (floop rnd p0 s0 d i)),
   rnd (snd (floop rnd p0 s0 d i) + d)).
Proof. intros. cbn [floop]. destruct (floop rnd p0 s0 d i). reflexivity. Qed.

(** ** Error lemmas *)

Section Model.
Context (rnd : R -> R) (u eta : R).
Context (Hstd : std_model rnd u eta) (Hok : fmt_ok u eta).

Lemma u_pos : 0 < u.
Proof. apply Hok. Qed.
Lemma u_small : u <= / 16777216.
Proof. apply Hok. Qed.
Lemma eta_pos : 0 <= eta.
Proof. apply Hok. Qed.
Lemma eta_small : eta * 1152921504606846976 <= u.
Proof. apply Hok. Qed.

(** Rounding of a value scaled by lam <= 2^24 (the scale is n or n^2). *)
Lemma rnd_sc : forall lam x M, 0 <= lam <= 16777216 -> Rabs (lam * x) <= M ->
  Rabs (lam * rnd x - lam * x) <= (M + / 68719476736) * u.
Proof.
  intros lam x M Hl HM.
  pose proof u_pos. pose proof eta_small. pose proof eta_pos.
  rewrite <- Rmult_minus_distr_l, Rabs_mult, (Rabs_pos_eq lam) by lra.
  pose proof (Hstd x) as Hx.
  assert (K1 : lam * Rabs (rnd x - x) <= lam * (u * Rabs x + eta))
    by (apply Rmult_le_compat_l; lra).
  assert (K2 : lam * Rabs x = Rabs (lam * x))
    by (rewrite Rabs_mult, (Rabs_pos_eq lam); lra).
  assert (K3 : lam * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  assert (K4 : u * (lam * Rabs x) <= u * M) by (apply Rmult_le_compat_l; lra).
  lra.
Qed.

Lemma rnd_1 : forall x M, Rabs x <= M -> Rabs (rnd x - x) <= (M + / 68719476736) * u.
Proof.
  intros x M H. pose proof (rnd_sc 1 x M) as H1.
  rewrite !Rmult_1_l in H1. apply H1; [lra | exact H].
Qed.

(** Three-term dot product: |fdot a b - a.b| <= (3 + 2^-20) u sum |a_j b_j| + 13 eta. *)
Lemma fdot_round : forall a b : vec,
  Rabs (fdot rnd a b - dot a b) <=
  (3 + / 1048576) * u * (Rabs (vx a * vx b) + Rabs (vy a * vy b) + Rabs (vz a * vz b))
  + 13 * eta.
Proof.
  intros a b. unfold fdot, dot.
  set (x1 := vx a * vx b). set (x2 := vy a * vy b). set (x3 := vz a * vz b).
  pose proof u_pos. pose proof u_small. pose proof eta_pos. pose proof eta_small.
  set (T := Rabs x1 + Rabs x2 + Rabs x3).
  pose proof (Hstd x1) as B1. pose proof (Hstd x2) as B2. pose proof (Hstd x3) as B3.
  set (s := rnd (rnd x1 + rnd x2)).
  pose proof (Hstd (rnd x1 + rnd x2)) as B4. fold s in B4.
  pose proof (Hstd (s + rnd x3)) as B5.
  assert (A4 : Rabs (rnd x1 + rnd x2) <= Rabs x1 + Rabs x2 + Rabs (rnd x1 - x1) + Rabs (rnd x2 - x2)).
  { replace (rnd x1 + rnd x2) with (x1 + x2 + (rnd x1 - x1) + (rnd x2 - x2)) by ring.
    repeat (eapply Rle_trans; [apply Rabs_triang | apply Rplus_le_compat_r]); lra. }
  assert (A5 : Rabs (s + rnd x3) <= Rabs x1 + Rabs x2 + Rabs x3 + Rabs (rnd x1 - x1)
                 + Rabs (rnd x2 - x2) + Rabs (rnd x3 - x3) + Rabs (s - (rnd x1 + rnd x2))).
  { replace (s + rnd x3) with (x1 + x2 + x3 + (rnd x1 - x1) + (rnd x2 - x2)
                                + (rnd x3 - x3) + (s - (rnd x1 + rnd x2))) by ring.
    repeat (eapply Rle_trans; [apply Rabs_triang | apply Rplus_le_compat_r]); lra. }
  assert (E : rnd (s + rnd x3) - (x1 + x2 + x3) =
     (rnd (s + rnd x3) - (s + rnd x3)) + (s - (rnd x1 + rnd x2))
     + (rnd x1 - x1) + (rnd x2 - x2) + (rnd x3 - x3)) by ring.
  rewrite E.
  assert (Tr : forall a1 a2 a3 a4 a5 : R,
    Rabs (a1 + a2 + a3 + a4 + a5) <= Rabs a1 + Rabs a2 + Rabs a3 + Rabs a4 + Rabs a5).
  { intros. repeat (eapply Rle_trans; [apply Rabs_triang | apply Rplus_le_compat_r]); lra. }
  eapply Rle_trans; [apply Tr|].
  assert (Hx1 : 0 <= Rabs x1) by apply Rabs_pos.
  assert (Hx2 : 0 <= Rabs x2) by apply Rabs_pos.
  assert (Hx3 : 0 <= Rabs x3) by apply Rabs_pos.
  set (r1 := Rabs (rnd x1 - x1)) in *. set (r2 := Rabs (rnd x2 - x2)) in *.
  set (r3 := Rabs (rnd x3 - x3)) in *. set (r4 := Rabs (s - (rnd x1 + rnd x2))) in *.
  set (r5 := Rabs (rnd (s + rnd x3) - (s + rnd x3))) in *.
  assert (C4 : r4 <= u * (Rabs x1 + Rabs x2 + r1 + r2) + eta).
  { eapply Rle_trans; [exact B4|]. apply Rplus_le_compat_r, Rmult_le_compat_l; lra. }
  assert (C5 : r5 <= u * (Rabs x1 + Rabs x2 + Rabs x3 + r1 + r2 + r3 + r4) + eta).
  { eapply Rle_trans; [exact B5|]. apply Rplus_le_compat_r, Rmult_le_compat_l; lra. }
  assert (F3 : u * eta <= eta) by (rewrite <- (Rmult_1_l eta) at 2; apply Rmult_le_compat_r; lra).
  assert (D4 : r4 <= (u + u / 16777216) * (Rabs x1 + Rabs x2) + 3 * eta).
  { assert (F1 : u * (r1 + r2) <= u * (u * (Rabs x1 + Rabs x2) + 2 * eta))
      by (apply Rmult_le_compat_l; lra).
    assert (F2 : u * (u * (Rabs x1 + Rabs x2)) <= / 16777216 * (u * (Rabs x1 + Rabs x2)))
      by (apply Rmult_le_compat_r; [apply Rmult_le_pos|]; lra).
    lra. }
  assert (D5 : r5 <= (1 + 3 / 16777216) * (u * T) + 7 * eta).
  { assert (F4 : u * (r1 + r2 + r3 + r4) <= u * (3 * (u * T) + 6 * eta)).
    { apply Rmult_le_compat_l; [lra|]. unfold T.
      assert (u / 16777216 <= u) by lra.
      assert (u / 16777216 * (Rabs x1 + Rabs x2) <= u * (Rabs x1 + Rabs x2))
        by (apply Rmult_le_compat_r; lra).
      lra. }
    assert (F5 : u * (u * T) <= / 16777216 * (u * T))
      by (apply Rmult_le_compat_r; [apply Rmult_le_pos; unfold T|]; lra).
    unfold T in *. lra. }
  assert (F6 : 0 <= u * T) by (apply Rmult_le_pos; unfold T; lra).
  unfold T in *. lra.
Qed.

End Model.
