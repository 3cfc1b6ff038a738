//! The arithmetic profiles (`docs/float.md` §18.1): which implementations a bound
//! covers — this crate's own evaluation, IEEE with any order and fusion, the
//! Vulkan/WGSL rules, or fixed point as a hardware span unit runs it. One type, low in
//! the layers, so that the catalogue's theorem rows ([`crate::method::Proved`]) and the
//! tolerances ([`crate::tolerance::profile`]) name the same profiles.

use std::fmt;
use std::str::FromStr;

/// The most fractional bits of `fixed:M.F`: a fixed-point value below 4 (every
/// method's values are) with `F ≤ 51` fractional bits is exact in `f64`, as which
/// `check` reads results, so its verdict is on the exact error.
pub const MAX_FRAC_BITS: u32 = 51;

/// An arithmetic profile (`docs/float.md` §18.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Profile {
    /// This crate's own `f32`/`f64` code: its operation order, round to nearest
    /// even, no fused multiply-add (the bounds of [`crate::tolerance::bound`]).
    Reference,
    /// IEEE binary32/binary64 with round to nearest, but any order of each dot
    /// product and of `p_n`'s three-term sum, fused multiply-add anywhere, and a
    /// division by `n` or 2 through a reciprocal.
    Ieee,
    /// The Vulkan/WGSL precision rules for 32-bit floats: add, sub and mul rounded in
    /// any direction (nearest or toward zero), division within 2.5 ulp, `sqrt` as
    /// `1/inversesqrt`, denormal inputs and results flushed to zero, any order of
    /// each dot product and sum, fused or not. The Coq theorems (Gouraud, corrected
    /// Euler and plain Euler, the recurrences and the closed forms) take every
    /// division — by `n`, by 2, the closed forms' `(i−1)/2` — as one 2.5-ulp division
    /// or a 2.5-ulp reciprocal then a product; corrected Euler's `n(n−1)/2` (in `p_n`)
    /// must be formed exactly (an integer converted, or `n·(n−1)·0.5` with a literal
    /// `0.5`), not by a 2.5-ulp `/2` nor with a computed `1/2`. The derived bounds
    /// (Phong, Duff) cover `·(1/n)` too.
    Shader,
    /// Fixed point `Qm.f` as a hardware span unit runs it (`fixed:m.f`): the set-up
    /// (`p_a`, `t_0`, `ds`, or Gouraud's `dp`) computed exactly and rounded once **to
    /// nearest** at `f ≤` [`MAX_FRAC_BITS`] fractional bits (the theorems' hypothesis
    /// `|e| ≤ 2^-(f+1)`: a truncated set-up, off by up to `2^-f`, is not covered),
    /// then the loop in integer additions,
    /// exact, in registers of `m` integer bits (the sign included) that must not
    /// overflow (`docs/float.md` §14, `proofs/Fixed.v`).
    Fixed {
        /// Integer bits `m`, the sign included.
        int_bits: u32,
        /// Fractional bits `f`.
        frac_bits: u32,
    },
}

impl Profile {
    /// The float profiles, in the order of the docs (fixed point takes its format
    /// as parameters: [`Profile::Fixed`]).
    pub const ALL: [Profile; 3] = [Profile::Reference, Profile::Ieee, Profile::Shader];

    /// The profile's name as `--profile` takes it (`fixed:16.16` for `Q16.16`).
    pub fn name(self) -> String {
        match self {
            Profile::Reference => "reference".into(),
            Profile::Ieee => "ieee".into(),
            Profile::Shader => "shader".into(),
            Profile::Fixed {
                int_bits,
                frac_bits,
            } => format!("fixed:{int_bits}.{frac_bits}"),
        }
    }
}

impl Profile {
    /// Checks that the profile is one the bounds take and `check` can judge: a
    /// fixed-point format of 1 to 64 integer bits and 1 to 51 fractional bits (what
    /// `fixed:M.F` parses: results are read as `f64`, which holds a fixed-point value
    /// below 4 exactly only up to 51 fractional bits); the float profiles always are.
    ///
    /// # Errors
    /// [`ProfileError::FixedWidths`], naming the widths.
    pub fn validate(&self) -> Result<(), ProfileError> {
        match *self {
            Profile::Fixed {
                int_bits,
                frac_bits,
            } if !((1..=64).contains(&int_bits) && (1..=MAX_FRAC_BITS).contains(&frac_bits)) => {
                Err(ProfileError::FixedWidths {
                    int_bits,
                    frac_bits,
                })
            }
            _ => Ok(()),
        }
    }
}

/// A profile that is not one: its name or its fixed-point widths.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ProfileError {
    /// A name that is no profile.
    #[error("unknown profile '{}' (expected reference, ieee, shader or fixed:M.F)", crate::error::shown(.0))]
    Unknown(String),
    /// `fixed:…` that is not `fixed:M.F` with widths the bounds take.
    #[error("'{}' is not fixed:M.F with 1 ≤ M ≤ 64 integer bits and 1 ≤ F ≤ {MAX_FRAC_BITS} fractional bits (e.g. fixed:16.16; results are read as f64, exact up to 51 fractional bits)", crate::error::shown(.0))]
    FixedSyntax(String),
    /// A fixed-point profile built with widths the bounds do not take.
    #[error("fixed point needs 1 ≤ M ≤ 64 integer bits and 1 ≤ F ≤ {MAX_FRAC_BITS} fractional bits (got M = {int_bits}, F = {frac_bits})")]
    FixedWidths {
        /// `M`.
        int_bits: u32,
        /// `F`.
        frac_bits: u32,
    },
}

impl fmt::Display for Profile {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name())
    }
}

impl FromStr for Profile {
    type Err = ProfileError;

    fn from_str(s: &str) -> Result<Self, ProfileError> {
        if let Some(q) = s.strip_prefix("fixed:") {
            let bits = q
                .split_once('.')
                .and_then(|(m, f)| Some((m.parse::<u32>().ok()?, f.parse::<u32>().ok()?)))
                .filter(|&(m, f)| (1..=64).contains(&m) && (1..=MAX_FRAC_BITS).contains(&f));
            return match bits {
                Some((int_bits, frac_bits)) => Ok(Profile::Fixed {
                    int_bits,
                    frac_bits,
                }),
                None => Err(ProfileError::FixedSyntax(s.to_string())),
            };
        }
        Profile::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| ProfileError::Unknown(s.to_string()))
    }
}
