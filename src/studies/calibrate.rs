//! The calibration study behind `reproduce --fit`: the scene choices the paper does
//! not state, treated as parameters within what its text allows and fitted to its 28
//! numbers (Table 2's 24 means and maxima, Table 1's 4 shares).
//!
//! **Distance.** Each of the 28 numbers gets a residual divided by its tolerance — the
//! targets of the study: a mean's relative error by 15 %, a maximum's difference by
//! 2 levels, a share's difference by 5 points — and the distance is the mean of their
//! squares. A number meets its target when its scaled residual is at most 1 (a
//! corrected-Euler maximum must be equal: below 1/2). For each rendered scene the
//! distance is taken for the Gouraud of Table 2 (span or vertex) and the reading of
//! Table 1 ([`Reading`], with or without one-pixel rows) that fit best, so the study
//! also says which reading the numbers support.
//!
//! **Search.** Coordinate descent from the start scene: each parameter in turn is set
//! to each of its values, the best scene so far is kept, and passes repeat until one
//! changes nothing (at most [`MAX_PASSES`]). Evaluations are cached.

use super::experiment::{Experiment, PaperDeviation, TorusResult, PAPER_TABLE_1, PAPER_TABLE_2};
use super::render::{index, Reading, Shader};
use crate::Method;
use std::collections::HashMap;

mod outputs;
pub use outputs::{
    describe, describe_fit, max_ratio_table, reach_table, report_md, residual_table,
    sensitivity_matrix, sensitivity_svg,
};

/// Passes of coordinate descent at most.
pub const MAX_PASSES: usize = 4;

/// A scene choice the study varies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Param {
    /// Ring segments per tube segment ([`super::experiment::Setup::ring_per_tube`]).
    RingPerTube,
    /// Tube radius `r` (the major radius stays 1).
    TubeRadius,
    /// Angle between light and view, degrees.
    LightDeg,
    /// Image side in pixels (square images; the torus spans 95 % of it).
    Size,
    /// `K_d`.
    Kd,
}

impl Param {
    /// The parameter's name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Param::RingPerTube => "ring/tube segments",
            Param::TubeRadius => "tube radius r",
            Param::LightDeg => "light angle (°)",
            Param::Size => "image side (px)",
            Param::Kd => "K_d",
        }
    }

    /// This parameter's value in `exp`.
    pub fn get(self, exp: &Experiment) -> f64 {
        match self {
            Param::RingPerTube => f64::from(exp.setup.ring_per_tube),
            Param::TubeRadius => f64::from(exp.radii.1),
            Param::LightDeg => f64::from(exp.setup.light_deg),
            Param::Size => f64::from(exp.size.0),
            Param::Kd => f64::from(exp.setup.kd),
        }
    }

    /// `exp` with this parameter set to `v`.
    pub fn set(self, exp: &Experiment, v: f64) -> Experiment {
        let mut e = exp.clone();
        match self {
            Param::RingPerTube => e.setup.ring_per_tube = v as f32,
            Param::TubeRadius => e.radii.1 = v as f32,
            Param::LightDeg => e.setup.light_deg = v as f32,
            Param::Size => e.size = (v as u32, v as u32),
            Param::Kd => e.setup.kd = v as f32,
        }
        e
    }
}

/// The parameters and the values each may take.
#[derive(Clone, Debug)]
pub struct Space {
    /// Each parameter with its values, in the order the search visits them.
    pub params: Vec<(Param, Vec<f64>)>,
    /// The visible pixels per frame (averaged over the tori) a scene must have to be
    /// eligible as the best.
    pub pixels_per_frame: (f64, f64),
}

impl Space {
    /// The studied space, within what the paper allows:
    /// - the four tessellations that divide every paper count (288, 512, 800, 1152
    ///   polygons) into whole ring × tube segments;
    /// - tube radii from a thin torus (r = 0.25) to a fat one (r = 0.8, R = 1);
    /// - the light from the view direction to 80° off it (upper left);
    /// - image sides from 190 to 260 pixels; a scene is eligible only if it renders
    ///   "about 4 million pixels for each object" over 200 frames ([`PIXELS_PER_FRAME`]);
    /// - `K_d` from 0.6 to 1.
    ///
    /// Face-averaged normals are not a parameter: on a regular torus they coincide with
    /// the analytic ones (docs/reproduction.md).
    pub fn paper() -> Space {
        Space {
            params: vec![
                (Param::RingPerTube, vec![0.125, 0.5, 2.0, 8.0]),
                (
                    Param::TubeRadius,
                    vec![0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.7, 0.8],
                ),
                (
                    Param::LightDeg,
                    vec![
                        0.0, 15.0, 30.0, 35.26, 40.0, 45.0, 50.0, 55.0, 60.0, 70.0, 80.0,
                    ],
                ),
                (
                    Param::Size,
                    vec![190.0, 200.0, 210.0, 225.0, 235.0, 245.0, 260.0],
                ),
                (Param::Kd, vec![0.6, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95, 1.0]),
            ],
            pixels_per_frame: PIXELS_PER_FRAME,
        }
    }

