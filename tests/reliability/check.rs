//! `check`'s inputs and verdicts: published and edited vector files, results files of
//! every shape, devices and FIFOs, memory and work bounded by the vector file, the
//! recomputation of modified files, ulps counted in the format checked, reports.

use super::*;

/// Defect d1 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn published_vectors_pass_and_modified_ones_are_refused() {
    let d = scratch("d1");
    let r = write(&d, "r.csv", &results_csv(&typical()));
    let v = root().join("vectors/typical.json").display().to_string();
    assert_eq!(code(&run(&["check", "--vectors", &v, "--results", &r])), 0);
    // The same content, re-serialized: not the published bytes.
    refused(
        &check_edited("d1b", |_| {}, &[]),
        "not that of a published vector set",
    );
    assert_eq!(code(&check_edited("d1c", |_| {}, ALLOW)), 0);
}

/// Defect d1 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn truncated_or_edited_expectations_cannot_make_garbage_pass() {
    // A modified file's expectations are not read: they are recomputed from its
    // inputs, so emptying or editing them changes nothing (the right results pass),
    // and a wrong result still fails.
    type Edit = fn(&mut Value);
    let edits: [(&str, Edit); 3] = [
        ("d1-empty", |v| {
            for c in v["cases"].as_array_mut().unwrap() {
                c["expected"]["corrected-euler"]["values"] = Value::Array(vec![]);
            }
        }),
        ("d1-qmin", |v| v["cases"][0]["q_min"] = 0.into()),
        ("d1-edit", |v| {
            v["cases"][3]["expected"]["corrected-euler"]["values"][1] = "1e39".into();
        }),
    ];
    for (name, edit) in edits {
        let o = check_edited(name, edit, ALLOW);
        assert_eq!(code(&o), 0, "{name}: {}", stderr(&o));
        let d = scratch(&format!("{name}-bad"));
        let mut v = typical();
        let bad = perturbed(&results_csv(&v), "typical-004", 1, "0.25");
        edit(&mut v);
        let vf = write(&d, "v.json", &serde_json::to_string(&v).unwrap());
        let rf = write(&d, "r.csv", &bad);
        let o = run(&[
            "check",
            "--vectors",
            &vf,
            "--results",
            &rf,
            "--allow-modified-vectors",
        ]);
        assert_eq!(code(&o), 1, "{name}: {}", stderr(&o));
    }
}

/// Defect d1 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn absurd_n_is_refused_without_allocating() {
    for n in [4_294_967_295u64, 400_000_000] {
        let t = Instant::now();
        let o = check_edited("d1-n", |v| v["cases"][0]["n"] = n.into(), ALLOW);
        refused(&o, "n = ");
        assert!(t.elapsed() < Duration::from_secs(30));
    }
}

/// Defect d1 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn ids_counts_and_versions_are_checked() {
    let o = check_edited(
        "d1-dup",
        |v| {
            let id = v["cases"][0]["id"].clone();
            v["cases"][1]["id"] = id;
        },
        ALLOW,
    );
    refused(&o, "not unique");
    let o = check_edited("d1-count", |v| v["number_of_cases"] = 41.into(), ALLOW);
    refused(&o, "number_of_cases");
    let o = check_edited("d1-version", |v| v["version"] = "99.0.0".into(), ALLOW);
    refused(&o, "not supported");
}

/// Defect d2 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn devices_and_fifos_are_capped() {
    let d = scratch("d2");
    let v = root().join("vectors/typical.json").display().to_string();
    let o = run_limited(
        &["check", "--vectors", &v, "--results", "/dev/zero"],
        Duration::from_secs(60),
    )
    .expect("reading /dev/zero stops at the cap");
    refused(&o, "larger than");
    let fifo = d.join("fifo");
    let c = std::ffi::CString::new(fifo.display().to_string()).unwrap();
    // SAFETY: `c` is a valid NUL-terminated path.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    let f = fifo.display().to_string();
    let o = run_limited(
        &["check", "--vectors", &v, "--results", &f],
        Duration::from_secs(30),
    )
    .expect("a FIFO without a writer does not block");
    refused(&o, "no results");
}

