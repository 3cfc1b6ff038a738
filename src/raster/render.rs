//! Rendering one frame of a rotating torus and measuring every method against Phong.
//!
//! The stages, in order: rotate the mesh (glam), project orthographically, cull back
//! faces, scan-convert each quad ([`super::scan`]), and per row: normalize the edge
//! normals, set up the [`Span`] from the first to the last covered pixel, shade it with
//! every method through the crate's generic code in `f32`, quantize to 8 bits (§6),
//! depth-test and store the levels per pixel. The statistics of Tables 1 and 2 are then
//! taken over the visible pixels (Table 2) and over every drawn row (Table 1).

use super::mesh::Mesh;
use super::scan::{rows, Row, ScreenVertex};
use crate::adaptive::Choice;
use crate::method::Prepared;
use crate::quantize::level;
use crate::scalar::Scalar;
use crate::{BigRational, Method, Span, Vec3};
use glam::{Mat3, Vec3 as G3};

pub use super::shader::Shader;

/// The columns of Tables 1–2: the paper's span methods and the second source's, and
/// classic vertex Gouraud; Phong first (the reference).
pub const COLUMNS: [Shader; 10] = [
    Shader::Span(Method::Phong),
    Shader::Span(Method::Duff),
    Shader::Span(Method::SymmetricPhong),
    Shader::Span(Method::Gouraud),
    Shader::VertexGouraud,
    Shader::Span(Method::Euler),
    Shader::Span(Method::CorrectedEuler),
    Shader::Span(Method::Adaptive),
    Shader::Span(Method::Angular),
    Shader::Span(Method::AngularTable(crate::method::SOURCE_TABLE)),
];

/// The position of `sh` in [`COLUMNS`].
///
/// # Panics
/// If `sh` is not a column of the tables.
pub fn index(sh: Shader) -> usize {
    COLUMNS
        .iter()
        .position(|s| *s == sh)
        .expect("a column of Tables 1-2")
}

/// The fixed scene of the experiment.
#[derive(Clone, Debug)]
pub struct Scene {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Pixels per world unit of the orthographic projection.
    pub scale: f32,
    /// Unit light direction (towards the light), in view space.
    pub light: G3,
    /// Unit view direction (towards the viewer): +z.
    pub view: G3,
    /// Diffuse coefficient `K_d` (intensity = `K_d·N·L`).
    pub kd: f32,
    /// Rotation per frame about x, y and z, in degrees.
    pub rates_deg: G3,
}

impl Scene {
    /// The default scene for a `width × height` image: light from the upper left
    /// front, `normalize(−1, 1, 2)`; `K_d = 1`; rotation 1.8°, 1.1° and 0.7° per frame
    /// about x, y and z; a scale that fits a torus of outer radius `outer` with 5 %
    /// margin.
    pub fn new(width: u32, height: u32, outer: f32) -> Scene {
        let scale = 0.95 * 0.5 * (width.min(height) as f32) / outer;
        Scene {
            width,
            height,
            scale,
            light: G3::new(-1.0, 1.0, 2.0).normalize(),
            view: G3::Z,
            kd: 1.0,
            rates_deg: G3::new(1.8, 1.1, 0.7),
        }
    }

    /// The rotation of frame `f`: about x, then y, then z.
    pub fn rotation(&self, f: u32) -> Mat3 {
        let a = self.rates_deg * (f as f32).to_radians();
        Mat3::from_rotation_z(a.z) * Mat3::from_rotation_y(a.y) * Mat3::from_rotation_x(a.x)
    }

    /// The half vector `H = normalize(L + V)` for specular light.
    pub fn half(&self) -> G3 {
        (self.light + self.view).normalize()
    }
}

/// Per-column accumulators of Table 2.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Deviation {
    /// Visible pixels counted.
    pub pixels: u64,
    /// Sum of |level − Phong level|.
    pub sum: u64,
    /// Maximum |level − Phong level|.
    pub max: u32,
}

