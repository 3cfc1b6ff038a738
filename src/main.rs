//! The `phong-approx` command line.
//!
//! - `phong-approx span`: one scan line by one method in one number type.
//! - `phong-approx reproduce`: the paper's Tables 1–2 and Figures 1–5.
//! - `phong-approx compare`: every method of the paper and its related work, diffuse
//!   and specular, in five precisions, with pictures (`docs/comparison.md`).
//! - `phong-approx vectors` / `check`: the conformance kit.
//! - `phong-approx skip`: whether a span's specular pass may be skipped (§7.1, a).
//! - `phong-approx setup`: each case's set-up rounded to fixed point, for a hardware
//!   span unit (`harness/hdl/`).
//! - `phong-approx gpu-check`: a compute kernel run on a GPU adapter and judged as
//!   `check` judges results (feature `gpu`).
//!
//! Bad input prints one line on stderr naming the argument and the problem and exits
//! with code 2.

mod cli;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// A verified reference for scan-line Phong-shading approximations.
#[derive(Parser, Debug)]
#[command(name = "phong-approx", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Shade one scan line with one method and print its values and 8-bit levels.
    #[command(allow_negative_numbers = true)]
    Span(Box<cli::span::SpanArgs>),
    /// Reproduce the paper's Tables 1–2 and Figures 1–5 on rotating tori.
    #[command(allow_negative_numbers = true)]
    Reproduce(cli::reproduce::ReproduceArgs),
    /// Compare every method (paper and related work) on the same tori: diffuse,
    /// specular, precisions, pictures.
    #[command(allow_negative_numbers = true)]
    Compare(cli::compare::CompareArgs),
    /// Write the conformance test vectors (JSON and CSV) from the exact references.
    #[command(allow_negative_numbers = true)]
    Vectors(cli::vectors::VectorsArgs),
    /// Check an implementation's results against a vector file (exit 0 pass, 1 fail).
    #[command(allow_negative_numbers = true)]
    Check(cli::check::CheckArgs),
    /// Decide whether a span's specular pass may be skipped (the paper's §7.1 question):
    /// the exact test and the float form with its margins.
    #[command(allow_negative_numbers = true)]
    Skip(Box<cli::skip::SkipArgs>),
    /// Print each case's set-up rounded to a fixed-point format M.F: the inputs of a
    /// hardware span unit (harness/hdl, docs/conformance.md "Hardware span units").
    Setup(cli::setup::SetupArgs),
    /// Run a compute kernel (WGSL, SPIR-V, GLSL) on a GPU adapter over every published
    /// case and judge it as `check` does (exit 0 pass, 1 fail); feature `gpu`.
    #[command(name = "gpu-check")]
    GpuCheck(cli::gpu::GpuCheckArgs),
}

/// Whether standard output was closed when the process started (`>&-`). Rust's runtime
/// opens `/dev/null` on a closed descriptor 0–2 before `main`, so `main` alone cannot
/// tell `>&-` from `> /dev/null`; this is recorded earlier, by a function in the
/// `.init_array` section, which the C runtime runs before Rust's start-up code.
static STDOUT_WAS_CLOSED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

#[cfg(target_os = "linux")]
#[used]
#[link_section = ".init_array"]
static RECORD_CLOSED_STDOUT: extern "C" fn() = record_closed_stdout;

#[cfg(target_os = "linux")]
extern "C" fn record_closed_stdout() {
    // SAFETY: fcntl(F_GETFD) on descriptor 1 only reads its flags.
    if unsafe { libc::fcntl(1, libc::F_GETFD) } == -1 {
        STDOUT_WAS_CLOSED.store(true, std::sync::atomic::Ordering::Relaxed);
    }
}

fn main() -> ExitCode {
    if STDOUT_WAS_CLOSED.load(std::sync::atomic::Ordering::Relaxed) {
        cli::report(
            "standard output is closed: give it a file or a pipe (e.g. > out.txt, or > /dev/null to discard it)",
        );
        return ExitCode::from(2);
    }
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => return cli::clap_error(e),
    };
    // A vector path asked for and not taken would change what a run measures without
    // a word (src/simd.rs): refused before any work.
    if let Err(message) = phong_approx::simd::from_env() {
        cli::report(&message.to_string());
        return ExitCode::from(2);
    }
    let result = match cli.command {
        Command::Span(args) => cli::span::run(&args),
        Command::Reproduce(args) => cli::reproduce::run(&args),
        Command::Compare(args) => cli::compare::run(&args),
        Command::Vectors(args) => cli::vectors::run(&args),
        Command::Check(args) => cli::check::run(&args),
        Command::Setup(args) => cli::setup::run(&args),
        Command::Skip(args) => cli::skip::run(&args),
        Command::GpuCheck(args) => cli::gpu::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            cli::report_details(&e.to_string(), &e.details);
            ExitCode::from(e.code())
        }
    }
}