/// Defect d9 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn levels_tolerance_does_not_pass_absurd_values() {
    // Where the expected level is clamped (0 or 255), ±1e300 has the same level.
    let d = scratch("d9");
    let text = std::fs::read_to_string(root().join("vectors/edge.json")).unwrap();
    let v: Value = serde_json::from_str(&text).unwrap();
    let mut csv = String::from("case,pixel,value\n");
    let mut clamped = 0;
    for c in v["cases"].as_array().unwrap() {
        let e = &c["expected"]["corrected-euler"];
        let levels = e["levels"].as_array().unwrap();
        for (i, x) in e["values"].as_array().unwrap().iter().enumerate() {
            let value = match levels[i].as_u64() {
                Some(255) => "1e300",
                Some(0) => "-1e300",
                _ => x.as_str().unwrap(),
            };
            clamped += usize::from(value.ends_with("e300"));
            csv.push_str(&format!("{},{i},{value}\n", c["id"].as_str().unwrap()));
        }
    }
    assert!(clamped > 1000);
    let r = write(&d, "r.csv", &csv);
    let vp = root().join("vectors/edge.json").display().to_string();
    let o = run(&[
        "check",
        "--vectors",
        &vp,
        "--results",
        &r,
        "--tolerance",
        "levels=0",
        "--precision",
        "f64",
    ]);
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    // In f32 (the default) 1e300 denotes no finite f32: refused as beyond its range.
    let o = run(&[
        "check",
        "--vectors",
        &vp,
        "--results",
        &r,
        "--tolerance",
        "levels=0",
    ]);
    refused(&o, "is outside the range of f32");
}

/// Defect d12 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn csv_with_a_bom_and_quotes_is_read() {
    let d = scratch("d12");
    let v = typical();
    let quoted: String = results_csv(&v)
        .lines()
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            format!("\"{}\",{},\"{}\"\r\n", f[0], f[1], f[2])
        })
        .collect();
    let r = write(&d, "r.csv", &format!("\u{feff}{quoted}"));
    let vp = root().join("vectors/typical.json").display().to_string();
    let o = run(&["check", "--vectors", &vp, "--results", &r]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    // Anything else is refused with the offending bytes escaped.
    let r = write(&d, "bad.csv", "case,pixel,value\n\"typical-001,0,0.5\n");
    let o = run(&["check", "--vectors", &vp, "--results", &r]);
    assert_eq!(code(&o), 2);
}

