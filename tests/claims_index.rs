//! One name per claim: every Coq `Theorem` in `proofs/` has a `#[test]` of the same
//! name in `tests/claims.rs` and vice versa, every name is explained in
//! `docs/derivations.md`, and every name is cited from a doc comment in `src/`.

use std::collections::BTreeSet;
use std::fs;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn read(p: &str) -> String {
    fs::read_to_string(root().join(p)).unwrap_or_else(|e| panic!("{p}: {e}"))
}

fn theorems() -> BTreeSet<String> {
    let mut names = BTreeSet::new();
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
                    assert!(
                        names.insert(name.clone()),
                        "theorem {name} is defined twice"
                    );
                }
            }
        }
    }
    names
}

fn claim_tests() -> BTreeSet<String> {
    let src = read("tests/claims.rs");
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
    let t = theorems();
    let c = claim_tests();
    assert!(t.len() >= 41, "only {} theorems found", t.len());
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
    let docs = read("docs/derivations.md");
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
        assert!(
            docs.contains(&quoted),
            "docs/derivations.md does not explain {name}"
        );
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