    /// Evaluations one pass can cost at most (each value of each parameter).
    pub fn per_pass(&self) -> usize {
        self.params.iter().map(|(_, v)| v.len()).sum()
    }
}

/// What a residual is of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A mean deviation of Table 2 (tolerance: 15 % relative).
    Mean,
    /// A maximum deviation of Table 2 (tolerance: 2 levels).
    Max,
    /// A share of Table 1 (tolerance: 5 points).
    Share,
}

/// One of the paper's 28 numbers beside ours.
#[derive(Clone, Debug, PartialEq)]
pub struct Residual {
    /// E.g. `288 Gouraud mean`.
    pub name: String,
    /// What it is.
    pub kind: Kind,
    /// The paper's value.
    pub paper: f64,
    /// Ours.
    pub ours: f64,
}

impl Residual {
    /// The residual divided by its tolerance.
    pub fn scaled(&self) -> f64 {
        match self.kind {
            Kind::Mean => (self.ours - self.paper) / (0.15 * self.paper),
            Kind::Max => (self.ours - self.paper) / 2.0,
            Kind::Share => (self.ours - self.paper) / 5.0,
        }
    }

    /// Whether the number meets its target: scaled residual at most 1, and equal for
    /// a corrected-Euler maximum.
    pub fn met(&self) -> bool {
        if self.kind == Kind::Max && self.name.contains("corrected Euler") {
            return self.ours == self.paper;
        }
        self.scaled().abs() <= 1.0
    }
}

/// The fit of one scene's results: the best Gouraud and Table 1 reading, the 28
/// residuals and the distance.
#[derive(Clone, Debug, PartialEq)]
pub struct Fit {
    /// Table 2's Gouraud: span (fence) or vertex.
    pub gouraud: Shader,
    /// Table 1's reading.
    pub reading: Reading,
    /// Whether one-pixel rows are counted in Table 1.
    pub single: bool,
    /// The 28 numbers.
    pub residuals: Vec<Residual>,
    /// Mean square of the scaled residuals.
    pub distance: f64,
}

/// The 28 residuals of `results` with the given choices.
pub fn residuals(
    results: &[TorusResult],
    gouraud: Shader,
    reading: Reading,
    single: bool,
) -> Vec<Residual> {
    let g = index(gouraud);
    let e = index(super::render::EULER);
    let ce = index(super::render::CORRECTED_EULER);
    let mut out = Vec::with_capacity(28);
    for (r, p) in results.iter().zip(PAPER_TABLE_2) {
        let d = &r.stats.deviation;
        for (col, name, PaperDeviation { mean, max }) in [
            (g, "Gouraud", p.gouraud),
            (e, "Euler", p.euler),
            (ce, "corrected Euler", p.corrected_euler),
        ] {
            out.push(Residual {
                name: format!("{} {name} mean", r.polygons),
                kind: Kind::Mean,
                paper: mean,
                ours: d[col].mean(),
            });
            out.push(Residual {
                name: format!("{} {name} max", r.polygons),
                kind: Kind::Max,
                paper: f64::from(max),
                ours: f64::from(d[col].max),
            });
        }
    }
    for (r, p) in results.iter().zip(PAPER_TABLE_1) {
        out.push(Residual {
            name: format!("{} Table 1 share", r.polygons),
            kind: Kind::Share,
            paper: p.percent,
            ours: reading.percent(&r.stats.rows, single),
        });
    }
    out
}

/// The mean square of the scaled residuals.
pub fn distance(residuals: &[Residual]) -> f64 {
    residuals.iter().map(|r| r.scaled().powi(2)).sum::<f64>() / residuals.len().max(1) as f64
}