/// Defect r2 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn check_memory_is_bounded_by_the_vector_file() {
    let d = scratch("r2");
    let v = root().join("vectors/typical.json").display().to_string();
    // The published typical set with its own exact results, within the base.
    let good = write(&d, "good.csv", &results_csv(&typical()));
    let (c, e, _) = run_within(
        &["check", "--vectors", &v, "--results", &good],
        BASE_MIB + 8,
    );
    assert_eq!(c, 0, "{e}");
    // 4 M zeros for one case (8 MB), with the id first and with it last; a CSV row
    // of 8 M commas; 3 MB of rows of empty fields. (Reading them whole took about 37
    // times the file: 296 MB for 8 MB of zeros.)
    let zeros = vec!["0"; 4 << 20].join(",");
    let cases = [
        (
            "first.json",
            format!(r#"{{"cases":[{{"id":"typical-001","values":[{zeros}]}}]}}"#),
            "typical-001 has more than",
        ),
        (
            "last.json",
            format!(r#"{{"cases":[{{"values":[{zeros}],"id":"typical-001"}}]}}"#),
            "has more than",
        ),
        ("commas.csv", ",".repeat(8 << 20), "bytes long"),
        ("empty.csv", ",,\n".repeat(1 << 20), "field is empty"),
    ];
    for (name, text, needle) in cases {
        let r = write(&d, name, &text);
        let mib = text.len() as u64 >> 20;
        let t = Instant::now();
        // The file's bytes once, and as much again for what is built from them.
        let (c, e, _) = run_within(
            &["check", "--vectors", &v, "--results", &r],
            BASE_MIB + 8 + 2 * mib,
        );
        assert_eq!(c, 2, "{name}: {e}");
        assert_eq!(e.trim_end().lines().count(), 1, "{name}: {e}");
        assert!(e.contains(needle), "{name}: {e}");
        assert!(t.elapsed() < Duration::from_secs(20), "{name}");
    }
}

/// Defect r6 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn modified_vectors_supply_cases_not_truth() {
    let d = scratch("r6");
    // Every corrected-Euler value set to 0.5 (level 127), and results of all 0.5:
    // the expectations are recomputed, so the results fail.
    let mut v = typical();
    let mut rows = String::from("case,pixel,value\n");
    for c in v["cases"].as_array_mut().unwrap() {
        let e = &mut c["expected"]["corrected-euler"];
        let n = e["values"].as_array().unwrap().len();
        e["values"] = Value::Array(vec![Value::from("0.5"); n]);
        e["levels"] = Value::Array(vec![Value::from(127); n]);
        for i in 0..n {
            rows.push_str(&format!("{},{i},0.5\n", c["id"].as_str().unwrap()));
        }
    }
    let vf = write(&d, "half.json", &serde_json::to_string(&v).unwrap());
    let rf = write(&d, "half.csv", &rows);
    let o = run(&[
        "check",
        "--vectors",
        &vf,
        "--results",
        &rf,
        "--allow-modified-vectors",
    ]);
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("recomputed from the file's inputs"), "{out}");
    // The right results pass whatever the file's expectations say (even none).
    let good = write(&d, "good.csv", &results_csv(&typical()));
    for c in v["cases"].as_array_mut().unwrap() {
        c["expected"] = serde_json::json!({});
        c["q_min"] = 0.into();
    }
    let vf = write(&d, "none.json", &serde_json::to_string(&v).unwrap());
    let o = run(&[
        "check",
        "--vectors",
        &vf,
        "--results",
        &good,
        "--allow-modified-vectors",
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    // A float form that is not the nearest float to the exact input is refused.
    let mut w = typical();
    w["cases"][2]["na"]["f32"][0] = "0.5".into();
    let wf = write(&d, "f32.json", &serde_json::to_string(&w).unwrap());
    refused(
        &run(&[
            "check",
            "--vectors",
            &wf,
            "--results",
            &good,
            "--allow-modified-vectors",
        ]),
        "is not the nearest f32",
    );
    // Echoed text is escaped and cut: no escape sequence, no line of 100 KB.
    let mut w = typical();
    w["set"] = format!("\u{1b}[2J{}", "s".repeat(100_000)).into();
    w["version"] = "1.0\u{1b}[31m".into();
    for c in w["cases"].as_array_mut().unwrap() {
        c["comment"] = format!("\u{1b}[31mred\n{}", "c".repeat(100_000)).into();
    }
    let wf = write(&d, "echo.json", &serde_json::to_string(&w).unwrap());
    let o = run(&[
        "check",
        "--vectors",
        &wf,
        "--results",
        &good,
        "--allow-modified-vectors",
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(!out.contains('\u{1b}'), "an escape sequence reached stdout");
    assert!(
        out.lines().all(|l| l.chars().count() < 600),
        "a long line reached stdout"
    );
    // A vector file of millions of values: skipped unread, not stored.
    let mut w = typical();
    w["cases"][0]["expected"]["corrected-euler"]["values"] =
        Value::Array(vec![Value::from("0"); 2 << 20]);
    let text = serde_json::to_string(&w).unwrap();
    let wf = write(&d, "big.json", &text);
    let mib = text.len() as u64 >> 20;
    drop(text);
    let (c, e, _) = run_within(
        &[
            "check",
            "--vectors",
            &wf,
            "--results",
            &good,
            "--allow-modified-vectors",
        ],
        BASE_MIB + 8 + 2 * mib,
    );
    assert_eq!(c, 0, "{e}");
}

/// Defect r9 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn exact_work_is_budgeted_by_method_and_input_size() {
    // What would take minutes is refused at once, naming --yes: binary's square root
    // per segment point at 65536 steps (3–4 minutes), 80-digit inputs at 65536 steps.
    let big = BigInt::from(10).pow(80u32);
    let na = format!(
        "{}/{},0,{}/{}",
        BigInt::from(10).pow(40u32) * 2,
        big.clone() + 1,
        big.clone() - 1,
        big + 1
    );
    for (m, na) in [
        ("binary", "0,0,1"),
        ("phong", na.as_str()),
        ("spherical", na.as_str()),
    ] {
        let t = Instant::now();
        let o = span_run(
            m,
            [na, "0.6,0,0.8", "0,0,1"],
            "65536",
            &["--scalar", "exact"],
        );
        refused(&o, "pass --yes");
        assert!(t.elapsed() < Duration::from_secs(5), "{m}");
    }
}

/// Defect q3 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn check_recomputes_nearly_opposite_normals_to_every_digit() {
    use phong_approx::conformance::vectors::InputsFile;
    use phong_approx::Method;
    // N_b 2·10^-60 from opposite N_a: Phong's middle value p/√q with q ≈ 10^-120,
    // where 2^-256 square roots leave about 17 digits.
    let a = BigInt::from(10).pow(60u32);
    let d = &a * &a + 1;
    let nb = [
        format!("{}/{d}", BigInt::from(2) * &a),
        "0".to_string(),
        format!("{}/{d}", BigInt::from(1) - &a * &a),
    ];
    let exact = |c: &[String; 3]| -> Vec<BigRational> {
        c.iter()
            .map(|s| phong_approx::parse::parse_rational(s).unwrap())
            .collect()
    };
    let forms = |c: &[String; 3]| -> Value {
        use phong_approx::Scalar;
        let e = exact(c);
        serde_json::json!({
            "exact": c,
            "f32": e.iter().map(|x| format!("{:?}", f32::from_rational(x))).collect::<Vec<_>>(),
            "f64": e.iter().map(|x| format!("{:?}", f64::from_rational(x))).collect::<Vec<_>>(),
        })
    };
    let na = ["0".to_string(), "0".to_string(), "1".to_string()];
    let l = ["2/3".to_string(), "1/3".to_string(), "2/3".to_string()];
    let file = serde_json::json!({
        "version": "1.0", "set": "opposite", "methods": ["phong"], "number_of_cases": 1,
        "cases": [{"id": "opposite-1", "na": forms(&na), "nb": forms(&nb), "l": forms(&l), "n": 2}],
    });
    let inputs: InputsFile = serde_json::from_value(file).unwrap();
    let got = inputs.recompute(Method::Phong, false).unwrap();
    let middle = &got.cases[0].expected["phong"].values[1];
    // Independently: N(1) = (N_a + N_b)/2 = (a, 0, 1)/d; p = (2a/3 + 2/3)/d,
    // q = (a² + 1)/d², so p/√q = (2/3)(a + 1)/√(a² + 1).
    let num = BigInt::from(4) * (&a + 1) * (&a + 1);
    let den = BigInt::from(9) * (&a * &a + 1);
    let want = sqrt_digits(&num, &den, 40, 25);
    let digits: String = middle.chars().filter(char::is_ascii_digit).collect();
    assert!(middle.starts_with("0.6"), "{middle}");
    assert_eq!(&digits[1..26], want, "{middle}");
}

/// Defect q5 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn ulps_are_counted_in_the_precision_checked() {
    use phong_approx::Format;
    assert_eq!(Format::Binary64.ulp(1.0), f64::EPSILON);
    assert_eq!(Format::Binary32.ulp(1.0), f64::from(f32::EPSILON));
    // f64 results off by a relative 2^-30 (2^22 f64 ulps) fail ulps=0.5 under f64.
    let d = scratch("q5");
    let csv = results_csv(&typical());
    let off: String = csv
        .lines()
        .map(|l| match l.rsplit_once(',') {
            Some((head, v)) if head != "case,pixel" => {
                let x: f64 = v.parse().unwrap();
                format!("{head},{:e}\n", x * (1.0 + 2f64.powi(-30)))
            }
            _ => format!("{l}\n"),
        })
        .collect();
    let r = write(&d, "r.csv", &off);
    let v = root().join("vectors/typical.json").display().to_string();
    let o = run(&[
        "check",
        "--vectors",
        &v,
        "--results",
        &r,
        "--precision",
        "f64",
        "--tolerance",
        "ulps=0.5",
    ]);
    assert_eq!(code(&o), 1, "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("f64 ulps"));
}

/// Defect q9 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn specular_exponents_and_work_are_refused_before_any_work() {
    let d = scratch("q9");
    for (s, n, needle) in [
        (4_294_967_295u64, 4u64, "shininess 4294967295 is outside"),
        (1_000_000, 4, "outside 1..=10000"),
        (10_000, 4096, "units of exact work"),
    ] {
        let (v, r) = specular_file(&d, s, n);
        for extra in [&["--specular"][..], &[][..]] {
            let t = Instant::now();
            let mut args = vec!["check", "--vectors", &v, "--results", &r];
            args.extend_from_slice(ALLOW);
            args.extend_from_slice(extra);
            let o = run(&args);
            if extra.is_empty() && s <= 10_000 {
                // Without --specular the powers are not computed at all.
                assert_ne!(code(&o), 2, "{}", stderr(&o));
            } else {
                refused(&o, needle);
            }
            assert!(t.elapsed() < Duration::from_secs(20), "{s} {n}");
        }
    }
}

