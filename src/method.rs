//! The span methods by name, so callers (the CLI, the rasterizer, the tests) can
//! iterate over them.

use crate::adaptive;
use crate::error::SpanError;
use crate::scalar::Real;
use crate::span::Span;
use std::fmt;
use std::str::FromStr;

/// One way of shading a span.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// [`crate::phong`]: the exact per-pixel value (eq. 4).
    Phong,
    /// [`crate::duff`]: Duff's forward differences (eqs. 5–7).
    Duff,
    /// [`crate::symmetric_phong`]: half the square roots (§4).
    SymmetricPhong,
    /// [`crate::gouraud`]: linear between the exact edge values (fence shading).
    Gouraud,
    /// [`crate::euler`]: eqs. 12–13.
    Euler,
    /// [`crate::corrected_euler`]: eqs. 16–17.
    CorrectedEuler,
    /// [`crate::adaptive`]: Gouraud or corrected Euler by eqs. 23–24, with `K_d = 1`.
    Adaptive,
    /// [`crate::angular`]: cosine of the linearly interpolated angle (second source).
    Angular,
    /// [`crate::angular::shade_table`] with a cosine table of this many entries.
    AngularTable(u32),
}

impl Method {
    /// Every method, with the second source's 256-entry table for the tabled one.
    pub const ALL: [Method; 9] = [
        Method::Phong,
        Method::Duff,
        Method::SymmetricPhong,
        Method::Gouraud,
        Method::Euler,
        Method::CorrectedEuler,
        Method::Adaptive,
        Method::Angular,
        Method::AngularTable(256),
    ];

    /// The CLI name (`corrected-euler`, …; the tabled angular method is `angular`
    /// with a table size).
    pub fn name(&self) -> &'static str {
        match self {
            Method::Phong => "phong",
            Method::Duff => "duff",
            Method::SymmetricPhong => "symmetric-phong",
            Method::Gouraud => "gouraud",
            Method::Euler => "euler",
            Method::CorrectedEuler => "corrected-euler",
            Method::Adaptive => "adaptive",
            Method::Angular | Method::AngularTable(_) => "angular",
        }
    }

    /// The equations the method implements.
    pub fn equations(&self) -> &'static str {
        match self {
            Method::Phong => "eq. 4",
            Method::Duff => "eqs. 5–7",
            Method::SymmetricPhong => "§4",
            Method::Gouraud => "§1 (fence), eq. 23's d_p",
            Method::Euler => "eqs. 12–14",
            Method::CorrectedEuler => "eqs. 15–17",
            Method::Adaptive => "eqs. 23–24",
            Method::Angular | Method::AngularTable(_) => "second source",
        }
    }

    /// Whether the method uses only field operations (exact in rationals).
    pub fn is_rational(&self) -> bool {
        matches!(
            self,
            Method::Gouraud | Method::Euler | Method::CorrectedEuler | Method::Adaptive
        )
    }

    /// Shades `span` into `out` (`n + 1` values).
    ///
    /// # Errors
    /// [`SpanError::OutputLength`] for a wrong `out`, [`SpanError::Parameter`] for a bad
    /// table size.
    pub fn shade<T: Real>(&self, span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
        match self {
            Method::Phong => crate::phong::shade(span, out),
            Method::Duff => crate::duff::shade(span, out),
            Method::SymmetricPhong => crate::symmetric_phong::shade(span, out),
            Method::Gouraud => crate::gouraud::shade(span, out),
            Method::Euler => crate::euler::shade(span, out),
            Method::CorrectedEuler => crate::corrected_euler::shade(span, out),
            Method::Adaptive => adaptive::shade(span, &T::one(), out).map(|_| ()),
            Method::Angular => crate::angular::shade(span, out),
            Method::AngularTable(size) => {
                let table = crate::angular::CosTable::new(*size)?;
                crate::angular::shade_table(span, &table, out)
            }
        }
    }

    /// Shades `span` into a new vector of `n + 1` values.
    ///
    /// # Errors
    /// As [`Method::shade`].
    pub fn values<T: Real>(&self, span: &Span<T>) -> Result<Vec<T>, SpanError> {
        let mut out = vec![T::zero(); span.len()];
        self.shade(span, &mut out)?;
        Ok(out)
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Method::AngularTable(size) => write!(f, "angular (table of {size})"),
            m => f.write_str(m.name()),
        }
    }
}

/// The error of parsing a method name.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown method '{0}' (expected one of: phong, duff, symmetric-phong, gouraud, euler, corrected-euler, adaptive, angular)")]
/// (The name as given, cut to 80 characters and escaped.)
pub struct UnknownMethod(pub String);

impl FromStr for Method {
    type Err = UnknownMethod;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Ok(match s {
            "phong" => Method::Phong,
            "duff" => Method::Duff,
            "symmetric-phong" => Method::SymmetricPhong,
            "gouraud" => Method::Gouraud,
            "euler" => Method::Euler,
            "corrected-euler" => Method::CorrectedEuler,
            "adaptive" => Method::Adaptive,
            "angular" => Method::Angular,
            other => return Err(UnknownMethod(crate::conformance::shown(other))),
        })
    }
}
