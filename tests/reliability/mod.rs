//! Reliability: every defect found by trying the tool as a careless user and as an
//! attacker would has a test that reproduces it, and now passes, organized by subject
//! (one module per command or concern); each test's doc names its defect in the list
//! of docs/conformance.md, "Limits and exit codes". The shared helpers are here.

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

mod check;
mod compare;
mod library;
mod outputs;
mod reproduce;
mod span;

/// `span --method method --na na --nb nb --light light --steps steps` and `extra`, run
/// to the end.
fn span_run(method: &str, [na, nb, light]: [&str; 3], steps: &str, extra: &[&str]) -> Output {
    let mut a = vec![
        "span", "--method", method, "--na", na, "--nb", nb, "--light", light, "--steps", steps,
    ];
    a.extend_from_slice(extra);
    run(&a)
}

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

/// The width and height of a PNG file.
fn png_size(p: &Path) -> (u32, u32) {
    let b = std::fs::read(p).unwrap();
    let be = |i: usize| u32::from_be_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
    (be(16), be(20))
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
/// the program, its libraries and allocator reserves. The published typical set's
/// own check runs within 40 MiB; with every feature the program maps about 31 MiB
/// (17 MiB of embedded data, 12 MiB of code: the GPU stack is compiled without
/// optimization, Cargo.toml), and 8 MB of zeros are refused within 60 MiB.
const BASE_MIB: u64 = 40;

fn levels_of(o: &Output) -> Vec<Value> {
    assert_eq!(code(o), 0, "{}", stderr(o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    v["levels"].as_array().unwrap().clone()
}

/// `√x` of a positive rational to `2^-bits`, independently of the crate (integer
/// square root of `x·4^bits`).
fn sqrt_to(x: &BigRational, bits: usize) -> BigRational {
    let scaled = (x.numer() << (2 * bits)) / x.denom();
    BigRational::new(scaled.sqrt(), BigInt::from(1) << bits)
}

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

/// `check` of the typical set's own exact results with `extra` arguments.
fn check_typical(d: &Path, extra: &[&str]) -> Output {
    let r = write(d, "r.csv", &results_csv(&typical()));
    let v = root().join("vectors/typical.json").display().to_string();
    let mut args = vec!["check", "--vectors", &v, "--results", &r];
    args.extend_from_slice(extra);
    run(&args)
}
