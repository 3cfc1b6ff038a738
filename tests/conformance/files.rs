//! The committed vector files: what the code generates, their schema, why each case is there, their published digests.

use super::*;

pub(crate) fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The committed files, read once.
pub(crate) fn committed(set: &str) -> &'static VectorFile {
    static FILES: OnceLock<Vec<VectorFile>> = OnceLock::new();
    let files = FILES.get_or_init(|| {
        SETS.iter()
            .map(|s| {
                let text =
                    std::fs::read_to_string(root().join(format!("vectors/{s}.json"))).unwrap();
                serde_json::from_str(&text).unwrap()
            })
            .collect()
    });
    &files[SETS.iter().position(|s| *s == set).unwrap()]
}

/// Runs `f` on every item of `work` on all cores, each core taking the next item in
/// order (put the largest first).
pub(crate) fn on_all_cores<T: Sync>(work: &[T], f: impl Fn(&T) + Sync) {
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let next = std::sync::atomic::AtomicUsize::new(0);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                while let Some(item) =
                    work.get(next.fetch_add(1, std::sync::atomic::Ordering::Relaxed))
                {
                    f(item);
                }
            });
        }
    });
}

/// Default tier: the committed files' headers; a sample of the cases regenerated and
/// compared value by value (every ninth `typical` case — n = 2, 3, 5, 8, 13, with and
/// without specular —, every `edge` and `paper` case of at most 64 steps), on all
/// cores; the CSV twins are what the committed JSON gives. Every case, and the files
/// byte for byte, are the extensive tier's
/// (`committed_vectors_are_what_the_code_generates_byte_for_byte`).
#[test]
fn committed_vectors_are_what_the_code_generates() {
    let read = |set: &str, ext: &str| {
        std::fs::read_to_string(root().join(format!("vectors/{set}{ext}"))).unwrap()
    };
    let mut sample = Vec::new();
    let mut raws = Vec::new();
    for set in SETS {
        let text = read(set, ".json");
        let raw: serde_json::Value = serde_json::from_str(&text).unwrap();
        let stale = format!(
            "vectors/{set}.json is stale: run `cargo run --release -- vectors --out vectors --force`"
        );
        // The header (every field but the cases).
        let file = committed(set);
        let specs = vectors::specs(set).unwrap();
        let header = serde_json::to_value(vectors::file_of(set, Vec::new())).unwrap();
        for (key, want) in header.as_object().unwrap() {
            if key != "cases" && key != "number_of_cases" {
                assert!(raw[key] == *want, "{stale}: {key}");
            }
        }
        assert_eq!(raw["number_of_cases"], specs.len(), "{stale}");
        for (k, spec) in specs.into_iter().enumerate() {
            assert_eq!(spec.id, file.cases[k].id, "{stale}");
            let keep = if set == "typical" {
                k % 9 == 0
            } else {
                spec.n <= 64
            };
            if keep {
                sample.push((raws.len(), k, spec, stale.clone()));
            }
        }
        assert!(
            read(set, ".csv") == to_csv(file),
            "vectors/{set}.csv is stale"
        );
        assert!(
            read(set, "-inputs.csv") == inputs_csv(file),
            "vectors/{set}-inputs.csv is stale"
        );
        raws.push(raw);
    }
    assert!(sample.len() >= 15, "only {} cases sampled", sample.len());
    // Largest first, spread over the cores.
    sample.sort_by_key(|(_, _, spec, _)| std::cmp::Reverse(spec.n));
    on_all_cores(&sample, |(set, k, spec, stale)| {
        let id = spec.id.clone();
        let case = spec.clone().compute().unwrap();
        let got: serde_json::Value =
            serde_json::from_str(&serde_json::to_string(&case).unwrap()).unwrap();
        assert!(got == raws[*set]["cases"][*k], "{stale}: case {id}");
    });
}

