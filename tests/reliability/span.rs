//! `span`: values and digits that are true in every number type, normalization, the
//! work budget and the refusals of bad requests.

use super::*;

// ------------------------------------------------------- span's refusals, end to end

/// Runs with `extra` replacing the named defaults; expects exit 2 and one stderr line
/// containing `needle`.
fn bad(extra: &[(&str, &str)], needle: &str) {
    let mut args: Vec<(String, String)> = [
        ("--method", "corrected-euler"),
        ("--na", "0,3/5,4/5"),
        ("--nb", "2/7,3/7,6/7"),
        ("--light", "2/3,1/3,2/3"),
        ("--steps", "4"),
    ]
    .iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect();
    for (k, v) in extra {
        match args.iter_mut().find(|(a, _)| a == k) {
            Some(slot) => slot.1 = v.to_string(),
            None => args.push((k.to_string(), v.to_string())),
        }
    }
    let mut cmd = bin();
    cmd.arg("span");
    for (k, v) in &args {
        cmd.arg(format!("{k}={v}"));
    }
    let out = cmd.output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{extra:?}: {err}");
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "{extra:?}: not one line: {err}"
    );
    assert!(err.contains(needle), "{extra:?}: '{err}' lacks '{needle}'");
    assert!(!err.contains("panicked"), "{extra:?}: {err}");
    assert!(out.stdout.is_empty());
}

/// End to end, as a process: exit code 2, one line on stderr, nothing on stdout. The
/// full table of bad requests is checked in process (`src/main.rs`,
/// `bad_span_requests_are_refused_in_process`); these need the process.
#[test]
fn bad_input_gets_one_line_and_exit_2() {
    bad(
        &[("--na", "0.6,x,0.8")],
        "--na: component 2 'x' is not a number",
    );
    bad(&[("--light", "0,0,0")], "--light: the vector is zero");
    bad(
        &[("--nb", "0,-3/5,-4/5"), ("--method", "phong")],
        "pixel 2 of n = 4: the interpolated normal is zero",
    );
    bad(&[("--bogus", "1")], "--bogus");
    // Missing required arguments: clap's message, folded to one line.
    let out = bin().args(["span", "--method", "phong"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("--na"), "{err}");
}

#[test]
fn huge_steps_are_refused_not_allocated() {
    bad(
        &[("--steps", "99999999999")],
        "--steps: n must be between 1 and 16777216",
    );
}

// --------------------------------------------------------- the reliability rounds

/// Defect d3 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn non_finite_values_are_errors_naming_the_pixel() {
    let o = span_run(
        "duff",
        ["0,0,1", "1e-30,0,-1", "0.6,0,0.8"],
        "2",
        &["--normalize"],
    );
    refused(&o, "pixel 1 of n = 2");
    let o = span_run(
        "duff",
        ["0,0,1", "3e-4,0,-1", "0.6,0,0.8"],
        "2",
        &["--normalize", "--scalar", "f32"],
    );
    refused(&o, "not finite");
    // Binary and Bishop–Weimer printed inf / NaN with exit 0 on these (exact unit
    // inputs, no --normalize; and a normalized tilt of 1e-10).
    for method in ["binary", "bishop-weimer", "spherical"] {
        let o = run(&[
            "span",
            "--method",
            method,
            "--na",
            "0,0,1",
            "--nb=200000/10000000001,0,-9999999999/10000000001",
            "--light",
            "0.6,0,0.8",
            "--steps",
            "2",
            "--scalar",
            "f32",
            "--format",
            "table",
        ]);
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(
            code(&o) == 2 || !(out.contains("inf") || out.contains("NaN")),
            "{method}: {out}"
        );
        if code(&o) == 2 {
            refused(&o, "not finite");
        }
        let o = run(&[
            "span",
            "--method",
            method,
            "--na",
            "0,0,1",
            "--nb",
            "1e-10,0,-1",
            "--normalize",
            "--light",
            "0.6,0,0.8",
            "--steps",
            "2",
            "--scalar",
            "f32",
        ]);
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(
            code(&o) == 2 || !(out.contains("inf") || out.contains("NaN")),
            "{method}: {out}"
        );
    }
}

