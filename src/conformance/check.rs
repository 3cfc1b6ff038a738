//! Checking an implementation's results against a vector file.
//!
//! Results are CSV rows `case,pixel,value` (an optional header `case,pixel,value`,
//! blank lines and `#` comments allowed), or JSON
//! `{"cases": [{"id": "...", "values": [v0, v1, …]}]}` with numbers or decimal
//! strings. Every case of the vector file must be present with every pixel `0..=n`
//! exactly once.

use super::vectors::{Case, Expected, VectorFile};
use crate::method::Method;
use crate::quantize::level;
use std::collections::HashMap;
use std::fmt;

/// The largest results or vector file read (reading stops there, whatever the file).
pub const MAX_RESULTS_BYTES: u64 = 256 << 20;

/// A problem with an input file: the file, the line (0 when not tied to one) and what.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InputError {
    /// The file's name as given.
    pub file: String,
    /// 1-based line, or 0.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line > 0 {
            write!(f, "{}:{}: {}", self.file, self.line, self.message)
        } else {
            write!(f, "{}: {}", self.file, self.message)
        }
    }
}

impl std::error::Error for InputError {}

/// How close a result must be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tolerance {
    /// At most this many 8-bit levels from the expected level.
    Levels(u32),
    /// At most this far from the expected value.
    Abs(f64),
    /// At most this many ulps from it, in the implementation's format (`f32` unless
    /// [`check_in`] is told the format's unit roundoff), counted at the case's scale:
    /// the ulp of the largest `|expected value|` of the span. The methods' errors are
    /// absolute, on values of that magnitude; the ulp of a value near zero would make
    /// a tiny absolute error look like tens of thousands of ulps.
    Ulps(f64),
    /// The crate's documented float bound for the method, case and precision
    /// (`src/tolerance.rs`): `f32` (u = 2^-24) or `f64` (u = 2^-53). The `reference`
    /// profile.
    Default {
        /// The unit roundoff of the implementation's arithmetic.
        u: f64,
    },
    /// The bound for every implementation of an arithmetic profile — proved or derived,
    /// as [`crate::tolerance::profile::status`] labels it per method and format
    /// ([`crate::tolerance::profile`], `docs/float.md` §18); `Reference` is
    /// [`Tolerance::Default`]. A case with no proved bound for the profile fails,
    /// naming why.
    Profile {
        /// The profile.
        profile: crate::tolerance::profile::Profile,
        /// The unit roundoff of the implementation's arithmetic.
        u: f64,
        /// The form the implementation declares it computes
        /// ([`crate::tolerance::profile::Form`]; `Any` unless declared): the bound is
        /// then that form's theorems' alone.
        form: crate::tolerance::profile::Form,
    },
}

impl fmt::Display for Tolerance {
    /// As `--tolerance` spells it (`levels=1`, `abs=0.001`, `ulps=4`), or the profile.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Tolerance::Levels(n) => write!(f, "levels={n}"),
            Tolerance::Abs(x) => write!(f, "abs={x}"),
            Tolerance::Ulps(x) => write!(f, "ulps={x}"),
            Tolerance::Default { .. } => f.write_str("the reference profile's bound"),
            Tolerance::Profile {
                profile,
                form: crate::tolerance::profile::Form::Any,
                ..
            } => write!(f, "the {profile} profile's bound"),
            Tolerance::Profile { profile, form, .. } => {
                write!(f, "the {profile} profile's bound for the {form} form")
            }
        }
    }
}

impl Tolerance {
    /// Parses `levels=N`, `abs=X` or `ulps=N`.
    ///
    /// # Errors
    /// A message saying what was expected.
    pub fn parse(s: &str) -> Result<Tolerance, String> {
        let (k, v) = s
            .split_once('=')
            .ok_or_else(|| format!("'{}' is not levels=N, abs=X or ulps=N", super::shown(s)))?;
        let num: f64 = v
            .trim()
            .parse()
            .map_err(|_| format!("'{}' is not a number", super::shown(v)))?;
        if !(num.is_finite() && num >= 0.0) {
            return Err(format!("'{}' must be a finite number ≥ 0", super::shown(v)));
        }
        match k.trim() {
            "levels" if num.fract() == 0.0 && num <= 255.0 => Ok(Tolerance::Levels(num as u32)),
            "levels" => Err(format!(
                "levels must be a whole number from 0 to 255 (got {v})"
            )),
            "abs" => Ok(Tolerance::Abs(num)),
            "ulps" => Ok(Tolerance::Ulps(num)),
            other => Err(format!(
                "unknown tolerance '{}' (expected levels, abs or ulps)",
                super::shown(other)
            )),
        }
    }
}

