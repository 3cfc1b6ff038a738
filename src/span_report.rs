//! One scan line, one method, one number type, as a report: the values, their 8-bit
//! levels where they are known, the exact fractions of a rational run, the adaptive
//! decision and the float error bounds per profile. This is what `phong-approx span`
//! prints (as JSON through serde, or as a table); the command only parses its
//! arguments and writes the [`SpanReport`].
//!
//! Every printed digit is known: an exact run's `acos`, `cos` and square roots are
//! taken to more bits until the asked digits are decided (up to
//! `2^-`[`MAX_BITS`](crate::reference::transcendental::MAX_BITS)), an MPFR run is
//! refused beyond what its precision decides, and a level is `None` where the value
//! is within its error of a level boundary.

use crate::adaptive::Decision;
use crate::error::shown;
use crate::method::Prepared;
use crate::quantize::level;
use crate::{BigRational, Input, Method, Real, Scalar, Span, SpanError, Vec3};
use serde::ser::{SerializeSeq, Serializer};
use serde::Serialize;
use std::fmt;

/// The most steps (and cosine-table entries) an exact or MPFR run takes without
/// being told to (`--yes`): about half a minute of work.
pub const SPAN_BUDGET: u32 = 1 << 16;

/// The most output a report writes without being told to (`--yes`).
pub const OUTPUT_BUDGET: u64 = 1 << 30;

/// The number type of a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arithmetic {
    /// `f32`.
    F32,
    /// `f64`.
    F64,
    /// Exact rationals (square roots, `acos` and `cos` to 2^-256 or more).
    Exact,
    /// MPFR at this many bits (feature `mpfr`).
    Mpfr(u32),
}

impl Arithmetic {
    /// Its name in the report: `f32`, `f64`, `exact`, `mpfr`.
    pub fn name(self) -> &'static str {
        match self {
            Arithmetic::F32 => "f32",
            Arithmetic::F64 => "f64",
            Arithmetic::Exact => "exact",
            Arithmetic::Mpfr(_) => "mpfr",
        }
    }

    /// Exact or MPFR.
    pub fn is_exact(self) -> bool {
        matches!(self, Arithmetic::Exact | Arithmetic::Mpfr(_))
    }
}

/// A request: the span, the method, the number type and the digits to print.
#[derive(Clone, Debug)]
pub struct Request {
    /// The method (`AngularTable(size)` for a tabled angular run).
    pub method: Method,
    /// `N_a`, exact.
    pub na: Vec3<BigRational>,
    /// `N_b`, exact.
    pub nb: Vec3<BigRational>,
    /// `L` (or `H`), exact.
    pub l: Vec3<BigRational>,
    /// Steps `n ≥ 1`.
    pub n: u32,
    /// `K_d` of the adaptive test (eq. 24), `0 ≤ K_d ≤ 1000`.
    pub kd: BigRational,
    /// Normalize the inputs first instead of requiring unit vectors.
    pub normalize: bool,
    /// Significant digits of exact and MPFR values.
    pub digits: usize,
    /// The number type.
    pub arithmetic: Arithmetic,
}

/// A request that cannot be run: the argument it is about and why, in one line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReportError {
    /// The argument (`--na`, `--steps`, …).
    pub arg: &'static str,
    /// What is wrong with it.
    pub message: String,
}

impl ReportError {
    fn new(arg: &'static str, message: impl fmt::Display) -> Self {
        ReportError {
            arg,
            message: message.to_string(),
        }
    }
}

impl fmt::Display for ReportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.arg, self.message)
    }
}

impl std::error::Error for ReportError {}

