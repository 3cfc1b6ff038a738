//! The number types the recurrences run on.
//!
//! Every recurrence of the paper uses only the field operations (+, −, ×, ÷), so it
//! is written once, bounded by [`Scalar`], and runs unchanged on `f32`, `f64`,
//! exact rationals ([`BigRational`]) and, with the `mpfr` feature, MPFR floats
//! (`reference::mpfr::Mpfr`). The exact run *is* the reference for the
//! float run.
//!
//! The few methods that need more than a field — the square root of Phong and Duff,
//! the arc cosine and cosine of angular interpolation — are bounded by [`Real`].
//!
//! # Laws
//! For the exact type, every [`Scalar`] operation is exact. For floats, each
//! operation is the correctly rounded IEEE-754 result (no fused multiply-add, no
//! fast-math), so results are reproducible across machines.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An ordered field: what every recurrence of the paper needs.
///
/// Bounded on num-traits' [`Zero`] and [`One`]; the arithmetic is by value (types
/// such as [`BigRational`] are `Clone`, not `Copy`).
pub trait Scalar:
    Clone
    + Debug
    + PartialOrd
    + Zero
    + One
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// Short name used by the CLI and in reports (`f32`, `f64`, `exact`, `mpfr`).
    const NAME: &'static str;

    /// Whether every field operation on this type is exact.
    const EXACT: bool;

    /// The integer `v` (exact while `|v|` fits the significand).
    fn from_i64(v: i64) -> Self;

    /// The exact rational `x`, rounded to nearest (ties to even) for floats.
    fn from_rational(x: &BigRational) -> Self;

    /// The exact value of `self` as a rational, or `None` when not finite.
    fn to_rational(&self) -> Option<BigRational>;

    /// The nearest `f64` (for reports and plots; never used for decisions).
    fn to_f64(&self) -> f64;

    /// `false` for NaN and ±∞ (always `true` for exact types).
    fn is_finite(&self) -> bool;

    /// The largest integer ≤ `self`, saturated to the `i64` range.
    fn floor_i64(&self) -> i64;

    /// `self ← self + x`, taking `x` by reference: the recurrences' step (eqs. 13,
    /// 16–17, Gouraud's `+ d_p`). Exact and MPFR values add in place without copying
    /// `x` (num-traits' by-reference arithmetic); the default moves `self` and copies
    /// `x`, which is free for the float and fixed-point types.
    fn add_assign_ref(&mut self, x: &Self) {
        let s = std::mem::replace(self, Self::zero());
        *self = s + x.clone();
    }

    /// `|self|` (named so as not to clash with num-traits' `Signed::abs`).
    fn magnitude(&self) -> Self {
        if *self < Self::zero() {
            -self.clone()
        } else {
            self.clone()
        }
    }

    /// How far `N·N` may be from 1 for a normal to count as unit length
    /// (0 for exact types; a few thousand ulps for floats, see the impls).
    fn unit_tolerance() -> Self;

    /// The unit roundoff `u` of one field operation (0 for exact types).
    fn unit_roundoff() -> f64;

    /// The value as text that reads back exactly where the type allows: a fraction
    /// `a/b` for rationals, the shortest round-trip decimal for floats (what a span's
    /// `Display` and `Debug` print).
    fn exact_text(&self) -> String {
        format!("{self:?}")
    }

    /// `self` as a decimal string with `digits` significant digits (floats print the
    /// shortest string that reads back to the same value, whatever `digits` is).
    fn to_decimal(&self, digits: usize) -> String;

    /// `self`, or for [`BigRational`] the nearest multiple of 2^-(b + 64) (ties up),
    /// `b` the accuracy of this thread's square roots and cosines
    /// ([`crate::reference::transcendental::bits`]: 256 unless an exact run raised
    /// it): long recurrences whose values come from those approximations (spherical
    /// interpolation's Chebyshev recurrence) call it each step so that exact rationals
    /// keep a bounded size; 2^-(b + 64) per step is far below those functions' own
    /// error of 2^-b, at every precision a run asks for. The identity for every other
    /// type.
    fn tidy(self) -> Self {
        self
    }
}

