//! A thin scan-line rasterizer for the paper's experiment (§5, §6): tori of quads,
//! rotated over 200 frames, every span shaded by every method of the crate, the
//! 8-bit levels compared with Phong's.
//!
//! - [`mesh`]: torus meshes with analytic or averaged vertex normals.
//! - [`scan`]: convex-polygon scan conversion (pixel centres, top-left rule).
//! - [`render`]: one frame: culling, depth buffer, per-span shading, statistics.
//! - [`experiment`]: the paper's Tables 1–2 over many frames, in parallel.
//! - [`calibrate`]: the scene choices the paper leaves open, fitted to its numbers.
//! - [`compare`], [`precision`]: every method of the paper and its related work on the
//!   same tori, and in every precision.
//! - [`pictures`]: PNG renders, heat maps with their legends, SVG plots (Figures 1–5);
//!   [`text`]: their labels, in embedded-graphics' mono font.
//! - [`report`]: `reproduce`'s tables, CSVs and pictures, as strings and images.
//! - [`compare_report`]: `compare`'s studies, report, CSVs and labelled picture grid.

pub mod calibrate;
pub mod compare;
pub mod compare_report;
pub mod experiment;
pub mod frame;
pub mod mesh;
pub mod pictures;
pub mod precision;
pub mod render;
pub mod report;
pub mod scan;
pub mod scene;
pub mod shader;
pub mod stats;
pub mod text;
