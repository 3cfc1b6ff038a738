//! The one way the tests run the `phong-approx` binary as a process.
#![allow(dead_code)]

use std::process::{Command, Output};

/// The binary under test, as a command to add arguments to.
pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_phong-approx"))
}

/// Runs the binary with `args` to the end.
pub fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("the binary runs")
}

/// The exit code (−1 for a signal).
pub fn code(o: &Output) -> i32 {
    o.status.code().unwrap_or(-1)
}

/// Standard error, lossily.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Exit code 2 with one line on stderr that contains `needle`, and no panic.
pub fn refused(o: &Output, needle: &str) {
    let e = stderr(o);
    assert_eq!(code(o), 2, "expected exit 2, got {}: {e}", code(o));
    assert!(!e.contains("panicked"), "panic: {e}");
    assert_eq!(e.trim_end().lines().count(), 1, "not one line: {e}");
    assert!(e.contains(needle), "'{needle}' not in: {e}");
}
