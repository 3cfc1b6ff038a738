//! Machine-readable reports of a check, for other languages' CI: JUnit XML (one test
//! case per vector case) and JSON, rendered from a judgement
//! ([`super::judgement::Judgement::junit`], [`super::judgement::Judgement::json`]).
//! Every text taken from a vector file or a results file goes through
//! [`super::shown`] (cut and escaped) and then the format's own escaping.

use super::check::{Advice, CaseReport, Results};
use super::judgement::Judgement;
use super::shown;
use super::vectors::VectorFile;

/// What a report says of one case: the verdict and, at the worst pixel, the expected
/// and the submitted value.
struct Row<'a> {
    r: &'a CaseReport,
    comment: String,
    /// The case's inputs: exact, and the nearest floats of the format judged.
    inputs: String,
    /// The `phong-approx span` command that reproduces the case.
    command: String,
    expected: Option<String>,
    got: Option<f64>,
}

fn rows<'a>(
    vectors: &VectorFile,
    reports: &'a [CaseReport],
    results: &Results,
    key: &str,
    specular: bool,
) -> Vec<Row<'a>> {
    reports
        .iter()
        .map(|r| {
            let case = vectors.cases.get(r.case);
            let exp = case.and_then(|c| {
                if specular {
                    c.specular.as_ref().and_then(|s| s.expected.get(key))
                } else {
                    c.expected.get(key)
                }
            });
            // Each piece of text from the file is shown (cut and escaped) on its own;
            // the vector file was validated, so its numbers are short.
            let inputs = case.map_or(String::new(), |c| {
                let list =
                    |v: &[String; 3]| v.iter().map(|x| shown(x)).collect::<Vec<_>>().join(", ");
                let floats = |v: &super::vectors::VectorInput| {
                    list(match r.format {
                        crate::Format::Binary64 => &v.f64,
                        crate::Format::Binary32 | crate::Format::Binary16 => &v.f32,
                    })
                };
                let mut t = format!(
                    "n = {}; N_a = ({}) = ({}); N_b = ({}) = ({}); L = ({}) = ({})",
                    c.n,
                    list(&c.na.exact),
                    floats(&c.na),
                    list(&c.nb.exact),
                    floats(&c.nb),
                    list(&c.l.exact),
                    floats(&c.l),
                );
                if let (Some(sp), true) = (&c.specular, specular) {
                    t += &format!(
                        "; H = ({}) = ({}); s = {}",
                        list(&sp.h.exact),
                        floats(&sp.h),
                        sp.s
                    );
                }
                t
            });
            let command = case.map_or(String::new(), |c| c.reproduce_shown(key, specular, shown));
            Row {
                r,
                comment: case.map_or(String::new(), |c| shown(&c.comment)),
                inputs,
                command,
                expected: exp
                    .and_then(|e| e.values.get(r.worst_pixel))
                    .map(|v| shown(v)),
                got: results
                    .get(&r.id)
                    .and_then(|v| v.get(r.worst_pixel))
                    .copied(),
            }
        })
        .collect()
}

/// `x` escaped for XML text and attribute values.
fn xml(x: &str) -> String {
    let mut out = String::with_capacity(x.len());
    for c in x.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            // XML 1.0 allows no other control character, even escaped, nor U+FFFE
            // and U+FFFF (its Char production: #x9 | #xA | #xD | [#x20-#xD7FF] |
            // [#xE000-#xFFFD] | [#x10000-#x10FFFF]; surrogates cannot be in a str).
            c if (c.is_control() && !matches!(c, '\n' | '\t'))
                || matches!(c, '\u{fffe}' | '\u{ffff}') =>
            {
                out.push('\u{fffd}')
            }
            c => out.push(c),
        }
    }
    out
}

fn got_text(g: Option<f64>) -> String {
    match g {
        Some(g) if g.is_finite() => format!("{g:e}"),
        Some(_) => "not finite".to_string(),
        None => "missing".to_string(),
    }
}

/// The failure line of a case: where, expected, got, allowed.
fn why(row: &Row, advice: Advice) -> String {
    format!(
        "pixel {}: expected {}, got {}, max |Δ| {}, allowed {}",
        row.r.worst_pixel,
        row.expected.as_deref().unwrap_or("?"),
        got_text(row.got),
        if row.r.not_finite.is_some() {
            "not finite".to_string()
        } else {
            format!("{:.3e}", row.r.max_abs)
        },
        allowed_text(row.r, advice)
    )
}

