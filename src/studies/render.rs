//! Rendering one frame of a rotating torus and measuring every method against Phong.
//!
//! The stages, in order: rotate the mesh (glam), project orthographically, cull back
//! faces, scan-convert each quad ([`crate::raster::scan`]), and per row: normalize the edge
//! normals, set up the [`Span`] from the first to the last covered pixel, shade it with
//! every method through the crate's generic code in `f32`, quantize to 8 bits (§6),
//! depth-test and store the levels per pixel. The statistics of Tables 1 and 2 are then
//! taken over the visible pixels (Table 2) and over every drawn row (Table 1).

use crate::adaptive::Choice;
use crate::method::Prepared;
use crate::quantize::level;
use crate::raster::frame::{draw, polygons, Polygon, Shading, Split};
use crate::raster::mesh::Mesh;
use crate::raster::scan::Row;
pub use crate::raster::scene::{project, Scene};
use crate::raster::stats::deviations;
pub use crate::raster::stats::Deviation;
use crate::scalar::Scalar;
use crate::{BigRational, Method, Span, Vec3};
use glam::Vec3 as G3;

pub use crate::raster::shader::Shader;

/// Phong per pixel along the span: the reference every column is measured against.
pub const PHONG: Shader = Shader::Span(Method::Phong);
/// Span Gouraud, which Table 1 compares with Phong and with corrected Euler.
pub const GOURAUD: Shader = Shader::Span(Method::Gouraud);
/// Plain Euler (eqs. 12–13), a column of Table 2.
pub const EULER: Shader = Shader::Span(Method::Euler);
/// Corrected Euler (eqs. 16–17), the paper's method ([`Method::PAPER`]).
pub const CORRECTED_EULER: Shader = Shader::Span(Method::PAPER);

/// The columns of Tables 1–2, read from the catalogue: every span method of the
/// paper and of the second source (not [`Method::is_related`]: the
/// related methods are the comparison's), in [`Method::ALL`]'s order — Phong first,
/// the reference — and after span Gouraud classic vertex Gouraud, the polygon form of
/// it (`raster::shader::POLYGON`) that a row's vertex intensities give. Code finds a
/// column by its shader ([`index`]), never by its position; a method added to the
/// catalogue in those families is a column by itself.
pub static COLUMNS: std::sync::LazyLock<Vec<Shader>> = std::sync::LazyLock::new(|| {
    let vertex_gouraud_after = crate::raster::shader::POLYGON
        .iter()
        .find(|p| p.shader == Shader::VertexGouraud)
        .and_then(|p| p.after);
    let mut c = Vec::new();
    for m in Method::ALL {
        if m.is_related() {
            continue;
        }
        c.push(Shader::Span(m));
        if Some(m) == vertex_gouraud_after {
            c.push(Shader::VertexGouraud);
        }
    }
    c
});

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

/// Per-row accumulators of Table 1.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RowStats {
    /// Rows drawn (with at least two pixels, so that a span exists).
    pub rows: u64,
    /// Single-pixel rows (no span: every method gives the exact edge value).
    pub single_pixel_rows: u64,
    /// Rows where span Gouraud and corrected Euler give the same levels at every pixel.
    pub gouraud_eq_corrected: u64,
    /// Rows where span Gouraud and Phong give the same 8-bit levels at every pixel,
    /// `level(K_d·Ph_i) = level(K_d·G_i)`. This is *not* the paper's text, which
    /// truncates the difference; that is [`RowStats::truncated_difference_zero`], and
    /// the two differ (errata A5).
    pub gouraud_eq_phong: u64,
    /// Rows where the paper's text criterion holds at every pixel: "the difference of
    /// Phong and Gouraud intensities was multiplied with 255 and then truncated",
    /// `trunc(255·K_d·(Ph_i − G_i)) = 0`, i.e. `|255·K_d·(Ph_i − G_i)| < 1`.
    pub truncated_difference_zero: u64,
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
        self.truncated_difference_zero += o.truncated_difference_zero;
        self.predicted_gouraud += o.predicted_gouraud;
        self.predicted_gouraud_but_differ += o.predicted_gouraud_but_differ;
        self.predicted_corrected_but_same += o.predicted_corrected_but_same;
    }
}

