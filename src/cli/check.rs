//! `phong-approx check`: compare an implementation's results with a vector file.

use super::CliError;
use clap::Args;
use phong_approx::conformance::check::{
    check, parse_results, CaseReport, Tolerance, MAX_RESULTS_BYTES,
};
use phong_approx::conformance::vectors::{method_key, VectorFile};
use phong_approx::Method;
use std::fs;
use std::path::Path;

/// Arguments of `phong-approx check`.
#[derive(Args, Debug)]
pub struct CheckArgs {
    /// The vector file (JSON, from `phong-approx vectors` or `vectors/`).
    #[arg(long, value_name = "FILE")]
    pub vectors: String,
    /// The implementation's results: CSV `case,pixel,value` or JSON.
    #[arg(long, value_name = "FILE")]
    pub results: String,
    /// The method the results are for (default corrected-euler); `angular-table256`
    /// for the tabled angular method.
    #[arg(long, value_name = "NAME", default_value = "corrected-euler")]
    pub method: String,
    /// levels=N, abs=X or ulps=N; default: the crate's float bound for the method at
    /// --precision.
    #[arg(long, value_name = "SPEC")]
    pub tolerance: Option<String>,
    /// The implementation's arithmetic, for the default tolerance: f32 or f64.
    #[arg(long, value_name = "TYPE", default_value = "f32")]
    pub precision: String,
    /// Check the specular expectations (max(0, method(N·H))^s) instead of diffuse.
    #[arg(long)]
    pub specular: bool,
}

fn read_limited(path: &str, what: &str) -> Result<String, CliError> {
    let p = Path::new(path);
    let meta = fs::metadata(p).map_err(|e| CliError::arg(what, format!("{path}: {e}")))?;
    if meta.len() > MAX_RESULTS_BYTES {
        return Err(CliError::arg(
            what,
            format!(
                "{path}: the file is larger than {} MiB",
                MAX_RESULTS_BYTES >> 20
            ),
        ));
    }
    let bytes = fs::read(p).map_err(|e| CliError::arg(what, format!("{path}: {e}")))?;
    String::from_utf8(bytes).map_err(|e| {
        CliError::arg(
            what,
            format!(
                "{path}: not UTF-8 text (byte {})",
                e.utf8_error().valid_up_to()
            ),
        )
    })
}

fn parse_method(s: &str) -> Result<Method, CliError> {
    if let Some(size) = s.strip_prefix("angular-table") {
        let n: u32 = size
            .parse()
            .map_err(|_| CliError::arg("--method", format!("'{s}': expected angular-table256")))?;
        return Ok(Method::AngularTable(n));
    }
    s.parse().map_err(|e| CliError::arg("--method", e))
}

/// Runs `phong-approx check`: exit 0 when every case is within tolerance, 1 when not,
/// 2 on bad input.
///
/// # Errors
/// A [`CliError`] with code 2 for bad input, 1 for results out of tolerance.
pub fn run(a: &CheckArgs) -> Result<(), CliError> {
    let method = parse_method(&a.method)?;
    let key = method_key(method);
    let u = match a.precision.as_str() {
        "f32" => f64::from(f32::EPSILON) / 2.0,
        "f64" => f64::EPSILON / 2.0,
        o => {
            return Err(CliError::arg(
                "--precision",
                format!("unknown precision '{o}' (expected f32 or f64)"),
            ))
        }
    };
    let tol = match &a.tolerance {
        Some(t) => Tolerance::parse(t).map_err(|e| CliError::arg("--tolerance", e))?,
        None => Tolerance::Default { u },
    };
    let vtext = read_limited(&a.vectors, "--vectors")?;
    let vectors: VectorFile = serde_json::from_str(&vtext).map_err(|e| {
        CliError::arg(
            "--vectors",
            format!("{}:{}: not a vector file: {e}", a.vectors, e.line()),
        )
    })?;
    if !vectors.methods.contains(&key) {
        return Err(CliError::arg(
            "--method",
            format!(
                "'{key}' is not in {} (it has: {})",
                a.vectors,
                vectors.methods.join(", ")
            ),
        ));
    }
    if a.specular && vectors.cases.iter().all(|c| c.specular.is_none()) {
        return Err(CliError::arg(
            "--specular",
            format!("{} has no specular cases", a.vectors),
        ));
    }
    let rtext = read_limited(&a.results, "--results")?;
    let results =
        parse_results(&rtext, &a.results, &vectors, a.specular).map_err(|e| CliError {
            message: e.to_string(),
            code: 2,
        })?;
    let reports = check(&vectors, &results, method, &key, tol, a.specular)
        .map_err(|e| CliError::arg("--method", e))?;
    print_report(&vectors, &reports, &key, a.specular)?;
    let failed: Vec<&CaseReport> = reports.iter().filter(|r| !r.pass).collect();
    if failed.is_empty() {
        Ok(())
    } else {
        Err(CliError {
            message: format!(
                "{} of {} cases out of tolerance, first: {}",
                failed.len(),
                reports.len(),
                failed[0].id
            ),
            code: 1,
        })
    }
}

fn print_report(
    vectors: &VectorFile,
    reports: &[CaseReport],
    key: &str,
    specular: bool,
) -> Result<(), CliError> {
    outln!(
        "{} {} set '{}' ({} cases), method {key}",
        if specular { "specular" } else { "diffuse" },
        vectors.version,
        vectors.set,
        reports.len()
    )?;
    outln!("| case | pixels | max Δlevel | mean Δlevel | max |Δ| | max ulps (f32) | allowed | verdict |")?;
    outln!("|---|---:|---:|---:|---:|---:|---:|---|")?;
    for r in reports {
        outln!(
            "| {} | {} | {} | {:.4} | {:.3e} | {:.1} | {} | {} |",
            r.id,
            r.pixels,
            r.max_levels,
            r.mean_levels,
            r.max_abs,
            r.max_ulps,
            r.allowed,
            if r.pass { "pass" } else { "FAIL" }
        )?;
    }
    let px: usize = reports.iter().map(|r| r.pixels).sum();
    let mean = reports
        .iter()
        .map(|r| r.mean_levels * r.pixels as f64)
        .sum::<f64>()
        / px.max(1) as f64;
    let max_l = reports.iter().map(|r| r.max_levels).max().unwrap_or(0);
    let max_a = reports.iter().map(|r| r.max_abs).fold(0.0, f64::max);
    let max_u = reports.iter().map(|r| r.max_ulps).fold(0.0, f64::max);
    outln!("\noverall: {px} pixels, max Δlevel {max_l}, mean Δlevel {mean:.4}, max |Δ| {max_a:.3e}, max {max_u:.1} f32 ulps")?;
    let worst = reports
        .iter()
        .filter(|r| !r.pass)
        .chain(reports.iter())
        .max_by(|a, b| a.max_abs.total_cmp(&b.max_abs));
    if let Some(w) = worst {
        if let Some(c) = vectors.cases.iter().find(|c| c.id == w.id) {
            outln!(
                "worst case {} (pixel {}): {}; Na = ({}), Nb = ({}), L = ({}), n = {}",
                w.id,
                w.worst_pixel,
                c.comment,
                c.na.exact.join(", "),
                c.nb.exact.join(", "),
                c.l.exact.join(", "),
                c.n
            )?;
        }
    }
    Ok(())
}
