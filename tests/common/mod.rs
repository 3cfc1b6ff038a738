//! Shared generators for the claim tests: exact unit normals from small integers, so
//! that a failing case prints (and shrinks to) a few small numbers.
#![allow(dead_code)]

use phong_approx::reference::unit::unit_from_ints;
use phong_approx::{BigRational, Span, Vec3};
use proptest::prelude::*;

/// Exact rationals.
pub type Q = BigRational;

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
/// N·L < 0 on part of the span, grazing light, n = 4096.
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
            why: "n = 4096",
            na: up,
            nb: tilt,
            l: light_oblique,
            n: 4096,
        },
        Case {
            why: "n = 4096, 170° apart",
            na: up,
            nb: far,
            l: light_oblique,
            n: 4096,
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
    let config = ProptestConfig {
        cases,
        failure_persistence: Some(Box::new(
            proptest::test_runner::FileFailurePersistence::Direct(file),
        )),
        ..ProptestConfig::default()
    };
    let mut runner = proptest::test_runner::TestRunner::new(config);
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
pub fn targeted_cases() -> Vec<Case> {
    let up = Stereo(0, 0, 1);
    let mut v = vec![Case {
        why: "reproducer: 178.8° apart, n = 4095",
        na: up,
        nb: Stereo(96, 0, 1),
        l: up,
        n: 4095,
    }];
    for k in [1u32, 3, 6, 8, 10, 11, 12] {
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
    let n = (1u32..=12, 0u32..=2).prop_map(|(k, j)| ((1u32 << k) + j - 1).clamp(1, 4096));
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
