//! What the harness can shade a row with: every span method of the catalogue
//! ([`Method`]), and the methods that are set up per polygon rather than per span.

use crate::Method;
use std::borrow::Cow;
use std::fmt;
use std::str::FromStr;

/// A column of the harness's tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Shader {
    /// A span method of the catalogue, on the row's unit edge normals.
    Span(Method),
    /// Phong with the polygon's normal field normalized at every pixel centre, in
    /// `f64` (the comparison's reference).
    PhongPixel,
    /// Classic Gouraud: intensities computed at the vertices and interpolated over the
    /// polygon.
    VertexGouraud,
    /// The second source as meant: vertex angles over the polygon, byte table.
    VertexAngle,
    /// Bishop & Weimer: the 2-D Taylor expansion at the triangle's centroid, forward
    /// differences.
    BishopWeimerTriangle,
    /// Seiler: six-point quadratic, forward differences.
    Seiler,
    /// A span method's fast `f32`/`f64` kernel on a cheap row set-up of
    /// [`crate::fast_rows`] (from the polygon's normal field, per row).
    Rows(RowSetup),
}

/// The cheap row set-ups of [`crate::fast_rows`], each with the kernel run on it:
/// `f32` and `f64` kernels (the `rsqrt` ones `f32` only), so the comparison runs
/// them in those precisions only.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RowSetup {
    /// Gouraud on the batched set-up (`Batch`, `RowSpan::gouraud`).
    BatchedGouraud,
    /// Corrected Euler on the batched set-up (`RowSpan::corrected_euler`).
    BatchedCorrectedEuler,
    /// Corrected Euler on the edge-stepped set-up (`EdgeStepper`).
    SteppedCorrectedEuler,
    /// The paper's Phong on the batched set-up (`RowSpan::phong`).
    BatchedPhong,
    /// The same with `rsqrtps` and one Newton step (`f32`).
    BatchedPhongRsqrt,
    /// Phong of the field, normalized at every pixel (`RowStart::phong_field`).
    FieldPhong,
    /// The same with `rsqrtps` and one Newton step (`f32`).
    FieldPhongRsqrt,
}

impl RowSetup {
    /// Every row set-up, in the order of the tables.
    pub const ALL: [RowSetup; 7] = [
        RowSetup::BatchedGouraud,
        RowSetup::BatchedCorrectedEuler,
        RowSetup::SteppedCorrectedEuler,
        RowSetup::BatchedPhong,
        RowSetup::BatchedPhongRsqrt,
        RowSetup::FieldPhong,
        RowSetup::FieldPhongRsqrt,
    ];

    /// The span method whose values it computes (Phong of the field: Phong's, with the
    /// normal normalized at every pixel rather than at the edges).
    pub fn method(self) -> Method {
        match self {
            RowSetup::BatchedGouraud => Method::Gouraud,
            RowSetup::BatchedCorrectedEuler | RowSetup::SteppedCorrectedEuler => {
                Method::CorrectedEuler
            }
            _ => Method::Phong,
        }
    }
}

/// The shaders that are not span methods.
pub const POLYGON_SHADERS: [Shader; 12] = [
    Shader::PhongPixel,
    Shader::VertexGouraud,
    Shader::VertexAngle,
    Shader::BishopWeimerTriangle,
    Shader::Seiler,
    Shader::Rows(RowSetup::BatchedGouraud),
    Shader::Rows(RowSetup::BatchedCorrectedEuler),
    Shader::Rows(RowSetup::SteppedCorrectedEuler),
    Shader::Rows(RowSetup::BatchedPhong),
    Shader::Rows(RowSetup::BatchedPhongRsqrt),
    Shader::Rows(RowSetup::FieldPhong),
    Shader::Rows(RowSetup::FieldPhongRsqrt),
];

