//! The library called directly: meaningless tolerances refused, hostile arguments
//! give errors and no panics, exact transcendental functions at extreme arguments.

use super::*;

/// Defect q6 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn the_library_refuses_meaningless_tolerances() {
    use phong_approx::conformance::check::Tolerance;
    use phong_approx::testkit::Suite;
    use phong_approx::tolerance::profile::Profile;
    for t in [
        Tolerance::Abs(f64::NAN),
        Tolerance::Ulps(f64::NAN),
        Tolerance::Abs(f64::INFINITY),
        Tolerance::Abs(-1.0),
        Tolerance::Profile {
            profile: Profile::Fixed {
                int_bits: 64,
                frac_bits: u32::MAX,
            },
            format: phong_approx::Format::Binary32,
            form: phong_approx::tolerance::profile::Form::Any,
        },
        Tolerance::Profile {
            profile: Profile::Fixed {
                int_bits: 1 << 31,
                frac_bits: 16,
            },
            format: phong_approx::Format::Binary32,
            form: phong_approx::tolerance::profile::Form::Any,
        },
    ] {
        assert!(t.validate().is_err(), "{t:?}");
        // The test kit fails every set with the reason (no pass, no panic).
        let r = Suite::published()
            .tolerance(t)
            .check_f32(|s| vec![3.0; s.n as usize + 1]);
        assert!(!r.is_ok(), "{t:?}");
    }
}

/// Defect q7 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn exact_cosine_of_large_arguments() {
    use phong_approx::reference::transcendental::cos;
    // cos(10^100), computed independently with Python's decimal module at 250 digits
    // (π by Machin's formula, 10^100 reduced modulo 2π, the Taylor series).
    use phong_approx::Scalar;
    let x = BigRational::from_integer(BigInt::from(10).pow(100u32));
    assert_eq!(cos(&x).to_decimal(30), "-0.928081905074655343456194643777");
    // And cos(x)² + cos(x − π/2)² = 1 for a large x, which a wrong reduction breaks.
    let x = BigRational::from_integer(BigInt::from(10).pow(25u32));
    let half_pi = phong_approx::reference::transcendental::frac_pi_2();
    let (a, b) = (cos(&x), cos(&(x.clone() - half_pi)));
    let one = a.clone() * a + b.clone() * b - BigRational::from_integer(1.into());
    assert!(
        one.abs() < BigRational::new(1.into(), BigInt::from(1) << 240),
        "{one}"
    );
}

/// Defect q11 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn hostile_library_arguments_give_errors_not_panics() {
    use phong_approx::fixed_span::FixedSpan;
    use phong_approx::testkit::Suite;
    use phong_approx::tolerance::profile::{fixed_bound, Profile};
    use phong_approx::{Method, Span, Vec3};
    assert_eq!(fixed_bound(Method::Gouraud, 4, 1.0, 64, 1 << 31), None);
    assert_eq!(fixed_bound(Method::Gouraud, 4, 1.0, 1 << 31, 16), None);
    assert!(Profile::Fixed {
        int_bits: 64,
        frac_bits: 1 << 31
    }
    .validate()
    .is_err());
    let r = Suite::published()
        .method(Method::AngularTable(512))
        .check_f32(|s| vec![0.0; s.n as usize + 1]);
    assert!(!r.is_ok());
    assert!(r.to_string().contains("angular-table512"), "{r}");
    let r = Suite::set("nope").check_f32(|s| vec![0.0; s.n as usize + 1]);
    assert!(
        !r.is_ok() && r.to_string().contains("no published set 'nope'"),
        "{r}"
    );
    // A span that is not unit (normalized inputs of huge length): refused, not a panic.
    let big = |x: i64| BigRational::from_integer(BigInt::from(x) << 80u32);
    let z = BigRational::from_integer(0.into());
    let v = Vec3::new(big(1), z.clone(), z.clone());
    if let Ok(s) = Span::normalized(v.clone(), v.clone(), v, 4) {
        let _ = FixedSpan::new(&s, 30);
    }
}

