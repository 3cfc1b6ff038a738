//! The catalogue of span methods: one list, and per method everything the rest of the
//! crate needs to know — its name (which parses back), source, equations, what it asks
//! of the scalar, whether its value is Phong's `p/√q`, and how to run it. The CLI (`span`,
//! `check`), the conformance vectors and the torus harness read it from here, and the
//! float error bound under the `reference` profile as data ([`Bound`], evaluated by
//! [`crate::tolerance::reference_bound`]; the acceptance profiles' bounds are
//! [`crate::tolerance::profile::status`]).
//!
//! Adding a span method: its own file with `shade(span, out)`, then one row of the list
//! (`method/list.rs`), which declares the variant, its place in [`Method::ALL`], how
//! it runs and its catalogue facts with its bounds (ARCHITECTURE.md, "Adding a span
//! method").

use crate::adaptive::Decision;
use crate::angular::CosTable;
use crate::error::SpanError;
use crate::reference::level::{level_of_rational, level_within, phong_level_exact};
use crate::scalar::{Real, Scalar};
use crate::span::Span;
use crate::BigRational;
use num_traits::One;
use std::borrow::Cow;
use std::fmt;
use std::str::FromStr;

#[macro_use]
mod declare;
mod catalogue;
mod list;
mod profiles;

pub use list::Method;

pub use catalogue::{
    Bound, DerivedForm, Family, FixedBound, FloatBound, Info, Needs, PhongPixels, ProfileBounds,
    Proved, Roots, ValueRange, WholeSpan,
};

/// The table size of the second source's byte angles.
pub const SOURCE_TABLE: u32 = 256;

