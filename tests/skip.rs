//! The specular skip test (`phong_approx::skip`, the paper's §7.1 question a), exactly
//! in rationals: a span it skips has specular level 0 at every pixel and at random
//! points between pixels — the levels computed from the definition, pixel by pixel
//! (in `f64` far from the threshold, exactly near it), not from the test's
//! candidates —; the cost of its conservatism; the paper's cheap
//! test (corrected Euler's quadratic) against Phong's values; the typed errors.
//! Theorems: `proofs/Skip.v`.

use super::common::coq::statement;
use super::common::*;
use num_traits::{One, Zero};
use phong_approx::skip::float::{float_skips, FloatSpan, Margins};
use phong_approx::skip::{phong_candidates, specular_skips, SkipError};
use phong_approx::specular::power;
use phong_approx::Format;
use phong_approx::Vec3;
use phong_approx::{Method, Span};
use proptest::strategy::{Strategy, ValueTree};

/// The shininess values tried: the comparison's, and 1 and 2 (the default tier 1, 8
/// and 128).
fn shininess() -> Vec<u32> {
    tiered(vec![1, 8, 128], vec![1, 2, 8, 32, 64, 128])
}

fn r(a: i64, b: i64) -> Q {
    Q::new(a.into(), b.into())
}

/// `K_s` values tried: 1, 1/2 (the extensive tier) and 3/1000, near the threshold's
/// scale.
fn ks_values() -> Vec<Q> {
    tiered(
        vec![r(1, 1), r(3, 1000)],
        vec![r(1, 1), r(1, 2), r(3, 1000)],
    )
}

/// Whether `255·K_s·v^s < 1` for `v = x^{1/2}` (`half`) or `v = x`, `x > 0`: in `f64`
/// (`powf`) where that is more than `10⁻⁶` from 1 relative — far beyond `powf`'s and
/// the conversions' errors —, else exactly in rationals (`x^s` against
/// `1/(255·K_s)²` when `half`).
fn below_threshold(x: &Q, ks: &Q, sh: u32, half: bool) -> bool {
    use num_traits::ToPrimitive;
    let k = Q::from_integer(255.into()) * ks;
    let xf = x.to_f64().unwrap();
    let e = if half {
        f64::from(sh) / 2.0
    } else {
        f64::from(sh)
    };
    let y = k.to_f64().unwrap() * xf.powf(e);
    if y.is_finite() && y < 1.0 - 1e-6 {
        true
    } else if y.is_finite() && y > 1.0 + 1e-6 {
        false
    } else if half {
        &k * &k * power(x, sh) < Q::one()
    } else {
        &k * power(x, sh) < Q::one()
    }
}

/// Phong's specular level at real `t` of `s` is 0, from the definition: `p ≤ 0`, or
/// `255·K_s·(p²/q)^{s/2} < 1`.
fn phong_level_is_zero(s: &Span<Q>, t: &Q, ks: &Q, sh: u32) -> bool {
    let p = &s.b + &s.a * t;
    let q = &s.e + &s.d * t + &s.c * t * t;
    p <= Q::zero() || below_threshold(&(&p * &p / q), ks, sh, true)
}

/// Whether the 8-bit level of `K_s·max(0, v)^s` is 0.
fn level_is_zero(v: &Q, ks: &Q, sh: u32) -> bool {
    *v <= Q::zero() || below_threshold(v, ks, sh, false)
}

/// Random points of `[0, n]` (rational, between the pixels).
fn between(n: u32) -> Vec<Q> {
    (0..8).map(|k| r(i64::from(n) * (2 * k + 1), 16)).collect()
}

/// The spans the tests decide on: the edge and targeted spans (n ≤ 16; 1024 in the
/// extensive tier) and seeded random ones.
fn spans() -> Vec<Span<Q>> {
    sample_spans(tiered(16, 1024), tiered(16, 512))
}

