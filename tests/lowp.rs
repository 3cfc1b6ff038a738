//! The low-precision scalars: binary16 rounding, fixed-point rounding and saturation,
//! and spans set up in each format. Reference: exact rationals.

use crate::common;

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

// ---------------------------------------------------------------------------
// Fixed point as a hardware span unit runs it (`src/fixed_span.rs`): set-up
// rounded once to f fractional bits, loop in exact integer additions. The three
// tests below are the theorems of proofs/Fixed.v of the same names.

mod fixed {
    use super::common::*;
    use phong_approx::fixed_span::{
        bits_for_half_level, corrected_euler_bound, gouraud_bits_for_half_level, gouraud_bound,
        FixedSpan,
    };
    use phong_approx::{Method, Scalar};
    use proptest::strategy::{Strategy, ValueTree};
    use proptest::test_runner::TestRunner;

    /// Edge, targeted and random spans.
    fn spans() -> Vec<(Case, phong_approx::Span<Q>)> {
        let mut cases = edge_cases();
        cases.extend(targeted_cases().into_iter().filter(|c| c.n <= 1024));
        let mut runner = TestRunner::deterministic();
        for _ in 0..300 {
            cases.push(arb_case().new_tree(&mut runner).unwrap().current());
        }
        cases
            .into_iter()
            .filter_map(|c| c.span().map(|s| (c, s)))
            .collect()
    }

    /// `|fixed − exact|` at every pixel, and whether the loop was exact (its values
    /// are the closed form of the rounded set-up, `p_a + i·t_0 + i(i − 1)/2·ds`).
    fn errors(f: &FixedSpan, raw: &[i64], exact: &[Q], gouraud: bool) -> Vec<Q> {
        for (i, &r) in raw.iter().enumerate() {
            let i = i as i64;
            let closed = if gouraud {
                f.p_a + i * f.dp
            } else {
                f.p_a + i * f.t0 + i * (i - 1) / 2 * f.ds
            };
            assert_eq!(r, closed, "the integer loop is exact");
        }
        raw.iter()
            .zip(exact)
            .map(|(&r, e)| {
                let d = f.value(r) - e.clone();
                if d < Q::from_integer(0.into()) {
                    -d
                } else {
                    d
                }
            })
            .collect()
    }

    #[test]
    fn fixed_point_corrected_euler_error() {
        for (c, s) in spans() {
            let exact = Method::CorrectedEuler.values(&s).unwrap();
            for bits in [8, 12, 16, 20, 24, 32] {
                let f = FixedSpan::new(&s, bits).unwrap();
                for (i, e) in errors(&f, &f.corrected_euler(), &exact, false)
                    .iter()
                    .enumerate()
                {
                    let b = corrected_euler_bound(i as u32, bits);
                    assert!(
                        e.to_f64() <= b,
                        "f = {bits}, pixel {i}: {} > {b}: {c:?}",
                        e.to_f64()
                    );
                }
            }
        }
    }

    #[test]
    fn fixed_point_gouraud_error() {
        for (c, s) in spans() {
            let exact = Method::Gouraud.values(&s).unwrap();
            for bits in [8, 12, 16, 20, 24, 32] {
                let f = FixedSpan::new(&s, bits).unwrap();
                for (i, e) in errors(&f, &f.gouraud(), &exact, true).iter().enumerate() {
                    let b = gouraud_bound(i as u32, bits);
                    assert!(
                        e.to_f64() <= b,
                        "f = {bits}, pixel {i}: {} > {b}: {c:?}",
                        e.to_f64()
                    );
                }
            }
        }
    }

    /// The table of docs/float.md, recomputed from its definition in floating point
    /// (⌈log2(255·(n² + n + 2))⌉ − 1), and corrected Euler within half a level on
    /// every span with that many bits.
    #[test]
    fn fixed_point_half_level_bits() {
        let table = [
            (1, 9),
            (2, 10),
            (4, 12),
            (8, 14),
            (16, 16),
            (32, 18),
            (64, 20),
            (128, 22),
            (256, 24),
            (512, 25),
            (1024, 27),
            (2048, 29),
            (4096, 31),
        ];
        for (n, bits) in table {
            let nf = f64::from(n);
            let by_log = (255.0 * (nf * nf + nf + 2.0)).log2().ceil() as u32 - 1;
            assert_eq!(bits_for_half_level(n), bits, "n = {n}");
            assert_eq!(by_log, bits, "n = {n}");
            assert!(corrected_euler_bound(n, bits) <= 1.0 / 510.0);
            assert!(corrected_euler_bound(n, bits - 1) > 1.0 / 510.0);
        }
        assert_eq!(gouraud_bits_for_half_level(4096), 20);
        assert!(gouraud_bound(4096, 20) <= 1.0 / 510.0);
        for (c, s) in spans() {
            let bits = bits_for_half_level(s.n);
            let f = FixedSpan::new(&s, bits).unwrap();
            let exact = Method::CorrectedEuler.values(&s).unwrap();
            for (i, e) in errors(&f, &f.corrected_euler(), &exact, false)
                .iter()
                .enumerate()
            {
                assert!(e.to_f64() <= 1.0 / 510.0, "pixel {i}, {bits} bits: {c:?}");
            }
        }
    }