impl Deviation {
    /// Mean deviation in 8-bit levels.
    pub fn mean(&self) -> f64 {
        if self.pixels == 0 {
            0.0
        } else {
            self.sum as f64 / self.pixels as f64
        }
    }

    /// Counts one pixel whose level is `a` where the reference's is `b`.
    pub(crate) fn add(&mut self, a: u8, b: u8) {
        let x = u32::from(a.abs_diff(b));
        self.pixels += 1;
        self.sum += u64::from(x);
        self.max = self.max.max(x);
    }

    pub(crate) fn merge(&mut self, o: &Deviation) {
        self.pixels += o.pixels;
        self.sum += o.sum;
        self.max = self.max.max(o.max);
    }
}

/// Per-row accumulators of Table 1.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RowStats {
    /// Rows drawn (with at least two pixels, so that a span exists).
    pub rows: u64,
    /// Single-pixel rows (no span: every method gives the exact edge value).
    pub single_pixel_rows: u64,
    /// Rows where span Gouraud and corrected Euler give the same levels at every pixel.
    pub gouraud_eq_corrected: u64,
    /// Rows where span Gouraud and Phong give the same levels at every pixel (the
    /// paper's text: "the difference of Phong and Gouraud … truncated").
    pub gouraud_eq_phong: u64,
    /// Rows the δ test of eq. 24 gives to Gouraud.
    pub predicted_gouraud: u64,
    /// … of which Gouraud and corrected Euler differ somewhere (false "same").
    pub predicted_gouraud_but_differ: u64,
    /// Rows the δ test gives to corrected Euler although both give the same levels.
    pub predicted_corrected_but_same: u64,
}

impl RowStats {
    fn merge(&mut self, o: &RowStats) {
        self.rows += o.rows;
        self.single_pixel_rows += o.single_pixel_rows;
        self.gouraud_eq_corrected += o.gouraud_eq_corrected;
        self.gouraud_eq_phong += o.gouraud_eq_phong;
        self.predicted_gouraud += o.predicted_gouraud;
        self.predicted_gouraud_but_differ += o.predicted_gouraud_but_differ;
        self.predicted_corrected_but_same += o.predicted_corrected_but_same;
    }
}

/// Agreement of the `f32` pipeline with the exact one (exact mode).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ExactCheck {
    /// Span pixels compared per column.
    pub pixels: u64,
    /// Per column: pixels whose `f32` level differs from the exact level.
    pub mismatches: Vec<u64>,
    /// … of which the exact value lies within the column's float bound of a level
    /// boundary (so rounding explains the difference).
    pub explained: Vec<u64>,
}

impl ExactCheck {
    fn merge(&mut self, o: &ExactCheck) {
        self.pixels += o.pixels;
        if self.mismatches.is_empty() {
            self.mismatches = vec![0; o.mismatches.len()];
            self.explained = vec![0; o.explained.len()];
        }
        for (a, b) in self.mismatches.iter_mut().zip(&o.mismatches) {
            *a += b;
        }
        for (a, b) in self.explained.iter_mut().zip(&o.explained) {
            *a += b;
        }
    }
}

/// Everything measured over some frames.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Stats {
    /// Per column of [`COLUMNS`]: deviation from Phong.
    pub deviation: Vec<Deviation>,
    /// Table 1.
    pub rows: RowStats,
    /// Visible pixels per frame, summed.
    pub pixels: u64,
    /// Frames rendered.
    pub frames: u64,
    /// Exact mode, when asked for.
    pub exact: Option<ExactCheck>,
}

impl Stats {
    /// Adds `o` into `self`.
    pub fn merge(&mut self, o: &Stats) {
        if self.deviation.is_empty() {
            self.deviation = vec![Deviation::default(); o.deviation.len()];
        }
        for (a, b) in self.deviation.iter_mut().zip(&o.deviation) {
            a.merge(b);
        }
        self.rows.merge(&o.rows);
        self.pixels += o.pixels;
        self.frames += o.frames;
        if let Some(e) = &o.exact {
            self.exact.get_or_insert_with(ExactCheck::default).merge(e);
        }
    }
}

