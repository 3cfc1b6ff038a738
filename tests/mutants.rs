//! Wrong implementations are rejected under every profile, on every published set
//! (`docs/conformance.md`, "What the profiles reject"): each mutant is a plausible
//! mistake, written here in `f32` from the paper's equations, and `check` must fail
//! at least one case of every set with it, whatever the profile. A profile with no
//! bound for a method rejects every case of it ("no bound"), which is listed apart:
//! it is a refusal, not evidence that the bound separates the mutant.
//!
//! Prints the table mutant × profile × set (`cargo test --test numerics mutants:: -- --nocapture`).

use phong_approx::conformance::check::{check, Criteria, Results, Tolerance};
use phong_approx::conformance::vectors::{Case, VectorFile};
use phong_approx::tolerance::profile::Profile;
use phong_approx::Method;
use std::path::Path;

use phong_approx::testkit::SETS;

/// The float profiles and 16.16 fixed point.
fn profiles() -> impl Iterator<Item = Profile> {
    Profile::ALL.into_iter().chain([Profile::Fixed {
        int_bits: 16,
        frac_bits: 16,
    }])
}

fn committed(set: &str) -> VectorFile {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("vectors/{set}.json")),
    )
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The nearest-`f32` inputs of a case, as an implementation reads them.
fn inputs(c: &Case) -> [[f32; 3]; 3] {
    let v = |x: &[String; 3]| x.clone().map(|s| s.parse::<f32>().unwrap());
    [v(&c.na.f32), v(&c.nb.f32), v(&c.l.f32)]
}

fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The paper's set-up (eqs. 2–3, 10–11, 14–17) in `f32`, with the mutations that
/// touch it.
struct Setup {
    pa: f32,
    pb: f32,
    a: f32,
    c: f32,
    d: f32,
    e: f32,
    dia: f32,
    ds: f32,
    t0: f32,
    dp: f32,
}

fn setup(c: &Case, eps_over_n_plus_1: bool, dqb_is_d: bool) -> Setup {
    let [na, nb, l] = inputs(c);
    let n = c.n as f32;
    let k = [0, 1, 2].map(|j| (nb[j] - na[j]) / n);
    let (a, pa, pb) = (dot(k, l), dot(na, l), dot(nb, l));
    let (cc, d, e) = (dot(k, k), 2.0 * dot(k, na), dot(na, na));
    let dqb = if dqb_is_d { d } else { 2.0 * n * cc + d };
    let dia = a - pa / 2.0 * d;
    let dib = a - pb / 2.0 * dqb;
    let ds = (dib - dia) / n;
    let pn = pa + n * dia + (c.n as f32 * (c.n as f32 - 1.0) / 2.0) * ds;
    let eps = pn - pb;
    let t0 = dia - eps / if eps_over_n_plus_1 { n + 1.0 } else { n };
    Setup {
        pa,
        pb,
        a,
        c: cc,
        d,
        e,
        dia,
        ds,
        t0,
        dp: (pb - pa) / n,
    }
}

fn recurrence(p0: f32, t0: f32, ds: f32, n: u32) -> Vec<f64> {
    let (mut p, mut t) = (p0, t0);
    let mut out = vec![f64::from(p)];
    for _ in 0..n {
        p += t;
        t += ds;
        out.push(f64::from(p));
    }
    out
}

/// Gouraud, `g += dp`, in `f32`.
fn gouraud_run(s: &Setup, n: u32) -> Vec<f64> {
    let mut g = s.pa;
    let mut out = vec![f64::from(g)];
    for _ in 0..n {
        g += s.dp;
        out.push(f64::from(g));
    }
    out
}

