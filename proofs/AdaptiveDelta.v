(** * AdaptiveDelta.v — the adaptive scheme's acceptance set (Profiles.v,
    [adaptive_accepts]) covers implementations that compute the test value
    δ̂ directly from their set-up, not as a difference of two computed pixels:

    (i)  the fast kernel: δ̂ = fl(fl(fl(0.5·ds)·lo)·hi), lo = ⌊n/2⌋, hi = ⌈n/2⌉,
         or any association of the three products ([fast_delta_ok]);
    (ii) eq. 24 as written: δ̂ = fl(fl(j·dp) − fl(fl(j·t0) + fl(c·ds))),
         j = ⌈n/2⌉, c = (j² − j)/2 exact ([eq24_delta_ok]);

    on the set-ups of Profiles.v ([ce_setup_ok] for t0, ds; [gouraud_setup_ok]
    for dp), every operation in the κ model (FloatModelK.v).  The checker's
    band x·(1.01(b_G + b_CE) + 2u) + 4u is unchanged: it suffices that the
    error of δ̂ against the exact δ = G(j) − C(j) is at most
    1.01(b_G + b_CE) + 2u ([adaptive_accepts_of_delta_error]); the errors are
    [fast_delta_err] and [eq24_delta_err] (any model), at most 17u and 83u
    for the ieee binary32 profile, 63u for (ii) when the two set-ups share
    the computed p_a, p_b ([eq24_shared_delta_err])
    ([adaptive_acceptance_covers_computed_delta]).  The same with (ii) evaluated
    at j = ⌈n/2⌉ or j = n − ⌈n/2⌉ = ⌊n/2⌋ (a step ⌊m̂⌋ + 1 from eq. 23 computed
    in floats may be either for odd n), same bounds ([eq24_delta_ok_at],
    [adaptive_acceptance_covers_computed_delta_generic_step],
    [adaptive_acceptance_covers_computed_delta_step]). *)

From Coq Require Import Reals Lra Lia.
From Flocq Require Import Core.
From PhongApprox Require Import Span Euler Adaptive FloatModel Float FloatModelK Profiles.
Open Scope R_scope.

(** ** Error of the fast kernel (i): a chain of three rounded products *)

Lemma ad_step : forall v eta c y z Z e,
  0 <= v -> 0 <= c -> ap1 v eta y (c * z) -> Rabs (z - Z) <= e ->
  Rabs (y - c * Z) <= c * (1 + v) * e + v * (c * Rabs Z) + eta.
Proof.
  intros v eta c y z Z e Hv Hc H1 H2. unfold ap1 in H1.
  assert (Hz : Rabs z <= Rabs Z + e).
  { replace z with (Z + (z - Z)) by ring. eapply Rle_trans; [apply Rabs_triang|]. lra. }
  rewrite Rabs_mult, (Rabs_pos_eq c) in H1 by lra.
  replace (y - c * Z) with ((y - c * z) + c * (z - Z)) by ring.
  eapply Rle_trans; [apply Rabs_triang|].
  rewrite Rabs_mult, (Rabs_pos_eq c) by lra.
  assert (c * Rabs (z - Z) <= c * e) by (apply Rmult_le_compat_l; lra).
  assert (v * (c * Rabs z) <= v * (c * (Rabs Z + e))).
  { apply Rmult_le_compat_l; [lra|]. apply Rmult_le_compat_l; lra. }
  nra.
Qed.

Lemma ad_chain3 : forall v eta c1 c2 c3 Z y1 y2 y3,
  0 <= v <= 1/1024 -> 0 <= eta -> 0 <= c1 -> 0 <= c2 -> 0 <= c3 ->
  ap1 v eta y1 (c1 * Z) -> ap1 v eta y2 (c2 * y1) -> ap1 v eta y3 (c3 * y2) ->
  Rabs (y3 - c3 * (c2 * (c1 * Z))) <=
    3004 / 1000 * v * Rabs (c3 * (c2 * (c1 * Z))) + (1 + 2 * c3 + 2 * (c3 * c2)) * eta.
