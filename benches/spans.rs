//! Span kernels: every method, serial (the paper's recurrences) and fast (closed
//! forms), `f32` and `f64`, n ∈ {8, 32, 128, 512}, one span per call with its set-up,
//! next to the peers measured in the same run: the store floor (filling the slice
//! with a constant), glam per-pixel Phong (what most users write), and the generic
//! reference path (`Span::new` + `Method::shade`).
//!
//! `cargo bench --bench spans`, then `python3 benches/summarize.py` for the tables of
//! `docs/performance.md` (ns per pixel and ratios).

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use phong_approx::fast::{phong_rsqrt_f32, FastSpan};
use phong_approx::{Method, Span, Vec3};
use std::time::Duration;

const NS: [u32; 4] = [8, 32, 128, 512];

/// A torus-like span: unit normals 12° apart, light in front.
fn inputs() -> ([f64; 3], [f64; 3], [f64; 3]) {
    let (a, b) = (0.35f64, 0.35f64 + 12f64.to_radians());
    let na = [a.sin(), 0.1, a.cos()];
    let nb = [b.sin(), -0.05, b.cos()];
    let l = [-0.4, 0.4, 0.8];
    let unit = |v: [f64; 3]| {
        let r = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] / r, v[1] / r, v[2] / r]
    };
    (unit(na), unit(nb), unit(l))
}

macro_rules! bench_type {
    ($fn_name:ident, $f:ident, $glam:ident) => {
        fn $fn_name(c: &mut Criterion) {
            let (na, nb, l) = inputs();
            let cv = |v: [f64; 3]| [v[0] as $f, v[1] as $f, v[2] as $f];
            let (na, nb, l) = (cv(na), cv(nb), cv(l));
            let mut g = c.benchmark_group(concat!("span_", stringify!($f)));
            g.warm_up_time(Duration::from_millis(300))
                .measurement_time(Duration::from_millis(900))
                .sample_size(30);
            for n in NS {
                g.throughput(Throughput::Elements(u64::from(n) + 1));
                let mut out = vec![0 as $f; n as usize + 1];
                g.bench_with_input(BenchmarkId::new("store_floor", n), &n, |b, _| {
                    b.iter(|| out.fill(black_box(0.5)))
                });
                g.bench_with_input(BenchmarkId::new("glam_phong", n), &n, |b, &n| {
                    b.iter(|| {
                        let (na, nb, l) = (
                            glam::$glam::from(black_box(na)),
                            glam::$glam::from(nb),
                            glam::$glam::from(l),
                        );
                        let inv = 1.0 / n as $f;
                        for (i, o) in out.iter_mut().enumerate() {
                            *o = na.lerp(nb, i as $f * inv).normalize().dot(l);
                        }
                    })
                });
                type K = fn(&FastSpan<$f>, &mut [$f]);
                let kernels: [(&str, K); 11] = [
                    ("adaptive_fast", |s, o| {
                        s.adaptive(1.0, o);
                    }),
                    ("angular_fast", FastSpan::<$f>::angular),
                    ("gouraud_serial", FastSpan::<$f>::gouraud_serial),
                    ("gouraud_fast", FastSpan::<$f>::gouraud),
                    ("euler_fast", FastSpan::<$f>::euler),
                    (
                        "corrected_euler_serial",
                        FastSpan::<$f>::corrected_euler_serial,
                    ),
                    ("corrected_euler_fast", FastSpan::<$f>::corrected_euler),
                    ("duff_serial", FastSpan::<$f>::duff_serial),
                    ("phong_fast", FastSpan::<$f>::phong),
                    ("symmetric_phong_fast", FastSpan::<$f>::symmetric_phong),
                    ("setup_only", |_, _| {}),
                ];
                for (name, k) in kernels {
                    g.bench_with_input(BenchmarkId::new(name, n), &n, |b, &n| {
                        b.iter(|| {
                            let s =
                                FastSpan::<$f>::new(black_box(na), black_box(nb), black_box(l), n);
                            k(&s, &mut out);
                            black_box(&s);
                        })
                    });
                }
                bench_extra_!($f, g, n, na, nb, l, out);
                // Every method of the catalogue through the checked generic path.
                for m in Method::ALL {
                    let name = format!("reference_{}", m.name());
                    g.bench_with_input(BenchmarkId::new(name, n), &n, |b, &n| {
                        b.iter(|| {
                            let v = |x: [$f; 3]| Vec3::new(x[0], x[1], x[2]);
                            let s = Span::new(v(black_box(na)), v(nb), v(l), n).unwrap();
                            m.shade(&s, &mut out).unwrap();
                        })
                    });
                }
            }
            g.finish();
        }
    };
}

