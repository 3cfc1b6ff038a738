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
use crate::{BigRational, Method, Real, Scalar, Span, SpanError, Vec3};
use serde::ser::{SerializeSeq, Serializer};
use serde::Serialize;
use std::fmt;

mod bounds;
mod decide;
mod error;
mod exact;

use bounds::{error_bound_status, error_bounds};
pub use error::{Field, Remedy, ReportError};
pub use exact::{exact_run, ExactRun};
use exact::{run_exact, run_mpfr};

/// The most steps (and cosine-table entries) an exact or MPFR run takes without
/// being told to ([`Remedy::RunAnyway`]): about half a minute of work.
pub const SPAN_BUDGET: u32 = 1 << 16;

/// The most output a report writes without being told to ([`Remedy::RunAnyway`]).
pub const OUTPUT_BUDGET: u64 = 1 << 30;

pub use crate::format::Arithmetic;

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

impl Request {
    /// Checks the request against the budgets: an exact or MPFR run of more than
    /// [`SPAN_BUDGET`] steps or table entries, an exact run whose estimated work
    /// exceeds `check`'s ([`crate::budget::exact_work`]), or more
    /// than [`OUTPUT_BUDGET`] bytes of output.
    ///
    /// # Errors
    /// A [`ReportError`] naming the field to change ([`Remedy::RunAnyway`]: or run anyway).
    pub fn within_budget(&self) -> Result<(), ReportError> {
        use crate::budget::{exact_work, input_bits, MAX_RECOMPUTED_WORK};
        let (n, method, digits) = (self.n, self.method, self.digits);
        let exact = self.arithmetic.is_exact();
        if exact && n > SPAN_BUDGET {
            return Err(ReportError::new(
                Field::Steps,
                format!(
                    "{n} steps in exact arithmetic take minutes or more (budget {SPAN_BUDGET})"
                ),
            )
            .or(Remedy::RunAnyway));
        }
        if self.arithmetic == Arithmetic::Exact {
            let work = exact_work(
                method,
                n,
                input_bits(&[&self.na, &self.nb, &self.l]),
                digits,
            );
            // A tabled cosine builds its table before the first pixel: where the table
            // alone is over the budget, the table's size is what to change.
            let table_work = match method {
                Method::AngularTable(_) => exact_work(
                    method,
                    0,
                    input_bits(&[&self.na, &self.nb, &self.l]),
                    digits,
                ),
                _ => 0,
            };
            if table_work > MAX_RECOMPUTED_WORK {
                if let Method::AngularTable(size) = method {
                    return Err(ReportError::new(
                        Field::TableSize,
                        format!(
                            "a table of {size} exact cosines to these digits takes about {}× the budget of half a minute",
                            table_work.div_ceil(MAX_RECOMPUTED_WORK)
                        ),
                    )
                    .or(Remedy::RunAnyway));
                }
            }
            if work > MAX_RECOMPUTED_WORK {
                return Err(ReportError::new(
                    Field::Steps,
                    format!(
                        "{n} steps of {method} in exact arithmetic with these inputs and digits take about {}× the budget of half a minute",
                        work.div_ceil(MAX_RECOMPUTED_WORK)
                    ),
                )
                .or(Remedy::RunAnyway));
            }
        }
        if let Method::AngularTable(size) = method {
            if exact && size > SPAN_BUDGET {
                return Err(ReportError::new(
                    Field::TableSize,
                    format!("a table of {size} exact cosines takes minutes (budget {SPAN_BUDGET})"),
                )
                .or(Remedy::RunAnyway));
            }
        }
        // Per pixel: the value (quoted, indented), its level, and for exact runs of
        // the field-operation methods a fraction of about the same length.
        let per_pixel = if exact { 2 * (digits + 12) + 10 } else { 42 };
        let bytes = (u64::from(n) + 1) * per_pixel as u64;
        if bytes > OUTPUT_BUDGET {
            return Err(ReportError::new(
                Field::Digits,
                format!(
                    "the output would be about {} MiB (budget {} MiB); ask for fewer digits or steps",
                    bytes >> 20,
                    OUTPUT_BUDGET >> 20
                ),
            )
            .or(Remedy::RunAnyway));
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
    pub scalar: String,
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
        other => {
            return Err(ReportError::new(
                Field::Arithmetic,
                format!("span runs in f32, f64, exact rationals or MPFR, not {other}"),
            ))
        }
    };
    let format = r.arithmetic.format();
    let bounds = format.map(|f| error_bounds(r, f));
    Ok(SpanReport {
        method: r.method.name().into_owned(),
        scalar: r.arithmetic.name().into_owned(),
        steps: r.n,
        values: o.values,
        levels: o.levels,
        fractions: o.fractions,
        error_bound_status: format
            .zip(bounds.as_ref())
            .map(|(f, b)| error_bound_status(r, f, b)),
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
    let arg = Field::from;
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
                "not a unit vector (length² = {}, |length² − 1| = {}, {})",
                shown(&length_squared),
                shown(&deviation),
                if tolerance == 0.0 {
                    "exact arithmetic allows only exactly 1".to_string()
                } else {
                    format!("allowed ≤ {tolerance:.3e}")
                },
            ),
        )
        .or(if normalize {
            Remedy::None
        } else {
            Remedy::Normalize
        }),
        SpanError::Opposite => ReportError::new(
            Field::Nb,
            "Nb = −Na: this method is undefined for opposite normals (no unique arc between them)",
        ),
        SpanError::ZeroSteps => ReportError::new(Field::Steps, "n must be at least 1"),
        SpanError::TooManySteps { max, got } => {
            ReportError::new(Field::Steps, format!("n must be at most {max} (got {got})"))
        }
        other => ReportError::new(Field::Span, other),
    }
}