/// A [`Scalar`] that also has the square root, arc cosine and cosine.
///
/// For floats these are the platform's `sqrt` (correctly rounded) and `acos`/`cos`;
/// for MPFR they are correctly rounded at the working precision; for [`BigRational`]
/// they are not exact (the results are irrational) but are computed to an absolute
/// error below 2^-[`crate::reference::transcendental::BITS`].
pub trait Real: Scalar {
    /// `√self` (`self` ≥ 0).
    fn sqrt(&self) -> Self;
    /// `acos(self)` in radians, for `-1 ≤ self ≤ 1`.
    fn acos(&self) -> Self;
    /// `cos(self)` for `self` in radians.
    fn cos(&self) -> Self;
    /// π/2.
    fn frac_pi_2() -> Self;
}

macro_rules! impl_float_scalar {
    ($t:ident, $name:literal, $tol:expr) => {
        impl Scalar for $t {
            const NAME: &'static str = $name;
            const EXACT: bool = false;

            fn from_i64(v: i64) -> Self {
                v as $t
            }

            fn from_rational(x: &BigRational) -> Self {
                nearest_float::<$t>(x)
            }

            fn to_rational(&self) -> Option<BigRational> {
                BigRational::from_float(*self)
            }

            fn to_f64(&self) -> f64 {
                *self as f64
            }

            fn is_finite(&self) -> bool {
                $t::is_finite(*self)
            }

            fn floor_i64(&self) -> i64 {
                // `as` saturates and maps NaN to 0.
                $t::floor(*self) as i64
            }

            fn unit_tolerance() -> Self {
                $tol
            }

            fn unit_roundoff() -> f64 {
                ($t::EPSILON as f64) / 2.0
            }

            fn to_decimal(&self, _digits: usize) -> String {
                format!("{:?}", self)
            }
        }

        impl Real for $t {
            fn sqrt(&self) -> Self {
                $t::sqrt(*self)
            }
            fn acos(&self) -> Self {
                $t::acos(*self)
            }
            fn cos(&self) -> Self {
                $t::cos(*self)
            }
            fn frac_pi_2() -> Self {
                std::$t::consts::FRAC_PI_2
            }
        }
    };
}

// Tolerances: 2^-17 (≈ 64 ulp of 1.0) for f32, 2^-40 (≈ 8192 ulp) for f64, so that
// normals typed as 7 or 13 significant decimals are accepted.
impl_float_scalar!(f32, "f32", 1.0 / 131_072.0);
impl_float_scalar!(f64, "f64", 1.0 / 1_099_511_627_776.0);

/// Rounds an exact rational to the nearest float of type `T`, ties to even.
///
/// `BigRational::to_f64` is correctly rounded; for `f32`, rounding through `f64`
/// could round twice, so the candidates next to the `f64` result are compared
/// exactly.
pub(crate) fn nearest_float<T: FloatBits>(x: &BigRational) -> T {
    let approx = T::from_f64_lossy(ToPrimitive::to_f64(x).unwrap_or(f64::NAN));
    if !approx.finite() {
        return approx;
    }
    let mut best = approx;
    let mut best_err = dist(x, best);
    for cand in [approx.step_down(), approx.step_up()] {
        if !cand.finite() {
            continue;
        }
        let err = dist(x, cand);
        if err < best_err || (err == best_err && cand.is_even() && !best.is_even()) {
            best = cand;
            best_err = err;
        }
    }
    best
}

fn dist<T: FloatBits>(x: &BigRational, f: T) -> BigRational {
    Signed::abs(&(f.exact() - x))
}

/// The bit-level operations [`nearest_float`] needs.
pub(crate) trait FloatBits: Copy {
    fn from_f64_lossy(v: f64) -> Self;
    fn finite(self) -> bool;
    fn step_up(self) -> Self;
    fn step_down(self) -> Self;
    fn is_even(self) -> bool;
    fn exact(self) -> BigRational;
}

