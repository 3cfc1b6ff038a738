//! Angular interpolation along the span (the second source, Mortensen 1995): the
//! angle `α = acos(N·L)` interpolated linearly between the edges, its cosine taken
//! back per pixel, exactly or from a table.
//!
//! Proved: `proofs/Angular.v`, `mortensen_equal_angles_counterexample`,
//! `mortensen_angle_not_linear`, `mortensen_unequal_angles_counterexample` (the angle
//! does *not* change linearly along the span, so this is an approximation).
//! Tested: `tests/claims/general.rs::mortensen_equal_angles_counterexample`,
//! `tests/methods.rs`.

use crate::error::SpanError;
use crate::scalar::{Real, Scalar};
use crate::span::Span;

/// `v` clamped to `[−1, 1]` (float dot products of unit vectors can leave it).
fn clamp_unit<T: Scalar>(v: &T) -> T {
    let one = T::one();
    if *v > one {
        one
    } else if *v < -one.clone() {
        -one
    } else {
        v.clone()
    }
}

/// The edge angles `α_a = acos(p_a)`, `α_b = acos(p_b)` and the step `(α_b − α_a)/n`.
fn angles<T: Real>(span: &Span<T>) -> (T, T) {
    let alpha_a = clamp_unit(&span.p_a).acos();
    let alpha_b = clamp_unit(&span.p_b).acos();
    let d_alpha = (alpha_b - alpha_a.clone()) / span.n_s.clone();
    (alpha_a, d_alpha)
}

/// Fills `out[i]` with `cos(α_a + i·(α_b − α_a)/n)`, `α = acos(N·L)` at the edges.
///
/// Exact at both edges only: between them it follows the cosine of a linear angle,
/// while the angle between Phong's normalized interpolated normal and `L` is not
/// linear in `i` — not when the edge angles are equal
/// (`mortensen_equal_angles_counterexample`), and not even when `L` lies in the
/// plane of `N_a` and `N_b` (`mortensen_unequal_angles_counterexample`: the
/// interpolated normal does not turn at a constant angular speed). Angles run over
/// `[0°, 180°]`, so `N·L < 0` is kept.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
///
/// Claims: `mortensen_equal_angles_counterexample`, `mortensen_angle_not_linear`, `mortensen_unequal_angles_counterexample` (proofs/Angular.v; tests/claims/).
pub fn shade<T: Real>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    let (mut alpha, d_alpha) = angles(span);
    for o in out.iter_mut() {
        *o = alpha.cos();
        alpha = alpha + d_alpha.clone();
    }
    Ok(())
}

/// A cosine table over `[0°, 90°]` as the second source uses: entry `j` holds
/// `cos(j · 90°/(size − 1))`; the source's byte-sized angles give `size = 256`.
#[derive(Clone, Debug)]
pub struct CosTable<T> {
    /// `cos` at the table's angles.
    pub values: Vec<T>,
    /// `(size − 1)/(π/2)`: table index per radian.
    pub per_radian: T,
}

impl<T: Real> CosTable<T> {
    /// A table with `size ≥ 2` entries.
    ///
    /// # Errors
    /// [`SpanError::Parameter`] when `size < 2` or `size > 2^24`.
    pub fn new(size: u32) -> Result<Self, SpanError> {
        if !(2..=1 << 24).contains(&size) {
            return Err(SpanError::Parameter(format!(
                "table size must be between 2 and 16777216 (got {size})"
            )));
        }
        let last = T::from_i64(i64::from(size) - 1);
        let step = T::frac_pi_2() / last.clone();
        // The ends exactly: cos 0° = 1 and cos 90° = 0 (a computed cos(π/2) is a
        // rounding of π/2's error, not 0, in every number type).
        let values = (0..size)
            .map(|j| match j {
                0 => T::one(),
                j if j == size - 1 => T::zero(),
                j => (T::from_i64(i64::from(j)) * step.clone()).cos(),
            })
            .collect();
        Ok(CosTable {
            values,
            per_radian: last / T::frac_pi_2(),
        })
    }

    /// `cos(α)` looked up at the nearest table angle; angles past 90° (light behind
    /// the surface) give the last entry, `cos 90° = 0`, as the source's 0–90° range
    /// implies, and negative angles the first.
    pub fn lookup(&self, alpha: &T) -> T {
        self.values[self.index(&self.position(alpha))].clone()
    }

    /// The table position of the angle `alpha`: `alpha·(size − 1)/(π/2)`, whose
    /// nearest integer ([`CosTable::index`]) is the entry read.
    pub fn position(&self, alpha: &T) -> T {
        alpha.clone() * self.per_radian.clone()
    }

    /// The entry read at table position `pos`: `⌊pos + ½⌋` clamped to `0..size`.
    pub fn index(&self, pos: &T) -> usize {
        let last = self.values.len() - 1;
        let half = T::one() / T::from_i64(2);
        (pos.clone() + half).floor_i64().clamp(0, last as i64) as usize
    }
}

/// The table position ([`CosTable::position`]) of every pixel's interpolated angle, as
/// [`shade_table`] computes them: `α_a + i·(α_b − α_a)/n` times `(size − 1)/(π/2)`.
pub fn table_positions<T: Real>(span: &Span<T>, table: &CosTable<T>) -> Vec<T> {
    let (mut alpha, d_alpha) = angles(span);
    (0..span.len())
        .map(|_| {
            let pos = table.position(&alpha);
            alpha = alpha.clone() + d_alpha.clone();
            pos
        })
        .collect()
}

/// [`shade`] with the cosine read from `table` (the second source's byte table when
/// `table` has 256 entries): the angle is interpolated exactly, then rounded to the
/// nearest table angle.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
pub fn shade_table<T: Real>(
    span: &Span<T>,
    table: &CosTable<T>,
    out: &mut [T],
) -> Result<(), SpanError> {
    span.check_output(out)?;
    for (o, pos) in out.iter_mut().zip(table_positions(span, table)) {
        *o = table.values[table.index(&pos)].clone();
    }
    Ok(())
}