/// Defect q14 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn reports_once_and_valid_xml_for_any_case_id() {
    let d = scratch("q14");
    let (a, b) = (d.join("a.xml"), d.join("b.json"));
    let o = check_typical(
        &d,
        &[
            "--report",
            "junit",
            a.to_str().unwrap(),
            "--report",
            "json",
            b.to_str().unwrap(),
        ],
    );
    refused(&o, "more than once");
    // A case id with U+FFFE and U+FFFF: the JUnit report stays XML.
    let mut v = typical();
    let id = "typical-\u{fffe}\u{ffff}";
    let first = v["cases"][0]["id"].as_str().unwrap().to_string();
    v["cases"][0]["id"] = id.into();
    let csv = results_csv(&typical()).replace(&format!("{first},"), &format!("{id},"));
    let vf = write(&d, "v.json", &v.to_string());
    let rf = write(&d, "r2.csv", &csv);
    let x = d.join("x.xml");
    let o = run(&[
        "check",
        "--vectors",
        &vf,
        "--results",
        &rf,
        "--allow-modified-vectors",
        "--report",
        "junit",
        x.to_str().unwrap(),
    ]);
    assert!(code(&o) <= 1, "{}", stderr(&o));
    let text = std::fs::read_to_string(&x).unwrap();
    assert!(roxmltree::Document::parse(&text).is_ok());
}

