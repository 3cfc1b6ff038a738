//! The adaptive test of §5 (eqs. 23–24): can this span use Gouraud instead of
//! corrected Euler?
//!
//! Proved: `proofs/Adaptive.v` (`eq_23_m_is_half_n_minus_1`,
//! `eq_24_gouraud_minus_corrected_euler`, `eq_24_delta_is_max_difference`,
//! `eq_24_delta_test_does_not_imply_same_levels`,
//! `eq_24_large_delta_implies_different_levels`).
//! Tested: `tests/claims/` under the same names.
//!
//! What is true (exactly, for any inputs): Gouraud minus corrected Euler at pixel `i`
//! is `ds/2 · i·(n − i)`; eq. 23's `m = (d_p − t_0)/ds` is always `(n − 1)/2`; the
//! step `⌊m⌋ + 1 = ⌈n/2⌉` maximizes `|Gouraud − corrected Euler|`, so eq. 24's `δ` is
//! that maximum. What is *not* true: `|δ·255·K_d| < 1` does not guarantee identical
//! 8-bit levels (two values less than one level apart can still straddle a level
//! boundary); only the converse holds, before clamping. See `docs/errata.md`.

use crate::error::SpanError;
use crate::scalar::Scalar;
use crate::span::Span;

/// Which method the test of eq. 24 picks for a span.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Choice {
    /// `|δ·255·K_d| < 1`: Gouraud.
    Gouraud,
    /// Otherwise: corrected Euler.
    CorrectedEuler,
}

impl Choice {
    /// `"gouraud"` or `"corrected-euler"`.
    pub fn name(self) -> &'static str {
        match self {
            Choice::Gouraud => "gouraud",
            Choice::CorrectedEuler => "corrected-euler",
        }
    }
}

/// The outcome of the adaptive test for one span.
#[derive(Clone, Debug, PartialEq)]
pub struct Decision<T> {
    /// Eq. 23: `m = (d_p − t_0)/ds`; `None` when `ds = 0`.
    pub m: Option<T>,
    /// The step used in eq. 24: `⌊m⌋ + 1`, clamped to `0..=n`; `None` when `ds = 0`.
    pub step: Option<u32>,
    /// Eq. 24: `δ = step·d_p − (step·t_0 + (step² − step)/2 · ds)`; 0 when `ds = 0`.
    pub delta: T,
    /// The pick: Gouraud when `|δ·255·K_d| < 1`.
    pub choice: Choice,
}

/// Evaluates eqs. 23–24 for `span` with diffuse coefficient `kd`.
///
/// When `ds = 0`, Gouraud and corrected Euler coincide exactly (their difference is
/// `ds/2 · i(n − i)`), so `m` and `step` are `None`, `δ = 0` and the choice is
/// Gouraud. In exact arithmetic `m = (n − 1)/2` always lies in `[0, n)`; float
/// rounding can move it, so the step is clamped to `0..=n` (and a non-finite `m`, from
/// a tiny `ds`, is clamped too).
///
/// Claims: `eq_23_24_paper_step_gives_delta`, `eq_24_large_delta_implies_different_clamped_levels` (proofs/ClosedForms.v); `eq_23_m_is_half_n_minus_1`, `eq_23_truncated_step_is_ceil_half`, `eq_24_delta_is_max_difference`, `eq_24_delta_test_fails_on_concrete_span`, `eq_24_large_delta_implies_different_levels` (proofs/Adaptive.v; tests/claims/).
pub fn decide<T: Scalar>(span: &Span<T>, kd: &T) -> Decision<T> {
    let ds = &span.ds;
    if ds.is_zero() {
        return Decision {
            m: None,
            step: None,
            delta: T::zero(),
            choice: Choice::Gouraud,
        };
    }
    let m = (span.dp.clone() - span.t0.clone()) / ds.clone();
    let trunc = if m.is_finite() {
        if m < T::zero() {
            -((-m.clone()).floor_i64())
        } else {
            m.floor_i64()
        }
    } else {
        i64::MAX
    };
    let step = trunc.saturating_add(1).clamp(0, i64::from(span.n)) as u32;
    let delta = delta_at(span, step);
    let level = (delta.clone() * T::from_i64(255) * kd.clone()).magnitude();
    let choice = if level < T::one() {
        Choice::Gouraud
    } else {
        Choice::CorrectedEuler
    };
    Decision {
        m: Some(m),
        step: Some(step),
        delta,
        choice,
    }
}

/// Eq. 24 at step `j`: `j·d_p − (j·t_0 + (j² − j)/2 · ds)`, the difference between
/// Gouraud and corrected Euler after `j` steps.
///
/// Proved: `eq_24_delta_closed_form` (`δ = ds/2 · j(n − j)` at `j = ⌈n/2⌉`),
/// `eq_24_delta_is_max_difference`. Tested: `tests/claims/`, same names.
///
/// With unit edge normals, at the step `⌈n/2⌉` this is `−(1 − N_a·N_b)(p_a + p_b)/8`
/// for even `n` and that times `1 − 1/n²` for odd `n`.
///
/// Claims: `eq_24_delta_closed_form` (proofs/Adaptive.v), `eq_24_delta_unit_closed_form` (proofs/ClosedForms.v); tests/claims/.
pub fn delta_at<T: Scalar>(span: &Span<T>, j: u32) -> T {
    let js = T::from_i64(i64::from(j));
    // (j² − j)/2 in 128 bits: exact for every u32 j.
    let tri =
        T::from_i64(((i128::from(j) * (i128::from(j) - 1)) / 2).min(i128::from(i64::MAX)) as i64);
    js.clone() * span.dp.clone() - (js * span.t0.clone() + tri * span.ds.clone())
}

/// Shades the span with the method [`decide`] picks, and returns the decision.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
pub fn shade<T: Scalar>(span: &Span<T>, kd: &T, out: &mut [T]) -> Result<Decision<T>, SpanError> {
    span.check_output(out)?;
    let d = decide(span, kd);
    match d.choice {
        Choice::Gouraud => crate::gouraud::shade(span, out)?,
        Choice::CorrectedEuler => crate::corrected_euler::shade(span, out)?,
    }
    Ok(d)
}
