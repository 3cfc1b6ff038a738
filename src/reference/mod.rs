//! Exact and high-precision references.
//!
//! - [`unit`](mod@unit): exact rational points on the unit sphere, so that the paper's
//!   identities (which need unit edge normals) can be tested with no tolerance.
//! - [`level`]: the exact 8-bit level of the Phong value `p/√q`, decided with
//!   rationals only.
//! - [`radical`]: exact signs and levels in `Q(√a, √b, √c)`, for spans of normalized
//!   rational inputs.
//! - [`transcendental`]: square root, arc cosine and cosine of rationals to 2^-256.
//! - [`decimal`]: correctly rounded decimal strings for rationals.
//! - `mpfr` (feature `mpfr`): an MPFR scalar through `rug`.

pub mod decimal;
pub mod level;
#[cfg(feature = "mpfr")]
pub mod mpfr;
pub mod radical;
pub mod transcendental;
pub mod unit;
