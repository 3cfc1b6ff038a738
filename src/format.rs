//! The binary float formats an implementation computes in, as a type.
//!
//! One [`Format`] travels from the command line (`--precision`), the test kit
//! (`Suite::check_f32`, `check_f64`) and the GPU runner down to the bounds: the
//! profiles' theorems are stated per format (`proofs/Profiles.v`: `_binary32`,
//! `_binary64`), the verdicts count ulps in it, and the reports name it. Nothing
//! decides a format from the value of its unit roundoff.
//!
//! The wider concept, the number type a run computes in, is [`Arithmetic`]: a float
//! [`Format`], fixed point, exact rationals or MPFR — what `span --scalar` runs, what
//! the precision study compares, and what names each in a report. Fixed point is not a
//! float format: its acceptance profile carries its widths (`fixed:M.F`,
//! [`crate::tolerance::profile::Profile::Fixed`]).

use std::borrow::Cow;
use std::fmt;
use std::str::FromStr;

/// An IEEE 754 binary float format, round to nearest even.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// binary16 (`f16`): 11 significand bits, `u = 2^-11`.
    Binary16,
    /// binary32 (`f32`): 24 significand bits, `u = 2^-24`.
    Binary32,
    /// binary64 (`f64`): 53 significand bits, `u = 2^-53`.
    Binary64,
}

impl Format {
    /// Every format, narrowest first.
    pub const ALL: [Format; 3] = [Format::Binary16, Format::Binary32, Format::Binary64];

    /// The significand's bits, the hidden bit included (11, 24, 53).
    pub const fn precision(self) -> u32 {
        match self {
            Format::Binary16 => 11,
            Format::Binary32 => 24,
            Format::Binary64 => 53,
        }
    }

    /// The unit roundoff `u = 2^-precision`: half the distance from 1 to the next
    /// float, the largest relative error of one rounding to nearest (below the
    /// subnormals).
    pub const fn u(self) -> f64 {
        match self {
            Format::Binary16 => 1.0 / 2048.0,
            Format::Binary32 => 1.0 / 16_777_216.0,
            Format::Binary64 => f64::EPSILON / 2.0,
        }
    }

    /// The smallest positive subnormal (`2^-24`, `2^-149`, `2^-1074`): the spacing of
    /// the floats below the normal range.
    pub fn smallest_subnormal(self) -> f64 {
        match self {
            Format::Binary16 => 2f64.powi(-24),
            Format::Binary32 => f64::from(f32::from_bits(1)),
            Format::Binary64 => f64::from_bits(1),
        }
    }

    /// The largest absolute error of one rounding to nearest among the subnormals,
    /// half the smallest subnormal (`2^-25`, `2^-150`), as an `f64` rounded up: in
    /// binary64 `2^-1075` is below every `f64`, so `2^-1074`.
    pub fn eta(self) -> f64 {
        match self {
            Format::Binary16 | Format::Binary32 => self.smallest_subnormal() / 2.0,
            Format::Binary64 => f64::from_bits(1),
        }
    }

    /// The smallest positive normal number (`2^-14`, `2^-126`, `2^-1022`): what
    /// flushing denormals to zero loses at most.
    pub fn min_normal(self) -> f64 {
        match self {
            Format::Binary16 => 2f64.powi(-14),
            Format::Binary32 => 2f64.powi(-126),
            Format::Binary64 => 2f64.powi(-1022),
        }
    }

    /// The largest finite number (`65504`, `(2 − 2^-23)·2^127`, `f64::MAX`).
    pub fn max(self) -> f64 {
        match self {
            Format::Binary16 => 65504.0,
            Format::Binary32 => f64::from(f32::MAX),
            Format::Binary64 => f64::MAX,
        }
    }

    /// Whether the format holds `x` exactly (finite, on the format's grid: an integer
    /// multiple of the ulp at `x`, within range).
    pub fn holds(self, x: f64) -> bool {
        if !x.is_finite() || x.abs() > self.max() {
            return false;
        }
        if x == 0.0 {
            return true;
        }
        match self {
            Format::Binary32 => f64::from(x as f32) == x,
            Format::Binary64 => true,
            Format::Binary16 => (x / self.ulp(x)).fract() == 0.0,
        }
    }