/// Defect d4 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn exact_normalize_takes_any_nonzero_finite_input() {
    for (na, scalar) in [
        ("1e-100,0,1e-100", "exact"),
        ("1e-9,2e-9,3e-9", "exact"),
        ("1e308,0,1", "f64"),
    ] {
        let o = span_run(
            "gouraud",
            [na, "0,0,1", "0,0,1"],
            "2",
            &["--normalize", "--scalar", scalar],
        );
        assert_eq!(code(&o), 0, "{na} {scalar}: {}", stderr(&o));
    }
}

/// Defect d5 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn no_digit_is_printed_that_is_not_known() {
    let o = span_run(
        "phong",
        ["0,0,1", "0.6,0,0.8", "0.28,0.96,0"],
        "3",
        &["--scalar", "exact", "--digits", "200"],
    );
    // More digits than 2^-256 gives: the run is repeated with more bits, and every
    // printed digit is right (value² = p²/q, independently, to 2·10^-199).
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let (na, nb, l) = ([0, 0, 5], [3, 0, 4], [7, 24, 0]); // ×1/5, ×1/5, ×1/25
    for (i, x) in v["values"].as_array().unwrap().iter().enumerate() {
        let s = x.as_str().unwrap();
        assert!(
            s == "0" || s.replace(['.', '-'], "").trim_start_matches('0').len() >= 200,
            "{s}"
        );
        let got = phong_approx::parse::parse_rational(s).unwrap();
        let t = BigRational::new(i.into(), 3.into());
        let comp = |k: usize| {
            (BigRational::from_integer(1.into()) - t.clone())
                * BigRational::from_integer(na[k].into())
                + t.clone() * BigRational::from_integer(nb[k].into())
        };
        let n = [comp(0), comp(1), comp(2)];
        let p: BigRational = (0..3)
            .map(|k| n[k].clone() * BigRational::from_integer(l[k].into()))
            .sum();
        let q: BigRational = (0..3).map(|k| n[k].clone() * n[k].clone()).sum();
        // p/√q with the 1/5 and 1/25 scales: (p/125)² / (q/25) = p²/(625·q).
        let want2 = p.clone() * p / (q * BigRational::from_integer(625.into()));
        let diff = (got.clone() * got - want2).abs();
        assert!(
            diff < BigRational::new(2.into(), BigInt::from(10).pow(199u32)),
            "pixel {i}"
        );
    }
    // Beyond what any precision this tool uses gives: refused at once.
    let t = Instant::now();
    let o = span_run(
        "phong",
        ["0,0,1", "0.6,0,0.8", "0.28,0.96,0"],
        "3",
        &["--scalar", "exact", "--digits", "10000"],
    );
    refused(&o, "at most 2446 significant digits");
    assert!(t.elapsed() < Duration::from_secs(5));
    // Rational methods are exact: any number of digits.
    let o = span_run(
        "corrected-euler",
        ["0,0,1", "0.6,0,0.8", "0.28,0.96,0"],
        "3",
        &["--scalar", "exact", "--digits", "200"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
}

/// Defect d6 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn work_beyond_the_budget_needs_yes() {
    let t = Instant::now();
    let span = |extra: &[&str]| {
        let mut a = vec![
            "span",
            "--method",
            "phong",
            "--na",
            "0,0,1",
            "--nb",
            "0.6,0,0.8",
            "--light",
            "0,0,1",
        ];
        a.extend_from_slice(extra);
        run(&a)
    };
    refused(
        &span(&["--steps", "16777216", "--scalar", "exact"]),
        "--yes",
    );
    // A million rational values of 10,000 digits each would be 20 GB of output.
    let o = span_run(
        "gouraud",
        ["0,0,1", "0.6,0,0.8", "0,0,1"],
        "1000000",
        &["--scalar", "f64", "--digits", "10000"],
    );
    assert_eq!(
        code(&o),
        0,
        "floats print their shortest form: {}",
        stderr(&o)
    );
    let o = span_run(
        "gouraud",
        ["0,0,1", "0.6,0,0.8", "0,0,1"],
        "60000",
        &["--scalar", "exact", "--digits", "10000"],
    );
    refused(&o, "MiB");
    let o = span_run(
        "angular",
        ["0,0,1", "0.6,0,0.8", "0,0,1"],
        "4",
        &["--scalar", "exact", "--table-size", "16777216"],
    );
    refused(&o, "--yes");
    let long = format!("0.{},0,1", "1".repeat(100_000));
    let o = span_run("phong", [&long, "0,0,1", "0,0,1"], "2", &["--normalize"]);
    refused(&o, "longer than");
    let d = scratch("d6");
    let out = d.display().to_string();
    refused(
        &run(&[
            "reproduce",
            "--size",
            "4096x4096",
            "--frames",
            "1",
            "--out",
            &out,
        ]),
        "--yes",
    );
    refused(
        &run(&[
            "compare",
            "--size",
            "4096x4096",
            "--frames",
            "1",
            "--out",
            &out,
        ]),
        "--yes",
    );
    assert!(t.elapsed() < Duration::from_secs(60), "refusals are quick");
}