/// One rendered frame: per-pixel depth and, per column, the 8-bit diffuse level
/// (`None` where no polygon is visible).
#[derive(Clone, Debug)]
pub struct Frame {
    /// Width.
    pub width: u32,
    /// Height.
    pub height: u32,
    /// Per column, per pixel (row-major): the level, if covered.
    pub levels: Vec<Vec<Option<u8>>>,
    /// Per column, per pixel: the specular value `max(0, N·H)` by the same method,
    /// before the power (for pictures).
    pub specular: Vec<Vec<f32>>,
    /// Per pixel: how many times a polygon wrote it (before the depth test).
    pub writes: Vec<u32>,
    /// The statistics of this frame.
    pub stats: Stats,
}

fn vec3(v: G3) -> Vec3<f32> {
    Vec3::new(v.x, v.y, v.z)
}

/// What one row's span produces for every column.
struct RowShade {
    levels: Vec<Vec<u8>>,
    specular: Vec<Vec<f32>>,
}

/// Shades a row's span with every column in `f32`; `None` if the normals are
/// unusable (zero after interpolation).
fn shade_row(
    scene: &Scene,
    row: &Row,
    prep: &Prepared<f32>,
    want_specular: bool,
) -> Option<(RowShade, RowExtra)> {
    let na = row.left.normal.try_normalize()?;
    let nb = row.right.normal.try_normalize()?;
    let n = (row.x_last - row.x_first) as u32;
    let cols = COLUMNS.len();
    let mut levels = vec![Vec::with_capacity(n as usize + 1); cols];
    let mut specular = vec![Vec::new(); cols];
    let kd = scene.kd;
    if n == 0 {
        // One pixel: its normal is the edge normal, every method gives p_a.
        let p = na.dot(scene.light);
        let h = na.dot(scene.half()).max(0.0);
        for c in 0..cols {
            let v = if COLUMNS[c] == Shader::VertexGouraud {
                row.left.intensity
            } else {
                p
            };
            levels[c].push(level(&(kd * v)));
            if want_specular {
                specular[c].push(h);
            }
        }
        return Some((RowShade { levels, specular }, RowExtra::single()));
    }
    let span = Span::new(vec3(na), vec3(nb), vec3(scene.light), n).ok()?;
    let mut out = vec![0.0f32; n as usize + 1];
    let mut decision = Choice::CorrectedEuler;
    for (c, col) in COLUMNS.iter().enumerate() {
        match col {
            Shader::Span(m) => {
                if let Some(d) = m.run(&span, prep, &mut out).ok()? {
                    decision = d.choice;
                }
            }
            _ => {
                // Classic Gouraud: the vertex intensities, interpolated down the
                // polygon's edges and along the row.
                let (a, b) = (row.left.intensity, row.right.intensity);
                for (i, o) in out.iter_mut().enumerate() {
                    *o = a + (b - a) * (i as f32 / n as f32);
                }
            }
        }
        levels[c].extend(out.iter().map(|v| level(&(kd * v))));
    }
    if want_specular {
        let span_h = Span::new(vec3(na), vec3(nb), vec3(scene.half()), n).ok()?;
        for (c, col) in COLUMNS.iter().enumerate() {
            // Classic Gouraud of N·H: vertex values are not kept per vertex here, so
            // the span's edge values (exact) are interpolated.
            let m = match col {
                Shader::Span(m) => *m,
                _ => Method::Gouraud,
            };
            m.run(&span_h, prep, &mut out).ok()?;
            specular[c].extend(out.iter().map(|v| v.max(0.0)));
        }
    }
    let extra = RowExtra {
        single: false,
        decision,
        span: Some(span),
    };
    Some((RowShade { levels, specular }, extra))
}

/// What Table 1 and the exact mode need of a row beyond its levels.
struct RowExtra {
    single: bool,
    decision: Choice,
    span: Option<Span<f32>>,
}

