//! The related-work methods' own claims, checked exactly in rationals (or, where the
//! method needs a cosine or a square root, to 2^-180 against the 2^-256 reference
//! functions), and their float runs against the exact run.
//!
//! Method docs: `src/related/*.rs`; discussion: `docs/comparison.md`.

use crate::common;

use common::{arb_case, arb_stereo, q, Q};
use phong_approx::angular::CosTable;
use phong_approx::related::binary;
use phong_approx::related::bishop_weimer::{self, Taylor};
use phong_approx::related::seiler::Quadratic;
use phong_approx::related::spherical;
use phong_approx::related::triangle::Triangle;
use phong_approx::related::vertex_angle;
use phong_approx::{Real, Scalar, Span, Vec3};
use proptest::prelude::*;

/// 2^-180: the tolerance for results built on the 2^-256 sqrt/acos/cos of rationals.
fn tiny() -> Q {
    Q::new(1.into(), num_bigint::BigInt::from(1) << 180)
}

fn close(what: &str, a: &Q, b: &Q) -> Result<(), TestCaseError> {
    let d = a.clone() - b.clone();
    if d.magnitude() <= tiny() {
        Ok(())
    } else {
        Err(TestCaseError::fail(format!(
            "{what}: {} vs {} (difference {:e})",
            a.to_f64(),
            b.to_f64(),
            d.to_f64()
        )))
    }
}

fn v(x: i64, y: i64, z: i64, d: i64) -> Vec3<Q> {
    Vec3::new(q(x, d), q(y, d), q(z, d))
}

fn arb_vec() -> impl Strategy<Value = Vec3<Q>> {
    (-20i64..=20, -20i64..=20, -20i64..=20).prop_map(|(x, y, z)| v(x, y, z, 16))
}

fn phong_value(span: &Span<Q>, i: u32) -> Q {
    span.p_at(i) / span.q_at(i).sqrt()
}

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases: common::proptest_cases(cases),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

// ---------------------------------------------------------------- Bishop & Weimer

/// A second-order Taylor polynomial in two variables, `[1, x, y, x², xy, y²]`:
/// truncated multiplication is automatic differentiation to second order.
#[derive(Clone, Debug, PartialEq)]
struct Jet([Q; 6]);

impl Jet {
    fn constant(c: Q) -> Jet {
        let z = q(0, 1);
        Jet([c, z.clone(), z.clone(), z.clone(), z.clone(), z])
    }
    fn affine(c: Q, x: Q, y: Q) -> Jet {
        let z = q(0, 1);
        Jet([c, x, y, z.clone(), z.clone(), z])
    }
    fn add(&self, o: &Jet) -> Jet {
        Jet(std::array::from_fn(|k| self.0[k].clone() + o.0[k].clone()))
    }
    fn mul(&self, o: &Jet) -> Jet {
        let (a, b) = (&self.0, &o.0);
        Jet([
            a[0].clone() * b[0].clone(),
            a[0].clone() * b[1].clone() + a[1].clone() * b[0].clone(),
            a[0].clone() * b[2].clone() + a[2].clone() * b[0].clone(),
            a[0].clone() * b[3].clone() + a[1].clone() * b[1].clone() + a[3].clone() * b[0].clone(),
            a[0].clone() * b[4].clone()
                + a[1].clone() * b[2].clone()
                + a[2].clone() * b[1].clone()
                + a[4].clone() * b[0].clone(),
            a[0].clone() * b[5].clone() + a[2].clone() * b[2].clone() + a[5].clone() * b[0].clone(),
        ])
    }
    /// `self^(−1/2)` for a constant term `s²` (given `s > 0`): the binomial series
    /// `s^-1 (1 + δ)^(−1/2) = s^-1 (1 − δ/2 + 3δ²/8)`, `δ = (self − s²)/s²`.
    fn inv_sqrt(&self, s: &Q) -> Jet {
        let s2 = s.clone() * s.clone();
        let mut delta = self.clone();
        delta.0[0] = q(0, 1);
        let delta = Jet(delta.0.map(|c| c / s2.clone()));
        let d2 = delta.mul(&delta);
        let series = Jet::constant(q(1, 1))
            .add(&Jet(delta.0.map(|c| c * q(-1, 2))))
            .add(&Jet(d2.0.map(|c| c * q(3, 8))));
        Jet(series.0.map(|c| c / s.clone()))
    }
}