Proof.
  intros v eta c1 c2 c3 Z y1 y2 y3 Hv He H1 H2 H3 A1 A2 A3.
  set (A := c1 * Rabs Z).
  assert (HA : 0 <= A) by (unfold A; apply Rmult_le_pos; [lra | apply Rabs_pos]).
  assert (E1 : Rabs (y1 - c1 * Z) <= v * A + eta).
  { unfold ap1 in A1. rewrite Rabs_mult, (Rabs_pos_eq c1) in A1 by lra. exact A1. }
  pose proof (ad_step v eta c2 y2 y1 (c1 * Z) _ ltac:(lra) H2 A2 E1) as E2.
  rewrite Rabs_mult, (Rabs_pos_eq c1) in E2 by lra. fold A in E2.
  pose proof (ad_step v eta c3 y3 y2 (c2 * (c1 * Z)) _ ltac:(lra) H3 A3 E2) as E3.
  rewrite Rabs_mult, (Rabs_mult c1), (Rabs_pos_eq c1), (Rabs_pos_eq c2) in E3 by lra. fold A in E3.
  rewrite !Rabs_mult, (Rabs_pos_eq c1), (Rabs_pos_eq c2), (Rabs_pos_eq c3) by lra. fold A.
  eapply Rle_trans; [exact E3|].
  assert (P : 0 <= c3 * c2 * A) by (apply Rmult_le_pos; [apply Rmult_le_pos|]; lra).
  assert (Q : 0 <= c3 * c2 * eta) by (apply Rmult_le_pos; [apply Rmult_le_pos|]; lra).
  assert (Q2 : 0 <= c3 * eta) by (apply Rmult_le_pos; lra).
  replace (c3 * (1 + v) * (c2 * (1 + v) * (v * A + eta) + v * (c2 * A) + eta) + v * (c3 * (c2 * A)) + eta)
    with ((3 * v + 3 * v * v + v * v * v) * (c3 * c2 * A)
          + ((1 + v) * (1 + v) * (c3 * c2 * eta) + (1 + v) * (c3 * eta) + eta)) by ring.
  assert (V0 : v * v <= v * (1 / 1024)) by (apply Rmult_le_compat_l; lra).
  assert (V0' : v * v * v <= v * v * 1) by (apply Rmult_le_compat_l; nra).
  assert (V1 : 3 * v + 3 * v * v + v * v * v <= 3004 / 1000 * v) by lra.
  assert (V2 : (1 + v) * (1 + v) <= 2)
    by (replace ((1 + v) * (1 + v)) with (1 + 2 * v + v * v) by ring; lra).
  assert (T1 : (3 * v + 3 * v * v + v * v * v) * (c3 * c2 * A) <= 3004 / 1000 * v * (c3 * (c2 * A))).
  { replace (c3 * (c2 * A)) with (c3 * c2 * A) by ring. apply Rmult_le_compat_r. exact P. exact V1. }
  assert (T2 : (1 + v) * (1 + v) * (c3 * c2 * eta) <= 2 * (c3 * c2 * eta)) by (apply Rmult_le_compat_r; lra).
  assert (T3 : (1 + v) * (c3 * eta) <= 2 * (c3 * eta)) by (apply Rmult_le_compat_r; lra).
  lra.
Qed.

Lemma ad_sc : forall th x M E, 0 <= th <= M -> Rabs x <= E -> Rabs (th * x) <= M * E.
Proof.
  intros th x M E Hth Hx. rewrite Rabs_mult, (Rabs_pos_eq th) by lra.
  apply Rmult_le_compat; try lra; apply Rabs_pos.
Qed.

(** j lo / (2 n^2) <= 1/8 for j + lo = n. *)
Lemma ad_kk : forall nr j lo, 1 <= nr -> 0 <= j -> 0 <= lo -> j + lo = nr ->
  0 <= j * lo / (2 * (nr * nr)) <= 1 / 8.
Proof.
  intros nr j lo Hn Hj Hlo Hs. split.
  - unfold Rdiv.
    apply Rmult_le_pos; [apply Rmult_le_pos; lra | apply Rlt_le, Rinv_0_lt_compat; nra].
  - assert (Hjl : j * lo <= nr * nr / 4)
      by (rewrite <- Hs; pose proof (Rle_0_sqr (j - lo)) as Sq; unfold Rsqr in Sq; lra).
    apply (Rmult_le_reg_r (2 * (nr * nr))); [nra|].
    replace (j * lo / (2 * (nr * nr)) * (2 * (nr * nr))) with (j * lo) by (field; nra).
    lra.
Qed.

(** the kernel's delta = ds/2 * j * lo with j + lo = n, c1 c2 c3 = j lo / 2 *)
Lemma ad_fast_err : forall v eta nr j lo dsx dsh Eds c1 c2 c3 y1 y2 dh,
  0 <= v <= 1/1024 -> 0 <= eta -> 1 <= nr -> 0 <= j -> 0 <= lo -> j + lo = nr ->
  0 <= c1 -> 0 <= c2 -> 0 <= c3 -> c3 <= 16777216 -> c3 * c2 <= 281474976710656 ->
  c1 * c2 * c3 = j * lo / 2 ->
  Rabs (nr * nr * dsh - nr * nr * dsx) <= Eds -> Rabs (nr * nr * dsx) <= 2 ->
  ap1 v eta y1 (c1 * dsh) -> ap1 v eta y2 (c2 * y1) -> ap1 v eta dh (c3 * y2) ->
  Rabs (dh - dsx / 2 * j * lo) <= Eds / 8 + 3004 / 1000 * v * (1 / 4 + Eds / 8)
                                   + 562949986975745 * eta.
Proof.
  intros v eta nr j lo dsx dsh Eds c1 c2 c3 y1 y2 dh Hv He Hn Hj Hlo Hs H1 H2 H3 H3b H23 Hc
         Hds Hdx A1 A2 A3.
  pose proof (ad_chain3 v eta c1 c2 c3 dsh y1 y2 dh Hv He H1 H2 H3 A1 A2 A3) as C.
  set (kk := j * lo / (2 * (nr * nr))).
  assert (Hk : 0 <= kk <= 1 / 8) by (apply ad_kk; lra).
  assert (HX : c3 * (c2 * (c1 * dsh)) = kk * (nr * nr * dsh)).
  { unfold kk. replace (c3 * (c2 * (c1 * dsh))) with (c1 * c2 * c3 * dsh) by ring.
    rewrite Hc. field. nra. }
  assert (HD : dsx / 2 * j * lo = kk * (nr * nr * dsx)) by (unfold kk; field; nra).
  rewrite HX in C. rewrite HD.
  assert (Hds0 : 0 <= Eds) by (pose proof (Rabs_pos (nr * nr * dsh - nr * nr * dsx)); lra).
  pose proof (abs_near _ _ _ Hds).
  assert (B1 : Rabs (kk * (nr * nr * dsh)) <= 1 / 8 * (2 + Eds)) by (apply ad_sc; lra).
  assert (B2 : Rabs (kk * (nr * nr * dsh - nr * nr * dsx)) <= 1 / 8 * Eds) by (apply ad_sc; lra).
  assert (B3 : (1 + 2 * c3 + 2 * (c3 * c2)) * eta <= 562949986975745 * eta)
    by (apply Rmult_le_compat_r; lra).
  assert (B4 : 3004 / 1000 * v * Rabs (kk * (nr * nr * dsh)) <= 3004 / 1000 * v * (1 / 4 + Eds / 8))
    by (apply Rmult_le_compat_l; lra).
  replace (dh - kk * (nr * nr * dsx))
    with ((dh - kk * (nr * nr * dsh)) + kk * (nr * nr * dsh - nr * nr * dsx)) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. lra.
Qed.

(** ** Error of eq. 24 as written (ii) *)

Lemma ad_ap1_abs : forall v eta y x M, 0 <= v -> ap1 v eta y x -> Rabs x <= M ->
  Rabs (y - x) <= v * M + eta.
Proof.
  intros v eta y x M Hv H HM. unfold ap1 in H.
  assert (v * Rabs x <= v * M) by (apply Rmult_le_compat_l; lra). lra.
Qed.

(** The error of eq. 24's δ̂; the second bound when Gouraud's and corrected
    Euler's set-ups share p_a, p_b: their errors cancel in δ̂. *)
Lemma ad_eq24_err :
  forall v eta nr j lo pa pb dsx pag pbg dph pac pbc t0h dsh a b c e dh
         Epg Edp Epc ER Eds,
  0 <= v -> 0 <= eta -> 1 <= nr -> 0 <= j -> 0 <= j * j - j -> 0 <= lo -> j + lo = nr ->
  Rabs pa <= 1 -> Rabs pb <= 1 -> Rabs (nr * nr * dsx) <= 2 ->
  Rabs (pag - pa) <= Epg -> Rabs (pbg - pb) <= Epg ->
  Rabs (nr * dph - (pbg - pag)) <= Edp ->
  Rabs (pac - pa) <= Epc -> Rabs (pbc - pb) <= Epc ->
  Rabs (nr * t0h - (pbc - pac - nr * (nr - 1) / 2 * dsh)) <= ER ->
  Rabs (nr * nr * dsh - nr * nr * dsx) <= Eds ->
  ap1 v eta a (j * dph) -> ap1 v eta b (j * t0h) -> ap1 v eta c ((j * j - j) / 2 * dsh) ->
  ap1 v eta e (b + c) -> ap1 v eta dh (a - e) ->
  let EG := Edp + 2 * Epg in
  let EC := ER + 2 * Epc + Eds / 8 in
  let EGC := Edp + ER + Eds / 8 in
  let MA := 2 + EG in
  let MB := 3 + 2 * Epc + Eds / 2 + ER in
  let MC := 1 + Eds / 2 in
  let E4 := EG + EC + (v * MA + eta) + (v * MB + eta) + (v * MC + eta)
            + (v * (MB + MC + (v * MB + eta) + (v * MC + eta)) + eta) in
  let E4s := EGC + (v * MA + eta) + (v * MB + eta) + (v * MC + eta)
            + (v * (MB + MC + (v * MB + eta) + (v * MC + eta)) + eta) in
  Rabs (dh - dsx / 2 * j * lo) <= E4 + v * (1 / 4 + E4) + eta /\
  (pag = pac -> pbg = pbc -> Rabs (dh - dsx / 2 * j * lo) <= E4s + v * (1 / 4 + E4s) + eta).
Proof.
  intros v eta nr j lo pa pb dsx pag pbg dph pac pbc t0h dsh a b c e dh Epg Edp Epc ER Eds
    Hv He Hn Hj Hjj Hlo Hs Hpa Hpb Hdx Hpag Hpbg Hdp Hpac Hpbc HR Hds Aa Ab Ac Ae Adh.
  intros EG EC EGC MA MB MC E4 E4s.
  set (th := j / nr).
  assert (Hth : 0 <= th <= 1) by (apply theta_rng; lra).
  set (kk := j * lo / (2 * (nr * nr))).
  assert (Hk : 0 <= kk <= 1 / 8) by (apply ad_kk; lra).
  set (kc := (j * j - j) / (2 * (nr * nr))).
  assert (Hkc : 0 <= kc <= 1 / 2).
  { unfold kc. split.
    - unfold Rdiv. apply Rmult_le_pos; [nra | apply Rlt_le, Rinv_0_lt_compat; nra].
    - apply (Rmult_le_reg_r (2 * (nr * nr))); [nra|].
      replace ((j * j - j) / (2 * (nr * nr)) * (2 * (nr * nr))) with (j * j - j) by (field; nra).
      assert (j * j <= nr * nr) by nra. lra. }
  assert (Hds0 : 0 <= Eds) by (pose proof (Rabs_pos (nr * nr * dsh - nr * nr * dsx)); lra).
  assert (HER0 : 0 <= ER) by (pose proof (Rabs_pos (nr * t0h - (pbc - pac - nr * (nr - 1) / 2 * dsh))); lra).
  assert (HEpc0 : 0 <= Epc) by (pose proof (Rabs_pos (pac - pa)); lra).
  assert (HEpg0 : 0 <= Epg) by (pose proof (Rabs_pos (pag - pa)); lra).
  assert (HEdp0 : 0 <= Edp) by (pose proof (Rabs_pos (nr * dph - (pbg - pag))); lra).
  (* Gouraud part: j dph vs th (pb - pa) *)
  assert (GA : Rabs (j * dph - th * (pb - pa)) <= EG).
  { replace (j * dph - th * (pb - pa))
      with (th * (nr * dph - (pbg - pag)) + th * (pbg - pb) + - (th * (pag - pa)))
      by (unfold th; field; lra).
    eapply Rle_trans; [apply tri3|]. rewrite Rabs_Ropp.
    pose proof (ad_sc th _ 1 _ Hth Hdp). pose proof (ad_sc th _ 1 _ Hth Hpbg).
    pose proof (ad_sc th _ 1 _ Hth Hpag). unfold EG. lra. }
  assert (Hpd : Rabs (th * (pb - pa)) <= 1 * 2)
    by (apply ad_sc; [lra | pose proof (absdiff pb pa); lra]).
  assert (MAb : Rabs (j * dph) <= MA) by (pose proof (abs_near _ _ _ GA); unfold MA; lra).
  (* corrected Euler part *)
  set (Rr := nr * t0h - (pbc - pac - nr * (nr - 1) / 2 * dsh)) in HR.
  assert (CA : Rabs (j * t0h + (j * j - j) / 2 * dsh - (th * (pb - pa) - dsx / 2 * j * lo)) <= EC).
  { replace (j * t0h + (j * j - j) / 2 * dsh - (th * (pb - pa) - dsx / 2 * j * lo))
      with (th * Rr + th * (pbc - pb) + - (th * (pac - pa)) + - (kk * (nr * nr * dsh - nr * nr * dsx)))
      by (unfold th, Rr, kk; rewrite <- Hs; field; lra).
    eapply Rle_trans; [apply tri4|]. rewrite !Rabs_Ropp.
    pose proof (ad_sc th _ 1 _ Hth HR). pose proof (ad_sc th _ 1 _ Hth Hpbc).
    pose proof (ad_sc th _ 1 _ Hth Hpac). pose proof (ad_sc kk _ (1 / 8) _ Hk Hds).
    unfold EC. lra. }
  assert (Hdsh : Rabs (nr * nr * dsh) <= 2 + Eds) by (pose proof (abs_near _ _ _ Hds); lra).
  assert (MBb : Rabs (j * t0h) <= MB).
  { assert (E1 : j * t0h = th * (nr * t0h)) by (unfold th; field; lra).
    assert (E2 : nr * (nr - 1) / 2 * dsh = (nr - 1) / (2 * nr) * (nr * nr * dsh)) by (field; lra).
    assert (H3 : 0 <= (nr - 1) / (2 * nr) <= 1 / 2).
    { pose proof (theta_rng nr (nr - 1) ltac:(lra) ltac:(lra)).
      replace ((nr - 1) / (2 * nr)) with ((nr - 1) / nr / 2) by (field; lra). lra. }
    assert (H4 : Rabs (nr * (nr - 1) / 2 * dsh) <= 1 / 2 * (2 + Eds))
      by (rewrite E2; apply ad_sc; lra).
    assert (H5 : Rabs (nr * t0h) <= MB).
    { replace (nr * t0h)
        with (Rr + (pbc - pb) + - (pac - pa) + (pb - pa) + - (nr * (nr - 1) / 2 * dsh))
        by (unfold Rr; ring).
      eapply Rle_trans; [apply tri5|]. rewrite !Rabs_Ropp.
      pose proof (absdiff pb pa). unfold MB. lra. }
    rewrite E1. pose proof (ad_sc th _ 1 _ Hth H5). lra. }
  assert (MCb : Rabs ((j * j - j) / 2 * dsh) <= MC).
  { replace ((j * j - j) / 2 * dsh) with (kc * (nr * nr * dsh)) by (unfold kc; field; lra).
    pose proof (ad_sc kc _ (1 / 2) _ Hkc Hdsh). unfold MC. lra. }
  pose proof (ad_ap1_abs _ _ _ _ _ Hv Aa MAb) as Ra.
  pose proof (ad_ap1_abs _ _ _ _ _ Hv Ab MBb) as Rb.
  pose proof (ad_ap1_abs _ _ _ _ _ Hv Ac MCb) as Rc.
  assert (Sbc : Rabs (b + c) <= MB + MC + (v * MB + eta) + (v * MC + eta)).
  { pose proof (abs_near _ _ _ Rb). pose proof (abs_near _ _ _ Rc).
    eapply Rle_trans; [apply Rabs_triang|]. lra. }
  pose proof (ad_ap1_abs _ _ _ _ _ Hv Ae Sbc) as Re.
  assert (Hdl : Rabs (dsx / 2 * j * lo) <= 1 / 4).
  { replace (dsx / 2 * j * lo) with (kk * (nr * nr * dsx)) by (unfold kk; field; lra).
    pose proof (ad_sc kk _ (1 / 8) _ Hk Hdx). lra. }
  assert (Fin : forall E, Rabs ((a - e) - dsx / 2 * j * lo) <= E ->
                Rabs (dh - dsx / 2 * j * lo) <= E + v * (1 / 4 + E) + eta).
  { intros E F4. pose proof (abs_near _ _ _ F4) as Hae.
    assert (Hae' : Rabs (a - e) <= 1 / 4 + E) by lra.
    pose proof (ad_ap1_abs _ _ _ _ _ Hv Adh Hae').
    replace (dh - dsx / 2 * j * lo) with ((dh - (a - e)) + ((a - e) - dsx / 2 * j * lo)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra. }
  split.
  - assert (F4 : Rabs ((a - e) - dsx / 2 * j * lo) <= E4).
    { replace ((a - e) - dsx / 2 * j * lo)
        with ((a - j * dph) + (j * dph - th * (pb - pa))
              + - (e - (b + c)) + - (b - j * t0h) + - (c - (j * j - j) / 2 * dsh)
              + - (j * t0h + (j * j - j) / 2 * dsh - (th * (pb - pa) - dsx / 2 * j * lo))) by ring.
      eapply Rle_trans; [apply tri6|]. rewrite !Rabs_Ropp.
      unfold E4. lra. }
    exact (Fin E4 F4).
  - intros Sa Sb.
    assert (GC : Rabs (j * dph - (j * t0h + (j * j - j) / 2 * dsh) - dsx / 2 * j * lo) <= EGC).
    { replace (j * dph - (j * t0h + (j * j - j) / 2 * dsh) - dsx / 2 * j * lo)
        with (th * (nr * dph - (pbg - pag)) + - (th * Rr) + kk * (nr * nr * dsh - nr * nr * dsx))
        by (unfold th, Rr, kk; rewrite Sa, Sb; rewrite <- Hs; field; lra).
      eapply Rle_trans; [apply tri3|]. rewrite Rabs_Ropp.
      pose proof (ad_sc th _ 1 _ Hth Hdp). pose proof (ad_sc th _ 1 _ Hth HR).
      pose proof (ad_sc kk _ (1 / 8) _ Hk Hds). unfold EGC. lra. }
    assert (F4 : Rabs ((a - e) - dsx / 2 * j * lo) <= E4s).
    { replace ((a - e) - dsx / 2 * j * lo)
        with ((a - j * dph) + (j * dph - (j * t0h + (j * j - j) / 2 * dsh) - dsx / 2 * j * lo)
              + - (e - (b + c)) + - (b - j * t0h) + - (c - (j * j - j) / 2 * dsh)) by ring.
      eapply Rle_trans; [apply tri5|]. rewrite !Rabs_Ropp.
      unfold E4s. lra. }
    exact (Fin E4s F4).
Qed.

(** An operation of factor k <= K1 is within the unit K1 u. *)
Lemma ad_K1 : forall (M : fmodel) (k K1 y x : R), 0 < m_u M -> k <= K1 ->
  approx k (m_u M) (m_eta M) y x -> ap1 (K1 * m_u M) (m_eta M) y x.
Proof. intros M k K1 y x Hu Hk H. eapply ap1_mono; [|exact H]. apply Rmult_le_compat_r; lra. Qed.

(** ** The set-up facts used (Profiles.v, sections Gouraud and CE) *)

Lemma ad_ce_facts : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (F : fsetup),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 ->
  ce_setup_ok M s F ->
  let v := K1 * m_u M in let d := k_div M * m_u M in
  Rabs (fs_pa F - pa s) <= 5002 / 1000 * v + 1 / 1000 * d
  /\ Rabs (fs_pb F - pb s) <= 5002 / 1000 * v + 1 / 1000 * d
  /\ Rabs (INR (n s) * fs_t0 F - (fs_pb F - fs_pa F - INR (n s) * (INR (n s) - 1) / 2 * fs_ds F))
     <= 2004 / 100 * v + 501 / 100 * d
  /\ Rabs (INR (n s) * INR (n s) * fs_ds F - e_n2ds s) <= 9211 / 100 * v + 1806 / 100 * d.
Proof.
  intros M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s F Ha Hb Hl Hn1 Hn2 HF v0 d0. unfold v0, d0.
  assert (Cds : Rabs (INR (n s) * INR (n s) * fs_ds F - e_n2ds s)
                <= 9211 / 100 * (K1 * m_u M) + 1806 / 100 * (k_div M * m_u M))
    by (apply ce_setup_eu in HF; eu_core K_ds; exact R0).
  ce_core K_R.
  split; [|split; [|split]]; [| | exact R0 | exact Cds].
  - exact (K_pa _ _ _ Hv Hdv s Ha Hb Hl _ _ _
             (VK _ _ Ina) (VK _ _ Inl) (FK _ _ _ Hpa)).
  - exact (K_pb _ _ _ Hv Hdv s Ha Hb Hl _ _ _
             (VK _ _ Inb) (VK _ _ Inl) (FK _ _ _ Hpb)).
Qed.

(** j = ⌈n/2⌉ (m_step), lo = ⌊n/2⌋: j + lo = n, and the exact δ. *)
Lemma ad_j_lo : forall m : nat, (1 <= m)%nat ->
  1 <= INR (m_step m) /\ 0 <= INR (m / 2) /\ INR (m_step m) + INR (m / 2) = INR m.
Proof.
  intros m Hm. destruct (m_step_half m) as (H1 & H2 & H3).
  split; [|split]; [apply (le_INR 1); lia | apply pos_INR | rewrite <- plus_INR; f_equal; lia].
Qed.

Lemma ad_delta_exact : forall s : span, (1 <= n s)%nat ->
  gouraud s (m_step (n s)) - ceuler s (m_step (n s))
  = ds s / 2 * INR (m_step (n s)) * INR (n s / 2)
  /\ INR (n s) * INR (n s) * ds s = e_n2ds s.
Proof.
  intros s Hn. destruct (ad_j_lo (n s) Hn) as (H1 & H2 & H3).
  split.
  - rewrite (eq_24_gouraud_minus_corrected_euler s _ ltac:(lia)).
    replace (INR (n s) - INR (m_step (n s))) with (INR (n s / 2)) by lra. reflexivity.
  - rewrite (ds_scaled s Hn). field. lra.
Qed.

(** ** The two implementations, in the κ model *)

(** (i) The fast kernel: ds·lo·hi/2 by three products (each ap_mul) applied
    to ds in a chain with exact factors c1 c2 c3 = hi·lo/2:
    fl(fl(fl(0.5·ds)·lo)·hi) is c1 = 1/2, c2 = lo, c3 = hi; any other
    association of the products of 0.5, ds, lo, hi is such a chain, since the
    sub-products of 0.5, lo, hi (≤ 2^23) are exact (a step that is exact,
    factor 1, satisfies ap_mul). *)
Definition fast_delta_ok (M : fmodel) (m : nat) (dsh dh : R) : Prop :=
  exists c1 c2 c3 y1 y2 : R,
    0 <= c1 /\ 0 <= c2 /\ 0 <= c3 /\ c3 <= 16777216 /\ c3 * c2 <= 281474976710656 /\
    c1 * c2 * c3 = INR (m_step m) * INR (m / 2) / 2 /\
    ap_mul M y1 (c1 * dsh) /\ ap_mul M y2 (c2 * y1) /\ ap_mul M dh (c3 * y2).

(** (ii) eq. 24 as written, j = m_step m, c = (j^2 - j)/2 exact:
    a = fl(j dp), b = fl(j t0), c' = fl(c ds), e = fl(b + c'), δ̂ = fl(a - e).
    A fused multiply-add is the case of an exact product. *)
Definition eq24_delta_ok (M : fmodel) (m : nat) (dph t0h dsh dh : R) : Prop :=
  exists a b c e : R,
    ap_mul M a (INR (m_step m) * dph) /\ ap_mul M b (INR (m_step m) * t0h) /\
    ap_mul M c ((INR (m_step m) * INR (m_step m) - INR (m_step m)) / 2 * dsh) /\
    ap_add M e (b + c) /\ ap_add M dh (a - e).

(** The error bounds: v = K1 u (inputs, additions, products), d = k_div u. *)
Definition fast_delta_err (M : fmodel) (K1 : R) : R :=
  let Eds := 9211 / 100 * (K1 * m_u M) + 1806 / 100 * (k_div M * m_u M) in
  Eds / 8 + 3004 / 1000 * (K1 * m_u M) * (1 / 4 + Eds / 8) + 562949986975745 * m_eta M.

(** (ii): the exact part of the error is E0 = EG + EC, or EGC when the two
    set-ups share the computed p_a, p_b ([shared], [eq24_shared_delta_err]). *)
Definition eq24_err_of (M : fmodel) (K1 : R) (shared : bool) : R :=
  let u := m_u M in let eta := m_eta M in let v := K1 * u in let d := k_div M * u in
  let Epg := (2 * (k_in M * u) + k_mul M * u + 2 * (k_add M * u)) * (1 + / 131072) + 18 * eta in
  let Edp := (k_add M * u + k_div M * u) * (2 + / 65536) + 16777218 * eta in
  let Epc := 5002 / 1000 * v + 1 / 1000 * d in
  let ER := 2004 / 100 * v + 501 / 100 * d in
  let Eds := 9211 / 100 * v + 1806 / 100 * d in
  let EG := Edp + 2 * Epg in
  let E0 := if shared then Edp + ER + Eds / 8 else EG + (ER + 2 * Epc + Eds / 8) in
  let MA := 2 + EG in
  let MB := 3 + 2 * Epc + Eds / 2 + ER in
  let MC := 1 + Eds / 2 in
  let E4 := E0 + (v * MA + eta) + (v * MB + eta) + (v * MC + eta)
            + (v * (MB + MC + (v * MB + eta) + (v * MC + eta)) + eta) in
  E4 + v * (1 / 4 + E4) + eta.

Definition eq24_delta_err (M : fmodel) (K1 : R) : R := eq24_err_of M K1 false.

Lemma fast_delta_error : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (F : fsetup) (dh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 ->
  ce_setup_ok M s F -> fast_delta_ok M (n s) (fs_ds F) dh ->
  Rabs (dh - (gouraud s (m_step (n s)) - ceuler s (m_step (n s)))) <= fast_delta_err M K1.
Proof.
  intros M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s F dh Ha Hb Hl Hn1 Hn2 HF
    (c1 & c2 & c3 & y1 & y2 & H1 & H2 & H3 & H3b & H23 & Hc & A1 & A2 & A3).
  pose proof HM as (Hu & He0 & He2 & Ki & Ka & Km & Kd & HK0 & HK2).
  destruct (ad_ce_facts M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s F Ha Hb Hl Hn1 Hn2 HF)
    as (_ & _ & _ & Hds).
  destruct (ad_delta_exact s Hn1) as [HD Hn2ds].
  destruct (ad_j_lo (n s) Hn1) as (J1 & J2 & J3).
  rewrite HD. rewrite <- Hn2ds in Hds.
  assert (HKu : K1 * m_u M <= K * m_u M) by (apply Rmult_le_compat_r; lra).
  assert (Hv0 : 0 <= K1 * m_u M) by (apply Rmult_le_pos; lra).
  pose proof (fun y x => ad_K1 M _ K1 y x Hu Hm1) as AK.
  pose proof (ad_fast_err (K1 * m_u M) (m_eta M) (INR (n s)) (INR (m_step (n s))) (INR (n s / 2))
    (ds s) (fs_ds F) _ c1 c2 c3 y1 y2 dh ltac:(lra) He0 ltac:(lra) ltac:(lra) J2 J3
    H1 H2 H3 H3b H23 Hc Hds ltac:(rewrite Hn2ds; apply n2ds_le; assumption)
    (AK _ _ A1) (AK _ _ A2) (AK _ _ A3)) as R.
  unfold fast_delta_err. exact R.
Qed.

(** (ii) with the p_a, p_b of the two set-ups the same computed values. *)
Definition eq24_shared_delta_err (M : fmodel) (K1 : R) : R := eq24_err_of M K1 true.

(** ** Eq. 24 at either middle step

    An implementation computing the step from eq. 23 in floats,
    step = ⌊m̂⌋ + 1, m̂ = fl((dp − t0)/ds), may, for odd n (exact m̂ = (n−1)/2 an
    integer), get m̂ just below (n−1)/2 and use j = (n−1)/2 = ⌊n/2⌋ = n − ⌈n/2⌉
    instead of ⌈n/2⌉.  The exact δ is the same at both steps (δ(j) = ds/2·j(n−j)
    is symmetric), and the coefficients j, (j²−j)/2 are no larger at the smaller
    step, so the same error bounds hold.  [eq24_delta_ok_at M m j] is
    [eq24_delta_ok M m] at the step j. *)
Definition eq24_delta_ok_at (M : fmodel) (m j : nat) (dph t0h dsh dh : R) : Prop :=
  exists a b c e : R,
    ap_mul M a (INR j * dph) /\ ap_mul M b (INR j * t0h) /\
    ap_mul M c ((INR j * INR j - INR j) / 2 * dsh) /\
    ap_add M e (b + c) /\ ap_add M dh (a - e).

Lemma m_sub_m_step : forall m : nat, (m - m_step m = m / 2)%nat.
Proof.
  intros m. destruct m as [|m']; [reflexivity|].
  destruct (ad_j_lo (S m') ltac:(lia)) as (_ & _ & H).
  rewrite <- plus_INR in H. apply INR_eq in H. lia.
Qed.

(** j ∈ {⌈m/2⌉, ⌊m/2⌋}, lo = m − j: the conditions of [ad_eq24_err], and
    j·lo = ⌈m/2⌉·⌊m/2⌋. *)
Lemma ad_j_lo_at : forall m j : nat, (1 <= m)%nat ->
  (j = m_step m \/ j = (m - m_step m)%nat) ->
  0 <= INR j /\ 0 <= INR j * INR j - INR j /\ 0 <= INR (m - j)
  /\ INR j + INR (m - j) = INR m
  /\ INR j * INR (m - j) = INR (m_step m) * INR (m / 2).
Proof.
  intros m j Hm Hj.
  destruct (ad_j_lo m Hm) as (_ & _ & H).
  rewrite <- plus_INR in H. apply INR_eq in H.
  assert (Hjm : (j <= m)%nat) by (rewrite (m_sub_m_step m) in Hj; lia).
  assert (Hjj : 0 <= INR j * INR j - INR j).
  { destruct (Nat.eq_0_gt_0_cases j) as [H0 | H0].
    - subst j. simpl. lra.
    - apply (le_INR 1) in H0. simpl in H0. nra. }
  split; [apply pos_INR|]. split; [exact Hjj|]. split; [apply pos_INR|]. split.
  - rewrite <- plus_INR. f_equal. lia.
  - rewrite (m_sub_m_step m) in Hj. destruct Hj as [Hj | Hj].
    + replace (m - j)%nat with (m / 2)%nat by lia. rewrite Hj. reflexivity.
    + replace (m - j)%nat with (m_step m) by lia. rewrite Hj. ring.
Qed.

(** The exact δ, by the symmetry of δ(j) = ds/2·j(n−j). *)
Lemma ad_delta_exact_at : forall (s : span) (j : nat), (1 <= n s)%nat ->
  (j = m_step (n s) \/ j = (n s - m_step (n s))%nat) ->
  gouraud s (m_step (n s)) - ceuler s (m_step (n s)) = ds s / 2 * INR j * INR (n s - j).
Proof.
  intros s j Hn Hj.
  destruct (ad_delta_exact s Hn) as [HD _].
  destruct (ad_j_lo_at (n s) j Hn Hj) as (_ & _ & _ & _ & Hp).
  rewrite HD.
  replace (ds s / 2 * INR j * INR (n s - j)) with (ds s / 2 * (INR j * INR (n s - j))) by ring.
  rewrite Hp. ring.
Qed.

(** Both bounds of [ad_eq24_err] at a middle step j: any set-ups, and set-ups
    sharing p_a, p_b. *)
Lemma eq24_delta_error_at : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (FG FC : fsetup) (j : nat) (dh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 ->
  (j = m_step (n s) \/ j = (n s - m_step (n s))%nat) ->
  gouraud_setup_ok M s FG -> ce_setup_ok M s FC ->
  eq24_delta_ok_at M (n s) j (fs_dp FG) (fs_t0 FC) (fs_ds FC) dh ->
  Rabs (dh - (gouraud s (m_step (n s)) - ceuler s (m_step (n s)))) <= eq24_delta_err M K1 /\
  (fs_pa FG = fs_pa FC -> fs_pb FG = fs_pb FC ->
   Rabs (dh - (gouraud s (m_step (n s)) - ceuler s (m_step (n s)))) <= eq24_shared_delta_err M K1).
Proof.
  intros M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s FG FC j dh Ha Hb Hl Hn1 Hn2 Hj HFG HFC
    (a & b & c & e & Aa & Ab & Ac & Ae & Adh).
  pose proof HM as (Hu & He0 & He2 & Ki & Ka & Km & Kd & HK0 & HK2).
  destruct (ad_ce_facts M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s FC Ha Hb Hl Hn1 Hn2 HFC)
    as (Cpa & Cpb & CR & Cds).
  destruct (g_pa_pb M K HM s Ha Hb Hl FG HFG) as [Gpa Gpb].
  pose proof (g_dp M K HM s Ha Hb Hl Hn1 Hn2 FG HFG) as Gdp.
  destruct (ad_delta_exact s Hn1) as [_ Hn2ds].
  destruct (ad_j_lo_at (n s) j Hn1 Hj) as (J0 & Jjj & J2 & J3 & _).
  rewrite (ad_delta_exact_at s j Hn1 Hj). rewrite <- Hn2ds in Cds.
  assert (Hnr : 1 <= INR (n s)) by (apply (le_INR 1) in Hn1; simpl in Hn1; lra).
  assert (HKu : K1 * m_u M <= K * m_u M) by (apply Rmult_le_compat_r; lra).
  assert (Hv0 : 0 <= K1 * m_u M) by (apply Rmult_le_pos; lra).
  pose proof (fun y x => ad_K1 M _ K1 y x Hu Hm1) as AM.
  pose proof (fun y x => ad_K1 M _ K1 y x Hu Ha1) as AA.
  exact (ad_eq24_err (K1 * m_u M) (m_eta M) (INR (n s)) (INR j) (INR (n s - j))
    (pa s) (pb s) (ds s) (fs_pa FG) (fs_pb FG) (fs_dp FG) (fs_pa FC) (fs_pb FC) (fs_t0 FC) (fs_ds FC)
    a b c e dh _ _ _ _ _ Hv0 He0 ltac:(lra) J0 Jjj J2 J3
    (pa_le s Ha Hl) (pb_le s Hb Hl) ltac:(rewrite Hn2ds; apply n2ds_le; assumption)
    Gpa Gpb Gdp Cpa Cpb CR Cds (AM _ _ Aa) (AM _ _ Ab) (AM _ _ Ac) (AA _ _ Ae) (AA _ _ Adh)).
Qed.

(** ** Acceptance, any model *)

(* Note: as [adaptive_acceptance_covers_computed_delta_generic], eq. 24 (ii)
   evaluated at a step j that is ⌈n/2⌉ or n − ⌈n/2⌉ = ⌊n/2⌋ (a step computed
   from eq. 23 in floats, ⌊m̂⌋ + 1, may be either for odd n); the tested δ is
   still G(⌈n/2⌉) − C(⌈n/2⌉), equal to G(j) − C(j). *)
(** The checker's acceptance set contains every run of an implementation that
    computes δ̂ by the fast kernel (i) or by eq. 24 as written (ii) at either
    middle step (with or without p_a, p_b shared by the two set-ups), provided
    the error bound of that δ̂ is at most 1.01(b_G + b_CE) + 2u. *)
Theorem adaptive_acceptance_covers_computed_delta_generic_step :
  forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (FG FC : fsetup) (j : nat) (dh x bG bCE th2 : R) (G C out : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 ->
  gouraud_setup_ok M s FG -> ce_setup_ok M s FC ->
  (fast_delta_ok M (n s) (fs_ds FC) dh
     /\ fast_delta_err M K1 <= 101 / 100 * (bG + bCE) + 2 * m_u M)
  \/ (eq24_delta_ok_at M (n s) j (fs_dp FG) (fs_t0 FC) (fs_ds FC) dh
     /\ (j = m_step (n s) \/ j = (n s - m_step (n s))%nat)
     /\ eq24_delta_err M K1 <= 101 / 100 * (bG + bCE) + 2 * m_u M)
  \/ (eq24_delta_ok_at M (n s) j (fs_dp FG) (fs_t0 FC) (fs_ds FC) dh
     /\ (j = m_step (n s) \/ j = (n s - m_step (n s))%nat)
     /\ fs_pa FG = fs_pa FC /\ fs_pb FG = fs_pb FC
     /\ eq24_shared_delta_err M K1 <= 101 / 100 * (bG + bCE) + 2 * m_u M) ->
  0 < x -> Rabs th2 <= 3 * m_u M ->
  (Rabs (x * dh * (1 + th2)) < 1 -> within_of bG out G (n s)) ->
  (1 <= Rabs (x * dh * (1 + th2)) -> within_of bCE out C (n s)) ->
  adaptive_accepts x (gouraud s (m_step (n s)) - ceuler s (m_step (n s))) bG bCE (m_u M)
    G C out (n s).
Proof.
  intros M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s FG FC j dh x bG bCE th2 G C out
    Ha Hb Hl Hn1 Hn2 HFG HFC Himpl Hx H2 Hgo Hce.
  pose proof HM as (Hu & He0 & He2 & Ki & Ka & Km & Kd & HK0 & HK2).
  assert (Hu1 : m_u M <= K * m_u M) by (rewrite <- (Rmult_1_l (m_u M)) at 1; apply Rmult_le_compat_r; lra).
  destruct Himpl as [[Hi HE] | [(Hi & Hj & HE) | (Hi & Hj & Sa & Sb & HE)]];
    (eapply (adaptive_accepts_of_delta_error x (m_u M) bG bCE _ dh _ th2); try eassumption;
     try lra).
  - exact (fast_delta_error M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s FC dh Ha Hb Hl Hn1 Hn2 HFC Hi).
  - exact (proj1 (eq24_delta_error_at M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s FG FC j dh Ha Hb Hl Hn1 Hn2 Hj
             HFG HFC Hi)).
  - exact (proj2 (eq24_delta_error_at M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s FG FC j dh Ha Hb Hl Hn1 Hn2 Hj
             HFG HFC Hi) Sa Sb).
Qed.

(* Note: Any model with the size conditions of [profile_corrected_euler_generic];
   the run's output is within b_G of Gouraud when the implementation's test
   says Gouraud and within b_CE of corrected Euler otherwise. *)
(** The checker's acceptance set contains every run of an implementation that
    computes δ̂ by the fast kernel (i) or by eq. 24 as written (ii) (with or
    without p_a, p_b shared by the two set-ups), provided
    the error bound of that δ̂ is at most 1.01(b_G + b_CE) + 2u. *)
Theorem adaptive_acceptance_covers_computed_delta_generic :
  forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (FG FC : fsetup) (dh x bG bCE th2 : R) (G C out : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 ->
  gouraud_setup_ok M s FG -> ce_setup_ok M s FC ->
  (fast_delta_ok M (n s) (fs_ds FC) dh
     /\ fast_delta_err M K1 <= 101 / 100 * (bG + bCE) + 2 * m_u M)
  \/ (eq24_delta_ok M (n s) (fs_dp FG) (fs_t0 FC) (fs_ds FC) dh
     /\ eq24_delta_err M K1 <= 101 / 100 * (bG + bCE) + 2 * m_u M)
  \/ (eq24_delta_ok M (n s) (fs_dp FG) (fs_t0 FC) (fs_ds FC) dh
     /\ fs_pa FG = fs_pa FC /\ fs_pb FG = fs_pb FC
     /\ eq24_shared_delta_err M K1 <= 101 / 100 * (bG + bCE) + 2 * m_u M) ->
  0 < x -> Rabs th2 <= 3 * m_u M ->
  (Rabs (x * dh * (1 + th2)) < 1 -> within_of bG out G (n s)) ->
  (1 <= Rabs (x * dh * (1 + th2)) -> within_of bCE out C (n s)) ->
  adaptive_accepts x (gouraud s (m_step (n s)) - ceuler s (m_step (n s))) bG bCE (m_u M)
    G C out (n s).
Proof.
  intros M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1 s FG FC dh x bG bCE th2 G C out
    Ha Hb Hl Hn1 Hn2 HFG HFC Himpl Hx H2 Hgo Hce.
  apply (adaptive_acceptance_covers_computed_delta_generic_step M K K1 HM HK1 Hi1 Ha1 Hm1 Hd1
           s FG FC (m_step (n s)) dh x bG bCE th2 G C out); try assumption.
  destruct Himpl as [H | [H | H]]; [left | right; left | right; right]; intuition.
Qed.

(** ** The ieee binary32 profile *)

(** The three error bounds at the ieee binary32 model: 17u, 83u, 63u. *)
Lemma delta_errs_ieee32 : fast_delta_err ieee32 1 <= 17 * bpow radix2 (-24)
  /\ eq24_delta_err ieee32 1 <= 83 * bpow radix2 (-24)
  /\ eq24_shared_delta_err ieee32 1 <= 63 * bpow radix2 (-24).
Proof.
  pose proof ieee32_ok as (Hu & He0 & He2 & _).
  unfold fast_delta_err, eq24_delta_err, eq24_shared_delta_err, eq24_err_of, ieee32 in *;
    cbn [m_u m_eta k_in k_add k_mul k_div] in *.
  cbv beta zeta iota. rewrite u24 in *. repeat split; lra.
Qed.

(* Note: as [adaptive_acceptance_covers_computed_delta], eq. 24 (ii) evaluated
   at a step j that is ⌈n/2⌉ or n − ⌈n/2⌉ = ⌊n/2⌋ (the step ⌊m̂⌋ + 1 of eq. 23
   computed in floats may be either for odd n); same error bounds 83u, 63u. *)
(** Adaptive scheme: the checker's acceptance set contains every run of an
    implementation computing δ̂ from its set-up by (i) or by (ii) at either
    middle step. *)
Theorem adaptive_acceptance_covers_computed_delta_step :
  forall (s : span) (FG FC : fsetup) (j : nat) (dh x bG bCE th2 : R) (G C out : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  gouraud_setup_ok ieee32 s FG -> ce_setup_ok ieee32 s FC ->
  (fast_delta_ok ieee32 (n s) (fs_ds FC) dh
     /\ 17 * bpow radix2 (-24) <= 101 / 100 * (bG + bCE) + 2 * bpow radix2 (-24))
  \/ (eq24_delta_ok_at ieee32 (n s) j (fs_dp FG) (fs_t0 FC) (fs_ds FC) dh
     /\ (j = m_step (n s) \/ j = (n s - m_step (n s))%nat)
     /\ 83 * bpow radix2 (-24) <= 101 / 100 * (bG + bCE) + 2 * bpow radix2 (-24))
  \/ (eq24_delta_ok_at ieee32 (n s) j (fs_dp FG) (fs_t0 FC) (fs_ds FC) dh
     /\ (j = m_step (n s) \/ j = (n s - m_step (n s))%nat)
     /\ fs_pa FG = fs_pa FC /\ fs_pb FG = fs_pb FC
     /\ 63 * bpow radix2 (-24) <= 101 / 100 * (bG + bCE) + 2 * bpow radix2 (-24)) ->
  0 < x -> Rabs th2 <= 3 * bpow radix2 (-24) ->
  (Rabs (x * dh * (1 + th2)) < 1 -> within_of bG out G (n s)) ->
  (1 <= Rabs (x * dh * (1 + th2)) -> within_of bCE out C (n s)) ->
  adaptive_accepts x (gouraud s (m_step (n s)) - ceuler s (m_step (n s))) bG bCE
    (bpow radix2 (-24)) G C out (n s).
Proof.
  intros s FG FC j dh x bG bCE th2 G C out Ha Hb Hl Hn HFG HFC Himpl Hx H2 Hgo Hce.
  pose proof (ce_profile_nr s Hn) as Hn'.
  pose proof delta_errs_ieee32 as (E1 & E2 & E3).
  change (bpow radix2 (-24)) with (m_u ieee32) in *.
  apply (adaptive_acceptance_covers_computed_delta_generic_step ieee32 _ 1 ieee32_ok)
    with (FG := FG) (FC := FC) (j := j) (dh := dh) (th2 := th2);
    unfold ieee32 in *; cbn [m_u k_in k_add k_mul k_div] in *; try assumption; try lra; try lia.
  destruct Himpl as [H | [H | H]]; [left | right; left | right; right]; intuition lra.
Qed.

(* Note: ieee profile, binary32 (round to nearest, division correctly rounded or
   reciprocal then product, subnormals kept), 1 <= n <= 4096; the set-ups as in
   profile_ieee_gouraud_binary32 (dp) and profile_ieee_corrected_euler_binary32
   (t0, ds); δ̂ by the fast kernel (i), error <= 17u, or by eq. 24 as written
   (ii), error <= 83u, or <= 63u when both set-ups use the same computed p_a, p_b; test t̂ = x δ̂ (1 + θ2), |θ2| <= 3u. *)
(** Adaptive scheme: the checker's acceptance set (band x(1.01(b_G + b_CE) + 2u) + 4u
    around |x δ| = 1, δ = G(j) - C(j) exact) contains every run of an
    implementation computing δ̂ from its set-up by (i) or (ii). *)
Theorem adaptive_acceptance_covers_computed_delta :
  forall (s : span) (FG FC : fsetup) (dh x bG bCE th2 : R) (G C out : nat -> R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) -> (1 <= n s <= 4096)%nat ->
  gouraud_setup_ok ieee32 s FG -> ce_setup_ok ieee32 s FC ->
  (fast_delta_ok ieee32 (n s) (fs_ds FC) dh
     /\ 17 * bpow radix2 (-24) <= 101 / 100 * (bG + bCE) + 2 * bpow radix2 (-24))
  \/ (eq24_delta_ok ieee32 (n s) (fs_dp FG) (fs_t0 FC) (fs_ds FC) dh
     /\ 83 * bpow radix2 (-24) <= 101 / 100 * (bG + bCE) + 2 * bpow radix2 (-24))
  \/ (eq24_delta_ok ieee32 (n s) (fs_dp FG) (fs_t0 FC) (fs_ds FC) dh
     /\ fs_pa FG = fs_pa FC /\ fs_pb FG = fs_pb FC
     /\ 63 * bpow radix2 (-24) <= 101 / 100 * (bG + bCE) + 2 * bpow radix2 (-24)) ->
  0 < x -> Rabs th2 <= 3 * bpow radix2 (-24) ->
  (Rabs (x * dh * (1 + th2)) < 1 -> within_of bG out G (n s)) ->
  (1 <= Rabs (x * dh * (1 + th2)) -> within_of bCE out C (n s)) ->
  adaptive_accepts x (gouraud s (m_step (n s)) - ceuler s (m_step (n s))) bG bCE
    (bpow radix2 (-24)) G C out (n s).
Proof.
  intros s FG FC dh x bG bCE th2 G C out Ha Hb Hl Hn HFG HFC Himpl Hx H2 Hgo Hce.
  apply (adaptive_acceptance_covers_computed_delta_step s FG FC (m_step (n s)) dh x bG bCE th2 G C out);
    try assumption.
  destruct Himpl as [H | [H | H]]; [left | right; left | right; right]; intuition.
Qed.

(* Note: u = 2^-24; b_G, b_CE at least the ieee binary32 profile bounds
   (profile_ieee_gouraud_binary32, profile_ieee_corrected_euler_binary32). *)
(** The conditions of [adaptive_acceptance_covers_computed_delta] at the profile
    bounds: (i) and (ii) with shared p_a, p_b always, (ii) otherwise for n >= 6. *)
Theorem adaptive_delta_conditions_at_profile_bounds :
  forall (m : nat) (bG bCE : R),
  (1 <= m)%nat ->
  (10006 / 10000 * INR m + 11001 / 1000) * bpow radix2 (-24) <= bG ->
  (22 / 10 * INR m + 5121 / 100) * bpow radix2 (-24) <= bCE ->
  17 * bpow radix2 (-24) <= 101 / 100 * (bG + bCE) + 2 * bpow radix2 (-24)
  /\ 63 * bpow radix2 (-24) <= 101 / 100 * (bG + bCE) + 2 * bpow radix2 (-24)
  /\ ((6 <= m)%nat ->
      83 * bpow radix2 (-24) <= 101 / 100 * (bG + bCE) + 2 * bpow radix2 (-24)).
Proof.
  intros m bG bCE Hm HG HC. rewrite u24 in *.
  assert (H1 : 1 <= INR m) by (apply (le_INR 1); exact Hm).
  split; [lra|]. split; [lra|].
  intros H6. assert (6 <= INR m) by (apply (le_INR 6) in H6; simpl in H6; lra). lra.
Qed.