impl Tolerance {
    /// The unit roundoff of the format the tolerance names (`None` for levels,
    /// absolute and ulps tolerances, which name none).
    pub fn unit_roundoff(&self) -> Option<f64> {
        match *self {
            Tolerance::Profile {
                profile: crate::tolerance::profile::Profile::Fixed { .. },
                ..
            } => None,
            Tolerance::Default { u } | Tolerance::Profile { u, .. } => Some(u),
            _ => None,
        }
    }

    /// Checks that the tolerance means something: finite, non-negative numbers, a
    /// unit roundoff in `(0, 2^-8]` (fixed point has none: its `u` is not read), a
    /// fixed-point format the bounds take
    /// ([`crate::tolerance::profile::Profile::validate`]).
    ///
    /// # Errors
    /// A one-line message saying what is wrong.
    pub fn validate(&self) -> Result<(), String> {
        let ok = |x: f64| x.is_finite() && x >= 0.0;
        match *self {
            Tolerance::Levels(n) if n > 255 => Err(format!("levels must be at most 255 (got {n})")),
            Tolerance::Abs(x) | Tolerance::Ulps(x) if !ok(x) => {
                Err(format!("a tolerance must be a finite number ≥ 0 (got {x})"))
            }
            Tolerance::Profile {
                profile: profile @ crate::tolerance::profile::Profile::Fixed { .. },
                ..
            } => profile.validate(),
            Tolerance::Default { u } | Tolerance::Profile { u, .. }
                if !(u > 0.0 && u <= 1.0 / 256.0) =>
            {
                Err(format!("the unit roundoff must be in (0, 2^-8] (got {u})"))
            }
            Tolerance::Profile { profile, .. } => profile.validate(),
            _ => Ok(()),
        }
    }
}

/// The name of the float format whose unit roundoff is `u` (`f32`, `f64`, `binary16`),
/// or `format` for another.
pub fn format_name(u: f64) -> &'static str {
    if u == f64::from(f32::EPSILON) / 2.0 {
        "f32"
    } else if u == f64::EPSILON / 2.0 {
        "f64"
    } else if u == 2f64.powi(-11) {
        "binary16"
    } else {
        "format"
    }
}

/// The spacing at `x` of the binary floats of unit roundoff `u` (their ulp): `f32`'s
/// and `f64`'s exactly (subnormals included), otherwise `2u·2^⌊log2 |x|⌋`.
pub fn ulp_in(x: f64, u: f64) -> f64 {
    if u == f64::from(f32::EPSILON) / 2.0 {
        return f32_ulp(x);
    }
    if u == f64::EPSILON / 2.0 {
        let a = x.abs().max(f64::MIN_POSITIVE);
        if !a.is_finite() {
            return f64::INFINITY;
        }
        return f64::from_bits(a.to_bits() + 1) - a;
    }
    let a = x.abs().max(f64::MIN_POSITIVE);
    2.0 * u * 2f64.powi(a.log2().floor() as i32)
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
            format!("value '{}' is not a number", super::shown(t)),
        )
    })?;
    if v.is_infinite() && !t.to_ascii_lowercase().contains("inf") {
        return Err(err(file, line, out_of_range(t)));
    }
    Ok(v)
}

