(** * PhongCount.v — the computed p and q of Phong under the kappa model.

    §18.4 of docs/float.md, first half (PhongValue.v is the second): from the
    unit inputs Na, Nb, L read into the format ([Profiles.vap]: each component
    within k_in of the exact), n >= 1 and a pixel i <= n (exact integers),
    bounds of |p^ - p_i| and |q^ - q_i|, p_i = N_i.L, q_i = N_i.N_i,
    N_i = Na + (i/n)(Nb - Na) ([Span.p], [Span.q] at x = i), for
    - Horner's closed form ([horner_ok]): k_j = (Nb_j - Na_j) / n (a rounded
      subtraction, then one division [Profiles.kcomp_ok], or a reciprocal
      1/n and a product [krecip_ok]); A = k.L, B = Na.L, C = k.k,
      D = 2 (k.Na) (the x2 exact), E = Na.Na, each dot product in any order,
      each product rounded or fused ([fdot_ok]); p^ = (A i) + B,
      q^ = ((C i + D) i) + E, each product and sum rounded (a fused product
      is the case of an exact product);
    - the per-pixel normal ([pixel_ok]): N_j = na_j + (i k_j), then
      p^ = N.l, q^ = N.N;
    - the lerp ([lerp_ok]): t^ = i/n (one division, or i (1/n)),
      N_j = ((1 - t^) na_j) + (t^ nb_j), then p^ = N.l, q^ = N.N.
    With K1 >= 1, k_in, k_add, k_mul and kd = k_div (one division) or
    kd = (1 + 2^-20) k_mul + k_div + 2^-36 (reciprocal then product):
      Horner:            |p^ - p_i| <= (20.03 K1 + 2.02 kd) u,
                         |q^ - q_i| <= (78.11 K1 + 12.04 kd) u;
      per-pixel, lerp:   |p^ - p_i| <= (14.04 K1 + 2.04 kd) u,
                         |q^ - q_i| <= (23.06 K1 + 4.06 kd) u.
    The absolute term eta of every operation is absorbed (model_ok: eta 2^84 <= u,
    n <= 2^24).  Size conditions: model_ok M K with K1 <= K, 1 <= k_div, and for
    the reciprocal forms kd u <= 2^-21.  The set-up errors of A, B, C, D, E are
    Profiles.K_a, K_pa, K_c, K_d0 (E = K_pa on the span with L := Na).
    The relations ([horner_ok], [pixel_ok], [lerp_ok], ...) and the shared
    steps are in PhongCountD.v; the per-pixel and lerp bounds here are its
    bounds at dd = 2 (|Nb - Na| <= 2 for unit Na, Nb). *)

From Coq Require Import Reals Lra Lia.
From PhongApprox Require Import Span FloatModel Float FloatModelK Profiles PhongCountD.
Open Scope R_scope.

(** ** Horner's closed form ([PhongCountD.horner_core]: unit v for inputs, additions,
    products and d for the division) *)

(** Phong, Horner's closed form, k_j = (Nb_j - Na_j) / n with one division:
    |p^ - p_i| <= (20.03 K1 + 2.02 k_div) u, |q^ - q_i| <= (78.11 K1 + 12.04 k_div) u,
    K1 >= k_in, k_add, k_mul, K1 >= 1, k_div >= 1 (and model_ok M K, K >= K1, k_div). *)
Theorem phong_horner_div_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  kcomp_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  kcomp_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  kcomp_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  horner_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (2003 / 100 * K1 + 202 / 100 * k_div M) * m_u M /\
  Rabs (qh - q s (INR i)) <= (7811 / 100 * K1 + 1204 / 100 * k_div M) * m_u M.
Proof. kd_model horner_core. Qed.

(** The same with k_j = (Nb_j - Na_j) * r, r = 1/n a rounded division:
    k_div is replaced by kd = (1 + 2^-20) k_mul + k_div + 2^-36, kd u <= 2^-21. *)
