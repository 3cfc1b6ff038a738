//! Beyond the published vectors: the exact reference ([`oracle`]), the acceptance
//! intervals ([`acceptance`]) and the verdict ([`check_span`]) on spans of your own.

use super::inputs::{Float, Inputs};
use super::outcome::Report;
use super::suite::judge;
use crate::conformance::check::{Criteria, Tolerance};
use crate::conformance::vectors::{case_for_span, file_of};
use crate::tolerance::profile::Profile;
use crate::{BigRational, Method, Span};

/// Why [`check_span`] cannot judge a span: what is wrong with it, never with the code
/// under test (that is a failing [`Report`]).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum KitError {
    /// An input is not exactly of unit length (a zero vector among them): the bounds
    /// hold for exact unit inputs, which [`crate::reference::unit`] makes.
    #[error("the span's {0} is not exactly of unit length (the bounds hold for exact unit inputs: reference::unit makes them)")]
    NotUnit(&'static str),
    /// A span of no steps (`n = 0`).
    #[error("the span has n = 0 steps (it needs n ≥ 1)")]
    NoSteps,
    /// More steps than the exact oracle takes in a test.
    #[error("n = {0} is more steps than the kit's exact oracle takes (at most {MAX_STEPS})")]
    TooLong(u32),
    /// The exact reference cannot give the case (a level it cannot decide, say).
    #[error("the exact reference cannot give this span: {0}")]
    Oracle(crate::conformance::integrity::VectorError),
}

/// The most steps [`check_span`] takes: its exact oracle costs about `n` times a few
/// hundred microseconds for the methods with square roots.
pub const MAX_STEPS: u32 = 1 << 14;

/// Judges your implementation of `method` on one exact span of your own, as
/// [`super::Suite`] judges the published cases: your function gets the nearest floats
/// ([`Inputs::nearest`]), its `n + 1` values are compared with the exact ones under
/// `profile`'s bound (a wrong number of values, a NaN or an infinity fails), and a
/// failing [`Report`] names the pixel, the values and the `phong-approx span` command
/// that reproduces the span. The helper a property test calls:
///
/// ```
/// use phong_approx::testkit::prelude::*;
/// let span = Span::new(unit_from_ints(0, 0, 1), unit_from_ints(1, 0, 3), unit_from_ints(0, 0, 1), 4).unwrap();
/// // Gouraud in f32, as written by hand.
/// let gouraud = |s: &Inputs<f32>| {
///     let dot = |a: [f32; 3], b: [f32; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
///     let (pa, pb) = (dot(s.na, s.l), dot(s.nb, s.l));
///     (0..=s.n).map(|i| pa + (pb - pa) * i as f32 / s.n as f32).collect()
/// };
/// check_span(Method::Gouraud, &span, Profile::Ieee, gouraud).unwrap().assert_ok();
/// // One value short: a failure, not a panic.
/// let short = check_span(Method::Gouraud, &span, Profile::Ieee, |s: &Inputs<f32>| vec![0.5; s.n as usize]);
/// assert!(!short.unwrap().is_ok());
/// ```
///
/// # Errors
/// [`KitError`] where the span is not one the bounds cover (inputs not exactly
/// unit, `n = 0`, more than [`MAX_STEPS`](crate::testkit::MAX_STEPS)) or the exact reference cannot give it.
pub fn check_span<T: Float, F: FnMut(&Inputs<T>) -> Vec<T>>(
    method: Method,
    span: &Span<BigRational>,
    profile: Profile,
    mut shade: F,
) -> Result<Report, KitError> {
    let one = BigRational::from_integer(1.into());
    for (what, v) in [("N_a", &span.na), ("N_b", &span.nb), ("L", &span.l)] {
        if v.length_squared() != one {
            return Err(KitError::NotUnit(what));
        }
    }
    if span.n == 0 {
        return Err(KitError::NoSteps);
    }
    if span.n > MAX_STEPS {
        return Err(KitError::TooLong(span.n));
    }
    // The either-method verdict near the adaptive threshold needs both runs.
    let methods = method.with_picks();
    let case =
        case_for_span(&methods, "span", &span.to_string(), span).map_err(KitError::Oracle)?;
    let file = file_of("span", vec![case]);
    let tol = Tolerance::Profile {
        profile,
        format: T::FORMAT,
        form: crate::tolerance::profile::Form::Any,
    };
    let mut report = Report::new(
        method,
        format!("the {profile} profile's bound"),
        T::FORMAT.name(),
    );
    // The span is exact already: its shape is read from it, not from the case's text.
    let shapes = [Some(crate::tolerance::Shape::of(span))];
    let criteria = Criteria::new(method, tol).in_format(T::FORMAT);
    judge(&mut report, "span", &file, &shapes, &criteria, &mut shade);
    Ok(report)
}

