//! The comparison harness: every method of the paper and of its related work on the
//! same rotating tori, diffuse and specular, against per-pixel Phong.
//!
//! Geometry: each quad of the paper's tori is drawn as two triangles (split along the
//! diagonal from its first to its third vertex), because Bishop & Weimer's and
//! Seiler's methods are defined over a triangle's affine normal field. Every
//! attribute is evaluated at pixel centres from that field:
//!
//! - the reference, [`Shader::PhongPixel`], normalizes the field's normal at each pixel
//!   centre, in `f64`;
//! - the span methods get the field's normal at the first and last covered pixel of
//!   a row, normalized, as their `N_a` and `N_b` (so their span Phong differs from the
//!   reference only by which normals are normalized: `Shader::Span(Method::Phong)` measures
//!   it);
//! - the polygon methods (vertex Gouraud, vertex angles, Bishop–Weimer, Seiler) set up
//!   once per triangle and step along each row by forward differences.
//!
//! The Tables 1–2 reproduction ([`super::render`]) keeps the paper's quads and edge
//! crossings; this harness answers the paper's future-work question.

use super::render::{Deviation, Scene};
use crate::adaptive::Choice;
use crate::fast_rows::{EdgeStepper, Field};
use crate::method::Prepared;
use crate::quantize::level;
use crate::raster::frame::{draw, polygons, Polygon, Shading, Split};
use crate::raster::mesh::Mesh;
use crate::raster::scan::Row;
use crate::raster::stats::deviations;
use crate::related::bishop_weimer::Taylor;
use crate::related::power::PowerTable;
use crate::related::seiler::Quadratic;
use crate::related::triangle::{Affine, Triangle};
use crate::related::vertex_angle;
use crate::scalar::Real;
use crate::{Method, Span, Vec3};
use glam::Vec3 as G3;
use std::cell::Cell;

use crate::raster::shader::RowSetup;

/// The shininess values of the specular tables.
pub const SHININESS: [u32; 3] = [10, 50, 200];

pub use crate::raster::shader::Shader;

mod rows;
mod skip;
mod squared;
pub use rows::{runs_in, Direction, RowKernels};
pub(crate) use rows::{shade_row, RowAt, RowInfo, TriangleSetup};
pub use skip::{table as skip_table, SkipCount, SKIP_SHININESS};
pub use squared::{
    table as squared_table, SquaredCount, SQUARED_FIGURE_SHININESS, SQUARED_METHODS,
    SQUARED_SHININESS,
};

/// Every column of the comparison, the reference first: every span method of the
/// catalogue ([`Method::ALL`], in its order), each followed by the polygon methods it
/// is compared with ([`crate::raster::shader::POLYGON`]'s `after`). A method added to the
/// catalogue appears here by itself.
pub static COLUMNS: std::sync::LazyLock<Vec<Shader>> = std::sync::LazyLock::new(|| {
    let mut c = vec![Shader::PhongPixel];
    for m in Method::ALL {
        c.push(Shader::Span(m));
        for p in crate::raster::shader::POLYGON {
            if p.after == Some(m) {
                c.push(p.shader);
            }
        }
    }
    c
});

/// The position of `sh` in [`COLUMNS`].
///
/// # Panics
/// If `sh` is not a column of the comparison.
pub fn index(sh: Shader) -> usize {
    COLUMNS
        .iter()
        .position(|s| *s == sh)
        .expect("a column of the comparison")
}

/// Per-shader accumulators of the comparison.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CompareStats {
    /// Diffuse: per shader of [`COLUMNS`], deviation from the reference in levels.
    pub diffuse: Vec<Deviation>,
    /// Specular `max(0, N·H)^s`, per shininess of [`SHININESS`], per shader.
    pub specular: Vec<Vec<Deviation>>,
    /// Rows of two or more pixels (spans).
    pub spans: u64,
    /// Spans the diffuse δ test gives to Gouraud.
    pub adaptive_gouraud: u64,
    /// Per shininess: the δ test applied to `N·H` (K = 1).
    pub specular_delta: Vec<DeltaCount>,
    /// Per shininess of [`SKIP_SHININESS`]: the specular skip test (§7.1, question a).
    pub skip: Vec<SkipCount>,
    /// Per shininess of [`SQUARED_SHININESS`], on the skip study's frames: corrected
    /// Euler on `(N·H)²` against Phong (§7.1, question b).
    pub squared: Vec<SquaredCount>,
    /// Rows dropped because some method could not shade them in this precision.
    pub dropped_rows: u64,
    /// Visible pixels.
    pub pixels: u64,
    /// Frames.
    pub frames: u64,
}

