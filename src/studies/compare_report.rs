//! The report of `phong-approx compare`: the measurements behind it (the precision
//! and long-span studies), the Markdown report (`comparison.md`), the CSVs and the
//! pictures (the labelled grid of every method with its heat map, and the highlight
//! figures), as strings and images; the command line writes them.

use super::compare::{
    render_compare, CompareFrame, CompareOptions, CompareResult, Shader, COLUMNS, SHININESS,
};
use super::experiment::Experiment;
use super::pictures::{
    fitting_scale, heat_legend, heat_map, level_image, stack, text_strip, BACKGROUND, INK,
};
use super::precision::{self, PrecisionStats, PRECISIONS, SPAN_LENGTHS};
use super::text;
use crate::table::{
    markdown, Align,
    Align::{Left, Right},
};
use crate::Arithmetic;
use crate::Method;
use image::RgbImage;
use rayon::prelude::*;
use serde::Serialize;
use std::fmt::Write as _;

mod pictures;
#[cfg(test)]
use pictures::grid_legend;
pub use pictures::{
    grid, picture_names, pictures, skip_figure, squared_figure, SKIP_MAP, SQUARED_MAP,
};

mod tables;
pub use tables::{precision_csv, spans_csv, table2_csv};

/// The tables `compare` writes, before its pictures ([`GRID`] and
/// [`picture_names`]).
pub const TABLES: [&str; 4] = [
    "comparison.md",
    "table2_extended.csv",
    "precision.csv",
    "longest_span.csv",
];

/// The file name of the picture grid.
pub const GRID: &str = "grid.png";

/// The shader of [`COLUMNS`] whose table label is `label`.
///
/// # Panics
/// If no shader has that label.
fn shader(label: &str) -> Shader {
    *COLUMNS
        .iter()
        .find(|s| s.label() == label)
        .unwrap_or_else(|| panic!("no shader labelled {label}"))
}

/// One method of the long-span study: per precision, the errors per span length
/// ([`SPAN_LENGTHS`]; `None` where the precision fails).
pub type SpanRow = (crate::Method, Vec<(Arithmetic, Vec<Option<f64>>)>);

/// Everything `compare` measures.
#[derive(Clone, Debug)]
pub struct Measured {
    /// The four tori, every shader, diffuse and specular.
    pub tori: Vec<CompareResult>,
    /// Per precision of [`PRECISIONS`]: the 800-polygon torus.
    pub precision: Vec<(Arithmetic, PrecisionStats)>,
    /// Per span method of the catalogue ([`Method::ALL`]: the polygon methods step
    /// along a row by the same additions as Gouraud or Bishop–Weimer), per precision: errors per span length.
    pub spans: Vec<SpanRow>,
    /// Test spans per length.
    pub span_count: usize,
}

/// The precision study: the 800-polygon torus of `exp` over `frames` frames in every
/// precision of [`PRECISIONS`]; `tick` is called once per frame and precision.
pub fn precision_study(
    exp: &Experiment,
    frames: u32,
    tick: &(dyn Fn() + Sync),
) -> Vec<(Arithmetic, PrecisionStats)> {
    let scene = exp.scene();
    let mesh = exp.mesh(40, 20);
    PRECISIONS
        .iter()
        .map(|&p| {
            (
                p.arithmetic,
                precision::torus(&mesh, &scene, frames, &p, tick),
            )
        })
        .collect()
}

/// The long-span study: every span method of the catalogue in every precision on
/// `count` test spans per length (shaders in parallel); `tick` is called once per
/// shader and precision.
pub fn span_study(count: usize, tick: &(dyn Fn() + Sync)) -> Vec<SpanRow> {
    let dirs = precision::test_directions(count);
    Method::ALL
        .par_iter()
        .map(|&sh| {
            let per: Vec<(Arithmetic, Vec<Option<f64>>)> = PRECISIONS
                .iter()
                .map(|&p| {
                    let e = precision::span_errors_in(sh, &p, &dirs);
                    tick();
                    (p.arithmetic, e)
                })
                .collect();
            (sh, per)
        })
        .collect()
}

