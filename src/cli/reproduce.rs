//! `phong-approx reproduce`: the paper's Tables 1–2 and Figures 1–5, end to end.

use super::output::OutDir;
use super::{parse_whole, CliError};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use phong_approx::conformance::shown;
use phong_approx::raster::experiment::{Experiment, TorusResult, PAPER_TABLE_1, PAPER_TABLE_2};
use phong_approx::raster::mesh::NormalMode;
use phong_approx::raster::pictures::{difference_image, line_plot, save_png, shaded_image, Look};
use phong_approx::raster::render::{render, RenderOptions, Scene, Shader, COLUMNS};
use phong_approx::{Method, Span, Vec3};
use std::fmt::Write as _;

use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `phong-approx reproduce`.
#[derive(Args, Debug)]
pub struct ReproduceArgs {
    /// Frames per torus (the paper: 200).
    #[arg(
        long,
        value_name = "N",
        default_value = "200",
        allow_hyphen_values = true
    )]
    pub frames: String,
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
    #[arg(long, value_name = "MODE", default_value = "analytic")]
    pub normals: String,
    /// Frames of the 800-polygon torus also evaluated in exact rationals.
    #[arg(long, value_name = "K", default_value = "1")]
    pub exact_frames: String,
}

/// The image size and torus radii, shared by `reproduce` and `compare`.
#[derive(Args, Debug)]
pub struct TorusArgs {
    /// Image size in pixels.
    #[arg(long, value_name = "WxH", default_value = "225x225")]
    pub size: String,
    /// Major and tube radius of the torus.
    #[arg(long, value_name = "R,r", default_value = "1,0.4")]
    pub radii: String,
    /// Run even when the request exceeds the budget (more than 1024×1024 pixels, more
    /// than 200 frames of 512×512, or exact frames of more than 600,000 pixels in
    /// all), which would take many minutes to hours.
    #[arg(long)]
    pub yes: bool,
}

/// `((width, height), (major radius, tube radius))`.
type SizeAndRadii = ((u32, u32), (f32, f32));

impl TorusArgs {
    /// The parsed `(size, radii)`.
    ///
    /// # Errors
    /// [`CliError`] naming `--size` or `--radii` when one is malformed.
    pub(crate) fn parse(&self) -> Result<SizeAndRadii, CliError> {
        Ok((parse_size(&self.size)?, parse_radii(&self.radii)?))
    }

    /// Refuses, unless `--yes`, a run whose work exceeds the budget: `frames` frames
    /// and `exact_frames` exact frames of `size` pixels.
    ///
    /// # Errors
    /// A [`CliError`] naming the option and the limit.
    pub(crate) fn budget(
        &self,
        size: (u32, u32),
        frames: u32,
        exact_frames: u32,
    ) -> Result<(), CliError> {
        if self.yes {
            return Ok(());
        }
        let px = u64::from(size.0) * u64::from(size.1);
        if px > 1 << 20 {
            return Err(CliError::arg(
                "--size",
                format!("{}x{} is more than 1024×1024 pixels, which takes many minutes; pass --yes to run anyway", size.0, size.1),
            ));
        }
        if px * u64::from(frames) > 200 * 512 * 512 {
            return Err(CliError::arg(
                "--frames",
                format!("{frames} frames of {}x{} is more than 200 frames of 512×512, which takes many minutes; pass --yes to run anyway", size.0, size.1),
            ));
        }
        if px * u64::from(exact_frames) > 600_000 {
            return Err(CliError::arg(
                "--exact-frames",
                format!("{exact_frames} exact frames of {}x{} is more than 600,000 exact pixels (about a minute); pass --yes to run anyway", size.0, size.1),
            ));
        }
        Ok(())
    }
}

fn parse_size(s: &str) -> Result<(u32, u32), CliError> {
    let bad = || CliError::arg("--size", format!("'{}' is not WxH, e.g. 200x200", shown(s)));
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    if !(16..=4096).contains(&w) || !(16..=4096).contains(&h) {
        return Err(CliError::arg(
            "--size",
            format!("{w}x{h} is out of range: width and height must be between 16 and 4096"),
        ));
    }
    Ok((w, h))
}