/// Defect d6 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn float_spans_of_any_allowed_length_stream() {
    // 2^22 pixels in f64, 32 MiB of values, run within twice that on top of the base:
    // the JSON is written as it goes (it held about 270 bytes per pixel when the whole
    // text was built first: 4.4 GB at 2^24), and the values are kept as numbers, not
    // as a string each (item 11: 1.06 GB at 2^24, about 8 times the values).
    let (c, e, out) = run_within(
        &[
            "span",
            "--method",
            "corrected-euler",
            "--na",
            "0,0,1",
            "--nb",
            "0.6,0,0.8",
            "--light",
            "0,0,1",
            "--steps",
            "4194304",
            "--scalar",
            "f64",
        ],
        BASE_MIB + 64,
    );
    assert_eq!(c, 0, "{e}");
    let v: Value = serde_json::from_slice(&out).expect("valid JSON");
    assert_eq!(v["values"].as_array().unwrap().len(), 4_194_305);
}

/// Item 13: the not-a-unit message shows the squared length in the number type (not
/// rounded to a float) and how far it is from 1; a bare `phong-approx` is one line.
///
/// Defect r13 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn not_unit_message_and_bare_command() {
    let o = span_run(
        "phong",
        ["0,0,1e-400", "0,0,1", "0,0,1"],
        "2",
        &["--scalar", "exact"],
    );
    refused(
        &o,
        "length² = 1.00000e-800, |length² − 1| = 1.00, exact arithmetic allows only exactly 1",
    );
    let near = format!("0,0,1.{}1", "0".repeat(380));
    let o = span_run(
        "phong",
        [&near, "0,0,1", "0,0,1"],
        "2",
        &["--scalar", "exact"],
    );
    refused(&o, "(length² = 1.00000, |length² − 1| = 2.00e-381,");
    let o = run(&[]);
    refused(&o, "a subcommand is needed");
}

