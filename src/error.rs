//! The typed errors of span set-up and shading.

use std::fmt;
use thiserror::Error;

/// Which input vector an error is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    /// The normal at the left edge, `N_a`.
    Na,
    /// The normal at the right edge, `N_b`.
    Nb,
    /// The light vector `L` (or the half vector `H` for specular).
    L,
}

impl fmt::Display for Input {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Input::Na => "Na",
            Input::Nb => "Nb",
            Input::L => "L",
        })
    }
}

/// Why a span could not be set up or shaded.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum SpanError {
    /// A component is NaN or infinite.
    #[error("{input}: component {component} is not finite")]
    NonFinite {
        /// The vector.
        input: Input,
        /// Its component index, 0 = x, 1 = y, 2 = z.
        component: usize,
    },
    /// The vector is zero.
    #[error("{input}: the vector is zero")]
    ZeroVector {
        /// The vector.
        input: Input,
    },
    /// The vector is not of unit length within the scalar's tolerance.
    #[error("{input}: not a unit vector (length² = {length_squared}, |length² − 1| = {deviation}, allowed ≤ {tolerance:e}); normalize it first")]
    NotUnit {
        /// The vector.
        input: Input,
        /// Its squared length in the span's number type, to 6 significant digits
        /// (exact rationals print `1e-800` for `(0, 0, 1e-400)`, not `0`).
        length_squared: String,
        /// `|length² − 1|` in the span's number type, to 3 significant digits (so a
        /// near-unit input shows how far it is, where its length² prints as 1).
        deviation: String,
        /// The tolerance on `|length² − 1|`, rounded to `f64`.
        tolerance: f64,
    },
    /// `N_b = −N_a` for a method that is undefined there (spherical interpolation has
    /// no unique great circle, binary interpolation bisects `N_a + N_b = 0`).
    #[error("Na and Nb are opposite: this method is undefined for opposite normals (there is no unique arc between them)")]
    Opposite,
    /// The interpolated normal is zero at this pixel (`N_b = −N_a` and `i = n/2`), where
    /// `N·L/|N|` is undefined; the methods that normalize refuse it.
    #[error("pixel {pixel} of n = {n}: the interpolated normal is zero there (Nb = −Na), so N·L/|N| is undefined")]
    ZeroNormal {
        /// The pixel, `n/2`.
        pixel: usize,
        /// The span's `n`.
        n: u32,
    },
    /// `n = 0`: a span needs at least one step.
    #[error("n must be at least 1 (got 0)")]
    ZeroSteps,
    /// `n` above [`crate::span::MAX_STEPS`] (2^24, where `f32` stops counting exactly).
    #[error("n must be at most {max} (got {got})")]
    TooManySteps {
        /// The limit.
        max: u32,
        /// The `n` given.
        got: u32,
    },
    /// The output slice does not hold `n + 1` values.
    #[error("output holds {got} values, the span has {expected} pixels (n + 1)")]
    OutputLength {
        /// `n + 1`.
        expected: usize,
        /// The slice's length.
        got: usize,
    },
    /// A computed value is NaN or infinite: in floats, a divisor rounded to zero at
    /// that pixel — the interpolated normal's squared length `q` (Phong, Duff,
    /// symmetric Phong), `sin Ω` (spherical and binary interpolation) or a power of
    /// `|N|` (Bishop–Weimer) — or a value overflowed, with edge normals nearly opposite.
    /// Every method's values are checked ([`crate::Method::run`]).
    #[error("pixel {pixel} of n = {n}: the value is not finite in this number type (a divisor such as q = N·N or sin Ω rounds to zero there: the edge normals are nearly opposite)")]
    NotFiniteValue {
        /// The pixel, `0..=n`.
        pixel: usize,
        /// The span's `n`.
        n: u32,
    },
    /// A parameter of the method (e.g. a table size) is out of range.
    #[error("{0}")]
    Parameter(String),
}

/// The longest piece of untrusted text a message shows.
pub const SHOWN_CHARS: usize = 80;

/// Untrusted text as a message may show it: at most [`SHOWN_CHARS`] characters (then
/// `…`), with control and other non-printable characters (and a byte-order mark)
/// escaped as `\u{…}`, so that no input can flood or drive the terminal.
pub fn shown(s: &str) -> String {
    let mut out = String::new();
    for (k, c) in s.chars().enumerate() {
        if k == SHOWN_CHARS {
            out.push('…');
            break;
        }
        if c.is_control() || c == '\u{feff}' || c == '\u{202e}' {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    out
}
