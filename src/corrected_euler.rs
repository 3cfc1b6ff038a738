//! Corrected Euler shading (eqs. 15–17): Euler with the edge error spread linearly,
//! so that both edges are exact.
//!
//! Proved: `proofs/Euler.v`, `eq_17_corrected_euler_starts_at_pa`,
//! `eq_17_corrected_euler_ends_at_pb`.
//! Tested: `tests/claims/equations.rs::eq_17_corrected_euler_ends_at_pb` and
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
/// Against Phong (§7), within one 8-bit level at every pixel of every span under every
/// light while the edge normals are at most 31.0° apart, half a level up to 24.6°, and
/// at most 7.83 levels at 60° (docs/derivations.md §11 has the table by angle).
///
/// Claims: `eq_16_17_corrected_is_euler_minus_linear_error`, `eq_17_corrected_euler_starts_at_pa`, `eq_17_corrected_euler_ends_at_pb` (proofs/Euler.v), `sec_7_corrected_euler_in_t`, `sec_7_error_sup_over_lights`, `sec_7_corrected_euler_angle_table`, `sec_7_corrected_euler_one_level` (proofs/Angle.v); tests/claims/.
pub fn shade<T: Scalar>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    crate::euler::recurrence(span.p_a.clone(), span.t0.clone(), &span.ds, out);
    Ok(())
}
