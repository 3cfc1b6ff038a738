//! One right triangle with legs of S pixels, shaded by every method with its own
//! set-up: the one list of what `benches/related.rs` times and
//! `examples/row_counts.rs` counts instructions of (`benches/callgrind.sh`).
//!
//! Rows `y = 0..S` hold pixels `x = 0..=S − 1 − y`. The polygon methods and the
//! `fast_*`/`span_*` rows take coordinates relative to the triangle's centroid
//! through the crate's generic `Triangle`; the `batched_*`, `stepped_*` and `field_*`
//! methods take them relative to the first vertex through `Field::from_triangle`.
//! Names are resolved to a [`Which`] once, outside the timed loop.

use criterion::black_box;
use phong_approx::angular::CosTable;
use phong_approx::fast::FastSpan;
use phong_approx::fast_rows::{self, EdgeStepper, Field, RowSpan};
use phong_approx::related::bishop_weimer::Taylor;
use phong_approx::related::seiler::Quadratic;
use phong_approx::related::triangle::Triangle;
use phong_approx::related::vertex_angle;
use phong_approx::{Method, Span, Vec3};

pub type V = Vec3<f32>;

/// What can be timed on the triangle: every method with its own set-up, and the
/// stages of the set-ups.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Which {
    /// Per-pixel Phong with glam on the crate's generic `Triangle` field.
    GlamPhong,
    /// Per-pixel Phong with glam on `Field::from_triangle` (plain `f32`).
    GlamPhongPlainField,
    /// Vertex Gouraud.
    VertexGouraud,
    /// Mortensen's vertex angles.
    VertexAngle,
    /// Bishop & Weimer over the triangle.
    BishopWeimer,
    /// Seiler's six-point quadratic.
    Seiler,
    /// `FastSpan` per row after normalizing both edge normals: fence.
    FastFence,
    /// The same, corrected Euler.
    FastCorrectedEuler,
    /// The same, Phong (`sqrt`, division).
    FastPhong,
    /// The same, Phong (`rsqrtps` and one Newton step).
    FastPhongRsqrt,
    /// The batched set-up (`fast_rows::Batch`): fence.
    BatchedFence,
    /// The batched set-up, corrected Euler.
    BatchedCorrectedEuler,
    /// The batched set-up, Phong.
    BatchedPhong,
    /// The batched set-up, Phong with `rsqrt`.
    BatchedPhongRsqrt,
    /// The edge-stepped set-up (`fast_rows::EdgeStepper`), corrected Euler.
    SteppedCorrectedEuler,
    /// Phong of the field in closed form per row (`RowStart::phong_field`).
    FieldPhong,
    /// Phong of the field with `rsqrt`.
    FieldPhongRsqrt,
    /// A span method of the catalogue through the checked generic path (`Span::new`,
    /// the method).
    Span(Method),
    /// A stage of a set-up (group `triangle_stages_f32`).
    Stage(Stage),
}

/// The stages of the per-row set-ups; each includes the ones before it in its group.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// The crate's generic triangle and its normal field (what the polygon methods and
    /// the `fast_*` and `span_*` rows pay per polygon).
    Triangle,
    /// Then the rows' first pixels and lengths.
    Rows,
    /// Then both edge normals of every row.
    EdgeNormals,
    /// Then normalized.
    Normalize,
    /// Then `FastSpan::new` (the kernel follows: `fast_corrected_euler`).
    FastSetup,
    /// `Field::from_triangle` alone (what the `batched_*`, `stepped_*` and `field_*`
    /// methods pay per polygon).
    PlainField,
    /// Then every row's `p_a`, `p_b`, `1 − c` by `Field::for_each_row` (the kernel follows:
    /// `batched_corrected_euler`).
    Batch,
}

