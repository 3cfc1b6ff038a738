//! Phong shading: the exact intensity at every pixel (eq. 4).
//!
//! Tested: `tests/claims/` (`eq_2_p_is_linear`, `eq_3_q_is_quadratic`,
//! `eq_5_7_duff_recurrence_exact`) and `tests/methods.rs`.

use crate::error::SpanError;
use crate::scalar::Real;
use crate::span::Span;

/// Fills `out[i]` with `N(i)·L / |N(i)|` (eq. 4), the interpolated normal
/// `N(i) = N_a + i·k` normalized at every pixel; `n + 1` values.
///
/// This is the reference every approximation is measured against. It is computed
/// from the interpolated vector itself, not from `p` and `q`, so that it checks them.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`; [`SpanError::NotFiniteValue`]
/// where a float `q` rounds to zero (edge normals nearly opposite);
/// [`SpanError::ZeroNormal`] at the middle pixel of a span with `N_b = −N_a`, even `n`.
///
/// Claims: `eq_4_phong_exact_on_edges` (proofs/Span.v); in closed form in `t = i/n`,
/// `sec_7_phong_in_t` (proofs/Angle.v); tests/claims/.
pub fn shade<T: Real>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    span.check_nonzero_normal()?;
    for (i, o) in out.iter_mut().enumerate() {
        let normal = span.normal_at(i as u32);
        *o = normal.dot(&span.l) / normal.length_squared().sqrt();
    }
    span.check_finite(out)
}
