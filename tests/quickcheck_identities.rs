//! The algebraic identities once more, with quickcheck's generators and shrinking
//! (small integer stereographic parameters → exact unit normals).

use crate::common;

use common::*;
use phong_approx::{Method, Span};
use quickcheck::{quickcheck, TestResult};

fn span(a: (i8, i8, u8), b: (i8, i8, u8), l: (i8, i8, u8), n: u8) -> Option<Span<Q>> {
    let st = |(x, y, d): (i8, i8, u8)| Stereo(i64::from(x), i64::from(y), i64::from(d) + 1).unit();
    Span::new(st(a), st(b), st(l), u32::from(n % 40) + 1).ok()
}

quickcheck! {
    fn eq_18_identity(a: (i8, i8, u8), b: (i8, i8, u8), l: (i8, i8, u8), n: u8) -> TestResult {
        let Some(s) = span(a, b, l, n) else { return TestResult::discard() };
        TestResult::from_bool(s.na.dot(&s.k) == -s.nb.dot(&s.k))
    }

    fn eq_22_identity(a: (i8, i8, u8), b: (i8, i8, u8), l: (i8, i8, u8), n: u8) -> TestResult {
        let Some(s) = span(a, b, l, n) else { return TestResult::discard() };
        TestResult::from_bool(s.dq_b == -s.dq_a.clone())
    }

    fn sec_4_identity(a: (i8, i8, u8), b: (i8, i8, u8), l: (i8, i8, u8), n: u8) -> TestResult {
        let Some(s) = span(a, b, l, n) else { return TestResult::discard() };
        TestResult::from_bool((0..=s.n).all(|i| s.q_at(i) == s.q_at(s.n - i)))
    }

    fn eq_17_identity(a: (i8, i8, u8), b: (i8, i8, u8), l: (i8, i8, u8), n: u8) -> TestResult {
        let Some(s) = span(a, b, l, n) else { return TestResult::discard() };
        let v = Method::CorrectedEuler.values(&s).unwrap();
        TestResult::from_bool(v[0] == s.p_a && v[s.n as usize] == s.p_b)
    }

    fn eq_24_identity(a: (i8, i8, u8), b: (i8, i8, u8), l: (i8, i8, u8), n: u8) -> TestResult {
        let Some(s) = span(a, b, l, n) else { return TestResult::discard() };
        let g = Method::Gouraud.values(&s).unwrap();
        let c = Method::CorrectedEuler.values(&s).unwrap();
        TestResult::from_bool((0..=s.n).all(|i| {
            g[i as usize].clone() - c[i as usize].clone()
                == s.ds.clone() / q(2, 1) * qi(i) * (qi(s.n) - qi(i))
        }))
    }
}
