//! Exact unit vectors and spans for property tests of your own code (feature
//! `proptest`): `prop_compose!`-style strategies whose defaults stay fast (`n ≤ 64`
//! unless asked).
//!
//! ```
//! # #[cfg(feature = "proptest")] {
//! use phong_approx::testkit::prelude::*;
//! use proptest::prelude::*;
//! proptest!(ProptestConfig::with_cases(16), |(span in strategy::mesh_span(1..=16))| {
//!     let iv = acceptance::<f32>(Method::Gouraud, &span, Profile::Ieee).unwrap();
//!     prop_assert_eq!(iv.len(), span.n as usize + 1);
//! });
//! # }
//! ```

use crate::reference::unit::unit_from_ints;
use crate::{BigRational, Span, Vec3};
use proptest::prelude::*;

/// An exact unit vector from integer stereographic parameters `(a, b)/d`.
pub fn unit_vector() -> impl Strategy<Value = Vec3<BigRational>> {
    (-40i64..=40, -40i64..=40, 1i64..=24).prop_map(|(a, b, d)| unit_from_ints(a, b, d))
}

fn span(
    na: Vec3<BigRational>,
    nb: Vec3<BigRational>,
    l: Vec3<BigRational>,
    n: u32,
) -> Option<Span<BigRational>> {
    Span::new(na, nb, l, n).ok().filter(|s| !s.is_opposite())
}

/// A span as a mesh gives one: nearby edge normals (a few degrees apart), light
/// anywhere, `n` in `steps`.
pub fn mesh_span(steps: std::ops::RangeInclusive<u32>) -> impl Strategy<Value = Span<BigRational>> {
    (
        (-30i64..=30, -30i64..=30, 1i64..=20),
        -3i64..=3,
        -3i64..=3,
        unit_vector(),
        steps,
    )
        .prop_filter_map("a valid span", |((a, b, d), da, db, l, n)| {
            let na = unit_from_ints(8 * a, 8 * b, 8 * d);
            let nb = unit_from_ints(8 * a + da, 8 * b + db, 8 * d);
            span(na, nb, l, n)
        })
}

/// Edge normals nearly opposite (`q` nearly vanishes mid-span): `(0, 0, 1)` and
/// the reflection of a vector `1/m` from `(0, 0, −1)`, `m` from 8 to 4096.
pub fn nearly_opposite(
    steps: std::ops::RangeInclusive<u32>,
) -> impl Strategy<Value = Span<BigRational>> {
    (3u32..=12, unit_vector(), steps).prop_filter_map("a valid span", |(k, l, n)| {
        let m = 1i64 << k;
        // (2m, 0, 1 − m²)/(1 + m²) with m large is near (0, 0, −1).
        let nb = unit_from_ints(m, 0, 1);
        span(unit_from_ints(0, 0, 1), nb, l, n)
    })
}

/// Any span whose `n` is `2^k − 1`, `2^k` or `2^k + 1` (`k ≤ max_k`), where
/// slopes sit next to powers of two.
pub fn around_powers_of_two(max_k: u32) -> impl Strategy<Value = Span<BigRational>> {
    (
        unit_vector(),
        unit_vector(),
        unit_vector(),
        1u32..=max_k.max(1),
        -1i64..=1,
    )
        .prop_filter_map("a valid span", |(na, nb, l, k, d)| {
            let n = ((1i64 << k) + d).max(1) as u32;
            span(na, nb, l, n)
        })
}

/// A mesh span with the light at a grazing angle to `N_a` (`N_a·L` below about
/// 0.05 in magnitude).
pub fn grazing_light(
    steps: std::ops::RangeInclusive<u32>,
) -> impl Strategy<Value = Span<BigRational>> {
    mesh_span(steps).prop_filter("grazing light", |s| {
        use crate::Scalar;
        s.p_a.to_f64().abs() < 0.05
    })
}
