//! One check, start to end, as the command line's `check` runs it: the vector file read
//! and trusted or recomputed ([`load_vectors`]), the results judged
//! ([`super::judgement::judge`]), and the verdict as text (`Judgement::text`) or its
//! one-line failure ([`failure`]).
//!
//! A published set (its SHA-256 one of [`super::integrity::SHA256SUMS`]) is read whole:
//! its expectations are this version's own. Any other file supplies cases, not truth:
//! its inputs are read (its expectations skipped unread) and the expectations of the
//! one method checked are recomputed by the exact reference, within the work budget
//! [`MAX_RECOMPUTED_WORK`].

use super::check::CaseReport;
use super::integrity::{published_set, sha256_hex, validate, MAX_CASES};
use super::vectors::{
    exact_input, method_key, InputsFile, VectorFile, DIGITS, MAX_CASE_STEPS, MAX_SHININESS,
};
use crate::budget::{exact_work, input_bits, specular_work, CASE_WORK, MAX_RECOMPUTED_WORK};
use crate::error::shown;
use crate::method::Method;
use crate::table::{markdown, Align};

/// Which input a refusal is about (the command line names it as the argument).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Culprit {
    /// The vector file.
    Vectors,
    /// The vector file is not a published set, and modified files were not allowed
    /// (`allow_modified` of [`load_vectors`]).
    Unpublished,
    /// The method asked for.
    Method,
    /// The specular switch.
    Specular,
}

/// Why a vector file cannot be checked against: the input at fault and a one-line
/// message (the file's name in it as given, [`shown`]).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct LoadError {
    /// The input at fault.
    pub culprit: Culprit,
    /// What is wrong.
    pub message: String,
}

/// A vector file ready to check against.
#[derive(Clone, Debug)]
pub struct Loaded {
    /// The cases and their expectations.
    pub file: VectorFile,
    /// `true` when the file is not a published set and the expectations of the
    /// method were recomputed from its inputs.
    pub recomputed: bool,
    /// The shape of each case's exact span, read once while the file was validated:
    /// what [`crate::conformance::judgement::judge`] takes.
    pub shapes: Vec<Option<crate::tolerance::Shape>>,
}

/// The vector file `text` (named `name` in messages) for checking `method`: a
/// published set as it is; any other file, only with `allow_modified`, its expectations
/// recomputed. Then the file's consistency ([`validate`]), that it has `method`, and
/// specular cases if `specular`.
///
/// # Errors
/// A [`LoadError`] naming the input at fault: a file that is not a published set (and
/// `allow_modified` is false), not a vector file, inconsistent, too large to recompute
/// (more than [`MAX_CASES`] cases, a case outside `1..=MAX_CASE_STEPS` steps, more
/// than [`MAX_RECOMPUTED_WORK`] units of exact work); a method the file lacks; no
/// specular cases.
pub fn load_vectors(
    text: String,
    name: &str,
    method: Method,
    specular: bool,
    allow_modified: bool,
) -> Result<Loaded, LoadError> {
    let vectors_error = |m: String| bad_vectors(name, m);
    let digest = sha256_hex(text.as_bytes());
    let published = published_set(&digest).is_some();
    if !published && !allow_modified {
        return Err(LoadError {
            culprit: Culprit::Unpublished,
            message: format!(
                "{}: SHA-256 {digest} is not that of a published vector set (docs/conformance.md)",
                shown(name)
            ),
        });
    }
    let not_vectors = |e: serde_json::Error| LoadError {
        culprit: Culprit::Vectors,
        message: format!("{}:{}: not a vector file: {e}", shown(name), e.line()),
    };
    let file: VectorFile = if published {
        serde_json::from_str(&text).map_err(not_vectors)?
    } else {
        let inputs: InputsFile = serde_json::from_str(&text).map_err(not_vectors)?;
        drop(text);
        recompute(name, &inputs, method, specular)?
    };
    let shapes = validate(&file).map_err(|e| vectors_error(e.to_string()))?;
    let key = method_key(method);
    if !file.methods.contains(&key) {
        return Err(missing_method(name, &key, &file.methods));
    }
    if specular && file.cases.iter().all(|c| c.specular.is_none()) {
        return Err(LoadError {
            culprit: Culprit::Specular,
            message: format!("{} has no specular cases", shown(name)),
        });
    }
    Ok(Loaded {
        file,
        recomputed: !published,
        shapes,
    })
}