/// `f(span, s, K_s)` for every span of [`spans`], shininess and `K_s`.
fn each_decision(mut f: impl FnMut(&Span<Q>, u32, &Q)) {
    for s in spans() {
        for sh in shininess() {
            for ks in ks_values() {
                f(&s, sh, &ks);
            }
        }
    }
}

/// The quadratic methods and their `s_0` and `ds` (eqs. 13, 17; Gouraud's line:
/// `ds = 0`).
fn quadratics(s: &Span<Q>) -> [(Method, Q, Q); 3] {
    [
        (Method::CorrectedEuler, s.t0.clone(), s.ds.clone()),
        (Method::Euler, s.di_a.clone(), s.ds.clone()),
        (Method::Gouraud, (&s.p_b - &s.p_a) / &s.n_s, Q::zero()),
    ]
}

/// `phong_skip_sound` (proofs/Skip.v): where Phong's test skips a span, the level of
/// `K_s·max(0, p/√q)^s` is 0 at points between the pixels too; Duff and symmetric
/// Phong, whose exact values are Phong's, take the same decision.
#[test]
fn phong_skip_sound() {
    let mut skips = 0;
    each_decision(|s, sh, ks| {
        let skip = specular_skips(Method::Phong, s, ks, sh).unwrap();
        for m in [Method::Duff, Method::SymmetricPhong] {
            assert_eq!(specular_skips(m, s, ks, sh).unwrap(), skip, "{m}");
        }
        if skip {
            skips += 1;
            for t in between(s.n) {
                assert!(
                    phong_level_is_zero(s, &t, ks, sh),
                    "t = {t}: s = {sh}, K_s = {ks}, {s:?}"
                );
            }
        }
    });
    // The test must skip (it would pass vacuously otherwise).
    assert!(skips > tiered(20, 400), "{skips} skips");
}

/// `phong_skip_levels` (proofs/Skip.v): where Phong's test skips a span, every pixel's
/// specular level is 0 — each decided from `p_i` and `q_i`, not from the candidates.
/// Prints how often a span whose pixels are all at level 0 is not skipped (the test
/// bounds every real `t ∈ [0, n]`, not only the pixels).
#[test]
fn phong_skip_levels() {
    let (mut skips, mut conservative, mut all) = (0, 0, 0);
    each_decision(|s, sh, ks| {
        all += 1;
        let zero = (0..=s.n).all(|i| phong_level_is_zero(s, &Q::from_integer(i.into()), ks, sh));
        if specular_skips(Method::Phong, s, ks, sh).unwrap() {
            skips += 1;
            assert!(zero, "a pixel above level 0: s = {sh}, K_s = {ks}, {s:?}");
        } else if zero {
            conservative += 1;
        }
    });
    println!(
        "Phong: {all} decisions, {skips} skips, {conservative} not skipped with every pixel at level 0"
    );
    assert!(skips > tiered(20, 400), "{skips} skips");
}

/// `quadratic_skip_sound` (proofs/Skip.v): where the test skips corrected Euler's,
/// Euler's or Gouraud's quadratic, `K_s·max(0, v(t))^s` is below one level at points
/// between the pixels too (`v` by eq. 17's closed form in `t`).
#[test]
fn quadratic_skip_sound() {
    let mut skips = 0;
    let half = r(1, 2);
    each_decision(|s, sh, ks| {
        for (m, s0, ds) in quadratics(s) {
            if specular_skips(m, s, ks, sh).unwrap() {
                skips += 1;
                for t in between(s.n) {
                    let v = &s.p_a + &t * &s0 + &t * (&t - Q::one()) * &half * &ds;
                    assert!(
                        level_is_zero(&v, ks, sh),
                        "{m} at t = {t}: s = {sh}, K_s = {ks}"
                    );
                }
            }
        }
    });
    assert!(skips > tiered(60, 1200), "{skips} skips");
}