impl Request {
    /// Checks the request against the budgets: an exact or MPFR run of more than
    /// [`SPAN_BUDGET`] steps or table entries, an exact run whose estimated work
    /// exceeds `check`'s ([`crate::budget::exact_work`]), or more
    /// than [`OUTPUT_BUDGET`] bytes of output.
    ///
    /// # Errors
    /// A [`ReportError`] naming the argument to change (or `--yes` to run anyway).
    pub fn within_budget(&self) -> Result<(), ReportError> {
        use crate::budget::{exact_work, input_bits, MAX_RECOMPUTED_WORK};
        let (n, method, digits) = (self.n, self.method, self.digits);
        let exact = self.arithmetic.is_exact();
        if exact && n > SPAN_BUDGET {
            return Err(ReportError::new(
                "--steps",
                format!("{n} steps in exact arithmetic take minutes or more (budget {SPAN_BUDGET}); pass --yes to run anyway"),
            ));
        }
        if self.arithmetic == Arithmetic::Exact {
            let work = exact_work(
                method,
                n,
                input_bits(&[&self.na, &self.nb, &self.l]),
                digits,
            );
            if work > MAX_RECOMPUTED_WORK {
                return Err(ReportError::new(
                    "--steps",
                    format!(
                        "{n} steps of {method} in exact arithmetic with these inputs and digits take about {}× the budget of half a minute; pass --yes to run anyway",
                        work.div_ceil(MAX_RECOMPUTED_WORK)
                    ),
                ));
            }
        }
        if let Method::AngularTable(size) = method {
            if exact && size > SPAN_BUDGET {
                return Err(ReportError::new(
                    "--table-size",
                    format!("a table of {size} exact cosines takes minutes (budget {SPAN_BUDGET}); pass --yes to run anyway"),
                ));
            }
        }
        // Per pixel: the value (quoted, indented), its level, and for exact runs of
        // the field-operation methods a fraction of about the same length.
        let per_pixel = if exact { 2 * (digits + 12) + 10 } else { 42 };
        let bytes = (u64::from(n) + 1) * per_pixel as u64;
        if bytes > OUTPUT_BUDGET {
            return Err(ReportError::new(
                "--digits",
                format!(
                    "the output would be about {} MiB (budget {} MiB); ask for fewer digits or steps, or pass --yes",
                    bytes >> 20,
                    OUTPUT_BUDGET >> 20
                ),
            ));
        }
        Ok(())
    }
}

/// A run's values, formatted as they are written: a float run keeps its numbers
/// (8 bytes a pixel at most), not a string per pixel, so a report holds little more
/// than the values however long the span. Serialized as an array of strings.
pub struct Values {
    len: usize,
    at: Box<dyn Fn(usize) -> String>,
}

impl Values {
    /// Values already formatted.
    fn eager(v: Vec<String>) -> Values {
        Values {
            len: v.len(),
            at: Box::new(move |i| v[i].clone()),
        }
    }

    /// The values, formatted, in pixel order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = String> + '_ {
        (0..self.len).map(|i| (self.at)(i))
    }
}

impl Serialize for Values {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(Some(self.len))?;
        for v in self.iter() {
            seq.serialize_element(&v)?;
        }
        seq.end()
    }
}

impl fmt::Debug for Values {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Values({})", self.len)
    }
}

/// The adaptive scheme's test on the run (eqs. 23–24).
#[derive(Debug, Serialize)]
pub struct Adaptive {
    /// Eq. 24's `δ`.
    pub delta: String,
    /// Eq. 23's `m` (`None` when `ds = 0`).
    pub m: Option<String>,
    /// The step of `m`, when there is one.
    pub step: Option<u32>,
    /// `gouraud` or `corrected-euler`.
    pub decision: &'static str,
}

/// The float bounds of a run, per profile (`docs/float.md` §18): decimals of three
/// significant digits rounded up, `None` where none is derived or proved.
#[derive(Debug, Serialize)]
pub struct ErrorBounds {
    /// This crate's own operation order.
    pub reference: Option<String>,
    /// Every IEEE round-to-nearest implementation of the catalogued forms.
    pub ieee: Option<String>,
    /// The Vulkan/WGSL rules (`f32` only: absent for `f64`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shader: Option<Option<String>>,
}

/// What `phong-approx span` prints: serialized in this order, absent fields left out.
#[derive(Debug, Serialize)]
pub struct SpanReport {
    /// The method's name.
    pub method: String,
    /// The number type's name.
    pub scalar: &'static str,
    /// `n`.
    pub steps: u32,
    /// The `n + 1` values, formatted.
    pub values: Values,
    /// Their 8-bit levels, `None` where not known.
    pub levels: Vec<Option<u8>>,
    /// For exact runs of the field-operation methods: each value as a fraction.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fractions: Option<Vec<String>>,
    /// For `f32` and `f64` runs: the bounds per profile.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_bound: Option<ErrorBounds>,
    /// How each of those bounds is known: `proved (theorem)` or `derived (section)`
    /// (`None` where there is no bound), from the one table of labels
    /// ([`crate::tolerance::profile::status`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_bound_status: Option<ErrorBounds>,
    /// The cosine table's size, for the tabled angular method.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub table_size: Option<u32>,
    /// The MPFR precision.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub precision: Option<u32>,
    /// The adaptive scheme's test.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub adaptive: Option<Adaptive>,
}

