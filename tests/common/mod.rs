//! Shared generators for the claim tests: exact unit normals from small integers, so
//! that a failing case prints (and shrinks to) a few small numbers.
#![allow(dead_code)]

pub mod coq;
pub mod emu;

use phong_approx::reference::unit::unit_from_ints;
use phong_approx::{BigRational, Span, Vec3};
use proptest::prelude::*;
use proptest::test_runner::{RngAlgorithm, TestRng, TestRunner};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Exact rationals.
pub type Q = BigRational;

/// The extensive tier is on: `PHONG_APPROX_TIER=extensive` (see `docs/testing.md`).
///
/// The default `cargo test` runs every claim, every method and every bad-input check on
/// a representative sample; the extensive tier, run by CI as
/// `PHONG_APPROX_TIER=extensive cargo test --release --all-features -- --include-ignored`,
/// runs the same tests on the larger samples (the `n = 4096` exact spans, more random
/// cases) plus the `#[ignore]`d long searches (the reports are `cargo xtask`).
pub fn extensive() -> bool {
    std::env::var("PHONG_APPROX_TIER").is_ok_and(|t| t == "extensive")
}

/// `default` in the default tier, `extensive` in the extensive tier.
pub fn tiered<T>(default: T, extensive_value: T) -> T {
    if extensive() {
        extensive_value
    } else {
        default
    }
}

/// The number of random cases of a proptest search: `PROPTEST_CASES` when set (as
/// proptest's own default configuration reads it), else `default` in the default
/// tier and four times as many in the extensive tier.
pub fn proptest_cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or_else(|| tiered(default, default.saturating_mul(4)))
}

/// The one proptest configuration of the claim tests: [`proptest_cases`] cases, failures
/// kept in `file` (so they run first next time).
pub fn proptest_config(default_cases: u32, file: &'static str) -> proptest::test_runner::Config {
    proptest::test_runner::Config {
        cases: proptest_cases(default_cases),
        failure_persistence: Some(Box::new(
            proptest::test_runner::FileFailurePersistence::Direct(file),
        )),
        ..proptest::test_runner::Config::default()
    }
}

/// The length of the long edge spans: 4096 (the longest of the float bounds' range) in
/// the extensive tier, 512 in the default tier (exact work grows with `n`, and the
/// `n = 4096` claims are the extensive tier's).
pub fn long_n() -> u32 {
    tiered(512, 4096)
}

/// `n/d` as a rational.
pub fn q(n: i64, d: i64) -> Q {
    BigRational::new(n.into(), d.into())
}

/// Stereographic parameters `(a/d, b/d)` of an exact unit vector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stereo(pub i64, pub i64, pub i64);

impl Stereo {
    /// The exact unit vector.
    pub fn unit(self) -> Vec3<Q> {
        unit_from_ints(self.0, self.1, self.2)
    }
}

/// A span given by its exact inputs.
#[derive(Clone, Debug)]
pub struct Case {
    /// Why the case is there (edge cases) or "random".
    pub why: &'static str,
    /// `N_a`.
    pub na: Stereo,
    /// `N_b`.
    pub nb: Stereo,
    /// `L`.
    pub l: Stereo,
    /// Steps.
    pub n: u32,
}

impl Case {
    /// The exact span, or `None` when `N_b = −N_a` (the claims are about spans whose
    /// normal never vanishes; opposite normals have tests of their own in
    /// `tests/methods.rs`).
    pub fn span(&self) -> Option<Span<Q>> {
        Span::new(self.na.unit(), self.nb.unit(), self.l.unit(), self.n)
            .ok()
            .filter(|s| !s.is_opposite())
    }
}

/// Parameters of a random exact unit vector.
pub fn arb_stereo() -> impl Strategy<Value = Stereo> {
    (-40i64..=40, -40i64..=40, 1i64..=24).prop_map(|(a, b, d)| Stereo(a, b, d))
}

/// A random span: either two unrelated normals, or (as a torus produces) two nearby
/// normals; light anywhere; 1 to 64 steps.
pub fn arb_case() -> impl Strategy<Value = Case> {
    let far = (arb_stereo(), arb_stereo());
    let near = (arb_stereo(), -3i64..=3, -3i64..=3).prop_map(|(s, da, db)| {
        let d = s.2 * 8;
        (
            Stereo(s.0 * 8, s.1 * 8, d),
            Stereo(s.0 * 8 + da, s.1 * 8 + db, d),
        )
    });
    (prop_oneof![far, near], arb_stereo(), 1u32..=64).prop_map(|((na, nb), l, n)| Case {
        why: "random",
        na,
        nb,
        l,
        n,
    })
}

