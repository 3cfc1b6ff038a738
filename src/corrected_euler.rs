//! Corrected Euler shading (eqs. 15–17): Euler with the edge error spread linearly,
//! so that both edges are exact.
//!
//! Proved: `proofs/Euler.v`, `eq_17_corrected_euler_starts_at_pa`,
//! `eq_17_corrected_euler_ends_at_pb`.
//! Tested: `tests/claims.rs::eq_17_corrected_euler_ends_at_pb` and
//! `tests/float_bounds.rs::corrected_euler_error_bound_*`.

use crate::error::SpanError;
use crate::scalar::Scalar;
use crate::span::Span;

/// Fills `out[i]` with `p_i` of `p_{i+1} = p_i + t_i` (eq. 16),
/// `t_{i+1} = t_i + ds` (eq. 17), `p_0 = p_a`, `t_0 = di_a − dε`, `dε = ε/n`,
/// `ε = p_n − p_b` (eq. 15). Two additions per pixel.
///
/// In exact arithmetic `p_0 = p_a` and `p_n = p_b` for every `n ≥ 1`, and
/// `Gouraud_i − p_i = ds/2 · i·(n − i)` (see [`crate::adaptive`]).
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
///
/// Claims: `eq_16_17_corrected_is_euler_minus_linear_error`, `eq_17_corrected_euler_starts_at_pa`, `eq_17_corrected_euler_ends_at_pb` (proofs/Euler.v; tests/claims.rs).
pub fn shade<T: Scalar>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    crate::euler::recurrence(span.p_a.clone(), span.t0.clone(), &span.ds, out);
    Ok(())
}
