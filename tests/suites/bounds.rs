//! The float bounds: the reference bounds of every method and of the related methods, attacked; the float model of the proofs.
//!
//! One test binary of several files (docs/testing.md, "Test binaries"); each file is a
//! module, its tests named `file::test`.

#[path = "../common/mod.rs"]
mod common;

#[path = "../float_bounds.rs"]
mod float_bounds;
#[path = "../float_bounds_related.rs"]
mod float_bounds_related;
#[path = "../float_model.rs"]
mod float_model;
