//! Reading an implementation's results: CSV rows `case,pixel,value` (an optional
//! header `case,pixel,value`, blank lines and `#` comments allowed), or JSON
//! `{"cases": [{"id": "...", "values": [v0, v1, …]}]}` with numbers or decimal
//! strings. Every case of the vector file must be present with every pixel `0..=n`
//! exactly once. Both readers stream: what they build is bounded by the vector file.

use crate::conformance::vectors::VectorFile;
use std::collections::HashMap;

mod json;

/// The largest results or vector file read (reading stops there, whatever the file).
pub const MAX_RESULTS_BYTES: u64 = 256 << 20;

/// A problem with an input file: the file, the line (0 when not tied to one) and what.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}{}: {message}", file, line_part(*line))]
pub struct InputError {
    /// The file's name as given.
    pub file: String,
    /// 1-based line, or 0.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

/// `:line` after the file's name, nothing for line 0 (not tied to a line).
fn line_part(line: usize) -> String {
    if line > 0 {
        format!(":{line}")
    } else {
        String::new()
    }
}

/// The results read from a file: per case id, the value at each pixel.
pub type Results = HashMap<String, Vec<f64>>;

fn err(file: &str, line: usize, message: impl Into<String>) -> InputError {
    InputError {
        file: file.to_string(),
        line,
        message: message.into(),
    }
}

/// The number of pixels each case of `vectors` needs, by id.
fn sizes(vectors: &VectorFile, specular: bool) -> HashMap<&str, usize> {
    vectors
        .cases
        .iter()
        .filter(|c| !specular || c.specular.is_some())
        .map(|c| (c.id.as_str(), c.n as usize + 1))
        .collect()
}

/// A value: a decimal number, or `nan`/`inf`/`infinity` (any case, signed), which an
/// implementation may well produce and which then fails its pixel (exit 1, named), not
/// the file.
#[cfg(feature = "csv")]
fn parse_value(file: &str, line: usize, s: &str) -> Result<f64, InputError> {
    let t = s.trim();
    let v: f64 = t.parse().map_err(|_| {
        err(
            file,
            line,
            format!("value '{}' is not a number", crate::conformance::shown(t)),
        )
    })?;
    if v.is_infinite() && !t.to_ascii_lowercase().contains("inf") {
        return Err(err(file, line, out_of_range(t)));
    }
    if underflows(t, v) {
        return Err(err(file, line, below_range(t)));
    }
    Ok(v)
}

/// The refusal of a decimal beyond `f64`'s range (CSV and JSON alike: no float
/// implementation prints one; an infinite result is written `inf`).
fn out_of_range(t: &str) -> String {
    format!(
        "value '{}' is outside the range of f64 (an infinite result is written inf, or \"inf\" in JSON)",
        crate::conformance::shown(t)
    )
}

/// Whether the decimal `t`, read as `v`, is a non-zero number that reads as zero:
/// below the smallest `f64` (a subnormal, about 4.9e-324).
pub(crate) fn underflows(t: &str, v: f64) -> bool {
    let mantissa = t.split(['e', 'E']).next().unwrap_or("");
    v == 0.0 && mantissa.bytes().any(|b| (b'1'..=b'9').contains(&b))
}

/// The refusal of a non-zero decimal below `f64`'s range, as [`out_of_range`] refuses
/// one above it: no float implementation prints one, and reading it as 0 would judge
/// a value the implementation did not compute.
pub(crate) fn below_range(t: &str) -> String {
    format!(
        "value '{}' is below the range of f64 (its magnitude is under the smallest f64, about 4.9e-324): no float implementation prints it; a result of zero is written 0",
        crate::conformance::shown(t)
    )
}

/// The number literal that ends at 1-based `line` and `column` of `text` (where
/// serde_json reports a number out of range), for the message.
fn number_at(text: &str, line: usize, column: usize) -> Option<&str> {
    let l = text.lines().nth(line.checked_sub(1)?)?;
    let end = column.min(l.len());
    let is_num = |c: char| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '+' | '-');
    let head = l.get(..end)?;
    let start = head
        .char_indices()
        .rev()
        .find(|&(_, c)| !is_num(c))
        .map_or(0, |(k, c)| k + c.len_utf8());
    let end = l[start..]
        .find(|c: char| !is_num(c))
        .map_or(l.len(), |k| start + k);
    let t = &l[start..end];
    (!t.is_empty()).then_some(t)
}