/// The adaptive scheme (eqs. 23–24, `K_d = 1`) in `f32`, with `gouraud(δ)` deciding
/// for Gouraud, the step `⌊m⌋ + step_plus` (the paper's is `+ 1`), and the ε/(n+1)
/// mutation in the corrected-Euler branch when `eps_bug`.
fn adaptive(c: &Case, gouraud: fn(f32) -> bool, step_plus: i64, eps_bug: bool) -> Vec<f64> {
    let s = setup(c, eps_bug, false);
    let m = (s.dp - s.t0) / s.ds;
    let trunc = if m.is_finite() {
        m.trunc() as i64
    } else {
        i64::MAX / 2
    };
    let j = (trunc + step_plus).clamp(0, i64::from(c.n)) as f32;
    let delta = j * s.dp - (j * s.t0 + (j * j - j) / 2.0 * s.ds);
    if s.ds == 0.0 || gouraud(delta) {
        gouraud_run(&s, c.n)
    } else {
        recurrence(s.pa, s.t0, s.ds, c.n)
    }
}

/// A wrong implementation of `method`.
struct Mutant {
    name: &'static str,
    method: Method,
    run: fn(&Case) -> Vec<f64>,
}

const MUTANTS: [Mutant; 11] = [
    Mutant {
        name: "adaptive: |256δ| < 1 for |255δ| < 1",
        method: Method::Adaptive,
        run: |c| adaptive(c, |d| (256.0 * d).abs() < 1.0, 1, false),
    },
    Mutant {
        name: "adaptive: |255δ| < 2",
        method: Method::Adaptive,
        run: |c| adaptive(c, |d| (255.0 * d).abs() < 2.0, 1, false),
    },
    Mutant {
        name: "adaptive: |128δ| < 1",
        method: Method::Adaptive,
        run: |c| adaptive(c, |d| (128.0 * d).abs() < 1.0, 1, false),
    },
    Mutant {
        name: "adaptive: δ halved",
        method: Method::Adaptive,
        run: |c| adaptive(c, |d| (255.0 * d / 2.0).abs() < 1.0, 1, false),
    },
    Mutant {
        name: "adaptive: always Gouraud",
        method: Method::Adaptive,
        run: |c| adaptive(c, |_| true, 1, false),
    },
    Mutant {
        name: "adaptive: δ at step ⌊m⌋ (eq. 24 without + 1)",
        method: Method::Adaptive,
        run: |c| adaptive(c, |d| (255.0 * d).abs() < 1.0, 0, false),
    },
    Mutant {
        name: "ε/(n+1) for ε/n (eqs. 16–17)",
        method: Method::CorrectedEuler,
        run: |c| {
            let s = setup(c, true, false);
            recurrence(s.pa, s.t0, s.ds, c.n)
        },
    },
    Mutant {
        name: "plain Euler as corrected Euler",
        method: Method::CorrectedEuler,
        run: |c| {
            let s = setup(c, false, false);
            recurrence(s.pa, s.dia, s.ds, c.n)
        },
    },
    Mutant {
        name: "dq_b = D (eq. 11 without 2nC)",
        method: Method::CorrectedEuler,
        run: |c| {
            let s = setup(c, false, true);
            recurrence(s.pa, s.t0, s.ds, c.n)
        },
    },
    Mutant {
        name: "Gouraud sampled at i + ½",
        method: Method::Gouraud,
        run: |c| {
            let s = setup(c, false, false);
            (0..=c.n)
                .map(|i| f64::from(s.pa + (i as f32 + 0.5) * s.dp))
                .collect()
        },
    },
    Mutant {
        name: "Duff's first difference D for C + D",
        method: Method::Duff,
        run: |c| {
            let s = setup(c, false, false);
            let _ = s.pb;
            let (mut p, mut q, mut dq) = (s.pa, s.e, s.d);
            let mut out = Vec::new();
            for _ in 0..=c.n {
                out.push(f64::from(p / q.sqrt()));
                p += s.a;
                q += dq;
                dq += 2.0 * s.c;
            }
            out
        },
    },
];

/// `check`'s verdict on one mutant, set and profile: the number of failing cases,
/// and whether they fail for want of a bound.
fn verdict(m: &Mutant, file: &VectorFile, profile: Profile) -> (usize, usize, bool) {
    let results: Results = file
        .cases
        .iter()
        .map(|c| (c.id.clone(), (m.run)(c)))
        .collect();
    let format = phong_approx::Format::Binary32;
    let tol = Tolerance::Profile {
        profile,
        format,
        form: phong_approx::tolerance::profile::Form::Any,
    };
    let reports = check(file, &results, &Criteria::new(m.method, tol)).unwrap();
    let failed = reports.iter().filter(|r| !r.pass).count();
    let no_bound = reports
        .iter()
        .all(|r| r.allowed.starts_with("no ") || r.allowed.contains("has no bound for"));
    (failed, reports.len(), no_bound)
}

