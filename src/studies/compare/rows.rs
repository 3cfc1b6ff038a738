//! One triangle set up for the comparison and its rows shaded by every column's
//! method, in any scalar type: the row kernels per type (sealed), the triangle's
//! set-up per direction, `shade_row`.

use super::*;

/// One triangle set up for one direction (`L` or `H`).
pub struct Direction<T> {
    dir: Vec3<T>,
    pub(super) vertex: [T; 3],
    gouraud: Affine<T>,
    angle: Affine<T>,
    taylor: Taylor<T>,
    seiler: Quadratic<T>,
}

/// One triangle set up in `T`.
pub(crate) struct TriangleSetup<T> {
    pub(super) lambda: [Affine<T>; 3],
    field: (Vec3<T>, Vec3<T>, Vec3<T>),
    pub(super) dirs: Vec<Direction<T>>,
    /// The row set-ups' fields of [`crate::fast_rows`], one per direction (empty
    /// when `T` has no `fast_rows` kernels: [`RowKernels`]).
    rows: Vec<RowsDir<T>>,
}

/// One direction's field, and the stepper's last row: its centroid-relative `(x0, y)`
/// and its state (the same row asked again gets the same state; the next row down
/// is stepped to; any other row restarts from the field).
pub struct RowsDir<F> {
    field: Field<F>,
    stepper: Cell<Option<(f64, f64, EdgeStepper<F>)>>,
}

/// The `rsqrt` row kernels, `f32` only.
fn rsqrt_f32(f: &Field<f32>, r: RowSetup, x: f32, y: f32, n: u32, o: &mut [f32]) -> Option<()> {
    if r == RowSetup::FieldPhongRsqrt {
        crate::fast_rows::phong_field_rsqrt(&f.start(x, y), f, n, o);
    } else {
        f.row(x, y, n).phong_rsqrt(o);
    }
    Some(())
}

/// `f64` has no `rsqrt` row kernel.
fn rsqrt_f64(_: &Field<f64>, _: RowSetup, _: f64, _: f64, _: u32, _: &mut [f64]) -> Option<()> {
    None
}

/// The number types the torus harness shades in: [`Real`] types, with the row
/// set-ups of [`crate::fast_rows`] where the type has them (`f32`, `f64`). Sealed:
/// implemented for `f32`, `f64`, the low-precision types of [`crate::lowp`] and
/// [`crate::BigRational`].
pub trait RowKernels: sealed::Rows {}

/// Whether `sh` runs in `T` (one of [`crate::studies::precision::PRECISIONS`] or exact
/// rationals): every shader but the row set-ups, which are kernels in `f32` (every
/// one) and `f64` (all but the `rsqrt` ones).
pub fn runs_in<T: RowKernels>(sh: &super::Shader) -> bool {
    match sh {
        super::Shader::Rows(r) => T::has_rows(*r),
        _ => true,
    }
}

impl<T: sealed::Rows> RowKernels for T {}

mod sealed {
    use super::{Direction, RowSetup, RowsDir};
    use crate::scalar::Real;
    use crate::Vec3;

    /// What [`super::RowKernels`] provides; the defaults are "no row kernels".
    pub trait Rows: Real + 'static {
        /// The row set-ups' field of `field` lit by each of `dirs`, with its stepper.
        fn rows_of(
            _field: &(Vec3<Self>, Vec3<Self>, Vec3<Self>),
            _dirs: &[Direction<Self>],
        ) -> Vec<RowsDir<Self>> {
            Vec::new()
        }

        /// Whether the type has a kernel for the row set-up `r`.
        fn has_rows(_r: RowSetup) -> bool {
            false
        }

        /// Shades a row with `r` for one direction's field into `o`; `None` where
        /// the type or the set-up has no kernel.
        fn shade_rows(
            _d: &RowsDir<Self>,
            _r: RowSetup,
            _x0: f64,
            _y: f64,
            _n: u32,
            _o: &mut [Self],
        ) -> Option<()> {
            None
        }
    }
}

