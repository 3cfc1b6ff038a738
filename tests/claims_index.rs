//! One name per claim: every Coq `Theorem` of the paper and the second source in
//! `proofs/` has a `#[test]` of the same name in `tests/claims/` and vice versa,
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

/// Proof files whose theorems are tested and explained somewhere else than
/// `tests/claims/` and `docs/derivations.md`: (file, test file, document).
const GROUPS: [(&str, &str, &str); 18] = [
    ("Related.v", "tests/related.rs", "docs/comparison.md"),
    ("Skip.v", "tests/skip.rs", "docs/derivations.md"),
    ("Squared.v", "tests/squared.rs", "docs/derivations.md"),
    ("SkipFloat.v", "tests/skip.rs", "docs/derivations.md"),
    ("Float.v", "tests/float_bounds.rs", "docs/float.md"),
    ("Fixed.v", "tests/lowp.rs", "docs/float.md"),
    ("Graph.v", "tests/graph.rs", "docs/float.md"),
    ("GraphAffine.v", "tests/graph_affine.rs", "docs/float.md"),
    ("FastSetup.v", "tests/fast_rows.rs", "docs/float.md"),
    ("ShaderSqrt.v", "tests/profiles/shader.rs", "docs/float.md"),
    ("Composed.v", "tests/composed.rs", "docs/float.md"),
    ("Profiles.v", "tests/profiles/", "docs/float.md"),
    ("PhongValue.v", "tests/phong_value.rs", "docs/float.md"),
    ("PhongCount.v", "tests/phong_value.rs", "docs/float.md"),
    ("DuffCount.v", "tests/duff_count.rs", "docs/float.md"),
    ("PhongCountD.v", "tests/phong_value.rs", "docs/float.md"),
    ("PhongNormalize.v", "tests/phong_value.rs", "docs/float.md"),
    (
        "AdaptiveDelta.v",
        "tests/profiles/adaptive.rs",
        "docs/float.md",
    ),
];

/// Every `Theorem` in `proofs/*.v` (except `Assumptions.v`) with its proof file.
fn theorems_with_files() -> Vec<(String, String)> {
    let mut all = BTreeSet::new();
    let mut out = Vec::new();
    for entry in fs::read_dir(root().join("proofs")).unwrap() {
        let path = entry.unwrap().path();
        let file = path.file_name().unwrap().to_string_lossy().to_string();
        if path.extension().is_some_and(|e| e == "v") && file != "Assumptions.v" {
            for line in fs::read_to_string(&path).unwrap().lines() {
                if let Some(rest) = line.trim_start().strip_prefix("Theorem ") {
                    let name: String = rest
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    assert!(all.insert(name.clone()), "theorem {name} is defined twice");
                    out.push((name, file.clone()));
                }
            }
        }
    }
    out
}

/// The test file and the document of a proof file.
fn home(file: &str) -> (&'static str, &'static str) {
    GROUPS
        .iter()
        .find(|(f, _, _)| *f == file)
        .map_or(("tests/claims/", "docs/derivations.md"), |(_, t, d)| {
            (*t, *d)
        })
}

/// The theorems of the paper and the second source (tested in `tests/claims/`).
fn paper_theorems() -> BTreeSet<String> {
    theorems_with_files()
        .into_iter()
        .filter(|(_, f)| home(f).0 == "tests/claims/")
        .map(|(t, _)| t)
        .collect()
}

/// The names of the `#[test]` functions in `file` (inside `proptest!` blocks too), or
/// in every `.rs` file of the folder `file` when it ends in `/`.
fn test_names(file: &str) -> BTreeSet<String> {
    if file.ends_with('/') {
        let mut files: Vec<_> = std::fs::read_dir(root().join(file))
            .unwrap_or_else(|e| panic!("{file}: {e}"))
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .filter(|f| f.ends_with(".rs"))
            .collect();
        files.sort();
        assert!(!files.is_empty(), "no test file in {file}");
        return files
            .iter()
            .flat_map(|f| test_names(&format!("{file}{f}")))
            .collect();
    }
    let src = read(file);
    let lines: Vec<&str> = src.lines().collect();
    let mut names = BTreeSet::new();
    for (i, line) in lines.iter().enumerate() {
        if line.trim() == "#[test]" {
            // Skip further attributes (`#[ignore]`) to the function.
            let next = lines[i + 1..]
                .iter()
                .map(|l| l.trim())
                .find(|l| !l.starts_with("#["))
                .expect("#[test] followed by fn");
            let name = next.strip_prefix("fn ").expect("#[test] followed by fn");
            names.insert(name.split('(').next().unwrap().to_string());
        }
    }
    names
}