fn parse_radii(s: &str) -> Result<(f32, f32), CliError> {
    let bad = |why: &str| CliError::arg("--radii", format!("'{}': {why}", shown(s)));
    let (a, b) = s
        .split_once(',')
        .ok_or_else(|| bad("expected R,r, e.g. 1,0.4"))?;
    let big: f32 = a.trim().parse().map_err(|_| bad("R is not a number"))?;
    let small: f32 = b.trim().parse().map_err(|_| bad("r is not a number"))?;
    if !(big.is_finite() && small.is_finite() && small > 0.0 && big > small) {
        return Err(bad("need 0 < r < R"));
    }
    Ok((big, small))
}

pub(crate) fn io_err(path: &Path, e: impl std::fmt::Display) -> CliError {
    CliError {
        message: format!("{}: {e}", path.display()),
        code: 2,
    }
}

/// The files `reproduce` writes into its folder.
const OUTPUTS: [&str; 13] = [
    "tables.md",
    "table1.csv",
    "table2.csv",
    "fig4_torus800_corrected_euler.png",
    "fig5_torus800_phong.png",
    "torus800_gouraud_diffuse.png",
    "diff_torus800_corrected_euler.png",
    "diff_torus800_gouraud.png",
    "diff_torus800_euler.png",
    "fig1_phong_minus_gouraud.svg",
    "fig2_phong_minus_euler.svg",
    "fig3_phong_minus_corrected_euler.svg",
    "fig0_curves.svg",
];

/// Runs `phong-approx reproduce`.
///
/// # Errors
/// A [`CliError`] naming the bad argument or the file that could not be written.
pub fn run(a: &ReproduceArgs) -> Result<(), CliError> {
    let frames = parse_whole("--frames", &a.frames, 1, 100_000, "")?;
    let (size, radii) = a.torus.parse()?;
    let normals = match a.normals.as_str() {
        "analytic" => NormalMode::Analytic,
        "averaged" => NormalMode::Averaged,
        o => {
            return Err(CliError::arg(
                "--normals",
                format!(
                    "unknown mode '{}' (expected analytic or averaged)",
                    shown(o)
                ),
            ))
        }
    };
    let exact_frames = parse_whole("--exact-frames", &a.exact_frames, 0, frames, "")?;
    a.torus.budget(size, frames, exact_frames)?;
    let out = OutDir::open(&a.out, a.force, "--out")?;
    out.check_all(OUTPUTS)?;
    let exp = Experiment {
        frames,
        size,
        radii,
        normals,
        exact_frames,
    };
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
    let report = report(&exp, &results, started.elapsed().as_secs_f64());
    outp!("{report}")?;
    out.write("tables.md", &report)?;
    out.write("table1.csv", &table1_csv(&results))?;
    out.write("table2.csv", &table2_csv(&results))?;
    pictures(&exp, &out)?;
    out.commit()?;
    outln!(
        "\nWrote tables.md, table1.csv, table2.csv and the figures to {}",
        a.out.display()
    )?;
    Ok(())
}