/// How the δ test of eq. 24 fares on the specular term.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DeltaCount {
    /// Spans the test gives to Gouraud.
    pub gouraud: u64,
    /// … of which Gouraud's and corrected Euler's levels of `(N·H)^s` differ.
    pub gouraud_but_differ: u64,
    /// Spans given to corrected Euler although both give the same levels.
    pub corrected_but_same: u64,
}

impl CompareStats {
    fn empty() -> Self {
        let cols = COLUMNS.len();
        CompareStats {
            diffuse: vec![Deviation::default(); cols],
            specular: vec![vec![Deviation::default(); cols]; SHININESS.len()],
            specular_delta: vec![DeltaCount::default(); SHININESS.len()],
            skip: vec![SkipCount::default(); SKIP_SHININESS.len()],
            squared: vec![SquaredCount::default(); SQUARED_SHININESS.len()],
            ..Default::default()
        }
    }

    /// Adds `o` into `self`.
    pub fn merge(&mut self, o: &CompareStats) {
        if self.diffuse.is_empty() {
            *self = CompareStats::empty();
        }
        for (a, b) in self.diffuse.iter_mut().zip(&o.diffuse) {
            a.merge(b);
        }
        for (sa, sb) in self.specular.iter_mut().zip(&o.specular) {
            for (a, b) in sa.iter_mut().zip(sb) {
                a.merge(b);
            }
        }
        for (a, b) in self.specular_delta.iter_mut().zip(&o.specular_delta) {
            a.gouraud += b.gouraud;
            a.gouraud_but_differ += b.gouraud_but_differ;
            a.corrected_but_same += b.corrected_but_same;
        }
        for (a, b) in self.skip.iter_mut().zip(&o.skip) {
            a.merge(b);
        }
        for (a, b) in self.squared.iter_mut().zip(&o.squared) {
            a.merge(b);
        }
        self.spans += o.spans;
        self.adaptive_gouraud += o.adaptive_gouraud;
        self.dropped_rows += o.dropped_rows;
        self.pixels += o.pixels;
        self.frames += o.frames;
    }

    /// The share of spans the diffuse δ test gives to Gouraud, in percent.
    pub fn adaptive_gouraud_percent(&self) -> f64 {
        if self.spans == 0 {
            0.0
        } else {
            100.0 * self.adaptive_gouraud as f64 / self.spans as f64
        }
    }
}

/// Options of [`render_compare`].
#[derive(Clone, Copy, Debug, Default)]
pub struct CompareOptions {
    /// Keep per-pixel pictures (levels of [`PICTURE_LOOK`]).
    pub pictures: bool,
    /// The shininess of the pictures, as an index into [`SHININESS`].
    pub shininess: usize,
    /// Decide every span's specular skip test exactly and count what it skips
    /// ([`SkipCount`]; each span is set up exactly, so [`run`] does it on every
    /// [`SKIP_EVERY`]-th frame).
    pub skip_study: bool,
}

/// [`run`] runs the skip study ([`CompareOptions::skip_study`]) on the frames `f` with
/// `f % SKIP_EVERY == 0`: the exact set-up of every span of a frame costs more than
/// shading the frame (here, 8 frames with the study on two of them took 47 s, with it
/// on one 40 s).
pub const SKIP_EVERY: u32 = 4;

/// The lighting of the pictures: `K_a + K_d·diffuse + K_s·specular`, clamped to 1.
pub const PICTURE_LOOK: (f64, f64, f64) = (0.08, 0.75, 0.5);

/// One frame of the comparison.
#[derive(Clone, Debug)]
pub struct CompareFrame {
    /// Width.
    pub width: u32,
    /// Height.
    pub height: u32,
    /// Per shader, per pixel: the picture level (only with
    /// [`CompareOptions::pictures`]; the reference is [`Shader::PhongPixel`]'s).
    pub picture: Vec<Vec<Option<u8>>>,
    /// Per pixel, where the frame was drawn with [`CompareOptions::pictures`] and
    /// [`CompareOptions::skip_study`]: from which shininess of [`SKIP_SHININESS`] on
    /// Phong's exact skip test skips the pixel's span (`k + 1` for
    /// `SKIP_SHININESS[k]`; `0` where it skips at none), `None` where no span was
    /// decided (the background, a one-pixel row, an undecided span).
    pub skip_map: Vec<Option<u8>>,
    /// Per pixel, under the same options: the specular levels at
    /// [`SQUARED_FIGURE_SHININESS`] of Phong's value of the pixel's span and of the
    /// three methods of [`SQUARED_METHODS`] (`None` where the span was not compared).
    pub squared_map: Vec<Option<[u8; 4]>>,
    /// The statistics.
    pub stats: CompareStats,
}

