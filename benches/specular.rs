//! The paper's two open questions (§7.1) in time, per span, in `f32`, shininess 32:
//!
//! - **the skip test** (question a): Phong's exact test (`skip::Candidates::phong`, the
//!   span's inputs as rationals, then `skips`), the float form with its margins given
//!   (`skip::float::float_skips`, what a renderer runs per span), the margins'
//!   `ieee` bound itself (`skip::float::Margins::ieee`, the graph evaluation), and what a
//!   skip saves: the specular pass of corrected Euler on `N·H` with the power;
//! - **the squared method** (question b): `squared_corrected_euler` (root-free set-up,
//!   two additions, `g^{s/2}`) against corrected Euler on `N·H` then the power, and
//!   Duff then the power — each with its own set-up from the span's inputs; and on
//!   edge normals that are not unit (`_raw`, `_normalizing`: as interpolated along a
//!   polygon's edges), where corrected Euler must normalize them first.
//!
//! Spans of n = 8 (the paper's polygon size, where the set-up decides) and n = 512
//! (the inner loop). Then the fast kernels on each vector path this CPU has
//! (`phong_approx::simd`, forced in turn; ids `KERNEL/PATH`): `fast::FastSquared`'s
//! specular pass against `fast::FastSpan`'s corrected Euler then the power, on unit and
//! on non-unit edge normals. `cargo bench --bench specular`, then `python3
//! benches/summarize.py` for the table of `docs/performance.md`.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use phong_approx::fast::{FastSpan, FastSquared};
use phong_approx::simd::{self, Path};
use phong_approx::skip::float::{float_skips, FloatSpan, Margins};
use phong_approx::skip::Candidates;
use phong_approx::specular::power;
use phong_approx::squared_corrected_euler::SquaredSpan;
use phong_approx::{BigRational, Format, Method, Span, Vec3};
use std::time::Duration;

/// The shininess of every row.
const S: u32 = 32;

/// A torus-like span: edge normals 12° apart, the half vector 20° off the first.
fn inputs() -> ([f32; 3], [f32; 3], [f32; 3]) {
    let unit = |v: [f64; 3]| {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        v.map(|c| (c / l) as f32)
    };
    let deg = |d: f64| d.to_radians();
    (
        unit([0.0, 0.0, 1.0]),
        unit([deg(12.0).sin(), 0.0, deg(12.0).cos()]),
        unit([0.0, deg(20.0).sin(), deg(20.0).cos()]),
    )
}

fn v3(v: [f32; 3]) -> Vec3<f32> {
    Vec3::new(v[0], v[1], v[2])
}

/// Corrected Euler (or Duff) on `N·H` with its set-up, then `max(0, v)^S` per pixel.
fn method_then_power(m: Method, na: [f32; 3], nb: [f32; 3], h: [f32; 3], n: u32, out: &mut [f32]) {
    let span = Span::new(v3(na), v3(nb), v3(h), n).expect("unit inputs");
    m.shade(&span, out).expect("shades");
    for v in out.iter_mut() {
        *v = power(v, S);
    }
}

fn specular(c: &mut Criterion) {
    let (na, nb, h) = inputs();
    let mut g = c.benchmark_group("specular_span_f32");
    g.warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(900))
        .sample_size(30);
    for n in [8u32, 512] {
        g.throughput(Throughput::Elements(u64::from(n) + 1));
        let mut out = vec![0f32; n as usize + 1];
        for (name, m) in [
            ("corrected_euler_then_power", Method::CorrectedEuler),
            ("duff_then_power", Method::Duff),
        ] {
            g.bench_with_input(BenchmarkId::new(name, n), &n, |b, &n| {
                b.iter(|| {
                    method_then_power(m, black_box(na), black_box(nb), black_box(h), n, &mut out)
                })
            });
        }
        // As a scan converter hands them over: edge normals interpolated along the
        // polygon's edges, not unit. Corrected Euler normalizes them first (two roots,
        // two divisions); the squared method takes them as they are.
        let (ra, rb) = (na.map(|c| 0.9 * c), nb.map(|c| 1.1 * c));
        g.bench_with_input(
            BenchmarkId::new("corrected_euler_normalizing_then_power", n),
            &n,
            |b, &n| {
                b.iter(|| {
                    let unit = |v: [f32; 3]| {
                        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                        v.map(|c| c / l)
                    };
                    let (a, bb) = (unit(black_box(ra)), unit(black_box(rb)));
                    method_then_power(Method::CorrectedEuler, a, bb, black_box(h), n, &mut out)
                })
            },
        );
        g.bench_with_input(
            BenchmarkId::new("squared_corrected_euler_raw", n),
            &n,
            |b, &n| {
                b.iter(|| {
                    let s = SquaredSpan::new(
                        &v3(black_box(ra)),
                        &v3(black_box(rb)),
                        &v3(black_box(h)),
                        n,
                    )
                    .expect("non-zero normals");
                    s.specular(S, &mut out).expect("length")
                })
            },
        );
        g.bench_with_input(
            BenchmarkId::new("squared_corrected_euler", n),
            &n,
            |b, &n| {
                b.iter(|| {
                    let s = SquaredSpan::new(
                        &v3(black_box(na)),
                        &v3(black_box(nb)),
                        &v3(black_box(h)),
                        n,
                    )
                    .expect("non-zero normals");
                    s.specular(S, &mut out).expect("length")
                })
            },
        );
        let fs = FloatSpan {
            na: na.map(f64::from),
            nb: nb.map(f64::from),
            h: h.map(f64::from),
            n,
        };
        let q = |v: [f32; 3]| {
            Vec3::new(
                BigRational::from_float(v[0]).expect("finite"),
                BigRational::from_float(v[1]).expect("finite"),
                BigRational::from_float(v[2]).expect("finite"),
            )
        };
        let tol = BigRational::new(1.into(), (1u64 << 18).into());
        let exact = Span::with_tolerance(q(na), q(nb), q(h), n, &tol).expect("unit in f32");
        let margins = Margins::ieee(Method::Phong, &exact, Format::Binary32).expect("a bound");
        g.bench_with_input(BenchmarkId::new("skip_float", n), &n, |b, &n| {
            b.iter(|| {
                float_skips(
                    Method::Phong,
                    black_box(&FloatSpan { n, ..fs }),
                    1.0,
                    S,
                    margins,
                )
            })
        });
        g.bench_with_input(BenchmarkId::new("skip_margins_ieee", n), &n, |b, _| {
            b.iter(|| Margins::ieee(Method::Phong, black_box(&exact), Format::Binary32))
        });
        let one = BigRational::from_integer(1.into());
        g.bench_with_input(BenchmarkId::new("skip_exact", n), &n, |b, _| {
            b.iter(|| {
                let e = Span::with_tolerance(q(na), q(nb), q(h), n, &tol).expect("unit in f32");
                Candidates::phong(black_box(&e)).map(|c| c.skips(&one, S))
            })
        });
    }
    g.finish();
}

