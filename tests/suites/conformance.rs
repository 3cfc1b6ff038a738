//! The conformance kit: the committed vectors are what the code generates, the
//! checker passes this crate's own float results and fails wrong ones (naming the
//! case), and every kind of malformed input gets one line naming file, line and
//! problem.

#[path = "../runner/mod.rs"]
mod runner;
use runner::bin;

/// The committed files (`files::*`).
#[path = "../conformance/files.rs"]
mod files;
/// `check`'s verdicts (`verdicts::*`).
#[path = "../conformance/verdicts.rs"]
mod verdicts;

// The helpers the modules share (`files`'s `pub(crate)` items).
use files::*;

use phong_approx::conformance::check::{check, parse_results, Criteria, Tolerance};
use phong_approx::conformance::vectors::{
    self as vectors, inputs_csv, to_csv, Case, VectorFile, SETS,
};
use phong_approx::parse::parse_rational;
use phong_approx::{Method, Real, Scalar, Span, Vec3};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