    /// binary16 has no such guarantee: its unit roundoff 2^-11 is already half of
    /// half a level, and spans of up to 64 steps run in binary16 (inputs, set-up and
    /// loop) miss their exact run by more than half a level.
    #[test]
    fn binary16_corrected_euler_misses_half_a_level() {
        use phong_approx::lowp::f16;
        let worst = spans()
            .iter()
            .filter(|(_, s)| s.n <= 64)
            .map(|(_, s)| {
                let h = s.cast::<f16>().unwrap();
                let got = Method::CorrectedEuler.values(&h).unwrap();
                let exact = Method::CorrectedEuler.values(s).unwrap();
                got.iter()
                    .zip(&exact)
                    .map(|(g, e)| (g.to_f64() - e.to_f64()).abs())
                    .fold(0.0, f64::max)
            })
            .fold(0.0, f64::max);
        assert!(worst > 1.0 / 510.0, "worst binary16 error {worst}");
    }

    /// `|fixed − exact|` at every pixel, as `f64` (the errors here are far above
    /// `f64`'s rounding of an exact rational).
    fn abs_errors(f: &FixedSpan, raw: &[i64], exact: &[Q]) -> Vec<f64> {
        raw.iter()
            .zip(exact)
            .map(|(&r, e)| (f.value(r) - e.clone()).to_f64().abs())
            .collect()
    }

    /// Plain Euler's loop: the same bound as corrected Euler's, and the registers'
    /// reach of the catalogue row (`|p_i| ≤ 5`, `|s_i|·n ≤ 12`, docs/float.md §14).
    #[test]
    fn fixed_point_euler_error() {
        for (c, s) in spans() {
            let exact = Method::Euler.values(&s).unwrap();
            let n = Q::from_integer(s.n.into());
            let mut slope = s.di_a.clone();
            for e in exact.iter() {
                assert!(e.to_f64().abs() <= 5.0, "value {e}: {c:?}");
                assert!((slope.clone() * n.clone()).to_f64().abs() <= 12.0, "{c:?}");
                slope += s.ds.clone();
            }
            for bits in [8, 16, 24, 32] {
                let f = FixedSpan::new(&s, bits).unwrap();
                for (i, e) in abs_errors(&f, &f.euler(), &exact).iter().enumerate() {
                    let b = corrected_euler_bound(i as u32, bits);
                    assert!(*e <= b, "f = {bits}, pixel {i}: {e} > {b}: {c:?}");
                }
            }
        }
    }

    /// The unit's `δ̂ = k·dp − k·t_0 − T·ds` on the rounded set-up is within
    /// `h(2k + T)` of eq. 24's exact `δ`.
    #[test]
    fn fixed_point_adaptive_delta_error() {
        use phong_approx::tolerance::profile::fixed_adaptive_band;
        for (c, s) in spans() {
            let exact = phong_approx::adaptive::decide(&s, &Q::from_integer(1.into())).delta;
            for bits in [8, 16, 24, 32] {
                let f = FixedSpan::new(&s, bits).unwrap();
                let k = i128::from(s.n.div_ceil(2));
                let raw = k * i128::from(f.dp)
                    - k * i128::from(f.t0)
                    - k * (k - 1) / 2 * i128::from(f.ds);
                let got = Q::new(raw.into(), num_bigint::BigInt::from(1) << bits);
                let e = (got - exact.clone()).to_f64().abs();
                let band = fixed_adaptive_band(s.n, bits);
                assert!(e <= band, "f = {bits}: {e} > {band}: {c:?}");
            }
        }
    }