/// The readings of Table 1 (errata A5): what "scan lines which could have been
/// computed with Gouraud" counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reading {
    /// The paper's text: `trunc(255·K_d·(Ph_i − G_i)) = 0` at every pixel.
    Text,
    /// The caption: Gouraud and corrected Euler on the same 8-bit level at every pixel.
    Caption,
    /// Gouraud and Phong on the same 8-bit level at every pixel.
    PhongLevels,
    /// The δ test of eq. 24 says Gouraud.
    Delta,
}

impl Reading {
    /// Every reading, the text first.
    pub const ALL: [Reading; 4] = [
        Reading::Text,
        Reading::Caption,
        Reading::PhongLevels,
        Reading::Delta,
    ];

    /// A short name (`text`, `caption`, `phong-levels`, `delta`).
    pub fn name(self) -> &'static str {
        match self {
            Reading::Text => "text",
            Reading::Caption => "caption",
            Reading::PhongLevels => "phong-levels",
            Reading::Delta => "delta",
        }
    }

    /// What the reading counts, for table headers.
    pub fn label(self) -> &'static str {
        match self {
            Reading::Text => "text: trunc(255(Ph − G)) = 0",
            Reading::Caption => "caption: levels G = CE",
            Reading::PhongLevels => "levels G = Ph",
            Reading::Delta => "δ test (eq. 24) says G",
        }
    }

    /// Rows of at least two pixels on which the reading holds.
    pub fn rows(self, t: &RowStats) -> u64 {
        match self {
            Reading::Text => t.truncated_difference_zero,
            Reading::Caption => t.gouraud_eq_corrected,
            Reading::PhongLevels => t.gouraud_eq_phong,
            Reading::Delta => t.predicted_gouraud,
        }
    }

    /// The percentage of rows on which the reading holds; with `single`, the
    /// one-pixel rows are counted too (every reading holds on them: every method gives
    /// the exact edge value).
    pub fn percent(self, t: &RowStats, single: bool) -> f64 {
        let extra = if single { t.single_pixel_rows } else { 0 };
        100.0 * (self.rows(t) + extra) as f64 / (t.rows + extra).max(1) as f64
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

mod row;
pub use row::truncated_difference_is_zero;
use row::{exact_row, shade_row, RowShade};

/// Options of [`render`].
#[derive(Clone, Copy, Debug, Default)]
pub struct RenderOptions {
    /// Also evaluate every span exactly and compare levels (slow).
    pub exact: bool,
    /// Also shade `N·H` for pictures.
    pub specular: bool,
}

/// Renders frame `f` of `mesh` in `scene` through the frame loop
/// ([`crate::raster::frame::draw`]), the paper's quads, every column of [`COLUMNS`] per row.
pub fn render(mesh: &Mesh, scene: &Scene, f: u32, opts: RenderOptions) -> Frame {
    let (w, h) = (scene.width, scene.height);
    let npix = (w * h) as usize;
    let cols = COLUMNS.len();
    let table = Method::AngularTable(crate::method::SOURCE_TABLE);
    let exact_prep = opts.exact.then(|| {
        let kd = BigRational::from_float(scene.kd).expect("finite");
        Prepared::new(table, kd).expect("256 entries")
    });
    let mut shading = Tables {
        scene,
        opts,
        prep: Prepared::new(table, scene.kd).expect("256 entries"),
        exact_prep,
        levels: vec![vec![None; npix]; cols],
        specular: if opts.specular {
            vec![vec![0.0f32; npix]; cols]
        } else {
            Vec::new()
        },
        rows: RowStats::default(),
        exact: opts.exact.then(ExactCheck::default),
    };
    let polys = polygons(mesh, scene, f, Split::Quads);
    let writes = draw(w, h, &polys, &mut shading);
    let phong = index(PHONG);
    let deviation = deviations(&shading.levels, phong);
    let pixels = shading.levels[phong].iter().flatten().count() as u64;
    Frame {
        width: w,
        height: h,
        levels: shading.levels,
        specular: shading.specular,
        writes,
        stats: Stats {
            deviation,
            rows: shading.rows,
            pixels,
            frames: 1,
            exact: shading.exact,
        },
    }
}

/// The [`Shading`] of Tables 1–2: every column's levels per pixel, Table 1 per row.
struct Tables<'a> {
    scene: &'a Scene,
    opts: RenderOptions,
    prep: Prepared<f32>,
    exact_prep: Option<Prepared<BigRational>>,
    levels: Vec<Vec<Option<u8>>>,
    specular: Vec<Vec<f32>>,
    rows: RowStats,
    exact: Option<ExactCheck>,
}