/// The tolerance of `r` in words, with the caller's advice where it has none.
fn allowed_text(r: &super::check::CaseReport, advice: Advice) -> String {
    r.unbounded
        .as_ref()
        .map_or_else(|| r.allowed.clone(), |u| u.with_advice(advice))
}

/// A JUnit XML report: one `<testsuite>` named `suite` (set, method, profile), one
/// `<testcase>` per vector case, a `<failure>` with the worst pixel for each failing
/// one.
fn junit(suite: &str, j: &Judgement, advice: Advice) -> String {
    let (vectors, key) = (j.vectors, j.key.as_str());
    let rows = rows(vectors, &j.reports, j.results, key, j.specular);
    let failures = rows.iter().filter(|r| !r.r.pass).count();
    let mut s = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    s += &format!(
        "<testsuites name=\"phong-approx check\" tests=\"{}\" failures=\"{failures}\">\n",
        rows.len()
    );
    let total: f64 = rows.iter().map(|r| r.r.seconds).sum();
    s += &format!(
        "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{failures}\" errors=\"0\" skipped=\"0\" time=\"{total:.6}\">\n",
        xml(&shown(suite)),
        rows.len()
    );
    for row in &rows {
        s += &format!(
            "    <testcase classname=\"{}\" name=\"{}\" time=\"{:.6}\"",
            xml(&format!("{}.{}", shown(&vectors.set), key)),
            xml(&shown(&row.r.id)),
            row.r.seconds
        );
        if row.r.pass {
            s += "/>\n";
        } else {
            s += &format!(
                ">\n      <failure message=\"{}\" type=\"out of tolerance\">{}</failure>\n    </testcase>\n",
                xml(&why(row, advice)),
                xml(&format!(
                    "{}\n{} pixels, max Δlevel {}, worst pixel {}: {} × allowed\ninputs ({}): {}\nreproduce: {}",
                    row.comment,
                    row.r.pixels,
                    row.r.max_levels,
                    row.r.worst_pixel,
                    if row.r.ratio.is_finite() { format!("{:.3}", row.r.ratio) } else { "∞".into() },
                    row.r.format,
                    row.inputs,
                    row.command
                ))
            );
        }
    }
    s += "  </testsuite>\n</testsuites>\n";
    s
}

/// A JSON report: the suite, counts, and per case the verdict and the worst pixel.
fn json(suite: &str, j: &Judgement, advice: Advice) -> String {
    let (vectors, key) = (j.vectors, j.key.as_str());
    let rows = rows(vectors, &j.reports, j.results, key, j.specular);
    let num = |x: f64| {
        if x.is_finite() {
            serde_json::json!(x)
        } else {
            serde_json::Value::Null
        }
    };
    let cases: Vec<serde_json::Value> = rows
        .iter()
        .map(|row| {
            serde_json::json!({
                "id": shown(&row.r.id),
                "pass": row.r.pass,
                "pixels": row.r.pixels,
                "worst_pixel": row.r.worst_pixel,
                "expected": row.expected,
                "got": row.got.map(num),
                "not_finite_pixel": row.r.not_finite,
                "max_abs": if row.r.not_finite.is_some() { serde_json::Value::Null } else { num(row.r.max_abs) },
                "max_levels": row.r.max_levels,
                "allowed": allowed_text(row.r, advice),
                "allowed_abs": row.r.allowed_abs.map(num),
                "ratio": num(row.r.ratio),
                "seconds": row.r.seconds,
                "inputs": row.inputs,
                "reproduce": row.command,
            })
        })
        .collect();
    let failed = rows.iter().filter(|r| !r.r.pass).count();
    let v = serde_json::json!({
        "generator": concat!("phong-approx ", env!("CARGO_PKG_VERSION"), " check"),
        "suite": shown(suite),
        "set": shown(&vectors.set),
        "method": key,
        "tests": rows.len(),
        "failures": failed,
        "cases": cases,
    });
    serde_json::to_string_pretty(&v).expect("a JSON value") + "\n"
}

impl Judgement<'_> {
    /// A JUnit XML report: one `<testsuite>` named `suite`, one `<testcase>` per case,
    /// a `<failure>` with the worst pixel for each failing one.
    pub fn junit(&self, suite: &str, advice: Advice) -> String {
        junit(suite, self, advice)
    }

    /// A JSON report named `suite`: the counts, and per case the verdict and the worst
    /// pixel.
    pub fn json(&self, suite: &str, advice: Advice) -> String {
        json(suite, self, advice)
    }
}
