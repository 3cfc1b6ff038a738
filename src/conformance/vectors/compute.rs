//! The exact expectations of a case: its inputs as fractions, each method's exact run
//! decided to levels, the specular values, from a [`CaseSpec`].

use super::*;

fn fraction(x: &BigRational) -> String {
    x.to_string()
}

fn input(v: &Vec3<BigRational>) -> VectorInput {
    let c = [&v.x, &v.y, &v.z];
    VectorInput {
        exact: c.map(fraction),
        f32: c.map(|x| format!("{:?}", f32::from_rational(x))),
        f64: c.map(|x| format!("{:?}", f64::from_rational(x))),
    }
}

/// Decided levels, or the message naming the first pixel whose level the exact run
/// cannot decide (its value within its error of a level boundary).
fn decided(levels: Vec<Option<u8>>, method: Method, what: &str) -> Result<Vec<u8>, VectorError> {
    levels
        .into_iter()
        .enumerate()
        .map(|(i, l)| {
            l.ok_or_else(|| {
                VectorError::file(format!(
                    "{method}: the {what} level of pixel {i} is not decided by the exact run"
                ))
            })
        })
        .collect()
}

/// The exact run of `method` on `span` with every one of the [`DIGITS`] digits known
/// (square roots, `acos` and `cos` taken to more bits until they are:
/// [`crate::span_report::exact_run`], the path `span --scalar exact` takes).
fn exact_run(
    method: Method,
    span: &Span<BigRational>,
) -> Result<crate::span_report::ExactRun, VectorError> {
    use crate::span_report::{exact_run, Arithmetic, Request};
    exact_run(&Request {
        method,
        na: span.na.clone(),
        nb: span.nb.clone(),
        l: span.l.clone(),
        n: span.n,
        kd: BigRational::from_integer(1.into()),
        normalize: false,
        digits: DIGITS,
        arithmetic: Arithmetic::Exact,
    })
    .map_err(|e| VectorError::file(format!("{method}: {}", e.message)))
}

/// The exact expectations of `method` on `span` (values to [`DIGITS`] digits, every
/// one known; levels decided exactly, [`Method::exact_levels`]).
fn expected(method: Method, span: &Span<BigRational>) -> Result<Expected, VectorError> {
    let run = exact_run(method, span)?;
    let levels = decided(run.levels, method, "diffuse")?;
    Ok(Expected {
        values: run.decimals,
        levels,
    })
}

/// The specular expectations `max(0, v)^s` of `method` on `span_h` (`N·H`): the base
/// values with every digit known, and each power's [`DIGITS`] digits checked against
/// the powers of the base's bounds `v ± 2^-bits` (refused where they differ).
fn specular_expected(
    method: Method,
    span_h: &Span<BigRational>,
    s: u32,
) -> Result<Expected, VectorError> {
    let run = exact_run(method, span_h)?;
    let base = run.values;
    let v: Vec<BigRational> = base.iter().map(|x| power(x, s)).collect();
    if let Some(bits) = run.bits {
        let e = BigRational::new(1.into(), BigInt::from(1) << bits.max(0) as usize);
        for (i, x) in base.iter().enumerate() {
            let (lo, hi) = (power(&(x - &e), s), power(&(x + &e), s));
            if lo.to_decimal(DIGITS) != hi.to_decimal(DIGITS) {
                return Err(VectorError::file(format!(
                    "{method}: the specular value of pixel {i} is not known to {DIGITS} digits"
                )));
            }
        }
    }
    let levels = decided(
        method.exact_power_levels(span_h, &base, s),
        method,
        "specular",
    )?;
    Ok(Expected {
        values: v.iter().map(|x| x.to_decimal(DIGITS)).collect(),
        levels,
    })
}

/// The largest shininess `s` a vector file may give (`check` refuses a file with a
/// larger one before any work: the exact power `v^s` grows with `s`).
pub const MAX_SHININESS: u32 = 10_000;

/// One case of a set before its expectations are computed: its id, comment and exact
/// unit inputs. [`specs`] lists a set's cases; [`CaseSpec::compute`] computes one, so a
/// part of a set can be regenerated without the rest (the default test tier checks the
/// short cases, the extensive tier every file byte for byte).
#[derive(Clone, Debug)]
pub struct CaseSpec {
    /// The case id, e.g. `edge-003`.
    pub id: String,
    /// Why the case is there.
    pub comment: &'static str,
    /// `N_a`, exactly unit.
    pub na: Vec3<BigRational>,
    /// `N_b`, exactly unit.
    pub nb: Vec3<BigRational>,
    /// `L`, exactly unit.
    pub l: Vec3<BigRational>,
    /// Steps.
    pub n: u32,
    /// The half vector and exponent of the specular expectations, if any.
    pub h: Option<(Vec3<BigRational>, u32)>,
}

