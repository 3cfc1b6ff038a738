//! Ouyang & Maynard's binary interpolation (C&G 20(6), 1996): the span is cut into
//! segments whose lengths are powers of two (largest first), the exact Phong value is
//! computed at the segment ends, and the inside of each segment is filled by
//! repeated halving, one multiplication and one addition per pixel.
//!
//! *Reconstructed*: two unit normals `U`, `V` at angle `θ` have the unit bisector
//! `(U + V) / (2 cos(θ/2))`, so `I_mid = (I_U + I_V) / (2 cos(θ/2))`, with one
//! constant factor per level, `cos(θ/2^{j+1}) = √((1 + cos(θ/2^j))/2)`.
//!
//! What that gives (tests/related.rs): the segment ends are Phong's values
//! (`binary_exact_at_ends_and_whole_span_midpoint`); every point inside a segment
//! bisects the *angle* between the segment's unit end normals, so it is the
//! spherical interpolation of [`crate::related::spherical`] between them
//! (`binary_deeper_points_are_spherical_not_phong`). That equals Phong's value only
//! at the midpoint of a segment whose ends have interpolated normals of equal length
//! — the middle of a span whose `n` is a power of two. The literature note "exact
//! Phong values at every binary subdivision point" holds at the segment ends and
//! there, nowhere else (`binary_quarter_point_is_not_phong`).

use crate::error::SpanError;
use crate::scalar::Real;
use crate::span::Span;

/// The segment boundaries of a span of `n` steps: `0 = b_0 < b_1 < … = n`, each
/// `b_{j+1} − b_j` a power of two, largest first (the binary digits of `n`).
pub fn segments(n: u32) -> Vec<u32> {
    let mut b = vec![0];
    let mut at = 0;
    for bit in (0..32).rev() {
        if n & (1 << bit) != 0 {
            at += 1 << bit;
            b.push(at);
        }
    }
    b
}

/// The exact Phong value `p/√q` at pixel `i` and `N(i)·N(j)/(|N(i)||N(j)|)`.
fn phong_at<T: Real>(span: &Span<T>, i: u32) -> T {
    span.p_at(i) / span.q_at(i).sqrt()
}

fn cos_between<T: Real>(span: &Span<T>, i: u32, j: u32) -> T {
    // N(i)·N(j) = E + (i + j)·D/2 + i·j·C.
    let two = T::from_i64(2);
    let (fi, fj) = (T::from_i64(i64::from(i)), T::from_i64(i64::from(j)));
    let dot = span.e.clone()
        + (fi.clone() + fj.clone()) * span.d.clone() / two
        + fi * fj * span.c.clone();
    let c = dot / (span.q_at(i) * span.q_at(j)).sqrt();
    if c > T::one() {
        T::one()
    } else {
        c
    }
}

/// Fills `out` by binary interpolation.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
pub fn shade<T: Real>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    if span.is_opposite() {
        return Err(SpanError::Opposite);
    }
    let bounds = segments(span.n);
    out[0] = phong_at(span, 0);
    let half = T::one() / T::from_i64(2);
    for w in bounds.windows(2) {
        let (a, b) = (w[0], w[1]);
        out[b as usize] = phong_at(span, b);
        let mut c = cos_between(span, a, b);
        let mut step = b - a;
        while step > 1 {
            // cos of half the current angle, and the level's factor 1/(2 cos(θ/2)).
            let h = half.clone() * (T::one() + c.clone());
            c = if h > T::zero() { h.sqrt() } else { T::zero() };
            // c = 0 only where rounding (or an approximate square root) took the
            // angle to 180°, which the span is not (it is not opposite): no factor is
            // right there, and 0 keeps the values finite; an exact run's accounting
            // (`Method::exact_bits`, which loses log2(1/sin²Ω) bits) refuses them.
            let factor = if c > T::zero() {
                half.clone() / c.clone()
            } else {
                T::zero()
            };
            let half_step = step / 2;
            let mut m = a + half_step;
            while m < b {
                let (lo, hi) = ((m - half_step) as usize, (m + half_step) as usize);
                out[m as usize] = (out[lo].clone() + out[hi].clone()) * factor.clone();
                m += step;
            }
            step = half_step;
        }
    }
    Ok(())
}
