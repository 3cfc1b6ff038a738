//! The rasterizer and `phong-approx reproduce`, end to end on a few frames.

use crate::runner;
use runner::bin;

use phong_approx::raster::mesh::{torus, Mesh, NormalMode};
use phong_approx::studies::experiment::Experiment;
use phong_approx::studies::render::{render, RenderOptions, Scene, Shader, COLUMNS};
use phong_approx::Method;

fn col(c: Shader) -> usize {
    COLUMNS.iter().position(|x| *x == c).unwrap()
}

fn few_frames() -> Experiment {
    Experiment {
        frames: 6,
        size: (160, 160),
        exact_frames: 0,
        ..Experiment::default()
    }
}

#[test]
fn corrected_euler_is_within_the_tables_bound_and_beats_euler_and_gouraud() {
    let results = few_frames().run(&|| {});
    assert_eq!(results.len(), 4);
    for r in &results {
        let d = &r.stats.deviation;
        let ce = &d[col(Shader::Span(Method::CorrectedEuler))];
        let eu = &d[col(Shader::Span(Method::Euler))];
        let go = &d[col(Shader::Span(Method::Gouraud))];
        assert!(ce.pixels > 1000, "{} polygons: too few pixels", r.polygons);
        // The bound the full tables show: at most 3 levels on the coarsest torus,
        // at most 1 from 512 polygons up (paper: 3, 1, 1, 1).
        let bound = if r.polygons == 288 { 3 } else { 1 };
        assert!(
            ce.max <= bound,
            "{} polygons: corrected Euler max {}",
            r.polygons,
            ce.max
        );
        assert!(
            ce.mean() < eu.mean() && ce.mean() < go.mean(),
            "{} polygons",
            r.polygons
        );
        // Duff and symmetric Phong are Phong up to rounding: at most one level.
        assert!(d[col(Shader::Span(Method::Duff))].max <= 1);
        assert!(d[col(Shader::Span(Method::SymmetricPhong))].max <= 1);
        // Phong against itself.
        assert_eq!(d[0].max, 0);
    }
    // Finer tori are better for every approximation.
    let ce =
        |i: usize| results[i].stats.deviation[col(Shader::Span(Method::CorrectedEuler))].mean();
    assert!(ce(0) > ce(3));
}

#[test]
fn rendering_is_deterministic() {
    let e = few_frames();
    let a = e.run(&|| {});
    let b = e.run(&|| {});
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.stats, y.stats);
    }
}

#[test]
fn a_flat_grid_is_covered_exactly_once_through_the_renderer() {
    // A 12×9 grid of quads facing the viewer (jittered inside), tiling a rectangle.
    let (gw, gh) = (13usize, 10usize);
    let mut positions = Vec::new();
    for j in 0..gh {
        for i in 0..gw {
            let inner = i > 0 && j > 0 && i < gw - 1 && j < gh - 1;
            let jit = if inner {
                ((i * 5 + j * 3) % 7) as f32 * 0.013 - 0.04
            } else {
                0.0
            };
            positions.push(glam::Vec3::new(
                -1.2 + 0.2 * i as f32 + jit,
                -0.9 + 0.2 * j as f32 - jit,
                0.0,
            ));
        }
    }
    let normals = vec![glam::Vec3::Z; positions.len()];
    let mut quads = Vec::new();
    for j in 0..gh - 1 {
        for i in 0..gw - 1 {
            let k = |i: usize, j: usize| (j * gw + i) as u32;
            quads.push([k(i, j), k(i + 1, j), k(i + 1, j + 1), k(i, j + 1)]);
        }
    }
    let mesh = Mesh {
        positions,
        normals,
        quads,
    };
    let mut scene = Scene::new(120, 120, 1.5);
    scene.rates_deg = glam::Vec3::ZERO;
    let frame = render(&mesh, &scene, 0, RenderOptions::default());
    let (cx, cy, s) = (60.0f32, 60.0f32, scene.scale);
    for y in 0..120u32 {
        for x in 0..120u32 {
            // Centre inside [-1.2, 1.2] × [-0.9, 0.9] in world units?
            let wx = (x as f32 + 0.5 - cx) / s;
            let wy = (cy - (y as f32 + 0.5)) / s;
            let w = frame.writes[(y * 120 + x) as usize];
            let margin = 0.5 / s;
            if wx.abs() < 1.2 - margin && wy.abs() < 0.9 - margin {
                assert_eq!(w, 1, "pixel ({x}, {y}) written {w} times");
            } else if wx.abs() > 1.2 + margin || wy.abs() > 0.9 + margin {
                assert_eq!(w, 0, "pixel ({x}, {y}) outside written");
            } else {
                assert!(w <= 1, "pixel ({x}, {y}) on the border written {w} times");
            }
        }
    }
}