/// The first number literal of the JSON `text` (outside strings) that is non-zero but
/// reads as zero ([`underflows`]), with its 1-based line: serde_json reads it as 0
/// without a word.
fn json_underflow(text: &str) -> Option<(usize, &str)> {
    let bytes = text.as_bytes();
    let (mut i, mut line, mut in_string) = (0, 1, false);
    while i < bytes.len() {
        let b = bytes[i];
        if b == b'\n' {
            line += 1;
        }
        if in_string {
            match b {
                b'\\' => i += 1,
                b'"' => in_string = false,
                _ => {}
            }
            i += 1;
            continue;
        }
        if b == b'"' {
            in_string = true;
            i += 1;
            continue;
        }
        if b == b'-' || b.is_ascii_digit() {
            let start = i;
            while i < bytes.len()
                && (bytes[i].is_ascii_digit()
                    || matches!(bytes[i], b'.' | b'e' | b'E' | b'+' | b'-'))
            {
                i += 1;
            }
            let t = &text[start..i];
            if t.parse::<f64>().is_ok_and(|v| underflows(t, v)) {
                return Some((line, t));
            }
            continue;
        }
        i += 1;
    }
    None
}

/// The values of one case as they are read: the value and the 1-based line of each
/// pixel (line 0: not read yet). Twelve bytes per pixel the vector file asks for, so
/// what is built from a results file is bounded by the vector file, not by the
/// results file.
struct Reading {
    values: Vec<f64>,
    lines: Vec<u32>,
}

impl Reading {
    fn new(len: usize) -> Reading {
        Reading {
            values: vec![0.0; len],
            lines: vec![0; len],
        }
    }
}

/// Checks that every needed case and pixel is present.
fn complete(
    file: &str,
    vectors: &VectorFile,
    specular: bool,
    mut got: HashMap<String, Reading>,
) -> Result<Results, InputError> {
    let mut out = Results::new();
    for c in vectors
        .cases
        .iter()
        .filter(|c| !specular || c.specular.is_some())
    {
        let Some(r) = got.remove(&c.id) else {
            return Err(err(
                file,
                0,
                format!(
                    "at end of file: case {} is missing (every case of the vector file is needed)",
                    crate::conformance::shown(&c.id)
                ),
            ));
        };
        if let Some(i) = r.lines.iter().position(|&l| l == 0) {
            return Err(err(
                file,
                0,
                format!(
                    "at end of file: case {} has no value for pixel {i}",
                    crate::conformance::shown(&c.id)
                ),
            ));
        }
        out.insert(c.id.clone(), r.values);
    }
    Ok(out)
}

/// The longest line a CSV results file may have: a row is `case,pixel,value`, so a
/// longer line is not a result (and a line of millions of separators would otherwise
/// be split into millions of fields before it could be refused).
pub const MAX_CSV_LINE: usize = 4096;