#[test]
fn every_theorem_has_a_test_and_every_test_a_theorem() {
    let all = theorems_with_files();
    let t = paper_theorems();
    assert!(t.len() >= 41, "only {} theorems found", t.len());
    for (file, _, _) in GROUPS {
        let n = all.iter().filter(|(_, f)| f == file).count();
        // Graph.v holds one theorem, the generic soundness of every operation graph.
        assert!(n >= 1, "no theorem found in proofs/{file}");
    }
    for (name, file) in &all {
        let (tests, _) = home(file);
        assert!(
            test_names(tests).contains(name),
            "theorem {name} of proofs/{file} has no test of that name in {tests}"
        );
    }
    let c = test_names("tests/claims/");
    let missing_proofs: Vec<_> = c.difference(&t).collect();
    assert!(
        missing_proofs.is_empty(),
        "tests of tests/claims/ without a theorem: {missing_proofs:?}"
    );
}

#[test]
fn every_claim_is_in_the_derivations_and_cited_from_the_code() {
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
    for (name, file) in theorems_with_files() {
        let quoted = format!("`{name}`");
        let (_, doc) = home(&file);
        assert!(read(doc).contains(&quoted), "{doc} does not explain {name}");
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

/// The kinds of `proofs/README.md`'s table "Theorems by kind" (between its
/// `<!-- kinds -->` markers): theorem → (kind, distinct result).
fn kinds() -> std::collections::BTreeMap<String, (String, String)> {
    let readme = read("proofs/README.md");
    let start = readme
        .find("<!-- kinds: begin -->")
        .expect("the kinds table");
    let end = readme
        .find("<!-- kinds: end -->")
        .expect("the kinds table's end");
    let mut out = std::collections::BTreeMap::new();
    for line in readme[start..end].lines().filter(|l| l.starts_with("| `")) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let name = cells[1].trim_matches('`').to_string();
        let kind = cells[3].to_string();
        let distinct = cells[4].trim_matches('`').to_string();
        assert!(
            ["substantive", "identity", "witness", "definitional"].contains(&kind.as_str()),
            "{name}: kind {kind}"
        );
        assert!(
            out.insert(name.clone(), (kind, distinct)).is_none(),
            "{name} twice"
        );
    }
    out
}

/// Every number written just before `word` in `text` ("57 substantive theorems").
fn counts_before(text: &str, word: &str) -> Vec<usize> {
    text.match_indices(word)
        .filter_map(|(i, _)| {
            let head = text[..i].trim_end();
            let digits: String = head
                .chars()
                .rev()
                .take_while(char::is_ascii_digit)
                .collect::<Vec<_>>()
                .into_iter()
                .rev()
                .collect();
            digits.parse().ok()
        })
        .collect()
}

/// Every theorem has one kind in proofs/README.md's table (substantive, identity,
/// witness, definitional), every substantive one a distinct result that is itself
/// substantive, and every count a document states — in all, or on the paper and the
/// second source — is the table's; docs/derivations.md's index gives each paper
/// theorem its kind.
#[test]
fn the_index_counts_only_substantive_theorems() {
    let all = theorems_with_files();
    let names: BTreeSet<String> = all.iter().map(|(t, _)| t.clone()).collect();
    let kinds = kinds();
    let listed: BTreeSet<String> = kinds.keys().cloned().collect();
    assert_eq!(
        listed, names,
        "proofs/README.md's kinds table is not the theorems"
    );
    for (name, (kind, distinct)) in &kinds {
        if kind == "substantive" {
            assert_eq!(
                kinds.get(distinct).map(|k| k.0.as_str()),
                Some("substantive"),
                "{name}: its distinct result {distinct} is not a substantive theorem"
            );
        } else {
            assert_eq!(distinct, "-", "{name} is {kind}: no distinct result");
        }
    }
    let paper = paper_theorems();
    let count = |kind: &str, only_paper: bool| {
        kinds
            .iter()
            .filter(|(n, k)| k.0 == kind && (!only_paper || paper.contains(*n)))
            .count()
    };
    let distinct: BTreeSet<&String> = kinds
        .values()
        .filter(|k| k.0 == "substantive")
        .map(|k| &k.1)
        .collect();
    // The counts the documents state.
    let phrases = [
        ("substantive theorems", "substantive"),
        ("one-step identities", "identity"),
        ("witness theorems", "witness"),
        ("definitional statements", "definitional"),
    ];
    for doc in ["README.md", "proofs/README.md", "docs/derivations.md"] {
        let text = read(doc);
        assert!(
            !counts_before(&text, "substantive theorems").is_empty(),
            "{doc} states no counts"
        );
        for (phrase, kind) in phrases {
            for c in counts_before(&text, phrase) {
                assert!(
                    c == count(kind, false) || c == count(kind, true),
                    "{doc} says {c} {phrase}; there are {} ({} on the paper and the second source)",
                    count(kind, false),
                    count(kind, true)
                );
            }
        }
        for c in counts_before(&text, "distinct substantive results") {
            assert_eq!(c, distinct.len(), "{doc}: distinct substantive results");
        }
    }
    // The index of docs/derivations.md: one row per paper theorem, its kind given.
    let deriv = read("docs/derivations.md");
    let index = &deriv[deriv.find("## 15. Index of claims").expect("§15")..];
    let mut rows = BTreeSet::new();
    for line in index.lines().filter(|l| l.starts_with("| `")) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let name = cells[1].trim_matches('`').to_string();
        let kind = cells[2];
        assert_eq!(
            Some(kind),
            kinds.get(&name).map(|k| k.0.as_str()),
            "index row {name}"
        );
        assert!(rows.insert(name.clone()), "index row {name} twice");
    }
    assert_eq!(rows, paper, "the index rows are not the paper's theorems");
}