/// The exact second-order jet of `(L·N)/|N|`, `N = n1 x + n2 y + n3`, `|n3| = s`.
fn intensity_jet(n1: &Vec3<Q>, n2: &Vec3<Q>, n3: &Vec3<Q>, l: &Vec3<Q>, s: &Q) -> Jet {
    let comps = |v: &Vec3<Q>| [v.x.clone(), v.y.clone(), v.z.clone()];
    let (a1, a2, a3, ll) = (comps(n1), comps(n2), comps(n3), comps(l));
    let n: Vec<Jet> = (0..3)
        .map(|k| Jet::affine(a3[k].clone(), a1[k].clone(), a2[k].clone()))
        .collect();
    let mut p = Jet::constant(q(0, 1));
    let mut qq = Jet::constant(q(0, 1));
    for k in 0..3 {
        p = p.add(&n[k].mul(&Jet::constant(ll[k].clone())));
        qq = qq.add(&n[k].mul(&n[k]));
    }
    p.mul(&qq.inv_sqrt(s))
}

/// `n3 = r·unit` so that `|n3| = |r|` is rational and the expansion's `√i` is exact.
fn arb_bw_inputs() -> impl Strategy<Value = (Vec3<Q>, Vec3<Q>, Vec3<Q>, Q, Vec3<Q>)> {
    (
        arb_vec(),
        arb_vec(),
        arb_stereo(),
        1i64..=12,
        1i64..=6,
        arb_stereo(),
    )
        .prop_map(|(n1, n2, s3, rn, rd, sl)| {
            let r = q(rn, rd);
            (n1, n2, s3.unit().scale(&r), r, sl.unit())
        })
}