#[test]
fn back_faces_are_culled_and_depth_test_keeps_the_front() {
    // A torus seen edge-on and face-on: the visible pixel count is within the
    // projected area, and no pixel keeps more than one surface.
    let mesh = torus(40, 20, 1.0, 0.4, NormalMode::Analytic);
    let scene = Scene::new(200, 200, 1.4);
    let frame = render(&mesh, &scene, 0, RenderOptions::default());
    let visible = frame.levels[0].iter().filter(|l| l.is_some()).count() as f32;
    let area = std::f32::consts::PI * (1.4f32.powi(2) - 0.6f32.powi(2)) * scene.scale.powi(2);
    assert!(
        (visible - area).abs() / area < 0.03,
        "visible {visible}, torus area {area}"
    );
}

#[test]
fn exact_mode_agrees_with_the_f32_pipeline() {
    let e = Experiment {
        frames: 1,
        size: (96, 96),
        exact_frames: 1,
        ..Experiment::default()
    };
    let results = e.run(&|| {});
    let x = results
        .iter()
        .find_map(|r| r.stats.exact.clone())
        .expect("exact mode ran");
    assert!(x.pixels > 500);
    // Every mismatch is explained by rounding near a level boundary.
    assert_eq!(x.mismatches, x.explained);
    let total: u64 = x.mismatches.iter().sum();
    assert!(
        total * 1000 < x.pixels,
        "{total} mismatches in {} pixels",
        x.pixels
    );
}

/// Runs `reproduce` with `args` into a fresh folder named after `tag`; its stdout and
/// the folder.
fn reproduce(tag: &str, args: &[&str]) -> (String, std::path::PathBuf) {
    let dir = std::env::temp_dir().join(format!("phong-approx-{tag}-{}", std::process::id()));
    let out = bin()
        .arg("reproduce")
        .args(args)
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (String::from_utf8(out.stdout).unwrap(), dir)
}

#[test]
fn reproduce_writes_tables_and_pictures() {
    let (text, dir) = reproduce(
        "repro",
        &["--frames", "2", "--size", "120x120", "--exact-frames", "0"],
    );
    assert!(text.contains("## Table 2"), "{text}");
    assert!(
        text.contains("| 800 | 0.38 / 6 |"),
        "paper's values beside ours"
    );
    assert!(text.contains("## Table 1"));
    for f in [
        "tables.md",
        "table1.csv",
        "table2.csv",
        "fig1_phong_minus_gouraud.svg",
        "fig2_phong_minus_euler.svg",
        "fig3_phong_minus_corrected_euler.svg",
        "fig4_torus800_corrected_euler.png",
        "fig5_torus800_phong.png",
        "diff_torus800_corrected_euler.png",
    ] {
        let p = dir.join(f);
        assert!(
            std::fs::metadata(&p)
                .map(|m| m.len() > 100)
                .unwrap_or(false),
            "{f} missing"
        );
    }
    let csv = std::fs::read_to_string(dir.join("table2.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 4 * COLUMNS.len());
    // Every reading of Table 1 is printed.
    for r in phong_approx::studies::render::Reading::ALL {
        assert!(text.contains(r.label()), "{}", r.label());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn reproduce_runs_the_calibrated_scene() {
    let (text, dir) = reproduce(
        "fit",
        &[
            "--scene",
            "paper-fit",
            "--frames",
            "1",
            "--exact-frames",
            "0",
        ],
    );
    let e = Experiment::paper_fit();
    let scene = format!(
        "Scene: tori R = {}, r = {}, analytic normals, ring × tube segments",
        e.radii.0, e.radii.1
    );
    assert!(text.contains(&scene), "{scene}\n{text}");
    assert!(text.contains(&format!("; {}×{} pixels,", e.size.0, e.size.1)));
    assert!(text.contains(&format!("K_d = {}", e.setup.kd)));
    let _ = std::fs::remove_dir_all(&dir);
}