/// The exact reference on a span of your own: the values (exact for the rational
/// methods; for the others computed to more bits until every one of the 30 digits
/// printed is known, [`crate::span_report::exact_run`], the path `span --scalar
/// exact` takes), as 30-digit decimals and their 8-bit levels (decided exactly,
/// `None` only where a non-rational method's value is within 2^-1024 of a level
/// boundary).
#[derive(Clone, Debug)]
pub struct Oracle {
    /// The values, pixel `0..=n`: exact for the rational methods, else within
    /// 2^-[`Oracle::bits`] of the method's exact values.
    pub values: Vec<crate::BigRational>,
    /// The values to 30 significant digits, every digit known.
    pub decimals: Vec<String>,
    /// The levels `floor(255·clamp(v, 0, 1))`.
    pub levels: Vec<Option<u8>>,
    /// The bits the values are known to (`None`: exact).
    pub bits: Option<i64>,
}

/// The exact values and levels of `method` on `span` (exact unit inputs:
/// [`crate::reference::unit`] makes them), within the budget `span --scalar exact`
/// keeps without `--yes` (about half a minute of exact work,
/// [`crate::budget::MAX_RECOMPUTED_WORK`]). Cost: exact rationals, so about `n`
/// times a few microseconds for the rational methods and a few hundred for the ones
/// with square roots, `acos` or `cos` (`docs/conformance.md`, budgets): keep `n` in
/// the hundreds in property tests.
///
/// ```
/// use phong_approx::testkit::prelude::*;
/// let span = Span::new(unit_from_ints(0, 0, 1), unit_from_ints(1, 0, 3), unit_from_ints(0, 0, 1), 4).unwrap();
/// let o = oracle(Method::Gouraud, &span).unwrap();
/// assert_eq!(o.decimals[0], "1.00000000000000000000000000000");
/// assert_eq!(o.levels[4], Some(204)); // p_b = 0.8
/// ```
///
/// # Errors
/// A [`crate::span_report::ReportError`]: the method's [`crate::SpanError`] on this
/// span (a normal that vanishes, say), work over the budget
/// ([`crate::span_report::Remedy::RunAnyway`]: [`oracle_without_budget`] runs it), or
/// digits not known even at 2^-8192.
pub fn oracle(
    method: Method,
    span: &crate::Span<crate::BigRational>,
) -> Result<Oracle, crate::span_report::ReportError> {
    oracle_run(method, span, true)
}

/// [`oracle`] without the work budget: for spans whose exact run is known to take
/// long (`n` in the hundred thousands, say).
///
/// # Errors
/// As [`oracle`], but never for the budget.
pub fn oracle_without_budget(
    method: Method,
    span: &crate::Span<crate::BigRational>,
) -> Result<Oracle, crate::span_report::ReportError> {
    oracle_run(method, span, false)
}

fn oracle_run(
    method: Method,
    span: &crate::Span<crate::BigRational>,
    budget: bool,
) -> Result<Oracle, crate::span_report::ReportError> {
    let r = crate::span_report::Request {
        method,
        na: span.na.clone(),
        nb: span.nb.clone(),
        l: span.l.clone(),
        n: span.n,
        kd: crate::BigRational::from_integer(1.into()),
        normalize: false,
        digits: 30,
        arithmetic: crate::Arithmetic::Exact,
    };
    if budget {
        r.within_budget()?;
    }
    let run = crate::span_report::exact_run(&r)?;
    Ok(Oracle {
        values: run.values,
        decimals: run.decimals,
        levels: run.levels,
        bits: run.bits,
    })
}

