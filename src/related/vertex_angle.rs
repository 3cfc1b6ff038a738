//! The second source's method as its author meant it: the angle `θ = acos(N·L)` is
//! computed at the polygon's *vertices*, interpolated linearly over the polygon like
//! Gouraud's intensity (one addition per pixel), and its cosine read from a table
//! indexed by a byte ([`crate::angular::CosTable`] with 256 entries over 0–90°).
//!
//! The span-level angular method of the core ([`crate::angular`]) takes the angles at
//! the span's edge pixels instead; this one never normalizes a normal per row.
//!
//! Its failure case: when the three vertex angles are equal, the interpolated angle is
//! constant and so is the intensity, whatever the normals in between do
//! (`vertex_angle_equal_angles_give_a_flat_polygon`, proofs/Related.v;
//! tests/related.rs) — a highlight
//! or a dark band inside the polygon cannot appear.

use crate::angular::CosTable;
use crate::related::triangle::{Affine, Triangle};
use crate::scalar::Real;
use crate::vector::Vec3;

/// `acos(N·L)` with `N·L` clamped to `[−1, 1]`.
pub fn vertex_angle<T: Real>(n: &Vec3<T>, l: &Vec3<T>) -> T {
    let one = T::one();
    let mut c = n.dot(l);
    if c > one {
        c = one.clone();
    }
    if c < -one.clone() {
        c = -one;
    }
    c.acos()
}

/// The affine field of the vertex angles over `tri`.
pub fn angle_field<T: Real>(tri: &Triangle<T>, normals: &[Vec3<T>; 3], l: &Vec3<T>) -> Affine<T> {
    tri.affine(&[
        vertex_angle(&normals[0], l),
        vertex_angle(&normals[1], l),
        vertex_angle(&normals[2], l),
    ])
}

/// Fills `out` with `table(θ(x0 + j, y))`: the angle by forward differences, the
/// cosine by look-up.
pub fn shade_row<T: Real>(field: &Affine<T>, table: &CosTable<T>, x0: &T, y: &T, out: &mut [T]) {
    field.shade_row(x0, y, out);
    for o in out.iter_mut() {
        *o = table.lookup(o);
    }
}