proptest! {
    #![proptest_config(config(96))]

    /// T0..T5 are the value, the first and the halved second derivatives of
    /// `(L·N)/|N|` at the expansion point, computed independently by jet arithmetic.
    #[test]
    fn bishop_weimer_coefficients_are_the_exact_derivatives((n1, n2, n3, s, l) in arb_bw_inputs()) {
        let t = Taylor::new(&n1, &n2, &n3, &l).expect("n3 ≠ 0");
        let j = intensity_jet(&n1, &n2, &n3, &l, &s);
        prop_assert_eq!(&t.t0, &j.0[0], "T0");
        prop_assert_eq!(&t.t2, &j.0[1], "T2 = dI/dx");
        prop_assert_eq!(&t.t1, &j.0[2], "T1 = dI/dy");
        prop_assert_eq!(&t.t5, &j.0[3], "T5 = ½ d²I/dx²");
        prop_assert_eq!(&t.t4, &j.0[4], "T4 = d²I/dxdy");
        prop_assert_eq!(&t.t3, &j.0[5], "T3 = ½ d²I/dy²");
    }

    /// Two additions per pixel give exactly the polynomial's values.
    ///
    /// Proved: `proofs/Related.v`, theorem of the same name.
    #[test]
    fn bishop_weimer_forward_differences_are_exact(
        (n1, n2, n3, _s, l) in arb_bw_inputs(), x0 in -40i64..40, y in -40i64..40, len in 1usize..48,
    ) {
        let t = Taylor::new(&n1, &n2, &n3, &l).expect("n3 ≠ 0");
        let (x0, y) = (q(x0, 2), q(y, 2));
        let mut out = vec![q(0, 1); len];
        t.shade_row(&x0, &y, &mut out);
        for (j, o) in out.iter().enumerate() {
            prop_assert_eq!(o, &t.at(&(x0.clone() + q(j as i64, 1)), &y), "pixel {}", j);
        }
    }

    /// Along one span expanded about its left edge, the 2-D coefficients reduce to the
    /// literature's scan-line case `B + (A − BD/2) x + (3BD²/8 − BC/2 − AD/2) x²`.
    ///
    /// Proved: `proofs/Related.v`, theorem of the same name.
    #[test]
    fn bishop_weimer_scanline_special_case(c in arb_case()) {
        let Some(span) = c.span() else { return Ok(()); };
        let t = Taylor::from_span_at(&span, &q(0, 1)).expect("N_a ≠ 0");
        let (a, b, cc, d) = (&span.a, &span.b, &span.c, &span.d);
        prop_assert_eq!(&t.t0, b);
        prop_assert_eq!(t.t2.clone(), a.clone() - b.clone() * d.clone() / q(2, 1));
        prop_assert_eq!(
            t.t5.clone(),
            q(3, 8) * b.clone() * d.clone() * d.clone() - b.clone() * cc.clone() / q(2, 1)
                - a.clone() * d.clone() / q(2, 1)
        );
    }

    /// Seiler's quadratic takes the six given values at the vertices and the edge
    /// midpoints, exactly.
    ///
    /// Proved: `proofs/Related.v`, theorem of the same name.
    #[test]
    fn seiler_is_exact_at_the_six_points(
        p in arb_triangle(), vals in proptest::array::uniform6(-64i64..64),
    ) {
        let Ok(tri) = Triangle::new(p.clone()) else { return Ok(()); };
        let vals = vals.map(|x| q(x, 32));
        let vertex = [vals[0].clone(), vals[1].clone(), vals[2].clone()];
        let mid = [vals[3].clone(), vals[4].clone(), vals[5].clone()];
        let quad = Quadratic::from_six(&tri, &vertex, &mid);
        for i in 0..3 {
            let (x, y) = tri.relative(&p[i].0, &p[i].1);
            prop_assert_eq!(quad.at(&x, &y), vertex[i].clone(), "vertex {}", i);
            let j = (i + 1) % 3;
            let mx = (p[i].0.clone() + p[j].0.clone()) / q(2, 1);
            let my = (p[i].1.clone() + p[j].1.clone()) / q(2, 1);
            let (x, y) = tri.relative(&mx, &my);
            prop_assert_eq!(quad.at(&x, &y), mid[i].clone(), "midpoint {}{}", i, j);
        }
    }

    /// The six-point quadratic of any quadratic is that quadratic, everywhere.
    ///
    /// Proved: `proofs/Related.v`, theorem of the same name.
    #[test]
    fn seiler_reproduces_quadratics(
        p in arb_triangle(), g in proptest::array::uniform6(-9i64..9), at in (-50i64..50, -50i64..50),
    ) {
        let Ok(tri) = Triangle::new(p.clone()) else { return Ok(()); };
        let g = g.map(|x| q(x, 4));
        // g(x, y) in absolute coordinates.
        let f = |x: &Q, y: &Q| {
            g[0].clone() * x.clone() * x.clone() + g[1].clone() * x.clone() * y.clone()
                + g[2].clone() * y.clone() * y.clone() + g[3].clone() * x.clone()
                + g[4].clone() * y.clone() + g[5].clone()
        };
        let vertex = [f(&p[0].0, &p[0].1), f(&p[1].0, &p[1].1), f(&p[2].0, &p[2].1)];
        let mid: [Q; 3] = std::array::from_fn(|i| {
            let j = (i + 1) % 3;
            f(&((p[i].0.clone() + p[j].0.clone()) / q(2, 1)), &((p[i].1.clone() + p[j].1.clone()) / q(2, 1)))
        });
        let quad = Quadratic::from_six(&tri, &vertex, &mid);
        let (ax, ay) = (q(at.0, 3), q(at.1, 3));
        let (x, y) = tri.relative(&ax, &ay);
        prop_assert_eq!(quad.at(&x, &y), f(&ax, &ay));
    }

    /// Seiler's forward differences give exactly the quadratic's values.
    ///
    /// Proved: `proofs/Related.v`, theorem of the same name.
    #[test]
    fn seiler_forward_differences_are_exact(
        p in arb_triangle(), vals in proptest::array::uniform6(-64i64..64), y in -30i64..30, len in 1usize..40,
    ) {
        let Ok(tri) = Triangle::new(p) else { return Ok(()); };
        let vals = vals.map(|x| q(x, 32));
        let quad = Quadratic::from_six(
            &tri,
            &[vals[0].clone(), vals[1].clone(), vals[2].clone()],
            &[vals[3].clone(), vals[4].clone(), vals[5].clone()],
        );
        let (x0, y) = (q(-7, 2), q(y, 3));
        let mut out = vec![q(0, 1); len];
        quad.shade_row(&x0, &y, &mut out);
        for (j, o) in out.iter().enumerate() {
            prop_assert_eq!(o, &quad.at(&(x0.clone() + q(j as i64, 1)), &y));
        }
    }

    /// Barycentric forms: `λ_i` is 1 at vertex `i`, 0 at the others, and they sum to 1;
    /// the normal field takes the vertex normals at the vertices.
    #[test]
    fn triangle_barycentrics_and_normal_field(
        p in arb_triangle(), s in (arb_stereo(), arb_stereo(), arb_stereo()), at in (-50i64..50, -50i64..50),
    ) {
        let Ok(tri) = Triangle::new(p) else { return Ok(()); };
        let normals = [s.0.unit(), s.1.unit(), s.2.unit()];
        let (n1, n2, n3) = tri.normal_field(&normals);
        for (i, vert) in tri.vertices.iter().enumerate() {
            for (j, l) in tri.lambda.iter().enumerate() {
                prop_assert_eq!(l.at(&vert.0, &vert.1), q(i64::from(i == j), 1));
            }
            let n = n1.scale(&vert.0).add(&n2.scale(&vert.1)).add(&n3);
            prop_assert_eq!(&n, &normals[i]);
        }
        let (x, y) = (q(at.0, 7), q(at.1, 5));
        let sum = tri.lambda.iter().fold(q(0, 1), |acc, l| acc + l.at(&x, &y));
        prop_assert_eq!(sum, q(1, 1));
    }
}