/// Argument checks that need no process: each bad `span` request is parsed and run in
/// this process and must fail with exit code 2 and a one-line message naming the
/// problem. (`tests/cli.rs` and `tests/reliability/` keep the end-to-end runs that
/// need a process: exit codes, stderr, pipes and files.)
#[cfg(test)]
mod tests {
    use super::{cli, Cli, Command};
    use clap::Parser;

    /// A valid `span` request with `extra` replacing or adding arguments.
    fn args(extra: &[(&str, &str)]) -> Vec<String> {
        let mut args: Vec<(String, String)> = [
            ("--method", "corrected-euler"),
            ("--na", "0,3/5,4/5"),
            ("--nb", "2/7,3/7,6/7"),
            ("--light", "2/3,1/3,2/3"),
            ("--steps", "4"),
        ]
        .iter()
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect();
        for (k, v) in extra {
            match args.iter_mut().find(|(a, _)| a == k) {
                Some(slot) => slot.1 = v.to_string(),
                None => args.push((k.to_string(), v.to_string())),
            }
        }
        let mut v = vec!["phong-approx".to_string(), "span".to_string()];
        v.extend(args.iter().map(|(k, v)| format!("{k}={v}")));
        v
    }

    /// The request fails before printing anything, with exit code 2 and one line
    /// containing `needle`.
    fn bad(extra: &[(&str, &str)], needle: &str) {
        let message = match Cli::try_parse_from(args(extra)) {
            Err(e) => {
                assert_ne!(e.exit_code(), 0, "{extra:?}");
                cli::clap_message(&e)
            }
            Ok(Cli {
                command: Command::Span(a),
            }) => {
                let e = cli::span::run(&a).expect_err("a bad request");
                assert_eq!(e.code(), 2, "{extra:?}: {e}");
                e.to_string()
            }
            Ok(other) => panic!("not a span request: {other:?}"),
        };
        let line = cli::one_line(&message);
        assert!(!line.contains('\n'), "{extra:?}: not one line: {line}");
        assert!(
            line.contains(needle),
            "{extra:?}: '{line}' lacks '{needle}'"
        );
    }

    #[test]
    fn bad_span_requests_are_refused_in_process() {
        bad(
            &[("--na", "0.6,x,0.8")],
            "--na: component 2 'x' is not a number",
        );
        bad(
            &[("--na", "0.6,0")],
            "--na: expected three components x,y,z, got 2",
        );
        bad(
            &[("--nb", "1,2,3,4")],
            "--nb: expected three components x,y,z, got 4",
        );
        bad(&[("--light", "0,0,0")], "--light: the vector is zero");
        bad(&[("--na", "1,1,1")], "--na: not a unit vector");
        bad(&[("--na", "1,1,1")], "--normalize");
        // Nb = −Na: Phong is undefined at the middle pixel of an even n, and says which.
        bad(
            &[("--nb", "0,-3/5,-4/5"), ("--method", "phong")],
            "pixel 2 of n = 4: the interpolated normal is zero",
        );
        bad(&[("--steps", "0")], "--steps: n must be between 1");
        bad(&[("--steps", "-3")], "--steps: '-3' is not a whole number");
        bad(
            &[("--steps", "abc")],
            "--steps: 'abc' is not a whole number",
        );
        bad(
            &[("--steps", "99999999999")],
            "--steps: n must be between 1 and 16777216",
        );
        bad(
            &[("--method", "bishop")],
            "--method: unknown method 'bishop'",
        );
        bad(
            &[("--scalar", "f16")],
            "--scalar: unknown value 'f16' (expected one of f32, f64, exact, mpfr)",
        );
        bad(&[("--format", "xml")], "--format: unknown value 'xml'");
        bad(
            &[("--na", "1/0,0,1")],
            "--na: component 1 '1/0' has a zero denominator",
        );
        bad(
            &[("--na", "nan,0,1")],
            "--na: component 1 'nan' is not a number",
        );
        bad(&[("--na", "1e999999,0,1")], "exponent");
        bad(&[("--light", "1e300,0,0"), ("--scalar", "f32")], "--light:");
        bad(&[("--kd", "one")], "--kd:");
        bad(&[("--kd", "-1")], "--kd:");
        bad(
            &[("--table-size", "256")],
            "--table-size: only the angular method",
        );
        bad(
            &[("--method", "angular"), ("--table-size", "1")],
            "--table-size: the table size must be between 2",
        );
        bad(&[("--precision", "0")], "--precision:");
        bad(&[("--digits", "0")], "--digits:");
        bad(&[("--bogus", "1")], "--bogus");
        if !cfg!(feature = "mpfr") {
            bad(&[("--scalar", "mpfr")], "--features mpfr");
        }
    }
}
