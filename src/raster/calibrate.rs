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
use super::pictures::PictureError;
use super::render::{index, Reading, Shader};
use crate::Method;
use std::collections::HashMap;
use std::fmt::Write as _;

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
    let e = index(Shader::Span(Method::Euler));
    let ce = index(Shader::Span(Method::CorrectedEuler));
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

/// A one-line description of a scene's varied choices.
pub fn describe(exp: &Experiment) -> String {
    format!(
        "ring/tube {}, R = {}, r = {}, light {:.2}° from the view, {}×{} px, K_d = {}",
        exp.setup.ring_per_tube,
        exp.radii.0,
        exp.radii.1,
        exp.setup.light_deg,
        exp.size.0,
        exp.size.1,
        exp.setup.kd
    )
}

/// The choices of a fit, in words.
pub fn describe_fit(f: &Fit) -> String {
    format!(
        "Gouraud {}, Table 1 read as \"{}\" {} one-pixel rows",
        if f.gouraud == Shader::VertexGouraud {
            "from the vertices"
        } else {
            "along the span (fence)"
        },
        f.reading.label(),
        if f.single { "with" } else { "without" }
    )
}

/// The residual table of `fit` (Markdown): each number, the paper's, ours, the scaled
/// residual and whether the target is met.
pub fn residual_table(fit: &Fit) -> String {
    let mut s = String::from(
        "| number | paper | ours | residual / tolerance | target met |\n|---|---:|---:|---:|---|\n",
    );
    for r in &fit.residuals {
        let ours = match r.kind {
            Kind::Mean => format!("{:.3}", r.ours),
            Kind::Max => format!("{}", r.ours),
            Kind::Share => format!("{:.1} %", r.ours),
        };
        let paper = match r.kind {
            Kind::Share => format!("{} %", r.paper),
            _ => format!("{}", r.paper),
        };
        let _ = writeln!(
            s,
            "| {} | {paper} | {ours} | {:+.2} | {} |",
            r.name,
            r.scaled(),
            if r.met() { "yes" } else { "**no**" }
        );
    }
    s
}

/// Per number: the paper's value and the smallest and largest value over every scene
/// of the study's log (Markdown), and whether the paper's value lies in that range.
pub fn reach_table(study: &Study) -> String {
    let mut s = String::from(
        "| number | paper | lowest | highest | in range |\n|---|---:|---:|---:|---|\n",
    );
    let Some(first) = study.log.first() else {
        return s;
    };
    for (i, r) in first.fit.residuals.iter().enumerate() {
        let (lo, hi) = study
            .log
            .iter()
            .map(|e| e.fit.residuals[i].ours)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        let fmt = |v: f64| match r.kind {
            Kind::Mean => format!("{v:.3}"),
            Kind::Max => format!("{v}"),
            Kind::Share => format!("{v:.1} %"),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} |",
            r.name,
            fmt(r.paper),
            fmt(lo),
            fmt(hi),
            if (lo..=hi).contains(&r.paper) {
                "yes"
            } else {
                "**no**"
            }
        );
    }
    s
}

/// Per torus, the lowest and highest ratio of Euler's to Gouraud's maximum over every
/// scene of the study's log (Markdown).
pub fn max_ratio_table(study: &Study) -> String {
    let mut s = String::from("| polygons | paper | lowest | highest |\n|---:|---:|---:|---:|\n");
    for p in PAPER_TABLE_2 {
        let ratio = |f: &Fit| {
            let get = |what: &str| {
                f.residuals
                    .iter()
                    .find(|r| r.name == format!("{} {what} max", p.polygons))
                    .map_or(f64::NAN, |r| r.ours)
            };
            get("Euler") / get("Gouraud")
        };
        let (lo, hi) = study
            .log
            .iter()
            .map(|e| ratio(&e.fit))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        let _ = writeln!(
            s,
            "| {} | {:.2} | {lo:.2} | {hi:.2} |",
            p.polygons,
            f64::from(p.euler.max) / f64::from(p.gouraud.max)
        );
    }
    s
}