fn arb_triangle() -> impl Strategy<Value = [(Q, Q); 3]> {
    proptest::array::uniform3((-40i64..40, -40i64..40))
        .prop_map(|p| p.map(|(x, y)| (q(x, 1), q(y, 1))))
}

/// The widely copied statement of T5 with `3 i g²` is not the second derivative; the
/// exact jet and our `3 c g²` agree. Counterexample: `N = (x, 0, 1) + …` with
/// `c ≠ i`.
#[test]
fn bishop_weimer_printed_t5_is_wrong() {
    let n1 = v(1, 0, 0, 1);
    let n2 = v(0, 0, 0, 1);
    let n3 = v(0, 0, 2, 1); // i = 4, s = 2
    let l = phong_approx::reference::unit::unit_from_ints(1, 0, 3); // (3/5, 0, 4/5)
    let s = q(2, 1);
    let t = Taylor::new(&n1, &n2, &n3, &l).expect("n3 ≠ 0");
    let j = intensity_jet(&n1, &n2, &n3, &l, &s);
    assert_eq!(t.t5, j.0[3]);
    // The printed variant: (3 i g² − 4 c d i − 4 a g i) / (8 i² s); here g = 0, so
    // use a shifted field where g ≠ 0.
    let n3 = v(1, 0, 2, 1); // g = 2 N1·N3 = 2, i = 5 — not a square, so take n3 = (3, 0, 4)
    let _ = n3;
    let n3 = v(3, 0, 4, 1); // i = 25, s = 5, g = 6, c = 9/5 + 16/5 = 5
    let l = phong_approx::reference::unit::unit_from_ints(0, 1, 3); // (0, 3/5, 4/5): c = 16/5
    let s = q(5, 1);
    let t = Taylor::new(&n1, &n2, &n3, &l).expect("n3 ≠ 0");
    let j = intensity_jet(&n1, &n2, &n3, &l, &s);
    assert_eq!(t.t5, j.0[3], "our T5 is the exact half second derivative");
    let (a, c, d, g, i) = (
        l.dot(&n1),
        l.dot(&n3),
        n1.dot(&n1),
        q(2, 1) * n1.dot(&n3),
        n3.dot(&n3),
    );
    let printed = (q(3, 1) * i.clone() * g.clone() * g.clone()
        - q(4, 1) * c * d * i.clone()
        - q(4, 1) * a * g * i.clone())
        / (q(8, 1) * i.clone() * i * s);
    assert_ne!(
        printed, j.0[3],
        "the printed T5 would be right here; the counterexample is void"
    );
}

