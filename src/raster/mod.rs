//! A thin scan-line rasterizer: tori of quads, projected and scan-converted, every row
//! handed to the caller as a span — small enough to read in one sitting. The studies
//! that run on it (the paper's tables, the comparison, the calibration, the pictures)
//! are [`crate::studies`].
//!
//! - [`mesh`]: torus meshes with analytic or averaged vertex normals.
//! - [`scene`]: the view: rotation per frame, orthographic projection.
//! - [`scan`]: convex-polygon scan conversion (pixel centres, top-left rule).
//! - [`frame`]: the one frame loop — project, cull, scan, shade (the caller's
//!   [`frame::Shading`]), depth-test.
//! - [`shader`]: what a row can be shaded with: every span method of the catalogue and
//!   the methods set up per polygon.
//! - [`stats`]: deviations in 8-bit levels over the visible pixels.

pub mod frame;
pub mod mesh;
pub mod scan;
pub mod scene;
pub mod shader;
pub mod stats;
