//! The report of `phong-approx reproduce`: the Markdown tables (`tables.md`), the CSVs
//! (`table1.csv`, `table2.csv`) and the pictures (Figures 1–5 and the heat maps), as
//! strings and images; the command line writes them.

use super::experiment::{Experiment, TorusResult, PAPER_TABLE_1, PAPER_TABLE_2};
use super::pictures::{
    labelled_difference_image, line_plot, shaded_image, Look, Picture, PictureError,
};
use super::render::{render, Reading, RenderOptions, Scene, Shader, COLUMNS};
use crate::raster::mesh::NormalMode;
use crate::table::{
    markdown,
    Align::{Left, Right},
};
use crate::{Method, Span, Vec3};
use serde::Serialize;
use std::fmt::Write as _;

mod figures;
pub use figures::{figure_span, pictures, scanline_figures};

/// The tables `reproduce` writes ([`tables`]).
pub const TABLES: [&str; 3] = ["tables.md", "table1.csv", "table2.csv"];

/// The renders of the 800-polygon torus, frame 37: file, method, and whether the
/// highlights are left out (Figures 4–5 and the diffuse Gouraud render).
const RENDERS: [(&str, Method, bool); 3] = [
    ("fig4_torus800_corrected_euler.png", Method::PAPER, false),
    ("fig5_torus800_phong.png", Method::Phong, false),
    ("torus800_gouraud_diffuse.png", Method::Gouraud, true),
];

/// The heat maps of each method's difference from Phong on the same frame.
const DIFFS: [(&str, Method); 3] = [
    ("diff_torus800_corrected_euler.png", Method::PAPER),
    ("diff_torus800_gouraud.png", Method::Gouraud),
    ("diff_torus800_euler.png", Method::Euler),
];

/// Figures 1–3 (each method's difference from Phong along one scan line: file,
/// title, method, curve label) and Figure 0 (the curves themselves).
const FIGURES: [(&str, &str, Method, &str); 3] = [
    (
        "fig1_phong_minus_gouraud.svg",
        "Figure 1: Phong − Gouraud, normals 60° apart",
        Method::Gouraud,
        "Phong − Gouraud",
    ),
    (
        "fig2_phong_minus_euler.svg",
        "Figure 2: Phong − Euler, normals 60° apart",
        Method::Euler,
        "Phong − Euler",
    ),
    (
        "fig3_phong_minus_corrected_euler.svg",
        "Figure 3: Phong − corrected Euler, normals 60° apart",
        Method::PAPER,
        "Phong − corrected Euler",
    ),
];

/// Figure 0's file.
const CURVES: &str = "fig0_curves.svg";

/// The files `reproduce` writes, in order: the tables, then the pictures of
/// [`pictures`] (derived from the lists the reports are made from, so that the two
/// cannot drift apart).
pub fn outputs() -> Vec<&'static str> {
    TABLES
        .into_iter()
        .chain(RENDERS.map(|r| r.0))
        .chain(DIFFS.map(|d| d.0))
        .chain(FIGURES.map(|f| f.0))
        .chain([CURVES])
        .collect()
}

/// The tables of [`TABLES`] with their contents: `tables.md` ([`tables_md`]),
/// `table1.csv`, `table2.csv`.
pub fn tables(exp: &Experiment, results: &[TorusResult], secs: f64) -> Vec<(&'static str, String)> {
    let [md, t1, t2] = TABLES;
    vec![
        (md, tables_md(exp, results, secs)),
        (t1, table1_csv(results)),
        (t2, table2_csv(results)),
    ]
}

