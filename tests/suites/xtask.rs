//! `cargo xtask REPORT`: the programs that regenerate tables of `docs/float.md` from
//! the test modules' implementations and searches. They check nothing (the tests of the
//! same cases do: each report names its tests below) and take minutes, so they are a
//! program of their own, not tests: `cargo test` does not build or run this target
//! (`test = false` in Cargo.toml), and `.cargo/config.toml` makes `cargo xtask` an alias
//! of `cargo test --release --test xtask --`.
//!
//! ```text
//! cargo xtask bound-ratios            docs/float.md §13, the methods' table
//! cargo xtask related-bound-ratios    docs/float.md §13, the related methods' rows
//! cargo xtask fast-bound-ratios       docs/float.md §13, the fast kernels' table
//! cargo xtask tightness               docs/float.md §18.6
//! cargo xtask counts-vs-graphs        docs/float.md §19.3
//! ```
//!
//! The test tier (`PHONG_APPROX_TIER`, docs/testing.md) sets the spans' sizes, as for
//! the tests; the tables of the docs are the extensive tier's.

// The test modules' helpers that no report calls, and their imports for tests that a
// program without `cfg(test)` leaves out.
#![allow(dead_code, unused_imports)]

#[path = "../common/mod.rs"]
mod common;
#[path = "../fast.rs"]
mod fast;
#[path = "../float_bounds.rs"]
mod float_bounds;
#[path = "../float_bounds_related.rs"]
mod float_bounds_related;
#[path = "profiles.rs"]
mod profiles;

use common::*;
use phong_approx::fast::FastSpan;
use phong_approx::tolerance::{fast_bound, Kernel};
use phong_approx::{Method, Real, Scalar};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;

/// The reports: name, what it regenerates, the function.
const REPORTS: [(&str, &str, fn()); 5] = [
    (
        "bound-ratios",
        "docs/float.md §13: (derived bound) / (worst error found) per method and format",
        bound_ratios,
    ),
    (
        "related-bound-ratios",
        "docs/float.md §13: the same for the related methods",
        related_bound_ratios,
    ),
    (
        "fast-bound-ratios",
        "docs/float.md §13: the same for the fast kernels",
        fast_bound_ratios,
    ),
    (
        "tightness",
        "docs/float.md §18.6: the model's adversary's worst fraction of each profile bound",
        tightness,
    ),
    (
        "counts-vs-graphs",
        "docs/float.md §19.3: where the count theorems' formula is below the graphs' bound",
        profiles::graph::counts_vs_graphs,
    ),
];

fn usage() -> String {
    let mut s = String::from("usage: cargo xtask REPORT\n\nreports:\n");
    for (name, what, _) in REPORTS {
        s.push_str(&format!("  {name:<22} {what}\n"));
    }
    s
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [a] if a == "-h" || a == "--help" || a == "list" => print!("{}", usage()),
        [name] => match REPORTS.iter().find(|(n, _, _)| n == name) {
            Some((_, what, run)) => {
                let tier = if extensive() { "extensive" } else { "default" };
                eprintln!("xtask {name}: {what} (the {tier} tier)");
                run();
            }
            None => {
                eprintln!("xtask: no report {name:?}\n\n{}", usage());
                std::process::exit(2);
            }
        },
        _ => {
            eprint!("{}", usage());
            std::process::exit(2);
        }
    }
}

/// The methods' (derived bound) / (worst error found), at the case where the error
/// comes closest to its bound, over the edge, random and targeted cases and 200 seeded
/// targeted spans. The same cases are checked by `float_bounds::every_method_error_bound_*`
/// and `bound_search_*`.
fn bound_ratios() {
    use float_bounds::{cases, check_case};
    let mut all = cases();
    all.extend(targeted_cases());
    let mut runner = TestRunner::deterministic();
    for _ in 0..200 {
        all.push(arb_targeted().new_tree(&mut runner).unwrap().current());
    }
    println!("| method | format | worst error found (u) | at n | bound there (u) | ratio |");
    println!("|---|---|---:|---:|---:|---:|");
    fn row<T: Real>(m: Method, all: &[Case]) {
        let u = T::unit_roundoff();
        let mut best: Option<(f64, f64, u32)> = None;
        for c in all {
            if let Some((e, b)) = check_case::<T>(m, c).unwrap() {
                if e > 0.0 && best.is_none_or(|(be, bb, _)| e / b > be / bb) {
                    best = Some((e, b, c.n));
                }
            }
        }
        if let Some((e, b, n)) = best {
            println!(
                "| {m} | {} | {:.1} | {n} | {:.1} | {:.2} |",
                T::NAME,
                e / u,
                b / u,
                b / e
            );
        }
    }
    for m in Method::ALL {
        row::<f32>(m, &all);
        row::<f64>(m, &all);
    }
}