/// An exact request of two steps with `K_d = 1` and 30 digits, for the boundary test.
fn exact_request(
    method: phong_approx::Method,
    na: &phong_approx::Vec3<BigRational>,
    nb: &phong_approx::Vec3<BigRational>,
    l: &phong_approx::Vec3<BigRational>,
) -> phong_approx::span_report::Request {
    phong_approx::span_report::Request {
        method,
        na: na.clone(),
        nb: nb.clone(),
        l: l.clone(),
        n: 2,
        kd: BigRational::from_integer(1.into()),
        normalize: false,
        digits: 30,
        arithmetic: phong_approx::Arithmetic::Exact,
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
    /// No public constructor or validator panics on a value its type admits (debug
    /// build: overflow checks on).
    ///
    /// Defect q11 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
    #[test]
    fn public_constructors_never_panic(
        m in proptest::prelude::any::<u32>(),
        f in proptest::prelude::any::<u32>(),
        n in proptest::prelude::any::<u32>(),
        x in proptest::prelude::any::<f64>(),
        fi in 0usize..3,
        size in 0u32..4096,
    ) {
        use phong_approx::conformance::check::Tolerance;
        use phong_approx::tolerance::profile::{fixed_bound, Profile};
        use phong_approx::Method;
        let p = Profile::Fixed { int_bits: m, frac_bits: f };
        let _ = p.validate();
        for method in [Method::Gouraud, Method::CorrectedEuler, Method::Phong, Method::Duff, Method::Adaptive] {
            let _ = fixed_bound(method, n, x, m, f);
        }
        let format = phong_approx::Format::ALL[fi];
        for t in [Tolerance::Abs(x), Tolerance::Ulps(x), Tolerance::Profile { profile: p, format, form: phong_approx::tolerance::profile::Form::Any }] {
            let _ = t.validate();
        }
        let _ = phong_approx::angular::CosTable::<f64>::new(size);
    }
}

/// Finding 3 of the fifth reliability round: the oracle's digits are the CLI's, every
/// one known, and it keeps a budget.
#[test]
fn the_oracle_prints_only_known_digits_and_keeps_a_budget() {
    use phong_approx::testkit::{oracle, oracle_without_budget};
    use phong_approx::{Method, Span, Vec3};
    let q = |n: BigInt, d: BigInt| BigRational::new(n, d);
    // N_a on the unit circle through u = 1 + 10^-70: (2u, 0, u² − 1)/(u² + 1), so p_a
    // = (u² − 1)/(u² + 1) ≈ 10^-70 with L = z, and angular's pixel 0 is cos(acos p_a)
    // = p_a exactly.
    let ten70 = BigInt::from(10).pow(70u32);
    let u = q(ten70.clone() + 1, ten70);
    let one = BigRational::from_integer(1.into());
    let zero = BigRational::from_integer(0.into());
    let uu = u.clone() * u.clone();
    let na = Vec3::new(
        u.clone() * BigRational::from_integer(2.into()) / (uu.clone() + one.clone()),
        zero.clone(),
        (uu.clone() - one.clone()) / (uu.clone() + one.clone()),
    );
    let z = Vec3::new(zero.clone(), zero.clone(), one.clone());
    let span = Span::new(na.clone(), z.clone(), z.clone(), 2).unwrap();
    let o = oracle(Method::Angular, &span).unwrap();
    let got = phong_approx::parse::parse_rational(&o.decimals[0]).unwrap();
    let want = na.z.clone();
    // 30 significant digits: within 10^-29 relative.
    let rel = ((got - want.clone()) / want).abs();
    assert!(
        rel < q(1.into(), BigInt::from(10).pow(29u32)),
        "{}",
        o.decimals[0]
    );
    // Over the budget: refused at once, with the remedy; the unbudgeted call exists.
    let big = Span::new(z.clone(), z.clone(), z.clone(), 200_000).unwrap();
    let t = Instant::now();
    let e = oracle(Method::Angular, &big).unwrap_err();
    assert_eq!(
        e.remedy,
        phong_approx::span_report::Remedy::RunAnyway,
        "{e}"
    );
    assert!(t.elapsed() < Duration::from_secs(2));
    let small = Span::new(z.clone(), z.clone(), z, 3).unwrap();
    assert_eq!(
        oracle_without_budget(Method::Gouraud, &small)
            .unwrap()
            .levels,
        vec![Some(255); 4]
    );
}

/// The exact adaptive choice for normalized inputs (finding 2 of the fifth reliability
/// round) agrees with eq. 24 evaluated in rationals where the inputs are already unit.
#[test]
fn the_exact_adaptive_choice_is_the_rational_one_on_unit_inputs() {
    // Unit rational inputs normalize to themselves, so the choice in the field is
    // eq. 24's test evaluated in rationals (`adaptive::decide`), for every kd.
    use phong_approx::reference::unit::unit_from_ints;
    let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    let vs = [
        (0, 0, 1),
        (1, 0, 3),
        (-2, 1, 2),
        (3, 4, 7),
        (1, 1, 1),
        (0, -1, 5),
    ];
    let mut both = [0; 2];
    for a in vs {
        for b in vs {
            for l in vs {
                let (na, nb, l) = (
                    unit_from_ints(a.0, a.1, a.2),
                    unit_from_ints(b.0, b.1, b.2),
                    unit_from_ints(l.0, l.1, l.2),
                );
                for n in [1, 2, 3, 8] {
                    for kd in [q(1, 1), q(1, 10), q(1, 200)] {
                        let span =
                            phong_approx::Span::new(na.clone(), nb.clone(), l.clone(), n).unwrap();
                        let want = phong_approx::adaptive::decide(&span, &kd).choice;
                        let got = if phong_approx::reference::radical::normalized_adaptive_gouraud(
                            (&na, &nb, &l),
                            n,
                            &kd,
                        ) {
                            phong_approx::adaptive::Choice::Gouraud
                        } else {
                            phong_approx::adaptive::Choice::CorrectedEuler
                        };
                        assert_eq!(got, want, "{a:?} {b:?} {l:?} n = {n} kd = {kd}");
                        both[usize::from(got == phong_approx::adaptive::Choice::Gouraud)] += 1;
                    }
                }
            }
        }
    }
    assert!(both[0] > 0 && both[1] > 0, "{both:?}");
}

/// A rational unit vector `(x, 0, z)` whose `z` lies within 10^-100 of `target` (in
/// `(−1, 1]`), by inverse stereographic projection through `u ≈ √((1 − z)/(1 + z))`
/// rounded to 100 decimals: the constructions of the boundary test, exact rationals.
fn unit_with_z_near(target: &BigRational) -> phong_approx::Vec3<BigRational> {
    let one = BigRational::from_integer(1.into());
    let scale = BigInt::from(10).pow(100u32);
    let r = (one.clone() - target.clone()) / (one + target.clone());
    let u2 = (r.numer() * &scale * &scale) / r.denom();
    let u = BigRational::new(u2.sqrt(), scale);
    phong_approx::reference::unit::unit_from_stereo(&u, &BigRational::from_integer(0.into()))
}

/// `floor(255·clamp(v, 0, 1))` in integers: the expected level, independent of the
/// crate's own level code.
fn level_by_integers(v: &BigRational) -> u8 {
    use num_integer::Integer;
    let l = (v.numer() * BigInt::from(255)).div_floor(v.denom());
    l.max(BigInt::from(0))
        .min(BigInt::from(255))
        .to_string()
        .parse()
        .unwrap()
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 24, ..proptest::prelude::ProptestConfig::default() })]

    /// Values planted 10^-80 from every boundary the exact path decides on: a level
    /// boundary `k/255` (and the clamps at 0 and 1) for the rational and the
    /// transcendental methods alike, and eq. 24's threshold `255·|δ| = 1`. Each is
    /// decided as the exact rationals built here say (finding 1–3 of the fifth
    /// reliability round: nothing decided at a working precision).
    #[test]
    fn values_planted_next_to_a_boundary_are_decided_exactly(k in 0u32..=255, above in proptest::bool::ANY) {
        use phong_approx::span_report::exact_run;
        use phong_approx::{Method, Vec3};
        let tiny = BigRational::new(1.into(), BigInt::from(10).pow(80u32));
        let boundary = BigRational::new(k.into(), 255.into());
        let target = if above { boundary + tiny.clone() } else { boundary - tiny.clone() };
        proptest::prop_assume!(target <= BigRational::from_integer(1.into()) && target > BigRational::from_integer((-1).into()));
        let n = unit_with_z_near(&target);
        let z = Vec3::new(BigRational::from_integer(0.into()), BigRational::from_integer(0.into()), BigRational::from_integer(1.into()));
        let want = level_by_integers(&n.z);
        for method in [Method::Gouraud, Method::CorrectedEuler, Method::Phong, Method::Duff, Method::Angular, Method::Adaptive] {
            let run = exact_run(&exact_request(method, &n, &n, &z)).unwrap();
            proptest::prop_assert_eq!(&run.levels, &vec![Some(want); 3], "{} at k = {}, above = {}", method, k, above);
        }
        // Eq. 24's threshold: N_a = L = z, N_b = (x, 0, c), n = 2: δ = −(1 − c²)/8, so
        // 255·|δ| = 1 ± 10^-80 for c² = 1 − 8(1 ± 10^-80)/255.
        let side = if above { BigRational::from_integer(1.into()) + tiny.clone() } else { BigRational::from_integer(1.into()) - tiny };
        let c2 = BigRational::from_integer(1.into()) - side * BigRational::new(8.into(), 255.into());
        // c = √c2 to 100 digits, as a rational point of the circle.
        let c = {
            let s = BigInt::from(10).pow(100u32);
            BigRational::new(((c2.numer() * &s * &s) / c2.denom()).sqrt(), s)
        };
        let nb = unit_with_z_near(&c);
        let delta255 = (BigRational::from_integer(1.into()) - nb.z.clone() * nb.z.clone()) * BigRational::new(255.into(), 8.into());
        let gouraud = delta255 < BigRational::from_integer(1.into());
        let r = exact_request(Method::Adaptive, &z, &nb, &z);
        let run = exact_run(&r).unwrap();
        let d = phong_approx::span_report::span_report(&r).unwrap();
        let got = serde_json::to_value(&d).unwrap();
        proptest::prop_assert_eq!(got["decision"].as_str().unwrap(), if gouraud { "gouraud" } else { "corrected-euler" });
        proptest::prop_assert_eq!(run.levels.len(), 3);
    }
}
