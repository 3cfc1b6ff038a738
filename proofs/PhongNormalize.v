(** * PhongNormalize.v — "normalize, then dot" under the kappa model.

    A computed normal N^ (per-pixel or lerp form, or any other), then
      q^ = N^.N^            a dot product in any order, products rounded or fused;
      s  ~ sqrt q^          (k_sqrt = ks),   r ~ 1 / s   (kd),
      w_j ~ N^_j * r        three products (km each),
      v^ = w.l              a dot product in any order, products rounded or fused
                            ([fdot_rel um ua eta w l vh]).
    From |N^.l - p| <= ep (the EXACT dot N^.l of the computed normal with the
    read-in l), |q^ - q| <= eq, qmin <= q <= 1, |p| <= sqrt q, |p| <= 1 and
    |l|^2 = l.l <= lam^2:

      |v^ - p/sqrt q| <= [phong_value_recip's bound for ep, eq, ks, kd, km]
                         + 1.03 lam (km u + um + 2 ua) + 2 lam eta + 8 eta.

    Proof: the exact (dot N^ l) * r satisfies phong_value_recip with the
    product done exactly; the rounding of w and of the last dot product act on
    sum_j |N^_j| |l_j| |r| <= |r| |N^| |l| <= (65/64) lam, since
    |N^|^2 = N^.N^ <= (q^ + 8 eta) / (1 - (um + 2 ua)(1 + 2^-19)) ([fdot_err])
    and |r| sqrt q^ <= 1.005.

    Theorems:
      [phong_normalize_dot]       the bound above, any N^, l with l.l <= lam^2;
      [phong_normalize_dot_unit]  the same with l read in from a unit L
                                  ([vap1 (kin u) eta l L]): lam = 1 + kin u + 2 eta;
      [pixel_ok_exact_dot], [lerp_ok_exact_dot]: the per-pixel and lerp forms of
        PhongCount.v accept p^ = dot N^ l (exact), so their p-bounds (e.g.
        (14.04 K1 + 2.04 k_div) u) are valid ep for the exact N^.l here.
    Size conditions: q <= 1, 2 eq <= qmin, (ks + kd + km) u <= 2^-10,
    1024 eta <= qmin - eq (this implies 1024 eta <= sqrt (qmin - eq)),
    um, ua <= 2^-21 (the dot products' units: k_mul u, k_add u). *)

From Coq Require Import Reals Lra.
From PhongApprox Require Import Span FloatModel Float FloatModelK Profiles PhongValue PhongCount PhongCountD.
Open Scope R_scope.

(** ** Helpers *)

(** One component of w = N^ r and its product with l_j. *)
Lemma nd_comp : forall kw eta w n r l, 0 <= kw -> ap1 kw eta w (n * r) ->
  Rabs ((w - n * r) * l) <= kw * (Rabs r * (Rabs n * Rabs l)) + eta * Rabs l /\
  Rabs (w * l) <= (1 + kw) * (Rabs r * (Rabs n * Rabs l)) + eta * Rabs l.
Proof.
  intros kw eta w n r l Hk H. unfold ap1 in H. rewrite Rabs_mult in H.
  pose proof (Rabs_pos l). pose proof (Rabs_pos n). pose proof (Rabs_pos r).
  assert (G1 : Rabs (w - n * r) * Rabs l <= (kw * (Rabs n * Rabs r) + eta) * Rabs l)
    by (apply Rmult_le_compat_r; lra).
  assert (Hw : Rabs w <= Rabs n * Rabs r + Rabs (w - n * r)).
  { replace w with (n * r + (w - n * r)) at 1 by ring.
    eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_mult. lra. }
  assert (G2 : Rabs w * Rabs l <= (Rabs n * Rabs r + (kw * (Rabs n * Rabs r) + eta)) * Rabs l)
    by (apply Rmult_le_compat_r; lra).
  rewrite !Rabs_mult. split; nra.
Qed.

(** The rounding of w and of the final dot product. *)
Lemma nd_extra : forall um ua kw eta (nh l w : vec) r vh R Ls,
  0 <= um <= / 2097152 -> 0 <= ua <= / 2097152 -> 0 <= eta -> 0 <= kw ->
  ap1 kw eta (vx w) (vx nh * r) -> ap1 kw eta (vy w) (vy nh * r) ->
  ap1 kw eta (vz w) (vz nh * r) ->
  fdot_rel um ua eta w l vh ->
  Rabs r * (Rabs (vx nh) * Rabs (vx l) + Rabs (vy nh) * Rabs (vy l) + Rabs (vz nh) * Rabs (vz l))
    <= R ->
  Rabs (vx l) + Rabs (vy l) + Rabs (vz l) <= Ls ->
  Rabs (vh - dot nh l * r) <=
    (kw + (um + 2 * ua) * (1 + / 524288) * (1 + kw)) * R
    + (1 + (um + 2 * ua) * (1 + / 524288)) * eta * Ls + 8 * eta.
Proof.
  intros um ua kw eta nh l w r vh R Ls Hum Hua He Hkw Hx Hy Hz Hd HR HL.
  destruct (nd_comp kw eta _ _ r (vx l) Hkw Hx) as [X1 X2].
  destruct (nd_comp kw eta _ _ r (vy l) Hkw Hy) as [Y1 Y2].
  destruct (nd_comp kw eta _ _ r (vz l) Hkw Hz) as [Z1 Z2].
  pose proof (fdot_err um ua eta w l vh Hum Hua He Hd) as F.
  set (S := Rabs (vx nh) * Rabs (vx l) + Rabs (vy nh) * Rabs (vy l) + Rabs (vz nh) * Rabs (vz l))
    in *.
  set (c2 := (um + 2 * ua) * (1 + / 524288)).
  assert (Hc2 : 0 <= c2) by (unfold c2; nra).
  assert (E : Rabs r * S = Rabs r * (Rabs (vx nh) * Rabs (vx l)) + Rabs r * (Rabs (vy nh) * Rabs (vy l))
                           + Rabs r * (Rabs (vz nh) * Rabs (vz l))) by (unfold S; ring).
  assert (D1 : Rabs (dot w l - dot nh l * r) <= kw * (Rabs r * S) + eta * Ls).
  { replace (dot w l - dot nh l * r) with
      ((vx w - vx nh * r) * vx l + (vy w - vy nh * r) * vy l + (vz w - vz nh * r) * vz l)
      by (unfold dot; ring).
    eapply Rle_trans; [apply tri3|].
    assert (eta * (Rabs (vx l) + Rabs (vy l) + Rabs (vz l)) <= eta * Ls)
      by (apply Rmult_le_compat_l; lra).
    rewrite E. lra. }
  assert (D2 : Rabs (vx w * vx l) + Rabs (vy w * vy l) + Rabs (vz w * vz l)
               <= (1 + kw) * (Rabs r * S) + eta * Ls).
  { assert (eta * (Rabs (vx l) + Rabs (vy l) + Rabs (vz l)) <= eta * Ls)
      by (apply Rmult_le_compat_l; lra).
    rewrite E. lra. }
  assert (D3 : c2 * (Rabs (vx w * vx l) + Rabs (vy w * vy l) + Rabs (vz w * vz l))
               <= c2 * ((1 + kw) * (Rabs r * S) + eta * Ls))
    by (apply Rmult_le_compat_l; lra).
  assert (D4 : kw * (Rabs r * S) <= kw * R) by (apply Rmult_le_compat_l; lra).
  assert (D5 : c2 * ((1 + kw) * (Rabs r * S)) <= c2 * ((1 + kw) * R))
    by (apply Rmult_le_compat_l; [lra|]; apply Rmult_le_compat_l; lra).
  replace (vh - dot nh l * r) with ((vh - dot w l) + (dot w l - dot nh l * r)) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  fold c2 in F.
  replace ((kw + c2 * (1 + kw)) * R + (1 + c2) * eta * Ls + 8 * eta)
    with (kw * R + eta * Ls + (c2 * ((1 + kw) * R) + c2 * (eta * Ls) + 8 * eta)) by ring.
  assert (c2 * ((1 + kw) * (Rabs r * S) + eta * Ls)
          = c2 * ((1 + kw) * (Rabs r * S)) + c2 * (eta * Ls)) by ring.
  lra.
Qed.

(** |r| |N^| |l| <= (65/64) lam. *)
Lemma nd_rho : forall t s r A B S lam c d eta qh,
  0 < t -> t * t = qh -> qh <= 3 / 2 -> 0 <= c <= / 512 -> Rabs (s - t) <= c * t ->
  0 <= d <= / 1024 -> ap1 d eta r (1 / s) -> 0 <= eta -> 1024 * eta <= t ->
  0 <= A -> A <= 1009 / 1000 * qh -> 0 <= B <= lam * lam -> 0 <= lam -> 0 <= S ->
  S * S <= A * B ->
  Rabs r * S <= 65 / 64 * lam.
Proof.
  intros t s r A B S lam c d eta qh Ht Htq Hq Hc Hst Hd Hr He Het HA HAq HB Hl HS HSS.
  destruct (pv_ratio c s t Ht ltac:(lra) Hst) as (Hs & Hr0 & Hts & _).
  assert (Hic : / (1 - c) <= 512 / 511).
  { replace (512 / 511) with (/ (1 - / 512)) by (field; lra).
    apply Rinv_le_contravar; lra. }
  unfold ap1 in Hr.
  assert (Hs1 : Rabs (1 / s) = 1 / s)
    by (apply Rabs_pos_eq; unfold Rdiv; rewrite Rmult_1_l; left; apply Rinv_0_lt_compat; lra).
  rewrite Hs1 in Hr.
  assert (Hra : Rabs r <= (1 + d) * (1 / s) + eta).
  { replace r with (1 / s + (r - 1 / s)) at 1 by ring.
    eapply Rle_trans; [apply Rabs_triang|].
    rewrite Hs1. lra. }
  assert (X0 : 0 <= Rabs r * t) by (apply Rmult_le_pos; [apply Rabs_pos|lra]).
  assert (X1 : Rabs r * t <= (1 + d) * (t / s) + eta * t).
  { assert (Rabs r * t <= ((1 + d) * (1 / s) + eta) * t) by (apply Rmult_le_compat_r; lra).
    replace ((1 + d) * (t / s)) with ((1 + d) * (1 / s) * t) by (field; lra). lra. }
  assert (X2 : (1 + d) * (t / s) <= (1 + / 1024) * (512 / 511))
    by (apply Rmult_le_compat; lra).
  assert (X3 : eta * t <= 3 / 2048).
  { assert (eta * t <= t / 1024 * t) by (apply Rmult_le_compat_r; lra). nra. }
  assert (Y1 : (Rabs r * S) * (Rabs r * S) <= (Rabs r * Rabs r) * (A * B)).
  { replace ((Rabs r * S) * (Rabs r * S)) with ((Rabs r * Rabs r) * (S * S)) by ring.
    apply Rmult_le_compat_l; [nra|exact HSS]. }
  assert (Y2 : A * B <= (1009 / 1000 * qh) * (lam * lam)) by (apply Rmult_le_compat; lra).
  assert (Y4 : (Rabs r * Rabs r) * ((1009 / 1000 * qh) * (lam * lam))
               = 1009 / 1000 * ((Rabs r * t) * (Rabs r * t)) * (lam * lam))
    by (rewrite <- Htq; ring).
  assert (Y6 : 1009 / 1000 * ((Rabs r * t) * (Rabs r * t)) * (lam * lam)
               <= 1009 / 1000 * ((1005 / 1000) * (1005 / 1000)) * (lam * lam))
    by (apply Rmult_le_compat_r; nra).
  apply nd_sq_le; [apply Rmult_le_pos; [apply Rabs_pos|lra] | lra |].
  nra.
Qed.

(** |l_1| + |l_2| + |l_3| <= sqrt 3 |l| <= (7/4) lam. *)
Lemma nd_l1 : forall (l : vec) lam, 0 <= lam -> dot l l <= lam * lam ->
  Rabs (vx l) + Rabs (vy l) + Rabs (vz l) <= 7 / 4 * lam.
Proof.
  intros l lam Hl H. unfold dot in H.
  rewrite <- (abs_sq (vx l)), <- (abs_sq (vy l)), <- (abs_sq (vz l)) in H.
  pose proof (Rabs_pos (vx l)). pose proof (Rabs_pos (vy l)). pose proof (Rabs_pos (vz l)).
  apply nd_sq_le; [lra|lra|].
  set (x := Rabs (vx l)) in *. set (y := Rabs (vy l)) in *. set (z := Rabs (vz l)) in *.
  pose proof (Rle_0_sqr (x - y)). pose proof (Rle_0_sqr (x - z)). pose proof (Rle_0_sqr (y - z)).
  unfold Rsqr in *. nra.
Qed.

(** |N^|^2 = N^.N^ from the computed q^ = N^.N^. *)
Lemma nd_norm : forall um ua eta (nh : vec) qh,
  0 <= um <= / 2097152 -> 0 <= ua <= / 2097152 -> 0 <= eta -> 0 <= qh ->
  1024 * eta <= qh -> fdot_rel um ua eta nh nh qh ->
  0 <= dot nh nh <= 1009 / 1000 * qh.
Proof.
  intros um ua eta nh qh Hum Hua He Hq Heq Hd.
  pose proof (fdot_err um ua eta nh nh qh Hum Hua He Hd) as F.
  pose proof (dot_sq0 nh) as A0.
  assert (E : Rabs (vx nh * vx nh) + Rabs (vy nh * vy nh) + Rabs (vz nh * vz nh) = dot nh nh)
    by (unfold dot; rewrite !Rabs_pos_eq by apply Rle_0_sqr; reflexivity).
  rewrite E in F.
  set (c2 := (um + 2 * ua) * (1 + / 524288)) in *.
  assert (Hc2 : c2 <= / 524288) by (unfold c2; nra).
  assert (Hc : c2 * dot nh nh <= / 524288 * dot nh nh) by (apply Rmult_le_compat_r; lra).
  pose proof (pv_abs_le _ _ F). split; [exact A0|]. lra.
Qed.

(** ** Normalize, then dot *)

Theorem phong_normalize_dot : forall u eta ks kd km um ua lam p q qmin ep eq
                                     (nh l w : vec) qh s r vh,
  0 < qmin -> qmin <= q -> q <= 1 -> Rabs p <= sqrt q -> Rabs p <= 1 ->
  Rabs (dot nh l - p) <= ep -> Rabs (qh - q) <= eq -> 0 <= ep -> 0 <= eq -> 2 * eq <= qmin ->
  0 <= u -> 0 <= eta -> 0 <= ks -> 0 <= kd -> 0 <= km ->
  (ks + kd + km) * u <= / 1024 -> 1024 * eta <= qmin - eq ->
  0 <= um <= / 2097152 -> 0 <= ua <= / 2097152 ->
  0 <= lam -> dot l l <= lam * lam ->
  fdot_rel um ua eta nh nh qh ->
  ap1 (ks * u) eta s (sqrt qh) ->
  ap1 (kd * u) eta r (1 / s) ->
  ap1 (km * u) eta (vx w) (vx nh * r) -> ap1 (km * u) eta (vy w) (vy nh * r) ->
  ap1 (km * u) eta (vz w) (vz nh * r) ->
  fdot_rel um ua eta w l vh ->
  Rabs (vh - p / sqrt q) <=
    (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq))))
      * (1 + (ks + kd + km) * u / (1 - (ks + kd + km) * u))
    + (ks + kd + km) * u / (1 - (ks + kd + km) * u)
    + (2 * (1 + (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq)))))
         * (eta / sqrt (qmin - eq))
       + ((1 + ep) * eta * (1 + km * u) + eta))
    + (103 / 100 * lam * (km * u + um + 2 * ua) + 2 * lam * eta + 8 * eta).
