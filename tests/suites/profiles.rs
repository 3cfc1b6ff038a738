//! The acceptance profiles (`docs/float.md` §18, `proofs/Profiles.v`): Gouraud,
//! corrected Euler and plain Euler computed by *other* implementations of the class
//! each profile allows stay within the proved bound of the exact values on the exact
//! inputs. Each test is named like its theorem.
//!
//! The implementations are written here from the definitions, not taken from `src/`:
//! - `ieee`: native `f32`/`f64` code with the dot products summed in other orders,
//!   with fused multiply-adds (`mul_add`), with `1/n` taken once and multiplied, and
//!   corrected Euler and Euler by their closed forms `p_a + i·(t_0 + (i−1)/2·ds)` and
//!   `p_a + i·(di_a + (i−1)/2·ds)`;
//! - `shader`: an operation-by-operation software model of binary32 (`common::emu`)
//!   that at every rounding takes what the Vulkan/WGSL precision rules allow and a
//!   careful implementation would not: round toward zero (or down, or up) for every
//!   addition, subtraction and multiplication, divisions 2 ulps toward zero from the
//!   nearest (within the 2.5 ulps allowed), fused or unfused products, and every
//!   input and result below `2^-126` flushed to zero; each division by `n` or by 2
//!   one such division or a reciprocal (`1/n`, a computed `1/2`) then a product; the
//!   recurrences and the closed forms, with `(i−1)/2` exact or halved in floats.
//!
//! Inputs: the edge, targeted and random spans of `tests/common` (n up to 4096 in the
//! extensive tier), exact values from the exact run.
//!
//! Phong under `ieee` has a derived (not machine-checked) bound, docs/float.md §18.4:
//! `phong_ieee_derived_*` run Horner's closed form, the per-pixel normal and
//! normalize-then-dot against it.

#[path = "../common/mod.rs"]
mod common;
/// The composed bounds against `proofs/Composed.v` (`composed::*`).
#[path = "../composed.rs"]
mod composed;
/// Duff's and symmetric Phong's counts against `proofs/DuffCount.v` (`duff_count::*`).
#[path = "../duff_count.rs"]
mod duff_count;
/// The operation graphs' per-case bounds against every implementation here (`graph::*`).
#[path = "../graph.rs"]
pub(crate) mod graph;
/// The affine error forms against `proofs/GraphAffine.v` (`graph_affine::*`).
#[path = "../graph_affine.rs"]
mod graph_affine;
/// Bugs a few times larger than rounding fail the published sets (`graph_mutants::*`).
#[path = "../graph_mutants.rs"]
mod graph_mutants;
/// How sharp the applied bounds are against legal binary32 executions (`graph_tightness::*`).
#[path = "../graph_tightness.rs"]
mod graph_tightness;
/// Phong's value step against `proofs/PhongValue.v` (`phong_value::phong_value_*`).
#[path = "../phong_value.rs"]
mod phong_value;
/// The profiles' tables against the theorems' statements (`profile_tables::test`).
#[path = "../profile_tables.rs"]
mod profile_tables;

/// The adaptive scheme's acceptance and δ band (`adaptive::*`).
#[path = "../profiles/adaptive.rs"]
mod adaptive;
/// The model's adversary and the Quake `rsqrt` in Phong (`adversary::*`).
#[path = "../profiles/adversary.rs"]
pub(crate) mod adversary;
/// Phong's, Duff's and symmetric Phong's composed bounds (`derived::*`).
#[path = "../profiles/derived.rs"]
mod derived;
/// The `ieee` bounds against native implementations (`ieee::*`).
#[path = "../profiles/ieee.rs"]
pub(crate) mod ieee;
/// The published sets judged as a user's code is (`published::*`).
#[path = "../profiles/published.rs"]
mod published;
/// The `shader` bounds against the software GPUs (`shader::*`).
#[path = "../profiles/shader.rs"]
mod shader;

// The implementations and helpers the modules share (each module's `pub(crate)` items).
use adversary::*;
use common::emu::{round_dir, toward_zero, Dir, Format as Emu, BINARY32};
use common::*;
use derived::*;
use ieee::*;
use num_traits::{Signed, Zero};
use phong_approx::tolerance::profile::{Form, Profile};
use phong_approx::{Format, Method, Scalar, Span};
use published::*;
use shader::*;