impl Shading for Tables<'_> {
    type Row = RowShade;

    fn row(&mut self, _: usize, _: &Polygon, row: &Row) -> Option<RowShade> {
        let (shade, extra) = shade_row(self.scene, row, &self.prep, self.opts.specular)?;
        let st = &mut self.rows;
        if extra.single {
            st.single_pixel_rows += 1;
        } else {
            st.rows += 1;
            let gouraud = &shade.levels[index(GOURAUD)];
            let same_gc = *gouraud == shade.levels[index(CORRECTED_EULER)];
            let same_gp = *gouraud == shade.levels[index(PHONG)];
            st.gouraud_eq_corrected += u64::from(same_gc);
            st.gouraud_eq_phong += u64::from(same_gp);
            st.truncated_difference_zero += u64::from(extra.text_same);
            if extra.decision == Choice::Gouraud {
                st.predicted_gouraud += 1;
                st.predicted_gouraud_but_differ += u64::from(!same_gc);
            } else {
                st.predicted_corrected_but_same += u64::from(same_gc);
            }
            if let (Some(check), Some(span), Some(p)) = (
                self.exact.as_mut(),
                extra.span.as_ref(),
                self.exact_prep.as_ref(),
            ) {
                exact_row(span, p, &shade.levels, check);
            }
        }
        Some(shade)
    }

    fn store(&mut self, shade: &RowShade, i: usize, pixel: usize) {
        for (c, column) in self.levels.iter_mut().enumerate() {
            column[pixel] = Some(shade.levels[c][i]);
        }
        if self.opts.specular {
            for (c, column) in self.specular.iter_mut().enumerate() {
                column[pixel] = shade.specular[c][i];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_are_span_methods_and_vertex_gouraud() {
        assert_eq!(COLUMNS[0], PHONG, "the reference comes first");
        for c in COLUMNS.iter() {
            assert!(
                matches!(c, Shader::Span(_) | Shader::VertexGouraud),
                "{c:?}: render_row shades span methods and vertex Gouraud only"
            );
        }
    }

    #[test]
    fn the_text_criterion_is_not_equal_levels() {
        // 0.5019 and 0.5021 straddle the level boundary 128/255 = 0.50196…: different
        // levels, but their difference truncates to 0.
        let (p, g) = ([0.5021f32, 0.3], [0.5019f32, 0.3]);
        assert_ne!(level(&p[0]), level(&g[0]));
        assert!(truncated_difference_is_zero(&p, &g, 1.0));
        // More than a level apart fails it; K_d scales the difference.
        let far = [0.5019f32 + 1.1 / 255.0, 0.3];
        assert!(!truncated_difference_is_zero(&far, &g, 1.0));
        assert!(truncated_difference_is_zero(&far, &g, 0.9));
    }

    #[test]
    fn every_reading_counts_one_pixel_rows_as_passing() {
        let t = RowStats {
            rows: 8,
            single_pixel_rows: 2,
            truncated_difference_zero: 6,
            gouraud_eq_corrected: 4,
            gouraud_eq_phong: 3,
            predicted_gouraud: 5,
            ..RowStats::default()
        };
        let want = [
            (6, 75.0, 80.0),
            (4, 50.0, 60.0),
            (3, 37.5, 50.0),
            (5, 62.5, 70.0),
        ];
        for (r, (rows, without, with)) in Reading::ALL.into_iter().zip(want) {
            assert_eq!(r.rows(&t), rows, "{}", r.name());
            assert!(
                (r.percent(&t, false) - without).abs() < 1e-12,
                "{}",
                r.name()
            );
            assert!((r.percent(&t, true) - with).abs() < 1e-12, "{}", r.name());
        }
    }
}