Proof.
  intros u eta ks kd km um ua lam p q qmin ep eq nh l w qh s r vh
    Hqm Hq Hq1 Hp Hp1 Hep Heq Hep0 Heq0 H2 Hu He Hks Hkd Hkm Hw He2 Hum Hua Hl0 Hl
    Hqh Hs Hr Hx Hy Hz Hv.
  pose proof (pv_abs_le _ _ Heq) as Hqb.
  assert (Hku : 0 <= ks * u /\ 0 <= kd * u /\ 0 <= km * u) by (repeat split; apply Rmult_le_pos; lra).
  (* 1024 eta <= qmin - eq <= sqrt (qmin - eq), as qmin - eq <= 1 *)
  assert (Ha1 : 0 < qmin - eq <= 1) by lra.
  assert (He3 : 1024 * eta <= sqrt (qmin - eq)).
  { assert (sqrt (qmin - eq) <= 1) by (rewrite <- sqrt_1; apply sqrt_le_1_alt; lra).
    assert (sqrt (qmin - eq) * sqrt (qmin - eq) = qmin - eq) by (apply sqrt_sqrt; lra).
    assert (0 <= sqrt (qmin - eq)) by apply sqrt_pos.
    nra. }
  (* the exact product (dot nh l) * r, through phong_value_recip *)
  assert (Hex : ap1 (km * u) eta (dot nh l * r) (dot nh l * r)) by (apply ap1_exact; lra).
  pose proof (phong_value_recip u eta ks kd km p q (dot nh l) qh qmin ep eq s r (dot nh l * r)
    Hqm Hq Hp Hp1 Hep Heq Hep0 Heq0 H2 Hu He Hks Hkd Hkm Hw He3 Hs Hr Hex) as H1.
  destruct (pv_setup u eta ks p q (dot nh l) qh qmin ep eq s Hqm Hq Hp Hep Heq Hep0 Heq0 H2
              He He3 Hs) as (Ht & _ & Heps & Hst & _).
  (* sizes *)
  assert (Hqh0 : qmin - eq <= qh) by lra.
  assert (Hqh1 : qh <= 3 / 2) by lra.
  assert (Htt : sqrt qh * sqrt qh = qh) by (apply sqrt_sqrt; lra).
  assert (Het : 1024 * eta <= sqrt qh).
  { assert (sqrt (qmin - eq) <= sqrt qh) by (apply sqrt_le_1_alt; lra). lra. }
  destruct (nd_norm um ua eta nh qh Hum Hua He ltac:(lra) ltac:(lra) Hqh) as [HA0 HA].
  assert (HB : 0 <= dot l l <= lam * lam) by (split; [apply dot_sq0 | exact Hl]).
  set (S := Rabs (vx nh) * Rabs (vx l) + Rabs (vy nh) * Rabs (vy l) + Rabs (vz nh) * Rabs (vz l)).
  assert (HS0 : 0 <= S)
    by (unfold S; repeat apply Rplus_le_le_0_compat; apply Rmult_le_pos; apply Rabs_pos).
  assert (Hc : 0 <= ks * u + eta / sqrt (qmin - eq) <= / 512) by lra.
  assert (Hd : 0 <= kd * u <= / 1024) by lra.
  pose proof (nd_rho (sqrt qh) s r (dot nh nh) (dot l l) S lam (ks * u + eta / sqrt (qmin - eq))
    (kd * u) eta qh Ht Htt Hqh1 Hc Hst Hd Hr He Het HA0 HA HB Hl0 HS0 (nd_cs nh l)) as HR.
  pose proof (nd_l1 l lam Hl0 Hl) as HL.
  pose proof (nd_extra um ua (km * u) eta nh l w r vh (65 / 64 * lam) (7 / 4 * lam)
    Hum Hua He (proj2 (proj2 Hku)) Hx Hy Hz Hv HR HL) as H2x.
  (* the constants *)
  assert (Hg : 0 <= um + 2 * ua <= 3 / 2097152) by lra.
  assert (Hkw : 0 <= km * u <= / 1024) by lra.
  set (g := um + 2 * ua) in *.
  set (kw := km * u) in *.
  assert (C1 : g * (1 + / 524288) * (1 + kw) <= g * ((1 + / 524288) * (1 + / 1024))).
  { rewrite Rmult_assoc. apply Rmult_le_compat_l; [lra|]. apply Rmult_le_compat_l; lra. }
  assert (C2 : (kw + g * (1 + / 524288) * (1 + kw)) * (65 / 64 * lam)
               <= 103 / 100 * lam * (kw + g)).
  { assert (kw + g * (1 + / 524288) * (1 + kw) <= 1015 / 1000 * (kw + g)) by lra.
    assert ((kw + g * (1 + / 524288) * (1 + kw)) * (65 / 64 * lam)
            <= 1015 / 1000 * (kw + g) * (65 / 64 * lam)) by (apply Rmult_le_compat_r; lra).
    nra. }
  assert (C3 : (1 + g * (1 + / 524288)) * eta * (7 / 4 * lam) <= 2 * lam * eta).
  { assert (g * (1 + / 524288) <= / 1000) by nra.
    assert (0 <= eta * lam) by (apply Rmult_le_pos; lra).
    assert ((1 + g * (1 + / 524288)) * (eta * lam) <= (1 + / 1000) * (eta * lam))
      by (apply Rmult_le_compat_r; lra).
    nra. }
  replace (vh - p / sqrt q) with ((vh - dot nh l * r) + (dot nh l * r - p / sqrt q)) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  replace (kw + um + 2 * ua) with (kw + g) by (unfold g; ring).
  lra.
