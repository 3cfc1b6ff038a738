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
        assert_eq!(r.cases(), 40 + 15 + 4);
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
fn wrong_lengths_and_non_finite_values_are_named() {
    let r = Suite::set("paper")
        .method(Method::Gouraud)
        .check_f64(|s| vec![0.5; s.n as usize]);
    assert_eq!(r.failures().len(), 4, "{r}");
    assert!(r.to_string().contains("the span has n + 1 = "), "{r}");
    let r = Suite::set("typical")
        .method(Method::Phong)
        .tolerance(Tolerance::Levels(1))
        .check_f64(|s| vec![f64::NAN; s.n as usize + 1]);
    assert_eq!(r.failures().len(), 40);
    assert!(r.to_string().contains("off by    = not finite"), "{r}");
}