/// The Markdown report of `compare` (`comparison.md`): the scene, the methods, the
/// extended Table 2 (diffuse, then specular at every [`SHININESS`]), the adaptive
/// scheme and the δ test on the specular term, the precision tables (`pframes` frames)
/// and the longest spans. `secs` is the run time it states.
pub fn report_md(exp: &Experiment, pframes: u32, r: &Measured, secs: f64) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# Every method on the same tori\n");
    let _ = writeln!(
        s,
        "{} frames per torus at {}×{}, tori of radii {} and {} with analytic normals, quads drawn as two triangles; \
         light normalize(−1, 1, 2), viewer +z, H = normalize(L + V). Reference: per-pixel Phong (the triangle's \
         normal field normalized at each pixel centre) in f64; every method in f32. Deviation = |level − reference \
         level|, 8-bit levels floor(255·v), over the visible pixels: mean / max. Ran in {:.0} s.\n",
        exp.frames, exp.size.0, exp.size.1, exp.radii.0, exp.radii.1, secs
    );
    let _ = writeln!(s, "## Methods\n");
    let rows: Vec<Vec<String>> = COLUMNS
        .iter()
        .map(|sh| {
            let pw = match sh.label().as_ref() {
                "phong-pixel" => "exact (f64)",
                "gouraud" => "at the span's edges, interpolated",
                "gouraud-vertex" => "at the vertices, interpolated",
                "vertex-angle" => "table of cos^s (byte angle)",
                _ if sh.power_from_table() => "1024-entry table",
                _ => "per pixel",
            };
            let reconstructed = if sh.reconstructed() { "yes" } else { "" };
            [&*sh.label(), sh.source(), reconstructed, pw]
                .map(String::from)
                .to_vec()
        })
        .collect();
    s.push_str(&markdown(
        &["column", "source", "reconstructed", "specular power"],
        &[Left; 4],
        &rows,
    ));
    let tori: Vec<String> = r
        .tori
        .iter()
        .map(|t| format!("{} polygons", t.polygons))
        .collect();
    let deviation = |d: &crate::raster::stats::Deviation| format!("{:.3} / {}", d.mean(), d.max);
    let _ = writeln!(
        s,
        "\n## Extended Table 2: diffuse (N·L), mean / max deviation\n"
    );
    // A row per shader, a cell per torus.
    let tori_rows = |cell: &dyn Fn(&CompareResult, usize) -> String| {
        COLUMNS
            .iter()
            .enumerate()
            .map(|(c, sh)| {
                let cells = r.tori.iter().map(|t| cell(t, c)).collect();
                (sh.label().into_owned(), cells)
            })
            .collect::<Vec<_>>()
    };
    let rows = tori_rows(&|t, c| deviation(&t.stats.diffuse[c]));
    s.push_str(&method_table(&tori, rows));
    for (k, sv) in SHININESS.iter().enumerate() {
        let _ = writeln!(
            s,
            "\n## Extended Table 2: specular (N·H)^{sv}, mean / max deviation\n"
        );
        let rows = tori_rows(&|t, c| deviation(&t.stats.specular[k][c]));
        s.push_str(&method_table(&tori, rows));
    }
    let _ = writeln!(
        s,
        "\n## The adaptive scheme (§5) and the δ test on the specular term\n"
    );
    let _ = writeln!(
        s,
        "Spans: rows of two or more pixels. Diffuse: the share the δ test (eq. 24, K_d = 1) gives to Gouraud. \
         Specular: the same test on N·H (K = 1) — the spans it gives to Gouraud, and of those, the share where \
         Gouraud's and corrected Euler's levels of (N·H)^s differ somewhere.\n"
    );
    let head: Vec<String> = ["torus", "spans", "diffuse → Gouraud"]
        .map(String::from)
        .into_iter()
        .chain(
            SHININESS
                .iter()
                .map(|sv| format!("s = {sv}: Gouraud spans that differ")),
        )
        .collect();
    let rows: Vec<Vec<String>> = r
        .tori
        .iter()
        .map(|t| {
            let st = &t.stats;
            let mut row = vec![
                t.polygons.to_string(),
                st.spans.to_string(),
                format!("{:.1} %", st.adaptive_gouraud_percent()),
            ];
            row.extend(st.specular_delta.iter().map(|d| {
                let pct = if d.gouraud == 0 {
                    0.0
                } else {
                    100.0 * d.gouraud_but_differ as f64 / d.gouraud as f64
                };
                format!("{pct:.1} % of {}", d.gouraud)
            }));
            row
        })
        .collect();
    s.push_str(&markdown(&head, &vec![Right; head.len()], &rows));
    let _ = writeln!(s, "\n{}", crate::studies::compare::skip_table(&r.tori));
    let _ = writeln!(s, "\n{}", crate::studies::compare::squared_table(&r.tori));
    let _ = writeln!(
        s,
        "\n## Precision: the 800-polygon torus, {pframes} frames, every drawn pixel, mean / max deviation from \
         per-pixel Phong in f64\n\nSet-up and steps entirely in the precision; a blank cell means every row failed, \
         or that the method has no kernel in that precision (the row set-ups of `fast_rows` are `f32` and `f64` \
         kernels, the `rsqrt` ones `f32` only).\n"
    );
    let precisions: Vec<String> = PRECISIONS.iter().map(|p| p.to_string()).collect();
    // A row per shader, a cell per precision (blank where nothing was drawn).
    let precision_rows = |cell: &dyn Fn(&PrecisionStats, usize) -> String| {
        COLUMNS
            .iter()
            .enumerate()
            .map(|(c, sh)| {
                let cells = r.precision.iter().map(|(_, st)| cell(st, c)).collect();
                (sh.label().into_owned(), cells)
            })
            .collect::<Vec<_>>()
    };
    let rows = precision_rows(&|st, c| {
        let d = &st.vs_phong[c];
        let fail = st.failed_rows[c];
        if d.pixels == 0 {
            String::new()
        } else if fail > 0 {
            format!(
                "{:.3} / {} ({:.1} % rows failed)",
                d.mean(),
                d.max,
                100.0 * fail as f64 / st.rows as f64
            )
        } else {
            deviation(d)
        }
    });
    s.push_str(&method_table(&precisions, rows));
    let _ = writeln!(
        s,
        "\nThe arithmetic's own share: the same, against the same method in f64.\n"
    );
    let rows = precision_rows(&|st, c| {
        let d = &st.vs_f64[c];
        if d.pixels == 0 {
            String::new()
        } else {
            deviation(d)
        }
    });
    s.push_str(&method_table(&precisions, rows));
    let _ = writeln!(
        s,
        "\n## Longest span within one 8-bit level\n\nPer method and precision: the longest n of {:?} up to which \
         the method in that precision stays within 1/255 of the same method in f64 on {} test spans (normals 5° to \
         45° apart, light within 60° of N_a); set-up in f64 rounded to the precision, steps in the precision. \
         “—”: not even n = 1; in brackets the worst error at n = 64, in levels.\n",
        SPAN_LENGTHS, r.span_count
    );
    let at64 = SPAN_LENGTHS
        .iter()
        .position(|&n| n == 64)
        .expect("64 is tried");
    let rows = r
        .spans
        .iter()
        .map(|(sh, per)| {
            let cells = per
                .iter()
                .map(|(_, e)| {
                    let longest = match precision::longest(e) {
                        None => "—".to_string(),
                        Some(n) if n == *SPAN_LENGTHS.last().expect("non-empty") => {
                            format!("≥ {n}")
                        }
                        Some(n) => n.to_string(),
                    };
                    let e64 = match e[at64] {
                        Some(v) => format!("{v:.2}"),
                        None => "fails".into(),
                    };
                    format!("{longest} ({e64})")
                })
                .collect();
            (sh.name().into_owned(), cells)
        })
        .collect();
    s.push_str(&method_table(&precisions, rows));
    s
}