/// A refusal of the vector file `name`.
fn bad_vectors(name: &str, message: String) -> LoadError {
    LoadError {
        culprit: Culprit::Vectors,
        message: format!("{}: {message}", shown(name)),
    }
}

fn missing_method(name: &str, key: &str, methods: &[String]) -> LoadError {
    LoadError {
        culprit: Culprit::Method,
        message: format!(
            "'{key}' is not in {} (it has: {})",
            shown(name),
            shown(&methods.join(", "))
        ),
    }
}

/// The expectations of `method` for a file that is not published, computed from its
/// inputs within the work budget [`MAX_RECOMPUTED_WORK`] (the budget is checked before
/// any exact work).
fn recompute(
    name: &str,
    inputs: &InputsFile,
    method: Method,
    specular: bool,
) -> Result<VectorFile, LoadError> {
    let bad = |m: String| bad_vectors(name, m);
    if inputs.cases.len() > MAX_CASES {
        return Err(bad(format!("more than {MAX_CASES} cases")));
    }
    let key = method_key(method);
    if !inputs.methods.contains(&key) {
        return Err(missing_method(name, &key, &inputs.methods));
    }
    if let Some(c) = inputs
        .cases
        .iter()
        .find(|c| c.n == 0 || c.n > MAX_CASE_STEPS)
    {
        return Err(bad(format!(
            "case {}: n = {} is outside 1..={MAX_CASE_STEPS}",
            shown(&c.id),
            c.n
        )));
    }
    if let Some(c) = inputs.cases.iter().find(|c| {
        c.specular
            .as_ref()
            .is_some_and(|sp| sp.s == 0 || sp.s > MAX_SHININESS)
    }) {
        return Err(bad(format!(
            "case {}: shininess {} is outside 1..={MAX_SHININESS}",
            shown(&c.id),
            c.specular.as_ref().map_or(0, |sp| sp.s)
        )));
    }
    let mut work = 0u64;
    for c in &inputs.cases {
        let mut vs = Vec::new();
        for x in [
            Some(&c.na),
            Some(&c.nb),
            Some(&c.l),
            c.specular.as_ref().map(|s| &s.h),
        ]
        .into_iter()
        .flatten()
        {
            vs.push(exact_input(x).ok_or_else(|| {
                bad(format!(
                    "case {}: an input is not three exact numbers",
                    shown(&c.id)
                ))
            })?);
        }
        let refs: Vec<_> = vs.iter().collect();
        let bits = input_bits(&refs);
        // The adaptive scheme is recomputed with both of its methods (`check_in`).
        let diffuse = method.with_picks().into_iter().fold(0u64, |w, m| {
            w.saturating_add(exact_work(m, c.n, bits, DIGITS))
        });
        // The specular expectations run the method again on N·H, then take powers.
        let shiny = match &c.specular {
            Some(sp) if specular => diffuse.saturating_add(specular_work(c.n, sp.s, bits)),
            _ => 0,
        };
        work = work
            .saturating_add(CASE_WORK)
            .saturating_add(diffuse)
            .saturating_add(shiny);
    }
    if work > MAX_RECOMPUTED_WORK {
        return Err(bad(format!(
            "recomputing the expectations of {key} for these cases is {work} units of exact work, \
             more than {MAX_RECOMPUTED_WORK} (about half a minute); split the file"
        )));
    }
    inputs
        .recompute(method, specular)
        .map_err(|e| bad(e.to_string()))
}