/// Defect q9 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn the_work_estimate_grows_with_every_input_and_refuses_the_documented_examples() {
    use phong_approx::budget::{exact_work, specular_work, CASE_WORK, MAX_RECOMPUTED_WORK};
    use phong_approx::Method;
    for m in [Method::CorrectedEuler, Method::Phong, Method::Binary] {
        let w = |n, bits, digits| exact_work(m, n, bits, digits);
        assert!(w(2, 40, 30) < w(3, 40, 30), "{m}: n");
        assert!(w(64, 40, 30) < w(64, 700, 30), "{m}: inputs");
        assert!(w(64, 40, 30) <= w(64, 40, 1000), "{m}: digits");
    }
    assert!(specular_work(4, 200, 40) < specular_work(4, 1000, 40));
    assert!(specular_work(4, 1000, 40) < specular_work(8, 1000, 40));
    // The documented examples (docs/conformance.md, "Limits and exit codes").
    let ce = |n, bits| exact_work(Method::CorrectedEuler, n, bits, 30);
    assert!(100_000 * (CASE_WORK + ce(1, 41)) > MAX_RECOMPUTED_WORK);
    assert!(20_000 * (CASE_WORK + ce(1, 41)) < MAX_RECOMPUTED_WORK);
    assert!(specular_work(4096, 10_000, 41) > MAX_RECOMPUTED_WORK);
    assert!(ce(65_536, 625) < MAX_RECOMPUTED_WORK);
    assert!(exact_work(Method::AngularTable(1 << 24), 1, 41, 30) > MAX_RECOMPUTED_WORK);
}