/// Runs the request.
///
/// # Errors
/// A [`ReportError`] naming the argument: inputs that are not unit vectors (without
/// `normalize`), opposite normals for a method undefined there, digits that cannot be
/// known, a build without MPFR asked for MPFR.
pub fn span_report(r: &Request) -> Result<SpanReport, ReportError> {
    let o = match r.arithmetic {
        Arithmetic::F32 => run_typed::<f32>(r)?,
        Arithmetic::F64 => run_typed::<f64>(r)?,
        Arithmetic::Exact => run_exact(r)?,
        Arithmetic::Mpfr(precision) => run_mpfr(r, precision)?,
    };
    let u = match r.arithmetic {
        Arithmetic::F32 => Some(f32::unit_roundoff()),
        Arithmetic::F64 => Some(f64::unit_roundoff()),
        _ => None,
    };
    let bounds = u.map(|u| error_bounds(r, u));
    Ok(SpanReport {
        method: r.method.name().into_owned(),
        scalar: r.arithmetic.name(),
        steps: r.n,
        values: o.values,
        levels: o.levels,
        fractions: o.fractions,
        error_bound_status: u
            .zip(bounds.as_ref())
            .map(|(u, b)| error_bound_status(r, u, b)),
        error_bound: bounds,
        table_size: match r.method {
            Method::AngularTable(size) => Some(size),
            _ => None,
        },
        precision: match r.arithmetic {
            Arithmetic::Mpfr(p) => Some(p),
            _ => None,
        },
        adaptive: o.adaptive,
    })
}

/// What a run produced, formatted.
struct Outcome {
    values: Values,
    fractions: Option<Vec<String>>,
    levels: Vec<Option<u8>>,
    adaptive: Option<Adaptive>,
}

fn span_error(e: SpanError, normalize: bool) -> ReportError {
    let arg = |i: Input| match i {
        Input::Na => "--na",
        Input::Nb => "--nb",
        Input::L => "--light",
    };
    match e {
        SpanError::NonFinite { input, component } => ReportError::new(
            arg(input),
            format!(
                "component {} is not finite in this number type",
                component + 1
            ),
        ),
        SpanError::ZeroVector { input } => ReportError::new(arg(input), "the vector is zero"),
        SpanError::NotUnit {
            input,
            length_squared,
            deviation,
            tolerance,
        } => ReportError::new(
            arg(input),
            format!(
                "not a unit vector (length² = {}, |length² − 1| = {}, {}){}",
                shown(&length_squared),
                shown(&deviation),
                if tolerance == 0.0 {
                    "exact arithmetic allows only exactly 1".to_string()
                } else {
                    format!("allowed ≤ {tolerance:.3e}")
                },
                if normalize {
                    ""
                } else {
                    "; pass --normalize to normalize it"
                }
            ),
        ),
        SpanError::Opposite => ReportError::new(
            "--nb",
            "Nb = −Na: this method is undefined for opposite normals (no unique arc between them)",
        ),
        SpanError::ZeroSteps => ReportError::new("--steps", "n must be at least 1"),
        SpanError::TooManySteps { max, got } => {
            ReportError::new("--steps", format!("n must be at most {max} (got {got})"))
        }
        other => ReportError::new("span", other),
    }
}

/// A run's span, values and (for `adaptive`) decision.
type Computed<T> = (Span<T>, Vec<T>, Option<Decision<T>>);

/// Runs the request in `T`.
fn compute<T: Real>(r: &Request) -> Result<Computed<T>, ReportError> {
    let conv = |v: &Vec3<BigRational>| v.cast::<T>().expect("rationals are finite");
    let (na, nb, l) = (conv(&r.na), conv(&r.nb), conv(&r.l));
    let span = if r.normalize {
        Span::normalized(na, nb, l, r.n)
    } else {
        Span::new(na, nb, l, r.n)
    }
    .map_err(|e| span_error(e, r.normalize))?;
    let mut out = vec![T::zero(); span.len()];
    let prep = Prepared::new(r.method, T::from_rational(&r.kd))
        .map_err(|e| ReportError::new("--table-size", e))?;
    let decision = r
        .method
        .run(&span, &prep, &mut out)
        .map_err(|e| span_error(e, r.normalize))?;
    Ok((span, out, decision))
}

