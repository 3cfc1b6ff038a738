//! `reproduce`'s refusals: every bad argument and a scene with nothing to measure get
//! one line and exit 2 before any work.

use super::*;

fn bad(args: &[&str], needle: &str) {
    let out = runner::bin().arg("reproduce").args(args).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: '{err}' lacks '{needle}'");
}

#[test]
fn bad_input_to_reproduce_gets_one_line_and_exit_2() {
    bad(&["--frames", "0"], "--frames: must be between 1");
    bad(
        &["--frames", "many"],
        "--frames: 'many' is not a whole number",
    );
    bad(&["--size", "99999x10"], "--size: 99999x10 is out of range");
    bad(&["--size", "big"], "--size: 'big' is not WxH");
    bad(&["--size", "0x0"], "--size:");
    bad(&["--radii", "1,2"], "--radii: '1,2': need 0 < r < R");
    bad(
        &["--normals", "smooth"],
        "--normals: unknown value 'smooth'",
    );
    bad(&["--scene", "nice"], "--scene: unknown value 'nice'");
    bad(
        &["--fit", "--fit-frames", "0", "--frames", "5"],
        "--fit-frames: must be between 1 and 5",
    );
    bad(
        &["--fit", "--fit-frames", "101", "--frames", "200"],
        "--fit-frames: 101 frames for each of up to 160 scenes",
    );
    bad(
        &["--exact-frames", "500", "--frames", "10"],
        "--exact-frames: must be between 0 and 10",
    );
    // An output "folder" that is a file, and one under /proc.
    let file = std::env::temp_dir().join(format!("phong-approx-file-{}", std::process::id()));
    std::fs::write(&file, b"x").unwrap();
    bad(
        &["--frames", "1", "--out", file.to_str().unwrap()],
        "--out: cannot create",
    );
    let _ = std::fs::remove_file(&file);
    bad(
        &["--frames", "1", "--out", "/proc/phong-approx"],
        "--out: cannot",
    );
}

/// Defect d10 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn a_scene_with_no_visible_pixel_exits_2() {
    let d = scratch("d10");
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--radii",
        "1e-30,1e-31",
        "--out",
        d.to_str().unwrap(),
    ]);
    refused(&o, "no visible pixel");
}

/// Defect q15 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn reproduce_messages_say_what_is_wrong() {
    refused(
        &run(&["reproduce", "--out", ""]),
        "--out: '' is not a valid value",
    );
}
