//! The conformance kit: published test vectors and a checker, for implementations in
//! other languages and number types to run in their CI.
//!
//! - [`vectors`]: the `typical`, `edge` and `paper` sets, generated from the exact
//!   references (committed under `vectors/`, with a JSON Schema).
//! - [`check`]: reading an implementation's results and comparing them, with
//!   per-method default tolerances from [`crate::tolerance`].
//! - [`export`]: the verdict as JUnit XML or JSON, for other languages' CI.
//! - [`verdict`]: one check start to end: the vector file trusted or recomputed, and
//!   the verdict as text.
//!
//! How to use it from C or a shader harness: `docs/conformance.md`.

pub mod check;
pub mod export;
pub mod integrity;
pub mod judgement;
pub mod vectors;
pub mod verdict;

pub use crate::error::{shown, SHOWN_CHARS};
