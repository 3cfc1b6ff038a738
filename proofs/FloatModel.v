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
    the two float loops (corrected Euler, eqs. 16-17, and Gouraud), whose
    bounds are FloatModelK.v's relational loops [cseq_err], [gseq_err] at
    one rounding function (Float.v). *)

From Coq Require Import Reals Lra Lia.
From Flocq Require Import Core Relative.
From PhongApprox Require Import Span.
Open Scope R_scope.

(** ** The standard model, from Flocq *)

Definition std_model (rnd : R -> R) (u eta : R) : Prop :=
  forall x : R, Rabs (rnd x - x) <= u * Rabs x + eta.

(** Round to nearest with any tie rule [choice] (Profiles.v [rn_covered]). *)
Lemma rn_std_model : forall (emin prec : Z) (choice : Z -> bool), (0 < prec)%Z ->
  std_model (fun x => round radix2 (FLT_exp emin prec) (Znearest choice) x)
            (bpow radix2 (- prec)) (bpow radix2 (emin - 1)).
Proof.
  intros emin prec choice Hp x.
  destruct (error_N_FLT radix2 emin prec Hp choice x) as (e & d & He & Hd & _ & Hr).
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

Lemma flt_std_model : forall emin prec : Z, (0 < prec)%Z ->
  std_model (fun x => round radix2 (FLT_exp emin prec) ZnearestE x)
            (bpow radix2 (- prec)) (bpow radix2 (emin - 1)).
Proof. intros emin prec Hp. exact (rn_std_model emin prec (fun z => negb (Z.even z)) Hp). Qed.

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


(** Componentwise approximation of a scaled computed vector [lam vh] to [v]
    with weights [w] (error of component j at most [u * w_j]). *)
Definition vapprox (u lam : R) (vh v w : vec) : Prop :=
  Rabs (lam * vx vh - vx v) <= u * vx w /\ Rabs (lam * vy vh - vy v) <= u * vy w
  /\ Rabs (lam * vz vh - vz v) <= u * vz w.
Definition vbounded (v : vec) (M : R) : Prop :=
  Rabs (vx v) <= M /\ Rabs (vy v) <= M /\ Rabs (vz v) <= M.
Definition wbounded (w : vec) : Prop :=
  0 <= vx w <= 8 /\ 0 <= vy w <= 8 /\ 0 <= vz w <= 8.
(** The first-order weight of the dot-product error. *)
Definition wsum (a b wa wb : vec) : R :=
  Rabs (vx a) * vx wb + vx wa * Rabs (vx b) + 3 * (Rabs (vx a) * Rabs (vx b))
  + (Rabs (vy a) * vy wb + vy wa * Rabs (vy b) + 3 * (Rabs (vy a) * Rabs (vy b)))
  + (Rabs (vz a) * vz wb + vz wa * Rabs (vz b) + 3 * (Rabs (vz a) * Rabs (vz b))).

(** 0 <= |v_j| for the three components of v (here and in Float.v). *)
Ltac abs_pos3 v :=
  pose proof (Rabs_pos (vx v)); pose proof (Rabs_pos (vy v)); pose proof (Rabs_pos (vz v)).