/// Every method with its name, in the order of the tables: per pixel, per polygon,
/// the fast span kernels with their set-up per row, the cheap set-ups, the checked
/// generic path.
pub const METHODS: [(&str, Which); 26] = [
    ("glam_phong", Which::GlamPhong),
    ("glam_phong_plain_field", Which::GlamPhongPlainField),
    ("vertex_gouraud", Which::VertexGouraud),
    ("vertex_angle", Which::VertexAngle),
    ("bishop_weimer", Which::BishopWeimer),
    ("seiler", Which::Seiler),
    ("fast_fence", Which::FastFence),
    ("fast_corrected_euler", Which::FastCorrectedEuler),
    ("fast_phong", Which::FastPhong),
    ("fast_phong_rsqrt", Which::FastPhongRsqrt),
    ("batched_fence", Which::BatchedFence),
    ("batched_corrected_euler", Which::BatchedCorrectedEuler),
    ("batched_phong", Which::BatchedPhong),
    ("batched_phong_rsqrt", Which::BatchedPhongRsqrt),
    ("stepped_corrected_euler", Which::SteppedCorrectedEuler),
    ("field_phong", Which::FieldPhong),
    ("field_phong_rsqrt", Which::FieldPhongRsqrt),
    ("span_phong", Which::Span(Method::Phong)),
    ("span_duff", Which::Span(Method::Duff)),
    ("span_fence", Which::Span(Method::Gouraud)),
    ("span_euler", Which::Span(Method::Euler)),
    ("span_corrected_euler", Which::Span(Method::CorrectedEuler)),
    ("span_angular", Which::Span(Method::Angular)),
    ("span_spherical", Which::Span(Method::Spherical)),
    ("span_binary", Which::Span(Method::Binary)),
    ("span_bishop_weimer", Which::Span(Method::BishopWeimer)),
];

/// The stages with their names: `fast_corrected_euler`'s set-up cut after each
/// stage, then `batched_corrected_euler`'s.
pub const STAGES: [(&str, Which); 7] = [
    ("stage_triangle", Which::Stage(Stage::Triangle)),
    ("stage_rows", Which::Stage(Stage::Rows)),
    ("stage_edge_normals", Which::Stage(Stage::EdgeNormals)),
    ("stage_normalize", Which::Stage(Stage::Normalize)),
    ("stage_fast_setup", Which::Stage(Stage::FastSetup)),
    ("stage_plain_field", Which::Stage(Stage::PlainField)),
    ("stage_batch", Which::Stage(Stage::Batch)),
];

/// The method or stage called `name` (for the instruction counts).
#[allow(dead_code)]
pub fn which(name: &str) -> Option<Which> {
    METHODS
        .iter()
        .chain(&STAGES)
        .find(|(n, _)| *n == name)
        .map(|(_, w)| *w)
}

