//! `phong-approx span`: one scan line, one method, one number type. The arguments
//! are parsed here; the run and its report are the library's
//! ([`phong_approx::span_report`]).

use super::BadValue;
use super::CliError;
use clap::{Args, ValueEnum};
use phong_approx::span_report::{
    span_report, Arithmetic, Field, Remedy, ReportError, Request, SpanReport,
};
use phong_approx::{BigRational, Method, Vec3};

/// Arguments of `phong-approx span`.
#[derive(Args, Debug)]
pub struct SpanArgs {
    /// A method of the catalogue (the list is the catalogue's: `super::methods_help`).
    #[arg(long, value_name = "NAME", help = super::methods_help(), value_parser = |s: &str| s.parse::<Method>())]
    pub method: Method,
    /// Unit normal at the left edge, N_a: three decimals or fractions, e.g. 0.6,0,0.8.
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = super::vector)]
    pub na: Vec3<BigRational>,
    /// Unit normal at the right edge, N_b.
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = super::vector)]
    pub nb: Vec3<BigRational>,
    /// Unit light vector L (or half vector H).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = super::vector)]
    pub light: Vec3<BigRational>,
    /// Number of steps n ≥ 1 (at most 2^24); the span has n + 1 pixels.
    #[arg(long, value_name = "N", allow_hyphen_values = true,
          value_parser = |s: &str| super::whole(s, 1, 1 << 24, "n"))]
    pub steps: u32,
    /// Number type: f32, f64, exact (rationals) or mpfr (needs the `mpfr` feature).
    #[arg(long, value_name = "TYPE", value_enum, default_value = "f64")]
    pub scalar: ScalarArg,
    /// Output: json or table.
    #[arg(long, value_name = "FORMAT", value_enum, default_value = "json")]
    pub format: Format,
    /// Normalize N_a, N_b and L first instead of requiring unit vectors (for exact,
    /// the result is unit to 2^-256, not exactly).
    #[arg(long)]
    pub normalize: bool,
    /// Diffuse coefficient K_d of the adaptive test |δ·255·K_d| < 1 (eq. 24), from 0
    /// to 1000.
    #[arg(long, value_name = "KD", default_value = "1", allow_hyphen_values = true,
          value_parser = kd)]
    pub kd: BigRational,
    /// For `angular`: read the cosine from a table of this many entries over 0–90°
    /// (the second source uses 256) instead of computing it.
    #[arg(long, value_name = "SIZE", value_parser = |s: &str| super::whole(s, 2, 1 << 24, "the table size"))]
    pub table_size: Option<u32>,
    /// MPFR precision in bits (for --scalar mpfr; default 256).
    #[arg(long, value_name = "BITS", value_parser = |s: &str| super::whole(s, 2, 1 << 20, "the precision"))]
    pub precision: Option<u32>,
    /// Run even when the request exceeds the budget (exact or MPFR spans of more than
    /// 65536 steps or tables of more than 65536 entries, or more than 1 GiB of
    /// output), which would take minutes to hours.
    #[arg(long)]
    pub yes: bool,
    /// Significant digits printed for exact and mpfr values (at least 25 by default).
    #[arg(long, value_name = "D", default_value = "30",
          value_parser = |s: &str| super::whole(s, 1, 10_000, "the number of digits"))]
    pub digits: u32,
}

/// `--scalar`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ScalarArg {
    /// IEEE binary32.
    F32,
    /// IEEE binary64.
    F64,
    /// Exact rationals.
    Exact,
    /// MPFR (feature `mpfr`).
    Mpfr,
}

/// `--format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// A JSON object (`SpanReport`).
    Json,
    /// A table for people.
    Table,
}

fn kd(s: &str) -> Result<BigRational, BadValue> {
    super::coefficient(
        s,
        0,
        1000,
        "K_d must be between 0 and 1000 (a diffuse reflectance, usually at most 1)",
    )
}

