//! The binary float formats an implementation computes in, as a type.
//!
//! One [`Format`] travels from the command line (`--precision`), the test kit
//! (`Suite::check_f32`, `check_f64`) and the GPU runner down to the bounds: the
//! profiles' theorems are stated per format (`proofs/Profiles.v`: `_binary32`,
//! `_binary64`), the verdicts count ulps in it, and the reports name it. Nothing
//! decides a format from the value of its unit roundoff.
//!
//! Fixed point is not a float format: its profile carries its own (`fixed:M.F`,
//! [`crate::tolerance::profile::Profile::Fixed`]).

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
    use super::Format;

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
