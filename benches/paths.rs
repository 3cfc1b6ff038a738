//! The fast kernels on each vector path this CPU has (`phong_approx::simd`: the
//! x86-64 baseline, AVX2 with FMA, AVX-512), forced in turn, in one run:
//!
//! - `paths_f32`: the store floor (filling the row with a constant, compiled for the
//!   same vector width) and the dispatched span kernels — Gouraud, corrected Euler,
//!   Phong in closed form, the adaptive scheme — at n = 8, 64, 512 and 4096, one span
//!   per call with its set-up; ids `KERNEL/PATH`. Beside them, what bounds the
//!   targets of docs/performance.md: `set_up` (`FastSpan::new` alone), the kernels
//!   with their set-up hoisted out of the loop (`*_kernel`), and `sqrt_div_floor`, a
//!   row of one correctly rounded square root and one division a pixel (the least a
//!   Phong pixel takes in `f32` without an approximate reciprocal square root).
//! - `paths_triangle_f32`: the paper's polygon and larger ones (legs S = 8, 32, 128),
//!   the batched kernels on each path next to Seiler's per-polygon quadratic,
//!   Bishop–Weimer and glam's per-pixel Phong (which take no path of ours).
//!
//! `cargo bench --bench paths`, then `python3 benches/paths_table.py` for the tables
//! of `docs/performance.md`.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use phong_approx::fast::FastSpan;
use phong_approx::simd::{self, Path};
use std::time::Duration;

#[path = "common/triangle.rs"]
#[allow(dead_code)]
mod triangle;
use triangle::{pixels, shade, Ctx, Which, METHODS};

const NS: [u32; 4] = [8, 64, 512, 4096];
const SIZES: [u32; 3] = [8, 32, 128];

/// A torus-like span: unit normals 12° apart, light in front (as `benches/spans.rs`).
fn span_inputs() -> ([f32; 3], [f32; 3], [f32; 3]) {
    let (a, b) = (0.35f64, 0.35f64 + 12f64.to_radians());
    let unit = |v: [f64; 3]| {
        let r = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [(v[0] / r) as f32, (v[1] / r) as f32, (v[2] / r) as f32]
    };
    (
        unit([a.sin(), 0.1, a.cos()]),
        unit([b.sin(), -0.05, b.cos()]),
        unit([-0.4, 0.4, 0.8]),
    )
}

/// `body()` compiled for `path`'s vector width, through the kernels' own dispatch
/// (`simd::dispatch`): `path` is the one forced for the run.
#[inline(always)]
fn on_path(path: Path, body: impl FnOnce()) {
    debug_assert_eq!(
        path,
        simd::path(),
        "the path being measured is the forced one"
    );
    simd::dispatch(|_| body())
}

/// The store floor on `path`: the row filled with one value, the loop compiled for
/// the path's vector width.
fn fill(path: Path, out: &mut [f32], v: f32) {
    on_path(path, || out.fill(v))
}

/// The square-root-and-division floor on `path`: `out[i] = p[i]/√q[i]` from rows
/// already in memory, the loop compiled for the path's vector width.
fn sqrt_div(path: Path, p: &[f32], q: &[f32], out: &mut [f32]) {
    on_path(path, || {
        for ((o, p), q) in out.iter_mut().zip(p).zip(q) {
            *o = p / q.sqrt();
        }
    })
}

/// `len` values of `buf` from a 64-byte boundary: the row starts on a cache line in
/// every run, so the store floor and the kernels meet the same alignment (a row whose
/// start moved from run to run moved the ratios to the floor by up to 2×).
fn aligned(buf: &mut [f32], len: usize) -> &mut [f32] {
    let skip = buf.as_ptr().align_offset(64);
    &mut buf[skip..skip + len]
}

