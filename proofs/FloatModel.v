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
    bounds [floop_err], [gloop_err] are FloatModelK.v's relational loops at
    one rounding function. *)

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

(** The product of two approximations (unit v: u of the standard model,
    or v of FloatModelK.v's section V). *)
Lemma comp_prod_gen : forall v, 0 < v <= / 2097152 -> forall A a B b wa wb,
  Rabs (A - a) <= v * wa -> Rabs (B - b) <= v * wb ->
  Rabs a <= 2 -> Rabs b <= 2 -> 0 <= wa <= 8 -> 0 <= wb <= 8 ->
  Rabs (A * B - a * b) <= v * (Rabs a * wb + wa * Rabs b) + 64 * (v * v)
  /\ Rabs (A * B) <= Rabs a * Rabs b + 33 * v.
Proof.
  intros v Hv A a B b wa wb HA HB Ha Hb Hwa Hwb.
  assert (E : A * B - a * b = (A - a) * b + a * (B - b) + (A - a) * (B - b)) by ring.
  assert (T1 : Rabs ((A - a) * b) <= v * wa * Rabs b).
  { rewrite Rabs_mult. apply Rmult_le_compat_r; [apply Rabs_pos | exact HA]. }
  assert (T2 : Rabs (a * (B - b)) <= Rabs a * (v * wb)).
  { rewrite Rabs_mult. apply Rmult_le_compat_l; [apply Rabs_pos | exact HB]. }
  assert (T3 : Rabs ((A - a) * (B - b)) <= (v * wa) * (v * wb)).
  { rewrite Rabs_mult. apply Rmult_le_compat; try apply Rabs_pos; assumption. }
  assert (T4 : (v * wa) * (v * wb) <= 64 * (v * v)).
  { replace ((v * wa) * (v * wb)) with ((v * v) * (wa * wb)) by ring.
    replace (64 * (v * v)) with ((v * v) * 64) by ring.
    apply Rmult_le_compat_l; [nra|]. nra. }
  assert (D : Rabs (A * B - a * b) <= v * (Rabs a * wb + wa * Rabs b) + 64 * (v * v)).
  { rewrite E. eapply Rle_trans; [apply Rabs_triang|].
    eapply Rle_trans; [apply Rplus_le_compat_r, Rabs_triang|]. nra. }
  split; [exact D|].
  assert (M1 : v * (Rabs a * wb + wa * Rabs b) <= v * 32).
  { apply Rmult_le_compat_l; [lra|].
    assert (Rabs a * wb <= 2 * 8) by (apply Rmult_le_compat; try lra; apply Rabs_pos).
    assert (wa * Rabs b <= 8 * 2) by (apply Rmult_le_compat; try lra; apply Rabs_pos).
    lra. }
  assert (M2 : v * v <= v / 2097152).
  { assert (v * v <= / 2097152 * v) by (apply Rmult_le_compat_r; lra). lra. }
  replace (A * B) with (a * b + (A * B - a * b)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_mult. lra.
Qed.

(** A computed dot product y within (3 + 2^-17) v sum |a_j b_j| + 13 eta of
    a.b (the standard model's [fdot], or FloatModelK.v's [fdot_rel]), of the
    scaled approximations lam ah, mu bh of a, b with weights wa, wb. *)
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
  intros v eta lam mu y ah bh a b wa wb Hv He He2 F Hl Hm Hlm [Ha1 [Ha2 Ha3]] [Hb1 [Hb2 Hb3]]
    [Ma1 [Ma2 Ma3]] [Mb1 [Mb2 Mb3]] [Wa1 [Wa2 Wa3]] [Wb1 [Wb2 Wb3]].
  pose proof (comp_prod_gen v Hv) as comp_prod.
  destruct (comp_prod _ _ _ _ _ _ Ha1 Hb1 Ma1 Mb1 Wa1 Wb1) as [Px Qx].
  destruct (comp_prod _ _ _ _ _ _ Ha2 Hb2 Ma2 Mb2 Wa2 Wb2) as [Py Qy].
  destruct (comp_prod _ _ _ _ _ _ Ha3 Hb3 Ma3 Mb3 Wa3 Wb3) as [Pz Qz].
  assert (E : lam * mu * y - dot a b =
     lam * mu * (y - dot ah bh)
     + ((lam * vx ah) * (mu * vx bh) - vx a * vx b)
     + ((lam * vy ah) * (mu * vy bh) - vy a * vy b)
     + ((lam * vz ah) * (mu * vz bh) - vz a * vz b)) by (unfold dot; ring).
  rewrite E.
  assert (G : Rabs (lam * mu * (y - dot ah bh)) <=
     (3 + / 131072) * v * (Rabs ((lam * vx ah) * (mu * vx bh))
        + Rabs ((lam * vy ah) * (mu * vy bh)) + Rabs ((lam * vz ah) * (mu * vz bh)))
     + 13 * (16777216 * eta)).
  { rewrite Rabs_mult, (Rabs_pos_eq (lam * mu)) by nra.
    assert (R1 : forall x z, Rabs ((lam * x) * (mu * z)) = lam * mu * Rabs (x * z)).
    { intros. replace ((lam * x) * (mu * z)) with ((lam * mu) * (x * z)) by ring.
      rewrite Rabs_mult, Rabs_pos_eq by nra. reflexivity. }
    rewrite !R1.
    assert (K : lam * mu * Rabs (y - dot ah bh) <=
              lam * mu * ((3 + / 131072) * v * (Rabs (vx ah * vx bh)
                + Rabs (vy ah * vy bh) + Rabs (vz ah * vz bh)) + 13 * eta))
      by (apply Rmult_le_compat_l; [nra | exact F]).
    assert (K2 : lam * mu * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
    nra. }
  set (S := Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b) + Rabs (vz a) * Rabs (vz b)).
  assert (HS0 : 0 <= S).
  { unfold S. pose proof (Rabs_pos (vx a)). pose proof (Rabs_pos (vy a)).
    pose proof (Rabs_pos (vz a)). pose proof (Rabs_pos (vx b)).
    pose proof (Rabs_pos (vy b)). pose proof (Rabs_pos (vz b)). nra. }
  assert (HS : S <= 12).
  { unfold S.
    assert (Rabs (vx a) * Rabs (vx b) <= 2 * 2) by (apply Rmult_le_compat; try apply Rabs_pos; lra).
    assert (Rabs (vy a) * Rabs (vy b) <= 2 * 2) by (apply Rmult_le_compat; try apply Rabs_pos; lra).
    assert (Rabs (vz a) * Rabs (vz b) <= 2 * 2) by (apply Rmult_le_compat; try apply Rabs_pos; lra).
    lra. }
  assert (G2 : (3 + / 131072) * v * (Rabs ((lam * vx ah) * (mu * vx bh))
        + Rabs ((lam * vy ah) * (mu * vy bh)) + Rabs ((lam * vz ah) * (mu * vz bh)))
        <= (3 + / 131072) * v * (S + 99 * v)).
  { apply Rmult_le_compat_l; [lra|]. unfold S. lra. }
  assert (G3 : v * S <= v * 12) by (apply Rmult_le_compat_l; lra).
  assert (G4 : v * v <= v / 2097152)
    by (assert (v * v <= / 2097152 * v) by (apply Rmult_le_compat_r; lra); lra).
  assert (G5 : 0 <= v * S) by (apply Rmult_le_pos; lra).
  unfold wsum. fold S.
  eapply Rle_trans; [apply tri4|]. unfold S in *. lra.
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
  eapply Rle_trans; [apply tri5|].
  assert (Hx1 : 0 <= Rabs x1) by apply Rabs_pos.
  assert (Hx2 : 0 <= Rabs x2) by apply Rabs_pos.
  assert (Hx3 : 0 <= Rabs x3) by apply Rabs_pos.
  assert (Hu1 : 0 <= u * Rabs x1) by (apply Rmult_le_pos; lra).
  assert (Hu2 : 0 <= u * Rabs x2) by (apply Rmult_le_pos; lra).
  assert (Hu3 : 0 <= u * Rabs x3) by (apply Rmult_le_pos; lra).
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
  pose proof (Rabs_pos (vx ah * vx bh)). pose proof (Rabs_pos (vy ah * vy bh)).
  pose proof (Rabs_pos (vz ah * vz bh)).
  apply (fdot_weighted_gen u eta); try lra. eapply Rle_trans; [eassumption|].
  apply Rplus_le_compat_r, Rmult_le_compat_r; lra.
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
