//! A thin scan-line rasterizer for the paper's experiment (§5, §6): tori of quads,
//! rotated over 200 frames, every span shaded by every method of the crate, the
//! 8-bit levels compared with Phong's.
//!
//! - [`mesh`]: torus meshes with analytic or averaged vertex normals.
//! - [`scan`]: convex-polygon scan conversion (pixel centres, top-left rule).
//! - [`render`]: one frame: culling, depth buffer, per-span shading, statistics.
//! - [`experiment`]: the paper's Tables 1–2 over many frames, in parallel.
//! - [`pictures`]: PNG renders and heat maps, SVG plots (Figures 1–5).

pub mod compare;
pub mod experiment;
pub mod mesh;
pub mod pictures;
pub mod precision;
pub mod render;
pub mod shader;
pub mod scan;