/// Defect r3 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn exact_levels_with_normalize() {
    // (1, 0, 1) everywhere: every value is exactly 1, level 255.
    for m in ["phong", "gouraud", "corrected-euler", "euler", "duff"] {
        let o = span_run(
            m,
            ["1,0,1", "1,0,1", "1,0,1"],
            "1",
            &["--scalar", "exact", "--normalize"],
        );
        assert_eq!(levels_of(&o), vec![Value::from(255); 2], "{m}");
    }
    // Symmetric normals: Phong's middle normal is parallel to L (exactly 1), the
    // ends are 1/√2 (180.3… → 180); Gouraud is 1/√2 throughout.
    let span = |m: &str| {
        span_run(
            m,
            ["1,0,1", "-1,0,1", "0,0,3"],
            "2",
            &["--scalar", "exact", "--normalize"],
        )
    };
    let l = |v: &[u8]| v.iter().map(|&x| Value::from(x)).collect::<Vec<_>>();
    assert_eq!(levels_of(&span("phong")), l(&[180, 255, 180]));
    assert_eq!(levels_of(&span("gouraud")), l(&[180, 180, 180]));
    // The float runs are unchanged: their level is that of the float value.
    let o = span_run(
        "phong",
        ["1,0,1", "1,0,1", "1,0,1"],
        "1",
        &["--scalar", "f64", "--normalize"],
    );
    assert_eq!(code(&o), 0);
}

/// Defect r4 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn angular_digits_are_true_near_plus_and_minus_one() {
    // N_a = (2·10^40, 0, 10^80 − 1)/(10^80 + 1) is exactly unit and 10^-40 from
    // (0, 0, 1); with N_b = (0.6, 0, 0.8), L = (0, 0, 1), n = 2 the middle pixel is
    // cos((θ_a + θ_b)/2) = √((1 + cos(θ_a + θ_b))/2), with cos(θ_a + θ_b) =
    // p_a·p_b − sin θ_a·sin θ_b all rational (sin θ_a = 2·10^40/(10^80 + 1)).
    let big = BigInt::from(10).pow(80u32);
    let den: BigInt = big.clone() + 1;
    let s40: BigInt = BigInt::from(10).pow(40u32) * 2;
    for sign in [1i32, -1] {
        let na = format!(
            "{s}/{den},0,{}{}/{den}",
            if sign < 0 { "-" } else { "" },
            big.clone() - 1,
            s = s40
        );
        let o = span_run(
            "angular",
            [&na, "0.6,0,0.8", "0,0,1"],
            "2",
            &["--scalar", "exact", "--digits", "74"],
        );
        assert_eq!(code(&o), 0, "{}", stderr(&o));
        let v: Value = serde_json::from_slice(&o.stdout).unwrap();
        let got = phong_approx::parse::parse_rational(v["values"][1].as_str().unwrap()).unwrap();
        let q = |n: BigInt, d: BigInt| BigRational::new(n, d);
        let pa = q((big.clone() - 1) * BigInt::from(sign), den.clone());
        let sa = q(s40.clone(), den.clone());
        let c = pa * q(4.into(), 5.into()) - sa * q(3.into(), 5.into());
        let want = BigRational::from_integer(sign.into())
            * sqrt_to(
                &((BigRational::from_integer(1.into()) + c) / BigRational::from_integer(2.into())),
                400,
            );
        let tol = q(1.into(), BigInt::from(10).pow(74u32));
        assert!(
            (got.clone() - want.clone()).abs() < tol,
            "sign {sign}: got {} want {}",
            v["values"][1],
            want.to_string().len()
        );
    }
}

/// Defect r12 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn nearly_equal_normals_get_the_precision_they_need() {
    for m in ["spherical", "binary", "bishop-weimer"] {
        let o = run(&[
            "span",
            "--method",
            m,
            "--na",
            "0,0,1",
            "--nb",
            "1e-20,0,1",
            "--normalize",
            "--light",
            "0.6,0,0.8",
            "--steps",
            "2",
            "--scalar",
            "exact",
        ]);
        assert_eq!(code(&o), 0, "{m}: {}", stderr(&o));
        // Every pixel is within 10^-25 of Phong's (the normals are 10^-20 apart:
        // all these methods agree with Phong to second order, about 10^-40).
        let v: Value = serde_json::from_slice(&o.stdout).unwrap();
        let p: Value = serde_json::from_slice(
            &run(&[
                "span",
                "--method",
                "phong",
                "--na",
                "0,0,1",
                "--nb",
                "1e-20,0,1",
                "--normalize",
                "--light",
                "0.6,0,0.8",
                "--steps",
                "2",
                "--scalar",
                "exact",
            ])
            .stdout,
        )
        .unwrap();
        for i in 0..3 {
            let a = phong_approx::parse::parse_rational(v["values"][i].as_str().unwrap()).unwrap();
            let b = phong_approx::parse::parse_rational(p["values"][i].as_str().unwrap()).unwrap();
            assert!(
                (a - b).abs() < BigRational::new(1.into(), BigInt::from(10).pow(25u32)),
                "{m} {i}"
            );
        }
    }
}

