//! Coverage of the catalogue (libm-test's `check_coverage` is the model): every
//! method of `Method::ALL` has each of the things a method must have, and a method
//! left out of any one of them fails here, naming the method and the place.
//!
//! - expected values in every published vector set;
//! - a float bound (`tolerance::reference_bound`) on an ordinary span, in `f32` and `f64`;
//! - a test that attacks that bound (`tests/float_bounds.rs` or
//!   `tests/float_bounds_related.rs` names it);
//! - at least one claim with a test of its name, cited from the method's module (and
//!   `tests/claims_index.rs` ties every Coq theorem to its test);
//! - the section of `docs/float.md` that derives its bound (`Info::float_section`);
//! - a benchmark: `benches/spans.rs` times every method of the catalogue.

use phong_approx::conformance::vectors::method_key;
use phong_approx::reference::unit::unit_from_ints;
use phong_approx::tolerance::{span_bound, Shape};
use phong_approx::{Method, Span};
use std::fs;
use std::path::Path;

/// `text` without its comments (`//` to the end of a line, doc comments included): a
/// test or a loop that is only mentioned in a comment does not count.
fn code_only(text: &str) -> String {
    text.lines()
        .map(|l| l.find("//").map_or(l, |i| &l[..i]))
        .collect::<Vec<_>>()
        .join("\n")
}

fn read(p: &str) -> String {
    fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(p))
        .unwrap_or_else(|e| panic!("{p}: {e}"))
}

#[test]
fn every_method_has_vectors() {
    for set in phong_approx::testkit::SETS {
        let file = phong_approx::testkit::published(set).unwrap();
        for m in Method::ALL {
            let key = method_key(m);
            assert!(file.methods.contains(&key), "{set}: no vectors for {m}");
            for c in &file.cases {
                assert!(
                    c.expected.contains_key(&key),
                    "{set} {}: no expectation for {m}",
                    c.id
                );
            }
        }
    }
}

#[test]
fn every_method_has_a_bound() {
    // Normals 60° apart, n = 16: every method's bound is defined there.
    let span = Span::new(
        unit_from_ints(0, 0, 1),
        unit_from_ints(1, 0, 2),
        unit_from_ints(1, 1, 3),
        16,
    )
    .unwrap();
    let shape = Shape::of(&span);
    for m in Method::ALL {
        for u in [f64::from(f32::EPSILON) / 2.0, f64::EPSILON / 2.0] {
            let b = span_bound(m, &shape, u);
            assert!(
                b.is_some_and(|b| b > 0.0 && b < 1e-2),
                "{m}: no float bound (u = {u:e}): {b:?}"
            );
        }
    }
}

#[test]
fn every_method_cites_a_tested_claim() {
    fn walk(dir: &Path, tests: &mut String) {
        for e in fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, tests);
            } else if p.extension().is_some_and(|x| x == "rs") {
                *tests += &code_only(&fs::read_to_string(p).unwrap());
            }
        }
    }
    let mut tests = String::new();
    walk(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("tests"),
        &mut tests,
    );
    for m in Method::ALL {
        let file = format!("src/{}.rs", m.info().module.replace("::", "/"));
        let text = read(&file);
        // Names in backticks in the module's doc comments that are tests.
        let cited: Vec<&str> = text
            .split('`')
            .skip(1)
            .step_by(2)
            .filter(|w| {
                w.len() > 6
                    && w.chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
            })
            .filter(|w| tests.contains(&format!("fn {w}(")))
            .collect();
        assert!(
            !cited.is_empty(),
            "{m}: {file} cites no claim with a test of its name"
        );
    }
}

#[test]
fn every_method_has_a_docs_section() {
    let float = read("docs/float.md");
    for m in Method::ALL {
        let sec = m.info().float_section;
        let number = sec.trim_start_matches('§');
        let heading = float.lines().any(|l| {
            l.starts_with('#')
                && l.trim_start_matches('#')
                    .trim_start()
                    .starts_with(&format!("{number} "))
                || l.trim_start_matches('#')
                    .trim_start()
                    .starts_with(&format!("{number}. "))
        });
        assert!(heading, "{m}: docs/float.md has no section {sec}");
    }
}