/// `quadratic_skip_levels` (proofs/Skip.v): where the test skips corrected Euler,
/// Euler or Gouraud, every pixel's level is 0 — the values of the method's own exact
/// run (its recurrence in rationals), not its closed form.
#[test]
fn quadratic_skip_levels() {
    let (mut skips, mut conservative) = (0, 0);
    each_decision(|s, sh, ks| {
        for (m, _, _) in quadratics(s) {
            let zero = m
                .values(s)
                .unwrap()
                .iter()
                .all(|v| level_is_zero(v, ks, sh));
            if specular_skips(m, s, ks, sh).unwrap() {
                skips += 1;
                assert!(
                    zero,
                    "{m}: a pixel above level 0: s = {sh}, K_s = {ks}, {s:?}"
                );
            } else if zero {
                conservative += 1;
            }
        }
    });
    println!("quadratics: {skips} skips, {conservative} not skipped with every pixel at level 0");
    assert!(skips > tiered(60, 1200), "{skips} skips");
}

/// At Phong's candidates (`0`, `n`, the root `t*` of its derivative's numerator) lies
/// its largest value on the span: no rational point between the pixels is above the
/// largest candidate (compared through `p²/q` where `p > 0`).
#[test]
fn phongs_largest_value_is_at_a_candidate() {
    let f2 = |s: &Span<Q>, t: &Q| {
        let p = &s.b + &s.a * t;
        let q = &s.e + &s.d * t + &s.c * t * t;
        (p.clone() > Q::zero()).then(|| &p * &p / q)
    };
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let mut inner = 0;
    for _ in 0..tiered(64, 2048) {
        let Some(s) = arb_case().new_tree(&mut runner).unwrap().current().span() else {
            continue;
        };
        let candidates = phong_candidates(&s);
        inner += usize::from(candidates.len() == 3);
        let top = candidates.iter().filter_map(|t| f2(&s, t)).max();
        for k in 0..=64 {
            let t = r(i64::from(s.n) * k, 64);
            if let Some(v) = f2(&s, &t) {
                assert!(
                    top.as_ref().is_some_and(|m| v <= *m),
                    "t = {t}: above every candidate"
                );
            }
        }
    }
    // The inner root must be exercised.
    assert!(inner > 10, "{inner} spans with an inner candidate");
}

/// The paper's cheap test — corrected Euler's quadratic from `p_a`, `t_0` and `ds`,
/// which the recurrence computes anyway — against Phong's values: where it skips
/// but Phong's levels are not all 0 (a wrong skip for Phong), corrected Euler's own
/// levels are still all 0 (what it guarantees); and how often each happens.
#[test]
fn the_cheap_test_guarantees_corrected_eulers_levels() {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let (mut wrong, mut missed, mut both) = (0, 0, 0);
    for _ in 0..tiered(16, 512) {
        let Some(s) = arb_case().new_tree(&mut runner).unwrap().current().span() else {
            continue;
        };
        let ce = Method::CorrectedEuler.values(&s).unwrap();
        for sh in shininess() {
            let ks = r(1, 1);
            let cheap = specular_skips(Method::CorrectedEuler, &s, &ks, sh).unwrap();
            let exact = specular_skips(Method::Phong, &s, &ks, sh).unwrap();
            let phong_zero =
                (0..=s.n).all(|i| phong_level_is_zero(&s, &Q::from_integer(i.into()), &ks, sh));
            if cheap {
                assert!(ce.iter().all(|v| level_is_zero(v, &ks, sh)));
                wrong += usize::from(!phong_zero);
                both += usize::from(exact);
            } else {
                missed += usize::from(exact);
            }
        }
    }
    println!(
        "cheap test: {both} skips Phong's test also makes, {wrong} with a Phong level above 0, \
         {missed} spans Phong's test skips and it does not"
    );
    assert!(both > 0);
}

