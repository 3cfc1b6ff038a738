//! An MPFR scalar through `rug` (feature `mpfr`).
//!
//! [`Mpfr`] wraps [`rug::Float`]. Values made from nothing (zero, one, integers,
//! rationals) take the thread's working precision, set with [`set_precision`] or
//! [`with_precision`] (default [`DEFAULT_PRECISION`] bits); an operation on two
//! values rounds to the larger of their precisions. Every operation, the square root,
//! `acos` and `cos` included, is correctly rounded (to nearest) at that precision.

use crate::scalar::{Real, Scalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use rug::float::Constant;
use rug::Float;
use std::cell::Cell;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Default working precision in bits (at least 200 bits are used for references).
pub const DEFAULT_PRECISION: u32 = 256;

thread_local! {
    static PRECISION: Cell<u32> = const { Cell::new(DEFAULT_PRECISION) };
}

/// The calling thread's working precision in bits.
pub fn precision() -> u32 {
    PRECISION.with(|p| p.get())
}

/// Sets the calling thread's working precision (clamped to MPFR's range, at least 2).
pub fn set_precision(bits: u32) {
    let bits = bits.clamp(rug::float::prec_min(), rug::float::prec_max());
    PRECISION.with(|p| p.set(bits));
}

/// Runs `f` with the working precision set to `bits`, then restores the old one.
pub fn with_precision<R>(bits: u32, f: impl FnOnce() -> R) -> R {
    let old = precision();
    set_precision(bits);
    let r = f();
    set_precision(old);
    r
}

/// An MPFR float; see the module docs for how precision is chosen.
#[derive(Clone, Debug, PartialEq, PartialOrd)]
pub struct Mpfr(pub Float);

impl Mpfr {
    /// `v` rounded to the working precision.
    pub fn from_f64(v: f64) -> Self {
        Mpfr(Float::with_val(precision(), v))
    }
}

fn prec2(a: &Float, b: &Float) -> u32 {
    a.prec().max(b.prec())
}

macro_rules! binop {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for Mpfr {
            type Output = Mpfr;
            fn $f(self, rhs: Mpfr) -> Mpfr {
                let p = prec2(&self.0, &rhs.0);
                Mpfr(Float::with_val(p, &self.0 $op &rhs.0))
            }
        }
    };
}
binop!(Add, add, +);
binop!(Sub, sub, -);
binop!(Mul, mul, *);
binop!(Div, div, /);

impl Neg for Mpfr {
    type Output = Mpfr;
    fn neg(self) -> Mpfr {
        Mpfr(-self.0)
    }
}

impl Zero for Mpfr {
    fn zero() -> Self {
        Mpfr(Float::with_val(precision(), 0))
    }
    fn is_zero(&self) -> bool {
        self.0.is_zero()
    }
}

impl One for Mpfr {
    fn one() -> Self {
        Mpfr(Float::with_val(precision(), 1))
    }
}

fn rug_to_big(r: &rug::Rational) -> BigRational {
    let n = BigInt::parse_bytes(r.numer().to_string_radix(16).as_bytes(), 16).expect("hex");
    let d = BigInt::parse_bytes(r.denom().to_string_radix(16).as_bytes(), 16).expect("hex");
    BigRational::new(n, d)
}

fn big_to_rug(x: &BigRational) -> rug::Rational {
    let n = rug::Integer::from_str_radix(&x.numer().to_str_radix(16), 16).expect("hex");
    let d = rug::Integer::from_str_radix(&x.denom().to_str_radix(16), 16).expect("hex");
    rug::Rational::from((n, d))
}

impl Scalar for Mpfr {
    const NAME: &'static str = "mpfr";
    const EXACT: bool = false;

    fn add_assign_ref(&mut self, x: &Self) {
        self.0 += &x.0;
    }

    fn from_i64(v: i64) -> Self {
        Mpfr(Float::with_val(precision(), v))
    }

    fn from_rational(x: &BigRational) -> Self {
        Mpfr(Float::with_val(precision(), big_to_rug(x)))
    }

    fn to_rational(&self) -> Option<BigRational> {
        self.0.to_rational().map(|r| rug_to_big(&r))
    }

    fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }

    fn is_finite(&self) -> bool {
        self.0.is_finite()
    }

    fn floor_i64(&self) -> i64 {
        self.0.clone().floor().to_f64() as i64
    }

    fn unit_tolerance() -> Self {
        let p = precision().saturating_sub(8).max(1) as i32;
        Mpfr(Float::with_val(precision(), Float::i_exp(1, -p)))
    }

    fn unit_roundoff() -> f64 {
        2f64.powi(-(precision() as i32))
    }

    fn to_decimal(&self, digits: usize) -> String {
        match self.to_rational() {
            Some(r) => crate::reference::decimal::rational_to_decimal(&r, digits),
            None => self.0.to_string(),
        }
    }
}

impl Real for Mpfr {
    fn sqrt(&self) -> Self {
        Mpfr(Float::with_val(self.0.prec(), self.0.sqrt_ref()))
    }
    fn acos(&self) -> Self {
        Mpfr(Float::with_val(self.0.prec(), self.0.acos_ref()))
    }
    fn cos(&self) -> Self {
        Mpfr(Float::with_val(self.0.prec(), self.0.cos_ref()))
    }
    fn frac_pi_2() -> Self {
        let pi = Float::with_val(precision(), Constant::Pi);
        Mpfr(pi / 2u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::Signed;

    #[test]
    fn rationals_round_trip_and_precision_is_scoped() {
        let x = BigRational::new((-22).into(), 7.into());
        with_precision(300, || {
            let m = Mpfr::from_rational(&x);
            assert_eq!(m.0.prec(), 300);
            let back = m.to_rational().unwrap();
            let err = Signed::abs(&(back - x.clone()));
            assert!(err < BigRational::new(1.into(), BigInt::from(2).pow(295)));
        });
        assert_eq!(precision(), DEFAULT_PRECISION);
        let h = Mpfr::from_rational(&BigRational::new(1.into(), 2.into()));
        assert_eq!(
            h.to_rational().unwrap(),
            BigRational::new(1.into(), 2.into())
        );
    }
}
