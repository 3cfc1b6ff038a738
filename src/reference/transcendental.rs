//! Square root, arc cosine and cosine of rationals, to a fixed absolute accuracy.
//!
//! The results are irrational, so they cannot be exact; they are computed in
//! fixed point with [`bits`] + 64 fractional bits and returned as rationals whose
//! absolute error is below 2^-[`bits`] ([`BITS`] = 256 unless a caller asks for more
//! with [`with_bits`]). This is what [`crate::scalar::Real`] means
//! for [`BigRational`]: the field-operation recurrences stay exact, and the one
//! square root (or cosine) per pixel is accurate far beyond any float.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::sync::OnceLock;

/// Accuracy of the results by default: absolute error below 2^-BITS.
pub const BITS: u32 = 256;

/// The most bits [`with_bits`] takes (about 2,400 decimal digits).
pub const MAX_BITS: u32 = 8192;

thread_local! {
    static PRECISION: std::cell::Cell<u32> = const { std::cell::Cell::new(BITS) };
}

/// The accuracy of this thread's results: absolute error below 2^-`bits()`
/// ([`BITS`] unless inside [`with_bits`]).
pub fn bits() -> u32 {
    PRECISION.with(std::cell::Cell::get)
}

/// Runs `f` with results accurate to 2^-`b` on this thread (`b` clamped to
/// [`BITS`]`..=`[`MAX_BITS`]), as an exact run that needs more digits than the default
/// gives does; the previous accuracy is restored afterwards, also on a panic.
pub fn with_bits<R>(b: u32, f: impl FnOnce() -> R) -> R {
    struct Restore(u32);
    impl Drop for Restore {
        fn drop(&mut self) {
            PRECISION.with(|p| p.set(self.0));
        }
    }
    let _restore = Restore(bits());
    PRECISION.with(|p| p.set(b.clamp(BITS, MAX_BITS)));
    f()
}

/// Working fractional bits (64 guard bits).
#[allow(non_snake_case)]
fn W() -> u32 {
    bits() + 64
}

fn one_fx() -> BigInt {
    BigInt::one() << W()
}

/// `x` in fixed point (floor of `x · 2^W`).
fn to_fx(x: &BigRational) -> BigInt {
    (x.numer() << W()).div_floor(x.denom())
}

/// A fixed-point value back to a rational, keeping [`BITS`] + 8 fractional bits
/// (the last guard bits are noise, and fewer bits keep the rationals small).
fn from_fx(v: &BigInt) -> BigRational {
    let keep = bits() + 8;
    let shift = W() - keep;
    let r: BigInt = (v + (BigInt::one() << (shift - 1))) >> shift;
    BigRational::new(r, BigInt::one() << keep)
}

/// `a·b` in fixed point, truncated toward zero (a plain `>>` floors, and a negative
/// series term would then never reach zero).
fn mul_fx(a: &BigInt, b: &BigInt) -> BigInt {
    let p = a * b;
    if p.is_negative() {
        -((-p) >> W())
    } else {
        p >> W()
    }
}

fn div_fx(a: &BigInt, b: &BigInt) -> BigInt {
    (a << W()).div_floor(b)
}

fn sqrt_fx(a: &BigInt) -> BigInt {
    if a.is_negative() {
        return BigInt::zero();
    }
    (a << W()).sqrt()
}

/// `√x` for `x ≥ 0` (negative `x` gives 0): exact when `x` is the square of a
/// rational, otherwise with absolute error below 2^-BITS·max(1, √x) and, however small
/// `x` is, relative error below 2^-(BITS + 8): a positive `x` never gives 0 (a caller
/// that divides by the root never divides by zero), however far its root lies below
/// 2^-BITS.
pub fn sqrt(x: &BigRational) -> BigRational {
    if !x.is_positive() {
        return BigRational::zero();
    }
    // A reduced fraction is a square exactly when its numerator and denominator are.
    let (rn, rd) = (x.numer().sqrt(), x.denom().sqrt());
    if &(&rn * &rn) == x.numer() && &(&rd * &rd) == x.denom() {
        return BigRational::new(rn, rd);
    }
    // x ≥ 2^-(d + 1) with d the bits of the denominator beyond the numerator's, so
    // √x ≥ 2^-(d/2 + 1): `tiny` more fractional bits keep as many significant bits of
    // a tiny root as of a root near 1.
    let d = i64::try_from(x.denom().bits()).unwrap_or(i64::MAX)
        - i64::try_from(x.numer().bits()).unwrap_or(0);
    let tiny = u32::try_from(d.max(0) / 2 + 1).unwrap_or(u32::MAX / 4);
    let keep = bits() + 8 + tiny;
    let w = keep + 56;
    // √(a/b) = √(a·b) / b: s = ⌊√(a·b)·2^w⌋, v = ⌊s / b⌋ = ⌊√x·2^w⌋.
    let ab: BigInt = (x.numer() * x.denom()) << (2 * w);
    let v = ab.sqrt().div_floor(x.denom());
    // Rounded to `keep` fractional bits (the last guard bits are noise).
    let shift = w - keep;
    let r: BigInt = (v + (BigInt::one() << (shift - 1))) >> shift;
    BigRational::new(r, BigInt::one() << keep)
}

