(** * Float.v — floating-point error bounds for the corrected Euler (eqs.
    16-17) and Gouraud recurrences, computed exactly as the Rust crate
    computes them (src/span.rs set-up, src/corrected_euler.rs and
    src/gouraud.rs loops), with every operation rounded to nearest-even in
    binary32 or binary64 (Flocq), against the exact real-number values of
    Span.v / Euler.v / Adaptive.v on the exact (unrounded) inputs.

    The model of the computation (every [rnd] is one rounded operation;
    n, 2n and n(n-1)/2 are exact integers of the format since n <= 4096):
      inputs   na = rnd Na, nb = rnd Nb, l = rnd L (componentwise)
      dot      fdot a b = rnd (rnd (rnd (ax bx) + rnd (ay by)) + rnd (az bz))
      k_j      = rnd (rnd (nb_j - na_j) / n)
      a = fdot k l, pa = fdot na l, c = fdot k k, d = rnd (2 fdot k na),
      pb = fdot nb l, dqb = rnd (rnd ((2n) c) + d),
      dia = rnd (a - rnd (rnd (pa/2) d)), dib = rnd (a - rnd (rnd (pb/2) dqb)),
      ds = rnd (rnd (dib - dia) / n),
      pn = rnd (rnd (pa + rnd (n dia)) + rnd (tri ds)), tri = n(n-1)/2,
      eps = rnd (pn - pb), t0 = rnd (dia - rnd (eps / n)),
      dp = rnd (rnd (pb - pa) / n);
      corrected Euler: P_0 = pa, S_0 = t0, P' = rnd (P + S), S' = rnd (S + ds);
      Gouraud: G_0 = pa, G' = rnd (G + dp). *)

From Coq Require Import Reals Lra Lia.
From Flocq Require Import Core.
From PhongApprox Require Import Span Euler Adaptive FloatModel.
From PhongApprox Require FloatModelK.
Open Scope R_scope.

(** ** The float computation, for a rounding function [rnd] *)

Definition rvec (rnd : R -> R) (v : vec) : vec :=
  mkV (rnd (vx v)) (rnd (vy v)) (rnd (vz v)).
Definition fk (rnd : R -> R) (m : R) (na nb : vec) : vec :=
  mkV (rnd (rnd (vx nb - vx na) / m)) (rnd (rnd (vy nb - vy na) / m))
      (rnd (rnd (vz nb - vz na) / m)).

Definition f_k (rnd : R -> R) (s : span) : vec :=
  fk rnd (INR (n s)) (rvec rnd (Na s)) (rvec rnd (Nb s)).
Definition f_pa (rnd : R -> R) (s : span) : R := fdot rnd (rvec rnd (Na s)) (rvec rnd (L s)).
Definition f_pb (rnd : R -> R) (s : span) : R := fdot rnd (rvec rnd (Nb s)) (rvec rnd (L s)).
Definition f_a (rnd : R -> R) (s : span) : R := fdot rnd (f_k rnd s) (rvec rnd (L s)).
Definition f_c (rnd : R -> R) (s : span) : R := fdot rnd (f_k rnd s) (f_k rnd s).
Definition f_d (rnd : R -> R) (s : span) : R :=
  rnd (2 * fdot rnd (f_k rnd s) (rvec rnd (Na s))).
Definition f_dqb (rnd : R -> R) (s : span) : R :=
  rnd (rnd (2 * INR (n s) * f_c rnd s) + f_d rnd s).
Definition f_dia (rnd : R -> R) (s : span) : R :=
  rnd (f_a rnd s - rnd (rnd (f_pa rnd s / 2) * f_d rnd s)).
Definition f_dib (rnd : R -> R) (s : span) : R :=
  rnd (f_a rnd s - rnd (rnd (f_pb rnd s / 2) * f_dqb rnd s)).
Definition f_ds (rnd : R -> R) (s : span) : R :=
  rnd (rnd (f_dib rnd s - f_dia rnd s) / INR (n s)).
Definition f_tri (s : span) : R := INR (n s) * (INR (n s) - 1) / 2.
Definition f_pn (rnd : R -> R) (s : span) : R :=
  rnd (rnd (f_pa rnd s + rnd (INR (n s) * f_dia rnd s)) + rnd (f_tri s * f_ds rnd s)).
Definition f_eps (rnd : R -> R) (s : span) : R := rnd (f_pn rnd s - f_pb rnd s).
Definition f_deps (rnd : R -> R) (s : span) : R := rnd (f_eps rnd s / INR (n s)).
Definition f_t0 (rnd : R -> R) (s : span) : R := rnd (f_dia rnd s - f_deps rnd s).
Definition f_dp (rnd : R -> R) (s : span) : R :=
  rnd (rnd (f_pb rnd s - f_pa rnd s) / INR (n s)).

(** Output pixel i of the two loops. *)
Definition f_ceuler (rnd : R -> R) (s : span) (i : nat) : R :=
  fst (floop rnd (f_pa rnd s) (f_t0 rnd s) (f_ds rnd s) i).
Definition f_gouraud (rnd : R -> R) (s : span) (i : nat) : R :=
  gloop rnd (f_pa rnd s) (f_dp rnd s) i.

(** ** Real-number facts for unit vectors *)

Lemma abs_sq : forall x, Rabs x * Rabs x = x * x.
Proof. intros x. rewrite <- Rabs_mult. apply Rabs_pos_eq. nra. Qed.

Lemma amgm1 : forall x y, Rabs x * Rabs y <= (x * x + y * y) / 2.
Proof.
  intros x y. rewrite <- (abs_sq x), <- (abs_sq y).
  pose proof (Rle_0_sqr (Rabs x - Rabs y)). unfold Rsqr in *. nra.
Qed.

Lemma amgm2 : forall x y, Rabs x * Rabs y <= x * x / 4 + y * y.
Proof.
  intros x y. rewrite <- (abs_sq x), <- (abs_sq y).
  pose proof (Rle_0_sqr (Rabs x - 2 * Rabs y)). unfold Rsqr in *. nra.
Qed.

Lemma abs_le_of_sq : forall x M, 0 <= M -> x * x <= M * M -> Rabs x <= M.
Proof. intros x M HM H. apply Rabs_le. split; nra. Qed.

Lemma dot_abs : forall a b : vec,
  Rabs (dot a b) <= Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b)
                    + Rabs (vz a) * Rabs (vz b).
Proof.
  intros a b. unfold dot. rewrite <- !Rabs_mult.
  eapply Rle_trans; [apply Rabs_triang|]. apply Rplus_le_compat_r, Rabs_triang.
Qed.

Lemma unit_bounded : forall v, is_unit v -> vbounded v 1.
Proof.
  intros v H. unfold is_unit, dot in H. unfold vbounded.
  pose proof (Rle_0_sqr (vx v)). pose proof (Rle_0_sqr (vy v)).
  pose proof (Rle_0_sqr (vz v)). unfold Rsqr in *.
  repeat split; apply abs_le_of_sq; lra.
Qed.

Lemma unit_pair : forall a b, is_unit a -> is_unit b ->
  Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b) + Rabs (vz a) * Rabs (vz b) <= 1.
Proof.
  intros a b Ha Hb. unfold is_unit, dot in *.
  pose proof (amgm1 (vx a) (vx b)). pose proof (amgm1 (vy a) (vy b)).
  pose proof (amgm1 (vz a) (vz b)). lra.
Qed.

Lemma unit_abs_sq : forall a, is_unit a ->
  Rabs (vx a) * Rabs (vx a) + Rabs (vy a) * Rabs (vy a) + Rabs (vz a) * Rabs (vz a) = 1.
Proof. intros a Ha. unfold is_unit, dot in Ha. rewrite !abs_sq. lra. Qed.

(** Differences Dl = b - a of two unit vectors. *)
Lemma diff_sq : forall a b, is_unit a -> is_unit b ->
  dot (vsub b a) (vsub b a) <= 4.
Proof.
  intros a b Ha Hb. unfold is_unit, dot, vsub in *; cbn [vx vy vz].
  pose proof (Rle_0_sqr (vx a + vx b)). pose proof (Rle_0_sqr (vy a + vy b)).
  pose proof (Rle_0_sqr (vz a + vz b)). unfold Rsqr in *. nra.
Qed.

Lemma diff_bounded : forall a b, is_unit a -> is_unit b -> vbounded (vsub b a) 2.
Proof.
  intros a b Ha Hb. destruct (unit_bounded a Ha) as [A1 [A2 A3]].
  destruct (unit_bounded b Hb) as [B1 [B2 B3]].
  unfold vbounded, vsub; cbn [vx vy vz].
  repeat split; (eapply Rle_trans; [apply Rabs_triang|]); rewrite Rabs_Ropp; lra.
Qed.

Lemma diff_pair : forall a b c, is_unit a -> is_unit b -> is_unit c ->
  Rabs (vx (vsub b a)) * Rabs (vx c) + Rabs (vy (vsub b a)) * Rabs (vy c)
  + Rabs (vz (vsub b a)) * Rabs (vz c) <= 2.
Proof.
  intros a b c Ha Hb Hc. pose proof (diff_sq a b Ha Hb) as D.
  unfold is_unit, dot in *.
  pose proof (amgm2 (vx (vsub b a)) (vx c)). pose proof (amgm2 (vy (vsub b a)) (vy c)).
  pose proof (amgm2 (vz (vsub b a)) (vz c)). lra.
Qed.

Lemma diff_abs_sq : forall a b, is_unit a -> is_unit b ->
  Rabs (vx (vsub b a)) * Rabs (vx (vsub b a)) + Rabs (vy (vsub b a)) * Rabs (vy (vsub b a))
  + Rabs (vz (vsub b a)) * Rabs (vz (vsub b a)) <= 4.
Proof.
  intros a b Ha Hb. pose proof (diff_sq a b Ha Hb) as D. unfold dot in D.
  rewrite !abs_sq. lra.
