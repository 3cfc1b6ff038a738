//! The low-precision scalars: binary16 rounding, fixed-point rounding and saturation,
//! and spans set up in each format. Reference: exact rationals.

mod common;

use common::{q, Q};
use phong_approx::lowp::{f16, I16F16, I8F8};
use phong_approx::{Method, Real, Scalar, Span, Vec3};
use proptest::prelude::*;

fn exact<T: Scalar>(v: &T) -> Q {
    v.to_rational().expect("finite")
}

proptest! {
    /// Each binary16 operation is the exact result rounded to nearest binary16.
    #[test]
    fn f16_operations_are_correctly_rounded(a in -2000i32..2000, b in 1i32..2000, sa in -14i32..3, sb in -14i32..3) {
        let x = f16::from_f64(f64::from(a) * 2f64.powi(sa) / 64.0);
        let y = f16::from_f64(f64::from(b) * 2f64.powi(sb) / 64.0);
        let (ex, ey) = (exact(&x), exact(&y));
        prop_assert_eq!(x + y, f16::from_rational(&(ex.clone() + ey.clone())));
        prop_assert_eq!(x - y, f16::from_rational(&(ex.clone() - ey.clone())));
        prop_assert_eq!(x * y, f16::from_rational(&(ex.clone() * ey.clone())));
        prop_assert_eq!(x / y, f16::from_rational(&(ex / ey.clone())));
        // √y: the candidate and its neighbours bracket the exact root.
        let r = Real::sqrt(&y);
        let er = exact(&r);
        let up = f16::from_bits(r.to_bits() + 1);
        let down = f16::from_bits(r.to_bits() - 1);
        let mid_up = (er.clone() + exact(&up)) / q(2, 1);
        let mid_down = (er + exact(&down)) / q(2, 1);
        prop_assert!(mid_down.clone() * mid_down <= ey.clone() && ey <= mid_up.clone() * mid_up);
    }

    /// Conversion of a rational to fixed point rounds to the nearest step inside the
    /// range (half a step beyond either end included) and saturates outside it, and
    /// `from_f64` agrees with it. The inputs reach well past I16F16's ±32768 and
    /// I8F8's ±128 on purpose.
    #[test]
    fn fixed_from_rational_rounds_to_nearest(n in -100_000i64..100_000, d in 1i64..5000) {
        let x = q(n, d);
        let a = I16F16::from_rational(&x);
        prop_assert_eq!(a, I16F16::from_f64(n as f64 / d as f64));
        rounds_or_saturates(&x, &a, (I16F16::from_f64(-1e9), I16F16::from_f64(1e9)), 16)?;
        let b = I8F8::from_rational(&x);
        prop_assert_eq!(b, I8F8::from_f64(n as f64 / d as f64));
        rounds_or_saturates(&x, &b, (I8F8::from_f64(-1e9), I8F8::from_f64(1e9)), 8)?;
    }

    /// A fixed-point product is within one step of the exact product of its operands
    /// (the format keeps its fractional bits; no saturation in range).
    #[test]
    fn fixed_product_within_one_step(a in -4000i32..4000, b in -4000i32..4000) {
        let x = I16F16::from_f64(f64::from(a) / 1000.0);
        let y = I16F16::from_f64(f64::from(b) / 1000.0);
        let err = (exact(&(x * y)) - exact(&x) * exact(&y)).magnitude();
        prop_assert!(err < q(1, 1 << 16), "{}", err);
    }
}

/// `a`, the conversion of `x` to a format with `frac` fractional bits and range
/// `[min, max]`, is within half a step of `x` when `x` is no more than half a step
/// outside the range, and is the nearer end of the range otherwise.
fn rounds_or_saturates<T: Scalar + std::fmt::Debug>(
    x: &Q,
    a: &T,
    (min, max): (T, T),
    frac: u32,
) -> Result<(), TestCaseError> {
    let half_step = q(1, 1 << (frac + 1));
    let (lo, hi) = (exact(&min), exact(&max));
    if *x > hi.clone() + half_step.clone() {
        prop_assert_eq!(a, &max, "{} above the range", x);
    } else if *x < lo.clone() - half_step.clone() {
        prop_assert_eq!(a, &min, "{} below the range", x);
    } else {
        let err = (exact(a) - x.clone()).magnitude();
        prop_assert!(err <= half_step, "{} converted with error {}", x, err);
    }
    Ok(())
}

/// Sums, products and quotients saturate at the range instead of wrapping or panicking;
/// a quotient by zero saturates by the dividend's sign.
#[test]
fn fixed_saturates_instead_of_wrapping() {
    let max = I8F8::from_f64(1e9);
    let min = I8F8::from_f64(-1e9);
    assert_eq!(max.to_f64(), 128.0 - 1.0 / 256.0);
    assert_eq!(min.to_f64(), -128.0);
    let one = I8F8::from_i64(1);
    assert_eq!(max + one, max);
    assert_eq!(min - one, min);
    assert_eq!(I8F8::from_i64(100) * I8F8::from_i64(100), max);
    assert_eq!(I8F8::from_i64(-100) * I8F8::from_i64(100), min);
    assert_eq!(one / I8F8::from_i64(0), max);
    assert_eq!(-one / I8F8::from_i64(0), min);
    assert_eq!(I8F8::from_i64(0) / I8F8::from_i64(0), I8F8::from_i64(0));
    assert_eq!(I8F8::from_i64(100) / I8F8::from_f64(0.01), max);
    assert_eq!(-min, max, "−MIN saturates");
    assert_eq!(I8F8::from_i64(300).to_f64(), 128.0 - 1.0 / 256.0);
}

/// Unit normals rounded to each format are accepted by `Span::new`, and every method
/// runs without a NaN; their values are within the format's reach of the exact ones.
#[test]
fn spans_set_up_in_every_format() {
    use phong_approx::reference::unit::unit_from_ints;
    let (na, nb, l) = (
        unit_from_ints(1, 2, 5),
        unit_from_ints(-2, 1, 6),
        unit_from_ints(-1, 1, 3),
    );
    let exact_span = Span::new(na.clone(), nb.clone(), l.clone(), 12).expect("valid");
    fn run<T: Real>(na: &Vec3<Q>, nb: &Vec3<Q>, l: &Vec3<Q>, reference: &[f64], tol: f64) {
        let span = Span::<T>::new(
            na.cast().unwrap(),
            nb.cast().unwrap(),
            l.cast().unwrap(),
            12,
        )
        .unwrap_or_else(|e| panic!("{}: {e}", T::NAME));
        let v = Method::CorrectedEuler.values(&span).expect("length");
        for (i, (a, b)) in v.iter().zip(reference).enumerate() {
            assert!(a.is_finite());
            assert!(
                (a.to_f64() - b).abs() <= tol,
                "{} pixel {i}: {} vs {b}",
                T::NAME,
                a.to_f64()
            );
        }
    }
    let reference: Vec<f64> = Method::CorrectedEuler
        .values(&exact_span)
        .unwrap()
        .iter()
        .map(Scalar::to_f64)
        .collect();
    run::<f16>(&na, &nb, &l, &reference, 0.01);
    run::<I16F16>(&na, &nb, &l, &reference, 0.001);
    run::<I8F8>(&na, &nb, &l, &reference, 0.1);
}
