//! `phong-approx span`: one scan line, one method, one number type.

use super::{parse_whole, CliError};
use clap::Args;
use phong_approx::adaptive::{self, Decision};
use phong_approx::angular::CosTable;
use phong_approx::conformance::shown;
use phong_approx::parse::{parse_rational, parse_vec3};
use phong_approx::quantize::level;
use phong_approx::reference::level::phong_level_exact;
use phong_approx::{BigRational, Input, Method, Real, Scalar, Span, SpanError, Vec3};
use serde_json::{json, Value};

/// Arguments of `phong-approx span`.
#[derive(Args, Debug)]
pub struct SpanArgs {
    /// phong, duff, symmetric-phong, gouraud, euler, corrected-euler, adaptive or angular.
    #[arg(long, value_name = "NAME")]
    pub method: String,
    /// Unit normal at the left edge, N_a: three decimals or fractions, e.g. 0.6,0,0.8.
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub na: String,
    /// Unit normal at the right edge, N_b.
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub nb: String,
    /// Unit light vector L (or half vector H).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    pub light: String,
    /// Number of steps n ≥ 1; the span has n + 1 pixels.
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub steps: String,
    /// Number type: f32, f64, exact (rationals) or mpfr (needs the `mpfr` feature).
    #[arg(long, value_name = "TYPE", default_value = "f64")]
    pub scalar: String,
    /// Output: json or table.
    #[arg(long, value_name = "FORMAT", default_value = "json")]
    pub format: String,
    /// Normalize N_a, N_b and L first instead of requiring unit vectors (for exact,
    /// the result is unit to 2^-256, not exactly).
    #[arg(long)]
    pub normalize: bool,
    /// Diffuse coefficient K_d of the adaptive test |δ·255·K_d| < 1 (eq. 24).
    #[arg(
        long,
        value_name = "KD",
        default_value = "1",
        allow_hyphen_values = true
    )]
    pub kd: String,
    /// For `angular`: read the cosine from a table of this many entries over 0–90°
    /// (the second source uses 256) instead of computing it.
    #[arg(long, value_name = "SIZE")]
    pub table_size: Option<String>,
    /// MPFR precision in bits (for --scalar mpfr).
    #[arg(long, value_name = "BITS", default_value = "256")]
    pub precision: String,
    /// Significant digits printed for exact and mpfr values (at least 25 by default).
    #[arg(long, value_name = "D", default_value = "30")]
    pub digits: String,
}

/// Which number type to run in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum ScalarKind {
    F32,
    F64,
    Exact,
    Mpfr,
}

/// The parsed, checked request.
struct Request {
    method: Method,
    na: Vec3<BigRational>,
    nb: Vec3<BigRational>,
    l: Vec3<BigRational>,
    n: u32,
    kd: BigRational,
    normalize: bool,
    digits: usize,
}

