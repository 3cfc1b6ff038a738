//! Reliability: every defect found by trying the tool as a careless user and as an
//! attacker would has a test here that reproduces it, and now passes. Numbers refer
//! to the list in docs/conformance.md, "Limits and exit codes".

use crate::runner;
use runner::{bin, code, refused, run, stderr};

use num_bigint::BigInt;
use num_traits::{Pow, Signed};
use phong_approx::BigRational;
use serde_json::Value;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Output, Stdio};
use std::time::{Duration, Instant};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A fresh folder for one test.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("phong-approx-rel-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn typical() -> Value {
    let text = std::fs::read_to_string(root().join("vectors/typical.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The exact expected corrected-Euler values of `v` as a results CSV.
fn results_csv(v: &Value) -> String {
    let mut s = String::from("case,pixel,value\n");
    for c in v["cases"].as_array().unwrap() {
        let id = c["id"].as_str().unwrap();
        for (i, x) in c["expected"]["corrected-euler"]["values"]
            .as_array()
            .unwrap()
            .iter()
            .enumerate()
        {
            s.push_str(&format!("{id},{i},{}\n", x.as_str().unwrap()));
        }
    }
    s
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

/// `check` on an edited copy of the typical vectors, with their own exact results.
fn check_edited(name: &str, edit: impl Fn(&mut Value), extra: &[&str]) -> Output {
    let d = scratch(name);
    let mut v = typical();
    let results = write(&d, "r.csv", &results_csv(&v));
    edit(&mut v);
    let vectors = write(&d, "v.json", &serde_json::to_string_pretty(&v).unwrap());
    let mut args = vec!["check", "--vectors", &vectors, "--results", &results];
    args.extend_from_slice(extra);
    run(&args)
}

const ALLOW: &[&str] = &["--allow-modified-vectors"];

#[test]
fn d1_published_vectors_pass_and_modified_ones_are_refused() {
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

/// `csv` with the value of `id`'s pixel `pixel` replaced by `value`.
fn perturbed(csv: &str, id: &str, pixel: usize, value: &str) -> String {
    let row = format!("{id},{pixel},");
    csv.lines()
        .map(|l| {
            if l.starts_with(&row) {
                format!("{row}{value}\n")
            } else {
                format!("{l}\n")
            }
        })
        .collect()
}

#[test]
fn d1_truncated_or_edited_expectations_cannot_make_garbage_pass() {
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

#[test]
fn d1_absurd_n_is_refused_without_allocating() {
    for n in [4_294_967_295u64, 400_000_000] {
        let t = Instant::now();
        let o = check_edited("d1-n", |v| v["cases"][0]["n"] = n.into(), ALLOW);
        refused(&o, "n = ");
        assert!(t.elapsed() < Duration::from_secs(30));
    }
}

#[test]
fn d1_ids_counts_and_versions_are_checked() {
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

/// Runs `bin args` with a time limit; `None` if it had to be killed.
fn run_limited(args: &[&str], limit: Duration) -> Option<Output> {
    let mut child = bin()
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    loop {
        if child.try_wait().unwrap().is_some() {
            return Some(child.wait_with_output().unwrap());
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn d2_devices_and_fifos_are_capped() {
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

#[test]
fn d3_non_finite_values_are_errors_naming_the_pixel() {
    let o = run(&[
        "span",
        "--method",
        "duff",
        "--na",
        "0,0,1",
        "--nb",
        "1e-30,0,-1",
        "--light",
        "0.6,0,0.8",
        "--steps",
        "2",
        "--normalize",
    ]);
    refused(&o, "pixel 1 of n = 2");
    let o = run(&[
        "span",
        "--method",
        "duff",
        "--na",
        "0,0,1",
        "--nb",
        "3e-4,0,-1",
        "--light",
        "0.6,0,0.8",
        "--steps",
        "2",
        "--normalize",
        "--scalar",
        "f32",
    ]);
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

#[test]
fn d4_exact_normalize_takes_any_nonzero_finite_input() {
    for (na, scalar) in [
        ("1e-100,0,1e-100", "exact"),
        ("1e-9,2e-9,3e-9", "exact"),
        ("1e308,0,1", "f64"),
    ] {
        let o = run(&[
            "span",
            "--method",
            "gouraud",
            "--na",
            na,
            "--nb",
            "0,0,1",
            "--light",
            "0,0,1",
            "--steps",
            "2",
            "--normalize",
            "--scalar",
            scalar,
        ]);
        assert_eq!(code(&o), 0, "{na} {scalar}: {}", stderr(&o));
    }
}

#[test]
fn d5_no_digit_is_printed_that_is_not_known() {
    let o = run(&[
        "span",
        "--method",
        "phong",
        "--na",
        "0,0,1",
        "--nb",
        "0.6,0,0.8",
        "--light",
        "0.28,0.96,0",
        "--steps",
        "3",
        "--scalar",
        "exact",
        "--digits",
        "200",
    ]);
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
    let o = run(&[
        "span",
        "--method",
        "phong",
        "--na",
        "0,0,1",
        "--nb",
        "0.6,0,0.8",
        "--light",
        "0.28,0.96,0",
        "--steps",
        "3",
        "--scalar",
        "exact",
        "--digits",
        "10000",
    ]);
    refused(&o, "at most 2446 significant digits");
    assert!(t.elapsed() < Duration::from_secs(5));
    // Rational methods are exact: any number of digits.
    let o = run(&[
        "span",
        "--method",
        "corrected-euler",
        "--na",
        "0,0,1",
        "--nb",
        "0.6,0,0.8",
        "--light",
        "0.28,0.96,0",
        "--steps",
        "3",
        "--scalar",
        "exact",
        "--digits",
        "200",
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
}

#[test]
fn d6_work_beyond_the_budget_needs_yes() {
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
    let o = run(&[
        "span",
        "--method",
        "gouraud",
        "--na",
        "0,0,1",
        "--nb",
        "0.6,0,0.8",
        "--light",
        "0,0,1",
        "--steps",
        "1000000",
        "--scalar",
        "f64",
        "--digits",
        "10000",
    ]);
    assert_eq!(
        code(&o),
        0,
        "floats print their shortest form: {}",
        stderr(&o)
    );
    let o = run(&[
        "span",
        "--method",
        "gouraud",
        "--na",
        "0,0,1",
        "--nb",
        "0.6,0,0.8",
        "--light",
        "0,0,1",
        "--steps",
        "60000",
        "--scalar",
        "exact",
        "--digits",
        "10000",
    ]);
    refused(&o, "MiB");
    let o = run(&[
        "span",
        "--method",
        "angular",
        "--na",
        "0,0,1",
        "--nb",
        "0.6,0,0.8",
        "--light",
        "0,0,1",
        "--steps",
        "4",
        "--scalar",
        "exact",
        "--table-size",
        "16777216",
    ]);
    refused(&o, "--yes");
    let long = format!("0.{},0,1", "1".repeat(100_000));
    let o = run(&[
        "span",
        "--method",
        "phong",
        "--na",
        &long,
        "--nb",
        "0,0,1",
        "--light",
        "0,0,1",
        "--steps",
        "2",
        "--normalize",
    ]);
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

#[test]
fn d6_float_spans_of_any_allowed_length_stream() {
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

#[test]
fn d7_outputs_never_replace_a_users_file_or_follow_a_link() {
    let d = scratch("d7");
    let out = d.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("tables.md"), "mine").unwrap();
    std::fs::write(out.join(".write-test"), "mine too").unwrap();
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        out.to_str().unwrap(),
    ]);
    refused(&o, "was not written by phong-approx");
    assert_eq!(
        std::fs::read_to_string(out.join("tables.md")).unwrap(),
        "mine"
    );
    assert_eq!(
        std::fs::read_to_string(out.join(".write-test")).unwrap(),
        "mine too"
    );
    // With --force it writes, and then may write again.
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        out.to_str().unwrap(),
        "--force",
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    // A symbolic link among the outputs is not written through.
    let target = d.join("precious.csv");
    std::fs::write(&target, "precious").unwrap();
    std::fs::remove_file(out.join("table1.csv")).unwrap();
    std::os::unix::fs::symlink(&target, out.join("table1.csv")).unwrap();
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        out.to_str().unwrap(),
        "--force",
    ]);
    refused(&o, "symbolic link");
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "precious");
    // No temporary file is left behind by a refused run.
    let leftovers: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains(".partial-"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
    // vectors: the CSV twins of my.json are the user's.
    std::fs::write(d.join("my.csv"), "mine").unwrap();
    let my = d.join("my.json");
    let o = run(&["vectors", "--set", "paper", "--out", my.to_str().unwrap()]);
    refused(&o, "my.csv");
    assert_eq!(std::fs::read_to_string(d.join("my.csv")).unwrap(), "mine");
    assert!(!my.exists(), "nothing is written when one name is refused");
}

#[test]
fn d8_closed_pipe_and_full_disk_keep_the_exit_code_contract() {
    let mut child = bin()
        .args([
            "span",
            "--method",
            "phong",
            "--na",
            "0,0,1",
            "--nb",
            "0.6,0,0.8",
            "--light",
            "0,0,1",
            "--steps",
            "200000",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut head = [0u8; 10];
    child.stdout.take().unwrap().read_exact(&mut head).unwrap();
    // The reader is gone (its end of the pipe was dropped with it).
    let o = child.wait_with_output().unwrap();
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(!stderr(&o).contains("panicked"));
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let v = root().join("vectors/typical.json").display().to_string();
    let d = scratch("d8");
    let r = write(&d, "r.csv", &results_csv(&typical()));
    let o = bin()
        .args(["check", "--vectors", &v, "--results", &r])
        .stdout(full)
        .output()
        .unwrap();
    refused(&o, "No space left");
}

#[test]
fn d9_levels_tolerance_does_not_pass_absurd_values() {
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
    ]);
    assert_eq!(code(&o), 1, "{}", stderr(&o));
}

#[test]
fn d10_a_scene_with_no_visible_pixel_exits_2() {
    let d = scratch("d10");
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--radii",
        "1e-30,1e-31",
        "--out",
        d.to_str().unwrap(),
    ]);
    refused(&o, "no visible pixel");
}

#[test]
fn d11_echoed_input_is_cut_and_escaped() {
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

#[test]
fn d12_csv_with_a_bom_and_quotes_is_read() {
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

#[test]
fn d13_minor_options_are_checked() {
    let span = |extra: &[&str]| {
        let mut a = vec![
            "span",
            "--method",
            "adaptive",
            "--na",
            "0,0,1",
            "--nb",
            "0.6,0,0.8",
            "--light",
            "0,0,1",
            "--steps",
            "4",
        ];
        a.extend_from_slice(extra);
        run(&a)
    };
    refused(&span(&["--precision", "64"]), "--precision");
    refused(&span(&["--kd", "-1"]), "--kd");
    refused(&span(&["--kd", "1e309"]), "--kd");
    let t = Instant::now();
    let o = run(&["vectors", "--out", "/proc/phong-approx-test"]);
    assert_eq!(code(&o), 2);
    assert!(
        t.elapsed() < Duration::from_secs(3),
        "fails before computing"
    );
}

/// The width and height of a PNG file.
fn png_size(p: &Path) -> (u32, u32) {
    let b = std::fs::read(p).unwrap();
    let be = |i: usize| u32::from_be_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
    (be(16), be(20))
}

#[test]
fn d13_pictures_follow_size() {
    let d = scratch("d13");
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "150x100",
        "--out",
        d.to_str().unwrap(),
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    // Scaled by a whole factor to at least 400 pixels on the shorter side.
    assert_eq!(
        png_size(&d.join("fig4_torus800_corrected_euler.png")),
        (600, 400)
    );
}

// ---------------------------------------------------------------------------------
// Third round (the hostile-input run): each test reproduces one finding.

/// Item 8: writing to a standard error that cannot take it never panics (exit 2, not
/// 101); `--help` and `--version` to a full disk exit 2.
#[test]
fn r8_stderr_and_stdout_failures_keep_the_exit_code_contract() {
    let full = || {
        std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap()
    };
    // A bad request whose one line cannot be written.
    let o = bin()
        .args(["span", "--method", "nope"])
        .stderr(full())
        .output()
        .unwrap();
    assert_eq!(code(&o), 2);
    let o = bin()
        .args(["span", "--bogus"])
        .stderr(full())
        .output()
        .unwrap();
    assert_eq!(code(&o), 2);
    for args in [&["span", "--help"][..], &["--version"], &["--help"]] {
        let o = bin().args(args).stdout(full()).output().unwrap();
        assert_eq!(code(&o), 2, "{args:?}");
        assert!(stderr(&o).contains("standard output"), "{args:?}");
        // And to a pipe that stays open, exit 0.
        let o = run(args);
        assert_eq!(code(&o), 0, "{args:?}");
    }
    // stderr is a closed pipe.
    let mut child = bin()
        .args(["span", "--method", "nope"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stderr.take());
    assert_eq!(child.wait().unwrap().code(), Some(2));
}

/// Item 13: the not-a-unit message shows the squared length in the number type (not
/// rounded to a float) and how far it is from 1; a bare `phong-approx` is one line.
#[test]
fn r13_not_unit_message_and_bare_command() {
    let o = run(&[
        "span",
        "--method",
        "phong",
        "--na",
        "0,0,1e-400",
        "--nb",
        "0,0,1",
        "--light",
        "0,0,1",
        "--steps",
        "2",
        "--scalar",
        "exact",
    ]);
    refused(
        &o,
        "length² = 1.00000e-800, |length² − 1| = 1.00, exact arithmetic allows only exactly 1",
    );
    let near = format!("0,0,1.{}1", "0".repeat(380));
    let o = run(&[
        "span", "--method", "phong", "--na", &near, "--nb", "0,0,1", "--light", "0,0,1", "--steps",
        "2", "--scalar", "exact",
    ]);
    refused(&o, "(length² = 1.00000, |length² − 1| = 2.00e-381,");
    let o = run(&[]);
    refused(&o, "a subcommand is needed");
}

/// A quick `reproduce` into `out` (small images, one frame).
fn quick_reproduce(out: &Path, extra: &[&str]) -> Output {
    let mut args = vec![
        "reproduce",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    run(&args)
}

/// Item 5: an `--out` folder that is a symbolic link is refused (nothing is written
/// into the folder it points to), by `reproduce`, `compare` and `vectors`.
#[test]
fn r5_an_out_folder_that_is_a_symlink_is_refused() {
    let d = scratch("r5");
    let real = d.join("real");
    std::fs::create_dir_all(&real).unwrap();
    let link = d.join("link");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let o = quick_reproduce(&link, &[]);
    refused(&o, "symbolic link");
    let o = run(&[
        "compare",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        link.to_str().unwrap(),
    ]);
    refused(&o, "symbolic link");
    let o = run(&["vectors", "--out", link.to_str().unwrap()]);
    refused(&o, "symbolic link");
    assert_eq!(std::fs::read_dir(&real).unwrap().count(), 0);
}

/// Item 7: a commit that was killed during its renames (its journal left behind) is
/// completed by the next run in the folder, stale temporary files of dead runs are
/// removed, and a manifest that is a folder is refused before any output is written.
#[test]
fn r7_interrupted_commits_are_completed_and_stale_temporaries_removed() {
    let d = scratch("r7");
    let out = d.join("out");
    std::fs::create_dir_all(&out).unwrap();
    // As a run killed between two renames leaves it: one temporary not yet renamed,
    // listed in the journal. (PID 4294967295 is no process.)
    std::fs::write(out.join(".partial-4294967295-1.extra.txt"), "NEW").unwrap();
    std::fs::write(
        out.join(".phong-approx-commit"),
        ".partial-4294967295-1.extra.txt\textra.txt\n",
    )
    .unwrap();
    std::fs::write(out.join(".partial-4294967295-2.table1.csv"), "stale").unwrap();
    let o = quick_reproduce(&out, &[]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert_eq!(
        std::fs::read_to_string(out.join("extra.txt")).unwrap(),
        "NEW"
    );
    assert!(!out.join(".phong-approx-commit").exists());
    let manifest = std::fs::read_to_string(out.join(".phong-approx-written")).unwrap();
    assert!(manifest.lines().any(|l| l == "extra.txt"), "{manifest}");
    let partials: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().starts_with(".partial-"))
        .collect();
    assert!(partials.is_empty(), "{partials:?}");
    // A manifest that is a folder: refused before anything is written.
    let out2 = d.join("out2");
    std::fs::create_dir_all(out2.join(".phong-approx-written")).unwrap();
    let o = quick_reproduce(&out2, &[]);
    refused(&o, "not a regular file");
    assert_eq!(std::fs::read_dir(&out2).unwrap().count(), 1);
}

/// Runs `bin args` with its address space limited to `limit_mib` MiB
/// (`RLIMIT_AS`, set in the child before it execs, so the limit covers only the
/// program: a peak measured with `wait4` would include this test process's own
/// memory, inherited at the fork). Returns the exit code (−1 if killed by a signal,
/// as an allocation failure aborts), stderr and stdout.
fn run_within(args: &[&str], limit_mib: u64) -> (i32, String, Vec<u8>) {
    use std::os::unix::process::CommandExt;
    let limit = limit_mib << 20;
    let mut cmd = bin();
    cmd.args(args);
    // SAFETY: setrlimit is async-signal-safe, and the closure touches nothing else.
    unsafe {
        cmd.pre_exec(move || {
            let r = libc::rlimit {
                rlim_cur: limit,
                rlim_max: limit,
            };
            if libc::setrlimit(libc::RLIMIT_AS, &r) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let o = cmd.output().unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stderr).into_owned(),
        o.stdout,
    )
}

/// The address space every run below is allowed on top of what its input needs:
/// the program, its libraries and allocator reserves (the published typical set's
/// own check runs within 40 MiB).
const BASE_MIB: u64 = 32;

#[test]
fn r2_check_memory_is_bounded_by_the_vector_file() {
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

fn levels_of(o: &Output) -> Vec<Value> {
    assert_eq!(code(o), 0, "{}", stderr(o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    v["levels"].as_array().unwrap().clone()
}

#[test]
fn r3_exact_levels_with_normalize() {
    // (1, 0, 1) everywhere: every value is exactly 1, level 255.
    for m in ["phong", "gouraud", "corrected-euler", "euler", "duff"] {
        let o = run(&[
            "span",
            "--method",
            m,
            "--na",
            "1,0,1",
            "--nb",
            "1,0,1",
            "--light",
            "1,0,1",
            "--steps",
            "1",
            "--scalar",
            "exact",
            "--normalize",
        ]);
        assert_eq!(levels_of(&o), vec![Value::from(255); 2], "{m}");
    }
    // Symmetric normals: Phong's middle normal is parallel to L (exactly 1), the
    // ends are 1/√2 (180.3… → 180); Gouraud is 1/√2 throughout.
    let span = |m: &str| {
        run(&[
            "span",
            "--method",
            m,
            "--na",
            "1,0,1",
            "--nb",
            "-1,0,1",
            "--light",
            "0,0,3",
            "--steps",
            "2",
            "--scalar",
            "exact",
            "--normalize",
        ])
    };
    let l = |v: &[u8]| v.iter().map(|&x| Value::from(x)).collect::<Vec<_>>();
    assert_eq!(levels_of(&span("phong")), l(&[180, 255, 180]));
    assert_eq!(levels_of(&span("gouraud")), l(&[180, 180, 180]));
    // The float runs are unchanged: their level is that of the float value.
    let o = run(&[
        "span",
        "--method",
        "phong",
        "--na",
        "1,0,1",
        "--nb",
        "1,0,1",
        "--light",
        "1,0,1",
        "--steps",
        "1",
        "--scalar",
        "f64",
        "--normalize",
    ]);
    assert_eq!(code(&o), 0);
}

/// `√x` of a positive rational to `2^-bits`, independently of the crate (integer
/// square root of `x·4^bits`).
fn sqrt_to(x: &BigRational, bits: usize) -> BigRational {
    let scaled = (x.numer() << (2 * bits)) / x.denom();
    BigRational::new(scaled.sqrt(), BigInt::from(1) << bits)
}

#[test]
fn r4_angular_digits_are_true_near_plus_and_minus_one() {
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
        let o = run(&[
            "span",
            "--method",
            "angular",
            "--na",
            &na,
            "--nb",
            "0.6,0,0.8",
            "--light",
            "0,0,1",
            "--steps",
            "2",
            "--scalar",
            "exact",
            "--digits",
            "74",
        ]);
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

#[test]
fn r6_modified_vectors_supply_cases_not_truth() {
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

#[test]
fn r9_exact_work_is_budgeted_by_method_and_input_size() {
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
        let o = run(&[
            "span",
            "--method",
            m,
            "--na",
            na,
            "--nb",
            "0.6,0,0.8",
            "--light",
            "0,0,1",
            "--steps",
            "65536",
            "--scalar",
            "exact",
        ]);
        refused(&o, "pass --yes");
        assert!(t.elapsed() < Duration::from_secs(5), "{m}");
    }
}

#[test]
fn r12_nearly_equal_normals_get_the_precision_they_need() {
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

// ---------------------------------------------------------------------------------
// Fourth round (issue 32): each test reproduces a defect of that round's list (the
// number in its name), fails on the code before the fix, and passes now.
// ---------------------------------------------------------------------------------

/// `span`'s JSON values for `args` (exit 0 asserted).
fn span_values(args: &[&str]) -> Vec<String> {
    let mut all = vec!["span"];
    all.extend_from_slice(args);
    let o = run(&all);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    v["values"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().unwrap().to_string())
        .collect()
}

/// The first `digits` significant decimal digits of `√(num/den)·10^shift` (an
/// independent computation: integer square roots only), as a string of digits.
fn sqrt_digits(num: &BigInt, den: &BigInt, shift: u32, digits: usize) -> String {
    let scale = BigInt::from(10).pow(2 * shift);
    let r = (num * &scale / den).sqrt();
    r.to_string().chars().take(digits).collect()
}

#[test]
fn q1_spherical_keeps_every_digit_at_high_precision() {
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

#[test]
fn q2_a_rounded_tiny_value_is_not_printed_as_zero() {
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

#[test]
fn q3_check_recomputes_nearly_opposite_normals_to_every_digit() {
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

#[test]
fn q4_phong_has_no_reference_bound_where_its_normals_nearly_cancel() {
    use phong_approx::tolerance::bound;
    use phong_approx::Method;
    let u = f64::from(f32::EPSILON) / 2.0;
    // Normals 10^-7 from opposite: q_min ≈ 2.5·10^-15, far below (250u)².
    assert_eq!(bound(Method::Phong, 2, 2.5e-15, u), None);
    assert!(bound(Method::Phong, 2, 0.5, u).is_some());
    // The span of the report: N_b 2·10^-7 from opposite, exactly unit; span printed a
    // reference bound of 5.97 there.
    let o = run(&[
        "span",
        "--method",
        "phong",
        "--na",
        "0,0,1",
        "--nb",
        "20000000/100000000000001,0,-99999999999999/100000000000001",
        "--light",
        "2/3,1/3,2/3",
        "--steps",
        "2",
        "--scalar",
        "f32",
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let j: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(j["error_bound"]["reference"].is_null(), "{j}");
}

#[test]
fn q5_ulps_are_counted_in_the_precision_checked() {
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

#[test]
fn q6_the_library_refuses_meaningless_tolerances() {
    use phong_approx::conformance::check::Tolerance;
    use phong_approx::testkit::Suite;
    use phong_approx::tolerance::profile::Profile;
    for t in [
        Tolerance::Abs(f64::NAN),
        Tolerance::Ulps(f64::NAN),
        Tolerance::Abs(f64::INFINITY),
        Tolerance::Abs(-1.0),
        Tolerance::Profile {
            profile: Profile::Fixed {
                int_bits: 64,
                frac_bits: u32::MAX,
            },
            format: phong_approx::Format::Binary32,
            form: phong_approx::tolerance::profile::Form::Any,
        },
        Tolerance::Profile {
            profile: Profile::Fixed {
                int_bits: 1 << 31,
                frac_bits: 16,
            },
            format: phong_approx::Format::Binary32,
            form: phong_approx::tolerance::profile::Form::Any,
        },
    ] {
        assert!(t.validate().is_err(), "{t:?}");
        // The test kit fails every set with the reason (no pass, no panic).
        let r = Suite::published()
            .tolerance(t)
            .check_f32(|s| vec![3.0; s.n as usize + 1]);
        assert!(!r.is_ok(), "{t:?}");
    }
}

#[test]
fn q7_exact_cosine_of_large_arguments() {
    use phong_approx::reference::transcendental::cos;
    // cos(10^100), computed independently with Python's decimal module at 250 digits
    // (π by Machin's formula, 10^100 reduced modulo 2π, the Taylor series).
    use phong_approx::Scalar;
    let x = BigRational::from_integer(BigInt::from(10).pow(100u32));
    assert_eq!(cos(&x).to_decimal(30), "-0.928081905074655343456194643777");
    // And cos(x)² + cos(x − π/2)² = 1 for a large x, which a wrong reduction breaks.
    let x = BigRational::from_integer(BigInt::from(10).pow(25u32));
    let half_pi = phong_approx::reference::transcendental::frac_pi_2();
    let (a, b) = (cos(&x), cos(&(x.clone() - half_pi)));
    let one = a.clone() * a + b.clone() * b - BigRational::from_integer(1.into());
    assert!(
        one.abs() < BigRational::new(1.into(), BigInt::from(1) << 240),
        "{one}"
    );
}

#[test]
fn q8_square_roots_of_tiny_rationals_never_divide_by_zero() {
    for args in [
        ["binary", "1e-60,0,-1", "2"],
        ["phong", "1e-90,1e-90,-1", "2"],
        ["duff", "1e-90,1e-90,-1", "2"],
        ["binary", "1e-90,1e-90,-1", "2"],
        ["spherical", "1e-90,0,1", "2"],
        ["bishop-weimer", "1e-280,0,-1", "3"],
    ] {
        let o = run(&[
            "span",
            "--method",
            args[0],
            "--na",
            "0,0,1",
            "--nb",
            args[1],
            "--light",
            "2/3,1/3,2/3",
            "--steps",
            args[2],
            "--scalar",
            "exact",
            "--normalize",
        ]);
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

/// A copy of the typical set's first specular case with `s` and `n` changed, as a
/// modified vector file, with results.
fn specular_file(d: &Path, s: u64, n: u64) -> (String, String) {
    let mut v = typical();
    let mut c = v["cases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| !c["specular"].is_null())
        .unwrap()
        .clone();
    c["specular"]["s"] = s.into();
    c["n"] = n.into();
    v["cases"] = Value::Array(vec![c.clone()]);
    v["number_of_cases"] = 1.into();
    let id = c["id"].as_str().unwrap();
    let rows: String = (0..=n).map(|i| format!("{id},{i},0.5\n")).collect();
    (write(d, "v.json", &v.to_string()), write(d, "r.csv", &rows))
}

#[test]
fn q9_specular_exponents_and_work_are_refused_before_any_work() {
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

#[test]
fn q10_a_huge_cosine_table_is_within_the_budget() {
    use phong_approx::budget::{exact_work, MAX_RECOMPUTED_WORK};
    use phong_approx::Method;
    assert!(exact_work(Method::AngularTable(16_777_216), 1, 10, 30) > MAX_RECOMPUTED_WORK);
    assert!(exact_work(Method::AngularTable(256), 1, 10, 30) < MAX_RECOMPUTED_WORK / 100);
}

#[test]
fn q11_hostile_library_arguments_give_errors_not_panics() {
    use phong_approx::fixed_span::FixedSpan;
    use phong_approx::testkit::Suite;
    use phong_approx::tolerance::profile::{fixed_bound, Profile};
    use phong_approx::{Method, Span, Vec3};
    assert_eq!(fixed_bound(Method::Gouraud, 4, 64, 1 << 31), None);
    assert_eq!(fixed_bound(Method::Gouraud, 4, 1 << 31, 16), None);
    assert!(Profile::Fixed {
        int_bits: 64,
        frac_bits: 1 << 31
    }
    .validate()
    .is_err());
    let r = Suite::published()
        .method(Method::AngularTable(512))
        .check_f32(|s| vec![0.0; s.n as usize + 1]);
    assert!(!r.is_ok());
    assert!(r.to_string().contains("angular-table512"), "{r}");
    let r = Suite::set("nope").check_f32(|s| vec![0.0; s.n as usize + 1]);
    assert!(
        !r.is_ok() && r.to_string().contains("no published set 'nope'"),
        "{r}"
    );
    // A span that is not unit (normalized inputs of huge length): refused, not a panic.
    let big = |x: i64| BigRational::from_integer(BigInt::from(x) << 80u32);
    let z = BigRational::from_integer(0.into());
    let v = Vec3::new(big(1), z.clone(), z.clone());
    if let Ok(s) = Span::normalized(v.clone(), v.clone(), v, 4) {
        let _ = FixedSpan::new(&s, 30);
    }
}

/// `check` of the typical set's own exact results with `extra` arguments.
fn check_typical(d: &Path, extra: &[&str]) -> Output {
    let r = write(d, "r.csv", &results_csv(&typical()));
    let v = root().join("vectors/typical.json").display().to_string();
    let mut args = vec!["check", "--vectors", &v, "--results", &r];
    args.extend_from_slice(extra);
    run(&args)
}

#[test]
fn q12_dot_named_outputs_are_written() {
    let d = scratch("q12");
    let out = d.join(".r.json");
    let o = check_typical(&d, &["--report", "json", out.to_str().unwrap()]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(out.is_file());
}

#[test]
fn q13_a_second_run_into_a_folder_in_use_exits_2_naming_it() {
    use std::os::unix::io::AsRawFd;
    let d = scratch("q13");
    let out = d.join("out");
    std::fs::create_dir_all(&out).unwrap();
    // Hold the folder's lock as a running phong-approx would.
    std::fs::write(out.join(".phong-approx-lock"), "12345").unwrap();
    let lock = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open(out.join(".phong-approx-lock"))
        .unwrap();
    // SAFETY: flock on a descriptor this test owns.
    assert_eq!(
        unsafe { libc::flock(lock.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) },
        0
    );
    let report = out.join("r.xml");
    let o = check_typical(&d, &["--report", "junit", report.to_str().unwrap()]);
    refused(
        &o,
        "being written by another phong-approx run (process 12345)",
    );
    drop(lock);
    let o = check_typical(&d, &["--report", "junit", report.to_str().unwrap()]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(report.is_file());
}

#[test]
fn q14_reports_once_and_valid_xml_for_any_case_id() {
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

#[test]
fn q15_messages_say_what_is_wrong() {
    let span = |extra: &[&str]| {
        let mut a = vec![
            "span", "--method", "gouraud", "--na", "0,0,1", "--nb", "0,0,1", "--light", "0,0,1",
            "--steps", "2",
        ];
        a.extend_from_slice(extra);
        run(&a)
    };
    refused(
        &span(&["--digits", "-1"]),
        "--digits: '-1' is not a whole number",
    );
    refused(
        &run(&["reproduce", "--out", ""]),
        "--out: '' is not a valid value",
    );
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

#[test]
fn q9_the_work_estimate_grows_with_every_input_and_refuses_the_documented_examples() {
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

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
    /// No public constructor or validator panics on a value its type admits (debug
    /// build: overflow checks on).
    #[test]
    fn q11_public_constructors_never_panic(
        m in proptest::prelude::any::<u32>(),
        f in proptest::prelude::any::<u32>(),
        n in proptest::prelude::any::<u32>(),
        x in proptest::prelude::any::<f64>(),
        fi in 0usize..3,
        size in 0u32..4096,
    ) {
        use phong_approx::conformance::check::Tolerance;
        use phong_approx::tolerance::profile::{fixed_bound, Profile};
        use phong_approx::Method;
        let p = Profile::Fixed { int_bits: m, frac_bits: f };
        let _ = p.validate();
        for method in [Method::Gouraud, Method::CorrectedEuler, Method::Phong] {
            let _ = fixed_bound(method, n, m, f);
        }
        let format = phong_approx::Format::ALL[fi];
        for t in [Tolerance::Abs(x), Tolerance::Ulps(x), Tolerance::Default { format }, Tolerance::Profile { profile: p, format, form: phong_approx::tolerance::profile::Form::Any }] {
            let _ = t.validate();
        }
        let _ = phong_approx::angular::CosTable::<f64>::new(size);
    }
}

#[test]
fn q3b_a_level_near_a_boundary_is_decided_with_more_bits() {
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
    let o = run(&[
        "span", "--method", "angular", "--na", &na, "--nb", "0,0,1", "--light", "0,0,1", "--steps",
        "2", "--scalar", "exact",
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let j: Value = serde_json::from_slice(&o.stdout).unwrap();
    // Independently: 1/(1 + t²) > (200/255)² since t < √((255/200)² − 1), so the value
    // is above 200/255 (and far below 201/255): level 200.
    let t2 = BigRational::new(&a * &a, &d * &d);
    let one = BigRational::from_integer(1.into());
    assert!(one.clone() / (one + t2) > BigRational::new(200.into(), 255.into()).pow(2));
    assert_eq!(j["levels"][1], 200, "{j}");
}
