//! The 8-bit quantiser of §6.

use crate::scalar::Scalar;

/// `floor(255 · clamp(v, 0, 1))`, computed in `T` (§6: "multiply our intensity value
/// with 255 and then truncate it"). For floats the product `255·v` is rounded first,
/// as an implementation in that type would; for the exact level of an irrational
/// Phong value use [`crate::reference::level::phong_level_exact`].
///
/// Claims: `eq_24_delta_test_does_not_imply_same_levels` (proofs/Adaptive.v), and for this
/// clamped quantiser `eq_24_delta_test_does_not_imply_same_clamped_levels`,
/// `eq_24_delta_test_fails_on_concrete_span_clamped`,
/// `eq_24_large_delta_implies_different_clamped_levels` (proofs/ClosedForms.v); tests/claims/.
pub fn level<T: Scalar>(v: &T) -> u8 {
    if *v <= T::zero() {
        return 0;
    }
    if *v >= T::one() {
        return 255;
    }
    (v.clone() * T::from_i64(255)).floor_i64().clamp(0, 255) as u8
}
