(** * Euler.v — Euler shading and corrected Euler shading, paper eqs. 12-17. *)

Require Import Reals Lra Lia.
From PhongApprox Require Import Span.
Open Scope R_scope.

(** eqs. 12-13 (and 16-17 with s_0 = t_0): state (p_i, s_i);
    p_{i+1} = p_i + s_i ; s_{i+1} = s_i + ds. *)
Fixpoint euler (p0 s0 d : R) (i : nat) : R * R :=
  match i with
  | O => (p0, s0)
  | S j => let (pj, sj) := euler p0 s0 d j in (pj + sj, sj + d)
  end.

Definition euler_p (p0 s0 d : R) (i : nat) : R := fst (euler p0 s0 d i).
Definition euler_s (p0 s0 d : R) (i : nat) : R := snd (euler p0 s0 d i).

(** eq. 15 and the correction: eps = p_n - p_b, d_eps = eps / n,
    t0 = s0 - d_eps (generic in n, p_a, p_b, s0 = di_a and ds). *)
Definition corr_eps (m : nat) (pa pb s0 d : R) : R := euler_p pa s0 d m - pb.
Definition corr_t0 (m : nat) (pa pb s0 d : R) : R :=
  s0 - corr_eps m pa pb s0 d / INR m.

(** The span instances. *)
Definition euler_span (s : span) (i : nat) : R := euler_p (pa s) (dia s) (ds s) i.
Definition eps (s : span) : R := corr_eps (n s) (pa s) (pb s) (dia s) (ds s).
Definition deps (s : span) : R := eps s / INR (n s).
Definition t0 (s : span) : R := corr_t0 (n s) (pa s) (pb s) (dia s) (ds s).
Definition ceuler (s : span) (i : nat) : R := euler_p (pa s) (t0 s) (ds s) i.

Lemma euler_S : forall p0 s0 d i,
  euler_p p0 s0 d (S i) = euler_p p0 s0 d i + euler_s p0 s0 d i
  /\ euler_s p0 s0 d (S i) = euler_s p0 s0 d i + d.
Proof.
  intros. unfold euler_p, euler_s. cbn [euler].
  destruct (euler p0 s0 d i). split; reflexivity.
Qed.

(** Paper eq. 13: "s_{i+1} = s_i + ds" gives s_i = s_0 + i ds. *)
Theorem eq_13_slope_closed_form : forall (p0 s0 d : R) (i : nat),
  euler_s p0 s0 d i = s0 + INR i * d.
Proof.
  intros p0 s0 d i. induction i as [| i IH].
  - unfold euler_s. cbn. ring.
  - rewrite (proj2 (euler_S p0 s0 d i)), IH, S_INR. ring.
Qed.

(* Note: Generic in p_0, s_0, ds; every i. *)
(** Paper eq. 14: "p_n = p_a + n di_a + (n^2 - n)/2 ds" for the Euler recurrence
    (eq. 12-13), as p_i = p_0 + i s_0 + (i^2 - i)/2 ds. *)
Theorem eq_14_euler_closed_form : forall (p0 s0 d : R) (i : nat),
  euler_p p0 s0 d i = p0 + INR i * s0 + (INR i ^ 2 - INR i) / 2 * d.
Proof.
  intros p0 s0 d i. induction i as [| i IH].
  - unfold euler_p. cbn. field.
  - rewrite (proj1 (euler_S p0 s0 d i)), IH, eq_13_slope_closed_form, S_INR.
    field.
Qed.

(* Note: sum_f_R0 f m = f 0 + ... + f m; n >= 1. *)
(** Paper after eq. 14: "(1 + 2 + 3 + ... + (n-1)) ds = (n^2 - n)/2 ds". *)
Theorem eq_14_arithmetic_series : forall (m : nat) (d : R),
  (1 <= m)%nat ->
  sum_f_R0 (fun j => INR j * d) (m - 1) = (INR m ^ 2 - INR m) / 2 * d.
Proof.
  intros m d Hm. destruct m as [| m]; [lia |].
  replace (S m - 1)%nat with m by lia. induction m as [| m IH].
  - cbn [sum_f_R0]. rewrite S_INR. cbn [INR]. field.
  - cbn [sum_f_R0]. rewrite IH by lia. rewrite !S_INR. field.
Qed.

(** Paper eq. 14 on a span: p_n = p_a + n di_a + (n^2 - n)/2 ds. *)
Theorem eq_14_euler_end_value : forall s : span,
  euler_span s (n s) = pa s + INR (n s) * dia s + (INR (n s) ^ 2 - INR (n s)) / 2 * ds s.