impl Method {
    /// The name, which [`FromStr`] parses back: `corrected-euler`, …,
    /// `angular-table256`.
    pub fn name(&self) -> Cow<'static, str> {
        match self {
            Method::AngularTable(size) => Cow::Owned(format!("angular-table{size}")),
            m => Cow::Borrowed(m.info().name),
        }
    }

    /// The equations the method implements.
    pub fn equations(&self) -> &'static str {
        self.info().equations
    }

    /// Whether the method uses only field operations (exact in rationals).
    pub fn is_rational(&self) -> bool {
        self.info().needs == Needs::Field
    }

    /// Whether the method's exact value is Phong's `p/√q` at every pixel.
    pub fn is_phong_valued(&self) -> bool {
        self.info().phong_pixels == PhongPixels::All
    }

    /// The methods it picks between per span ([`Info::picks`]: the adaptive scheme's
    /// Gouraud and corrected Euler), `None` for a method that runs itself.
    pub fn picks(&self) -> Option<[Method; 2]> {
        self.info().picks
    }

    /// The method and the ones it picks between ([`Method::picks`]): every method
    /// whose exact run may judge an implementation of it.
    pub fn with_picks(&self) -> Vec<Method> {
        std::iter::once(*self)
            .chain(self.picks().into_iter().flatten())
            .collect()
    }

    /// Whether the method is one of the related methods along a span
    /// ([`Family::Related`]).
    pub fn is_related(&self) -> bool {
        self.info().family == Family::Related
    }

    /// Shades `span` into `out` (`n + 1` values) with the prepared parameters; the
    /// adaptive method returns its decision (eqs. 23–24 with `prep.kd`).
    ///
    /// Every method's values pass the same finiteness check here, before anything
    /// returns them: a float run whose value overflows or divides by a `√q`, `sin Ω`
    /// or `|N|` that rounded to zero (Phong's family, spherical and binary
    /// interpolation, Bishop–Weimer on nearly opposite normals) is an error naming the
    /// pixel, never an infinity or NaN.
    ///
    /// # Errors
    /// [`SpanError::OutputLength`] for a wrong `out`; [`SpanError::Parameter`] for a
    /// bad table size; the method's own refusals ([`SpanError::Opposite`],
    /// [`SpanError::ZeroNormal`]); [`SpanError::NotFiniteValue`] for a value that is
    /// not finite.
    pub fn run<T: Real>(
        &self,
        span: &Span<T>,
        prep: &Prepared<T>,
        out: &mut [T],
    ) -> Result<Option<Decision<T>>, SpanError> {
        let decision = self.dispatch(span, prep, out)?;
        span.check_finite(out)?;
        Ok(decision)
    }

    /// [`Method::run`] in a number type with field operations only (with the same
    /// finiteness check).
    ///
    /// # Errors
    /// As [`Method::run`]; [`SpanError::Parameter`] for a method that needs square
    /// roots or trigonometry.
    pub fn run_field<T: Scalar>(
        &self,
        span: &Span<T>,
        kd: &T,
        out: &mut [T],
    ) -> Result<Option<Decision<T>>, SpanError> {
        let decision = self.dispatch_field(span, kd, out)?;
        span.check_finite(out)?;
        Ok(decision)
    }

    /// Shades `span` into `out` with `K_d = 1` (the adaptive method's δ test) and the
    /// table built for the call.
    ///
    /// # Errors
    /// As [`Method::run`].
    pub fn shade<T: Real>(&self, span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
        self.run(span, &Prepared::new(*self, T::one())?, out)
            .map(|_| ())
    }

    /// Fills `out[i]` with `max(0, v_i)^shininess`, where `v` is the method run on
    /// `span_h` — a span whose light vector is the unit half vector `H` (§6.1: the
    /// same recurrences for `N·H`; [`crate::specular::power`]).
    ///
    /// # Errors
    /// As [`Method::shade`].
    pub fn shade_specular<T: Real>(
        &self,
        span_h: &Span<T>,
        shininess: u32,
        out: &mut [T],
    ) -> Result<(), SpanError> {
        self.shade(span_h, out)?;
        for o in out.iter_mut() {
            *o = crate::specular::power(o, shininess);
        }
        Ok(())
    }

    /// Shades `span` into a new vector of `n + 1` values ([`Method::shade`]).
    ///
    /// # Errors
    /// As [`Method::run`].
    pub fn values<T: Real>(&self, span: &Span<T>) -> Result<Vec<T>, SpanError> {
        let mut out = vec![T::zero(); span.len()];
        self.shade(span, &mut out)?;
        Ok(out)
    }

    /// How well the exact run ([`Method::run`] in [`BigRational`], whose square roots,
    /// `acos` and `cos` are accurate to 2^-256) knows its values: `None` when they
    /// are exact (field-only methods), else `bits` with every value within
    /// `2^-bits` of the method's value in real arithmetic. What is lost of 2^-(b − 6), `b`
    /// the accuracy of the square roots, `acos` and `cos` ([`crate::reference::transcendental::bits`],
    /// 256 by default):
    /// - Phong-valued methods: `p/√q` moves by `e/√q_min` when `√q` is off by `e`,
    ///   and `q` itself is exact: `⌈log2(1/q_min)⌉/2 + 2`;
    /// - the related methods (spherical, binary, Bishop–Weimer): their set-up divides
    ///   by `sin Ω` (spherical's `w·L`), by `sin(Ω/n)` (spherical's `sin Δ` from
    ///   `cos Δ`) or by powers of `|N|` (Bishop–Weimer's expansion), and the
    ///   recurrences carry an error of the first values or of the coefficients over
    ///   `n` steps with a factor of at most `n` (Chebyshev: `sin(kΔ)/sin Δ ≤ k`) or
    ///   `n²` (the quadratic's forward differences):
    ///   `2·⌈log2(n + 1)⌉ + 2·⌈log2(1/sin²Ω)⌉ + 2·⌈log2(1/q_min)⌉ + 8`;
    /// - angular interpolation: nothing more (its `acos` and `cos` are taken of exact
    ///   arguments).
    pub fn exact_bits(&self, span: &Span<BigRational>) -> Option<i64> {
        if self.is_rational() {
            return None;
        }
        let q = log2_recip(span.q_min().to_f64());
        let loss = if self.is_phong_valued() {
            q / 2 + 2
        } else if self.info().family == Family::Related {
            let c = span.na.dot(&span.nb);
            let s2 = BigRational::from_integer(1.into()) - c.clone() * c;
            let n_bits = 64 - i64::from(u64::from(span.n + 1).leading_zeros());
            let sin = if s2 == BigRational::from_integer(0.into()) {
                0
            } else {
                log2_recip(s2.to_f64())
            };
            2 * n_bits + 2 * sin + 2 * q + 8
        } else {
            0
        };
        Some(i64::from(crate::reference::transcendental::bits()) - 6 - loss)
    }

    /// The exact 8-bit levels of `values`, the method's exact run on `span`, scaled
    /// by `kd ≥ 0`: for Phong-valued methods decided from `kd·p_i` and `q_i` in
    /// rationals (no square root), and so for a method whose value is a root of its
    /// exact run's rationals ([`Info::roots`]); for field-only methods `level(kd·v)` of the exact
    /// value; otherwise decided within the run's error ([`Method::exact_bits`]), and
    /// `None` at a pixel whose value is within that error of a level boundary (or
    /// missing from `values`: a Phong-valued method needs none, so its exact run, with
    /// a square root per pixel, can be skipped).
    pub fn exact_levels(
        &self,
        span: &Span<BigRational>,
        values: &[BigRational],
        kd: &BigRational,
    ) -> Vec<Option<u8>> {
        self.levels_within(span, values, kd, self.exact_bits(span))
    }

    /// [`Method::exact_levels`] for values known to within `2^-bits` of the method's
    /// values on the exact `span` (`None`: exact), however they were computed (the
    /// exact run, MPFR): decided exactly where the value is known
    /// ([`PhongPixels::exact_at`]), else from the value, `None` where undecided.
    pub fn levels_within(
        &self,
        span: &Span<BigRational>,
        values: &[BigRational],
        kd: &BigRational,
        bits: Option<i64>,
    ) -> Vec<Option<u8>> {
        let phong = self.info().phong_pixels;
        let roots = self.info().roots.pairs(span);
        let e = bits.map(|b| {
            kd.clone()
                * BigRational::new(1.into(), num_bigint::BigInt::from(1) << b.max(0) as usize)
        });
        (0..=span.n)
            .map(|i| {
                let pair = phong.exact_at(span, i);
                if let Some((p, q)) = pair.or_else(|| roots.as_ref()?.get(i as usize).cloned()) {
                    return phong_level_exact(&(p * kd.clone()), &q);
                }
                let v = values.get(i as usize)?;
                if phong == PhongPixels::Table && v.is_one() {
                    return Some(level_of_rational(kd));
                }
                match &e {
                    None => Some(level_of_rational(&(v.clone() * kd.clone()))),
                    Some(e) => level_within(&(v.clone() * kd.clone()), e),
                }
            })
            .collect()
    }

    /// The exact 8-bit levels of `max(0, v)^s` (the specular term) for the method's
    /// exact run `values` on `span` (with `L` the half vector): decided in rationals
    /// where the value is known ([`PhongPixels::exact_at`], [`Info::roots`]:
    /// `ℓ ≤ 255·(p/√q)^s` iff `ℓ²·q^s ≤ 255²·p^{2s}` for `p > 0`) or exact, else within `s` times the run's
    /// error (`|d(v^s)/dv| ≤ s` on `[0, 1]`, and `(1 + e)^{s−1} < 1.01` for the
    /// errors here), `None` where that straddles a level boundary.
    pub fn exact_power_levels(
        &self,
        span: &Span<BigRational>,
        values: &[BigRational],
        s: u32,
    ) -> Vec<Option<u8>> {
        use num_traits::{Pow, Signed};
        let phong = self.info().phong_pixels;
        let roots = self.info().roots.pairs(span);
        let e = self.exact_bits(span).map(|b| {
            BigRational::new(
                (101 * i64::from(s)).into(),
                num_bigint::BigInt::from(100) << b.max(0) as usize,
            )
        });
        let pow = |v: &BigRational| crate::specular::power(v, s);
        values
            .iter()
            .enumerate()
            .map(|(i, v)| {
                let pair = phong.exact_at(span, i as u32);
                if let Some((p, q)) = pair.or_else(|| roots.as_ref()?.get(i).cloned()) {
                    if s == 0 {
                        return Some(255);
                    }
                    if !p.is_positive() {
                        return Some(0);
                    }
                    let (ps, qs) = (Pow::pow(p, 2 * s), Pow::pow(q, s));
                    let limit = ps * BigRational::from_integer((255 * 255).into());
                    return (0..=255u32)
                        .rev()
                        .find(|&l| BigRational::from_integer((l * l).into()) * qs.clone() <= limit)
                        .map(|l| l as u8);
                }
                match &e {
                    None => Some(level_of_rational(&pow(v))),
                    Some(e) => level_within(&pow(v), e),
                }
            })
            .collect()
    }
}