/// `max(0, v)^S` at every pixel on `path` (five squarings: `S = 32`), the loop
/// compiled for the path's vector width.
fn power_pass(path: Path, out: &mut [f32]) {
    debug_assert_eq!(
        path,
        simd::path(),
        "the path being measured is the forced one"
    );
    simd::dispatch(|_| {
        for v in out.iter_mut() {
            let mut x = v.max(0.0);
            for _ in 0..5 {
                x *= x;
            }
            *v = x;
        }
    })
}

/// Edge normals of unit length, divided by it.
fn normalized(v: [f32; 3]) -> [f32; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|c| c / l)
}

fn specular_paths(c: &mut Criterion) {
    assert_eq!(S, 32, "power_pass squares five times");
    let (na, nb, h) = inputs();
    let (ra, rb) = (na.map(|c| 0.9 * c), nb.map(|c| 1.1 * c));
    let mut g = c.benchmark_group("specular_paths_f32");
    g.warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(900))
        .sample_size(30);
    let chosen = simd::path();
    for path in Path::supported_paths() {
        simd::force(path).expect("a supported path");
        for n in [8u32, 512] {
            g.throughput(Throughput::Elements(u64::from(n) + 1));
            let mut out = vec![0f32; n as usize + 1];
            g.bench_with_input(
                BenchmarkId::new(format!("corrected_euler_fast_then_power/{path}"), n),
                &n,
                |b, &n| {
                    b.iter(|| {
                        let s = FastSpan::<f32>::new(black_box(na), black_box(nb), black_box(h), n);
                        s.corrected_euler(&mut out);
                        power_pass(path, &mut out);
                    })
                },
            );
            g.bench_with_input(
                BenchmarkId::new(
                    format!("corrected_euler_fast_normalizing_then_power/{path}"),
                    n,
                ),
                &n,
                |b, &n| {
                    b.iter(|| {
                        let (a, bb) = (normalized(black_box(ra)), normalized(black_box(rb)));
                        let s = FastSpan::<f32>::new(a, bb, black_box(h), n);
                        s.corrected_euler(&mut out);
                        power_pass(path, &mut out);
                    })
                },
            );
            for (name, a, bb) in [("squared_fast", na, nb), ("squared_fast_raw", ra, rb)] {
                g.bench_with_input(
                    BenchmarkId::new(format!("{name}/{path}"), n),
                    &n,
                    |b, &n| {
                        b.iter(|| {
                            let s = FastSquared::<f32>::new(
                                black_box(a),
                                black_box(bb),
                                black_box(h),
                                n,
                            );
                            s.specular(S, &mut out);
                        })
                    },
                );
            }
            g.bench_with_input(
                BenchmarkId::new(format!("squared_fast_set_up/{path}"), n),
                &n,
                |b, &n| {
                    b.iter(|| {
                        FastSquared::<f32>::new(black_box(ra), black_box(rb), black_box(h), n)
                    })
                },
            );
            g.bench_with_input(
                BenchmarkId::new(format!("corrected_euler_fast_set_up/{path}"), n),
                &n,
                |b, &n| {
                    b.iter(|| FastSpan::<f32>::new(black_box(na), black_box(nb), black_box(h), n))
                },
            );
        }
    }
    simd::force(chosen).expect("the path chosen before");
    g.finish();
}

criterion_group!(benches, specular, specular_paths);
criterion_main!(benches);
