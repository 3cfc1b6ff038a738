//! The command line end to end: its commands and refusals, `compare`, `reproduce`, the reliability of its inputs and outputs, the MPFR references.
//!
//! One test binary of several files (docs/testing.md, "Test binaries"); each file is a
//! module, its tests named `file::test`.

#[path = "../common/mod.rs"]
mod common;
#[path = "../runner/mod.rs"]
mod runner;

#[path = "../cli.rs"]
mod cli;
#[path = "../compare.rs"]
mod compare;
#[path = "../mpfr.rs"]
mod mpfr;
#[path = "../reliability/mod.rs"]
mod reliability;
#[path = "../reproduce.rs"]
mod reproduce;