/// Bad input is a typed error: a shininess of 0 or above the cap, a negative `K_s`, a
/// normal that vanishes on the span, a method with no test.
#[test]
fn skip_errors_are_typed() {
    let z = |x: i64, y: i64, w: i64| Vec3::new(r(x, 1), r(y, 1), r(w, 1));
    let s = Span::new(z(0, 0, 1), z(1, 0, 0), z(0, 0, 1), 4).unwrap();
    let one = r(1, 1);
    assert_eq!(
        specular_skips(Method::Phong, &s, &one, 0),
        Err(SkipError::Shininess(0))
    );
    assert_eq!(
        specular_skips(Method::Phong, &s, &one, 1025),
        Err(SkipError::Shininess(1025))
    );
    assert_eq!(
        specular_skips(Method::CorrectedEuler, &s, &r(-1, 2), 8),
        Err(SkipError::NegativeKs)
    );
    let opposite = Span::new(z(0, 0, 1), z(0, 0, -1), z(0, 0, 1), 4).unwrap();
    assert_eq!(
        specular_skips(Method::Phong, &opposite, &one, 8),
        Err(SkipError::NormalVanishes)
    );
    assert!(matches!(
        specular_skips(Method::Angular, &s, &one, 8),
        Err(SkipError::Unsupported(_))
    ));
    // A zero shininess is refused before anything is read.
    let msg = SkipError::Shininess(0).to_string();
    assert!(msg.contains("1 to 1024"), "{msg}");
}

/// The decision `skip` makes is the one `proofs/Skip.v` proves sound: its candidates
/// (`L`'s root `tstar`, the quadratic's vertex `tv`) and its inequalities (`ok`,
/// `okv`) as the file defines them, and the theorems' hypotheses (`q > 0` on
/// `[0, n]`, which `Candidates::phong` checks, `K_s ≥ 0`, `s ≥ 1`, which it refuses
/// otherwise). An edit of the proof's decision fails here.
#[test]
fn the_decision_is_the_proved_one() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("proofs/Skip.v"),
    )
    .unwrap();
    let flat = text.split_whitespace().collect::<Vec<_>>().join(" ");
    for want in [
        "Definition L (A B C D E t : R) : R := (A * E - B * D / 2) + t * (A * D / 2 - B * C).",
        "Definition tstar (A B C D E : R) : R := - (A * E - B * D / 2) / (A * D / 2 - B * C).",
        "p A B x <= 0 \\/ (255 * Ks) ^ 2 * p A B x ^ (2 * s) < q C D E x ^ s.",
        "ok A B C D E Ks s 0 /\\ ok A B C D E Ks s n /\\ (A * D / 2 - B * C <> 0 /\\ 0 < tstar A B C D E < n -> ok A B C D E Ks s (tstar A B C D E)).",
        "Definition v (pa s0 ds t : R) : R := pa + t * s0 + t * (t - 1) / 2 * ds.",
        "Definition tv (s0 ds : R) : R := / 2 - s0 / ds.",
        "v pa s0 ds x <= 0 \\/ 255 * Ks * v pa s0 ds x ^ s < 1.",
        "okv pa s0 ds Ks s 0 /\\ okv pa s0 ds Ks s n /\\ (ds < 0 /\\ 0 < tv s0 ds < n -> okv pa s0 ds Ks s (tv s0 ds)).",
    ] {
        assert!(flat.contains(want), "proofs/Skip.v no longer says: {want}");
    }
    let sound = statement("proofs/Skip.v", "phong_skip_sound");
    assert!(
        sound.contains("0 <= Ks -> (1 <= s)%nat -> (forall t, 0 <= t <= n -> 0 < q C D E t)"),
        "{sound}"
    );
}

