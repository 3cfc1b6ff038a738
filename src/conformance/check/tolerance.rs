//! How close a result must be: levels, absolute, ulps, or a profile's bound; and the
//! float formats' ulps the verdicts count in.

use std::fmt;

/// How close a result must be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tolerance {
    /// At most this many 8-bit levels from the expected level.
    Levels(u32),
    /// At most this far from the expected value.
    Abs(f64),
    /// At most this many ulps from it, in the implementation's format (`f32` unless
    /// [`check_in`](super::check_in) is told the format), counted at the case's scale:
    /// the ulp of the largest `|expected value|` of the span. The methods' errors are
    /// absolute, on values of that magnitude; the ulp of a value near zero would make
    /// a tiny absolute error look like tens of thousands of ulps.
    Ulps(f64),
    /// The bound for every implementation of an arithmetic profile, as
    /// [`crate::tolerance::profile::status`] labels it per method and format
    /// ([`crate::tolerance::profile`], `docs/float.md` §18); under
    /// [`Profile::Reference`](crate::tolerance::profile::Profile::Reference), the
    /// crate's documented float bound for its own evaluation (`src/tolerance.rs`). A
    /// case with no bound for the profile fails, naming why.
    Profile {
        /// The profile.
        profile: crate::tolerance::profile::Profile,
        /// The implementation's float format (not read under fixed point, whose
        /// profile names its own).
        format: crate::Format,
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
    /// A [`ToleranceError`] saying what was expected.
    pub fn parse(s: &str) -> Result<Tolerance, ToleranceError> {
        let (k, v) = s
            .split_once('=')
            .ok_or_else(|| ToleranceError::Syntax(s.to_string()))?;
        let num: f64 = v
            .trim()
            .parse()
            .map_err(|_| ToleranceError::NotANumber(v.to_string()))?;
        if !(num.is_finite() && num >= 0.0) {
            return Err(ToleranceError::NotFinite(v.to_string()));
        }
        match k.trim() {
            "levels" if num.fract() == 0.0 && num <= 255.0 => Ok(Tolerance::Levels(num as u32)),
            "levels" => Err(ToleranceError::Levels(v.to_string())),
            "abs" => Ok(Tolerance::Abs(num)),
            "ulps" => Ok(Tolerance::Ulps(num)),
            other => Err(ToleranceError::Unknown(other.to_string())),
        }
    }
}

impl Tolerance {
    /// The float format the tolerance names (`None` for levels, absolute and ulps
    /// tolerances, which name none, and for fixed point, whose format is its profile's).
    pub fn format(&self) -> Option<crate::Format> {
        match *self {
            Tolerance::Profile {
                profile: crate::tolerance::profile::Profile::Fixed { .. },
                ..
            } => None,
            Tolerance::Profile { format, .. } => Some(format),
            _ => None,
        }
    }

    /// Checks that the tolerance means something: finite, non-negative numbers, a
    /// fixed-point format the bounds take
    /// ([`crate::tolerance::profile::Profile::validate`]).
    ///
    /// # Errors
    /// A [`ToleranceError`] saying what is wrong.
    pub fn validate(&self) -> Result<(), ToleranceError> {
        let ok = |x: f64| x.is_finite() && x >= 0.0;
        match *self {
            Tolerance::Levels(n) if n > 255 => Err(ToleranceError::Levels(n.to_string())),
            Tolerance::Abs(x) | Tolerance::Ulps(x) if !ok(x) => {
                Err(ToleranceError::NotFinite(x.to_string()))
            }
            Tolerance::Profile { profile, .. } => Ok(profile.validate()?),
            _ => Ok(()),
        }
    }
}

/// A tolerance that is not one: how `levels=N`, `abs=X` or `ulps=N` was misspelt, or
/// a profile the bounds do not take.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ToleranceError {
    /// No `=`.
    #[error("'{}' is not levels=N, abs=X or ulps=N", crate::conformance::shown(.0))]
    Syntax(String),
    /// The value is not a number.
    #[error("'{}' is not a number", crate::conformance::shown(.0))]
    NotANumber(String),
    /// The value is negative, infinite or NaN.
    #[error("'{}' must be a finite number ≥ 0", crate::conformance::shown(.0))]
    NotFinite(String),
    /// `levels=` not a whole number from 0 to 255.
    #[error("levels must be a whole number from 0 to 255 (got {})", crate::conformance::shown(.0))]
    Levels(String),
    /// A kind other than levels, abs and ulps.
    #[error("unknown tolerance '{}' (expected levels, abs or ulps)", crate::conformance::shown(.0))]
    Unknown(String),
    /// A profile the bounds do not take.
    #[error(transparent)]
    Profile(#[from] crate::tolerance::profile::ProfileError),
}

