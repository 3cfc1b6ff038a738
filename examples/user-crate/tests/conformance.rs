//! This crate's shading against phong-approx's published vectors, under the `ieee`
//! profile (any IEEE round-to-nearest implementation of the method).

use glam::Vec3;
use phong_approx::testkit::prelude::*;
use shader_under_test::{corrected_euler, phong};

fn v(x: [f32; 3]) -> Vec3 {
    Vec3::from_array(x)
}

#[test]
fn corrected_euler_conforms() {
    Suite::published()
        .method(Method::CorrectedEuler)
        .profile(Profile::Ieee)
        .check_f32(|s| corrected_euler(v(s.na), v(s.nb), v(s.l), s.n))
        .assert_ok();
}

#[test]
fn phong_conforms() {
    Suite::published()
        .method(Method::Phong)
        .profile(Profile::Ieee)
        .check_f32(|s| phong(v(s.na), v(s.nb), v(s.l), s.n))
        .assert_ok();
}

/// A planted bug — `ε/(n + 1)` for `ε/n`, the paper's printed "dε = ε/N" read with
/// `N` pixels — fails, and the report says where and how to reproduce it.
#[test]
fn a_planted_bug_is_caught() {
    let r = Suite::published()
        .method(Method::CorrectedEuler)
        .profile(Profile::Ieee)
        .check_f32(|s| buggy_corrected_euler(v(s.na), v(s.nb), v(s.l), s.n));
    assert!(!r.is_ok());
    println!("{r}");
    assert!(r.to_string().contains("reproduce = phong-approx span"));
    // The worst case first: the most over its own pixel's allowance (n = 2, 24 levels
    // off).
    let worst = r.worst().unwrap();
    assert_eq!((worst.case.as_str(), worst.levels), ("edge-003", Some(24)));
    assert!(worst.ratio > 1e3);
}

/// `corrected_euler` with the bug planted.
fn buggy_corrected_euler(na: Vec3, nb: Vec3, l: Vec3, n: u32) -> Vec<f32> {
    let nf = n as f32;
    let k = (nb - na) / nf;
    let (a, pa, pb) = (k.dot(l), na.dot(l), nb.dot(l));
    let (c, d) = (k.dot(k), 2.0 * k.dot(na));
    let di_a = a - pa / 2.0 * d;
    let di_b = a - pb / 2.0 * (2.0 * nf * c + d);
    let ds = (di_b - di_a) / nf;
    let eps = pa + nf * di_a + nf * (nf - 1.0) / 2.0 * ds - pb;
    let (mut p, mut t) = (pa, di_a - eps / (nf + 1.0));
    let mut out = vec![p];
    for _ in 0..n {
        p += t;
        t += ds;
        out.push(p);
    }
    out
}