/// The span `s` with its inputs rounded to `f32` (as a renderer holds them): the float
/// form's inputs, and the same values as an exact span (unit within `f32` rounding).
fn rounded(s: &Span<Q>) -> Option<(FloatSpan, Span<Q>)> {
    use num_traits::ToPrimitive;
    let f = |v: &Vec3<Q>| [&v.x, &v.y, &v.z].map(|c| f64::from(c.to_f64().unwrap() as f32));
    let (na, nb, h) = (f(&s.na), f(&s.nb), f(&s.l));
    let q = |v: [f64; 3]| -> Option<Vec3<Q>> {
        Some(Vec3::new(
            Q::from_float(v[0])?,
            Q::from_float(v[1])?,
            Q::from_float(v[2])?,
        ))
    };
    let exact = Span::with_tolerance(q(na)?, q(nb)?, q(h)?, s.n, &r(1, 1 << 18)).ok()?;
    Some((FloatSpan { na, nb, h, n: s.n }, exact))
}

/// `K_s` values of the float form (`[0, 1]`).
fn ks_floats() -> Vec<f64> {
    tiered(vec![1.0, 0.003], vec![1.0, 0.5, 0.003])
}

/// Whether `255·K_s·(x + e)^s·(1 + u)^{2s+2} < 1`, exactly in rationals, for `x` Phong's
/// value `p/√q` given by `x² = p²/q` (`squared`) or the value itself: the square root
/// replaced by a rational above it (`√` of the nearest `f64`, times `1 + 2^-50`).
fn float_margin_holds(x: &Q, squared: bool, e: f64, u: f64, ks: f64, sh: u32) -> bool {
    use num_traits::ToPrimitive;
    let x = if !squared || x.is_zero() {
        x.clone()
    } else {
        let xf = x.to_f64().unwrap().sqrt().max(1e-300);
        Q::from_float(xf).unwrap() * (Q::one() + r(1, 1 << 50))
    };
    let q = |v: f64| Q::from_float(v).unwrap();
    let m = power(&(Q::one() + q(u)), 2 * sh + 2);
    Q::from_integer(255.into()) * q(ks) * power(&(x + q(e)), sh) * m < Q::one()
}

/// The largest exact value of `m` over the pixels of `exact`, and whether it is
/// Phong's squared (`max(0, p)²/q`, for the methods whose values are Phong's; for the
/// squared method `max(0, g)`, whose root is at least its value `sign(p)·√max(0, g)`)
/// or the method's own value.
fn largest(m: Method, exact: &Span<Q>) -> (Q, bool) {
    if m == Method::SquaredCorrectedEuler {
        let sq = phong_approx::squared_corrected_euler::SquaredSpan::of(exact).unwrap();
        let mut g = vec![Q::zero(); exact.n as usize + 1];
        sq.shade(&mut g).unwrap();
        let top = g
            .into_iter()
            .fold(Q::zero(), |a, x| if x > a { x } else { a });
        return (top, true);
    }
    let squared = m.is_phong_valued();
    let values: Vec<Q> = if squared {
        (0..=exact.n)
            .map(|i| {
                let p = exact.p_at(i).max(Q::zero());
                &p * &p / exact.q_at(i)
            })
            .collect()
    } else {
        m.values(exact).unwrap()
    };
    let top = values
        .iter()
        .fold(Q::zero(), |a, x| if *x > a { x.clone() } else { a });
    (top, squared)
}