/// Edge cases enumerated on purpose: n = 1 and 2, N_a = N_b, normals 170° apart,
/// N·L < 0 on part of the span, grazing light, a long span ([`long_n`]: 4096 in the
/// extensive tier).
pub fn edge_cases() -> Vec<Case> {
    let up = Stereo(0, 0, 1); // (0, 0, 1)
    let tilt = Stereo(1, 0, 3); // (3/5, 0, 4/5)
    let tilt_back = Stereo(-1, 0, 3); // (−3/5, 0, 4/5)
                                      // tan(85°) ≈ 11.430: (2u, 0, 1 − u²)/(1 + u²) is 170.0° from (0, 0, 1).
    let far = Stereo(11430, 0, 1000);
    let side = Stereo(1, 0, 1); // (1, 0, 0)
    let light_oblique = Stereo(2, 1, 5);
    let mut v = vec![
        Case {
            why: "n = 1",
            na: up,
            nb: tilt,
            l: light_oblique,
            n: 1,
        },
        Case {
            why: "n = 2, equal edge angles",
            na: tilt,
            nb: tilt_back,
            l: up,
            n: 2,
        },
        Case {
            why: "Na = Nb",
            na: tilt,
            nb: tilt,
            l: light_oblique,
            n: 7,
        },
        Case {
            why: "normals 170° apart",
            na: up,
            nb: far,
            l: light_oblique,
            n: 33,
        },
        Case {
            why: "normals 170° apart, even n",
            na: up,
            nb: far,
            l: up,
            n: 64,
        },
        Case {
            why: "N·L < 0 on part of the span",
            na: up,
            nb: side,
            l: Stereo(-1, 0, 2),
            n: 9,
        },
        Case {
            why: "grazing light",
            na: up,
            nb: tilt,
            l: Stereo(999, 0, 1000),
            n: 12,
        },
        Case {
            why: "light = Na",
            na: tilt,
            nb: Stereo(1, 1, 4),
            l: tilt,
            n: 5,
        },
        Case {
            why: "long span",
            na: up,
            nb: tilt,
            l: light_oblique,
            n: long_n(),
        },
        Case {
            why: "long span, 170° apart",
            na: up,
            nb: far,
            l: light_oblique,
            n: long_n(),
        },
    ];
    v.push(Case {
        why: "90° apart, light between",
        na: up,
        nb: side,
        l: Stereo(1, 0, 2),
        n: 16,
    });
    v
}

/// The exact run of `method` on `span` (the exact span of `c`), computed once per test
/// binary and shared by every test that asks: the `f32` and `f64` tests of a method,
/// and the tests that compare different things with the same exact values, run the
/// same cases (the default tier's searches have a fixed seed). A second asker waits
/// for the first.
pub fn exact_values(method: phong_approx::Method, c: &Case, span: &Span<Q>) -> Arc<Vec<Q>> {
    type Cell = Arc<OnceLock<Arc<Vec<Q>>>>;
    static CACHE: OnceLock<Mutex<HashMap<String, Cell>>> = OnceLock::new();
    let key = format!("{method} {:?} {:?} {:?} {}", c.na, c.nb, c.l, c.n);
    let cell = CACHE
        .get_or_init(Default::default)
        .lock()
        .unwrap()
        .entry(key)
        .or_default()
        .clone();
    cell.get_or_init(|| Arc::new(method.values(span).unwrap()))
        .clone()
}

/// A proptest runner for `cases` cases (see [`proptest_config`]): with a fixed seed in
/// the default tier, so that every run (and every test of a binary) checks the same
/// sample, and a fresh seed per run in the extensive tier.
pub fn runner(cases: u32, file: &'static str) -> TestRunner {
    let config = proptest_config(cases, file);
    if extensive() {
        TestRunner::new(config)
    } else {
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha))
    }
}

/// Runs `check` on every edge case, then on `cases` random ones; a failure panics
/// with the case (its exact inputs) and the message.
pub fn for_all_spans(cases: u32, check: impl Fn(&Case, &Span<Q>) -> Result<(), String>) {
    for c in edge_cases() {
        let span = c.span().expect("edge cases are valid spans");
        if let Err(e) = check(&c, &span) {
            panic!("edge case '{}' failed: {e}\ninputs: {c:?}", c.why);
        }
    }
    search(arb_case(), cases, "proptest-regressions/claims.txt", &check);
}

/// A check of one span: `Err` with a message when it fails.
type SpanCheck<'a> = dyn Fn(&Case, &Span<Q>) -> Result<(), String> + 'a;

