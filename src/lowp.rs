//! Low-precision scalars: IEEE binary16 (`half::f16`) and saturating fixed point
//! (`fixed`'s `I16F16` and the 8.8 format `I8F8`), for the question of porting the
//! recurrences to a GPU shader or a microcontroller.
//!
//! All three implement [`Scalar`] and [`Real`], so every generic method runs on them
//! unchanged. What the arithmetic is:
//!
//! - [`f16`](struct@f16): each of `+ − × ÷ √` is the correctly rounded binary16 result (the `half`
//!   crate computes in `f32` and rounds once; `f32` carries more than twice binary16's
//!   11 significant bits plus two, so the double rounding is innocuous). `acos` and
//!   `cos` are `f32`'s, rounded to binary16.
//! - [`I16F16`], [`I8F8`]: the [`Saturating`] wrapper around `fixed`'s types. Sums,
//!   differences and products saturate at the format's range instead of wrapping
//!   (as a DSP's saturating instructions do); products keep the format's
//!   fractional bits as `fixed` does. A quotient by zero saturates by the sign of the
//!   dividend (0/0 is 0). `√`, `acos` and `cos` are the correctly rounded `f64`
//!   result rounded to the format (what a table or a hardware unit gives at best); the
//!   square root of a negative (a rounding artefact) is 0.
//!
//! None of these types can be NaN in our use: fixed point has no NaN, and binary16
//! overflows to ±∞, which [`Scalar::is_finite`] reports.

use crate::scalar::{FloatBits, Real, Scalar};
use fixed::traits::{FixedSigned, ToFixed};
pub use half::f16;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::ops::{Add, Div, Mul, Neg, Sub};

impl FloatBits for f16 {
    fn from_f64_lossy(v: f64) -> Self {
        f16::from_f64(v)
    }
    fn finite(self) -> bool {
        self.is_finite()
    }
    fn step_up(self) -> Self {
        if self == f16::ZERO || self == f16::NEG_ZERO {
            return f16::from_bits(1);
        }
        let b = self.to_bits();
        f16::from_bits(if self > f16::ZERO { b + 1 } else { b - 1 })
    }
    fn step_down(self) -> Self {
        -(-self).step_up()
    }
    fn is_even(self) -> bool {
        self.to_bits() & 1 == 0
    }
    fn exact(self) -> BigRational {
        BigRational::from_float(self.to_f64()).expect("finite")
    }
}

impl Scalar for f16 {
    const NAME: &'static str = "f16";
    const EXACT: bool = false;

    fn from_i64(v: i64) -> Self {
        f16::from_f64(v as f64)
    }
    fn from_rational(x: &BigRational) -> Self {
        crate::scalar::nearest_float::<f16>(x)
    }
    fn to_rational(&self) -> Option<BigRational> {
        BigRational::from_float(self.to_f64())
    }
    fn to_f64(&self) -> f64 {
        f16::to_f64(*self)
    }
    fn is_finite(&self) -> bool {
        f16::is_finite(*self)
    }
    fn floor_i64(&self) -> i64 {
        f16::to_f64(*self).floor() as i64
    }
    /// 2^-7 (16 ulp of 1.0): a normal rounded to binary16 and squared in binary16
    /// stays well inside it.
    fn unit_tolerance() -> Self {
        f16::from_f64(1.0 / 128.0)
    }
    fn unit_roundoff() -> f64 {
        f16::EPSILON.to_f64() / 2.0
    }
    fn to_decimal(&self, _digits: usize) -> String {
        format!("{}", self.to_f64())
    }
}

impl Real for f16 {
    fn sqrt(&self) -> Self {
        f16::from_f32(self.to_f32().sqrt())
    }
    fn acos(&self) -> Self {
        f16::from_f32(self.to_f32().acos())
    }
    fn cos(&self) -> Self {
        f16::from_f32(self.to_f32().cos())
    }
    fn frac_pi_2() -> Self {
        f16::FRAC_PI_2
    }
}

/// A `fixed` number with saturating arithmetic (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd, Default)]
pub struct Saturating<F>(pub F);

/// Signed fixed point, 16 integer and 16 fractional bits (range ±32768, step 2^-16).
pub type I16F16 = Saturating<fixed::types::I16F16>;

/// Signed 8.8 fixed point, 8 integer and 8 fractional bits (range ±128, step 1/256):
/// what an embedded rasterizer with 16-bit registers would use.
pub type I8F8 = Saturating<fixed::types::I8F8>;

/// The fixed formats the crate names: [`Scalar::NAME`] and the unit tolerance.
pub trait FixedFormat: FixedSigned + ToFixed {
    /// Name in reports.
    const NAME: &'static str;
    /// Tolerance on `|N·N − 1|` for a unit normal rounded to this format.
    fn unit_tolerance_f64() -> f64;
}

