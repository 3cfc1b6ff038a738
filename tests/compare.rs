//! The comparison harness (`phong-approx compare`): its reference against exact
//! rationals, the relations the tables must show, and the command line.

use crate::runner;

use phong_approx::raster::mesh::{torus, NormalMode};
use phong_approx::studies::compare::{
    index, render_compare, runs_in, CompareOptions, Shader, COLUMNS, SHININESS,
};
use phong_approx::studies::precision::{self, longest, SPAN_LENGTHS};
use phong_approx::studies::render::Scene;
use phong_approx::BigRational;
use phong_approx::Method;

fn small() -> (phong_approx::raster::mesh::Mesh, Scene) {
    (
        torus(24, 12, 1.0, 0.4, NormalMode::Analytic),
        Scene::new(96, 96, 1.4),
    )
}

/// The whole generic row pipeline run in exact rationals agrees with its `f64` run:
/// the `f64` levels differ from the exact ones only where a value sits within
/// rounding of a level boundary (rare), never by more than one level.
#[test]
fn f64_harness_agrees_with_exact_rationals() {
    let (mesh, _) = small();
    let scene = Scene::new(24, 24, 1.4);
    let exact = precision::frame::<BigRational>(&mesh, &scene, 3);
    assert!(exact.rows > 30, "too few rows: {}", exact.rows);
    for (c, sh) in COLUMNS.iter().enumerate() {
        let d = &exact.vs_f64[c];
        if !runs_in::<BigRational>(sh) {
            // The row set-ups are f32/f64 kernels: not run in rationals.
            assert_eq!((d.pixels, exact.failed_rows[c]), (0, 0), "{}", sh.label());
            continue;
        }
        assert_eq!(exact.failed_rows[c], 0, "{}", sh.label());
        assert!(d.pixels > 100, "{}: {} pixels", sh.label(), d.pixels);
        assert!(d.max <= 1, "{}: max {}", sh.label(), d.max);
        assert!(d.mean() < 0.01, "{}: mean {}", sh.label(), d.mean());
    }
}

/// The relations the extended tables must show on one frame: the reference column
/// is zero; the Phong-valued methods (span Phong, Duff, symmetric Phong, binary and
/// spherical on fine spans) and corrected Euler within one level; every column over
/// the same pixels; Euler and the fence worse than corrected Euler.
#[test]
fn one_frame_relations() {
    let (mesh, scene) = small();
    let f = render_compare(&mesh, &scene, 5, CompareOptions::default());
    let st = &f.stats;
    assert!(st.pixels > 1000);
    assert_eq!(st.dropped_rows, 0);
    let d = |s: Shader| &st.diffuse[index(s)];
    // Every column is measured against the exact Phong per pixel: one that is known
    // to deviate must, or nothing was measured (the reference column's own 0 is by
    // construction and says nothing).
    assert!(d(Shader::VertexGouraud).max > 0);
    for k in 0..SHININESS.len() {
        assert!(
            st.specular[k][index(Shader::VertexGouraud)].max > 0,
            "shininess {k}"
        );
    }
    for s in [
        Shader::Span(Method::Phong),
        Shader::Span(Method::Duff),
        Shader::Span(Method::SymmetricPhong),
        Shader::Span(Method::CorrectedEuler),
    ] {
        assert!(d(s).max <= 1, "{}: {}", s.label(), d(s).max);
    }
    for dev in &st.diffuse {
        assert_eq!(dev.pixels, st.pixels);
    }
    assert!(d(Shader::Span(Method::Euler)).mean() > d(Shader::Span(Method::CorrectedEuler)).mean());
    assert!(
        d(Shader::Span(Method::Gouraud)).mean() > d(Shader::Span(Method::CorrectedEuler)).mean()
    );
    assert!(d(Shader::VertexGouraud).mean() > d(Shader::Span(Method::Gouraud)).mean());
    assert!(st.adaptive_gouraud <= st.spans);
    for dc in &st.specular_delta {
        assert!(dc.gouraud_but_differ <= dc.gouraud && dc.gouraud <= st.spans);
    }
    // Without the skip study nothing is counted.
    assert!(st.skip.iter().all(|c| c.spans == 0));
}