/// Expanded about the middle of the span, Bishop & Weimer is exact there (to the
/// reference's 2^-180) and, on a wide span, off by more than one 8-bit level at the
/// edges: the complaint of the Euler paper.
#[test]
fn bishop_weimer_exact_at_centre_only() {
    let na = phong_approx::reference::unit::unit_from_ints(1, 0, 2); // 53° apart from nb
    let nb = phong_approx::reference::unit::unit_from_ints(-1, 0, 2);
    let l = phong_approx::reference::unit::unit_from_ints(2, 1, 3);
    let span = Span::new(na, nb, l, 16).expect("valid");
    let mut out = vec![q(0, 1); 17];
    bishop_weimer::shade(&span, &mut out).expect("length");
    let centre = phong_value(&span, 8);
    assert!((out[8].clone() - centre).magnitude() <= tiny());
    let level = q(1, 255);
    let off_a = (out[0].clone() - span.p_a.clone()).magnitude();
    let off_b = (out[16].clone() - span.p_b.clone()).magnitude();
    assert!(
        off_a > level || off_b > level,
        "edges within a level: {} {}",
        off_a.to_f64(),
        off_b.to_f64()
    );
}

// ---------------------------------------------------------------- spherical

proptest! {
    #![proptest_config(config(24))]

    /// The Chebyshev recurrence follows the closed form `(u·L) cos iΔ + (w·L) sin iΔ`,
    /// starts at `p_a` exactly and ends at `p_b`.
    ///
    /// Proved: `proofs/Related.v`, theorem of the same name.
    #[test]
    fn spherical_recurrence_matches_closed_form(c in arb_case()) {
        let Some(span) = c.span() else { return Ok(()); };
        let n = span.n.min(24);
        let Ok(span) = Span::new(span.na.clone(), span.nb.clone(), span.l.clone(), n) else { return Ok(()); };
        let mut out = vec![q(0, 1); span.len()];
        spherical::shade(&span, &mut out).expect("length");
        prop_assert_eq!(&out[0], &span.p_a);
        for i in 0..=n {
            close(&format!("pixel {i}"), &out[i as usize], &spherical::at(&span, i))?;
        }
        close("end value p_b", &out[n as usize], &span.p_b)?;
        // R ≤ 1.
        prop_assert!(spherical::amplitude(&span) <= q(1, 1) + tiny());
    }

    /// Spherical and Phong agree at the middle pixel of an even span (both give the
    /// normalized bisector).
    ///
    /// Proved: `proofs/Related.v`, theorem of the same name.
    #[test]
    fn spherical_equals_phong_at_the_middle(c in arb_case()) {
        let Some(span) = c.span() else { return Ok(()); };
        let n = 2 * span.n.min(16);
        let Ok(span) = Span::new(span.na.clone(), span.nb.clone(), span.l.clone(), n) else { return Ok(()); };
        close("middle", &spherical::at(&span, n / 2), &phong_value(&span, n / 2))?;
    }

    /// With `L` in the plane of `N_a` and `N_b`, outside the arc between them, the angle
    /// to `L` is linear along the arc, so the second source's angle interpolation
    /// (`angular::shade`) equals the spherical one, and `R = 1`.
    #[test]
    fn spherical_equals_angular_when_light_in_plane(a in -6i64..=6, b in -6i64..=6, n in 1u32..=12) {
        // Normals in the x–z plane at stereographic x-parameters a/8, b/8; light at
        // parameter −9/8, beyond both (parameters are monotone in the angle).
        let na = phong_approx::reference::unit::unit_from_ints(a, 0, 8);
        let nb = phong_approx::reference::unit::unit_from_ints(b, 0, 8);
        let l = phong_approx::reference::unit::unit_from_ints(-9, 0, 8);
        let span = Span::new(na, nb, l, n).expect("valid");
        let mut sph = vec![q(0, 1); span.len()];
        let mut ang = vec![q(0, 1); span.len()];
        spherical::shade(&span, &mut sph).expect("length");
        phong_approx::angular::shade(&span, &mut ang).expect("length");
        for i in 0..span.len() {
            close(&format!("pixel {i}"), &sph[i], &ang[i])?;
        }
        if a != b {
            close("R", &spherical::amplitude(&span), &q(1, 1))?;
        }
    }
}