/// Where the float form skips a span for one of `methods`, every pixel's exact value
/// `x` of the method on the float inputs satisfies
/// `255·K_s·(max(0, x) + e)^s·(1 + u)^{2s+2} < 1` for the `ieee` allowance `e` in
/// `binary32` ([`Margins::ieee`]) — checked in rationals at the largest pixel: no
/// `ieee` implementation reaches level 1 there. With zero margins the float form skips
/// only what the exact test skips. Returns the skips with margins, the exact test's
/// skips and those of them the float form without margins does not make.
fn float_form_against_rationals(methods: &[Method]) -> (u32, u32, u32) {
    let (mut skips, mut exact_skips, mut missed) = (0u32, 0u32, 0u32);
    for s in spans() {
        let Some((fs, exact)) = rounded(&s) else {
            continue;
        };
        for &m in methods {
            let Some(margins) = Margins::ieee(m, &exact, Format::Binary32) else {
                continue;
            };
            let (top, squared) = largest(m, &exact);
            for sh in shininess() {
                for ks in ks_floats() {
                    let zero = Margins {
                        allowance: 0.0,
                        u: 0.0,
                    };
                    let ks_q = Q::from_float(ks).unwrap();
                    let bare = float_skips(m, &fs, ks, sh, zero).unwrap();
                    let exact_skip = specular_skips(m, &exact, &ks_q, sh);
                    if let Ok(x) = exact_skip {
                        exact_skips += u32::from(x);
                        missed += u32::from(x && !bare);
                        assert!(!bare || x, "{m}: the float form skips, the exact test not: s = {sh}, K_s = {ks}, {fs:?}");
                    }
                    if float_skips(m, &fs, ks, sh, margins).unwrap() {
                        skips += 1;
                        // The condition grows with x: the largest pixel decides.
                        assert!(
                            float_margin_holds(&top, squared, margins.allowance, margins.u, ks, sh),
                            "{m} at its largest pixel {top}: s = {sh}, K_s = {ks}, e = {:e}, {fs:?}",
                            margins.allowance
                        );
                    }
                }
            }
        }
    }
    println!("float form on {methods:?}: {skips} skips with the ieee margins; with none, {missed} of the exact test's {exact_skips} skips not made");
    (skips, exact_skips, missed)
}

/// `float_skip_sound` (proofs/SkipFloat.v): the float form on Phong's values (Phong,
/// Duff, symmetric Phong), against rationals ([`float_form_against_rationals`]); its
/// own rounding costs little: it makes 99 % of the exact test's skips.
#[test]
fn float_skip_sound() {
    assert_float_form(&[Method::Phong, Method::Duff, Method::SymmetricPhong]);
}

/// `float_quadratic_skip_sound` (proofs/SkipFloat.v): the same for the quadratic
/// recurrences (corrected Euler, Euler, Gouraud), their set-up in intervals.
#[test]
fn float_quadratic_skip_sound() {
    assert_float_form(&[Method::CorrectedEuler, Method::Euler, Method::Gouraud]);
}

/// `float_squared_skip_sound` (proofs/SkipFloat.v): the same for the squared method,
/// `g`'s set-up in intervals and the root of its quadratic's largest value.
#[test]
fn float_squared_skip_sound() {
    assert_float_form(&[Method::SquaredCorrectedEuler]);
}

/// [`float_form_against_rationals`] on `methods`, which must skip (the test would pass
/// vacuously otherwise) and make 99 % of the exact test's skips.
fn assert_float_form(methods: &[Method]) {
    let (skips, exact, missed) = float_form_against_rationals(methods);
    assert!(skips > tiered(20, 400), "{skips} skips");
    assert!(missed * 100 <= exact, "{missed} of {exact}");
}