/// A case spec from its parts.
pub(super) fn make_case(
    id: String,
    comment: &'static str,
    na: Vec3<BigRational>,
    nb: Vec3<BigRational>,
    l: Vec3<BigRational>,
    n: u32,
    h: Option<(Vec3<BigRational>, u32)>,
) -> CaseSpec {
    CaseSpec {
        id,
        comment,
        na,
        nb,
        l,
        n,
        h,
    }
}

impl CaseSpec {
    /// The case with its exact expectations.
    ///
    /// # Errors
    /// A level at some pixel that the exact run cannot decide (named, with the method
    /// and pixel).
    pub fn compute(self) -> Result<Case, VectorError> {
        let CaseSpec {
            id,
            comment,
            na,
            nb,
            l,
            n,
            h,
        } = self;
        let exact = ExactCase {
            id,
            comment,
            na,
            nb,
            l,
            n,
            h,
        };
        compute_case_for(&Method::ALL, exact)
    }
}

/// A case from an exact span (exactly unit inputs), with the expectations of
/// `methods` only: what the test kit's `check_span` judges against.
///
/// # Errors
/// As [`CaseSpec::compute`].
pub(crate) fn case_for_span(
    methods: &[Method],
    id: &str,
    comment: &str,
    span: &Span<BigRational>,
) -> Result<Case, VectorError> {
    let exact = ExactCase {
        id: id.to_string(),
        comment,
        na: span.na.clone(),
        nb: span.nb.clone(),
        l: span.l.clone(),
        n: span.n,
        h: None,
    };
    compute_case_for(methods, exact)
}

/// A case's exact inputs, whose expectations [`compute_case_for`] computes: a
/// [`CaseSpec`] whose comment may be borrowed (from a file being recomputed).
pub(super) struct ExactCase<'a> {
    /// The case id.
    pub id: String,
    /// Why the case is there.
    pub comment: &'a str,
    /// `N_a`, exactly unit.
    pub na: Vec3<BigRational>,
    /// `N_b`, exactly unit.
    pub nb: Vec3<BigRational>,
    /// `L`, exactly unit.
    pub l: Vec3<BigRational>,
    /// Steps.
    pub n: u32,
    /// The half vector and exponent of the specular expectations, if any.
    pub h: Option<(Vec3<BigRational>, u32)>,
}

/// A case from exact unit inputs, with the expectations of `methods`.
pub(super) fn compute_case_for(methods: &[Method], exact: ExactCase) -> Result<Case, VectorError> {
    let ExactCase {
        id,
        comment,
        na,
        nb,
        l,
        n,
        h,
    } = exact;
    let at = |e: VectorError| VectorError::case(&id, e.problem);
    let span = Span::new(na.clone(), nb.clone(), l.clone(), n)
        .map_err(|e| VectorError::case(&id, e.to_string()))?;
    let q_min = (0..=n)
        .map(|i| span.q_at(i).to_f64())
        .fold(f64::INFINITY, f64::min);
    let d = adaptive::decide(&span, &BigRational::from_i64(1));
    let expected = methods
        .iter()
        .map(|&m| Ok((method_key(m), self::expected(m, &span)?)))
        .collect::<Result<_, VectorError>>()
        .map_err(at)?;
    let specular = h.map(|(h, s)| -> Result<SpecularCase, VectorError> {
        let span_h = Span::new(na.clone(), nb.clone(), h.clone(), n)
            .map_err(|e| VectorError::file(format!("specular: {e}")))?;
        let expected = methods
            .iter()
            .map(|&m| Ok((method_key(m), specular_expected(m, &span_h, s)?)))
            .collect::<Result<_, VectorError>>()?;
        Ok(SpecularCase {
            h: input(&h),
            s,
            expected,
        })
    });
    let specular = specular.transpose().map_err(at)?;
    Ok(Case {
        id,
        comment: comment.to_string(),
        na: input(&na),
        nb: input(&nb),
        l: input(&l),
        n,
        q_min,
        delta: d.delta.to_decimal(DIGITS),
        decision: d.choice.name().to_string(),
        expected,
        specular,
    })
}
