//! One name per claim: every Coq `Theorem` of the paper and the second source in
//! `proofs/` has a `#[test]` of the same name in `tests/claims.rs` and vice versa,
//! and is explained in `docs/derivations.md`; every `Theorem` of
//! `proofs/Related.v` (the related-work methods) has a test of the same name in
//! `tests/related.rs` and is explained in `docs/comparison.md`; every name is cited
//! from a doc comment in `src/`.

use std::collections::BTreeSet;
use std::fs;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn read(p: &str) -> String {
    fs::read_to_string(root().join(p)).unwrap_or_else(|e| panic!("{p}: {e}"))
}

/// The proof file of the related-work methods; its theorems are checked against
/// `tests/related.rs` and `docs/comparison.md`.
const RELATED: &str = "Related.v";

/// Every `Theorem` in `proofs/*.v` (except `Assumptions.v`), split into those of the
/// paper and the second source, and those of [`RELATED`].
fn theorems_by_source() -> (BTreeSet<String>, BTreeSet<String>) {
    let mut all = BTreeSet::new();
    let (mut paper, mut related) = (BTreeSet::new(), BTreeSet::new());
    for entry in fs::read_dir(root().join("proofs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "v")
            && path.file_name().unwrap() != "Assumptions.v"
        {
            for line in fs::read_to_string(&path).unwrap().lines() {
                if let Some(rest) = line.trim_start().strip_prefix("Theorem ") {
                    let name: String = rest
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    assert!(all.insert(name.clone()), "theorem {name} is defined twice");
                    if path.file_name().unwrap() == RELATED {
                        related.insert(name);
                    } else {
                        paper.insert(name);
                    }
                }
            }
        }
    }
    (paper, related)
}

fn theorems() -> BTreeSet<String> {
    let (mut paper, related) = theorems_by_source();
    paper.extend(related);
    paper
}

/// The names of the `#[test]` functions in `file` (inside `proptest!` blocks too).
fn test_names(file: &str) -> BTreeSet<String> {
    let src = read(file);
    let lines: Vec<&str> = src.lines().collect();
    let mut names = BTreeSet::new();
    for (i, line) in lines.iter().enumerate() {
        if line.trim() == "#[test]" {
            let next = lines[i + 1].trim();
            let name = next.strip_prefix("fn ").expect("#[test] followed by fn");
            names.insert(name.split('(').next().unwrap().to_string());
        }
    }
    names
}

#[test]
fn every_theorem_has_a_test_and_every_test_a_theorem() {
    let (t, related) = theorems_by_source();
    let c = test_names("tests/claims.rs");
    assert!(t.len() >= 41, "only {} theorems found", t.len());
    assert!(
        related.len() >= 8,
        "only {} related theorems",
        related.len()
    );
    let related_tests = test_names("tests/related.rs");
    let untested: Vec<_> = related.difference(&related_tests).collect();
    assert!(
        untested.is_empty(),
        "theorems of proofs/{RELATED} without a test in tests/related.rs: {untested:?}"
    );
    let missing_tests: Vec<_> = t.difference(&c).collect();
    let missing_proofs: Vec<_> = c.difference(&t).collect();
    assert!(
        missing_tests.is_empty(),
        "theorems without a test: {missing_tests:?}"
    );
    assert!(
        missing_proofs.is_empty(),
        "tests without a theorem: {missing_proofs:?}"
    );
}

#[test]
fn every_claim_is_in_the_derivations_and_cited_from_the_code() {
    let (_, related) = theorems_by_source();
    let derivations = read("docs/derivations.md");
    let comparison = read("docs/comparison.md");
    let mut code = String::new();
    let mut stack = vec![root().join("src")];
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                code.push_str(&fs::read_to_string(&path).unwrap());
            }
        }
    }
    for name in theorems() {
        let quoted = format!("`{name}`");
        let (docs, doc_name) = if related.contains(&name) {
            (&comparison, "docs/comparison.md")
        } else {
            (&derivations, "docs/derivations.md")
        };
        assert!(docs.contains(&quoted), "{doc_name} does not explain {name}");
        assert!(
            code.contains(&quoted),
            "no doc comment in src/ cites {name}"
        );
    }
}

#[test]
fn proofs_admit_nothing() {
    for entry in fs::read_dir(root().join("proofs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "v") {
            let text = fs::read_to_string(&path).unwrap();
            for word in [
                "Admitted",
                "admit",
                "Axiom",
                "Parameter",
                "Conjecture",
                "Hypothesis",
            ] {
                let hit = text
                    .split(|c: char| !c.is_alphanumeric() && c != '_')
                    .any(|w| w == word);
                assert!(!hit, "{} uses {word}", path.display());
            }
        }
    }
}