fn outcome<T: Real + 'static>(
    r: &Request,
    values: Vec<T>,
    decision: Option<Decision<T>>,
    levels: Option<Vec<Option<u8>>>,
) -> Outcome {
    let digits = r.digits;
    let fmt = move |v: &T| v.to_decimal(digits);
    let levels = levels.unwrap_or_else(|| values.iter().map(|v| Some(level(v))).collect());
    let adaptive = decision.map(|d| Adaptive {
        delta: fmt(&d.delta),
        m: d.m.as_ref().map(fmt),
        step: d.step,
        decision: d.choice.name(),
    });
    Outcome {
        values: Values {
            len: values.len(),
            at: Box::new(move |i| fmt(&values[i])),
        },
        fractions: None,
        levels,
        adaptive,
    }
}

fn run_typed<T: Real + 'static>(r: &Request) -> Result<Outcome, ReportError> {
    let (_, values, decision) = compute::<T>(r)?;
    Ok(outcome(r, values, decision, None))
}

/// A positive `x` as a decimal of three significant digits, rounded up (the slack
/// `1e-12` covers the rounding of the scaling in `f64`).
fn round_up_3(x: f64) -> String {
    let mut e = x.log10().floor() as i32;
    let mut m = (x * (1.0 + 1e-12) / 10f64.powi(e - 2)).ceil() as u64;
    if m >= 1000 {
        m = m.div_ceil(10);
        e += 1;
    }
    format!("{}.{:02}e{e}", m / 100, m % 100)
}

/// The bounds per profile: `reference` (this crate's own operation order,
/// [`crate::tolerance::span_bound`]), `ieee` and `shader` (for every implementation of
/// the profile, [`crate::tolerance::profile`]; `shader` only for `f32`). `None`
/// where none is derived or proved, and for every profile with `normalize`, whose
/// float normalization no derivation covers.
fn error_bounds(r: &Request, u: f64) -> ErrorBounds {
    use crate::tolerance::profile::{profile_span_bound, Form, Profile};
    let shape = (!r.normalize)
        .then(|| Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok())
        .flatten()
        .map(|s| crate::tolerance::Shape::of(&s));
    let of = |m: Method, p: Profile| -> Option<f64> {
        let shape = shape.as_ref()?;
        match p {
            Profile::Reference => crate::tolerance::span_bound(m, shape, u),
            p => profile_span_bound(m, p, Form::Any, shape, u),
        }
    };
    // The adaptive scheme where its test is too close to call
    // (`tolerance::adaptive_too_close`): the float run may pick the other method, whose values differ from the exact pick's
    // by at most `|δ|` (eq. 24's δ is the largest difference, `eq_24_delta_is_max_difference`),
    // so the bound against the exact run's pick is the larger bound plus `|δ|`.
    let delta = (r.method == Method::Adaptive && !r.normalize)
        .then(|| Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok())
        .flatten()
        .map(|s| {
            let d = crate::adaptive::decide(&s, &r.kd);
            (d.delta.to_f64().abs(), r.kd.to_f64())
        });
    let bound = |p: Profile| -> Option<String> {
        let b = of(r.method, p)?;
        let b = match delta {
            Some((d, kd)) => {
                let (bg, bce) = (of(Method::Gouraud, p)?, of(Method::CorrectedEuler, p)?);
                if crate::tolerance::adaptive_too_close(d, kd, bg, bce, u) {
                    bg.max(bce) + d * (1.0 + 1e-12)
                } else {
                    b
                }
            }
            None => b,
        };
        Some(round_up_3(b))
    };
    ErrorBounds {
        reference: bound(Profile::Reference),
        ieee: bound(Profile::Ieee),
        shader: (u == f64::from(f32::EPSILON) / 2.0).then(|| bound(Profile::Shader)),
    }
}

/// The labels of the bounds `printed` ([`error_bounds`]): the reference profile's from the
/// catalogue (Gouraud and corrected Euler proved in this crate's order,
/// `proofs/Float.v`; the others derived in their `docs/float.md` section), the
/// acceptance profiles' from [`crate::tolerance::profile::status`]; `None` where no
/// bound is printed.
fn error_bound_status(r: &Request, u: f64, printed: &ErrorBounds) -> ErrorBounds {
    use crate::tolerance::profile::{status, Profile, Status};
    let label = |p: Profile, shown: &Option<String>| -> Option<String> {
        shown.as_ref()?;
        let s = match p {
            Profile::Reference => {
                let b32 = u == f64::from(f32::EPSILON) / 2.0;
                match r.method {
                    Method::Gouraud if r.n <= 4096 && b32 => {
                        Status::Proved("float_gouraud_binary32")
                    }
                    Method::Gouraud if r.n <= 4096 => Status::Proved("float_gouraud_binary64"),
                    Method::CorrectedEuler if r.n <= 4096 && b32 => {
                        Status::Proved("float_corrected_euler_binary32")
                    }
                    Method::CorrectedEuler if r.n <= 4096 => {
                        Status::Proved("float_corrected_euler_binary64")
                    }
                    m => {
                        return Some(format!(
                            "derived (docs/float.md {})",
                            m.info().float_section
                        ))
                    }
                }
            }
            p => status(r.method, p, u)?,
        };
        Some(s.label())
    };
    ErrorBounds {
        reference: label(Profile::Reference, &printed.reference),
        ieee: label(Profile::Ieee, &printed.ieee),
        shader: printed.shader.as_ref().map(|s| label(Profile::Shader, s)),
    }
}

