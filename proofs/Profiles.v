(** * Profiles.v — acceptance profiles: error bounds for the Gouraud,
    corrected-Euler (eqs. 16-17) and Euler (eqs. 12-14) computations that
    hold for EVERY implementation of a class (model of FloatModelK.v), against
    the exact real values [gouraud s i] (Adaptive.v), [ceuler s i] and
    [euler_span s i] (Euler.v) on the exact inputs.

    The computation is Float.v's (src/span.rs set-up, src/gouraud.rs and
    src/corrected_euler.rs loops), but every operation is only known to be
    within its class's bound (FloatModelK.approx) of the exact result of that
    operation on the computed operands, each operation with its own rounding:
      inputs   na, nb, l         ap_in  of Na, Nb, L (componentwise)
      k_j      t_j ap_add (nb_j - na_j), k_j ap_div t_j / n
      a = k.l, pa = na.l, c = k.k, pb = nb.l   dot products (fdot_ok: any
               order of the three-term sum, each product rounded or fused)
      d        e = k.na (fdot_ok), d ap_mul 2 e
      dqb      q ap_mul (2n) c, dqb ap_add q + d
      dia      h ap_div pa/2, x ap_mul h d, dia ap_add a - x
      dib      h' ap_div pb/2, x' ap_mul h' dqb, dib ap_add a - x'
      ds       w ap_add dib - dia, ds ap_div w / n
      pn       q2 ap_mul n dia, q3 ap_mul (n(n-1)/2) ds,
               pn = pa + q2 + q3 in ANY order (sum3)
      eps ap_add pn - pb, deps ap_div eps / n, t0 ap_add dia - deps,
      dp       w' ap_add pb - pa, dp ap_div w' / n;
      corrected Euler: P_0 = pa, S_0 = t0, P_{j+1} ap_add P_j + S_j,
                       S_{j+1} ap_add S_j + ds;
      Euler (src/euler.rs): the same loop from S_0 = dia, on the set-up
                       up to ds (pn, eps, deps, t0 not computed);
      Gouraud: G_0 = pa, G_{j+1} ap_add G_j + dp.
    A product that feeds an addition may be exact (fused multiply-add): an
    exact result satisfies every bound.  n, 2n, n(n-1)/2 are exact reals
    (integers of the format): n(n-1)/2 is formed exactly, as an integer then
    converted (exact: n(n-1) < 2^24 for n <= 4096) or as n (n-1) 0.5 in floats
    with the literal 0.5 (every product exact), NOT by a rounded division by
    2 nor by a computed 1/2 (not covered by any theorem here); likewise the
    closed forms' (i-1)/2 in [ap_mul M h ((i-1)/2 ds)], while the [_half]
    theorems let (i-1)/2 be halved in floats ([half_ok]).  Division (by n,
    and p_a/2, p_b/2) is either one rounded division or a reciprocal followed
    by a product ([recip_mul_covered], [shader32_recip_mul_covered]).  Nothing else is
    assumed: each relation may be met by a different rounding (direction,
    flushing) at each operation, each three-term sum in its own order.

    Profiles (u = unit roundoff):
      ieee    k_in = k_add = k_mul = 1 (round to nearest, any tie rule:
              [rn_covered], [ieee32_covered], [ieee64_covered]),
              k_div = 2 + 2^-20 (correctly rounded division, or reciprocal
              then product, [recip_mul_covered]); binary32 u = 2^-24,
              eta = 2^-150; binary64 u = 2^-53, eta = 2^-1075 (subnormals kept).
      shader  k_in = k_add = k_mul = 2 (any rounding of binary32: nearest,
              toward zero, ..., [faithful_covered]), k_div = 5 (within 2.5 ulp,
              [shader32_div_covered]), u = 2^-24, eta = 2^-126 (results and
              inputs may be flushed to zero, [flush_covered], [shader32_covered]).
      shader, division as .(1/n)  ([shader32_recip]): as shader, with
              k_div = 7 + 2^-20: each division (by n, by 2) a reciprocal within
              2.5 ulp then a shader product ([shader32_recip_mul_covered]) or
              one 2.5-ulp division ([shader32_recip_covered]), either way at
              each division.

    Theorems (unit Na, Nb, L; every pixel i <= n):
      profile_ieee_gouraud_binary32 / _binary64   1 <= n <= 4096:
          |G_i - gouraud s i|  <= (1.0006 n + 11.001) u
      profile_ieee_gouraud_binary64_large         1 <= n <= 2^24: the same
      profile_shader_gouraud_binary32             1 <= n <= 4096:
          |G_i - gouraud s i|  <= (2.0012 n + 24.002) 2^-24
      profile_ieee_corrected_euler_binary32 / _binary64   1 <= n <= 4096:
          |P_i - ceuler s i|   <= (2.2 n + 51.21) u
      profile_ieee_corrected_euler_binary64_large         1 <= n <= 2^24: the same
      profile_shader_corrected_euler_binary32     1 <= n <= 4096:
          |P_i - ceuler s i|   <= (4.4 n + 109.7) 2^-24
      profile_ieee_corrected_euler_closed_binary32 / _binary64   1 <= n <= 4096:
          p_i = p_a + i (t0 + (i-1)/2 ds) evaluated in the model (h = (i-1)/2 ds,
          g = t0 + h, m = i g, p = pa + m, fused or not) on an ieee set-up:
          |p_i - ceuler s i|   <= 59.61 u   (independent of n)
      profile_ieee_corrected_euler_closed_binary64_large  1 <= n <= 2^24: the same
      profile_ieee_euler_binary32 / _binary64     1 <= n <= 4096:
          plain Euler (eqs. 12-14) on the set-up up to ds (eu_setup_ok, the
          part of ce_setup_ok before p_n), P_0 = pa, S_0 = dia (euler_run):
          |P_i - euler_span s i| <= (5.55 n + 121.41) u
      profile_ieee_euler_binary64_large           1 <= n <= 2^24: the same
      profile_shader_euler_binary32               1 <= n <= 4096:
          |P_i - euler_span s i| <= (11.1 n + 257.9) 2^-24
      profile_ieee_euler_closed_binary32 / _binary64   1 <= n <= 4096:
          p_i = p_a + i (dia + (i-1)/2 ds) evaluated in the model (h = (i-1)/2 ds,
          g = dia + h, m = i g, p = pa + m, fused or not) on an ieee set-up:
          |p_i - euler_span s i| <= 131.41 u   (independent of n)
      profile_ieee_euler_closed_binary64_large    1 <= n <= 2^24: the same
      shader, 1 <= n <= 4096, u = 2^-24 (the _recip ones on shader32_recip):
      profile_shader_gouraud_recip_binary32             (2.0012 n + 28.0014) u
      profile_shader_corrected_euler_recip_binary32     (4.4 n + 124.31) u
      profile_shader_euler_recip_binary32               (11.1 n + 288.11) u
      profile_shader_corrected_euler_closed_binary32         126.5 u
      profile_shader_corrected_euler_closed_recip_binary32   141.11 u
      profile_shader_euler_closed_binary32                   277.9 u
      profile_shader_euler_closed_recip_binary32             308.11 u
          (closed forms with (i-1)/2 exact, as the ieee ones)
      profile_shader_corrected_euler_closed_half_binary32        131.5 u
      profile_shader_corrected_euler_closed_half_recip_binary32  148.11 u
      profile_shader_euler_closed_half_binary32                  281.65 u
      profile_shader_euler_closed_half_recip_binary32            313.36 u
          (closed forms with h from [half_ok]: c = (i-1)/2 by a division
          then h = c ds, or y = (i-1) ds then h = y/2 by a division)
    They are instances of [profile_gouraud_generic]
    ((1.0006 k_add n + 2.0001 k_in + 1.0001 k_mul + 4.0001 k_add + 2.0001 k_div
    + 10^-6) u) and [profile_corrected_euler_generic]
    ((2.2 k_add n + 36.6 K1 + 7.3 k_div) u, K1 >= k_in, k_add, k_mul), under
    [model_ok] and n k_add u <= 2^-11, and of
    [profile_corrected_euler_closed_generic] ((45 K1 + 7.3 k_div) u), and for
    Euler of [profile_euler_generic] ((5.55 k_add n + 91.2 K1 + 15.1 k_div) u)
    and [profile_euler_closed_generic] ((101.2 K1 + 15.1 k_div) u), and with
    the halving in floats of [profile_corrected_euler_closed_half_generic]
    ((45 K1 + 8.3 k_div) u) and [profile_euler_closed_half_generic]
    ((101.2 K1 + 15.85 k_div) u). *)

From Coq Require Import Reals Lra Lia.
From Flocq Require Import Core Relative.
From PhongApprox Require Import Span Euler Adaptive FloatModel Float FloatModelK.
Open Scope R_scope.

(** ** The computation as a relation *)

(** The computed values of the set-up (the intermediates are quantified in
    [ce_setup_ok] and [gouraud_setup_ok]). *)
Record fsetup := mkSetup {
  fs_na : vec; fs_nb : vec; fs_l : vec; fs_k : vec;
  fs_a : R; fs_pa : R; fs_c : R; fs_d : R; fs_pb : R; fs_dqb : R;
  fs_dia : R; fs_dib : R; fs_ds : R; fs_pn : R; fs_eps : R; fs_deps : R;
  fs_t0 : R; fs_dp : R }.

Definition vap (M : fmodel) (vh v : vec) : Prop :=
  ap_in M (vx vh) (vx v) /\ ap_in M (vy vh) (vy v) /\ ap_in M (vz vh) (vz v).

Definition inputs_ok (M : fmodel) (s : span) (F : fsetup) : Prop :=
  vap M (fs_na F) (Na s) /\ vap M (fs_nb F) (Nb s) /\ vap M (fs_l F) (L s).

Definition kcomp_ok (M : fmodel) (m kj a b : R) : Prop :=
  exists t, ap_add M t (b - a) /\ ap_div M kj (t / m).

Definition gouraud_setup_ok (M : fmodel) (s : span) (F : fsetup) : Prop :=
  inputs_ok M s F /\
  fdot_ok M (fs_na F) (fs_l F) (fs_pa F) /\ fdot_ok M (fs_nb F) (fs_l F) (fs_pb F) /\
  exists w, ap_add M w (fs_pb F - fs_pa F) /\ ap_div M (fs_dp F) (w / INR (n s)).

(** Plain Euler (eqs. 12-14): its set-up is the part of [ce_setup_ok] up to
    ds ([ce_setup_eu]): inputs, k, a, p_a, c, d, p_b, dq_b, di_a, di_b, ds;
    the loop starts from s_0 = di_a ([euler_run]). *)
Definition eu_setup_ok (M : fmodel) (s : span) (F : fsetup) : Prop :=
  inputs_ok M s F /\
  kcomp_ok M (INR (n s)) (vx (fs_k F)) (vx (fs_na F)) (vx (fs_nb F)) /\
  kcomp_ok M (INR (n s)) (vy (fs_k F)) (vy (fs_na F)) (vy (fs_nb F)) /\
  kcomp_ok M (INR (n s)) (vz (fs_k F)) (vz (fs_na F)) (vz (fs_nb F)) /\
  fdot_ok M (fs_k F) (fs_l F) (fs_a F) /\
  fdot_ok M (fs_na F) (fs_l F) (fs_pa F) /\
  fdot_ok M (fs_k F) (fs_k F) (fs_c F) /\
  (exists e, fdot_ok M (fs_k F) (fs_na F) e /\ ap_mul M (fs_d F) (2 * e)) /\
  fdot_ok M (fs_nb F) (fs_l F) (fs_pb F) /\
  (exists q, ap_mul M q (2 * INR (n s) * fs_c F) /\ ap_add M (fs_dqb F) (q + fs_d F)) /\
  (exists h x, ap_div M h (fs_pa F / 2) /\ ap_mul M x (h * fs_d F)
               /\ ap_add M (fs_dia F) (fs_a F - x)) /\
  (exists h x, ap_div M h (fs_pb F / 2) /\ ap_mul M x (h * fs_dqb F)
               /\ ap_add M (fs_dib F) (fs_a F - x)) /\
  (exists w, ap_add M w (fs_dib F - fs_dia F) /\ ap_div M (fs_ds F) (w / INR (n s))).

(** Corrected Euler's set-up: Euler's ([eu_setup_ok], up to ds), then
    p_n = p_a + n di_a + n(n-1)/2 ds (any order), eps, d_eps and t0. *)
Definition ce_setup_ok (M : fmodel) (s : span) (F : fsetup) : Prop :=
  eu_setup_ok M s F /\
  (exists q2 q3, ap_mul M q2 (INR (n s) * fs_dia F)
                 /\ ap_mul M q3 (INR (n s) * (INR (n s) - 1) / 2 * fs_ds F)
                 /\ sum3 M (fs_pa F) q2 q3 (fs_pn F)) /\
  ap_add M (fs_eps F) (fs_pn F - fs_pb F) /\
  ap_div M (fs_deps F) (fs_eps F / INR (n s)) /\
  ap_add M (fs_t0 F) (fs_dia F - fs_deps F).

Lemma ce_setup_eu : forall M s F, ce_setup_ok M s F -> eu_setup_ok M s F.
Proof. intros M s F H. exact (proj1 H). Qed.

(** The loops: any sequence each of whose steps is within the addition bound. *)
Definition gouraud_run (M : fmodel) (F : fsetup) (m : nat) (G : nat -> R) : Prop :=
  G O = fs_pa F /\ forall j, (j < m)%nat -> ap_add M (G (S j)) (G j + fs_dp F).

Definition ceuler_run (M : fmodel) (F : fsetup) (m : nat) (P Q : nat -> R) : Prop :=
  P O = fs_pa F /\ Q O = fs_t0 F /\
  forall j, (j < m)%nat -> ap_add M (P (S j)) (P j + Q j) /\ ap_add M (Q (S j)) (Q j + fs_ds F).

Definition euler_run (M : fmodel) (F : fsetup) (m : nat) (P Q : nat -> R) : Prop :=
  P O = fs_pa F /\ Q O = fs_dia F /\
  forall j, (j < m)%nat -> ap_add M (P (S j)) (P j + Q j) /\ ap_add M (Q (S j)) (Q j + fs_ds F).

(** ** The profiles *)

Definition ieee32 : fmodel := mkModel (bpow radix2 (-24)) (bpow radix2 (-150)) 1 1 1 (2 + / 1048576).
Definition ieee64 : fmodel := mkModel (bpow radix2 (-53)) (bpow radix2 (-1075)) 1 1 1 (2 + / 1048576).
Definition shader32 : fmodel := mkModel (bpow radix2 (-24)) (bpow radix2 (-126)) 2 2 2 5.

Lemma u24 : bpow radix2 (-24) = / 16777216.
Proof. simpl. lra. Qed.
Lemma u53 : bpow radix2 (-53) = / 9007199254740992.
Proof. simpl. lra. Qed.

Lemma eta84 : forall e q : Z, (e + 84 <= q)%Z ->
  bpow radix2 e * 19342813113834066795298816 <= bpow radix2 q.
Proof.
  intros e q H. replace 19342813113834066795298816 with (bpow radix2 84) by (simpl; lra).
  rewrite <- bpow_plus. apply bpow_le. exact H.
Qed.

(** A profile's size conditions from Flocq's [flt_fmt_ok] for (emin, prec):
    u = 2^p (p = -prec), eta = 2^e (e = emin - 1). *)
Ltac model_ok_by M emin prec e p urw :=
  destruct (flt_fmt_ok emin prec ltac:(lia) ltac:(lia)) as (H1 & H2 & H3 & H4);
  change (Z.opp prec) with p in *; change (emin - 1)%Z with e in *;
  pose proof (eta84 e p ltac:(lia)) as H5;
  unfold M, model_ok; cbn [m_u m_eta k_in k_add k_mul k_div];
  rewrite urw in *; repeat split; lra.

Lemma ieee32_ok : model_ok ieee32 (2 + / 1048576).
Proof. model_ok_by ieee32 (-149)%Z 24%Z (-150)%Z (-24)%Z u24. Qed.

Lemma ieee64_ok : model_ok ieee64 (2 + / 1048576).
Proof. model_ok_by ieee64 (-1074)%Z 53%Z (-1075)%Z (-53)%Z u53. Qed.

Lemma shader32_ok : model_ok shader32 5.
Proof. model_ok_by shader32 (-125)%Z 24%Z (-126)%Z (-24)%Z u24. Qed.

(** The shader profile with every division (by n, by 2) allowed to be a
    reciprocal within 2.5 ulp followed by a product rounded as the profile's
    products (k = 5 + 2 + 2^-20: [shader32_recip_mul_covered]); a single
    2.5-ulp division is covered too (k = 5 <= 7 + 2^-20), so the theorems on
    [shader32_recip] hold whichever way each division is done. *)
Definition shader32_recip : fmodel :=
  mkModel (bpow radix2 (-24)) (bpow radix2 (-126)) 2 2 2 (7 + / 1048576).

Lemma shader32_recip_ok : model_ok shader32_recip (7 + / 1048576).
Proof. model_ok_by shader32_recip (-125)%Z 24%Z (-126)%Z (-24)%Z u24. Qed.

(** ** Inputs and dot products of unit vectors, factor by factor *)

Definition vap1 (v eta : R) (vh w : vec) : Prop :=
  ap1 v eta (vx vh) (vx w) /\ ap1 v eta (vy vh) (vy w) /\ ap1 v eta (vz vh) (vz w).

Lemma comp_in : forall ui eta A a B b,
  0 <= ui <= / 2097152 -> 0 <= eta -> eta * 1152921504606846976 <= 1 ->
  ap1 ui eta A a -> ap1 ui eta B b -> Rabs a <= 1 -> Rabs b <= 1 ->
  Rabs (A * B - a * b) <= (2 * ui + ui * ui) * (Rabs a * Rabs b) + 3 * eta /\
  Rabs (A * B) <= (1 + 2 * ui + ui * ui) * (Rabs a * Rabs b) + 3 * eta.
