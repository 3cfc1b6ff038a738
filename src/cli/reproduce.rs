//! `phong-approx reproduce`: the paper's Tables 1–2 and Figures 1–5, end to end.

use super::output::OutDir;
use super::torus::{io_err, TorusArgs};
use super::CliError;
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use phong_approx::raster::mesh::NormalMode;
use phong_approx::studies::experiment::Experiment;
use phong_approx::studies::pictures::{save_png, Picture};
use phong_approx::studies::reproduction;
use std::path::PathBuf;
use std::time::Instant;

mod fit;

/// Arguments of `phong-approx reproduce`.
#[derive(Args, Debug)]
pub struct ReproduceArgs {
    /// Frames per torus (the paper: 200).
    #[arg(
        long,
        value_name = "N",
        default_value = "200",
        allow_hyphen_values = true,
        value_parser = |s: &str| super::whole(s, 1, 100_000, "")
    )]
    pub frames: u32,
    /// Output folder for the CSVs and pictures.
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
    /// Replace files in the output folder that phong-approx did not write.
    #[arg(long)]
    pub force: bool,
    /// The image and the torus.
    #[command(flatten)]
    pub torus: TorusArgs,
    /// Vertex normals: analytic (the torus's own) or averaged (from the faces).
    #[arg(long, value_name = "MODE", value_enum, default_value = "analytic")]
    pub normals: Normals,
    /// Frames of the 800-polygon torus also evaluated in exact rationals (at most
    /// --frames).
    #[arg(long, value_name = "K", default_value = "1",
          value_parser = |s: &str| super::whole(s, 0, 100_000, ""))]
    pub exact_frames: u32,
    /// The scene: `default` (docs/reproduction.md's choices, with --size, --radii and
    /// --normals) or `paper-fit` (the calibrated scene of `--fit`, which sets its own
    /// size and radii).
    #[arg(long, value_name = "NAME", value_enum, default_value = "default")]
    pub scene: SceneArg,
    /// Run the calibration study instead: fit the scene choices the paper leaves open
    /// to its Tables 1–2 (starting from --scene), confirm the best scene at --frames,
    /// and write fit.md and fit_sensitivity.svg.
    #[arg(long)]
    pub fit: bool,
    /// Frames per torus for each scene of the --fit search (at most --frames).
    #[arg(long, value_name = "N", default_value = "40",
          value_parser = |s: &str| super::whole(s, 0, 100_000, ""))]
    pub fit_frames: u32,
}

/// `--normals`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Normals {
    /// The torus's own normals.
    Analytic,
    /// Averaged from the faces.
    Averaged,
}

/// `--scene`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum SceneArg {
    /// docs/reproduction.md's choices, with --size, --radii and --normals.
    Default,
    /// The calibrated scene of `--fit`.
    PaperFit,
}

/// Runs `phong-approx reproduce`.
///
/// # Errors
/// A [`CliError`] naming the bad argument or the file that could not be written.
pub fn run(a: &ReproduceArgs) -> Result<(), CliError> {
    let frames = a.frames;
    let (size, radii) = (a.torus.size, a.torus.radii);
    let normals = match a.normals {
        Normals::Analytic => NormalMode::Analytic,
        Normals::Averaged => NormalMode::Averaged,
    };
    let exact_frames = super::within("--exact-frames", a.exact_frames, 0, frames)?;
    let exp = match a.scene {
        SceneArg::Default => Experiment {
            frames,
            size,
            radii,
            normals,
            exact_frames,
            ..Experiment::default()
        },
        SceneArg::PaperFit => Experiment {
            frames,
            normals,
            exact_frames,
            ..Experiment::paper_fit()
        },
    };
    a.torus.budget(exp.size, frames, exact_frames)?;
    if a.fit {
        let fit_frames = super::within("--fit-frames", a.fit_frames, 1, frames)?;
        fit::budget(fit_frames, a.torus.yes)?;
        return fit::run(a, &exp, fit_frames);
    }
    let out = OutDir::open(&a.out, a.force, "--out")?;
    out.check_all(reproduction::outputs())?;
    let started = Instant::now();
    let bar = ProgressBar::new(u64::from(frames) * 4);
    bar.set_style(
        ProgressStyle::with_template("{spinner} rendering {pos}/{len} frames [{bar:40}] {elapsed}")
            .expect("template")
            .progress_chars("=> "),
    );
    let results = exp.run(&|| bar.inc(1));
    bar.finish_and_clear();
    if results.iter().all(|r| r.stats.pixels == 0) {
        return Err(CliError::arg(
            "--radii",
            "the scene has no visible pixel (the torus is too small, or too large, for the image)",
        ));
    }
    let tables = reproduction::tables(&exp, &results, started.elapsed().as_secs_f64());
    outp!("{}", tables[0].1)?;
    for (name, text) in &tables {
        out.write(name, text)?;
    }
    for (name, picture) in reproduction::pictures(&exp).map_err(|e| io_err(out.dir(), e))? {
        match picture {
            Picture::Png(img) => {
                let p = out.path_for(name)?;
                save_png(&img, &p).map_err(|e| io_err(&out.dir().join(name), e))?;
            }
            Picture::Svg(svg) => out.write(name, &svg)?,
        }
    }
    out.commit()?;
    outln!(
        "\nWrote tables.md, table1.csv, table2.csv and the figures to {}",
        a.out.display()
    )?;
    Ok(())
}
