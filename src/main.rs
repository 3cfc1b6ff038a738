//! The `phong-approx` command line.
//!
//! - `phong-approx span`: one scan line by one method in one number type.
//! - `phong-approx reproduce`: the paper's Tables 1–2 and Figures 1–5.
//! - `phong-approx compare`: every method of the paper and its related work, diffuse
//!   and specular, in five precisions, with pictures (`docs/comparison.md`).
//! - `phong-approx vectors` / `check`: the conformance kit.
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
    Span(cli::span::SpanArgs),
    /// Reproduce the paper's Tables 1–2 and Figures 1–5 on rotating tori.
    Reproduce(cli::reproduce::ReproduceArgs),
    /// Compare every method (paper and related work) on the same tori: diffuse,
    /// specular, precisions, pictures.
    Compare(cli::compare::CompareArgs),
    /// Write the conformance test vectors (JSON and CSV) from the exact references.
    Vectors(cli::vectors::VectorsArgs),
    /// Check an implementation's results against a vector file (exit 0 pass, 1 fail).
    Check(cli::check::CheckArgs),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => return cli::clap_error(e),
    };
    let result = match cli.command {
        Command::Span(args) => cli::span::run(&args),
        Command::Reproduce(args) => cli::reproduce::run(&args),
        Command::Compare(args) => cli::compare::run(&args),
        Command::Vectors(args) => cli::vectors::run(&args),
        Command::Check(args) => cli::check::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("phong-approx: {}", cli::one_line(&e.to_string()));
            ExitCode::from(e.code())
        }
    }
}