/// Extensive tier: every file regenerated in full and compared byte for byte. The
/// cases of the three sets are computed on all cores, largest first (`generate` is
/// the same specs computed in order), then each file is assembled and compared.
#[test]
#[ignore = "extensive tier"]
fn committed_vectors_are_what_the_code_generates_byte_for_byte() {
    let mut work = Vec::new();
    for (s, set) in SETS.iter().enumerate() {
        for (k, spec) in vectors::specs(set).unwrap().into_iter().enumerate() {
            work.push((s, k, spec));
        }
    }
    work.sort_by_key(|(_, _, spec)| std::cmp::Reverse(spec.n));
    let computed = std::sync::Mutex::new(Vec::with_capacity(work.len()));
    on_all_cores(&work, |(s, k, spec)| {
        let case = spec.clone().compute().unwrap();
        computed.lock().unwrap().push((*s, *k, case));
    });
    let mut computed = computed.into_inner().unwrap();
    computed.sort_by_key(|(s, k, _)| (*s, *k));
    for (s, set) in SETS.iter().enumerate() {
        let cases = computed
            .iter()
            .filter(|(t, _, _)| *t == s)
            .map(|(_, _, case)| case.clone())
            .collect();
        let file = vectors::file_of(set, cases);
        let json = serde_json::to_string_pretty(&file).unwrap() + "\n";
        let read = |ext: &str| {
            std::fs::read_to_string(root().join(format!("vectors/{set}{ext}"))).unwrap()
        };
        assert!(
            read(".json") == json,
            "vectors/{set}.json is stale: run `cargo run --release -- vectors --out vectors`"
        );
        assert!(read(".csv") == to_csv(&file), "vectors/{set}.csv is stale");
        assert!(
            read("-inputs.csv") == inputs_csv(&file),
            "vectors/{set}-inputs.csv is stale"
        );
    }
}

/// The schema is derived from the types (`vectors::schema`, with the catalogue's
/// method names); the committed files are read by those types strictly (an unknown
/// field is refused) and pass `integrity::validate`, which enforces what the schema's
/// enumerations and ranges say and more.
#[test]
fn files_follow_the_schema() {
    let committed_schema = std::fs::read_to_string(root().join("vectors/schema.json")).unwrap();
    assert!(
        committed_schema == phong_approx::conformance::vectors::schema(),
        "vectors/schema.json is stale: regenerate with `phong-approx vectors --out vectors --force`"
    );
    for set in SETS {
        let text = std::fs::read_to_string(root().join(format!("vectors/{set}.json"))).unwrap();
        let f: VectorFile = serde_json::from_str(&text).unwrap();
        phong_approx::conformance::integrity::validate(&f).unwrap();
        assert_eq!(f.set, set);
        assert_eq!(
            f.version,
            phong_approx::conformance::vectors::FORMAT_VERSION
        );
        assert_eq!(f.number_of_cases, f.cases.len());
        let mut ids: Vec<&str> = f.cases.iter().map(|c| c.id.as_str()).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), f.cases.len(), "{set}: duplicate ids");
        for c in &f.cases {
            assert!(!c.comment.is_empty());
            for e in c.expected.values() {
                assert_eq!(e.values.len(), c.n as usize + 1, "{}", c.id);
                for s in &e.values {
                    let digits = s
                        .trim_start_matches('-')
                        .chars()
                        .take_while(|ch| *ch != 'e')
                        .filter(char::is_ascii_digit)
                        .count();
                    assert!(
                        s == "0" || digits >= 25,
                        "{}: '{s}' has {digits} digits",
                        c.id
                    );
                }
            }
        }
        // What the schema forbids is refused: a field it does not name, a method
        // outside its enumeration, a step count below its minimum.
        let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
        v["cases"][0]["extra"] = 1.into();
        assert!(
            serde_json::from_value::<VectorFile>(v).is_err(),
            "{set}: extra field"
        );
        for (field, value) in [
            ("methods", serde_json::json!(["gouraud", "nope"])),
            ("n", 0.into()),
        ] {
            let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
            if field == "n" {
                v["cases"][0]["n"] = value;
            } else {
                v[field] = value;
            }
            let f: VectorFile = serde_json::from_value(v).unwrap();
            assert!(
                phong_approx::conformance::integrity::validate(&f).is_err(),
                "{set}: {field}"
            );
        }
    }
}