/// The specular power of shader `sh` applied to `v` (its base value of `N·H`).
fn power(sh: Shader, v: f64, table: &PowerTable) -> f64 {
    if sh.power_from_table() {
        table.lookup(v)
    } else if v <= 0.0 {
        0.0
    } else {
        v.powi(table.shininess as i32)
    }
}

/// Levels of one row for one shader: diffuse, and specular per shininess.
type RowLevels = Vec<[u8; 4]>;

/// Renders frame `f` of `mesh` in `scene` with every shader in `f32` (the reference in
/// `f64`) through the frame loop ([`crate::raster::frame::draw`], triangles) and measures the
/// deviations.
pub fn render_compare(mesh: &Mesh, scene: &Scene, f: u32, opts: CompareOptions) -> CompareFrame {
    let (w, h) = (scene.width, scene.height);
    let npix = (w * h) as usize;
    let cols = COLUMNS.len();
    let table = Method::AngularTable(crate::method::SOURCE_TABLE);
    let mut st = CompareStats::empty();
    st.frames = 1;
    let mut shading = Comparison {
        dirs: [scene.light, scene.half()],
        prep32: Prepared::new(table, 1.0f32).expect("256 entries"),
        prep64: Prepared::new(table, 1.0f64).expect("256 entries"),
        powers: SHININESS.iter().map(|&s| PowerTable::new(s)).collect(),
        opts,
        setup: None,
        levels: vec![vec![vec![None; npix]; cols]; 1 + SHININESS.len()],
        picture: if opts.pictures {
            vec![vec![None; npix]; cols]
        } else {
            Vec::new()
        },
        skip_map: if opts.pictures && opts.skip_study {
            vec![None; npix]
        } else {
            Vec::new()
        },
        squared_map: if opts.pictures && opts.skip_study {
            vec![None; npix]
        } else {
            Vec::new()
        },
        stats: st,
        out32: vec![Vec::new(); cols],
        out64: vec![Vec::new(); cols],
        spec32: vec![Vec::new(); cols],
        spec64: vec![Vec::new(); cols],
    };
    let polys = polygons(mesh, scene, f, Split::Triangles);
    draw(w, h, &polys, &mut shading);
    let mut stats = shading.stats;
    stats.pixels = shading.levels[0][0].iter().flatten().count() as u64;
    stats.diffuse = deviations(&shading.levels[0], 0);
    for k in 0..SHININESS.len() {
        stats.specular[k] = deviations(&shading.levels[k + 1], 0);
    }
    CompareFrame {
        width: w,
        height: h,
        picture: shading.picture,
        skip_map: shading.skip_map,
        squared_map: shading.squared_map,
        stats,
    }
}

/// A triangle's centroid, its vertices relative to the centroid, and its unit vertex
/// normals.
pub(crate) type TriangleInputs = ((f64, f64), [(f64, f64); 3], [G3; 3]);

/// The vertices of triangle `poly` relative to its centroid, and its unit vertex
/// normals: what every polygon method is set up from.
pub(crate) fn triangle_inputs(poly: &Polygon) -> TriangleInputs {
    let (xc, yc) = poly.centre();
    let v = [poly.v[0], poly.v[1], poly.v[2]];
    (
        (xc, yc),
        v.map(|s| (f64::from(s.x) - xc, f64::from(s.y) - yc)),
        v.map(|s| s.normal.normalize()),
    )
}

/// One shaded row of the comparison: per column, per pixel, the diffuse level and
/// the specular levels per shininess; the picture levels.
struct CompareRow {
    levels: Vec<RowLevels>,
    picture: Vec<Vec<u8>>,
    /// The row's code of [`CompareFrame::skip_map`].
    skip: Option<u8>,
    /// The row's levels of [`CompareFrame::squared_map`] (empty: none).
    squared: Vec<[u8; 4]>,
}

/// A triangle's centroid and its set-ups in `f32` and `f64`.
type TriangleSetups = ((f64, f64), TriangleSetup<f32>, TriangleSetup<f64>);