/// Where the digits asked for are more than is known: the first such pixel and how
/// many significant digits of it are known.
struct Short {
    pixel: usize,
    known: usize,
}

impl Short {
    fn error(&self, bits: i64) -> ReportError {
        let message = if self.known == 0 {
            format!(
                "no digit of pixel {} is known: computed to 2^-{bits}, the value lies within that of 0 or of a change of its leading digit",
                self.pixel
            )
        } else {
            format!(
                "only {} significant digits of pixel {} are known (these values are computed to 2^-{bits}); ask for at most that many",
                self.known, self.pixel
            )
        };
        ReportError::new("--digits", message)
    }
}

/// Where a value of exactly 0 is the method's exact value, not a rounded one: a tabled
/// cosine's last entry, and a pixel whose exact value is Phong's `p/√q` ([`crate::method::PhongPixels::exact_at`])
/// with `p = 0` on the exact span. With `normalize` the span's inputs are themselves
/// rounded, and only the end pixels keep an exact zero (`N_a·L = 0` or `N_b·L = 0` on
/// the inputs as given: normalizing scales a dot product, it cannot make it zero).
fn exact_zeros(r: &Request) -> impl Fn(usize) -> bool + '_ {
    use num_traits::Zero;
    let phong = r.method.info().phong_pixels;
    let span = (!r.normalize)
        .then(|| Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok())
        .flatten();
    move |i: usize| {
        let Ok(i) = u32::try_from(i) else {
            return false;
        };
        // A tabled cosine of 0 is the table's last entry, cos 90° = 0, held exactly
        // (`angular::CosTable::new`).
        if phong == crate::method::PhongPixels::Table {
            return true;
        }
        match &span {
            Some(s) => phong.exact_at(s, i).is_some_and(|(p, _)| p.is_zero()),
            None => {
                let end = (i == 0).then_some(&r.na).or((i == r.n).then_some(&r.nb));
                end.is_some_and(|n| phong.at(r.n, i) && n.dot(&r.l).is_zero())
            }
        }
    }
}

/// Checks that every value's digits are known: a value's digits are printed only if
/// its lower and upper ends (±2^-bits) print the same. A value of 0 is printed as `0`
/// only where it is exactly zero (`exact_zero(pixel)`); elsewhere a computed 0 is a
/// value within 2^-bits of zero like any other, whose first digit is not known.
fn check_digits<T: Real>(
    r: &Request,
    values: &[T],
    bits: i64,
    exact_zero: impl Fn(usize) -> bool,
) -> Result<(), Short> {
    use num_traits::One;
    if bits < 4 {
        return Err(Short { pixel: 0, known: 0 });
    }
    let e = BigRational::new(
        num_bigint::BigInt::one(),
        num_bigint::BigInt::one() << (bits as usize),
    );
    for (i, v) in values.iter().enumerate() {
        let Some(v) = v.to_rational() else {
            continue;
        };
        if num_traits::Zero::is_zero(&v) && exact_zero(i) {
            continue;
        }
        let (lo, hi) = (v.clone() - e.clone(), v.clone() + e.clone());
        if lo.to_decimal(r.digits) != hi.to_decimal(r.digits) {
            // About log10(|v|/e) digits are known: search down from just above that
            // (not from the digits asked for, which may be thousands).
            let guess = ((v.to_f64().abs().max(f64::MIN_POSITIVE).log2() + bits as f64)
                * std::f64::consts::LOG10_2)
                .max(0.0) as usize
                + 2;
            let known = (1..r.digits.min(guess + 1))
                .rev()
                .find(|&d| lo.to_decimal(d) == hi.to_decimal(d))
                .unwrap_or(0);
            return Err(Short { pixel: i, known });
        }
    }
    Ok(())
}