(** Two small facts about approximations. *)
Lemma abs_near : forall X Y e, Rabs (Y - X) <= e -> Rabs Y <= Rabs X + e.
Proof.
  intros X Y e H. replace Y with (X + (Y - X)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.

Lemma absdiff : forall x y, Rabs (x - y) <= Rabs x + Rabs y.
Proof.
  intros. unfold Rminus. eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp. lra.
Qed.
Lemma tri3 : forall x y z, Rabs (x + y + z) <= Rabs x + Rabs y + Rabs z.
Proof.
  intros. eapply Rle_trans; [apply Rabs_triang|]. pose proof (Rabs_triang x y). lra.
Qed.
Lemma tri4 : forall w x y z, Rabs (w + x + y + z) <= Rabs w + Rabs x + Rabs y + Rabs z.
Proof.
  intros. eapply Rle_trans; [apply Rabs_triang|]. pose proof (tri3 w x y). lra.
Qed.
Lemma tri5 : forall a b c d e,
  Rabs (a + b + c + d + e) <= Rabs a + Rabs b + Rabs c + Rabs d + Rabs e.
Proof. intros. eapply Rle_trans; [apply Rabs_triang|]. pose proof (tri4 a b c d). lra. Qed.
Lemma tri6 : forall a b c d e f,
  Rabs (a + b + c + d + e + f) <= Rabs a + Rabs b + Rabs c + Rabs d + Rabs e + Rabs f.
Proof. intros. eapply Rle_trans; [apply Rabs_triang|]. pose proof (tri5 a b c d e). lra. Qed.

(** A three-term sum ((x1 + x2) + x3) with the terms rounded by um and the
    additions by ua (here and in FloatModelK.v's [sum3_err]). *)
Lemma sum_chain_abs : forall um ua eta x1 x2 x3 q1 q2 q3 r y,
  0 <= um <= / 2097152 -> 0 <= ua <= / 2097152 -> 0 <= eta ->
  Rabs (q1 - x1) <= um * Rabs x1 + eta -> Rabs (q2 - x2) <= um * Rabs x2 + eta ->
  Rabs (q3 - x3) <= um * Rabs x3 + eta -> Rabs (r - (q1 + q2)) <= ua * Rabs (q1 + q2) + eta ->
  Rabs (y - (r + q3)) <= ua * Rabs (r + q3) + eta ->
  Rabs (y - (x1 + x2 + x3)) <=
  (um + 2 * ua) * (1 + / 524288) * (Rabs x1 + Rabs x2 + Rabs x3) + 8 * eta.
Proof.
  intros um ua eta x1 x2 x3 q1 q2 q3 r y Hm Ha He H1 H2 H3 H4 H5.
  pose proof (Rabs_pos x1). pose proof (Rabs_pos x2). pose proof (Rabs_pos x3).
  assert (A12 : Rabs (q1 + q2) <= (1 + um) * (Rabs x1 + Rabs x2) + 2 * eta).
  { replace (q1 + q2) with (x1 + x2 + (q1 - x1) + (q2 - x2)) by ring.
    eapply Rle_trans; [apply tri4|]. lra. }
  assert (P1 : ua * Rabs (q1 + q2) <= ua * ((1 + um) * (Rabs x1 + Rabs x2) + 2 * eta))
    by (apply Rmult_le_compat_l; lra).
  assert (P2 : ua * um * (Rabs x1 + Rabs x2) <= / 2097152 * (ua * (Rabs x1 + Rabs x2))).
  { replace (ua * um * (Rabs x1 + Rabs x2)) with (um * (ua * (Rabs x1 + Rabs x2))) by ring.
    apply Rmult_le_compat_r; [apply Rmult_le_pos|]; lra. }
  assert (P3 : ua * eta <= / 2097152 * eta) by (apply Rmult_le_compat_r; lra).
  assert (E1 : Rabs (r - (q1 + q2)) <= (1 + / 2097152) * (ua * (Rabs x1 + Rabs x2)) + 2 * eta)
    by nra.
  assert (P4 : ua * (Rabs x1 + Rabs x2) <= / 2097152 * (Rabs x1 + Rabs x2))
    by (apply Rmult_le_compat_r; lra).
  assert (P5 : um * Rabs x3 <= / 2097152 * Rabs x3) by (apply Rmult_le_compat_r; lra).
  assert (P6 : um * Rabs x1 <= / 2097152 * Rabs x1) by (apply Rmult_le_compat_r; lra).
  assert (P7 : um * Rabs x2 <= / 2097152 * Rabs x2) by (apply Rmult_le_compat_r; lra).
  assert (A3 : Rabs (r + q3) <= (1 + / 524288) * (Rabs x1 + Rabs x2 + Rabs x3) + 5 * eta).
  { replace (r + q3) with (x1 + x2 + (q1 - x1) + (q2 - x2) + (r - (q1 + q2)) + x3 + (q3 - x3))
      by ring.
    assert (T : forall a1 a2 a3 a4 a5 a6 a7 : R,
      Rabs (a1 + a2 + a3 + a4 + a5 + a6 + a7) <=
      Rabs a1 + Rabs a2 + Rabs a3 + Rabs a4 + Rabs a5 + Rabs a6 + Rabs a7).
    { intros. repeat (eapply Rle_trans; [apply Rabs_triang | apply Rplus_le_compat_r]); lra. }
    eapply Rle_trans; [apply T|]. lra. }
  assert (P8 : ua * Rabs (r + q3) <= ua * ((1 + / 524288) * (Rabs x1 + Rabs x2 + Rabs x3) + 5 * eta))
    by (apply Rmult_le_compat_l; lra).
  assert (E2 : Rabs (y - (r + q3)) <= (1 + / 524288) * (ua * (Rabs x1 + Rabs x2 + Rabs x3)) + 2 * eta)
    by nra.
  replace (y - (x1 + x2 + x3)) with
    ((y - (r + q3)) + (r - (q1 + q2)) + (q1 - x1) + (q2 - x2) + (q3 - x3)) by ring.
  eapply Rle_trans; [apply tri5|].
  assert (Q1 : 0 <= ua * Rabs x3) by (apply Rmult_le_pos; lra).
  assert (Q2 : 0 <= ua * (Rabs x1 + Rabs x2)) by (apply Rmult_le_pos; lra).
  assert (Q3 : 0 <= um * (Rabs x1 + Rabs x2 + Rabs x3)) by (apply Rmult_le_pos; lra).
  lra.
Qed.

Lemma prod_err : forall X x Y y ex ey MY Mx,
  Rabs (X - x) <= ex -> Rabs (Y - y) <= ey -> Rabs Y <= MY -> Rabs x <= Mx ->
  Rabs (X * Y - x * y) <= ex * MY + Mx * ey.
Proof.
  intros X x Y y ex ey MY Mx H1 H2 H3 H4.
  replace (X * Y - x * y) with ((X - x) * Y + x * (Y - y)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. rewrite !Rabs_mult.
  apply Rplus_le_compat; apply Rmult_le_compat; try apply Rabs_pos; assumption.
Qed.

(** ** Error lemmas *)

(** The product of two approximations with absolute errors wa, wb <= W. *)
Lemma comp_prod_abs : forall A a B b wa wb W,
  Rabs (A - a) <= wa -> Rabs (B - b) <= wb ->
  Rabs a <= 2 -> Rabs b <= 2 -> 0 <= wa <= W -> 0 <= wb <= W ->
  Rabs (A * B - a * b) <= Rabs a * wb + wa * Rabs b + W * W
  /\ Rabs (A * B) <= Rabs a * Rabs b + 4 * W + W * W.
Proof.
  intros A a B b wa wb W HA HB Ha Hb Hwa Hwb.
  assert (E : A * B - a * b = (A - a) * b + a * (B - b) + (A - a) * (B - b)) by ring.
  assert (T1 : Rabs ((A - a) * b) <= wa * Rabs b).
  { rewrite Rabs_mult. apply Rmult_le_compat_r; [apply Rabs_pos | exact HA]. }
  assert (T2 : Rabs (a * (B - b)) <= Rabs a * wb).
  { rewrite Rabs_mult. apply Rmult_le_compat_l; [apply Rabs_pos | exact HB]. }
  assert (T3 : Rabs ((A - a) * (B - b)) <= W * W).
  { rewrite Rabs_mult. apply Rmult_le_compat; try apply Rabs_pos; lra. }
  assert (D : Rabs (A * B - a * b) <= Rabs a * wb + wa * Rabs b + W * W).
  { rewrite E. eapply Rle_trans; [apply Rabs_triang|].
    eapply Rle_trans; [apply Rplus_le_compat_r, Rabs_triang|]. lra. }
  split; [exact D|].
  assert (Rabs a * wb <= 2 * W) by (apply Rmult_le_compat; try lra; apply Rabs_pos).
  assert (wa * Rabs b <= W * 2) by (apply Rmult_le_compat; try lra; apply Rabs_pos).
  replace (A * B) with (a * b + (A * B - a * b)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_mult. lra.
Qed.

(** A computed dot product y within c sum |ah_j bh_j| + e of ah.bh, of the
    scaled approximations lam ah, mu bh (lam mu <= Lm) of a, b with absolute
    weights wa, wb at most W ([fdot_weighted_gen] below, FloatModelK.v's
    [fdot_abs]). *)
Lemma fdot_core : forall (c e Lm lam mu y W : R) (ah bh a b wa wb : vec),
  0 <= c -> 0 <= e ->
  Rabs (y - dot ah bh) <=
    c * (Rabs (vx ah * vx bh) + Rabs (vy ah * vy bh) + Rabs (vz ah * vz bh)) + e ->
  0 < lam -> 0 < mu -> lam * mu <= Lm ->
  vapprox 1 lam ah a wa -> vapprox 1 mu bh b wb -> vbounded a 2 -> vbounded b 2 ->
  0 <= vx wa <= W /\ 0 <= vy wa <= W /\ 0 <= vz wa <= W ->
  0 <= vx wb <= W /\ 0 <= vy wb <= W /\ 0 <= vz wb <= W ->
  Rabs (lam * mu * y - dot a b) <=
    Rabs (vx a) * vx wb + vx wa * Rabs (vx b) + (Rabs (vy a) * vy wb + vy wa * Rabs (vy b))
    + (Rabs (vz a) * vz wb + vz wa * Rabs (vz b)) + 3 * (W * W)
    + c * (Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b)
           + Rabs (vz a) * Rabs (vz b) + 12 * W + 3 * (W * W)) + Lm * e.
Proof.
  intros c e Lm lam mu y W ah bh a b wa wb Hc He F Hl Hm Hlm [Ha1 [Ha2 Ha3]] [Hb1 [Hb2 Hb3]]
    [Ma1 [Ma2 Ma3]] [Mb1 [Mb2 Mb3]] [Wa1 [Wa2 Wa3]] [Wb1 [Wb2 Wb3]].
  rewrite Rmult_1_l in Ha1, Ha2, Ha3, Hb1, Hb2, Hb3.
  destruct (comp_prod_abs _ _ _ _ _ _ W Ha1 Hb1 Ma1 Mb1 Wa1 Wb1) as [Px Qx].
  destruct (comp_prod_abs _ _ _ _ _ _ W Ha2 Hb2 Ma2 Mb2 Wa2 Wb2) as [Py Qy].
  destruct (comp_prod_abs _ _ _ _ _ _ W Ha3 Hb3 Ma3 Mb3 Wa3 Wb3) as [Pz Qz].
  assert (E : lam * mu * y - dot a b =
     lam * mu * (y - dot ah bh)
     + ((lam * vx ah) * (mu * vx bh) - vx a * vx b)
     + ((lam * vy ah) * (mu * vy bh) - vy a * vy b)
     + ((lam * vz ah) * (mu * vz bh) - vz a * vz b)) by (unfold dot; ring).
  rewrite E.
  assert (G : Rabs (lam * mu * (y - dot ah bh)) <=
     c * (Rabs ((lam * vx ah) * (mu * vx bh))
        + Rabs ((lam * vy ah) * (mu * vy bh)) + Rabs ((lam * vz ah) * (mu * vz bh))) + Lm * e).
  { rewrite Rabs_mult, (Rabs_pos_eq (lam * mu)) by nra.
    assert (R1 : forall x z, Rabs ((lam * x) * (mu * z)) = lam * mu * Rabs (x * z)).
    { intros. replace ((lam * x) * (mu * z)) with ((lam * mu) * (x * z)) by ring.
      rewrite Rabs_mult, Rabs_pos_eq by nra. reflexivity. }
    rewrite !R1.
    assert (K : lam * mu * Rabs (y - dot ah bh) <=
              lam * mu * (c * (Rabs (vx ah * vx bh)
                + Rabs (vy ah * vy bh) + Rabs (vz ah * vz bh)) + e))
      by (apply Rmult_le_compat_l; [nra | exact F]).
    assert (K2 : lam * mu * e <= Lm * e) by (apply Rmult_le_compat_r; lra).
    lra. }
  assert (G2 : c * (Rabs ((lam * vx ah) * (mu * vx bh))
        + Rabs ((lam * vy ah) * (mu * vy bh)) + Rabs ((lam * vz ah) * (mu * vz bh)))
        <= c * (Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b)
                + Rabs (vz a) * Rabs (vz b) + 12 * W + 3 * (W * W)))
    by (apply Rmult_le_compat_l; lra).
  eapply Rle_trans; [apply tri4|]. lra.
Qed.

(** A weight in [0, 8] scaled by v > 0 (kept out of the large contexts, where [nra]
    is slow). *)
Lemma scale8 v x : 0 < v -> 0 <= x <= 8 -> 0 <= v * x <= 8 * v.
Proof. intros Hv Hx. split; nra. Qed.

(** A computed dot product y within (3 + 2^-17) v sum |a_j b_j| + 13 eta of
    a.b (the standard model's [fdot]), of the scaled approximations lam ah,
    mu bh of a, b with weights wa, wb. *)
Lemma fdot_weighted_gen : forall (v eta lam mu y : R) (ah bh a b wa wb : vec),
  0 < v <= / 2097152 -> 0 <= eta -> eta * 1152921504606846976 <= v ->
  Rabs (y - dot ah bh) <=
    (3 + / 131072) * v * (Rabs (vx ah * vx bh) + Rabs (vy ah * vy bh) + Rabs (vz ah * vz bh))
    + 13 * eta ->
  0 < lam -> 0 < mu -> lam * mu <= 16777216 ->
  vapprox v lam ah a wa -> vapprox v mu bh b wb ->
  vbounded a 2 -> vbounded b 2 -> wbounded wa -> wbounded wb ->
  Rabs (lam * mu * y - dot a b) <= v * (wsum a b wa wb + / 1000).
Proof.
  intros v eta lam mu y ah bh a b wa wb Hv He He2 F Hl Hm Hlm HA HB Ba Bb
    [Wa1 [Wa2 Wa3]] [Wb1 [Wb2 Wb3]].
  assert (VS : forall l h x w, vapprox v l h x w -> vapprox 1 l h x (vscale v w)).
  { intros l h x w. unfold vapprox, vscale; cbn [vx vy vz]. rewrite !Rmult_1_l. auto. }
  pose proof (fdot_core ((3 + / 131072) * v) (13 * eta) 16777216 lam mu y (8 * v) ah bh a b
    _ _ ltac:(lra) ltac:(lra) F Hl Hm Hlm (VS _ _ _ _ HA) (VS _ _ _ _ HB) Ba Bb) as G.
  unfold vscale in G; cbn [vx vy vz] in G.
  pose proof (scale8 v _ (proj1 Hv) Wa1); pose proof (scale8 v _ (proj1 Hv) Wa2).
  pose proof (scale8 v _ (proj1 Hv) Wa3); pose proof (scale8 v _ (proj1 Hv) Wb1).
  pose proof (scale8 v _ (proj1 Hv) Wb2); pose proof (scale8 v _ (proj1 Hv) Wb3).
  specialize (G ltac:(repeat split; lra) ltac:(repeat split; lra)).
  destruct Ba as [Ma1 [Ma2 Ma3]], Bb as [Mb1 [Mb2 Mb3]].
  set (S := Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b) + Rabs (vz a) * Rabs (vz b))
    in G.
  assert (HS : 0 <= S <= 12).
  { abs_pos3 a. abs_pos3 b. unfold S. split; nra. }
  assert (G3 : v * S <= v * 12) by (apply Rmult_le_compat_l; lra).
  assert (G4 : v * v <= v / 2097152)
    by (assert (v * v <= / 2097152 * v) by (apply Rmult_le_compat_r; lra); lra).
  assert (G5 : v * (v * v) <= v * v) by (rewrite <- (Rmult_1_l (v * v)) at 2; nra).
  unfold wsum. unfold S in *. lra.
Qed.

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

(** One rounded operation in a chain: the exact operand (scaled by lam) is
    [Y], within [e] of the reference [X], and [|X| + e <= M]. *)
Lemma rnd_step : forall lam x Y X e M, 0 <= lam <= 16777216 -> lam * x = Y ->
  Rabs (Y - X) <= e -> Rabs X + e <= M ->
  Rabs (lam * rnd x - X) <= e + (M + / 68719476736) * u.
Proof.
  intros lam x Y X e M Hl HY He HM.
  assert (HB : Rabs (lam * x) <= M) by (rewrite HY; pose proof (abs_near X Y e He); lra).
  pose proof (rnd_sc lam x M Hl HB) as H.
  replace (lam * rnd x - X) with ((lam * rnd x - lam * x) + (Y - X)) by (rewrite <- HY; ring).
  eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.

(** Three-term dot product: |fdot a b - a.b| <= (3 + 2^-17) u sum |a_j b_j| + 13 eta. *)
Lemma fdot_round : forall a b : vec,
  Rabs (fdot rnd a b - dot a b) <=
  (3 + / 131072) * u * (Rabs (vx a * vx b) + Rabs (vy a * vy b) + Rabs (vz a * vz b))
  + 13 * eta.
Proof.
  intros a b. unfold fdot, dot.
  pose proof u_pos. pose proof u_small. pose proof eta_pos.
  eapply Rle_trans; [eapply (sum_chain_abs u u eta); try apply Hstd; lra|].
  pose proof (Rabs_pos (vx a * vx b)). pose proof (Rabs_pos (vy a * vy b)).
  pose proof (Rabs_pos (vz a * vz b)). nra.
Qed.

Lemma u_u : forall z, 0 <= z -> u * (u * z) <= / 16777216 * (u * z).
Proof.
  intros z Hz. pose proof u_pos. pose proof u_small.
  apply Rmult_le_compat_r; [apply Rmult_le_pos|]; lra.
Qed.

(** Weighted error of a dot product of two approximated vectors: component j
    of [lam ah] is within [u * wa_j] of [a_j], component j of [mu bh] within
    [u * wb_j] of [b_j]. *)
Lemma fdot_weighted : forall (lam mu : R) (ah bh a b wa wb : vec),
  0 < lam -> 0 < mu -> lam * mu <= 16777216 ->
  vapprox u lam ah a wa -> vapprox u mu bh b wb ->
  vbounded a 2 -> vbounded b 2 -> wbounded wa -> wbounded wb ->
  Rabs (lam * mu * fdot rnd ah bh - dot a b) <= u * (wsum a b wa wb + / 1000).
Proof.
  intros lam mu ah bh a b wa wb. pose proof u_pos. pose proof u_small.
  pose proof eta_pos. pose proof eta_small. pose proof (fdot_round ah bh).
  apply (fdot_weighted_gen u eta); lra.
Qed.

Lemma dot_inst : forall (lam mu : R) (ah bh a b wa wb : vec) (K : R),
  0 < lam -> 0 < mu -> lam * mu <= 16777216 ->
  vapprox u lam ah a wa -> vapprox u mu bh b wb ->
  vbounded a 2 -> vbounded b 2 -> wbounded wa -> wbounded wb ->
  wsum a b wa wb + / 1000 <= K ->
  Rabs (lam * mu * fdot rnd ah bh - dot a b) <= K * u.
Proof.
  intros. eapply Rle_trans; [eapply fdot_weighted; eassumption|].
  rewrite (Rmult_comm K). apply Rmult_le_compat_l; [pose proof u_pos; lra | assumption].
Qed.

End Model.