/// Equal-angle steps are not Phong's: at a quarter of a 90° span the normal of Phong
/// is atan(1/3) ≈ 18.4° from `N_a`, the spherical one 22.5°; with `L = N_a` that is
/// cos 18.4° − cos 22.5° ≈ 0.025, six 8-bit levels.
#[test]
fn spherical_differs_from_phong_between() {
    let na = v(1, 0, 0, 1);
    let nb = v(0, 1, 0, 1);
    let span = Span::new(na.clone(), nb, na, 4).expect("valid");
    let sph = spherical::at(&span, 1);
    let ph = phong_value(&span, 1);
    let diff = (ph - sph).to_f64();
    assert!(
        (diff - (0.9486832980505138 - 0.9238795325112867)).abs() < 1e-12,
        "{diff}"
    );
    assert!(diff * 255.0 > 6.0);
}

// ---------------------------------------------------------------- binary

/// The segments of `n` have power-of-two lengths, largest first, one per binary digit.
#[test]
fn binary_segments_are_powers_of_two() {
    for n in 1..=5000u32 {
        let b = binary::segments(n);
        assert_eq!(b[0], 0);
        assert_eq!(*b.last().unwrap(), n);
        assert_eq!(b.len() as u32 - 1, n.count_ones(), "n = {n}");
        let lens: Vec<u32> = b.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(
            lens.iter().all(|l| l.is_power_of_two()),
            "n = {n}: {lens:?}"
        );
        assert!(lens.windows(2).all(|w| w[0] > w[1]), "n = {n}: {lens:?}");
    }
}

/// `sin x` for `0 ≤ x ≤ π` from the reference cosine.
fn sin(x: &Q) -> Q {
    (Q::frac_pi_2() - x.clone()).cos()
}

