//! Tests behind the entries of `docs/errata.md` that are not already claims of
//! `tests/claims.rs`. Each either checks an exact counterexample or measures what a
//! source states as a fact, and prints what it found.

mod common;

use common::*;
use num_traits::{One, Signed};
use phong_approx::adaptive;
use phong_approx::quantize::level;
use phong_approx::reference::level::phong_level_exact;
use phong_approx::{Method, Span, Vec3};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;

fn vals(m: Method, s: &Span<Q>) -> Vec<Q> {
    m.values(s).unwrap()
}

fn phong_levels(s: &Span<Q>) -> Vec<u8> {
    (0..=s.n)
        .map(|i| phong_level_exact(&s.p_at(i), &s.q_at(i)).unwrap())
        .collect()
}

fn levels(v: &[Q]) -> Vec<u8> {
    v.iter().map(level).collect()
}

/// Deterministic random spans (fixed seed).
fn sample(count: usize) -> Vec<Case> {
    let mut runner = TestRunner::deterministic();
    (0..count)
        .map(|_| arb_case().new_tree(&mut runner).unwrap().current())
        .collect()
}

#[test]
fn erratum_gouraud_slope_equals_a() {
    // Eq. 23's d_p (the Gouraud slope) and §2.1's dp = A are the same number, and
    // fence shading along a span is the unnormalized dot product p(i) = A·i + B.
    for_all_spans(96, |_, s| {
        eq("d_p vs A", &s.dp, &s.a)?;
        let g = vals(Method::Gouraud, s);
        for i in 0..=s.n {
            eq(
                &format!("gouraud({i}) vs p({i})"),
                &g[i as usize],
                &s.p_at(i),
            )?;
        }
        Ok(())
    });
}

#[test]
fn erratum_clamped_levels_can_agree_with_large_delta() {
    // The light is behind the span: everything clamps to level 0, whatever δ is.
    let s = Span::new(
        Stereo(1, 0, 3).unit(),
        Stereo(-1, 0, 3).unit(),
        Vec3::new(q(0, 1), q(0, 1), q(-1, 1)),
        2,
    )
    .unwrap();
    let d = adaptive::decide(&s, &Q::one());
    assert_eq!(d.delta.abs(), q(18, 125));
    assert!(d.delta.abs() * q(255, 1) >= Q::one());
    let g = levels(&vals(Method::Gouraud, &s));
    let c = levels(&vals(Method::CorrectedEuler, &s));
    assert_eq!(g, c);
    assert_eq!(g, vec![0, 0, 0]);
}

#[test]
fn erratum_table_1_criteria_differ() {
    // Table 1's text counts lines where Phong and Gouraud agree; its caption, lines
    // where Gouraud could replace corrected Euler; the δ test predicts the latter.
    let mut gce_not_phong = None;
    let mut phong_not_ce = None;
    for c in sample(3000) {
        let Some(s) = c.span() else { continue };
        let p = phong_levels(&s);
        let g = levels(&vals(Method::Gouraud, &s));
        let ce = levels(&vals(Method::CorrectedEuler, &s));
        if gce_not_phong.is_none() && g == ce && g != p {
            gce_not_phong = Some(c.clone());
        }
        if phong_not_ce.is_none() && p == g && g != ce {
            phong_not_ce = Some(c.clone());
        }
        if gce_not_phong.is_some() && phong_not_ce.is_some() {
            break;
        }
    }
    println!("Gouraud = corrected Euler ≠ Phong: {gce_not_phong:?}");
    println!("Phong = Gouraud ≠ corrected Euler: {phong_not_ce:?}");
    assert!(
        gce_not_phong.is_some(),
        "no span where Gouraud = corrected Euler ≠ Phong"
    );
    assert!(
        phong_not_ce.is_some(),
        "no span where Phong = Gouraud ≠ corrected Euler"
    );
}

#[test]
fn erratum_mortensen_99_percent() {
    // Share of random spans (torus-like nearby normals and unrelated ones) on which
    // angular interpolation gives Phong's exact 8-bit level at every pixel.
    let cases = sample(600);
    let (mut near_total, mut near_ok, mut far_total, mut far_ok) = (0u32, 0u32, 0u32, 0u32);
    for c in &cases {
        let Some(s) = c.span() else { continue };
        let same = levels(&vals(Method::Angular, &s)) == phong_levels(&s);
        // "near" spans: normals within about 10° (q_min > cos²(5°)).
        let near = s.c.clone() * qi(s.n) * qi(s.n) / q(4, 1) < q(76, 10_000);
        if near {
            near_total += 1;
            near_ok += u32::from(same);
        } else {
            far_total += 1;
            far_ok += u32::from(same);
        }
    }
    let share = |ok: u32, total: u32| f64::from(ok) / f64::from(total.max(1));
    println!(
        "angular = Phong at every pixel: nearby normals {near_ok}/{near_total} ({:.1}%), others {far_ok}/{far_total} ({:.1}%)",
        100.0 * share(near_ok, near_total),
        100.0 * share(far_ok, far_total)
    );
    assert!(near_total > 50 && far_total > 50, "sample too small");
    // Far from 99 % once the normals are not close together.
    assert!(
        share(far_ok, far_total) < 0.99,
        "angular matched Phong on ≥ 99 % of wide spans"
    );
    // And on the equal-angle span the source names, it fails.
    let s = Span::new(
        Stereo(1, 0, 3).unit(),
        Stereo(-1, 0, 3).unit(),
        Stereo(0, 0, 1).unit(),
        2,
    )
    .unwrap();
    assert_ne!(levels(&vals(Method::Angular, &s)), phong_levels(&s));
}

#[test]
fn erratum_symmetry_needs_equal_edge_lengths() {
    // Na of length 1, Nb of length 2 (exactly): q is no longer symmetric and
    // dq_b ≠ −dq_a, while eq. 21 (dq_b = 2k·Nb) still holds.
    let na = Stereo(1, 0, 3).unit();
    let nb = Stereo(-1, 2, 5).unit().scale(&q(2, 1));
    let l = Stereo(0, 0, 1).unit();
    let s = Span::with_tolerance(na, nb, l, 6, &q(4, 1)).unwrap();
    assert_ne!(s.dq_b, -s.dq_a.clone());
    assert!((0..=s.n).any(|i| s.q_at(i) != s.q_at(s.n - i)));
    assert_eq!(s.dq_b, q(2, 1) * s.k.dot(&s.nb));
    // Symmetric Phong then differs from Phong.
    assert_ne!(vals(Method::SymmetricPhong, &s), vals(Method::Phong, &s));
}