/// The refusal of a decimal beyond `f64`'s range (CSV and JSON alike: no float
/// implementation prints one; an infinite result is written `inf`).
fn out_of_range(t: &str) -> String {
    format!(
        "value '{}' is outside the range of f64 (an infinite result is written inf, or \"inf\" in JSON)",
        super::shown(t)
    )
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
                    super::shown(&c.id)
                ),
            ));
        };
        if let Some(i) = r.lines.iter().position(|&l| l == 0) {
            return Err(err(
                file,
                0,
                format!(
                    "at end of file: case {} has no value for pixel {i}",
                    super::shown(&c.id)
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
                format!("unknown case id '{}'", super::shown(id)),
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
                format!("pixel '{}' is not a whole number", super::shown(px)),
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

/// Streaming JSON results: `{"cases": [{"id": …, "values": […]}, …]}` read with
/// serde's seeds, so that each case's values go straight into a [`Reading`] of the
/// size its vector-file case needs and reading stops at the first value too many.
mod json {
    use super::Reading;
    use crate::error::shown;
    use serde::de::{self, DeserializeSeed, IgnoredAny, MapAccess, SeqAccess, Visitor};
    use std::cell::RefCell;
    use std::collections::HashMap;
    use std::fmt;

    /// What the reader knows and has read. `problem` holds the message of the first
    /// problem found (serde's error then only carries the line).
    pub(super) struct Ctx<'a> {
        pub need: &'a HashMap<&'a str, usize>,
        pub longest: usize,
        pub got: RefCell<HashMap<String, Reading>>,
        pub problem: RefCell<Option<String>>,
    }

    impl Ctx<'_> {
        fn fail<E: de::Error>(&self, message: String) -> E {
            let e = E::custom(&message);
            self.problem.borrow_mut().get_or_insert(message);
            e
        }
    }

    /// The whole file.
    pub(super) struct File<'c, 'a>(pub &'c Ctx<'a>);
    impl<'de> DeserializeSeed<'de> for File<'_, '_> {
        type Value = ();
        fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
            d.deserialize_map(self)
        }
    }
    impl<'de> Visitor<'de> for File<'_, '_> {
        type Value = ();
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str(r#"an object {"cases": [...]}"#)
        }
        fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<(), A::Error> {
            let mut cases = false;
            while let Some(k) = m.next_key::<std::borrow::Cow<'de, str>>()? {
                if k == "cases" {
                    if cases {
                        return Err(self.0.fail("the key \"cases\" appears twice".into()));
                    }
                    cases = true;
                    m.next_value_seed(Cases(self.0))?;
                } else {
                    m.next_value::<IgnoredAny>()?;
                }
            }
            if !cases {
                return Err(self.0.fail("no \"cases\" array".into()));
            }
            Ok(())
        }
    }

    struct Cases<'c, 'a>(&'c Ctx<'a>);
    impl<'de> DeserializeSeed<'de> for Cases<'_, '_> {
        type Value = ();
        fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
            d.deserialize_seq(self)
        }
    }
    impl<'de> Visitor<'de> for Cases<'_, '_> {
        type Value = ();
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str("an array of cases")
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut s: A) -> Result<(), A::Error> {
            let mut k = 0usize;
            while s.next_element_seed(OneCase { ctx: self.0, k })?.is_some() {
                k += 1;
            }
            Ok(())
        }
    }

    struct OneCase<'c, 'a> {
        ctx: &'c Ctx<'a>,
        k: usize,
    }
    impl<'de> DeserializeSeed<'de> for OneCase<'_, '_> {
        type Value = ();
        fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
            d.deserialize_map(self)
        }
    }
    impl<'de> Visitor<'de> for OneCase<'_, '_> {
        type Value = ();
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str(r#"a case {"id": ..., "values": [...]}"#)
        }
        fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<(), A::Error> {
            let ctx = self.ctx;
            let at = format!("cases[{}]", self.k);
            let mut id: Option<String> = None;
            let mut values: Option<(Vec<f64>, usize)> = None;
            while let Some(key) = m.next_key::<std::borrow::Cow<'de, str>>()? {
                match key.as_ref() {
                    "id" if id.is_some() => {
                        return Err(ctx.fail(format!("{at}: \"id\" appears twice")))
                    }
                    "id" => {
                        let s: std::borrow::Cow<'de, str> = m.next_value()?;
                        if !ctx.need.contains_key(s.as_ref()) {
                            return Err(
                                ctx.fail(format!("{at}: unknown case id '{}'", shown(s.as_ref())))
                            );
                        }
                        if ctx.got.borrow().contains_key(s.as_ref()) {
                            return Err(ctx
                                .fail(format!("{at}: duplicate case id '{}'", shown(s.as_ref()))));
                        }
                        id = Some(s.into_owned());
                    }
                    "values" if values.is_some() => {
                        return Err(ctx.fail(format!("{at}: \"values\" appears twice")))
                    }
                    "values" => {
                        // The id may come first (then its size is known) or after.
                        let cap = id.as_deref().map_or(ctx.longest, |i| ctx.need[i]);
                        values = Some(m.next_value_seed(Values {
                            ctx,
                            at: &at,
                            id: id.as_deref(),
                            cap,
                        })?);
                    }
                    _ => {
                        m.next_value::<IgnoredAny>()?;
                    }
                }
            }
            let Some(id) = id else {
                return Err(ctx.fail(format!("{at}: the case has no \"id\"")));
            };
            let Some((vals, count)) = values else {
                return Err(ctx.fail(format!("{at}: case {id} has no \"values\"")));
            };
            let len = ctx.need[id.as_str()];
            if count != len {
                return Err(ctx.fail(format!(
                    "{at}: case {id} needs {len} values, found {}",
                    if count > len {
                        format!("more ({count} or more)")
                    } else {
                        count.to_string()
                    }
                )));
            }
            let mut r = Reading::new(0);
            r.lines = vec![1; len];
            r.values = vals;
            ctx.got.borrow_mut().insert(id, r);
            Ok(())
        }
    }

    /// A case's values: at most `cap` of them are kept; one more stops the reading.
    struct Values<'c, 'a, 's> {
        ctx: &'c Ctx<'a>,
        at: &'s str,
        id: Option<&'s str>,
        cap: usize,
    }
    impl<'de> DeserializeSeed<'de> for Values<'_, '_, '_> {
        type Value = (Vec<f64>, usize);
        fn deserialize<D: de::Deserializer<'de>>(
            self,
            d: D,
        ) -> Result<(Vec<f64>, usize), D::Error> {
            d.deserialize_seq(self)
        }
    }
    impl<'de> Visitor<'de> for Values<'_, '_, '_> {
        type Value = (Vec<f64>, usize);
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str("an array of numbers")
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut s: A) -> Result<(Vec<f64>, usize), A::Error> {
            let who = match self.id {
                Some(id) => format!("case {id}"),
                None => "the case".to_string(),
            };
            let mut out = Vec::with_capacity(self.cap.min(1 << 16));
            loop {
                let i = out.len();
                let Some(x) = s.next_element_seed(Number)? else {
                    break;
                };
                // "NaN" or "inf" as a string is a result (a failing pixel), not an
                // error of the file.
                let Some(x) = x else {
                    return Err(self
                        .ctx
                        .fail(format!("{}: value {i} of {who} is not a number", self.at)));
                };
                if i == self.cap {
                    return Err(self.ctx.fail(format!(
                        "{}: {who} has more than {} values",
                        self.at, self.cap
                    )));
                }
                out.push(x);
            }
            let n = out.len();
            Ok((out, n))
        }
    }

    /// One value: a number, or a string holding one; `None` for anything else.
    struct Number;
    impl<'de> DeserializeSeed<'de> for Number {
        type Value = Option<f64>;
        fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<Option<f64>, D::Error> {
            d.deserialize_any(self)
        }
    }
    impl<'de> Visitor<'de> for Number {
        type Value = Option<f64>;
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str("a number")
        }
        fn visit_f64<E>(self, v: f64) -> Result<Option<f64>, E> {
            Ok(Some(v))
        }
        fn visit_i64<E>(self, v: i64) -> Result<Option<f64>, E> {
            Ok(Some(v as f64))
        }
        fn visit_u64<E>(self, v: u64) -> Result<Option<f64>, E> {
            Ok(Some(v as f64))
        }
        fn visit_str<E>(self, v: &str) -> Result<Option<f64>, E> {
            Ok(v.trim().parse::<f64>().ok())
        }
        fn visit_bool<E>(self, _: bool) -> Result<Option<f64>, E> {
            Ok(None)
        }
        fn visit_unit<E>(self) -> Result<Option<f64>, E> {
            Ok(None)
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut s: A) -> Result<Option<f64>, A::Error> {
            while s.next_element::<IgnoredAny>()?.is_some() {}
            Ok(None)
        }
        fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<Option<f64>, A::Error> {
            while m.next_entry::<IgnoredAny, IgnoredAny>()?.is_some() {}
            Ok(None)
        }
    }
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
                    out_of_range("a number")
                }
                None => format!("not a results file: {e}"),
            };
            err(file, e.line(), message)
        })?;
    complete(file, vectors, specular, ctx.got.into_inner())
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

