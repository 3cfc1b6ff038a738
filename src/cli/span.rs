//! `phong-approx span`: one scan line, one method, one number type.

use super::{parse_whole, CliError};
use clap::Args;
use phong_approx::adaptive::Decision;
use phong_approx::conformance::shown;
use phong_approx::method::Prepared;
use phong_approx::parse::{parse_rational, parse_vec3};
use phong_approx::quantize::level;
use phong_approx::{BigRational, Input, Method, Real, Scalar, Span, SpanError, Vec3};
use serde_json::{json, Value};

/// Arguments of `phong-approx span`.
#[derive(Args, Debug)]
pub struct SpanArgs {
    /// A method of the catalogue (the list is the catalogue's: `super::methods_help`).
    #[arg(long, value_name = "NAME", help = super::methods_help())]
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
    /// MPFR precision in bits (for --scalar mpfr; default 256).
    #[arg(long, value_name = "BITS")]
    pub precision: Option<String>,
    /// Run even when the request exceeds the budget (exact or MPFR spans of more than
    /// 65536 steps or tables of more than 65536 entries, or more than 1 GiB of
    /// output), which would take minutes to hours.
    #[arg(long)]
    pub yes: bool,
    /// Significant digits printed for exact and mpfr values (at least 25 by default).
    #[arg(long, value_name = "D", default_value = "30")]
    pub digits: String,
}

/// The most steps (and cosine-table entries) an exact or MPFR run takes without
/// `--yes`: about half a minute of work.
const SPAN_BUDGET: u32 = 1 << 16;

/// The most output `span` writes without `--yes`.
const OUTPUT_BUDGET: u64 = 1 << 30;

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

/// A run's values, formatted as they are written: a float run keeps its numbers
/// (8 bytes a pixel at most), not a string per pixel, so `span` holds little more
/// than the values however long the span.
struct Shown {
    len: usize,
    at: Box<dyn Fn(usize) -> String>,
}

impl Shown {
    /// Values already formatted.
    #[cfg_attr(not(feature = "mpfr"), allow(dead_code))]
    fn eager(v: Vec<String>) -> Shown {
        Shown {
            len: v.len(),
            at: Box::new(move |i| v[i].clone()),
        }
    }

    fn iter(&self) -> impl ExactSizeIterator<Item = String> + '_ {
        (0..self.len).map(|i| (self.at)(i))
    }
}