#[test]
fn the_span_bench_loops_over_the_catalogue() {
    // A text search: benches/spans.rs times every method by looping over the
    // catalogue (`Method::ALL`), so a method added to it is timed by construction.
    let bench = code_only(&read("benches/spans.rs"));
    assert!(
        bench.contains("for m in Method::ALL"),
        "benches/spans.rs no longer times every method of the catalogue"
    );
}

/// The text docs/conformance.md holds between a generated table's markers.
fn generated_table(name: &str, by: &str) -> String {
    let docs = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/conformance.md"),
    )
    .unwrap();
    let begin = format!("<!-- {name}: generated by {by} -->\n");
    let end = format!("<!-- end {name} -->");
    let at = docs
        .find(&begin)
        .unwrap_or_else(|| panic!("docs/conformance.md has the {name}'s markers"))
        + begin.len();
    docs[at..at + docs[at..].find(&end).unwrap()].to_string()
}

/// Labels from data (issue 31): docs/conformance.md holds the table of how each
/// method's bound is known under each profile exactly as `status_table` makes it from
/// the catalogue of bounds, so no document row says *proved* where the data does not.
#[test]
fn the_docs_status_table_is_the_datas() {
    let table = generated_table("status-table", "tolerance::profile::status_table");
    let want = phong_approx::tolerance::profile::status_table();
    assert_eq!(
        table, want,
        "regenerate the table in docs/conformance.md:\n{want}"
    );
}

/// docs/conformance.md §3 shows the bounds `check` applies by default — the `ieee`
/// profile's — exactly as `ieee_table` makes them from the catalogue of bounds.
#[test]
fn the_docs_default_bounds_table_is_the_datas() {
    let table = generated_table("ieee-table", "tolerance::profile::ieee_table");
    let want = phong_approx::tolerance::profile::ieee_table();
    assert_eq!(
        table, want,
        "regenerate the table in docs/conformance.md:\n{want}"
    );
}

/// No dead bound kind: every variant of the catalogue's profile columns
/// (`FloatBound`, `FixedBound`, `DerivedForm`) is the kind of some method's row, every
/// method with a bound under a profile has a proved status there, and every variant
/// of `tolerance::profile::Status` is some method's status under `ieee`, `shader` or
/// fixed point. The matches are exhaustive, so a new variant does not compile until it
/// is listed here.
#[test]
fn every_bound_kind_is_used_by_a_row() {
    use phong_approx::method::{DerivedForm, FixedBound, FloatBound};
    use phong_approx::tolerance::profile::{status, Profile, Status};
    use std::collections::BTreeSet;
    let float = |b: &FloatBound| match b {
        FloatBound::Proved(_) => "float Proved",
        FloatBound::Composed { .. } => "float Composed",
        FloatBound::Graphs { .. } => "float Graphs",
        FloatBound::None(_) => "float None",
    };
    let form = |f: &DerivedForm| match f {
        DerivedForm::PerPixel => "form PerPixel",
        DerivedForm::Ratio => "form Ratio",
        DerivedForm::HalfRatio => "form HalfRatio",
        DerivedForm::LargerOfPicks => "form LargerOfPicks",
    };
    let fixed = |b: &FixedBound| match b {
        FixedBound::Proved { .. } => "fixed Proved",
        FixedBound::Ratio { .. } => "fixed Ratio",
        FixedBound::Picks { .. } => "fixed Picks",
        FixedBound::None(_) => "fixed None",
    };
    let all = [
        "float Proved",
        "float Composed",
        "float Graphs",
        "float None",
        "form PerPixel",
        "form Ratio",
        "form HalfRatio",
        "form LargerOfPicks",
        "fixed Proved",
        "fixed Ratio",
        "fixed Picks",
        "fixed None",
        // Every variant of `tolerance::profile::Status` is some method's label.
        "status Proved",
        "status PerPixel",
        "status Graphs",
    ];
    let mut used = BTreeSet::new();
    for m in Method::ALL {
        let row = m.info().profiles;
        used.insert(float(&row.float));
        if let FloatBound::Composed { form: f, .. } = &row.float {
            used.insert(form(f));
        }
        used.insert(fixed(&row.fixed));
        for p in [
            Profile::Ieee,
            Profile::Shader,
            Profile::Fixed {
                int_bits: 16,
                frac_bits: 16,
            },
        ] {
            match status(m, p, phong_approx::Format::Binary32) {
                Some(Status::Proved(t)) => {
                    assert!(!t.is_empty(), "{m} under {p}");
                    used.insert("status Proved");
                }
                Some(Status::PerPixel(t, graphs, _)) => {
                    assert!(!graphs.is_empty(), "{m} under {p}");
                    assert!(!t.is_empty(), "{m} under {p}");
                    used.insert("status PerPixel");
                }
                Some(Status::Graphs(t, graphs, _)) => {
                    assert!(!graphs.is_empty(), "{m} under {p}");
                    assert!(!t.is_empty(), "{m} under {p}");
                    used.insert("status Graphs");
                }
                None => {}
            }
        }
    }
    for kind in all {
        assert!(
            used.contains(kind),
            "no method's row is of the kind {kind}: remove it"
        );
    }
}