/// The spacing of `f32` numbers at `x` (its ulp).
pub fn f32_ulp(x: f64) -> f64 {
    let a = (x.abs() as f32).max(f32::MIN_POSITIVE);
    let b = f32::from_bits(a.to_bits() + 1);
    f64::from(b) - f64::from(a)
}

/// The comparison of one case.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseReport {
    /// Case id.
    pub id: String,
    /// Pixels.
    pub pixels: usize,
    /// Largest |level − expected level|.
    pub max_levels: u32,
    /// Mean |level − expected level|.
    pub mean_levels: f64,
    /// Largest |value − expected|.
    pub max_abs: f64,
    /// Largest |value − expected| in ulps of the case's scale (the largest
    /// `|expected value|` of the span; [`Tolerance::Ulps`]), in the format
    /// [`CaseReport::format`] names.
    pub max_ulps: f64,
    /// The format whose ulps `max_ulps` counts (`f32`, `f64`, …).
    pub format: &'static str,
    /// The case's scale, the largest `|expected value|` of the span: its ulp is the
    /// unit of `max_ulps` ([`Tolerance::Ulps`]).
    pub scale: f64,
    /// The pixel where the tolerance is exceeded most (relative to it), if any.
    pub worst_pixel: usize,
    /// How much of the tolerance the worst pixel uses: `|value − expected|` over the
    /// allowed absolute error (or levels over allowed levels, ulps over allowed ulps);
    /// above 1 the case fails. Infinite where a value is missing or not finite, or no
    /// bound holds.
    pub ratio: f64,
    /// The allowed absolute error, where the tolerance is one (a profile's bound, the
    /// reference bound, [`Tolerance::Abs`]).
    pub allowed_abs: Option<f64>,
    /// The tolerance applied (as an absolute value, or levels).
    pub allowed: String,
    /// Whether every pixel is within the tolerance.
    pub pass: bool,
    /// The first pixel whose result is NaN or infinite (it fails, whatever the
    /// tolerance), if any.
    pub not_finite: Option<usize>,
    /// The time the verdict on this case took (seconds; the JUnit report's `time`).
    pub seconds: f64,
}