/// Defect q3b of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn a_level_near_a_boundary_is_decided_with_more_bits() {
    // Angular interpolation from N_a to N_b = L = +z over 2 steps: the middle value is
    // cos(α_a/2) = 1/√(1 + t²) for N_a of stereographic parameter t. With t just below
    // √((255/200)² − 1) (2^-258 below), the value is k/255 + about 2^-258 (k = 200):
    // within 2^-250 of a level boundary, so 2^-256 square roots and cosines cannot
    // decide its level, and check's recomputation refused such a case; 512 bits do.
    let k = BigInt::from(200);
    let scale = BigInt::from(1) << 258u32;
    let a = ((BigInt::from(255 * 255) - &k * &k) << 516u32).sqrt();
    let d = &k * &scale; // t = a/d
    let s = &a * &a + &d * &d;
    let na = format!(
        "{}/{},0,{}/{}",
        BigInt::from(2) * &a * &d,
        s,
        &d * &d - &a * &a,
        s
    );
    let o = span_run(
        "angular",
        [&na, "0,0,1", "0,0,1"],
        "2",
        &["--scalar", "exact"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let j: Value = serde_json::from_slice(&o.stdout).unwrap();
    // Independently: 1/(1 + t²) > (200/255)² since t < √((255/200)² − 1), so the value
    // is above 200/255 (and far below 201/255): level 200.
    let t2 = BigRational::new(&a * &a, &d * &d);
    let one = BigRational::from_integer(1.into());
    assert!(one.clone() / (one + t2) > BigRational::new(200.into(), 255.into()).pow(2));
    assert_eq!(j["levels"][1], 200, "{j}");
}

/// Defect d11 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn echoed_input_is_cut_and_escaped() {
    let d = scratch("d11");
    let v = root().join("vectors/typical.json").display().to_string();
    // An id of 10 MB is a line too long to be a row; one of 4000 characters is an
    // unknown id, shown cut and escaped.
    for (len, needle) in [(10_000_000, "bytes long"), (4000, "unknown case id")] {
        let id = format!("\x1b[31m{}", "x".repeat(len));
        let r = write(&d, "r.csv", &format!("case,pixel,value\n{id},0,0.5\n"));
        let o = run(&["check", "--vectors", &v, "--results", &r]);
        refused(&o, needle);
        let e = stderr(&o);
        assert!(e.len() < 2000, "{} bytes of stderr", e.len());
        assert!(!e.contains('\x1b'), "raw escape byte");
    }
}

/// Defect q15 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn check_messages_say_what_is_wrong() {
    let v = root().join("vectors/typical.json").display().to_string();
    refused(
        &run(&["check", "--vectors", "-", "--results", "-"]),
        "cannot be both --vectors and --results",
    );
    let d = scratch("q15");
    let bom = write(&d, "bom.json", "\u{feff}{\"cases\": []}");
    let o = run(&["check", "--vectors", &v, "--results", &bom]);
    assert_eq!(code(&o), 2);
    assert!(!stderr(&o).contains("columns"), "{}", stderr(&o));
    let arr = write(&d, "arr.json", "[1, 2]");
    let o = run(&["check", "--vectors", &v, "--results", &arr]);
    assert!(!stderr(&o).contains("columns"), "{}", stderr(&o));
    // 1e400 is refused alike in CSV and JSON.
    let csv = write(&d, "big.csv", "typical-001,0,1e400\n");
    refused(
        &run(&["check", "--vectors", &v, "--results", &csv]),
        "outside the range of f64",
    );
    let json = write(
        &d,
        "big.json",
        "{\"cases\": [{\"id\": \"typical-001\", \"values\": [1e400]}]}",
    );
    refused(
        &run(&["check", "--vectors", &v, "--results", &json]),
        "outside the range of f64",
    );
    // A line of exactly the limit, with CRLF, is not refused for its length.
    let long = format!("# {}\r\n", "x".repeat(4094));
    let f = write(&d, "crlf.csv", &(long + &results_csv(&typical())));
    let o = run(&["check", "--vectors", &v, "--results", &f]);
    assert!(!stderr(&o).contains("bytes long"), "{}", stderr(&o));
}

/// Writes `text` to a fresh file named `name` of the scratch folder `check-malformed`.
fn tmp(name: &str, text: &str) -> PathBuf {
    let p = std::env::temp_dir().join(format!("phong-approx-rel-{}-m-{name}", std::process::id()));
    std::fs::write(&p, text).unwrap();
    p
}

/// `check` of `results` against `vectors` with `extra`: exit code, stdout, stderr.
fn run_check(vectors: &str, results: &Path, extra: &[&str]) -> (i32, String, String) {
    let out = runner::bin()
        .args(["check", "--vectors", vectors, "--results"])
        .arg(results)
        .args(extra)
        .output()
        .unwrap();
    (
        code(&out),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr(&out),
    )
}

fn typical_path() -> String {
    root().join("vectors/typical.json").display().to_string()
}

fn malformed(text: &str, needle: &str) {
    let p = tmp("m.csv", text);
    let (code, out, err) = run_check(&typical_path(), &p, &[]);
    assert_eq!(code, 2, "{needle}: {out}{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(
        err.contains(&p.display().to_string()),
        "file not named: {err}"
    );
    assert!(err.contains(needle), "'{err}' lacks '{needle}'");
    assert!(!err.contains("panicked"));
}