/// The Markdown report of `reproduce` (`tables.md`): the scene, Table 2 beside the
/// paper's, Table 2 for every column of [`COLUMNS`], Table 1 beside the paper's,
/// and, when a torus has an exact check, the exact-mode table. `secs` is the run time
/// it states.
pub fn tables_md(exp: &Experiment, results: &[TorusResult], secs: f64) -> String {
    let scene = exp.scene();
    let mut s = String::new();
    let px: u64 = results.iter().map(|r| r.stats.pixels).sum();
    let frames: u64 = results.iter().map(|r| r.stats.frames).sum();
    let _ = writeln!(
        s,
        "# Tables 1 and 2 of Hast, Barrera & Bengtsson, reproduced\n"
    );
    let _ = writeln!(
        s,
        "Scene: tori R = {}, r = {}, {} normals, ring × tube segments {}; {}×{} pixels, orthographic, {:.1} px per unit; light {:?} ({:.2}° from the view); K_d = {}; rotation {}°, {}°, {}° per frame about x, y, z; {} frames per torus; {:.0} visible pixels per frame on average; f32 arithmetic; {:.1} s.\n",
        exp.radii.0,
        exp.radii.1,
        match exp.normals {
            NormalMode::Analytic => "analytic",
            NormalMode::Averaged => "face-averaged",
        },
        results
            .iter()
            .map(|r| format!("{}×{}", r.segments.0, r.segments.1))
            .collect::<Vec<_>>()
            .join(", "),
        scene.width,
        scene.height,
        scene.scale,
        [scene.light.x, scene.light.y, scene.light.z].map(|v| (v * 1e4).round() / 1e4),
        exp.setup.light_deg,
        scene.kd,
        scene.rates_deg.x,
        scene.rates_deg.y,
        scene.rates_deg.z,
        exp.frames,
        px as f64 / frames.max(1) as f64,
        secs
    );
    let g = crate::studies::render::index(crate::studies::render::GOURAUD);
    let gv = crate::studies::render::index(Shader::VertexGouraud);
    let e = crate::studies::render::index(crate::studies::render::EULER);
    let ce = crate::studies::render::index(crate::studies::render::CORRECTED_EULER);
    let _ = writeln!(
        s,
        "## Table 2: deviation from Phong in 8-bit levels (mean / max), ours beside the paper's\n"
    );
    let head = [
        "polygons",
        "Gouraud (paper)",
        "Gouraud, span",
        "Gouraud, vertex",
        "Euler (paper)",
        "Euler",
        "Corr. Euler (paper)",
        "Corr. Euler",
    ];
    let rows: Vec<Vec<String>> = results
        .iter()
        .zip(PAPER_TABLE_2)
        .map(|(r, p)| {
            let d = &r.stats.deviation;
            let f = |i: usize| format!("{:.3} / {}", d[i].mean(), d[i].max);
            vec![
                r.polygons.to_string(),
                format!("{:.2} / {}", p.gouraud.mean, p.gouraud.max),
                f(g),
                f(gv),
                format!("{:.2} / {}", p.euler.mean, p.euler.max),
                f(e),
                format!("{:.3} / {}", p.corrected_euler.mean, p.corrected_euler.max),
                f(ce),
            ]
        })
        .collect();
    s.push_str(&markdown(&head, &[Right; 8], &rows));
    let _ = writeln!(
        s,
        "\n## Table 2, every method (mean / max deviation from Phong, 8-bit levels)\n"
    );
    let head: Vec<String> = std::iter::once("polygons".to_string())
        .chain(COLUMNS.iter().skip(1).map(|c| c.label().into_owned()))
        .collect();
    let rows: Vec<Vec<String>> = results
        .iter()
        .map(|r| {
            std::iter::once(r.polygons.to_string())
                .chain(
                    r.stats
                        .deviation
                        .iter()
                        .skip(1)
                        .map(|d| format!("{:.3} / {}", d.mean(), d.max)),
                )
                .collect()
        })
        .collect();
    s.push_str(&markdown(&head, &vec![Right; head.len()], &rows));
    let _ = writeln!(
        s,
        "\n## Table 1: scan lines that \"could have been computed with Gouraud\", every reading\n"
    );
    let _ = writeln!(s, "Percent of rows of two or more pixels (in brackets: with the one-pixel rows counted, on which every reading holds). The paper's text counts the first reading, its caption the second (errata A5).\n");
    s.push_str(&table1_md(results));
    if let Some(r) = results.iter().find(|r| r.stats.exact.is_some()) {
        let x = r.stats.exact.as_ref().expect("checked");
        let _ = writeln!(
            s,
            "\n## Exact mode: the {}-polygon torus, first {} frame(s), every span also in exact rationals\n",
            r.polygons, exp.exact_frames
        );
        let rows: Vec<Vec<String>> = COLUMNS
            .iter()
            .enumerate()
            .filter(|&(c, _)| c != gv && !x.mismatches.is_empty())
            .map(|(c, col)| {
                vec![
                    col.label().into_owned(),
                    x.pixels.to_string(),
                    x.mismatches[c].to_string(),
                    x.explained[c].to_string(),
                ]
            })
            .collect();
        s.push_str(&markdown(
            &[
                "method",
                "span pixels",
                "f32 level ≠ exact level",
                "of which within rounding of a level boundary",
            ],
            &[Left, Right, Right, Right],
            &rows,
        ));
    }
    s
}