/// The verdict as text: a heading line (diffuse or specular, version, set, cases,
/// method), a Markdown table with a row per case, the overall figures and the worst
/// case with its inputs; a case with no bound says why, with `advice`. Every string
/// from the files is [`shown`].
pub(crate) fn text(
    vectors: &VectorFile,
    reports: &[CaseReport],
    results: &super::check::Results,
    key: &str,
    specular: bool,
    advice: super::check::Advice,
) -> String {
    let mut s = format!(
        "{} {} set '{}' ({} cases), method {key}\n",
        if specular { "specular" } else { "diffuse" },
        shown(&vectors.version),
        shown(&vectors.set),
        reports.len()
    );
    let rows: Vec<Vec<String>> = reports
        .iter()
        .map(|r| {
            // A NaN or infinite result fails its case; no difference is printed for it.
            let (abs, ulps) = match r.not_finite {
                Some(p) => (format!("not finite at pixel {p}"), "—".to_string()),
                None if !ulps_mean_something(r) => (format!("{:.3e}", r.max_abs), "—".to_string()),
                None => (format!("{:.3e}", r.max_abs), format!("{:.1}", r.max_ulps)),
            };
            vec![
                shown(&r.id),
                r.pixels.to_string(),
                r.max_levels.to_string(),
                format!("{:.4}", r.mean_levels),
                abs,
                ulps,
                r.unbounded
                    .as_ref()
                    .map_or_else(|| r.allowed.clone(), |u| u.with_advice(advice)),
                times_allowed(r.ratio),
                (if r.pass { "pass" } else { "FAIL" }).to_string(),
            ]
        })
        .collect();
    let (l, r) = (Align::Left, Align::Right);
    let format = reports
        .first()
        .map_or(crate::Format::Binary32, |r| r.format);
    let ulps_head = format!("max ulps ({format})");
    s += &markdown(
        &[
            "case",
            "pixels",
            "max Δlevel",
            "mean Δlevel",
            "max |Δ|",
            &ulps_head,
            "allowed",
            "× allowed",
            "verdict",
        ],
        &[l, r, r, r, r, r, r, r, l],
        &rows,
    );
    let px: usize = reports.iter().map(|r| r.pixels).sum();
    let mean = reports
        .iter()
        .map(|r| r.mean_levels * r.pixels as f64)
        .sum::<f64>()
        / px.max(1) as f64;
    let max_l = reports.iter().map(|r| r.max_levels).max().unwrap_or(0);
    let max_a = reports.iter().map(|r| r.max_abs).fold(0.0, f64::max);
    let max_u = reports
        .iter()
        .filter(|r| r.not_finite.is_none() && ulps_mean_something(r))
        .map(|r| r.max_ulps)
        .fold(0.0, f64::max);
    let margin = reports.iter().map(|r| r.ratio).fold(0.0, f64::max);
    s += &format!("\noverall: {px} pixels, max Δlevel {max_l}, mean Δlevel {mean:.4}, max |Δ| {max_a:.3e}, max {max_u:.1} {format} ulps, largest use of the allowance {}\n", times_allowed(margin));
    if reports
        .iter()
        .any(|r| r.not_finite.is_none() && !ulps_mean_something(r))
    {
        s += &format!("(ulps —: every value of the case is below one level, 2^-8, where ulps of {format} at the values' own scale say nothing of the absolute error the bound allows)\n");
    }
    if let Some(w) = worst(reports) {
        if let Some(c) = vectors.cases.get(w.case) {
            let exp = if specular {
                c.specular.as_ref().and_then(|sp| sp.expected.get(key))
            } else {
                c.expected.get(key)
            };
            let expected = exp
                .and_then(|e| e.values.get(w.worst_pixel))
                .map_or_else(|| "?".to_string(), |v| shown(v));
            let got = results
                .get(&c.id)
                .and_then(|v| v.get(w.worst_pixel))
                .map_or_else(|| "?".to_string(), |g| format!("{g:e}"));
            let what = match (&w.unbounded, w.not_finite) {
                (_, Some(p)) => format!("pixel {p} is not finite"),
                (Some(u), None) => format!("no bound: {}", u.with_advice(advice)),
                (None, None) => format!(
                    "pixel {}: expected {expected}, got {got}, |Δ| {:.3e} = {} allowed, {} levels off",
                    w.worst_pixel,
                    w.max_abs,
                    times_allowed(w.ratio),
                    w.max_levels
                ),
            };
            s += &format!(
                "worst case {} for {key}: {what}; Na = ({}), Nb = ({}), L = ({}), n = {} (the case: {})\n",
                shown(&w.id),
                shown(&c.na.exact.join(", ")),
                shown(&c.nb.exact.join(", ")),
                shown(&c.l.exact.join(", ")),
                c.n,
                shown(&c.comment),
            );
        }
    }
    s
}

/// Whether a case's ulps say something: the tolerance is in ulps, or some value of the
/// case reaches one level (2^-8); below that, ulps at the values' own scale (10^10 of
/// them for values of 10^-8) say nothing of the absolute error every bound allows.
fn ulps_mean_something(r: &CaseReport) -> bool {
    r.allowed.ends_with("ulps") || r.scale >= 1.0 / 256.0
}

