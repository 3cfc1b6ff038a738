//! The kit's verdict as data: [`Report`] (every case, ranked failures, margins) and
//! [`Failure`] (one failing case at its worst pixel: inputs, expected, got, allowed,
//! ratio, ulps, levels, the command that reproduces it).

use super::inputs::{Float, Inputs};
use crate::conformance::check::CaseReport;
use crate::conformance::vectors::Case;
use crate::conformance::verdict::times_allowed;
use crate::quantize::level;
use crate::Method;
use std::fmt;

/// The inputs of a failing case: the exact fractions and the floats your function was
/// given (as `f64`, exactly; `format` names their format).
#[derive(Clone, Debug, PartialEq)]
pub struct FailureInputs {
    /// The format of the floats: `f32` or `f64`.
    pub format: &'static str,
    /// `N_a`, `N_b`, `L` as exact fractions.
    pub exact: [[String; 3]; 3],
    /// `N_a`, `N_b`, `L` as given to your function.
    pub floats: [[f64; 3]; 3],
    /// The half vector `H` as given (specular cases), exact and as a float.
    pub h: Option<([String; 3], [f64; 3])>,
    /// The shininess `s` (specular cases).
    pub s: Option<u32>,
}

/// One failing case, at its worst pixel: the values as data (for your own reporting)
/// and as the lines [`Report`]'s `Display` prints (`lines`).
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    /// The set (`typical`, `edge`, `paper`; `span` for [`super::check_span`]; `?`
    /// where the suite itself is wrong: an unknown set or case).
    pub set: &'static str,
    /// The case id, e.g. `edge-003`.
    pub case: String,
    /// Why the case is there.
    pub comment: String,
    /// The steps `n` (the span has `n + 1` pixels).
    pub n: u32,
    /// The inputs (absent where the suite itself is wrong).
    pub inputs: Option<FailureInputs>,
    /// The worst pixel (absent where your function returned the wrong number of
    /// values, or the suite itself is wrong).
    pub pixel: Option<usize>,
    /// The exact expected value at the worst pixel: 30 significant digits.
    pub expected: Option<String>,
    /// Its 8-bit level.
    pub expected_level: Option<u8>,
    /// Your value at the worst pixel (as `f64`, exactly).
    pub got: Option<f64>,
    /// The allowed absolute error, where the tolerance is one.
    pub allowed: Option<f64>,
    /// How far over the allowance the worst pixel is: `|got − expected| / allowed`
    /// (or levels over allowed levels, ulps over allowed ulps); infinite where a
    /// value is missing or not finite, or no bound holds.
    pub ratio: f64,
    /// `|got − expected|` in ulps of the format at the case's scale (the largest
    /// `|expected|` of the span), where both are finite.
    pub ulps: Option<f64>,
    /// `|level(got) − level(expected)|`, where `got` is finite.
    pub levels: Option<u32>,
    /// What judged the case: the profile's bound or the tolerance.
    pub profile: String,
    /// The tolerance in words (the allowance, or why there is none).
    pub allowed_text: String,
    /// The `phong-approx span` command that computes the case's exact values.
    pub command: Option<String>,
    /// The lines the report prints for this failure.
    pub lines: Vec<String>,
}

/// Your function's inputs for case `c` of a vector file (its nearest floats), with the
/// specular half vector and shininess where the case has them.
pub(crate) fn case_inputs<'a, T: Float>(c: &'a Case) -> Inputs<'a, T> {
    Inputs::of_case(c)
}

fn shown_inputs<T: Float>(what: &str, exact: &[String; 3], v: [T; 3]) -> String {
    let parts: Vec<String> = v
        .iter()
        .zip(exact)
        .map(|(x, e)| format!("{x} ({}; exactly {e})", x.hex()))
        .collect();
    format!("{what:<9} = ({})", parts.join(", "))
}

/// The context a failure is built in: the set, the judge, the format's name.
pub(crate) struct Judged<'a> {
    pub(crate) set: &'static str,
    pub(crate) key: &'a str,
    pub(crate) profile: &'a str,
    pub(crate) specular: bool,
    pub(crate) format: crate::Format,
}

impl Failure {
    /// A failure of the suite itself (an unknown set or case, a method the sets do not
    /// hold): no inputs, infinitely over.
    pub(crate) fn of_suite(set: &'static str, case: String, profile: &str, why: String) -> Failure {
        Failure {
            set,
            case,
            comment: String::new(),
            n: 0,
            inputs: None,
            pixel: None,
            expected: None,
            expected_level: None,
            got: None,
            allowed: None,
            ratio: f64::INFINITY,
            ulps: None,
            levels: None,
            profile: profile.to_string(),
            allowed_text: String::new(),
            command: None,
            lines: vec![why],
        }
    }