proptest! {
    #![proptest_config(config(24))]

    /// Segment ends are Phong's values exactly (to the reference). The midpoint of a
    /// segment is Phong's only when both ends have the same length of interpolated
    /// normal — when the segment is the whole span (`n` a power of two) between the
    /// unit edge normals.
    #[test]
    fn binary_exact_at_ends_and_whole_span_midpoint(c in arb_case()) {
        let Some(span) = c.span() else { return Ok(()); };
        let mut out = vec![q(0, 1); span.len()];
        binary::shade(&span, &mut out).expect("length");
        let b = binary::segments(span.n);
        for w in b.windows(2) {
            close(&format!("end {}", w[1]), &out[w[1] as usize], &phong_value(&span, w[1]))?;
            if w[1] - w[0] >= 2 && w[0] == 0 && w[1] == span.n {
                let m = (w[0] + w[1]) / 2;
                close(&format!("midpoint {m}"), &out[m as usize], &phong_value(&span, m))?;
            }
        }
    }

    /// Inside a segment every point bisects the angle: it is the spherical
    /// interpolation `(sin((1−t)θ) I_U + sin(tθ) I_V) / sin θ` between the segment's
    /// end normals.
    #[test]
    fn binary_deeper_points_are_spherical_not_phong(c in arb_case()) {
        let Some(span) = c.span() else { return Ok(()); };
        let mut out = vec![q(0, 1); span.len()];
        binary::shade(&span, &mut out).expect("length");
        let b = binary::segments(span.n);
        for w in b.windows(2) {
            let (a, e) = (w[0], w[1]);
            let u = span.normal_at(a).scale(&(q(1, 1) / span.q_at(a).sqrt()));
            let vv = span.normal_at(e).scale(&(q(1, 1) / span.q_at(e).sqrt()));
            let cos_t = u.dot(&vv);
            if cos_t >= q(1, 1) - tiny() { continue; }
            let theta = cos_t.acos();
            let s = sin(&theta);
            let (iu, iv) = (u.dot(&span.l), vv.dot(&span.l));
            for m in a + 1..e {
                let t = q(i64::from(m - a), i64::from(e - a));
                let want = (sin(&((q(1, 1) - t.clone()) * theta.clone())) * iu.clone()
                    + sin(&(t * theta.clone())) * iv.clone()) / s.clone();
                close(&format!("pixel {m}"), &out[m as usize], &want)?;
            }
        }
    }
}

/// A counterexample to "exact Phong values at every binary subdivision point": on a
/// 90° span of 4 steps the quarter point is spherical, six levels from Phong.
#[test]
fn binary_quarter_point_is_not_phong() {
    let na = v(1, 0, 0, 1);
    let span = Span::new(na.clone(), v(0, 1, 0, 1), na, 4).expect("valid");
    let mut out = vec![q(0, 1); 5];
    binary::shade(&span, &mut out).expect("length");
    let diff = (phong_value(&span, 1) - out[1].clone()).to_f64() * 255.0;
    assert!(diff > 6.0, "{diff}");
}

// ---------------------------------------------------------------- vertex angles

/// Three vertex normals at the same angle (53.1°) to `L`, 120° apart around it: the
/// interpolated angle is constant, so is the intensity (0.6 everywhere), while Phong
/// at the centroid is near 1 — the failure case of interpolating vertex angles.
///
/// Proved: `proofs/Related.v`, theorem of the same name.
#[test]
fn vertex_angle_equal_angles_give_a_flat_polygon() {
    use phong_approx::reference::unit::unit_from_ints;
    let normals = [
        unit_from_ints(3, 4, 10),
        unit_from_ints(4, -3, 10),
        unit_from_ints(-5, 0, 10),
    ];
    let l = v(0, 0, 1, 1);
    for nrm in &normals {
        assert_eq!(nrm.dot(&l), q(3, 5));
    }
    let tri = Triangle::new([(q(0, 1), q(0, 1)), (q(40, 1), q(0, 1)), (q(0, 1), q(40, 1))])
        .expect("area");
    let field = vertex_angle::angle_field(&tri, &normals, &l);
    assert_eq!(field.ax, q(0, 1));
    assert_eq!(field.by, q(0, 1));
    let table = CosTable::<f64>::new(256).expect("size");
    let mut out = vec![0.0f64; 30];
    let field64 = phong_approx::related::triangle::Affine {
        ax: field.ax.to_f64(),
        by: field.by.to_f64(),
        c: field.c.to_f64(),
    };
    vertex_angle::shade_row(&field64, &table, &-15.0, &3.0, &mut out);
    assert!(out.iter().all(|&o| o == out[0]), "not flat: {out:?}");
    assert!((out[0] - 0.6).abs() < 0.004, "{}", out[0]);
    // Phong at the centroid: the normalized mean normal.
    let (_, _, n3) = tri.normal_field(&normals);
    let phong = n3.dot(&l) / n3.length_squared().sqrt();
    assert!(phong.to_f64() - out[0] > 0.3, "Phong {}", phong.to_f64());
}

