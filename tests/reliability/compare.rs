//! `compare`'s refusals: every bad argument gets one line and exit 2.

use super::*;

#[test]
fn cli_compare_rejects_bad_arguments() {
    for (args, needle) in [
        (vec!["--frames", "0"], "--frames"),
        (vec!["--spans", "x"], "--spans"),
        (vec!["--size", "5x5"], "--size"),
        (vec!["--precision-frames", "-3"], "--precision-frames"),
    ] {
        let o = runner::bin()
            .arg("compare")
            .args(&args)
            .output()
            .expect("runs");
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{err}");
    }
}
