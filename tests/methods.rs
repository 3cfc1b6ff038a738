//! Method-level behaviour: typed errors for bad input (never a panic, never a NaN),
//! the specular term, the quantiser, and each method against an independent formula.

use crate::common;

use common::*;
use num_traits::One;
use phong_approx::quantize::level;
use phong_approx::specular::{intensity, power};
use phong_approx::{Input, Method, Span, SpanError, Vec3};

fn v32(x: f32, y: f32, z: f32) -> Vec3<f32> {
    Vec3::new(x, y, z)
}

#[test]
fn bad_spans_get_typed_errors() {
    let up = v32(0.0, 0.0, 1.0);
    let tilt = v32(0.6, 0.0, 0.8);
    assert_eq!(
        Span::new(v32(f32::NAN, 0.0, 1.0), tilt.clone(), up.clone(), 4).unwrap_err(),
        SpanError::NonFinite {
            input: Input::Na,
            component: 0
        }
    );
    assert_eq!(
        Span::new(up.clone(), v32(0.0, f32::INFINITY, 1.0), up.clone(), 4).unwrap_err(),
        SpanError::NonFinite {
            input: Input::Nb,
            component: 1
        }
    );
    assert_eq!(
        Span::new(up.clone(), tilt.clone(), v32(0.0, 0.0, 0.0), 4).unwrap_err(),
        SpanError::ZeroVector { input: Input::L }
    );
    assert!(matches!(
        Span::new(v32(1.0, 1.0, 0.0), tilt.clone(), up.clone(), 4).unwrap_err(),
        SpanError::NotUnit {
            input: Input::Na,
            ..
        }
    ));
    assert!(matches!(
        Span::new(v32(1e30, 0.0, 0.0), tilt.clone(), up.clone(), 4).unwrap_err(),
        SpanError::NotUnit {
            input: Input::Na,
            ..
        }
    ));
    assert_eq!(
        Span::new(up.clone(), tilt.clone(), up.clone(), 0).unwrap_err(),
        SpanError::ZeroSteps
    );
    assert_eq!(
        Span::new(up.clone(), tilt.clone(), up.clone(), (1 << 24) + 1).unwrap_err(),
        SpanError::TooManySteps {
            max: 1 << 24,
            got: (1 << 24) + 1
        }
    );
    // Nb = −Na is a span: the methods that normalize refuse the middle pixel of an
    // even n by name, the related methods that need an arc refuse the span.
    let opposite = Span::new(tilt.clone(), v32(-0.6, 0.0, -0.8), up.clone(), 4).unwrap();
    assert!(opposite.is_opposite());
    for m in [Method::Phong, Method::Duff, Method::SymmetricPhong] {
        assert_eq!(
            m.values(&opposite).unwrap_err(),
            SpanError::ZeroNormal { pixel: 2, n: 4 },
            "{m}"
        );
    }
    for m in [
        Method::Gouraud,
        Method::Euler,
        Method::CorrectedEuler,
        Method::Adaptive,
        Method::Angular,
    ] {
        let v = m.values(&opposite).unwrap();
        assert!(v.iter().all(|x| x.is_finite()), "{m}");
    }
    let odd = Span::new(tilt.clone(), v32(-0.6, 0.0, -0.8), up.clone(), 5).unwrap();
    assert!(Method::Phong
        .values(&odd)
        .unwrap()
        .iter()
        .all(|x| x.is_finite()));
    let mut out = vec![0f32; 5];
    for (name, r) in [
        (
            "spherical",
            phong_approx::related::spherical::shade(&opposite, &mut out),
        ),
        (
            "binary",
            phong_approx::related::binary::shade(&opposite, &mut out),
        ),
        (
            "bishop-weimer",
            phong_approx::related::bishop_weimer::shade(&opposite, &mut out),
        ),
    ] {
        assert_eq!(r.unwrap_err(), SpanError::Opposite, "{name}");
    }
    // Exact: a decimal normal that is not exactly unit is refused, and accepted after
    // normalizing.
    let na = Vec3::new(q(267, 1000), q(534, 1000), q(802, 1000));
    assert!(matches!(
        Span::new(
            na.clone(),
            Stereo(0, 0, 1).unit(),
            Stereo(0, 0, 1).unit(),
            3
        ),
        Err(SpanError::NotUnit { .. })
    ));
    let s = Span::normalized(na, Stereo(0, 0, 1).unit(), Stereo(0, 0, 1).unit(), 3).unwrap();
    assert!((s.e.clone() - Q::one()) < q(1, 1_000_000_000));
    // Messages name the input.
    let e = Span::new(up.clone(), v32(2.0, 0.0, 0.0), up.clone(), 3).unwrap_err();
    assert!(e.to_string().starts_with("Nb: not a unit vector"), "{e}");
}

