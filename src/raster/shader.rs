//! What the harness can shade a row with: every span method of the catalogue
//! ([`Method`]), and the methods that are set up per polygon rather than per span.

use crate::adaptive::Choice;
use crate::method::Prepared;
use crate::scalar::Real;
use crate::{Method, Span};
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
    /// normal normalized at every pixel rather than at the edges): its row of
    /// [`POLYGON`].
    pub fn method(self) -> Method {
        polygon(Shader::Rows(self))
            .after
            .expect("every row set-up computes a span method (POLYGON)")
    }
}

/// A shader that is not a span method, and its facts: one row of [`POLYGON`].
#[derive(Clone, Copy, Debug)]
pub struct Polygon {
    /// The shader.
    pub shader: Shader,
    /// Its name in tables, file names and pictures.
    pub label: &'static str,
    /// The span method the comparison shows it after: the one it is the polygon form
    /// of or is compared with; for a row set-up, the method whose values it computes.
    /// `None` for the reference, which comes first.
    pub after: Option<Method>,
    /// Who it is by; `None`: the method it is shown after is.
    pub source: Option<&'static str>,
    /// Whether part of it is a reconstruction (see `docs/comparison.md`).
    pub reconstructed: bool,
    /// Whether it reads the specular power from a table
    /// ([`crate::related::power::PowerTable`]) rather than computing it.
    pub power_from_table: bool,
}

/// Every shader that is not a span method, in the order of the tables: the one table
/// of their facts.
pub const POLYGON: [Polygon; 12] = {
    use RowSetup as R;
    use Shader as S;
    let ce = Some(Method::CorrectedEuler);
    [
        Polygon {
            shader: S::PhongPixel,
            label: "phong-pixel",
            after: None,
            source: Some("Phong 1975"),
            reconstructed: false,
            power_from_table: false,
        },
        Polygon {
            shader: S::VertexGouraud,
            label: "gouraud-vertex",
            after: Some(Method::Gouraud),
            source: Some("Gouraud 1971"),
            reconstructed: false,
            power_from_table: false,
        },
        Polygon {
            shader: S::VertexAngle,
            label: "vertex-angle",
            after: Some(Method::AngularTable(crate::method::SOURCE_TABLE)),
            source: Some("Mortensen 1995"),
            reconstructed: false,
            power_from_table: false,
        },
        Polygon {
            shader: S::BishopWeimerTriangle,
            label: "bishop-weimer-triangle",
            after: Some(Method::BishopWeimer),
            source: Some("Bishop & Weimer 1986"),
            reconstructed: false,
            power_from_table: true,
        },
        Polygon {
            shader: S::Seiler,
            label: "seiler",
            after: Some(Method::BishopWeimer),
            source: Some("Seiler 1998"),
            reconstructed: true,
            power_from_table: true,
        },
        Polygon {
            shader: S::Rows(R::BatchedGouraud),
            label: "gouraud-batched",
            after: Some(Method::Gouraud),
            source: None,
            reconstructed: false,
            power_from_table: false,
        },
        Polygon {
            shader: S::Rows(R::BatchedCorrectedEuler),
            label: "corrected-euler-batched",
            after: ce,
            source: None,
            reconstructed: false,
            power_from_table: false,
        },
        Polygon {
            shader: S::Rows(R::SteppedCorrectedEuler),
            label: "corrected-euler-stepped",
            after: ce,
            source: None,
            reconstructed: false,
            power_from_table: false,
        },
        Polygon {
            shader: S::Rows(R::BatchedPhong),
            label: "phong-batched",
            after: Some(Method::Phong),
            source: None,
            reconstructed: false,
            power_from_table: false,
        },
        Polygon {
            shader: S::Rows(R::BatchedPhongRsqrt),
            label: "phong-batched-rsqrt",
            after: Some(Method::Phong),
            source: None,
            reconstructed: false,
            power_from_table: false,
        },
        Polygon {
            shader: S::Rows(R::FieldPhong),
            label: "phong-field",
            after: Some(Method::Phong),
            source: None,
            reconstructed: false,
            power_from_table: false,
        },
        Polygon {
            shader: S::Rows(R::FieldPhongRsqrt),
            label: "phong-field-rsqrt",
            after: Some(Method::Phong),
            source: None,
            reconstructed: false,
            power_from_table: false,
        },
    ]
};

