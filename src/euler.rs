//! Euler shading (eqs. 12–13): the derivative of `p/√q` interpolated linearly
//! between its edge values and integrated one pixel at a time.
//!
//! Proved: `proofs/Euler.v`, `eq_14_euler_closed_form`.
//! Tested: `tests/claims/equations.rs::eq_14_euler_closed_form`.
//!
//! Float error, for every implementation of the `ieee` profile (any order, fused
//! multiply-adds, `/n` or `·(1/n)`; this code is one) against the exact run:
//! `(5.55·n + 121.41)·u` for the recurrence (`profile_ieee_euler_binary32`,
//! `profile_ieee_euler_binary64`, `profile_ieee_euler_binary64_large`) and `131.41·u`
//! for the closed form `p_a + i·(di_a + (i−1)/2·ds)` (`profile_ieee_euler_closed_binary32`,
//! `profile_ieee_euler_closed_binary64`, `profile_ieee_euler_closed_binary64_large`),
//! `proofs/Profiles.v`. Under `shader` (binary32, `n ≤ 4096`), with every division
//! one 2.5-ulp division or a 2.5-ulp reciprocal then a product:
//! `(11.1·n + 288.11)·2^-24` for the recurrence (`profile_shader_euler_recip_binary32`;
//! `profile_shader_euler_binary32`, `(11.1·n + 257.9)·2^-24`, for one division each),
//! `308.11·2^-24` for the closed form (`profile_shader_euler_closed_recip_binary32`,
//! `profile_shader_euler_closed_binary32`) and `313.36·2^-24` with its `(i−1)/2` halved
//! in floats (`profile_shader_euler_closed_half_recip_binary32`,
//! `profile_shader_euler_closed_half_binary32`); `check` applies the largest
//! ([`crate::tolerance::profile::proved`]).

use crate::error::SpanError;
use crate::scalar::Scalar;
use crate::span::Span;

/// Fills `out[i]` with `p_i` of the recurrence `p_{i+1} = p_i + s_i` (eq. 12),
/// `s_{i+1} = s_i + ds` (eq. 13), `p_0 = p_a`, `s_0 = di_a`. Two additions per pixel.
///
/// Starts exactly at `p_a` but ends at `p_n = p_a + n·di_a + (n² − n)/2·ds`
/// (eq. 14), not at `p_b`: the error `ε = p_n − p_b` is what
/// [`crate::corrected_euler`] removes.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
///
/// Against Phong, at most `1 − N_a·N_b` off, reached on one-step spans (one 8-bit level
/// up to θ = 5.07°).
///
/// Claims: `eq_13_slope_closed_form`, `eq_14_euler_closed_form` (proofs/Euler.v), `eq_14_euler_sum_of_slopes` (proofs/ClosedForms.v), `sec_7_euler_in_t`, `sec_7_euler_angle_bound` (proofs/Angle.v); tests/claims/.
pub fn shade<T: Scalar>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    recurrence(span.p_a.clone(), span.di_a.clone(), &span.ds, out);
    Ok(())
}

/// `p_{i+1} = p_i + s_i`, `s_{i+1} = s_i + ds` from `(p_0, s_0)`, written to `out`.
/// Shared by Euler (`s_0 = di_a`) and corrected Euler (`s_0 = t_0`).
pub(crate) fn recurrence<T: Scalar>(mut p: T, mut s: T, ds: &T, out: &mut [T]) {
    for o in out.iter_mut() {
        *o = p.clone();
        p.add_assign_ref(&s);
        s.add_assign_ref(ds);
    }
}