    /// The failure of case `c` as `check` judged it (`r`), with your values `got`.
    pub(crate) fn new<T: Float>(j: &Judged, c: &Case, r: &CaseReport, got: &[f64]) -> Failure {
        let exp = if j.specular {
            c.specular.as_ref().and_then(|sp| sp.expected.get(j.key))
        } else {
            c.expected.get(j.key)
        };
        let inputs = case_inputs::<T>(c);
        let mut lines = vec![format!("{}/{} (n = {}): {}", j.set, c.id, c.n, c.comment)];
        lines.push(shown_inputs::<T>("N_a", &c.na.exact, inputs.na));
        lines.push(shown_inputs::<T>("N_b", &c.nb.exact, inputs.nb));
        lines.push(shown_inputs::<T>("L", &c.l.exact, inputs.l));
        if let (Some(sp), Some(h), true) = (&c.specular, inputs.h, j.specular) {
            lines.push(shown_inputs::<T>("H", &sp.h.exact, h));
            lines.push(format!("s         = {}", sp.s));
        }
        let mut f = Failure {
            set: j.set,
            case: c.id.clone(),
            comment: c.comment.clone(),
            n: c.n,
            inputs: Some(FailureInputs {
                format: T::FORMAT.name(),
                exact: [c.na.exact.clone(), c.nb.exact.clone(), c.l.exact.clone()],
                floats: [inputs.na, inputs.nb, inputs.l].map(|v| v.map(T::to_f64)),
                h: match (&c.specular, inputs.h, j.specular) {
                    (Some(sp), Some(h), true) => Some((sp.h.exact.clone(), h.map(T::to_f64))),
                    _ => None,
                },
                s: inputs.s.filter(|_| j.specular),
            }),
            pixel: None,
            expected: None,
            expected_level: None,
            got: None,
            allowed: r.worst_allowed,
            ratio: r.ratio,
            ulps: None,
            levels: None,
            profile: j.profile.to_string(),
            allowed_text: allowed_text(r),
            command: Some(c.reproduce(j.key, j.specular)),
            lines: Vec::new(),
        };
        match exp {
            Some(exp) if got.len() == c.n as usize + 1 => {
                let i = r.worst_pixel;
                let e: f64 = exp.values[i].parse().unwrap_or(f64::NAN);
                let g = got[i];
                f.pixel = Some(i);
                f.expected = Some(exp.values[i].clone());
                f.expected_level = Some(exp.levels[i]);
                f.got = Some(g);
                lines.push(format!("pixel     = {i} (the worst of the case)"));
                lines.push(format!(
                    "expected  = {} (level {})",
                    exp.values[i], exp.levels[i]
                ));
                let gt = T::from_f64(g);
                if g.is_finite() {
                    let scale = r.scale.max(e.abs());
                    let ulps = (g - e).abs() / j.format.ulp(scale);
                    let dl = u32::from(level(&g).abs_diff(exp.levels[i]));
                    f.ulps = Some(ulps);
                    f.levels = Some(dl);
                    lines.push(format!(
                        "got       = {gt} ({}) (level {})",
                        gt.hex(),
                        level(&g)
                    ));
                    lines.push(format!(
                        "off by    = {:.3e} = {:.1} {} ulps at the span's scale {:.3}, {dl} levels",
                        (g - e).abs(),
                        ulps,
                        T::FORMAT.name(),
                        scale
                    ));
                } else {
                    lines.push(format!("got       = {gt} ({})", gt.hex()));
                    lines.push("off by    = not finite".into());
                }
            }
            _ => lines.push(format!(
                "returned {} values; the span has n + 1 = {} pixels",
                got.len(),
                c.n + 1
            )),
        }
        lines.push(format!("allowed   = {}{}", allowed_text(r), times(r.ratio)));
        lines.push(format!(
            "reproduce = {}",
            f.command.as_deref().unwrap_or("")
        ));
        f.lines = lines;
        f
    }
}

/// ` (the worst pixel is off by 12.3 × this)`, or nothing where no ratio means
/// anything.
fn times(ratio: f64) -> String {
    if ratio.is_finite() {
        format!(" (the worst pixel is off by {} this)", times_allowed(ratio))
    } else {
        String::new()
    }
}

/// One set's part of a [`Report`].
#[derive(Clone, Debug, PartialEq)]
pub struct SetSummary {
    /// The set.
    pub set: &'static str,
    /// Cases judged.
    pub cases: usize,
    /// Cases that failed.
    pub failed: usize,
    /// The largest fraction of its allowance any case of the set used (its worst
    /// pixel's [`Failure::ratio`]): below 1 for a set that passes, its margin.
    pub margin: f64,
    /// The case that used it.
    pub worst_case: Option<String>,
}

/// The verdict on every case: inspect it, or [`Report::assert_ok`] in a test.
/// Failures are ranked by harm: the most over its allowance first (then by levels).
#[derive(Clone, Debug)]
pub struct Report {
    pub(crate) method: Method,
    pub(crate) judged_by: String,
    pub(crate) format: &'static str,
    pub(crate) cases: usize,
    pub(crate) failures: Vec<Failure>,
    pub(crate) sets: Vec<SetSummary>,
}