/// The skip study on one frame (`studies::compare`'s skip counts, §7.1 question a):
/// every span decided exactly at each shininess, more skipped as the shininess grows,
/// and in the spans Phong's test skips no `f32` run of Phong, Duff or symmetric Phong
/// has a specular level above 0 — nor corrected Euler's run in those its cheap test
/// skips — on this frame (the exact values' levels are 0 by `phong_skip_levels`; this
/// checks the `f32` runs against the exact decision); the float form with its `ieee`
/// margins skips nearly as much, and no `f32` level above 0 either.
#[test]
fn one_frame_skip_study() {
    use phong_approx::studies::compare::SKIP_SHININESS;
    let (mesh, scene) = small();
    let opts = CompareOptions {
        skip_study: true,
        ..CompareOptions::default()
    };
    let st = render_compare(&mesh, &scene, 5, opts).stats;
    assert_eq!(st.skip.len(), SKIP_SHININESS.len());
    let mut last = 0;
    for c in &st.skip {
        assert_eq!(c.spans, st.spans);
        assert_eq!(c.undecided, 0);
        assert!(c.skipped >= last && c.skipped <= c.spans, "{c:?}");
        last = c.skipped;
        assert_eq!(c.changed, 0, "{c:?}");
        assert_eq!(c.changed_cheap, 0, "{c:?}");
        // The float form skips only what the exact test skips, nearly all of it, and
        // no f32 run has a level above 0 where it skips.
        assert!(
            c.skipped_float <= c.skipped && 100 * c.skipped_float >= 95 * c.skipped,
            "{c:?}"
        );
        assert_eq!(c.changed_float, 0, "{c:?}");
        assert!(c.combined_changed <= c.combined_pixels);
    }
    // At s = 128 most spans of a torus have no highlight.
    assert!(2 * st.skip[3].skipped > st.spans, "{:?}", st.skip[3]);
    // The squared method's study counts the same pixels at every shininess.
    let px = st.squared[0].pixels;
    assert!(px > st.spans, "{:?}", st.squared);
    for c in &st.squared {
        assert_eq!(c.pixels, px);
        assert!(c.differ.iter().all(|&d| d <= px), "{c:?}");
    }
    println!("{:?}", st.squared);
}

/// The longest span is the last length before the first error above one level.
#[test]
fn longest_span_logic() {
    let mut e: Vec<Option<f64>> = vec![Some(0.1); SPAN_LENGTHS.len()];
    assert_eq!(longest(&e), Some(*SPAN_LENGTHS.last().unwrap()));
    e[5] = Some(1.5);
    assert_eq!(longest(&e), Some(SPAN_LENGTHS[4]));
    e[2] = None;
    assert_eq!(longest(&e), Some(SPAN_LENGTHS[1]));
    e[0] = Some(2.0);
    assert_eq!(longest(&e), None);
}

/// The test spans are what the table says: unit vectors, normals 5°–45° apart, light
/// within 60° of `N_a`.
#[test]
fn long_span_directions() {
    for (na, nb, l) in precision::test_directions(64) {
        for v in [&na, &nb, &l] {
            assert!((v.dot(v) - 1.0).abs() < 1e-12);
        }
        let a = na.dot(&nb).clamp(-1.0, 1.0).acos().to_degrees();
        assert!((5.0 - 1e-9..=45.0 + 1e-9).contains(&a), "{a}");
        let b = na.dot(&l).clamp(-1.0, 1.0).acos().to_degrees();
        assert!(b <= 60.0 + 1e-9, "{b}");
    }
}

/// In `f64` every span method stays within one level of itself at every length (the
/// table's first column), and `I8F8` cannot hold even a one-step span's Phong value.
#[test]
fn long_span_extremes() {
    let dirs = precision::test_directions(4);
    for m in phong_approx::Method::ALL {
        let e = precision::span_errors::<f64>(m, &dirs);
        assert_eq!(longest(&e), Some(4096), "{m}");
    }
    let e = precision::span_errors::<phong_approx::lowp::I8F8>(Method::Phong, &dirs);
    assert!(e[0].unwrap() > 1.0);
}

