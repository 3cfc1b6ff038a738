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
}

/// The shaders that are not span methods.
pub const POLYGON_SHADERS: [Shader; 5] = [
    Shader::PhongPixel,
    Shader::VertexGouraud,
    Shader::VertexAngle,
    Shader::BishopWeimerTriangle,
    Shader::Seiler,
];

/// Where the comparison shows each polygon method: after the span method it is the
/// polygon form of (or is compared with).
pub const POLYGON_AFTER: [(Method, Shader); 4] = [
    (Method::Gouraud, Shader::VertexGouraud),
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