/// atan(y) for |y| ≤ 1 in fixed point.
fn atan_fx(y: &BigInt) -> BigInt {
    // Halve the angle until |y| < 2^-8: atan(y) = 2·atan(y / (1 + √(1 + y²))).
    let mut y = y.clone();
    let mut doublings = 0u32;
    let small = one_fx() >> 8;
    while y.abs() > small {
        let r = sqrt_fx(&(one_fx() + mul_fx(&y, &y)));
        y = div_fx(&y, &(one_fx() + r));
        doublings += 1;
    }
    // Taylor series y − y³/3 + y⁵/5 − …
    let y2 = mul_fx(&y, &y);
    let mut term = y.clone();
    let mut sum = BigInt::zero();
    let mut k = 0u64;
    while !term.is_zero() {
        let t = &term / BigInt::from(2 * k + 1);
        if k.is_multiple_of(2) {
            sum += t;
        } else {
            sum -= t;
        }
        term = mul_fx(&term, &y2);
        k += 1;
    }
    sum << doublings
}

fn pi_fx() -> BigInt {
    static PI: OnceLock<BigInt> = OnceLock::new();
    // Machin: π = 16·atan(1/5) − 4·atan(1/239).
    let machin = || {
        let a = atan_fx(&(one_fx() / 5));
        let b = atan_fx(&(one_fx() / 239));
        a * 16 - b * 4
    };
    if bits() == BITS {
        PI.get_or_init(machin).clone()
    } else {
        thread_local! {
            static MORE: std::cell::RefCell<Option<(u32, BigInt)>> = const { std::cell::RefCell::new(None) };
        }
        MORE.with(|m| {
            let mut m = m.borrow_mut();
            match &*m {
                Some((b, pi)) if *b == bits() => pi.clone(),
                _ => {
                    let pi = machin();
                    *m = Some((bits(), pi.clone()));
                    pi
                }
            }
        })
    }
}

/// π/2 to 2^-[`bits`].
pub fn frac_pi_2() -> BigRational {
    from_fx(&(pi_fx() >> 1))
}

/// acos(x) in [0, π] for −1 ≤ x ≤ 1 (clamped outside), absolute error below 2^-BITS.
pub fn acos(x: &BigRational) -> BigRational {
    let one = BigRational::one();
    if *x >= one {
        return BigRational::zero();
    }
    if *x <= -one.clone() {
        return from_fx(&pi_fx());
    }
    let xf = to_fx(x);
    // √(1 − x²) from the exact 1 − x² = (1 − x)(1 + x): near ±1 that is tiny, and a
    // fixed-point square would lose its digits (an error e in 1 − x² moves the root
    // by e/(2√(1 − x²))), while the root of the exact value is within 2^-W.
    let sf = to_fx(&sqrt(&((one.clone() - x) * (one.clone() + x))));
    let half = BigRational::new(1.into(), 2.into());
    let v = if x.abs() * x.abs() <= half {
        // acos = π/2 − atan(x / √(1 − x²)), argument in [−1, 1].
        (pi_fx() >> 1) - atan_fx(&div_fx(&xf, &sf))
    } else if x.is_positive() {
        atan_fx(&div_fx(&sf, &xf))
    } else {
        pi_fx() - atan_fx(&div_fx(&sf, &(-xf)))
    };
    from_fx(&v)
}

/// cos(x) for any rational `x` (radians), absolute error below 2^-[`bits`].
///
/// An `|x|` of 8 or more is first reduced modulo 2π with π to as many more bits as `|x|`
/// has bits before the point (the reduction `x − 2πk` then loses nothing: its error is
/// below 2^-(bits + 64)); the rest is halved below ½ and the series summed, each
/// halving undone by `cos 2a = 2cos²a − 1`, which at most quadruples the error (at
/// most five halvings; the 64 guard bits cover them).
pub fn cos(x: &BigRational) -> BigRational {
    let int_bits = i64::try_from(x.numer().bits()).unwrap_or(i64::MAX)
        - i64::try_from(x.denom().bits()).unwrap_or(0)
        + 1;
    if int_bits > 3 {
        let extra = u32::try_from(int_bits).unwrap_or(u32::MAX / 4) + 8;
        return cos_series(&reduce_2pi(x, extra));
    }
    cos_series(x)
}