#[test]
fn cli_compare_writes_its_tables_and_pictures() {
    let out = std::env::temp_dir().join(format!("phong-compare-{}", std::process::id()));
    let o = runner::bin()
        .args([
            "compare",
            "--frames",
            "1",
            "--precision-frames",
            "1",
            "--spans",
            "2",
            "--size",
            "64x64",
            "--out",
        ])
        .arg(&out)
        .output()
        .expect("runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let md = std::fs::read_to_string(out.join("comparison.md")).expect("comparison.md");
    for sh in COLUMNS.iter() {
        assert!(
            md.contains(&format!("| {} |", sh.label())),
            "{}",
            sh.label()
        );
    }
    let csv = std::fs::read_to_string(out.join("table2_extended.csv")).expect("csv");
    assert_eq!(
        csv.lines().count(),
        1 + 4 * COLUMNS.len() * (1 + SHININESS.len())
    );
    for f in [
        "precision.csv",
        "longest_span.csv",
        "grid.png",
        "fig4_corrected_euler_s50.png",
        "fig5_phong_s200.png",
    ] {
        assert!(out.join(f).exists(), "{f}");
    }
    let _ = std::fs::remove_dir_all(out);
}

/// The row set-ups of `fast_rows` as columns: on one frame each is within one level of
/// its span method at every pixel's level statistics (same mean to 0.01, max within
/// one), corrected Euler's and Phong's within one level of the reference, Phong of
/// the field as close to the reference as the reference's own `f32` run; they run in
/// `f32` and `f64` (the `rsqrt` ones in `f32`) and in no other precision.
#[test]
fn row_setups_match_their_span_methods() {
    use phong_approx::raster::shader::{RowSetup, Shader as S};
    let (mesh, scene) = small();
    let f = render_compare(&mesh, &scene, 7, CompareOptions::default());
    let st = &f.stats;
    assert_eq!(st.dropped_rows, 0);
    let d = |s: Shader| &st.diffuse[index(s)];
    for r in RowSetup::ALL {
        let (row, span) = (d(S::Rows(r)), d(S::Span(r.method())));
        assert_eq!(row.pixels, st.pixels, "{r:?}");
        if r == RowSetup::FieldPhong || r == RowSetup::FieldPhongRsqrt {
            assert!(
                row.max <= 1 && row.mean() < 0.001,
                "{r:?}: {} / {}",
                row.mean(),
                row.max
            );
        } else {
            assert!(
                (row.mean() - span.mean()).abs() < 0.01,
                "{r:?}: {} vs {}",
                row.mean(),
                span.mean()
            );
            assert!(
                row.max <= span.max + 1,
                "{r:?}: max {} vs {}",
                row.max,
                span.max
            );
        }
        if r.method() != Method::Gouraud {
            assert!(row.max <= 1, "{r:?}: max {}", row.max);
        }
        assert!(runs_in::<f32>(&S::Rows(r)));
        use phong_approx::lowp::{f16, I16F16, I8F8};
        assert!(!runs_in::<f16>(&S::Rows(r)), "{r:?} in f16");
        assert!(!runs_in::<I16F16>(&S::Rows(r)), "{r:?} in I16F16");
        assert!(!runs_in::<I8F8>(&S::Rows(r)), "{r:?} in I8F8");
        assert!(!runs_in::<BigRational>(&S::Rows(r)), "{r:?} in exact");
    }
    let stepped = d(S::Rows(RowSetup::SteppedCorrectedEuler));
    let batched = d(S::Rows(RowSetup::BatchedCorrectedEuler));
    assert!((stepped.mean() - batched.mean()).abs() < 0.005);
    // The precision study fills the row set-ups' cells in f32 and f64 only.
    let p32 = precision::frame::<f32>(&mesh, &scene, 2);
    let p16 = precision::frame::<phong_approx::lowp::f16>(&mesh, &scene, 2);
    for r in RowSetup::ALL {
        let c = index(S::Rows(r));
        assert!(p32.vs_phong[c].pixels > 100, "{r:?} in f32");
        assert_eq!(p16.vs_phong[c].pixels, 0, "{r:?} in f16");
        assert_eq!(p16.failed_rows[c], 0, "{r:?} in f16");
    }
}