macro_rules! bench_extra_ {
    (f32, $g:ident, $n:ident, $na:ident, $nb:ident, $l:ident, $out:ident) => {
        $g.bench_with_input(BenchmarkId::new("phong_rsqrt_simd", $n), &$n, |b, &n| {
            b.iter(|| {
                let s = FastSpan::<f32>::new(black_box($na), black_box($nb), black_box($l), n);
                phong_rsqrt_f32(&s, &mut $out);
            })
        });
        let table: Vec<f32> = phong_approx::angular::CosTable::<f32>::new(256)
            .unwrap()
            .values;
        $g.bench_with_input(
            BenchmarkId::new("angular_table256_fast", $n),
            &$n,
            |b, &n| {
                b.iter(|| {
                    let s = FastSpan::<f32>::new(black_box($na), black_box($nb), black_box($l), n);
                    s.angular_table(&table, &mut $out);
                })
            },
        );
        $g.bench_with_input(
            BenchmarkId::new("corrected_euler_wide", $n),
            &$n,
            |b, &n| {
                b.iter(|| {
                    let s = FastSpan::<f32>::new(black_box($na), black_box($nb), black_box($l), n);
                    corrected_euler_wide(&s, &mut $out);
                })
            },
        );
        $g.bench_with_input(BenchmarkId::new("phong_wide", $n), &$n, |b, &n| {
            b.iter(|| {
                let s = FastSpan::<f32>::new(black_box($na), black_box($nb), black_box($l), n);
                phong_wide(&s, &mut $out);
            })
        });
    };
    (f64, $g:ident, $n:ident, $na:ident, $nb:ident, $l:ident, $out:ident) => {};
}

/// Corrected Euler's closed form with the portable SIMD crate `wide` (8 lanes), to
/// compare with the auto-vectorized `FastSpan::corrected_euler`.
fn corrected_euler_wide(s: &FastSpan<f32>, out: &mut [f32]) {
    use wide::f32x8;
    let out = &mut out[..=s.n as usize];
    let (p0, t, h) = (
        f32x8::splat(s.b),
        f32x8::splat(s.t0),
        f32x8::splat(0.5 * s.ds),
    );
    let mut x = f32x8::from([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
    let one = f32x8::splat(1.0);
    let eight = f32x8::splat(8.0);
    let mut chunks = out.chunks_exact_mut(8);
    for ch in &mut chunks {
        let v = p0 + x * (t + (x - one) * h);
        ch.copy_from_slice(&v.to_array());
        x += eight;
    }
    let base = x.to_array()[0];
    for (j, o) in chunks.into_remainder().iter_mut().enumerate() {
        let xf = base + j as f32;
        *o = s.b + xf * (s.t0 + (xf - 1.0) * 0.5 * s.ds);
    }
}

/// Phong's closed form with `wide` (sqrt and division, 8 lanes).
fn phong_wide(s: &FastSpan<f32>, out: &mut [f32]) {
    use wide::f32x8;
    let out = &mut out[..=s.n as usize];
    let (a, b, c, d, e) = (
        f32x8::splat(s.a),
        f32x8::splat(s.b),
        f32x8::splat(s.c),
        f32x8::splat(s.d),
        f32x8::splat(s.e),
    );
    let mut x = f32x8::from([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
    let eight = f32x8::splat(8.0);
    let mut chunks = out.chunks_exact_mut(8);
    for ch in &mut chunks {
        let v = (a * x + b) / ((c * x + d) * x + e).sqrt();
        ch.copy_from_slice(&v.to_array());
        x += eight;
    }
    let base = x.to_array()[0];
    for (j, o) in chunks.into_remainder().iter_mut().enumerate() {
        let xf = base + j as f32;
        *o = (s.a * xf + s.b) / ((s.c * xf + s.d) * xf + s.e).sqrt();
    }
}

bench_type!(span_f32, f32, Vec3);
bench_type!(span_f64, f64, DVec3);

/// The per-span set-up alone at n = 8: the fast set-up (one reciprocal) and the
/// checked reference `Span::new`.
fn setup(c: &mut Criterion) {
    let (na, nb, l) = inputs();
    let cv = |v: [f64; 3]| [v[0] as f32, v[1] as f32, v[2] as f32];
    let (na, nb, l) = (cv(na), cv(nb), cv(l));
    let mut g = c.benchmark_group("setup_f32_n8");
    g.warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(900))
        .sample_size(30);
    g.bench_function("fast", |b| {
        b.iter(|| FastSpan::<f32>::new(black_box(na), black_box(nb), black_box(l), 8))
    });
    g.bench_function("reference", |b| {
        b.iter(|| {
            let v = |x: [f32; 3]| Vec3::new(x[0], x[1], x[2]);
            Span::new(v(black_box(na)), v(nb), v(l), 8).unwrap()
        })
    });
    g.finish();
}

criterion_group!(benches, span_f32, span_f64, setup);
criterion_main!(benches);