/// Compares `results` with the vector file's expectations for `method`, counting ulps
/// in the format the tolerance names (`f32` when it names none: see [`check_in`]).
///
/// # Errors
/// A message when the method is not in the file, or the tolerance is not valid
/// ([`Tolerance::validate`]).
pub fn check(
    vectors: &VectorFile,
    results: &Results,
    method: Method,
    method_key: &str,
    tol: Tolerance,
    specular: bool,
) -> Result<Vec<CaseReport>, String> {
    let u = tol.unit_roundoff().unwrap_or(f64::from(f32::EPSILON) / 2.0);
    check_in(vectors, results, method, method_key, tol, specular, u)
}

/// [`check`] for an implementation in the float format of unit roundoff `u`: ulps (of
/// [`Tolerance::Ulps`] and of the report) are that format's.
///
/// # Errors
/// As [`check`]; also a `u` outside `(0, 2^-8]`.
pub fn check_in(
    vectors: &VectorFile,
    results: &Results,
    method: Method,
    method_key: &str,
    tol: Tolerance,
    specular: bool,
    u: f64,
) -> Result<Vec<CaseReport>, String> {
    tol.validate()?;
    if !(u > 0.0 && u <= 1.0 / 256.0) {
        return Err(format!("the unit roundoff must be in (0, 2^-8] (got {u})"));
    }
    let mut reports = Vec::new();
    for c in &vectors.cases {
        let exp: &Expected = if specular {
            let Some(sp) = &c.specular else { continue };
            sp.expected.get(method_key)
        } else {
            c.expected.get(method_key)
        }
        .ok_or_else(|| format!("the vector file has no method '{method_key}'"))?;
        let got = &results[&c.id];
        let start = std::time::Instant::now();
        let mut r = match (method == Method::Adaptive && !specular)
            .then(|| adaptive_either(c, got, tol, u))
            .flatten()
        {
            Some(r) => r,
            None => case_report(c, exp, got, method, tol, specular, u),
        };
        r.seconds = start.elapsed().as_secs_f64();
        reports.push(r);
    }
    Ok(reports)
}

