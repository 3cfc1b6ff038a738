//! The paper's first open question (§7.1): "since we have the derivative for the
//! specular light, maybe we could use this to make some decision whether we have to
//! compute the specular intensity for a scan line at all."
//!
//! A span's specular term `K_s·max(0, v)^s` has 8-bit level 0 at a pixel exactly when
//! `255·K_s·max(0, v)^s < 1` ([`crate::quantize::level`] truncates). These tests
//! decide, from two or three candidate points, that this holds at **every real
//! `t ∈ [0, n]`** — so at every pixel, and shading the span's specular term can be
//! skipped without changing one of its levels:
//!
//! - **Phong** (and Duff and symmetric Phong, whose exact values are Phong's): with
//!   `p(t) = B + A·t` and `q(t) = E + D·t + C·t²` (eqs. 2–3, `L` replaced by `H`), the
//!   derivative of `f = p/√q` is `L(t)/q^{3/2}` with `L(t) = (A·E − B·D/2) +
//!   t·(A·D/2 − B·C)` — linear in `t` —, so `f`'s largest value on `[0, n]` is at `0`,
//!   at `n` or at `L`'s root `t*`. At each candidate `x` with `p(x) > 0` the test is
//!   `(255·K_s)²·p(x)^{2s} < q(x)^s`: no square root.
//! - **Corrected Euler, Euler and Gouraud**: the values are the quadratic
//!   `v(t) = p_a + t·s_0 + t(t − 1)/2·ds` (eq. 17 with `s_0 = t_0`, eq. 13 with
//!   `s_0 = di_a`, and Gouraud's line with `ds = 0`): the candidates are `0`, `n` and,
//!   where `ds < 0`, the vertex `t_v = 1/2 − s_0/ds`; the test is
//!   `255·K_s·v(x)^s < 1`. From the set-up quantities the recurrence computes anyway
//!   (`p_a`, `t_0`, `ds`), this is the paper's cheap test: it guarantees the method's
//!   own levels, not Phong's.
//!
//! Decided exactly, in rationals (a float filter first, with a proved margin, and
//! the rational comparison where it does not decide). Proofs: `proofs/Skip.v` (`phong_skip_sound`,
//! `quadratic_skip_sound`; at the pixels, `phong_skip_levels`,
//! `quadratic_skip_levels`); tests: `tests/skip.rs`.

pub mod float;

use crate::reference::radical::Valued;
use crate::{BigRational, Method, Span};

/// The largest shininess the tests take (`p^{2s}` is exact: its size grows with `s`).
pub const MAX_SHININESS: u32 = 1024;

/// Why a skip test cannot decide.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum SkipError {
    /// A shininess of 0 (the term is `K_s` everywhere) or above [`MAX_SHININESS`].
    #[error("the specular exponent must be 1 to {MAX_SHININESS} (got {0})")]
    Shininess(u32),
    /// A negative `K_s`.
    #[error("K_s must be at least 0")]
    NegativeKs,
    /// `q(t) = |N(t)|²` reaches 0 on the span (a zero edge normal, or edge normals
    /// opposite and of equal length): the value `p/√q` is undefined there.
    #[error("the interpolated normal vanishes on the span (q reaches 0): no specular value there")]
    NormalVanishes,
    /// A method whose values are not Phong's or a quadratic in `t` (angular
    /// interpolation, the related methods, the adaptive scheme).
    #[error("no skip test for {0}: its values are neither Phong's nor a quadratic along the span")]
    Unsupported(Method),
    /// An input of the float form ([`float::float_skips`]) outside its domain.
    #[error("{0}")]
    FloatInput(&'static str),
}

fn q(x: i64) -> BigRational {
    BigRational::from_integer(x.into())
}

/// Whether `k·x^e < 1`, for `k, x ≥ 0` and `1 ≤ e ≤ 2·MAX_SHININESS`, exactly; `xf` is
/// `x` rounded to the nearest `f64`.
///
/// A filter first: `k` and `x` rounded to the nearest `f64` (`to_f64` is correctly
/// rounded, relative error at most `2^-53` each in the normal range) and `k·x^e` by
/// repeated squaring (at most `2·log₂e + 2 ≤ 24` products, each within `2^-53`
/// relative while every result stays normal), so the float result is within a factor
/// `(1 ± 2^-53)^(e + 25)` of `k·x^e`, inside `1 ± 2^-40` for `e ≤ 2048`. Where it is
/// below `1 − 2^-40` or above `1 + 2^-40` that decides; elsewhere, or where a result
/// leaves the normal range, the comparison is made in rationals.
fn below_one(k: &BigRational, x: &BigRational, xf: f64, e: u32) -> bool {
    use num_traits::ToPrimitive;
    const MARGIN: f64 = 1.0 / (1u64 << 40) as f64;
    let normal = |v: f64| v == 0.0 || (v.is_normal() && v.abs() < 1e300);
    let Some(kf) = k.to_f64() else {
        return exact_below_one(k, x, e);
    };
    if kf == 0.0 && *k == q(0) || xf == 0.0 && *x == q(0) {
        return true;
    }
    let mut ok = normal(kf) && normal(xf) && kf != 0.0 && xf != 0.0;
    let (mut acc, mut base, mut left) = (kf, xf, e);
    while ok && left > 0 {
        if left & 1 == 1 {
            acc *= base;
            ok &= normal(acc) && acc != 0.0;
        }
        left >>= 1;
        if left > 0 {
            base *= base;
            ok &= normal(base) && base != 0.0;
        }
    }
    if ok && acc < 1.0 - MARGIN {
        true
    } else if ok && acc > 1.0 + MARGIN {
        false
    } else {
        exact_below_one(k, x, e)
    }
}

