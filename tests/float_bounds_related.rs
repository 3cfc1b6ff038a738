//! The float runs of the related span methods against their exact runs: spherical
//! (Kuijk & Blake), binary (Ouyang & Maynard) and Bishop–Weimer along a span, each run
//! in `f32` and `f64` (inputs rounded to the float type) stays within the derived bound
//! of `phong_approx::tolerance::related` (`docs/float.md` §16) of the same method run
//! exactly on the exact inputs, at every pixel, wherever the bound is `Some`.
//!
//! Inputs: the enumerated edge cases and targeted cases of `tests/common`, random spans
//! from a fixed seed, and a proptest search in the regions where these methods are
//! ill-conditioned (`arb_hard`: nearly equal normals, nearly opposite normals, long
//! spans, grazing light). Opposite normals are refused by the three methods and
//! skipped. A failure prints the method, type, pixel, the exact inputs, both values
//! and the bound.
//!
//! The exact spherical run is the crate's function on `Span<BigRational>` for
//! `n ≤ 64`; beyond, its recurrence's rationals grow by 264 bits a step (minutes at
//! `n = 1024`), so the same set-up (`spherical::setup` on the exact span) is followed by
//! the same recurrence with each value truncated to a multiple of 2^-320, which moves
//! pixel `m` by at most `m²·2^-320` (`spherical_truncated_run_is_the_exact_run`).

use crate::common;

use common::*;
use phong_approx::related::{binary, spherical};
use phong_approx::tolerance::{span_bound, Shape};
use phong_approx::{BigRational, Method, Real, Scalar, Span};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{TestCaseError, TestRunner};

/// The related methods of the catalogue ([`Method::is_related`]), through the
/// catalogue's own interface: their bound ([`span_bound`]), their run
/// ([`Method::values`]) and their exact run.
trait Rel: Copy {
    fn bound(self, shape: &Shape, u: f64) -> Option<f64>;
    fn run<T: Real>(self, span: &Span<T>) -> Result<Vec<T>, String>;
    fn exact(self, span: &Span<Q>) -> Vec<Q>;
}

impl Rel for Method {
    fn bound(self, shape: &Shape, u: f64) -> Option<f64> {
        span_bound(self, shape, u)
    }

    fn run<T: Real>(self, span: &Span<T>) -> Result<Vec<T>, String> {
        self.values(span)
            .map_err(|e| format!("{} in {}: {e}", self.name(), T::NAME))
    }

    fn exact(self, span: &Span<Q>) -> Vec<Q> {
        if self == Method::Spherical && span.n > EXACT_SPHERICAL_N {
            spherical_truncated(span)
        } else if self == Method::Binary && span.n > EXACT_BINARY_N {
            binary_truncated(span)
        } else {
            Rel::run(self, span).expect("the exact run of a span that is not opposite")
        }
    }
}

/// The related methods, from the catalogue.
pub(crate) fn related_methods() -> impl Iterator<Item = Method> {
    Method::ALL.into_iter().filter(Method::is_related)
}

/// Up to this `n` the exact spherical run is the crate's function in rationals.
const EXACT_SPHERICAL_N: u32 = 64;

/// Up to this `n` the exact binary run is the crate's function in rationals.
const EXACT_BINARY_N: u32 = 64;

/// `x` truncated toward −∞ to a multiple of 2^-320.
fn truncate(x: &Q) -> Q {
    let scale = num_bigint::BigInt::from(1u8) << 320u32;
    let v = (x.numer() * &scale).div_floor(x.denom());
    BigRational::new(v, scale)
}

use num_integer::Integer;

/// The spherical recurrence on the exact set-up, each value truncated to 2^-320.
fn spherical_truncated(span: &Span<Q>) -> Vec<Q> {
    let (u_l, w_l, cos_d, sin_d) = spherical::setup(span);
    let two_cos = Q::from_i64(2) * cos_d.clone();
    let mut out = vec![q(0, 1); span.len()];
    let mut prev = u_l.clone();
    let mut cur = truncate(&(u_l * cos_d + w_l * sin_d));
    out[0] = prev.clone();
    for o in out.iter_mut().skip(1) {
        *o = cur.clone();
        let next = truncate(&(two_cos.clone() * cur.clone() - prev));
        prev = cur;
        cur = next;
    }
    out
}

