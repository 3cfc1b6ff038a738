//! An independent software model of binary floating point, written from the IEEE 754
//! definitions (not taken from the crate): every operation is computed exactly in
//! rationals and the result rounded to the format — to nearest (ties to even), toward
//! zero, down or up, with subnormals or with them flushed to zero.

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use phong_approx::BigRational;

/// A binary floating-point format.
#[derive(Clone, Copy, Debug)]
pub struct Format {
    /// Significand bits, the hidden one included (24, 53).
    pub prec: u32,
    /// Exponent of the smallest subnormal, `2^emin` (−149, −1074).
    pub emin: i64,
    /// Largest finite values are below `2^emax` (128, 1024).
    pub emax: i64,
}

/// IEEE binary32.
pub const BINARY32: Format = Format {
    prec: 24,
    emin: -149,
    emax: 128,
};
/// IEEE binary64.
pub const BINARY64: Format = Format {
    prec: 53,
    emin: -1074,
    emax: 1024,
};

/// A rounding direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    /// To nearest, ties to even.
    Nearest,
    /// Toward zero (truncation).
    TowardZero,
    /// Toward −∞.
    Down,
    /// Toward +∞.
    Up,
}

/// `2^e`.
pub fn pow2(e: i64) -> BigRational {
    let one = BigInt::one();
    if e >= 0 {
        BigRational::from_integer(one << (e as usize))
    } else {
        BigRational::new(one.clone(), one << ((-e) as usize))
    }
}

/// `⌊log2 |x|⌋` for `x ≠ 0`.
pub fn ilog2(x: &BigRational) -> i64 {
    let (n, d) = (x.numer().abs(), x.denom().abs());
    let mut e = n.bits() as i64 - d.bits() as i64;
    // 2^e ≤ |x| < 2^(e+1), adjusted from the bit-length estimate (off by one at most).
    let a = x.abs();
    if a < pow2(e) {
        e -= 1;
    }
    if a >= pow2(e + 1) {
        e += 1;
    }
    e
}

/// The spacing of `f` at `x` (its ulp; the subnormal spacing below the normal range).
pub fn ulp(x: &BigRational, f: Format) -> BigRational {
    if x.is_zero() {
        return pow2(f.emin);
    }
    pow2((ilog2(x) - i64::from(f.prec) + 1).max(f.emin))
}

/// `x` rounded to `f` in direction `dir`; panics on overflow (the bounded inputs here
/// never overflow).
pub fn round_dir(x: &BigRational, f: Format, dir: Dir) -> BigRational {
    if x.is_zero() {
        return x.clone();
    }
    let quantum = ulp(x, f);
    let scaled = x.abs() / &quantum;
    let floor = scaled.floor();
    let frac = &scaled - &floor;
    let mut m = floor.to_integer();
    let up_in_magnitude = match dir {
        Dir::Nearest => {
            let half = BigRational::new(1.into(), 2.into());
            let odd = (&m % BigInt::from(2)) == BigInt::one();
            frac > half || (frac == half && odd)
        }
        Dir::TowardZero => false,
        Dir::Down => x.is_negative() && !frac.is_zero(),
        Dir::Up => x.is_positive() && !frac.is_zero(),
    };
    if up_in_magnitude {
        m += 1;
    }
    let r = BigRational::from_integer(m) * quantum;
    assert!(r < pow2(f.emax), "overflow in the model: {x}");
    if x.is_negative() {
        -r
    } else {
        r
    }
}

/// `x` rounded to nearest, ties to even.
pub fn round(x: &BigRational, f: Format) -> BigRational {
    round_dir(x, f, Dir::Nearest)
}

/// `x` moved `k` units of `f` toward zero (a representable `x`; stops at zero).
pub fn toward_zero(x: &BigRational, f: Format, k: u32) -> BigRational {
    let mut y = x.clone();
    for _ in 0..k {
        if y.is_zero() {
            break;
        }
        // The spacing below |y| (half of ulp(y) at a power of two).
        let below = y.abs() - BigRational::new(1.into(), 4.into()) * ulp(&y, f);
        let step = ulp(&below, f);
        y = if y.is_negative() { y + step } else { y - step };
    }
    y
}