#[test]
fn malformed_results_get_one_line_naming_file_line_and_problem() {
    // The exact corrected-Euler values of the typical set: every line passes.
    let good = results_csv(&typical());
    let lines: Vec<&str> = good.lines().collect();
    let with = |k: usize, replacement: &str| {
        let mut v: Vec<String> = lines.iter().map(|s| s.to_string()).collect();
        v[k] = replacement.to_string();
        v.join("\n")
    };
    malformed(
        &with(3, "typical-001,2"),
        ":4: expected 3 columns (case,pixel,value), found 2",
    );
    malformed(&with(3, "typical-001,2,0.5,9"), ":4: expected 3 columns");
    malformed(
        &with(3, "typical-001,2,abc"),
        ":4: value 'abc' is not a number",
    );
    // A NaN or an infinity is a result, and fails its pixel (exit 1, named).
    for bad in ["NaN", "inf", "-Infinity"] {
        let p = tmp("nonfinite.csv", &with(3, &format!("typical-001,2,{bad}")));
        let (code, out, err) = run_check(&typical_path(), &p, &[]);
        assert_eq!(code, 1, "{bad}: {out}{err}");
        assert!(
            err.contains("worst: typical-001 (pixel 2 is not finite)"),
            "{bad}: {err}"
        );
        assert!(out.contains("not finite at pixel 2"), "{out}");
        assert!(!out.contains("NaN") && !out.contains(" inf"), "{out}");
    }
    malformed(
        &with(3, "typical-001,two,0.5"),
        ":4: pixel 'two' is not a whole number",
    );
    malformed(
        &with(3, "nosuch-001,2,0.5"),
        ":4: unknown case id 'nosuch-001'",
    );
    malformed(
        &with(3, "typical-001,99,0.5"),
        ":4: pixel 99 is out of range for case typical-001",
    );
    malformed(
        &with(3, "typical-001,1,0.5"),
        ":4: duplicate row for case typical-001 pixel 1 (first at line 3)",
    );
    // typical-001 has n = 2: dropping pixel 2 leaves it missing.
    malformed(
        &with(3, "# dropped"),
        "at end of file: case typical-001 has no value for pixel 2",
    );
    // Header, typical-001 (n = 2) and typical-002 (n = 3): typical-003 is missing.
    malformed(
        &lines[..8].join("\n"),
        "at end of file: case typical-003 is missing",
    );
    malformed("", ":1: the file holds no results");
    malformed("case,pixel,value\n", ":1: the file holds no results");
    malformed("{\"cases\": [", "not a results file");
    malformed("\u{1}\u{2}garbage,,", ":1: unknown case id");
    malformed("\u{1}\u{2}garbage", ":1: expected 3 columns");
    // A file over the size limit is refused before it is read.
    let big =
        std::env::temp_dir().join(format!("phong-approx-conf-{}-big.csv", std::process::id()));
    let f = std::fs::File::create(&big).unwrap();
    f.set_len(phong_approx::conformance::check::MAX_RESULTS_BYTES + 1)
        .unwrap();
    let (code, _, err) = run_check(&typical_path(), &big, &[]);
    assert_eq!(code, 2);
    assert!(err.contains("larger than 256 MiB"), "{err}");
    let _ = std::fs::remove_file(big);
    // Bad arguments.
    let p = tmp("ok.csv", &good);
    for (args, needle) in [
        (vec!["--tolerance", "levels=x"], "--tolerance:"),
        (vec!["--tolerance", "rel=1"], "unknown tolerance 'rel'"),
        (vec!["--method", "bishop"], "--method: unknown method"),
        (
            vec!["--precision", "f16"],
            "--precision: unknown value 'f16'",
        ),
    ] {
        let (code, _, err) = run_check(&typical_path(), &p, &args);
        assert_eq!(code, 2, "{args:?}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    let (code, _, err) = run_check("/nonexistent/vectors.json", &p, &[]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--vectors: /nonexistent/vectors.json"),
        "{err}"
    );
}

