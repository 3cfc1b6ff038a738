//! A three-component vector over any [`Scalar`].
//!
//! glam's vectors are `f32`/`f64` only; the recurrences need the same code on
//! rationals and MPFR, so the span set-up uses this small generic type. Conversions
//! from glam's `Vec3` and `DVec3` are provided.

use crate::scalar::{Real, Scalar};

/// A vector `(x, y, z)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Vec3<T> {
    /// First component.
    pub x: T,
    /// Second component.
    pub y: T,
    /// Third component.
    pub z: T,
}

impl<T: Scalar> Vec3<T> {
    /// `(x, y, z)`.
    pub fn new(x: T, y: T, z: T) -> Self {
        Vec3 { x, y, z }
    }

    /// The components in order.
    pub fn components(&self) -> [&T; 3] {
        [&self.x, &self.y, &self.z]
    }

    /// The dot product `self · o`.
    pub fn dot(&self, o: &Self) -> T {
        self.x.clone() * o.x.clone() + self.y.clone() * o.y.clone() + self.z.clone() * o.z.clone()
    }

    /// `self · self`.
    pub fn length_squared(&self) -> T {
        self.dot(self)
    }

    /// `self + o`.
    pub fn add(&self, o: &Self) -> Self {
        Vec3::new(
            self.x.clone() + o.x.clone(),
            self.y.clone() + o.y.clone(),
            self.z.clone() + o.z.clone(),
        )
    }

    /// `self − o`.
    pub fn sub(&self, o: &Self) -> Self {
        Vec3::new(
            self.x.clone() - o.x.clone(),
            self.y.clone() - o.y.clone(),
            self.z.clone() - o.z.clone(),
        )
    }

    /// `s · self`.
    pub fn scale(&self, s: &T) -> Self {
        Vec3::new(
            self.x.clone() * s.clone(),
            self.y.clone() * s.clone(),
            self.z.clone() * s.clone(),
        )
    }

    /// `self / s`.
    pub fn div(&self, s: &T) -> Self {
        Vec3::new(
            self.x.clone() / s.clone(),
            self.y.clone() / s.clone(),
            self.z.clone() / s.clone(),
        )
    }

    /// The vector converted component-wise to another scalar type (exactly for
    /// exact targets, rounded to nearest for floats).
    pub fn cast<U: Scalar>(&self) -> Option<Vec3<U>> {
        let c = |v: &T| v.to_rational().map(|r| U::from_rational(&r));
        Some(Vec3::new(c(&self.x)?, c(&self.y)?, c(&self.z)?))
    }
}

impl<T: Real> Vec3<T> {
    /// `self / |self|`. For exact rationals the result is only as accurate as
    /// [`Real::sqrt`] (2^-256); use [`crate::reference::unit`] for exact unit vectors.
    pub fn normalize(&self) -> Self {
        self.div(&self.length_squared().sqrt())
    }
}

#[cfg(feature = "glam")]
impl From<glam::Vec3> for Vec3<f32> {
    fn from(v: glam::Vec3) -> Self {
        Vec3::new(v.x, v.y, v.z)
    }
}

#[cfg(feature = "glam")]
impl From<glam::DVec3> for Vec3<f64> {
    fn from(v: glam::DVec3) -> Self {
        Vec3::new(v.x, v.y, v.z)
    }
}

#[cfg(feature = "glam")]
impl From<Vec3<f32>> for glam::Vec3 {
    fn from(v: Vec3<f32>) -> Self {
        glam::Vec3::new(v.x, v.y, v.z)
    }
}
