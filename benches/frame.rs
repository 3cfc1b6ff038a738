//! The frame benchmark: the 800-polygon torus at the default size (225×225), shaded
//! by one method at a time with the fast kernels, in visible pixels per second —
//! single-threaded (one frame) and with rayon (eight frames in parallel). Two rows
//! profile the frame: `profile_scan_depth` (no set-up, no kernel: culling, scan
//! conversion, the depth test and quantization) and `profile_setup` (the rows' edge
//! normals normalized and `FastSpan::new`, no kernel). Two rows time a specular pass
//! (the paper's §7.1, question a): corrected Euler's fast kernel on `N·H` then the power
//! 32 on every row (`specular_corrected_euler`), and the same where the float skip test
//! (`skip::float::float_skips`, margins from corrected Euler's `ieee` bound at the
//! frame's longest row) does not skip the row first (`specular_corrected_euler_skip`).
//! One more (question b): the squared method's fast kernel on the rows' edge normals as
//! interpolated, not normalized, `g^{s/2}` with no root (`specular_squared`).

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use phong_approx::fast::{phong_rsqrt_f32, FastSpan, FastSquared};
use phong_approx::profile::Profile;
use phong_approx::quantize::level;
use phong_approx::raster::frame::{draw, polygons, Polygon, Shading, Split};
use phong_approx::raster::mesh::Mesh;
use phong_approx::raster::scan::Row;
use phong_approx::skip::float::{float_skips, FloatSpan, Margins};
use phong_approx::specular::power;
use phong_approx::studies::experiment::Experiment;
use phong_approx::studies::render::Scene;
use phong_approx::tolerance::profile::profile_bound;
use phong_approx::{Format, Method};
use rayon::prelude::*;
use std::time::Duration;

type Kernel = fn(&FastSpan<f32>, &mut [f32]);

/// What a row does: nothing, the set-up alone, or the set-up and a kernel; or the
/// specular pass on `H`, with or without the skip test first.
#[derive(Clone, Copy)]
enum Mode {
    ScanDepth,
    Setup,
    Kernel(Kernel),
    Specular { skip: bool },
    SquaredSpecular,
}

/// The specular exponent of the specular rows.
const SHININESS: u32 = 32;

/// Frame `f` with `kernel` through the crate's frame loop
/// (`phong_approx::raster::frame`): culling, scan conversion, per-row set-up, the
/// kernel, 8-bit quantization and the depth test. Returns the visible pixel count.
fn frame(mesh: &Mesh, scene: &Scene, f: u32, mode: Mode) -> u64 {
    struct Fast {
        mode: Mode,
        l: [f32; 3],
        h: [f32; 3],
        margins: Margins,
        /// The current row's values (one buffer for the frame, as a renderer keeps).
        span: Vec<f32>,
        image: Vec<Option<u8>>,
    }
    impl Shading for Fast {
        type Row = ();
        fn row(&mut self, _: usize, _: &Polygon, row: &Row) -> Option<()> {
            let n = (row.x_last - row.x_first) as u32;
            let kernel = match self.mode {
                Mode::ScanDepth => return Some(()),
                Mode::Setup => None,
                Mode::Kernel(k) => Some(k),
                Mode::Specular { skip } => {
                    specular_row(row, n, self.h, skip.then_some(self.margins), &mut self.span);
                    return Some(());
                }
                Mode::SquaredSpecular => {
                    squared_row(row, n, self.h, &mut self.span);
                    return Some(());
                }
            };
            let na = row.left.normal.normalize().to_array();
            let nb = row.right.normal.normalize().to_array();
            let span = &mut self.span[..n as usize + 1];
            if n == 0 {
                let l = self.l;
                span[0] = na[0] * l[0] + na[1] * l[1] + na[2] * l[2];
            } else {
                let fs = FastSpan::<f32>::new(na, nb, self.l, n);
                match kernel {
                    Some(k) => k(&fs, span),
                    None => {
                        black_box(&fs);
                    }
                }
            }
            Some(())
        }
        fn store(&mut self, _: &(), i: usize, pixel: usize) {
            self.image[pixel] = Some(level(&self.span[i]));
        }
    }
    let (w, h) = (scene.width, scene.height);
    let mut s = Fast {
        mode,
        l: scene.light.to_array(),
        h: scene.half().to_array(),
        // One allowance for every row: corrected Euler's ieee bound at the longest row
        // (the bound grows with n; the normals are unit, q = 1 at the edges).
        margins: Margins {
            allowance: profile_bound(
                Method::CorrectedEuler,
                Profile::Ieee,
                scene.width,
                1.0,
                Format::Binary32,
            )
            .expect("a bound"),
            u: Format::Binary32.u(),
        },
        span: vec![0f32; scene.width as usize + 1],
        image: vec![None; (w * h) as usize],
    };
    draw(w, h, &polygons(mesh, scene, f, Split::Quads), &mut s);
    black_box(&s.image);
    s.image.iter().flatten().count() as u64
}

