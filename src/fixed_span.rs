//! Gouraud and corrected Euler in integer fixed point, the way a hardware span unit
//! runs them: the set-up (`p_a`, `t_0`, `ds`, `dp`) rounded once to `f` fractional
//! bits, then the loop in integer additions, which are exact.
//!
//! Because the loop adds exactly, its error is the set-up's rounding carried along
//! the span: at most `2^-(f+1)·(1 + i + i(i − 1)/2)` at pixel `i` for corrected
//! Euler (`fixed_point_corrected_euler_error`, proofs/Fixed.v) and
//! `2^-(f+1)·(1 + i)` for Gouraud (`fixed_point_gouraud_error`). So corrected Euler
//! stays within half an 8-bit level of its exact run on spans of up to `n` steps
//! when `2^(f+1) ≥ 255·(n² + n + 2)` (`fixed_point_half_level_bits`):
//! [`bits_for_half_level`] answers the hardware implementer's question, and
//! `docs/float.md` ("Low precision") tabulates it. Tested: `tests/lowp.rs`.
//!
//! (The crate's generic run on `lowp::I16F16` (feature `lowp`) computes the set-up in the
//! format too, which costs far more than the loop: see `docs/float.md`.)

use crate::error::SpanError;
use crate::span::Span;
use crate::BigRational;
use num_traits::{One, Signed, ToPrimitive};

/// The most fractional bits [`FixedSpan`] takes: values up to 4 in magnitude, the
/// sums of a span's loop included, stay far inside `i64` (`4·2^48 = 2^50`).
pub const MAX_FRAC_BITS: u32 = 48;

/// The set-up of a span rounded to `frac_bits` fractional bits (raw integers: the
/// value is `raw·2^-frac_bits`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FixedSpan {
    /// Steps `n`.
    pub n: u32,
    /// Fractional bits `f`.
    pub frac_bits: u32,
    /// `p_a` rounded to the grid.
    pub p_a: i64,
    /// `t_0` (eq. 17) rounded to the grid.
    pub t0: i64,
    /// `ds` rounded to the grid.
    pub ds: i64,
    /// The Gouraud slope `dp = (p_b − p_a)/n` rounded to the grid.
    pub dp: i64,
}

/// `x·2^f` rounded to the nearest integer (halves away from zero).
fn to_grid(x: &BigRational, f: u32) -> Option<i64> {
    let scaled = x * BigRational::from_integer(num_bigint::BigInt::one() << f as usize);
    let half = BigRational::new(1.into(), 2.into());
    let r = if scaled.is_negative() {
        -((-scaled) + half).floor()
    } else {
        (scaled + half).floor()
    };
    r.to_integer().to_i64()
}

impl FixedSpan {
    /// Rounds the exact set-up of `span` to `frac_bits` fractional bits.
    ///
    /// # Errors
    /// [`SpanError::Parameter`] when `frac_bits > MAX_FRAC_BITS`, or when a set-up
    /// value or a value the loops reach does not fit 64-bit integers (a span of unit
    /// vectors always fits).
    pub fn new(span: &Span<BigRational>, frac_bits: u32) -> Result<Self, SpanError> {
        if frac_bits > MAX_FRAC_BITS {
            return Err(SpanError::Parameter(format!(
                "fractional bits must be at most {MAX_FRAC_BITS} (got {frac_bits})"
            )));
        }
        let too_large = || {
            SpanError::Parameter(format!(
                "the span's set-up or its values do not fit 64-bit integers at {frac_bits} fractional bits"
            ))
        };
        let g = |x: &BigRational| to_grid(x, frac_bits).ok_or_else(too_large);
        let f = FixedSpan {
            n: span.n,
            frac_bits,
            p_a: g(&span.p_a)?,
            t0: g(&span.t0)?,
            ds: g(&span.ds)?,
            dp: g(&span.dp)?,
        };
        // Every value and slope the loops reach is at most |p_a| + n·|t0| + n²·|ds|
        // (or |p_a| + n·|dp|): within i64, so no addition overflows (unit spans are far
        // inside; other spans may not be).
        let n = i128::from(f.n);
        let reach = i128::from(f.p_a).abs()
            + n * (i128::from(f.t0).abs() + i128::from(f.dp).abs())
            + n * n * i128::from(f.ds).abs();
        if reach >= i128::from(i64::MAX) {
            return Err(too_large());
        }
        Ok(f)
    }

    /// Corrected Euler, `p += t; t += ds` (eqs. 16–17), in exact integer additions:
    /// the raw values of pixels `0..=n`.
    pub fn corrected_euler(&self) -> Vec<i64> {
        let (mut p, mut t) = (self.p_a, self.t0);
        (0..=self.n)
            .map(|_| {
                let v = p;
                p += t;
                t += self.ds;
                v
            })
            .collect()
    }

    /// Gouraud, `g += dp`, in exact integer additions.
    pub fn gouraud(&self) -> Vec<i64> {
        let mut g = self.p_a;
        (0..=self.n)
            .map(|_| {
                let v = g;
                g += self.dp;
                v
            })
            .collect()
    }

    /// The exact value of a raw result.
    pub fn value(&self, raw: i64) -> BigRational {
        BigRational::new(
            raw.into(),
            num_bigint::BigInt::one() << self.frac_bits as usize,
        )
    }
}

/// `2^-(f+1)·(1 + n + n(n − 1)/2)`: the largest error of corrected Euler over a span
/// of `n` steps with `f` fractional bits (`fixed_point_corrected_euler_error`).
pub fn corrected_euler_bound(n: u32, frac_bits: u32) -> f64 {
    let n = f64::from(n);
    (1.0 + n + n * (n - 1.0) / 2.0) * 2f64.powi(-(frac_bits as i32) - 1)
}

/// `2^-(f+1)·(1 + n)`: the largest error of Gouraud over a span of `n` steps with `f`
/// fractional bits (`fixed_point_gouraud_error`).
pub fn gouraud_bound(n: u32, frac_bits: u32) -> f64 {
    (1.0 + f64::from(n)) * 2f64.powi(-(frac_bits as i32) - 1)
}

/// The fewest fractional bits `f` with `2^(f+1) ≥ 255·(n² + n + 2)`: enough for
/// corrected Euler to stay within half an 8-bit level of its exact run at every pixel
/// of every span of up to `n` steps (`fixed_point_half_level_bits`).
pub fn bits_for_half_level(n: u32) -> u32 {
    let need = 255 * (u128::from(n) * u128::from(n) + u128::from(n) + 2);
    (0..128)
        .find(|&f| 1u128 << (f + 1) >= need)
        .expect("n < 2^32")
}

/// The fewest fractional bits `f` with `2^(f+1) ≥ 510·(1 + n)`: enough for Gouraud
/// to stay within half an 8-bit level (`fixed_point_gouraud_error`).
pub fn gouraud_bits_for_half_level(n: u32) -> u32 {
    let need = 510 * (1 + u128::from(n));
    (0..128)
        .find(|&f| 1u128 << (f + 1) >= need)
        .expect("n < 2^32")
}