/// Spans next to the threshold, where a float decision is most likely to be wrong:
/// `K_s` set so that the largest pixel sits just below or just above level 1 (by
/// `10⁻⁶` and `10⁻⁹` relative and by a few ulps) — of the exact value with no margin,
/// and of the value plus the `ieee` allowance with the margins —, on the edge and
/// random spans. The float form must never skip where the exact test or the margin's
/// condition (checked in rationals at every pixel's largest) says no.
#[test]
fn the_float_form_is_sound_at_the_threshold() {
    use num_traits::ToPrimitive;
    let zero = Margins {
        allowance: 0.0,
        u: 0.0,
    };
    let (mut decided, mut skips) = (0, 0);
    for s in spans() {
        let Some((fs, exact)) = rounded(&s) else {
            continue;
        };
        for m in [
            Method::Phong,
            Method::CorrectedEuler,
            Method::Gouraud,
            Method::SquaredCorrectedEuler,
        ] {
            let (top, squared) = largest(m, &exact);
            let top_f = top.to_f64().unwrap();
            let top_f = if squared { top_f.sqrt() } else { top_f };
            let Some(ieee) = Margins::ieee(m, &exact, Format::Binary32) else {
                continue;
            };
            if top_f <= 1e-3 {
                continue;
            }
            for margins in [zero, ieee] {
                for sh in [1u32, 8] {
                    let base = 255.0
                        * (top_f + margins.allowance).powi(sh as i32)
                        * (1.0 + margins.u).powi(2 * sh as i32 + 2);
                    for f in [
                        1.0 - 1e-6,
                        1.0 - 1e-9,
                        1.0 - 4e-16,
                        1.0,
                        1.0 + 4e-16,
                        1.0 + 1e-9,
                        1.0 + 1e-6,
                    ] {
                        let ks = f / base;
                        if !(0.0..=1.0).contains(&ks) {
                            continue;
                        }
                        decided += 1;
                        if !float_skips(m, &fs, ks, sh, margins).unwrap() {
                            continue;
                        }
                        skips += 1;
                        let exact_skip = specular_skips(m, &exact, &Q::from_float(ks).unwrap(), sh);
                        assert!(
                            exact_skip != Ok(false),
                            "{m}: s = {sh}, K_s = {ks:e}, {fs:?}"
                        );
                        assert!(
                            float_margin_holds(&top, squared, margins.allowance, margins.u, ks, sh),
                            "{m}: s = {sh}, K_s = {ks:e}, margins {margins:?}, {fs:?}"
                        );
                    }
                }
            }
        }
    }
    // Both sides of the threshold are reached: the test skips some, not all.
    assert!(
        decided > tiered(100, 2000) && skips > tiered(20, 400) && skips < decided / 2,
        "{skips} of {decided}"
    );
}

/// The float form's bad input is a typed error, never a skip: a `K_s` outside
/// `[0, 1]` or not a number, infinite inputs, `n = 0`, a zero edge normal, a
/// non-finite margin, a method with no test.
#[test]
fn float_skip_errors_are_typed() {
    let fs = FloatSpan {
        na: [0.0, 0.0, 1.0],
        nb: [1.0, 0.0, 0.0],
        h: [0.0, 0.0, 1.0],
        n: 4,
    };
    let m = Margins {
        allowance: 1e-6,
        u: 2f64.powi(-24),
    };
    let skip =
        |fs: &FloatSpan, ks: f64, sh: u32, m: Margins| float_skips(Method::Phong, fs, ks, sh, m);
    assert_eq!(skip(&fs, 1.0, 0, m), Err(SkipError::Shininess(0)));
    for ks in [-0.5, 1.5, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(skip(&fs, ks, 8, m), Err(SkipError::FloatInput(_))),
            "{ks}"
        );
    }
    let bad_margins = Margins {
        allowance: f64::NAN,
        ..m
    };
    assert!(matches!(
        skip(&fs, 1.0, 8, bad_margins),
        Err(SkipError::FloatInput(_))
    ));
    for bad in [
        FloatSpan { n: 0, ..fs },
        FloatSpan {
            n: (1 << 24) + 1,
            ..fs
        },
        FloatSpan {
            h: [f64::INFINITY, 0.0, 0.0],
            ..fs
        },
    ] {
        assert!(
            matches!(skip(&bad, 1.0, 8, m), Err(SkipError::FloatInput(_))),
            "{bad:?}"
        );
    }
    let zero = FloatSpan { nb: [0.0; 3], ..fs };
    assert_eq!(skip(&zero, 1.0, 8, m), Err(SkipError::NormalVanishes));
    assert!(matches!(
        float_skips(Method::Angular, &fs, 1.0, 8, m),
        Err(SkipError::Unsupported(_))
    ));
    // Opposite normals: q vanishes inside; the float form does not skip (never a wrong
    // skip), even where every end is dark.
    let opposite = FloatSpan {
        na: [0.0, 0.0, 1.0],
        nb: [0.0, 0.0, -1.0],
        h: [1.0, 0.0, 0.0],
        n: 4,
    };
    assert_eq!(skip(&opposite, 1.0, 8, m), Ok(false));
}