/// At a vertex the method gives the byte table's cosine of the exact vertex angle:
/// within half a table step (90°/255/2) of `N·L`.
#[test]
fn vertex_angle_at_vertices_within_half_a_table_step() {
    let table = CosTable::<f64>::new(256).expect("size");
    let half_step = (std::f64::consts::FRAC_PI_2 / 255.0) / 2.0;
    for (a, b, d) in [(1, 2, 5), (0, 0, 1), (3, -1, 4), (7, 7, 9), (-2, 5, 11)] {
        let n: Vec3<f64> = phong_approx::reference::unit::unit_from_ints(a, b, d)
            .cast()
            .unwrap();
        let l: Vec3<f64> = phong_approx::reference::unit::unit_from_ints(1, -1, 3)
            .cast()
            .unwrap();
        let theta = vertex_angle::vertex_angle(&n, &l);
        let got = table.lookup(&theta);
        let exact = n.dot(&l).max(0.0);
        assert!(
            (got - exact).abs() <= half_step.sin() + 1e-12,
            "{a} {b} {d}: {got} vs {exact}"
        );
    }
}

// ---------------------------------------------------------------- floats against exact

/// In `f64`, every new span method stays within 1e-9 of its exact run (n ≤ 64).
#[test]
fn related_span_methods_f64_against_exact() {
    type Shade<T> = fn(&Span<T>, &mut [T]) -> Result<(), phong_approx::SpanError>;
    let methods: [(&str, Shade<Q>, Shade<f64>); 3] = [
        ("spherical", spherical::shade, spherical::shade),
        ("binary", binary::shade, binary::shade),
        ("bishop-weimer", bishop_weimer::shade, bishop_weimer::shade),
    ];
    let mut runner = proptest::test_runner::TestRunner::new(config(16));
    runner
        .run(&arb_case(), |c| {
            let Some(exact) = c.span() else { return Ok(()) };
            let float: Span<f64> = exact.cast().expect("finite");
            for (name, fe, ff) in &methods {
                let mut e = vec![q(0, 1); exact.len()];
                let mut f = vec![0.0; exact.len()];
                fe(&exact, &mut e).expect("length");
                ff(&float, &mut f).expect("length");
                for (i, (a, b)) in e.iter().zip(&f).enumerate() {
                    prop_assert!(
                        (a.to_f64() - b).abs() <= 1e-9,
                        "{} pixel {}: {} vs {}",
                        name,
                        i,
                        a.to_f64(),
                        b
                    );
                }
            }
            Ok(())
        })
        .unwrap();
}

/// Bad input to the polygon methods gets a typed error, never a panic or a NaN: a
/// collinear or non-finite triangle, a zero normal at the expansion point, a
/// non-finite light, opposite vertex normals.
#[test]
fn related_bad_input_gets_typed_errors() {
    use phong_approx::SpanError;
    let is_param = |r: Result<(), SpanError>| matches!(r, Err(SpanError::Parameter(_)));
    let collinear = [(0.0f64, 0.0), (1.0, 1.0), (2.0, 2.0)];
    assert!(is_param(Triangle::new(collinear).map(|_| ())));
    let nan = [(0.0f64, 0.0), (f64::NAN, 1.0), (2.0, 0.0)];
    assert!(is_param(Triangle::new(nan).map(|_| ())));
    let zero = Vec3::new(0.0f64, 0.0, 0.0);
    let z = Vec3::new(0.0f64, 0.0, 1.0);
    assert!(is_param(Taylor::new(&z, &z, &zero, &z).map(|_| ())));
    let inf = Vec3::new(f64::INFINITY, 0.0, 0.0);
    assert!(is_param(Taylor::new(&z, &z, &z, &inf).map(|_| ())));
    let tri = Triangle::new([(0.0f64, 0.0), (4.0, 0.0), (0.0, 4.0)]).expect("area");
    let down = Vec3::new(0.0f64, 0.0, -1.0);
    assert!(is_param(
        Quadratic::from_normals(&tri, &[z.clone(), down, z.clone()], &z).map(|_| ())
    ));
}