/// `⌈log2(1/q_min)⌉` (0 when `q_min ≥ 1`), from the span's own `q_min`.
#[cfg(feature = "mpfr")]
fn q_bits<T: Real>(span: &Span<T>) -> i64 {
    let q = span.q_min().to_f64();
    if q >= 1.0 {
        0
    } else if q > 0.0 {
        (-q.log2()).ceil() as i64
    } else {
        i64::MAX / 4
    }
}

/// The bits known of the exact values ([`Method::exact_bits`]). Rational methods on
/// exact inputs are exact (`None`: every digit is known).
///
/// With `normalize` the inputs are normalized through square roots accurate to
/// 2^-b (`b` = [`crate::reference::transcendental::bits`], 256 unless the run asks
/// for more), so `p_a`, `p_b` and every dot product are off by at most 2^-(b − 18):
/// what the exact run's own accounting allows for an error of 2^-(b − 6), less 16
/// bits, and at most `b − 76` bits (180 at the default). Angular interpolation takes
/// `acos p`, which moves by `e/sin θ` (or at most `2.23·√e`, acos being ½-Hölder with
/// constant `π/√2`) when `p` moves by `e`: `max(b − 19 − ⌈log2(1/sin θ)⌉, (b − 18)/2 − 2)`
/// bits.
fn exact_bits(r: &Request, span: &Span<BigRational>) -> Option<i64> {
    if !r.normalize {
        return r.method.exact_bits(span);
    }
    let b = i64::from(crate::reference::transcendental::bits());
    let own = r
        .method
        .exact_bits(span)
        .map_or(b - 76, |own| (own - 16).min(b - 76));
    if !matches!(r.method, Method::Angular) {
        return Some(own);
    }
    // sin²θ ≥ 1 − (|p| + e)² at both ends (the f64 rounding of p is far above e).
    let s2 = [&span.p_a, &span.p_b]
        .iter()
        .map(|p| 1.0 - (p.to_f64().abs() + 1e-30).powi(2))
        .fold(f64::INFINITY, f64::min);
    let by_slope = if s2 > 0.0 {
        b - 19 - (-0.5 * s2.log2()).ceil() as i64
    } else {
        0
    };
    Some(own.min(by_slope.max((b - 18) / 2 - 2)))
}

/// The bits known of MPFR values at `precision` bits: every operation is correctly
/// rounded, and the recurrences' rounding grows at most like `n²` steps of the
/// unit roundoff (docs/float.md §6–8), plus `q_bits` for the Phong-valued methods and
/// what [`Method::exact_bits`] says the exact run loses for the others (`span`, the
/// exact span of the request); 8 bits of margin.
#[cfg(feature = "mpfr")]
fn mpfr_bits(r: &Request, span: Option<&Span<BigRational>>, precision: u32, q_bits: i64) -> i64 {
    let n_bits = 64 - u64::from(r.n + 1).leading_zeros() as i64;
    // In MPFR `q` is rounded too: the Phong-valued methods lose all of `q_bits`;
    // the others what the exact run loses (`Method::exact_bits`).
    let loss = if r.method.is_phong_valued() {
        q_bits
    } else {
        span.map_or(0, |s| r.method.exact_bits(s).map_or(0, |b| 250 - b))
    };
    i64::from(precision) - 8 - 2 * n_bits - loss
}

/// The levels of an exact `normalize` run: from `values` (known to `2^-bits`) where
/// that decides them, else exactly for the normalized inputs
/// ([`crate::reference::radical`]) at the pixels whose value is known in closed form:
/// Phong's `p/√q` where the method's is, Gouraud's, Euler's and corrected Euler's
/// everywhere; undecided (`None`) elsewhere.
fn normalized_levels(r: &Request, values: &[BigRational], bits: i64) -> Vec<Option<u8>> {
    use crate::method::PhongPixels;
    use crate::reference::radical::{normalized_levels, Valued};
    use num_traits::Zero;
    let phong = r.method.info().phong_pixels;
    let cross = Vec3::new(
        r.na.y.clone() * r.nb.z.clone() - r.na.z.clone() * r.nb.y.clone(),
        r.na.z.clone() * r.nb.x.clone() - r.na.x.clone() * r.nb.z.clone(),
        r.na.x.clone() * r.nb.y.clone() - r.na.y.clone() * r.nb.x.clone(),
    );
    // Parallel edge normals: every untabled method is the constant p_a there.
    let parallel = cross.length_squared().is_zero()
        && r.na.dot(&r.nb) > BigRational::zero()
        && !matches!(phong, PhongPixels::None | PhongPixels::Table);
    let field = match r.method {
        Method::Gouraud => Some(Valued::Gouraud),
        Method::Euler => Some(Valued::Euler),
        Method::CorrectedEuler => Some(Valued::CorrectedEuler),
        _ => None,
    };
    let e = BigRational::new(
        1.into(),
        num_bigint::BigInt::from(1) << bits.max(0) as usize,
    );
    let one = BigRational::from_integer(1.into());
    normalized_levels(
        |i| {
            if parallel || phong.at(r.n, i) {
                Some(Valued::Phong)
            } else {
                field
            }
        },
        (&r.na, &r.nb, &r.l),
        r.n,
        &one,
        values,
        &e,
    )
}