/// The [`Shading`] of the comparison.
struct Comparison {
    dirs: [G3; 2],
    prep32: Prepared<f32>,
    prep64: Prepared<f64>,
    powers: Vec<PowerTable>,
    opts: CompareOptions,
    /// The current triangle: its centroid and its set-ups in `f32` and `f64`.
    setup: Option<TriangleSetups>,
    /// Per channel (diffuse, then specular per shininess), per column, per pixel.
    levels: Vec<Vec<Vec<Option<u8>>>>,
    picture: Vec<Vec<Option<u8>>>,
    skip_map: Vec<Option<u8>>,
    squared_map: Vec<Option<[u8; 4]>>,
    stats: CompareStats,
    out32: Vec<Vec<f32>>,
    out64: Vec<Vec<f64>>,
    spec32: Vec<Vec<f32>>,
    spec64: Vec<Vec<f64>>,
}

impl Comparison {
    /// The levels of the row `at` (the half vector's; the light's share its `x0`, `y`
    /// and `n`) for every shader: diffuse, then specular per shininess, from the
    /// values [`shade_row`] left in `out32`, `out64`, `spec32` and `spec64`.
    fn row_levels(
        &self,
        s32: &TriangleSetup<f32>,
        h32: &RowInfo<f32>,
        at: RowAt,
    ) -> Vec<RowLevels> {
        let (out32, out64, spec32, spec64) = (&self.out32, &self.out64, &self.spec32, &self.spec64);
        let len = at.n as usize + 1;
        COLUMNS
            .iter()
            .enumerate()
            .map(|(c, &sh)| {
                (0..len)
                    .map(|j| {
                        let mut l = [0u8; 4];
                        if c == 0 {
                            l[0] = level(&out64[0][j]);
                            for (k, pt) in self.powers.iter().enumerate() {
                                l[k + 1] = level(&power(Shader::PhongPixel, spec64[0][j], pt));
                            }
                        } else {
                            l[0] = level(&out32[c][j]);
                            for (k, pt) in self.powers.iter().enumerate() {
                                let v = specular_value(sh, &spec32[c], s32, h32, at, j, pt);
                                l[k + 1] = level(&v);
                            }
                        }
                        l
                    })
                    .collect()
            })
            .collect()
    }
}

impl Shading for Comparison {
    type Row = CompareRow;

    fn polygon(&mut self, _: usize, poly: &Polygon) -> bool {
        let (centre, rel, normals) = triangle_inputs(poly);
        self.setup = match (
            TriangleSetup::<f32>::new(rel, normals, &self.dirs),
            TriangleSetup::<f64>::new(rel, normals, &self.dirs),
        ) {
            (Some(a), Some(b)) => Some((centre, a, b)),
            _ => None,
        };
        self.setup.is_some()
    }

    fn row(&mut self, _: usize, _: &Polygon, row: &Row) -> Option<CompareRow> {
        let ((xc, yc), s32, s64) = self.setup.as_ref()?;
        let n = (row.x_last - row.x_first) as u32;
        let x0 = f64::from(row.x_first) + 0.5 - xc;
        let y = f64::from(row.y) + 0.5 - yc;
        let reference = [Shader::PhongPixel];
        let all: &[Shader] = &COLUMNS;
        let light = RowAt { d: 0, x0, y, n };
        let half = RowAt { d: 1, ..light };
        let shaded = shade_row(s32, light, &self.prep32, all, &mut self.out32)
            .zip(shade_row(
                s64,
                light,
                &self.prep64,
                &reference,
                &mut self.out64,
            ))
            .zip(shade_row(
                s32,
                half,
                &self.prep32,
                &COLUMNS[..],
                &mut self.spec32,
            ))
            .zip(shade_row(
                s64,
                half,
                &self.prep64,
                &reference,
                &mut self.spec64,
            ));
        let Some((((d32, _), h32), _)) = shaded else {
            self.stats.dropped_rows += 1;
            return None;
        };
        let len = n as usize + 1;
        let levels = self.row_levels(s32, &h32, half);
        let (out32, out64, spec32, spec64) = (&self.out32, &self.out64, &self.spec32, &self.spec64);
        let powers = &self.powers;
        let stats = &mut self.stats;
        let (mut skip_code, mut squared_levels) = (None, Vec::new());
        if n >= 1 {
            stats.spans += 1;
            stats.adaptive_gouraud += u64::from(d32.choice == Choice::Gouraud);
            // The δ test on N·H, and what the power does to it: Gouraud of N·H (the
            // δ test's alternative: the linear N·H, power per pixel) against
            // corrected Euler's levels of (N·H)^s.
            let ce = &levels[index(super::render::CORRECTED_EULER)];
            let lin = &spec32[index(Shader::Span(Method::Gouraud))];
            for (k, pt) in powers.iter().enumerate() {
                let same = lin.iter().zip(ce.iter()).all(|(a, c)| {
                    level(&power(Shader::Span(Method::Euler), f64::from(*a), pt)) == c[k + 1]
                });
                let dc = &mut stats.specular_delta[k];
                if h32.choice == Choice::Gouraud {
                    dc.gouraud += 1;
                    dc.gouraud_but_differ += u64::from(!same);
                } else {
                    dc.corrected_but_same += u64::from(same);
                }
            }
            if let (true, Some(span)) = (self.opts.skip_study, &h32.span) {
                skip_code = skip::count_row(span, out32, spec32, &mut stats.skip);
                squared_levels = squared::count_row(span, spec32, &mut stats.squared);
            }
        }
        let mut picture = Vec::new();
        if self.opts.pictures {
            let (ka, kd, ks) = PICTURE_LOOK;
            let pt = &powers[self.opts.shininess.min(SHININESS.len() - 1)];
            for (c, &sh) in COLUMNS.iter().enumerate() {
                picture.push(
                    (0..len)
                        .map(|j| {
                            let (dv, sv) = if c == 0 {
                                (out64[0][j], power(Shader::PhongPixel, spec64[0][j], pt))
                            } else {
                                let sv = specular_value(sh, &spec32[c], s32, &h32, half, j, pt);
                                (f64::from(out32[c][j]), sv)
                            };
                            level(&(ka + kd * dv.max(0.0) + ks * sv))
                        })
                        .collect(),
                );
            }
        }
        Some(CompareRow {
            levels,
            picture,
            skip: skip_code,
            squared: squared_levels,
        })
    }