Qed.

(** |Dl . w| <= |Dl|^2/4 + |w|^2 *)
Lemma diff_dot_le : forall (d w : vec), Rabs (dot d w) <= dot d d / 4 + dot w w.
Proof.
  intros d w. eapply Rle_trans; [apply dot_abs|]. unfold dot.
  pose proof (amgm2 (vx d) (vx w)). pose proof (amgm2 (vy d) (vy w)).
  pose proof (amgm2 (vz d) (vz w)). lra.
Qed.

(** Pure helpers for the combinations of the exact values and of the final bounds. *)
Lemma theta_rng : forall m i, 1 <= m -> 0 <= i <= m -> 0 <= i / m <= 1.
Proof.
  intros m i Hm Hi. split.
  - unfold Rdiv. apply Rmult_le_pos; [lra | apply Rlt_le, Rinv_0_lt_compat; lra].
  - apply (Rmult_le_reg_r m); [lra|]. unfold Rdiv.
    rewrite Rmult_assoc, Rinv_l by lra. lra.
Qed.

Lemma inr_rng : forall i m : nat, (i <= m)%nat -> 0 <= INR i <= INR m.
Proof. intros i m H. split; [apply pos_INR | apply le_INR; exact H]. Qed.

Lemma kappa_rng : forall m i, 1 <= m -> 0 <= i <= m ->
  0 <= i * (m - i) / (2 * (m * m)) <= 1 / 8.
Proof.
  intros m i Hm Hi. split.
  - unfold Rdiv. apply Rmult_le_pos; [nra | apply Rlt_le, Rinv_0_lt_compat; nra].
  - apply (Rmult_le_reg_r (2 * (m * m))); [nra|]. unfold Rdiv.
    rewrite Rmult_assoc, Rinv_l by nra.
    pose proof (Rle_0_sqr (m - 2 * i)). unfold Rsqr in *. nra.
Qed.

Lemma comb_bound : forall th ka a b r d ea er ed,
  0 <= th <= 1 -> 0 <= ka <= 1 / 8 ->
  Rabs a <= ea -> Rabs b <= ea -> Rabs r <= er -> Rabs d <= ed ->
  Rabs ((1 - th) * a + th * b + th * r - ka * d) <= ea + er + ed / 8.
Proof.
  intros th ka a b r d ea er ed Ht Hk Ha Hb Hr Hd.
  replace ((1 - th) * a + th * b + th * r - ka * d)
    with ((1 - th) * a + th * b + th * r + - (ka * d)) by ring.
  eapply Rle_trans; [apply tri4|].
  rewrite Rabs_Ropp, !Rabs_mult, (Rabs_pos_eq th), (Rabs_pos_eq (1 - th)), (Rabs_pos_eq ka)
    by lra.
  assert ((1 - th) * Rabs a <= (1 - th) * ea) by (apply Rmult_le_compat_l; lra).
  assert (th * Rabs b <= th * ea) by (apply Rmult_le_compat_l; lra).
  assert (th * Rabs r <= 1 * er) by (apply Rmult_le_compat; try lra; apply Rabs_pos).
  assert (ka * Rabs d <= 1 / 8 * ed) by (apply Rmult_le_compat; try lra; apply Rabs_pos).
  lra.
Qed.

(** ** The exact set-up, scaled by n (unit normals and light) *)

Definition e_ndia (s : span) : R :=
  dot (vsub (Nb s) (Na s)) (L s) - pa s * dot (vsub (Nb s) (Na s)) (Na s).
Definition e_ndib (s : span) : R :=
  dot (vsub (Nb s) (Na s)) (L s) - pb s * dot (vsub (Nb s) (Na s)) (Nb s).
Definition e_n2ds (s : span) : R := e_ndib s - e_ndia s.

Section Exact.
Context (s : span) (Hua : is_unit (Na s)) (Hub : is_unit (Nb s)) (Hul : is_unit (L s))
        (Hn1 : (1 <= n s)%nat).

Lemma nr_ge1 : 1 <= INR (n s).
Proof. apply (le_INR 1). exact Hn1. Qed.

Lemma dia_scaled : dia s = e_ndia s / INR (n s).
Proof.
  pose proof nr_ge1.
  unfold e_ndia, dia, dqa, A, D, k, pa, dot, vscale, vsub; cbn [vx vy vz]. field. lra.
Qed.

Lemma ds_scaled : ds s = e_n2ds s / (INR (n s) * INR (n s)).
Proof.
  pose proof nr_ge1.
  unfold e_n2ds, e_ndib, e_ndia, ds, dib, dia, dqb, dqa, A, C, D, k, pa, pb, dot, vscale, vsub;
    cbn [vx vy vz]. field. lra.
Qed.

Lemma pa_le : Rabs (pa s) <= 1.
Proof. unfold pa. eapply Rle_trans; [apply dot_abs|]. apply unit_pair; assumption. Qed.
Lemma pb_le : Rabs (pb s) <= 1.
Proof. unfold pb. eapply Rle_trans; [apply dot_abs|]. apply unit_pair; assumption. Qed.

Lemma dl_dot_le : forall c : vec, is_unit c -> Rabs (dot (vsub (Nb s) (Na s)) c) <= 2.
Proof.
  intros c Hc. eapply Rle_trans; [apply dot_abs|]. apply diff_pair; assumption.
Qed.

Lemma dl_na : dot (vsub (Nb s) (Na s)) (Na s) = dot (Na s) (Nb s) - 1.
Proof. unfold is_unit in Hua. rewrite <- Hua. unfold dot, vsub; cbn [vx vy vz]. ring. Qed.
Lemma dl_nb : dot (vsub (Nb s) (Na s)) (Nb s) = 1 - dot (Na s) (Nb s).
Proof. unfold is_unit in Hub. rewrite <- Hub. unfold dot, vsub; cbn [vx vy vz]. ring. Qed.

(** |n di_a| <= 2: n di_a = Dl . (L - p_a Na) and |L - p_a Na|^2 = 1 - p_a^2. *)
(** n di at an edge X (Na or Nb), scaled: |Dl.L - (X.L)(Dl.X)| <= 2. *)
Lemma nd_le : forall X, is_unit X ->
  Rabs (dot (vsub (Nb s) (Na s)) (L s) - dot X (L s) * dot (vsub (Nb s) (Na s)) X) <= 2.
Proof.
  intros X HX.
  set (w := mkV (vx (L s) - dot X (L s) * vx X) (vy (L s) - dot X (L s) * vy X)
                (vz (L s) - dot X (L s) * vz X)).
  assert (E : dot (vsub (Nb s) (Na s)) (L s) - dot X (L s) * dot (vsub (Nb s) (Na s)) X
              = dot (vsub (Nb s) (Na s)) w) by (unfold w, dot, vsub; cbn [vx vy vz]; ring).
  assert (Ew : dot w w = dot (L s) (L s) - 2 * dot X (L s) * dot X (L s)
                         + dot X (L s) * dot X (L s) * dot X X).
  { unfold w, dot; cbn [vx vy vz]. ring. }
  unfold is_unit in *. rewrite Hul, HX in Ew.
  pose proof (diff_sq (Na s) (Nb s) Hua Hub).
  rewrite E. eapply Rle_trans; [apply diff_dot_le|]. nra.
Qed.

Lemma ndia_le : Rabs (e_ndia s) <= 2.
Proof. exact (nd_le (Na s) Hua). Qed.
Lemma ndib_le : Rabs (e_ndib s) <= 2.
Proof. exact (nd_le (Nb s) Hub). Qed.

(** n^2 ds = -(1 - Na.Nb)(p_a + p_b), and |n^2 ds| <= 2 (Cauchy-Schwarz). *)
Lemma n2ds_form : e_n2ds s = - (1 - dot (Na s) (Nb s)) * (pa s + pb s).
Proof. unfold e_n2ds, e_ndib, e_ndia. rewrite dl_na, dl_nb. ring. Qed.

(** The sharp form: |n^2 ds| <= 1.54 (max of (1-c) sqrt(2(1+c)) is (4/3)^(3/2) = 1.5396). *)
Lemma n2ds_le' : Rabs (e_n2ds s) <= 154 / 100.
Proof.
  rewrite n2ds_form. set (c := dot (Na s) (Nb s)).
  pose proof (unit_dot_bounds _ _ Hua Hub) as Hc. fold c in Hc.
  set (S := vadd (Na s) (Nb s)).
  assert (ES : dot S S = 2 + 2 * c).
  { unfold is_unit in *. unfold c.
    replace 2 with (dot (Na s) (Na s) + dot (Nb s) (Nb s)) at 1 by lra.
    unfold S, vadd, dot; cbn [vx vy vz]. ring. }
  assert (EL : pa s + pb s = dot S (L s)).
  { unfold S, pa, pb, vadd, dot; cbn [vx vy vz]. ring. }
  pose proof (cs3 S (L s)) as CS. unfold is_unit in Hul. rewrite Hul, ES, <- EL in CS.
  apply abs_le_of_sq; [lra|].
  set (x := 1 - c). assert (0 <= x <= 2) by (unfold x; lra).
  replace (- x * (pa s + pb s) * (- x * (pa s + pb s)))
    with ((x * x) * ((pa s + pb s) * (pa s + pb s))) by ring.
  assert ((x * x) * ((pa s + pb s) * (pa s + pb s)) <= (x * x) * (2 + 2 * c))
    by (apply Rmult_le_compat_l; nra).
  replace c with (1 - x) in * by (unfold x; ring).
  assert (0 <= 2 * ((x - 4 / 3) * (x - 4 / 3)) * (x + 2 / 3)).
  { apply Rmult_le_pos; [|lra]. pose proof (Rle_0_sqr (x - 4 / 3)). unfold Rsqr in *. lra. }
  nra.