/// The interval `[lo, hi]` every pixel of a correct implementation of `method` in
/// the format `T` (`f32`, `f64`) and `profile` falls in, on `span`: the exact value
/// plus and minus the profile's bound for the case (its Coq theorem or derivation,
/// `docs/float.md` §18; the crate's derived bound for `Reference`), rounded outward.
/// `None` where the profile has no bound for the method, format and span — as
/// `check` then fails the case.
///
/// ```
/// use phong_approx::testkit::prelude::*;
/// let span = Span::new(unit_from_ints(0, 0, 1), unit_from_ints(1, 0, 3), unit_from_ints(0, 0, 1), 4).unwrap();
/// let iv = acceptance::<f32>(Method::Gouraud, &span, Profile::Ieee).unwrap();
/// let mine = 0.8f32; // pixel 4 of some implementation
/// assert!(iv[4].0 <= f64::from(mine) && f64::from(mine) <= iv[4].1);
/// ```
pub fn acceptance<T: Float>(
    method: Method,
    span: &crate::Span<crate::BigRational>,
    profile: Profile,
) -> Option<Vec<(f64, f64)>> {
    use crate::Scalar as _;
    let shape = crate::tolerance::Shape::of(span);
    // Per pixel: under `ieee` and `shader` the smaller of the formula and the operation
    // graphs' bound at each pixel (the adaptive scheme: its picks' formulas).
    let n1 = span.n as usize + 1;
    let b: Vec<f64> = match profile {
        Profile::Reference => {
            vec![crate::tolerance::span_bound(method, &shape, T::FORMAT.u())?; n1]
        }
        p if method.picks().is_some() => vec![
            crate::tolerance::profile::profile_span_bound(
                method,
                p,
                crate::tolerance::profile::Form::Any,
                &shape,
                T::FORMAT,
            )?;
            n1
        ],
        p => crate::tolerance::graphs::profile_pixel_bounds(
            method,
            p,
            crate::tolerance::profile::Form::Any,
            &shape,
            None,
            T::FORMAT,
        )?,
    };
    let values = method.values(span).ok()?;
    let interval = |x: f64, b: f64| {
        // The f64 of the exact value is within half an f64 ulp: widen by one.
        let slack = f64::EPSILON * x.abs().max(f64::MIN_POSITIVE);
        let lo = (x - b) - slack - f64::EPSILON * (x - b).abs();
        let hi = (x + b) + slack + f64::EPSILON * (x + b).abs();
        (lo, hi)
    };
    let mut iv: Vec<(f64, f64)> = values
        .iter()
        .zip(&b)
        .map(|(v, &b)| interval(v.to_f64(), b))
        .collect();
    // The adaptive scheme where its test is too close to call (docs/float.md §10): an
    // implementation may pick either method, so each pixel's interval also holds the
    // other method's (the hull of the two; `check` asks one method for the whole span).
    if let Some([ma, mb]) = method.picks() {
        let bound = |m: Method| match profile {
            Profile::Reference => crate::tolerance::span_bound(m, &shape, T::FORMAT.u()),
            p => crate::tolerance::profile::profile_span_bound(
                m,
                p,
                crate::tolerance::profile::Form::Any,
                &shape,
                T::FORMAT,
            ),
        };
        let (ba, bb) = (bound(ma)?, bound(mb)?);
        let d = crate::adaptive::decide(span, &crate::BigRational::from_integer(1.into()));
        let (wa, wb, u) = crate::tolerance::profile::adaptive_band(profile, T::FORMAT, ba, bb);
        if crate::tolerance::adaptive_too_close(d.delta.to_f64(), 1.0, wa, wb, u) {
            for (m, b) in [(ma, ba), (mb, bb)] {
                for (i, v) in m.values(span).ok()?.iter().enumerate() {
                    let (lo, hi) = interval(v.to_f64(), b);
                    iv[i] = (iv[i].0.min(lo), iv[i].1.max(hi));
                }
            }
        }
    }
    Some(iv)
}
