//! `phong-approx compare`: every method of the paper and its related work on the same
//! tori — extended Table 2 (diffuse and specular), the adaptive scheme, the precision
//! tables, and a picture grid with heat maps.

use super::output::OutDir;
use super::reproduce::TorusArgs;
use super::{parse_whole, CliError};
use clap::Args;
use image::{Rgb, RgbImage};
use indicatif::{ProgressBar, ProgressStyle};
use phong_approx::raster::compare::{
    self, render_compare, CompareOptions, CompareResult, Shader, SHININESS,
};
use phong_approx::raster::experiment::Experiment;
use phong_approx::raster::pictures::save_png;
use phong_approx::raster::precision::{
    self, PrecisionStats, PRECISIONS, SPAN_LENGTHS, SPAN_METHODS,
};
use rayon::prelude::*;
use std::fmt::Write as _;

use std::path::PathBuf;
use std::time::Instant;

/// Arguments of `phong-approx compare`.
#[derive(Args, Debug)]
pub struct CompareArgs {
    /// Frames per torus for the diffuse and specular tables (the paper: 200).
    #[arg(
        long,
        value_name = "N",
        default_value = "200",
        allow_hyphen_values = true
    )]
    pub frames: String,
    /// Frames of the 800-polygon torus for the precision table.
    #[arg(
        long,
        value_name = "N",
        default_value = "20",
        allow_hyphen_values = true
    )]
    pub precision_frames: String,
    /// Test spans per length in the long-span study.
    #[arg(
        long,
        value_name = "N",
        default_value = "24",
        allow_hyphen_values = true
    )]
    pub spans: String,
    /// Output folder for the tables and pictures.
    #[arg(long, value_name = "DIR", default_value = "out/compare")]
    pub out: PathBuf,
    /// Replace files in the output folder that phong-approx did not write.
    #[arg(long)]
    pub force: bool,
    /// The image and the torus.
    #[command(flatten)]
    pub torus: TorusArgs,
    /// The frame of the pictures.
    #[arg(
        long,
        value_name = "F",
        default_value = "30",
        allow_hyphen_values = true
    )]
    pub picture_frame: String,
}

fn bar(len: u64, what: &str) -> ProgressBar {
    let b = ProgressBar::new(len);
    b.set_style(
        ProgressStyle::with_template(&format!(
            "{{spinner}} {what} {{pos}}/{{len}} [{{bar:40}}] {{elapsed}}"
        ))
        .expect("template")
        .progress_chars("=> "),
    );
    b
}