use crate::common::coq::stated_profile_bounds;

/// The constants the checker applies under `ieee` and `shader`
/// (`tolerance::profile::proved`) are the Coq statements' own — `α`, `β` (as the
/// nearest `f64` of the statement's fraction), the largest `n` and the format — and
/// every binary32 and large binary64 bound theorem of `proofs/Profiles.v` is one the
/// checker applies: a theorem changed without the table, or the table without the
/// theorem, fails here.
#[test]
fn the_checkers_profile_constants_are_the_theorems() {
    use phong_approx::tolerance::profile::{proved, Profile};
    let stated = stated_profile_bounds();
    assert!(stated.len() >= 29, "{} bound theorems read", stated.len());
    let mut applied = BTreeSet::new();
    for m in phong_approx::Method::ALL {
        for profile in [Profile::Ieee, Profile::Shader] {
            for (f, e) in [
                (phong_approx::Format::Binary32, 24),
                (phong_approx::Format::Binary64, 53),
            ] {
                for p in proved(m, profile, f).unwrap_or_default() {
                    let s = stated.get(p.theorem).unwrap_or_else(|| {
                        panic!("{} is not a bound theorem of Profiles.v", p.theorem)
                    });
                    let f = |(a, b): (u64, u64)| a as f64 / b as f64;
                    assert_eq!(p.alpha, f(s.alpha), "{}: α", p.theorem);
                    assert_eq!(p.beta, f(s.beta), "{}: β", p.theorem);
                    assert_eq!(p.max_n, s.max_n, "{}: largest n", p.theorem);
                    assert_eq!(s.e, e, "{}: the format", p.theorem);
                    applied.insert(p.theorem.to_string());
                }
            }
        }
    }
    let theorems: BTreeSet<String> = stated
        .keys()
        .filter(|t| t.ends_with("_binary32") || t.ends_with("_binary64_large"))
        .cloned()
        .collect();
    assert_eq!(
        applied, theorems,
        "the checker's table and Profiles.v's theorems"
    );
}