/// The most bits an exact run takes to decide a level near a boundary (2^-1024).
const LEVEL_BITS: u32 = 1024;

/// An exact run with every printed digit known: the values, the adaptive decision,
/// the levels (`None` where undecided), the bits the values are known to (`None`:
/// exact).
pub struct ExactRun {
    /// The exact run's values (within 2^-`bits` of the method's exact values).
    pub values: Vec<BigRational>,
    /// Each value to the request's digits, every digit known (a value is `0` only
    /// where it is exactly zero).
    pub decimals: Vec<String>,
    /// The 8-bit levels, `None` where the run does not decide them.
    pub levels: Vec<Option<u8>>,
    /// The bits the values are known to (`None`: exact).
    pub bits: Option<i64>,
    decision: Option<Decision<BigRational>>,
}

/// Runs `r` in exact arithmetic (its `arithmetic` is not read) with square roots,
/// `acos` and `cos` to more bits (from 2^-256 up to 2^-`MAX_BITS`) until every
/// value's `r.digits` significant digits are known, and up to 2^-1024 while a level
/// is within the values' error of a boundary; the one path `span --scalar
/// exact`, the published vectors and `check`'s recomputation of a modified file take.
///
/// # Errors
/// A [`ReportError`]: inputs the span refuses, or digits not known at 2^-`MAX_BITS`.
pub fn exact_run(r: &Request) -> Result<ExactRun, ReportError> {
    use crate::reference::transcendental::{with_bits, BITS, MAX_BITS};
    digits_within_reach(r)?;
    let mut b = BITS;
    loop {
        let attempt = with_bits(
            b,
            || -> Result<Result<ExactRun, (Short, i64)>, ReportError> {
                let (span, values, decision) = compute::<BigRational>(r)?;
                let known = exact_bits(r, &span);
                if let Some(bits) = known {
                    if let Err(short) = check_digits(r, &values, bits, exact_zeros(r)) {
                        return Ok(Err((short, bits)));
                    }
                }
                // Phong-valued methods: the exact level of p/√q decided with rationals
                // only; with normalize, in Q(√a, √b, √c) where the approximate value
                // does not decide it.
                let one = BigRational::from_integer(1.into());
                let levels = if r.normalize {
                    normalized_levels(r, &values, known.unwrap_or(0))
                } else {
                    r.method.exact_levels(&span, &values, &one)
                };
                let decimals = values.iter().map(|v| v.to_decimal(r.digits)).collect();
                Ok(Ok(ExactRun {
                    values,
                    decimals,
                    levels,
                    bits: known,
                    decision,
                }))
            },
        )?;
        match attempt {
            // A level within the run's error of a boundary: decided, if at all, by a
            // few more bits (up to 2^-LEVEL_BITS; closer than that it stays undecided:
            // `span` prints `?`, the vectors refuse the case).
            Ok(o) if o.levels.iter().any(Option::is_none) && b < LEVEL_BITS => b *= 2,
            Ok(o) => return Ok(o),
            Err((short, bits)) if b >= MAX_BITS => return Err(short.error(bits)),
            Err((short, _)) => {
                let missing = r.digits.saturating_sub(short.known) as f64;
                let more = (missing / std::f64::consts::LOG10_2).ceil() as u32 + 16;
                b = (b + more).max(2 * b).min(MAX_BITS);
            }
        }
    }
}

fn run_exact(r: &Request) -> Result<Outcome, ReportError> {
    let run = exact_run(r)?;
    let fractions = r
        .method
        .is_rational()
        .then(|| run.values.iter().map(ToString::to_string).collect());
    let mut o = outcome(r, run.values, run.decision, Some(run.levels));
    o.fractions = fractions;
    o.values = Values::eager(run.decimals);
    Ok(o)
}