/// cos(x) by halving below ½, the series, and doubling back (|x| below about 16: at
/// most five halvings, which the 64 guard bits cover).
fn cos_series(x: &BigRational) -> BigRational {
    let mut xf = to_fx(x).abs();
    // Reduce |x| below 1/2 by halving; undo with cos 2a = 2cos²a − 1.
    let mut halvings = 0u32;
    let half = one_fx() >> 1;
    while xf > half {
        xf >>= 1;
        halvings += 1;
    }
    let x2 = mul_fx(&xf, &xf);
    let mut term = one_fx();
    let mut sum = BigInt::zero();
    let mut k = 0u64;
    while !term.is_zero() {
        if k.is_multiple_of(2) {
            sum += &term;
        } else {
            sum -= &term;
        }
        term = mul_fx(&term, &x2) / BigInt::from((2 * k + 1) * (2 * k + 2));
        k += 1;
    }
    for _ in 0..halvings {
        sum = mul_fx(&sum, &sum) * 2 - one_fx();
    }
    from_fx(&sum)
}

/// `x − 2πk` with `k` the integer nearest `x/2π` (so `|result| ≤ π`), computed with π
/// to `extra` more bits than this thread's [`bits`]: exact but for π's error times
/// `|k|`, below 2^-(bits + 64) when `|x| < 2^(extra − 8)`.
fn reduce_2pi(x: &BigRational, extra: u32) -> BigRational {
    let b = bits().saturating_add(extra);
    // π at b bits (not clamped to MAX_BITS: the reduction needs bits in proportion to
    // the size of x, which the caller already holds in memory).
    let (two_pi, w) = {
        struct Restore(u32);
        impl Drop for Restore {
            fn drop(&mut self) {
                PRECISION.with(|p| p.set(self.0));
            }
        }
        let _restore = Restore(bits());
        PRECISION.with(|p| p.set(b));
        (pi_fx() << 1, W())
    };
    let scale = BigInt::one() << w;
    let two_pi = BigRational::new(two_pi, scale);
    let k = (x / &two_pi).round();
    x - k * two_pi
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::ToPrimitive;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    fn close(a: &BigRational, b: f64, tol: f64) -> bool {
        (a.to_f64().unwrap() - b).abs() <= tol
    }

    #[test]
    fn agrees_with_libm_to_double_precision() {
        for &(n, d) in &[
            (0, 1),
            (1, 7),
            (1, 2),
            (-1, 3),
            (99, 100),
            (-999, 1000),
            (3, 5),
        ] {
            let x = q(n, d);
            let xf = n as f64 / d as f64;
            assert!(close(&acos(&x), xf.acos(), 4e-16), "acos({n}/{d})");
            assert!(close(&cos(&x), xf.cos(), 4e-16), "cos({n}/{d})");
            assert!(close(&cos(&(q(7, 2) * x.clone())), (3.5 * xf).cos(), 4e-16));
        }
        assert!(close(&sqrt(&q(2, 1)), 2f64.sqrt(), 4e-16));
        assert_eq!(sqrt(&q(16, 25)), q(4, 5));
        assert_eq!(sqrt(&q(1, 1)), q(1, 1));
        assert!(close(&frac_pi_2(), std::f64::consts::FRAC_PI_2, 4e-16));
    }

    #[test]
    fn identities_hold_to_2_pow_minus_250() {
        let tol = BigRational::new(1.into(), BigInt::one() << 250);
        for &(n, d) in &[(1, 7), (-5, 6), (7, 10), (-1, 100), (1, 1_000_000)] {
            let x = q(n, d);
            let back = cos(&acos(&x));
            assert!((back - x.clone()).abs() < tol, "cos(acos({n}/{d}))");
            let s = sqrt(&(x.clone() * x.clone()));
            assert!((s - x.abs()).abs() < tol, "sqrt(x²) for {n}/{d}");
        }
        // cos(π/2) = 0 and acos(0) = π/2.
        assert!(cos(&frac_pi_2()).abs() < tol);
        assert!((acos(&BigRational::zero()) - frac_pi_2()).abs() < tol);
    }
}