macro_rules! row_kernels {
    ($f:ident, $rsqrt:ident, $has_rsqrt:expr) => {
        impl sealed::Rows for $f {
            fn has_rows(r: RowSetup) -> bool {
                $has_rsqrt || !matches!(r, RowSetup::BatchedPhongRsqrt | RowSetup::FieldPhongRsqrt)
            }

            fn rows_of(
                field: &(Vec3<$f>, Vec3<$f>, Vec3<$f>),
                dirs: &[Direction<$f>],
            ) -> Vec<RowsDir<$f>> {
                let a = |v: &Vec3<$f>| [v.x, v.y, v.z];
                dirs.iter()
                    .map(|d| RowsDir {
                        field: Field::<$f>::new(a(&field.0), a(&field.1), a(&field.2), a(&d.dir)),
                        stepper: Cell::new(None),
                    })
                    .collect()
            }

            fn shade_rows(
                d: &RowsDir<$f>,
                r: RowSetup,
                x0: f64,
                y: f64,
                n: u32,
                o: &mut [$f],
            ) -> Option<()> {
                let f = &d.field;
                let (xf, yf) = (x0 as $f, y as $f);
                match r {
                    RowSetup::BatchedGouraud => f.row(xf, yf, n).gouraud(o),
                    RowSetup::BatchedCorrectedEuler => f.row(xf, yf, n).corrected_euler(o),
                    RowSetup::BatchedPhong => f.row(xf, yf, n).phong(o),
                    RowSetup::FieldPhong => f.start(xf, yf).phong_field(f, n, o),
                    RowSetup::SteppedCorrectedEuler => {
                        let st = match d.stepper.get() {
                            Some((lx, ly, e)) if lx == x0 && ly == y => e,
                            Some((lx, ly, mut e)) if (y - ly - 1.0).abs() < 1e-9 => {
                                e.step(f, (x0 - lx).round() as $f);
                                e
                            }
                            _ => EdgeStepper::<$f>::new(f, xf, yf),
                        };
                        d.stepper.set(Some((x0, y, st)));
                        st.start.span(f, n).corrected_euler(o)
                    }
                    RowSetup::BatchedPhongRsqrt | RowSetup::FieldPhongRsqrt => {
                        return $rsqrt(f, r, xf, yf, n, o)
                    }
                }
                Some(())
            }
        }
    };
}
row_kernels!(f32, rsqrt_f32, true);
row_kernels!(f64, rsqrt_f64, false);
impl sealed::Rows for crate::lowp::f16 {}
impl sealed::Rows for crate::lowp::I16F16 {}
impl sealed::Rows for crate::lowp::I8F8 {}
impl sealed::Rows for crate::BigRational {}

fn to_vec<T: Real>(v: G3) -> Option<Vec3<T>> {
    Vec3::new(f64::from(v.x), f64::from(v.y), f64::from(v.z)).cast()
}

fn to_t<T: Real>(v: f64) -> T {
    let r = crate::BigRational::from_float(v).unwrap_or_default();
    T::from_rational(&r)
}

impl<T: RowKernels> TriangleSetup<T> {
    /// `rel`: vertex positions relative to the centroid (computed in `f64`);
    /// `normals`: unit vertex normals; `dirs`: unit directions.
    pub(crate) fn new(rel: [(f64, f64); 3], normals: [G3; 3], dirs: &[G3]) -> Option<Self> {
        let tri = Triangle::new(rel.map(|(x, y)| (to_t::<T>(x), to_t::<T>(y)))).ok()?;
        // Unit in `T`: normalized after the conversion.
        let nrm = [
            to_vec::<T>(normals[0])?.normalize(),
            to_vec::<T>(normals[1])?.normalize(),
            to_vec::<T>(normals[2])?.normalize(),
        ];
        let field = tri.normal_field(&nrm);
        let mut out = Vec::with_capacity(dirs.len());
        for d in dirs {
            let dir = to_vec::<T>(*d)?.normalize();
            let vertex = [nrm[0].dot(&dir), nrm[1].dot(&dir), nrm[2].dot(&dir)];
            let gouraud = tri.affine(&vertex);
            let angle = vertex_angle::angle_field(&tri, &nrm, &dir);
            // Centroid-relative: the expansion point is (0, 0).
            let taylor = Taylor::new(&field.0, &field.1, &field.2, &dir).ok()?;
            let seiler = Quadratic::from_normals(&tri, &nrm, &dir).ok()?;
            out.push(Direction {
                dir,
                vertex,
                gouraud,
                angle,
                taylor,
                seiler,
            });
        }
        Some(TriangleSetup {
            lambda: tri.lambda.clone(),
            rows: T::rows_of(&field, &out),
            field,
            dirs: out,
        })
    }

