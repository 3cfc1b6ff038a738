//! `phong-approx span` end to end: output shape, values checked against independent
//! closed forms computed here in rationals (not by the recurrences under test). Its
//! refusals (one clear line, exit code 2) are `reliability/span.rs`'s.

use crate::runner;
use runner::bin;

use num_bigint::BigInt;
use num_rational::BigRational as Q;
use num_traits::{One, Signed, ToPrimitive, Zero};
use serde_json::Value;

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

/// Parses the CLI's decimal strings exactly (they are plain decimals).
fn dec(s: &str) -> Q {
    phong_approx::parse::parse_rational(s).expect("decimal")
}

fn run_json(args: &[&str]) -> Value {
    let out = bin().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

fn values(v: &Value) -> Vec<Q> {
    v["values"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| dec(x.as_str().unwrap()))
        .collect()
}

fn levels(v: &Value) -> Vec<u64> {
    v["levels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap())
        .collect()
}

/// The span used below: Na = (0, 3/5, 4/5), Nb = (2/7, 3/7, 6/7), L = (2/3, 1/3, 2/3),
/// all exactly unit.
const NA: &str = "0,3/5,4/5";
const NB: &str = "2/7,3/7,6/7";
const L: &str = "2/3,1/3,2/3";

struct Ref {
    pa: Q,
    pb: Q,
    a: Q,
    c: Q,
    d: Q,
}

/// The set-up written out by hand from the paper's definitions.
fn reference(n: i64) -> Ref {
    let na = [q(0, 1), q(3, 5), q(4, 5)];
    let nb = [q(2, 7), q(3, 7), q(6, 7)];
    let l = [q(2, 3), q(1, 3), q(2, 3)];
    let dot = |x: &[Q; 3], y: &[Q; 3]| {
        x[0].clone() * y[0].clone() + x[1].clone() * y[1].clone() + x[2].clone() * y[2].clone()
    };
    let k: [Q; 3] = std::array::from_fn(|j| (nb[j].clone() - na[j].clone()) / q(n, 1));
    Ref {
        pa: dot(&na, &l),
        pb: dot(&nb, &l),
        a: dot(&k, &l),
        c: dot(&k, &k),
        d: q(2, 1) * dot(&k, &na),
    }
}

fn span_args<'a>(method: &'a str, steps: &'a str, scalar: &'a str) -> Vec<&'a str> {
    vec![
        "span", "--method", method, "--na", NA, "--nb", NB, "--light", L, "--steps", steps,
        "--scalar", scalar,
    ]
}

/// |a − b| ≤ 10^-e.
fn close(a: &Q, b: &Q, e: u32) -> bool {
    (a.clone() - b.clone()).abs() <= Q::new(BigInt::one(), BigInt::from(10).pow(e))
}

#[test]
fn json_shape() {
    let v = run_json(&span_args("gouraud", "5", "exact"));
    assert_eq!(v["method"], "gouraud");
    assert_eq!(v["scalar"], "exact");
    assert_eq!(v["steps"], 5);
    assert_eq!(v["values"].as_array().unwrap().len(), 6);
    assert_eq!(v["levels"].as_array().unwrap().len(), 6);
    for s in v["values"].as_array().unwrap() {
        let digits = s
            .as_str()
            .unwrap()
            .chars()
            .filter(char::is_ascii_digit)
            .count();
        assert!(digits >= 25, "{s} has fewer than 25 digits");
    }
}