/// `⌈log2(1/f)⌉` for `0 < f` (0 when `f ≥ 1`; very large, and safe to add to, for
/// `f ≤ 0`): the bits a quantity as small as `f` costs (`span`'s MPFR run reads it
/// for `q_min` too).
pub(crate) fn log2_recip(f: f64) -> i64 {
    if f >= 1.0 {
        0
    } else if f > 0.0 {
        (-f.log2()).ceil() as i64
    } else {
        i64::MAX / 8
    }
}

/// A method's parameters, prepared once for many spans: the diffuse coefficient of
/// the adaptive test and, for the tabled angular method, its cosine table.
#[derive(Clone, Debug)]
pub struct Prepared<T> {
    /// `K_d` of eq. 24's test `|δ·255·K_d| < 1`.
    pub kd: T,
    /// The cosine table of [`Method::AngularTable`].
    pub table: Option<CosTable<T>>,
}

impl<T: Real> Prepared<T> {
    /// The parameters of `method` with diffuse coefficient `kd`.
    ///
    /// # Errors
    /// [`SpanError::Parameter`] for a table size out of range.
    pub fn new(method: Method, kd: T) -> Result<Self, SpanError> {
        let table = match method {
            Method::AngularTable(size) => Some(CosTable::new(size)?),
            _ => None,
        };
        Ok(Prepared { kd, table })
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name())
    }
}

