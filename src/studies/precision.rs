//! Low precision: every method in `f64`, `f32`, binary16 and fixed point
//! ([`crate::lowp`]), on the torus harness and on long spans.
//!
//! - [`torus`]: the diffuse value of every shader of [`COLUMNS`] over the
//!   800-polygon torus, set up and stepped entirely in the precision under test (pixel
//!   coordinates are taken relative to each triangle's centroid in `f64` first, as an
//!   integer rasterizer would), against per-pixel Phong in `f64` and against the same
//!   method in `f64`.
//! - [`span_errors`] and [`longest`]: per span method, the longest span before the recurrence's
//!   accumulated error exceeds one 8-bit level: the set-up computed in `f64` and
//!   rounded to the precision ([`Span::cast`]), the steps in the precision.

use super::compare::{
    runs_in, shade_row, triangle_inputs, RowAt, RowKernels, Shader, TriangleSetup, COLUMNS,
};
use super::render::{Deviation, Scene};
use crate::lowp::{f16, I16F16, I8F8};
use crate::method::Prepared;
use crate::quantize::level;
use crate::raster::frame::{polygons, Split};
use crate::raster::mesh::Mesh;
use crate::raster::scan::rows;
use crate::scalar::Real;
use crate::{Arithmetic, Format, Method, Span, Vec3};

/// A number type of the precision study: its [`Arithmetic`] (which names it in the
/// tables) and the study's runs in its Rust type, so that the type is a row's data
/// rather than a `match` on the arithmetic.
#[derive(Clone, Copy)]
pub struct Precision {
    /// The arithmetic.
    pub arithmetic: Arithmetic,
    /// [`torus`] in this type.
    torus: fn(&Mesh, &Scene, u32, &(dyn Fn() + Sync)) -> PrecisionStats,
    /// [`span_errors`] in this type.
    span_errors: SpanErrors,
}

/// [`span_errors`] in one type.
type SpanErrors = fn(Method, &[(Vec3<f64>, Vec3<f64>, Vec3<f64>)]) -> Vec<Option<f64>>;

impl Precision {
    /// The row of `T`, computing in `arithmetic`.
    const fn of<T: RowKernels>(arithmetic: Arithmetic) -> Precision {
        Precision {
            arithmetic,
            torus: torus_in::<T>,
            span_errors: span_errors::<T>,
        }
    }
}

impl std::fmt::Debug for Precision {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Precision({})", self.arithmetic)
    }
}

/// Its name in the tables (`f64`, `f32`, `f16`, `I16F16`, `I8F8`): its arithmetic's.
impl std::fmt::Display for Precision {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.arithmetic)
    }
}

/// The precisions of the tables, widest first: binary64, binary32, binary16
/// ([`crate::lowp::f16`]), 16.16 and 8.8 fixed point ([`crate::lowp::I16F16`],
/// [`crate::lowp::I8F8`]).
pub const PRECISIONS: [Precision; 5] = [
    Precision::of::<f64>(Arithmetic::F64),
    Precision::of::<f32>(Arithmetic::F32),
    Precision::of::<f16>(Arithmetic::Float(Format::Binary16)),
    Precision::of::<I16F16>(Arithmetic::Fixed {
        int_bits: 16,
        frac_bits: 16,
    }),
    Precision::of::<I8F8>(Arithmetic::Fixed {
        int_bits: 8,
        frac_bits: 8,
    }),
];

/// Per shader, in one precision.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PrecisionStats {
    /// Per shader of [`COLUMNS`]: levels against per-pixel Phong in `f64`.
    pub vs_phong: Vec<Deviation>,
    /// Per shader: levels against the same shader in `f64` (the arithmetic's own
    /// error).
    pub vs_f64: Vec<Deviation>,
    /// Per shader: rows the precision could not shade (a set-up that fails, a
    /// non-finite value); the `f64` run shades them all.
    pub failed_rows: Vec<u64>,
    /// Rows shaded in `f64`.
    pub rows: u64,
}

impl PrecisionStats {
    fn empty() -> Self {
        let c = COLUMNS.len();
        PrecisionStats {
            vs_phong: vec![Deviation::default(); c],
            vs_f64: vec![Deviation::default(); c],
            failed_rows: vec![0; c],
            rows: 0,
        }
    }

