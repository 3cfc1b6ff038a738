//! The related-work methods against the paper's, on one triangle: every method with
//! its own set-up (per polygon for vertex Gouraud, vertex angles, Bishop–Weimer and
//! Seiler; per scan line for the span methods), through the crate's generic code in
//! `f32`, in ns per shaded pixel. Triangles with legs of S = 8, 32 and 128 pixels
//! (36, 528 and 8 256 pixels): small polygons show what the set-up costs, large ones
//! what the inner loop costs.
//!
//! The span methods run through the checked generic path (`Span::new` +
//! `Method::shade`, as `reference_*` in `benches/spans.rs`), like the polygon
//! methods, which have no other path; `fast_*` add the paper's fast kernels
//! (`FastSpan`, `src/fast.rs`) with their one-reciprocal set-up, the best a span
//! method can do.
//!
//! `cargo bench --bench related`, then `python3 benches/summarize.py` for the table of
//! `docs/performance.md`.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use phong_approx::angular::CosTable;
use phong_approx::fast::FastSpan;
use phong_approx::related::bishop_weimer::Taylor;
use phong_approx::related::seiler::Quadratic;
use phong_approx::related::triangle::Triangle;
use phong_approx::related::{binary, spherical, vertex_angle};
use phong_approx::{Method, Span, Vec3};
use std::time::Duration;

/// Leg lengths of the right triangle `(0, 0), (S, 0), (0, S)`.
const SIZES: [u32; 3] = [8, 32, 128];

type V = Vec3<f32>;

/// Unit vertex normals about 15° apart (a torus-like patch) and the light.
fn inputs() -> ([V; 3], V) {
    let unit = |x: f32, y: f32, z: f32| Vec3::new(x, y, z).normalize();
    (
        [
            unit(0.10, 0.05, 1.0),
            unit(0.37, 0.02, 0.93),
            unit(0.08, 0.31, 0.95),
        ],
        unit(-0.4, 0.4, 0.8),
    )
}

/// The rows of the triangle with legs `s`: `(y, n)` with pixels `x = 0..=n`.
fn rows(s: u32) -> impl Iterator<Item = (u32, u32)> {
    (0..s).map(move |y| (y, s - 1 - y))
}

fn pixels(s: u32) -> u64 {
    u64::from(s) * u64::from(s + 1) / 2
}

fn triangle(s: u32) -> Triangle<f32> {
    let s = s as f32;
    Triangle::new([(0.0, 0.0), (s, 0.0), (0.0, s)]).expect("a proper triangle")
}

/// A polygon method: set-up for the triangle, then one call per row.
fn per_polygon(
    s: u32,
    normals: &[V; 3],
    l: &V,
    table: &CosTable<f32>,
    which: &str,
    out: &mut [f32],
) {
    let tri = triangle(s);
    let rel = |y: u32| tri.relative(&0.0, &(y as f32));
    match which {
        "vertex_gouraud" => {
            let f = tri.affine(&[normals[0].dot(l), normals[1].dot(l), normals[2].dot(l)]);
            for (y, n) in rows(s) {
                let (x0, y) = rel(y);
                f.shade_row(&x0, &y, &mut out[..=n as usize]);
            }
        }
        "vertex_angle" => {
            let f = vertex_angle::angle_field(&tri, normals, l);
            for (y, n) in rows(s) {
                let (x0, y) = rel(y);
                vertex_angle::shade_row(&f, table, &x0, &y, &mut out[..=n as usize]);
            }
        }
        "bishop_weimer" => {
            let (n1, n2, n3) = tri.normal_field(normals);
            let t = Taylor::new(&n1, &n2, &n3, l).expect("N3 ≠ 0");
            for (y, n) in rows(s) {
                let (x0, y) = rel(y);
                t.shade_row(&x0, &y, &mut out[..=n as usize]);
            }
        }
        "seiler" => {
            let q = Quadratic::from_normals(&tri, normals, l).expect("no opposite normals");
            for (y, n) in rows(s) {
                let (x0, y) = rel(y);
                q.shade_row(&x0, &y, &mut out[..=n as usize]);
            }
        }
        _ => unreachable!("unknown polygon method {which}"),
    }
    black_box(&out);
}