Qed.

(** ** The read-in light l of a unit L: |l| <= 1 + v + 2 eta *)

Lemma nd_lam_comp : forall v eta y x, 0 <= v -> 0 <= eta -> ap1 v eta y x ->
  Rabs y * Rabs y <= ((1 + v) * Rabs x + eta) * ((1 + v) * Rabs x + eta).
Proof.
  intros v eta y x Hv He H. unfold ap1 in H.
  pose proof (abs_near _ _ _ H) as H1. pose proof (Rabs_pos y). pose proof (Rabs_pos x).
  apply Rmult_le_compat; lra.
Qed.

Lemma nd_lam : forall v eta (l L : vec), 0 <= v -> 0 <= eta -> is_unit L -> vap1 v eta l L ->
  dot l l <= (1 + v + 2 * eta) * (1 + v + 2 * eta).
Proof.
  intros v eta l L Hv He HL (Hx & Hy & Hz).
  pose proof (nd_l1 L 1 ltac:(lra) ltac:(unfold is_unit in HL; lra)) as H1.
  pose proof (nd_lam_comp v eta _ _ Hv He Hx) as X.
  pose proof (nd_lam_comp v eta _ _ Hv He Hy) as Y.
  pose proof (nd_lam_comp v eta _ _ Hv He Hz) as Z.
  unfold is_unit, dot in HL. unfold dot.
  rewrite <- (abs_sq (vx L)), <- (abs_sq (vy L)), <- (abs_sq (vz L)) in HL.
  rewrite <- (abs_sq (vx l)), <- (abs_sq (vy l)), <- (abs_sq (vz l)).
  set (a1 := Rabs (vx L)) in *. set (a2 := Rabs (vy L)) in *. set (a3 := Rabs (vz L)) in *.
  assert (E : ((1 + v) * a1 + eta) * ((1 + v) * a1 + eta) + ((1 + v) * a2 + eta) * ((1 + v) * a2 + eta)
              + ((1 + v) * a3 + eta) * ((1 + v) * a3 + eta)
              = (1 + v) * (1 + v) * (a1 * a1 + a2 * a2 + a3 * a3)
                + 2 * ((1 + v) * eta) * (a1 + a2 + a3) + 3 * (eta * eta)) by ring.
  rewrite HL in E.
  assert (0 <= (1 + v) * eta) by (apply Rmult_le_pos; lra).
  nra.