/// Whether an adaptive mutant accepted under a fixed-point profile is accepted
/// because that profile does not pin the decision: a unit with `F` fractional bits
/// rounds `δ` by up to `e_δ = h(2k + T)` (`fixed_point_adaptive_delta_error`), so on a
/// case with `|255·|δ| − 1| ≤ 255·e_δ` it may pick either method
/// (`fixed_point_adaptive_decision`), and at 16.16 that band holds every case whose
/// pick the decision mutants change. Checked, not assumed: every case on which the
/// mutant's pick differs from the exact test's must lie in the band.
fn decision_unpinned(m: &Mutant, file: &VectorFile, profile: Profile) -> bool {
    let Profile::Fixed { frac_bits, .. } = profile else {
        return false;
    };
    if m.method != Method::Adaptive {
        return false;
    }
    file.cases.iter().all(|c| {
        let picked_gouraud = (m.run)(c) == gouraud_run(&setup(c, false, false), c.n);
        let exact_gouraud = c.decision == "gouraud";
        let delta: f64 = c.delta.parse().unwrap();
        let band = phong_approx::tolerance::profile::fixed_adaptive_band(c.n, frac_bits);
        picked_gouraud == exact_gouraud || ((255.0 * delta).abs() - 1.0).abs() <= 255.0 * band
    })
}

#[test]
fn every_mutant_is_rejected_under_every_profile_on_every_set() {
    let files: Vec<VectorFile> = SETS.iter().map(|s| committed(s)).collect();
    println!("| mutant | profile | {} |", SETS.join(" | "));
    println!("|---|---|{}", "---|".repeat(SETS.len()));
    let mut missed = Vec::new();
    for m in &MUTANTS {
        for profile in profiles() {
            let cells: Vec<String> = SETS
                .iter()
                .zip(&files)
                .map(|(set, f)| {
                    let (failed, total, no_bound) = verdict(m, f, profile);
                    if failed == 0 && !decision_unpinned(m, f, profile) {
                        missed.push(format!("{} / {profile} / {set}", m.name));
                    }
                    if no_bound {
                        format!("no bound ({failed}/{total})")
                    } else {
                        format!("{failed}/{total} cases fail")
                    }
                })
                .collect();
            println!("| {} | {profile} | {} |", m.name, cells.join(" | "));
        }
    }
    assert!(missed.is_empty(), "mutants accepted: {missed:?}");
}

/// The mutants are wrong and the correct code is right: the same harness with the
/// corrected Euler and Gouraud recurrences unmutated passes every set under every
/// profile (so the rejections above come from the mutations, not the harness).
#[test]
fn the_unmutated_harness_passes() {
    let good = [
        Mutant {
            name: "adaptive",
            method: Method::Adaptive,
            run: |c| adaptive(c, |d| (255.0 * d).abs() < 1.0, 1, false),
        },
        Mutant {
            name: "corrected Euler",
            method: Method::CorrectedEuler,
            run: |c| {
                let s = setup(c, false, false);
                recurrence(s.pa, s.t0, s.ds, c.n)
            },
        },
        Mutant {
            name: "Gouraud",
            method: Method::Gouraud,
            run: |c| gouraud_run(&setup(c, false, false), c.n),
        },
    ];
    for set in SETS {
        let f = committed(set);
        for m in &good {
            for profile in profiles() {
                // A profile without a bound for the method (the adaptive scheme in
                // fixed point) refuses every case: nothing to pass.
                let format = phong_approx::Format::Binary32;
                if profile != Profile::Reference
                    && phong_approx::tolerance::profile::status(m.method, profile, format).is_none()
                {
                    continue;
                }
                let (failed, total, _) = verdict(m, &f, profile);
                assert_eq!(failed, 0, "{} {profile} {set}: {failed}/{total}", m.name);
            }
        }
    }
}
