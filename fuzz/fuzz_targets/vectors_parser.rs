//! Fuzzes the vector-file reader: any bytes must parse and validate to a file or give
//! an error, never a panic, a hang or unbounded memory.
#![no_main]

use libfuzzer_sys::fuzz_target;
use phong_approx::conformance::integrity::{sha256_hex, validate};
use phong_approx::conformance::vectors::VectorFile;

fuzz_target!(|data: &[u8]| {
    let _ = sha256_hex(data);
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(file) = serde_json::from_str::<VectorFile>(text) {
            let _ = validate(&file);
        }
    }
});