    fn normal(&self, x: &T, y: &T) -> Vec3<T> {
        self.field
            .0
            .scale(x)
            .add(&self.field.1.scale(y))
            .add(&self.field.2)
    }
}

/// What a row gives beyond its values.
pub(crate) struct RowInfo<T> {
    /// The adaptive pick (Gouraud for a one-pixel row).
    pub(super) choice: Choice,
    /// The exact values at the row's first and last pixel (the fence's samples).
    pub(super) edges: (T, T),
    /// The row's span in `T` (rows of two or more pixels).
    pub(super) span: Option<Span<T>>,
}

/// Where a row is: `n + 1` pixels starting at centroid-relative `(x0, y)`, shaded for
/// direction `d` of the triangle's set-up (0: the light, 1: the half vector).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RowAt {
    /// The direction's index.
    pub d: usize,
    /// The first pixel's centre, relative to the centroid.
    pub x0: f64,
    /// The row's centre, relative to the centroid.
    pub y: f64,
    /// Steps: the row has `n + 1` pixels.
    pub n: u32,
}

/// Shades the row `at` for every shader in `which`, into `out[shader index]`.
pub(crate) fn shade_row<T: RowKernels>(
    s: &TriangleSetup<T>,
    at: RowAt,
    prep: &Prepared<T>,
    which: &[Shader],
    out: &mut [Vec<T>],
) -> Option<RowInfo<T>> {
    let RowAt { d, x0, y, n } = at;
    let dir = &s.dirs[d];
    let (tx0, ty) = (to_t::<T>(x0), to_t::<T>(y));
    let txn = to_t::<T>(x0 + f64::from(n));
    let unit = |v: Vec3<T>| -> Option<Vec3<T>> {
        let l2 = v.length_squared();
        if l2 <= T::zero() || !l2.is_finite() {
            None
        } else {
            Some(v.div(&l2.sqrt()))
        }
    };
    let na = unit(s.normal(&tx0, &ty))?;
    let nb = unit(s.normal(&txn, &ty))?;
    let span = if n >= 1 {
        // Normalized in `T`: unit within rounding (within 2^-200 for rationals, whose
        // square roots are not exact).
        let tol = T::unit_tolerance()
            + T::from_rational(&crate::BigRational::new(
                1.into(),
                num_bigint::BigInt::from(1) << 200,
            ));
        Some(Span::with_tolerance(na.clone(), nb.clone(), dir.dir.clone(), n, &tol).ok()?)
    } else {
        None
    };
    let p_a = na.dot(&dir.dir);
    let p_b = nb.dot(&dir.dir);
    // The one row shader: the span methods on the row's span, the polygon methods on
    // the triangle's set-up for this direction.
    let choice = crate::raster::shader::shade_row(
        span.as_ref(),
        &p_a,
        prep,
        which,
        index,
        out,
        &mut |sh, o| {
            match sh {
                Shader::PhongPixel => {
                    for (j, v) in o.iter_mut().enumerate() {
                        let x = to_t::<T>(x0 + j as f64);
                        *v = unit(s.normal(&x, &ty))?.dot(&dir.dir);
                    }
                }
                Shader::VertexGouraud => dir.gouraud.shade_row(&tx0, &ty, o),
                Shader::VertexAngle => {
                    vertex_angle::shade_row(&dir.angle, prep.table.as_ref()?, &tx0, &ty, o)
                }
                Shader::BishopWeimerTriangle => dir.taylor.shade_row(&tx0, &ty, o),
                Shader::Seiler => dir.seiler.shade_row(&tx0, &ty, o),
                Shader::Rows(r) => T::shade_rows(s.rows.get(d)?, r, x0, y, n, o)?,
                Shader::Span(_) => unreachable!("the row shader runs the span methods"),
            }
            Some(())
        },
    )?
    .unwrap_or(Choice::Gouraud);
    if which
        .iter()
        .any(|&sh| out[index(sh)].iter().any(|v| !v.is_finite()))
    {
        return None;
    }
    Some(RowInfo {
        choice,
        edges: (p_a, p_b),
        span,
    })
}