/// Table 1 in every reading beside the paper's (Markdown): per torus, each reading's
/// percentage without (and, in brackets, with) the one-pixel rows, the δ test's two
/// kinds of disagreement with the caption, and the row counts.
pub fn table1_md(results: &[TorusResult]) -> String {
    let head: Vec<String> = ["polygons", "paper"]
        .into_iter()
        .map(String::from)
        .chain(Reading::ALL.iter().map(|r| r.label().to_string()))
        .chain(
            [
                "δ says G, levels G ≠ CE",
                "δ says CE, levels G = CE",
                "rows",
                "1-pixel rows",
            ]
            .map(String::from),
        )
        .collect();
    let rows: Vec<Vec<String>> = results
        .iter()
        .zip(PAPER_TABLE_1)
        .map(|(r, p)| {
            let t = &r.stats.rows;
            let pc = |k: u64| 100.0 * k as f64 / t.rows.max(1) as f64;
            let mut row = vec![r.polygons.to_string(), format!("{:.1} %", p.percent)];
            row.extend(Reading::ALL.iter().map(|reading| {
                format!(
                    "{:.1} % ({:.1} %)",
                    reading.percent(t, false),
                    reading.percent(t, true)
                )
            }));
            row.extend([
                format!("{:.2} %", pc(t.predicted_gouraud_but_differ)),
                format!("{:.2} %", pc(t.predicted_corrected_but_same)),
                t.rows.to_string(),
                t.single_pixel_rows.to_string(),
            ]);
            row
        })
        .collect();
    markdown(&head, &vec![Right; head.len()], &rows)
}

/// `table1.csv`: per torus, the paper's Table 1 percentage and our row counts (one
/// line per torus, the header first).
pub fn table1_csv(results: &[TorusResult]) -> String {
    /// A line of `table1.csv`.
    #[derive(Serialize)]
    struct Row {
        polygons: u32,
        paper_percent: String,
        rows: u64,
        single_pixel_rows: u64,
        truncated_difference_zero: u64,
        gouraud_eq_corrected: u64,
        gouraud_eq_phong: u64,
        predicted_gouraud: u64,
        predicted_gouraud_but_differ: u64,
        predicted_corrected_but_same: u64,
    }
    crate::table::csv(results.iter().zip(PAPER_TABLE_1).map(|(r, p)| {
        let t = &r.stats.rows;
        Row {
            polygons: r.polygons,
            paper_percent: p.percent.to_string(),
            rows: t.rows,
            single_pixel_rows: t.single_pixel_rows,
            truncated_difference_zero: t.truncated_difference_zero,
            gouraud_eq_corrected: t.gouraud_eq_corrected,
            gouraud_eq_phong: t.gouraud_eq_phong,
            predicted_gouraud: t.predicted_gouraud,
            predicted_gouraud_but_differ: t.predicted_gouraud_but_differ,
            predicted_corrected_but_same: t.predicted_corrected_but_same,
        }
    }))
}

