//! The set-up of one screen-space triangle, shared by the polygon-level methods:
//! barycentric coordinates as affine forms of `(x, y)`, and affine fields of vertex
//! attributes (the normal, an intensity, an angle).
//!
//! Coordinates are taken relative to the triangle's centroid `(x_c, y_c)`, which keeps
//! the numbers small in low precision and is where Bishop & Weimer's expansion is
//! centred ([`crate::related::bishop_weimer`]).

use crate::error::SpanError;
use crate::scalar::Scalar;
use crate::vector::Vec3;

/// `ax·x + by·y + c` in centroid-relative coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Affine<T> {
    /// Coefficient of `x`.
    pub ax: T,
    /// Coefficient of `y`.
    pub by: T,
    /// Value at the centroid.
    pub c: T,
}

impl<T: Scalar> Affine<T> {
    /// The value at centroid-relative `(x, y)`.
    pub fn at(&self, x: &T, y: &T) -> T {
        self.ax.clone() * x.clone() + self.by.clone() * y.clone() + self.c.clone()
    }

    /// Fills `out` with the values at `(x0 + i, y)` by forward differences: one
    /// addition per pixel (classic Gouraud's inner loop).
    pub fn shade_row(&self, x0: &T, y: &T, out: &mut [T]) {
        let mut v = self.at(x0, y);
        for o in out.iter_mut() {
            *o = v.clone();
            v = v + self.ax.clone();
        }
    }
}

/// Fills `out` with a quadratic's values at successive pixels by second-order forward
/// differences from `v`, its first difference `dv` and its constant second difference
/// `ddv`: `v += dv; dv += ddv` — the two additions per pixel of Bishop & Weimer and
/// Seiler.
pub fn forward_differences<T: Scalar>(mut v: T, mut dv: T, ddv: &T, out: &mut [T]) {
    for o in out.iter_mut() {
        *o = v.clone();
        v = v + dv.clone();
        dv = dv + ddv.clone();
    }
}

/// A triangle in screen space with its barycentric forms.
#[derive(Clone, Debug)]
pub struct Triangle<T> {
    /// The centroid, origin of every affine form.
    pub centroid: (T, T),
    /// The vertices relative to the centroid.
    pub vertices: [(T, T); 3],
    /// `λ_i(x, y)`: 1 at vertex `i`, 0 at the other two.
    pub lambda: [Affine<T>; 3],
}

impl<T: Scalar> Triangle<T> {
    /// The triangle with vertices `p` (absolute screen coordinates).
    ///
    /// # Errors
    /// [`SpanError::Parameter`] if a coordinate is not finite or the triangle has no
    /// area.
    pub fn new(p: [(T, T); 3]) -> Result<Self, SpanError> {
        if p.iter().any(|(x, y)| !x.is_finite() || !y.is_finite()) {
            return Err(SpanError::Parameter(
                "triangle: a vertex coordinate is not finite".into(),
            ));
        }
        let three = T::from_i64(3);
        let xc = (p[0].0.clone() + p[1].0.clone() + p[2].0.clone()) / three.clone();
        let yc = (p[0].1.clone() + p[1].1.clone() + p[2].1.clone()) / three;
        let v = p.clone().map(|(x, y)| (x - xc.clone(), y - yc.clone()));
        // Twice the signed area.
        let det = (v[1].0.clone() - v[0].0.clone()) * (v[2].1.clone() - v[0].1.clone())
            - (v[2].0.clone() - v[0].0.clone()) * (v[1].1.clone() - v[0].1.clone());
        if det.is_zero() || !det.is_finite() {
            return Err(SpanError::Parameter(
                "triangle: the vertices are collinear".into(),
            ));
        }
        // λ_i = ((x_k − x_j)(y − y_j) − (y_k − y_j)(x − x_j)) / det for (i, j, k) cyclic.
        let form = |i: usize| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let (xj, yj) = v[j].clone();
            let (xk, yk) = v[k].clone();
            let ax = -(yk.clone() - yj.clone()) / det.clone();
            let by = (xk.clone() - xj.clone()) / det.clone();
            // Value at the origin: (x_j·y_k − x_k·y_j) / det.
            let c = (xj * yk - xk * yj) / det.clone();
            Affine { ax, by, c }
        };
        let lambda = [form(0), form(1), form(2)];
        Ok(Triangle {
            centroid: (xc, yc),
            vertices: v,
            lambda,
        })
    }

    /// The affine field that takes `values[i]` at vertex `i`:
    /// `Σ values_i λ_i` (linear interpolation over the triangle).
    pub fn affine(&self, values: &[T; 3]) -> Affine<T> {
        let mut ax = T::zero();
        let mut by = T::zero();
        let mut c = T::zero();
        for (l, v) in self.lambda.iter().zip(values) {
            ax = ax + l.ax.clone() * v.clone();
            by = by + l.by.clone() * v.clone();
            c = c + l.c.clone() * v.clone();
        }
        Affine { ax, by, c }
    }

    /// The affine normal field `N(x, y) = N1·x + N2·y + N3` of the vertex normals
    /// (Phong's interpolated, not yet normalized, normal), as `(N1, N2, N3)`; `N3` is
    /// the normal at the centroid.
    pub fn normal_field(&self, normals: &[Vec3<T>; 3]) -> (Vec3<T>, Vec3<T>, Vec3<T>) {
        let comp =
            |f: fn(&Vec3<T>) -> T| self.affine(&[f(&normals[0]), f(&normals[1]), f(&normals[2])]);
        let (x, y, z) = (
            comp(|v| v.x.clone()),
            comp(|v| v.y.clone()),
            comp(|v| v.z.clone()),
        );
        (
            Vec3::new(x.ax, y.ax, z.ax),
            Vec3::new(x.by, y.by, z.by),
            Vec3::new(x.c, y.c, z.c),
        )
    }

    /// Centroid-relative coordinates of the absolute point `(x, y)`.
    pub fn relative(&self, x: &T, y: &T) -> (T, T) {
        (
            x.clone() - self.centroid.0.clone(),
            y.clone() - self.centroid.1.clone(),
        )
    }
}