/// Defect q1 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn spherical_keeps_every_digit_at_high_precision() {
    // Pixel 4 is N_b·L = 3/5·2/3 + 4/5·2/3 = 14/15 exactly; the recurrence rounded
    // each step to 2^-320 whatever the digits asked, and printed false digits.
    let v = span_values(&[
        "--method",
        "spherical",
        "--na",
        "0,0,1",
        "--nb",
        "3/5,0,4/5",
        "--light",
        "2/3,1/3,2/3",
        "--steps",
        "4",
        "--scalar",
        "exact",
        "--digits",
        "110",
    ]);
    assert_eq!(
        v[4],
        format!("0.{}", "3".repeat(109)).replacen("0.3", "0.93", 1)
    );
}

/// Defect q2 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn a_rounded_tiny_value_is_not_printed_as_zero() {
    // The middle angle is π/2 − 3h/(2√5) with h = (2/3)·10^-100: its cosine is
    // 10^-100/√5 (to 10^-200 relative) = √(1/5)·10^-100.
    let v = span_values(&[
        "--method",
        "angular",
        "--na",
        "0,0,1",
        "--nb",
        "1e-100,0,-1",
        "--light",
        "2/3,1/3,2/3",
        "--steps",
        "2",
        "--scalar",
        "exact",
        "--normalize",
    ]);
    let want = sqrt_digits(&BigInt::from(1), &BigInt::from(5), 40, 25);
    let got: String = v[1].chars().filter(char::is_ascii_digit).take(26).collect();
    assert!(v[1].ends_with("e-101"), "{}", v[1]);
    assert_eq!(&got[..25], want, "{}", v[1]);
    // A value that is exactly zero still prints as 0 (p_a = 0 at an end pixel).
    let v = span_values(&[
        "--method",
        "angular",
        "--na",
        "0,0,1",
        "--nb",
        "3/5,0,4/5",
        "--light",
        "1,0,0",
        "--steps",
        "2",
        "--scalar",
        "exact",
    ]);
    assert_eq!(v[0], "0");
}

/// Defect q4 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn phong_has_no_reference_bound_where_its_normals_nearly_cancel() {
    use phong_approx::tolerance::bound;
    use phong_approx::Method;
    let u = f64::from(f32::EPSILON) / 2.0;
    // Normals 10^-7 from opposite: q_min ≈ 2.5·10^-15, far below (250u)².
    assert_eq!(bound(Method::Phong, 2, 2.5e-15, u), None);
    assert!(bound(Method::Phong, 2, 0.5, u).is_some());
    // The span of the report: N_b 2·10^-7 from opposite, exactly unit; span printed a
    // reference bound of 5.97 there.
    let o = span_run(
        "phong",
        [
            "0,0,1",
            "20000000/100000000000001,0,-99999999999999/100000000000001",
            "2/3,1/3,2/3",
        ],
        "2",
        &["--scalar", "f32"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let j: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(j["error_bound"]["reference"].is_null(), "{j}");
}

/// Defect q8 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn square_roots_of_tiny_rationals_never_divide_by_zero() {
    for args in [
        ["binary", "1e-60,0,-1", "2"],
        ["phong", "1e-90,1e-90,-1", "2"],
        ["duff", "1e-90,1e-90,-1", "2"],
        ["binary", "1e-90,1e-90,-1", "2"],
        ["spherical", "1e-90,0,1", "2"],
        ["bishop-weimer", "1e-280,0,-1", "3"],
    ] {
        let o = span_run(
            args[0],
            ["0,0,1", args[1], "2/3,1/3,2/3"],
            args[2],
            &["--scalar", "exact", "--normalize"],
        );
        let e = stderr(&o);
        assert!(!e.contains("panicked"), "{args:?}: {e}");
        assert!(code(&o) == 0 || code(&o) == 2, "{args:?}: {e}");
    }
    // √(10^-200) is 10^-100, not 0.
    let s = phong_approx::reference::transcendental::sqrt(&BigRational::new(
        2.into(),
        BigInt::from(10).pow(200u32),
    ));
    assert!(s > BigRational::new(1.into(), BigInt::from(10).pow(101u32)));
}