    /// Adds `o` into `self`.
    pub fn merge(&mut self, o: &PrecisionStats) {
        if self.vs_phong.is_empty() {
            *self = PrecisionStats::empty();
        }
        for (a, b) in self.vs_phong.iter_mut().zip(&o.vs_phong) {
            a.merge(b);
        }
        for (a, b) in self.vs_f64.iter_mut().zip(&o.vs_f64) {
            a.merge(b);
        }
        for (a, b) in self.failed_rows.iter_mut().zip(&o.failed_rows) {
            *a += b;
        }
        self.rows += o.rows;
    }
}

/// Every drawn row of front-facing triangles of frame `f` (no depth test: every
/// span counts), each shader in `T` against `f64`.
pub fn frame<T: RowKernels>(mesh: &Mesh, scene: &Scene, f: u32) -> PrecisionStats {
    let dirs = [scene.light];
    let table_t = Prepared::new(Method::AngularTable(crate::method::SOURCE_TABLE), T::one())
        .expect("256 entries");
    let table64 = Prepared::new(Method::AngularTable(crate::method::SOURCE_TABLE), 1.0f64)
        .expect("256 entries");
    let cols = COLUMNS.len();
    // The shaders with a kernel in `T` (the row set-ups of `fast_rows` are `f32` and
    // `f64` kernels); the others' cells stay empty.
    let here: Vec<Shader> = COLUMNS.iter().copied().filter(runs_in::<T>).collect();
    // The f64 run of every shader that has one (the `rsqrt` kernels are `f32` only:
    // their cells against the same method in f64 stay empty).
    let in64: Vec<Shader> = COLUMNS.iter().copied().filter(runs_in::<f64>).collect();
    let mut st = PrecisionStats::empty();
    let mut out_t: Vec<Vec<T>> = vec![Vec::new(); cols];
    let mut out64: Vec<Vec<f64>> = vec![Vec::new(); cols];
    let mut one: Vec<Vec<T>> = vec![Vec::new(); cols];
    for poly in polygons(mesh, scene, f, Split::Triangles) {
        let ((xc, yc), rel, normals) = triangle_inputs(&poly);
        let Some(s64) = TriangleSetup::<f64>::new(rel, normals, &dirs) else {
            continue;
        };
        let st_t = TriangleSetup::<T>::new(rel, normals, &dirs);
        rows(&poly.v, scene.width, scene.height, |row| {
            let n = (row.x_last - row.x_first) as u32;
            let x0 = f64::from(row.x_first) + 0.5 - xc;
            let y = f64::from(row.y) + 0.5 - yc;
            if shade_row(&s64, RowAt { d: 0, x0, y, n }, &table64, &in64, &mut out64).is_none() {
                return;
            }
            st.rows += 1;
            let reference: Vec<u8> = out64[0].iter().map(level).collect();
            // All shaders at once; if that fails, each alone, to count per shader.
            let all_ok = st_t
                .as_ref()
                .and_then(|s| shade_row(s, RowAt { d: 0, x0, y, n }, &table_t, &here, &mut out_t))
                .is_some();
            for &sh in &here {
                let c = super::compare::index(sh);
                let values: &[T] = if all_ok {
                    &out_t[c]
                } else {
                    let ok = st_t
                        .as_ref()
                        .and_then(|s| {
                            shade_row(s, RowAt { d: 0, x0, y, n }, &table_t, &[sh], &mut one)
                        })
                        .is_some();
                    if !ok {
                        st.failed_rows[c] += 1;
                        continue;
                    }
                    &one[c]
                };
                let has64 = runs_in::<f64>(&sh);
                for (j, val) in values.iter().enumerate() {
                    // The level of the value the precision holds, taken exactly (a
                    // quantizer in 8.8 cannot even form 255·v).
                    let l = level(&val.to_f64());
                    st.vs_phong[c].add(l, reference[j]);
                    if has64 {
                        st.vs_f64[c].add(l, level(&out64[c][j]));
                    }
                }
            }
        });
    }
    st
}

/// [`frame`] over frames `0..frames` in `precision`, frames in parallel.
pub fn torus(
    mesh: &Mesh,
    scene: &Scene,
    frames: u32,
    precision: &Precision,
    tick: &(dyn Fn() + Sync),
) -> PrecisionStats {
    (precision.torus)(mesh, scene, frames, tick)
}