/// Finding 8 of the fifth reliability round: a result beyond f64's range is named, and
/// one below it is refused alike rather than read as 0.
#[test]
fn results_beyond_and_below_f64_are_refused_alike_and_named() {
    let d = scratch("f50-range");
    let v = root().join("vectors/typical.json").display().to_string();
    let json = write(
        &d,
        "big.json",
        "{\"cases\": [{\"id\": \"typical-001\", \"values\": [0.5, 1e400]}]}",
    );
    refused(
        &run(&["check", "--vectors", &v, "--results", &json]),
        "value '1e400' is outside the range of f64",
    );
    for (name, text) in [
        (
            "tiny.csv",
            "case,pixel,value\ntypical-001,0,1e-400\n".to_string(),
        ),
        (
            "tiny.json",
            "{\"cases\": [{\"id\": \"typical-001\", \"values\": [0.5, 1e-400]}]}".to_string(),
        ),
        (
            "tiny-string.json",
            "{\"cases\": [{\"id\": \"typical-001\", \"values\": [\"1e-400\"]}]}".to_string(),
        ),
    ] {
        let f = write(&d, name, &text);
        let o = run(&["check", "--vectors", &v, "--results", &f]);
        assert_eq!(code(&o), 2, "{name}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("1e-400") || stderr(&o).contains("not a number"),
            "{name}: {}",
            stderr(&o)
        );
    }
    // A zero written as such is a value.
    let zero = write(&d, "zero.csv", "case,pixel,value\ntypical-001,0,0e-400\n");
    assert!(
        !stderr(&run(&["check", "--vectors", &v, "--results", &zero])).contains("below the range")
    );
}

/// A result is judged as the float it denotes (`--precision f32`): the float's
/// shortest decimal, its exact decimal expansion and a decimal a third of an ulp away
/// from it denote one `f32`, and get one verdict, to the last digit of every ratio.
#[test]
fn a_result_is_the_float_it_denotes() {
    let d = scratch("f51-denote");
    let v = typical();
    let mut files = [
        String::from("case,pixel,value\n"),
        String::from("case,pixel,value\n"),
        String::from("case,pixel,value\n"),
    ];
    let mut k = 0i32;
    for c in v["cases"].as_array().unwrap() {
        let id = c["id"].as_str().unwrap();
        for (i, x) in c["expected"]["corrected-euler"]["values"]
            .as_array()
            .unwrap()
            .iter()
            .enumerate()
        {
            // The nearest f32 to the exact value, moved by −1, 0 or 1 ulp.
            let mut g: f32 = x.as_str().unwrap().parse().unwrap();
            k += 1;
            g = match k % 3 {
                0 => g.next_down(),
                1 => g,
                _ => g.next_up(),
            };
            let third = f64::from(g) + (f64::from(g.next_up()) - f64::from(g)) / 3.0;
            files[0] += &format!("{id},{i},{g}\n");
            files[1] += &format!("{id},{i},{:.80e}\n", f64::from(g));
            files[2] += &format!("{id},{i},{third:e}\n");
        }
    }
    let vectors = root().join("vectors/typical.json").display().to_string();
    let verdicts: Vec<Value> = files
        .iter()
        .enumerate()
        .map(|(k, text)| {
            let r = write(&d, &format!("r{k}.csv"), text);
            let o = run(&[
                "check",
                "--vectors",
                &vectors,
                "--results",
                &r,
                "--report",
                "json",
                "-",
            ]);
            assert!(code(&o) <= 1, "{}", stderr(&o));
            let mut j: Value = serde_json::from_slice(&o.stdout).unwrap();
            for c in j["cases"].as_array_mut().unwrap() {
                c.as_object_mut().unwrap().retain(|k, _| {
                    ["id", "pass", "max_abs", "ratio", "max_levels"].contains(&k.as_str())
                });
            }
            j["cases"].clone()
        })
        .collect();
    assert_eq!(verdicts[0], verdicts[1]);
    assert_eq!(verdicts[0], verdicts[2]);
    // A decimal halfway between two f32 denotes neither: refused.
    let mid = f64::from(0.5f32) + (f64::from(0.5f32.next_up()) - 0.5) / 2.0;
    let r = write(
        &d,
        "mid.csv",
        &files[0].replacen(
            &files[0].lines().nth(1).unwrap().to_string(),
            &format!("typical-001,0,{mid:e}"),
            1,
        ),
    );
    refused(
        &run(&["check", "--vectors", &vectors, "--results", &r]),
        "halfway between two f32",
    );
}