/// The digits asked of a method whose exact values are not rational: at most what
/// 2^-`MAX_BITS` gives, refused before any work.
fn digits_within_reach(r: &Request) -> Result<(), ReportError> {
    use crate::reference::transcendental::MAX_BITS;
    let most = (f64::from(MAX_BITS - 64) * std::f64::consts::LOG10_2) as usize;
    if !r.method.is_rational() && r.digits > most {
        return Err(ReportError::new(
            "--digits",
            format!(
                "at most {most} significant digits of {} are computed (its square roots, acos and cos to 2^-{}); ask for at most that many",
                r.method,
                MAX_BITS
            ),
        ));
    }
    Ok(())
}

#[cfg(feature = "mpfr")]
fn run_mpfr(r: &Request, precision: u32) -> Result<Outcome, ReportError> {
    use crate::reference::mpfr::{with_precision, Mpfr};
    with_precision(precision, || {
        let (span, values, decision) = compute::<Mpfr>(r)?;
        let exact = if r.normalize {
            None
        } else {
            Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok()
        };
        let bits = mpfr_bits(r, exact.as_ref(), precision, q_bits(&span));
        check_digits(r, &values, bits, exact_zeros(r)).map_err(|s| s.error(bits))?;
        // A level is printed only where it is known: decided exactly where the value
        // is (Phong's p/√q, p_a), else only where its error cannot cross a boundary.
        let rationals: Vec<BigRational> = values.iter().filter_map(|v| v.to_rational()).collect();
        let levels = match &exact {
            Some(x) if rationals.len() == values.len() => {
                let one = BigRational::from_integer(1.into());
                r.method.levels_within(x, &rationals, &one, Some(bits))
            }
            _ => {
                let e = BigRational::new(
                    1.into(),
                    num_bigint::BigInt::from(1) << bits.max(0) as usize,
                );
                values
                    .iter()
                    .map(|v| {
                        v.to_rational()
                            .and_then(|x| crate::reference::level::level_within(&x, &e))
                    })
                    .collect()
            }
        };
        // Formatted here, within the precision the values were computed at.
        let mut o = outcome(r, values, decision, Some(levels));
        o.values = Values::eager(o.values.iter().collect());
        Ok(o)
    })
}

#[cfg(not(feature = "mpfr"))]
fn run_mpfr(_r: &Request, _precision: u32) -> Result<Outcome, ReportError> {
    Err(ReportError::new(
        "--scalar",
        "mpfr is not in this build; rebuild with `--features mpfr` (needs m4 and a C compiler), e.g. `cargo run --features mpfr -- span ...`",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::unit::unit_from_ints;

    fn request(method: Method, arithmetic: Arithmetic) -> Request {
        Request {
            method,
            na: unit_from_ints(0, 0, 1),
            nb: unit_from_ints(1, 0, 3),
            l: unit_from_ints(0, 0, 1),
            n: 4,
            kd: BigRational::from_integer(1.into()),
            normalize: false,
            digits: 30,
            arithmetic,
        }
    }

    #[test]
    fn a_report_serializes_in_the_documented_order() {
        let r = span_report(&request(Method::Adaptive, Arithmetic::F32)).unwrap();
        let j = serde_json::to_string(&r).unwrap();
        let keys = [
            "\"method\"",
            "\"scalar\"",
            "\"steps\"",
            "\"values\"",
            "\"levels\"",
            "\"error_bound\"",
            "\"delta\"",
            "\"m\"",
            "\"step\"",
            "\"decision\"",
        ];
        let at: Vec<usize> = keys.iter().map(|k| j.find(k).unwrap()).collect();
        assert!(at.windows(2).all(|w| w[0] < w[1]), "{j}");
        assert!(j.contains("\"shader\""), "{j}");
        let r = span_report(&request(Method::Gouraud, Arithmetic::F64)).unwrap();
        let j = serde_json::to_string(&r).unwrap();
        assert!(!j.contains("shader") && !j.contains("fractions") && !j.contains("delta"));
    }

    #[test]
    fn exact_runs_of_rational_methods_give_fractions() {
        let r = span_report(&request(Method::CorrectedEuler, Arithmetic::Exact)).unwrap();
        assert_eq!(r.fractions.as_ref().map(Vec::len), Some(5));
        assert!(r.error_bound.is_none());
        assert!(r.levels.iter().all(Option::is_some));
    }

    #[test]
    fn budgets_refuse_what_takes_minutes() {
        let mut q = request(Method::Phong, Arithmetic::Exact);
        q.n = SPAN_BUDGET + 1;
        assert_eq!(q.within_budget().unwrap_err().arg, "--steps");
        q.arithmetic = Arithmetic::F64;
        assert!(q.within_budget().is_ok());
    }
}