/// `binary::shade`'s operations, in its order, on the exact span, with each value
/// truncated to 2^-320: the ends are `p(i)/√q(i)`, `cos θ` between the ends is
/// `N(a)·N(b)/√(q(a)q(b))`, and each level halves the angle.
fn binary_truncated(span: &Span<Q>) -> Vec<Q> {
    let one = q(1, 1);
    let half = q(1, 2);
    let phong_at = |i: u32| truncate(&(span.p_at(i) / span.q_at(i).sqrt()));
    let mut out = vec![q(0, 1); span.len()];
    out[0] = phong_at(0);
    for w in binary::segments(span.n).windows(2) {
        let (a, b) = (w[0], w[1]);
        out[b as usize] = phong_at(b);
        let (fa, fb) = (qi(a), qi(b));
        let dot = span.e.clone()
            + (fa.clone() + fb.clone()) * span.d.clone() / q(2, 1)
            + fa * fb * span.c.clone();
        let mut c = dot / (span.q_at(a) * span.q_at(b)).sqrt();
        if c > one {
            c = one.clone();
        }
        let mut step = b - a;
        while step > 1 {
            let h = half.clone() * (one.clone() + c.clone());
            c = if h > q(0, 1) { h.sqrt() } else { q(0, 1) };
            let factor = half.clone() / c.clone();
            let half_step = step / 2;
            let mut m = a + half_step;
            while m < b {
                let (lo, hi) = ((m - half_step) as usize, (m + half_step) as usize);
                out[m as usize] = truncate(&((out[lo].clone() + out[hi].clone()) * factor.clone()));
                m += step;
            }
            step = half_step;
        }
    }
    out
}

fn abs_err<T: Scalar>(a: &T, b: &Q) -> f64 {
    Scalar::to_f64(&(a.to_rational().expect("finite") - b.clone())).abs()
}

/// The largest error and the bound of one format, `None` where there is no bound.
pub(crate) type Outcome = Option<(f64, f64)>;

/// The float run of `m` in `T` against `want` (the exact run), pixel by pixel.
fn compare<T: Real>(
    m: Method,
    c: &Case,
    float: &Span<T>,
    want: &[Q],
    b: f64,
) -> Result<f64, String> {
    let got = Rel::run(m, float).map_err(|e| format!("{e}\ninputs: {c:?}"))?;
    let mut worst: f64 = 0.0;
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        let e = if g.is_finite() {
            abs_err(g, w)
        } else {
            f64::INFINITY
        };
        worst = worst.max(e);
        if e > b {
            return Err(format!(
                "{} in {}: pixel {i} of n = {}: got {g:?}, exact {}, error {e:e} = {:.1}u > bound {b:e} = {:.1}u\ninputs: {c:?}",
                m.name(),
                T::NAME,
                c.n,
                w.to_f64(),
                e / T::unit_roundoff(),
                b / T::unit_roundoff(),
            ));
        }
    }
    Ok(worst)
}

/// Runs `m` in `f32` and `f64` and exactly on `c` (once for both), and checks every
/// pixel against the bound; `[f32, f64]`.
pub(crate) fn check_case(m: Method, c: &Case) -> Result<[Outcome; 2], String> {
    let Some(exact_span) = c.span() else {
        return Ok([None, None]);
    };
    let shape = Shape::of(&exact_span);
    let b32 = m.bound(&shape, f32::unit_roundoff());
    let b64 = m.bound(&shape, f64::unit_roundoff());
    if b32.is_none() && b64.is_none() {
        return Ok([None, None]);
    }
    let want = m.exact(&exact_span);
    let mut out = [None, None];
    if let Some(b) = b32 {
        let s = exact_span.cast::<f32>().expect("finite");
        out[0] = Some((compare(m, c, &s, &want, b)?, b));
    }
    if let Some(b) = b64 {
        let s = exact_span.cast::<f64>().expect("finite");
        out[1] = Some((compare(m, c, &s, &want, b)?, b));
    }
    Ok(out)
}

/// Edge cases, random spans from a fixed seed and the targeted cases.
pub(crate) fn cases() -> Vec<Case> {
    let mut runner = TestRunner::deterministic();
    let mut v = edge_cases();
    let lens = [1u32, 2, 3, 7, 16, 64, 255];
    for j in 0..tiered(28, 112) {
        let mut c = arb_case().new_tree(&mut runner).unwrap().current();
        c.n = lens[j % lens.len()];
        v.push(c);
    }
    v.extend(targeted_cases());
    v
}