/// Defect q10 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn a_huge_cosine_table_is_within_the_budget() {
    use phong_approx::budget::{exact_work, MAX_RECOMPUTED_WORK};
    use phong_approx::Method;
    assert!(exact_work(Method::AngularTable(16_777_216), 1, 10, 30) > MAX_RECOMPUTED_WORK);
    assert!(exact_work(Method::AngularTable(256), 1, 10, 30) < MAX_RECOMPUTED_WORK / 100);
}

/// Defect d13 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn span_minor_options_are_checked() {
    bad(
        &[("--method", "adaptive"), ("--precision", "64")],
        "--precision",
    );
    bad(&[("--kd", "-1")], "--kd");
    bad(&[("--kd", "1e309")], "--kd");
}

/// Defect q15 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn span_messages_say_what_is_wrong() {
    bad(
        &[("--digits", "-1")],
        "--digits: '-1' is not a whole number",
    );
    // A closed standard output (`>&-`) is an error, not silence; `> /dev/null` is not.
    let sh = |redirect: &str| {
        std::process::Command::new("sh")
            .arg("-c")
            .arg(format!(
                "'{}' span --method gouraud --na 0,0,1 --nb 0,0,1 --light 0,0,1 --steps 2 {redirect}",
                env!("CARGO_BIN_EXE_phong-approx")
            ))
            .output()
            .unwrap()
    };
    refused(&sh(">&-"), "standard output is closed");
    assert_eq!(code(&sh(">/dev/null")), 0);
}

/// Nb = −Na where a method is not defined: the related methods refuse (no unique arc,
/// no bisector, a zero normal at the expansion point); a Phong-valued method refuses
/// only the pixel where the normal is zero, naming it. (Where they are defined:
/// `cli::opposite_normals_are_computed_where_defined`.)
#[test]
fn opposite_normals_are_refused_where_undefined() {
    let opposite = |method: &'static str, steps: &'static str| {
        [
            ("--method", method),
            ("--na", "0,0,1"),
            ("--nb", "0,0,-1"),
            ("--light", "0,0,1"),
            ("--steps", steps),
            ("--scalar", "exact"),
        ]
    };
    for m in ["spherical", "binary", "bishop-weimer"] {
        bad(&opposite(m, "5"), "opposite");
    }
    bad(&opposite("phong", "4"), "pixel 2 of n = 4");
}

// ------------------------------------------------ exact decisions at finite precision

/// A light whose table position is 1.6·10⁻⁸¹ above the midpoint 100.5 (L_z the cosine
/// of that angle to about 10⁻⁹⁰, a rational point of the unit circle; made and checked
/// with mpmath at 400 digits): the exact index ⌊pos + ½⌋ is 101.
const LIGHT_ABOVE_100_5: &str = "6253525788149510366527448862879897692713546792874329916477589382934432517664330818354000000000000000000000000000000000000000000000000000000000000000000000000000000000000/10776646195762738702331955074360151109430211517870561624579277255389710656848629240478015769004590925414459006719811226627100156022128991139745540331932867562723835817329,0,8776646195762738702331955074360151109430211517870561624579277255389710656848629240478015769004590925414459006719811226627100156022128991139745540331932867562723835817329/10776646195762738702331955074360151109430211517870561624579277255389710656848629240478015769004590925414459006719811226627100156022128991139745540331932867562723835817329";