/// One row's specular pass: corrected Euler's fast kernel on `N·H`, then
/// `max(0, v)^SHININESS`; first, with `margins`, the float skip test, which fills the
/// row with 0 where it skips.
fn specular_row(row: &Row, n: u32, h: [f32; 3], margins: Option<Margins>, out: &mut [f32]) {
    let out = &mut out[..n as usize + 1];
    let na = row.left.normal.normalize().to_array();
    let nb = row.right.normal.normalize().to_array();
    if n == 0 {
        out[0] = power(&(na[0] * h[0] + na[1] * h[1] + na[2] * h[2]), SHININESS);
        return;
    }
    if let Some(m) = margins {
        let fs = FloatSpan {
            na: na.map(f64::from),
            nb: nb.map(f64::from),
            h: h.map(f64::from),
            n,
        };
        if float_skips(Method::CorrectedEuler, &fs, 1.0, SHININESS, m) == Ok(true) {
            out.fill(0.0);
            return;
        }
    }
    FastSpan::<f32>::new(na, nb, h, n).corrected_euler(out);
    for v in out.iter_mut() {
        *v = power(v, SHININESS);
    }
}

/// One row's specular pass by the squared method's fast kernel, on the edge normals
/// as the scan conversion interpolates them (no normalization, no root for `s = 32`).
fn squared_row(row: &Row, n: u32, h: [f32; 3], out: &mut [f32]) {
    let out = &mut out[..n as usize + 1];
    let (na, nb) = (row.left.normal.to_array(), row.right.normal.to_array());
    if n == 0 {
        let p = na[0] * h[0] + na[1] * h[1] + na[2] * h[2];
        let g = p * p / (na[0] * na[0] + na[1] * na[1] + na[2] * na[2]);
        out[0] = if p > 0.0 {
            power(&g, SHININESS / 2)
        } else {
            0.0
        };
        return;
    }
    FastSquared::<f32>::new(na, nb, h, n).specular(SHININESS, out);
}

fn frames(c: &mut Criterion) {
    let exp = Experiment::default();
    let scene = exp.scene();
    let mesh = exp.mesh(40, 20);
    let kernels: [(&str, Mode); 12] = [
        ("profile_scan_depth", Mode::ScanDepth),
        ("profile_setup", Mode::Setup),
        ("gouraud_fast", Mode::Kernel(FastSpan::<f32>::gouraud)),
        (
            "corrected_euler_serial",
            Mode::Kernel(FastSpan::<f32>::corrected_euler_serial),
        ),
        (
            "corrected_euler_fast",
            Mode::Kernel(FastSpan::<f32>::corrected_euler),
        ),
        ("duff_serial", Mode::Kernel(FastSpan::<f32>::duff_serial)),
        ("phong_fast", Mode::Kernel(FastSpan::<f32>::phong)),
        ("phong_rsqrt_simd", Mode::Kernel(phong_rsqrt_f32)),
        (
            "symmetric_phong_fast",
            Mode::Kernel(FastSpan::<f32>::symmetric_phong),
        ),
        ("specular_corrected_euler", Mode::Specular { skip: false }),
        (
            "specular_corrected_euler_skip",
            Mode::Specular { skip: true },
        ),
        ("specular_squared", Mode::SquaredSpecular),
    ];
    let mut g = c.benchmark_group("frame_torus800_225");
    g.warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(20);
    let px_one = frame(&mesh, &scene, 17, kernels[0].1);
    let px_eight: u64 = (0..8)
        .map(|f| frame(&mesh, &scene, 17 + f, kernels[0].1))
        .sum();
    for (name, k) in kernels {
        g.throughput(Throughput::Elements(px_one));
        g.bench_function(BenchmarkId::new("single", name), |b| {
            b.iter(|| frame(&mesh, &scene, 17, k))
        });
        g.throughput(Throughput::Elements(px_eight));
        g.bench_function(BenchmarkId::new("rayon8", name), |b| {
            b.iter(|| {
                (0..8u32)
                    .into_par_iter()
                    .map(|f| frame(&mesh, &scene, 17 + f, k))
                    .sum::<u64>()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, frames);
criterion_main!(benches);