/// How many failures a report prints in full.
const SHOWN_FAILURES: usize = 5;

impl Report {
    pub(crate) fn new(method: Method, judged_by: String, format: &'static str) -> Report {
        Report {
            method,
            judged_by,
            format,
            cases: 0,
            failures: Vec::new(),
            sets: Vec::new(),
        }
    }

    /// Adds one set's judged cases (`reports`, from `check`) and their failures.
    pub(crate) fn add_set(
        &mut self,
        set: &'static str,
        reports: &[CaseReport],
        failures: Vec<Failure>,
    ) {
        let worst = reports.iter().max_by(|a, b| a.ratio.total_cmp(&b.ratio));
        self.sets.push(SetSummary {
            set,
            cases: reports.len(),
            failed: failures.len(),
            margin: worst.map_or(0.0, |r| r.ratio),
            worst_case: worst.map(|r| r.id.clone()),
        });
        self.cases += reports.len();
        self.failures.extend(failures);
        self.rank();
    }

    /// Adds a failure of the suite itself.
    pub(crate) fn add_failure(&mut self, f: Failure) {
        self.failures.push(f);
        self.rank();
    }

    fn rank(&mut self) {
        self.failures.sort_by(|a, b| {
            b.ratio
                .total_cmp(&a.ratio)
                .then(b.levels.unwrap_or(0).cmp(&a.levels.unwrap_or(0)))
        });
    }

    /// Whether every case passed.
    pub fn is_ok(&self) -> bool {
        self.failures.is_empty()
    }

    /// The failing cases, the most harmful first (by [`Failure::ratio`], then levels).
    pub fn failures(&self) -> &[Failure] {
        &self.failures
    }

    /// The worst failure, if any.
    pub fn worst(&self) -> Option<&Failure> {
        self.failures.first()
    }

    /// Per set: cases, failures and the margin (the largest fraction of the
    /// allowance used).
    pub fn sets(&self) -> &[SetSummary] {
        &self.sets
    }

    /// The largest fraction of its allowance any case used, over every set: below 1
    /// when the report passes (how close the implementation came to failing).
    pub fn margin(&self) -> f64 {
        self.sets.iter().map(|s| s.margin).fold(0.0, f64::max)
    }

    /// The number of cases judged.
    pub fn cases(&self) -> usize {
        self.cases
    }

    /// The method judged.
    pub fn method(&self) -> Method {
        self.method
    }

    /// Panics with the report when a case failed.
    ///
    /// # Panics
    /// When [`Report::is_ok`] is false.
    #[track_caller]
    pub fn assert_ok(&self) {
        if !self.is_ok() {
            panic!("{self}");
        }
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{} in {} judged by {}: {} of {} cases fail",
            crate::conformance::vectors::method_key(self.method),
            self.format,
            self.judged_by,
            self.failures.len(),
            self.cases
        )?;
        let per_set: Vec<String> = self
            .sets
            .iter()
            .map(|s| {
                format!(
                    "{} {} of {} ({} {} allowed)",
                    s.set,
                    s.failed,
                    s.cases,
                    if s.failed > 0 {
                        "worst"
                    } else {
                        "margin: uses"
                    },
                    times_allowed(s.margin)
                )
            })
            .collect();
        if !per_set.is_empty() {
            writeln!(f, "  per set: {}", per_set.join("; "))?;
        }
        if let Some(w) = self.worst() {
            let at = match (w.pixel, w.levels) {
                (Some(i), Some(l)) => format!(" pixel {i}, {l} levels off,"),
                (Some(i), None) => format!(" pixel {i}, not finite,"),
                _ => String::new(),
            };
            writeln!(
                f,
                "  worst: {}/{}{at} {} allowed (failures follow, worst first)",
                w.set,
                w.case,
                times_allowed(w.ratio)
            )?;
        }
        for fl in self.failures.iter().take(SHOWN_FAILURES) {
            writeln!(f)?;
            for l in &fl.lines {
                writeln!(f, "  {l}")?;
            }
        }
        if self.failures.len() > SHOWN_FAILURES {
            let rest: Vec<String> = self.failures[SHOWN_FAILURES..]
                .iter()
                .map(|fl| format!("{} ({})", fl.case, times_allowed(fl.ratio)))
                .collect();
            writeln!(f, "\n  and {} more: {}", rest.len(), rest.join(", "))?;
        }
        Ok(())
    }
}

/// The tolerance of `r` in words, with the test kit's advice where it has none.
fn allowed_text(r: &crate::conformance::check::CaseReport) -> String {
    match (&r.unbounded, r.worst_allowed) {
        (Some(u), _) => u.with_advice(crate::conformance::check::Unbounded::kit_advice),
        // The worst pixel's own allowance, where it differs from the case's largest.
        (None, Some(w)) if Some(w) != r.allowed_abs => format!("{w:.3e} at this pixel"),
        (None, _) => r.allowed.clone(),
    }
}