#[test]
fn wrong_output_length_is_an_error_for_every_method() {
    let s = Span::new(
        v32(0.0, 0.0, 1.0),
        v32(0.6, 0.0, 0.8),
        v32(0.0, 0.0, 1.0),
        4,
    )
    .unwrap();
    for m in Method::ALL {
        let mut short = vec![0.0f32; 3];
        assert_eq!(
            m.shade(&s, &mut short),
            Err(SpanError::OutputLength {
                expected: 5,
                got: 3
            }),
            "{m}"
        );
    }
    assert!(matches!(
        Method::AngularTable(1).values(&s),
        Err(SpanError::Parameter(_))
    ));
}

#[test]
fn no_method_makes_a_nan_on_valid_input() {
    for_all_spans(64, |_, s| {
        let f = s.cast::<f32>().unwrap();
        for m in Method::ALL {
            let v = m.values(&f).map_err(|e| e.to_string())?;
            ensure(v.iter().all(|x| x.is_finite()), || {
                format!("{m} made a non-finite value")
            })?;
        }
        Ok(())
    });
}

#[test]
fn specular_power_and_eq_1() {
    // Exact powers by squaring, clamped below at 0.
    assert_eq!(power(&q(1, 2), 10), q(1, 1024));
    assert_eq!(power(&q(-1, 2), 3), q(0, 1));
    assert_eq!(power(&q(3, 4), 0), Q::one());
    assert!((power(&0.9f64, 50) - 0.9f64.powi(50)).abs() < 1e-15);
    // Eq. 1 with the clamp on both dot products.
    assert_eq!(
        intensity(&q(1, 2), &q(1, 4), 2, &q(3, 5), &q(4, 5)),
        q(3, 10) + q(4, 25)
    );
    assert_eq!(
        intensity(&q(1, 2), &q(1, 4), 2, &q(-3, 5), &q(-4, 5)),
        q(0, 1)
    );
    // Specular through a method: Phong's N·H then the power, pixel by pixel.
    let s = Span::new(
        Stereo(1, 0, 3).unit(),
        Stereo(-1, 1, 4).unit(),
        Stereo(1, 1, 5).unit(),
        6,
    )
    .unwrap();
    let mut out = vec![q(0, 1); 7];
    Method::CorrectedEuler
        .shade_specular(&s, 3, &mut out)
        .unwrap();
    let ce = Method::CorrectedEuler.values(&s).unwrap();
    for (o, c) in out.iter().zip(&ce) {
        assert_eq!(*o, power(c, 3));
    }
}

#[test]
fn quantizer_is_floor_of_255_v_clamped() {
    assert_eq!(level(&0.0f32), 0);
    assert_eq!(level(&-0.3f32), 0);
    assert_eq!(level(&1.0f32), 255);
    assert_eq!(level(&7.0f64), 255);
    assert_eq!(level(&q(100, 255)), 100);
    assert_eq!(level(&(q(100, 255) - q(1, 1_000_000))), 99);
    assert_eq!(level(&0.5f64), 127);
    assert_eq!(level(&f32::NAN), 0);
}