/// The bound a profile (or the reference bounds) gives `method` on case `c`, before the
/// specular power: `None` for the other tolerances and where no bound holds. Specular
/// cases shade `N·H`, not `N·L`, so the reference bound takes no edge values there.
fn case_bound(c: &Case, method: Method, tol: Tolerance, specular: bool) -> Option<f64> {
    use crate::tolerance::profile::{profile_bound, profile_span_bound, Profile};
    match tol {
        Tolerance::Profile {
            profile: Profile::Reference,
            u,
            ..
        }
        | Tolerance::Default { u } => match case_shape(c).filter(|_| !specular) {
            Some(shape) => crate::tolerance::span_bound(method, &shape, u),
            None => crate::tolerance::bound(method, c.n, c.q_min, u),
        },
        // The vector file's q_min is to nearest: a relative 2^-40 below it is below
        // the span's.
        // The case's exact span gives Phong's derived bound its |N_b − N_a|.
        Tolerance::Profile { profile, u, form } => match case_shape(c) {
            Some(shape) => profile_span_bound(method, profile, form, &shape, u),
            None if form == crate::tolerance::profile::Form::Any => {
                profile_bound(method, profile, c.n, c.q_min * (1.0 - 2f64.powi(-40)), u)
            }
            None => None,
        },
        _ => None,
    }
}

/// The adaptive scheme where its test is too close to call: when `|255·δ|` (the
/// case's exact `δ`, eq. 24, `K_d = 1`) is within `255·e_δ` of 1 — `e_δ` what an
/// implementation's own `δ` may be off by — a correct float run may pick either
/// method, and lands up to `|δ|` (one level) from the exact run's pick. The case then
/// passes when the results are within Gouraud's bound of the exact Gouraud run, or
/// within corrected Euler's bound of the exact corrected-Euler run (one method for the
/// whole span, as an implementation runs it); `None` elsewhere (judged as usual).
///
/// `e_δ`: [`crate::tolerance::adaptive_too_close`].
fn adaptive_either(c: &Case, got: &[f64], tol: Tolerance, u: f64) -> Option<CaseReport> {
    let delta: f64 = c.delta.parse().ok()?;
    // Only where the profile bounds the adaptive scheme at all (not fixed point).
    case_bound(c, Method::Adaptive, tol, false)?;
    let (bg, bce) = (
        case_bound(c, Method::Gouraud, tol, false)?,
        case_bound(c, Method::CorrectedEuler, tol, false)?,
    );
    if !crate::tolerance::adaptive_too_close(delta, 1.0, bg, bce, u) {
        return None;
    }
    let either = [
        (Method::Gouraud, "gouraud"),
        (Method::CorrectedEuler, "corrected-euler"),
    ];
    let mut best: Option<CaseReport> = None;
    for (m, key) in either {
        let exp = c.expected.get(key)?;
        let mut r = case_report(c, exp, got, m, tol, false, u);
        r.allowed = format!(
            "{} as {key} (|255δ| = {:.6} is within rounding of 1: either method passes)",
            r.allowed,
            (255.0 * delta).abs()
        );
        if r.pass {
            return Some(r);
        }
        best.get_or_insert(r);
    }
    best
}

