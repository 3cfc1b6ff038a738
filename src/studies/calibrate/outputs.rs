//! The calibration study in words and pictures: the fit, the residuals, the reach
//! of each parameter, the sensitivity matrix and its picture, the report page.

use super::*;
use crate::studies::pictures::PictureError;
use std::fmt::Write as _;

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
    let names = residual_names(study);
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
    let names = residual_names(study);
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

/// The names of the paper's numbers, in the order of the best scene's residuals.
fn residual_names(study: &Study) -> Vec<&str> {
    study
        .best
        .fit
        .residuals
        .iter()
        .map(|r| r.name.as_str())
        .collect()
}
