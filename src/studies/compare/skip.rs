//! The specular skip test ([`crate::skip`], the paper's §7.1 question a) on the tori:
//! per shininess, how many spans it skips, and whether a skipped span's specular
//! levels — as the comparison's `f32` span methods compute them — are all 0.
//!
//! Each row's `f32` inputs (the unit-in-`f32` edge normals and `H`) are read exactly as
//! rationals and decided exactly: the theorems (`phong_skip_levels`,
//! `quadratic_skip_levels`) then say the exact values' levels are 0; what this counts is
//! whether the `f32` runs agree, pixel by pixel.

use super::{index, level, Shader, PICTURE_LOOK};
use crate::skip::float::{float_skips, FloatSpan, Margins};
use crate::skip::Candidates;
use crate::{BigRational, Format, Method, Span, Vec3};

/// The shininess values of the skip table (the 1, 8, 32 and 128).
pub const SKIP_SHININESS: [u32; 4] = [1, 8, 32, 128];

/// The methods whose values are Phong's (one decision for all three).
const PHONG_VALUED: [Method; 3] = [Method::Phong, Method::Duff, Method::SymmetricPhong];

/// How the skip test fares at one shininess (`K_s = 1` unless said otherwise).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SkipCount {
    /// Spans (rows of two or more pixels) decided.
    pub spans: u64,
    /// Spans whose exact inputs the test could not decide (a vanishing normal).
    pub undecided: u64,
    /// Spans Phong's exact test skips.
    pub skipped: u64,
    /// Pixels of those spans (`n + 1` each).
    pub skipped_pixels: u64,
    /// Pixels of skipped spans where an `f32` run of Phong, Duff or symmetric Phong
    /// has a specular level above 0 (each method's pixel counted).
    pub changed: u64,
    /// Spans the float form ([`crate::skip::float`]) skips for Phong's values, with the
    /// largest `binary32` `ieee` allowance of Phong, Duff and symmetric Phong.
    pub skipped_float: u64,
    /// Pixels of those spans where an `f32` run of Phong, Duff or symmetric Phong has
    /// a specular level above 0.
    pub changed_float: u64,
    /// Spans corrected Euler's cheap test (from `p_a`, `t_0`, `ds`) skips.
    pub skipped_cheap: u64,
    /// Pixels of those spans where the `f32` corrected Euler run's level is above 0.
    pub changed_cheap: u64,
    /// Pixels of those spans where the `f32` Phong run's level is above 0: the cheap
    /// test used for Phong's values.
    pub cheap_wrong_for_phong: u64,
    /// Pixels of spans Phong's test skips at the pictures' `K_s`
    /// ([`PICTURE_LOOK`]): the combined intensity's pixels.
    pub combined_pixels: u64,
    /// … of which the combined level `K_a + K_d·diffuse + K_s·specular` (Phong's `f32`
    /// run) changes when the specular term is dropped.
    pub combined_changed: u64,
}

impl SkipCount {
    /// Adds `o` into `self`.
    pub fn merge(&mut self, o: &SkipCount) {
        self.spans += o.spans;
        self.undecided += o.undecided;
        self.skipped += o.skipped;
        self.skipped_pixels += o.skipped_pixels;
        self.changed += o.changed;
        self.skipped_float += o.skipped_float;
        self.changed_float += o.changed_float;
        self.skipped_cheap += o.skipped_cheap;
        self.changed_cheap += o.changed_cheap;
        self.cheap_wrong_for_phong += o.cheap_wrong_for_phong;
        self.combined_pixels += o.combined_pixels;
        self.combined_changed += o.combined_changed;
    }
}

/// The `f32` span as exact rationals (its inputs are unit within `f32` rounding).
fn exact(span: &Span<f32>) -> Option<Span<BigRational>> {
    let q = |v: &Vec3<f32>| {
        let c = |x: f32| BigRational::from_float(f64::from(x));
        Some(Vec3::new(c(v.x)?, c(v.y)?, c(v.z)?))
    };
    let tol = BigRational::new(1.into(), (1u64 << 18).into());
    Span::with_tolerance(q(&span.na)?, q(&span.nb)?, q(&span.l)?, span.n, &tol).ok()
}

/// `max(0, v)^s`'s level.
fn spec_level(v: f32, s: u32) -> u8 {
    level(&crate::specular::power(&f64::from(v), s))
}