    /// The name results and reports use: `binary16`, `f32`, `f64`.
    pub const fn name(self) -> &'static str {
        match self {
            Format::Binary16 => "binary16",
            Format::Binary32 => "f32",
            Format::Binary64 => "f64",
        }
    }

    /// The spacing of this format's numbers at `x` (its ulp there), subnormals
    /// included: `2u·2^⌊log2 |x|⌋`, at least the smallest subnormal; infinite for a
    /// non-finite `x`.
    pub fn ulp(self, x: f64) -> f64 {
        let a = x.abs();
        if !a.is_finite() {
            return f64::INFINITY;
        }
        if a < self.min_normal() {
            return self.smallest_subnormal();
        }
        match self {
            // Exactly, from the bits.
            Format::Binary32 => {
                let a = a as f32;
                f64::from(f32::from_bits(a.to_bits() + 1)) - f64::from(a)
            }
            Format::Binary64 => f64::from_bits(a.to_bits() + 1) - a,
            Format::Binary16 => 2.0 * self.u() * 2f64.powi(a.log2().floor() as i32),
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A name [`Format`] does not know.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown float format '{0}' (expected f16, f32 or f64)")]
pub struct UnknownFormat(pub String);

impl FromStr for Format {
    type Err = UnknownFormat;

    /// `f16`/`binary16`, `f32`/`binary32`, `f64`/`binary64`.
    fn from_str(s: &str) -> Result<Format, UnknownFormat> {
        match s.trim() {
            "f16" | "binary16" => Ok(Format::Binary16),
            "f32" | "binary32" => Ok(Format::Binary32),
            "f64" | "binary64" => Ok(Format::Binary64),
            other => Err(UnknownFormat(crate::error::shown(other))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Arithmetic, Format};

    #[test]
    fn arithmetics_are_named_as_the_reports_name_them() {
        let names: Vec<String> = [
            Arithmetic::Float(Format::Binary16),
            Arithmetic::F32,
            Arithmetic::F64,
            Arithmetic::Fixed {
                int_bits: 8,
                frac_bits: 8,
            },
            Arithmetic::Exact,
            Arithmetic::Mpfr(256),
        ]
        .iter()
        .map(ToString::to_string)
        .collect();
        assert_eq!(names, ["f16", "f32", "f64", "I8F8", "exact", "mpfr"]);
        assert_eq!(Arithmetic::F32.format(), Some(Format::Binary32));
        assert!(Arithmetic::Mpfr(64).is_exact() && !Arithmetic::F64.is_exact());
    }

    #[test]
    fn the_units_are_the_types_own() {
        assert_eq!(Format::Binary32.u(), f64::from(f32::EPSILON) / 2.0);
        assert_eq!(Format::Binary64.u(), f64::EPSILON / 2.0);
        for f in Format::ALL {
            assert_eq!(f.u(), 2f64.powi(-(f.precision() as i32)), "{f}");
        }
        assert_eq!(Format::Binary32.min_normal(), f64::from(f32::MIN_POSITIVE));
        assert_eq!(Format::Binary64.min_normal(), f64::MIN_POSITIVE);
        assert_eq!(Format::Binary32.eta(), 2f64.powi(-150));
        assert_eq!(Format::Binary32.smallest_subnormal(), 2f64.powi(-149));
        // 2^-1075 is not an f64: the bound takes the next one up, never 0.
        assert_eq!(Format::Binary64.eta(), f64::from_bits(1));
        assert!(Format::Binary64.eta() > 0.0);
    }

    #[test]
    fn ulps_are_the_spacing_of_the_floats() {
        for x in [1.0, 0.75, 1.5e-3, 3.0, 1e-40, 0.0, -2.0] {
            let a = (x as f32).abs();
            let next = f64::from(f32::from_bits(a.to_bits() + 1)) - f64::from(a);
            assert_eq!(Format::Binary32.ulp(x), next, "{x}");
            let b = f64::abs(x);
            assert_eq!(Format::Binary64.ulp(x), f64::from_bits(b.to_bits() + 1) - b);
        }
        assert_eq!(Format::Binary16.ulp(1.0), 2f64.powi(-10));
        assert_eq!(Format::Binary16.ulp(1e-6), 2f64.powi(-24));
        assert!(Format::Binary32.ulp(f64::NAN).is_infinite());
    }

    #[test]
    fn names_read_back() {
        for f in Format::ALL {
            assert_eq!(f.name().parse::<Format>(), Ok(f));
        }
        assert!("f8".parse::<Format>().is_err());
    }
}

/// The number type a run computes in: a float [`Format`], fixed point, exact rationals
/// or MPFR. `span` runs in one (`--scalar`), the precision study compares several, and
/// every report names each by [`Arithmetic::name`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Arithmetic {
    /// An IEEE binary float format, round to nearest even.
    Float(Format),
    /// Signed fixed point of `int_bits` integer bits (the sign included) and
    /// `frac_bits` fractional bits (`lowp::I16F16`, feature `lowp`, is 16 and 16).
    Fixed {
        /// Integer bits, the sign included.
        int_bits: u32,
        /// Fractional bits.
        frac_bits: u32,
    },
    /// Exact rationals (square roots, `acos` and `cos` to 2^-256 or more).
    Exact,
    /// MPFR at this many bits (feature `mpfr`).
    Mpfr(u32),
}

impl Arithmetic {
    /// `f32`.
    pub const F32: Arithmetic = Arithmetic::Float(Format::Binary32);
    /// `f64`.
    pub const F64: Arithmetic = Arithmetic::Float(Format::Binary64);

    /// Its name in reports: `f16`, `f32`, `f64`, `I16F16` (fixed point as the `fixed`
    /// crate names it), `exact`, `mpfr`.
    pub fn name(self) -> Cow<'static, str> {
        match self {
            Arithmetic::Float(Format::Binary16) => Cow::Borrowed("f16"),
            Arithmetic::Float(f) => Cow::Borrowed(f.name()),
            Arithmetic::Fixed {
                int_bits,
                frac_bits,
            } => Cow::Owned(format!("I{int_bits}F{frac_bits}")),
            Arithmetic::Exact => Cow::Borrowed("exact"),
            Arithmetic::Mpfr(_) => Cow::Borrowed("mpfr"),
        }
    }

    /// The float format of a float run (`None` for the others).
    pub fn format(self) -> Option<Format> {
        match self {
            Arithmetic::Float(f) => Some(f),
            _ => None,
        }
    }

    /// Exact or MPFR: a reference run rather than an implementation's arithmetic.
    pub fn is_exact(self) -> bool {
        matches!(self, Arithmetic::Exact | Arithmetic::Mpfr(_))
    }
}

impl fmt::Display for Arithmetic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name())
    }
}
