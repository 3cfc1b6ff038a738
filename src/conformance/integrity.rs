//! A vector file that cannot be fooled: its SHA-256 against the published sets, and a
//! full check of its own invariants before `check` uses it.
//!
//! `check` refuses a vector file whose digest is not one of [`SHA256SUMS`] unless the
//! user says `--allow-modified-vectors` (for people who generate their own), and
//! always refuses one that breaks an invariant of [`validate`]: so a truncated,
//! edited or hostile file can neither make garbage pass nor exhaust memory.

use super::vectors::{exact_input, method_keys, Case, Expected, VectorFile};
use crate::method::ValueRange;
use crate::parse::parse_rational;
use crate::scalar::Scalar;
use crate::span::Span;
use crate::tolerance::Shape;
use crate::BigRational;

/// `vectors/SHA256SUMS`: the SHA-256 of the published vector files, in `sha256sum`'s
/// format (`DIGEST  SET.json` per line), as `phong-approx vectors` of this version
/// writes them beside the sets; embedded at build (tested: `tests/conformance/`).
pub const SHA256SUMS: &str = include_str!("../../vectors/SHA256SUMS");

/// The digests of the sets published before (format 1.2.0,
/// `vectors/SHA256SUMS-1.2.0`): still trusted, so a file a user took from an earlier
/// release is judged as it was (it has no expectations of the methods added since).
pub const PREVIOUS_SHA256SUMS: &str = include_str!("../../vectors/SHA256SUMS-1.2.0");

/// The published sets and their digests, `(set, SHA-256)`, read from [`SHA256SUMS`].
pub fn published() -> impl Iterator<Item = (&'static str, &'static str)> {
    SHA256SUMS.lines().filter_map(|line| {
        let (digest, file) = line.split_once("  ")?;
        Some((file.strip_suffix(".json")?, digest))
    })
}

pub use super::vectors::MAX_CASE_STEPS;

pub use super::vectors::VectorError;

pub use crate::budget::{exact_work, input_bits, MAX_RECOMPUTED_WORK};

/// The most cases a vector file may hold.
pub const MAX_CASES: usize = 100_000;

/// The largest `|value|` a method may have on `span` (its catalogue entry's
/// [`ValueRange`]): [`MAX_DIFFUSE_VALUE`], or for Bishop–Weimer's expansion, which
/// grows without limit as the normals near opposite, `|v| ≤ 1 + τ + τ²/2`,
/// `τ = tan(Ω/2)` (`docs/float.md` §16.3), with 0.1 % for the rounding of `τ`.
fn value_range(method: &str, span: &Span<BigRational>) -> f64 {
    let range = method
        .parse::<crate::Method>()
        .map_or(ValueRange::Diffuse, |m| m.info().range);
    if range == ValueRange::Diffuse {
        return MAX_DIFFUSE_VALUE;
    }
    let c = span.na.dot(&span.nb).to_f64().clamp(-1.0, 1.0);
    let tau = ((1.0 - c) / (1.0 + c)).sqrt();
    MAX_DIFFUSE_VALUE.max(1.001 * (1.0 + tau + tau * tau / 2.0))
}

/// No method's value on exact unit inputs leaves `[−4, 4]` (plain Euler's overshoot
/// is the largest, `|E_i| ≤ 3.77`: `docs/float.md` §3); diffuse expectations outside
/// this range are refused (Bishop–Weimer's expansion aside, whose range grows as the
/// normals near opposite: `1 + τ + τ²/2`, `τ = tan(Ω/2)`, docs/float.md §16.3).
pub const MAX_DIFFUSE_VALUE: f64 = 4.0;