macro_rules! impl_float_bits {
    ($t:ident, $bits:ident) => {
        impl FloatBits for $t {
            fn from_f64_lossy(v: f64) -> Self {
                v as $t
            }
            fn finite(self) -> bool {
                self.is_finite()
            }
            fn step_up(self) -> Self {
                if self == 0.0 {
                    return $t::from_bits(1);
                }
                let b = self.to_bits();
                $t::from_bits(if self > 0.0 { b + 1 } else { b - 1 })
            }
            fn step_down(self) -> Self {
                -(-self).step_up()
            }
            fn is_even(self) -> bool {
                self.to_bits() & 1 == 0
            }
            fn exact(self) -> BigRational {
                BigRational::from_float(self).expect("finite")
            }
        }
    };
}
impl_float_bits!(f32, u32);
impl_float_bits!(f64, u64);

impl Scalar for BigRational {
    const NAME: &'static str = "exact";
    const EXACT: bool = true;

    fn add_assign_ref(&mut self, x: &Self) {
        *self += x;
    }

    fn from_i64(v: i64) -> Self {
        BigRational::from_integer(BigInt::from(v))
    }

    fn from_rational(x: &BigRational) -> Self {
        x.clone()
    }

    fn to_rational(&self) -> Option<BigRational> {
        Some(self.clone())
    }

    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }

    fn is_finite(&self) -> bool {
        true
    }

    fn floor_i64(&self) -> i64 {
        let f = self.floor().to_integer();
        f.to_i64()
            .unwrap_or(if f.is_negative() { i64::MIN } else { i64::MAX })
    }

    fn unit_tolerance() -> Self {
        BigRational::zero()
    }

    fn unit_roundoff() -> f64 {
        0.0
    }

    fn tidy(self) -> Self {
        let bits = crate::reference::transcendental::bits() as usize + 64;
        let scale: num_bigint::BigInt = num_bigint::BigInt::from(1) << bits;
        let scaled = self * BigRational::from_integer(scale.clone());
        let half = BigRational::new(1.into(), 2.into());
        BigRational::new((scaled + half).floor().to_integer(), scale)
    }

    fn exact_text(&self) -> String {
        self.to_string()
    }

    fn to_decimal(&self, digits: usize) -> String {
        crate::reference::decimal::rational_to_decimal(self, digits)
    }
}

impl Real for BigRational {
    fn sqrt(&self) -> Self {
        crate::reference::transcendental::sqrt(self)
    }
    fn acos(&self) -> Self {
        crate::reference::transcendental::acos(self)
    }
    fn cos(&self) -> Self {
        crate::reference::transcendental::cos(self)
    }
    fn frac_pi_2() -> Self {
        crate::reference::transcendental::frac_pi_2()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn f32_rounding_is_nearest_with_ties_to_even() {
        // 1 + 2^-24 is exactly half-way between 1 and 1 + 2^-23: ties to even (1.0).
        let half = q(1, 1) + BigRational::new(1.into(), BigInt::from(1u64 << 24));
        assert_eq!(f32::from_rational(&half), 1.0f32);
        // Just above the half-way point rounds up, even though the f64 rounding of
        // the value may land on the tie.
        let above = half + BigRational::new(1.into(), BigInt::from(1u128 << 80));
        assert_eq!(f32::from_rational(&above), 1.0f32 + f32::EPSILON);
        assert_eq!(f32::from_rational(&q(1, 10)), 0.1f32);
        assert_eq!(f64::from_rational(&q(-2, 3)), -2.0f64 / 3.0);
    }

    #[test]
    fn floor_of_rationals_and_floats() {
        assert_eq!(q(-1, 3).floor_i64(), -1);
        assert_eq!(q(7, 2).floor_i64(), 3);
        assert_eq!((-0.5f32).floor_i64(), -1);
        assert_eq!(f64::NAN.floor_i64(), 0);
    }
}
