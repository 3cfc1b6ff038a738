//! The exact 8-bit level of the Phong value, decided with rationals only.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// `floor(255 · clamp(p/√q, 0, 1))` for rational `p` and `q > 0`, exactly.
///
/// `p/√q` is irrational in general, so it is never computed: for `p > 0` the level
/// is the largest `ℓ ∈ 0..=255` with `ℓ/255 ≤ p/√q`, i.e. `ℓ²·q ≤ 255²·p²` (both
/// sides are non-negative, so squaring keeps the order). For `p ≤ 0` the clamp gives
/// level 0. Returns `None` when `q ≤ 0` (the normal vanished).
pub fn phong_level_exact(p: &BigRational, q: &BigRational) -> Option<u8> {
    if !q.is_positive() {
        return None;
    }
    if !p.is_positive() {
        return Some(0);
    }
    let rhs = p * p * BigRational::from_integer(BigInt::from(255 * 255));
    let fits = |l: i64| -> bool {
        let l = BigRational::from_integer(BigInt::from(l));
        &l * &l * q <= rhs
    };
    // Binary search for the largest l in 0..=255 with fits(l); fits(0) holds.
    let (mut lo, mut hi) = (0i64, 255i64);
    while lo < hi {
        let mid = (lo + hi + 1) / 2;
        if fits(mid) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    Some(lo as u8)
}

/// `floor(255 · clamp(v, 0, 1))` for an exact rational `v`.
pub fn level_of_rational(v: &BigRational) -> u8 {
    let c = if v.is_negative() {
        BigRational::zero()
    } else if *v > BigRational::from_integer(1.into()) {
        BigRational::from_integer(1.into())
    } else {
        v.clone()
    };
    let s = c * BigRational::from_integer(BigInt::from(255));
    s.floor().to_integer().try_into().unwrap_or(255)
}

/// The level of a value known only to within `e` of `v`: `Some` when every value of
/// `[v − e, v + e]` has the same level, `None` when that interval straddles a level
/// boundary `k/255` (the level is then not known).
pub fn level_within(v: &BigRational, e: &BigRational) -> Option<u8> {
    let lo = level_of_rational(&(v - e));
    (lo == level_of_rational(&(v + e))).then_some(lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn levels_at_and_near_boundaries() {
        // p/√q = 1/2 → 127.5 → 127.
        assert_eq!(phong_level_exact(&q(1, 2), &q(1, 1)), Some(127));
        // p/√q = 3/5 / √(9/25) = 1 → 255.
        assert_eq!(phong_level_exact(&q(3, 5), &q(9, 25)), Some(255));
        // Exactly 100/255 → level 100, not 99.
        assert_eq!(phong_level_exact(&q(100, 255), &q(1, 1)), Some(100));
        assert_eq!(phong_level_exact(&q(-1, 2), &q(1, 1)), Some(0));
        assert_eq!(phong_level_exact(&q(1, 2), &q(0, 1)), None);
        // Above 1 clamps.
        assert_eq!(phong_level_exact(&q(2, 1), &q(1, 1)), Some(255));
        assert_eq!(level_of_rational(&q(100, 255)), 100);
        assert_eq!(level_of_rational(&q(-1, 255)), 0);
        assert_eq!(level_of_rational(&q(3, 2)), 255);
        // Within 1/1000 of 100/255: undecided; 1/1000 from 100.5/255: level 100.
        assert_eq!(level_within(&q(100, 255), &q(1, 1000)), None);
        assert_eq!(level_within(&q(201, 510), &q(1, 1000)), Some(100));
        assert_eq!(level_within(&q(1, 1), &q(1, 1 << 30)), None);
        assert_eq!(level_within(&q(3, 1), &q(1, 1)), Some(255));
    }
}