fn spans(c: &mut Criterion) {
    let (na, nb, l) = span_inputs();
    let mut g = c.benchmark_group("paths_f32");
    g.warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(900))
        .sample_size(30);
    type K = fn(&FastSpan<f32>, &mut [f32]);
    let kernels: [(&str, K); 4] = [
        ("gouraud_fast", FastSpan::<f32>::gouraud),
        ("corrected_euler_fast", FastSpan::<f32>::corrected_euler),
        ("phong_fast", FastSpan::<f32>::phong),
        ("adaptive_fast", |s, o| {
            s.adaptive(1.0, o);
        }),
    ];
    let chosen = simd::path();
    for path in Path::supported_paths() {
        simd::force(path).expect("a supported path");
        for n in NS {
            g.throughput(Throughput::Elements(u64::from(n) + 1));
            let mut buf = vec![0f32; n as usize + 1 + 16];
            let out = aligned(&mut buf, n as usize + 1);
            g.bench_with_input(
                BenchmarkId::new(format!("store_floor/{path}"), n),
                &n,
                |b, _| b.iter(|| fill(path, out, black_box(0.5))),
            );
            // The span's own p_i and q_i (eqs. 2-3), as Phong's kernel sees them.
            let s0 = FastSpan::<f32>::new(na, nb, l, n);
            let (p, q): (Vec<f32>, Vec<f32>) = (0..=n)
                .map(|i| {
                    let x = i as f32;
                    (s0.a * x + s0.b, (s0.c * x + s0.d) * x + s0.e)
                })
                .unzip();
            g.bench_with_input(
                BenchmarkId::new(format!("sqrt_div_floor/{path}"), n),
                &n,
                |b, _| b.iter(|| sqrt_div(path, black_box(&p), black_box(&q), out)),
            );
            g.bench_with_input(
                BenchmarkId::new(format!("set_up/{path}"), n),
                &n,
                |b, &n| {
                    b.iter(|| FastSpan::<f32>::new(black_box(na), black_box(nb), black_box(l), n))
                },
            );
            for (name, k) in &kernels[..3] {
                let name = name.replace("_fast", "_kernel");
                g.bench_with_input(BenchmarkId::new(format!("{name}/{path}"), n), &n, |b, _| {
                    b.iter(|| k(black_box(&s0), out))
                });
            }
            for (name, k) in kernels {
                g.bench_with_input(
                    BenchmarkId::new(format!("{name}/{path}"), n),
                    &n,
                    |b, &n| {
                        b.iter(|| {
                            let s =
                                FastSpan::<f32>::new(black_box(na), black_box(nb), black_box(l), n);
                            k(&s, out);
                            black_box(&s);
                        })
                    },
                );
            }
        }
    }
    simd::force(chosen).expect("the path chosen before");
    g.finish();
}

fn triangles(c: &mut Criterion) {
    triangle::smoke();
    let mut ctx = Ctx::new();
    let (normals, l) = triangle::inputs();
    let which = |name: &str| -> Which {
        METHODS
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, w)| *w)
            .expect("a method of benches/common/triangle.rs")
    };
    let mut g = c.benchmark_group("paths_triangle_f32");
    g.warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(900))
        .sample_size(30);
    let chosen = simd::path();
    for s in SIZES {
        g.throughput(Throughput::Elements(pixels(s)));
        let mut out = vec![0f32; s as usize + 1];
        for name in ["seiler", "bishop_weimer", "glam_phong"] {
            let w = which(name);
            g.bench_with_input(BenchmarkId::new(name, s), &s, |b, &s| {
                b.iter(|| shade(w, s, black_box(&normals), black_box(&l), &mut ctx, &mut out))
            });
        }
        for path in Path::supported_paths() {
            simd::force(path).expect("a supported path");
            for name in ["batched_corrected_euler", "batched_phong", "batched_fence"] {
                let w = which(name);
                g.bench_with_input(
                    BenchmarkId::new(format!("{name}/{path}"), s),
                    &s,
                    |b, &s| {
                        b.iter(|| {
                            shade(w, s, black_box(&normals), black_box(&l), &mut ctx, &mut out)
                        })
                    },
                );
            }
        }
        simd::force(chosen).expect("the path chosen before");
    }
    g.finish();
}

criterion_group!(benches, spans, triangles);
criterion_main!(benches);