Proof.
  intros ui eta A a B b Hu He He1 HA HB Ha Hb. unfold ap1 in *.
  pose proof (Rabs_pos a). pose proof (Rabs_pos b).
  pose proof (Rabs_pos (A - a)). pose proof (Rabs_pos (B - b)).
  assert (D : Rabs (A * B - a * b) <= (2 * ui + ui * ui) * (Rabs a * Rabs b) + 3 * eta).
  { replace (A * B - a * b) with ((A - a) * b + a * (B - b) + (A - a) * (B - b)) by ring.
    eapply Rle_trans; [apply tri3|]. rewrite !Rabs_mult.
    assert (0 <= ui * eta) by nra. nra. }
  split; [exact D|].
  replace (A * B) with (a * b + (A * B - a * b)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_mult. lra.
Qed.

Lemma dot_in : forall ui eta (A a B b : vec),
  0 <= ui <= / 2097152 -> 0 <= eta -> eta * 1152921504606846976 <= 1 ->
  vap1 ui eta A a -> vap1 ui eta B b -> vbounded a 1 -> vbounded b 1 ->
  Rabs (dot A B - dot a b) <=
    (2 * ui + ui * ui) * (Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b)
                          + Rabs (vz a) * Rabs (vz b)) + 9 * eta /\
  Rabs (vx A * vx B) + Rabs (vy A * vy B) + Rabs (vz A * vz B) <=
    (1 + 2 * ui + ui * ui) * (Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b)
                              + Rabs (vz a) * Rabs (vz b)) + 9 * eta.
Proof.
  intros ui eta A a B b Hu He He1 [A1 [A2 A3]] [B1 [B2 B3]] [a1 [a2 a3]] [b1 [b2 b3]].
  destruct (comp_in ui eta _ _ _ _ Hu He He1 A1 B1 a1 b1) as [X1 Y1].
  destruct (comp_in ui eta _ _ _ _ Hu He He1 A2 B2 a2 b2) as [X2 Y2].
  destruct (comp_in ui eta _ _ _ _ Hu He He1 A3 B3 a3 b3) as [X3 Y3].
  split; [|lra].
  unfold dot.
  replace (vx A * vx B + vy A * vy B + vz A * vz B - (vx a * vx b + vy a * vy b + vz a * vz b))
    with ((vx A * vx B - vx a * vx b) + (vy A * vy B - vy a * vy b) + (vz A * vz B - vz a * vz b))
    by ring.
  eapply Rle_trans; [apply tri3|]. lra.
Qed.

(** A computed dot product of two rounded unit vectors (p_a, p_b). *)
Lemma pa_err : forall ui um ua eta (a b A B : vec) (y : R),
  0 <= ui <= / 2097152 -> 0 <= um <= / 2097152 -> 0 <= ua <= / 2097152 ->
  0 <= eta -> eta * 1152921504606846976 <= 1 ->
  is_unit a -> is_unit b -> vap1 ui eta A a -> vap1 ui eta B b ->
  fdot_rel um ua eta A B y ->
  Rabs (y - dot a b) <= (2 * ui + um + 2 * ua) * (1 + / 131072) + 18 * eta.
Proof.
  intros ui um ua eta a b A B y Hi Hm Ha He He1 Hua Hub HA HB Hy.
  pose proof (unit_pair a b Hua Hub) as S1.
  set (S := Rabs (vx a) * Rabs (vx b) + Rabs (vy a) * Rabs (vy b) + Rabs (vz a) * Rabs (vz b))
    in *.
  destruct (dot_in ui eta A a B b Hi He He1 HA HB (unit_bounded a Hua) (unit_bounded b Hub))
    as [D1 D2]. fold S in D1, D2.
  pose proof (fdot_err um ua eta A B y Hm Ha He Hy) as F.
  set (T := Rabs (vx A * vx B) + Rabs (vy A * vy B) + Rabs (vz A * vz B)) in *.
  set (G := um + 2 * ua) in *.
  assert (G0 : 0 <= G <= 3 / 2097152) by (unfold G; lra).
  assert (U1 : ui * ui <= / 2097152 * ui) by (apply Rmult_le_compat_r; lra).
  assert (X1 : (2 * ui + ui * ui) * S <= (2 * ui + ui * ui) * 1) by nra.
  assert (X2 : T <= 1 + 3 / 2097152 + 9 * eta) by nra.
  assert (X3 : G * (1 + / 524288) * T <= G * (1 + / 524288) * (1 + 3 / 2097152 + 9 * eta)) by nra.
  assert (X4 : G * eta <= 3 / 2097152 * eta) by (apply Rmult_le_compat_r; lra).
  replace (y - dot a b) with ((y - dot A B) + (dot A B - dot a b)) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  unfold G in *. lra.
Qed.

(** ** Gouraud, factor by factor *)

Section Gouraud.
Context (M : fmodel) (K : R) (HM : model_ok M K).
Context (s : span) (Hua : is_unit (Na s)) (Hub : is_unit (Nb s)) (Hul : is_unit (L s))
        (Hn1 : (1 <= n s)%nat) (Hn2 : INR (n s) <= 16777216).
Context (F : fsetup) (HF : gouraud_setup_ok M s F).

Local Notation u := (m_u M).
Local Notation eta := (m_eta M).
Local Notation nr := (INR (n s)).

Lemma g_nr : 1 <= nr <= 16777216.
Proof. split; [apply (le_INR 1); exact Hn1 | exact Hn2]. Qed.

(** The units k u of the model (each at most 2^-21) and eta. *)
Lemma g_units : 0 <= k_in M * u <= / 2097152 /\ 0 <= k_add M * u <= / 2097152 /\
  0 <= k_mul M * u <= / 2097152 /\ 0 <= k_div M * u <= / 2097152 /\
  0 <= eta /\ eta * 1152921504606846976 <= u /\ u <= / 2097152.
Proof.
  pose proof HM as (H1 & H2 & H3 & Ki & Ka & Km & Kd & H8 & H9).
  assert (G : forall k, 0 <= k <= K -> 0 <= k * u <= / 2097152)
    by (intros k Hk; destruct (model_unit M K k HM Hk) as [[A B] C]; lra).
  assert (u <= K * u) by (rewrite <- (Rmult_1_l u) at 1; apply Rmult_le_compat_r; lra).
  repeat split; try apply G; lra.
Qed.

Lemma g_pa_pb :
  Rabs (fs_pa F - pa s) <= (2 * (k_in M * u) + k_mul M * u + 2 * (k_add M * u)) * (1 + / 131072) + 18 * eta
  /\ Rabs (fs_pb F - pb s) <= (2 * (k_in M * u) + k_mul M * u + 2 * (k_add M * u)) * (1 + / 131072) + 18 * eta.
Proof.
  destruct HF as ((Ina & Inb & Inl) & Hpa & Hpb & _).
  destruct g_units as (Ui & Ua & Um & Ud & E1 & E2 & E3).
  split; eapply pa_err; try eassumption; lra.
Qed.

Lemma g_dp : Rabs (nr * fs_dp F - (fs_pb F - fs_pa F))
             <= (k_add M * u + k_div M * u) * (2 + / 65536) + 16777218 * eta.
