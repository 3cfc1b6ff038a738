//! Bishop & Weimer's fast Phong shading (SIGGRAPH 1986): the diffuse intensity
//! `I(x, y) = (a x + b y + c) / √(d x² + e x y + f y² + g x + h y + i)` replaced by
//! its second-order Taylor polynomial about one point, evaluated along a scan line by
//! forward differences in two additions per pixel.
//!
//! **Where the expansion is centred.** Over a triangle, at its centroid: the
//! polygon's normal field `N(x, y) = N1·x + N2·y + N3` is written in
//! centroid-relative coordinates ([`crate::related::triangle`]), so `N3` is the
//! (unnormalized) normal there and `x = y = 0` is the expansion point. Along a single
//! span ([`shade`]), at the span's middle pixel `n/2`; [`Taylor::from_span_at`]
//! expands about any pixel (the literature's scan-line special case expands about the
//! left edge, `x = 0`).
//!
//! The coefficients `T0..T5` are checked against an exact second-order derivative
//! (jet arithmetic in rationals) in `tests/related.rs`
//! (`bishop_weimer_coefficients_are_the_exact_derivatives`), not against a printed
//! text: a widely copied statement of `T5` has `3 i g²` where `3 c g²` is right
//! (`bishop_weimer_printed_t5_is_wrong`).

use crate::error::SpanError;
use crate::related::triangle::forward_differences;
use crate::scalar::Real;
use crate::span::Span;
use crate::vector::Vec3;

/// The six Taylor coefficients: `I ≈ T5 x² + T4 x y + T3 y² + T2 x + T1 y + T0`.
#[derive(Clone, Debug, PartialEq)]
pub struct Taylor<T> {
    /// `T0 = c/s`, the exact intensity at the expansion point (`s = √i`).
    pub t0: T,
    /// `T1 = (2 b i − c h) / (2 i s)` = ∂I/∂y.
    pub t1: T,
    /// `T2 = (2 a i − c g) / (2 i s)` = ∂I/∂x.
    pub t2: T,
    /// `T3 = (3 c h² − 4 c f i − 4 b h i) / (8 i² s)` = ½ ∂²I/∂y².
    pub t3: T,
    /// `T4 = (3 c g h − 2 c e i − 2 b g i − 2 a h i) / (4 i² s)` = ∂²I/∂x∂y.
    pub t4: T,
    /// `T5 = (3 c g² − 4 c d i − 4 a g i) / (8 i² s)` = ½ ∂²I/∂x².
    pub t5: T,
}

impl<T: Real> Taylor<T> {
    /// The expansion of `(L·N) / |N|` for `N(x, y) = n1·x + n2·y + n3` about `(0, 0)`:
    /// `a = L·N1, b = L·N2, c = L·N3, d = N1·N1, e = 2 N1·N2, f = N2·N2,
    /// g = 2 N1·N3, h = 2 N2·N3, i = N3·N3`.
    ///
    /// # Errors
    /// [`SpanError::Parameter`] if an input is not finite or `N3` is zero (the
    /// intensity is undefined at the expansion point).
    pub fn new(n1: &Vec3<T>, n2: &Vec3<T>, n3: &Vec3<T>, l: &Vec3<T>) -> Result<Self, SpanError> {
        let all = [n1, n2, n3, l];
        if all
            .iter()
            .any(|v| v.components().iter().any(|c| !c.is_finite()))
        {
            return Err(SpanError::Parameter(
                "Bishop–Weimer: an input is not finite".into(),
            ));
        }
        let two = T::from_i64(2);
        let (a, b, c) = (l.dot(n1), l.dot(n2), l.dot(n3));
        let (d, e, f) = (n1.dot(n1), two.clone() * n1.dot(n2), n2.dot(n2));
        let (g, h, i) = (
            two.clone() * n1.dot(n3),
            two.clone() * n2.dot(n3),
            n3.dot(n3),
        );
        if i.is_zero() || !i.is_finite() {
            return Err(SpanError::Parameter(
                "Bishop–Weimer: the normal at the expansion point is zero".into(),
            ));
        }
        let s = i.sqrt();
        let k = |v: i64| T::from_i64(v);
        let is = i.clone() * s.clone();
        let i2s = i.clone() * is.clone();
        let t0 = c.clone() / s;
        let t1 = (k(2) * b.clone() * i.clone() - c.clone() * h.clone()) / (k(2) * is.clone());
        let t2 = (k(2) * a.clone() * i.clone() - c.clone() * g.clone()) / (k(2) * is);
        let t3 = (k(3) * c.clone() * h.clone() * h.clone()
            - k(4) * c.clone() * f * i.clone()
            - k(4) * b.clone() * h.clone() * i.clone())
            / (k(8) * i2s.clone());
        let t4 = (k(3) * c.clone() * g.clone() * h.clone()
            - k(2) * c.clone() * e * i.clone()
            - k(2) * b * g.clone() * i.clone()
            - k(2) * a.clone() * h * i.clone())
            / (k(4) * i2s.clone());
        let t5 = (k(3) * c.clone() * g.clone() * g.clone()
            - k(4) * c * d * i.clone()
            - k(4) * a * g * i)
            / (k(8) * i2s);
        Ok(Taylor {
            t0,
            t1,
            t2,
            t3,
            t4,
            t5,
        })
    }