    fn store(&mut self, r: &CompareRow, j: usize, pixel: usize) {
        for (c, l) in r.levels.iter().enumerate() {
            for (k, channel) in self.levels.iter_mut().enumerate() {
                channel[c][pixel] = Some(l[j][k]);
            }
        }
        for (c, p) in r.picture.iter().enumerate() {
            self.picture[c][pixel] = Some(p[j]);
        }
        if let (Some(code), Some(m)) = (r.skip, self.skip_map.get_mut(pixel)) {
            *m = Some(code);
        }
        if let (Some(l), Some(m)) = (r.squared.get(j), self.squared_map.get_mut(pixel)) {
            *m = Some(*l);
        }
    }
}

/// The specular value (after the power) of shader `sh` at pixel `j` of the row `at`.
fn specular_value(
    sh: Shader,
    base: &[f32],
    s: &TriangleSetup<f32>,
    info: &RowInfo<f32>,
    at: RowAt,
    j: usize,
    pt: &PowerTable,
) -> f64 {
    let RowAt { x0, y, n, .. } = at;
    match sh {
        // Behrens: the exact intensity at the span's edges, linear between.
        Shader::Span(Method::Gouraud) => {
            let (a, b) = (
                power(sh, f64::from(info.edges.0), pt),
                power(sh, f64::from(info.edges.1), pt),
            );
            if n == 0 {
                a
            } else {
                a + (b - a) * (j as f64 / f64::from(n))
            }
        }
        // Gouraud: the vertex intensities interpolated.
        Shader::VertexGouraud => {
            let d = &s.dirs[1];
            let powered = d.vertex.map(|v| power(sh, f64::from(v), pt));
            let (x, y) = ((x0 + j as f64) as f32, y as f32);
            s.lambda
                .iter()
                .zip(&powered)
                .map(|(l, v)| f64::from(l.at(&x, &y)) * v)
                .sum()
        }
        _ => power(sh, f64::from(base[j]), pt),
    }
}

/// The comparison over one torus.
#[derive(Clone, Debug)]
pub struct CompareResult {
    /// Polygons (quads) of the torus.
    pub polygons: u32,
    /// Merged statistics.
    pub stats: CompareStats,
}

/// Runs the comparison on every paper torus over `exp.frames` frames, in parallel;
/// `tick` is called once per finished frame.
pub fn run(exp: &super::experiment::Experiment, tick: &(dyn Fn() + Sync)) -> Vec<CompareResult> {
    use rayon::prelude::*;
    let scene = exp.scene();
    crate::raster::mesh::paper_tori()
        .iter()
        .map(|&(polygons, ring, tube)| {
            let mesh = exp.mesh(ring, tube);
            let stats = (0..exp.frames)
                .into_par_iter()
                .map(|f| {
                    let opts = CompareOptions {
                        skip_study: f % SKIP_EVERY == 0,
                        ..CompareOptions::default()
                    };
                    let s = render_compare(&mesh, &scene, f, opts).stats;
                    tick();
                    s
                })
                .reduce(CompareStats::default, |mut a, b| {
                    a.merge(&b);
                    a
                });
            CompareResult { polygons, stats }
        })
        .collect()
}
