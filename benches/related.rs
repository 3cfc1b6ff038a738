//! The related-work methods against the paper's, on one triangle: every method with
//! its own set-up (per polygon for vertex Gouraud, vertex angles, Bishop–Weimer and
//! Seiler; per scan line for the span methods), in `f32`, in ns per shaded pixel.
//! Triangles with legs of S = 8, 32 and 128 pixels (36, 528 and 8 256 pixels): S = 8
//! is the paper's polygon size, where the set-up decides; S = 128 shows the inner loop.
//!
//! The methods are listed once, in `benches/common/triangle.rs` (shared with the
//! instruction counts of `benches/callgrind.sh`):
//! - `fast_*`: the paper's fast kernels (`FastSpan`) after the two edge normals are
//!   normalized, one reciprocal per span;
//! - `batched_*`: the set-up of all rows of the triangle at once (`fast_rows::Batch`);
//! - `stepped_*`: the set-up stepped down the edge (`fast_rows::EdgeStepper`);
//! - `field_phong*`: Phong of the normal field in closed form per row;
//! - `span_*`: the checked generic path (`Span::new` and `Method::shade`);
//! - `stage_*` (group `triangle_stages_f32`, S = 8): `fast_corrected_euler` cut after
//!   each stage of its per-row set-up.
//!
//! `cargo bench --bench related`, then `python3 benches/summarize.py` for the tables of
//! `docs/performance.md`.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::time::Duration;

#[path = "common/triangle.rs"]
mod triangle;
use triangle::{inputs, pixels, shade, Ctx, Which, METHODS, STAGES};

/// Leg lengths of the right triangle `(0, 0), (S, 0), (0, S)`.
const SIZES: [u32; 3] = [8, 32, 128];

/// Times every entry of `list` on the triangles with legs `sizes`, in group `group`.
fn group(c: &mut Criterion, group: &str, list: &[(&str, Which)], sizes: &[u32], ctx: &mut Ctx) {
    let (normals, l) = inputs();
    let mut g = c.benchmark_group(group);
    g.warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(900))
        .sample_size(30);
    for &s in sizes {
        g.throughput(Throughput::Elements(pixels(s)));
        let mut out = vec![0f32; s as usize + 1];
        for &(name, w) in list {
            g.bench_with_input(BenchmarkId::new(name, s), &s, |b, &s| {
                b.iter(|| shade(w, s, black_box(&normals), black_box(&l), ctx, &mut out))
            });
        }
    }
    g.finish();
}

fn related(c: &mut Criterion) {
    triangle::smoke();
    let mut ctx = Ctx::new();
    group(c, "triangle_f32", &METHODS, &SIZES, &mut ctx);
    // The stages at the paper's polygon size.
    group(c, "triangle_stages_f32", &STAGES, &[8], &mut ctx);
}

criterion_group!(benches, related);
criterion_main!(benches);