#[test]
fn exact_gouraud_euler_and_corrected_euler_match_closed_forms() {
    let n = 9;
    let r = reference(n);
    let ni = q(n, 1);
    // di_a from eq. 10, ds from the closed form D(p_a + p_b)/(2n).
    let di_a = r.a.clone() - r.pa.clone() / q(2, 1) * r.d.clone();
    let ds = r.d.clone() * (r.pa.clone() + r.pb.clone()) / (q(2, 1) * ni.clone());
    let g = values(&run_json(&span_args("gouraud", "9", "exact")));
    let e = values(&run_json(&span_args("euler", "9", "exact")));
    let c = values(&run_json(&span_args("corrected-euler", "9", "exact")));
    for i in 0..=n {
        let x = q(i, 1);
        let gi = r.pa.clone() + x.clone() * (r.pb.clone() - r.pa.clone()) / ni.clone();
        let ei = r.pa.clone()
            + x.clone() * di_a.clone()
            + (x.clone() * x.clone() - x.clone()) / q(2, 1) * ds.clone();
        let ci = gi.clone() - ds.clone() / q(2, 1) * x.clone() * (ni.clone() - x.clone());
        assert!(close(&g[i as usize], &gi, 29), "gouraud {i}");
        assert!(close(&e[i as usize], &ei, 29), "euler {i}");
        assert!(close(&c[i as usize], &ci, 29), "corrected euler {i}");
    }
    // The exact fractions: corrected Euler is p_a and p_b at the edges (eq. 17), and
    // every value is the closed form exactly.
    let v = run_json(&span_args("corrected-euler", "9", "exact"));
    let fr: Vec<Q> = v["fractions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().unwrap().parse::<Q>().unwrap())
        .collect();
    assert_eq!(fr[0], r.pa);
    assert_eq!(fr[n as usize], r.pb);
    for i in 0..=n {
        let x = q(i, 1);
        let gi = r.pa.clone() + x.clone() * (r.pb.clone() - r.pa.clone()) / ni.clone();
        assert_eq!(
            fr[i as usize],
            gi - ds.clone() / q(2, 1) * x.clone() * (ni.clone() - x)
        );
    }
    assert!(run_json(&span_args("phong", "9", "exact"))
        .get("fractions")
        .is_none());
}

#[test]
fn exact_phong_duff_symmetric_match_p_over_sqrt_q() {
    let n = 7;
    let r = reference(n);
    for method in ["phong", "duff", "symmetric-phong"] {
        let v = run_json(&span_args(method, "7", "exact"));
        let vals = values(&v);
        let lv = levels(&v);
        for i in 0..=n {
            let x = q(i, 1);
            let p = r.a.clone() * x.clone() + r.pa.clone();
            let qq = (r.c.clone() * x.clone() + r.d.clone()) * x.clone() + Q::one();
            // The printed value v (30 digits) satisfies (v ∓ 1e-29)² ≶ p²/q, same sign as p.
            let eps = Q::new(BigInt::one(), BigInt::from(10).pow(29));
            let target = p.clone() * p.clone() / qq.clone();
            let val = vals[i as usize].clone();
            assert_eq!(val.is_negative(), p.is_negative(), "{method} {i} sign");
            let (lo, hi) = (val.abs() - eps.clone(), val.abs() + eps.clone());
            assert!(
                lo.clone() * lo <= target && target <= hi.clone() * hi,
                "{method} pixel {i}"
            );
            // Level: ℓ/255 ≤ p/√q < (ℓ + 1)/255, decided by squares here as well.
            let l = lv[i as usize] as i64;
            if p.is_positive() {
                let lq = q(l, 255);
                let l1 = q(l + 1, 255);
                assert!(lq.clone() * lq * qq.clone() <= p.clone() * p.clone() || l == 0);
                assert!(
                    l == 255 || p.clone() * p.clone() < l1.clone() * l1 * qq.clone(),
                    "{method} level {i}"
                );
            } else {
                assert_eq!(l, 0);
            }
        }
    }
}

#[test]
fn adaptive_reports_delta_m_and_decision() {
    // The span of the eq. 24 counterexample: |δ·255| ≈ 0.63 → Gouraud.
    let v = run_json(&[
        "span",
        "--method",
        "adaptive",
        "--na",
        "0,3/5,4/5",
        "--nb",
        "0,8/17,15/17",
        "--light",
        "0,0,1",
        "--steps",
        "2",
        "--scalar",
        "exact",
    ]);
    assert_eq!(v["decision"], "gouraud");
    assert_eq!(dec(v["m"].as_str().unwrap()), q(1, 2));
    assert_eq!(v["step"], 1);
    // δ = ds/2 · 1 · 1 with ds = D(p_a + p_b)/(2n): D = 2k·Na, k = (Nb − Na)/2.
    let k = [
        q(0, 1),
        (q(8, 17) - q(3, 5)) / q(2, 1),
        (q(15, 17) - q(4, 5)) / q(2, 1),
    ];
    let d = q(2, 1) * (k[1].clone() * q(3, 5) + k[2].clone() * q(4, 5));
    let ds = d * (q(4, 5) + q(15, 17)) / q(4, 1);
    assert!(close(
        &dec(v["delta"].as_str().unwrap()),
        &(ds / q(2, 1)),
        29
    ));
    // K_d scales the test: with K_d = 2, |δ·255·K_d| > 1 → corrected Euler.
    let v2 = run_json(&[
        "span",
        "--method",
        "adaptive",
        "--na",
        "0,3/5,4/5",
        "--nb",
        "0,8/17,15/17",
        "--light",
        "0,0,1",
        "--steps",
        "2",
        "--scalar",
        "exact",
        "--kd",
        "2",
    ]);
    assert_eq!(v2["decision"], "corrected-euler");
}

/// Every method of the catalogue, in every float scalar, is within its printed
/// derived bound (`error_bound`) of its exact run, and prints its own name, which
/// parses back to the method.
#[test]
fn every_method_and_float_scalar_is_within_its_bound_of_exact() {
    for m in phong_approx::Method::ALL {
        let name = m.name();
        let exact_json = run_json(&span_args(&name, "12", "exact"));
        assert_eq!(exact_json["method"], name.as_ref());
        assert_eq!(name.parse::<phong_approx::Method>(), Ok(m));
        let exact = values(&exact_json);
        for scalar in ["f32", "f64"] {
            let j = run_json(&span_args(&name, "12", scalar));
            let bound: f64 = j["error_bound"]["reference"]
                .as_str()
                .unwrap_or_else(|| panic!("{name} {scalar}: no bound"))
                .parse()
                .unwrap();
            let v = values(&j);
            for (i, (a, b)) in v.iter().zip(&exact).enumerate() {
                let d = (a.clone() - b.clone()).abs().to_f64().unwrap();
                assert!(d <= bound, "{name} {scalar} pixel {i}: {d} > {bound}");
            }
        }
    }
}

/// An exact level that the value's error cannot decide prints as null, never a guess:
/// spherical interpolation between these normals passes exactly through L at the
/// middle (value 1, a level boundary), which the exact run decides from the middle
/// pixel's p/√q; everything it prints is a level.
#[test]
fn exact_levels_are_decided_or_null() {
    let j = run_json(&[
        "span",
        "--method",
        "spherical",
        "--na",
        "3/5,0,4/5",
        "--nb=-3/5,0,4/5",
        "--light",
        "0,0,1",
        "--steps",
        "4",
        "--scalar",
        "exact",
    ]);
    let l: Vec<Value> = j["levels"].as_array().unwrap().clone();
    assert_eq!(l[2], 255, "{l:?}");
    assert!(l.iter().all(|x| x.is_u64() || x.is_null()));
}

#[test]
fn angular_matches_cosine_of_interpolated_angle() {
    let n = 6;
    let r = reference(n);
    let v = values(&run_json(&span_args("angular", "6", "exact")));
    let (aa, ab) = (r.pa.to_f64().unwrap().acos(), r.pb.to_f64().unwrap().acos());
    for i in 0..=n {
        let want = (aa + (ab - aa) * i as f64 / n as f64).cos();
        assert!(
            (v[i as usize].to_f64().unwrap() - want).abs() < 1e-14,
            "pixel {i}"
        );
    }
    // With the 256-entry table every value is the cosine of a multiple of 90°/255.
    let t = values(&run_json(&[
        "span",
        "--method",
        "angular",
        "--na",
        NA,
        "--nb",
        NB,
        "--light",
        L,
        "--steps",
        "6",
        "--scalar",
        "f64",
        "--table-size",
        "256",
    ]));
    for x in t {
        let j = x.to_f64().unwrap().acos() / (std::f64::consts::FRAC_PI_2 / 255.0);
        assert!((j - j.round()).abs() < 1e-6, "{j} is not a table angle");
    }
}

#[test]
fn table_format_lists_pixels() {
    let out = bin()
        .args(span_args("corrected-euler", "3", "f64"))
        .args(["--format", "table"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("method corrected-euler · scalar f64 · n = 3"));
    assert_eq!(text.lines().count(), 2 + 4);
}

#[test]
fn normalize_accepts_non_unit_inputs() {
    let v = run_json(&[
        "span",
        "--method",
        "phong",
        "--na",
        "0,3,4",
        "--nb",
        "0,0,2",
        "--light",
        "0,0,5",
        "--steps",
        "2",
        "--scalar",
        "f64",
        "--normalize",
    ]);
    let vals = values(&v);
    assert!(close(&vals[0], &q(4, 5), 15));
    assert!(close(&vals[2], &Q::one(), 15));
}

#[test]
fn zero_is_printed_plainly() {
    // N·L = 0 at the left edge.
    let v = run_json(&[
        "span", "--method", "gouraud", "--na", "1,0,0", "--nb", "0,0,1", "--light", "0,0,1",
        "--steps", "2", "--scalar", "exact",
    ]);
    assert_eq!(v["values"][0], "0");
    assert!(Q::zero() < dec(v["values"][1].as_str().unwrap()));
}

/// Nb = −Na: every method computes what is defined (the example: Gouraud from
/// (0, 0, 1) to (0, 0, −1) in 5 steps, exactly), and Phong with an odd n; where it
/// is not defined the command refuses (`reliability::span::opposite_normals_are_refused_where_undefined`).
#[test]
fn opposite_normals_are_computed_where_defined() {
    let run = |method: &str, steps: &str| {
        bin()
            .args([
                "span",
                "--method",
                method,
                "--na=0,0,1",
                "--nb=0,0,-1",
                "--light=0,0,1",
                "--steps",
                steps,
                "--scalar",
                "exact",
            ])
            .output()
            .unwrap()
    };
    let out = run("gouraud", "5");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let fractions: Vec<&str> = v["fractions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().unwrap())
        .collect();
    assert_eq!(fractions, ["1", "3/5", "1/5", "-1/5", "-3/5", "-1"]);
    for m in [
        "euler",
        "corrected-euler",
        "adaptive",
        "angular",
        "phong",
        "duff",
        "symmetric-phong",
    ] {
        let out = run(m, "5");
        assert!(
            out.status.success(),
            "{m}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    // Phong on an odd n: N·L/|N| is +1 before the middle and −1 after it.
    let v: serde_json::Value = serde_json::from_slice(&run("phong", "5").stdout).unwrap();
    let levels: Vec<u64> = v["levels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap())
        .collect();
    assert_eq!(levels, [255, 255, 255, 0, 0, 0]);
}

/// Every `--flag` a message of the tool suggests (in a string of `src/`, comments and
/// tests apart) is one that the command printing it accepts: `check`'s path (its CLI
/// file and the library's conformance kit) only `check`'s flags, `span`'s only
/// `span`'s, and so on; no advice names an argument the user cannot pass.
#[test]
fn every_suggested_flag_is_accepted() {
    use std::collections::BTreeSet;
    /// The `--name` tokens of `text`.
    fn flags(text: &str) -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        let mut rest = text;
        while let Some(at) = rest.find("--") {
            let before = rest[..at].chars().next_back().unwrap_or(' ');
            let tail = &rest[at + 2..];
            let len = tail
                .find(|c: char| !(c.is_ascii_lowercase() || c == '-'))
                .unwrap_or(tail.len());
            let name = tail[..len].trim_end_matches('-');
            if !before.is_alphanumeric() && before != '-' && !name.is_empty() {
                out.insert(name.to_string());
            }
            rest = &tail[len..];
        }
        out
    }
    /// The flags in the string literals of source `text`, up to its unit tests.
    fn suggested(text: &str) -> BTreeSet<String> {
        let code = text.split("#[cfg(test)]").next().unwrap_or(text);
        code.lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .flat_map(|l| {
                l.split('"')
                    .enumerate()
                    .filter(|(k, _)| k % 2 == 1)
                    .flat_map(|(_, p)| flags(p))
                    .collect::<Vec<_>>()
            })
            .collect()
    }
    let accepted = |cmd: &str| {
        flags(&String::from_utf8_lossy(
            &runner::run(&[cmd, "--help"]).stdout,
        ))
    };
    let commands = ["span", "reproduce", "compare", "vectors", "check"];
    let of: std::collections::BTreeMap<&str, BTreeSet<String>> =
        commands.iter().map(|c| (*c, accepted(c))).collect();
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let file = |f: &str| std::fs::read_to_string(src.join(f)).unwrap();
    let mut wrong = Vec::new();
    let mut judge = |f: &str, cmds: &[&str]| {
        for flag in suggested(&file(f)) {
            // `cargo run --features mpfr` is cargo's flag, named as such.
            if flag == "features" {
                continue;
            }
            if !cmds.iter().any(|c| of[c].contains(&flag)) {
                wrong.push(format!("src/{f}: --{flag} (not a flag of {cmds:?})"));
            }
        }
    };
    judge("cli/check.rs", &["check"]);
    // Every file of a folder, its subfolders included, relative to `src/`.
    fn tree(dir: &std::path::Path, base: &std::path::Path, out: &mut Vec<String>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                tree(&p, base, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p.strip_prefix(base).unwrap().display().to_string());
            }
        }
    }
    let under = |d: &str| {
        let mut v = Vec::new();
        tree(&src.join(d), &src, &mut v);
        v
    };
    let conformance = under("conformance");
    assert!(conformance.len() >= 10, "{conformance:?}");
    for f in conformance {
        // The conformance kit's messages are check's, and its reproduce commands
        // (`Case::reproduce`) are span's.
        judge(&f, &["check", "span"]);
    }
    judge("cli/span.rs", &["span"]);
    judge("span_report.rs", &["span"]);
    for f in under("span_report") {
        judge(&f, &["span"]);
    }
    for f in under("testkit") {
        // The kit's advice reproduces a case with `span`; it judges as `check` does.
        judge(&f, &["span", "check"]);
    }
    judge("cli/vectors.rs", &["vectors"]);
    judge("cli/output.rs", &["reproduce", "compare", "vectors"]);
    judge("cli/torus.rs", &["reproduce", "compare"]);
    judge("cli/reproduce.rs", &["reproduce"]);
    judge("cli/compare.rs", &["compare"]);
    assert!(
        wrong.is_empty(),
        "advice naming flags the command does not take: {wrong:?}"
    );
}

/// `setup`: each published case's set-up, every value within half a grid step
/// (`2^-(F+1)`) of the exact set-up read from the case's exact span — the rounding
/// proofs/Fixed.v assumes — in the columns of docs/conformance.md ("Hardware span
/// units"); a method without a unit, a format past 64 bits or a value that does not
/// fit the registers is refused with exit code 2.
#[test]
fn setup_rounds_each_cases_set_up_to_nearest() {
    use phong_approx::conformance::integrity::case_span;
    let f = 28u32;
    for (method, columns) in [
        ("gouraud", ["p_a", "dp", "", "", "", "", ""]),
        ("euler", ["p_a", "", "di_a", "ds", "", "", ""]),
        ("corrected-euler", ["p_a", "", "t0", "ds", "", "", ""]),
        ("adaptive", ["p_a", "dp", "t0", "ds", "", "", ""]),
        ("duff", ["b", "a", "", "", "e", "c+d", "2c"]),
    ] {
        let out = bin()
            .args([
                "setup",
                "--vectors",
                "vectors/edge.json",
                "--method",
                method,
            ])
            .args(["--fixed", &format!("8.{f}")])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{method}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8(out.stdout).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("case,n,p0,dp,t0,ds,q0,dq0,d2q"));
        let file = phong_approx::testkit::published("edge").unwrap();
        for (line, c) in lines.zip(&file.cases) {
            let cells: Vec<&str> = line.split(',').collect();
            assert_eq!(
                (cells[0], cells[1]),
                (c.id.as_str(), c.n.to_string().as_str())
            );
            let s = case_span(c).unwrap();
            for (cell, col) in cells[2..].iter().zip(columns) {
                let exact = match col {
                    "p_a" => s.p_a.clone(),
                    "dp" => s.dp.clone(),
                    "di_a" => s.di_a.clone(),
                    "t0" => s.t0.clone(),
                    "ds" => s.ds.clone(),
                    "b" => s.b.clone(),
                    "a" => s.a.clone(),
                    "e" => s.e.clone(),
                    "c+d" => s.c.clone() + s.d.clone(),
                    "2c" => s.c.clone() + s.c.clone(),
                    _ => Q::zero(),
                };
                let raw: BigInt = cell.parse().unwrap();
                let err = (Q::new(raw, BigInt::one() << f) - exact).abs();
                assert!(
                    err <= Q::new(BigInt::one(), BigInt::one() << (f + 1)),
                    "{method} {col} of {}: off by {err}",
                    c.id
                );
            }
        }
    }
    for (args, needle) in [
        (
            ["--method", "phong", "--fixed", "8.28"],
            "no hardware set-up for phong",
        ),
        (["--method", "duff", "--fixed", "40.40"], "at most 64"),
        (["--method", "duff", "--fixed", "1.20"], "does not fit 1.20"),
    ] {
        let out = bin()
            .args(["setup", "--vectors", "vectors/edge.json"])
            .args(args)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains(needle) && err.lines().count() == 1,
            "{args:?}: {err}"
        );
    }
}

/// `phong-approx skip`: the exact and float decisions on a span whose highlight is far
/// (skip: checked here, `(255·K_s)²·p_i^{2s} < q_i^s` at every pixel and half-pixel
/// from `p` and `q` computed here) and on one whose first pixel is lit (shade:
/// `255·K_s·p_a^s ≥ 1`), the squared method's too; bad input is one line and exit 2.
#[test]
fn skip_decides_and_refuses_bad_input() {
    // `skip` on N_a = z, N_b = `nb`, H = `h`, n = 8, K_s = 1/2, s = 32.
    let skip_args = |m: &'static str, nb: &'static str, h: &'static str| {
        let mut a = vec!["skip", "--method", m, "--na", "0,0,1", "--nb", nb];
        a.extend(["--half-vector", h]);
        a.extend(["--steps", "8", "--ks", "1/2", "--shininess", "32"]);
        a
    };
    let run = |m: &'static str, h: &'static str| run_json(&skip_args(m, "3/5,0,4/5", h));
    // H = (0, 3/5, 4/5): N·H/|N| is at most 4/5 on the span, and 127.5·(4/5)^32 < 1.
    let far = run("phong", "0,3/5,4/5");
    assert_eq!(far["exact"]["skips"], Value::Bool(true), "{far}");
    assert_eq!(far["float"]["skips"], Value::Bool(true), "{far}");
    let (na, nb, h) = (
        [q(0, 1), q(0, 1), q(1, 1)],
        [q(3, 5), q(0, 1), q(4, 5)],
        [q(0, 1), q(3, 5), q(4, 5)],
    );
    let k2 = q(255, 2) * q(255, 2);
    for j in 0..=16 {
        let t = q(j, 16);
        let nt: Vec<Q> = (0..3).map(|c| &na[c] + &t * (&nb[c] - &na[c])).collect();
        let p: Q = (0..3).map(|c| &nt[c] * &h[c]).sum();
        let qq: Q = (0..3).map(|c| &nt[c] * &nt[c]).sum();
        assert!(
            &k2 * num_traits::Pow::pow(&p, 64u32) < num_traits::Pow::pow(&qq, 32u32),
            "t = {t}"
        );
    }
    let lit = run("corrected-euler", "0,0,1");
    assert_eq!(lit["exact"]["skips"], Value::Bool(false), "{lit}");
    assert_eq!(lit["float"]["skips"], Value::Bool(false), "{lit}");
    let sq = run("squared-corrected-euler", "0,3/5,4/5");
    assert_eq!(sq["exact"]["skips"], Value::Bool(true), "{sq}");
    assert_eq!(sq["float"]["skips"], Value::Bool(true), "{sq}");
    // The float form decides on the inputs rounded to binary64 and says when that
    // changed them (3/5 is not a binary64 number; 0 and 1 are).
    assert_eq!(far["float_inputs_rounded"], Value::Bool(true), "{far}");
    let dyadic = run_json(&skip_args("phong", "0,0,1", "0,0,1"));
    assert_eq!(
        dyadic["float_inputs_rounded"],
        Value::Bool(false),
        "{dyadic}"
    );
    assert_eq!(dyadic["exact"]["skips"], Value::Bool(false), "{dyadic}");
    assert_eq!(dyadic["float"]["skips"], Value::Bool(false), "{dyadic}");
    for (args, flag) in [
        (vec!["--method", "angular"], "--method"),
        (vec!["--ks", "2"], "--ks"),
        (vec!["--shininess", "0"], "--shininess"),
        (vec!["--shininess", "1025"], "--shininess"),
        (vec!["--na", "0,0,0"], "span"),
        (vec!["--nb", "0,0,-1"], "span"),
    ] {
        let mut a = skip_args("phong", "3/5,0,4/5", "0,0,1");
        // The flag's value replaced by the bad one.
        let at = a.iter().position(|x| *x == args[0]).unwrap();
        a[at + 1] = args[1];
        let out = bin().args(&a).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{a:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{a:?}: {err}");
        assert!(err.contains(flag), "{a:?}: {err}");
    }
}