/// The run's last line for a CI log: `PASS: all N cases …` or `FAIL: k of N cases …
/// out of tolerance, worst …`, with `what` (the set, method, profile and format).
pub fn verdict_line(reports: &[CaseReport], what: &str) -> String {
    match failure(reports) {
        None => format!(
            "PASS: all {} cases within tolerance ({what})",
            reports.len()
        ),
        Some(m) => format!("FAIL: {m} ({what})"),
    }
}

/// The case that did most harm: the failing case most over its allowance (then the
/// most levels off), or where every case passes the one that used most of it.
pub fn worst(reports: &[CaseReport]) -> Option<&CaseReport> {
    let harm = |a: &&CaseReport, b: &&CaseReport| {
        a.ratio
            .total_cmp(&b.ratio)
            .then(a.max_levels.cmp(&b.max_levels))
            .then(a.max_abs.total_cmp(&b.max_abs))
    };
    reports
        .iter()
        .filter(|r| !r.pass)
        .max_by(harm)
        .or_else(|| reports.iter().max_by(harm))
}

/// `12.3 ×`, `0.412 ×`, `∞ ×`: a ratio to the allowance, as the reports print it.
pub fn times_allowed(r: f64) -> String {
    if r.is_infinite() {
        "∞ ×".into()
    } else if r >= 1e4 {
        format!("{r:.2e} ×")
    } else if r >= 10.0 {
        format!("{r:.1} ×")
    } else {
        format!("{r:.3} ×")
    }
}

/// The one-line message of a failed check: how many cases are out of tolerance and the
/// worst of them ([`worst`]: how far over its allowance, or its first non-finite
/// pixel); `None` when every case passes.
pub fn failure(reports: &[CaseReport]) -> Option<String> {
    let failed = reports.iter().filter(|r| !r.pass).count();
    if failed == 0 {
        return None;
    }
    let w = worst(reports)?;
    Some(format!(
        "{} of {} cases out of tolerance, worst: {}{}",
        failed,
        reports.len(),
        shown(&w.id),
        match (w.not_finite, &w.unbounded) {
            (Some(p), _) => format!(" (pixel {p} is not finite)"),
            (None, Some(u)) => format!(" (no bound: {u})"),
            (None, None) => format!(
                " (pixel {}: {} allowed, {} levels off)",
                w.worst_pixel,
                times_allowed(w.ratio),
                w.max_levels
            ),
        }
    ))
}

// The tests read and write CSV.
#[cfg(all(test, feature = "csv"))]
mod tests {
    use super::*;
    use crate::conformance::check::{check, parse_results, Tolerance};

    const EDGE: &str = include_str!("../../vectors/edge.json");

    /// The edge set cut to its first `k` cases (no longer a published file).
    fn cut(k: usize) -> String {
        let mut v: serde_json::Value = serde_json::from_str(EDGE).unwrap();
        v["cases"].as_array_mut().unwrap().truncate(k);
        v["number_of_cases"] = k.into();
        v.to_string()
    }

    #[test]
    fn a_published_set_is_trusted_and_another_file_refused_or_recomputed() {
        let m = Method::Gouraud;
        let l = load_vectors(EDGE.to_string(), "edge.json", m, false, false).unwrap();
        assert!(!l.recomputed);
        let e = load_vectors(cut(3), "cut.json", m, false, false).unwrap_err();
        assert_eq!(e.culprit, Culprit::Unpublished);
        assert!(e.message.starts_with("cut.json: SHA-256 "), "{e}");
        let r = load_vectors(cut(3), "cut.json", m, false, true).unwrap();
        assert!(r.recomputed);
        assert_eq!(r.file.cases.len(), 3);
        // The recomputed expectations are the published ones, case by case.
        for (a, b) in r.file.cases.iter().zip(&l.file.cases) {
            assert_eq!(a.expected["gouraud"], b.expected["gouraud"]);
        }
    }

    #[test]
    fn refusals_name_the_input_at_fault() {
        let m = Method::Gouraud;
        let e = load_vectors("{".into(), "x.json", m, false, true).unwrap_err();
        assert_eq!(e.culprit, Culprit::Vectors);
        let mut v: serde_json::Value = serde_json::from_str(&cut(2)).unwrap();
        v["methods"] = serde_json::json!(["phong"]);
        let e = load_vectors(v.to_string(), "x.json", m, false, true).unwrap_err();
        assert_eq!(e.culprit, Culprit::Method);
        assert!(e.message.contains("'gouraud' is not in x.json"), "{e}");
        let mut v: serde_json::Value = serde_json::from_str(&cut(2)).unwrap();
        v["cases"][0]["n"] = (MAX_CASE_STEPS + 1).into();
        let e = load_vectors(v.to_string(), "x.json", m, false, true).unwrap_err();
        assert!(e.message.contains("is outside 1..="), "{e}");
        let paper = include_str!("../../vectors/paper.json").to_string();
        let has_specular = serde_json::from_str::<VectorFile>(&paper)
            .unwrap()
            .cases
            .iter()
            .any(|c| c.specular.is_some());
        if !has_specular {
            let e = load_vectors(paper, "paper.json", m, true, false).unwrap_err();
            assert_eq!(e.culprit, Culprit::Specular);
        }
    }