/// The related methods' ratios, over the edge, random and targeted cases and 200 more
/// spans of `arb_hard`; checked by `float_bounds_related::every_related_method_error_bound`
/// and `related_bound_search`.
fn related_bound_ratios() {
    use float_bounds_related::{arb_hard, cases, check_case, related_methods};
    let mut all = cases();
    let mut runner = TestRunner::deterministic();
    for _ in 0..200 {
        all.push(arb_hard().new_tree(&mut runner).unwrap().current());
    }
    println!("| method | format | worst error found (u) | at n | bound there (u) | ratio |");
    println!("|---|---|---:|---:|---:|---:|");
    for m in related_methods() {
        let mut best: [Option<(f64, f64, u32)>; 2] = [None, None];
        for c in &all {
            let r = check_case(m, c).unwrap_or_else(|e| panic!("{e}"));
            for k in 0..2 {
                if let Some((e, b)) = r[k] {
                    if e > 0.0 && best[k].is_none_or(|(be, bb, _)| e / b > be / bb) {
                        best[k] = Some((e, b, c.n));
                    }
                }
            }
        }
        for (k, (name, u)) in [("f32", f32::unit_roundoff()), ("f64", f64::unit_roundoff())]
            .into_iter()
            .enumerate()
        {
            if let Some((e, b, n)) = best[k] {
                println!(
                    "| {} | {name} | {:.1} | {n} | {:.1} | {:.2} |",
                    m.name(),
                    e / u,
                    b / u,
                    b / e
                );
            }
        }
    }
}

/// The fast kernels' ratios, over the edge, targeted and 200 seeded targeted spans;
/// checked by `fast::fast_kernels_match_exact_and_twins_*` and
/// `fast_rows::every_row_length_on_every_path`.
fn fast_bound_ratios() {
    use fast::{err, q_min};
    let mut all: Vec<Case> = edge_cases();
    all.extend(targeted_cases());
    let mut runner = TestRunner::deterministic();
    for _ in 0..200 {
        all.push(arb_targeted().new_tree(&mut runner).unwrap().current());
    }
    println!("| kernel | format | worst error found (u) | at n | bound there (u) | ratio |");
    println!("|---|---|---:|---:|---:|---:|");
    macro_rules! report {
        ($f:ident) => {{
            type Run = fn(&FastSpan<$f>, &mut [$f]);
            let kernels: [(&str, Method, Kernel, Run); 8] = [
                (
                    "corrected_euler",
                    Method::CorrectedEuler,
                    Kernel::CorrectedEuler,
                    FastSpan::<$f>::corrected_euler,
                ),
                (
                    "corrected_euler_serial",
                    Method::CorrectedEuler,
                    Kernel::CorrectedEulerSerial,
                    FastSpan::<$f>::corrected_euler_serial,
                ),
                ("euler", Method::Euler, Kernel::Euler, FastSpan::<$f>::euler),
                (
                    "gouraud",
                    Method::Gouraud,
                    Kernel::Gouraud,
                    FastSpan::<$f>::gouraud,
                ),
                (
                    "gouraud_serial",
                    Method::Gouraud,
                    Kernel::GouraudSerial,
                    FastSpan::<$f>::gouraud_serial,
                ),
                ("phong", Method::Phong, Kernel::Phong, FastSpan::<$f>::phong),
                (
                    "symmetric_phong",
                    Method::SymmetricPhong,
                    Kernel::SymmetricPhong,
                    FastSpan::<$f>::symmetric_phong,
                ),
                (
                    "duff_serial",
                    Method::Duff,
                    Kernel::DuffSerial,
                    FastSpan::<$f>::duff_serial,
                ),
            ];
            let u = <$f as Scalar>::unit_roundoff();
            for (name, m, k, run) in kernels {
                let mut best: Option<(f64, f64, u32)> = None;
                for c in &all {
                    let Some(s) = c.span() else { continue };
                    let Some(b) = fast_bound(k, s.n, q_min(&s), u) else {
                        continue;
                    };
                    let fast = FastSpan::<$f>::from_span(&s.cast::<$f>().unwrap());
                    let mut out = vec![0 as $f; s.len()];
                    run(&fast, &mut out);
                    let exact = exact_values(m, c, &s);
                    let e = (0..s.len())
                        .map(|i| err(&out[i], &exact[i]))
                        .fold(0.0, f64::max);
                    if e > 0.0 && best.is_none_or(|(be, bb, _)| e / b > be / bb) {
                        best = Some((e, b, s.n));
                    }
                }
                if let Some((e, b, n)) = best {
                    println!(
                        "| {name} | {} | {:.1} | {n} | {:.1} | {:.2} |",
                        stringify!($f),
                        e / u,
                        b / u,
                        b / e
                    );
                }
            }
        }};
    }
    report!(f32);
    report!(f64);
}

/// The worst fraction of the bound `check` applies that the model's adversary reaches,
/// per (method, form, profile, format), over the profile spans up to n = 256 and six
/// sign patterns (two of them pseudo-random); the same adversary is checked against
/// every bound by `profiles::adversary::the_models_adversary_stays_within_the_bounds`.
fn tightness() {
    use profiles::adversary::adversary_runs;
    use profiles::ieee::spans;
    let spans = spans();
    println!("| method | form | profile and format | worst error ÷ bound | bound ÷ worst error |");
    println!("|---|---|---|---:|---:|");
    adversary_runs(256, 6, &spans, |row, w| {
        println!("{row} {w:.3} | {:.1} |", 1.0 / w);
    });
}