/// Why a case has no bound under its tolerance, so that it fails: as data, so that
/// each caller gives its own advice ([`Advice`]: the command line names its
/// flags, the test kit its methods).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum Unbounded {
    /// A declared form for a method whose forms no theorem tells apart.
    #[error("a declared form tells apart only euler's and corrected-euler's theorems; {method} takes the form any")]
    FormNotToldApart {
        /// The method.
        method: String,
    },
    /// A specular case under a profile that does not model the power.
    #[error("the {profile} profile does not model the specular power")]
    SpecularNotModelled {
        /// The profile.
        profile: String,
    },
    /// No bound for the method under the profile in this format.
    #[error("the {profile} profile has no bound for {method} in this format")]
    NoBound {
        /// The profile.
        profile: String,
        /// The method.
        method: String,
    },
    /// A declared closed form under fixed point, whose theorems are the loop's.
    #[error("the {profile} profile's theorems cover the loop, not the closed form")]
    FixedClosedForm {
        /// The profile.
        profile: String,
    },
    /// Fixed-point registers that may overflow on the span.
    #[error("the {profile} profile's registers may overflow on this span: its values and slopes must stay below 2^{limit} in {int_bits} integer bits (docs/float.md §14)")]
    FixedOverflow {
        /// The profile.
        profile: String,
        /// The largest power of two the values and slopes must stay below.
        limit: u32,
        /// The registers' integer bits.
        int_bits: u32,
    },
    /// Duff's fixed-point unit on a span whose `q_min` is too small for its fractional
    /// bits: `r = √(q_min − E_q)` must exceed `2^-F` (`fixed_point_duff_unit_error`).
    #[error("the {profile} profile bounds Duff's unit only where r = √(q_min − E_q) > 2^-{frac_bits}, E_q = 2^-({frac_bits}+1)·(1 + n + n(n−1)/2): this span's q_min is too small (docs/float.md §14)")]
    FixedQMin {
        /// The profile.
        profile: String,
        /// Its fractional bits.
        frac_bits: u32,
    },
    /// The profile's bound does not reach this span: `n` past its range, or `q` may
    /// lose half of itself.
    #[error(
        "no {profile} bound for this span: n past the bound's range, or q may lose half of itself"
    )]
    OutOfRange {
        /// The profile.
        profile: String,
    },
    /// The reference profile has no derived bound for the span.
    #[error("no derived bound")]
    NoDerivedBound,
}

/// What a caller tells its user to do about a case with no bound, per reason (`None`
/// where the reason says it): the command line names its flags, the test kit its
/// methods ([`Unbounded::kit_advice`]). The library's reports take one.
pub type Advice = fn(&Unbounded) -> Option<&'static str>;

impl Unbounded {
    /// The test kit's advice: what to give `Suite` instead.
    pub fn kit_advice(&self) -> Option<&'static str> {
        match self {
            Unbounded::FormNotToldApart { .. } | Unbounded::FixedClosedForm { .. } => None,
            Unbounded::NoBound { .. } => Some(
                "Profile::Reference judges this crate's own evaluation; or give Suite::tolerance",
            ),
            Unbounded::FixedOverflow { .. } => Some("more integer bits, or give Suite::tolerance"),
            Unbounded::FixedQMin { .. } => Some("more fractional bits, or give Suite::tolerance"),
            Unbounded::SpecularNotModelled { .. }
            | Unbounded::OutOfRange { .. }
            | Unbounded::NoDerivedBound => Some("give Suite::tolerance"),
        }
    }

    /// The reason with the caller's advice: `reason (advice)`.
    pub fn with_advice(&self, advice: Advice) -> String {
        match advice(self) {
            Some(a) => format!("{self} ({a})"),
            None => self.to_string(),
        }
    }
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
pub(super) fn exceeds(g: f64, e: f64, ev: &str, b: f64) -> bool {
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

/// Why a case under `tol` has no bound (it then fails): for a profile, the first of its
/// reasons that holds (a declared form the method does not tell apart, a specular case
/// the profile does not model, no bound for the method, a fixed-point closed form, a
/// `q_min` too small for Duff's fixed-point unit — `fixed_q_min`, its fractional bits —,
/// a fixed-point overflow, else a span out of the bounds' range); no derived bound
/// otherwise (the reference profile's bounds are the crate's own, derived).
pub(super) fn why_unbounded(
    tol: Tolerance,
    method: crate::Method,
    specular: bool,
    fixed_q_min: impl FnOnce() -> Option<u32>,
) -> Unbounded {
    use crate::tolerance::profile::{Form, Profile};
    let Tolerance::Profile {
        profile,
        format,
        form,
    } = tol
    else {
        return Unbounded::NoDerivedBound;
    };
    let p = profile.to_string();
    if profile == Profile::Reference {
        Unbounded::NoDerivedBound
    } else if form != Form::Any && !Form::applies_to(method) {
        Unbounded::FormNotToldApart {
            method: method.to_string(),
        }
    } else if specular && matches!(profile, Profile::Shader | Profile::Fixed { .. }) {
        Unbounded::SpecularNotModelled { profile: p }
    } else if crate::tolerance::profile::status(method, profile, format).is_none() {
        Unbounded::NoBound {
            profile: p,
            method: method.to_string(),
        }
    } else if form == Form::Closed && matches!(profile, Profile::Fixed { .. }) {
        Unbounded::FixedClosedForm { profile: p }
    } else if let Some(frac_bits) = fixed_q_min() {
        Unbounded::FixedQMin {
            profile: p,
            frac_bits,
        }
    } else if let Profile::Fixed { int_bits, .. } = profile {
        Unbounded::FixedOverflow {
            profile: p,
            limit: int_bits.saturating_sub(1),
            int_bits,
        }
    } else {
        Unbounded::OutOfRange { profile: p }
    }
}