Qed.

Lemma n2ds_le : Rabs (e_n2ds s) <= 2.
Proof. pose proof n2ds_le'. lra. Qed.

(** Exact magnitudes along the span. *)
Lemma gouraud_le : forall i, (i <= n s)%nat -> Rabs (gouraud s i) <= 1.
Proof.
  intros i Hi. pose proof nr_ge1.
  pose proof (inr_rng i (n s) Hi) as Hi'.
  set (th := INR i / INR (n s)).
  replace (gouraud s i) with ((1 - th) * pa s + th * pb s + th * 0 - 0 * 0)
    by (unfold gouraud, dp, th; field; lra).
  eapply Rle_trans; [apply (comb_bound _ _ _ _ _ _ 1 0 0); rewrite ?Rabs_R0;
    try apply theta_rng; try apply pa_le; try apply pb_le; lra |]. lra.
Qed.

Lemma ceuler_le : forall i, (i <= n s)%nat -> Rabs (ceuler s i) <= 11925 / 10000.
Proof.
  intros i Hi. pose proof nr_ge1. pose proof n2ds_le'.
  pose proof (inr_rng i (n s) Hi) as Hi'.
  assert (E := eq_24_gouraud_minus_corrected_euler s i ltac:(lia)).
  replace (ceuler s i) with (gouraud s i - ds s / 2 * INR i * (INR (n s) - INR i)) by lra.
  rewrite ds_scaled. unfold gouraud, dp.
  set (th := INR i / INR (n s)).
  set (kap := INR i * (INR (n s) - INR i) / (2 * (INR (n s) * INR (n s)))).
  replace (pa s + INR i * ((pb s - pa s) / INR (n s))
           - e_n2ds s / (INR (n s) * INR (n s)) / 2 * INR i * (INR (n s) - INR i))
    with ((1 - th) * pa s + th * pb s + th * 0 - kap * e_n2ds s) by (unfold th, kap; field; lra).
  eapply Rle_trans; [apply (comb_bound _ _ _ _ _ _ 1 0 (154 / 100)); rewrite ?Rabs_R0;
    try apply theta_rng; try apply kappa_rng; try apply pa_le; try apply pb_le; lra |]. lra.
Qed.

(** |n (t0 + j ds)| <= 2 for 0 <= j <= n - 1: n (t0 + j ds) = w . L with
    w = (1 - g x) Nb - (1 + g x) Na, x = 1 - Na.Nb, |g| <= 1/2, and
    |w|^2 = 2x + 2 g^2 x^2 (2 - x) <= 4. *)
Lemma slope_le : forall j, (j < n s)%nat ->
  Rabs (INR (n s) * (t0 s + INR j * ds s)) <= 2.