/// [`torus`] in `T`.
fn torus_in<T: RowKernels>(
    mesh: &Mesh,
    scene: &Scene,
    frames: u32,
    tick: &(dyn Fn() + Sync),
) -> PrecisionStats {
    use rayon::prelude::*;
    (0..frames)
        .into_par_iter()
        .map(|f| {
            let s = frame::<T>(mesh, scene, f);
            tick();
            s
        })
        .reduce(PrecisionStats::default, |mut a, b| {
            a.merge(&b);
            a
        })
}

/// The span lengths tried by [`span_errors`] and [`longest`].
pub const SPAN_LENGTHS: [u32; 13] = [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096];

/// Shades `span` with `m` and the prepared parameters; `None` if the method refuses
/// the span or a value is not finite.
pub fn shade_span<T: Real>(
    m: Method,
    span: &Span<T>,
    prep: &Prepared<T>,
    out: &mut [T],
) -> Option<()> {
    m.run(span, prep, out).ok()?;
    out.iter().all(|v| v.is_finite()).then_some(())
}

/// The test spans of [`span_errors`] and [`longest`]: `count` unit normal pairs 5° to 45° apart,
/// lights within 60° of `N_a`, from a fixed generator (reproducible).
pub fn test_directions(count: usize) -> Vec<(Vec3<f64>, Vec3<f64>, Vec3<f64>)> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let g = |a: f64, b: f64| glam::DVec3::new(a.sin() * b.cos(), a.sin() * b.sin(), a.cos());
        let na = g(next() * 1.2, next() * std::f64::consts::TAU);
        let axis = na.any_orthonormal_vector();
        let axis = glam::DQuat::from_axis_angle(na, next() * std::f64::consts::TAU) * axis;
        let angle = (5.0 + 40.0 * next()).to_radians();
        let nb = glam::DQuat::from_axis_angle(axis, angle) * na;
        let l_axis = glam::DQuat::from_axis_angle(na, next() * std::f64::consts::TAU)
            * na.any_orthonormal_vector();
        let l = glam::DQuat::from_axis_angle(l_axis, next() * 60f64.to_radians()) * na;
        out.push((
            Vec3::from(na),
            Vec3::from(nb.normalize()),
            Vec3::from(l.normalize()),
        ));
    }
    out
}

/// For method `m` in `T`: the largest error (in units of one 8-bit level, 1/255)
/// against the same shader in `f64`, per entry of [`SPAN_LENGTHS`], over
/// `directions`; `None` where the precision could not shade some span.
pub fn span_errors<T: Real>(
    m: Method,
    directions: &[(Vec3<f64>, Vec3<f64>, Vec3<f64>)],
) -> Vec<Option<f64>> {
    let table_t = Prepared::new(Method::AngularTable(crate::method::SOURCE_TABLE), T::one())
        .expect("256 entries");
    let table64 = Prepared::new(Method::AngularTable(crate::method::SOURCE_TABLE), 1.0f64)
        .expect("256 entries");
    SPAN_LENGTHS
        .iter()
        .map(|&n| {
            let mut worst = 0.0f64;
            for (na, nb, l) in directions {
                let s64 = Span::<f64>::normalized(na.clone(), nb.clone(), l.clone(), n).ok()?;
                let st: Span<T> = s64.cast()?;
                let mut a = vec![0.0f64; s64.len()];
                let mut b = vec![T::zero(); s64.len()];
                shade_span(m, &s64, &table64, &mut a)?;
                shade_span(m, &st, &table_t, &mut b)?;
                for (x, y) in a.iter().zip(&b) {
                    worst = worst.max((x - y.to_f64()).abs() * 255.0);
                }
            }
            Some(worst)
        })
        .collect()
}

/// The longest entry of [`SPAN_LENGTHS`] up to which every error is at most one level
/// (`None` if even `n = 1` fails), from [`span_errors`]'s output.
pub fn longest(errors: &[Option<f64>]) -> Option<u32> {
    let mut best = None;
    for (n, e) in SPAN_LENGTHS.iter().zip(errors) {
        match e {
            Some(e) if *e <= 1.0 => best = Some(*n),
            _ => break,
        }
    }
    best
}

/// [`span_errors`] in `precision`.
pub fn span_errors_in(
    m: Method,
    precision: &Precision,
    directions: &[(Vec3<f64>, Vec3<f64>, Vec3<f64>)],
) -> Vec<Option<f64>> {
    (precision.span_errors)(m, directions)
}