/// The hexadecimal SHA-256 of `bytes`.
pub fn sha256_hex(bytes: &[u8]) -> String {
    hmac_sha256::Hash::hash(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The published set whose file has this digest, if any: of the current sets
/// ([`SHA256SUMS`]) or of an earlier format ([`PREVIOUS_SHA256SUMS`]).
pub fn published_set(digest: &str) -> Option<&'static str> {
    let previous = PREVIOUS_SHA256SUMS.lines().filter_map(|line| {
        let (digest, file) = line.split_once("  ")?;
        Some((file.strip_suffix(".json")?, digest))
    });
    published()
        .chain(previous)
        .find(|(_, d)| d.eq_ignore_ascii_case(digest))
        .map(|(s, _)| s)
}

/// The exact span of a case, after checking `n` and the inputs.
///
/// # Errors
/// A message naming the case and what is wrong.
pub fn case_span(c: &Case) -> Result<Span<BigRational>, VectorError> {
    let id = &c.id;
    if c.n == 0 || c.n > MAX_CASE_STEPS {
        return Err(VectorError::case(
            id,
            format!("n = {} is outside 1..={MAX_CASE_STEPS}", c.n),
        ));
    }
    let v = |x, what: &str| {
        exact_input(x)
            .ok_or_else(|| VectorError::case(id, format!("{what} is not three exact numbers")))
    };
    Span::new(v(&c.na, "na")?, v(&c.nb, "nb")?, v(&c.l, "l")?, c.n)
        .map_err(|e| VectorError::case(id, format!("{e}")))
}

/// The nearest `f64` to the exact `x` read from `v`: Rust's parser of a plain decimal
/// rounds correctly, and is much cheaper than converting the rational; a fraction is
/// converted.
fn nearest_f64(v: &str, x: &BigRational) -> f64 {
    let t = v.trim();
    match t.parse::<f64>() {
        Ok(f) if !t.contains('/') && f.is_finite() => f,
        _ => x.to_f64(),
    }
}

/// [`crate::quantize::level`] of an exact rational, `⌊255·x⌋` clamped to 0–255, by one integer
/// division (no reduction of `255·x`).
fn exact_level(x: &BigRational) -> u8 {
    use num_integer::Integer;
    use num_traits::{One, Zero};
    if *x <= BigRational::zero() {
        return 0;
    }
    if *x >= BigRational::one() {
        return 255;
    }
    let l = (x.numer() * 255u32).div_floor(x.denom());
    u8::try_from(l).unwrap_or(255)
}

/// Checks one method's expectations: `n + 1` values and levels, every value a finite
/// decimal within `range` (`None`: non-negative, any size), every level the level of
/// its value (or one off where the value is within rounding of a level boundary).
fn check_expected(
    id: &str,
    what: &str,
    n: u32,
    e: &Expected,
    range: Option<f64>,
) -> Result<(), VectorError> {
    let len = n as usize + 1;
    if e.values.len() != len || e.levels.len() != len {
        return Err(VectorError::case(
            id,
            format!(
                "{what} has {} values and {} levels, the span has {len} pixels",
                e.values.len(),
                e.levels.len()
            ),
        ));
    }
    for (i, (v, &l)) in e.values.iter().zip(&e.levels).enumerate() {
        let x = parse_rational(v).map_err(|_| {
            VectorError::case(id, format!("{what} value {i} is not a decimal number"))
        })?;
        let f = nearest_f64(v, &x);
        let ok = match range {
            Some(r) => f.abs() <= r,
            None => f >= 0.0 && f.is_finite(),
        };
        if !ok {
            return Err(VectorError::case(
                id,
                format!(
                    "{what} value {i} = {} is out of range",
                    crate::conformance::shown(v)
                ),
            ));
        }
        let lv = exact_level(&x);
        // The values carry 30 significant digits: a value within 1e-25 of a level
        // boundary may round to the other side of it.
        let scaled = f * 255.0;
        let near_boundary = (scaled - scaled.round()).abs() < 1e-9;
        if lv != l && !(near_boundary && lv.abs_diff(l) == 1) {
            return Err(VectorError::case(
                id,
                format!(
                    "{what} pixel {i}: level {l} is not the level of value {} ({lv})",
                    crate::conformance::shown(v)
                ),
            ));
        }
    }
    Ok(())
}

/// Checks every invariant of a vector file: a supported version, the stated number of
/// cases, unique ids, `1 ≤ n ≤` [`MAX_CASE_STEPS`], exact unit inputs, `q_min` equal to
/// the span's, every method's `n + 1` finite values within range with consistent
/// levels, and a valid adaptive decision. Returns the shape of each case's exact span,
/// built here once, for the bounds of [`super::check::check_in`].
///
/// # Errors
/// The first problem found, naming the case.
pub fn validate(file: &VectorFile) -> Result<Vec<Option<Shape>>, VectorError> {
    let major = file.version.split('.').next().unwrap_or("");
    if major != "1" {
        return Err(VectorError::file(format!(
            "version '{}' is not supported (this checker reads 1.x)",
            crate::conformance::shown(&file.version)
        )));
    }
    if file.cases.len() > MAX_CASES {
        return Err(VectorError::file(format!("more than {MAX_CASES} cases")));
    }
    if file.cases.is_empty() {
        return Err(VectorError::file("the file has no cases"));
    }
    if file.number_of_cases != file.cases.len() {
        return Err(VectorError::file(format!(
            "number_of_cases is {} but the file holds {} cases",
            file.number_of_cases,
            file.cases.len()
        )));
    }
    let known = method_keys();
    if file.methods.is_empty() {
        return Err(VectorError::file("the file lists no methods"));
    }
    for m in &file.methods {
        if !known.contains(m) {
            return Err(VectorError::file(format!(
                "unknown method '{}' (known: {})",
                crate::conformance::shown(m),
                known.join(", ")
            )));
        }
    }
    let mut ids = std::collections::HashSet::new();
    let mut shapes = Vec::with_capacity(file.cases.len());
    for c in &file.cases {
        if c.id.is_empty() || !ids.insert(c.id.as_str()) {
            return Err(VectorError::file(format!(
                "case id '{}' is empty or not unique",
                crate::conformance::shown(&c.id)
            )));
        }
        let span = case_span(c)?;
        let q = span.q_min().to_f64();
        if !(c.q_min.is_finite() && c.q_min > 0.0 && (c.q_min - q).abs() <= 1e-12 * q) {
            return Err(VectorError::case(
                &c.id,
                format!("q_min = {} but the span's is {q}", c.q_min),
            ));
        }
        if c.decision != "gouraud" && c.decision != "corrected-euler" {
            return Err(VectorError::case(&c.id, "unknown decision"));
        }
        if parse_rational(&c.delta).is_err() {
            return Err(VectorError::case(&c.id, "delta is not a number"));
        }
        for m in &file.methods {
            let e = c.expected.get(m).ok_or_else(|| {
                VectorError::case(&c.id, format!("no expectations for method {m}"))
            })?;
            check_expected(&c.id, m, c.n, e, Some(value_range(m, &span)))?;
        }
        if let Some(sp) = &c.specular {
            let h = exact_input(&sp.h)
                .ok_or_else(|| VectorError::case(&c.id, "h is not three exact numbers"))?;
            Span::new(span.na.clone(), span.nb.clone(), h, c.n)
                .map_err(|e| VectorError::case(&c.id, format!("specular: {e}")))?;
            if sp.s == 0 || sp.s > super::vectors::MAX_SHININESS {
                return Err(VectorError::case(
                    &c.id,
                    format!("shininess {} out of range", sp.s),
                ));
            }
            for m in &file.methods {
                let e = sp.expected.get(m).ok_or_else(|| {
                    VectorError::case(&c.id, format!("no specular expectations for method {m}"))
                })?;
                check_expected(&c.id, &format!("specular {m}"), c.n, e, None)?;
            }
        }
        shapes.push(Some(Shape::of(&span)));
    }
    Ok(shapes)
}
