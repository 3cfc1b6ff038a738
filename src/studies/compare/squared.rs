//! Corrected Euler on `(N·H)²` ([`crate::squared_corrected_euler`], the paper's §7.1
//! question b) on the tori: per shininess, how many specular levels of a span differ
//! from Phong's, and by how much, beside corrected Euler on `N·H` then the power and
//! Duff then the power.
//!
//! The reference is Phong's value of the same span, `p_i/√q_i` on the row's `f32`
//! inputs computed in `f64`; the three methods are the `f32` runs (the squared method
//! from [`SquaredSpan`] with `g^{s/2}`, the other two the comparison's own `N·H` columns
//! with `max(0, v)^s`).

use super::{index, level, Shader};
use crate::squared_corrected_euler::SquaredSpan;
use crate::{Method, Span, Vec3};

/// The shininess values of the squared method's table (the 8, 32 and 128:
/// even, so the method takes no root per pixel).
pub const SQUARED_SHININESS: [u32; 3] = [8, 32, 128];

/// The methods compared, in the table's order.
pub const SQUARED_METHODS: [&str; 3] = [
    "squared corrected Euler",
    "corrected Euler then power",
    "Duff then power",
];

/// Specular levels against Phong's at one shininess.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SquaredCount {
    /// Pixels compared.
    pub pixels: u64,
    /// Per method of [`SQUARED_METHODS`]: pixels whose level differs from Phong's.
    pub differ: [u64; 3],
    /// Per method: the largest difference, in levels.
    pub max: [u8; 3],
}

impl SquaredCount {
    /// Adds `o` into `self`.
    pub fn merge(&mut self, o: &SquaredCount) {
        self.pixels += o.pixels;
        for k in 0..3 {
            self.differ[k] += o.differ[k];
            self.max[k] = self.max[k].max(o.max[k]);
        }
    }
}

/// The shininess of the squared method's figure ([`super::CompareFrame::squared_map`]).
pub const SQUARED_FIGURE_SHININESS: u32 = SQUARED_SHININESS[1];

/// Counts one row: `span` its half-vector span in `f32`, `spec` the comparison's `f32`
/// `N·H` values per column, into `counts` (one per [`SQUARED_SHININESS`]). A row whose
/// inputs do not set up in `f64` is left out. Returns, per pixel at
/// [`SQUARED_FIGURE_SHININESS`], Phong's level and the three methods' (empty for a row
/// left out).
pub(super) fn count_row(
    span: &Span<f32>,
    spec: &[Vec<f32>],
    counts: &mut [SquaredCount],
) -> Vec<[u8; 4]> {
    let mut figure = Vec::new();
    let c64 = |v: &Vec3<f32>| Vec3::new(f64::from(v.x), f64::from(v.y), f64::from(v.z));
    let Ok(s64) = Span::with_tolerance(c64(&span.na), c64(&span.nb), c64(&span.l), span.n, &1e-5)
    else {
        return figure;
    };
    let len = span.n as usize + 1;
    let mut phong = vec![0f64; len];
    if Method::Phong.shade(&s64, &mut phong).is_err() {
        return figure;
    }
    let Ok(sq) = SquaredSpan::of(span) else {
        return figure;
    };
    let mut g = vec![0f32; len];
    let (ce, duff) = (
        &spec[index(Shader::Span(Method::CorrectedEuler))],
        &spec[index(Shader::Span(Method::Duff))],
    );
    for (count, &s) in counts.iter_mut().zip(&SQUARED_SHININESS) {
        if sq.specular(s, &mut g).is_err() {
            return Vec::new();
        }
        let pow = |v: f64| level(&crate::specular::power(&v, s));
        for j in 0..len {
            let want = pow(phong[j]);
            let got = [
                level(&f64::from(g[j])),
                pow(f64::from(ce[j])),
                pow(f64::from(duff[j])),
            ];
            if s == SQUARED_FIGURE_SHININESS {
                figure.push([want, got[0], got[1], got[2]]);
            }
            count.pixels += 1;
            for ((differ, max), got) in count.differ.iter_mut().zip(&mut count.max).zip(got) {
                let d = got.abs_diff(want);
                *differ += u64::from(d != 0);
                *max = (*max).max(d);
            }
        }
    }
    figure
}

/// The squared method's section of the report: per torus and shininess, the pixels
/// whose specular level differs from Phong's and the largest difference, per method.
pub fn table(tori: &[super::CompareResult]) -> String {
    let mut s = String::from(
        "## Corrected Euler on (N·H)² (§7.1, question b)\n\n\
         Every span of every fourth frame (`SKIP_EVERY`), K_s = 1: the specular level of each f32 run — \
         the squared method (`squared_corrected_euler`, g^(s/2), no root), corrected Euler on N·H then \
         the power, Duff then the power — against Phong's value of the same span (p/√q on the f32 \
         inputs, in f64; its level decided in f64, so a pixel within f64 rounding of a level boundary may count \
         either way): the pixels whose level differs, and the largest difference in levels.\n\n\
         | torus | s | pixels |",
    );
    for m in SQUARED_METHODS {
        s += &format!(" {m}: differ | max |");
    }
    s += "\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for t in tori {
        for (c, sh) in t.stats.squared.iter().zip(SQUARED_SHININESS) {
            s += &format!("| {} | {sh} | {} |", t.polygons, c.pixels);
            for k in 0..3 {
                let pct = if c.pixels == 0 {
                    0.0
                } else {
                    100.0 * c.differ[k] as f64 / c.pixels as f64
                };
                s += &format!(" {} ({pct:.2} %) | {} |", c.differ[k], c.max[k]);
            }
            s += "\n";
        }
    }
    s
}
