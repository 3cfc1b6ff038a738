//! Duff's forward differences for `p/√q` along the scan line (eqs. 5–7).
//!
//! Proved: `proofs/Duff.v`, `eq_5_7_duff_recurrence_exact`.
//! Tested: `tests/claims/equations.rs::eq_5_7_duff_recurrence_exact`.

use crate::error::SpanError;
use crate::scalar::{Real, Scalar};
use crate::span::Span;

/// Fills `out[i]` with `p_i/√q_i`, where `p` and `q` follow Duff's recurrence:
///
/// `p_{i+1} = p_i + dp` (eq. 5), `q_{i+1} = q_i + dq_i` (eq. 6),
/// `dq_{i+1} = dq_i + d²q` (eq. 7), with `p_0 = B`, `dp = A`, `q_0 = E`,
/// `dq_0 = C + D`, `d²q = 2C`.
///
/// In exact arithmetic `p_i = A·i + B` and `q_i = C·i² + D·i + E`, so the values are
/// Phong's (eq. 4). Three additions, one square root and one division per pixel.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`; [`SpanError::NotFiniteValue`]
/// where a float `q` rounds to zero (edge normals nearly opposite);
/// [`SpanError::ZeroNormal`] at the middle pixel of a span with `N_b = −N_a`, even `n`.
///
/// Claims: `eq_5_7_duff_computes_phong` (proofs/Duff.v; tests/claims/).
pub fn shade<T: Real>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    span.check_nonzero_normal()?;
    let mut pq = Recurrence::new(span);
    for o in out.iter_mut() {
        *o = pq.p.clone() / pq.q.sqrt();
        pq.step();
    }
    span.check_finite(out)
}

/// The state of Duff's recurrence (eqs. 5–7): `p_i`, `q_i`, `dq_i`.
#[derive(Clone, Debug)]
///
/// Claims: `eq_5_7_duff_recurrence_exact`, `sec_4_dq_zero_at_middle` (proofs/Duff.v, proofs/Symmetry.v; tests/claims/).
pub struct Recurrence<T> {
    /// `p_i`.
    pub p: T,
    /// `q_i`.
    pub q: T,
    /// `dq_i = q_{i+1} − q_i`.
    pub dq: T,
    /// `dp = A`.
    pub dp: T,
    /// `d²q = 2C`.
    pub d2q: T,
}

impl<T: Scalar> Recurrence<T> {
    /// The initial state `p_0 = B`, `q_0 = E`, `dq_0 = C + D`, `d²q = 2C` (§2.1).
    ///
    /// Claims: `eq_7_duff_dq0_and_d2q` (proofs/Duff.v; tests/claims/).
    pub fn new(span: &Span<T>) -> Self {
        Recurrence {
            p: span.b.clone(),
            q: span.e.clone(),
            dq: span.c.clone() + span.d.clone(),
            dp: span.a.clone(),
            d2q: span.c.clone() + span.c.clone(),
        }
    }

    /// One step of eqs. 5–7.
    pub fn step(&mut self) {
        self.p = self.p.clone() + self.dp.clone();
        self.q = self.q.clone() + self.dq.clone();
        self.dq = self.dq.clone() + self.d2q.clone();
    }
}