Proof.
  destruct HF as (_ & _ & _ & w & Hw & Hdp).
  destruct g_units as (Ui & Ua & Um & Ud & E1 & E2 & E3). pose proof g_nr as Hn.
  destruct g_pa_pb as [P1 P2].
  pose proof (pa_le s Hua Hul). pose proof (pb_le s Hub Hul).
  set (ua := k_add M * u) in *. set (ud := k_div M * u) in *.
  set (X := fs_pb F - fs_pa F).
  assert (BX : Rabs X <= 2 + / 131072).
  { unfold X. replace (fs_pb F - fs_pa F) with ((pb s - pa s) + (fs_pb F - pb s) + - (fs_pa F - pa s))
      by ring.
    eapply Rle_trans; [apply tri3|]. rewrite Rabs_Ropp.
    pose proof (absdiff (pb s) (pa s)). lra. }
  unfold ap_add, ap_div, approx, ap1 in Hw, Hdp. fold ua ud X in Hw, Hdp.
  assert (BW : Rabs w <= (2 + / 131072) * (1 + / 2097152) + eta).
  { pose proof (abs_near _ _ _ Hw).
    assert (ua * Rabs X <= / 2097152 * (2 + / 131072)) by
      (apply Rmult_le_compat; try lra; apply Rabs_pos). nra. }
  assert (HD : Rabs (nr * fs_dp F - w) <= ud * Rabs w + nr * eta).
  { replace (nr * fs_dp F - w) with (nr * (fs_dp F - w / nr)) by (field; lra).
    rewrite Rabs_mult, (Rabs_pos_eq nr) by lra.
    replace (ud * Rabs w) with (nr * (ud * Rabs (w / nr))).
    - rewrite <- Rmult_plus_distr_l. apply Rmult_le_compat_l; lra.
    - unfold Rdiv. rewrite Rabs_mult, (Rabs_pos_eq (/ nr)) by (apply Rlt_le, Rinv_0_lt_compat; lra).
      field. lra. }
  assert (W1 : ua * Rabs X <= ua * (2 + / 131072)) by (apply Rmult_le_compat_l; lra).
  assert (W2 : ud * Rabs w <= ud * ((2 + / 131072) * (1 + / 2097152) + eta)) by nra.
  assert (W3 : ud * eta <= eta) by (rewrite <- (Rmult_1_l eta) at 2; apply Rmult_le_compat_r; lra).
  assert (W4 : nr * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
  replace (nr * fs_dp F - X) with ((nr * fs_dp F - w) + (w - X)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.

Lemma g_ideal : forall i, (i <= n s)%nat ->
  Rabs (fs_pa F + INR i * fs_dp F - gouraud s i) <=
  (2 * (k_in M * u) + k_mul M * u + 2 * (k_add M * u)) * (1 + / 131072)
  + (k_add M * u + k_div M * u) * (2 + / 65536) + 16777236 * eta.
Proof.
  intros i Hi. destruct g_pa_pb as [P1 P2].
  pose proof (g_near s _ _ _ _ _ Hn1 P1 P2 g_dp i Hi). lra.
Qed.

(** Any model with the size conditions, 1 <= n <= 2^24 and n k_add u <= 2^-11. *)
Lemma profile_gouraud_generic : forall G, gouraud_run M F (n s) G ->
  nr * (k_add M * u) <= / 2048 ->
  forall i, (i <= n s)%nat ->
  Rabs (G i - gouraud s i) <=
  (10006 / 10000 * k_add M * nr + (20001 / 10000 * k_in M + 10001 / 10000 * k_mul M
   + 40001 / 10000 * k_add M + 20001 / 10000 * k_div M + / 1000000)) * u.
Proof.
  intros G [HG0 HG] Hnu i Hi. destruct g_units as (Ui & Ua & Um & Ud & E1 & E2 & E3).
  pose proof (gloop_near (n s) _ _ _ eta (k_add M * u) (gouraud s) G g_nr E1 ltac:(lra) Hnu
    (fun j Hj => conj (g_ideal j Hj) (gouraud_le s Hua Hub Hul Hn1 j Hj))) as L.
  specialize (L ltac:(lra) HG0 HG i Hi). lra.
Qed.

End Gouraud.

Lemma nat_R : forall (m : nat) (z : Z), (Z.of_nat m <= z)%Z -> INR m <= IZR z.
Proof. intros m z H. rewrite INR_IZR_INZ. apply IZR_le. exact H. Qed.

Lemma ce_profile_nr : forall s : span, (1 <= n s <= 4096)%nat ->
  1 <= INR (n s) <= 4096.
Proof.
  intros s Hn. split; [apply (le_INR 1); lia | apply (nat_R _ 4096); lia].
Qed.

(** One instantiation tactic for every profile: [gen] is a generic bound at
    the profile's model; the size conditions come from n <= 4096 (or
    n <= 2^24), the constants from unfolding the model. *)
Ltac profile_inst gen :=
  intros;
  repeat match goal with
  | H : (1 <= n ?s <= 4096)%nat |- _ => pose proof (ce_profile_nr s H); destruct H
  | H : (Z.of_nat (n ?s) <= 16777216)%Z |- _ =>
      pose proof (nat_R _ _ H); pose proof (pos_INR (n s)); clear H
  end;
  eapply Rle_trans;
  [ eapply gen; try eassumption;
    cbn [ieee32 ieee64 shader32 shader32_recip m_u k_in k_add k_mul k_div];
    rewrite ?u24, ?u53; solve [lra | lia]
  | cbn [ieee32 ieee64 shader32 shader32_recip m_u k_in k_add k_mul k_div];
    apply Rmult_le_compat_r; [apply bpow_ge_0 | lra] ].

(** ** Gouraud: the generic bound and the profiles *)

(* Note: ieee profile, binary32: round to nearest (k = 1), division correctly
   rounded or reciprocal then product (k = 2 + 2^-20), subnormals kept. *)
(** Gouraud, ieee profile, binary32: |G_i - gouraud i| <= (1.0006 n + 11.001) 2^-24. *)
Theorem profile_ieee_gouraud_binary32 : forall (s : span) (F : fsetup) (G : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  gouraud_setup_ok ieee32 s F -> gouraud_run ieee32 F (n s) G ->
  forall i, (i <= n s)%nat ->
  Rabs (G i - gouraud s i) <= (10006 / 10000 * INR (n s) + 11001 / 1000) * bpow radix2 (-24).
Proof. profile_inst (profile_gouraud_generic ieee32 _ ieee32_ok). Qed.

(* Note: ieee profile, binary64 (u = 2^-53, eta = 2^-1075). *)
(** Gouraud, ieee profile, binary64: |G_i - gouraud i| <= (1.0006 n + 11.001) 2^-53. *)
Theorem profile_ieee_gouraud_binary64 : forall (s : span) (F : fsetup) (G : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  gouraud_setup_ok ieee64 s F -> gouraud_run ieee64 F (n s) G ->
  forall i, (i <= n s)%nat ->
  Rabs (G i - gouraud s i) <= (10006 / 10000 * INR (n s) + 11001 / 1000) * bpow radix2 (-53).
Proof. profile_inst (profile_gouraud_generic ieee64 _ ieee64_ok). Qed.

(* Note: ieee profile, binary64, spans up to 2^24 pixels. *)
(** Gouraud, ieee profile, binary64, n <= 2^24: |G_i - gouraud i| <= (1.0006 n + 11.001) 2^-53. *)
Theorem profile_ieee_gouraud_binary64_large : forall (s : span) (F : fsetup) (G : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> (Z.of_nat (n s) <= 16777216)%Z ->
  gouraud_setup_ok ieee64 s F -> gouraud_run ieee64 F (n s) G ->
  forall i, (i <= n s)%nat ->
  Rabs (G i - gouraud s i) <= (10006 / 10000 * INR (n s) + 11001 / 1000) * bpow radix2 (-53).
Proof. profile_inst (profile_gouraud_generic ieee64 _ ieee64_ok). Qed.

(* Note: shader profile (Vulkan / WGSL float32): add, sub, mul within 2u
   (nearest or toward zero), division within 2.5 ulp (5u), inputs and results
   may be flushed (eta = 2^-126), any order, fused or not. *)
(** Gouraud, shader profile: |G_i - gouraud i| <= (2.0012 n + 24.002) 2^-24. *)
Theorem profile_shader_gouraud_binary32 : forall (s : span) (F : fsetup) (G : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  gouraud_setup_ok shader32 s F -> gouraud_run shader32 F (n s) G ->
  forall i, (i <= n s)%nat ->
  Rabs (G i - gouraud s i) <= (20012 / 10000 * INR (n s) + 24002 / 1000) * bpow radix2 (-24).
Proof. profile_inst (profile_gouraud_generic shader32 _ shader32_ok). Qed.

(** ** Halving computed in floats (closed forms)

    The closed forms take (i-1)/2 ds.  [half_ok] is that product with the
    halving done in the model: c = (i-1)/2 as a division (one rounded
    division, within 2.5 ulp, or (i-1) times a computed 1/2) then h = c ds;
    or y = (i-1) ds then h = y/2 (a division).  The exact coefficient
    ((i-1)/2 an integer or half-integer of the format formed exactly, e.g.
    (i-1) * 0.5 with the literal 0.5, h = ap_mul of it) is the case c exact. *)
Definition half_rel (v d eta : R) (i : nat) (ds hh : R) : Prop :=
  (exists c, ap1 d eta c ((INR i - 1) / 2) /\ ap1 v eta hh (c * ds)) \/
  (exists y, ap1 v eta y ((INR i - 1) * ds) /\ ap1 d eta hh (y / 2)).

Definition half_ok (M : fmodel) (i : nat) (ds h : R) : Prop :=
  (exists c, ap_div M c ((INR i - 1) / 2) /\ ap_mul M h (c * ds)) \/
  (exists y, ap_mul M y ((INR i - 1) * ds) /\ ap_div M h (y / 2)).

(** The closed forms p = p_a + i (t + h), h within w |X| + e of
    X = (i-1)/2 ds (a product, or the halving of [half_rel]), evaluated as
    g = t + h, m = i g, p = p_a + m: |n t| <= T, |n^2 ds| <= D, the ideal
    value within E0 of the exact ex, |ex| <= B; Sg, Spm bound |i g|, |p_a + m|. *)
Lemma closed_form_err : forall v eta w e nr ii t fds hh g m p fpa ex T D E0 B Sg Spm,
  0 <= v <= / 2097152 -> 0 <= eta -> 0 <= w -> 0 <= e ->
  1 <= nr <= 16777216 -> 0 <= ii <= nr ->
  Rabs (nr * t) <= T -> Rabs (nr * nr * fds) <= D ->
  Rabs (hh - (ii - 1) / 2 * fds) <= w * Rabs ((ii - 1) / 2 * fds) + e ->
  ap1 v eta g (t + hh) -> ap1 v eta m (ii * g) -> ap1 v eta p (fpa + m) ->
  Rabs (fpa + ii * t + ii * (ii - 1) / 2 * fds - ex) <= E0 -> Rabs ex <= B ->
  let Eh := w * (D / 2) + 16777216 * e in
  let E2 := v * (T + D / 2) + (1 + / 2097152) * Eh + 16777216 * eta in
  T + D / 2 + E2 <= Sg -> E0 + B + (Sg * v + eta) + E2 <= Spm ->
  Rabs (p - ex) <= Spm * v + eta + (Sg * v + eta) + E2 + E0.
Proof.
  intros v eta w e nr ii t fds hh g m p fpa ex T D E0 B Sg Spm Hv He Hw Hee Hnr Hi S0 D2 Hh
    Hg Hm Hp G0 G1 Eh E2 HSg HSpm.
  unfold ap1 in Hg, Hm, Hp.
  set (X := (ii - 1) / 2 * fds) in *.
  assert (EX : nr * X = (ii - 1) / (2 * nr) * (nr * nr * fds)) by (unfold X; field; lra).
  assert (Hci : Rabs ((ii - 1) / (2 * nr)) <= 1 / 2).
  { apply Rabs_le. split; apply (Rmult_le_reg_r (2 * nr)); try lra; unfold Rdiv;
      rewrite Rmult_assoc, Rinv_l by lra; lra. }
  assert (BX : Rabs (nr * X) <= D / 2).
  { rewrite EX, Rabs_mult. replace (D / 2) with (1 / 2 * D) by field.
    apply Rmult_le_compat; try apply Rabs_pos; lra. }
  set (Gx := t + X).
  assert (BG : Rabs (nr * Gx) <= T + D / 2).
  { unfold Gx. rewrite Rmult_plus_distr_l. eapply Rle_trans; [apply Rabs_triang|]. lra. }
  assert (AB : forall z, Rabs (nr * z) = nr * Rabs z)
    by (intros z; rewrite Rabs_mult, Rabs_pos_eq by lra; reflexivity).
  rewrite AB in BX, BG.
  assert (E1 : nr * Rabs (hh - X) <= Eh).
  { assert (nr * Rabs (hh - X) <= nr * (w * Rabs X + e)) by (apply Rmult_le_compat_l; lra).
    assert (w * (nr * Rabs X) <= w * (D / 2)) by (apply Rmult_le_compat_l; lra).
    assert (nr * e <= 16777216 * e) by (apply Rmult_le_compat_r; lra).
    unfold Eh. lra. }
  assert (E2b : nr * Rabs (g - Gx) <= E2).
  { replace (g - Gx) with ((g - (t + hh)) + (hh - X)) by (unfold Gx; ring).
    assert (Rabs (t + hh) <= Rabs Gx + Rabs (hh - X)).
    { replace (t + hh) with (Gx + (hh - X)) by (unfold Gx; ring). apply Rabs_triang. }
    assert (nr * Rabs (g - (t + hh)) <= nr * (v * (Rabs Gx + Rabs (hh - X)) + eta)).
    { apply Rmult_le_compat_l; [lra|]. eapply Rle_trans; [exact Hg|].
      apply Rplus_le_compat_r, Rmult_le_compat_l; lra. }
    assert (v * (nr * Rabs Gx) <= v * (T + D / 2)) by (apply Rmult_le_compat_l; lra).
    assert (v * (nr * Rabs (hh - X)) <= / 2097152 * (nr * Rabs (hh - X)))
      by (apply Rmult_le_compat_r; [apply Rmult_le_pos; [lra | apply Rabs_pos] | lra]).
    assert (nr * eta <= 16777216 * eta) by (apply Rmult_le_compat_r; lra).
    assert (nr * Rabs (g - (t + hh) + (hh - X))
            <= nr * Rabs (g - (t + hh)) + nr * Rabs (hh - X)).
    { rewrite <- Rmult_plus_distr_l. apply Rmult_le_compat_l; [lra | apply Rabs_triang]. }
    unfold E2. lra. }
  assert (Ii : forall z, Rabs (ii * z) <= nr * Rabs z) by (intros z; rewrite Rabs_mult,
    (Rabs_pos_eq ii) by lra; apply Rmult_le_compat_r; [apply Rabs_pos | lra]).
  pose proof (Ii Gx) as IG. pose proof (Ii (g - Gx)) as IE.
  assert (Bg : Rabs (ii * g) <= Sg).
  { replace (ii * g) with (ii * Gx + ii * (g - Gx)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra. }
  assert (E3 : Rabs (m - ii * g) <= Sg * v + eta).
  { assert (v * Rabs (ii * g) <= v * Sg) by (apply Rmult_le_compat_l; lra). lra. }
  replace (fpa + ii * t + ii * (ii - 1) / 2 * fds) with (fpa + ii * Gx) in G0
    by (unfold Gx, X; field).
  assert (Bpm : Rabs (fpa + m) <= Spm).
  { replace (fpa + m) with ((fpa + ii * Gx - ex) + ex + (m - ii * g) + ii * (g - Gx)) by ring.
    eapply Rle_trans; [apply tri4|]. lra. }
  assert (E4 : Rabs (p - (fpa + m)) <= Spm * v + eta).
  { assert (v * Rabs (fpa + m) <= v * Spm) by (apply Rmult_le_compat_l; lra). lra. }
  replace (p - ex) with ((p - (fpa + m)) + (m - ii * g) + ii * (g - Gx) + (fpa + ii * Gx - ex))
    by ring.
  eapply Rle_trans; [apply tri4|]. lra.
Qed.

(** ** Corrected Euler: the set-up, with unit v for inputs, additions and
    products and unit d for divisions *)

(** Weights v w1 + d w2 of the componentwise errors (w1, w2 unit-free). *)
Definition vlin (x y : R) (w1 w2 : vec) : vec :=
  mkV (x * vx w1 + y * vx w2) (x * vy w1 + y * vy w2) (x * vz w1 + y * vz w2).

(** The dot-product lemma with weights v w1 + d w2, each weight in [0, W]
    (W <= 16), the second-order terms within the margin m. *)
Lemma dot_w : forall (v d eta Sb W m lam mu y Cv Cd : R) (ah bh a0 b0 wa1 wa2 wb1 wb2 : vec),
  small_ok v eta -> small_ok d eta -> 0 <= W -> W * W / 262144 + W / 32768 + / 10000 <= m ->
  fdot_rel v v eta ah bh y -> 0 < lam -> 0 < mu -> lam * mu <= 281474976710656 ->
  vapprox 1 lam ah a0 (vlin v d wa1 wa2) -> vapprox 1 mu bh b0 (vlin v d wb1 wb2) ->
  vbounded a0 2 -> vbounded b0 2 -> wle wa1 W -> wle wa2 W -> wle wb1 W -> wle wb2 W ->
  Rabs (vx a0) * Rabs (vx b0) + Rabs (vy a0) * Rabs (vy b0) + Rabs (vz a0) * Rabs (vz b0) <= Sb ->
  Sb <= 12 ->
  wsum0 a0 b0 wa1 wb1 + 3 * Sb + m <= Cv -> wsum0 a0 b0 wa2 wb2 + m <= Cd ->
  Rabs (lam * mu * y - dot a0 b0) <= Cv * v + Cd * d.
Proof.
  intros v d eta Sb W m lam mu y Cv Cd ah bh a0 b0 wa1 wa2 wb1 wb2 Hv Hdv HW Hm Hy Hl Hmu Hlm
    HA HB Ba Bb W1 W2 W3 W4 HS HS12 C1 C2.
  small_facts Hv. v_facts Hdv.
  assert (WL : forall w1 w2, wle w1 W -> wle w2 W -> wle (vlin v d w1 w2) (W * (v + d))).
  { intros w1 w2 [X1 [X2 X3]] [Y1 [Y2 Y3]]. unfold wle, vlin; cbn [vx vy vz].
    repeat split; nra. }
  pose proof (fdot_abs v eta Hv lam mu y (W * (v + d)) ah bh a0 b0 _ _ Hy Hl Hmu Hlm HA HB Ba Bb
                (WL _ _ W1 W2) (WL _ _ W3 W4)) as F.
  assert (E : wsum0 a0 b0 (vlin v d wa1 wa2) (vlin v d wb1 wb2)
              = v * wsum0 a0 b0 wa1 wb1 + d * wsum0 a0 b0 wa2 wb2)
    by (unfold wsum0, vlin; cbn [vx vy vz]; ring).
  rewrite E in F.
  set (S := Rabs (vx a0) * Rabs (vx b0) + Rabs (vy a0) * Rabs (vy b0) + Rabs (vz a0) * Rabs (vz b0))
    in *.
  assert (V1 : v * (wsum0 a0 b0 wa1 wb1 + 3 * Sb + m) <= v * Cv) by nra.
  assert (V2 : d * (wsum0 a0 b0 wa2 wb2 + m) <= d * Cd) by (apply Rmult_le_compat_l; lra).
  assert (F1 : v * S <= v * Sb) by (apply Rmult_le_compat_l; lra).
  assert (F2 : v * Sb <= v * 12) by (apply Rmult_le_compat_l; lra).
  set (e := v + d) in *.
  assert (G1 : e * e <= / 1048576 * e) by (apply Rmult_le_compat_r; unfold e; lra).
  assert (0 <= W * W) by nra. assert (0 <= W * e) by (unfold e; nra).
  assert (G2 : W * e * (W * e) <= W * W / 1048576 * e) by nra.
  assert (G3 : v * (W * e) <= W / 2097152 * e) by nra.
  assert (G4 : v * (W * e * (W * e)) <= / 2097152 * (W * W / 1048576 * e)) by nra.
  assert (G5 : m * e >= (W * W / 262144 + W / 32768 + / 10000) * e) by nra.
  assert (0 <= W * W / 1048576 * e) by (unfold e; apply Rmult_le_pos; [nra | lra]).
  eapply Rle_trans; [exact F|]. unfold e in *. lra.
Qed.

Section CE.
Context (v d eta : R) (Hv : small_ok v eta) (Hdv : small_ok d eta).
Context (s : span) (Hua : is_unit (Na s)) (Hub : is_unit (Nb s)) (Hul : is_unit (L s))
        (Hn1 : (1 <= n s)%nat) (Hn2 : INR (n s) <= 16777216).
Context (na nb l kk : vec) (fa fpa fc fd fpb fdqb fdia fdib fds : R).
Context (Ina : vap1 v eta na (Na s)) (Inb : vap1 v eta nb (Nb s)) (Inl : vap1 v eta l (L s)).
Context (tx ty tz : R)
        (Htx : ap1 v eta tx (vx nb - vx na)) (Hkx : ap1 d eta (vx kk) (tx / INR (n s)))
        (Hty : ap1 v eta ty (vy nb - vy na)) (Hky : ap1 d eta (vy kk) (ty / INR (n s)))
        (Htz : ap1 v eta tz (vz nb - vz na)) (Hkz : ap1 d eta (vz kk) (tz / INR (n s))).
Context (Ha : fdot_rel v v eta kk l fa) (Hpa : fdot_rel v v eta na l fpa)
        (Hc : fdot_rel v v eta kk kk fc) (e : R) (He : fdot_rel v v eta kk na e)
        (Hd : ap1 v eta fd (2 * e)) (Hpb : fdot_rel v v eta nb l fpb).
Context (q : R) (Hq : ap1 v eta q (2 * INR (n s) * fc)) (Hdqb : ap1 v eta fdqb (q + fd)).
Context (h1 x1 : R) (Hh1 : ap1 d eta h1 (fpa / 2)) (Hx1 : ap1 v eta x1 (h1 * fd))
        (Hdia : ap1 v eta fdia (fa - x1)).
Context (h2 x2 : R) (Hh2 : ap1 d eta h2 (fpb / 2)) (Hx2 : ap1 v eta x2 (h2 * fdqb))
        (Hdib : ap1 v eta fdib (fa - x2)).
Context (w : R) (Hw : ap1 v eta w (fdib - fdia)) (Hds : ap1 d eta fds (w / INR (n s))).
Context (q2 q3 fpn : R) (Hq2 : ap1 v eta q2 (INR (n s) * fdia))
        (Hq3 : ap1 v eta q3 (INR (n s) * (INR (n s) - 1) / 2 * fds))
        (Hpn : sum3_rel v eta fpa q2 q3 fpn).
Context (feps fdeps ft0 : R) (Heps : ap1 v eta feps (fpn - fpb))
        (Hdeps : ap1 d eta fdeps (feps / INR (n s))) (Ht0 : ap1 v eta ft0 (fdia - fdeps)).

Local Notation nr := (INR (n s)).
Local Notation Dl := (vsub (Nb s) (Na s)).
Local Notation t36 := (/ 68719476736).

Lemma K_nr : 1 <= nr <= 16777216.
Proof. split; [apply (le_INR 1); exact Hn1 | exact Hn2]. Qed.

Ltac basics :=
  pose proof K_nr as Hnr; pose proof (v_pos v eta Hv) as Hu0;
  pose proof (v_small v eta Hv) as Hu1; pose proof (v_pos d eta Hdv) as Hd0;
  pose proof (v_small d eta Hdv) as Hd1.
Ltac ebasics := basics; pose proof (e_pos v eta Hv) as He0; pose proof (e_small v eta Hv) as He1.

Definition vzero : vec := mkV 0 0 0.
(** The weights of n k_j: c (|a0_j| + |b0_j|) + 2^-28, c = 2.001 (v), 1.001 (d). *)
Definition wKc (c : R) (a0 b0 : vec) : vec :=
  mkV (c * (Rabs (vx a0) + Rabs (vx b0)) + / 268435456)
      (c * (Rabs (vy a0) + Rabs (vy b0)) + / 268435456)
      (c * (Rabs (vz a0) + Rabs (vz b0)) + / 268435456).
Definition wKv := wKc (2001 / 1000).
Definition wKd := wKc (1001 / 1000).

Lemma vzero_bounded : wbounded vzero.
Proof. unfold wbounded, vzero; cbn [vx vy vz]. repeat split; lra. Qed.

Lemma wKc_bounded : forall c a0 b0, 0 <= c <= 3 -> vbounded a0 1 -> vbounded b0 1 ->
  wbounded (wKc c a0 b0).
Proof.
  intros c a0 b0 Hc0 [A1 [A2 A3]] [B1 [B2 B3]]. unfold wbounded, wKc; cbn [vx vy vz].
  pose proof (Rabs_pos (vx a0)). pose proof (Rabs_pos (vy a0)). pose proof (Rabs_pos (vz a0)).
  pose proof (Rabs_pos (vx b0)). pose proof (Rabs_pos (vy b0)). pose proof (Rabs_pos (vz b0)).
  repeat split; nra.
Qed.

Lemma K_in_vec : forall vh w0, vap1 v eta vh w0 -> vapprox 1 1 vh w0 (vlin v d (wIn w0) vzero).
Proof.
  intros vh w0 [H1 [H2 H3]]. unfold vapprox, vlin, wIn, vzero; cbn [vx vy vz].
  rewrite !Rmult_1_l, !Rmult_0_r, !Rplus_0_r.
  repeat split; apply (FloatModelK.in_comp v eta Hv); assumption.
Qed.

(** One component of n k: input, subtraction (unit v), division (unit d). *)
Lemma K_comp : forall (m a0 b0 ra rb t kj : R), 1 <= m <= 16777216 -> Rabs a0 <= 1 -> Rabs b0 <= 1 ->
  ap1 v eta ra a0 -> ap1 v eta rb b0 -> ap1 v eta t (rb - ra) -> ap1 d eta kj (t / m) ->
  Rabs (m * kj - (b0 - a0)) <=
  v * (2001 / 1000 * (Rabs a0 + Rabs b0) + / 268435456)
  + d * (1001 / 1000 * (Rabs a0 + Rabs b0) + / 268435456).
Proof.
  intros m a0 b0 ra rb t kj Hm Ha0 Hb0 Hra Hrb Ht Hkj.
  v_facts Hv. v_facts Hdv.
  pose proof (Rabs_pos a0). pose proof (Rabs_pos b0).
  pose proof (FloatModelK.in_comp v eta Hv _ _ Hra) as F1.
  pose proof (FloatModelK.in_comp v eta Hv _ _ Hrb) as F2.
  assert (D1 : Rabs (rb - ra) <= Rabs a0 + Rabs b0 + Rabs (ra - a0) + Rabs (rb - b0)).
  { replace (rb - ra) with ((b0 - a0) + (rb - b0) + - (ra - a0)) by ring.
    eapply Rle_trans; [apply tri3|]. rewrite Rabs_Ropp. pose proof (absdiff b0 a0). lra. }
  pose proof (ap_1 v eta Hv t (rb - ra) (Rabs (rb - ra)) Ht (Rle_refl _)) as F3.
  assert (HK : m * (t / m) = t) by (field; lra).
  pose proof (ap_sc d eta Hdv m kj (t / m) (Rabs t) Hkj ltac:(lra)
                ltac:(rewrite HK; lra)) as F4.
  rewrite HK in F4.
  set (sa := Rabs a0 + Rabs b0) in *.
  assert (P1 : v * sa <= / 2097152 * sa) by (apply Rmult_le_compat_r; unfold sa; lra).
  assert (R1 : Rabs (rb - ra) <= (1 + / 2097152) * sa + / 1125899906842624).
  { assert (v * / 1073741824 <= / 2097152 * / 1073741824) by (apply Rmult_le_compat_r; lra).
    unfold sa in *. lra. }
  assert (P2 : v * Rabs (rb - ra) <= v * ((1 + / 2097152) * sa + / 1125899906842624)) by nra.
  assert (T1 : Rabs t <= (1 + / 1048576) * sa + / 1099511627776).
  { pose proof (abs_near _ _ _ F3).
    assert (0 <= sa <= 2) by (unfold sa; lra). lra. }
  assert (P3 : d * Rabs t <= d * ((1 + / 1048576) * sa + / 1099511627776)) by nra.
  assert (P5 : 0 <= v * sa) by (apply Rmult_le_pos; unfold sa; lra).
  assert (P6 : 0 <= d * sa) by (apply Rmult_le_pos; unfold sa; lra).
  replace (m * kj - (b0 - a0))
    with ((m * kj - t) + (t - (rb - ra)) + (rb - b0) + - (ra - a0)) by ring.
  eapply Rle_trans; [apply tri4|]. rewrite Rabs_Ropp. unfold sa in *. lra.
Qed.

Lemma K_k_vec : vapprox 1 nr kk Dl (vlin v d (wKv (Na s) (Nb s)) (wKd (Na s) (Nb s))).
Proof.
  pose proof K_nr as Hm.
  destruct (unit_bounded _ Hua) as [A1 [A2 A3]].
  destruct (unit_bounded _ Hub) as [B1 [B2 B3]].
  destruct Ina as [I1 [I2 I3]]. destruct Inb as [J1 [J2 J3]].
  unfold vapprox, vlin, wKv, wKd, wKc, vsub; cbn [vx vy vz]. rewrite !Rmult_1_l.
  repeat split; eapply K_comp; eassumption.
Qed.

(** The dot-product lemma with weights v w1 + d w2. *)
Lemma K_dot : forall (lam mu y Sb Cv Cd : R) (ah bh a0 b0 wa1 wa2 wb1 wb2 : vec),
  fdot_rel v v eta ah bh y -> 0 < lam -> 0 < mu -> lam * mu <= 281474976710656 ->
  vapprox 1 lam ah a0 (vlin v d wa1 wa2) -> vapprox 1 mu bh b0 (vlin v d wb1 wb2) ->
  vbounded a0 2 -> vbounded b0 2 -> wbounded wa1 -> wbounded wa2 -> wbounded wb1 -> wbounded wb2 ->
  Rabs (vx a0) * Rabs (vx b0) + Rabs (vy a0) * Rabs (vy b0) + Rabs (vz a0) * Rabs (vz b0) <= Sb ->
  Sb <= 12 ->
  wsum0 a0 b0 wa1 wb1 + 3 * Sb + / 1000 <= Cv -> wsum0 a0 b0 wa2 wb2 + / 1000 <= Cd ->
  Rabs (lam * mu * y - dot a0 b0) <= Cv * v + Cd * d.
Proof.
  intros. assert (B : forall z, wbounded z -> wle z 8)
    by (intros z (? & ? & ?); repeat split; lra).
  eapply (dot_w v d eta Sb 8 (/ 1000)); (apply B; assumption) || eassumption || lra.
Qed.

Ltac unit_facts := unit_facts_of s Hua Hub Hul.

Ltac wKb := first [ apply vzero_bounded
  | apply (wIn_bounded _ (unit_bounded _ Hua)) | apply (wIn_bounded _ (unit_bounded _ Hub))
  | apply (wIn_bounded _ (unit_bounded _ Hul))
  | (eapply wKc_bounded; [lra | apply (unit_bounded _ Hua) | apply (unit_bounded _ Hub)]) ].

(** A set-up dot product H by [K_dot] with scales lam, mu and |a0| |b0| <= Sb. *)
Ltac kdot lam mu Sb H :=
  unit_facts;
  lazymatch lam with 1 => idtac | _ => pose proof K_nr; assert (nr * nr <= 281474976710656) by nra end;
  match goal with |- _ <= ?Cv * v + ?Cd * d => epose proof (K_dot lam mu _ Sb Cv Cd
    _ _ _ _ _ _ _ _ H ltac:(lra) ltac:(lra) ltac:(lra)) as HD;
    rewrite ?Rmult_1_l, ?Rmult_1_r in HD; eapply HD end;
  first [ apply K_k_vec | apply K_in_vec; assumption | apply diff_bounded; assumption
        | apply vb12, unit_bounded; assumption | wKb
        | unfold wsum0, wIn, wKv, wKd, wKc, vzero; cbn [vx vy vz]; lra ].

Lemma K_pa : Rabs (fpa - pa s) <= 5002 / 1000 * v + 1 / 1000 * d.
Proof. kdot 1 1 1 Hpa. Qed.

Lemma K_pb : Rabs (fpb - pb s) <= 5002 / 1000 * v + 1 / 1000 * d.
Proof. kdot 1 1 1 Hpb. Qed.

Lemma K_a : Rabs (nr * fa - dot Dl (L s)) <= 1201 / 100 * v + 201 / 100 * d.
Proof. kdot (INR (n s)) 1 2 Ha. Qed.

Lemma K_c : Rabs (nr * nr * fc - dot Dl Dl) <= 2802 / 100 * v + 801 / 100 * d.
Proof. kdot (INR (n s)) (INR (n s)) 4 Hc. Qed.

Lemma K_d0 : Rabs (nr * e - dot Dl (Na s)) <= 1201 / 100 * v + 201 / 100 * d.
Proof. kdot (INR (n s)) 1 2 He. Qed.

Lemma K_d : Rabs (nr * fd - 2 * dot Dl (Na s)) <= 2803 / 100 * v + 402 / 100 * d.
Proof.
  basics. pose proof K_d0 as H0. pose proof (dl_dot_le s Hua Hub (Na s) Hua) as H1.
  eapply Rle_trans; [apply (ap_step v eta Hv nr fd (2 * e) (2 * (nr * e)) _
             (2402 / 100 * v + 402 / 100 * d) (4001 / 1000) Hd); [lra | ring | | ] | lra].
  - rewrite <- Rmult_minus_distr_l, Rabs_mult, (Rabs_pos_eq 2) by lra. lra.
  - rewrite Rabs_mult, (Rabs_pos_eq 2) by lra. lra.
Qed.

Lemma K_c2 : Rabs (nr * q - 2 * dot Dl Dl) <= 6405 / 100 * v + 1602 / 100 * d.
Proof.
  basics. pose proof K_c as H0. pose proof (dl_dd s Hua Hub) as H1.
  eapply Rle_trans; [apply (ap_step v eta Hv nr q (2 * nr * fc) (2 * (nr * nr * fc)) _
             (5604 / 100 * v + 1602 / 100 * d) (8001 / 1000) Hq); [lra | ring | | ] | lra].
  - rewrite <- Rmult_minus_distr_l, Rabs_mult, (Rabs_pos_eq 2) by lra. lra.
  - rewrite Rabs_mult, (Rabs_pos_eq 2), Rabs_pos_eq by lra. lra.
Qed.

Lemma K_qb : Rabs (nr * fdqb - 2 * dot Dl (Nb s)) <= 9609 / 100 * v + 2004 / 100 * d.
Proof.
  basics. pose proof K_c2 as H0. pose proof K_d as H1.
  pose proof (dl_dot_le s Hua Hub (Nb s) Hub) as H2.
  eapply Rle_trans; [apply (ap_step v eta Hv nr fdqb (q + fd) (nr * q + nr * fd) _
             (9208 / 100 * v + 2004 / 100 * d) (4001 / 1000) Hdqb); [lra | ring | | ] | lra].
  - rewrite <- (dl_sum s).
    replace (nr * q + nr * fd - 2 * (dot Dl Dl + dot Dl (Na s)))
      with ((nr * q - 2 * dot Dl Dl) + (nr * fd - 2 * dot Dl (Na s))) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra.
  - rewrite Rabs_mult, (Rabs_pos_eq 2) by lra. lra.
Qed.

Lemma K_h : forall (x X h : R), ap1 d eta h (X / 2) -> Rabs x <= 1 ->
  Rabs (X - x) <= 5002 / 1000 * v + 1 / 1000 * d ->
  Rabs (h - x / 2) <= 2501 / 1000 * v + 502 / 1000 * d.
Proof.
  intros x X h Hh Hx HX. basics.
  pose proof (ap_step d eta Hdv 1 h (X / 2) (X / 2) (x / 2) (2501 / 1000 * v + 5 / 10000 * d)
                (501 / 1000) Hh ltac:(lra) ltac:(ring)) as H.
  rewrite Rmult_1_l in H. eapply Rle_trans; [apply H|lra].
  - replace (X / 2 - x / 2) with ((X - x) * / 2) by field.
    rewrite Rabs_mult, (Rabs_pos_eq (/ 2)) by lra. lra.
  - unfold Rdiv. rewrite Rabs_mult, (Rabs_pos_eq (/ 2)) by lra. lra.
Qed.

(** x = h F with h the halving of fP (within [K_h]) and n F within E of 2 X. *)
Lemma K_x : forall (P fP h F X x E : R), Rabs P <= 1 ->
  Rabs (fP - P) <= 5002 / 1000 * v + 1 / 1000 * d -> ap1 d eta h (fP / 2) ->
  Rabs (nr * F - 2 * X) <= E -> E <= / 1000 -> Rabs X <= 2 -> ap1 v eta x (h * F) ->
  Rabs (nr * x - P * X)
  <= (2501 / 1000 * v + 502 / 1000 * d) * (4001 / 1000) + 1 / 2 * E
     + (2001 / 1000 + / 68719476736) * v.
Proof.
  intros P fP h F X x E HP HfP Hh H0 HE H1 Hx. basics.
  pose proof (K_h P fP h Hh HP HfP) as H3.
  assert (H4 : Rabs (nr * F) <= 4001 / 1000).
  { pose proof (abs_near _ _ _ H0).
    assert (Rabs (2 * X) <= 4) by (rewrite Rabs_mult, (Rabs_pos_eq 2) by lra; lra). lra. }
  assert (H5 : Rabs (P / 2) <= 1 / 2)
    by (unfold Rdiv; rewrite Rabs_mult, (Rabs_pos_eq (/ 2)) by lra; lra).
  pose proof (prod_err h (P / 2) (nr * F) (2 * X) _ _ _ _ H3 H0 H4 H5) as H6.
  replace (P / 2 * (2 * X)) with (P * X) in H6 by field.
  assert (H7 : Rabs (P * X) <= 2)
    by (rewrite Rabs_mult; pose proof (Rabs_pos P); pose proof (Rabs_pos X); nra).
  apply (ap_step v eta Hv nr x (h * F) (h * (nr * F)) _ _ (2001 / 1000) Hx);
    [lra | ring | exact H6 | lra].
Qed.

Lemma K_xa : Rabs (nr * x1 - pa s * dot Dl (Na s)) <= 2603 / 100 * v + 402 / 100 * d.
Proof.
  basics. pose proof (K_x _ _ _ _ _ _ _ (pa_le s Hua Hul) K_pa Hh1 K_d ltac:(lra)
    (dl_dot_le s Hua Hub (Na s) Hua) Hx1). lra.
Qed.

Lemma K_xb : Rabs (nr * x2 - pb s * dot Dl (Nb s)) <= 6006 / 100 * v + 1203 / 100 * d.
Proof.
  basics. pose proof (K_x _ _ _ _ _ _ _ (pb_le s Hub Hul) K_pb Hh2 K_qb ltac:(lra)
    (dl_dot_le s Hua Hub (Nb s) Hub) Hx2). lra.
Qed.

(** di = a - x with n x within E of Y, |a.L - Y| <= 2. *)
Lemma K_di_r : forall (x fdi Y E : R), ap1 v eta fdi (fa - x) -> Rabs (nr * x - Y) <= E ->
  E <= / 1024 -> Rabs (dot Dl (L s) - Y) <= 2 ->
  Rabs (nr * fdi - (nr * fa - nr * x)) <= 2002 / 1000 * v.
Proof.
  intros x fdi Y E Hdi HY HE H2. basics. pose proof K_a as H0.
  rewrite <- Rmult_minus_distr_l.
  eapply Rle_trans; [apply (ap_sc v eta Hv _ _ _ (2001 / 1000) Hdi); [lra|] | lra].
  rewrite Rmult_minus_distr_l.
  apply (Rle_trans _ (Rabs (dot Dl (L s) - Y) + ((1201 / 100 * v + 201 / 100 * d) + E))); [|lra].
  apply abs_near.
  replace (nr * fa - nr * x - (dot Dl (L s) - Y))
    with ((nr * fa - dot Dl (L s)) - (nr * x - Y)) by ring.
  eapply Rle_trans; [apply absdiff|]. lra.
Qed.

Lemma K_dia_r : Rabs (nr * fdia - (nr * fa - nr * x1)) <= 2002 / 1000 * v.
Proof. basics. exact (K_di_r _ _ _ _ Hdia K_xa ltac:(lra) (ndia_le s Hua Hub Hul)). Qed.

Lemma K_dib_r : Rabs (nr * fdib - (nr * fa - nr * x2)) <= 2002 / 1000 * v.
Proof. basics. exact (K_di_r _ _ _ _ Hdib K_xb ltac:(lra) (ndib_le s Hua Hub Hul)). Qed.

Lemma K_dia : Rabs (nr * fdia - e_ndia s) <= 4005 / 100 * v + 603 / 100 * d.
Proof.
  basics. pose proof K_a as H0. pose proof K_xa as H1. pose proof K_dia_r as H2.
  unfold e_ndia.
  replace (nr * fdia - (dot Dl (L s) - pa s * dot Dl (Na s)))
    with ((nr * fdia - (nr * fa - nr * x1)) + (nr * fa - dot Dl (L s))
          + - (nr * x1 - pa s * dot Dl (Na s))) by ring.
  eapply Rle_trans; [apply tri3|]. rewrite Rabs_Ropp. lra.
Qed.

Lemma K_w : Rabs (nr * w - e_n2ds s) <= 9211 / 100 * v + 1605 / 100 * d.
Proof.
  basics. pose proof K_xa as H0. pose proof K_xb as H1. pose proof K_dia_r as H2.
  pose proof K_dib_r as H3. pose proof (n2ds_le s Hua Hub Hul) as H4.
  eapply Rle_trans; [apply (ap_step v eta Hv nr w (fdib - fdia) (nr * fdib - nr * fdia) _
             (9010 / 100 * v + 1605 / 100 * d) (2001 / 1000) Hw); [lra | ring | | lra] | lra].
  unfold e_n2ds, e_ndib, e_ndia.
  replace (nr * fdib - nr * fdia
           - (dot Dl (L s) - pb s * dot Dl (Nb s) - (dot Dl (L s) - pa s * dot Dl (Na s))))
    with ((nr * fdib - (nr * fa - nr * x2))
          + - (nr * fdia - (nr * fa - nr * x1))
          + (nr * x1 - pa s * dot Dl (Na s))
          + - (nr * x2 - pb s * dot Dl (Nb s))) by ring.
  eapply Rle_trans; [apply tri4|]. rewrite !Rabs_Ropp. lra.
Qed.

Lemma K_ds : Rabs (nr * nr * fds - e_n2ds s) <= 9211 / 100 * v + 1806 / 100 * d.
Proof.
  basics. pose proof K_w as H0. pose proof (n2ds_le s Hua Hub Hul) as H1.
  eapply Rle_trans; [apply (ap_step d eta Hdv (nr * nr) fds (w / nr) (nr * w) _
             (9211 / 100 * v + 1605 / 100 * d) (2001 / 1000) Hds);
    [nra | field; lra | exact H0 | lra] | lra].
Qed.

Lemma K_Yb : Rabs (nr * (nr - 1) / 2 * fds) <= 1001 / 1000.
Proof. basics. exact (Yb_near nr _ _ _ ltac:(lra) K_ds (n2ds_le s Hua Hub Hul) ltac:(lra)). Qed.

(** p_n = p_a + n di_a + n(n-1)/2 ds, the three terms summed in any order. *)
Lemma K_rhon : Rabs (fpn - (fpa + nr * fdia + nr * (nr - 1) / 2 * fds)) <= 1202 / 100 * v.
Proof.
  ebasics. pose proof K_dia as G0. pose proof (ndia_le s Hua Hub Hul) as G1.
  pose proof K_pa as G2. pose proof (pa_le s Hua Hul) as G3. pose proof K_Yb as G4.
  pose proof (sum3_err v v eta fpa (nr * fdia) (nr * (nr - 1) / 2 * fds) fpa q2 q3 fpn
                ltac:(lra) ltac:(lra) He0 (ap1_exact v eta fpa ltac:(lra) He0) Hq2 Hq3 Hpn) as S.
  assert (B1 : Rabs (nr * fdia) <= 2001 / 1000) by (pose proof (abs_near _ _ _ G0); lra).
  assert (B2 : Rabs fpa <= 1001 / 1000) by (pose proof (abs_near _ _ _ G2); lra).
  assert (B3 : (v + 2 * v) * (1 + / 524288) * (Rabs fpa + Rabs (nr * fdia)
                 + Rabs (nr * (nr - 1) / 2 * fds))
               <= (v + 2 * v) * (1 + / 524288) * (4003 / 1000))
    by (apply Rmult_le_compat_l; [apply Rmult_le_pos|]; lra).
  lra.
Qed.

Lemma K_pnb : Rabs fpn <= 4005 / 1000.
Proof.
  basics. pose proof K_rhon as G0. pose proof K_dia as G1. pose proof (ndia_le s Hua Hub Hul).
  pose proof K_pa as G2. pose proof (pa_le s Hua Hul). pose proof K_Yb.
  apply (Rle_trans _ _ _ (abs_near _ _ _ G0)).
  pose proof (tri3 fpa (nr * fdia) (nr * (nr - 1) / 2 * fds)).
  pose proof (abs_near _ _ _ G1). pose proof (abs_near _ _ _ G2). lra.
Qed.

Lemma K_rhoe : Rabs (feps - (fpn - fpb)) <= 5007 / 1000 * v.
Proof.
  basics. pose proof K_pnb. pose proof K_pb as G0. pose proof (pb_le s Hub Hul).
  eapply Rle_trans; [apply (ap_1 v eta Hv _ _ (5006 / 1000) Heps)|lra].
  eapply Rle_trans; [apply absdiff|]. pose proof (abs_near _ _ _ G0). lra.
Qed.

Lemma K_rhod : Rabs (nr * fdeps - feps) <= 5008 / 1000 * d.
Proof.
  basics. pose proof K_pnb. pose proof K_pb as G0. pose proof (pb_le s Hub Hul).
  pose proof K_rhoe as G1.
  assert (B : Rabs feps <= 5007 / 1000).
  { apply (Rle_trans _ _ _ (abs_near _ _ _ G1)).
    pose proof (absdiff fpn fpb). pose proof (abs_near _ _ _ G0). lra. }
  eapply Rle_trans; [apply (ap_step d eta Hdv nr fdeps (feps / nr) feps feps 0 (5007 / 1000) Hdeps);
      [lra | field; lra | rewrite Rminus_diag_eq, Rabs_R0 by reflexivity; lra | lra] | lra].
Qed.

Lemma K_R : Rabs (nr * ft0 - (fpb - fpa - nr * (nr - 1) / 2 * fds)) <= 2004 / 100 * v + 501 / 100 * d.
Proof.
  basics. pose proof (R_near nr _ ft0 _ _ _ _ _ _ _ _ _ _ _ _ _ K_rhon K_rhoe K_rhod K_pa K_pb
    (pa_le s Hua Hul) (pb_le s Hub Hul) K_Yb ltac:(lra)
    (ap_sc v eta Hv nr ft0 (fdia - fdeps) _ Ht0 ltac:(lra))). lra.
Qed.

Lemma K_ce_ideal : forall i, (i <= n s)%nat ->
  Rabs (fpa + INR i * ft0 + INR i * (INR i - 1) / 2 * fds - ceuler s i)
  <= 3656 / 100 * v + 727 / 100 * d.
Proof.
  intros i Hi. basics.
  pose proof (ce_near s Hn1 _ _ _ _ _ _ _ K_pa K_pb K_R K_ds i Hi). lra.
Qed.

(** Computed slopes (ideal, on the computed t0 and ds) for 1 <= J <= n-1. *)
Lemma K_slope : forall J, (J < n s)%nat ->
  Rabs (nr * (ft0 + INR J * fds)) <= 2 + 200 * (v + d).
Proof.
  intros J HJ. basics.
  pose proof (slope_near s Hua Hub Hul Hn1 _ _ _ _ _ _ _ K_pa K_pb K_R K_ds J HJ). lra.
Qed.

(** The loop, with its own addition unit ua <= v and n ua <= 2^-11. *)
Lemma K_ce_final : forall (ua : R) (P Q : nat -> R), 0 <= ua <= v -> nr * ua <= / 2048 ->
  P O = fpa -> Q O = ft0 ->
  (forall j, (j < n s)%nat -> ap1 ua eta (P (S j)) (P j + Q j) /\ ap1 ua eta (Q (S j)) (Q j + fds)) ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - ceuler s i) <= 22 / 10 * (nr * ua) + 366 / 10 * v + 73 / 10 * d.
Proof.
  intros ua P Q Hua0 Hnua HP0 HQ0 Hstep i Hi. ebasics.
  pose proof (loop_near (n s) fpa fds ft0 (2 + 200 * (v + d)) (2002 / 1000) (1194 / 1000)
    (3656 / 100 * v + 727 / 100 * d) (11925 / 10000) eta ua (ceuler s) P Q K_nr He0 (proj1 Hua0)
    Hnua ltac:(lra) ltac:(lra) ltac:(lra) ltac:(lra) K_slope
    (fun j Hj => conj (K_ce_ideal j Hj) (ceuler_le s Hua Hub Hul Hn1 j Hj))
    HP0 HQ0 Hstep i Hi).
  assert (0 <= nr * ua) by (apply Rmult_le_pos; lra). lra.
Qed.

(** A closed form by [closed_form_err]: the step h within w |X| + e of
    X = (i-1)/2 ds, against corrected Euler ([ce_closed]) or Euler ([eu_closed]). *)
Ltac closed_by w e t ex T D Sg Spm :=
  match goal with Hi : (?i <= n s)%nat |- _ =>
    assert (0 <= INR i <= nr) by (split; [apply pos_INR | apply le_INR; exact Hi]);
    eapply Rle_trans;
      [eapply (closed_form_err v eta w e nr (INR i) t fds _ _ _ _ fpa (ex i) T D _ _ Sg Spm);
       try eassumption; try lra | lra]
  end.
Ltac ce_closed w e :=
  ebasics; pose proof (K_slope 0 ltac:(lia)) as S0; cbn [INR] in S0;
  rewrite Rmult_0_l, Rplus_0_r in S0;
  pose proof K_ds as D0; pose proof (n2ds_le s Hua Hub Hul); pose proof (abs_near _ _ _ D0);
  match goal with Hi : (?i <= n s)%nat |- _ =>
    pose proof (K_ce_ideal i Hi); pose proof (ceuler_le s Hua Hub Hul Hn1 i Hi) end;
  closed_by w e ft0 (ceuler s) (20002 / 10000) (2001 / 1000) (30009 / 10000) (11926 / 10000).
(** The closed form p_i = p_a + i (t0 + (i-1)/2 ds), evaluated as
    h = (i-1)/2 * ds, g = t0 + h, m = i * g, p = p_a + m (each within its
    bound, h and m possibly exact: fused multiply-adds). *)
Lemma K_closed : forall i, (i <= n s)%nat -> forall hh g m p : R,
  ap1 v eta hh ((INR i - 1) / 2 * fds) -> ap1 v eta g (ft0 + hh) ->
  ap1 v eta m (INR i * g) -> ap1 v eta p (fpa + m) ->
  Rabs (p - ceuler s i) <= 45 * v + 73 / 10 * d.
Proof. intros i Hi hh g m p Hh Hg Hm Hp. ce_closed v eta. Qed.


(** *** Plain Euler (eqs. 12-14) on the same set-up

    Euler's set-up is the part of corrected Euler's up to ds (p_a, di_a, ds);
    the lemmas below use only [K_pa], [K_dia] and [K_ds], so after the
    section they take only those operations (not p_n, eps, d_eps, t_0).
    The exact run is [euler_span s i] = p_a + i di_a + i(i-1)/2 ds. *)

Lemma K_kap : forall i, (i <= n s)%nat ->
  0 <= INR i / nr <= 1 /\ 0 <= INR i * (INR i - 1) / (2 * (nr * nr)) <= 1 / 2.
Proof.
  intros i Hi. basics.
  assert (Hi' : 0 <= INR i <= nr) by (split; [apply pos_INR | apply le_INR; exact Hi]).
  split; [apply theta_rng; lra|].
  assert (H0 : 0 <= INR i * (INR i - 1)).
  { destruct i as [|i']; [cbn [INR]; lra|].
    assert (1 <= INR (S i')) by (apply (le_INR 1); lia). nra. }
  split.
  - unfold Rdiv. apply Rmult_le_pos; [lra | apply Rlt_le, Rinv_0_lt_compat; nra].
  - apply (Rmult_le_reg_r (2 * (nr * nr))); [nra|]. unfold Rdiv.
    rewrite Rmult_assoc, Rinv_l by nra.
    assert (INR i * INR i <= nr * nr) by (apply Rmult_le_compat; lra). nra.
Qed.

(** The exact Euler value, scaled: p_a + (i/n) (n di_a) + i(i-1)/(2n^2) (n^2 ds). *)
Lemma K_eu_exact : forall i, (i <= n s)%nat ->
  euler_span s i = pa s + INR i / nr * e_ndia s
                   + INR i * (INR i - 1) / (2 * (nr * nr)) * e_n2ds s.
Proof.
  intros i Hi. basics. unfold euler_span.
  rewrite eq_14_euler_closed_form, (dia_scaled s Hn1), (ds_scaled s Hn1).
  field. lra.
Qed.

(** The combination a + th b + ka c of [K_eu_exact] (th in [0, 1], ka in [0, 1/2]). *)
Lemma comb3 : forall th ka a b c ea eb ec, 0 <= th <= 1 -> 0 <= ka <= 1 / 2 ->
  Rabs a <= ea -> Rabs b <= eb -> Rabs c <= ec -> Rabs (a + th * b + ka * c) <= ea + eb + ec / 2.
Proof.
  intros th ka a b c ea eb ec Th Ka Xa Xb Xc.
  eapply Rle_trans; [apply tri3|]. rewrite !Rabs_mult, (Rabs_pos_eq th), (Rabs_pos_eq ka) by lra.
  assert (th * Rabs b <= 1 * eb) by (apply Rmult_le_compat; try lra; apply Rabs_pos).
  assert (ka * Rabs c <= 1 / 2 * ec) by (apply Rmult_le_compat; try lra; apply Rabs_pos).
  lra.
Qed.

(** |p_i| <= 1 + 2 + 1.54/2 on the exact run. *)
Lemma K_eu_le : forall i, (i <= n s)%nat -> Rabs (euler_span s i) <= 377 / 100.
Proof.
  intros i Hi. destruct (K_kap i Hi) as [Th Ka]. rewrite (K_eu_exact i Hi).
  pose proof (comb3 _ _ _ _ _ _ _ _ Th Ka (pa_le s Hua Hul) (ndia_le s Hua Hub Hul)
                (n2ds_le' s Hua Hub Hul)). lra.
Qed.

(** The computed values on their exact recurrence: p_a, di_a, ds carried exactly. *)
Lemma K_eu_ideal : forall i, (i <= n s)%nat ->
  Rabs (fpa + INR i * fdia + INR i * (INR i - 1) / 2 * fds - euler_span s i)
  <= 9111 / 100 * v + 1507 / 100 * d.
Proof.
  intros i Hi. basics. destruct (K_kap i Hi) as [Th Ka]. rewrite (K_eu_exact i Hi).
  replace (fpa + INR i * fdia + INR i * (INR i - 1) / 2 * fds
           - (pa s + INR i / nr * e_ndia s + INR i * (INR i - 1) / (2 * (nr * nr)) * e_n2ds s))
    with ((fpa - pa s) + INR i / nr * (nr * fdia - e_ndia s)
          + INR i * (INR i - 1) / (2 * (nr * nr)) * (nr * nr * fds - e_n2ds s))
    by (field; lra).
  pose proof (comb3 _ _ _ _ _ _ _ _ Th Ka K_pa K_dia K_ds). lra.
Qed.

(** Computed slopes (ideal, on the computed di_a and ds): |n (di_a + J ds)| <= 2 + 1.54. *)
Lemma K_eu_slope : forall J, (J <= n s)%nat ->
  Rabs (nr * (fdia + INR J * fds)) <= 354 / 100 + 200 * (v + d).
Proof.
  intros J HJ. basics. destruct (K_kap J HJ) as [Th _].
  pose proof (abs_near _ _ _ K_dia). pose proof (abs_near _ _ _ K_ds).
  pose proof (ndia_le s Hua Hub Hul). pose proof (n2ds_le' s Hua Hub Hul).
  replace (nr * (fdia + INR J * fds)) with (nr * fdia + INR J / nr * (nr * nr * fds))
    by (field; lra).
  eapply Rle_trans; [apply Rabs_triang|].
  rewrite (Rabs_mult (INR J / nr)), (Rabs_pos_eq (INR J / nr)) by lra.
  assert (INR J / nr * Rabs (nr * nr * fds) <= 1 * (154 / 100 + (9211 / 100 * v + 1806 / 100 * d)))
    by (apply Rmult_le_compat; try lra; apply Rabs_pos).
  lra.
Qed.

(** The loop p += s, s += ds from (p_a, di_a), with its own addition unit
    ua <= v and n ua <= 2^-11: the loop contributes 5.55 n ua
    (n^2/2 max|s_k| + n max|p_j|, with n |s_k| <= 3.545 and |p_j| <= 3.775). *)
Lemma K_eu_final : forall (ua : R) (P Q : nat -> R), 0 <= ua <= v -> nr * ua <= / 2048 ->
  P O = fpa -> Q O = fdia ->
  (forall j, (j < n s)%nat -> ap1 ua eta (P (S j)) (P j + Q j) /\ ap1 ua eta (Q (S j)) (Q j + fds)) ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - euler_span s i) <= 555 / 100 * (nr * ua) + 912 / 10 * v + 151 / 10 * d.
Proof.
  intros ua P Q Hua0 Hnua HP0 HQ0 Hstep i Hi. ebasics.
  pose proof (loop_near (n s) fpa fds fdia (354 / 100 + 200 * (v + d)) (3545 / 1000)
    (3775 / 1000) (9111 / 100 * v + 1507 / 100 * d) (377 / 100) eta ua (euler_span s) P Q K_nr
    He0 (proj1 Hua0) Hnua ltac:(lra) ltac:(lra) ltac:(lra) ltac:(lra)
    (fun J HJ => K_eu_slope J ltac:(lia))
    (fun j Hj => conj (K_eu_ideal j Hj) (K_eu_le j Hj)) HP0 HQ0 Hstep i Hi).
  assert (0 <= nr * ua) by (apply Rmult_le_pos; lra). lra.
Qed.


Ltac eu_closed w e :=
  ebasics; pose proof K_dia as A0; pose proof (ndia_le s Hua Hub Hul);
  pose proof (abs_near _ _ _ A0);
  pose proof K_ds as D0; pose proof (n2ds_le' s Hua Hub Hul); pose proof (abs_near _ _ _ D0);
  match goal with Hi : (?i <= n s)%nat |- _ =>
    pose proof (K_eu_ideal i Hi); pose proof (K_eu_le i Hi) end;
  closed_by w e fdia (euler_span s) (20001 / 10000) (15401 / 10000) (27703 / 10000) (37702 / 10000).

(** Euler's closed form p_i = p_a + i (di_a + (i-1)/2 ds), evaluated as
    h = (i-1)/2 * ds, g = di_a + h, m = i * g, p = p_a + m (each within its
    bound, h and m possibly exact: fused multiply-adds). *)
Lemma K_eu_closed : forall i, (i <= n s)%nat -> forall hh g m p : R,
  ap1 v eta hh ((INR i - 1) / 2 * fds) -> ap1 v eta g (fdia + hh) ->
  ap1 v eta m (INR i * g) -> ap1 v eta p (fpa + m) ->
  Rabs (p - euler_span s i) <= 1012 / 10 * v + 151 / 10 * d.
Proof. intros i Hi hh g m p Hh Hg Hm Hp. eu_closed v eta. Qed.


(** *** The closed forms with the halving computed in floats ([half_rel]) *)

(** h is within (v + d)(1 + 2^-21) |(i-1)/2 ds| + 4 eta of (i-1)/2 ds, in both orders. *)
Lemma K_half : forall i hh, half_rel v d eta i fds hh ->
  Rabs (hh - (INR i - 1) / 2 * fds)
  <= (v + d) * (1 + / 2097152) * Rabs ((INR i - 1) / 2 * fds) + 4 * eta.
Proof.
  intros i hh H. ebasics.
  pose proof K_ds as D0. pose proof (n2ds_le s Hua Hub Hul) as D1.
  assert (D2 : Rabs (nr * nr * fds) <= 2001 / 1000) by (pose proof (abs_near _ _ _ D0); lra).
  assert (Bds : Rabs fds <= 2001 / 1000).
  { rewrite Rabs_mult, (Rabs_pos_eq (nr * nr)) in D2 by nra.
    assert (1 <= nr * nr) by nra. nra. }
  set (a := (INR i - 1) / 2) in *. set (X := a * fds) in *.
  assert (AX : Rabs X = Rabs a * Rabs fds) by (unfold X; apply Rabs_mult).
  pose proof (Rabs_pos X) as X0. pose proof (Rabs_pos fds) as F0.
  assert (VX : 0 <= v * Rabs X) by (apply Rmult_le_pos; lra).
  assert (DX : 0 <= d * Rabs X) by (apply Rmult_le_pos; lra).
  assert (VD : v * d * Rabs X <= / 2097152 * d * Rabs X) by nra.
  destruct H as [(c & Hcc & Hhh) | (y & Hyy & Hhh)]; unfold ap1 in *.
  - assert (E1 : Rabs ((c - a) * fds) <= d * Rabs X + eta * Rabs fds).
    { rewrite Rabs_mult, AX.
      assert (Rabs (c - a) * Rabs fds <= (d * Rabs a + eta) * Rabs fds)
        by (apply Rmult_le_compat_r; [exact F0 | exact Hcc]).
      lra. }
    assert (E2 : Rabs (c * fds) <= Rabs X + (d * Rabs X + eta * Rabs fds)).
    { replace (c * fds) with (X + (c - a) * fds) by (unfold X; ring).
      eapply Rle_trans; [apply Rabs_triang|]. lra. }
    assert (E3 : v * Rabs (c * fds) <= v * (Rabs X + (d * Rabs X + eta * Rabs fds)))
      by (apply Rmult_le_compat_l; lra).
    assert (E4 : eta * Rabs fds <= eta * (2001 / 1000)) by (apply Rmult_le_compat_l; lra).
    assert (E5 : v * (eta * Rabs fds) <= / 2097152 * (eta * (2001 / 1000)))
      by (apply Rmult_le_compat; try lra; apply Rmult_le_pos; lra).
    replace (hh - X) with ((hh - c * fds) + (c - a) * fds) by (unfold X; ring).
    eapply Rle_trans; [apply Rabs_triang|]. lra.
  - assert (EY : (INR i - 1) * fds = 2 * X) by (unfold X, a; field).
    rewrite EY in Hyy. rewrite Rabs_mult, (Rabs_pos_eq 2) in Hyy by lra.
    assert (E1 : Rabs (y / 2 - X) <= v * Rabs X + eta / 2).
    { replace (y / 2 - X) with (/ 2 * (y - 2 * X)) by field.
      rewrite Rabs_mult, (Rabs_pos_eq (/ 2)) by lra. lra. }
    assert (E2 : Rabs (y / 2) <= Rabs X + (v * Rabs X + eta / 2))
      by (pose proof (abs_near _ _ _ E1); lra).
    assert (E3 : d * Rabs (y / 2) <= d * (Rabs X + (v * Rabs X + eta / 2)))
      by (apply Rmult_le_compat_l; lra).
    assert (E4 : d * eta <= 1 * eta) by (apply Rmult_le_compat_r; lra).
    replace (hh - X) with ((hh - y / 2) + (y / 2 - X)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.

(** Corrected Euler's closed form with h from [half_rel]: 45 v + 8.3 d. *)
Lemma K_closed_h : forall i, (i <= n s)%nat -> forall hh g m p : R,
  half_rel v d eta i fds hh -> ap1 v eta g (ft0 + hh) ->
  ap1 v eta m (INR i * g) -> ap1 v eta p (fpa + m) ->
  Rabs (p - ceuler s i) <= 45 * v + 83 / 10 * d.
Proof.
  intros i Hi hh g m p Hh0 Hg Hm Hp. pose proof (K_half i hh Hh0) as Hh.
  ce_closed ((v + d) * (1 + / 2097152)) (4 * eta).
Qed.

(** Euler's closed form with h from [half_rel]: 101.2 v + 15.85 d. *)
Lemma K_eu_closed_h : forall i, (i <= n s)%nat -> forall hh g m p : R,
  half_rel v d eta i fds hh -> ap1 v eta g (fdia + hh) ->
  ap1 v eta m (INR i * g) -> ap1 v eta p (fpa + m) ->
  Rabs (p - euler_span s i) <= 1012 / 10 * v + 1585 / 100 * d.
Proof.
  intros i Hi hh g m p Hh0 Hg Hm Hp. pose proof (K_half i hh Hh0) as Hh.
  eu_closed ((v + d) * (1 + / 2097152)) (4 * eta).
Qed.

End CE.

(** The units of a model as the set-up's v = K1 u and d = k_div u. *)
Lemma model_units : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  small_ok (K1 * m_u M) (m_eta M) /\ small_ok (k_div M * m_u M) (m_eta M) /\
  k_add M * m_u M <= K1 * m_u M /\ 0 <= k_add M * m_u M /\
  (forall k y x, k <= K1 -> approx k (m_u M) (m_eta M) y x -> ap1 (K1 * m_u M) (m_eta M) y x) /\
  (forall a b y, fdot_ok M a b y -> fdot_rel (K1 * m_u M) (K1 * m_u M) (m_eta M) a b y) /\
  (forall vh w0, vap M vh w0 -> vap1 (K1 * m_u M) (m_eta M) vh w0).
Proof.
  intros M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1.
  pose proof HM as (Hu & He0 & He2 & Ki & Ka & Km & Kd & HK0 & HK2).
  set (u := m_u M) in *.
  assert (Hsm : forall k, 1 <= k <= K -> small_ok (k * u) (m_eta M))
    by (intros k Hk; repeat split; nra).
  assert (AK : forall k y x, k <= K1 -> approx k u (m_eta M) y x -> ap1 (K1 * u) (m_eta M) y x)
    by (intros k y x Hk H; eapply ap1_mono; [|exact H]; nra).
  assert (Wa : k_add M * u <= K1 * u) by nra. assert (Wm : k_mul M * u <= K1 * u) by nra.
  split; [apply Hsm; lra|]. split; [apply Hsm; lra|]. split; [exact Wa|].
  split; [nra|]. split; [exact AK|].
  split; [intros a b y H; eapply fdot_mono; [exact Wm | exact Wa | exact H]|].
  intros vh w0 (A1 & A2 & A3). repeat split; (eapply AK; [| eassumption]); lra.
Qed.

(** The set-up of the class in the section's terms: [lem] is a lemma of
    section CE (corrected Euler) or its Euler part, [R0] its instance. *)
Ltac eu_core lem :=
  match goal with
  | HM : model_ok ?M ?K, HK1 : 1 <= ?K1 <= ?K, Hi1 : k_in ?M <= ?K1, Ha1 : k_add ?M <= ?K1,
    Hm1 : k_mul ?M <= ?K1, Hd1 : 1 <= k_div ?M, HF : eu_setup_ok ?M ?s _,
    Ha : is_unit (Na ?s), Hb : is_unit (Nb ?s), Hl : is_unit (L ?s),
    Hn1 : (1 <= n ?s)%nat, Hn2 : INR (n ?s) <= 16777216 |- _ =>
  destruct (model_units M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1) as (Hv & Hdv & Wa & Wa0 & AK & FK & VK);
  destruct HF as ((Ina & Inb & Inl) & (tx & Htx & Hkx) & (ty & Hty & Hky) & (tz & Htz & Hkz)
    & Ha' & Hpa & Hc & (e & He & Hd) & Hpb & (q & Hq & Hdqb) & (h1 & x1 & Hh1 & Hx1 & Hdia)
    & (h2 & x2 & Hh2 & Hx2 & Hdib) & (w & Hw & Hds));
  pose proof (lem _ _ _ Hv Hdv s Ha Hb Hl Hn1 Hn2
    _ _ _ _ _ _ _ _ _ _ _ _ _
    (VK _ _ Ina) (VK _ _ Inb) (VK _ _ Inl) _ _ _
    (AK _ _ _ Ha1 Htx) Hkx (AK _ _ _ Ha1 Hty) Hky (AK _ _ _ Ha1 Htz) Hkz
    (FK _ _ _ Ha') (FK _ _ _ Hpa) (FK _ _ _ Hc) _ (FK _ _ _ He) (AK _ _ _ Hm1 Hd) (FK _ _ _ Hpb)
    _ (AK _ _ _ Hm1 Hq) (AK _ _ _ Ha1 Hdqb)
    _ _ Hh1 (AK _ _ _ Hm1 Hx1) (AK _ _ _ Ha1 Hdia)
    _ _ Hh2 (AK _ _ _ Hm1 Hx2) (AK _ _ _ Ha1 Hdib)
    _ (AK _ _ _ Ha1 Hw) Hds) as R0;
  (* a lemma of corrected Euler: p_n, eps, d_eps, t0 too (see [ce_core]) *)
  try match goal with
  | Hq2 : ap_mul _ _ (INR (n _) * fs_dia _),
    Hq3 : ap_mul _ _ (INR (n _) * (INR (n _) - 1) / 2 * fs_ds _), Hpn : sum3 _ _ _ _ _,
    Heps : ap_add _ (fs_eps _) _, Hdeps : ap_div _ (fs_deps _) _, Ht0 : ap_add _ (fs_t0 _) _ |- _ =>
    specialize (R0 _ _ _ (AK _ _ _ Hm1 Hq2) (AK _ _ _ Hm1 Hq3) (sum3_mono _ _ _ _ _ _ _ Wa Hpn)
      _ _ _ (AK _ _ _ Ha1 Heps) Hdeps (AK _ _ _ Ha1 Ht0))
  end
  end.
(** The same for a lemma of section CE that uses p_n, eps, d_eps and t0 too. *)
Ltac ce_core lem :=
  match goal with HF : ce_setup_ok _ _ _ |- _ =>
    destruct HF as (HE & (q2 & q3 & Hq2 & Hq3 & Hpn) & Heps & Hdeps & Ht0)
  end;
  eu_core lem.

(** ** The generic bounds of corrected Euler and Euler

    Any model with the size conditions (model_ok M K, K1 >= 1 bounding k_in,
    k_add, k_mul, so v = K1 u, and k_div >= 1, so d = k_div u) and any span of
    unit vectors with 1 <= n <= 2^24. *)

Lemma half_ok_rel : forall (M : fmodel) (K1 : R) (i : nat) (ds h : R),
  0 <= m_u M -> k_mul M <= K1 -> half_ok M i ds h ->
  half_rel (K1 * m_u M) (k_div M * m_u M) (m_eta M) i ds h.
Proof.
  intros M K1 i ds h Hu Hm [(c & Hc & Hh) | (y & Hy & Hh)]; [left; exists c | right; exists y];
    split; try exact Hc; try exact Hh;
    (eapply ap1_mono; [| eassumption]); apply Rmult_le_compat_r; lra.
Qed.

Section Generic.
Context (M : fmodel) (K K1 : R) (HM : model_ok M K) (HK1 : 1 <= K1 <= K) (Hi1 : k_in M <= K1)
        (Ha1 : k_add M <= K1) (Hm1 : k_mul M <= K1) (Hd1 : 1 <= k_div M).
Context (s : span) (Ha : is_unit (Na s)) (Hb : is_unit (Nb s)) (Hl : is_unit (L s))
        (Hn1 : (1 <= n s)%nat) (Hn2 : INR (n s) <= 16777216).

(** A generic bound from the section CE lemma [lem] through [core] ([ce_core] or
    [eu_core]): the loop ([loop_gen]) or a closed form, h exact or halved
    ([closed_gen]); each operation's bound taken to the unit v = K1 u. *)
Ltac loop_gen core lem :=
  intros F P Q Hnu HF [HP0 [HQ0 Hst]] i Hi; core lem;
  match goal with R0 : forall ua (P Q : nat -> R), _ |- _ =>
    eapply Rle_trans; [exact (R0 (k_add M * m_u M) P Q ltac:(lra) Hnu HP0 HQ0 Hst i Hi)|]; lra end.
Ltac closed_gen core lem :=
  intros F HF i Hi h g m p Hh Hg Hm Hp;
  try apply (half_ok_rel M K1 i (fs_ds F) h ltac:(pose proof (model_u M K HM); lra) Hm1) in Hh;
  core lem; match goal with AK : forall k y x, k <= K1 -> approx k _ _ y x -> _,
    R0 : forall i, (i <= n s)%nat -> _ |- _ =>
    eapply Rle_trans; [apply (R0 i Hi h g m p); first [exact Hh | exact (AK _ _ _ Hm1 Hh)
      | exact (AK _ _ _ Hm1 Hm) | exact (AK _ _ _ Ha1 Hg) | exact (AK _ _ _ Ha1 Hp)] | lra] end.

(** Any model with the size conditions, 1 <= n <= 2^24 and n k_add u <= 2^-11;
    K1 >= 1 bounds k_in, k_add, k_mul (unit v = K1 u) and k_div >= 1 (unit
    d = k_div u): the loop contributes 2.2 k_add n u, the set-up
    36.6 v + 7.3 d. *)
Lemma profile_corrected_euler_generic :
  forall (F : fsetup) (P Q : nat -> R), INR (n s) * (k_add M * m_u M) <= / 2048 ->
  ce_setup_ok M s F -> ceuler_run M F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - ceuler s i) <=
  (22 / 10 * k_add M * INR (n s) + 366 / 10 * K1 + 73 / 10 * k_div M) * m_u M.
Proof.
  loop_gen ce_core K_ce_final.
Qed.

(** Any model with the size conditions, 1 <= n <= 2^24 and n k_add u <= 2^-11;
    K1 as in [profile_corrected_euler_generic]: the loop contributes
    5.55 k_add n u, the set-up 91.2 v + 15.1 d (no end-point correction:
    the errors of di_a and ds reach pixel i multiplied by i and i(i-1)/2). *)
Lemma profile_euler_generic :
  forall (F : fsetup) (P Q : nat -> R), INR (n s) * (k_add M * m_u M) <= / 2048 ->
  eu_setup_ok M s F -> euler_run M F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - euler_span s i) <=
  (555 / 100 * k_add M * INR (n s) + 912 / 10 * K1 + 151 / 10 * k_div M) * m_u M.
Proof.
  loop_gen eu_core K_eu_final.
Qed.

(** Euler's closed form p_i = p_a + i (di_a + (i-1)/2 ds) evaluated in the model
    (h = (i-1)/2 ds, g = di_a + h, m = i g, p = p_a + m; fused or not), on a
    set-up of the class. *)
Lemma profile_euler_closed_generic : forall F : fsetup, eu_setup_ok M s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul M h ((INR i - 1) / 2 * fs_ds F) -> ap_add M g (fs_dia F + h) ->
  ap_mul M m (INR i * g) -> ap_add M p (fs_pa F + m) ->
  Rabs (p - euler_span s i) <= (1012 / 10 * K1 + 151 / 10 * k_div M) * m_u M.
Proof.
  closed_gen eu_core K_eu_closed.
Qed.

(** p_i = p_a + i (t0 + (i-1)/2 ds) evaluated in the model (h = (i-1)/2 ds,
    g = t0 + h, m = i g, p = p_a + m; fused or not), on a set-up of the class. *)
Lemma profile_corrected_euler_closed_generic : forall F : fsetup, ce_setup_ok M s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul M h ((INR i - 1) / 2 * fs_ds F) -> ap_add M g (fs_t0 F + h) ->
  ap_mul M m (INR i * g) -> ap_add M p (fs_pa F + m) ->
  Rabs (p - ceuler s i) <= (45 * K1 + 73 / 10 * k_div M) * m_u M.
Proof.
  closed_gen ce_core K_closed.
Qed.

(** As [profile_corrected_euler_closed_generic] and
    [profile_euler_closed_generic], with h from [half_ok]: (i-1)/2 rounded as
    a division (or (i-1) ds rounded, then halved by a division) before the
    rest of the closed form.  The halving adds about |i (i-1)/2 ds| k_div u
    (at most 1.0007 and 0.7701 k_div u). *)
Lemma profile_corrected_euler_closed_half_generic : forall F : fsetup, ce_setup_ok M s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  half_ok M i (fs_ds F) h -> ap_add M g (fs_t0 F + h) ->
  ap_mul M m (INR i * g) -> ap_add M p (fs_pa F + m) ->
  Rabs (p - ceuler s i) <= (45 * K1 + 83 / 10 * k_div M) * m_u M.
Proof.
  closed_gen ce_core K_closed_h.
Qed.

Lemma profile_euler_closed_half_generic : forall F : fsetup, eu_setup_ok M s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  half_ok M i (fs_ds F) h -> ap_add M g (fs_dia F + h) ->
  ap_mul M m (INR i * g) -> ap_add M p (fs_pa F + m) ->
  Rabs (p - euler_span s i) <= (1012 / 10 * K1 + 1585 / 100 * k_div M) * m_u M.
Proof.
  closed_gen eu_core K_eu_closed_h.
Qed.

End Generic.

(** ** Corrected Euler: the profiles *)

(* Note: ieee profile, binary32 (see profile_ieee_gouraud_binary32). *)
(** Corrected Euler, ieee profile, binary32: |P_i - ceuler i| <= (2.2 n + 51.21) 2^-24. *)
Theorem profile_ieee_corrected_euler_binary32 :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok ieee32 s F -> ceuler_run ieee32 F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - ceuler s i) <= (22 / 10 * INR (n s) + 5121 / 100) * bpow radix2 (-24).
Proof. profile_inst (profile_corrected_euler_generic ieee32 _ 1 ieee32_ok). Qed.

(* Note: ieee profile, binary64 (see profile_ieee_gouraud_binary64). *)
(** Corrected Euler, ieee profile, binary64: |P_i - ceuler i| <= (2.2 n + 51.21) 2^-53. *)
Theorem profile_ieee_corrected_euler_binary64 :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok ieee64 s F -> ceuler_run ieee64 F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - ceuler s i) <= (22 / 10 * INR (n s) + 5121 / 100) * bpow radix2 (-53).
Proof. profile_inst (profile_corrected_euler_generic ieee64 _ 1 ieee64_ok). Qed.

(* Note: shader profile (see profile_shader_gouraud_binary32). *)
(** Corrected Euler, shader profile: |P_i - ceuler i| <= (4.4 n + 109.7) 2^-24. *)
Theorem profile_shader_corrected_euler_binary32 :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok shader32 s F -> ceuler_run shader32 F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - ceuler s i) <= (44 / 10 * INR (n s) + 1097 / 10) * bpow radix2 (-24).
Proof. profile_inst (profile_corrected_euler_generic shader32 _ 2 shader32_ok). Qed.

(** ** Plain Euler: the profiles *)

(* Note: ieee profile, binary32 (see profile_ieee_gouraud_binary32). *)
(** Euler, ieee profile, binary32: |P_i - euler_span i| <= (5.55 n + 121.41) 2^-24. *)
Theorem profile_ieee_euler_binary32 :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok ieee32 s F -> euler_run ieee32 F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - euler_span s i) <= (555 / 100 * INR (n s) + 12141 / 100) * bpow radix2 (-24).
Proof. profile_inst (profile_euler_generic ieee32 _ 1 ieee32_ok). Qed.

(* Note: ieee profile, binary64 (see profile_ieee_gouraud_binary64). *)
(** Euler, ieee profile, binary64: |P_i - euler_span i| <= (5.55 n + 121.41) 2^-53. *)
Theorem profile_ieee_euler_binary64 :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok ieee64 s F -> euler_run ieee64 F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - euler_span s i) <= (555 / 100 * INR (n s) + 12141 / 100) * bpow radix2 (-53).
Proof. profile_inst (profile_euler_generic ieee64 _ 1 ieee64_ok). Qed.

(* Note: ieee profile, binary64, spans up to 2^24 pixels. *)
(** Euler, ieee profile, binary64, n <= 2^24: |P_i - euler_span i| <= (5.55 n + 121.41) 2^-53. *)
Theorem profile_ieee_euler_binary64_large :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> (Z.of_nat (n s) <= 16777216)%Z ->
  eu_setup_ok ieee64 s F -> euler_run ieee64 F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - euler_span s i) <= (555 / 100 * INR (n s) + 12141 / 100) * bpow radix2 (-53).
Proof. profile_inst (profile_euler_generic ieee64 _ 1 ieee64_ok). Qed.

(* Note: shader profile (see profile_shader_gouraud_binary32). *)
(** Euler, shader profile: |P_i - euler_span i| <= (11.1 n + 257.9) 2^-24. *)
Theorem profile_shader_euler_binary32 :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok shader32 s F -> euler_run shader32 F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - euler_span s i) <= (111 / 10 * INR (n s) + 2579 / 10) * bpow radix2 (-24).
Proof. profile_inst (profile_euler_generic shader32 _ 2 shader32_ok). Qed.

(* Note: ieee profile, binary32; the bound does not grow with n. *)
(** Euler by its closed form, ieee profile, binary32:
    |p_i - euler_span i| <= 131.41 2^-24. *)
Theorem profile_ieee_euler_closed_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok ieee32 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul ieee32 h ((INR i - 1) / 2 * fs_ds F) -> ap_add ieee32 g (fs_dia F + h) ->
  ap_mul ieee32 m (INR i * g) -> ap_add ieee32 p (fs_pa F + m) ->
  Rabs (p - euler_span s i) <= 13141 / 100 * bpow radix2 (-24).
Proof. profile_inst (profile_euler_closed_generic ieee32 _ 1 ieee32_ok). Qed.

(* Note: ieee profile, binary64. *)
(** Euler by its closed form, ieee profile, binary64:
    |p_i - euler_span i| <= 131.41 2^-53. *)
Theorem profile_ieee_euler_closed_binary64 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok ieee64 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul ieee64 h ((INR i - 1) / 2 * fs_ds F) -> ap_add ieee64 g (fs_dia F + h) ->
  ap_mul ieee64 m (INR i * g) -> ap_add ieee64 p (fs_pa F + m) ->
  Rabs (p - euler_span s i) <= 13141 / 100 * bpow radix2 (-53).
Proof. profile_inst (profile_euler_closed_generic ieee64 _ 1 ieee64_ok). Qed.

(* Note: ieee profile, binary64, spans up to 2^24 pixels. *)
(** Euler by its closed form, ieee profile, binary64, n <= 2^24:
    |p_i - euler_span i| <= 131.41 2^-53. *)
Theorem profile_ieee_euler_closed_binary64_large : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> (Z.of_nat (n s) <= 16777216)%Z ->
  eu_setup_ok ieee64 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul ieee64 h ((INR i - 1) / 2 * fs_ds F) -> ap_add ieee64 g (fs_dia F + h) ->
  ap_mul ieee64 m (INR i * g) -> ap_add ieee64 p (fs_pa F + m) ->
  Rabs (p - euler_span s i) <= 13141 / 100 * bpow radix2 (-53).
Proof. profile_inst (profile_euler_closed_generic ieee64 _ 1 ieee64_ok). Qed.

(** ** Corrected Euler by its closed form *)

(* Note: ieee profile, binary32; the bound does not grow with n. *)
(** Corrected Euler by its closed form, ieee profile, binary32:
    |p_i - ceuler i| <= 59.61 2^-24. *)
Theorem profile_ieee_corrected_euler_closed_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok ieee32 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul ieee32 h ((INR i - 1) / 2 * fs_ds F) -> ap_add ieee32 g (fs_t0 F + h) ->
  ap_mul ieee32 m (INR i * g) -> ap_add ieee32 p (fs_pa F + m) ->
  Rabs (p - ceuler s i) <= 5961 / 100 * bpow radix2 (-24).
Proof. profile_inst (profile_corrected_euler_closed_generic ieee32 _ 1 ieee32_ok). Qed.

(* Note: ieee profile, binary64. *)
(** Corrected Euler by its closed form, ieee profile, binary64:
    |p_i - ceuler i| <= 59.61 2^-53. *)
Theorem profile_ieee_corrected_euler_closed_binary64 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok ieee64 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul ieee64 h ((INR i - 1) / 2 * fs_ds F) -> ap_add ieee64 g (fs_t0 F + h) ->
  ap_mul ieee64 m (INR i * g) -> ap_add ieee64 p (fs_pa F + m) ->
  Rabs (p - ceuler s i) <= 5961 / 100 * bpow radix2 (-53).
Proof. profile_inst (profile_corrected_euler_closed_generic ieee64 _ 1 ieee64_ok). Qed.

(* Note: ieee profile, binary64, spans up to 2^24 pixels. *)
(** Corrected Euler, ieee profile, binary64, n <= 2^24: |P_i - ceuler i| <= (2.2 n + 51.21) 2^-53. *)
Theorem profile_ieee_corrected_euler_binary64_large :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> (Z.of_nat (n s) <= 16777216)%Z ->
  ce_setup_ok ieee64 s F -> ceuler_run ieee64 F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - ceuler s i) <= (22 / 10 * INR (n s) + 5121 / 100) * bpow radix2 (-53).
Proof. profile_inst (profile_corrected_euler_generic ieee64 _ 1 ieee64_ok). Qed.

(* Note: ieee profile, binary64, spans up to 2^24 pixels. *)
(** Corrected Euler by its closed form, ieee profile, binary64, n <= 2^24:
    |p_i - ceuler i| <= 59.61 2^-53. *)
Theorem profile_ieee_corrected_euler_closed_binary64_large : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> (Z.of_nat (n s) <= 16777216)%Z ->
  ce_setup_ok ieee64 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul ieee64 h ((INR i - 1) / 2 * fs_ds F) -> ap_add ieee64 g (fs_t0 F + h) ->
  ap_mul ieee64 m (INR i * g) -> ap_add ieee64 p (fs_pa F + m) ->
  Rabs (p - ceuler s i) <= 5961 / 100 * bpow radix2 (-53).
Proof. profile_inst (profile_corrected_euler_closed_generic ieee64 _ 1 ieee64_ok). Qed.

(** ** The shader profile: division as .(1/n), the closed forms, the halving *)

(* Note: shader profile with every division by n computed as a reciprocal
   within 2.5 ulp then a product (or as one 2.5-ulp division):
   [shader32_recip], k_div = 7 + 2^-20. *)
(** Gouraud, shader profile, division as .(1/n): |G_i - gouraud i| <= (2.0012 n + 28.0014) 2^-24. *)
Theorem profile_shader_gouraud_recip_binary32 : forall (s : span) (F : fsetup) (G : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  gouraud_setup_ok shader32_recip s F -> gouraud_run shader32_recip F (n s) G ->
  forall i, (i <= n s)%nat ->
  Rabs (G i - gouraud s i) <= (20012 / 10000 * INR (n s) + 280014 / 10000) * bpow radix2 (-24).
Proof. profile_inst (profile_gouraud_generic shader32_recip _ shader32_recip_ok). Qed.

(* Note: shader profile, every division (by n, by 2) a reciprocal within 2.5 ulp
   then a product, or one 2.5-ulp division ([shader32_recip]). *)
(** Corrected Euler, shader profile, division as .(1/n): |P_i - ceuler i| <= (4.4 n + 124.31) 2^-24. *)
Theorem profile_shader_corrected_euler_recip_binary32 :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok shader32_recip s F -> ceuler_run shader32_recip F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - ceuler s i) <= (44 / 10 * INR (n s) + 12431 / 100) * bpow radix2 (-24).
Proof. profile_inst (profile_corrected_euler_generic shader32_recip _ 2 shader32_recip_ok). Qed.

(* Note: shader profile, every division (by n, by 2) a reciprocal within 2.5 ulp
   then a product, or one 2.5-ulp division ([shader32_recip]). *)
(** Euler, shader profile, division as .(1/n): |P_i - euler_span i| <= (11.1 n + 288.11) 2^-24. *)
Theorem profile_shader_euler_recip_binary32 :
  forall (s : span) (F : fsetup) (P Q : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok shader32_recip s F -> euler_run shader32_recip F (n s) P Q ->
  forall i, (i <= n s)%nat ->
  Rabs (P i - euler_span s i) <= (111 / 10 * INR (n s) + 28811 / 100) * bpow radix2 (-24).
Proof. profile_inst (profile_euler_generic shader32_recip _ 2 shader32_recip_ok). Qed.

(* Note: shader profile (one 2.5-ulp division per division); the bound does
   not grow with n. *)
(** Corrected Euler by its closed form, shader profile: |p_i - ceuler i| <= 126.5 2^-24. *)
Theorem profile_shader_corrected_euler_closed_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok shader32 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul shader32 h ((INR i - 1) / 2 * fs_ds F) -> ap_add shader32 g (fs_t0 F + h) ->
  ap_mul shader32 m (INR i * g) -> ap_add shader32 p (fs_pa F + m) ->
  Rabs (p - ceuler s i) <= 1265 / 10 * bpow radix2 (-24).
Proof. profile_inst (profile_corrected_euler_closed_generic shader32 _ 2 shader32_ok). Qed.

(* Note: shader profile, every division (by n, by 2) a reciprocal within 2.5 ulp
   then a product, or one 2.5-ulp division ([shader32_recip]). *)
(** Corrected Euler by its closed form, shader profile, division as .(1/n):
    |p_i - ceuler i| <= 141.11 2^-24. *)
Theorem profile_shader_corrected_euler_closed_recip_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok shader32_recip s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul shader32_recip h ((INR i - 1) / 2 * fs_ds F) -> ap_add shader32_recip g (fs_t0 F + h) ->
  ap_mul shader32_recip m (INR i * g) -> ap_add shader32_recip p (fs_pa F + m) ->
  Rabs (p - ceuler s i) <= 14111 / 100 * bpow radix2 (-24).
Proof. profile_inst (profile_corrected_euler_closed_generic shader32_recip _ 2 shader32_recip_ok). Qed.

(* Note: shader profile; (i-1)/2 halved in floats ([half_ok]): c = (i-1)/2
   by a division then h = c ds, or y = (i-1) ds then h = y/2. *)
(** Corrected Euler by its closed form, shader profile, (i-1)/2 halved in floats:
    |p_i - ceuler i| <= 131.5 2^-24. *)
Theorem profile_shader_corrected_euler_closed_half_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok shader32 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  half_ok shader32 i (fs_ds F) h -> ap_add shader32 g (fs_t0 F + h) ->
  ap_mul shader32 m (INR i * g) -> ap_add shader32 p (fs_pa F + m) ->
  Rabs (p - ceuler s i) <= 1315 / 10 * bpow radix2 (-24).
Proof. profile_inst (profile_corrected_euler_closed_half_generic shader32 _ 2 shader32_ok). Qed.

(* Note: shader profile, every division (by n, by 2, the halving of the
   closed form) a reciprocal then a product, or one 2.5-ulp division. *)
(** Corrected Euler by its closed form, shader profile, (i-1)/2 halved in floats,
    division as .(1/n): |p_i - ceuler i| <= 148.11 2^-24. *)
Theorem profile_shader_corrected_euler_closed_half_recip_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  ce_setup_ok shader32_recip s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  half_ok shader32_recip i (fs_ds F) h -> ap_add shader32_recip g (fs_t0 F + h) ->
  ap_mul shader32_recip m (INR i * g) -> ap_add shader32_recip p (fs_pa F + m) ->
  Rabs (p - ceuler s i) <= 14811 / 100 * bpow radix2 (-24).
Proof. profile_inst (profile_corrected_euler_closed_half_generic shader32_recip _ 2 shader32_recip_ok). Qed.

(* Note: shader profile (one 2.5-ulp division per division); the bound does
   not grow with n. *)
(** Euler by its closed form, shader profile: |p_i - euler_span i| <= 277.9 2^-24. *)
Theorem profile_shader_euler_closed_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok shader32 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul shader32 h ((INR i - 1) / 2 * fs_ds F) -> ap_add shader32 g (fs_dia F + h) ->
  ap_mul shader32 m (INR i * g) -> ap_add shader32 p (fs_pa F + m) ->
  Rabs (p - euler_span s i) <= 2779 / 10 * bpow radix2 (-24).
Proof. profile_inst (profile_euler_closed_generic shader32 _ 2 shader32_ok). Qed.

(* Note: shader profile, every division (by n, by 2) a reciprocal within 2.5 ulp
   then a product, or one 2.5-ulp division ([shader32_recip]). *)
(** Euler by its closed form, shader profile, division as .(1/n):
    |p_i - euler_span i| <= 308.11 2^-24. *)
Theorem profile_shader_euler_closed_recip_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok shader32_recip s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  ap_mul shader32_recip h ((INR i - 1) / 2 * fs_ds F) -> ap_add shader32_recip g (fs_dia F + h) ->
  ap_mul shader32_recip m (INR i * g) -> ap_add shader32_recip p (fs_pa F + m) ->
  Rabs (p - euler_span s i) <= 30811 / 100 * bpow radix2 (-24).
Proof. profile_inst (profile_euler_closed_generic shader32_recip _ 2 shader32_recip_ok). Qed.

(* Note: shader profile; (i-1)/2 halved in floats ([half_ok]): c = (i-1)/2
   by a division then h = c ds, or y = (i-1) ds then h = y/2. *)
(** Euler by its closed form, shader profile, (i-1)/2 halved in floats:
    |p_i - euler_span i| <= 281.65 2^-24. *)
Theorem profile_shader_euler_closed_half_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok shader32 s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  half_ok shader32 i (fs_ds F) h -> ap_add shader32 g (fs_dia F + h) ->
  ap_mul shader32 m (INR i * g) -> ap_add shader32 p (fs_pa F + m) ->
  Rabs (p - euler_span s i) <= 28165 / 100 * bpow radix2 (-24).
Proof. profile_inst (profile_euler_closed_half_generic shader32 _ 2 shader32_ok). Qed.

(* Note: shader profile, every division (by n, by 2, the halving of the
   closed form) a reciprocal then a product, or one 2.5-ulp division. *)
(** Euler by its closed form, shader profile, (i-1)/2 halved in floats,
    division as .(1/n): |p_i - euler_span i| <= 313.36 2^-24. *)
Theorem profile_shader_euler_closed_half_recip_binary32 : forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  eu_setup_ok shader32_recip s F ->
  forall i, (i <= n s)%nat -> forall h g m p : R,
  half_ok shader32_recip i (fs_ds F) h -> ap_add shader32_recip g (fs_dia F + h) ->
  ap_mul shader32_recip m (INR i * g) -> ap_add shader32_recip p (fs_pa F + m) ->
  Rabs (p - euler_span s i) <= 31336 / 100 * bpow radix2 (-24).
Proof. profile_inst (profile_euler_closed_half_generic shader32_recip _ 2 shader32_recip_ok). Qed.

(** ** What the profile factors cover (Flocq) *)

(** Round to nearest (any tie-breaking rule), subnormals kept:
    k = 1, eta = 2^(emin-1) (binary32: 2^-150, binary64: 2^-1075). *)
Lemma rn_covered : forall (emin prec : Z) (choice : Z -> bool), (0 < prec)%Z -> forall x : R,
  approx 1 (bpow radix2 (- prec)) (bpow radix2 (emin - 1))
    (round radix2 (FLT_exp emin prec) (Znearest choice) x) x.
Proof.
  intros emin prec choice Hp x. unfold approx, ap1. rewrite Rmult_1_l.
  exact (rn_std_model emin prec choice Hp x).
Qed.

(** One ulp of the format is at most 2^(1-prec) |x| + 2^emin. *)
Lemma ulp_le_rel : forall (emin prec : Z) (x : R), Prec_gt_0 prec ->
  ulp radix2 (FLT_exp emin prec) x <= 2 * bpow radix2 (- prec) * Rabs x + bpow radix2 emin.
Proof.
  intros emin prec x HP.
  assert (U0 : 0 < bpow radix2 (- prec)) by apply bpow_gt_0.
  pose proof (Rabs_pos x). pose proof (bpow_ge_0 radix2 emin).
  destruct (Rlt_or_le (Rabs x) (bpow radix2 (emin + prec - 1))) as [Hs | Hb].
  - rewrite (ulp_FLT_small radix2 emin prec x).
    + assert (0 <= 2 * bpow radix2 (- prec) * Rabs x) by nra. lra.
    + eapply Rlt_le_trans; [exact Hs|]. apply bpow_le. lia.
  - pose proof (ulp_FLT_le radix2 emin prec x Hb) as U.
    replace (bpow radix2 (1 - prec)) with (2 * bpow radix2 (- prec)) in U
      by (replace (1 - prec)%Z with (1 + - prec)%Z by ring; rewrite bpow_plus, bpow_1; reflexivity).
    lra.
Qed.

(** Any rounding of the format (toward zero, up, down, to nearest, ...):
    error below one ulp, so k = 2, eta = 2^emin. *)
Lemma faithful_covered : forall (emin prec : Z) (rnd : R -> Z), (0 < prec)%Z -> Valid_rnd rnd ->
  forall x : R,
  approx 2 (bpow radix2 (- prec)) (bpow radix2 emin)
    (round radix2 (FLT_exp emin prec) rnd x) x.
Proof.
  intros emin prec rnd Hp Hr x. unfold approx, ap1.
  assert (HP : Prec_gt_0 prec) by exact Hp. pose proof (bpow_ge_0 radix2 emin).
  destruct (Req_dec x 0) as [H0 | H0].
  - subst x. rewrite round_0 by exact Hr. rewrite Rminus_0_r, Rabs_R0. lra.
  - pose proof (error_lt_ulp radix2 (FLT_exp emin prec) rnd x H0).
    pose proof (ulp_le_rel emin prec x HP). lra.
Qed.

(** Flushing a result below the smallest normal number 2^(emin+prec-1) to zero. *)
Definition flush (emin prec : Z) (y : R) : R :=
  if Rlt_dec (Rabs y) (bpow radix2 (emin + prec - 1)) then 0 else y.

Lemma flush_covered : forall (emin prec : Z) (rnd : R -> Z), (1 < prec)%Z -> Valid_rnd rnd ->
  forall x : R,
  approx 2 (bpow radix2 (- prec)) (bpow radix2 (emin + prec - 1))
    (flush emin prec (round radix2 (FLT_exp emin prec) rnd x)) x.
Proof.
  intros emin prec rnd Hp Hr x. unfold flush.
  assert (U0 : 0 < bpow radix2 (- prec)) by apply bpow_gt_0.
  pose proof (Rabs_pos x) as Hx0.
  assert (HP : Prec_gt_0 prec) by (unfold Prec_gt_0; lia).
  destruct (Rlt_dec _ _) as [Hl | Hl].
  - unfold approx, ap1. rewrite Rminus_0_l, Rabs_Ropp.
    assert (Hx : Rabs x < bpow radix2 (emin + prec - 1)).
    { destruct (Rlt_or_le (Rabs x) (bpow radix2 (emin + prec - 1))) as [H | H]; [exact H|].
      exfalso. apply (Rlt_not_le _ _ Hl).
      apply abs_round_ge_generic;
        first [exact H | exact Hr | exact (FLT_exp_valid emin prec)
              | (apply generic_format_bpow; unfold FLT_exp; lia)]. }
    assert (0 <= 2 * bpow radix2 (- prec) * Rabs x) by nra. lra.
  - pose proof (faithful_covered emin prec rnd ltac:(lia) Hr x) as F.
    unfold approx, ap1 in *.
    assert (bpow radix2 emin <= bpow radix2 (emin + prec - 1)) by (apply bpow_le; lia).
    lra.
Qed.

(** Division by m (1 <= m <= 2^24, e.g. n or 2) as a reciprocal within kr u
    (relative) followed by a product within km u: k = kr + km + 2^-20
    (kr <= 5, km <= 2). *)
Lemma recip_mul_gen : forall (kr km u eta m x r y : R), 0 <= kr <= 5 -> 0 <= km <= 2 ->
  0 < u <= / 16777216 -> 0 <= eta -> eta * 1152921504606846976 <= u -> 1 <= m <= 16777216 ->
  approx kr u eta r (/ m) -> approx km u eta y (x * r) ->
  approx (kr + km + / 1048576) u eta y (x / m).
Proof.
  intros kr km u eta m x r y Hkr Hkm Hu He He2 Hm Hr Hy. unfold approx, ap1 in *.
  assert (Im2 : / 16777216 <= / m) by (apply Rinv_le_contravar; lra).
  rewrite (Rabs_pos_eq (/ m)) in Hr by lra.
  set (d := (kr + / 68719476736) * u).
  assert (Hd : 0 <= d <= / 3000000) by (unfold d; split; nra).
  assert (X1 : Rabs (x * r - x / m) <= d * Rabs (x / m)).
  { replace (x * r - x / m) with (x * (r - / m)) by (field; lra).
    replace (x / m) with (x * / m) by (field; lra).
    rewrite !Rabs_mult, (Rabs_pos_eq (/ m)) by lra.
    replace (d * (Rabs x * / m)) with (Rabs x * (d * / m)) by ring.
    apply Rmult_le_compat_l; [apply Rabs_pos|]. unfold d. nra. }
  assert (X2 : Rabs (x * r) <= (1 + d) * Rabs (x / m)) by (pose proof (abs_near _ _ _ X1); lra).
  pose proof (Rabs_pos (x / m)) as X0. set (X := Rabs (x / m)) in *.
  assert (X3 : km * u * Rabs (x * r) <= km * u * ((1 + d) * X))
    by (apply Rmult_le_compat_l; nra).
  assert (X5 : (km * d) * (u * X) <= (2 * / 3000000) * (u * X))
    by (apply Rmult_le_compat_r; nra).
  replace (y - x / m) with ((y - x * r) + (x * r - x / m)) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  assert (E : km * u * ((1 + d) * X) + d * X
              = km * (u * X) + kr * (u * X) + / 68719476736 * (u * X) + (km * d) * (u * X))
    by (unfold d; ring).
  assert (0 <= u * X) by nra.
  assert (E2 : (kr + km + / 1048576) * u * X
               = km * (u * X) + kr * (u * X) + / 1048576 * (u * X)) by ring.
  rewrite E2. lra.
Qed.

(** Division by m (1 <= m <= 2^24, e.g. n or 2) as a reciprocal rounded to
    nearest followed by a product rounded to nearest: k = 2 + 2^-20. *)
Lemma recip_mul_covered : forall (u eta m x r y : R),
  0 < u <= / 16777216 -> 0 <= eta -> eta * 1152921504606846976 <= u -> 1 <= m <= 16777216 ->
  approx 1 u eta r (/ m) -> approx 1 u eta y (x * r) ->
  approx (2 + / 1048576) u eta y (x / m).
Proof.
  intros. replace (2 + / 1048576) with (1 + 1 + / 1048576) by ring.
  apply recip_mul_gen with (r := r); assumption || lra.
Qed.

(** Round to nearest in (emin, prec) covers every operation of [M] (k = 1, the
    division's k_div >= 1). *)
Ltac rn_model_covered M emin prec p e :=
  intros choice x y;
  pose proof (rn_covered emin prec choice ltac:(lia) x) as H;
  change (Z.opp prec) with p in H; change (emin - 1)%Z with e in H;
  unfold ap_in, ap_add, ap_mul, ap_div, M; cbn [m_u m_eta k_in k_add k_mul k_div];
  repeat split; try exact H;
  unfold approx in *; eapply ap1_mono; [|exact H];
  apply Rmult_le_compat_r; [apply bpow_ge_0 | lra].

(** So every operation of the ieee profile is covered: add, sub, mul, inputs
    and division rounded to nearest (k = 1 <= 2 + 2^-20), and division as
    reciprocal then product ([recip_mul_covered]); binary32 shown, binary64
    is the same with (prec, emin) = (53, -1074). *)
Lemma ieee32_covered : forall (choice : Z -> bool) (x : R),
  let y := round radix2 (FLT_exp (-149) 24) (Znearest choice) x in
  ap_in ieee32 y x /\ ap_add ieee32 y x /\ ap_mul ieee32 y x /\ ap_div ieee32 y x.
Proof. rn_model_covered ieee32 (-149)%Z 24%Z (-24)%Z (-150)%Z. Qed.

Lemma ieee64_covered : forall (choice : Z -> bool) (x : R),
  let y := round radix2 (FLT_exp (-1074) 53) (Znearest choice) x in
  ap_in ieee64 y x /\ ap_add ieee64 y x /\ ap_mul ieee64 y x /\ ap_div ieee64 y x.
Proof. rn_model_covered ieee64 (-1074)%Z 53%Z (-53)%Z (-1075)%Z. Qed.

(** The shader profile: any rounding of binary32 (nearest or toward zero,
    ...), with or without flushing to zero, for inputs and for add, sub and
    mul; division within 2.5 ulp. *)
Lemma shader32_covered : forall (rnd : R -> Z), Valid_rnd rnd -> forall x : R,
  let y := round radix2 (FLT_exp (-149) 24) rnd x in
  (ap_in shader32 y x /\ ap_add shader32 y x /\ ap_mul shader32 y x) /\
  (ap_in shader32 (flush (-149) 24 y) x /\ ap_add shader32 (flush (-149) 24 y) x
   /\ ap_mul shader32 (flush (-149) 24 y) x).
Proof.
  intros rnd Hr x y. subst y.
  pose proof (faithful_covered (-149) 24 rnd ltac:(lia) Hr x) as H1.
  pose proof (flush_covered (-149) 24 rnd ltac:(lia) Hr x) as H2.
  change (Z.opp 24) with (-24)%Z in H1, H2. change (-149 + 24 - 1)%Z with (-126)%Z in H2.
  assert (E : bpow radix2 (-149) <= bpow radix2 (-126)) by (apply bpow_le; lia).
  unfold ap_in, ap_add, ap_mul, shader32; cbn [m_u m_eta k_in k_add k_mul].
  unfold approx, ap1 in *. repeat split; lra.
Qed.

Lemma shader32_div_covered : forall (x y : R),
  Rabs (y - x) <= 5 / 2 * ulp radix2 (FLT_exp (-149) 24) x -> ap_div shader32 y x.
Proof.
  intros x y H. unfold ap_div, approx, ap1, shader32; cbn [m_u m_eta k_div].
  assert (E : bpow radix2 (-149) <= / 4 * bpow radix2 (-126)).
  { replace (/ 4 * bpow radix2 (-126)) with (bpow radix2 (-128)) by (simpl; lra).
    apply bpow_le; lia. }
  pose proof (ulp_le_rel (-149) 24 x ltac:(unfold Prec_gt_0; lia)).
  change (- (24))%Z with (-24)%Z in *. pose proof (bpow_ge_0 radix2 (-126)). lra.
Qed.

(** So [shader32_recip] covers every operation of [shader32] (the same
    relation for inputs, add, sub, mul; a 2.5-ulp division has k = 5 <=
    7 + 2^-20) and a division by n or by 2 done as a 2.5-ulp reciprocal then
    a product of the shader profile (possibly flushed). *)
Lemma shader32_recip_covered : forall (y x : R),
  (ap_in shader32 y x -> ap_in shader32_recip y x) /\
  (ap_add shader32 y x -> ap_add shader32_recip y x) /\
  (ap_mul shader32 y x -> ap_mul shader32_recip y x) /\
  (ap_div shader32 y x -> ap_div shader32_recip y x).
Proof.
  intros y x. unfold ap_in, ap_add, ap_mul, ap_div, shader32, shader32_recip;
    cbn [m_u m_eta k_in k_add k_mul k_div].
  repeat split; try (intros H; exact H).
  intros H. unfold approx in *. eapply ap1_mono; [|exact H].
  apply Rmult_le_compat_r; [apply bpow_ge_0 | lra].
Qed.

(** Division by m (1 <= m <= 2^24: n or 2) as a reciprocal within 5u (2.5 ulp,
    the specifications' bound on 1.0/x) followed by a product within 2u (any
    rounding of the format): k = 7 + 2^-20 ([recip_mul_gen]). *)
Lemma shader32_recip_mul_covered : forall (m x r y : R), 1 <= m <= 16777216 ->
  ap_div shader32 r (/ m) -> ap_mul shader32 y (x * r) -> ap_div shader32_recip y (x / m).
Proof.
  intros m x r y Hm Hr Hy.
  unfold ap_div, ap_mul, shader32, shader32_recip in *; cbn [m_u m_eta k_mul k_div] in *.
  pose proof (eta84 (-126) (-24) ltac:(lia)) as H5.
  pose proof (bpow_ge_0 radix2 (-126)) as H6.
  rewrite u24 in *. replace (7 + / 1048576) with (5 + 2 + / 1048576) by ring.
  apply (recip_mul_gen _ _ _ _ m x r y); try assumption; lra.
Qed.

(** ** The adaptive scheme's acceptance set (docs/float.md §10)

    An implementation decides between Gouraud and corrected Euler with its own
    δ̂ = (Ĝ(j) − Ĉ(j))(1 + θ₁): the two methods' values at the middle pixel j,
    each within its bound b_G, b_CE of the exact value, subtracted with one
    rounding (|θ₁| ≤ u); the test's product t̂ = 255·K_d·δ̂ carries at most
    two more (|θ₂| ≤ 3u covers (1 + u)² − 1). It runs Gouraud when |t̂| < 1
    and corrected Euler otherwise, and its run is within that method's bound.
    With x = 255·K_d and δ = G(j) − C(j) the exact difference (|δ| ≤ 1/2 for
    unit normals, eq_24_delta_unit_closed_form), the checker accepts either
    method's values where ||x·δ| − 1| is within the band
    x·(1.01(b_G + b_CE) + 2u) + 4u (src/tolerance.rs, adaptive_too_close) and
    the exact run's own pick elsewhere. The set contains every such run:
    outside the band every implementation decides as the exact run does. *)

Definition within_of (b : R) (out ex : nat -> R) (n : nat) : Prop :=
  forall i, (i <= n)%nat -> Rabs (out i - ex i) <= b.

Definition adaptive_band (x bG bCE u : R) : R :=
  x * (101 / 100 * (bG + bCE) + 2 * u) + 4 * u.

Definition adaptive_accepts (x delta bG bCE u : R) (G C out : nat -> R) (n : nat) : Prop :=
  (Rabs (Rabs (x * delta) - 1) <= adaptive_band x bG bCE u
     /\ (within_of bG out G n \/ within_of bCE out C n))
  \/ (adaptive_band x bG bCE u < Rabs (Rabs (x * delta) - 1)
      /\ ((Rabs (x * delta) < 1 /\ within_of bG out G n)
          \/ (1 <= Rabs (x * delta) /\ within_of bCE out C n))).
(** Outside the band the test on δ̂ (within E of δ) decides as the exact δ
    would; inside it either method's set is accepted (here and in AdaptiveDelta.v). *)
Lemma acc_decision_far_below : forall x u E D Dh th2,
  0 < x -> 0 <= u <= 1/1024 -> Rabs (Dh - D) <= E -> Rabs th2 <= 3 * u ->
  x * Rabs D < 1 - (x * E + 4 * u) -> Rabs (x * Dh * (1 + th2)) < 1.
Proof.
  intros x u E D Dh th2 Hx Hu HD H2 Hlt.
  pose proof (abs_near _ _ _ HD) as HDh. pose proof (Rabs_pos Dh).
  pose proof (Rabs_triang 1 th2). rewrite Rabs_R1 in *.
  rewrite !Rabs_mult, (Rabs_pos_eq x) by lra.
  assert (x * Rabs Dh <= x * (Rabs D + E)) by (apply Rmult_le_compat_l; lra).
  assert (x * Rabs Dh * Rabs (1 + th2) <= x * Rabs Dh * (1 + 3 * u))
    by (apply Rmult_le_compat_l; nra).
  nra.
Qed.

Lemma acc_decision_far_above : forall x u E D Dh th2,
  0 < x -> 0 <= u <= 1/1024 -> Rabs (Dh - D) <= E -> Rabs th2 <= 3 * u ->
  1 + (x * E + 4 * u) < x * Rabs D -> 1 <= Rabs (x * Dh * (1 + th2)).
Proof.
  intros x u E D Dh th2 Hx Hu HD H2 Hgt.
  pose proof (Rabs_triang_inv D Dh) as T. rewrite Rabs_minus_sym in T.
  pose proof (Rabs_triang_inv 1 (- th2)) as T2. rewrite Rabs_R1, Rabs_Ropp in T2.
  replace (1 - - th2) with (1 + th2) in T2 by ring.
  rewrite !Rabs_mult, (Rabs_pos_eq x) by lra.
  assert (x * (Rabs D - E) <= x * Rabs Dh) by (apply Rmult_le_compat_l; lra).
  apply Rle_trans with ((1 + 4 * u) * (1 - 3 * u)); [nra|].
  apply Rmult_le_compat; lra.
Qed.

Lemma adaptive_accepts_of_delta_error :
  forall (x u bG bCE D Dh E th2 : R) (G C out : nat -> R) (n : nat),
    0 < x -> 0 <= u <= 1/1024 ->
    Rabs (Dh - D) <= E -> E <= 101 / 100 * (bG + bCE) + 2 * u -> Rabs th2 <= 3 * u ->
    (Rabs (x * Dh * (1 + th2)) < 1 -> within_of bG out G n) ->
    (1 <= Rabs (x * Dh * (1 + th2)) -> within_of bCE out C n) ->
    adaptive_accepts x D bG bCE u G C out n.
Proof.
  intros x u bG bCE D Dh E th2 G C out n Hx Hu HD HE H2 Hgo Hce.
  assert (HxE : x * E <= x * (101 / 100 * (bG + bCE) + 2 * u)) by (apply Rmult_le_compat_l; lra).
  unfold adaptive_accepts, adaptive_band.
  rewrite Rabs_mult, (Rabs_pos_eq x) by lra.
  destruct (Rle_or_lt (Rabs (x * Rabs D - 1))
                      (x * (101 / 100 * (bG + bCE) + 2 * u) + 4 * u)) as [Hnear|Hfar].
  - left. split; [exact Hnear|].
    destruct (Rlt_or_le (Rabs (x * Dh * (1 + th2))) 1) as [Ht|Ht];
      [left; apply Hgo | right; apply Hce]; exact Ht.
  - right. split; [exact Hfar|].
    destruct (Rlt_or_le (x * Rabs D) 1) as [Hb|Ha].
    + left. split; [exact Hb|]. apply Hgo.
      rewrite Rabs_left in Hfar by lra.
      apply (acc_decision_far_below x u E D Dh th2); try assumption; lra.
    + right. split; [exact Ha|]. apply Hce.
      rewrite Rabs_pos_eq in Hfar by lra.
      apply (acc_decision_far_above x u E D Dh th2); try assumption; lra.
Qed.

Theorem adaptive_acceptance_contains_every_run :
  forall (x u bG bCE Gj Cj Gh Ch th1 th2 : R) (G C out : nat -> R) (n : nat),
    0 < x -> 0 <= u <= 1/1024 -> 0 <= bG -> 0 <= bCE ->
    Rabs (Gj - Cj) <= 2 ->
    Rabs (Gh - Gj) <= bG -> Rabs (Ch - Cj) <= bCE ->
    Rabs th1 <= u -> Rabs th2 <= 3 * u ->
    (Rabs (x * ((Gh - Ch) * (1 + th1)) * (1 + th2)) < 1 -> within_of bG out G n) ->
    (1 <= Rabs (x * ((Gh - Ch) * (1 + th1)) * (1 + th2)) -> within_of bCE out C n) ->
    adaptive_accepts x (Gj - Cj) bG bCE u G C out n.
Proof.
  intros x u bG bCE Gj Cj Gh Ch th1 th2 G C out n Hx Hu HbG HbCE HD2 HG HC H1 H2 Hgo Hce.
  assert (HD : Rabs ((Gh - Ch) - (Gj - Cj)) <= bG + bCE).
  { replace ((Gh - Ch) - (Gj - Cj)) with ((Gh - Gj) + - (Ch - Cj)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_Ropp. lra. }
  assert (Ht : Rabs ((Gh - Ch) * th1) <= (2 + (bG + bCE)) * u).
  { rewrite Rabs_mult. pose proof (abs_near _ _ _ HD).
    apply Rmult_le_compat; try apply Rabs_pos; lra. }
  apply (adaptive_accepts_of_delta_error x u bG bCE _ ((Gh - Ch) * (1 + th1))
           ((bG + bCE) + (2 + (bG + bCE)) * u) th2); try assumption; [|nra].
  replace ((Gh - Ch) * (1 + th1) - (Gj - Cj)) with (((Gh - Ch) - (Gj - Cj)) + (Gh - Ch) * th1)
    by ring.
  eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.