/// The rows of the span methods: the normal field once per polygon, then per row the
/// two edge normals (normalized) and `shade(N_a, N_b, n, row)`; a one-pixel row gets
/// `N·L`.
fn per_row(
    s: u32,
    normals: &[V; 3],
    l: &V,
    out: &mut [f32],
    mut shade: impl FnMut(V, V, u32, &mut [f32]),
) {
    let tri = triangle(s);
    let (n1, n2, n3) = tri.normal_field(normals);
    let at = |x: f32, y: f32| n1.scale(&x).add(&n2.scale(&y)).add(&n3).normalize();
    for (y, n) in rows(s) {
        let (x0, yr) = tri.relative(&0.0, &(y as f32));
        let na = at(x0, yr);
        let o = &mut out[..=n as usize];
        if n == 0 {
            o[0] = na.dot(l);
        } else {
            shade(na, at(x0 + n as f32, yr), n, o);
        }
    }
    black_box(&out);
}

/// A span method through the checked generic path: `Span::new`, then the method.
fn per_span(s: u32, normals: &[V; 3], l: &V, which: &str, out: &mut [f32]) {
    per_row(s, normals, l, out, |na, nb, n, o| {
        let span = Span::new(na, nb, l.clone(), n).expect("unit normals");
        match which {
            "spherical" => spherical::shade(&span, o),
            "binary" => binary::shade(&span, o),
            "bishop_weimer_span" => phong_approx::related::bishop_weimer::shade(&span, o),
            name => name
                .parse::<Method>()
                .expect("a method of the paper")
                .shade(&span, o),
        }
        .expect("the output length is n + 1");
    });
}

/// A fast span kernel of the paper: `FastSpan::new` per row, then the kernel.
fn per_span_fast(s: u32, normals: &[V; 3], l: &V, kernel: Kernel, out: &mut [f32]) {
    let arr = |v: &V| v.components().map(|c| *c);
    let la = arr(l);
    per_row(s, normals, l, out, |na, nb, n, o| {
        kernel(&FastSpan::<f32>::new(arr(&na), arr(&nb), la, n), o)
    });
}

type Kernel = fn(&FastSpan<f32>, &mut [f32]);

/// Per-pixel Phong as most users write it: the normal field at every pixel,
/// normalized, dotted with `L`.
fn per_pixel_phong(s: u32, normals: &[V; 3], l: &V, out: &mut [f32]) {
    let tri = triangle(s);
    let (n1, n2, n3) = tri.normal_field(normals);
    let g = |v: &V| glam::Vec3::from(v.components().map(|c| *c));
    let (n1, n2, n3, l) = (g(&n1), g(&n2), g(&n3), g(l));
    for (y, n) in rows(s) {
        let (x0, yr) = tri.relative(&0.0, &(y as f32));
        let base = n2 * yr + n3;
        for (j, o) in out[..=n as usize].iter_mut().enumerate() {
            *o = (n1 * (x0 + j as f32) + base).normalize().dot(l);
        }
    }
    black_box(&out);
}

fn related(c: &mut Criterion) {
    let (normals, l) = inputs();
    let table = CosTable::<f32>::new(256).expect("256 entries");
    let mut g = c.benchmark_group("triangle_f32");
    g.warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(900))
        .sample_size(30);
    for s in SIZES {
        g.throughput(Throughput::Elements(pixels(s)));
        let mut out = vec![0f32; s as usize + 1];
        g.bench_with_input(BenchmarkId::new("glam_phong", s), &s, |b, &s| {
            b.iter(|| per_pixel_phong(s, black_box(&normals), black_box(&l), &mut out))
        });
        for name in ["vertex_gouraud", "vertex_angle", "bishop_weimer", "seiler"] {
            g.bench_with_input(BenchmarkId::new(name, s), &s, |b, &s| {
                b.iter(|| {
                    per_polygon(
                        s,
                        black_box(&normals),
                        black_box(&l),
                        &table,
                        name,
                        &mut out,
                    )
                })
            });
        }
        let kernels: [(&str, Kernel); 3] = [
            ("fast_fence", FastSpan::<f32>::gouraud),
            ("fast_corrected_euler", FastSpan::<f32>::corrected_euler),
            ("fast_phong", FastSpan::<f32>::phong),
        ];
        for (label, k) in kernels {
            g.bench_with_input(BenchmarkId::new(label, s), &s, |b, &s| {
                b.iter(|| per_span_fast(s, black_box(&normals), black_box(&l), k, &mut out))
            });
        }
        for (label, name) in [
            ("span_phong", "phong"),
            ("span_duff", "duff"),
            ("span_fence", "gouraud"),
            ("span_euler", "euler"),
            ("span_corrected_euler", "corrected-euler"),
            ("span_angular", "angular"),
            ("span_spherical", "spherical"),
            ("span_binary", "binary"),
            ("span_bishop_weimer", "bishop_weimer_span"),
        ] {
            g.bench_with_input(BenchmarkId::new(label, s), &s, |b, &s| {
                b.iter(|| per_span(s, black_box(&normals), black_box(&l), name, &mut out))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, related);
criterion_main!(benches);