/// The row of [`POLYGON`] of a shader that is not a span method.
///
/// # Panics
/// If `sh` is a span method or has no row (a test checks every one has).
fn polygon(sh: Shader) -> &'static Polygon {
    POLYGON
        .iter()
        .find(|p| p.shader == sh)
        .expect("every shader that is not a span method has a row of POLYGON")
}

impl Shader {
    /// The name in tables, file names and pictures; a span method's is its catalogue
    /// name, and every label parses back ([`FromStr`]).
    pub fn label(&self) -> Cow<'static, str> {
        match self {
            Shader::Span(m) => m.name(),
            _ => Cow::Borrowed(polygon(*self).label),
        }
    }

    /// Who the method is by.
    pub fn source(&self) -> &'static str {
        match self {
            Shader::Span(m) => m.info().source,
            _ => {
                let p = polygon(*self);
                p.source.unwrap_or_else(|| {
                    p.after
                        .expect("a row of POLYGON without a source is shown after a method")
                        .info()
                        .source
                })
            }
        }
    }

    /// Whether part of the method is a reconstruction (see `docs/comparison.md`).
    pub fn reconstructed(&self) -> bool {
        match self {
            Shader::Span(m) => m.info().reconstructed,
            _ => polygon(*self).reconstructed,
        }
    }

    /// Whether the method reads the specular power from a table (Bishop–Weimer's and
    /// Seiler's polygon methods: [`crate::related::power::PowerTable`]).
    pub fn power_from_table(&self) -> bool {
        match self {
            Shader::Span(_) => false,
            _ => polygon(*self).power_from_table,
        }
    }
}

/// Shades one row of `n + 1` pixels with every shader of `which`, into
/// `out[slot(shader)]` (each cleared and filled with `n + 1` values): the one way every
/// study shades a row. A span method runs on `span`, the row's span between its unit
/// edge normals (`None` for a one-pixel row: its value is `p_a`, the edge normal's);
/// a polygon shader is the study's own set-up, `polygon(shader, values)`. Returns the
/// adaptive scheme's pick where it ran (`Some(None)` where it did not), or `None`
/// where a method or the set-up cannot shade the row.
pub fn shade_row<T: Real>(
    span: Option<&Span<T>>,
    p_a: &T,
    prep: &Prepared<T>,
    which: &[Shader],
    slot: impl Fn(Shader) -> usize,
    out: &mut [Vec<T>],
    polygon: &mut dyn FnMut(Shader, &mut [T]) -> Option<()>,
) -> Option<Option<Choice>> {
    let len = span.map_or(1, |s| s.n as usize + 1);
    let mut choice = None;
    for &sh in which {
        let o = &mut out[slot(sh)];
        o.clear();
        o.resize(len, T::zero());
        match (sh, span) {
            (Shader::Span(_), None) => o[0] = p_a.clone(),
            (Shader::Span(m), Some(span)) => {
                if let Some(d) = m.run(span, prep, o).ok()? {
                    choice = Some(d.choice);
                }
            }
            _ => polygon(sh, o)?,
        }
    }
    Some(choice)
}

impl fmt::Display for Shader {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}

impl FromStr for Shader {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        POLYGON
            .iter()
            .find(|p| p.label == s)
            .map(|p| p.shader)
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
            .chain(POLYGON.iter().map(|p| p.shader))
            .collect();
        let mut seen = std::collections::HashSet::new();
        for s in &all {
            assert_eq!(s.label().parse::<Shader>(), Ok(*s));
            assert!(seen.insert(s.label()), "two shaders labelled {s}");
        }
        // Every row set-up has its row, with the method it computes.
        for r in RowSetup::ALL {
            let _ = r.method();
        }
    }
}