/// The sensitivity matrix: for each parameter, per number, the spread (largest minus
/// smallest) of the scaled residual as the parameter runs over its values at the best
/// scene.
pub fn sensitivity_matrix(study: &Study) -> Vec<(Param, Vec<f64>)> {
    study
        .sensitivity
        .iter()
        .map(|(p, row)| {
            let n = row.first().map_or(0, |(_, f)| f.residuals.len());
            let spread = (0..n)
                .map(|i| {
                    let vals = row.iter().map(|(_, f)| f.residuals[i].scaled());
                    let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                        (a.min(v), b.max(v))
                    });
                    hi - lo
                })
                .collect();
            (*p, spread)
        })
        .collect()
}

/// The sensitivity picture (SVG, through plotters): parameters down, the 28 numbers
/// across (their names written upwards), each cell shaded by how far that parameter
/// moves that number (spread of the scaled residual, white 0, black 4 or more), with
/// the spread written in the cell.
///
/// # Errors
/// [`PictureError::Svg`] if plotters fails.
pub fn sensitivity_svg(study: &Study) -> Result<String, PictureError> {
    use plotters::prelude::*;
    use plotters::style::text_anchor::{HPos, Pos, VPos};
    const TITLE: &str = "How far each scene choice moves each of the paper's 28 numbers (spread of residual/tolerance over the choice's values, at the best scene)";
    let m = sensitivity_matrix(study);
    let names: Vec<&str> = study
        .best
        .fit
        .residuals
        .iter()
        .map(|r| r.name.as_str())
        .collect();
    let (cw, ch, left, top) = (34i32, 26i32, 150i32, 190i32);
    let w = left + cw * names.len() as i32 + 130;
    let h = top + ch * m.len() as i32 + 60;
    let font = |size: f64| ("sans-serif", size).into_font();
    let at = |h: HPos| Pos::new(h, VPos::Center);
    let mut svg = String::new();
    let drawn = (|| -> Result<(), Box<dyn std::error::Error>> {
        let root = SVGBackend::with_string(&mut svg, (w as u32, h as u32)).into_drawing_area();
        root.fill(&WHITE)?;
        root.draw(&Text::new(TITLE, (10, 8), font(14.0)))?;
        for (j, n) in names.iter().enumerate() {
            let x = left + cw * j as i32 + cw / 2;
            let style = font(11.0)
                .transform(FontTransform::Rotate270)
                .color(&BLACK)
                .pos(at(HPos::Left));
            root.draw(&Text::new(*n, (x, top - 6), style))?;
        }
        for (i, (p, row)) in m.iter().enumerate() {
            let y = top + ch * i as i32;
            let style = font(11.0).color(&BLACK).pos(at(HPos::Left));
            root.draw(&Text::new(p.name(), (10, y + ch / 2), style))?;
            for (j, v) in row.iter().enumerate() {
                let x = left + cw * j as i32;
                let g = (255.0 * (1.0 - (v / 4.0).clamp(0.0, 1.0))).round() as u8;
                let ink = if g < 110 { WHITE } else { BLACK };
                let cell = [(x, y), (x + cw, y + ch)];
                root.draw(&Rectangle::new(cell, RGBColor(g, g, g).filled()))?;
                root.draw(&Rectangle::new(cell, RGBColor(204, 204, 204)))?;
                let style = font(9.0).color(&ink).pos(at(HPos::Center));
                root.draw(&Text::new(
                    format!("{v:.1}"),
                    (x + cw / 2, y + ch / 2),
                    style,
                ))?;
            }
        }
        root.draw(&Text::new(
            "Shade: white 0 to black 4 or more. Tolerances: means 15 % of the paper's value, maxima 2 levels, Table 1 shares 5 points.",
            (10, h - 30),
            font(11.0),
        ))?;
        root.present()?;
        Ok(())
    })();
    drawn.map_err(|e| PictureError::Svg {
        title: "fit_sensitivity".into(),
        message: e.to_string(),
    })?;
    Ok(svg)
}