Qed.

(** The same theorem with l read in from a unit L (each component within
    kin u |L_j| + eta, [Profiles.vap1]): lam = 1 + kin u + 2 eta. *)
Theorem phong_normalize_dot_unit : forall u eta ks kd km kin um ua p q qmin ep eq
                                          (nh l L w : vec) qh s r vh,
  0 < qmin -> qmin <= q -> q <= 1 -> Rabs p <= sqrt q -> Rabs p <= 1 ->
  Rabs (dot nh l - p) <= ep -> Rabs (qh - q) <= eq -> 0 <= ep -> 0 <= eq -> 2 * eq <= qmin ->
  0 <= u -> 0 <= eta -> 0 <= ks -> 0 <= kd -> 0 <= km -> 0 <= kin ->
  (ks + kd + km) * u <= / 1024 -> 1024 * eta <= qmin - eq ->
  0 <= um <= / 2097152 -> 0 <= ua <= / 2097152 ->
  is_unit L -> vap1 (kin * u) eta l L ->
  fdot_rel um ua eta nh nh qh ->
  ap1 (ks * u) eta s (sqrt qh) ->
  ap1 (kd * u) eta r (1 / s) ->
  ap1 (km * u) eta (vx w) (vx nh * r) -> ap1 (km * u) eta (vy w) (vy nh * r) ->
  ap1 (km * u) eta (vz w) (vz nh * r) ->
  fdot_rel um ua eta w l vh ->
  Rabs (vh - p / sqrt q) <=
    (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq))))
      * (1 + (ks + kd + km) * u / (1 - (ks + kd + km) * u))
    + (ks + kd + km) * u / (1 - (ks + kd + km) * u)
    + (2 * (1 + (ep / sqrt (qmin - eq) + eq / (sqrt (qmin - eq) * (sqrt qmin + sqrt (qmin - eq)))))
         * (eta / sqrt (qmin - eq))
       + ((1 + ep) * eta * (1 + km * u) + eta))
    + (103 / 100 * (1 + kin * u + 2 * eta) * (km * u + um + 2 * ua)
       + 2 * (1 + kin * u + 2 * eta) * eta + 8 * eta).