/// What a run produced, formatted.
struct Outcome {
    values: Vec<String>,
    /// For the exact scalar and the methods that use only field operations: each
    /// value as an exact fraction.
    fractions: Option<Vec<String>>,
    levels: Vec<u8>,
    adaptive: Option<(String, Option<String>, Option<u32>, &'static str)>,
}

fn parse_request(a: &SpanArgs) -> Result<(Request, ScalarKind, bool, u32), CliError> {
    let mut method: Method = a.method.parse().map_err(|e| CliError::arg("--method", e))?;
    let scalar = match a.scalar.as_str() {
        "f32" => ScalarKind::F32,
        "f64" => ScalarKind::F64,
        "exact" => ScalarKind::Exact,
        "mpfr" => ScalarKind::Mpfr,
        other => {
            return Err(CliError::arg(
                "--scalar",
                format!(
                    "unknown scalar '{}' (expected f32, f64, exact or mpfr)",
                    shown(other)
                ),
            ))
        }
    };
    let json = match a.format.as_str() {
        "json" => true,
        "table" => false,
        other => {
            return Err(CliError::arg(
                "--format",
                format!("unknown format '{}' (expected json or table)", shown(other)),
            ))
        }
    };
    let vec = |arg: &str, s: &str| parse_vec3(s).map_err(|e| CliError::arg(arg, e));
    let na = vec("--na", &a.na)?;
    let nb = vec("--nb", &a.nb)?;
    let l = vec("--light", &a.light)?;
    let n = parse_whole("--steps", &a.steps, 1, 1 << 24, "n")?;
    let kd = parse_rational(&a.kd).map_err(|e| CliError::arg("--kd", e))?;
    if let Some(t) = &a.table_size {
        if method != Method::Angular {
            return Err(CliError::arg(
                "--table-size",
                "only the angular method uses a table",
            ));
        }
        method = Method::AngularTable(parse_whole(
            "--table-size",
            t,
            2,
            1 << 24,
            "the table size",
        )?);
    }
    let precision = parse_whole("--precision", &a.precision, 2, 1 << 20, "the precision")?;
    let digits = parse_whole("--digits", &a.digits, 1, 10_000, "the number of digits")? as usize;
    if scalar == ScalarKind::Mpfr && !cfg!(feature = "mpfr") {
        return Err(CliError::arg(
            "--scalar",
            "mpfr is not in this build; rebuild with `--features mpfr` (needs m4 and a C compiler), e.g. `cargo run --features mpfr -- span ...`",
        ));
    }
    let req = Request {
        method,
        na,
        nb,
        l,
        n,
        kd,
        normalize: a.normalize,
        digits,
    };
    Ok((req, scalar, json, precision))
}

fn span_error(e: SpanError, normalize: bool) -> CliError {
    let arg = |i: Input| match i {
        Input::Na => "--na",
        Input::Nb => "--nb",
        Input::L => "--light",
    };
    match e {
        SpanError::NonFinite { input, component } => CliError::arg(
            arg(input),
            format!("component {} is not finite in this number type", component + 1),
        ),
        SpanError::ZeroVector { input } => CliError::arg(arg(input), "the vector is zero"),
        SpanError::NotUnit {
            input,
            length_squared,
            tolerance,
        } => CliError::arg(
            arg(input),
            format!(
                "not a unit vector (length² = {length_squared}, allowed |length² − 1| ≤ {tolerance:e}){}",
                if normalize { "" } else { "; pass --normalize to normalize it" }
            ),
        ),
        SpanError::Opposite => CliError::arg("--nb", "Nb = −Na: the interpolated normal passes through zero"),
        SpanError::ZeroSteps => CliError::arg("--steps", "n must be at least 1"),
        SpanError::TooManySteps { max, got } => {
            CliError::arg("--steps", format!("n must be at most {max} (got {got})"))
        }
        other => CliError::arg("span", other),
    }
}

/// A run's span, values and (for `adaptive`) decision.
type Computed<T> = (Span<T>, Vec<T>, Option<Decision<T>>);

/// Runs the request in `T`.
fn compute<T: Real>(r: &Request) -> Result<Computed<T>, CliError> {
    let conv = |v: &Vec3<BigRational>| v.cast::<T>().expect("rationals are finite");
    let (na, nb, l) = (conv(&r.na), conv(&r.nb), conv(&r.l));
    let span = if r.normalize {
        Span::normalized(na, nb, l, r.n)
    } else {
        Span::new(na, nb, l, r.n)
    }
    .map_err(|e| span_error(e, r.normalize))?;
    let mut out = vec![T::zero(); span.len()];
    let decision = match r.method {
        Method::Adaptive => Some(
            adaptive::shade(&span, &T::from_rational(&r.kd), &mut out)
                .map_err(|e| CliError::arg("span", e))?,
        ),
        Method::AngularTable(size) => {
            let table = CosTable::new(size).map_err(|e| CliError::arg("--table-size", e))?;
            phong_approx::angular::shade_table(&span, &table, &mut out)
                .map_err(|e| CliError::arg("span", e))?;
            None
        }
        m => {
            m.shade(&span, &mut out)
                .map_err(|e| CliError::arg("span", e))?;
            None
        }
    };
    Ok((span, out, decision))
}

fn outcome<T: Real>(
    r: &Request,
    values: &[T],
    decision: Option<Decision<T>>,
    levels: Option<Vec<u8>>,
) -> Outcome {
    let fmt = |v: &T| v.to_decimal(r.digits);
    Outcome {
        values: values.iter().map(fmt).collect(),
        fractions: None,
        levels: levels.unwrap_or_else(|| values.iter().map(level).collect()),
        adaptive: decision.map(|d| {
            (
                fmt(&d.delta),
                d.m.as_ref().map(fmt),
                d.step,
                d.choice.name(),
            )
        }),
    }
}

fn run_typed<T: Real>(r: &Request) -> Result<Outcome, CliError> {
    let (_, values, decision) = compute::<T>(r)?;
    Ok(outcome(r, &values, decision, None))
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

/// The derived bound on `|float − exact|` at every pixel of this span
/// (`phong_approx::tolerance::bound`), for float runs of unit inputs; `None` with
/// `--normalize` (the float run's own normalization is not in the derivation), past
/// the derivation's range of `n`, or where the method has no bound.
fn error_bound(r: &Request, u: f64) -> Option<f64> {
    if r.normalize {
        return None;
    }
    let exact = Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok()?;
    let shape = phong_approx::tolerance::Shape::of(&exact);
    phong_approx::tolerance::span_bound(r.method, &shape, u)
}

/// Refuses `--digits` beyond what is known of exact values that are not exact:
/// square roots, `acos` and `cos` are computed to 2^-256 (so `p/√q` to
/// `2^-256/√q_min` and the angular values to `2^-254`), and `--normalize` makes the
/// inputs unit only to 2^-240. A value's digits are printed only if the value's lower
/// and upper ends (±2^-b, with `b` the bits known, less a margin) print the same.
fn check_digits(
    r: &Request,
    span: &Span<BigRational>,
    values: &[BigRational],
) -> Result<(), CliError> {
    use num_traits::One;
    if r.method.is_rational() && !r.normalize {
        return Ok(());
    }
    let mut bits: i64 = 250;
    if matches!(
        r.method,
        Method::Phong | Method::Duff | Method::SymmetricPhong
    ) {
        // 1/√q_min ≤ 2^k.
        let q = span.q_min();
        let k = (i64::try_from(q.denom().bits()).unwrap_or(i64::MAX)
            - i64::try_from(q.numer().bits()).unwrap_or(0))
            / 2
            + 2;
        bits -= k.max(0);
    }
    if r.normalize {
        bits = bits.min(180);
    }
    if bits < 4 {
        return Err(CliError::arg(
            "--digits",
            "no digit of these values is known",
        ));
    }
    let e = BigRational::new(
        num_bigint::BigInt::one(),
        num_bigint::BigInt::one() << (bits as usize),
    );
    for (i, v) in values.iter().enumerate() {
        let lo = (v.clone() - e.clone()).to_decimal(r.digits);
        let hi = (v.clone() + e.clone()).to_decimal(r.digits);
        if lo != hi {
            let known = (1..r.digits)
                .rev()
                .find(|&d| {
                    (v.clone() - e.clone()).to_decimal(d) == (v.clone() + e.clone()).to_decimal(d)
                })
                .unwrap_or(0);
            return Err(CliError::arg(
                "--digits",
                format!(
                    "only {known} significant digits of pixel {i} are known (these values are computed to 2^-{bits}); ask for at most that many"
                ),
            ));
        }
    }
    Ok(())
}

fn run_exact(r: &Request) -> Result<Outcome, CliError> {
    let (span, values, decision) = compute::<BigRational>(r)?;
    check_digits(r, &span, &values)?;
    // Phong-valued methods: decide the exact level of p/√q with rationals only.
    let levels = match r.method {
        Method::Phong | Method::Duff | Method::SymmetricPhong if !r.normalize => Some(
            (0..=span.n)
                .map(|i| phong_level_exact(&span.p_at(i), &span.q_at(i)).unwrap_or(0))
                .collect(),
        ),
        _ => None,
    };
    let mut o = outcome(r, &values, decision, levels);
    if r.method.is_rational() {
        o.fractions = Some(values.iter().map(ToString::to_string).collect());
    }
    Ok(o)
}

#[cfg(feature = "mpfr")]
fn run_mpfr(r: &Request, precision: u32) -> Result<Outcome, CliError> {
    use phong_approx::reference::mpfr::{with_precision, Mpfr};
    with_precision(precision, || run_typed::<Mpfr>(r))
}

#[cfg(not(feature = "mpfr"))]
fn run_mpfr(_r: &Request, _precision: u32) -> Result<Outcome, CliError> {
    unreachable!("parse_request rejects mpfr without the feature")
}

/// Runs `phong-approx span`.
///
/// # Errors
/// A [`CliError`] naming the bad argument (exit code 2).
pub fn run(a: &SpanArgs) -> Result<(), CliError> {
    let (r, scalar, json, precision) = parse_request(a)?;
    let o = match scalar {
        ScalarKind::F32 => run_typed::<f32>(&r)?,
        ScalarKind::F64 => run_typed::<f64>(&r)?,
        ScalarKind::Exact => run_exact(&r)?,
        ScalarKind::Mpfr => run_mpfr(&r, precision)?,
    };
    let scalar_name = match scalar {
        ScalarKind::F32 => "f32",
        ScalarKind::F64 => "f64",
        ScalarKind::Exact => "exact",
        ScalarKind::Mpfr => "mpfr",
    };
    if json {
        let mut obj = json!({
            "method": r.method.name(),
            "scalar": scalar_name,
            "steps": r.n,
            "values": o.values,
            "levels": o.levels,
        });
        if let Some(f) = &o.fractions {
            obj["fractions"] = json!(f);
        }
        if let Some(u) = match scalar {
            ScalarKind::F32 => Some(f32::unit_roundoff()),
            ScalarKind::F64 => Some(f64::unit_roundoff()),
            _ => None,
        } {
            // Rounded up to 3 significant digits: a bound, never understated.
            obj["error_bound"] = error_bound(&r, u).map_or(Value::Null, |b| json!(round_up_3(b)));
        }
        if let Method::AngularTable(size) = r.method {
            obj["table_size"] = json!(size);
        }
        if scalar == ScalarKind::Mpfr {
            obj["precision"] = json!(precision);
        }
        if let Some((delta, m, step, decision)) = &o.adaptive {
            obj["delta"] = json!(delta);
            obj["m"] = m.as_ref().map_or(Value::Null, |m| json!(m));
            obj["step"] = step.map_or(Value::Null, |s| json!(s));
            obj["decision"] = json!(decision);
        }
        outln!(
            "{}",
            serde_json::to_string_pretty(&obj).expect("plain JSON")
        )?;
    } else {
        outln!("method {} · scalar {} · n = {}", r.method, scalar_name, r.n)?;
        if let Some((delta, m, step, decision)) = &o.adaptive {
            let m = m.as_deref().unwrap_or("none (ds = 0)");
            let step = step.map_or("none".to_string(), |s| s.to_string());
            outln!("eq. 23 m = {m} · step = {step} · eq. 24 δ = {delta} · decision: {decision}")?;
        }
        let width = o.values.iter().map(String::len).max().unwrap_or(5).max(5);
        outln!("{:>6}  {:<width$}  level", "i", "value")?;
        for (i, (v, l)) in o.values.iter().zip(&o.levels).enumerate() {
            outln!("{i:>6}  {v:<width$}  {l:>5}")?;
        }
    }
    Ok(())
}