impl RowExtra {
    fn single() -> Self {
        RowExtra {
            single: true,
            decision: Choice::Gouraud,
            span: None,
        }
    }
}

/// The indices of Phong, span Gouraud and corrected Euler in [`COLUMNS`].
const PHONG: usize = 0;
const GOURAUD: usize = 3;
const CORRECTED: usize = 6;

/// Exact levels of a row's span for every span column, for the exact mode: the same
/// span, its `f32` inputs converted exactly (they are within 2^-17 of unit length).
fn exact_row(span: &Span<f32>, prep: &Prepared<BigRational>, got: &[Vec<u8>], check: &mut ExactCheck) {
    let tol = BigRational::new(1.into(), (1u64 << 16).into());
    let (Some(na), Some(nb), Some(l)) = (span.na.cast(), span.nb.cast(), span.l.cast()) else {
        return;
    };
    let Ok(exact) = Span::<BigRational>::with_tolerance(na, nb, l, span.n, &tol) else {
        return;
    };
    let cols = COLUMNS.len();
    if check.mismatches.is_empty() {
        check.mismatches = vec![0; cols];
        check.explained = vec![0; cols];
    }
    check.pixels += u64::from(span.n) + 1;
    let mut out = vec![BigRational::from_i64(0); span.len()];
    let kd = &prep.kd;
    let u = f32::unit_roundoff();
    let q_min = (0..=exact.n)
        .map(|i| exact.q_at(i).to_f64())
        .fold(f64::INFINITY, f64::min);
    for (c, col) in COLUMNS.iter().enumerate() {
        let Shader::Span(m) = col else { continue };
        if m.run(&exact, prep, &mut out).is_err() {
            return;
        }
        // Phong-valued pixels: the exact level of p/√q (for q ≈ 1 edges the span's E
        // is within 2^-16 of 1; p/√q is still what the f32 code computes).
        let levels = m.exact_levels(&exact, &out, kd);
        // Without a derived bound, no mismatch counts as explained.
        let bound = crate::tolerance::bound(*m, exact.n, q_min, u)
            .map_or(-1.0, |b| b * 255.0 + 8.0 * u * 255.0);
        for (i, (&g, e)) in got[c].iter().zip(&levels).enumerate() {
            // A level the exact run cannot decide is not counted either way.
            if e.is_some_and(|e| e != g) {
                check.mismatches[c] += 1;
                // Distance of the exact scaled value from the nearest level boundary.
                let v = if m.is_phong_valued() {
                    use crate::scalar::Real;
                    (exact.p_at(i as u32) / exact.q_at(i as u32).sqrt()).to_f64()
                } else {
                    out[i].to_f64()
                } * 255.0;
                if (v - v.round()).abs() <= bound {
                    check.explained[c] += 1;
                }
            }
        }
    }
}

/// Options of [`render`].
#[derive(Clone, Copy, Debug, Default)]
pub struct RenderOptions {
    /// Also evaluate every span exactly and compare levels (slow).
    pub exact: bool,
    /// Also shade `N·H` for pictures.
    pub specular: bool,
}

/// The mesh's vertices rotated by `rot` and projected orthographically into `scene`'s
/// image, with their rotated normals and vertex (Gouraud) intensities.
pub fn project(mesh: &Mesh, scene: &Scene, rot: &Mat3) -> Vec<ScreenVertex> {
    let (cx, cy) = (scene.width as f32 / 2.0, scene.height as f32 / 2.0);
    mesh.positions
        .iter()
        .zip(&mesh.normals)
        .map(|(p, n)| {
            let p = *rot * *p;
            let n = *rot * *n;
            ScreenVertex {
                x: cx + scene.scale * p.x,
                y: cy - scene.scale * p.y,
                z: p.z,
                normal: n,
                intensity: n.dot(scene.light),
            }
        })
        .collect()
}