/// Unit vertex normals about 15° apart (a torus-like patch) and the light.
pub fn inputs() -> ([V; 3], V) {
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
pub fn rows(s: u32) -> impl Iterator<Item = (u32, u32)> {
    (0..s).map(move |y| (y, s - 1 - y))
}

/// Pixels of the triangle with legs `s`.
pub fn pixels(s: u32) -> u64 {
    u64::from(s) * u64::from(s + 1) / 2
}

fn triangle(s: u32) -> Triangle<f32> {
    let s = s as f32;
    Triangle::new([(0.0, 0.0), (s, 0.0), (0.0, s)]).expect("a proper triangle")
}

fn arr(v: &V) -> [f32; 3] {
    v.components().map(|c| *c)
}

/// What the methods keep between polygons.
pub struct Ctx {
    /// The second source's cosine table.
    pub table: CosTable<f32>,
}

impl Ctx {
    /// The 256-entry table.
    pub fn new() -> Self {
        Ctx {
            table: CosTable::<f32>::new(256).expect("256 entries"),
        }
    }
}

/// Shades the triangle with legs `s` with `which`, every row into `out[..=n]`.
pub fn shade(which: Which, s: u32, normals: &[V; 3], l: &V, ctx: &mut Ctx, out: &mut [f32]) {
    match which {
        Which::GlamPhong => per_pixel_phong(s, normals, l, out),
        Which::GlamPhongPlainField => per_pixel_phong_plain(s, normals, l, out),
        Which::VertexGouraud | Which::VertexAngle | Which::BishopWeimer | Which::Seiler => {
            per_polygon(s, normals, l, &ctx.table, which, out)
        }
        Which::FastFence => per_span_fast(s, normals, l, FastSpan::<f32>::gouraud, out),
        Which::FastCorrectedEuler => {
            per_span_fast(s, normals, l, FastSpan::<f32>::corrected_euler, out)
        }
        Which::FastPhong => per_span_fast(s, normals, l, FastSpan::<f32>::phong, out),
        Which::FastPhongRsqrt => {
            per_span_fast(s, normals, l, phong_approx::fast::phong_rsqrt_f32, out)
        }
        Which::BatchedFence => batched(s, normals, l, RowSpan::<f32>::gouraud, out),
        Which::BatchedCorrectedEuler => {
            batched(s, normals, l, RowSpan::<f32>::corrected_euler, out)
        }
        Which::BatchedPhong => batched(s, normals, l, RowSpan::<f32>::phong, out),
        Which::BatchedPhongRsqrt => batched(s, normals, l, fast_rows::phong_rsqrt, out),
        Which::SteppedCorrectedEuler => stepped(s, normals, l, out),
        Which::FieldPhong => field_phong(s, normals, l, false, out),
        Which::FieldPhongRsqrt => field_phong(s, normals, l, true, out),
        Which::Span(m) => per_span(s, normals, l, m, out),
        Which::Stage(Stage::Triangle) => {
            black_box(triangle(s).normal_field(normals));
        }
        Which::Stage(Stage::PlainField) => {
            black_box(field(s, normals, l));
        }
        // Each row's set-up is consumed (`black_box`), so none of it is optimized away.
        Which::Stage(Stage::Batch) => batched(
            s,
            normals,
            l,
            |r, _| {
                black_box(r);
            },
            out,
        ),
        Which::Stage(stage) => profile(s, normals, l, stage, out),
    }
}

/// A polygon method: set-up for the triangle, then one call per row.
fn per_polygon(
    s: u32,
    normals: &[V; 3],
    l: &V,
    table: &CosTable<f32>,
    which: Which,
    out: &mut [f32],
) {
    let tri = triangle(s);
    let rel = |y: u32| tri.relative(&0.0, &(y as f32));
    match which {
        Which::VertexGouraud => {
            let f = tri.affine(&[normals[0].dot(l), normals[1].dot(l), normals[2].dot(l)]);
            for (y, n) in rows(s) {
                let (x0, y) = rel(y);
                f.shade_row(&x0, &y, &mut out[..=n as usize]);
            }
        }
        Which::VertexAngle => {
            let f = vertex_angle::angle_field(&tri, normals, l);
            for (y, n) in rows(s) {
                let (x0, y) = rel(y);
                vertex_angle::shade_row(&f, table, &x0, &y, &mut out[..=n as usize]);
            }
        }
        Which::BishopWeimer => {
            let (n1, n2, n3) = tri.normal_field(normals);
            let t = Taylor::new(&n1, &n2, &n3, l).expect("N3 ≠ 0");
            for (y, n) in rows(s) {
                let (x0, y) = rel(y);
                t.shade_row(&x0, &y, &mut out[..=n as usize]);
            }
        }
        Which::Seiler => {
            let q = Quadratic::from_normals(&tri, normals, l).expect("no opposite normals");
            for (y, n) in rows(s) {
                let (x0, y) = rel(y);
                q.shade_row(&x0, &y, &mut out[..=n as usize]);
            }
        }
        _ => unreachable!("not a polygon method: {which:?}"),
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
fn per_span(s: u32, normals: &[V; 3], l: &V, m: Method, out: &mut [f32]) {
    per_row(s, normals, l, out, |na, nb, n, o| {
        let span = Span::new(na, nb, l.clone(), n).expect("unit normals");
        m.shade(&span, o).expect("the output length is n + 1");
    });
}

/// A fast span kernel of the paper: the two edge normals normalized, then
/// `FastSpan::new` per row, then the kernel.
fn per_span_fast(
    s: u32,
    normals: &[V; 3],
    l: &V,
    kernel: impl Fn(&FastSpan<f32>, &mut [f32]),
    out: &mut [f32],
) {
    let la = arr(l);
    per_row(s, normals, l, out, |na, nb, n, o| {
        kernel(&FastSpan::<f32>::new(arr(&na), arr(&nb), la, n), o)
    });
}

/// The triangle's field, lit, in coordinates relative to its first vertex `(0, 0)`
/// (`Field::from_triangle`: plain `f32`, one reciprocal).
fn field(s: u32, normals: &[V; 3], l: &V) -> Field<f32> {
    let s = s as f32;
    Field::<f32>::from_triangle(
        [[0.0, 0.0], [s, 0.0], [0.0, s]],
        normals.each_ref().map(arr),
        arr(l),
    )
    .expect("a proper triangle")
}

/// The batched set-up (`Field::for_each_row`): the rows as the scan converter hands
/// them over (first pixel, row, length), set up eight at a time in one vectorized
/// pass (`fast_rows::Batch`), then the kernel per row.
fn batched(
    s: u32,
    normals: &[V; 3],
    l: &V,
    kernel: impl Fn(&RowSpan<f32>, &mut [f32]),
    out: &mut [f32],
) {
    let f = field(s, normals, l);
    f.for_each_row(rows(s).map(|(y, n)| (0.0, y as f32, n)), |_, row| {
        kernel(row, &mut out[..=row.n as usize])
    });
    black_box(&out);
}

/// The edge-stepped set-up (`fast_rows::EdgeStepper`), then corrected Euler per row.
fn stepped(s: u32, normals: &[V; 3], l: &V, out: &mut [f32]) {
    let f = field(s, normals, l);
    let mut e = EdgeStepper::<f32>::new(&f, 0.0, 0.0);
    for (y, n) in rows(s) {
        if y > 0 {
            e.step(&f, 0.0);
        }
        e.start.span(&f, n).corrected_euler(&mut out[..=n as usize]);
    }
    black_box(&out);
}

/// Phong of the field in closed form per row (`RowStart::phong_field`): no per-row
/// square root.
fn field_phong(s: u32, normals: &[V; 3], l: &V, rsqrt: bool, out: &mut [f32]) {
    let f = field(s, normals, l);
    for (y, n) in rows(s) {
        let st = f.start(0.0, y as f32);
        let o = &mut out[..=n as usize];
        if rsqrt {
            fast_rows::phong_field_rsqrt(&st, &f, n, o);
        } else {
            st.phong_field(&f, n, o);
        }
    }
    black_box(&out);
}

/// `fast_corrected_euler` cut after a stage: what the rows cost without shading.
fn profile(s: u32, normals: &[V; 3], l: &V, stage: Stage, out: &mut [f32]) {
    let tri = triangle(s);
    let (n1, n2, n3) = tri.normal_field(normals);
    let la = arr(l);
    let at = |x: f32, y: f32| n1.scale(&x).add(&n2.scale(&y)).add(&n3);
    for (y, n) in rows(s) {
        let (x0, yr) = tri.relative(&0.0, &(y as f32));
        match stage {
            Stage::Rows => {
                black_box((x0, yr, n));
            }
            Stage::EdgeNormals => {
                black_box((at(x0, yr), at(x0 + n as f32, yr)));
            }
            Stage::Normalize => {
                black_box((at(x0, yr).normalize(), at(x0 + n as f32, yr).normalize()));
            }
            Stage::FastSetup => {
                let (na, nb) = (at(x0, yr).normalize(), at(x0 + n as f32, yr).normalize());
                black_box(FastSpan::<f32>::new(arr(&na), arr(&nb), la, n.max(1)));
            }
            _ => unreachable!("not a row stage: {stage:?}"),
        }
    }
    black_box(&out);
}

/// Per-pixel Phong as most users write it: the normal field at every pixel,
/// normalized, dotted with `L`.
fn per_pixel_phong(s: u32, normals: &[V; 3], l: &V, out: &mut [f32]) {
    let tri = triangle(s);
    let (n1, n2, n3) = tri.normal_field(normals);
    let g = |v: &V| glam::Vec3::from(arr(v));
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

/// [`per_pixel_phong`] on the field of `Field::from_triangle` (plain `f32`, one
/// reciprocal) instead of the crate's generic `Triangle`: the same per-polygon
/// set-up as the `batched_*`, `stepped_*` and `field_*` methods.
fn per_pixel_phong_plain(s: u32, normals: &[V; 3], l: &V, out: &mut [f32]) {
    let f = field(s, normals, l);
    let (n1, n2, n3, l) = (
        glam::Vec3::from(f.n1),
        glam::Vec3::from(f.n2),
        glam::Vec3::from(f.n3),
        glam::Vec3::from(f.l),
    );
    for (y, n) in rows(s) {
        let base = n2 * y as f32 + n3;
        for (j, o) in out[..=n as usize].iter_mut().enumerate() {
            *o = (n1 * j as f32 + base).normalize().dot(l);
        }
    }
    black_box(&out);
}

/// Whether every method and stage runs on every size (the bench's own check).
#[allow(dead_code)]
pub fn smoke() {
    let (normals, l) = inputs();
    let mut ctx = Ctx::new();
    for s in [1, 2, 8, 33] {
        let mut out = vec![0f32; s as usize + 1];
        for (_, w) in METHODS.iter().chain(&STAGES) {
            shade(*w, s, &normals, &l, &mut ctx, &mut out);
        }
    }
}