Proof. intros s. apply eq_14_euler_closed_form. Qed.

(* Note: Any n, p_a, p_b, di_a, ds. *)
(** Paper eqs. 16-17 / Fig. 3: corrected Euler starts at p_0 = p_a. *)
Theorem eq_17_corrected_euler_starts_at_pa : forall (m : nat) (pa pb s0 d : R),
  euler_p pa (corr_t0 m pa pb s0 d) d 0 = pa.
Proof. intros. reflexivity. Qed.

(* Note: Every n >= 1 and any p_a, p_b, di_a, ds (no unit hypothesis). *)
(** Paper eqs. 15-17: "This will make sure that we will have correct values at the
    edges": corrected Euler p_n = p_b. *)
Theorem eq_17_corrected_euler_ends_at_pb : forall (m : nat) (pa pb s0 d : R),
  (0 < m)%nat -> euler_p pa (corr_t0 m pa pb s0 d) d m = pb.
Proof.
  intros m pa pb s0 d Hm.
  assert (Hm' : INR m <> 0) by (apply not_0_INR; lia).
  unfold corr_t0, corr_eps. rewrite !eq_14_euler_closed_form. field. exact Hm'.
Qed.

(* Note: Any i, n, p_a, p_b, di_a, ds. *)
(** Paper §3.1: corrected Euler is Euler minus the linearly interpolated error,
    p_i - i d_eps with d_eps = eps/n. *)
Theorem eq_16_17_corrected_is_euler_minus_linear_error :
  forall (m : nat) (pa pb s0 d : R) (i : nat),
  euler_p pa (corr_t0 m pa pb s0 d) d i
  = euler_p pa s0 d i - INR i * (corr_eps m pa pb s0 d / INR m).
Proof.
  intros. unfold corr_t0. rewrite !eq_14_euler_closed_form. ring.
Qed.

(** Span corollaries. *)
Lemma ceuler_closed_form : forall s i,
  ceuler s i = pa s + INR i * t0 s + (INR i ^ 2 - INR i) / 2 * ds s.
Proof. intros. apply eq_14_euler_closed_form. Qed.

Lemma t0_closed_form : forall s, (0 < n s)%nat ->
  t0 s = (pb s - pa s) / INR (n s) - (INR (n s) - 1) / 2 * ds s.
Proof.
  intros s Hn. pose proof (INR_n_neq_0 s Hn) as Hm'.
  unfold t0, corr_t0, corr_eps. rewrite eq_14_euler_closed_form. field. exact Hm'.
Qed.

(* Note: Span Na = (3/5,0,4/5), Nb = (-3/5,0,4/5), L = (0,0,1), n = 2 (unit normals):
   di_a = 36/125, ds = -36/125, p_2 = 4/5 + 36/125 <> 4/5 = p_b, eps = 36/125. *)
(** Paper §3.1 / Fig. 2: "we will end up with another value for p_n than p_b"
    (eq. 15: eps = p_n - p_b is nonzero in general). *)
Theorem eq_15_euler_misses_pb :
  let s := mortensen_span in
  is_unit (Na s) /\ is_unit (Nb s)
  /\ dia s = 36/125 /\ ds s = -36/125
  /\ euler_span s (n s) = 4/5 + 36/125 /\ pb s = 4/5
  /\ eps s = 36/125 /\ euler_span s (n s) <> pb s.
Proof.
  cbv zeta.
  assert (Hpa : pa mortensen_span = 4/5) by span_val mortensen_span.
  assert (Hpb : pb mortensen_span = 4/5) by span_val mortensen_span.
  assert (Hdia : dia mortensen_span = 36/125) by span_val mortensen_span.
  assert (Hds : ds mortensen_span = -36/125) by span_val mortensen_span.
  assert (He : euler_span mortensen_span (n mortensen_span) = 4/5 + 36/125).
  { rewrite eq_14_euler_end_value, Hpa, Hdia, Hds. cbn [n mortensen_span].
    rewrite INR_2. field. }
  assert (Heps : eps mortensen_span = 36/125).
  { unfold eps, corr_eps. fold (euler_span mortensen_span (n mortensen_span)).
    rewrite He, Hpb. field. }
  repeat split; try assumption; [span_val mortensen_span.. |]. rewrite He, Hpb. lra.
Qed.