/// The fractions `a / b *` of a statement, in order (`1702 / 100 * K1` gives
/// `(1702, 100)`; a bare `/ 1048576` has no numerator and is not one).
fn fractions(statement: &str) -> Vec<(u64, u64)> {
    let t: Vec<&str> = statement.split_whitespace().collect();
    t.windows(4)
        .filter(|w| w[1] == "/" && w[3] == "*")
        .filter_map(|w| {
            let a = w[0].trim_start_matches('(');
            Some((a.parse().ok()?, w[2].parse().ok()?))
        })
        .collect()
}

/// The constants the checker composes Duff's and symmetric Phong's `ieee` and `shader`
/// bounds from (`tolerance::profile::DUFF_COUNTS`) are the statements' of
/// `proofs/DuffCount.v` — `p`'s and `q`'s `K1`, `kd` and per-step constants, as the
/// nearest `f64` of each fraction — for all four theorems, with the size condition
/// `n·κ_add·u ≤ 2^-11` the code checks.
#[test]
fn the_checkers_duff_constants_are_the_theorems() {
    use phong_approx::tolerance::profile::DUFF_COUNTS;
    let text = read("proofs/DuffCount.v");
    let c = DUFF_COUNTS;
    let want = [c.p.0, c.p.1, c.p.2, c.q.0, c.q.1, c.q.2];
    for name in [
        "duff_div_generic",
        "duff_recip_generic",
        "symmetric_phong_div_generic",
        "symmetric_phong_recip_generic",
    ] {
        let at = text
            .find(&format!("Theorem {name} "))
            .unwrap_or_else(|| panic!("{name} in proofs/DuffCount.v"));
        let statement = &text[at..at + text[at..].find("Proof.").expect("its proof")];
        let got: Vec<f64> = fractions(statement)
            .into_iter()
            .map(|(a, b)| a as f64 / b as f64)
            .collect();
        assert_eq!(
            got, want,
            "{name}: the constants (K1, kd, step) of p and of q"
        );
        assert!(
            statement.contains("INR (n s) * (k_add M * m_u M) <= / 2048"),
            "{name}: the size condition n·κ_add·u ≤ 2^-11"
        );
        assert!(
            statement.contains("INR (n s) <= 16777216"),
            "{name}: n ≤ 2^24"
        );
    }
}

/// Every fraction `a / b` of a statement with a numeric numerator, in order (a bare
/// `/ 1048576` has none and is not one).
fn all_fractions(statement: &str) -> Vec<f64> {
    let t: Vec<&str> = statement.split_whitespace().collect();
    t.windows(3)
        .filter(|w| w[1] == "/")
        .filter_map(|w| {
            let a: f64 = w[0].trim_start_matches('(').parse().ok()?;
            let b: f64 = w[2].trim_end_matches([')', ';', ',']).parse().ok()?;
            Some(a / b)
        })
        .collect()
}

/// The statement of theorem `name` in `file` (up to its proof).
fn statement_of(file: &str, name: &str) -> String {
    let text = read(file);
    let at = text
        .find(&format!("Theorem {name} "))
        .unwrap_or_else(|| panic!("{name} in {file}"));
    text[at..at + text[at..].find("Proof.").expect("its proof")].to_string()
}

