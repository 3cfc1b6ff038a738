//! `phong-approx setup`: each case's set-up rounded to a fixed-point format, the inputs
//! of a hardware span unit (`harness/hdl/`, docs/conformance.md "Hardware span units").

use super::BadValue;
use super::{read_capped, CliError};
use clap::Args;
use phong_approx::conformance::check::MAX_RESULTS_BYTES;
use phong_approx::conformance::integrity::case_span;
use phong_approx::conformance::verdict::load_vectors;
use phong_approx::fixed_span::FixedSpan;
use phong_approx::tolerance::profile::Profile;
use phong_approx::Method;

/// The methods a span unit of `harness/hdl/` implements.
const HARDWARE: [Method; 5] = [
    Method::Gouraud,
    Method::Euler,
    Method::CorrectedEuler,
    Method::Adaptive,
    Method::Duff,
];

/// Arguments of `phong-approx setup`.
#[derive(Args, Debug)]
pub struct SetupArgs {
    /// The vector file (JSON, from `vectors/`).
    #[arg(long, value_name = "FILE")]
    pub vectors: String,
    /// The unit's method: gouraud, euler, corrected-euler, adaptive or duff.
    #[arg(long, value_name = "NAME", value_parser = hardware_method)]
    pub method: Method,
    /// The fixed-point format M.F of the unit's registers: M integer bits (the sign
    /// included) and F ≤ 48 fractional bits, M + F ≤ 64.
    #[arg(long, value_name = "M.F", value_parser = fixed_format)]
    pub fixed: (u32, u32),
    /// Accept a vector file that is not one of the published sets.
    #[arg(long)]
    pub allow_modified_vectors: bool,
}

/// `--method`: a method a unit implements.
fn hardware_method(s: &str) -> Result<Method, BadValue> {
    let m: Method = s
        .parse()
        .map_err(|e: phong_approx::method::UnknownMethod| e.to_string())?;
    if HARDWARE.contains(&m) {
        Ok(m)
    } else {
        Err(BadValue::from(format!(
            "no hardware set-up for {m} (gouraud, euler, corrected-euler, adaptive or duff)"
        )))
    }
}

/// `--fixed`: `M.F`, as the profile `fixed:M.F` takes it, with `M + F ≤ 64`.
fn fixed_format(s: &str) -> Result<(u32, u32), BadValue> {
    match format!("fixed:{s}")
        .parse::<Profile>()
        .map_err(|e| e.to_string())?
    {
        Profile::Fixed {
            int_bits,
            frac_bits,
        } if int_bits + frac_bits <= 64 => Ok((int_bits, frac_bits)),
        Profile::Fixed { .. } => Err(BadValue::from(format!(
            "'{}': the registers are M + F bits, at most 64",
            phong_approx::conformance::shown(s)
        ))),
        _ => unreachable!("fixed:… parses as a fixed-point profile or not at all"),
    }
}

/// The row of one case: `p0, dp, t0, ds, q0, dq0, d2q` for `method` (columns the method
/// does not use are 0; docs/conformance.md, "Hardware span units"), or `None` for a
/// method no unit implements.
pub fn row(f: &FixedSpan, method: Method) -> Option<[i64; 7]> {
    Some(match method {
        Method::Gouraud => [f.p_a, f.dp, 0, 0, 0, 0, 0],
        Method::Euler => [f.p_a, 0, f.di_a, f.ds, 0, 0, 0],
        Method::CorrectedEuler => [f.p_a, 0, f.t0, f.ds, 0, 0, 0],
        Method::Adaptive => [f.p_a, f.dp, f.t0, f.ds, 0, 0, 0],
        Method::Duff => [f.b, f.a, 0, 0, f.q0, f.dq0, f.d2q],
        _ => return None,
    })
}

/// The column names of [`row`].
const COLUMNS: [&str; 7] = ["p0", "dp", "t0", "ds", "q0", "dq0", "d2q"];

/// Runs `phong-approx setup`.
///
/// # Errors
/// A [`CliError`] (exit code 2) for a vector file that cannot be read or is not a
/// published set, or a set-up value that does not fit the format's registers (naming
/// the case and the value).
pub fn run(a: &SetupArgs) -> Result<(), CliError> {
    let (m, f) = a.fixed;
    let text = read_capped(&a.vectors, "--vectors", MAX_RESULTS_BYTES)?;
    let loaded = load_vectors(text, &a.vectors, a.method, false, a.allow_modified_vectors)
        .map_err(|e| CliError::arg("--vectors", e.message))?;
    let limit = 1i128 << (m + f - 1);
    let mut csv = format!("case,n,{}\n", COLUMNS.join(","));
    for c in &loaded.file.cases {
        let span = case_span(c).map_err(|e| CliError::arg("--vectors", e))?;
        let fs = FixedSpan::new(&span, f).map_err(|e| CliError::arg("--fixed", e))?;
        let values = row(&fs, a.method).ok_or_else(|| {
            CliError::arg("--method", format!("no hardware set-up for {}", a.method))
        })?;
        for (v, name) in values.iter().zip(COLUMNS) {
            if i128::from(*v).abs() >= limit {
                return Err(CliError::arg(
                    "--fixed",
                    format!(
                        "case {}: {name} = {v}·2^-{f} does not fit {m}.{f} (registers of {} bits)",
                        c.id,
                        m + f
                    ),
                ));
            }
        }
        let cells: Vec<String> = values.iter().map(i64::to_string).collect();
        csv += &format!("{},{},{}\n", c.id, c.n, cells.join(","));
    }
    outp!("{csv}")
}