/// The report of the study (Markdown): the space, the distance, the search, the best
/// scene's residuals at the search's frame count, and the sensitivity table.
pub fn report_md(study: &Study, space: &Space, frames: u32) -> String {
    let mut s = String::from(
        "# Calibration: the scene choices the paper leaves open, fitted to its 28 numbers\n\n",
    );
    let _ = writeln!(
        s,
        "Each scene is rendered for {frames} frames per torus, spread over the full run's rotation. The distance is the mean square of the 28 residuals, each divided by its tolerance (means 15 % relative, maxima 2 levels, Table 1 shares 5 points); for each scene the Gouraud of Table 2 (span or vertex) and the reading of Table 1 that fit best are taken. Coordinate descent, {} pass(es), {} scenes rendered.\n",
        study.passes,
        study.log.len()
    );
    let _ = writeln!(s, "## The space\n\n| parameter | values |\n|---|---|");
    for (p, v) in &space.params {
        let vals: Vec<String> = v.iter().map(|x| format!("{x}")).collect();
        let _ = writeln!(s, "| {} | {} |", p.name(), vals.join(", "));
    }
    let _ = writeln!(
        s,
        "\n## Start and best\n\n- start: {} — {}; {:.0} visible pixels per frame; distance {:.3}\n- best: {} — {}; {:.0} visible pixels per frame; distance {:.3}\n\nA scene is eligible when it renders about 4 million pixels per object over 200 frames ({:.0} to {:.0} visible pixels per frame).\n",
        describe(&study.start.exp),
        describe_fit(&study.start.fit),
        study.start.pixels_per_frame,
        study.start.fit.distance,
        describe(&study.best.exp),
        describe_fit(&study.best.fit),
        study.best.pixels_per_frame,
        study.best.fit.distance,
        space.pixels_per_frame.0,
        space.pixels_per_frame.1
    );
    let _ = writeln!(s, "## The best scene's numbers ({frames} frames)\n");
    s.push_str(&residual_table(&study.best.fit));
    let _ = writeln!(
        s,
        "\n## Sensitivity: spread of each residual/tolerance as one choice runs over its values\n"
    );
    let m = sensitivity_matrix(study);
    let groups = [
        ("Gouraud mean", "Gouraud mean"),
        ("Gouraud max", "Gouraud max"),
        ("Euler mean", "Euler mean"),
        ("Euler max", "Euler max"),
        ("corr. Euler mean", "corrected Euler mean"),
        ("corr. Euler max", "corrected Euler max"),
        ("Table 1", "Table 1 share"),
    ];
    let mut head = String::from("| parameter |");
    let mut rule = String::from("|---|");
    for (label, _) in groups {
        let _ = write!(head, " {label} |");
        rule.push_str("---:|");
    }
    let _ = writeln!(s, "{head}\n{rule}");
    let names: Vec<&str> = study
        .best
        .fit
        .residuals
        .iter()
        .map(|r| r.name.as_str())
        .collect();
    for (p, row) in &m {
        let mut line = format!("| {} |", p.name());
        for (_, pat) in groups {
            let worst = names
                .iter()
                .zip(row)
                // Names are "<polygons> <what>": group by what.
                .filter(|(n, _)| n.split_once(' ').is_some_and(|(_, what)| what == pat))
                .map(|(_, v)| *v)
                .fold(0.0f64, f64::max);
            let _ = write!(line, " {worst:.1} |");
        }
        let _ = writeln!(s, "{line}");
    }
    let _ = writeln!(
        s,
        "\n## What the space reaches\n\nEach number's range over every scene rendered (with each scene's own best Gouraud and Table 1 reading): a paper value outside it is not reached by any scene the search visited.\n"
    );
    s.push_str(&reach_table(study));
    let _ = writeln!(
        s,
        "\nEuler's maximum over Gouraud's, per torus, over every scene rendered:\n"
    );
    s.push_str(&max_ratio_table(study));
    let _ = writeln!(
        s,
        "\n## Every scene rendered\n\n| scene | fit choices | visible pixels per frame | distance |\n|---|---|---:|---:|"
    );
    for e in &study.log {
        let _ = writeln!(
            s,
            "| {} | {} | {:.0}{} | {:.3} |",
            describe(&e.exp),
            describe_fit(&e.fit),
            e.pixels_per_frame,
            if e.eligible(space.pixels_per_frame) {
                ""
            } else {
                " (outside)"
            },
            e.fit.distance
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::render::{RowStats, Stats, COLUMNS};
    use crate::raster::stats::Deviation;

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
