//! Seiler's quadratic shading (SIGGRAPH 1998 sketch): one quadratic per triangle that
//! takes the exact intensity at six points, the three vertices and the three edge
//! midpoints (the mid-edge normal normalized), evaluated along a scan line by forward
//! differences in two additions per pixel.
//!
//! *Reconstructed*: the form of the quadratic is the standard six-node Lagrange
//! element, `I = Σ I_i λ_i (2λ_i − 1) + Σ_{i<j} 4 I_ij λ_i λ_j` in barycentric
//! coordinates `λ`, rewritten in screen space as `A x² + B x y + C y² + D x + E y + F`
//! (centroid-relative). The sketch gives the six points; the basis is ours.
//!
//! Claims: `seiler_is_exact_at_the_six_points`, `seiler_reproduces_quadratics`,
//! `seiler_forward_differences_are_exact` (proofs/Related.v; tests/related.rs).

use crate::error::SpanError;
use crate::related::triangle::{forward_differences, Affine, Triangle};
use crate::scalar::{Real, Scalar};
use crate::vector::Vec3;

/// `A x² + B x y + C y² + D x + E y + F` in centroid-relative coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Quadratic<T> {
    /// `x²`.
    pub a: T,
    /// `x y`.
    pub b: T,
    /// `y²`.
    pub c: T,
    /// `x`.
    pub d: T,
    /// `y`.
    pub e: T,
    /// 1 (the value at the centroid).
    pub f: T,
}

/// The product of two affine forms.
fn product<T: Scalar>(p: &Affine<T>, q: &Affine<T>) -> Quadratic<T> {
    Quadratic {
        a: p.ax.clone() * q.ax.clone(),
        b: p.ax.clone() * q.by.clone() + p.by.clone() * q.ax.clone(),
        c: p.by.clone() * q.by.clone(),
        d: p.ax.clone() * q.c.clone() + p.c.clone() * q.ax.clone(),
        e: p.by.clone() * q.c.clone() + p.c.clone() * q.by.clone(),
        f: p.c.clone() * q.c.clone(),
    }
}

impl<T: Scalar> Quadratic<T> {
    fn zero() -> Self {
        Quadratic {
            a: T::zero(),
            b: T::zero(),
            c: T::zero(),
            d: T::zero(),
            e: T::zero(),
            f: T::zero(),
        }
    }

    fn add_scaled(self, q: &Quadratic<T>, w: &T) -> Self {
        Quadratic {
            a: self.a + q.a.clone() * w.clone(),
            b: self.b + q.b.clone() * w.clone(),
            c: self.c + q.c.clone() * w.clone(),
            d: self.d + q.d.clone() * w.clone(),
            e: self.e + q.e.clone() * w.clone(),
            f: self.f + q.f.clone() * w.clone(),
        }
    }

    /// The quadratic through `vertex[i]` at vertex `i` and `mid[k]` at the midpoint of
    /// the edge from vertex `k` to vertex `k + 1 (mod 3)`.
    pub fn from_six(tri: &Triangle<T>, vertex: &[T; 3], mid: &[T; 3]) -> Self {
        let one = T::one();
        let two = T::from_i64(2);
        let four = T::from_i64(4);
        let mut q = Quadratic::zero();
        for i in 0..3 {
            // λ_i (2 λ_i − 1) = 2 λ_i² − λ_i.
            let l = &tri.lambda[i];
            let sq = product(l, l);
            q = q.add_scaled(&sq, &(two.clone() * vertex[i].clone()));
            let lin = Quadratic {
                d: l.ax.clone(),
                e: l.by.clone(),
                f: l.c.clone(),
                ..Quadratic::zero()
            };
            q = q.add_scaled(&lin, &(-(one.clone()) * vertex[i].clone()));
            let j = (i + 1) % 3;
            let cross = product(l, &tri.lambda[j]);
            q = q.add_scaled(&cross, &(four.clone() * mid[i].clone()));
        }
        q
    }

    /// The value at centroid-relative `(x, y)`.
    pub fn at(&self, x: &T, y: &T) -> T {
        let (x, y) = (x.clone(), y.clone());
        self.a.clone() * x.clone() * x.clone()
            + self.b.clone() * x.clone() * y.clone()
            + self.c.clone() * y.clone() * y.clone()
            + self.d.clone() * x
            + self.e.clone() * y
            + self.f.clone()
    }

    /// Fills `out` with the values at `(x0 + j, y)` by forward differences:
    /// `v += Δ; Δ += 2A`, starting from `Δ = A(2 x0 + 1) + B y + D`.
    pub fn shade_row(&self, x0: &T, y: &T, out: &mut [T]) {
        let two = T::from_i64(2);
        let dv = self.a.clone() * (two.clone() * x0.clone() + T::one())
            + self.b.clone() * y.clone()
            + self.d.clone();
        let ddv = two * self.a.clone();
        forward_differences(self.at(x0, y), dv, &ddv, out);
    }
}

impl<T: Real> Quadratic<T> {
    /// Seiler's quadratic of `N·L` over `tri` with unit vertex normals `normals`: the
    /// vertex values `N_i·L` and the mid-edge values `normalize(N_i + N_j)·L`.
    ///
    /// # Errors
    /// [`SpanError::Parameter`] if two vertex normals are opposite (the mid-edge normal
    /// is zero).
    pub fn from_normals(
        tri: &Triangle<T>,
        normals: &[Vec3<T>; 3],
        l: &Vec3<T>,
    ) -> Result<Self, SpanError> {
        let vertex = [normals[0].dot(l), normals[1].dot(l), normals[2].dot(l)];
        let mut mid = [T::zero(), T::zero(), T::zero()];
        for (k, m) in mid.iter_mut().enumerate() {
            let s = normals[k].add(&normals[(k + 1) % 3]);
            let len2 = s.length_squared();
            if len2.is_zero() {
                return Err(SpanError::Parameter(
                    "Seiler: two vertex normals are opposite".into(),
                ));
            }
            *m = s.dot(l) / len2.sqrt();
        }
        Ok(Quadratic::from_six(tri, &vertex, &mid))
    }
}