/// `table2.csv`: per torus and column of [`COLUMNS`], the pixels and the mean
/// (6 decimals) and maximum deviation from Phong in 8-bit levels.
pub fn table2_csv(results: &[TorusResult]) -> String {
    /// A line of `table2.csv`.
    #[derive(Serialize)]
    struct Row {
        polygons: u32,
        method: String,
        pixels: u64,
        mean_deviation: String,
        max_deviation: u32,
    }
    crate::table::csv(results.iter().flat_map(|r| {
        COLUMNS.iter().zip(&r.stats.deviation).map(|(c, d)| Row {
            polygons: r.polygons,
            method: c.label().into_owned(),
            pixels: d.pixels,
            mean_deviation: format!("{:.6}", d.mean()),
            max_deviation: d.max,
        })
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::studies::experiment::PaperTable1;
    use crate::studies::pictures::tests_support::csv_rows;
    use crate::studies::render::{Deviation, ExactCheck, RowStats, Stats};

    /// A hand-made result per paper torus: column `c` has `10 + c` pixels, a deviation
    /// sum of `c` and a maximum of `c`; the 800-polygon torus has an exact check.
    fn results() -> Vec<TorusResult> {
        PAPER_TABLE_1
            .iter()
            .map(|&PaperTable1 { polygons, .. }| TorusResult {
                polygons,
                segments: (1, 1),
                stats: Stats {
                    deviation: (0..COLUMNS.len() as u64)
                        .map(|c| Deviation {
                            pixels: 10 + c,
                            sum: c,
                            max: c as u32,
                        })
                        .collect(),
                    rows: RowStats {
                        rows: 8,
                        single_pixel_rows: 3,
                        gouraud_eq_corrected: 4,
                        gouraud_eq_phong: 2,
                        truncated_difference_zero: 5,
                        predicted_gouraud: 1,
                        predicted_gouraud_but_differ: 1,
                        predicted_corrected_but_same: 0,
                    },
                    pixels: 500,
                    frames: 2,
                    exact: (polygons == 800).then(|| ExactCheck {
                        pixels: 99,
                        mismatches: vec![5; COLUMNS.len()],
                        explained: vec![4; COLUMNS.len()],
                    }),
                },
            })
            .collect()
    }

    fn exp() -> Experiment {
        Experiment {
            frames: 2,
            ..Experiment::default()
        }
    }

    #[test]
    fn the_report_has_its_tables_and_the_numbers_with_their_digits() {
        let md = tables_md(&exp(), &results(), 1.3);
        assert!(md.starts_with("# Tables 1 and 2 of Hast, Barrera & Bengtsson, reproduced\n"));
        assert!(md.contains(
            "2 frames per torus; 250 visible pixels per frame on average; f32 arithmetic; 1.3 s."
        ));
        assert!(md.contains("| polygons | Gouraud (paper) | Gouraud, span | Gouraud, vertex | Euler (paper) | Euler | Corr. Euler (paper) | Corr. Euler |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n"));
        // 288 polygons: the paper's numbers, then ours with 3 decimals / max.
        let (g, gv, e, ce) = (
            crate::studies::render::index(crate::studies::render::GOURAUD) as f64,
            crate::studies::render::index(Shader::VertexGouraud) as f64,
            crate::studies::render::index(crate::studies::render::EULER) as f64,
            crate::studies::render::index(crate::studies::render::CORRECTED_EULER) as f64,
        );
        let ours = |c: f64| format!("{:.3} / {}", c / (10.0 + c), c);
        let row = format!(
            "| 288 | 1.08 / 15 | {} | {} | 0.75 / 21 | {} | 0.081 / 3 | {} |",
            ours(g),
            ours(gv),
            ours(e),
            ours(ce)
        );
        assert!(md.contains(&row), "{row}\n{md}");
        // Every method: one column per label after Phong's.
        let head: String = COLUMNS[1..]
            .iter()
            .map(|c| format!(" {} |", c.label()))
            .collect();
        assert!(md.contains(&format!("| polygons |{head}\n")));
        // Table 1, every reading without and with the 3 one-pixel rows: text 5 of 8
        // (8 of 11), caption 4 of 8 (7 of 11), G = Ph 2 of 8 (5 of 11), δ 1 of 8
        // (4 of 11); then 1 of 8 is 12.50 %.
        let row = "| 800 | 80.9 % | 62.5 % (72.7 %) | 50.0 % (63.6 %) | 25.0 % (45.5 %) | 12.5 % (36.4 %) | 12.50 % | 0.00 % | 8 | 3 |";
        assert!(md.contains(row), "{row}\n{md}");
        // The exact table: every column but vertex Gouraud.
        assert!(md.contains("## Exact mode: the 800-polygon torus, first 1 frame(s)"));
        assert!(md.contains("| corrected-euler | 99 | 5 | 4 |"));
        assert!(!md.contains("| gouraud-vertex | 99 |"));
    }

    #[test]
    fn without_an_exact_check_there_is_no_exact_table() {
        let mut r = results();
        for t in &mut r {
            t.stats.exact = None;
        }
        assert!(!tables_md(&exp(), &r, 0.0).contains("Exact mode"));
    }

    #[test]
    fn table1_csv_parses_back_with_one_row_per_torus() {
        let (head, rows) = csv_rows(&table1_csv(&results()));
        assert_eq!(
            head,
            [
                "polygons",
                "paper_percent",
                "rows",
                "single_pixel_rows",
                "truncated_difference_zero",
                "gouraud_eq_corrected",
                "gouraud_eq_phong",
                "predicted_gouraud",
                "predicted_gouraud_but_differ",
                "predicted_corrected_but_same"
            ]
        );
        assert_eq!(rows.len(), 4);
        assert_eq!(
            rows[2],
            ["800", "80.9", "8", "3", "5", "4", "2", "1", "1", "0"]
        );
    }

    #[test]
    fn table2_csv_parses_back_with_a_row_per_torus_and_column() {
        let (head, rows) = csv_rows(&table2_csv(&results()));
        assert_eq!(
            head,
            [
                "polygons",
                "method",
                "pixels",
                "mean_deviation",
                "max_deviation"
            ]
        );
        assert_eq!(rows.len(), 4 * COLUMNS.len());
        let labels: Vec<String> = COLUMNS.iter().map(|c| c.label().into_owned()).collect();
        for (k, row) in rows.iter().enumerate() {
            let c = k % COLUMNS.len();
            assert_eq!(row[1], labels[c]);
            assert_eq!(row[2], (10 + c).to_string());
            assert_eq!(row[3], format!("{:.6}", c as f64 / (10 + c) as f64));
            assert_eq!(row[4], c.to_string());
        }
    }

    #[test]
    fn the_figure_span_has_unit_normals_sixty_degrees_apart() {
        let s = figure_span(&exp().scene());
        let cos = s.na.x * s.nb.x + s.na.y * s.nb.y + s.na.z * s.nb.z;
        assert!((cos - 0.5).abs() < 1e-12);
    }

    #[test]
    fn the_scanline_figures_are_labelled_svgs() {
        let figs = scanline_figures(&exp().scene()).expect("plots");
        let names: Vec<&str> = figs.iter().map(|f| f.0).collect();
        assert_eq!(names, outputs()[9..]);
        for (name, svg) in &figs {
            assert!(svg.starts_with("<svg"), "{name}");
            assert!(
                svg.contains("pixel i along the scan line (pixels, n = 100)"),
                "{name}"
            );
            assert!(svg.contains("(8-bit levels)"), "{name}");
        }
        for series in ["Phong", "Gouraud", "Euler", "corrected Euler"] {
            assert!(
                figs[3].1.contains(&format!("\n{series}\n</text>")),
                "{series}"
            );
        }
    }
}