#[test]
fn every_case_states_why_it_is_there() {
    let edge = committed("edge");
    let has = |pred: &dyn Fn(&Case) -> bool| edge.cases.iter().any(pred);
    assert!(has(&|c| c.n == 1) && has(&|c| c.n == 2) && has(&|c| c.n == 4096));
    assert!(has(&|c| c.na == c.nb));
    assert!(has(&|c| c.q_min < 0.01), "normals 170° apart");
    assert!(has(&|c| c.expected["phong"].levels.contains(&0)
        && c.expected["phong"].levels.iter().any(|&l| l > 0)));
    assert!(committed("paper")
        .cases
        .iter()
        .all(|c| c.comment.contains("60°")
            || c.comment.contains("Figures 1–3")
            || c.comment.starts_with("adaptive threshold")));
    // The adaptive test on both sides of its threshold, in every set (issue 31).
    for set in phong_approx::testkit::SETS {
        let f = committed(set);
        for d in ["gouraud", "corrected-euler"] {
            assert!(
                f.cases
                    .iter()
                    .any(|c| c.decision == d && c.comment.starts_with("adaptive threshold")),
                "{set} has no threshold case deciding {d}"
            );
        }
    }
}

#[test]
fn published_digests_are_those_of_the_committed_files() {
    use phong_approx::conformance::integrity::{published, published_set, sha256_hex};
    let sets: Vec<&str> = published().map(|(s, _)| s).collect();
    assert_eq!(sets, SETS, "vectors/SHA256SUMS lists every set, in order");
    for (set, digest) in published() {
        let bytes = std::fs::read(root().join(format!("vectors/{set}.json"))).unwrap();
        assert_eq!(sha256_hex(&bytes), digest, "{set}");
        assert_eq!(published_set(digest), Some(set));
        // And the committed file is valid by every invariant.
        phong_approx::conformance::integrity::validate(committed(set)).unwrap();
    }
    assert_eq!(
        sha256_hex(b"abc"),
        "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
    );
}

/// The sets of format 1.2.0 stay trusted (`vectors/SHA256SUMS-1.2.0`), and format
/// 1.3.0 only added the squared method: the committed files with its expectations and
/// its name taken out of their text, and the old version, are the 1.2.0 files byte
/// for byte (their digests), so no other expectation changed. (On the text: a file
/// read and written again may print a `q_min` one digit differently.)
#[test]
fn the_1_2_0_sets_are_the_current_ones_without_the_squared_method() {
    use phong_approx::conformance::integrity::{published_set, sha256_hex, PREVIOUS_SHA256SUMS};
    let previous: Vec<(&str, &str)> = PREVIOUS_SHA256SUMS
        .lines()
        .filter_map(|l| l.split_once("  "))
        .collect();
    assert_eq!(previous.len(), SETS.len());
    for (digest, file) in previous {
        let set = file.strip_suffix(".json").unwrap();
        assert_eq!(published_set(digest), Some(set), "{file} is still trusted");
        let text = std::fs::read_to_string(root().join(format!("vectors/{file}"))).unwrap();
        let mut old = String::new();
        let mut skip_to: Option<String> = None;
        let (mut blocks, mut names) = (0, 0);
        for line in text.lines() {
            if let Some(end) = &skip_to {
                if line == format!("{end},") || line == *end {
                    skip_to = None;
                }
                continue;
            }
            let trimmed = line.trim_start();
            let indent = &line[..line.len() - trimmed.len()];
            if trimmed == "\"squared-corrected-euler\": {" {
                skip_to = Some(format!("{indent}}}"));
                blocks += 1;
                continue;
            }
            if trimmed == "\"squared-corrected-euler\"," {
                names += 1;
                continue;
            }
            if trimmed == "\"version\": \"1.3.0\"," {
                old += &format!("{indent}\"version\": \"1.2.0\",\n");
                continue;
            }
            old += line;
            old += "\n";
        }
        let cases = committed(set).cases.len();
        let speculars = committed(set)
            .cases
            .iter()
            .filter(|c| c.specular.is_some())
            .count();
        assert_eq!((names, blocks), (1, cases + speculars), "{set}");
        assert_eq!(sha256_hex(old.as_bytes()), digest, "{set}");
    }
}