/// `k·x^e < 1` in rationals.
fn exact_below_one(k: &BigRational, x: &BigRational, e: u32) -> bool {
    k * crate::specular::power(x, e) < q(1)
}

fn check(ks: &BigRational, shininess: u32) -> Result<(), SkipError> {
    if !(1..=MAX_SHININESS).contains(&shininess) {
        return Err(SkipError::Shininess(shininess));
    }
    if *ks < q(0) {
        return Err(SkipError::NegativeKs);
    }
    Ok(())
}

/// The candidates of Phong's largest value on `[0, n]`: `0`, `n`, and the root `t*` of
/// `L(t) = (A·E − B·D/2) + t·(A·D/2 − B·C)` where it lies strictly inside.
pub fn phong_candidates(span: &Span<BigRational>) -> Vec<BigRational> {
    let half = BigRational::new(1.into(), 2.into());
    let n = span.n_s.clone();
    let mut out = vec![q(0), n.clone()];
    let l0 = &span.a * &span.e - &span.b * &span.d * &half;
    let l1 = &span.a * &span.d * &half - &span.b * &span.c;
    if l1 != q(0) {
        let t = -(l0 / l1);
        if t > q(0) && t < n {
            out.push(t);
        }
    }
    out
}

/// A span's candidates, set up once and decided for any `K_s` and shininess: the
/// values at the candidate points where they are positive — Phong's `p²/q` (compared
/// at exponent `s`, against `1/(255·K_s)²`) or the quadratic's `v` (at exponent `s`,
/// against `1/(255·K_s)`); a candidate whose value is not positive contributes level 0
/// at any shininess and is dropped.
#[derive(Clone, Debug, PartialEq)]
pub struct Candidates {
    /// The positive candidate values, each with its nearest `f64` (for the filter).
    values: Vec<(BigRational, f64)>,
    /// Whether the values are Phong's squares `p²/q`.
    squared: bool,
}

impl Candidates {
    fn new(values: Vec<BigRational>, squared: bool) -> Self {
        use num_traits::ToPrimitive;
        let values = values
            .into_iter()
            .filter(|v| *v > q(0))
            .map(|v| {
                let f = v.to_f64().unwrap_or(f64::NAN);
                (v, f)
            })
            .collect();
        Candidates { values, squared }
    }

    /// Phong's candidates on `span` (whose `l` is `H`): `p²/q` at `0`, `n` and `t*`
    /// ([`phong_candidates`]) where `p > 0`.
    ///
    /// # Errors
    /// [`SkipError::NormalVanishes`] where `q` reaches 0 on `[0, n]` (`phong_skip_sound`
    /// assumes `q > 0` there).
    pub fn phong(span: &Span<BigRational>) -> Result<Self, SkipError> {
        let (p, qq) = (
            |t: &BigRational| &span.b + &span.a * t,
            |t: &BigRational| &span.e + &span.d * t + &span.c * t * t,
        );
        // q > 0 on [0, n]: at the ends and, where C > 0, at its lowest point inside.
        let mut lowest = vec![q(0), span.n_s.clone()];
        if span.c > q(0) {
            let t = -(&span.d / (q(2) * &span.c));
            if t > q(0) && t < span.n_s {
                lowest.push(t);
            }
        }
        if lowest.iter().any(|t| qq(t) <= q(0)) {
            return Err(SkipError::NormalVanishes);
        }
        let values = phong_candidates(span)
            .iter()
            .map(|t| {
                let pt = p(t);
                if pt > q(0) {
                    &pt * &pt / qq(t)
                } else {
                    q(0)
                }
            })
            .collect();
        Ok(Candidates::new(values, true))
    }

    /// The quadratic `v(t) = p_a + t·s_0 + t(t − 1)/2·ds`'s candidates: `v` at `0`, `n`
    /// and, where `ds < 0`, the vertex `1/2 − s_0/ds` strictly inside.
    pub fn quadratic(p_a: &BigRational, s0: &BigRational, ds: &BigRational, n: u32) -> Self {
        let half = BigRational::new(1.into(), 2.into());
        let n = q(n.into());
        let v = |t: &BigRational| p_a + t * s0 + t * (t - q(1)) * &half * ds;
        let mut points = vec![q(0), n.clone()];
        if *ds < q(0) {
            let t = &half - s0 / ds;
            if t > q(0) && t < n {
                points.push(t);
            }
        }
        Candidates::new(points.iter().map(v).collect(), false)
    }

