//! Writes the rustdoc copies of the docs that `src/lib.rs` embeds as the modules
//! `derivations`, `errata` and `float`: `$OUT_DIR/<name>.md` is `docs/<name>.md` with the
//! TeX of its `$…$` and `$$…$$` math escaped so that rustdoc's Markdown leaves it intact
//! for KaTeX (build/math.rs). The files in docs/ are the ones GitHub renders, unchanged.

use std::{env, fs, path::PathBuf};

#[path = "build/math.rs"]
mod math;

fn main() {
    let root = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("OUT_DIR"));
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=build/math.rs");
    for name in ["derivations", "errata", "float"] {
        let src = root.join("docs").join(format!("{name}.md"));
        println!("cargo:rerun-if-changed={}", src.display());
        let text =
            fs::read_to_string(&src).unwrap_or_else(|e| panic!("reading {}: {e}", src.display()));
        let dst = out.join(format!("{name}.md"));
        fs::write(&dst, math::escape_math(&text))
            .unwrap_or_else(|e| panic!("writing {}: {e}", dst.display()));
    }
}
