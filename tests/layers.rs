//! The library's layers (ARCHITECTURE.md, "Layers"): every file of `src/` (the
//! library; the CLI is the binary's and imports the library by name) imports only
//! from its own layer or lower ones, and no files import each other in a circle.
//!
//! Imports are read from the code as text: `crate::a::b` paths and `use crate::{…}`
//! groups, `super::` paths, and the crate root's re-exports (`crate::Method` is
//! `src/method.rs`); comments and the `#[cfg(test)]` modules at the end of a file
//! are left out (a unit test may use any layer).

use phong_approx::Method;
use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Layers from the ground up: a file's layer is that of the longest prefix of its
/// path (relative to `src/`) listed here, or [`METHOD_LAYER`] for a method's module.
const LAYERS: &[(&str, u32)] = &[
    // Errors and the message helpers; exact arithmetic with no crate dependency.
    ("error.rs", 0),
    ("table.rs", 0),
    ("reference/decimal.rs", 0),
    ("reference/transcendental.rs", 0),
    // The number types.
    ("scalar.rs", 1),
    ("format.rs", 1),
    ("profile.rs", 1),
    ("vector.rs", 2),
    ("lowp.rs", 2),
    ("quantize.rs", 2),
    // The exact references and the parsers of exact numbers.
    ("reference/", 3),
    ("parse.rs", 3),
    // The scan line.
    ("span.rs", 4),
    // The methods, each generic over the scalar: the module of every catalogued
    // method ([`METHOD_LAYER`], read from the catalogue), and beside them:
    ("specular.rs", 5),
    // The squared method (the paper's §7.1, question b), not in the catalogue.
    ("squared_corrected_euler.rs", 5),
    ("related/", 5),
    // The catalogue.
    ("method.rs", 6),
    ("method/", 6),
    // Fast kernels.
    ("simd.rs", 7),
    ("fast.rs", 7),
    ("fast/", 7),
    ("fast_rows.rs", 7),
    ("fast_rows/", 7),
    ("fixed_span.rs", 7),
    // The budgets of exact work.
    ("budget.rs", 7),
    // The float bounds.
    ("tolerance.rs", 8),
    ("tolerance/", 8),
    // The specular skip test (the paper's §7.1, question a), from the catalogue; its
    // float form's margins are the float bounds.
    ("skip.rs", 9),
    ("skip/", 9),
    // The span report (what `span` prints, and the exact run with every digit known
    // that the vectors use), the conformance kit and the rasterizer.
    ("span_report.rs", 9),
    ("span_report/", 9),
    ("conformance/", 9),
    ("raster/", 9),
    // The test kit; the studies run on the rasterizer (the paper's tables, the
    // comparison, the calibration, the pictures).
    ("testkit/", 10),
    ("studies/", 10),
    // The GPU runner (feature `gpu`): kernels judged through the test kit.
    ("gpu/", 11),
];

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The library's files, relative to `src/` (the CLI, `main.rs` and `lib.rs` apart).
fn files() -> Vec<String> {
    fn walk(dir: &Path, base: &Path, out: &mut Vec<String>) {
        for e in fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, base, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(
                    p.strip_prefix(base)
                        .unwrap()
                        .to_string_lossy()
                        .replace('\\', "/"),
                );
            }
        }
    }
    let mut out = Vec::new();
    walk(&src(), &src(), &mut out);
    out.retain(|f| !f.starts_with("cli/") && f != "main.rs" && f != "lib.rs");
    out.sort();
    out
}

/// The layer of the methods' own files: each catalogued method's module
/// (`Method::info().module`), so that a new method's file needs no line in [`LAYERS`].
const METHOD_LAYER: u32 = 5;

fn is_method_file(file: &str) -> bool {
    Method::ALL
        .iter()
        .any(|m| format!("{}.rs", m.info().module.replace("::", "/")) == file)
}

fn layer(file: &str) -> u32 {
    if is_method_file(file) {
        return METHOD_LAYER;
    }
    LAYERS
        .iter()
        .filter(|(prefix, _)| file.starts_with(prefix))
        .max_by_key(|(prefix, _)| prefix.len())
        .map(|&(_, l)| l)
        .unwrap_or_else(|| panic!("src/{file} is in no layer: add it to LAYERS (tests/layers.rs)"))
}

