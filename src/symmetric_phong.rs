//! Phong with half the square roots, by the symmetry of the normalization (§4).
//!
//! Proved: `proofs/Symmetry.v`, `sec_4_q_is_symmetric`,
//! `sec_4_symmetric_phong_equals_phong`.
//! Tested: `tests/claims/equations.rs::sec_4_symmetric_phong_equals_phong`.

use crate::duff::Recurrence;
use crate::error::SpanError;
use crate::scalar::Real;
use crate::span::Span;

/// Fills `out[i]` with `p_i / √q_i`, computing `√q_i` only for `i ≤ ⌊n/2⌋` (walking
/// Duff's recurrence from the left edge) and reusing `√q_i = √q_{n−i}` for the
/// right half.
///
/// For unit edge normals `q(x) = q(n − x)` (§4; `dq_b = −dq_a`, eq. 22), so the
/// values equal Phong's exactly in exact arithmetic. With non-unit edge normals the
/// mirror is wrong; [`crate::span::Span::new`] only accepts unit ones.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`; [`SpanError::NotFiniteValue`]
/// where a float `q` rounds to zero (edge normals nearly opposite);
/// [`SpanError::ZeroNormal`] at the middle pixel of a span with `N_b = −N_a`, even `n`.
///
/// Claims: `sec_4_q_is_symmetric`, `sec_4_symmetric_phong_equals_phong`, `sec_4_duff_q_is_symmetric` (proofs/Symmetry.v); this function, step by step, is `sec_4_symmetric_phong_algorithm` (proofs/ClosedForms.v); tests/claims/.
pub fn shade<T: Real>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    span.check_nonzero_normal()?;
    let n = span.n as usize;
    let half = n / 2;
    let mut root = Vec::with_capacity(half + 1);
    let mut pq = Recurrence::new(span);
    for _ in 0..=half {
        root.push(pq.q.sqrt());
        pq.step();
    }
    let mut p = span.b.clone();
    for (i, o) in out.iter_mut().enumerate() {
        let r = if i <= half { &root[i] } else { &root[n - i] };
        *o = p.clone() / r.clone();
        p = p + span.a.clone();
    }
    span.check_finite(out)
}