/// Whether the result `g` is farther than the bound `b` from the expected value
/// (`e`, its decimal `ev` of 30 significant digits), decided so that the verdict never
/// rests on `f64` rounding: the bound, evaluated in `f64` in at most a few dozen
/// operations, is taken `2^-45` (relatively) larger, which covers up to 256 roundings
/// of its formula; where `|g − e|` computed in `f64` (off by at most
/// `(|g| + |e|)·2^-52`) is within that of the bound, the difference is computed
/// exactly in rationals from the decimal, allowed `10^-29·|e|` more for the decimal's
/// own rounding. So a fixed-point result with up to 51 fractional bits (exact in
/// `f64`) is judged by its exact error.
fn exceeds(g: f64, e: f64, ev: &str, b: f64) -> bool {
    let b = b * (1.0 + 2f64.powi(-45));
    let d = (g - e).abs();
    let slack = (g.abs() + e.abs()) * 2f64.powi(-52) + f64::from_bits(1);
    if d + slack < b {
        return false;
    }
    if d - slack > b + 1e-29 * e.abs() {
        return true;
    }
    let (Some(gq), Ok(eq), Some(bq)) = (
        crate::BigRational::from_float(g),
        crate::parse::parse_rational(ev),
        crate::BigRational::from_float(b),
    ) else {
        return d > b;
    };
    let decimal = crate::BigRational::new(1.into(), num_bigint::BigInt::from(10).pow(29))
        * num_traits::Signed::abs(&eq);
    num_traits::Signed::abs(&(gq - eq)) > bq + decimal
}

/// The shape of a case's span (its exact inputs re-read), for the bounds.
fn case_shape(c: &Case) -> Option<crate::tolerance::Shape> {
    super::integrity::case_span(c)
        .ok()
        .map(|span| crate::tolerance::Shape::of(&span))
}