/// The best fit of `results` over Table 2's Gouraud (span or vertex) and Table 1's
/// readings (with and without one-pixel rows).
pub fn fit(results: &[TorusResult]) -> Fit {
    let mut best: Option<Fit> = None;
    for gouraud in [Shader::Span(Method::Gouraud), Shader::VertexGouraud] {
        for reading in Reading::ALL {
            for single in [false, true] {
                let residuals = residuals(results, gouraud, reading, single);
                let distance = distance(&residuals);
                if best.as_ref().is_none_or(|b| distance < b.distance) {
                    best = Some(Fit {
                        gouraud,
                        reading,
                        single,
                        residuals,
                        distance,
                    });
                }
            }
        }
    }
    best.expect("at least one choice")
}

/// A scene of the study: the experiment and its fit.
#[derive(Clone, Debug)]
pub struct Evaluated {
    /// The scene (with the search's frame count).
    pub exp: Experiment,
    /// Its fit.
    pub fit: Fit,
    /// Visible pixels per frame, averaged over the four tori.
    pub pixels_per_frame: f64,
}

/// The paper's "about 4 million pixels were rendered for each object" over 200 frames,
/// read as 4 million ± 30 %: the visible pixels per frame a scene may have to be
/// eligible as the best.
pub const PIXELS_PER_FRAME: (f64, f64) = (14_000.0, 26_000.0);

impl Evaluated {
    /// Whether the scene's visible pixels per frame lie in `range`.
    pub fn eligible(&self, range: (f64, f64)) -> bool {
        (range.0..=range.1).contains(&self.pixels_per_frame)
    }
}

/// The outcome of [`calibrate`].
#[derive(Clone, Debug)]
pub struct Study {
    /// The start scene, evaluated.
    pub start: Evaluated,
    /// The best scene found.
    pub best: Evaluated,
    /// Every evaluated scene, in the order evaluated.
    pub log: Vec<Evaluated>,
    /// Passes run.
    pub passes: usize,
    /// For each parameter, the best scene with that parameter set to each of its values
    /// (the sensitivity of every number to that parameter).
    pub sensitivity: Vec<(Param, Vec<(f64, Fit)>)>,
}

/// A cache key for a scene: the varied parameters' values.
fn key(space: &Space, exp: &Experiment) -> Vec<u64> {
    space
        .params
        .iter()
        .map(|(p, _)| p.get(exp).to_bits())
        .collect()
}