/// The error of parsing a method name.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown method '{0}' (expected one of: {names})", names = names())]
/// (The name as given, cut to 80 characters and escaped.)
pub struct UnknownMethod(pub String);

/// Every method's name, comma-separated (the tabled one as `angular-table<SIZE>`).
pub fn names() -> String {
    Method::ALL
        .iter()
        .map(|m| match m {
            Method::AngularTable(_) => "angular-table<SIZE>".to_string(),
            m => m.name().into_owned(),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

impl FromStr for Method {
    type Err = UnknownMethod;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        if let Some(size) = s.strip_prefix("angular-table") {
            // Digits only, no sign or leading zero, so the name round-trips.
            if !size.is_empty()
                && size.bytes().all(|b| b.is_ascii_digit())
                && !size.starts_with('0')
            {
                if let Ok(size) = size.parse() {
                    return Ok(Method::AngularTable(size));
                }
            }
        }
        Method::ALL
            .iter()
            .find(|m| !matches!(m, Method::AngularTable(_)) && m.info().name == s)
            .copied()
            .ok_or_else(|| UnknownMethod(crate::error::shown(s)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_parses_back() {
        for m in Method::ALL
            .into_iter()
            .chain([Method::AngularTable(2), Method::AngularTable(1 << 24)])
        {
            assert_eq!(m.name().parse::<Method>(), Ok(m), "{m}");
            assert_eq!(m.to_string(), m.name());
        }
        let mut seen = std::collections::HashSet::new();
        for m in Method::ALL {
            assert!(seen.insert(m.name()), "two methods named {m}");
        }
        for bad in [
            "",
            "fence",
            "gouraud-span",
            "angular-table",
            "angular-table0256",
            "angular-table+5",
            "Phong",
        ] {
            assert!(bad.parse::<Method>().is_err(), "{bad}");
        }
    }

    #[test]
    fn field_methods_run_on_field_operations() {
        use crate::reference::unit::unit_from_ints;
        let span = Span::new(
            unit_from_ints(1, 0, 3),
            unit_from_ints(-1, 0, 3),
            unit_from_ints(0, 0, 1),
            4,
        )
        .unwrap();
        let one = BigRational::from_integer(1.into());
        for m in Method::ALL {
            let mut a = vec![one.clone(); 5];
            let r = m.run_field(&span, &one, &mut a);
            assert_eq!(r.is_ok(), m.is_rational(), "{m}");
            if r.is_ok() {
                assert_eq!(a, m.values(&span).unwrap(), "{m}");
            }
        }
    }
}
