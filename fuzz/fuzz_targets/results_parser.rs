//! Fuzzes the checker's results parser (CSV and JSON) against the `paper` vectors:
//! any input must give results or an error, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use phong_approx::conformance::check::parse_results;
use phong_approx::conformance::vectors::VectorFile;
use std::sync::OnceLock;

fn vectors() -> &'static VectorFile {
    static V: OnceLock<VectorFile> = OnceLock::new();
    V.get_or_init(|| {
        let text = include_str!("../../vectors/paper.json");
        serde_json::from_str(text).expect("committed vectors parse")
    })
}

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let _ = parse_results(text, "fuzz", vectors(), false);
        let _ = parse_results(text, "fuzz", vectors(), true);
    }
});