#[test]
fn gouraud_and_corrected_euler_match_their_closed_forms_exactly() {
    // Independent formulas, in exact rationals: Gouraud p_a + i(p_b − p_a)/n, corrected
    // Euler Gouraud − ds/2·i(n − i).
    for_all_spans(48, |_, s| {
        let n = qi(s.n);
        let g = Method::Gouraud.values(s).unwrap();
        let c = Method::CorrectedEuler.values(s).unwrap();
        for i in 0..=s.n {
            let x = qi(i);
            let gi = s.p_a.clone() + x.clone() * (s.p_b.clone() - s.p_a.clone()) / n.clone();
            eq("gouraud", &g[i as usize], &gi)?;
            let ci = gi - s.ds.clone() / q(2, 1) * x.clone() * (n.clone() - x);
            eq("corrected euler", &c[i as usize], &ci)?;
        }
        Ok(())
    });
}

/// Issue item "no infinity with exit 0": on nearly opposite normals every method's
/// float values are finite or the run is [`SpanError::NotFiniteValue`] (one check in
/// `Method::run` for every method, the related ones included) — never an infinity or
/// NaN handed back. The two spans are the reproductions that printed `inf` (binary, an
/// exact unit `N_b` 179.99° from `N_a`) and NaN (Bishop–Weimer, normalized).
#[test]
fn every_method_returns_finite_values_or_a_typed_error() {
    use phong_approx::method::Prepared;
    use phong_approx::parse::parse_vec3;
    use phong_approx::{Real, Scalar};
    fn all_methods<T: Real>(na: &str, nb: &str, l: &str, n: u32, normalize: bool) -> usize {
        let v = |s: &str| parse_vec3(s).unwrap().cast::<T>().unwrap();
        let span = if normalize {
            Span::normalized(v(na), v(nb), v(l), n)
        } else {
            Span::new(v(na), v(nb), v(l), n)
        }
        .unwrap();
        let mut refused = 0;
        for m in Method::ALL {
            let mut out = vec![T::zero(); span.len()];
            let prep = Prepared::new(m, T::one()).unwrap();
            match m.run(&span, &prep, &mut out) {
                Ok(_) => assert!(
                    out.iter().all(Scalar::is_finite),
                    "{m} in {}: a value is not finite",
                    T::NAME
                ),
                Err(SpanError::NotFiniteValue { pixel, n: sn }) => {
                    assert!(pixel <= sn as usize);
                    refused += 1;
                }
                Err(SpanError::Opposite | SpanError::ZeroNormal { .. }) => {}
                Err(e) => panic!("{m} in {}: {e}", T::NAME),
            }
        }
        refused
    }
    let far = "200000/10000000001,0,-9999999999/10000000001";
    for normalize in [false, true] {
        assert!(all_methods::<f32>("0,0,1", far, "0.6,0,0.8", 2, normalize) > 0);
        all_methods::<f64>("0,0,1", far, "0.6,0,0.8", 2, normalize);
    }
    assert!(all_methods::<f32>("0,0,1", "1e-10,0,-1", "0.6,0,0.8", 2, true) > 0);
    all_methods::<f64>("0,0,1", "1e-10,0,-1", "0.6,0,0.8", 2, true);
}

/// Item 10 of the third reliability round: `Span::normalized` accepts any finite
/// non-zero vector in floats too — its squared length may underflow (1e-170 in f64,
/// 1e-23 in f32) or overflow, since it scales by the largest component first.
#[test]
fn normalize_takes_tiny_and_huge_float_vectors() {
    let up64 = Vec3::new(0.0f64, 0.0, 1.0);
    for v in [
        Vec3::new(1e-170, 0.0, 1e-170),
        Vec3::new(1e-300, 0.0, 1e-300),
        Vec3::new(1e300, 0.0, 1e300),
    ] {
        let s = Span::normalized(v, up64.clone(), up64.clone(), 2).unwrap();
        assert!((s.p_a - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15);
    }
    let up32 = v32(0.0, 0.0, 1.0);
    for v in [v32(1e-23, 0.0, 1e-23), v32(1e-40, 0.0, 1e-40)] {
        let s = Span::normalized(v, up32.clone(), up32.clone(), 2).unwrap();
        assert!((s.p_a - std::f32::consts::FRAC_1_SQRT_2).abs() < 1e-6);
    }
    assert_eq!(
        Span::normalized(v32(0.0, 0.0, 0.0), up32.clone(), up32, 2).unwrap_err(),
        SpanError::ZeroVector { input: Input::Na }
    );
}