/// A run's span, values and (for `adaptive`) decision.
type Computed<T> = (Span<T>, Vec<T>, Option<Decision<T>>);

/// Runs the request in `T`.
fn compute<T: Real>(r: &Request) -> Result<Computed<T>, ReportError> {
    let conv = |v: &Vec3<BigRational>| v.cast::<T>().expect("rationals are finite");
    let (na, nb, l) = (conv(&r.na), conv(&r.nb), conv(&r.l));
    // A non-zero vector whose every component rounds to 0 in this number type is not
    // "zero": it underflows (1e-300 in f32), and the message says so.
    for (exact, typed, field) in [
        (&r.na, &na, Field::Na),
        (&r.nb, &nb, Field::Nb),
        (&r.l, &l, Field::Light),
    ] {
        let exact_zero = exact
            .components()
            .iter()
            .all(|c| num_traits::Zero::is_zero(*c));
        if !exact_zero && typed.components().iter().all(|c| c.is_zero()) {
            return Err(ReportError::new(
                field,
                format!(
                    "every component underflows to 0 in {}: the vector is too small for this number type (only its direction counts: scale it up, or use a wider type)",
                    r.arithmetic
                ),
            ));
        }
    }
    let span = if r.normalize {
        Span::normalized(na, nb, l, r.n)
    } else {
        Span::new(na, nb, l, r.n)
    }
    .map_err(|e| span_error(e, r.normalize))?;
    let mut out = vec![T::zero(); span.len()];
    let prep = Prepared::new(r.method, T::from_rational(&r.kd))
        .map_err(|e| ReportError::new(Field::TableSize, e))?;
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
        let r = span_report(&request(Method::Euler, Arithmetic::Exact)).unwrap();
        assert_eq!(r.fractions.as_ref().map(Vec::len), Some(5));
        assert!(r.error_bound.is_none());
        assert!(r.levels.iter().all(Option::is_some));
    }

    #[test]
    fn budgets_refuse_what_takes_minutes() {
        let mut q = request(Method::Phong, Arithmetic::Exact);
        q.n = SPAN_BUDGET + 1;
        let e = q.within_budget().unwrap_err();
        assert_eq!((e.field, e.remedy), (Field::Steps, Remedy::RunAnyway));
        q.arithmetic = Arithmetic::F64;
        assert!(q.within_budget().is_ok());
    }

    #[test]
    fn arithmetics_without_a_span_run_are_refused_naming_the_number_type() {
        for a in [
            Arithmetic::Float(crate::Format::Binary16),
            Arithmetic::Fixed {
                int_bits: 16,
                frac_bits: 16,
            },
        ] {
            let e = span_report(&request(Method::Gouraud, a)).unwrap_err();
            assert_eq!(e.field, Field::Arithmetic, "{a}");
            assert!(e.message.contains(&*a.name()), "{a}: {}", e.message);
        }
    }
}