Theorem phong_horner_recip_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  krecip_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  krecip_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  krecip_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  horner_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (2003 / 100 * K1
      + 202 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M /\
  Rabs (qh - q s (INR i)) <= (7811 / 100 * K1
      + 1204 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M.
Proof. kd_model horner_core. Qed.

(** ** The per-pixel normal and the lerp: PhongCountD.v at dd = 2 *)

(** [T] is the PhongCountD.v bound; dd = 2 >= |Nb - Na| for unit Na, Nb. *)
Ltac from_dist T :=
  intros;
  match goal with HM : model_ok ?M ?K, Ha : is_unit (Na ?s), Hb : is_unit (Nb ?s) |- _ =>
    pose proof (diff_sq _ _ Ha Hb); pose proof (model_u M K HM);
    pose proof HM as (_ & _ & _ & _ & _ & ? & ? & _ & _) end;
  eapply conj_le; [eapply T with (dd := 2); try eassumption; lra | |];
  apply Rmult_le_compat_r; lra.

(** Phong, per-pixel normal N_i = na + i k, k_j = (Nb_j - Na_j) / n with one division:
    |p^ - p_i| <= (14.04 K1 + 2.04 k_div) u, |q^ - q_i| <= (23.06 K1 + 4.06 k_div) u. *)
Theorem phong_pixel_div_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  kcomp_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  kcomp_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  kcomp_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  pixel_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1 + 204 / 100 * k_div M) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1 + 406 / 100 * k_div M) * m_u M.
Proof. from_dist phong_pixel_div_dist. Qed.

(** The same with k_j = (Nb_j - Na_j) * r, r = 1/n a rounded division. *)
Theorem phong_pixel_recip_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l kk : vec) (i : nat) (ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  krecip_ok M (INR (n s)) (vx kk) (vx na) (vx nb) ->
  krecip_ok M (INR (n s)) (vy kk) (vy na) (vy nb) ->
  krecip_ok M (INR (n s)) (vz kk) (vz na) (vz nb) ->
  pixel_ok M i na l kk ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1
      + 204 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1
      + 406 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M.
Proof. from_dist phong_pixel_recip_dist. Qed.

(** Phong, lerp N_i = ((1 - t) Na) + (t Nb), t = i/n one rounded division:
    |p^ - p_i| <= (14.04 K1 + 2.04 k_div) u, |q^ - q_i| <= (23.06 K1 + 4.06 k_div) u. *)
Theorem phong_lerp_div_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  forall (s : span) (na nb l : vec) (i : nat) (th ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  ap_div M th (INR i / INR (n s)) ->
  lerp_ok M th na nb l ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1 + 204 / 100 * k_div M) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1 + 406 / 100 * k_div M) * m_u M.
Proof. from_dist phong_lerp_div_dist. Qed.

(** The same with t = i * r, r = 1/n a rounded division. *)
Theorem phong_lerp_recip_generic : forall (M : fmodel) (K K1 : R), model_ok M K ->
  1 <= K1 <= K -> k_in M <= K1 -> k_add M <= K1 -> k_mul M <= K1 -> 1 <= k_div M ->
  ((1 + / 1048576) * k_mul M + k_div M + / 68719476736) * m_u M <= / 2097152 ->
  forall (s : span) (na nb l : vec) (i : nat) (r th ph qh : R),
  is_unit (Na s) -> is_unit (Nb s) -> is_unit (L s) ->
  (1 <= n s)%nat -> INR (n s) <= 16777216 -> (i <= n s)%nat ->
  vap M na (Na s) -> vap M nb (Nb s) -> vap M l (L s) ->
  ap_div M r (1 / INR (n s)) -> ap_mul M th (INR i * r) ->
  lerp_ok M th na nb l ph qh ->
  Rabs (ph - p s (INR i)) <= (1404 / 100 * K1
      + 204 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M /\
  Rabs (qh - q s (INR i)) <= (2306 / 100 * K1
      + 406 / 100 * ((1 + / 1048576) * k_mul M + k_div M + / 68719476736)) * m_u M.
Proof. from_dist phong_lerp_recip_dist. Qed.
