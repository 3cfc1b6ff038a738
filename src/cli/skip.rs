//! `phong-approx skip`: the paper's first open question (§7.1, a) on one span — may
//! its specular pass be skipped? The exact test ([`phong_approx::skip`], decided in
//! rationals: `phong_skip_sound`, `quadratic_skip_sound`, `sq_skip_sound`) and the
//! float form with its margins for every `ieee` implementation
//! ([`phong_approx::skip::float`], `float_skip_sound`), side by side.

use super::BadValue;
use super::CliError;
use clap::{Args, ValueEnum};
use phong_approx::skip::float::{float_skips, FloatSpan, Margins};
use phong_approx::skip::{specular_skips, SkipError, MAX_SHININESS};
use phong_approx::{BigRational, Format, Method, Span, Vec3};
use serde::Serialize;

/// Arguments of `phong-approx skip`.
#[derive(Args, Debug)]
pub struct SkipArgs {
    /// A method of the catalogue with a skip test: Phong, Duff, symmetric Phong (Phong's
    /// values), Gouraud, Euler, corrected Euler (their quadratics) or the squared method.
    #[arg(long, value_name = "NAME", value_parser = |s: &str| s.parse::<Method>())]
    pub method: Method,
    /// Normal at the left edge, N_a: three decimals or fractions, e.g. 0.6,0,0.8; unit
    /// to within 2^-20 (the span is decided as given).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = super::vector)]
    pub na: Vec3<BigRational>,
    /// Normal at the right edge, N_b.
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = super::vector)]
    pub nb: Vec3<BigRational>,
    /// The half vector H of the specular term (the span's light for it).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = super::vector)]
    pub half_vector: Vec3<BigRational>,
    /// Number of steps n ≥ 1 (at most 2^24); the span has n + 1 pixels.
    #[arg(long, value_name = "N", allow_hyphen_values = true,
          value_parser = |s: &str| super::whole(s, 1, 1 << 24, "n"))]
    pub steps: u32,
    /// Specular coefficient K_s, from 0 to 1.
    #[arg(long, value_name = "KS", allow_hyphen_values = true, value_parser = ks)]
    pub ks: BigRational,
    /// Specular exponent s (the paper's shininess), 1 to 1024.
    #[arg(long, value_name = "S", allow_hyphen_values = true,
          value_parser = |s: &str| super::whole(s, 1, MAX_SHININESS, "the specular exponent"))]
    pub shininess: u32,
    /// The implementations' format for the float form's margins: binary32 or binary64.
    #[arg(long, value_name = "FORMAT", value_enum, default_value = "f32")]
    pub precision: Precision,
    /// Output: json or table.
    #[arg(long, value_name = "FORMAT", value_enum, default_value = "json")]
    pub format: super::span::Format,
}

/// `--precision`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Precision {
    /// IEEE binary32.
    F32,
    /// IEEE binary64.
    F64,
}

fn ks(s: &str) -> Result<BigRational, BadValue> {
    super::coefficient(
        s,
        0,
        1,
        "K_s must be between 0 and 1 (a specular reflectance)",
    )
}

/// One form's answer.
#[derive(Serialize)]
struct Decision {
    /// Whether the span's specular pass may be skipped.
    skips: Option<bool>,
    /// Why the form does not decide here (no test for the method, no proved margin).
    refused: Option<String>,
}

/// The report.
#[derive(Serialize)]
struct SkipReport {
    method: String,
    steps: u32,
    ks: String,
    shininess: u32,
    /// The exact test, in rationals, of the method's exact values on the span.
    exact: Decision,
    /// The float form in `f64` with the margins of every `ieee` implementation, on the
    /// inputs rounded to `f64`.
    float: Decision,
    /// Whether rounding the inputs to `f64` changed them (the float form then decides
    /// for the rounded span, as a renderer holding floats has it).
    float_inputs_rounded: bool,
    /// The `ieee` allowance the float form takes (`check`'s bound on the span).
    allowance: Option<f64>,
    /// What a skip guarantees.
    guarantee: &'static str,
}

const GUARANTEE: &str = "a skip means 255·K_s·max(0, v)^s < 1 at every pixel: the specular \
    term's 8-bit level is 0 there (exact: for the method's exact values; float: for every \
    ieee implementation within the allowance). A combined intensity K_a + K_d·diffuse + \
    K_s·specular may still cross a level boundary by that term's part of one level.";