    #[test]
    fn a_file_that_cannot_be_judged_names_the_input_at_fault() {
        use crate::conformance::check::{check_in, shapes, Criteria, JudgeError, Results};
        let m = Method::Gouraud;
        let l = load_vectors(EDGE.to_string(), "edge.json", m, false, false).unwrap();
        let res = Results::new();
        let levels = Criteria::new(m, Tolerance::Levels(0));
        // A method the file does not hold: a cosine table of another size.
        let other = Criteria::new(Method::AngularTable(64), Tolerance::Levels(0));
        let e = check_in(&l.file, &l.shapes, &res, &other);
        let key = "angular-table64".to_string();
        assert_eq!(e.unwrap_err(), JudgeError::Method { key });
        let bad = Criteria::new(m, Tolerance::Abs(f64::NAN));
        let e = check_in(&l.file, &l.shapes, &res, &bad);
        assert!(matches!(e, Err(JudgeError::Tolerance(_))), "{e:?}");
        let e = check_in(&l.file, &[], &res, &levels);
        let cases = l.file.cases.len();
        assert_eq!(e.unwrap_err(), JudgeError::Shapes { shapes: 0, cases });
        // The shapes `load_vectors` read are `shapes`' for the same file.
        assert_eq!(l.shapes, shapes(&l.file));
        // Results that lack a case fail it; they do not panic.
        let r = check_in(&l.file, &l.shapes, &res, &levels);
        assert!(r.unwrap().iter().all(|c| !c.pass));
    }

    #[test]
    fn the_verdict_text_and_failure_line_follow_the_reports() {
        let m = Method::Gouraud;
        let file = load_vectors(EDGE.to_string(), "edge.json", m, false, false)
            .unwrap()
            .file;
        let csv = |scale: f64| {
            let mut s = String::new();
            for c in &file.cases {
                for (i, v) in c.expected["gouraud"].values.iter().enumerate() {
                    let v: f64 = v.parse().unwrap();
                    s += &format!("{},{i},{}\n", c.id, v * scale);
                }
            }
            s
        };
        let tol = Tolerance::Levels(0);
        let run = |scale: f64| {
            let res = parse_results(&csv(scale), "r.csv", &file, false).unwrap();
            check(
                &file,
                &res,
                &crate::conformance::check::Criteria::new(m, tol),
            )
            .unwrap()
        };
        let good = run(1.0);
        assert_eq!(failure(&good), None);
        let res = parse_results(&csv(1.0), "r.csv", &file, false).unwrap();
        let t = text(&file, &good, &res, "gouraud", false, |u| u.kit_advice());
        assert!(t.starts_with(&format!(
            "diffuse {} set 'edge'",
            crate::conformance::vectors::FORMAT_VERSION
        )));
        assert_eq!(t.matches("| pass |").count(), good.len());
        assert!(t.contains("\noverall: ") && t.contains("\nworst case "));
        assert!(verdict_line(&good, "edge").starts_with("PASS: all "));
        let bad = run(0.9);
        let f = failure(&bad).unwrap();
        assert!(verdict_line(&bad, "edge").starts_with("FAIL: "));
        // The worst case is told by what failed for the method judged: its pixel,
        // the expected and the computed value.
        let res = parse_results(&csv(0.9), "r.csv", &file, false).unwrap();
        let t = text(&file, &bad, &res, "gouraud", false, |u| u.kit_advice());
        let line = t.lines().find(|l| l.starts_with("worst case ")).unwrap();
        assert!(
            line.contains(" for gouraud: pixel ")
                && line.contains("expected ")
                && line.contains(", got "),
            "{line}"
        );
        let n = bad.iter().filter(|r| !r.pass).count();
        assert!(
            n > 0 && f.starts_with(&format!("{n} of {} cases", bad.len())),
            "{f}"
        );
    }
}