/// Parses CSV results (see the module docs). Reading stops at the first problem;
/// what it builds is twelve bytes per pixel the vector file asks for, whatever the
/// results file holds.
///
/// # Errors
/// An [`InputError`] naming the line: a line longer than [`MAX_CSV_LINE`], a missing,
/// extra or empty column, a non-number, an unknown case id, a pixel out of range, a
/// duplicate row, an empty file, or (at the end) a missing case or pixel.
#[cfg(feature = "csv")]
pub fn parse_results_csv(
    text: &str,
    file: &str,
    vectors: &VectorFile,
    specular: bool,
) -> Result<Results, InputError> {
    let need = sizes(vectors, specular);
    // RFC 4180 (quoted fields, CRLF), a UTF-8 byte-order mark, `#` comments.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if let Some((k, l)) = text
        .split('\n')
        .map(|l| l.strip_suffix('\r').unwrap_or(l))
        .enumerate()
        .find(|(_, l)| l.len() > MAX_CSV_LINE)
    {
        return Err(err(
            file,
            k + 1,
            format!(
                "the line is {} bytes long (at most {MAX_CSV_LINE}); a row is case,pixel,value",
                l.len()
            ),
        ));
    }
    let mut got: HashMap<String, Reading> = HashMap::new();
    let mut rows = 0usize;
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let mut record = csv::StringRecord::new();
    loop {
        match reader.read_record(&mut record) {
            Ok(true) => {}
            Ok(false) => break,
            Err(e) => {
                let line = e.position().map_or(0, |p| p.line() as usize);
                return Err(err(file, line, format!("not CSV: {e}")));
            }
        }
        let line = record.position().map_or(0, |p| p.line() as usize);
        if record.len() == 1 && record[0].is_empty() {
            continue; // a blank line
        }
        if rows == 0
            && record.get(0).is_some_and(|c| {
                c.eq_ignore_ascii_case("case") || c.eq_ignore_ascii_case("case_id")
            })
        {
            if record.len() != 3 {
                return Err(err(
                    file,
                    line,
                    format!(
                        "the header has {} columns, expected case,pixel,value",
                        record.len()
                    ),
                ));
            }
            rows += 1;
            continue;
        }
        rows += 1;
        if record.len() != 3 {
            return Err(err(
                file,
                line,
                format!(
                    "expected 3 columns (case,pixel,value), found {}",
                    record.len()
                ),
            ));
        }
        let (id, px, val) = (&record[0], &record[1], &record[2]);
        if id.is_empty() {
            return Err(err(file, line, "the case field is empty"));
        }
        let Some(&len) = need.get(id) else {
            return Err(err(
                file,
                line,
                format!("unknown case id '{}'", crate::conformance::shown(id)),
            ));
        };
        for (k, what) in [(px, "pixel"), (val, "value")] {
            if k.is_empty() {
                return Err(err(file, line, format!("the {what} field is empty")));
            }
        }
        let pixel: usize = px.parse().map_err(|_| {
            err(
                file,
                line,
                format!(
                    "pixel '{}' is not a whole number",
                    crate::conformance::shown(px)
                ),
            )
        })?;
        if pixel >= len {
            return Err(err(
                file,
                line,
                format!(
                    "pixel {pixel} is out of range for case {id} (pixels 0..={})",
                    len - 1
                ),
            ));
        }
        let v = parse_value(file, line, val)?;
        let r = got
            .entry(id.to_string())
            .or_insert_with(|| Reading::new(len));
        if r.lines[pixel] != 0 {
            return Err(err(
                file,
                line,
                format!(
                    "duplicate row for case {id} pixel {pixel} (first at line {})",
                    r.lines[pixel]
                ),
            ));
        }
        r.values[pixel] = v;
        r.lines[pixel] = u32::try_from(line).unwrap_or(u32::MAX).max(1);
    }
    if got.is_empty() {
        return Err(err(file, 1, "the file holds no results"));
    }
    complete(file, vectors, specular, got)
}

