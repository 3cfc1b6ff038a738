//! Kuijk & Blake's angular interpolation of the normal (CGF 8, 1989), along one
//! span: the normal turns from `N_a` to `N_b` at a constant angular speed, and
//! `N·L` follows a sinusoid evaluated by the Chebyshev recurrence
//! `I_{k+1} = 2 cos Δ · I_k − I_{k−1}` (one multiplication and one subtraction per
//! pixel).
//!
//! *Reconstructed* along one span: `u = N_a`, `w` the unit part of `N_b` orthogonal
//! to `N_a`, `Ω = acos(N_a·N_b)`, `N(θ) = cos θ·u + sin θ·w`, `θ = iΩ/n`; then
//! `N·L = (u·L) cos θ + (w·L) sin θ = R cos(θ − φ)` with `R ≤ 1`.
//!
//! This is *not* Phong's normalized linear interpolation: the two agree at both ends
//! and, for even `n`, at the middle pixel, and differ in between
//! (`spherical_differs_from_phong_between`). The second source's angle interpolation
//! equals it when `L` lies in the plane of `N_a`, `N_b` on one side of the span
//! (`spherical_equals_angular_when_light_in_plane`).
//!
//! Claims: `spherical_recurrence_matches_closed_form`,
//! `spherical_equals_phong_at_the_middle` (proofs/Related.v; tests/related.rs);
//! `spherical_differs_from_phong_between`,
//! `spherical_equals_angular_when_light_in_plane` (tests/related.rs).

use crate::error::SpanError;
use crate::scalar::Real;
use crate::span::Span;

/// The constants of the sinusoid along `span`: `(u·L, w·L, cos Δ, sin Δ)`, with
/// `Δ = Ω/n`; `w·L = 0` and `Δ = 0` when `N_a = N_b`.
pub fn setup<T: Real>(span: &Span<T>) -> (T, T, T, T) {
    let one = T::one();
    let mut cos_omega = span.na.dot(&span.nb);
    if cos_omega > one {
        cos_omega = one.clone();
    }
    let sin2 = one.clone() - cos_omega.clone() * cos_omega.clone();
    let u_l = span.p_a.clone();
    if sin2 <= T::zero() {
        return (u_l, T::zero(), one, T::zero());
    }
    let sin_omega = sin2.sqrt();
    let w_l = (span.p_b.clone() - cos_omega.clone() * span.p_a.clone()) / sin_omega;
    let delta = cos_omega.acos() / span.n_s.clone();
    let cos_d = delta.cos();
    let s2 = one - cos_d.clone() * cos_d.clone();
    let sin_d = if s2 > T::zero() { s2.sqrt() } else { T::zero() };
    (u_l, w_l, cos_d, sin_d)
}

/// Fills `out[i]` with `N(iΩ/n)·L` by the Chebyshev recurrence, from
/// `I_0 = p_a`, `I_1 = (u·L) cos Δ + (w·L) sin Δ`.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
pub fn shade<T: Real>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    if span.is_opposite() {
        return Err(SpanError::Opposite);
    }
    let (u_l, w_l, cos_d, sin_d) = setup(span);
    let two_cos = T::from_i64(2) * cos_d.clone();
    let mut prev = u_l.clone();
    let mut cur = u_l * cos_d + w_l * sin_d;
    out[0] = prev.clone();
    for o in out.iter_mut().skip(1) {
        *o = cur.clone();
        let next = (two_cos.clone() * cur.clone() - prev).tidy();
        prev = cur;
        cur = next;
    }
    Ok(())
}

/// `N(iΩ/n)·L` evaluated directly, `(u·L) cos(iΔ) + (w·L) sin(iΔ)` (the reference for
/// the recurrence).
pub fn at<T: Real>(span: &Span<T>, i: u32) -> T {
    let one = T::one();
    let mut cos_omega = span.na.dot(&span.nb);
    if cos_omega > one {
        cos_omega = one.clone();
    }
    let sin2 = one.clone() - cos_omega.clone() * cos_omega.clone();
    if sin2 <= T::zero() {
        return span.p_a.clone();
    }
    let sin_omega = sin2.sqrt();
    let w_l = (span.p_b.clone() - cos_omega.clone() * span.p_a.clone()) / sin_omega;
    let theta = cos_omega.acos() * T::from_i64(i64::from(i)) / span.n_s.clone();
    let c = theta.cos();
    let s2 = one - c.clone() * c.clone();
    let s = if s2 > T::zero() { s2.sqrt() } else { T::zero() };
    span.p_a.clone() * c + w_l * s
}

/// `R = √((u·L)² + (w·L)²)`, the amplitude of the sinusoid (1 exactly when `L` lies
/// in the plane of `N_a` and `N_b`).
pub fn amplitude<T: Real>(span: &Span<T>) -> T {
    let (u_l, w_l, _, _) = setup(span);
    (u_l.clone() * u_l + w_l.clone() * w_l).sqrt()
}