/// One method of the long-span study: per precision, the errors per span length.
type SpanRow = (phong_approx::Method, Vec<(&'static str, Vec<Option<f64>>)>);

/// Everything `compare` measures.
struct Results {
    tori: Vec<CompareResult>,
    precision: Vec<(&'static str, PrecisionStats)>,
    /// Per span shader, per precision: errors per span length.
    spans: Vec<SpanRow>,
    span_count: usize,
}

/// Runs `phong-approx compare`.
///
/// # Errors
/// A [`CliError`] naming the bad argument or the file that could not be written.
pub fn run(a: &CompareArgs) -> Result<(), CliError> {
    let frames = parse_whole("--frames", &a.frames, 1, 100_000, "")?;
    let pframes = parse_whole("--precision-frames", &a.precision_frames, 1, 100_000, "")?;
    let span_count = parse_whole("--spans", &a.spans, 1, 10_000, "")? as usize;
    let picture_frame = parse_whole("--picture-frame", &a.picture_frame, 0, 1_000_000, "")?;
    let (size, radii) = a.torus.parse()?;
    a.torus.budget(size, frames.max(pframes), 0)?;
    let out = OutDir::open(&a.out, a.force, "--out")?;
    out.check_all(
        [
            "comparison.md",
            "table2_extended.csv",
            "precision.csv",
            "longest_span.csv",
            "grid.png",
        ]
        .into_iter()
        .chain(picture_names().iter().map(String::as_str)),
    )?;
    let exp = Experiment {
        frames,
        size,
        radii,
        ..Experiment::default()
    };
    let started = Instant::now();
    let b = bar(u64::from(frames) * 4, "every method, 4 tori:");
    let tori = compare::run(&exp, &|| b.inc(1));
    if tori.iter().all(|t| t.stats.spans == 0) {
        return Err(CliError::arg(
            "--radii",
            "the scene has no visible pixel (the torus is too small, or too large, for the image)",
        ));
    }
    b.finish_and_clear();
    let scene = exp.scene();
    let mesh = exp.mesh(40, 20);
    let b = bar(
        u64::from(pframes) * PRECISIONS.len() as u64,
        "precisions, 800-polygon torus:",
    );
    let precision: Vec<(&'static str, PrecisionStats)> = PRECISIONS
        .iter()
        .map(|&p| {
            let st =
                precision::torus(&mesh, &scene, pframes, p, &|| b.inc(1)).expect("known precision");
            (p, st)
        })
        .collect();
    b.finish_and_clear();
    let dirs = precision::test_directions(span_count);
    let b = bar(
        (SPAN_METHODS.len() * PRECISIONS.len()) as u64,
        "long spans:",
    );
    let spans: Vec<SpanRow> = SPAN_METHODS
        .par_iter()
        .map(|&sh| {
            let per: Vec<(&'static str, Vec<Option<f64>>)> = PRECISIONS
                .iter()
                .map(|&p| {
                    let e = precision::span_errors_named(sh, p, &dirs).expect("known precision");
                    b.inc(1);
                    (p, e)
                })
                .collect();
            (sh, per)
        })
        .collect();
    b.finish_and_clear();
    let results = Results {
        tori,
        precision,
        spans,
        span_count,
    };
    let report = report(&exp, pframes, &results, started.elapsed().as_secs_f64());
    outp!("{report}")?;
    out.write("comparison.md", &report)?;
    out.write("table2_extended.csv", &table2_csv(&results.tori))?;
    out.write("precision.csv", &precision_csv(&results.precision))?;
    out.write("longest_span.csv", &spans_csv(&results.spans))?;
    pictures(&exp, picture_frame, &out)?;
    out.commit()?;
    outln!(
        "\nWrote comparison.md, table2_extended.csv, precision.csv, longest_span.csv, grid.png and the highlight figures to {}",
        a.out.display()
    )?;
    Ok(())
}

fn report(exp: &Experiment, pframes: u32, r: &Results, secs: f64) -> String {
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
    let _ = writeln!(
        s,
        "## Methods\n\n| column | source | reconstructed | specular power |\n|---|---|---|---|"
    );
    for sh in compare::COLUMNS {
        let pw = match sh {
            Shader::PhongPixel => "exact (f64)",
            Shader::Span(phong_approx::Method::Gouraud) => "at the span's edges, interpolated",
            Shader::VertexGouraud => "at the vertices, interpolated",
            Shader::VertexAngle => "table of cos^s (byte angle)",
            s if s.power_from_table() => "1024-entry table",
            _ => "per pixel",
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} |",
            sh.label(),
            sh.source(),
            if sh.reconstructed() { "yes" } else { "" },
            pw
        );
    }
    let header = |s: &mut String| {
        table_header(s, r.tori.iter().map(|t| format!("{} polygons", t.polygons)));
    };
    let _ = writeln!(
        s,
        "\n## Extended Table 2: diffuse (N·L), mean / max deviation\n"
    );
    header(&mut s);
    for (c, sh) in compare::COLUMNS.iter().enumerate() {
        let _ = write!(s, "| {} |", sh.label());
        for t in &r.tori {
            let d = &t.stats.diffuse[c];
            let _ = write!(s, " {:.3} / {} |", d.mean(), d.max);
        }
        let _ = writeln!(s);
    }
    for (k, sv) in SHININESS.iter().enumerate() {
        let _ = writeln!(
            s,
            "\n## Extended Table 2: specular (N·H)^{sv}, mean / max deviation\n"
        );
        header(&mut s);
        for (c, sh) in compare::COLUMNS.iter().enumerate() {
            let _ = write!(s, "| {} |", sh.label());
            for t in &r.tori {
                let d = &t.stats.specular[k][c];
                let _ = write!(s, " {:.3} / {} |", d.mean(), d.max);
            }
            let _ = writeln!(s);
        }
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
    let _ = write!(s, "| torus | spans | diffuse → Gouraud |");
    for sv in SHININESS {
        let _ = write!(s, " s = {sv}: Gouraud spans that differ |");
    }
    let _ = write!(s, "\n|---:|---:|---:|");
    for _ in SHININESS {
        let _ = write!(s, "---:|");
    }
    let _ = writeln!(s);
    for t in &r.tori {
        let st = &t.stats;
        let _ = write!(
            s,
            "| {} | {} | {:.1} % |",
            t.polygons,
            st.spans,
            st.adaptive_gouraud_percent()
        );
        for d in &st.specular_delta {
            let pct = if d.gouraud == 0 {
                0.0
            } else {
                100.0 * d.gouraud_but_differ as f64 / d.gouraud as f64
            };
            let _ = write!(s, " {pct:.1} % of {} |", d.gouraud);
        }
        let _ = writeln!(s);
    }
    let _ = writeln!(
        s,
        "\n## Precision: the 800-polygon torus, {pframes} frames, every drawn pixel, mean / max deviation from \
         per-pixel Phong in f64\n\nSet-up and steps entirely in the precision; a blank cell means every row failed.\n"
    );
    table_header(&mut s, PRECISIONS.iter().map(|p| p.to_string()));
    for (c, sh) in compare::COLUMNS.iter().enumerate() {
        let _ = write!(s, "| {} |", sh.label());
        for (_, st) in &r.precision {
            let d = &st.vs_phong[c];
            let fail = st.failed_rows[c];
            if d.pixels == 0 {
                let _ = write!(s, " |");
            } else if fail > 0 {
                let _ = write!(
                    s,
                    " {:.3} / {} ({:.1} % rows failed) |",
                    d.mean(),
                    d.max,
                    100.0 * fail as f64 / st.rows as f64
                );
            } else {
                let _ = write!(s, " {:.3} / {} |", d.mean(), d.max);
            }
        }
        let _ = writeln!(s);
    }
    let _ = writeln!(
        s,
        "\nThe arithmetic's own share: the same, against the same method in f64.\n"
    );
    table_header(&mut s, PRECISIONS.iter().map(|p| p.to_string()));
    for (c, sh) in compare::COLUMNS.iter().enumerate() {
        let _ = write!(s, "| {} |", sh.label());
        for (_, st) in &r.precision {
            let d = &st.vs_f64[c];
            if d.pixels == 0 {
                let _ = write!(s, " |");
            } else {
                let _ = write!(s, " {:.3} / {} |", d.mean(), d.max);
            }
        }
        let _ = writeln!(s);
    }
    let _ = writeln!(
        s,
        "\n## Longest span within one 8-bit level\n\nPer method and precision: the longest n of {:?} up to which \
         the method in that precision stays within 1/255 of the same method in f64 on {} test spans (normals 5° to \
         45° apart, light within 60° of N_a); set-up in f64 rounded to the precision, steps in the precision. \
         “—”: not even n = 1; in brackets the worst error at n = 64, in levels.\n",
        SPAN_LENGTHS, r.span_count
    );
    table_header(&mut s, PRECISIONS.iter().map(|p| p.to_string()));
    let at64 = SPAN_LENGTHS
        .iter()
        .position(|&n| n == 64)
        .expect("64 is tried");
    for (sh, per) in &r.spans {
        let _ = write!(s, "| {} |", sh.name());
        for (_, e) in per {
            let longest = match precision::longest(e) {
                None => "—".to_string(),
                Some(n) if n == *SPAN_LENGTHS.last().expect("non-empty") => format!("≥ {n}"),
                Some(n) => n.to_string(),
            };
            let e64 = match e[at64] {
                Some(v) => format!("{v:.2}"),
                None => "fails".into(),
            };
            let _ = write!(s, " {longest} ({e64}) |");
        }
        let _ = writeln!(s);
    }
    s
}

/// A Markdown table header: `method` and one right-aligned column per name.
fn table_header(s: &mut String, columns: impl Iterator<Item = String>) {
    let columns: Vec<String> = columns.collect();
    let _ = write!(s, "| method |");
    for c in &columns {
        let _ = write!(s, " {c} |");
    }
    let _ = write!(s, "\n|---|");
    for _ in &columns {
        let _ = write!(s, "---:|");
    }
    let _ = writeln!(s);
}

fn table2_csv(tori: &[CompareResult]) -> String {
    let mut s = String::from("polygons,method,term,mean,max,pixels\n");
    for t in tori {
        for (c, sh) in compare::COLUMNS.iter().enumerate() {
            let d = &t.stats.diffuse[c];
            let _ = writeln!(
                s,
                "{},{},diffuse,{:.6},{},{}",
                t.polygons,
                sh.label(),
                d.mean(),
                d.max,
                d.pixels
            );
            for (k, sv) in SHININESS.iter().enumerate() {
                let d = &t.stats.specular[k][c];
                let _ = writeln!(
                    s,
                    "{},{},specular{sv},{:.6},{},{}",
                    t.polygons,
                    sh.label(),
                    d.mean(),
                    d.max,
                    d.pixels
                );
            }
        }
    }
    s
}

fn precision_csv(p: &[(&'static str, PrecisionStats)]) -> String {
    let mut s = String::from("precision,method,mean_vs_phong,max_vs_phong,mean_vs_f64,max_vs_f64,pixels,failed_rows,rows\n");
    for (name, st) in p {
        for (c, sh) in compare::COLUMNS.iter().enumerate() {
            let (a, b) = (&st.vs_phong[c], &st.vs_f64[c]);
            let _ = writeln!(
                s,
                "{name},{},{:.6},{},{:.6},{},{},{},{}",
                sh.label(),
                a.mean(),
                a.max,
                b.mean(),
                b.max,
                a.pixels,
                st.failed_rows[c],
                st.rows
            );
        }
    }
    s
}

fn spans_csv(spans: &[SpanRow]) -> String {
    let mut s = String::from("method,precision,n,max_error_levels\n");
    for (sh, per) in spans {
        for (p, e) in per {
            for (n, v) in SPAN_LENGTHS.iter().zip(e) {
                let v = v.map_or("fails".to_string(), |v| format!("{v:.6}"));
                let _ = writeln!(s, "{},{p},{n},{v}", sh.name());
            }
        }
    }
    s
}

fn shaded(frame: &compare::CompareFrame, c: usize) -> RgbImage {
    let mut img = RgbImage::from_pixel(frame.width, frame.height, Rgb([24, 26, 32]));
    for (idx, l) in frame.picture[c].iter().enumerate() {
        if let Some(l) = l {
            let v = f32::from(*l) / 255.0;
            let px = [(255.0 * v) as u8, (235.0 * v) as u8, (200.0 * v) as u8];
            img.put_pixel(idx as u32 % frame.width, idx as u32 / frame.width, Rgb(px));
        }
    }
    img
}

fn heat(frame: &compare::CompareFrame, c: usize) -> RgbImage {
    let mut img = RgbImage::from_pixel(frame.width, frame.height, Rgb([24, 26, 32]));
    for (idx, (a, b)) in frame.picture[c].iter().zip(&frame.picture[0]).enumerate() {
        if let (Some(a), Some(b)) = (a, b) {
            let px = match a.abs_diff(*b) {
                0 => [90, 90, 96],
                1 => [250, 220, 40],
                2 => [250, 140, 20],
                _ => [230, 30, 30],
            };
            img.put_pixel(idx as u32 % frame.width, idx as u32 / frame.width, Rgb(px));
        }
    }
    img
}

/// The highlight figures [`pictures`] writes besides `grid.png`.
fn picture_names() -> Vec<String> {
    SHININESS
        .iter()
        .flat_map(|sv| {
            ["fig4_corrected_euler", "fig5_phong"].map(|name| format!("{name}_s{sv}.png"))
        })
        .collect()
}

/// The grid (every method on the 800-polygon torus, shading and heat map side by side,
/// four methods per row in [`compare::COLUMNS`] order) and Figures 4–5 with highlights at
/// every shininess.
fn pictures(exp: &Experiment, f: u32, out: &OutDir) -> Result<(), CliError> {
    let scene = exp.scene();
    let mesh = exp.mesh(40, 20);
    for (k, sv) in SHININESS.iter().enumerate() {
        let frame = render_compare(
            &mesh,
            &scene,
            f,
            CompareOptions {
                pictures: true,
                shininess: k,
            },
        );
        if *sv == 50 {
            let (w, h) = (frame.width, frame.height);
            let per_row = 4u32;
            let rows = (compare::COLUMNS.len() as u32).div_ceil(per_row);
            let mut grid = RgbImage::from_pixel(w * 2 * per_row, h * rows, Rgb([0, 0, 0]));
            for c in 0..compare::COLUMNS.len() {
                let (gx, gy) = ((c as u32 % per_row) * 2 * w, (c as u32 / per_row) * h);
                image::imageops::replace(
                    &mut grid,
                    &shaded(&frame, c),
                    i64::from(gx),
                    i64::from(gy),
                );
                image::imageops::replace(
                    &mut grid,
                    &heat(&frame, c),
                    i64::from(gx + w),
                    i64::from(gy),
                );
            }
            save_png(&grid, &out.path_for("grid.png")?).map_err(|e| CliError::arg("--out", e))?;
        }
        for (name, sh) in [
            ("fig4_corrected_euler", Shader::Span(phong_approx::Method::CorrectedEuler)),
            ("fig5_phong", Shader::PhongPixel),
        ] {
            let p = out.path_for(&format!("{name}_s{sv}.png"))?;
            save_png(&shaded(&frame, compare::index(sh)), &p).map_err(|e| CliError::arg("--out", e))?;
        }
    }
    Ok(())
}