/// The constants the checker composes Phong's `ieee` and `shader` bounds from
/// (`tolerance::profile::PHONG_COUNTS`, `NORMALIZE_EXTRA`) are the statements' of
/// `proofs/PhongCount.v`, `proofs/PhongCountD.v` and `proofs/PhongNormalize.v` —
/// every fraction of each of the twelve count theorems (the zero coefficients are not
/// written as fractions) and normalize-then-dot's factor with its terms — and the
/// constants of the adaptive band's error (`tolerance::profile::delta_error`, checked
/// against the same formula in `tests/profiles/adaptive.rs`) are `proofs/AdaptiveDelta.v`'s
/// definitions.
#[test]
fn the_checkers_phong_and_adaptive_constants_are_the_theorems() {
    use phong_approx::tolerance::profile::{NORMALIZE_EXTRA, PHONG_COUNTS};
    for c in PHONG_COUNTS {
        for way in ["div", "recip"] {
            let name = format!("phong_{}_{way}_generic", c.form);
            let got = all_fractions(&statement_of("proofs/PhongCount.v", &name));
            assert_eq!(got, [c.p.0, c.p.1, c.q.0, c.q.1], "{name}");
            let name = format!("phong_{}_{way}_dist", c.form);
            let got = all_fractions(&statement_of("proofs/PhongCountD.v", &name));
            let (a0, a1, b0, b1) = c.pd;
            let (c0, c1, c2, e0, e1, e2) = c.qd;
            let want: Vec<f64> = [a0, a1, b0, b1, c0, c1, c2, e0, e1, e2]
                .into_iter()
                .filter(|&x| x != 0.0)
                .collect();
            assert_eq!(got, want, "{name}");
            let st = statement_of("proofs/PhongCountD.v", &name);
            assert!(
                st.contains("0 <= dd <= 2")
                    && st.contains("dot (vsub (Nb s) (Na s)) (vsub (Nb s) (Na s)) <= dd * dd"),
                "{name}: d's hypotheses"
            );
        }
    }
    let st = statement_of("proofs/PhongNormalize.v", "phong_normalize_dot_unit");
    assert_eq!(
        all_fractions(&st),
        [NORMALIZE_EXTRA],
        "phong_normalize_dot_unit"
    );
    let flat: String = st.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        flat.contains("(103 / 100 * (1 + kin * u + 2 * eta) * (km * u + um + 2 * ua) + 2 * (1 + kin * u + 2 * eta) * eta + 8 * eta)"),
        "phong_normalize_dot_unit's term"
    );
    // The adaptive band's error terms: the fractions of the two definitions.
    let text = read("proofs/AdaptiveDelta.v");
    let def = |name: &str| {
        let at = text.find(&format!("Definition {name} ")).expect(name);
        text[at..at + text[at..].find(".\n").expect("its end")].to_string()
    };
    assert_eq!(
        all_fractions(&def("fast_delta_err")),
        [92.11, 18.06, 3.004, 0.25],
        "fast_delta_err"
    );
    assert!(def("fast_delta_err").contains("562949986975745 * m_eta M"));
    // `eq24_delta_err` and `eq24_shared_delta_err` are `eq24_err_of` with its `shared`
    // switch off and on: one formula, whose constants are the checker's.
    assert_eq!(
        all_fractions(&def("eq24_err_of")),
        [5.002, 0.001, 20.04, 5.01, 92.11, 18.06, 0.25],
        "eq24_err_of"
    );
    let e = def("eq24_err_of");
    for term in [
        "(1 + / 131072) + 18 * eta",
        "(2 + / 65536) + 16777218 * eta",
        "if shared then Edp + ER + Eds / 8 else EG + (ER + 2 * Epc + Eds / 8)",
    ] {
        assert!(e.contains(term), "eq24_err_of: {term}");
    }
    for (name, shared) in [
        ("eq24_delta_err", "false"),
        ("eq24_shared_delta_err", "true"),
    ] {
        assert!(
            def(name).ends_with(&format!(":= eq24_err_of M K1 {shared}")),
            "{name} is not eq24_err_of M K1 {shared}"
        );
    }
}

