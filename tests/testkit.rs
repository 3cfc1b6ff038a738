//! The test kit (`phong_approx::testkit`) as an implementer calls it: a correct
//! implementation passes, wrong ones fail with a message that helps fix them.

use phong_approx::conformance::check::Tolerance;
use phong_approx::testkit::Suite;
use phong_approx::tolerance::profile::Profile;
use phong_approx::Method;

fn dot<T: Copy + std::ops::Mul<Output = T> + std::ops::Add<Output = T>>(a: [T; 3], b: [T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Corrected Euler (eqs. 15–17) in `f32`, with `ε/(n + bias)`: 0 is right, 1 is the
/// mutant of the paper's printed "dε = ε/N" read with N = n + 1.
fn corrected_euler(na: [f32; 3], nb: [f32; 3], l: [f32; 3], n: u32, bias: f32) -> Vec<f32> {
    let nf = n as f32;
    let k = [0, 1, 2].map(|j| (nb[j] - na[j]) / nf);
    let (a, pa, pb) = (dot(k, l), dot(na, l), dot(nb, l));
    let (c, d) = (dot(k, k), 2.0 * dot(k, na));
    let dia = a - pa / 2.0 * d;
    let dib = a - pb / 2.0 * (2.0 * nf * c + d);
    let ds = (dib - dia) / nf;
    let eps = pa + nf * dia + nf * (nf - 1.0) / 2.0 * ds - pb;
    let (mut p, mut t) = (pa, dia - eps / (nf + bias));
    let mut out = vec![p];
    for _ in 0..n {
        p += t;
        t += ds;
        out.push(p);
    }
    out
}

#[test]
fn a_correct_implementation_passes_under_every_profile() {
    for profile in Profile::ALL {
        let r = Suite::published()
            .method(Method::CorrectedEuler)
            .profile(profile)
            .check_f32(|s| corrected_euler(s.na, s.nb, s.l, s.n, 0.0));
        assert!(r.is_ok(), "{r}");
        assert_eq!(r.cases(), 42 + 23 + 6);
    }
}

#[test]
fn a_wrong_implementation_fails_with_a_message_that_helps() {
    let r = Suite::published()
        .method(Method::CorrectedEuler)
        .profile(Profile::Ieee)
        .check_f32(|s| corrected_euler(s.na, s.nb, s.l, s.n, 1.0));
    assert!(!r.is_ok());
    let text = r.to_string();
    println!("{text}");
    assert!(text.starts_with("corrected-euler in f32 judged by the ieee profile's bound: "));
    for needle in [
        "typical/typical-",
        "N_a       = (",
        "(0x",
        "pixel     = ",
        "expected  = ",
        "got       = ",
        " f32 ulps, ",
        " levels",
        "allowed   = ",
        "reproduce = phong-approx span --method corrected-euler --na=",
        " more: ",
    ] {
        assert!(text.contains(needle), "'{needle}' not in:\n{text}");
    }
    // At most five failures in full, then the ids of the rest.
    assert_eq!(text.matches("reproduce = ").count(), 5);
    // assert_ok panics with the same text.
    let panic = std::panic::catch_unwind(|| r.assert_ok()).unwrap_err();
    let msg = panic.downcast_ref::<String>().unwrap();
    assert_eq!(msg, &text);
}

#[test]
fn eight_bit_implementations_are_judged_in_levels() {
    // A span unit that shades in f64 and outputs floor(255·clamp(v)): within a level.
    let levels = |s: &phong_approx::testkit::Inputs<f64>| -> Vec<u8> {
        let na = s.na.map(|x| x as f32);
        let nb = s.nb.map(|x| x as f32);
        let l = s.l.map(|x| x as f32);
        corrected_euler(na, nb, l, s.n, 0.0)
            .into_iter()
            .map(|v| (255.0 * v.clamp(0.0, 1.0)).floor() as u8)
            .collect()
    };
    let r = Suite::published()
        .method(Method::CorrectedEuler)
        .check_levels(levels);
    assert!(r.is_ok(), "{r}");
    // Off by two levels everywhere: fails, named in levels.
    let r = Suite::set("paper")
        .method(Method::CorrectedEuler)
        .check_levels(|s| levels(s).into_iter().map(|l| l.saturating_sub(2)).collect());
    assert!(!r.is_ok());
    assert!(
        r.to_string().starts_with("corrected-euler in 8-bit levels"),
        "{r}"
    );
}

#[test]
fn wrong_lengths_and_non_finite_values_are_named() {
    let r = Suite::set("paper")
        .method(Method::Gouraud)
        .check_f64(|s| vec![0.5; s.n as usize]);
    assert_eq!(r.failures().len(), 6, "{r}");
    assert!(r.to_string().contains("the span has n + 1 = "), "{r}");
    let r = Suite::set("typical")
        .method(Method::Phong)
        .tolerance(Tolerance::Levels(1))
        .check_f64(|s| vec![f64::NAN; s.n as usize + 1]);
    assert_eq!(r.failures().len(), 42);
    assert!(r.to_string().contains("off by    = not finite"), "{r}");
}

/// The generators and the oracle (features `proptest` and `quickcheck`; CI runs them
/// with `--all-features`).
#[cfg(all(feature = "proptest", feature = "quickcheck"))]
mod generators {
    use super::{corrected_euler, Profile};
    use phong_approx::testkit::{acceptance, oracle, strategy, ArbSpan};
    use phong_approx::{BigRational, Scalar, Span};
    use proptest::prelude::*;

    fn floats(v: &phong_approx::Vec3<BigRational>) -> [f32; 3] {
        [
            v.x.to_f64() as f32,
            v.y.to_f64() as f32,
            v.z.to_f64() as f32,
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// The five-line differential test the kit is for: an implementation's values in
        /// the acceptance interval of its profile on spans of every kind.
        #[test]
        fn own_code_is_within_the_acceptance_interval(
            span in prop_oneof![
                strategy::mesh_span(1..=32),
                strategy::nearly_opposite(1..=32),
                strategy::around_powers_of_two(6),
                strategy::grazing_light(1..=32),
            ]
        ) {
            let got = corrected_euler(floats(&span.na), floats(&span.nb), floats(&span.l), span.n, 0.0);
            let iv = acceptance::<f32>(phong_approx::Method::CorrectedEuler, &span, Profile::Ieee).unwrap();
            for (i, (g, (lo, hi))) in got.iter().zip(&iv).enumerate() {
                prop_assert!(*lo <= f64::from(*g) && f64::from(*g) <= *hi, "pixel {}", i);
            }
            // And the ε/(n+1) mutant leaves it somewhere on spans with a correction.
            let bad = corrected_euler(floats(&span.na), floats(&span.nb), floats(&span.l), span.n, 1.0);
            let eps = span.eps.to_f64().abs();
            if eps > 1e-3 {
                prop_assert!(bad.iter().zip(&iv).any(|(g, (lo, hi))| f64::from(*g) < *lo || f64::from(*g) > *hi));
            }
        }
    }

    /// The oracle agrees with the paper's identities on any span: corrected Euler ends
    /// at `p_a` and `p_b` exactly (eq. 17), and every level is the level of its value.
    #[test]
    fn the_oracle_is_exact_where_the_paper_says() {
        fn prop(s: ArbSpan) -> bool {
            let span: Span<BigRational> = s.0;
            let o = oracle(phong_approx::Method::CorrectedEuler, &span).unwrap();
            o.values[0] == span.p_a
                && o.values[span.n as usize] == span.p_b
                && o.values
                    .iter()
                    .zip(&o.levels)
                    .all(|(v, l)| *l == Some(phong_approx::reference::level::level_of_rational(v)))
        }
        quickcheck::QuickCheck::new()
            .tests(64)
            .quickcheck(prop as fn(ArbSpan) -> bool);
    }
}