/// The Markdown report: scene, Table 2 beside the paper's, all methods, Table 1.
fn report(exp: &Experiment, results: &[TorusResult], secs: f64) -> String {
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
        "Scene: tori R = {}, r = {}, {} normals; {}×{} pixels, orthographic, {:.1} px per unit; light {:?}; K_d = {}; rotation {}°, {}°, {}° per frame about x, y, z; {} frames per torus; {:.0} visible pixels per frame on average; f32 arithmetic; {:.1} s.\n",
        exp.radii.0,
        exp.radii.1,
        match exp.normals {
            NormalMode::Analytic => "analytic",
            NormalMode::Averaged => "face-averaged",
        },
        scene.width,
        scene.height,
        scene.scale,
        [scene.light.x, scene.light.y, scene.light.z].map(|v| (v * 1e4).round() / 1e4),
        scene.kd,
        scene.rates_deg.x,
        scene.rates_deg.y,
        scene.rates_deg.z,
        exp.frames,
        px as f64 / frames.max(1) as f64,
        secs
    );
    let col = |c: Shader| COLUMNS.iter().position(|x| *x == c).expect("column");
    let g = col(Shader::Span(Method::Gouraud));
    let gv = col(Shader::VertexGouraud);
    let e = col(Shader::Span(Method::Euler));
    let ce = col(Shader::Span(Method::CorrectedEuler));
    let _ = writeln!(
        s,
        "## Table 2: deviation from Phong in 8-bit levels (mean / max), ours beside the paper's\n"
    );
    let _ = writeln!(s, "| polygons | Gouraud (paper) | Gouraud, span | Gouraud, vertex | Euler (paper) | Euler | Corr. Euler (paper) | Corr. Euler |");
    let _ = writeln!(s, "|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (r, p) in results.iter().zip(PAPER_TABLE_2) {
        let d = &r.stats.deviation;
        let f = |i: usize| format!("{:.3} / {}", d[i].mean(), d[i].max);
        let _ = writeln!(
            s,
            "| {} | {:.2} / {} | {} | {} | {:.2} / {} | {} | {:.3} / {} | {} |",
            r.polygons,
            p.1,
            p.2,
            f(g),
            f(gv),
            p.3,
            p.4,
            f(e),
            p.5,
            p.6,
            f(ce)
        );
    }
    let _ = writeln!(
        s,
        "\n## Table 2, every method (mean / max deviation from Phong, 8-bit levels)\n"
    );
    let mut head = String::from("| polygons |");
    let mut rule = String::from("|---:|");
    for c in COLUMNS.iter().skip(1) {
        let _ = write!(head, " {} |", c.label());
        rule.push_str("---:|");
    }
    let _ = writeln!(s, "{head}\n{rule}");
    for r in results {
        let mut line = format!("| {} |", r.polygons);
        for d in r.stats.deviation.iter().skip(1) {
            let _ = write!(line, " {:.3} / {} |", d.mean(), d.max);
        }
        let _ = writeln!(s, "{line}");
    }
    let _ = writeln!(s, "\n## Table 1: scan lines on which Gouraud gives the same 8-bit levels as corrected Euler\n");
    let _ = writeln!(s, "| polygons | paper | ours: Gouraud = corr. Euler | δ test (eq. 24) says Gouraud | … but levels differ | δ test says corr. Euler, levels equal | Gouraud = Phong | rows | 1-pixel rows |");
    let _ = writeln!(s, "|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (r, p) in results.iter().zip(PAPER_TABLE_1) {
        let t = &r.stats.rows;
        let pc = |k: u64| 100.0 * k as f64 / t.rows.max(1) as f64;
        let _ = writeln!(
            s,
            "| {} | {:.1} % | {:.1} % | {:.1} % | {:.2} % | {:.2} % | {:.1} % | {} | {} |",
            r.polygons,
            p.1,
            pc(t.gouraud_eq_corrected),
            pc(t.predicted_gouraud),
            pc(t.predicted_gouraud_but_differ),
            pc(t.predicted_corrected_but_same),
            pc(t.gouraud_eq_phong),
            t.rows,
            t.single_pixel_rows
        );
    }
    if let Some(r) = results.iter().find(|r| r.stats.exact.is_some()) {
        let x = r.stats.exact.as_ref().expect("checked");
        let _ = writeln!(
            s,
            "\n## Exact mode: the {}-polygon torus, first {} frame(s), every span also in exact rationals\n",
            r.polygons, exp.exact_frames
        );
        let _ = writeln!(s, "| method | span pixels | f32 level ≠ exact level | of which within rounding of a level boundary |");
        let _ = writeln!(s, "|---|---:|---:|---:|");
        for (c, col) in COLUMNS.iter().enumerate() {
            if *col == Shader::VertexGouraud || x.mismatches.is_empty() {
                continue;
            }
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} |",
                col.label(),
                x.pixels,
                x.mismatches[c],
                x.explained[c]
            );
        }
    }
    s
}

fn table1_csv(results: &[TorusResult]) -> String {
    let mut s = String::from("polygons,paper_percent,rows,single_pixel_rows,gouraud_eq_corrected,gouraud_eq_phong,predicted_gouraud,predicted_gouraud_but_differ,predicted_corrected_but_same\n");
    for (r, p) in results.iter().zip(PAPER_TABLE_1) {
        let t = &r.stats.rows;
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{}",
            r.polygons,
            p.1,
            t.rows,
            t.single_pixel_rows,
            t.gouraud_eq_corrected,
            t.gouraud_eq_phong,
            t.predicted_gouraud,
            t.predicted_gouraud_but_differ,
            t.predicted_corrected_but_same
        );
    }
    s
}

fn table2_csv(results: &[TorusResult]) -> String {
    let mut s = String::from("polygons,method,pixels,mean_deviation,max_deviation\n");
    for r in results {
        for (c, d) in COLUMNS.iter().zip(&r.stats.deviation) {
            let _ = writeln!(
                s,
                "{},{},{},{:.6},{}",
                r.polygons,
                c.label(),
                d.pixels,
                d.mean(),
                d.max
            );
        }
    }
    s
}

