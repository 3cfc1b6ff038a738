//! The bound theorems of `proofs/Profiles.v` as their statements give them, read from
//! the `.v` file, so that the tests take their constants from the proofs and not from
//! a copy (`tests/claims_index.rs` ties the checker's table to the same statements).

use std::collections::BTreeMap;

fn read(p: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(p);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{p}: {e}"))
}

/// The statement of `Theorem name` in `file` (a path from the crate's root), from
/// `Theorem name :` to the `.` that ends it before `Proof.`, its whitespace collapsed
/// to single spaces, so that a test can look for a formula as it is written.
pub fn statement(file: &str, name: &str) -> String {
    let text = read(file);
    let at = text
        .find(&format!("Theorem {name} :"))
        .unwrap_or_else(|| panic!("no Theorem {name} in {file}"));
    let rest = &text[at..];
    let end = rest
        .find(".\nProof.")
        .unwrap_or_else(|| panic!("{file}: {name} ends before Proof."));
    rest[..end].split_whitespace().collect::<Vec<_>>().join(" ")
}

/// One bound theorem of `proofs/Profiles.v` as its statement gives it: `α` and `β` as
/// fractions (`α = 0` for the closed forms), the largest `n`, and `u = 2^-e`.
#[derive(Debug, PartialEq)]
pub struct Stated {
    /// `α` as a fraction (0 for the closed forms).
    pub alpha: (u64, u64),
    /// `β` as a fraction.
    pub beta: (u64, u64),
    /// The largest `n`.
    pub max_n: u32,
    /// `u = 2^-e`.
    pub e: i32,
}

/// Every `Theorem profile_*` of `proofs/Profiles.v` whose conclusion is
/// `Rabs (…) <= (A / B * INR (n s) + C / D) * bpow radix2 (-E)` or
/// `Rabs (…) <= C / D * bpow radix2 (-E)`, by name.
pub fn stated_profile_bounds() -> BTreeMap<String, Stated> {
    let text = read("proofs/Profiles.v");
    let num = |s: &str| -> u64 { s.trim().parse().unwrap_or_else(|_| panic!("'{s}'")) };
    let frac = |s: &str| -> (u64, u64) {
        let (a, b) = s
            .split_once('/')
            .unwrap_or_else(|| panic!("no fraction in '{s}'"));
        (num(a), num(b))
    };
    let mut out = BTreeMap::new();
    for part in text.split("\nTheorem ").skip(1) {
        let name: String = part
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if !name.starts_with("profile_") {
            continue;
        }
        let statement = part[..part.find("Proof.").expect("a proof")]
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        let concl = &statement[statement.rfind("<= ").expect("a bound") + 3..];
        let Some((bound, exp)) = concl.split_once(" * bpow radix2 (-") else {
            continue; // a lemma-like statement without a bound in u
        };
        let e: i32 = exp
            .trim_end_matches(['.', ')'])
            .parse()
            .expect("an exponent");
        let bound = bound.trim().trim_start_matches('(').trim_end_matches(')');
        let (alpha, beta) = match bound.split_once(" * INR (n s) + ") {
            Some((a, b)) => (frac(a), frac(b)),
            None => ((0, 1), frac(bound)),
        };
        let max_n = if let Some(k) = statement.find(")%Z") {
            let head = &statement[..k];
            num(&head[head.rfind("<= ").expect("a range") + 3..]) as u32
        } else {
            let k = statement.find(")%nat").expect("a range of n");
            let head = &statement[..k];
            num(&head[head.rfind("<= ").expect("a range") + 3..]) as u32
        };
        out.insert(
            name,
            Stated {
                alpha,
                beta,
                max_n,
                e,
            },
        );
    }
    out
}

/// `(α, β)` of the theorem `name` of `proofs/Profiles.v`, each the nearest `f64` of
/// the statement's fraction.
pub fn constants(name: &str) -> (f64, f64) {
    static STATED: std::sync::OnceLock<BTreeMap<String, Stated>> = std::sync::OnceLock::new();
    let s = STATED
        .get_or_init(stated_profile_bounds)
        .get(name)
        .unwrap_or_else(|| panic!("{name} is not a bound theorem of proofs/Profiles.v"));
    let f = |(a, b): (u64, u64)| a as f64 / b as f64;
    (f(s.alpha), f(s.beta))
}