/// Runs `check` on `cases` random spans of `strategy` (failures kept in `file`, so
/// they run first next time); a failure panics with the shrunk case.
fn search(
    strategy: impl Strategy<Value = Case>,
    cases: u32,
    file: &'static str,
    check: &SpanCheck<'_>,
) {
    let mut runner = runner(cases, file);
    let result = runner.run(&strategy, |c| {
        let Some(span) = c.span() else {
            return Ok(());
        };
        check(&c, &span).map_err(|e| TestCaseError::fail(format!("{e}\ninputs: {c:?}")))
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}

/// `Ok` if `a == b`, else a message naming both.
pub fn eq(what: &str, a: &Q, b: &Q) -> Result<(), String> {
    if a == b {
        Ok(())
    } else {
        Err(format!("{what}: {a} ≠ {b}"))
    }
}

/// `Ok` if `cond`, else `msg`.
pub fn ensure(cond: bool, msg: impl FnOnce() -> String) -> Result<(), String> {
    if cond {
        Ok(())
    } else {
        Err(msg())
    }
}

/// `i` as a rational.
pub fn qi(i: u32) -> Q {
    q(i64::from(i), 1)
}

/// Where rounding errors pile up, enumerated on purpose (`docs/float.md`, "the
/// worst case"): near-opposite normals (a Gouraud slope of about `2/n` and `p_a + p_b`
/// near 0, so `|ds|` is below half an ulp of the slope and every rounding of the slope
/// has the same sign), `n = 2^k − 1`, `2^k` and `2^k + 1` (slopes just above, at and
/// below a power of two), light along `N_a` or along the span, and the reproducer of
/// the bound that was once false (`N_b = (192, 0, −9215)/9217`, `n = 4095`).
/// The edge and targeted spans of at most `max_n` steps, then `random` seeded random
/// ones ([`arb_case`], the same every run): a fixed sample for tests that decide
/// every span exactly.
pub fn sample_spans(max_n: u32, random: usize) -> Vec<Span<Q>> {
    let mut spans: Vec<Span<Q>> = edge_cases()
        .iter()
        .chain(&targeted_cases())
        .filter(|c| c.n <= max_n)
        .filter_map(Case::span)
        .collect();
    let mut runner = TestRunner::deterministic();
    for _ in 0..random {
        use proptest::strategy::ValueTree;
        spans.extend(arb_case().new_tree(&mut runner).unwrap().current().span());
    }
    spans
}

pub fn targeted_cases() -> Vec<Case> {
    let up = Stereo(0, 0, 1);
    let mut v = vec![Case {
        why: "reproducer: 178.8° apart, n = 4095",
        na: up,
        nb: Stereo(96, 0, 1),
        l: up,
        n: 4095,
    }];
    // n next to 2^11 and 2^12 in the extensive tier only (the exact reference's cost
    // grows with n); the reproducer above (n = 4095) runs in both.
    let ks: &[u32] = tiered(&[1, 3, 6, 8, 10], &[1, 3, 6, 8, 10, 11, 12]);
    for &k in ks {
        for n in [(1u32 << k) - 1, 1 << k, (1 << k) + 1] {
            if n == 0 || n > 4096 {
                continue;
            }
            for (why, nb, l) in [
                ("near-opposite, light = Na", Stereo(96, 0, 1), up),
                (
                    "near-opposite, off-axis",
                    Stereo(517, 33, 3),
                    Stereo(1, 2, 7),
                ),
                (
                    "near-opposite, light along the span",
                    Stereo(40, 0, 1),
                    Stereo(1, 0, 1),
                ),
                ("90° apart", Stereo(1, 0, 1), Stereo(1, 0, 3)),
                (
                    "close normals, grazing light",
                    Stereo(1, 1, 40),
                    Stereo(999, 0, 1000),
                ),
            ] {
                v.push(Case {
                    why,
                    na: up,
                    nb,
                    l,
                    n,
                });
            }
        }
    }
    v
}

/// Random spans in the regions of [`targeted_cases`]: near-opposite normals at any
/// orientation, `n` next to a power of two (up to 4096), light near `N_a`, along the
/// span or anywhere.
pub fn arb_targeted() -> impl Strategy<Value = Case> {
    let na = (-3i64..=3, -3i64..=3, 1i64..=16).prop_map(|(a, b, d)| Stereo(a, b, d));
    let far = (8i64..=3000, -200i64..=200, 1i64..=3).prop_map(|(a, b, d)| Stereo(a, b, d));
    let n =
        (1u32..=tiered(10, 12), 0u32..=2).prop_map(|(k, j)| ((1u32 << k) + j - 1).clamp(1, 4096));
    let l = prop_oneof![Just(Stereo(0, 0, 1)), Just(Stereo(1, 0, 1)), arb_stereo(),];
    (na, far, l, n).prop_map(|(na, nb, l, n)| Case {
        why: "targeted",
        na,
        nb,
        l,
        n,
    })
}

/// Runs `check` on every targeted case ([`targeted_cases`]), then on `cases` random
/// ones in the same regions ([`arb_targeted`]); a failure panics with the case.
pub fn for_targeted_spans(cases: u32, check: impl Fn(&Case, &Span<Q>) -> Result<(), String>) {
    for c in targeted_cases() {
        let Some(span) = c.span() else { continue };
        if let Err(e) = check(&c, &span) {
            panic!("targeted case '{}' failed: {e}\ninputs: {c:?}", c.why);
        }
    }
    search(
        arb_targeted(),
        cases,
        "proptest-regressions/targeted.txt",
        &check,
    );
}