/// The standard models the checker applies (`tolerance::profile::arith`, and through it
/// the operation graphs' `graphs::model`) are `proofs/Profiles.v`'s `fmodel`s: the unit
/// `u`, `η`, and `κ` of an input, an addition and a product equal to the `mkModel`
/// arguments, and its `k_div` covering what the checker lets a division by `n` (or by
/// 2 under `shader`) be — one division, or a reciprocal then a product,
/// `(1 + κ_div·u)(1 + κ_mul·u) − 1` — so an edit of either side fails here.
#[test]
fn the_checkers_models_are_the_theorems() {
    use phong_approx::tolerance::graphs::model;
    use phong_approx::tolerance::profile::{arith, Profile};
    use phong_approx::Format;
    let text = read("proofs/Profiles.v");
    // `Definition NAME : fmodel := mkModel (bpow radix2 (-24)) (bpow radix2 (-150)) 1 1 1 (2 + / 1048576).`
    let stated = |name: &str| -> [f64; 6] {
        let at = text
            .find(&format!("Definition {name} : fmodel :="))
            .unwrap_or_else(|| panic!("no fmodel {name} in Profiles.v"));
        let rest = &text[at..];
        let def = &rest[..rest.find('.').unwrap()];
        let args = def.split_once("mkModel").unwrap().1.trim();
        fn pow(s: &str) -> (f64, &str) {
            let s = s.trim_start().strip_prefix("(bpow radix2 (").unwrap();
            let (e, rest) = s.split_once("))").unwrap();
            // 2^e rounded up to an f64 (2^-1075, binary64's η, is below every f64 but 0).
            let e: i32 = e.parse().unwrap();
            (
                if e < -1074 {
                    f64::from_bits(1)
                } else {
                    2f64.powi(e)
                },
                rest,
            )
        }
        let (u, rest) = pow(args);
        let (eta, rest) = pow(rest);
        let mut ks = Vec::new();
        let mut rest = rest.trim();
        while !rest.is_empty() {
            if let Some(r) = rest.strip_prefix('(') {
                let (inner, after) = r.split_once(')').unwrap();
                let (a, b) = inner.split_once("+ /").unwrap();
                ks.push(a.trim().parse::<f64>().unwrap() + 1.0 / b.trim().parse::<f64>().unwrap());
                rest = after.trim();
            } else {
                let (k, after) = rest.split_once(' ').unwrap_or((rest, ""));
                ks.push(k.parse().unwrap());
                rest = after.trim();
            }
        }
        assert_eq!(ks.len(), 4, "{name}: four κ");
        [u, eta, ks[0], ks[1], ks[2], ks[3]]
    };
    let cases = [
        ("ieee32", Profile::Ieee, Format::Binary32, "ieee32"),
        ("ieee64", Profile::Ieee, Format::Binary64, "ieee64"),
        (
            "shader32",
            Profile::Shader,
            Format::Binary32,
            "shader32_recip",
        ),
    ];
    for (one, profile, format, either) in cases {
        let a = arith(profile, format).unwrap();
        let [u, eta, k_in, k_add, k_mul, _] = stated(one);
        assert_eq!((a.u, a.eta), (u, eta), "{one}: u and η");
        assert_eq!(
            (a.input, a.add, a.mul),
            (k_in, k_add, k_mul),
            "{one}: κ of inputs, sums, products"
        );
        // A division by n either way, in the model whose theorems the checker applies.
        let k_div = stated(either)[5];
        let two_ways = a.div + a.mul + a.div * a.mul * a.u;
        assert!(
            k_div >= a.div && k_div >= two_ways,
            "{either}: k_div {k_div} < {two_ways}"
        );
        assert!(
            k_div - two_ways < 1e-5,
            "{either}: k_div {k_div} is not the two ways' {two_ways}"
        );
        if profile == Profile::Shader {
            // One 2.5-ulp division (shader32's k_div) and the halving as a division or a
            // computed 1/2 and a product (shader32_recip's).
            assert_eq!(stated("shader32")[5], a.div, "shader32: one division");
            assert_eq!(a.half, a.div + a.mul, "shader: the halving either way");
            assert!(k_div >= a.half + a.div * a.mul * a.u);
        } else {
            assert_eq!(a.half, 0.0, "ieee: halving is exact");
        }
        let g = model(profile, format).unwrap();
        assert_eq!(
            (g.u, g.eta, g.input, g.add, g.mul, g.div),
            (a.u, a.eta, a.input, a.add, a.mul, a.div),
            "{one}: the graph model is the standard model"
        );
    }
}