    /// The one-dimensional expansion along `span` about pixel `x_c` (`N1 = k`,
    /// `N2 = 0`, `N3 = N(x_c)`); the polynomial's variable is `i − x_c`.
    ///
    /// Claims: `bishop_weimer_scanline_special_case` (proofs/Related.v;
    /// tests/related.rs).
    ///
    /// # Errors
    /// As [`Taylor::new`].
    pub fn from_span_at(span: &Span<T>, x_c: &T) -> Result<Self, SpanError> {
        let zero = Vec3::new(T::zero(), T::zero(), T::zero());
        let n3 = span.na.add(&span.k.scale(x_c));
        Taylor::new(&span.k, &zero, &n3, &span.l)
    }

    /// The polynomial at `(x, y)` (relative to the expansion point).
    pub fn at(&self, x: &T, y: &T) -> T {
        let (x, y) = (x.clone(), y.clone());
        self.t5.clone() * x.clone() * x.clone()
            + self.t4.clone() * x.clone() * y.clone()
            + self.t3.clone() * y.clone() * y.clone()
            + self.t2.clone() * x
            + self.t1.clone() * y
            + self.t0.clone()
    }

    /// Fills `out` with the polynomial at `(x0 + j, y)`, `j = 0, 1, …` by forward
    /// differences: `I += ΔI; ΔI += 2 T5` (two additions per pixel), starting from
    /// `ΔI = T5 (2 x0 + 1) + T4 y + T2`.
    ///
    /// Claims: `bishop_weimer_forward_differences_are_exact` (proofs/Related.v;
    /// tests/related.rs).
    pub fn shade_row(&self, x0: &T, y: &T, out: &mut [T]) {
        let two = T::from_i64(2);
        let dv = self.t5.clone() * (two.clone() * x0.clone() + T::one())
            + self.t4.clone() * y.clone()
            + self.t2.clone();
        let ddv = two * self.t5.clone();
        forward_differences(self.at(x0, y), dv, &ddv, out);
    }
}

/// Shades `span` with the expansion about its middle pixel `n/2`.
///
/// # Errors
/// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`; [`SpanError::Opposite`] if
/// `N_b = −N_a` (the middle normal, the expansion's centre, is zero);
/// [`SpanError::Parameter`] if the middle normal is zero otherwise (in floats).
pub fn shade<T: Real>(span: &Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    span.check_output(out)?;
    if span.is_opposite() {
        return Err(SpanError::Opposite);
    }
    let x_c = span.n_s.clone() / T::from_i64(2);
    let taylor = Taylor::from_span_at(span, &x_c)?;
    taylor.shade_row(&-x_c, &T::zero(), out);
    Ok(())
}