/// Renders frame `f` of `mesh` in `scene`.
pub fn render(mesh: &Mesh, scene: &Scene, f: u32, opts: RenderOptions) -> Frame {
    let (w, h) = (scene.width, scene.height);
    let npix = (w * h) as usize;
    let cols = COLUMNS.len();
    let rot = scene.rotation(f);
    let verts = project(mesh, scene, &rot);
    let table = Method::AngularTable(crate::method::SOURCE_TABLE);
    let prep = Prepared::new(table, scene.kd).expect("256 entries");
    let exact_prep = opts.exact.then(|| {
        let kd = BigRational::from_float(scene.kd).expect("finite");
        Prepared::new(table, kd).expect("256 entries")
    });
    let mut depth = vec![f32::NEG_INFINITY; npix];
    let mut levels = vec![vec![None; npix]; cols];
    let mut specular = if opts.specular {
        vec![vec![0.0f32; npix]; cols]
    } else {
        Vec::new()
    };
    let mut writes = vec![0u32; npix];
    let mut rows_stats = RowStats::default();
    let mut exact = opts.exact.then(ExactCheck::default);
    for q in &mesh.quads {
        let poly: Vec<ScreenVertex> = q.iter().map(|&i| verts[i as usize]).collect();
        // Back-face culling: the face normal (from the rotated positions) must face +z.
        let p: Vec<G3> = q
            .iter()
            .map(|&i| rot * mesh.positions[i as usize])
            .collect();
        if (p[2] - p[0]).cross(p[3] - p[1]).z <= 0.0 {
            continue;
        }
        rows(&poly, w, h, |row| {
            let Some((shade, extra)) = shade_row(scene, &row, &prep, opts.specular) else {
                return;
            };
            if extra.single {
                rows_stats.single_pixel_rows += 1;
            } else {
                rows_stats.rows += 1;
                let same_gc = shade.levels[GOURAUD] == shade.levels[CORRECTED];
                let same_gp = shade.levels[GOURAUD] == shade.levels[PHONG];
                rows_stats.gouraud_eq_corrected += u64::from(same_gc);
                rows_stats.gouraud_eq_phong += u64::from(same_gp);
                if extra.decision == Choice::Gouraud {
                    rows_stats.predicted_gouraud += 1;
                    rows_stats.predicted_gouraud_but_differ += u64::from(!same_gc);
                } else {
                    rows_stats.predicted_corrected_but_same += u64::from(same_gc);
                }
                if let (Some(check), Some(span), Some(p)) =
                    (exact.as_mut(), extra.span.as_ref(), exact_prep.as_ref())
                {
                    exact_row(span, p, &shade.levels, check);
                }
            }
            let n = row.x_last - row.x_first;
            for (i, x) in (row.x_first..=row.x_last).enumerate() {
                let idx = (row.y as u32 * w + x as u32) as usize;
                writes[idx] += 1;
                let t = if n == 0 { 0.0 } else { i as f32 / n as f32 };
                let z = row.left.z + t * (row.right.z - row.left.z);
                if z > depth[idx] {
                    depth[idx] = z;
                    for c in 0..cols {
                        levels[c][idx] = Some(shade.levels[c][i]);
                        if opts.specular {
                            specular[c][idx] = shade.specular[c][i];
                        }
                    }
                }
            }
        });
    }
    let mut deviation = vec![Deviation::default(); cols];
    let mut pixels = 0u64;
    for (idx, phong) in levels[PHONG].iter().enumerate() {
        let Some(p) = *phong else {
            continue;
        };
        pixels += 1;
        for (column, dev) in levels.iter().zip(deviation.iter_mut()) {
            let l = column[idx].expect("every column writes the same pixels");
            let d = u32::from(l.abs_diff(p));
            dev.pixels += 1;
            dev.sum += u64::from(d);
            dev.max = dev.max.max(d);
        }
    }
    Frame {
        width: w,
        height: h,
        levels,
        specular,
        writes,
        stats: Stats {
            deviation,
            rows: rows_stats,
            pixels,
            frames: 1,
            exact,
        },
    }
}