/// Runs the study from `start` over `space`, each scene rendered for `frames` frames
/// per torus, spread over `start.frames` (every `⌈start.frames/frames⌉`-th frame);
/// `tick` is called once per rendered frame (four tori per scene).
/// Scenes whose tessellation does not divide the paper's counts are skipped; scenes
/// outside [`PIXELS_PER_FRAME`] are rendered and logged but cannot be the best.
pub fn calibrate(
    start: &Experiment,
    space: &Space,
    frames: u32,
    tick: &(dyn Fn() + Sync),
) -> Study {
    // Spread the search's frames over the start scene's rotation.
    let stride = start.frames.div_ceil(frames.max(1)).max(1);
    let mut cache: HashMap<Vec<u64>, Evaluated> = HashMap::new();
    let mut log = Vec::new();
    let mut eval = |exp: &Experiment| -> Option<Evaluated> {
        exp.setup.tori()?;
        let k = key(space, exp);
        if let Some(e) = cache.get(&k) {
            return Some(e.clone());
        }
        let exp = Experiment {
            frames,
            exact_frames: 0,
            frame_stride: stride,
            ..exp.clone()
        };
        let results = exp.run(tick);
        let frames: u64 = results.iter().map(|r| r.stats.frames).sum();
        let pixels: u64 = results.iter().map(|r| r.stats.pixels).sum();
        let e = Evaluated {
            fit: fit(&results),
            pixels_per_frame: pixels as f64 / frames.max(1) as f64,
            exp,
        };
        cache.insert(k, e.clone());
        log.push(e.clone());
        Some(e)
    };
    let first = eval(start).expect("the start scene divides the paper's counts");
    let mut best = first.clone();
    let mut passes = 0;
    while passes < MAX_PASSES {
        passes += 1;
        let mut changed = false;
        for (p, values) in &space.params {
            for &v in values {
                if let Some(e) = eval(&p.set(&best.exp, v)) {
                    if e.eligible(space.pixels_per_frame) && e.fit.distance < best.fit.distance {
                        best = e;
                        changed = true;
                    }
                }
            }
        }
        if !changed {
            break;
        }
    }
    let sensitivity = space
        .params
        .iter()
        .map(|(p, values)| {
            let row = values
                .iter()
                .filter_map(|&v| eval(&p.set(&best.exp, v)).map(|e| (v, e.fit)))
                .collect();
            (*p, row)
        })
        .collect();
    Study {
        start: first,
        best,
        log,
        passes,
        sensitivity,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::raster::stats::Deviation;
    use crate::studies::render::{RowStats, Stats, COLUMNS};

    /// Results that are exactly the paper's numbers (span Gouraud, text reading without
    /// one-pixel rows), as far as integer counts allow.
    fn paper_results() -> Vec<TorusResult> {
        PAPER_TABLE_2
            .iter()
            .zip(PAPER_TABLE_1)
            .map(|(p, t1)| {
                let mut deviation = vec![Deviation::default(); COLUMNS.len()];
                let pixels = 1_000_000u64;
                for (m, _, PaperDeviation { mean, max }) in p.methods() {
                    let col = index(Shader::Span(m));
                    deviation[col] = Deviation {
                        pixels,
                        sum: (mean * pixels as f64).round() as u64,
                        max,
                    };
                }
                let rows = 1000u64;
                TorusResult {
                    polygons: p.polygons,
                    segments: (1, 1),
                    stats: Stats {
                        deviation,
                        rows: RowStats {
                            rows,
                            truncated_difference_zero: (t1.percent * 10.0).round() as u64,
                            ..RowStats::default()
                        },
                        pixels,
                        frames: 1,
                        exact: None,
                    },
                }
            })
            .collect()
    }

    #[test]
    fn the_paper_fits_itself_with_distance_zero_and_the_text_reading() {
        let f = fit(&paper_results());
        assert!(f.distance < 1e-12, "{}", f.distance);
        assert_eq!(f.residuals.len(), 28);
        assert_eq!(f.reading, Reading::Text);
        assert!(!f.single);
        assert_eq!(f.gouraud, Shader::Span(Method::Gouraud));
        assert!(f.residuals.iter().all(Residual::met));
    }

    #[test]
    fn residuals_are_scaled_by_their_tolerances() {
        let mean = Residual {
            name: "x mean".into(),
            kind: Kind::Mean,
            paper: 2.0,
            ours: 2.6,
        };
        assert!((mean.scaled() - 2.0).abs() < 1e-12);
        assert!(!mean.met());
        let max = Residual {
            name: "800 corrected Euler max".into(),
            kind: Kind::Max,
            paper: 1.0,
            ours: 2.0,
        };
        assert!((max.scaled() - 0.5).abs() < 1e-12);
        assert!(!max.met(), "corrected Euler maxima must be equal");
        let share = Residual {
            name: "s".into(),
            kind: Kind::Share,
            paper: 50.0,
            ours: 45.0,
        };
        assert!((share.scaled() + 1.0).abs() < 1e-12 && share.met());
        assert!((distance(&[mean, share]) - 2.5).abs() < 1e-12);
    }

    #[test]
    fn a_tiny_study_runs_keeps_the_best_and_measures_sensitivity() {
        let start = Experiment {
            size: (48, 48),
            ..Experiment::default()
        };
        let space = Space {
            params: vec![
                (Param::LightDeg, vec![35.26, 70.0]),
                (Param::RingPerTube, vec![2.0, 3.0]),
            ],
            pixels_per_frame: (0.0, f64::INFINITY),
        };
        let study = calibrate(&start, &space, 1, &|| {});
        assert!(study.best.fit.distance <= study.start.fit.distance);
        // Ratio 3 does not divide the paper's counts: skipped, never rendered.
        assert!(study.log.iter().all(|e| e.exp.setup.ring_per_tube != 3.0));
        assert_eq!(study.sensitivity.len(), 2);
        assert_eq!(study.sensitivity[0].1.len(), 2);
        assert_eq!(study.sensitivity[1].1.len(), 1);
        let md = report_md(&study, &space, 1);
        assert!(md.contains("## The best scene's numbers (1 frames)"));
        // The best scene's residual row and the reach table's row.
        assert_eq!(md.matches("| 288 Gouraud mean |").count(), 2);
        assert!(md.contains("## What the space reaches"));
        let svg = sensitivity_svg(&study).expect("a plot");
        assert!(svg.starts_with("<svg") && svg.contains("light angle (°)"));
    }
}