Proof.
  intros u eta ks kd km kin um ua p q qmin ep eq nh l L w qh s r vh
    Hqm Hq Hq1 Hp Hp1 Hep Heq Hep0 Heq0 H2 Hu He Hks Hkd Hkm Hkin Hw He2 Hum Hua HL Hl.
  assert (0 <= kin * u) by (apply Rmult_le_pos; lra).
  apply (phong_normalize_dot u eta ks kd km um ua (1 + kin * u + 2 * eta) p q qmin ep eq nh l w);
    try assumption; try lra.
  apply (nd_lam (kin * u) eta l L); assumption.
Qed.

(** ** The p-bounds of PhongCount.v hold for the exact dot N^.l

    [pixel_ok] and [lerp_ok] take p^ with [fdot_ok M nh l ph]; the exact dot
    product (each product and both sums exact) is one such p^.  So
    phong_pixel_div_generic, phong_pixel_recip_generic, phong_lerp_div_generic
    and phong_lerp_recip_generic bound |dot nh l - p_i| by their p-bound. *)

Lemma fdot_exact : forall um ua eta (a b : vec), 0 <= um -> 0 <= ua -> 0 <= eta ->
  fdot_rel um ua eta a b (dot a b).
Proof.
  intros um ua eta a b Hm Ha He.
  exists (vx a * vx b), (vy a * vy b), (vz a * vz b).
  repeat split; try (apply ap1_exact; assumption).
  exists (vx a * vx b + vy a * vy b). left. split; apply ap1_exact; assumption.
