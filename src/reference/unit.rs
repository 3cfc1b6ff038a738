//! Exact rational unit vectors by inverse stereographic projection.
//!
//! For rational `(u, v)`, the point
//! `((2u, 2v, 1 − u² − v²)) / (1 + u² + v²)` lies exactly on the unit sphere, and
//! every rational point of the sphere except the south pole arises this way. These
//! are the exact-unit normals the claim tests use.

use crate::vector::Vec3;
use num_rational::BigRational;
use num_traits::One;

/// The exact unit vector that stereographic parameters `(u, v)` project to.
pub fn unit_from_stereo(u: &BigRational, v: &BigRational) -> Vec3<BigRational> {
    let one = BigRational::one();
    let two = &one + &one;
    let r2 = u * u + v * v;
    let den = &one + &r2;
    Vec3::new(&two * u / &den, &two * v / &den, (&one - &r2) / &den)
}

/// [`unit_from_stereo`] with integer parameters over a common denominator:
/// `(u, v) = (a/d, b/d)`, `d ≠ 0`.
pub fn unit_from_ints(a: i64, b: i64, d: i64) -> Vec3<BigRational> {
    let r = |x: i64| BigRational::new(x.into(), d.into());
    unit_from_stereo(&r(a), &r(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_are_exactly_unit() {
        for &(a, b, d) in &[(0, 0, 1), (1, 2, 3), (-7, 5, 11), (100, -3, 7)] {
            let n = unit_from_ints(a, b, d);
            assert_eq!(n.dot(&n), BigRational::one(), "({a},{b})/{d}");
        }
    }
}