/// A [`ReportError`] as the command's: its field as the flag that sets it, its remedy
/// as the flag that gives it.
fn report_error(e: ReportError) -> CliError {
    let flag = match e.field {
        Field::Na => "--na",
        Field::Nb => "--nb",
        Field::Light => "--light",
        Field::Steps => "--steps",
        Field::TableSize => "--table-size",
        Field::Digits => "--digits",
        Field::Arithmetic => "--scalar",
        Field::Span => "span",
    };
    let advice = match e.remedy {
        Remedy::None => "",
        Remedy::RunAnyway => "; pass --yes to run anyway",
        Remedy::Normalize => "; pass --normalize to normalize it",
        Remedy::BuildWithMpfr => {
            "; rebuild with `--features mpfr` (needs m4 and a C compiler), e.g. `cargo run --features mpfr -- span ...`"
        }
    };
    CliError::arg(flag, format!("{}{advice}", e.message))
}

/// The request `a` asks for: the method with its table, the number type.
fn request(a: &SpanArgs) -> Result<Request, CliError> {
    let method = match (a.method, a.table_size) {
        (m, None) => m,
        (Method::Angular, Some(size)) => Method::AngularTable(size),
        (Method::AngularTable(s), Some(size)) if s == size => a.method,
        (Method::AngularTable(s), Some(size)) => {
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
    if let Method::AngularTable(size) = method {
        if !(2..=1 << 24).contains(&size) {
            return Err(CliError::arg(
                "--method",
                format!("the table size must be between 2 and 16777216 (got {size})"),
            ));
        }
    }
    let arithmetic = match (a.scalar, a.precision) {
        (ScalarArg::Mpfr, p) => Arithmetic::Mpfr(p.unwrap_or(256)),
        (_, Some(_)) => {
            return Err(CliError::arg(
                "--precision",
                "only --scalar mpfr has a precision to set",
            ))
        }
        (ScalarArg::F32, None) => Arithmetic::F32,
        (ScalarArg::F64, None) => Arithmetic::F64,
        (ScalarArg::Exact, None) => Arithmetic::Exact,
    };
    Ok(Request {
        method,
        na: a.na.clone(),
        nb: a.nb.clone(),
        l: a.light.clone(),
        n: a.steps,
        kd: a.kd.clone(),
        normalize: a.normalize,
        digits: a.digits as usize,
        arithmetic,
    })
}

/// Runs `phong-approx span`.
///
/// # Errors
/// A [`CliError`] naming the bad argument (exit code 2).
pub fn run(a: &SpanArgs) -> Result<(), CliError> {
    let r = request(a)?;
    if !a.yes {
        r.within_budget().map_err(report_error)?;
    }
    // Exact work on long spans takes seconds: show that it is under way.
    let spinner = (r.arithmetic.is_exact() && r.n > 4096).then(|| {
        let b = indicatif::ProgressBar::new_spinner();
        b.set_message(format!(
            "{} pixels in {} arithmetic",
            r.n + 1,
            r.arithmetic.name()
        ));
        b.enable_steady_tick(std::time::Duration::from_millis(200));
        b
    });
    let report = span_report(&r);
    if let Some(b) = spinner {
        b.finish_and_clear();
    }
    let report = report.map_err(report_error)?;
    match a.format {
        Format::Json => super::write_json(&report),
        Format::Table => table(&report),
    }
}

/// The report as a table: a header line, the adaptive test, then `i value level`.
fn table(o: &SpanReport) -> Result<(), CliError> {
    outln!(
        "method {} · scalar {} · n = {}",
        o.method,
        o.scalar,
        o.steps
    )?;
    if let Some(ad) = &o.adaptive {
        let m = ad.m.as_deref().unwrap_or("none (ds = 0)");
        let step = ad.step.map_or("none".to_string(), |s| s.to_string());
        outln!(
            "eq. 23 m = {m} · step = {step} · eq. 24 δ = {} · decision: {}",
            ad.delta,
            ad.decision
        )?;
    }
    let width = o.values.iter().map(|v| v.len()).max().unwrap_or(5).max(5);
    outln!("{:>6}  {:<width$}  level", "i", "value")?;
    for (i, (v, l)) in o.values.iter().zip(&o.levels).enumerate() {
        // An unknown level prints as "?" (its value is within its error of a level
        // boundary).
        let l = l.map_or_else(|| "?".to_string(), |l| l.to_string());
        outln!("{i:>6}  {v:<width$}  {l:>5}")?;
    }
    Ok(())
}