/// Where the comparison shows each polygon method: after the span method it is the
/// polygon form of (or is compared with); the row set-ups after the method they
/// compute.
pub const POLYGON_AFTER: [(Method, Shader); 11] = [
    (Method::Gouraud, Shader::VertexGouraud),
    (Method::Gouraud, Shader::Rows(RowSetup::BatchedGouraud)),
    (
        Method::CorrectedEuler,
        Shader::Rows(RowSetup::BatchedCorrectedEuler),
    ),
    (
        Method::CorrectedEuler,
        Shader::Rows(RowSetup::SteppedCorrectedEuler),
    ),
    (Method::Phong, Shader::Rows(RowSetup::BatchedPhong)),
    (Method::Phong, Shader::Rows(RowSetup::BatchedPhongRsqrt)),
    (Method::Phong, Shader::Rows(RowSetup::FieldPhong)),
    (Method::Phong, Shader::Rows(RowSetup::FieldPhongRsqrt)),
    (
        Method::AngularTable(crate::method::SOURCE_TABLE),
        Shader::VertexAngle,
    ),
    (Method::BishopWeimer, Shader::BishopWeimerTriangle),
    (Method::BishopWeimer, Shader::Seiler),
];

impl Shader {
    /// The name in tables, file names and pictures; a span method's is its catalogue
    /// name, and every label parses back ([`FromStr`]).
    pub fn label(&self) -> Cow<'static, str> {
        Cow::Borrowed(match self {
            Shader::Span(m) => return m.name(),
            Shader::PhongPixel => "phong-pixel",
            Shader::VertexGouraud => "gouraud-vertex",
            Shader::VertexAngle => "vertex-angle",
            Shader::BishopWeimerTriangle => "bishop-weimer-triangle",
            Shader::Seiler => "seiler",
            Shader::Rows(r) => match r {
                RowSetup::BatchedGouraud => "gouraud-batched",
                RowSetup::BatchedCorrectedEuler => "corrected-euler-batched",
                RowSetup::SteppedCorrectedEuler => "corrected-euler-stepped",
                RowSetup::BatchedPhong => "phong-batched",
                RowSetup::BatchedPhongRsqrt => "phong-batched-rsqrt",
                RowSetup::FieldPhong => "phong-field",
                RowSetup::FieldPhongRsqrt => "phong-field-rsqrt",
            },
        })
    }

    /// Who the method is by.
    pub fn source(&self) -> &'static str {
        match self {
            Shader::Span(m) => m.info().source,
            Shader::PhongPixel => "Phong 1975",
            Shader::VertexGouraud => "Gouraud 1971",
            Shader::VertexAngle => "Mortensen 1995",
            Shader::BishopWeimerTriangle => "Bishop & Weimer 1986",
            Shader::Seiler => "Seiler 1998",
            Shader::Rows(r) => r.method().info().source,
        }
    }

    /// Whether part of the method is a reconstruction (see `docs/comparison.md`).
    pub fn reconstructed(&self) -> bool {
        match self {
            Shader::Span(m) => m.info().reconstructed,
            Shader::Seiler => true,
            _ => false,
        }
    }

    /// Whether the method reads the specular power from a table (Bishop–Weimer's and
    /// Seiler's polygon methods: [`crate::related::power::PowerTable`]).
    pub fn power_from_table(&self) -> bool {
        matches!(self, Shader::BishopWeimerTriangle | Shader::Seiler)
    }
}

impl fmt::Display for Shader {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}

impl FromStr for Shader {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        POLYGON_SHADERS
            .iter()
            .find(|p| p.label() == s)
            .copied()
            .map_or_else(|| s.parse().map(Shader::Span), Ok)
            .map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_label_parses_back_and_is_unique() {
        let all: Vec<Shader> = Method::ALL
            .into_iter()
            .map(Shader::Span)
            .chain(POLYGON_SHADERS)
            .collect();
        let mut seen = std::collections::HashSet::new();
        for s in &all {
            assert_eq!(s.label().parse::<Shader>(), Ok(*s));
            assert!(seen.insert(s.label()), "two shaders labelled {s}");
        }
    }
}
