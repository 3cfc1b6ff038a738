//! The composed bounds of Phong, Duff and symmetric Phong (`src/tolerance/profile/phong.rs`,
//! `counts.rs`) against `proofs/Composed.v`, where their composition is stated: the
//! count theorems' constants as `Composed.v` defines them, and at every point of a grid
//! of spans (`n`, `q_min`, `|N_b − N_a|`) under `ieee` and `shader`, the checker's bound
//! at least the right-hand side of the theorem of the same name, evaluated here from the
//! statement's own formula with the smallest errors `EP`, `EQ` its hypotheses allow —
//! computed here, not by the checker — and its side conditions true wherever the
//! checker gives a bound. The right-hand sides are evaluated in `f64` and compared
//! within a relative `2^-40`: the checker's own `f64` rounding is what it is not held to.

use super::*;
use phong_approx::tolerance::profile::{
    arith, duff_bound, phong_bound, symmetric_phong_bound, Arith, PHONG_COUNTS,
};

fn composed() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/proofs/Composed.v"))
        .expect("proofs/Composed.v")
}

/// The text of `Definition name ... :=` up to its `.`, whitespace collapsed.
fn definition(text: &str, name: &str) -> String {
    let at = text
        .find(&format!("Definition {name} "))
        .unwrap_or_else(|| panic!("no Definition {name} in Composed.v"));
    let rest = &text[at..];
    let body = &rest[rest.find(":=").unwrap() + 2..];
    body[..body.find(".\n").unwrap()]
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// The fractions `a / 100` (or `/ 1000`) of a definition, in order, as `f64`.
fn fractions(def: &str) -> Vec<f64> {
    let t: Vec<&str> = def.split_whitespace().collect();
    t.windows(3)
        .map(|w| {
            (
                w[0].trim_start_matches('('),
                w[1],
                w[2].trim_end_matches(')'),
            )
        })
        .filter(|(a, op, _)| *op == "/" && !a.is_empty() && a.chars().all(|c| c.is_ascii_digit()))
        .map(|(a, _, b)| a.parse::<f64>().unwrap() / b.parse::<f64>().unwrap())
        .collect()
}

/// `phong_value_either`'s right-hand side as `Composed.v` states it, with `ep := EP`,
/// `eq := EQ`, `u`, `η` and the value step's `ks`, `kv`, `km`.
fn rhs(a: &Arith, ep: f64, eq: f64, qmin: f64, (ks, kv, km): (f64, f64, f64)) -> f64 {
    let (u, eta) = (a.u, a.eta);
    let w = (ks + kv + km) * u;
    let g = w / (1.0 - w);
    let r = (qmin - eq).sqrt();
    let b = ep / r + eq / (r * (qmin.sqrt() + r));
    b * (1.0 + g) + g + (2.0 * (1.0 + b) * (eta / r) + ((1.0 + ep) * eta * (1.0 + km * u) + eta))
}

/// The parts of the right-hand side the statements must still contain (an edit of the
/// theorem that changes the formula fails here before the numbers are compared).
const RHS_TEXT: [&str; 3] = [
    "(EP / sqrt (qmin - EQ) + EQ / (sqrt (qmin - EQ) * (sqrt qmin + sqrt (qmin - EQ)))) * (1 + (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M))",
    "+ (ks + kv + km) * m_u M / (1 - (ks + kv + km) * m_u M)",
    "((1 + EP) * m_eta M * (1 + km * m_u M) + m_eta M)",
];

/// `K1` and the two `kd` of the theorems (`kd_recip`), for `a`.
fn k1_kds(a: &Arith) -> (f64, [f64; 2]) {
    let k1 = a.input.max(a.add).max(a.mul).max(1.0);
    (
        k1,
        [
            a.div,
            (1.0 + 2f64.powi(-20)) * a.mul + a.div + 2f64.powi(-36),
        ],
    )
}

/// The two models and the value step's `κ` (`ks` the square root, `kv` the division,
/// `km` the product), as the checker takes them.
fn models() -> Vec<(Profile, Arith)> {
    [Profile::Ieee, Profile::Shader]
        .into_iter()
        .map(|p| (p, arith(p, Format::Binary32).unwrap()))
        .collect()
}

fn at_least(what: &str, got: f64, want: f64) {
    assert!(
        got >= want * (1.0 - 2f64.powi(-40)),
        "{what}: the checker's {got:e} < the theorem's {want:e}"
    );
}

/// Phong's grid: for each model, `n`, `q_min` and `dd` where `phong_bound` gives a
/// bound `b`, the smallest `EP`, `EQ` the theorem's `*_errors_ok` allows over the
/// forms `forms` keeps (the smaller of the two count theorems, either way of `/n`),
/// handed to `check(what, profile, a, q_min, b, EP, EQ)`. Returns the points checked.
fn phong_grid(
    forms: impl Fn(&str) -> bool,
    check: impl Fn(&str, &Arith, f64, f64, f64, f64),
) -> usize {
    let mut checked = 0;
    for (profile, a) in models() {
        let (k1, kds) = k1_kds(&a);
        for n in [1u32, 2, 7, 64, 1000, 4096] {
            for qmin in [1.0, 0.5, 0.1, 1e-2, 1e-3] {
                for dd in [0.0, 0.1, 1.0, 2.0] {
                    let Some(b) = phong_bound(&a, n, qmin, dd) else {
                        continue;
                    };
                    let (mut ep, mut eq) = (0f64, 0f64);
                    for c in PHONG_COUNTS.iter().filter(|c| forms(c.form)) {
                        for kd in kds {
                            let (p, q) = c.errors((k1, kd), dd);
                            ep = ep.max(p * a.u);
                            eq = eq.max(q * a.u);
                        }
                    }
                    let what = format!("{profile} n = {n} q_min = {qmin} dd = {dd}");
                    check(&what, &a, qmin, b, ep, eq);
                    checked += 1;
                }
            }
        }
    }
    checked
}

/// `proofs/Composed.v`, `phong_composed`: the count constants are `PHONG_COUNTS`, and
/// `phong_bound` is at least the theorem's bound with `EP`, `EQ` the largest over the
/// three forms of the smaller of the two count theorems, for either way of `/n`.
#[test]
fn phong_composed() {
    let text = composed();
    let st = common::coq::statement("proofs/Composed.v", "phong_composed");
    for part in RHS_TEXT.iter().chain(&[
        "phong_form_ok M s na nb l i ph qh",
        "phong_errors_ok M K1 dd EP EQ",
        "2 * EQ <= qmin",
    ]) {
        assert!(
            st.contains(part),
            "phong_composed's statement changed: no {part:?}"
        );
    }
    assert_eq!(
        definition(&text, "kd_recip (M : fmodel) : R"),
        "(1 + / 1048576) * k_mul M + k_div M + / 68719476736"
    );
    for c in PHONG_COUNTS {
        let f = |x: &str| fractions(&definition(&text, &format!("{}_{x}", c.form)));
        assert_eq!(f("p"), vec![c.p.0, c.p.1], "{}_p", c.form);
        assert_eq!(f("q"), vec![c.q.0, c.q.1], "{}_q", c.form);
        let (a0, a1, b0, b1) = c.pd;
        // (`0 * dd` is written as a bare 0: the zero constants are not fractions.)
        let want: Vec<f64> = [a0, a1, b0, b1].into_iter().filter(|&x| x != 0.0).collect();
        assert_eq!(f("pd"), want, "{}_pd", c.form);
        let (c0, c1, c2, e0, e1, e2) = c.qd;
        let want: Vec<f64> = [c0, c1, c2, e0, e1, e2]
            .into_iter()
            .filter(|&x| x != 0.0)
            .collect();
        assert_eq!(f("qd"), want, "{}_qd", c.form);
    }
    let checked = phong_grid(
        |_| true,
        |what, a, qmin, b, ep, eq| {
            assert!(
                2.0 * eq <= qmin && 1024.0 * a.eta <= (qmin - eq).sqrt(),
                "{what}"
            );
            assert!((a.sqrt + a.div + a.mul) * a.u <= 1.0 / 1024.0);
            at_least(what, b, rhs(a, ep, eq, qmin, (a.sqrt, a.div, a.mul)));
        },
    );
    assert!(checked >= 150, "{checked} points");
}

/// `proofs/Composed.v`, `phong_composed_normalize`: normalize-then-dot (the per-pixel
/// normal or the lerp) adds the statement's term to the same right-hand side, with
/// `EP`, `EQ` over those two forms; `phong_bound` is at least that.
#[test]
fn phong_composed_normalize() {
    let st = common::coq::statement("proofs/Composed.v", "phong_composed_normalize");
    for part in RHS_TEXT.iter().chain(&[
        "normal_form_ok M s na nb i nh",
        "pl_errors_ok M K1 dd EP EQ",
        "1024 * m_eta M <= qmin - EQ",
        "(103 / 100 * (1 + k_in M * m_u M + 2 * m_eta M) * (km * m_u M + k_mul M * m_u M + 2 * (k_add M * m_u M)) + 2 * (1 + k_in M * m_u M + 2 * m_eta M) * m_eta M + 8 * m_eta M)",
    ]) {
        assert!(st.contains(part), "phong_composed_normalize's statement changed: no {part:?}");
    }
    let checked = phong_grid(
        |form| form != "horner",
        |what, a, qmin, b, ep, eq| {
            let (u, eta) = (a.u, a.eta);
            let lam = 1.0 + a.input * u + 2.0 * eta;
            let term = 1.03 * lam * (a.mul * u + a.mul * u + 2.0 * (a.add * u))
                + 2.0 * lam * eta
                + 8.0 * eta;
            assert!(1024.0 * eta <= qmin - eq, "{what}");
            at_least(what, b, rhs(a, ep, eq, qmin, (a.sqrt, a.div, a.mul)) + term);
        },
    );
    assert!(checked >= 150, "{checked} points");
}

/// Duff's counts as `Composed.v` defines them (`duff_p`, `duff_q`) with `SP`, `SQ`
/// steps and `kd`, in units of `u`.
fn duff_counts(text: &str, a: &Arith, sp: f64, sq: f64) -> (f64, f64) {
    let p = fractions(&definition(text, "duff_p"));
    let q = fractions(&definition(text, "duff_q"));
    assert_eq!(p.len(), 3, "duff_p: {p:?}");
    assert_eq!(q.len(), 3, "duff_q: {q:?}");
    let (k1, kds) = k1_kds(a);
    kds.iter().fold((0f64, 0f64), |(ep, eq), &kd| {
        (
            ep.max((p[0] * k1 + p[1] * kd + p[2] * sp * a.add) * a.u),
            eq.max((q[0] * k1 + q[1] * kd + q[2] * sq * a.add) * a.u),
        )
    })
}

/// `proofs/Composed.v`, `duff_composed`: `duff_bound` is at least the theorem's bound
/// at `i = n` with `SP = SQ = n` (the counts grow with the steps, so every pixel's is
/// within it).
#[test]
fn duff_composed() {
    let text = composed();
    let st = common::coq::statement("proofs/Composed.v", "duff_composed");
    for part in RHS_TEXT.iter().chain(&[
        "duff_form_ok M s na nb l P Q G",
        "INR i <= SP -> INR i <= SQ",
        "duff_errors_ok M K1 SP SQ EP EQ",
    ]) {
        assert!(
            st.contains(part),
            "duff_composed's statement changed: no {part:?}"
        );
    }
    let mut checked = 0;
    for (profile, a) in models() {
        for n in [1u32, 2, 7, 64, 1000, 4096] {
            for qmin in [1.0, 0.5, 0.1, 1e-2, 1e-3] {
                let Some(b) = duff_bound(&a, n, qmin) else {
                    continue;
                };
                let nf = f64::from(n);
                let (ep, eq) = duff_counts(&text, &a, nf, nf);
                assert!(
                    2.0 * eq <= qmin && nf * a.add * a.u <= 1.0 / 2048.0,
                    "{profile} n = {n}"
                );
                at_least(
                    &format!("{profile} n = {n} q_min = {qmin}"),
                    b,
                    rhs(&a, ep, eq, qmin, (a.sqrt, a.div, a.mul)),
                );
                checked += 1;
            }
        }
    }
    assert!(checked >= 40, "{checked} points");
}

/// `proofs/Composed.v`, `symmetric_phong_composed`: at every pixel `i`, `p` walked `i`
/// steps and `q` walked `min(i, n − i)`; `symmetric_phong_bound` (the largest of its
/// eight pieces) is at least the theorem's bound at each pixel — which checks the
/// pieces' steps cover every pixel's.
#[test]
fn symmetric_phong_composed() {
    let text = composed();
    let st = common::coq::statement("proofs/Composed.v", "symmetric_phong_composed");
    for part in RHS_TEXT.iter().chain(&[
        "INR (Nat.min i (n s - i)) <= SQ",
        "duff_errors_ok M K1 SP SQ EP EQ",
    ]) {
        assert!(
            st.contains(part),
            "symmetric_phong_composed's statement changed: no {part:?}"
        );
    }
    let mut checked = 0;
    for (profile, a) in models() {
        for n in [1u32, 2, 3, 7, 64, 1000, 4096] {
            for qmin in [1.0, 0.1, 1e-3] {
                let Some(b) = symmetric_phong_bound(&a, n, qmin) else {
                    continue;
                };
                for i in 0..=n {
                    let (ep, eq) = duff_counts(&text, &a, f64::from(i), f64::from(i.min(n - i)));
                    at_least(
                        &format!("{profile} n = {n} q_min = {qmin} i = {i}"),
                        b,
                        rhs(&a, ep, eq, qmin, (a.sqrt, a.div, a.mul)),
                    );
                }
                checked += 1;
            }
        }
    }
    assert!(checked >= 20, "{checked} points");
}