/// The hardware cost table of docs/performance.md is the one of today's units: its
/// `sources:` line is the SHA-256 of `harness/hdl/units/*.sv` in name order,
/// concatenated (the recipe of `harness/hdl/synth/cost.sh`, which CI reruns with
/// `--check` to compare the numbers themselves; this test needs no hardware tool).
#[test]
fn the_hardware_cost_table_is_of_the_current_units() {
    let doc = read("docs/performance.md");
    let marker = "<!-- hdl-cost: generated by harness/hdl/synth/cost.sh -->";
    let block = &doc[doc.find(marker).expect("the hdl-cost markers")..];
    let recorded = block
        .lines()
        .find_map(|l| l.strip_prefix("sources: "))
        .expect("a sources: line")
        .trim();
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("harness/hdl/units");
    let mut names: Vec<String> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".sv"))
        .collect();
    names.sort();
    assert!(names.len() >= 4, "{names:?}");
    let mut all = Vec::new();
    for n in &names {
        all.extend(fs::read(dir.join(n)).unwrap());
    }
    let now = phong_approx::conformance::integrity::sha256_hex(&all);
    assert_eq!(
        recorded, now,
        "the units changed since the cost table was made: run harness/hdl/synth/cost.sh --write"
    );
}

/// The README's method table and lib.rs's are the catalogue's: every method of
/// `Method::ALL` is a row of the README's (by its `--method` name, the tabled angular
/// method as `angular-table256`) with its module, and every module of lib.rs's rows
/// is a method's; no row names a method the catalogue lacks.
#[test]
fn the_method_tables_of_readme_and_lib_are_the_catalogues() {
    let readme = read("README.md");
    let rows: Vec<&str> = readme
        .lines()
        .skip_while(|l| !l.starts_with("| method (`--method`) |"))
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .collect();
    let mut listed = std::collections::BTreeSet::new();
    for r in &rows {
        let first = r.split('|').nth(1).unwrap();
        for name in first.split('`').skip(1).step_by(2) {
            listed.insert(name.to_string());
        }
    }
    let lib = read("src/lib.rs");
    for m in Method::ALL {
        let name = m.name().into_owned();
        assert!(
            listed.remove(&name),
            "README's method table has no row for {name}"
        );
        let module = m.info().module;
        let row = rows
            .iter()
            .find(|r| r.split('|').nth(1).unwrap().contains(&format!("`{name}`")))
            .unwrap();
        let last = module.rsplit("::").next().unwrap();
        assert!(
            row.contains(&format!("[`{module}`]")) || row.contains(&format!("`{last}`")),
            "README's row of {name} does not name its module {module}: {row}"
        );
        if !module.contains("::") && m.info().family != phong_approx::method::Family::Related {
            assert!(
                lib.contains(&format!("[`{module}`]")),
                "lib.rs's method table lacks {module} ({name})"
            );
        }
    }
    assert!(
        listed.is_empty(),
        "README's table names methods the catalogue lacks: {listed:?}"
    );
}