/// Parses JSON results (see the module docs), streaming: each case's values are read
/// into an array of the size its vector-file case needs, and reading stops at the
/// first problem, so what is built is bounded by the vector file whatever the results
/// file holds.
///
/// # Errors
/// An [`InputError`]: malformed JSON (with its line), an unknown or duplicate case id,
/// a wrong number of values, a non-number, or a missing case.
pub fn parse_results_json(
    text: &str,
    file: &str,
    vectors: &VectorFile,
    specular: bool,
) -> Result<Results, InputError> {
    use serde::de::DeserializeSeed;
    if text.trim().is_empty() {
        return Err(err(file, 1, "the file holds no results"));
    }
    if let Some((line, t)) = json_underflow(text) {
        return Err(err(file, line, below_range(t)));
    }
    let need = sizes(vectors, specular);
    let ctx = json::Ctx {
        need: &need,
        longest: need.values().copied().max().unwrap_or(0),
        got: std::cell::RefCell::new(HashMap::new()),
        problem: std::cell::RefCell::new(None),
    };
    let mut de = serde_json::Deserializer::from_str(text);
    json::File(&ctx)
        .deserialize(&mut de)
        .and_then(|()| de.end())
        .map_err(|e| {
            let message = match ctx.problem.borrow_mut().take() {
                Some(m) => m,
                None if e.to_string().starts_with("number out of range") => {
                    out_of_range(number_at(text, e.line(), e.column()).unwrap_or("a number"))
                }
                None => format!("not a results file: {e}"),
            };
            err(file, e.line(), message)
        })?;
    complete(file, vectors, specular, ctx.got.into_inner())
}

/// Each value of `results` (read as the `f64` nearest its decimal) as the value of
/// `format` nearest that decimal — the number the implementation computed, whose
/// shortest decimal is what it prints — so that a verdict compares that number, not a
/// decimal up to half an ulp away. For `f32` the `f64` is rounded again, which is the
/// decimal's own rounding except where the `f64` is exactly halfway between two `f32`
/// (a decimal within 2^-53 of such a midpoint): such a value denotes no one `f32` and
/// is refused. A finite value beyond the format's range, or non-zero and rounding to
/// zero in it, is refused as one beyond `f64`'s is; NaN and infinities stay (they fail
/// their pixel). Binary64 leaves the values as they are; fixed point and binary16
/// results are judged as read.
///
/// # Errors
/// An [`InputError`] naming the file, the case and the value.
pub fn denote(results: &mut Results, file: &str, format: crate::Format) -> Result<(), InputError> {
    if format != crate::Format::Binary32 {
        return Ok(());
    }
    let mut ids: Vec<&String> = results.keys().collect();
    ids.sort();
    let mut bad = None;
    for id in ids {
        for (i, v) in results[id].iter().enumerate() {
            if !v.is_finite() {
                continue;
            }
            let f = *v as f32;
            let why = if f.is_infinite() {
                Some("is outside the range of f32 (an infinite result is written inf)")
            } else if f == 0.0 && *v != 0.0 {
                Some("is below the range of f32 (under its smallest subnormal, about 1.4e-45): a result of zero is written 0")
            } else {
                // Halfway between two f32: f lies on one side; the neighbour on the other.
                let next = if f64::from(f) < *v {
                    f.next_up()
                } else {
                    f.next_down()
                };
                let mid = (f64::from(f) + f64::from(next)) / 2.0;
                (mid == *v).then_some("lies halfway between two f32 (within 2^-53 of the midpoint): it denotes no one f32; write the float's shortest decimal")
            };
            if let Some(why) = why {
                bad = Some(format!(
                    "case {}: value {i} ({v:e}) {why}",
                    crate::conformance::shown(id)
                ));
                break;
            }
        }
        if bad.is_some() {
            break;
        }
    }
    if let Some(m) = bad {
        return Err(err(file, 0, m));
    }
    for vals in results.values_mut() {
        for v in vals.iter_mut() {
            if v.is_finite() {
                *v = f64::from(*v as f32);
            }
        }
    }
    Ok(())
}

/// Parses results by content: JSON when the first non-blank character is `{`.
///
/// # Errors
/// As [`parse_results_csv`] / [`parse_results_json`].
#[cfg(feature = "csv")]
pub fn parse_results(
    text: &str,
    file: &str,
    vectors: &VectorFile,
    specular: bool,
) -> Result<Results, InputError> {
    // JSON by its first character (after a byte-order mark): an object, or an array
    // (refused by the JSON reader with its own message, not misread as CSV).
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.trim_start().starts_with(['{', '[']) {
        parse_results_json(text, file, vectors, specular)
    } else {
        parse_results_csv(text, file, vectors, specular)
    }
}