    /// Outside the band `|255·|δ| − 1| ≤ 255·e_δ` the unit picks what the exact test
    /// picks; its run is then that method's loop.
    #[test]
    fn fixed_point_adaptive_decision() {
        use phong_approx::adaptive::{decide, Choice};
        use phong_approx::tolerance::profile::fixed_adaptive_band;
        let (mut outside, mut inside) = (0, 0);
        for (c, s) in spans() {
            let d = decide(&s, &Q::from_integer(1.into()));
            let x = (d.delta.to_f64() * 255.0).abs();
            for bits in [8, 12, 16, 24] {
                let f = FixedSpan::new(&s, bits).unwrap();
                let pick = f.adaptive_choice();
                let run = match pick {
                    Choice::Gouraud => f.gouraud(),
                    Choice::CorrectedEuler => f.corrected_euler(),
                };
                assert_eq!(f.adaptive(), run);
                if (x - 1.0).abs() > 255.0 * fixed_adaptive_band(s.n, bits) + 1e-12 {
                    outside += 1;
                    assert_eq!(pick, d.choice, "f = {bits}, |255δ| = {x}: {c:?}");
                } else {
                    inside += 1;
                }
            }
        }
        assert!(
            outside > 100 && inside > 0,
            "{outside} outside, {inside} inside"
        );
    }

    /// The value step alone: any `p̂`, `q̂` within `E_p`, `E_q` of `p`, `q`
    /// (`|p| ≤ √q`, `q ≥ q_min`), a root `ŝ ∈ (√q̂ − 2h, √q̂]` and a quotient within
    /// `2h` of `p̂/ŝ` — the extremes of each taken — stay within the bound.
    #[test]
    fn fixed_point_duff_error() {
        let mut runner = TestRunner::deterministic();
        let unit = proptest::num::f64::POSITIVE | proptest::num::f64::NORMAL;
        let mut tried = 0;
        for _ in 0..2000 {
            let mut draw = || unit.new_tree(&mut runner).unwrap().current() % 1.0;
            let (q_min, h) = (draw().max(1e-3), 2f64.powi(-10 - (draw() * 30.0) as i32));
            let (ep, eq) = (h * (1.0 + draw() * 100.0), h * (1.0 + draw() * 100.0));
            if q_min <= eq || (q_min - eq).sqrt() <= 2.0 * h * (1.0 + 1e-9) {
                continue;
            }
            tried += 1;
            let r = (q_min - eq).sqrt();
            let bound = (ep + eq / (2.0 * r) + 2.0 * h) / (r - 2.0 * h) + 2.0 * h;
            let q = q_min + draw() * (1.0 - q_min);
            let p = q.sqrt() * (2.0 * draw() - 1.0);
            for (sp, sq, ss, sv) in [
                (1.0, -1.0, 1.0, 1.0),
                (-1.0, 1.0, 0.0, -1.0),
                (1.0, 1.0, 1.0, 1.0),
            ] {
                let (ph, qh) = (p + sp * ep, q + sq * eq);
                let sh = qh.sqrt() - ss * 2.0 * h * (1.0 - 1e-9);
                let vh = ph / sh + sv * 2.0 * h;
                let err = (vh - p / q.sqrt()).abs();
                assert!(
                    err <= bound * (1.0 + 1e-9),
                    "{err} > {bound}: p {p}, q {q}, h {h}"
                );
            }
        }
        assert!(tried > 1000, "{tried} cases");
    }

    /// Duff's unit — the loops of `p` and `q`, then the truncated square root and
    /// divider — within `(E_p + E_q/(2r) + 2h)/(r − 2h) + 2h` of `p/√q` at every pixel,
    /// `r = √(q_min − E_q)`, wherever that is defined (`fixed_bound`). The exact value
    /// is taken in `f64` from the exact `p` and `q` (within 2^-50, far below any bound
    /// here, which is at least 2^-33).
    #[test]
    fn fixed_point_duff_unit_error() {
        use phong_approx::tolerance::profile::fixed_bound;
        let mut bounded = 0;
        for (c, s) in spans() {
            let q_min = s.q_min().to_f64() * (1.0 - 1e-15);
            let exact: Vec<f64> = (0..=s.n)
                .map(|i| {
                    let i = Q::from_integer(i.into());
                    let p = s.a.clone() * i.clone() + s.b.clone();
                    let q = (s.c.clone() * i.clone() + s.d.clone()) * i + s.e.clone();
                    p.to_f64() / q.to_f64().sqrt()
                })
                .collect();
            for bits in [16, 24, 32] {
                let Some(b) = fixed_bound(Method::Duff, s.n, q_min, 64, bits) else {
                    continue;
                };
                bounded += 1;
                let f = FixedSpan::new(&s, bits).unwrap();
                for (i, (&r, e)) in f.duff().iter().zip(&exact).enumerate() {
                    let got = r as f64 * 2f64.powi(-(bits as i32));
                    let err = (got - e).abs();
                    assert!(err <= b, "f = {bits}, pixel {i}: {err} > {b}: {c:?}");
                }
            }
        }
        assert!(bounded > 500, "{bounded} spans bounded");
    }