/// A module path (`["reference", "transcendental", "sqrt"]`) to the file that defines
/// its longest prefix.
fn resolve(
    path: &[String],
    all: &BTreeSet<String>,
    reexports: &BTreeMap<String, String>,
) -> Option<String> {
    if let Some(first) = path.first() {
        if let Some(f) = reexports.get(first) {
            return Some(f.clone());
        }
    }
    for k in (1..=path.len()).rev() {
        let stem = path[..k].join("/");
        for cand in [format!("{stem}.rs"), format!("{stem}/mod.rs")] {
            if all.contains(&cand) {
                return Some(cand);
            }
        }
    }
    None
}

/// The code of a file without comments and without its trailing test module.
fn code(text: &str) -> String {
    let text = match text.find("#[cfg(test)]\nmod tests") {
        Some(i) => &text[..i],
        None => text,
    };
    text.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Every module path the code names from `crate::` (or from `super::`, resolved
/// against the file's own module).
fn imported_paths(file: &str, text: &str) -> Vec<Vec<String>> {
    let module: Vec<String> = {
        let mut m: Vec<String> = file
            .trim_end_matches(".rs")
            .split('/')
            .map(String::from)
            .collect();
        if m.last().is_some_and(|x| x == "mod") {
            m.pop();
        }
        m
    };
    // The path at the start of `s`: identifiers joined by `::`.
    let ident = |s: &str| -> Vec<String> {
        let s: String = s
            .trim_start()
            .chars()
            .take_while(|&c| c.is_alphanumeric() || c == '_' || c == ':')
            .collect();
        s.split("::")
            .take_while(|x| !x.is_empty())
            .map(String::from)
            .collect()
    };
    let mut out = Vec::new();
    let code = code(text);
    for (root, base) in [
        ("crate::", Vec::new()),
        ("super::", module[..module.len().saturating_sub(1)].to_vec()),
    ] {
        let mut rest = code.as_str();
        while let Some(i) = rest.find(root) {
            let before = rest[..i].chars().last();
            rest = &rest[i + root.len()..];
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
                continue;
            }
            if let Some(group) = rest.strip_prefix('{') {
                // use crate::{a::b, c::{d, e}}: each top-level item of the group.
                let (mut depth, mut item, mut end) = (0, String::new(), 0);
                for (k, c) in group.char_indices() {
                    match c {
                        '{' => depth += 1,
                        '}' if depth == 0 => {
                            end = k;
                            break;
                        }
                        '}' => depth -= 1,
                        ',' if depth == 0 => {
                            out.push([base.clone(), ident(&item)].concat());
                            item.clear();
                            continue;
                        }
                        _ => {}
                    }
                    if depth == 0 || c != '{' {
                        item.push(c);
                    }
                }
                out.push([base.clone(), ident(&item)].concat());
                rest = &group[end..];
            } else {
                out.push([base.clone(), ident(rest)].concat());
            }
        }
    }
    out.retain(|p| !p.is_empty());
    out
}

/// The file-to-file imports of the library.
fn imports() -> BTreeMap<String, BTreeSet<String>> {
    let all: BTreeSet<String> = files().into_iter().collect();
    let lib = fs::read_to_string(src().join("lib.rs")).unwrap();
    // pub use module::{A, B}; → A, B live in module.
    let mut reexports = BTreeMap::new();
    for line in lib.lines().filter(|l| l.starts_with("pub use ")) {
        let body = line.trim_start_matches("pub use ").trim_end_matches(';');
        if let Some((module, names)) = body.split_once("::") {
            let file = format!("{module}.rs");
            if !all.contains(&file) {
                continue;
            }
            for name in names.trim_matches(|c| c == '{' || c == '}').split(',') {
                reexports.insert(name.trim().to_string(), file.clone());
            }
        }
    }
    let mut graph = BTreeMap::new();
    for f in &all {
        let text = fs::read_to_string(src().join(f)).unwrap();
        let mut to = BTreeSet::new();
        for p in imported_paths(f, &text) {
            if let Some(t) = resolve(&p, &all, &reexports) {
                if &t != f {
                    to.insert(t);
                }
            }
        }
        graph.insert(f.clone(), to);
    }
    graph
}

#[test]
fn no_file_imports_from_a_higher_layer() {
    let mut up = Vec::new();
    for (f, to) in imports() {
        for t in to {
            if layer(&t) > layer(&f) {
                up.push(format!(
                    "src/{f} (layer {}) imports src/{t} (layer {})",
                    layer(&f),
                    layer(&t)
                ));
            }
        }
    }
    assert!(
        up.is_empty(),
        "imports from a higher layer:\n{}",
        up.join("\n")
    );
}

#[test]
fn no_files_import_each_other_in_a_circle() {
    let g = imports();
    // Depth-first search for a back edge; the circle is the stack from its target.
    fn visit(
        f: &str,
        g: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(f.to_string(), 1);
        stack.push(f.to_string());
        for t in g.get(f).into_iter().flatten() {
            match state.get(t.as_str()) {
                Some(1) => {
                    let i = stack.iter().position(|x| x == t).unwrap();
                    let mut c = stack[i..].to_vec();
                    c.push(t.clone());
                    return Some(c);
                }
                Some(_) => {}
                None => {
                    if let Some(c) = visit(t, g, state, stack) {
                        return Some(c);
                    }
                }
            }
        }
        stack.pop();
        state.insert(f.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for f in g.keys() {
        if !state.contains_key(f.as_str()) {
            if let Some(c) = visit(f, &g, &mut state, &mut Vec::new()) {
                panic!("an import circle: {}", c.join(" → "));
            }
        }
    }
}

/// The reader sees what it must: a known import of each kind is found, so the two
/// tests above cannot pass by reading nothing.
#[test]
fn the_import_reader_finds_known_imports() {
    let g = imports();
    let has = |a: &str, b: &str| g[a].contains(b);
    assert!(has("method.rs", "span.rs"), "use crate::span::Span");
    assert!(
        has("tolerance/profile.rs", "method.rs"),
        "crate::Method through lib.rs"
    );
    assert!(
        has("conformance/integrity.rs", "conformance/vectors.rs"),
        "super::vectors"
    );
    assert!(
        has("scalar.rs", "reference/transcendental.rs"),
        "a path in code"
    );
    assert!(files().len() > 40);
    for f in files() {
        layer(&f);
    }
}

/// Every `.rs` file under `dir`, recursively.
fn rs_files(dir: &Path) -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, &mut out);
    out
}

/// Every file of `src/` (the command line's included) stays under 600 lines: a file
/// that grows past it is doing more than one job and is split by job (ARCHITECTURE.md,
/// "Layers"; the children of `tolerance/profile.rs`, `conformance/check.rs`,
/// `conformance/vectors.rs`, `span_report.rs`, `method.rs` are such splits).
#[test]
fn every_file_of_src_is_under_600_lines() {
    let all = rs_files(&src());
    assert!(all.len() > 60, "{}", all.len());
    let long: Vec<String> = all
        .iter()
        .map(|p| (p, fs::read_to_string(p).unwrap().lines().count()))
        .filter(|&(_, n)| n >= 600)
        .map(|(p, n)| format!("{}: {n} lines", p.display()))
        .collect();
    assert!(long.is_empty(), "split these by job: {long:?}");
}

/// The test tree reads like a table of contents (docs/testing.md, "Test binaries"):
/// every test binary's root is in `tests/suites/` and is a list of modules; no file of
/// `tests/` is over 1,000 lines; no test is `#[ignore]`d but for the extensive tier;
/// and CI runs every test target (`gpu` in a stage of its own) without skipping a test
/// by name — the report generators are the `xtask` program, not ignored tests.
#[test]
fn the_tests_are_a_table_of_contents() {
    let root = src().parent().unwrap().to_path_buf();
    let manifest = fs::read_to_string(root.join("Cargo.toml")).unwrap();
    let mut roots = 0;
    for block in manifest.split("\n[[test]]\n").skip(1) {
        let path = block
            .lines()
            .take_while(|l| !l.starts_with('['))
            .find_map(|l| l.strip_prefix("path = \""))
            .and_then(|l| l.strip_suffix('"'))
            .expect("every [[test]] names its path");
        assert!(
            path.starts_with("tests/suites/"),
            "{path}: a test binary's root outside tests/suites/"
        );
        roots += 1;
    }
    assert!(roots >= 7, "{roots} test binaries");
    let all = rs_files(&root.join("tests"));
    assert!(all.len() > 40, "{}", all.len());
    for p in &all {
        let text = fs::read_to_string(p).unwrap();
        let n = text.lines().count();
        assert!(
            n <= 1000,
            "{}: {n} lines (at most 1,000: split it by subject)",
            p.display()
        );
        for (i, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("#[ignore") {
                assert!(
                    line.contains("extensive tier"),
                    "{}:{}: an ignored test that is not of the extensive tier: {line}",
                    p.display(),
                    i + 1
                );
            }
        }
    }
    let ci = fs::read_to_string(root.join(".ci/run")).unwrap();
    let skips: Vec<&str> = ci
        .lines()
        .filter(|l| !l.trim_start().starts_with('#') && l.contains("--skip"))
        .collect();
    assert!(skips.is_empty(), "CI skips tests by name: {skips:?}");
}

/// ARCHITECTURE.md is skimmed, and its checklists are true: every section is one screen
/// (at most 60 lines), and in the "Adding …" sections every file or folder named in
/// backticks exists (`NAME` stands for the new item's name) and every test named as
/// `module::test` (or a bare test name in parentheses after a place) is a `#[test]`
/// of `tests/`.
#[test]
fn the_architecture_checklists_name_real_places() {
    let root = src().parent().unwrap().to_path_buf();
    let text = fs::read_to_string(root.join("ARCHITECTURE.md")).unwrap();
    let mut tests = BTreeSet::new();
    let mut modules = BTreeSet::new();
    for p in rs_files(&root.join("tests")) {
        modules.insert(p.file_stem().unwrap().to_string_lossy().into_owned());
        let src = fs::read_to_string(&p).unwrap();
        let lines: Vec<&str> = src.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            if l.trim() == "#[test]" {
                if let Some(f) = lines[i + 1..]
                    .iter()
                    .map(|l| l.trim())
                    .find(|l| !l.starts_with("#["))
                {
                    if let Some(name) = f.strip_prefix("fn ") {
                        tests.insert(name.split('(').next().unwrap().to_string());
                    }
                }
            }
        }
    }
    assert!(tests.len() > 300, "{} tests found", tests.len());
    let sections: Vec<&str> = text.split("\n## ").collect();
    let mut checked = (0, 0);
    for s in &sections {
        let title = s.lines().next().unwrap_or("");
        let n = s.lines().count();
        assert!(
            n <= 60,
            "ARCHITECTURE.md, section {title:?}: {n} lines (one screen: 60)"
        );
        if !title.starts_with("Adding") {
            continue;
        }
        for word in s.split('`').skip(1).step_by(2) {
            let w = word.trim();
            let is_path = (w.starts_with("src/")
                || w.starts_with("tests/")
                || w.starts_with("proofs/")
                || w.starts_with("docs/")
                || w.starts_with("benches/")
                || w == "README.md")
                && !w.contains(' ');
            if is_path {
                if w.contains("NAME") {
                    let dir = &w[..w.rfind('/').unwrap()];
                    assert!(
                        root.join(dir).is_dir(),
                        "ARCHITECTURE.md, {title:?}: no folder {dir}"
                    );
                } else {
                    assert!(
                        root.join(w).exists(),
                        "ARCHITECTURE.md, {title:?}: no file {w}"
                    );
                }
                checked.0 += 1;
            } else if let Some((module, name)) = w.rsplit_once("::") {
                let is_test_name = modules.contains(module)
                    && name.len() > 12
                    && name
                        .chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
                if is_test_name && !name.ends_with('_') {
                    let name = name.trim_end_matches("_f32");
                    assert!(
                        tests.contains(name) || tests.contains(&format!("{name}_f32")),
                        "ARCHITECTURE.md, {title:?}: no test {w}"
                    );
                    checked.1 += 1;
                }
            } else if w.starts_with("the_") && tests.contains(w) {
                checked.1 += 1;
            }
        }
    }
    assert!(
        checked.0 >= 30 && checked.1 >= 8,
        "{checked:?} places and tests checked"
    );
}