    /// The candidates of `method` on `span`: Phong's for the methods whose exact values
    /// are Phong's at every pixel ([`Method::is_phong_valued`]), the quadratic's for
    /// those whose closed form is one (the catalogue's `closed_form`: Gouraud's line,
    /// Euler's and corrected Euler's quadratics), and for the squared method
    /// ([`crate::method::Roots::SignedRootOfG`]) the quadratic `g`'s, compared as
    /// squares: its specular term is `g^{s/2}` (`sq_skip_sound`).
    ///
    /// # Errors
    /// [`SkipError::NormalVanishes`] (Phong's), [`SkipError::Unsupported`] for the
    /// other methods.
    pub fn of(method: Method, span: &Span<BigRational>) -> Result<Self, SkipError> {
        let quadratic = |s0: &BigRational, ds: &BigRational| {
            Ok(Candidates::quadratic(&span.p_a, s0, ds, span.n))
        };
        if method.info().roots == crate::method::Roots::SignedRootOfG {
            let sq = crate::squared_corrected_euler::SquaredSpan::of(span)
                .map_err(|_| SkipError::NormalVanishes)?;
            let g = Candidates::quadratic(&sq.g_a, &sq.t0, &sq.ds, span.n);
            return Ok(Candidates { squared: true, ..g });
        }
        match method.info().closed_form {
            Some(Valued::Gouraud) => quadratic(&((&span.p_b - &span.p_a) / &span.n_s), &q(0)),
            Some(Valued::Euler) => quadratic(&span.di_a, &span.ds),
            Some(Valued::CorrectedEuler) => quadratic(&span.t0, &span.ds),
            Some(Valued::Phong) => Candidates::phong(span),
            None if method.is_phong_valued() => Candidates::phong(span),
            None => Err(SkipError::Unsupported(method)),
        }
    }

    /// Whether `K_s·max(0, v)^s` is below one level at every real `t ∈ [0, n]`:
    /// `(255·K_s)²·(p²/q)^s < 1` at each of Phong's positive candidates
    /// (`phong_skip_sound`, whose `ok` is `(255·K_s)²·p^{2s} < q^s`), `255·K_s·v^s < 1` at
    /// each of the quadratic's (`quadratic_skip_sound`), `(255·K_s)²·g^s < 1` at each of
    /// the squared method's (`sq_skip_sound`).
    ///
    /// # Errors
    /// [`SkipError`]: a shininess outside `1..=MAX_SHININESS` or a negative `K_s`.
    pub fn skips(&self, ks: &BigRational, shininess: u32) -> Result<bool, SkipError> {
        check(ks, shininess)?;
        let k = q(255) * ks;
        let k = if self.squared { &k * &k } else { k };
        Ok(self
            .values
            .iter()
            .all(|(x, xf)| below_one(&k, x, *xf, shininess)))
    }
}

/// The skip test of `method` on `span` (its `l` the half vector):
/// [`Candidates::of`], then [`Candidates::skips`].
///
/// # Errors
/// [`SkipError`]; [`SkipError::Unsupported`] for a method with no test.
pub fn specular_skips(
    method: Method,
    span: &Span<BigRational>,
    ks: &BigRational,
    shininess: u32,
) -> Result<bool, SkipError> {
    check(ks, shininess)?;
    Candidates::of(method, span)?.skips(ks, shininess)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The filter agrees with the rational comparison, on both sides of the
    /// threshold and next to it.
    #[test]
    fn the_filter_is_the_exact_comparison() {
        let r = |a: i64, b: i64| BigRational::new(a.into(), b.into());
        for e in [1, 2, 3, 8, 127, 128, 2048] {
            for (k, x) in [
                (r(255, 1), r(1, 255)),
                (r(255, 1), r(1, 256)),
                (r(255, 1), r(1, 254)),
                (r(1, 1), r(999_999_999, 1_000_000_000)),
                (r(1, 1), r(1_000_000_001, 1_000_000_000)),
                (r(65025, 1), r(0, 1)),
                (r(0, 1), r(7, 3)),
                (r(1, 1), r(1, 1)),
                (r(1, 3), r(3, 1)),
                (r(3, 1), r(1, 3)),
            ] {
                let xf = num_traits::ToPrimitive::to_f64(&x).unwrap();
                assert_eq!(
                    below_one(&k, &x, xf, e),
                    exact_below_one(&k, &x, e),
                    "{k} {x} {e}"
                );
            }
            // Exactly at the threshold: 2^e · (1/2)^e = 1 is not below.
            let two_e = crate::specular::power(&r(2, 1), e);
            assert!(!below_one(&two_e, &r(1, 2), 0.5, e));
            assert!(below_one(&(two_e - r(1, 1 << 20)), &r(1, 2), 0.5, e));
        }
    }

    #[test]
    fn a_zero_shininess_is_an_error() {
        let s = Span::new(
            crate::Vec3::new(q(0), q(0), q(1)),
            crate::Vec3::new(q(0), q(0), q(1)),
            crate::Vec3::new(q(0), q(0), q(1)),
            4,
        )
        .unwrap();
        assert_eq!(
            specular_skips(Method::Phong, &s, &q(1), 0),
            Err(SkipError::Shininess(0))
        );
    }
}
