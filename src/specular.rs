//! Specular highlights (eq. 1, §6.1): any span method applied to `N·H`, then the
//! power `s` ([`crate::Method::shade_specular`]); and the full intensity `I = K_d·max(0, N·L) + K_s·max(0, N·H)^s`.
//!
//! Where clamping happens: the recurrences themselves are unclamped (they approximate
//! `N·L/|N|`, which is negative where the light is behind the surface). The clamp
//! `max(0, ·)` is applied here, before the power and in eq. 1, and the 8-bit
//! quantiser ([`crate::quantize::level`]) clamps to `[0, 1]` last.

use crate::scalar::Scalar;

/// `max(0, v)^shininess`, by repeated squaring (field operations only: exact for rationals).
pub fn power<T: Scalar>(v: &T, shininess: u32) -> T {
    let mut base = if *v < T::zero() { T::zero() } else { v.clone() };
    let mut acc = T::one();
    let mut e = shininess;
    while e > 0 {
        if e & 1 == 1 {
            acc = acc * base.clone();
        }
        e >>= 1;
        if e > 0 {
            base = base.clone() * base;
        }
    }
    acc
}

/// Eq. 1: `I = K_d·max(0, N·L) + K_s·max(0, N·H)^shininess` from the two dot
/// products.
///
/// The shininess is the paper's `n` in eq. 1 (not the span length).
pub fn intensity<T: Scalar>(kd: &T, ks: &T, shininess: u32, n_dot_l: &T, n_dot_h: &T) -> T {
    kd.clone() * power(n_dot_l, 1) + ks.clone() * power(n_dot_h, shininess)
}
