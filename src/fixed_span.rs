//! The span methods in integer fixed point, the way a hardware span unit runs them
//! (`harness/hdl/`): the set-up (`p_a`, `t_0`, `ds`, `dp`, `di_a`, and Duff's `B`, `A`,
//! `E`, `C + D`, `2C`) rounded once to `f` fractional bits, then the loop in integer
//! additions, which are exact — Gouraud, Euler, corrected Euler, the adaptive choice
//! between the first and the last, and Duff with a truncated integer square root and a
//! truncated divider per pixel. Each is bit for bit what the units of `harness/hdl/`
//! compute (the contract: `docs/conformance.md`, "Hardware span units").
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
    /// Euler's start slope `di_a` (eq. 10) rounded to the grid.
    pub di_a: i64,
    /// Duff's `p_0 = B` (eq. 5) rounded to the grid.
    pub b: i64,
    /// Duff's `dp = A` (eq. 5) rounded to the grid.
    pub a: i64,
    /// Duff's `q_0 = E` (eq. 6) rounded to the grid.
    pub q0: i64,
    /// Duff's `dq_0 = C + D` (eq. 7) rounded to the grid.
    pub dq0: i64,
    /// Duff's `d²q = 2C` (eq. 7) rounded to the grid.
    pub d2q: i64,
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
            di_a: g(&span.di_a)?,
            b: g(&span.b)?,
            a: g(&span.a)?,
            q0: g(&span.e)?,
            dq0: g(&(span.c.clone() + span.d.clone()))?,
            d2q: g(&(span.c.clone() + span.c.clone()))?,
        };
        // Every value and slope the loops reach, the update after the last pixel
        // included, is at most |p_a| + (n + 1)·|t0| + (n + 1)²·|ds| (or
        // |p_a| + (n + 1)·|dp|, and Duff's q likewise): within i64, so no addition
        // overflows (unit spans are far inside; other spans may not be).
        let n = i128::from(f.n) + 1;
        let m = |x: i64| i128::from(x).abs();
        let reach = m(f.p_a).max(m(f.b))
            + n * (m(f.t0).max(m(f.di_a)) + m(f.dp) + m(f.a))
            + n * n * m(f.ds);
        let reach_q = m(f.q0) + n * m(f.dq0) + n * n * m(f.d2q);
        if reach.max(reach_q) >= i128::from(i64::MAX) {
            return Err(too_large());
        }
        Ok(f)
    }

    /// Corrected Euler, `p += t; t += ds` (eqs. 16–17), in exact integer additions:
    /// the raw values of pixels `0..=n`.
    pub fn corrected_euler(&self) -> Vec<i64> {
        second_order(self.p_a, self.t0, self.ds, self.n)
    }

    /// Plain Euler, `p += s; s += ds` from `s_0 = di_a` (eqs. 12–13), in exact integer
    /// additions: the raw values of pixels `0..=n`, within `h(1 + i + i(i − 1)/2)` of the
    /// exact run (`fixed_point_euler_error`, proofs/Fixed.v).
    pub fn euler(&self) -> Vec<i64> {
        second_order(self.p_a, self.di_a, self.ds, self.n)
    }

    /// The adaptive test of eq. 24 on the rounded set-up, in exact integers: with
    /// `k = ⌈n/2⌉` (eq. 23's step) and `T = k(k − 1)/2`,
    /// `δ̂ = k·dp − k·t_0 − T·ds` (raw), and Gouraud exactly when `255·|δ̂| < 2^f`
    /// (`K_d = 1`). `δ̂` is within `h(2k + T)` of the exact `δ`
    /// (`fixed_point_adaptive_delta_error`, proofs/Fixed.v), so the choice is the
    /// exact test's outside that band (`fixed_point_adaptive_decision`).
    pub fn adaptive_choice(&self) -> crate::adaptive::Choice {
        let k = i128::from(self.n.div_ceil(2));
        let t = k * (k - 1) / 2;
        let delta = k * i128::from(self.dp) - k * i128::from(self.t0) - t * i128::from(self.ds);
        if 255 * delta.abs() < 1i128 << self.frac_bits {
            crate::adaptive::Choice::Gouraud
        } else {
            crate::adaptive::Choice::CorrectedEuler
        }
    }

    /// The adaptive scheme: the loop of [`Self::adaptive_choice`]'s pick.
    pub fn adaptive(&self) -> Vec<i64> {
        match self.adaptive_choice() {
            crate::adaptive::Choice::Gouraud => self.gouraud(),
            crate::adaptive::Choice::CorrectedEuler => self.corrected_euler(),
        }
    }

    /// Duff's method (eqs. 5–7) as a span unit runs it: `p += A`, `q += dq`,
    /// `dq += 2C` in exact integer additions, then per pixel the truncated square root
    /// `s = ⌊√(q·2^f)⌋` (raw; a value in `(√q̂ − 2^-f, √q̂]`) and the quotient
    /// `p·2^f / s` truncated toward zero (within `2^-f` of `p̂/ŝ`); `0` where `q ≤ 0`
    /// or `s = 0`, spans no bound covers. Within
    /// `(E_p + E_q/(2r) + 2h)/(r − 2h) + 2h` of `p/√q`, `r = √(q_min − E_q)`: the value
    /// step `fixed_point_duff_error` composed with the loops,
    /// `fixed_point_duff_unit_error` (proofs/Fixed.v).
    pub fn duff(&self) -> Vec<i64> {
        let f = self.frac_bits;
        let (mut p, mut q, mut dq) = (self.b, self.q0, self.dq0);
        (0..=self.n)
            .map(|_| {
                let v = if q <= 0 {
                    0
                } else {
                    let s = num_integer::Roots::sqrt(&((q as u128) << f));
                    if s == 0 {
                        0
                    } else {
                        // |p|·2^f < 2^(63 + 48): within i128; the quotient is at most
                        // |p|·2^f, and within i64 wherever a bound holds.
                        let v = (i128::from(p) << f) / s as i128;
                        i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX })
                    }
                };
                p += self.a;
                q += dq;
                dq += self.d2q;
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

/// `p += t; t += ds` from `(p_0, t_0)` in exact integer additions: pixels `0..=n`.
fn second_order(p0: i64, t0: i64, ds: i64, n: u32) -> Vec<i64> {
    let (mut p, mut t) = (p0, t0);
    (0..=n)
        .map(|_| {
            let v = p;
            p += t;
            t += ds;
            v
        })
        .collect()
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