/// Runs `phong-approx skip`.
///
/// # Errors
/// A [`CliError`] naming the bad argument (exit code 2).
pub fn run(a: &SkipArgs) -> Result<(), CliError> {
    let tol = BigRational::new(1.into(), (1u64 << 20).into());
    let span = Span::with_tolerance(
        a.na.clone(),
        a.nb.clone(),
        a.half_vector.clone(),
        a.steps,
        &tol,
    )
    .map_err(|e| CliError::arg("span", e))?;
    let method = a.method;
    let exact = match specular_skips(method, &span, &a.ks, a.shininess) {
        Ok(s) => Decision {
            skips: Some(s),
            refused: None,
        },
        Err(e @ SkipError::Unsupported(_)) => return Err(CliError::arg("--method", e)),
        Err(e @ SkipError::NormalVanishes) => return Err(CliError::arg("span", e)),
        Err(e) => return Err(CliError::arg("--ks/--shininess", e)),
    };
    let format = match a.precision {
        Precision::F32 => Format::Binary32,
        Precision::F64 => Format::Binary64,
    };
    // The float form decides on `f64` inputs: the given ones rounded to nearest (a
    // renderer's), with the margins of that span, so that its answer is proved for
    // exactly what it reads (`rounded` says whether that differs from the given span).
    let to = |v: &Vec3<BigRational>| {
        v.components()
            .map(|c| num_traits::ToPrimitive::to_f64(c).unwrap_or(f64::NAN))
    };
    let fs = FloatSpan {
        na: to(&a.na),
        nb: to(&a.nb),
        h: to(&a.half_vector),
        n: a.steps,
    };
    let back = |v: [f64; 3]| -> Option<Vec3<BigRational>> {
        let [x, y, z] = v.map(BigRational::from_float);
        Some(Vec3::new(x?, y?, z?))
    };
    let float_span = match (back(fs.na), back(fs.nb), back(fs.h)) {
        (Some(na), Some(nb), Some(h)) => Span::with_tolerance(na, nb, h, a.steps, &tol).ok(),
        _ => None,
    };
    let rounded = float_span
        .as_ref()
        .is_some_and(|f| f.na != span.na || f.nb != span.nb || f.l != span.l);
    let margins = float_span
        .as_ref()
        .and_then(|f| Margins::ieee(method, f, format));
    // K_s as an f64 at least the given one (the test grows with it).
    let ks =
        num_traits::ToPrimitive::to_f64(&a.ks).map_or(
            f64::NAN,
            |f| match BigRational::from_float(f) {
                Some(q) if q < a.ks => f.next_up(),
                _ => f,
            },
        );
    let float = match margins {
        None => Decision {
            skips: None,
            refused: Some(format!(
                "no proved ieee bound of {method} covers this span in {format}"
            )),
        },
        Some(m) => match float_skips(method, &fs, ks, a.shininess, m) {
            Ok(s) => Decision {
                skips: Some(s),
                refused: None,
            },
            Err(SkipError::Unsupported(m)) => Decision {
                skips: None,
                refused: Some(format!("the float form has no test for {m}")),
            },
            Err(e) => Decision {
                skips: None,
                refused: Some(e.to_string()),
            },
        },
    };
    let report = SkipReport {
        method: method.to_string(),
        steps: a.steps,
        ks: a.ks.to_string(),
        shininess: a.shininess,
        exact,
        float,
        float_inputs_rounded: rounded,
        allowance: margins.map(|m| m.allowance),
        guarantee: GUARANTEE,
    };
    match a.format {
        super::span::Format::Json => super::write_json(&report),
        super::span::Format::Table => {
            let said = |d: &Decision| match (d.skips, &d.refused) {
                (Some(true), _) => "skip".to_string(),
                (Some(false), _) => "shade".to_string(),
                (None, Some(why)) => format!("not decided: {why}"),
                (None, None) => "not decided".to_string(),
            };
            outln!(
                "method {} · n = {} · K_s = {} · s = {}",
                report.method,
                report.steps,
                report.ks,
                report.shininess
            )?;
            outln!("exact: {}", said(&report.exact))?;
            let note = if report.float_inputs_rounded {
                ", on the inputs rounded to binary64"
            } else {
                ""
            };
            outln!("float ({format}{note}): {}", said(&report.float))?;
            outln!("{GUARANTEE}")
        }
    }
}