/// Every case of `cases` within the bound, in both formats; each format must have a
/// bound somewhere.
fn check_method(m: Method) {
    let mut bounded = [0, 0];
    for c in cases() {
        match check_case(m, &c) {
            Ok(r) => {
                for (k, o) in r.iter().enumerate() {
                    bounded[k] += usize::from(o.is_some());
                }
            }
            Err(e) => panic!("{e}"),
        }
    }
    assert!(bounded.iter().all(|&b| b > 0), "{}: {bounded:?}", m.name());
}

/// Every related method of the catalogue ([`related_methods`]): a new one is attacked
/// as soon as its row exists.
#[test]
fn every_related_method_error_bound() {
    for m in related_methods() {
        check_method(m);
    }
}

/// Where these methods are ill-conditioned: nearly equal normals (a few units apart
/// at a scale of up to 2^11, angles down to about 10^-4), nearly opposite normals
/// (`arb_targeted`'s), light along `N_a`, along the span, grazing or anywhere, `n`
/// next to a power of two up to 4096.
pub(crate) fn arb_hard() -> impl Strategy<Value = Case> {
    let close = (
        -3i64..=3,
        -3i64..=3,
        1i64..=4,
        3u32..=11,
        -2i64..=2,
        -2i64..=2,
    )
        .prop_map(|(a, b, d, k, da, db)| {
            let s = 1i64 << k;
            let db = if da == 0 && db == 0 { 1 } else { db };
            (
                Stereo(a * s, b * s, d * s),
                Stereo(a * s + da, b * s + db, d * s),
            )
        });
    let far = (
        (-3i64..=3, -3i64..=3, 1i64..=16).prop_map(|(a, b, d)| Stereo(a, b, d)),
        (8i64..=3000, -200i64..=200, 1i64..=3).prop_map(|(a, b, d)| Stereo(a, b, d)),
    );
    let l = prop_oneof![
        Just(Stereo(0, 0, 1)),
        Just(Stereo(1, 0, 1)),
        Just(Stereo(999, 0, 1000)),
        Just(Stereo(0, 999, 1000)),
        arb_stereo(),
    ];
    let n =
        (0u32..=12, 0u32..=2).prop_map(|(k, j)| ((1u32 << k) + j).saturating_sub(1).clamp(1, 4096));
    (prop_oneof![close, far], l, n).prop_map(|((na, nb), l, n)| Case {
        why: "hard",
        na,
        nb,
        l,
        n,
    })
}

/// A search for spans that break a bound, every method, `f32` and `f64`.
#[test]
fn related_bound_search() {
    let mut runner = runner(12, "proptest-regressions/float_bounds_related.txt");
    let result = runner.run(&arb_hard(), |c| {
        for m in related_methods() {
            check_case(m, &c).map_err(TestCaseError::fail)?;
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}

/// The substitute exact run of the spherical recurrence (values truncated to
/// 2^-320) agrees with the crate's function in rationals to `n²·2^-320`.
#[test]
fn spherical_truncated_run_is_the_exact_run() {
    for c in edge_cases().into_iter().filter(|c| c.n <= 64) {
        let span = c.span().expect("edge cases are valid spans");
        let exact = Rel::run(Method::Spherical, &span).expect("not opposite");
        let trunc = spherical_truncated(&span);
        let tol = Q::new(
            num_bigint::BigInt::from(u64::from(c.n + 1).pow(2)),
            num_bigint::BigInt::from(1u8) << 320u32,
        );
        for (a, b) in exact.iter().zip(&trunc) {
            let d = a.clone() - b.clone();
            let d = if d < q(0, 1) { -d } else { d };
            assert!(d <= tol, "{}: {}", c.why, d.to_f64());
        }
    }
}

/// The substitute exact binary run (values truncated to 2^-320) agrees with the
/// crate's function in rationals to 2^-300 (each level divides the earlier error by a
/// cosine of at least `cos(Ω/2)`, so the truncations add up to at most
/// `log₂ n·(Ω/sin Ω)·2^-320`).
#[test]
fn binary_truncated_run_is_the_exact_run() {
    let mut all = edge_cases();
    all.extend(targeted_cases());
    for c in all.into_iter().filter(|c| c.n <= 64) {
        let Some(span) = c.span() else { continue };
        let exact = Rel::run(Method::Binary, &span).expect("not opposite");
        let trunc = binary_truncated(&span);
        let tol = Q::new(1.into(), num_bigint::BigInt::from(1u8) << 300u32);
        for (i, (a, b)) in exact.iter().zip(&trunc).enumerate() {
            let d = a.clone() - b.clone();
            let d = if d < q(0, 1) { -d } else { d };
            assert!(d <= tol, "{} pixel {i}: {}", c.why, d.to_f64());
        }
    }
}