fn case_report(
    c: &Case,
    exp: &Expected,
    got: &[f64],
    method: Method,
    tol: Tolerance,
    specular: bool,
    format_u: f64,
) -> CaseReport {
    use crate::tolerance::profile::Profile;
    let tol = match tol {
        Tolerance::Profile {
            profile: Profile::Reference,
            u,
            ..
        } => Tolerance::Default { u },
        t => t,
    };
    // Specular raises the value v ≥ 0 to the power s: an error e in v moves v^s by at
    // most s·(v + e)^(s−1)·e (mean value theorem), and evaluating the power adds a
    // relative γ_s (s − 1 products, or a pow within an ulp). The values may exceed 1
    // (corrected Euler reaches about 1.19), so the factor is taken at the case's
    // largest base value, v_max = max (v^s)^(1/s). Specular cases shade N·H with a
    // unit H, so the diffuse bounds hold with H for L.
    let spec = specular.then(|| {
        let s = c.specular.as_ref().map_or(1, |sp| sp.s.max(1));
        let v_max = exp
            .values
            .iter()
            .filter_map(|x| x.parse::<f64>().ok())
            .map(|x| x.max(0.0).powf(1.0 / f64::from(s)) * (1.0 + 1e-12))
            .fold(0.0, f64::max);
        (f64::from(s), v_max)
    });
    let raise = |b: f64, u: f64| match spec {
        None => b,
        Some((s, v_max)) => crate::tolerance::specular_bound(b, s, v_max, u),
    };
    let allowed_abs = match tol {
        Tolerance::Abs(x) => Some(x),
        // The power is not in the shader profile's model (Vulkan's pow is exp2 of a
        // log2, with errors relative to neither), nor in fixed point's: diffuse only.
        Tolerance::Profile {
            profile: Profile::Shader | Profile::Fixed { .. },
            ..
        } if specular => None,
        // No bound (n too long for the precision, or q may round to zero): the case
        // cannot pass on the profile's tolerance.
        Tolerance::Profile { u, .. } | Tolerance::Default { u } => {
            case_bound(c, method, tol, specular).map(|b| raise(b, u))
        }
        _ => None,
    };
    let unbounded = matches!(tol, Tolerance::Default { .. } | Tolerance::Profile { .. })
        && allowed_abs.is_none();
    let (mut max_levels, mut sum_levels, mut max_abs, mut max_ulps) = (0u32, 0u64, 0f64, 0f64);
    let (mut worst, mut worst_excess, mut pass) = (0usize, f64::NEG_INFINITY, true);
    let mut ratio = 0f64;
    // Ulps are counted at the case's scale (Tolerance::Ulps).
    let scale = exp
        .values
        .iter()
        .filter_map(|v| v.parse::<f64>().ok())
        .fold(0f64, |m, v| m.max(v.abs()));
    let mut not_finite = None;
    // The vector file was validated, so both lists have n + 1 values; a shorter list
    // would end the comparison early, so it fails.
    if got.len() != exp.values.len() || exp.levels.len() != exp.values.len() {
        pass = false;
        ratio = f64::INFINITY;
    }
    for (i, (&g, (ev, &el))) in got
        .iter()
        .zip(exp.values.iter().zip(&exp.levels))
        .enumerate()
    {
        if !g.is_finite() {
            pass = false;
            if not_finite.is_none() {
                not_finite = Some(i);
                worst = i;
                worst_excess = f64::INFINITY;
                ratio = f64::INFINITY;
            }
            continue;
        }
        let e: f64 = ev.parse().unwrap_or(f64::NAN);
        let d = (g - e).abs();
        // No method comes near 16 times its exact value in magnitude: such a result
        // fails whatever the tolerance (levels clamp, so they alone would pass 1e300).
        let implausible = g.abs() > 16.0 * e.abs().max(1.0);
        let dl = u32::from(level(&g).abs_diff(el));
        let du = d / ulp_in(scale.max(e.abs()), format_u);
        max_levels = max_levels.max(dl);
        sum_levels += u64::from(dl);
        max_abs = max_abs.max(d);
        max_ulps = max_ulps.max(du);
        let excess = match tol {
            Tolerance::Levels(n) => f64::from(dl) - f64::from(n),
            Tolerance::Ulps(n) => du - n,
            _ => d - allowed_abs.unwrap_or(0.0),
        };
        // Bounds and their comparison, decided exactly where f64 cannot decide them.
        let over = match (tol, allowed_abs) {
            (Tolerance::Levels(_) | Tolerance::Ulps(_), _) | (_, None) => excess > 0.0,
            (_, Some(b)) => exceeds(g, e, ev, b),
        };
        if over || d.is_nan() || unbounded || implausible {
            pass = false;
        }
        if excess > worst_excess {
            worst_excess = excess;
            worst = i;
            ratio = ratio.max(match tol {
                Tolerance::Levels(n) => f64::from(dl) / f64::from(n),
                Tolerance::Ulps(n) => du / n,
                _ => d / allowed_abs.unwrap_or(0.0),
            });
        }
        if implausible || d.is_nan() {
            ratio = f64::INFINITY;
        }
    }
    if unbounded {
        ratio = f64::INFINITY;
    }
    // 0/0 (an exact result under a zero tolerance) uses none of it.
    if ratio.is_nan() {
        ratio = 0.0;
    }
    let allowed = match tol {
        Tolerance::Levels(n) => format!("{n} levels"),
        Tolerance::Ulps(n) => format!("{n} ulps"),
        Tolerance::Profile { profile, u, form } if unbounded => {
            use crate::tolerance::profile::Form;
            if form != Form::Any && !Form::applies_to(method) {
                format!(
                    "a declared form tells apart only euler's and corrected-euler's theorems; {method} takes the form any"
                )
            } else if specular && matches!(profile, Profile::Shader | Profile::Fixed { .. }) {
                format!(
                    "the {profile} profile does not model the specular power (pass --tolerance)"
                )
            } else if crate::tolerance::profile::status(method, profile, u).is_none() {
                format!(
                    "the {profile} profile has no bound for {method} in this format \
                     (--profile reference judges this crate's own evaluation; or pass --tolerance)"
                )
            } else if form == Form::Closed && matches!(profile, Profile::Fixed { .. }) {
                format!("the {profile} profile's theorems cover the loop, not the closed form")
            } else if let Profile::Fixed { int_bits, .. } = profile {
                format!(
                    "the {profile} profile's registers may overflow on this span: its values and slopes must stay below 2^{} in {int_bits} integer bits (docs/float.md §14); more integer bits, or pass --tolerance",
                    int_bits.saturating_sub(1)
                )
            } else {
                format!(
                    "no {profile} bound for this span: n past the bound's range, or q may lose half of itself (pass --tolerance)"
                )
            }
        }
        _ if unbounded => "no derived bound (pass --tolerance)".to_string(),
        _ => format!("{:.3e}", allowed_abs.unwrap_or(0.0)),
    };
    CaseReport {
        id: c.id.clone(),
        pixels: got.len(),
        max_levels,
        mean_levels: sum_levels as f64 / got.len().max(1) as f64,
        max_abs,
        max_ulps,
        format: format_name(format_u),
        scale,
        worst_pixel: worst,
        ratio,
        allowed_abs,
        allowed,
        pass,
        not_finite,
        seconds: 0.0,
    }
}