    /// The hardware units' twins (bit for bit the units of harness/hdl/) pass
    /// `check --profile fixed:M.F` on every published set; planted bugs fail on at
    /// least one: ε/(n+1) for ε/n, a set-up truncated to F bits where the theorem
    /// rounds to nearest, one pixel too few, and Duff's first difference D for C + D.
    #[test]
    fn hardware_twins_pass_their_fixed_bounds_and_bugs_fail() {
        use phong_approx::conformance::check::{check, Criteria, Tolerance};
        use phong_approx::conformance::integrity::case_span;
        use phong_approx::testkit::published;
        use phong_approx::tolerance::profile::{Form, Profile};
        type Run = fn(&FixedSpan, &phong_approx::Span<Q>) -> Vec<i64>;
        let verdict = |set: &str, method: Method, f: u32, run: Run| -> usize {
            let file = published(set).unwrap();
            let mut results = std::collections::HashMap::new();
            for c in &file.cases {
                let s = case_span(c).unwrap();
                let fs = FixedSpan::new(&s, f).unwrap();
                let v = run(&fs, &s);
                let v = v.iter().map(|&r| r as f64 * 2f64.powi(-(f as i32)));
                results.insert(c.id.clone(), v.collect());
            }
            let tol = Tolerance::Profile {
                profile: Profile::Fixed {
                    int_bits: 8,
                    frac_bits: f,
                },
                format: phong_approx::Format::Binary64,
                form: Form::Any,
            };
            let r = check(file, &results, &Criteria::new(method, tol)).unwrap();
            r.iter().filter(|c| !c.pass).count()
        };
        let good: [(Method, Run); 5] = [
            (Method::Gouraud, |f, _| f.gouraud()),
            (Method::Euler, |f, _| f.euler()),
            (Method::CorrectedEuler, |f, _| f.corrected_euler()),
            (Method::Adaptive, |f, _| f.adaptive()),
            (Method::Duff, |f, _| f.duff()),
        ];
        for set in ["typical", "edge", "paper"] {
            for (m, run) in good {
                assert_eq!(verdict(set, m, 40, run), 0, "{m} on {set}");
            }
        }
        // `x` rounded to the grid of `f`, to nearest, as the unit's host rounds.
        fn grid(x: Q, f: &FixedSpan) -> i64 {
            let raw = (x * Q::from_integer(num_bigint::BigInt::from(1) << f.frac_bits)).round();
            i64::try_from(raw.to_integer()).unwrap()
        }
        // ε/(n+1): t_0 = di_a − ε/(n + 1).
        let eps_n1: Run = |f, s| {
            let n1 = Q::from_integer((s.n + 1).into());
            let t0 = s.di_a.clone() - s.eps.clone() / n1;
            let g = FixedSpan {
                t0: grid(t0, f),
                ..*f
            };
            g.corrected_euler()
        };
        // The set-up rounded to F + 8 bits, then truncated to F.
        let truncated: Run = |f, s| {
            let fine = FixedSpan::new(s, f.frac_bits + 8).unwrap();
            let t = |x: i64| x >> 8;
            let g = FixedSpan {
                p_a: t(fine.p_a),
                t0: t(fine.t0),
                ds: t(fine.ds),
                ..*f
            };
            g.corrected_euler()
        };
        let short: Run = |f, _| {
            let mut v = f.corrected_euler();
            v.pop();
            v
        };
        // Duff's first difference D for C + D (eq. 7).
        let first_difference: Run = |f, s| {
            let g = FixedSpan {
                dq0: grid(s.d.clone(), f),
                ..*f
            };
            g.duff()
        };
        let bugs: [(&str, Method, u32, Run); 4] = [
            ("eps/(n+1)", Method::CorrectedEuler, 24, eps_n1),
            ("truncated set-up", Method::CorrectedEuler, 24, truncated),
            ("one pixel too few", Method::CorrectedEuler, 40, short),
            ("D for C + D", Method::Duff, 40, first_difference),
        ];
        for (what, m, f, run) in bugs {
            let failed: usize = ["typical", "edge", "paper"]
                .iter()
                .map(|set| verdict(set, m, f, run))
                .sum();
            assert!(failed > 0, "{what}: every published set passes");
        }
    }
}