Proof.
  intros j Hj. pose proof nr_ge1.
  assert (Hj' : INR j + 1 <= INR (n s)) by (rewrite <- S_INR; apply le_INR; lia).
  pose proof (pos_INR j).
  rewrite (t0_closed_form s ltac:(lia)), ds_scaled.
  set (g := (2 * INR j - INR (n s) + 1) / (2 * INR (n s))).
  assert (Hg : Rabs g <= 1 / 2).
  { pose proof (theta_rng (INR (n s)) ((2 * INR j + 1) / 2) ltac:(lra) ltac:(lra)).
    replace g with ((2 * INR j + 1) / 2 / INR (n s) - 1 / 2) by (unfold g; field; lra).
    apply Rabs_le. lra. }
  replace (INR (n s) * ((pb s - pa s) / INR (n s)
             - (INR (n s) - 1) / 2 * (e_n2ds s / (INR (n s) * INR (n s)))
             + INR j * (e_n2ds s / (INR (n s) * INR (n s)))))
    with ((pb s - pa s) + g * e_n2ds s) by (unfold g; field; lra).
  rewrite n2ds_form. set (c := dot (Na s) (Nb s)).
  pose proof (unit_dot_bounds _ _ Hua Hub) as Hc. fold c in Hc.
  set (x := 1 - c). assert (Hx : 0 <= x <= 2) by (unfold x; lra).
  set (w := mkV ((1 - g * x) * vx (Nb s) - (1 + g * x) * vx (Na s))
                ((1 - g * x) * vy (Nb s) - (1 + g * x) * vy (Na s))
                ((1 - g * x) * vz (Nb s) - (1 + g * x) * vz (Na s))).
  assert (EwL : pb s - pa s + g * (- x * (pa s + pb s)) = dot w (L s)).
  { unfold w, pa, pb, dot; cbn [vx vy vz]. ring. }
  assert (Eww : dot w w = (1 - g * x) * (1 - g * x) * dot (Nb s) (Nb s)
                          + (1 + g * x) * (1 + g * x) * dot (Na s) (Na s)
                          - 2 * ((1 - g * x) * (1 + g * x)) * dot (Na s) (Nb s)).
  { unfold w, dot; cbn [vx vy vz]. ring. }
  unfold is_unit in Hua, Hub. rewrite Hua, Hub in Eww. fold c in Eww.
  replace c with (1 - x) in Eww by (unfold x; ring).
  pose proof (cs3 w (L s)) as CS. unfold is_unit in Hul. rewrite Hul, <- EwL, Eww in CS.
  apply abs_le_of_sq; [lra|].
  assert (Hg2 : g * g <= 1 / 4).
  { pose proof (Rabs_pos g). rewrite <- abs_sq. nra. }
  assert (K : 0 <= x * x * (2 - x)) by (apply Rmult_le_pos; nra).
  assert (K2 : g * g * (x * x * (2 - x)) <= 1 / 4 * (x * x * (2 - x)))
    by (apply Rmult_le_compat_r; lra).
  assert (K3 : 0 <= (x - 2) * (x - 2) * (x + 2)) by (apply Rmult_le_pos; nra).
  nra.
Qed.

(** ** The float set-up, step by step *)

(** Weights of the componentwise errors: inputs (|x_j| + 2^-30) and
    n k_j (3.001 (|Na_j| + |Nb_j|) + 2^-28). *)
Definition wIn (v : vec) : vec :=
  mkV (Rabs (vx v) + / 1073741824) (Rabs (vy v) + / 1073741824) (Rabs (vz v) + / 1073741824).
Definition wK (a b : vec) : vec :=
  mkV (3001 / 1000 * (Rabs (vx a) + Rabs (vx b)) + / 268435456)
      (3001 / 1000 * (Rabs (vy a) + Rabs (vy b)) + / 268435456)
      (3001 / 1000 * (Rabs (vz a) + Rabs (vz b)) + / 268435456).

Lemma vb12 : forall v, vbounded v 1 -> vbounded v 2.
Proof. intros v [A [B C]]. repeat split; lra. Qed.

Lemma ce_identity : forall m i PA PB pa pb t d n2, m <> 0 ->
  PA + i * t + i * (i - 1) / 2 * d
  - (pa + i * ((pb - pa) / m - (m - 1) / 2 * (n2 / (m * m))) + (i ^ 2 - i) / 2 * (n2 / (m * m)))
  = (1 - i / m) * (PA - pa) + i / m * (PB - pb)
    + i / m * (m * t - (PB - PA - (m - 1) / (2 * m) * (m * m * d)))
    - i * (m - i) / (2 * (m * m)) * (m * m * d - n2).
Proof. intros. field. assumption. Qed.

Lemma div_helper : forall m A E c, 0 < m -> A + m * E * m <= c -> A / m + m * E <= c / m.
Proof.
  intros m A E c Hm H.
  replace (A / m + m * E) with ((A + m * E * m) * / m) by (field; lra).
  unfold Rdiv. apply Rmult_le_compat_r; [apply Rlt_le, Rinv_0_lt_compat|]; lra.
Qed.

(** n(n-1)/2 x for n^2 x within E <= 0.002 of Y, |Y| <= 2 (the set-up's
    n(n-1)/2 ds, here and in Profiles.v). *)
Lemma Yb_near : forall m x Y E : R, 1 <= m -> Rabs (m * m * x - Y) <= E -> Rabs Y <= 2 ->
  E <= 2 / 1000 -> Rabs (m * (m - 1) / 2 * x) <= 1001 / 1000.
Proof.
  intros m x Y E Hm H HY HE.
  replace (m * (m - 1) / 2 * x) with ((m - 1) / (2 * m) * (m * m * x)) by (field; lra).
  rewrite Rabs_mult.
  assert (Rabs ((m - 1) / (2 * m)) <= 1 / 2).
  { rewrite Rabs_pos_eq.
    - apply (Rmult_le_reg_r (2 * m)); [lra|]. unfold Rdiv.
      rewrite Rmult_assoc, Rinv_l by lra. lra.
    - unfold Rdiv. apply Rmult_le_pos; [lra | apply Rlt_le, Rinv_0_lt_compat; lra]. }
  pose proof (abs_near _ _ _ H).
  replace (1001 / 1000) with (1 / 2 * (2002 / 1000)) by field.
  apply Rmult_le_compat; try apply Rabs_pos; lra.
Qed.

(** The correction t0 = di_a - d_eps on computed p_n, eps, d_eps (within E1, E2,
    E3 of their operands), p_a, p_b (within Ea of pa0, pb0) and |Y| <= 1.001,
    Y = n(n-1)/2 ds; [Hstep] is the rounding of di_a - d_eps scaled by n
    (here and in Profiles.v). *)
Lemma R_near : forall nr w t0 dia deps fpa fpb fpn feps Y pa0 pb0 Ea E1 E2 E3 : R,
  Rabs (fpn - (fpa + nr * dia + Y)) <= E1 -> Rabs (feps - (fpn - fpb)) <= E2 ->
  Rabs (nr * deps - feps) <= E3 -> Rabs (fpa - pa0) <= Ea -> Rabs (fpb - pb0) <= Ea ->
  Rabs pa0 <= 1 -> Rabs pb0 <= 1 -> Rabs Y <= 1001 / 1000 -> 2 * Ea + E1 + E2 + E3 <= / 1000 ->
  (Rabs (nr * (dia - deps)) <= 3002 / 1000 -> Rabs (nr * t0 - nr * (dia - deps)) <= w) ->
  Rabs (nr * t0 - (fpb - fpa - Y)) <= w + E1 + E2 + E3.
Proof.
  intros nr w t0 dia deps fpa fpb fpn feps Y pa0 pb0 Ea E1 E2 E3 G0 G1 G2 G3 G4 P0 P1 HY HE Hstep.
  assert (B : Rabs (nr * (dia - deps)) <= 3002 / 1000).
  { replace (nr * (dia - deps))
      with ((fpb - fpa - Y) + - (fpn - (fpa + nr * dia + Y)) + - (feps - (fpn - fpb))
            + - (nr * deps - feps)) by ring.
    eapply Rle_trans; [apply tri4|]. rewrite !Rabs_Ropp.
    assert (Rabs (fpb - fpa - Y) <= 2 + 2 * Ea + 1001 / 1000).
    { unfold Rminus. eapply Rle_trans; [apply tri3|]. rewrite !Rabs_Ropp.
      pose proof (abs_near _ _ _ G3). pose proof (abs_near _ _ _ G4). lra. }
    lra. }
  pose proof (Hstep B) as RT.
  replace (nr * t0 - (fpb - fpa - Y))
    with ((nr * t0 - nr * (dia - deps)) + - (fpn - (fpa + nr * dia + Y))
          + - (feps - (fpn - fpb)) + - (nr * deps - feps)) by ring.
  eapply Rle_trans; [apply tri4|]. rewrite !Rabs_Ropp. lra.
Qed.

(** The corrected Euler values and slopes on computed p_a, p_b (within Ea),
    t0 (n t0 within ER of p_b - p_a - n(n-1)/2 ds) and ds (n^2 ds within Eds),
    here and in Profiles.v. *)
Context (fpa fpb ft0 fds Ea ER Eds : R) (Hpa : Rabs (fpa - pa s) <= Ea)
        (Hpb : Rabs (fpb - pb s) <= Ea)
        (HR : Rabs (INR (n s) * ft0 - (fpb - fpa - INR (n s) * (INR (n s) - 1) / 2 * fds)) <= ER)
        (Hds : Rabs (INR (n s) * INR (n s) * fds - e_n2ds s) <= Eds).
Local Notation nr := (INR (n s)).

Lemma ce_near : forall i, (i <= n s)%nat ->
  Rabs (fpa + INR i * ft0 + INR i * (INR i - 1) / 2 * fds - ceuler s i) <= Ea + ER + Eds / 8.
Proof.
  intros i Hi. pose proof nr_ge1.
  pose proof (inr_rng i (n s) Hi) as Hi'.
  rewrite ceuler_closed_form, (t0_closed_form s ltac:(lia)), ds_scaled.
  rewrite (ce_identity nr (INR i) fpa fpb) by lra.
  replace (nr * (nr - 1) / 2 * fds) with ((nr - 1) / (2 * nr) * (nr * nr * fds)) in HR
    by (field; lra).
  apply comb_bound; [apply theta_rng; lra | apply kappa_rng; lra | assumption..].
Qed.

(** Computed slopes (ideal, on the computed t0 and ds) for 1 <= J <= n-1. *)
Lemma slope_near : forall J, (J < n s)%nat ->
  Rabs (nr * (ft0 + INR J * fds)) <= 2 + (ER + 2 * Ea + Eds).
Proof.
  intros J HJ. pose proof nr_ge1.
  pose proof (inr_rng J (n s) ltac:(lia)) as HJ'.
  pose proof (slope_le J HJ) as G0.
  rewrite (t0_closed_form s ltac:(lia)), ds_scaled in G0.
  set (X := nr * ((pb s - pa s) / nr - (nr - 1) / 2 * (e_n2ds s / (nr * nr))
                  + INR J * (e_n2ds s / (nr * nr)))) in *.
  assert (E : nr * (ft0 + INR J * fds) - X =
     (nr * ft0 - (fpb - fpa - nr * (nr - 1) / 2 * fds))
     + ((fpb - pb s) - (fpa - pa s))
     + (INR J / nr - (nr - 1) / (2 * nr)) * (nr * nr * fds - e_n2ds s))
    by (unfold X; field; lra).
  assert (Hg : Rabs (INR J / nr - (nr - 1) / (2 * nr)) <= 1).
  { pose proof (theta_rng nr (INR J) ltac:(lra) HJ').
    pose proof (theta_rng nr ((nr - 1) / 2) ltac:(lra) ltac:(lra)).
    replace ((nr - 1) / (2 * nr)) with ((nr - 1) / 2 / nr) by (field; lra).
    apply Rabs_le. lra. }
  assert (B : Rabs (nr * (ft0 + INR J * fds) - X) <= ER + 2 * Ea + Eds).
  { rewrite E. eapply Rle_trans; [apply tri3|]. rewrite Rabs_mult.
    assert (Rabs (INR J / nr - (nr - 1) / (2 * nr)) * Rabs (nr * nr * fds - e_n2ds s)
            <= 1 * Eds) by (apply Rmult_le_compat; try apply Rabs_pos; lra).
    pose proof (absdiff (fpb - pb s) (fpa - pa s)). lra. }
  pose proof (abs_near _ _ _ B). lra.
Qed.

End Exact.

(** Gouraud's values p_a + i dp on computed p_a, p_b (within Ea) and dp
    (n dp within Edp of p_b - p_a), here and in Profiles.v. *)
Lemma g_near : forall (s : span) (fpa fpb fdp Ea Edp : R), (1 <= n s)%nat ->
  Rabs (fpa - pa s) <= Ea -> Rabs (fpb - pb s) <= Ea ->
  Rabs (INR (n s) * fdp - (fpb - fpa)) <= Edp ->
  forall i, (i <= n s)%nat -> Rabs (fpa + INR i * fdp - gouraud s i) <= Ea + Edp.
Proof.
  intros s fpa fpb fdp Ea Edp Hn1 P1 P2 P3 i Hi. pose proof (nr_ge1 s Hn1).
  pose proof (inr_rng i (n s) Hi) as Hi'.
  unfold gouraud, dp.
  replace (fpa + INR i * fdp - (pa s + INR i * ((pb s - pa s) / INR (n s))))
    with ((1 - INR i / INR (n s)) * (fpa - pa s) + INR i / INR (n s) * (fpb - pb s)
          + INR i / INR (n s) * (INR (n s) * fdp - (fpb - fpa)) - 0 * 0)
    by (field; lra).
  eapply Rle_trans.
  { apply comb_bound; [apply theta_rng; lra | lra | apply P1 | apply P2 | apply P3
                      | rewrite Rabs_R0; apply Rle_refl]. }
  lra.
Qed.

(** The loops p += s, s += ds from (p_a, t) (t = t0: corrected Euler; t = di_a:
    Euler) with their own addition unit ua, m ua <= 2^-11: |m (t + J ds)| <= Cs,
    the closed form on the computed values within E0 of ex and |ex| <= B;
    Msn / m and Mp bound the loop's s and p (here and in Profiles.v). *)
Lemma loop_near : forall (m : nat) (fpa fds t Cs Msn Mp E0 B eta ua : R) (ex P Q : nat -> R),
  1 <= INR m <= 16777216 -> 0 <= eta -> 0 <= ua -> INR m * ua <= / 2048 -> 0 <= Msn -> 0 <= Mp ->
  Cs + Msn / 2048 + 281474976710656 * eta <= Msn ->
  B + E0 + (Msn / 2 + Mp) / 2048 + 281474976710656 * eta <= Mp ->
  (forall J, (J < m)%nat -> Rabs (INR m * (t + INR J * fds)) <= Cs) ->
  (forall j, (j <= m)%nat ->
     Rabs (fpa + INR j * t + INR j * (INR j - 1) / 2 * fds - ex j) <= E0 /\ Rabs (ex j) <= B) ->
  P O = fpa -> Q O = t ->
  (forall j, (j < m)%nat -> FloatModelK.ap1 ua eta (P (S j)) (P j + Q j)
                            /\ FloatModelK.ap1 ua eta (Q (S j)) (Q j + fds)) ->
  forall i, (i <= m)%nat ->
  Rabs (P i - ex i) <= (Msn / 2 + Mp) * (INR m * ua) + E0 + 281474976710656 * eta.
Proof.
  intros m fpa fds t Cs Msn Mp E0 B eta ua ex P Q Hnr He0 Hua0 Hnua HMsn HMp HC1 HC2 Hsl Hid HP0
    HQ0 Hstep i Hi.
  set (Ms := Msn / INR m).
  assert (HMs : 0 <= Ms)
    by (unfold Ms, Rdiv; apply Rmult_le_pos; [lra | apply Rlt_le, Rinv_0_lt_compat; lra]).
  assert (Hnn : INR m * INR m <= 281474976710656) by nra.
  assert (Hne : INR m * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  assert (Hnne : INR m * INR m * eta <= 281474976710656 * eta) by (apply Rmult_le_compat_r; lra).
  assert (Hnu0 : 0 <= INR m * ua) by (apply Rmult_le_pos; lra).
  assert (Hs1 : Msn * (INR m * ua) <= Msn / 2048) by (apply Rmult_le_compat_l; lra).
  assert (Hp1 : Mp * (INR m * ua) <= Mp / 2048) by (apply Rmult_le_compat_l; lra).
  assert (Ems2 : INR m * INR m / 2 * (ua * Ms + eta)
                 = Msn / 2 * (INR m * ua) + INR m * INR m * eta / 2)
    by (unfold Ms; field; lra).
  assert (Emp : INR m * (ua * Mp + eta) = Mp * (INR m * ua) + INR m * eta) by ring.
  destruct (FloatModelK.cseq_err ua eta P Q fds m Ms Mp ltac:(lra) He0 HMs HMp Hstep)
    with (i := i) as [_ HPi]; [| | exact Hi |].
  - intros j Hj. rewrite HQ0. pose proof (Hsl (S j) Hj) as G0.
    assert (G1 : Rabs (t + INR (S j) * fds) <= Cs / INR m).
    { replace (t + INR (S j) * fds) with (INR m * (t + INR (S j) * fds) / INR m) by (field; lra).
      unfold Rdiv. rewrite Rabs_mult, (Rabs_pos_eq (/ INR m))
        by (apply Rlt_le, Rinv_0_lt_compat; lra).
      apply Rmult_le_compat_r; [apply Rlt_le, Rinv_0_lt_compat; lra | exact G0]. }
    assert (G2 : Cs / INR m + INR m * (ua * Ms + eta) <= Ms).
    { unfold Ms. apply div_helper; [lra|].
      replace (INR m * (ua * (Msn / INR m) + eta) * INR m)
        with (Msn * (INR m * ua) + INR m * INR m * eta)
        by (field; lra).
      lra. }
    lra.
  - intros j Hj. rewrite HP0, HQ0. destruct (Hid (S j) Hj) as [G0 G1].
    pose proof (abs_near _ _ _ G0) as G2. rewrite Ems2, Emp. lra.
  - rewrite HP0, HQ0 in HPi. destruct (Hid i Hi) as [G0 _].
    pose proof (inr_rng i m Hi) as Hi'.
    replace (P i - ex i)
      with ((P i - (fpa + INR i * t + INR i * (INR i - 1) / 2 * fds))
            + (fpa + INR i * t + INR i * (INR i - 1) / 2 * fds - ex i)) by ring.
    eapply Rle_trans; [apply Rabs_triang|].
    assert (Es0 : 0 <= ua * Ms + eta) by (pose proof (Rmult_le_pos ua Ms); lra).
    assert (K1 : INR i * (INR i - 1) / 2 <= INR m * (INR m - 1) / 2) by nra.
    assert (K2 : INR i * (INR i - 1) / 2 * (ua * Ms + eta)
                 <= INR m * (INR m - 1) / 2 * (ua * Ms + eta))
      by (apply Rmult_le_compat_r; lra).
    assert (K3 : INR m * (INR m - 1) / 2 * (ua * Ms + eta)
                 = Msn / 2 * (INR m * ua) - Msn / 2 * ua + INR m * INR m * eta / 2
                   - INR m * eta / 2)
      by (unfold Ms; field; lra).
    assert (K4 : INR i * (ua * Mp + eta) <= INR m * (ua * Mp + eta))
      by (apply Rmult_le_compat_r; [nra | lra]).
    assert (K5 : 0 <= Msn / 2 * ua) by (apply Rmult_le_pos; lra).
    assert (K6 : 0 <= INR m * eta) by (apply Rmult_le_pos; lra).
    lra.
Qed.

(** The Gouraud loop g += dp from p_a with its own addition unit ua, m ua <= 2^-11,
    the values p_a + j dp within Eid of ex and |ex| <= 1 (here and in Profiles.v). *)
Lemma gloop_near : forall (m : nat) (fpa fdp Eid eta ua : R) (ex G : nat -> R),
  1 <= INR m <= 16777216 -> 0 <= eta -> 0 <= ua -> INR m * ua <= / 2048 ->
  (forall j, (j <= m)%nat -> Rabs (fpa + INR j * fdp - ex j) <= Eid /\ Rabs (ex j) <= 1) ->
  Eid + 16777216 * eta <= / 10000 ->
  G O = fpa -> (forall j, (j < m)%nat -> FloatModelK.ap1 ua eta (G (S j)) (G j + fdp)) ->
  forall i, (i <= m)%nat ->
  Rabs (G i - ex i) <= 10006 / 10000 * (INR m * ua) + Eid + 16777216 * eta.
Proof.
  intros m fpa fdp Eid eta ua ex G Hm He0 Hua Hnua Hid HE HG0 HG i Hi.
  pose proof (FloatModelK.gseq_err ua eta G fdp m (10006 / 10000) Hua He0 ltac:(lra) HG) as L.
  rewrite HG0 in L.
  assert (Hne : INR m * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  pose proof (inr_rng i m Hi) as Hi'.
  specialize (L ltac:(intros j Hj; destruct (Hid (S j) Hj) as [G0 G1];
    pose proof (abs_near _ _ _ G0); lra) i Hi).
  destruct (Hid i Hi) as [G0 _].
  replace (G i - ex i) with ((G i - (fpa + INR i * fdp)) + (fpa + INR i * fdp - ex i)) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  assert (INR i * (ua * (10006 / 10000) + eta) <= INR m * (ua * (10006 / 10000) + eta))
    by (apply Rmult_le_compat_r; nra).
  lra.
Qed.

(** The facts on the unit inputs of a span used by the set-up bounds (here
    and in Profiles.v): component bounds, products, squares. *)
Ltac unit_facts_of s Hua Hub Hul :=
  pose proof (unit_bounded _ Hua) as [UA1 [UA2 UA3]];
  pose proof (unit_bounded _ Hub) as [UB1 [UB2 UB3]];
  pose proof (unit_bounded _ Hul) as [UL1 [UL2 UL3]];
  pose proof (diff_bounded _ _ Hua Hub) as [UD1 [UD2 UD3]];
  pose proof (unit_pair _ _ Hua Hul); pose proof (unit_pair _ _ Hub Hul);
  pose proof (unit_pair _ _ Hub Hua); pose proof (unit_abs_sq _ Hua);
  pose proof (diff_pair _ _ _ Hua Hub Hul); pose proof (diff_pair _ _ _ Hua Hub Hua);
  pose proof (diff_pair _ _ _ Hua Hub Hub); pose proof (diff_abs_sq _ _ Hua Hub);
  abs_pos3 (Na s); abs_pos3 (Nb s); abs_pos3 (L s); abs_pos3 (vsub (Nb s) (Na s)).

Section Chain.
Context (rnd : R -> R) (u eta : R) (Hstd : std_model rnd u eta) (Hok : fmt_ok u eta).

Lemma in_comp : forall x, Rabs (rnd x - x) <= u * (Rabs x + / 1073741824).
Proof.
  intros x. pose proof (Hstd x). pose proof (u_pos u eta Hok).
  pose proof (eta_small u eta Hok). lra.
Qed.

Lemma in_vec : forall v, vapprox u 1 (rvec rnd v) v (wIn v).
Proof.
  intros v. unfold vapprox, rvec, wIn; cbn [vx vy vz]. rewrite !Rmult_1_l.
  repeat split; apply in_comp.
Qed.

Lemma wIn_bounded : forall v, vbounded v 1 -> wbounded (wIn v).
Proof.
  intros v [A [B C]]. unfold wbounded, wIn; cbn [vx vy vz].
  abs_pos3 v. repeat split; lra.
Qed.

Lemma wK_bounded : forall a b, vbounded a 1 -> vbounded b 1 -> wbounded (wK a b).
Proof.
  intros a b [A1 [A2 A3]] [B1 [B2 B3]]. unfold wbounded, wK; cbn [vx vy vz].
  abs_pos3 a. abs_pos3 b. repeat split; lra.
Qed.

(** One component of n k: |n rnd (rnd (rnd b - rnd a) / n) - (b - a)| <= u (3.001 (|a|+|b|) + 2^-28). *)
Lemma k_comp : forall (m a b : R), 1 <= m <= 4096 -> Rabs a <= 1 -> Rabs b <= 1 ->
  Rabs (m * rnd (rnd (rnd b - rnd a) / m) - (b - a))
  <= u * (3001 / 1000 * (Rabs a + Rabs b) + / 268435456).
Proof.
  intros m a b Hm Ha Hb.
  pose proof (u_pos u eta Hok). pose proof (u_small u eta Hok).
  pose proof (in_comp a) as F1. pose proof (in_comp b) as F2.
  set (ra := rnd a) in *. set (rb := rnd b) in *.
  set (s1 := rnd (rb - ra)).
  assert (D1 : Rabs (rb - ra) <= Rabs a + Rabs b + Rabs (ra - a) + Rabs (rb - b)).
  { replace (rb - ra) with ((b - a) + (rb - b) + - (ra - a)) by ring.
    eapply Rle_trans; [apply tri3|]. rewrite Rabs_Ropp. pose proof (absdiff b a). lra. }
  pose proof (rnd_1 rnd u eta Hstd Hok (rb - ra) (Rabs (rb - ra)) (Rle_refl _)) as F3.
  fold s1 in F3.
  assert (HK : m * (s1 / m) = s1) by (field; lra).
  pose proof (rnd_sc rnd u eta Hstd Hok m (s1 / m) (Rabs s1) ltac:(lra)
                ltac:(rewrite HK; lra)) as F4.
  rewrite HK in F4.
  assert (S1 : Rabs s1 <= Rabs (rb - ra) + Rabs (s1 - (rb - ra))).
  { apply abs_near. lra. }
  assert (Pa : 0 <= u * Rabs a) by (apply Rmult_le_pos; [lra | apply Rabs_pos]).
  assert (Pb : 0 <= u * Rabs b) by (apply Rmult_le_pos; [lra | apply Rabs_pos]).
  assert (G1 : u * Rabs (rb - ra) <= u * (Rabs a + Rabs b + u * Rabs a + u * Rabs b
                                           + 2 * (u * / 1073741824)))
    by (apply Rmult_le_compat_l; lra).
  pose proof (u_u u eta Hok (Rabs a) (Rabs_pos _)).
  pose proof (u_u u eta Hok (Rabs b) (Rabs_pos _)).
  assert (G2 : u * (u * / 1073741824) <= / 1073741824 * u) by nra.
  assert (G3 : u * Rabs s1 <= u * (Rabs (rb - ra) + (Rabs (rb - ra) + / 68719476736) * u))
    by (apply Rmult_le_compat_l; lra).
  assert (G4 : u * ((Rabs (rb - ra) + / 68719476736) * u)
               <= / 16777216 * (u * Rabs (rb - ra)) + / 68719476736 * (u * u)).
  { pose proof (u_u u eta Hok (Rabs (rb - ra)) (Rabs_pos _)). nra. }
  assert (G5 : u * u <= / 16777216 * u) by nra.
  replace (m * rnd (s1 / m) - (b - a))
    with ((m * rnd (s1 / m) - s1) + (s1 - (rb - ra)) + (rb - b) + - (ra - a)) by ring.
  eapply Rle_trans; [apply tri4|]. rewrite Rabs_Ropp. lra.
Qed.

Section Span_.
Context (s : span) (Hua : is_unit (Na s)) (Hub : is_unit (Nb s)) (Hul : is_unit (L s))
        (Hn1 : (1 <= n s)%nat) (Hn2 : (n s <= 4096)%nat).

Lemma nr_range : 1 <= INR (n s) <= 4096.
Proof.
  split; [apply (le_INR 1); exact Hn1|].
  replace 4096 with (INR 4096) by (simpl; lra). apply le_INR. exact Hn2.
Qed.

Lemma k_vec : vapprox u (INR (n s)) (f_k rnd s) (vsub (Nb s) (Na s)) (wK (Na s) (Nb s)).
Proof.
  pose proof nr_range as Hm.
  destruct (unit_bounded _ Hua) as [A1 [A2 A3]].
  destruct (unit_bounded _ Hub) as [B1 [B2 B3]].
  unfold vapprox, f_k, fk, rvec, wK, vsub; cbn [vx vy vz].
  repeat split; apply k_comp; assumption.
Qed.

Ltac unit_facts := unit_facts_of s Hua Hub Hul.

(** A set-up dot product by [dot_inst] with scales lam, mu (the vectors read
    from the goal: an input [in_vec] or k [k_vec]). *)
Ltac ldot lam mu :=
  unit_facts;
  lazymatch lam with 1 => idtac | _ => pose proof nr_range;
    assert (INR (n s) * INR (n s) <= 16777216) by nra end;
  match goal with |- _ <= ?K * u =>
    epose proof (dot_inst rnd u eta Hstd Hok lam mu _ _ _ _ _ _ K
      ltac:(lra) ltac:(lra) ltac:(lra)) as HD;
    rewrite ?Rmult_1_l, ?Rmult_1_r in HD; eapply HD end;
  first [ apply k_vec | apply in_vec | apply diff_bounded; assumption
        | apply vb12, unit_bounded; assumption
        | apply wK_bounded; apply unit_bounded; assumption
        | apply wIn_bounded, unit_bounded; assumption
        | unfold wsum, wIn, wK; cbn [vx vy vz]; lra ].

Lemma L_pa : Rabs (f_pa rnd s - pa s) <= 5002 / 1000 * u.
Proof. ldot 1 1. Qed.

Lemma L_pb : Rabs (f_pb rnd s - pb s) <= 5002 / 1000 * u.
Proof. ldot 1 1. Qed.

Lemma L_a : Rabs (INR (n s) * f_a rnd s - dot (vsub (Nb s) (Na s)) (L s)) <= 1401 / 100 * u.
Proof. ldot (INR (n s)) 1. Qed.

Lemma L_c : Rabs (INR (n s) * INR (n s) * f_c rnd s - dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)))
            <= 3602 / 100 * u.
Proof. ldot (INR (n s)) (INR (n s)). Qed.

Lemma L_d0 : Rabs (INR (n s) * fdot rnd (f_k rnd s) (rvec rnd (Na s))
                   - dot (vsub (Nb s) (Na s)) (Na s)) <= 1401 / 100 * u.
Proof. ldot (INR (n s)) 1. Qed.


Local Notation nr := (INR (n s)).
Local Notation Dl := (vsub (Nb s) (Na s)).
Local Notation t36 := (/ 68719476736).

Ltac basics :=
  pose proof nr_range as Hnr; pose proof (u_pos u eta Hok) as Hu0;
  pose proof (u_small u eta Hok) as Hu1.

Lemma dl_dd : 0 <= dot Dl Dl <= 4.
Proof.
  split; [|apply diff_sq; assumption].
  unfold dot. pose proof (Rle_0_sqr (vx Dl)). pose proof (Rle_0_sqr (vy Dl)).
  pose proof (Rle_0_sqr (vz Dl)). unfold Rsqr in *. lra.
Qed.

Lemma dl_sum : dot Dl Dl + dot Dl (Na s) = dot Dl (Nb s).
Proof. unfold dot, vsub; cbn [vx vy vz]. ring. Qed.

Lemma L_d : Rabs (nr * f_d rnd s - 2 * dot Dl (Na s)) <= 321 / 10 * u.
Proof.
  basics. pose proof L_d0 as H0. pose proof (dl_dot_le s Hua Hub (Na s) Hua) as H1.
  unfold f_d. set (fd := fdot rnd (f_k rnd s) (rvec rnd (Na s))) in *.
  eapply Rle_trans.
  { apply (rnd_step rnd u eta Hstd Hok nr _ (2 * (nr * fd)) _ (2802 / 100 * u) (4001 / 1000));
      [lra | ring | | ].
    - rewrite <- Rmult_minus_distr_l, Rabs_mult, (Rabs_pos_eq 2) by lra. lra.
    - rewrite Rabs_mult, (Rabs_pos_eq 2) by lra. lra. }
  lra.
Qed.

Lemma L_c2 : Rabs (nr * rnd (2 * nr * f_c rnd s) - 2 * dot Dl Dl) <= 801 / 10 * u.
Proof.
  basics. pose proof L_c as H0. pose proof dl_dd as H1.
  eapply Rle_trans.
  { apply (rnd_step rnd u eta Hstd Hok nr _ (2 * (nr * nr * f_c rnd s)) _ (7204 / 100 * u)
             (8001 / 1000)); [lra | ring | | ].
    - rewrite <- Rmult_minus_distr_l, Rabs_mult, (Rabs_pos_eq 2) by lra. lra.
    - rewrite Rabs_mult, (Rabs_pos_eq 2), Rabs_pos_eq by lra. lra. }
  lra.
Qed.

Lemma L_qb : Rabs (nr * f_dqb rnd s - 2 * dot Dl (Nb s)) <= 1163 / 10 * u.
Proof.
  basics. pose proof L_c2 as H0. pose proof L_d as H1. pose proof (dl_dot_le s Hua Hub (Nb s) Hub) as H2.
  unfold f_dqb.
  eapply Rle_trans.
  { apply (rnd_step rnd u eta Hstd Hok nr _ (nr * rnd (2 * nr * f_c rnd s) + nr * f_d rnd s) _
             (1122 / 10 * u) (4001 / 1000)); [lra | ring | | ].
    - rewrite <- dl_sum.
      replace (nr * rnd (2 * nr * f_c rnd s) + nr * f_d rnd s - 2 * (dot Dl Dl + dot Dl (Na s)))
        with ((nr * rnd (2 * nr * f_c rnd s) - 2 * dot Dl Dl) + (nr * f_d rnd s - 2 * dot Dl (Na s)))
        by ring.
      eapply Rle_trans; [apply Rabs_triang|]. lra.
    - rewrite Rabs_mult, (Rabs_pos_eq 2) by lra. lra. }
  lra.
Qed.

Lemma L_h : forall (x X : R), Rabs x <= 1 -> Rabs (X - x) <= 5002 / 1000 * u ->
  Rabs (rnd (X / 2) - x / 2) <= 301 / 100 * u.
Proof.
  intros x X Hx HX. basics.
  pose proof (rnd_step rnd u eta Hstd Hok 1 (X / 2) (X / 2) (x / 2) (2501 / 1000 * u) (501 / 1000)
                ltac:(lra) ltac:(ring)) as H.
  rewrite Rmult_1_l in H. eapply Rle_trans; [apply H|lra].
  - replace (X / 2 - x / 2) with ((X - x) * / 2) by field.
    rewrite Rabs_mult, (Rabs_pos_eq (/ 2)) by lra. lra.
  - replace (x / 2) with (x * / 2) by field.
    rewrite Rabs_mult, (Rabs_pos_eq (/ 2)) by lra. lra.
Qed.

(** rnd (rnd (fP / 2) * F) with fP within 5.002 u of P and n F within E of 2 X. *)
Lemma L_x : forall (P fP F X E : R), Rabs P <= 1 -> Rabs (fP - P) <= 5002 / 1000 * u ->
  Rabs (nr * F - 2 * X) <= E -> E <= / 1000 -> Rabs X <= 2 ->
  Rabs (nr * rnd (rnd (fP / 2) * F) - P * X)
  <= 301 / 100 * u * (4001 / 1000) + 1 / 2 * E + (2001 / 1000 + / 68719476736) * u.
Proof.
  intros P fP F X E HP HfP H0 HE H1. basics.
  pose proof (L_h P fP HP HfP) as H3.
  set (HA := rnd (fP / 2)) in *.
  assert (H4 : Rabs (nr * F) <= 4001 / 1000).
  { pose proof (abs_near _ _ _ H0).
    assert (Rabs (2 * X) <= 4) by (rewrite Rabs_mult, (Rabs_pos_eq 2) by lra; lra). lra. }
  assert (H5 : Rabs (P / 2) <= 1 / 2).
  { replace (P / 2) with (P * / 2) by field.
    rewrite Rabs_mult, (Rabs_pos_eq (/ 2)) by lra. lra. }
  pose proof (prod_err HA (P / 2) (nr * F) (2 * X) _ _ _ _ H3 H0 H4 H5) as H6.
  replace (P / 2 * (2 * X)) with (P * X) in H6 by field.
  assert (H7 : Rabs (P * X) <= 2).
  { rewrite Rabs_mult. replace 2 with (1 * 2) by ring.
    apply Rmult_le_compat; try apply Rabs_pos; assumption. }
  apply (rnd_step rnd u eta Hstd Hok nr _ (HA * (nr * F)) _ _ (2001 / 1000));
    [lra | ring | exact H6 | lra].
Qed.

Lemma L_xa : Rabs (nr * rnd (rnd (f_pa rnd s / 2) * f_d rnd s) - pa s * dot Dl (Na s))
             <= 302 / 10 * u.
Proof.
  basics. pose proof (L_x _ _ _ _ _ (pa_le s Hua Hul) L_pa L_d ltac:(lra)
    (dl_dot_le s Hua Hub (Na s) Hua)). lra.
Qed.

Lemma L_xb : Rabs (nr * rnd (rnd (f_pb rnd s / 2) * f_dqb rnd s) - pb s * dot Dl (Nb s))
             <= 723 / 10 * u.
Proof.
  basics. pose proof (L_x _ _ _ _ _ (pb_le s Hub Hul) L_pb L_qb ltac:(lra)
    (dl_dot_le s Hua Hub (Nb s) Hub)). lra.
Qed.

(** di_a and di_b: the rounding of [a - x] relative to the computed operands
    (the error of [a] cancels in di_b - di_a); n x within E of Y. *)
Lemma L_di_r : forall (x Y E : R), Rabs (nr * x - Y) <= E -> E <= / 1024 ->
  Rabs (dot Dl (L s) - Y) <= 2 ->
  Rabs (nr * rnd (f_a rnd s - x) - (nr * f_a rnd s - nr * x)) <= 2002 / 1000 * u.
Proof.
  intros x Y E HY HE H2. basics. pose proof L_a as H0.
  rewrite <- Rmult_minus_distr_l.
  eapply Rle_trans; [apply (rnd_sc rnd u eta Hstd Hok _ _ (2001 / 1000)); [lra|] | lra].
  rewrite Rmult_minus_distr_l.
  apply (Rle_trans _ (Rabs (dot Dl (L s) - Y) + (1401 / 100 * u + E))); [|lra].
  apply abs_near.
  replace (nr * f_a rnd s - nr * x - (dot Dl (L s) - Y))
    with ((nr * f_a rnd s - dot Dl (L s)) - (nr * x - Y)) by ring.
  eapply Rle_trans; [apply absdiff|]. lra.
Qed.

Lemma L_dia_r : Rabs (nr * f_dia rnd s
                      - (nr * f_a rnd s - nr * rnd (rnd (f_pa rnd s / 2) * f_d rnd s)))
                <= 2002 / 1000 * u.
Proof. basics. exact (L_di_r _ _ _ L_xa ltac:(lra) (ndia_le s Hua Hub Hul)). Qed.

Lemma L_dib_r : Rabs (nr * f_dib rnd s
                      - (nr * f_a rnd s - nr * rnd (rnd (f_pb rnd s / 2) * f_dqb rnd s)))
                <= 2002 / 1000 * u.
Proof. basics. exact (L_di_r _ _ _ L_xb ltac:(lra) (ndib_le s Hua Hub Hul)). Qed.

Lemma L_dia : Rabs (nr * f_dia rnd s - e_ndia s) <= 464 / 10 * u.
Proof.
  basics. pose proof L_a as H0. pose proof L_xa as H1. pose proof L_dia_r as H2.
  unfold e_ndia.
  replace (nr * f_dia rnd s - (dot Dl (L s) - pa s * dot Dl (Na s)))
    with ((nr * f_dia rnd s - (nr * f_a rnd s - nr * rnd (rnd (f_pa rnd s / 2) * f_d rnd s)))
          + (nr * f_a rnd s - dot Dl (L s))
          + - (nr * rnd (rnd (f_pa rnd s / 2) * f_d rnd s) - pa s * dot Dl (Na s))) by ring.
  eapply Rle_trans; [apply tri3|]. rewrite Rabs_Ropp. lra.
Qed.

Lemma L_w : Rabs (nr * rnd (f_dib rnd s - f_dia rnd s) - e_n2ds s) <= 1088 / 10 * u.
Proof.
  basics. pose proof L_xa as H0. pose proof L_xb as H1. pose proof L_dia_r as H2.
  pose proof L_dib_r as H3. pose proof (n2ds_le s Hua Hub Hul) as H4.
  eapply Rle_trans.
  { apply (rnd_step rnd u eta Hstd Hok nr _ (nr * f_dib rnd s - nr * f_dia rnd s) _
             (1066 / 10 * u) (2001 / 1000)); [lra | ring | | lra].
    unfold e_n2ds, e_ndib, e_ndia.
    replace (nr * f_dib rnd s - nr * f_dia rnd s
             - (dot Dl (L s) - pb s * dot Dl (Nb s) - (dot Dl (L s) - pa s * dot Dl (Na s))))
      with ((nr * f_dib rnd s - (nr * f_a rnd s - nr * rnd (rnd (f_pb rnd s / 2) * f_dqb rnd s)))
            + - (nr * f_dia rnd s - (nr * f_a rnd s - nr * rnd (rnd (f_pa rnd s / 2) * f_d rnd s)))
            + (nr * rnd (rnd (f_pa rnd s / 2) * f_d rnd s) - pa s * dot Dl (Na s))
            + - (nr * rnd (rnd (f_pb rnd s / 2) * f_dqb rnd s) - pb s * dot Dl (Nb s))) by ring.
    eapply Rle_trans; [apply tri4|]. rewrite !Rabs_Ropp. lra. }
  lra.
Qed.

Lemma L_ds : Rabs (nr * nr * f_ds rnd s - e_n2ds s) <= 1109 / 10 * u.
Proof.
  basics. pose proof L_w as H0. pose proof (n2ds_le s Hua Hub Hul) as H1.
  unfold f_ds.
  eapply Rle_trans.
  { apply (rnd_step rnd u eta Hstd Hok (nr * nr) _ (nr * rnd (f_dib rnd s - f_dia rnd s)) _
             (1088 / 10 * u) (2001 / 1000)); [nra | field; lra | exact H0 | lra]. }
  lra.
Qed.

(** The correction t0 = di_a - (p_n - p_b)/n. *)
Lemma L_Yb : Rabs (f_tri s * f_ds rnd s) <= 1001 / 1000.
Proof. basics. exact (Yb_near nr _ _ _ ltac:(lra) L_ds (n2ds_le s Hua Hub Hul) ltac:(lra)). Qed.

Lemma L_rhon : Rabs (f_pn rnd s - (f_pa rnd s + nr * f_dia rnd s + f_tri s * f_ds rnd s))
               <= 1002 / 100 * u.
Proof.
  basics. pose proof L_dia as G0. pose proof (ndia_le s Hua Hub Hul) as G1.
  pose proof L_pa as G2. pose proof (pa_le s Hua Hul) as G3. pose proof L_Yb as G4.
  unfold f_pn.
  set (DIA := nr * f_dia rnd s) in *. set (PA := f_pa rnd s) in *.
  set (Y := f_tri s * f_ds rnd s) in *.
  assert (B1 : Rabs DIA <= 2001 / 1000) by (pose proof (abs_near _ _ _ G0); lra).
  pose proof (rnd_1 rnd u eta Hstd Hok DIA _ B1) as R1.
  set (y1 := rnd DIA) in *.
  assert (B2 : Rabs (PA + y1) <= 3003 / 1000).
  { eapply Rle_trans; [apply Rabs_triang|].
    pose proof (abs_near _ _ _ G2). pose proof (abs_near _ _ _ R1). lra. }
  pose proof (rnd_1 rnd u eta Hstd Hok (PA + y1) _ B2) as R2.
  set (y2 := rnd (PA + y1)) in *.
  pose proof (rnd_1 rnd u eta Hstd Hok Y _ G4) as R3.
  set (y3 := rnd Y) in *.
  assert (B4 : Rabs (y2 + y3) <= 4005 / 1000).
  { eapply Rle_trans; [apply Rabs_triang|].
    pose proof (abs_near _ _ _ R2). pose proof (abs_near _ _ _ R3). lra. }
  pose proof (rnd_1 rnd u eta Hstd Hok (y2 + y3) _ B4) as R4.
  replace (rnd (y2 + y3) - (PA + DIA + Y))
    with ((rnd (y2 + y3) - (y2 + y3)) + (y2 - (PA + y1)) + (y1 - DIA) + (y3 - Y)) by ring.
  eapply Rle_trans; [apply tri4|]. lra.
Qed.

Lemma L_pnb : Rabs (f_pn rnd s) <= 4005 / 1000.
Proof.
  basics. pose proof L_rhon as G0. pose proof L_dia as G1. pose proof (ndia_le s Hua Hub Hul).
  pose proof L_pa as G2. pose proof (pa_le s Hua Hul). pose proof L_Yb.
  apply (Rle_trans _ _ _ (abs_near _ _ _ G0)).
  pose proof (tri3 (f_pa rnd s) (nr * f_dia rnd s) (f_tri s * f_ds rnd s)).
  pose proof (abs_near _ _ _ G1). pose proof (abs_near _ _ _ G2). lra.
Qed.

Lemma L_rhoe : Rabs (f_eps rnd s - (f_pn rnd s - f_pb rnd s)) <= 5007 / 1000 * u.
Proof.
  basics. pose proof L_pnb. pose proof L_pb as G0. pose proof (pb_le s Hub Hul).
  unfold f_eps.
  eapply Rle_trans; [apply (rnd_1 rnd u eta Hstd Hok _ (5006 / 1000))|lra].
  eapply Rle_trans; [apply absdiff|]. pose proof (abs_near _ _ _ G0). lra.
Qed.

Lemma L_rhod : Rabs (nr * f_deps rnd s - f_eps rnd s) <= 5008 / 1000 * u.
Proof.
  basics. pose proof L_pnb. pose proof L_pb as G0. pose proof (pb_le s Hub Hul).
  pose proof L_rhoe as G1.
  assert (B : Rabs (f_eps rnd s) <= 5007 / 1000).
  { apply (Rle_trans _ _ _ (abs_near _ _ _ G1)).
    pose proof (absdiff (f_pn rnd s) (f_pb rnd s)). pose proof (abs_near _ _ _ G0). lra. }
  unfold f_deps.
  eapply Rle_trans.
  { apply (rnd_step rnd u eta Hstd Hok nr _ (f_eps rnd s) _ 0 (5007 / 1000));
      [lra | field; lra | rewrite Rminus_diag_eq, Rabs_R0 by reflexivity; lra | lra]. }
  lra.
Qed.

Lemma L_R : Rabs (nr * f_t0 rnd s - (f_pb rnd s - f_pa rnd s - f_tri s * f_ds rnd s))
            <= 231 / 10 * u.
Proof.
  basics. pose proof (R_near nr _ (f_t0 rnd s) _ _ _ _ _ _ _ _ _ _ _ _ _ L_rhon L_rhoe L_rhod L_pa
    L_pb (pa_le s Hua Hul) (pb_le s Hub Hul) L_Yb ltac:(lra)
    (rnd_sc rnd u eta Hstd Hok nr (f_dia rnd s - f_deps rnd s) _ ltac:(lra))). lra.
Qed.

Lemma L_dp : Rabs (nr * f_dp rnd s - (f_pb rnd s - f_pa rnd s)) <= 401 / 100 * u.
Proof.
  basics. pose proof L_pa as G3. pose proof L_pb as G4. pose proof (pa_le s Hua Hul).
  pose proof (pb_le s Hub Hul).
  assert (B : Rabs (f_pb rnd s - f_pa rnd s) <= 20001 / 10000).
  { eapply Rle_trans; [apply absdiff|].
    pose proof (abs_near _ _ _ G3). pose proof (abs_near _ _ _ G4). lra. }
  pose proof (rnd_1 rnd u eta Hstd Hok _ _ B) as R1.
  unfold f_dp.
  eapply Rle_trans.
  { apply (rnd_step rnd u eta Hstd Hok nr _ (rnd (f_pb rnd s - f_pa rnd s)) _
             ((20001 / 10000 + t36) * u) (20002 / 10000));
      [lra | field; lra | exact R1 | lra]. }
  lra.
Qed.


Lemma ce_ideal : forall i, (i <= n s)%nat ->
  Rabs (f_pa rnd s + INR i * f_t0 rnd s + INR i * (INR i - 1) / 2 * f_ds rnd s - ceuler s i)
  <= 4197 / 100 * u.
Proof.
  intros i Hi. basics.
  pose proof (ce_near s Hn1 _ _ _ _ _ _ _ L_pa L_pb L_R L_ds i Hi). lra.
Qed.

Lemma g_ideal : forall i, (i <= n s)%nat ->
  Rabs (f_pa rnd s + INR i * f_dp rnd s - gouraud s i) <= 9012 / 1000 * u.
Proof. intros i Hi. pose proof (g_near s _ _ _ _ _ Hn1 L_pa L_pb L_dp i Hi). lra. Qed.

Lemma slope_f : forall J, (J < n s)%nat ->
  Rabs (nr * (f_t0 rnd s + INR J * f_ds rnd s)) <= 2 + 200 * u.
Proof.
  intros J HJ. basics.
  pose proof (slope_near s Hua Hub Hul Hn1 _ _ _ _ _ _ _ L_pa L_pb L_R L_ds J HJ). lra.
Qed.

Lemma ce_final : forall i, (i <= n s)%nat ->
  Rabs (f_ceuler rnd s i - ceuler s i) <= (22 / 10 * INR (n s) + 42) * u.
Proof.
  intros i Hi. basics. pose proof (eta_pos u eta Hok) as He0. pose proof (eta_small u eta Hok).
  assert (nr * u <= 4096 * u) by (apply Rmult_le_compat_r; lra).
  pose proof (loop_near (n s) (f_pa rnd s) (f_ds rnd s) (f_t0 rnd s) (2 + 200 * u) (2002 / 1000)
    (1194 / 1000) (4197 / 100 * u) (11925 / 10000) eta u (ceuler s)
    (fun j => fst (floop rnd (f_pa rnd s) (f_t0 rnd s) (f_ds rnd s) j))
    (fun j => snd (floop rnd (f_pa rnd s) (f_t0 rnd s) (f_ds rnd s) j)) ltac:(lra) He0
    ltac:(lra) ltac:(lra) ltac:(lra) ltac:(lra) ltac:(lra) ltac:(lra) slope_f
    (fun j Hj => conj (ce_ideal j Hj) (ceuler_le s Hua Hub Hul Hn1 j Hj)) eq_refl eq_refl
    ltac:(intros j _; cbv beta; rewrite floop_S; cbn [fst snd]; split; apply Hstd) i Hi).
  unfold f_ceuler. assert (0 <= nr * u) by (apply Rmult_le_pos; lra). lra.
Qed.

Lemma g_final : forall i, (i <= n s)%nat ->
  Rabs (f_gouraud rnd s i - gouraud s i) <= (1001 / 1000 * INR (n s) + 10) * u.
Proof.
  intros i Hi. basics. pose proof (eta_pos u eta Hok) as He0. pose proof (eta_small u eta Hok).
  assert (nr * u <= 4096 * u) by (apply Rmult_le_compat_r; lra).
  pose proof (gloop_near (n s) (f_pa rnd s) (f_dp rnd s) (9012 / 1000 * u) eta u (gouraud s)
    (gloop rnd (f_pa rnd s) (f_dp rnd s)) ltac:(lra) He0 ltac:(lra) ltac:(lra)
    (fun j Hj => conj (g_ideal j Hj) (gouraud_le s Hua Hub Hul Hn1 j Hj)) ltac:(lra) eq_refl
    ltac:(intros j _; cbn [gloop]; apply Hstd) i Hi).
  unfold f_gouraud. assert (0 <= nr * u) by (apply Rmult_le_pos; lra). lra.
Qed.

End Span_.
End Chain.

(** ** The bounds *)

Lemma flt_prec_ok : forall emin prec : Z, (24 <= prec)%Z -> (emin <= - prec - 59)%Z ->
  std_model (fun x => round radix2 (FLT_exp emin prec) ZnearestE x)
            (bpow radix2 (- prec)) (bpow radix2 (emin - 1))
  /\ fmt_ok (bpow radix2 (- prec)) (bpow radix2 (emin - 1)).
Proof.
  intros emin prec H1 H2. split; [apply flt_std_model; lia | apply flt_fmt_ok; assumption].
Qed.

(** A bound [gen] (for any format with the standard model and the size
    conditions prec >= 24, emin <= -prec - 59) in the format FLT(emin, prec). *)
Ltac flt_inst emin prec gen :=
  intros; destruct (flt_prec_ok emin prec ltac:(lia) ltac:(lia)) as [F1 F2];
  eapply gen; eassumption || lia.

(* Note: binary32 (prec 24, emin -149), round to nearest even; u = 2^-24. *)
(** Gouraud in binary32: |G_i(float) - G_i| <= (1.001 n + 10) u. *)
Theorem float_gouraud_binary32 : forall s : span,
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  forall i : nat, (i <= n s)%nat ->
  Rabs (f_gouraud (fun x => round radix2 (FLT_exp (-149) 24) ZnearestE x) s i - gouraud s i)
  <= (1001 / 1000 * INR (n s) + 10) * bpow radix2 (-24).
Proof. flt_inst (-149)%Z 24%Z g_final. Qed.

(* Note: binary64 (prec 53, emin -1074), round to nearest even; u = 2^-53. *)
(** Gouraud in binary64: |G_i(float) - G_i| <= (1.001 n + 10) u. *)
Theorem float_gouraud_binary64 : forall s : span,
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  forall i : nat, (i <= n s)%nat ->
  Rabs (f_gouraud (fun x => round radix2 (FLT_exp (-1074) 53) ZnearestE x) s i - gouraud s i)
  <= (1001 / 1000 * INR (n s) + 10) * bpow radix2 (-53).
Proof. flt_inst (-1074)%Z 53%Z g_final. Qed.

(* Note: binary32; the exact value is ceuler of Euler.v on the exact inputs. *)
(** Corrected Euler (eqs. 16-17) in binary32: |P_i(float) - P_i| <= (2.2 n + 42) u. *)
Theorem float_corrected_euler_binary32 : forall s : span,
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  forall i : nat, (i <= n s)%nat ->
  Rabs (f_ceuler (fun x => round radix2 (FLT_exp (-149) 24) ZnearestE x) s i - ceuler s i)
  <= (22 / 10 * INR (n s) + 42) * bpow radix2 (-24).
Proof. flt_inst (-149)%Z 24%Z ce_final. Qed.

(* Note: binary64; the exact value is ceuler of Euler.v on the exact inputs. *)
(** Corrected Euler (eqs. 16-17) in binary64: |P_i(float) - P_i| <= (2.2 n + 42) u. *)
Theorem float_corrected_euler_binary64 : forall s : span,
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  forall i : nat, (i <= n s)%nat ->
  Rabs (f_ceuler (fun x => round radix2 (FLT_exp (-1074) 53) ZnearestE x) s i - ceuler s i)
  <= (22 / 10 * INR (n s) + 42) * bpow radix2 (-53).
Proof. flt_inst (-1074)%Z 53%Z ce_final. Qed.
