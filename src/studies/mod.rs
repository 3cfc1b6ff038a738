//! The studies run on the rasterizer ([`crate::raster`]): the paper's experiment (§5,
//! §6) — tori of quads rotated over 200 frames, every span shaded by every method of
//! the crate, the 8-bit levels compared with Phong's — and what is built on it.
//!
//! - [`render`]: one frame of the paper's experiment: every method per row, the
//!   statistics of Tables 1 and 2.
//! - [`experiment`]: the paper's Tables 1–2 over many frames, in parallel.
//! - [`calibrate`]: the scene choices the paper leaves open, fitted to its numbers.
//! - [`compare`], [`precision`]: every method of the paper and its related work on the
//!   same tori, and in every precision.
//! - [`pictures`]: PNG renders, heat maps with their legends, SVG plots (Figures 1–5);
//!   [`text`]: their labels, in embedded-graphics' mono font.
//! - [`reproduction`]: `reproduce`'s tables, CSVs and pictures, as strings and images.
//! - [`compare_report`]: `compare`'s studies, report, CSVs and labelled picture grid.

pub mod calibrate;
pub mod compare;
pub mod compare_report;
pub mod experiment;
pub mod pictures;
pub mod precision;
pub mod render;
pub mod reproduction;
pub mod text;