Qed.

Lemma fdot_ok_exact : forall M K (a b : vec), model_ok M K -> fdot_ok M a b (dot a b).
Proof.
  intros M K a b HM. pose proof HM as (U1 & U2 & _ & _ & [A0 _] & [M0 _] & _).
  unfold fdot_ok. apply fdot_exact; [apply Rmult_le_pos; lra | apply Rmult_le_pos; lra | lra].
Qed.

Theorem pixel_ok_exact_dot : forall M K i (na l kk nh : vec) qh, model_ok M K ->
  ncomp_ok M i (vx nh) (vx na) (vx kk) -> ncomp_ok M i (vy nh) (vy na) (vy kk) ->
  ncomp_ok M i (vz nh) (vz na) (vz kk) -> fdot_ok M nh nh qh ->
  pixel_ok M i na l kk (dot nh l) qh.
Proof.
  intros M K i na l kk nh qh HM Hx Hy Hz Hq.
  exists nh. repeat split; try assumption. exact (fdot_ok_exact M K nh l HM).
Qed.

Theorem lerp_ok_exact_dot : forall M K th (na nb l nh : vec) qh, model_ok M K ->
  lcomp_ok M th (vx nh) (vx na) (vx nb) -> lcomp_ok M th (vy nh) (vy na) (vy nb) ->
  lcomp_ok M th (vz nh) (vz na) (vz nb) -> fdot_ok M nh nh qh ->
  lerp_ok M th na nb l (dot nh l) qh.
Proof.
  intros M K th na nb l nh qh HM Hx Hy Hz Hq.
  exists nh. repeat split; try assumption. exact (fdot_ok_exact M K nh l HM).
Qed.