impl FixedFormat for fixed::types::I16F16 {
    const NAME: &'static str = "I16F16";
    /// 2^-12: three components rounded to 2^-17 and three products each within
    /// 2^-16 leave `N·N` within about 2^-14 of 1.
    fn unit_tolerance_f64() -> f64 {
        1.0 / 4096.0
    }
}

impl FixedFormat for fixed::types::I8F8 {
    const NAME: &'static str = "I8F8";
    /// 2^-4: components rounded to 2^-9 and products within 2^-8 leave `N·N` within
    /// about 2^-6 of 1.
    fn unit_tolerance_f64() -> f64 {
        1.0 / 16.0
    }
}

impl<F: FixedFormat> Saturating<F> {
    /// The nearest value of the format to `v` (ties to even), saturated to its range.
    pub fn from_f64(v: f64) -> Self {
        Saturating(F::saturating_from_num(v))
    }

    /// The exact value as `f64` (at most 32 significant bits).
    pub fn to_f64(self) -> f64 {
        self.0.to_num::<f64>()
    }

    fn frac_bits() -> i32 {
        F::FRAC_NBITS as i32
    }
}

impl<F: FixedFormat> Add for Saturating<F> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Saturating(self.0.saturating_add(o.0))
    }
}

impl<F: FixedFormat> Sub for Saturating<F> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Saturating(self.0.saturating_sub(o.0))
    }
}

impl<F: FixedFormat> Mul for Saturating<F> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Saturating(self.0.saturating_mul(o.0))
    }
}

impl<F: FixedFormat> Div for Saturating<F> {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        if let Some(q) = self.0.checked_div(o.0) {
            return Saturating(q);
        }
        let negative = (self.0 < F::ZERO) != (o.0 < F::ZERO);
        if self.0 == F::ZERO {
            Saturating(F::ZERO)
        } else if negative {
            Saturating(F::MIN)
        } else {
            Saturating(F::MAX)
        }
    }
}

impl<F: FixedFormat> Neg for Saturating<F> {
    type Output = Self;
    fn neg(self) -> Self {
        Saturating(self.0.saturating_neg())
    }
}

impl<F: FixedFormat> Zero for Saturating<F> {
    fn zero() -> Self {
        Saturating(F::ZERO)
    }
    fn is_zero(&self) -> bool {
        self.0 == F::ZERO
    }
}

impl<F: FixedFormat> One for Saturating<F> {
    fn one() -> Self {
        Saturating(F::saturating_from_num(1))
    }
}

impl<F: FixedFormat> Scalar for Saturating<F> {
    const NAME: &'static str = F::NAME;
    const EXACT: bool = false;

    fn from_i64(v: i64) -> Self {
        Saturating(F::saturating_from_num(v))
    }

    /// Rounded to nearest (ties to even) exactly: `round(x·2^frac)` as an integer,
    /// then scaled, saturated to the range.
    fn from_rational(x: &BigRational) -> Self {
        use num_integer::Integer;
        use num_traits::ToPrimitive;
        let scaled =
            x * BigRational::from_integer(num_bigint::BigInt::from(1u64 << Self::frac_bits()));
        let floor = scaled.floor();
        let rest = &scaled - &floor;
        let half = BigRational::new(1.into(), 2.into());
        let mut k = floor.to_integer();
        if rest > half || (rest == half && k.is_odd()) {
            k += 1;
        }
        match k.to_i64() {
            Some(k) if k.unsigned_abs() < 1 << 40 => Saturating(F::saturating_from_num(
                k as f64 / (1u64 << Self::frac_bits()) as f64,
            )),
            _ => {
                if k.sign() == num_bigint::Sign::Minus {
                    Saturating(F::MIN)
                } else {
                    Saturating(F::MAX)
                }
            }
        }
    }

    fn to_rational(&self) -> Option<BigRational> {
        BigRational::from_float(self.to_f64())
    }

    fn to_f64(&self) -> f64 {
        Saturating::to_f64(*self)
    }

    fn is_finite(&self) -> bool {
        true
    }

    fn floor_i64(&self) -> i64 {
        self.to_f64().floor() as i64
    }

    fn unit_tolerance() -> Self {
        Self::from_f64(F::unit_tolerance_f64())
    }

    /// One step of the format, `2^-frac` (an absolute, not a relative, resolution).
    fn unit_roundoff() -> f64 {
        F::DELTA.to_num::<f64>()
    }

    fn to_decimal(&self, _digits: usize) -> String {
        format!("{}", self.0)
    }
}

impl<F: FixedFormat> Real for Saturating<F> {
    fn sqrt(&self) -> Self {
        let v = self.to_f64();
        Self::from_f64(if v > 0.0 { v.sqrt() } else { 0.0 })
    }
    fn acos(&self) -> Self {
        Self::from_f64(self.to_f64().clamp(-1.0, 1.0).acos())
    }
    fn cos(&self) -> Self {
        Self::from_f64(self.to_f64().cos())
    }
    fn frac_pi_2() -> Self {
        Self::from_f64(std::f64::consts::FRAC_PI_2)
    }
}