/// Figures 4–5 (the 800-polygon torus by corrected Euler and by Phong, with
/// highlights), the difference heat maps, and Figures 1–3 (one scan line, normals
/// 60° apart).
fn pictures(exp: &Experiment, out: &OutDir) -> Result<(), CliError> {
    // The pictures follow --size, scaled up by a whole factor to at least 400 pixels
    // on the shorter side.
    let k = 400u32.div_ceil(exp.size.0.min(exp.size.1)).max(1);
    let big = Experiment {
        size: (exp.size.0 * k, exp.size.1 * k),
        ..exp.clone()
    };
    let scene = big.scene();
    let mesh = big.mesh(40, 20);
    let frame = render(
        &mesh,
        &scene,
        37,
        RenderOptions {
            exact: false,
            specular: true,
        },
    );
    let look = Look::default();
    let save = |img: &image::RgbImage, name: &str| {
        let p = out.path_for(name)?;
        save_png(img, &p).map_err(|e| io_err(&out.dir().join(name), e))
    };
    save(
        &shaded_image(&frame, Shader::Span(Method::CorrectedEuler), look),
        "fig4_torus800_corrected_euler.png",
    )?;
    save(
        &shaded_image(&frame, Shader::Span(Method::Phong), look),
        "fig5_torus800_phong.png",
    )?;
    let diffuse = Look { ks: 0.0, ..look };
    save(
        &shaded_image(&frame, Shader::Span(Method::Gouraud), diffuse),
        "torus800_gouraud_diffuse.png",
    )?;
    let phong = Shader::Span(Method::Phong);
    save(
        &difference_image(&frame, Shader::Span(Method::CorrectedEuler), phong),
        "diff_torus800_corrected_euler.png",
    )?;
    save(
        &difference_image(&frame, Shader::Span(Method::Gouraud), phong),
        "diff_torus800_gouraud.png",
    )?;
    save(
        &difference_image(&frame, Shader::Span(Method::Euler), phong),
        "diff_torus800_euler.png",
    )?;
    scanline_figures(&scene, out)
}

/// The span of Figures 1–3: unit normals 60° apart in the x–z plane, the scene's
/// light, 100 steps.
pub fn figure_span(scene: &Scene) -> Span<f64> {
    let a = 30f64.to_radians();
    let na = Vec3::new(-a.sin(), 0.0, a.cos());
    let nb = Vec3::new(a.sin(), 0.0, a.cos());
    let l = Vec3::new(
        f64::from(scene.light.x),
        f64::from(scene.light.y),
        f64::from(scene.light.z),
    );
    Span::normalized(na, nb, l, 100).expect("a valid span")
}

fn scanline_figures(scene: &Scene, out: &OutDir) -> Result<(), CliError> {
    let span = figure_span(scene);
    let phong = Method::Phong.values(&span).expect("span");
    let curve = |m: Method| -> Vec<f64> {
        let v = m.values(&span).expect("span");
        phong.iter().zip(&v).map(|(p, x)| 255.0 * (p - x)).collect()
    };
    let figs = [
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
            Method::CorrectedEuler,
            "Phong − corrected Euler",
        ),
    ];
    for (file, title, m, label) in figs {
        let p = out.path_for(file)?;
        line_plot(&p, title, "difference (8-bit levels)", &[(label, curve(m))])
            .map_err(|e| io_err(&out.dir().join(file), e))?;
    }
    let p = out.path_for("fig0_curves.svg")?;
    let as_levels = |v: Vec<f64>| v.into_iter().map(|x| 255.0 * x).collect::<Vec<_>>();
    line_plot(
        &p,
        "One scan line, normals 60° apart",
        "intensity (8-bit levels)",
        &[
            ("Phong", as_levels(phong.clone())),
            (
                "Gouraud",
                as_levels(Method::Gouraud.values(&span).expect("span")),
            ),
            (
                "Euler",
                as_levels(Method::Euler.values(&span).expect("span")),
            ),
            (
                "corrected Euler",
                as_levels(Method::CorrectedEuler.values(&span).expect("span")),
            ),
        ],
    )
    .map_err(|e| io_err(&out.dir().join("fig0_curves.svg"), e))
}