/// N_b = (x, 0, 1) with x rational such that, for the normalized inputs with N_a = L =
/// (0, 0, 1) and n = 2, 255|δ| = 255x²/(8(1 + x²)) = 1 + 1.8·10⁻⁸⁵ exactly (δ =
/// −(1 − w²)/8, w = 1/√(1 + x²), from eq. 24 at j = 1): the exact choice is corrected
/// Euler.
const NB_JUST_OVER_THE_THRESHOLD: &str = "17996850826633901960628631372210289870565388152307933026935743145888333598798103564469/100000000000000000000000000000000000000000000000000000000000000000000000000000000000000,0,1";

/// Finding 1 of the fifth reliability round: the tabled cosine's index decided exactly.
#[test]
fn the_table_index_is_decided_exactly_near_a_midpoint() {
    let o = span_run(
        "angular-table256",
        ["0,0,1", "0,0,1", LIGHT_ABOVE_100_5],
        "1",
        &["--scalar", "exact"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    // cos(101π/510) by mpmath; entry 100 would be 0.816196912356221690871852540431.
    assert_eq!(v["values"][0], "0.812622370966445628419638151755");
    assert_eq!(v["levels"][0], 207);
    // An exact tie: N_a = (1, 0, 1)/√2, L = z: α_a = π/4, position 127.5 exactly, so
    // ⌊128⌋ = 128 (cos(128π/510) by mpmath), whatever the square roots' accuracy.
    let o = span_run(
        "angular-table256",
        ["1,0,1", "0,0,1", "0,0,1"],
        "2",
        &["--scalar", "exact", "--normalize"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["values"][0], "0.704925546906147157479095692187");
    assert_eq!(v["values"][1], "0.923289106105489354018447523133");
    // An exact tie between edge angles that are no rational multiples of π (edge-008):
    // acos(3/5) + acos(4/5) = π/2, so pixel 8 of 16 is at π/4, position 127.5, decided
    // in rationals (z_a^1020·z_b^1020 = 1), entry 128.
    let o = span_run(
        "angular-table256",
        ["0,0,1", "1,0,0", "4/5,0,3/5"],
        "16",
        &["--scalar", "exact"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["values"][8], "0.704925546906147157479095692187");
}

/// The same with 255|δ| = 1 − 2.5·10⁻⁸⁵: the exact choice is Gouraud (the square roots
/// to 2^-256 picked corrected Euler here before).
const NB_JUST_UNDER_THE_THRESHOLD: &str = "3599370165326780392125726274442057974113077630461586605387148629177666719759620712893/20000000000000000000000000000000000000000000000000000000000000000000000000000000000000,0,1";

/// Finding 2 of the fifth reliability round: the adaptive test with --normalize decided
/// exactly.
#[test]
fn the_adaptive_test_with_normalize_is_decided_exactly() {
    let o = span_run(
        "adaptive",
        ["0,0,1", NB_JUST_OVER_THE_THRESHOLD, "0,0,1"],
        "2",
        &["--scalar", "exact", "--normalize"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["decision"], "corrected-euler");
    // Corrected Euler's middle pixel (1 + w)/2 + (1 − w²)/8, by mpmath at 60 digits
    // (Gouraud's would be 0.992094363659144179000903558205).
    assert_eq!(v["values"][1], "0.996015932286595159393060420950");
    let o = span_run(
        "adaptive",
        ["0,0,1", NB_JUST_UNDER_THE_THRESHOLD, "0,0,1"],
        "2",
        &["--scalar", "exact", "--normalize"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["decision"], "gouraud");
    // Gouraud's middle pixel (1 + w)/2, by mpmath at 60 digits.
    assert_eq!(v["values"][1], "0.992094363659144179000903558205");
}

/// Finding 8 of the fifth reliability round: fractions only for rational values, and a
/// vector that underflows is not called zero.
#[test]
fn normalize_prints_no_fractions_and_underflow_is_named() {
    let o = span_run(
        "gouraud",
        ["1,0,1", "0,0,1", "0,0,1"],
        "2",
        &["--scalar", "exact", "--normalize"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v.get("fractions").is_none(), "{v}");
    let o = span_run(
        "gouraud",
        ["0,0,1", "0.6,0,0.8", "0,0,1"],
        "2",
        &["--scalar", "exact"],
    );
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["fractions"][1], "9/10", "{v}");
    let o = span_run(
        "gouraud",
        ["1e-300,0,1e-300", "0,0,1", "0,0,1"],
        "2",
        &["--scalar", "f32", "--normalize"],
    );
    refused(&o, "underflows to 0 in f32");
    assert!(!stderr(&o).contains("is zero"), "{}", stderr(&o));
    let o = span_run(
        "gouraud",
        ["1e-300,0,1e-300", "0,0,1", "0,0,1"],
        "2",
        &["--scalar", "f64", "--normalize"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
}

/// Finding 8 of the fifth reliability round: a vector path asked for and not taken is
/// refused, not ignored.
#[test]
fn an_unknown_or_missing_vector_path_is_refused() {
    let o = bin()
        .env("PHONG_APPROX_SIMD", "sse9")
        .args([
            "span", "--method", "gouraud", "--na", "0,0,1", "--nb", "0,0,1", "--light", "0,0,1",
            "--steps", "1",
        ])
        .output()
        .unwrap();
    refused(&o, "PHONG_APPROX_SIMD: unknown vector path 'sse9'");
    for p in phong_approx::simd::Path::ALL {
        let o = bin()
            .env("PHONG_APPROX_SIMD", p.name())
            .args([
                "span", "--method", "gouraud", "--na", "0,0,1", "--nb", "0,0,1", "--light",
                "0,0,1", "--steps", "1",
            ])
            .output()
            .unwrap();
        if p.supported() {
            assert_eq!(code(&o), 0, "{p}: {}", stderr(&o));
        } else {
            refused(&o, "this CPU cannot take");
        }
    }
}

/// Finding 8 of the fifth reliability round: a table over the exact-work budget names
/// the table, not the steps.
#[test]
fn a_table_over_the_budget_names_the_table() {
    let o = span_run(
        "angular-table60000",
        ["0,0,1", "0.6,0,0.8", "0,0,1"],
        "2",
        &["--scalar", "exact", "--digits", "600"],
    );
    refused(&o, "a table of 60000 exact cosines");
    assert!(!stderr(&o).contains("--steps"), "{}", stderr(&o));
}

/// Findings 1 and 2 of the fifth reliability round in MPFR: a decision its rounding
/// cannot make is refused (naming the exact run), never printed with false digits; with
/// enough bits the table's entry is the exact one.
#[cfg(feature = "mpfr")]
#[test]
fn mpfr_refuses_decisions_its_rounding_cannot_make() {
    let o = span_run(
        "angular-table256",
        ["0,0,1", "0,0,1", LIGHT_ABOVE_100_5],
        "1",
        &["--scalar", "mpfr"],
    );
    refused(&o, "the cosine table's entry at pixel 0 is not decided");
    let o = span_run(
        "angular-table256",
        ["0,0,1", "0,0,1", LIGHT_ABOVE_100_5],
        "1",
        &["--scalar", "mpfr", "--precision", "400"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["values"][0], "0.812622370966445628419638151755");
    let o = span_run(
        "adaptive",
        ["0,0,1", NB_JUST_OVER_THE_THRESHOLD, "0,0,1"],
        "2",
        &["--scalar", "mpfr", "--normalize"],
    );
    let e = stderr(&o);
    // MPFR's δ at 256 bits lands on either side: refused, or the exact choice.
    if code(&o) == 0 {
        let v: Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(v["decision"], "corrected-euler");
    } else {
        refused(&o, "where the exact test picks corrected-euler");
        assert!(e.contains("picks gouraud"), "{e}");
    }
}
