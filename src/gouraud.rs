//! Gouraud (fence) shading along the span: linear between the exact edge values.
//!
//! Tested: `tests/claims/equations.rs::eq_24_gouraud_minus_corrected_euler`.

use crate::error::SpanError;
use crate::scalar::Scalar;
use crate::span::Span;

/// Fills `out[i]` with the forward difference `g_0 = p_a`, `g_{i+1} = g_i + dp`,
/// `dp = (p_b − p_a)/n`: the intensity interpolated linearly between the exact edge
/// values (fence shading, Behrens; the span part of Gouraud). One addition per pixel.
///
/// Classic vertex Gouraud differs in where the edge values come from (intensities
/// interpolated along the polygon's edges instead of normals): that is the
/// rasterizer's business, not the span's.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
///
/// Against Phong, at most `1 − cos(θ/2)` off for edge normals `θ` apart (one 8-bit level
/// up to θ = 10.15°).
///
/// Claims: `eq_24_gouraud_minus_corrected_euler` (proofs/Adaptive.v), `sec_7_gouraud_in_t`,
/// `sec_7_gouraud_angle_bound`, `sec_7_error_sup_over_lights` (proofs/Angle.v); tests/claims/.
pub fn shade<T: Scalar>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    let mut g = span.p_a.clone();
    for o in out.iter_mut() {
        *o = g.clone();
        g.add_assign_ref(&span.dp);
    }
    Ok(())
}