/// Counts one row: `span` its half-vector span in `f32`, `diffuse` and `spec` the
/// comparison's `f32` values per column (`N·L` and `N·H`), into `counts` (one per
/// [`SKIP_SHININESS`]). Returns the row's code of the skip map
/// ([`super::CompareFrame::skip_map`]): `k + 1` for the first `SKIP_SHININESS[k]` at
/// which Phong's exact test skips the span, `0` for none, `None` if undecided.
pub(super) fn count_row(
    span: &Span<f32>,
    diffuse: &[Vec<f32>],
    spec: &[Vec<f32>],
    counts: &mut [SkipCount],
) -> Option<u8> {
    let mut code = None;
    let exact = exact(span);
    // The candidates once per span; the decisions per shininess and K_s.
    let phong = exact.as_ref().map(Candidates::phong);
    let cheap = exact
        .as_ref()
        .map(|ex| Candidates::of(Method::CorrectedEuler, ex));
    let one = BigRational::from_integer(1.into());
    // The float form: its inputs the f32 values, its allowance the largest ieee bound
    // of the three methods with Phong's values.
    let fs = FloatSpan {
        na: [span.na.x, span.na.y, span.na.z].map(f64::from),
        nb: [span.nb.x, span.nb.y, span.nb.z].map(f64::from),
        h: [span.l.x, span.l.y, span.l.z].map(f64::from),
        n: span.n,
    };
    let margins = exact.as_ref().and_then(|ex| {
        PHONG_VALUED
            .iter()
            .map(|&m| Margins::ieee(m, ex, Format::Binary32))
            .try_fold(0f64, |e, m| m.map(|m| e.max(m.allowance)))
            .map(|allowance| Margins {
                allowance,
                u: Format::Binary32.u(),
            })
    });
    let (ka, kd, ks) = PICTURE_LOOK;
    let ks_q = BigRational::from_float(ks).expect("finite");
    let col = |m: Method| index(Shader::Span(m));
    let len = span.n as usize + 1;
    for (k, (count, &s)) in counts.iter_mut().zip(&SKIP_SHININESS).enumerate() {
        count.spans += 1;
        let (Some(Ok(phong)), Some(Ok(cheap))) = (&phong, &cheap) else {
            count.undecided += 1;
            continue;
        };
        let nonzero = |m: Method| {
            spec[col(m)]
                .iter()
                .take(len)
                .filter(|&&v| spec_level(v, s) != 0)
                .count() as u64
        };
        code.get_or_insert(0);
        if phong.skips(&one, s) == Ok(true) {
            if code == Some(0) {
                code = Some(k as u8 + 1);
            }
            count.skipped += 1;
            count.skipped_pixels += len as u64;
            count.changed += PHONG_VALUED.iter().map(|&m| nonzero(m)).sum::<u64>();
        }
        if margins.is_some_and(|m| float_skips(Method::Phong, &fs, 1.0, s, m) == Ok(true)) {
            count.skipped_float += 1;
            count.changed_float += PHONG_VALUED.iter().map(|&m| nonzero(m)).sum::<u64>();
        }
        if cheap.skips(&one, s) == Ok(true) {
            count.skipped_cheap += 1;
            count.changed_cheap += nonzero(Method::CorrectedEuler);
            count.cheap_wrong_for_phong += nonzero(Method::Phong);
        }
        if phong.skips(&ks_q, s) == Ok(true) {
            let c = col(Method::Phong);
            count.combined_pixels += len as u64;
            count.combined_changed += (0..len)
                .filter(|&j| {
                    let d = ka + kd * f64::from(diffuse[c][j]).max(0.0);
                    let sv = crate::specular::power(&f64::from(spec[c][j]), s);
                    level(&(d + ks * sv)) != level(&d)
                })
                .count() as u64;
        }
    }
    code
}

/// The skip section of the report: per torus and shininess, the spans skipped by
/// Phong's test and by corrected Euler's cheap one, and what the `f32` runs say of them.
pub fn table(tori: &[super::CompareResult]) -> String {
    let mut s = String::from(
        "## Skipping the specular pass (§7.1, question a)\n\n\
         Every span of every fourth frame (`SKIP_EVERY`). Each span's f32 inputs read exactly and decided exactly (`skip`, `proofs/Skip.v`), K_s = 1: \
         the spans Phong's test skips (Duff and symmetric Phong take the same decision) and the f32 runs' \
         pixels above level 0 in them; corrected Euler's cheap test (from p_a, t0, ds) and the f32 corrected \
         Euler and Phong pixels above level 0 in the spans it skips; and, at the pictures' K_a = 0.08, \
         K_d = 0.75, K_s = 0.5, the pixels of skipped spans whose combined level changes when the specular \
         term is dropped. The float form (`skip::float`, `proofs/SkipFloat.v`) decides in f64 with the \
         largest binary32 ieee allowance of the three methods with Phong's values.\n\n\
         | torus | s | spans | skipped (Phong's test) | f32 levels above 0 in them | skipped (float form) | f32 levels above 0 in them | skipped (cheap test) | f32 corrected Euler levels above 0 in them | f32 Phong levels above 0 in them | combined levels changed |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    let pct = |a: u64, b: u64| {
        if b == 0 {
            "0.0 %".to_string()
        } else {
            format!("{:.1} %", 100.0 * a as f64 / b as f64)
        }
    };
    for t in tori {
        let polygons = t.polygons;
        for (c, sh) in t.stats.skip.iter().zip(SKIP_SHININESS) {
            s += &format!(
                "| {polygons} | {sh} | {} | {} | {} | {} | {} | {} | {} | {} | {} of {} pixels |\n",
                c.spans,
                pct(c.skipped, c.spans),
                c.changed,
                pct(c.skipped_float, c.spans),
                c.changed_float,
                pct(c.skipped_cheap, c.spans),
                c.changed_cheap,
                c.cheap_wrong_for_phong,
                c.combined_changed,
                c.combined_pixels
            );
        }
    }
    s
}