/// What a run produced, formatted.
struct Outcome {
    values: Shown,
    /// For the exact scalar and the methods that use only field operations: each
    /// value as an exact fraction.
    fractions: Option<Vec<String>>,
    /// `None` where the level is not known (a value within its error of a level
    /// boundary).
    levels: Vec<Option<u8>>,
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
        let size = parse_whole("--table-size", t, 2, 1 << 24, "the table size")?;
        method = match method {
            Method::Angular => Method::AngularTable(size),
            Method::AngularTable(s) if s == size => method,
            Method::AngularTable(s) => {
                return Err(CliError::arg(
                    "--table-size",
                    format!("{size} contradicts the method's own table size, {s}"),
                ))
            }
            _ => {
                return Err(CliError::arg(
                    "--table-size",
                    "only the angular method uses a table",
                ))
            }
        };
    }
    if let Method::AngularTable(size) = method {
        if !(2..=1 << 24).contains(&size) {
            return Err(CliError::arg(
                "--method",
                format!("the table size must be between 2 and 16777216 (got {size})"),
            ));
        }
    }
    let precision = match &a.precision {
        Some(p) if scalar == ScalarKind::Mpfr => {
            parse_whole("--precision", p, 2, 1 << 20, "the precision")?
        }
        Some(_) => {
            return Err(CliError::arg(
                "--precision",
                "only --scalar mpfr has a precision to set",
            ))
        }
        None => 256,
    };
    let digits = parse_whole("--digits", &a.digits, 1, 10_000, "the number of digits")? as usize;
    let zero = BigRational::from_integer(0.into());
    let most = BigRational::from_integer(1000.into());
    if kd < zero || kd > most {
        return Err(CliError::arg(
            "--kd",
            "K_d must be between 0 and 1000 (a diffuse reflectance, usually at most 1)",
        ));
    }
    // The budget: what would take minutes to hours, or gigabytes, needs --yes.
    let exact = matches!(scalar, ScalarKind::Exact | ScalarKind::Mpfr);
    if !a.yes {
        if exact && n > SPAN_BUDGET {
            return Err(CliError::arg(
                "--steps",
                format!("{n} steps in exact arithmetic take minutes or more (budget {SPAN_BUDGET}); pass --yes to run anyway"),
            ));
        }
        if scalar == ScalarKind::Exact {
            use phong_approx::conformance::integrity::{
                exact_work, input_bits, MAX_RECOMPUTED_WORK,
            };
            let work = exact_work(method, n, input_bits(&[&na, &nb, &l]), digits);
            if work > MAX_RECOMPUTED_WORK {
                return Err(CliError::arg(
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
                return Err(CliError::arg(
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
            return Err(CliError::arg(
                "--digits",
                format!(
                    "the output would be about {} MiB (budget {} MiB); ask for fewer digits or steps, or pass --yes",
                    bytes >> 20,
                    OUTPUT_BUDGET >> 20
                ),
            ));
        }
    }
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
            format!(
                "component {} is not finite in this number type",
                component + 1
            ),
        ),
        SpanError::ZeroVector { input } => CliError::arg(arg(input), "the vector is zero"),
        SpanError::NotUnit {
            input,
            length_squared,
            deviation,
            tolerance,
        } => CliError::arg(
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
        SpanError::Opposite => CliError::arg(
            "--nb",
            "Nb = −Na: this method is undefined for opposite normals (no unique arc between them)",
        ),
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
    let prep = Prepared::new(r.method, T::from_rational(&r.kd))
        .map_err(|e| CliError::arg("--table-size", e))?;
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
    let adaptive = decision.map(|d| {
        (
            fmt(&d.delta),
            d.m.as_ref().map(fmt),
            d.step,
            d.choice.name(),
        )
    });
    Outcome {
        values: Shown {
            len: values.len(),
            at: Box::new(move |i| fmt(&values[i])),
        },
        fractions: None,
        levels,
        adaptive,
    }
}

fn run_typed<T: Real + 'static>(r: &Request) -> Result<Outcome, CliError> {
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

/// `error_bound` of the JSON output: an object keyed by profile — `reference` (this
/// crate's own operation order, [`error_bound`]), `ieee` and `shader` (proved for
/// every implementation of the profile, `phong_approx::tolerance::profile`; `shader`
/// only for `f32`). `null` where none is derived or proved (and for every profile
/// with `--normalize`, whose float normalization no derivation covers).
fn error_bounds(r: &Request, u: f64) -> Value {
    use phong_approx::tolerance::profile::{profile_bound, Profile};
    let shown = |b: Option<f64>| b.map_or(Value::Null, |b| json!(round_up_3(b)));
    let mut m = serde_json::Map::new();
    for p in Profile::ALL {
        let b = match p {
            _ if r.normalize => None,
            Profile::Reference => error_bound(r, u),
            Profile::Shader if u != f64::from(f32::EPSILON) / 2.0 => continue,
            p => Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n)
                .ok()
                .and_then(|s| {
                    let shape = phong_approx::tolerance::Shape::of(&s);
                    profile_bound(r.method, p, r.n, shape.q_min, u)
                }),
        };
        m.insert(p.name(), shown(b));
    }
    Value::Object(m)
}

/// Where `--digits` asks for more than is known: the first such pixel and how many
/// significant digits of it are known.
struct Short {
    pixel: usize,
    known: usize,
}

impl Short {
    fn error(&self, bits: i64) -> CliError {
        let what = if self.known == 0 {
            format!("no digit of pixel {} is known", self.pixel)
        } else {
            format!(
                "only {} significant digits of pixel {} are known",
                self.known, self.pixel
            )
        };
        CliError::arg(
            "--digits",
            format!("{what} (these values are computed to 2^-{bits}); ask for at most that many"),
        )
    }
}

/// Checks that every value's `--digits` digits are known: a value's digits are
/// printed only if its lower and upper ends (±2^-bits) print the same.
fn check_digits<T: Real>(r: &Request, values: &[T], bits: i64) -> Result<(), Short> {
    use num_traits::One;
    if bits < 4 {
        return Err(Short { pixel: 0, known: 0 });
    }
    let e = BigRational::new(
        num_bigint::BigInt::one(),
        num_bigint::BigInt::one() << (bits as usize),
    );
    for (i, v) in values.iter().enumerate() {
        // A value of exactly 0 comes from an exact p = 0 (0/√q), and prints as "0".
        let Some(v) = v.to_rational().filter(|v| !num_traits::Zero::is_zero(v)) else {
            continue;
        };
        let (lo, hi) = (v.clone() - e.clone(), v.clone() + e.clone());
        if lo.to_decimal(r.digits) != hi.to_decimal(r.digits) {
            // About log10(|v|/e) digits are known: search down from just above that
            // (not from --digits, which may be thousands).
            let guess = ((v.to_f64().abs().log2() + bits as f64) * std::f64::consts::LOG10_2)
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
/// With `--normalize` the inputs are normalized through square roots accurate to
/// 2^-b (`b` = [`transcendental::bits`], 256 unless the run asks for more), so `p_a`,
/// `p_b` and every dot product are off by at most 2^-(b − 18): what the exact run's
/// own accounting allows for an error of 2^-(b − 6), less 16 bits, and at most
/// `b − 76` bits (180 at the default). Angular interpolation takes `acos p`, which
/// moves by `e/sin θ` (or at most `2.23·√e`, acos being ½-Hölder with constant `π/√2`)
/// when `p` moves by `e`: `max(b − 19 − ⌈log2(1/sin θ)⌉, (b − 18)/2 − 2)` bits.
///
/// [`transcendental::bits`]: phong_approx::reference::transcendental::bits
fn exact_bits(r: &Request, span: &Span<BigRational>) -> Option<i64> {
    if !r.normalize {
        return r.method.exact_bits(span);
    }
    let b = i64::from(phong_approx::reference::transcendental::bits());
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

/// The levels of an exact `--normalize` run: from `values` (known to `2^-bits`) where
/// that decides them, else exactly for the normalized inputs
/// (`phong_approx::reference::radical`) at the pixels whose value is known in closed
/// form: Phong's `p/√q` where the method's is, Gouraud's, Euler's and corrected
/// Euler's everywhere; undecided (`None`) elsewhere.
fn normalized_levels(r: &Request, values: &[BigRational], bits: i64) -> Vec<Option<u8>> {
    use num_traits::Zero;
    use phong_approx::method::PhongPixels;
    use phong_approx::reference::radical::{normalized_levels, Valued};
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

fn run_exact(r: &Request) -> Result<Outcome, CliError> {
    use phong_approx::reference::transcendental::{with_bits, BITS, MAX_BITS};
    digits_within_reach(r)?;
    let mut b = BITS;
    loop {
        let attempt = with_bits(b, || -> Result<Result<Outcome, (Short, i64)>, CliError> {
            let (span, values, decision) = compute::<BigRational>(r)?;
            let known = exact_bits(r, &span);
            if let Some(bits) = known {
                if let Err(short) = check_digits(r, &values, bits) {
                    return Ok(Err((short, bits)));
                }
            }
            // Phong-valued methods: the exact level of p/√q decided with rationals
            // only; with --normalize, in Q(√a, √b, √c) where the approximate value
            // does not decide it.
            let one = BigRational::from_integer(1.into());
            let levels = Some(if r.normalize {
                normalized_levels(r, &values, known.unwrap_or(0))
            } else {
                r.method.exact_levels(&span, &values, &one)
            });
            let fractions = r
                .method
                .is_rational()
                .then(|| values.iter().map(ToString::to_string).collect());
            let mut o = outcome(r, values, decision, levels);
            o.fractions = fractions;
            // Formatted within the precision the values were computed at.
            o.values = Shown::eager(o.values.iter().collect());
            Ok(Ok(o))
        })?;
        match attempt {
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

/// `--digits` for a method whose exact values are not rational: at most what
/// 2^-`MAX_BITS` gives, refused before any work.
fn digits_within_reach(r: &Request) -> Result<(), CliError> {
    use phong_approx::reference::transcendental::MAX_BITS;
    let most = (f64::from(MAX_BITS - 64) * std::f64::consts::LOG10_2) as usize;
    if !r.method.is_rational() && r.digits > most {
        return Err(CliError::arg(
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
fn run_mpfr(r: &Request, precision: u32) -> Result<Outcome, CliError> {
    use phong_approx::reference::mpfr::{with_precision, Mpfr};
    with_precision(precision, || {
        let (span, values, decision) = compute::<Mpfr>(r)?;
        let exact = if r.normalize {
            None
        } else {
            Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok()
        };
        let bits = mpfr_bits(r, exact.as_ref(), precision, q_bits(&span));
        check_digits(r, &values, bits).map_err(|s| s.error(bits))?;
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
                            .and_then(|x| phong_approx::reference::level::level_within(&x, &e))
                    })
                    .collect()
            }
        };
        // Formatted here, within the precision the values were computed at.
        let mut o = outcome(r, values, decision, Some(levels));
        o.values = Shown::eager(o.values.iter().collect());
        Ok(o)
    })
}

#[cfg(not(feature = "mpfr"))]
fn run_mpfr(_r: &Request, _precision: u32) -> Result<Outcome, CliError> {
    unreachable!("parse_request rejects mpfr without the feature")
}

/// A field of the JSON output: one value, or a long array written as it goes.
enum Field<'a> {
    One(Value),
    Strings(&'a [String]),
    Shown(&'a Shown),
    Levels(&'a [Option<u8>]),
}

/// Writes the object as `serde_json`'s pretty printer would, streaming the arrays in
/// pieces instead of building the whole text (2^24 values would take gigabytes).
fn write_json(fields: &[(&str, Field)]) -> Result<(), CliError> {
    outp!("{{")?;
    for (k, (name, field)) in fields.iter().enumerate() {
        let sep = if k == 0 { "" } else { "," };
        outp!("{sep}\n  {}: ", json!(name))?;
        match field {
            Field::One(v) => outp!("{v}")?,
            Field::Strings(items) => write_array(items.iter().map(|x| json!(x).to_string()))?,
            Field::Shown(items) => write_array(items.iter().map(|x| json!(x).to_string()))?,
            Field::Levels(items) => write_array(
                items
                    .iter()
                    .map(|l| l.map_or_else(|| "null".to_string(), |l| l.to_string())),
            )?,
        }
    }
    outln!("\n}}")
}

/// `[` items one per line, indented by four `]`, in chunks of about 64 KiB.
fn write_array(items: impl ExactSizeIterator<Item = String>) -> Result<(), CliError> {
    if items.len() == 0 {
        return outp!("[]");
    }
    let mut chunk = String::from("[");
    for (i, item) in items.enumerate() {
        if i > 0 {
            chunk.push(',');
        }
        chunk.push_str("\n    ");
        chunk.push_str(&item);
        if chunk.len() > 1 << 16 {
            outp!("{chunk}")?;
            chunk.clear();
        }
    }
    chunk.push_str("\n  ]");
    outp!("{chunk}")
}

/// Runs `phong-approx span`.
///
/// # Errors
/// A [`CliError`] naming the bad argument (exit code 2).
pub fn run(a: &SpanArgs) -> Result<(), CliError> {
    let (r, scalar, json, precision) = parse_request(a)?;
    // Exact work on long spans takes seconds: show that it is under way.
    let spinner =
        (matches!(scalar, ScalarKind::Exact | ScalarKind::Mpfr) && r.n > 4096).then(|| {
            let b = indicatif::ProgressBar::new_spinner();
            b.set_message(format!("{} pixels in {} arithmetic", r.n + 1, a.scalar));
            b.enable_steady_tick(std::time::Duration::from_millis(200));
            b
        });
    let o = match scalar {
        ScalarKind::F32 => run_typed::<f32>(&r),
        ScalarKind::F64 => run_typed::<f64>(&r),
        ScalarKind::Exact => run_exact(&r),
        ScalarKind::Mpfr => run_mpfr(&r, precision),
    };
    if let Some(b) = spinner {
        b.finish_and_clear();
    }
    let o = o?;
    let scalar_name = match scalar {
        ScalarKind::F32 => "f32",
        ScalarKind::F64 => "f64",
        ScalarKind::Exact => "exact",
        ScalarKind::Mpfr => "mpfr",
    };
    if json {
        let mut fields: Vec<(&str, Field)> = vec![
            ("method", Field::One(json!(r.method.name()))),
            ("scalar", Field::One(json!(scalar_name))),
            ("steps", Field::One(json!(r.n))),
            ("values", Field::Shown(&o.values)),
            ("levels", Field::Levels(&o.levels)),
        ];
        if let Some(f) = &o.fractions {
            fields.push(("fractions", Field::Strings(f)));
        }
        if let Some(u) = match scalar {
            ScalarKind::F32 => Some(f32::unit_roundoff()),
            ScalarKind::F64 => Some(f64::unit_roundoff()),
            _ => None,
        } {
            // Per profile (docs/float.md §18), rounded up to 3 significant digits: a
            // bound, never understated; null where none is derived or proved.
            fields.push(("error_bound", Field::One(error_bounds(&r, u))));
        }
        if let Method::AngularTable(size) = r.method {
            fields.push(("table_size", Field::One(json!(size))));
        }
        if scalar == ScalarKind::Mpfr {
            fields.push(("precision", Field::One(json!(precision))));
        }
        if let Some((delta, m, step, decision)) = &o.adaptive {
            fields.push(("delta", Field::One(json!(delta))));
            fields.push((
                "m",
                Field::One(m.as_ref().map_or(Value::Null, |m| json!(m))),
            ));
            fields.push(("step", Field::One(step.map_or(Value::Null, |s| json!(s)))));
            fields.push(("decision", Field::One(json!(decision))));
        }
        write_json(&fields)?;
    } else {
        outln!("method {} · scalar {} · n = {}", r.method, scalar_name, r.n)?;
        if let Some((delta, m, step, decision)) = &o.adaptive {
            let m = m.as_deref().unwrap_or("none (ds = 0)");
            let step = step.map_or("none".to_string(), |s| s.to_string());
            outln!("eq. 23 m = {m} · step = {step} · eq. 24 δ = {delta} · decision: {decision}")?;
        }
        let width = o.values.iter().map(|v| v.len()).max().unwrap_or(5).max(5);
        outln!("{:>6}  {:<width$}  level", "i", "value")?;
        for (i, (v, l)) in o.values.iter().zip(&o.levels).enumerate() {
            let v = v.as_str();
            // An unknown level prints as "?" (its value is within its error of a
            // level boundary).
            let l = l.map_or_else(|| "?".to_string(), |l| l.to_string());
            outln!("{i:>6}  {v:<width$}  {l:>5}")?;
        }
    }
    Ok(())
}
