//! The methods and kernels: every method in every format, the fast kernels, the related methods, the low-precision scalars, the planted mutants, the test kit from a user's side.
//!
//! One test binary of several files (docs/testing.md, "Test binaries"); each file is a
//! module, its tests named `file::test`.

#[path = "../common/mod.rs"]
mod common;

#[path = "../fast.rs"]
mod fast;
#[path = "../fast_paths.rs"]
mod fast_paths;
#[path = "../fast_rows.rs"]
mod fast_rows;
#[cfg(feature = "lowp")]
#[path = "../lowp.rs"]
mod lowp;
#[path = "../methods.rs"]
mod methods;
#[path = "../mutants.rs"]
mod mutants;
#[path = "../related.rs"]
mod related;
/// The specular skip test (`skip::*`).
#[path = "../skip.rs"]
mod skip;
/// The squared method (`squared_corrected_euler`).
#[path = "../squared.rs"]
mod squared;
#[path = "../testkit.rs"]
mod testkit;
