//! `reproduce --fit`: the calibration study, its best scene confirmed at the full frame
//! count beside the start scene, and the report (`fit.md`, `fit_sensitivity.svg`).

use super::super::output::OutDir;
use super::super::CliError;
use super::ReproduceArgs;
use indicatif::{ProgressBar, ProgressStyle};
use phong_approx::studies::calibrate::{
    calibrate, describe, describe_fit, fit, report_md, residual_table, sensitivity_svg, Space,
    MAX_PASSES,
};
use phong_approx::studies::experiment::Experiment;
use std::fmt::Write as _;
use std::time::Instant;

/// Frames per scene of the search at most, unless `--yes`: with up to
/// `MAX_PASSES × Space::per_pass()` scenes (160) of up to 260×260 pixels, 100 frames
/// per scene is about 2.5 times the default search (a few minutes on 2 cores).
pub const MAX_FIT_FRAMES: u32 = 100;

/// Refuses, unless `yes`, a search of more than [`MAX_FIT_FRAMES`] frames per scene.
///
/// # Errors
/// A [`CliError`] naming `--fit-frames` and the limit.
pub(super) fn budget(fit_frames: u32, yes: bool) -> Result<(), CliError> {
    if fit_frames > MAX_FIT_FRAMES && !yes {
        let scenes = MAX_PASSES * Space::paper().per_pass();
        return Err(CliError::arg(
            "--fit-frames",
            format!("{fit_frames} frames for each of up to {scenes} scenes is more than {MAX_FIT_FRAMES} per scene, which takes many minutes; pass --yes to run anyway"),
        ));
    }
    Ok(())
}

/// The files `reproduce --fit` writes.
pub const FIT_OUTPUTS: [&str; 2] = ["fit.md", "fit_sensitivity.svg"];

fn bar(what: &'static str) -> ProgressBar {
    let b = ProgressBar::new_spinner();
    b.set_style(
        ProgressStyle::with_template("{spinner} {msg}: {pos} frames rendered {elapsed}")
            .expect("template"),
    );
    b.set_message(what);
    b
}

/// Runs the study from `start` (each scene at `fit_frames` frames), then renders the
/// best and the start scene at `start.frames` frames and writes the report.
///
/// # Errors
/// A [`CliError`] naming the output file that could not be written.
pub(super) fn run(a: &ReproduceArgs, start: &Experiment, fit_frames: u32) -> Result<(), CliError> {
    let out = OutDir::open(&a.out, a.force, "--out")?;
    out.check_all(FIT_OUTPUTS)?;
    let space = Space::paper();
    let started = Instant::now();
    let b = bar("fitting the scene");
    let study = calibrate(start, &space, fit_frames, &|| b.inc(1));
    b.finish_and_clear();
    let b = bar("confirming the best and the start scene");
    let confirm = |e: &Experiment| {
        let exp = Experiment {
            frames: start.frames,
            exact_frames: 0,
            frame_stride: 1,
            ..e.clone()
        };
        let results = exp.run(&|| b.inc(1));
        (fit(&results), results)
    };
    let (best, best_results) = confirm(&study.best.exp);
    let (first, _) = confirm(&study.start.exp);
    b.finish_and_clear();
    let mut md = report_md(&study, &space, fit_frames);
    let met =
        |f: &phong_approx::studies::calibrate::Fit| f.residuals.iter().filter(|r| r.met()).count();
    let _ = writeln!(
        md,
        "\n## Confirmed at {} frames\n\nBest scene: {} — {}; distance {:.3}, {} of 28 targets met.\n",
        start.frames,
        describe(&study.best.exp),
        describe_fit(&best),
        best.distance,
        met(&best)
    );
    md.push_str(&residual_table(&best));
    let _ = writeln!(
        md,
        "\nTable 1 of the best scene under every reading (percent of rows; in brackets with the one-pixel rows), beside the paper's:\n"
    );
    md.push_str(&phong_approx::studies::reproduction::table1_md(
        &best_results,
    ));
    let _ = writeln!(
        md,
        "\nStart scene: {} — {}; distance {:.3}, {} of 28 targets met.\n",
        describe(&study.start.exp),
        describe_fit(&first),
        first.distance,
        met(&first)
    );
    md.push_str(&residual_table(&first));
    let _ = writeln!(md, "\nRan in {:.0} s.", started.elapsed().as_secs_f64());
    outp!("{md}")?;
    out.write("fit.md", &md)?;
    let svg = sensitivity_svg(&study).map_err(|e| CliError::arg("--fit", e))?;
    out.write("fit_sensitivity.svg", &svg)?;
    out.commit()?;
    outln!(
        "\nWrote fit.md and fit_sensitivity.svg to {}",
        a.out.display()
    )?;
    Ok(())
}