/// A Markdown table of `method` and one right-aligned column per name of `columns`:
/// a row per method, its name and its cells.
fn method_table(columns: &[String], rows: Vec<(String, Vec<String>)>) -> String {
    let head: Vec<&str> = std::iter::once("method")
        .chain(columns.iter().map(String::as_str))
        .collect();
    let align: Vec<Align> = std::iter::once(Left)
        .chain(columns.iter().map(|_| Right))
        .collect();
    let rows: Vec<Vec<String>> = rows
        .into_iter()
        .map(|(name, cells)| std::iter::once(name).chain(cells).collect())
        .collect();
    markdown(&head, &align, &rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::studies::compare::{CompareStats, DeltaCount};
    use crate::studies::pictures::tests_support::csv_rows;
    use crate::studies::render::Deviation;

    /// Shader `c` deviates by `c` in `c` of `10` pixels, diffuse; specular `k` adds `k`
    /// to the maximum.
    fn dev(c: usize, k: u32) -> Deviation {
        Deviation {
            pixels: 10,
            sum: c as u64,
            max: c as u32 + k,
        }
    }

    fn results() -> Measured {
        let n = COLUMNS.len();
        let tori = [288, 512, 800, 1152]
            .map(|polygons| CompareResult {
                polygons,
                stats: CompareStats {
                    diffuse: (0..n).map(|c| dev(c, 0)).collect(),
                    specular: (1..=SHININESS.len() as u32)
                        .map(|k| (0..n).map(|c| dev(c, k)).collect())
                        .collect(),
                    spans: 40,
                    adaptive_gouraud: 10,
                    specular_delta: vec![
                        DeltaCount {
                            gouraud: 8,
                            gouraud_but_differ: 2,
                            corrected_but_same: 0,
                        };
                        SHININESS.len()
                    ],
                    skip: vec![Default::default(); 4],
                    squared: vec![Default::default(); 3],
                    dropped_rows: 0,
                    pixels: 400,
                    frames: 1,
                },
            })
            .to_vec();
        let precision = PRECISIONS
            .iter()
            .map(|&p| {
                let mut st = PrecisionStats {
                    vs_phong: (0..n).map(|c| dev(c, 0)).collect(),
                    vs_f64: (0..n).map(|c| dev(c, 1)).collect(),
                    failed_rows: vec![0; n],
                    rows: 20,
                };
                if p.arithmetic
                    == (Arithmetic::Fixed {
                        int_bits: 8,
                        frac_bits: 8,
                    })
                {
                    let duff = crate::studies::compare::index(shader("duff"));
                    st.failed_rows[1] = 5;
                    st.vs_phong[duff].pixels = 0;
                    st.vs_f64[duff].pixels = 0;
                }
                (p.arithmetic, st)
            })
            .collect();
        let spans = Method::ALL
            .iter()
            .map(|&sh| {
                let per = PRECISIONS
                    .iter()
                    .map(|&p| {
                        let e = SPAN_LENGTHS
                            .iter()
                            .map(|&len| (len <= 64).then_some(len as f64 / 64.0))
                            .collect();
                        (p.arithmetic, e)
                    })
                    .collect();
                (sh, per)
            })
            .collect();
        Measured {
            tori,
            precision,
            spans,
            span_count: 3,
        }
    }

    #[test]
    fn the_report_has_every_table_with_the_expected_digits() {
        let exp = Experiment {
            frames: 1,
            ..Experiment::default()
        };
        let md = report_md(&exp, 2, &results(), 3.4);
        assert!(md.starts_with("# Every method on the same tori\n"));
        assert!(md.contains("1 frames per torus at 225×225, tori of radii 1 and 0.4"));
        assert!(md.contains("Ran in 3 s."));
        assert!(md.contains("| phong-pixel | Phong 1975 |  | exact (f64) |"));
        assert!(md.contains("| spherical | Kuijk & Blake 1989 | yes | per pixel |"));
        assert!(md.contains("| seiler | Seiler 1998 | yes | 1024-entry table |"));
        let head = "| method | 288 polygons | 512 polygons | 800 polygons | 1152 polygons |\n|---|---:|---:|---:|---:|\n";
        assert_eq!(md.matches(head).count(), 1 + SHININESS.len());
        // Diffuse, Duff's column c: mean c/10, max c.
        let c = crate::studies::compare::index(shader("duff"));
        let m = format!("{:.3}", c as f64 / 10.0);
        assert!(md.contains(&format!(
            "| duff | {m} / {c} | {m} / {c} | {m} / {c} | {m} / {c} |"
        )));
        // Specular s = 200 adds 3 to the maximum.
        let c3 = c + 3;
        assert!(md.contains(&format!("| duff | {m} / {c3} | {m} / {c3} |")));
        assert!(md.contains("| 800 | 40 | 25.0 % | 25.0 % of 8 |"));
        // Precision: I8F8 is the last column; shader 1 failed 5 of 20 rows, Duff
        // has no pixel there (a blank cell).
        assert!(md.contains(" 0.100 / 1 (25.0 % rows failed) |\n"));
        assert!(md.contains(&format!(
            "| duff | {m} / {c} | {m} / {c} | {m} / {c} | {m} / {c} |  |\n"
        )));
        // Longest span: up to 64 within one level, the error at 64 is 1.00.
        assert!(md.contains("on 3 test spans"));
        assert!(md.contains("| corrected-euler | 64 (1.00) | 64 (1.00) |"));
    }

    #[test]
    fn table2_csv_has_a_diffuse_and_specular_row_per_torus_and_shader() {
        let (head, rows) = csv_rows(&table2_csv(&results().tori));
        assert_eq!(
            head,
            ["polygons", "method", "term", "mean", "max", "pixels"]
        );
        assert_eq!(rows.len(), 4 * COLUMNS.len() * (1 + SHININESS.len()));
        assert_eq!(
            rows[0],
            ["288", "phong-pixel", "diffuse", "0.000000", "0", "10"]
        );
        let duff_s200 = rows
            .iter()
            .find(|r| r[0] == "1152" && r[1] == "duff" && r[2] == "specular200")
            .expect("a row");
        let c = crate::studies::compare::index(shader("duff"));
        let mean = format!("{:.6}", c as f64 / 10.0);
        let max = (c + 3).to_string();
        assert_eq!(duff_s200[3..], [mean.as_str(), max.as_str(), "10"]);
    }

    #[test]
    fn precision_csv_has_a_row_per_precision_and_shader() {
        let (head, rows) = csv_rows(&precision_csv(&results().precision));
        assert_eq!(
            head,
            [
                "precision",
                "method",
                "mean_vs_phong",
                "max_vs_phong",
                "mean_vs_f64",
                "max_vs_f64",
                "pixels",
                "failed_rows",
                "rows"
            ]
        );
        assert_eq!(rows.len(), PRECISIONS.len() * COLUMNS.len());
        let r = &rows[PRECISIONS.len() * COLUMNS.len() - COLUMNS.len() + 1];
        assert_eq!(
            r,
            &[
                "I8F8",
                &COLUMNS[1].label(),
                "0.100000",
                "1",
                "0.100000",
                "2",
                "10",
                "5",
                "20"
            ]
        );
    }

    #[test]
    fn spans_csv_has_a_row_per_shader_precision_and_length() {
        let (head, rows) = csv_rows(&spans_csv(&results().spans));
        assert_eq!(head, ["method", "precision", "n", "max_error_levels"]);
        assert_eq!(
            rows.len(),
            Method::ALL.len() * PRECISIONS.len() * SPAN_LENGTHS.len()
        );
        assert_eq!(rows[0], [&*Method::ALL[0].name(), "f64", "1", "0.015625"]);
        assert_eq!(rows[12], [&*Method::ALL[0].name(), "f64", "4096", "fails"]);
    }

    /// A 40 × 30 frame: shader `c` has level `c` everywhere but the top row (nothing).
    fn frame() -> CompareFrame {
        let (w, h) = (40u32, 30u32);
        CompareFrame {
            width: w,
            height: h,
            picture: (0..COLUMNS.len())
                .map(|c| (0..w * h).map(|i| (i >= w).then_some(c as u8)).collect())
                .collect(),
            skip_map: Vec::new(),
            squared_map: Vec::new(),
            stats: CompareStats::default(),
        }
    }

    #[test]
    fn the_grid_has_a_title_a_labelled_pair_per_shader_and_a_legend() {
        let f = frame();
        let title = ["title".to_string()];
        let g = grid(&f, &title);
        assert_eq!(g.width(), 8 * f.width);
        // Tiles too narrow for scale 2: labels at scale 1, a head of one line and 8
        // pixels per row.
        let rows = (COLUMNS.len() as u32).div_ceil(4);
        let top = text_strip(g.width(), &title, 2).height();
        let legend = grid_legend(g.width()).height();
        let head = text::text_height(1) + 8;
        let tiles = rows * (f.height + head);
        assert_eq!(g.height(), top + tiles + legend);
        // The heat map of shader 5 (second row, second pair) is red (5 ≥ 3) at its
        // bottom-right pixel; that of the reference is the colour of 0.
        let y = top + (head + f.height) + head + f.height - 1;
        let heat5 = g.get_pixel(4 * f.width - 1, y);
        assert_eq!(*heat5, crate::studies::pictures::heat_colour(5));
        let y0 = top + head + f.height - 1;
        assert_eq!(
            *g.get_pixel(2 * f.width - 1, y0),
            crate::studies::pictures::heat_colour(0)
        );
        // Text (INK) is drawn in the head above the first tile.
        let has_ink = (0..f.width).any(|x| (top..top + head).any(|y| *g.get_pixel(x, y) == INK));
        assert!(has_ink);
        // Labels are cut to their tiles: no ink within 4 pixels of a tile's edge.
        for row in 0..rows {
            let y0 = top + row * (head + f.height);
            for edge in (1..8).map(|k| k * f.width) {
                for x in edge - 4..edge + 4 {
                    for y in y0..y0 + head {
                        assert_ne!(*g.get_pixel(x, y), INK, "label ink at ({x}, {y})");
                    }
                }
            }
        }
    }
}
