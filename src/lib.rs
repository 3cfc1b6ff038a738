//! # phong-approx
//!
//! A verified numerical reference for scan-line approximations of Phong shading, after
//! A. Hast, T. Barrera and E. Bengtsson, *Approximated Phong Shading by using the Euler
//! Method*, and Z. Mortensen's 1995 text on linear interpolation of angles.
//!
//! Every recurrence is written once, generic over [`Scalar`], and runs on `f32`, `f64`,
//! exact rationals ([`num_rational::BigRational`]) and, with the `mpfr` feature, MPFR
//! floats: the exact run is the reference for the float run.
//!
//! | method | module | equations |
//! |---|---|---|
//! | Phong, exact per pixel | [`phong`] | eq. 4 |
//! | Duff's forward differences | [`duff`] | eqs. 5–7 |
//! | symmetric (half-square-root) Phong | [`symmetric_phong`] | §4 |
//! | Gouraud / fence along the span | [`gouraud`] | §1, eq. 23 |
//! | Euler | [`euler`] | eqs. 12–14 |
//! | corrected Euler | [`corrected_euler`] | eqs. 15–17 |
//! | adaptive Gouraud test | [`adaptive`] | eqs. 23–24 |
//! | angular interpolation | [`angular`] | second source |
//! | specular `(N·H)^s` | [`specular`] | eq. 1, §6.1 |
//! | 8-bit levels | [`quantize`] | §6 |
//! | skipping the specular pass | [`skip`] | §7.1, question a |
//! | corrected Euler on `(N·H)²` | [`squared_corrected_euler`] | §7.1, question b |
//!
//! The methods of the paper's related work — Bishop & Weimer, Seiler, Kuijk & Blake,
//! Mortensen's vertex angles, Ouyang & Maynard — are in [`related`]; low-precision
//! scalars (binary16, 16.16 and 8.8 fixed point) in `lowp` (feature `lowp`); the comparison of all of
//! them on the torus harness in `studies::compare` and `studies::precision`
//! (`phong-approx compare`, `docs/comparison.md`).
//!
//! To test an implementation of your own from `cargo test`: [`testkit`]
//! (`Suite::published().method(…).profile(…).check_f32(…).assert_ok()`), the
//! published vectors embedded and judged as `phong-approx check` judges them.
//!
//! The set-up of a scan line (k, A, B, C, D, E, p_a, p_b, dq_a, dq_b, di_a, di_b, ds,
//! p_n, ε, dε, t_0, d_p) lives in [`Span`].
//!
//! The derivation of every claim, with links to its Coq proof (`proofs/`) and its
//! property test (`tests/claims/`), is in [`derivations`] (the crate's
//! `docs/derivations.md`); the places where the sources are wrong or ambiguous are in
//! [`errata`] (`docs/errata.md`).
//!
//! ```
//! use phong_approx::{reference::unit::unit_from_ints, Method, Span};
//! // Exact unit normals (3/5, 0, 4/5) and (−3/5, 0, 4/5), 4·atan(1/3) ≈ 73.7° apart,
//! // light straight on, 8 steps.
//! let na = unit_from_ints(1, 0, 3);
//! let nb = unit_from_ints(-1, 0, 3);
//! let l = unit_from_ints(0, 0, 1);
//! let span = Span::new(na, nb, l, 8).unwrap();
//! let v = Method::CorrectedEuler.values(&span).unwrap();
//! // Corrected Euler is exact at both edges (eqs. 15–17).
//! assert_eq!(v[0], span.p_a);
//! assert_eq!(v[8], span.p_b);
//! ```

#![warn(missing_docs)]

pub mod adaptive;

// docs/derivations.md, errata.md and float.md with their math escaped for rustdoc (build.rs).
#[doc = include_str!(concat!(env!("OUT_DIR"), "/derivations.md"))]
pub mod derivations {}

#[doc = include_str!(concat!(env!("OUT_DIR"), "/errata.md"))]
pub mod errata {}

#[doc = include_str!(concat!(env!("OUT_DIR"), "/float.md"))]
pub mod float {}

pub mod angular;
pub mod budget;
pub mod conformance;
pub mod corrected_euler;
pub mod duff;
pub mod error;
pub mod euler;
pub mod fast;
pub mod fast_rows;
pub mod fixed_span;
pub mod format;
pub mod gouraud;
#[cfg(feature = "gpu")]
pub mod gpu;
#[cfg(feature = "lowp")]
pub mod lowp;
pub mod method;
pub mod parse;
pub mod phong;
pub mod profile;
pub mod quantize;
#[cfg(feature = "harness")]
pub mod raster;
pub mod reference;
pub mod related;
pub mod scalar;
pub mod simd;
pub mod skip;
pub mod span;
pub mod span_report;
pub mod specular;
pub mod squared_corrected_euler;
#[cfg(feature = "harness")]
pub mod studies;
pub mod symmetric_phong;
pub mod table;
pub mod testkit;
pub mod tolerance;
pub mod vector;

pub use error::{Input, SpanError};
pub use format::{Arithmetic, Format};
pub use method::Method;
pub use num_rational::BigRational;
pub use scalar::{Real, Scalar};
pub use span::Span;
pub use vector::Vec3;
