//! `phong-approx compare`: every method of the paper and its related work on the same
//! tori — extended Table 2 (diffuse and specular), the adaptive scheme, the precision
//! tables, and a picture grid with heat maps.

use super::output::OutDir;
use super::torus::TorusArgs;
use super::CliError;
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use phong_approx::studies::compare;
use phong_approx::studies::compare_report::{
    self as report, picture_names, Measured, GRID, TABLES,
};
use phong_approx::studies::experiment::Experiment;
use phong_approx::studies::pictures::save_png;
use phong_approx::studies::precision::PRECISIONS;
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
        allow_hyphen_values = true,
        value_parser = |s: &str| super::whole(s, 1, 100_000, "")
    )]
    pub frames: u32,
    /// Frames of the 800-polygon torus for the precision table.
    #[arg(
        long,
        value_name = "N",
        default_value = "20",
        allow_hyphen_values = true,
        value_parser = |s: &str| super::whole(s, 1, 100_000, "")
    )]
    pub precision_frames: u32,
    /// Test spans per length in the long-span study.
    #[arg(
        long,
        value_name = "N",
        default_value = "24",
        allow_hyphen_values = true,
        value_parser = |s: &str| super::whole(s, 1, 10_000, "")
    )]
    pub spans: u32,
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
        allow_hyphen_values = true,
        value_parser = |s: &str| super::whole(s, 0, 1_000_000, "")
    )]
    pub picture_frame: u32,
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

/// Runs `phong-approx compare`.
///
/// # Errors
/// A [`CliError`] naming the bad argument or the file that could not be written.
pub fn run(a: &CompareArgs) -> Result<(), CliError> {
    let (frames, pframes) = (a.frames, a.precision_frames);
    let (span_count, picture_frame) = (a.spans as usize, a.picture_frame);
    let (size, radii) = (a.torus.size, a.torus.radii);
    a.torus.budget(size, frames.max(pframes), 0)?;
    let out = OutDir::open(&a.out, a.force, "--out")?;
    let pictures = picture_names();
    out.check_all(
        TABLES
            .into_iter()
            .chain([GRID])
            .chain(pictures.iter().map(String::as_str)),
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
    let b = bar(
        u64::from(pframes) * PRECISIONS.len() as u64,
        "precisions, 800-polygon torus:",
    );
    let precision = report::precision_study(&exp, pframes, &|| b.inc(1));
    b.finish_and_clear();
    let b = bar(
        (phong_approx::Method::ALL.len() * PRECISIONS.len()) as u64,
        "long spans:",
    );
    let spans = report::span_study(span_count, &|| b.inc(1));
    b.finish_and_clear();
    let results = Measured {
        tori,
        precision,
        spans,
        span_count,
    };
    let md = report::report_md(&exp, pframes, &results, started.elapsed().as_secs_f64());
    outp!("{md}")?;
    out.write("comparison.md", &md)?;
    out.write("table2_extended.csv", &report::table2_csv(&results.tori))?;
    out.write("precision.csv", &report::precision_csv(&results.precision))?;
    out.write("longest_span.csv", &report::spans_csv(&results.spans))?;
    for (name, img) in report::pictures(&exp, picture_frame) {
        save_png(&img, &out.path_for(&name)?).map_err(|e| CliError::arg("--out", e))?;
    }
    out.commit()?;
    outln!(
        "\nWrote comparison.md, table2_extended.csv, precision.csv, longest_span.csv, grid.png, the highlight figures, skip_map.png and squared_specular.png to {}",
        a.out.display()
    )?;
    Ok(())
}
