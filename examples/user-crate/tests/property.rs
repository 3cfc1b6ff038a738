//! A property test as the test kit's docs show it (docs/conformance.md §4): this
//! crate's Phong on random mesh spans, each judged exactly under `ieee`. The exact
//! oracle is the costly part; `Cargo.toml` optimizes phong-approx and its big-number
//! crates in the dev profile, as the docs recommend (the debug and release figures:
//! docs/conformance.md, "Cost").

use glam::Vec3;
use phong_approx::testkit::prelude::*;
use proptest::prelude::*;
use shader_under_test::phong;

fn v(x: [f32; 3]) -> Vec3 {
    Vec3::from_array(x)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn my_phong_is_within_ieee(span in strategy::mesh_span(1..=64)) {
        let r = check_span(Method::Phong, &span, Profile::Ieee, |s: &Inputs<f32>| {
            phong(v(s.na), v(s.nb), v(s.l), s.n)
        })?;
        prop_assert!(r.is_ok(), "{}", r);
    }
}
