//! The claims beyond the paper's own spans: the second source (angles are not linear), the closed forms for any unit normals, the clamped levels, symmetric Phong's algorithm and §7's error analysis in t.

use super::*;

// ---- the second source: angles are not linear -------------------------------------

pub(crate) fn mortensen_span() -> Span<Q> {
    Span::new(
        Stereo(1, 0, 3).unit(),
        Stereo(-1, 0, 3).unit(),
        Stereo(0, 0, 1).unit(),
        2,
    )
    .unwrap()
}

#[test]
fn mortensen_equal_angles_counterexample() {
    let s = mortensen_span();
    assert_eq!((s.p_a.clone(), s.p_b.clone()), (q(4, 5), q(4, 5)));
    let tol = two_pow(-250);
    let ang = values(Method::Angular, &s);
    for a in &ang {
        assert!(
            (a.clone() - q(4, 5)).abs() < tol,
            "angular value {} ≠ 4/5",
            a.to_f64()
        );
    }
    let phong = values(Method::Phong, &s);
    assert_eq!(phong[1], Q::one());
}

#[test]
fn mortensen_angle_not_linear() {
    let s = mortensen_span();
    let phong = values(Method::Phong, &s);
    let angle: Vec<Q> = phong.iter().map(transcendental::acos).collect();
    assert_eq!(angle[0], angle[2]);
    assert_eq!(angle[1], Q::zero());
    let mean = (angle[0].clone() + angle[2].clone()) / q(2, 1);
    assert!(mean > q(1, 2), "acos(4/5) ≈ 0.6435 is not 0");
}

#[test]
fn mortensen_unequal_angles_counterexample() {
    // Na = L = (0, 0, 1), Nb = (1, 0, 0), n = 3.
    let s = Span::new(
        Stereo(0, 0, 1).unit(),
        Stereo(1, 0, 1).unit(),
        Stereo(0, 0, 1).unit(),
        3,
    )
    .unwrap();
    let ang = values(Method::Angular, &s);
    let phong = values(Method::Phong, &s);
    let tol = two_pow(-250);
    // Angular: cos(30°) = √3/2; Phong: (2/3)/√(5/9) = 2/√5.
    assert!((ang[1].clone() * ang[1].clone() - q(3, 4)).abs() < tol);
    assert!((phong[1].clone() * phong[1].clone() - q(4, 5)).abs() < tol);
    assert!((ang[1].clone() - phong[1].clone()).abs() > q(1, 100));
}

// ---- closed forms with unit normals (proofs/ClosedForms.v) -----------------------

/// `c = N_a·N_b`, the cosine of the angle between the edge normals.
pub(crate) fn cos_ab(s: &Span<Q>) -> Q {
    s.na.dot(&s.nb)
}

#[test]
fn eq_11_ds_unit_closed_form() {
    for_all_spans(CASES, |_, s| {
        let want = -(Q::one() - cos_ab(s)) * (s.p_a.clone() + s.p_b.clone()) / (qi(s.n) * qi(s.n));
        eq("ds", &s.ds, &want)
    });
}

#[test]
fn eq_15_eps_closed_form() {
    for_all_spans(CASES, |_, s| {
        let want = (Q::one() - cos_ab(s))
            * ((s.p_a.clone() - s.p_b.clone()) / q(2, 1)
                + (s.p_a.clone() + s.p_b.clone()) / (q(2, 1) * qi(s.n)));
        eq("ε", &s.eps, &want)?;
        // ε is where plain Euler's recurrence ends, minus p_b.
        let e = values(Method::Euler, s);
        eq(
            "p_n − p_b",
            &(e[s.n as usize].clone() - s.p_b.clone()),
            &want,
        )
    });
}

#[test]
fn eq_15_eps_limit() {
    // Fixed edge normals and light, n = 1, 2, 4, …, 4096: the distance of ε from
    // (1 − c)(p_a − p_b)/2 is exactly (1 − c)|p_a + p_b|/(2n), so it halves with n and
    // the limit is not 0 unless c = 1 or p_a = p_b.
    let cases = [
        (Stereo(1, 2, 7), Stereo(3, -1, 8), Stereo(2, 1, 5)),
        (Stereo(1, 0, 3), Stereo(-1, 0, 3), Stereo(1, 1, 4)),
        (Stereo(5, 2, 9), Stereo(5, 3, 9), Stereo(-2, 7, 11)),
    ];
    for (na, nb, l) in cases {
        let mut last: Option<Q> = None;
        for e in 0..=12 {
            let n = 1u32 << e;
            let s = Span::new(na.unit(), nb.unit(), l.unit(), n).unwrap();
            let c = cos_ab(&s);
            let limit = (Q::one() - c.clone()) * (s.p_a.clone() - s.p_b.clone()) / q(2, 1);
            let gap = (s.eps.clone() - limit.clone()).abs();
            let want = (Q::one() - c) * (s.p_a.clone() + s.p_b.clone()).abs() / (q(2, 1) * qi(n));
            assert_eq!(gap, want, "n = {n}, {na:?} {nb:?} {l:?}");
            if let Some(prev) = last {
                assert_eq!(gap.clone() * q(2, 1), prev, "the gap halves with n");
            }
            last = Some(gap);
            assert!(!limit.is_zero(), "these spans have a nonzero limit");
        }
    }
}

#[test]
fn eq_15_euler_misses_pb_general() {
    for_all_spans(CASES, |_, s| {
        let e = values(Method::Euler, s);
        let hits = e[s.n as usize] == s.p_b;
        let cond = cos_ab(s).is_one()
            || (qi(s.n) * (s.p_a.clone() - s.p_b.clone()) + s.p_a.clone() + s.p_b.clone())
                .is_zero();
        ensure(hits == cond, || {
            format!("Euler hits p_b: {hits}, the condition: {cond}")
        })?;
        ensure(cos_ab(s).is_one() == (s.na == s.nb), || {
            "c = 1 iff N_a = N_b".into()
        })
    });
    // The second alternative, on purpose: L perpendicular to both normals (p_a = p_b = 0),
    // and n = 1 with p_a = 0.
    for (na, nb, l, n) in [
        (Stereo(1, 0, 3), Stereo(-1, 0, 3), Stereo(0, 1, 1), 5),
        (Stereo(0, 0, 1), Stereo(1, 0, 2), Stereo(1, 0, 1), 1),
    ] {
        let s = Span::new(na.unit(), nb.unit(), l.unit(), n).unwrap();
        assert!(s.na != s.nb);
        assert!(
            s.eps.is_zero(),
            "ε = {} on {na:?} {nb:?} {l:?} n = {n}",
            s.eps
        );
    }
}

#[test]
fn eq_24_delta_unit_closed_form() {
    for_all_spans(CASES, |_, s| {
        let base = -(Q::one() - cos_ab(s)) * (s.p_a.clone() + s.p_b.clone()) / q(8, 1);
        let want = if s.n % 2 == 0 {
            base
        } else {
            base * (Q::one() - Q::one() / (qi(s.n) * qi(s.n)))
        };
        eq("δ", &adaptive::delta_at(s, s.n.div_ceil(2)), &want)?;
        eq("decide's δ", &adaptive::decide(s, &Q::one()).delta, &want)
    });
}

#[test]
fn eq_23_24_paper_step_gives_delta() {
    // The paper's procedure, written out here independently of `adaptive::decide`:
    // m = (d_p − t_0)/d_s, truncate and add 1, eq. 24 at that step.
    for_all_spans(CASES, |_, s| {
        if s.ds.is_zero() {
            // m is undefined; δ = 0 and corrected Euler is Gouraud at every pixel.
            eq("δ", &adaptive::delta_at(s, s.n.div_ceil(2)), &Q::zero())?;
            let g = values(Method::Gouraud, s);
            let c = values(Method::CorrectedEuler, s);
            return ensure(g == c, || "ds = 0 but G ≠ CE".into());
        }
        let m = (s.dp.clone() - s.t0.clone()) / s.ds.clone();
        let step = m.trunc() + Q::one();
        let delta = step.clone() * s.dp.clone()
            - (step.clone() * s.t0.clone()
                + (step.clone() * step.clone() - step.clone()) / q(2, 1) * s.ds.clone());
        eq("step", &step, &qi(s.n.div_ceil(2)))?;
        eq("δ", &delta, &adaptive::delta_at(s, s.n.div_ceil(2)))?;
        eq("decide's δ", &delta, &adaptive::decide(s, &Q::one()).delta)
    });
    // ds = 0 on purpose: p_a + p_b = 0 with N_a ≠ N_b.
    let s = Span::new(
        Stereo(1, 0, 3).unit(),
        Stereo(-1, 0, 3).unit(),
        Stereo(1, 0, 1).unit(),
        4,
    )
    .unwrap();
    assert!(s.ds.is_zero() && !s.p_a.is_zero());
    assert_eq!(
        values(Method::Gouraud, &s),
        values(Method::CorrectedEuler, &s)
    );
    assert!(adaptive::decide(&s, &Q::one()).delta.is_zero());
}

/// `floor(255·clamp(v, 0, 1))` written out (with 1 ↦ 255), to check the crate's
/// quantiser against.
pub(crate) fn clamped_level(v: &Q) -> u8 {
    if !v.is_positive() {
        0
    } else if *v >= Q::one() {
        255
    } else {
        (v.clone() * q(255, 1))
            .floor()
            .to_integer()
            .try_into()
            .unwrap()
    }
}

#[test]
fn eq_24_delta_test_does_not_imply_same_clamped_levels() {
    let g = q(1, 255);
    let c = q(1, 255) - q(1, 1000);
    assert!((g.clone() - c.clone()).abs() * q(255, 1) < Q::one());
    assert_eq!((clamped_level(&g), clamped_level(&c)), (1, 0));
    assert_eq!((level(&g), level(&c)), (1, 0));
    // The crate's quantiser is the clamped one on a grid through [−1, 2].
    for i in -255..=510 {
        for off in [q(0, 1), q(1, 1000), q(-1, 1000)] {
            let v = q(i, 255) + off;
            assert_eq!(level(&v), clamped_level(&v), "v = {v}");
        }
    }
}

#[test]
fn eq_24_delta_test_fails_on_concrete_span_clamped() {
    let s = Span::new(
        Stereo(0, 1, 3).unit(),
        Stereo(0, 1, 4).unit(),
        Stereo(0, 0, 1).unit(),
        2,
    )
    .unwrap();
    let d = adaptive::decide(&s, &Q::one());
    assert!((d.delta.clone() * q(255, 1)).abs() < Q::one());
    let g = values(Method::Gouraud, &s);
    let c = values(Method::CorrectedEuler, &s);
    assert_eq!((clamped_level(&g[1]), clamped_level(&c[1])), (214, 215));
}

#[test]
fn eq_24_large_delta_implies_different_clamped_levels() {
    for_all_spans(CASES, |_, s| {
        let d = adaptive::decide(s, &Q::one());
        let Some(step) = d.step else { return Ok(()) };
        let g = values(Method::Gouraud, s)[step as usize].clone();
        let c = values(Method::CorrectedEuler, s)[step as usize].clone();
        let inside = |v: &Q| !v.is_negative() && *v <= Q::one();
        if (d.delta.clone() * q(255, 1)).abs() >= Q::one() && inside(&g) && inside(&c) {
            ensure(clamped_level(&g) != clamped_level(&c), || {
                format!("|δ·255| ≥ 1, values in [0, 1], equal levels at {step}")
            })?;
        }
        Ok(())
    });
    // Without the premise it fails: both values above 1, or both below 0.
    for (g, c) in [
        (q(2, 1), q(1, 1)),
        (q(-1, 1), q(0, 1)),
        (q(-1, 1), q(1, 1000)),
    ] {
        assert!((g.clone() - c.clone()).abs() * q(255, 1) >= Q::one());
        assert_eq!(clamped_level(&g), clamped_level(&c), "{g} {c}");
    }
}

#[test]
fn sec_4_symmetric_phong_algorithm() {
    // The mirrored half-span computation, both parities on purpose and on random spans.
    for n in 1..=9 {
        let s = Span::new(
            Stereo(1, 2, 7).unit(),
            Stereo(-3, 1, 5).unit(),
            Stereo(2, -1, 6).unit(),
            n,
        )
        .unwrap();
        let sym = values(Method::SymmetricPhong, &s);
        for i in 0..=n {
            let want = s.p_at(i) / s.q_at(i).sqrt();
            assert_eq!(sym[i as usize], want, "n = {n}, pixel {i}");
        }
    }
    for_all_spans(CASES, |_, s| {
        let sym = values(Method::SymmetricPhong, s);
        for i in 0..=s.n {
            eq(
                &format!("pixel {i}"),
                &sym[i as usize],
                &(s.p_at(i) / s.q_at(i).sqrt()),
            )?;
        }
        Ok(())
    });
}

#[test]
fn eq_14_euler_sum_of_slopes() {
    // The recurrence's value after m steps is p_0 plus the sum of the slopes it used,
    // s_0 + j·ds for j < m, which is the arithmetic series of eq. 14.
    for_all_spans(CASES, |_, s| {
        let e = values(Method::Euler, s);
        let mut sum = s.p_a.clone();
        for m in 0..=s.n {
            eq(&format!("p_{m}"), &e[m as usize], &sum)?;
            let closed = s.p_a.clone()
                + qi(m) * s.di_a.clone()
                + (qi(m) * qi(m) - qi(m)) / q(2, 1) * s.ds.clone();
            eq(&format!("closed form at {m}"), &sum, &closed)?;
            sum = sum + s.di_a.clone() + qi(m) * s.ds.clone();
        }
        Ok(())
    });
}

// ---- §7: the error against Phong, by angle (proofs/Angle.v) -----------------------

/// The fraction `t = i/n` of pixel `i`.
pub(crate) fn t_of(s: &Span<Q>, i: u32) -> Q {
    qi(i) / qi(s.n)
}

/// `(a, b)` with `Ph(t) − M(t) = a·p_a + b·p_b` for the methods of §7, from the
/// closed forms in `t` (`1 − c = k`, `h = 1/n`); `r = 1/√q(t)` to `2^-256`.
pub(crate) fn error_coefficients(method: Method, s: &Span<Q>, i: u32) -> (Q, Q) {
    let t = t_of(s, i);
    let u = Q::one() - t.clone();
    let k = Q::one() - cos_ab(s);
    let r = Q::one() / s.q_at(i).sqrt();
    let st = t.clone() * u.clone();
    let h = Q::one() / qi(s.n);
    let two = q(2, 1);
    let (alpha, beta) = match method {
        Method::Gouraud => (u.clone(), t.clone()),
        Method::CorrectedEuler => (
            u.clone() + k.clone() * st.clone() / two.clone(),
            t.clone() + k.clone() * st.clone() / two.clone(),
        ),
        Method::Euler => {
            let w = k.clone() * (t.clone() * t.clone() - t.clone() * h) / two.clone();
            (u.clone() + t.clone() * k.clone() - w.clone(), t.clone() - w)
        }
        _ => unreachable!("§7 covers Gouraud, corrected Euler and Euler"),
    };
    (u * r.clone() - alpha, t * r - beta)
}

/// `√(a² + b² + 2abc)`: the length of `a N_a + b N_b`, the largest error over unit lights.
pub(crate) fn sup_over_lights(s: &Span<Q>, (a, b): &(Q, Q)) -> Q {
    (a.clone() * a.clone() + b.clone() * b.clone() + q(2, 1) * a.clone() * b.clone() * cos_ab(s))
        .sqrt()
}

/// Phong at pixel `i`, to `2^-256`.
pub(crate) fn phong_value(s: &Span<Q>, i: u32) -> Q {
    s.p_at(i) / s.q_at(i).sqrt()
}

pub(crate) fn tiny() -> Q {
    two_pow(-200)
}

#[test]
fn sec_7_phong_in_t() {
    // p(i)/√q(i) = ((1−t)p_a + t p_b)/√(1 − 2(1−c)t(1−t)), checked exactly on p and q.
    for_all_spans(CASES, |_, s| {
        let k = Q::one() - cos_ab(s);
        for i in 0..=s.n {
            let t = t_of(s, i);
            let g = (Q::one() - t.clone()) * s.p_a.clone() + t.clone() * s.p_b.clone();
            eq(&format!("p({i})"), &s.p_at(i), &g)?;
            let qt = Q::one() - q(2, 1) * k.clone() * t.clone() * (Q::one() - t);
            eq(&format!("q({i})"), &s.q_at(i), &qt)?;
        }
        Ok(())
    });
}

#[test]
fn sec_7_gouraud_in_t() {
    for_all_spans(CASES, |_, s| {
        let g = values(Method::Gouraud, s);
        for i in 0..=s.n {
            let t = t_of(s, i);
            let want = (Q::one() - t.clone()) * s.p_a.clone() + t * s.p_b.clone();
            eq(&format!("G({i})"), &g[i as usize], &want)?;
        }
        Ok(())
    });
}

#[test]
fn sec_7_corrected_euler_in_t() {
    // CE(t) = (1−t)p_a + t p_b + (1−c)(p_a+p_b)/2 · t(1−t): independent of n.
    for_all_spans(CASES, |_, s| {
        let ce = values(Method::CorrectedEuler, s);
        let k = Q::one() - cos_ab(s);
        for i in 0..=s.n {
            let t = t_of(s, i);
            let want = (Q::one() - t.clone()) * s.p_a.clone()
                + t.clone() * s.p_b.clone()
                + k.clone() * (s.p_a.clone() + s.p_b.clone()) / q(2, 1)
                    * t.clone()
                    * (Q::one() - t);
            eq(&format!("CE({i})"), &ce[i as usize], &want)?;
        }
        Ok(())
    });
}

#[test]
fn sec_7_euler_in_t() {
    // E(t) = CE(t) + t·ε with ε = (1−c)((p_a − p_b)/2 + (p_a + p_b)/(2n)).
    for_all_spans(CASES, |_, s| {
        let e = values(Method::Euler, s);
        let ce = values(Method::CorrectedEuler, s);
        let k = Q::one() - cos_ab(s);
        let eps = k
            * ((s.p_a.clone() - s.p_b.clone()) / q(2, 1)
                + (s.p_a.clone() + s.p_b.clone()) / (q(2, 1) * qi(s.n)));
        for i in 0..=s.n {
            let want = ce[i as usize].clone() + t_of(s, i) * eps.clone();
            eq(&format!("E({i})"), &e[i as usize], &want)?;
        }
        Ok(())
    });
}

#[test]
fn sec_7_error_sup_over_lights() {
    // The error is linear in L: Ph − M = a p_a + b p_b = L·(a N_a + b N_b), so it is at
    // most |a N_a + b N_b|, and that is reached at L = (a N_a + b N_b)/|…|.
    for_all_spans(CASES, |_, s| {
        for m in [Method::Gouraud, Method::CorrectedEuler, Method::Euler] {
            let v = values(m, s);
            for i in 0..=s.n {
                let ab = error_coefficients(m, s, i);
                let err = phong_value(s, i) - v[i as usize].clone();
                let lin = ab.0.clone() * s.p_a.clone() + ab.1.clone() * s.p_b.clone();
                ensure((err.clone() - lin).abs() < tiny(), || {
                    format!("{m:?} pixel {i}: error is not a·p_a + b·p_b")
                })?;
                ensure(err.abs() <= sup_over_lights(s, &ab) + tiny(), || {
                    format!("{m:?} pixel {i}: error above |a N_a + b N_b|")
                })?;
            }
        }
        Ok(())
    });
    // Reached: for a span in the x–z plane, a rational light close to V/|V| comes
    // within 10^-6 of the bound.
    let s = plane_span(q(1, 2), 16);
    for m in [Method::Gouraud, Method::CorrectedEuler, Method::Euler] {
        for i in [3, 8, 13] {
            let ab = error_coefficients(m, &s, i);
            let sup = sup_over_lights(&s, &ab);
            let (best, _) = worst_light(&s, m, i);
            assert!(
                sup.clone() - best.clone() < q(1, 1_000_000),
                "{m:?} pixel {i}: sup {sup} best light {best}"
            );
        }
    }
}

/// The span `N_a = (0, 0, 1)`, `N_b = (sin θ, 0, cos θ)` with `tan(θ/2) = m`, light along
/// `N_a` (the light is replaced per pixel by [`worst_light`]).
pub(crate) fn plane_span(m: Q, n: u32) -> Span<Q> {
    let one = Q::one();
    let den = one.clone() + m.clone() * m.clone();
    let nb = phong_approx::Vec3::new(
        q(2, 1) * m.clone() / den.clone(),
        Q::zero(),
        (one.clone() - m.clone() * m) / den,
    );
    let na = phong_approx::Vec3::new(Q::zero(), Q::zero(), one.clone());
    Span::new(na.clone(), nb, na, n).unwrap()
}

/// The light in the plane of the normals closest to `(a N_a + b N_b)/|…|` among rational
/// unit vectors `(2w, 0, 1 − w²)/(1 + w²)` with `w` on a `10^-9` grid: the error of
/// `method` at pixel `i` under it, and the span.
pub(crate) fn worst_light(s: &Span<Q>, method: Method, i: u32) -> (Q, Span<Q>) {
    let (a, b) = error_coefficients(method, s, i);
    let f = |x: &Q| num_traits::ToPrimitive::to_f64(x).unwrap();
    // V = a N_a + b N_b in the x–z plane.
    let vx = f(&a) * f(&s.na.x) + f(&b) * f(&s.nb.x);
    let vz = f(&a) * f(&s.na.z) + f(&b) * f(&s.nb.z);
    let phi = vx.atan2(vz);
    let w = Q::new(
        (((phi / 2.0).tan() * 1e9).round() as i64).into(),
        1_000_000_000i64.into(),
    );
    let den = Q::one() + w.clone() * w.clone();
    let l = phong_approx::Vec3::new(
        q(2, 1) * w.clone() / den.clone(),
        Q::zero(),
        (Q::one() - w.clone() * w) / den,
    );
    let t = Span::new(s.na.clone(), s.nb.clone(), l, s.n).unwrap();
    let err = (phong_value(&t, i) - values(method, &t)[i as usize].clone()).abs();
    (err, t)
}

/// `tan(θ/2)` of an angle in degrees, rounded down to a multiple of `10^-9` (so the
/// span's angle is at most `θ` and within about `10^-7` degrees of it).
pub(crate) fn half_tan_below(deg: f64) -> Q {
    let t = (deg.to_radians() / 2.0).tan();
    Q::new(
        ((t * 1e9).floor() as i64 - 1).into(),
        1_000_000_000i64.into(),
    )
}

/// `tan(θ/2)` rounded up (the angle is at least `θ`).
pub(crate) fn half_tan_above(deg: f64) -> Q {
    let t = (deg.to_radians() / 2.0).tan();
    Q::new(
        ((t * 1e9).ceil() as i64 + 1).into(),
        1_000_000_000i64.into(),
    )
}

/// The largest error of `method` against Phong over every pixel of a 64-step span at
/// angle `m = tan(θ/2)`, each pixel under its own worst light (rational, near
/// `V/|V|`), computed in rationals with a `2^-256`-accurate square root.
pub(crate) fn worst_error_at_angle(method: Method, m: Q, n: u32) -> Q {
    let s = plane_span(m, n);
    (0..=n).map(|i| worst_light(&s, method, i).0).max().unwrap()
}

/// On the edge cases and random spans: `method` is within `bound(span)` of Phong
/// (to `2^-256`) at every pixel, where a bound is given.
pub(crate) fn within_bound_on_random_spans(method: Method, bound: impl Fn(&Span<Q>) -> Option<Q>) {
    for_all_spans(CASES, |_, s| {
        let Some(bound) = bound(s) else { return Ok(()) };
        let v = values(method, s);
        for i in 0..=s.n {
            let err = (phong_value(s, i) - v[i as usize].clone()).abs();
            ensure(err <= bound.clone() + tiny(), || {
                format!("{method:?} pixel {i}: {err} above {bound}")
            })?;
        }
        Ok(())
    });
}

/// The proved table of corrected Euler's worst error (8-bit levels, `K_d = 1`) by the
/// angle between the edge normals: (degrees, bound in levels) — `sec_7_corrected_euler_angle_table`.
pub(crate) const CE_TABLE: [(f64, f64); 14] = [
    (5.0, 0.00408),
    (10.0, 0.0328),
    (15.0, 0.111),
    (20.0, 0.264),
    (25.0, 0.519),
    (30.0, 0.904),
    (35.0, 1.45),
    (40.0, 2.19),
    (45.0, 3.16),
    (50.0, 4.39),
    (60.0, 7.83),
    (70.0, 12.9),
    (80.0, 20.1),
    (90.0, 30.0),
];

#[test]
fn sec_7_corrected_euler_angle_table() {
    // At each angle of the table: no pixel of any light exceeds the proved bound, and the
    // worst light found comes within 2 % of it (the bound is tight).
    for (deg, levels) in CE_TABLE {
        let bound = Q::new(
            ((levels * 1e6).round() as i64).into(),
            255_000_000i64.into(),
        );
        let worst = worst_error_at_angle(Method::CorrectedEuler, half_tan_below(deg), 64);
        let ratio = num_traits::ToPrimitive::to_f64(&(worst.clone() / bound.clone())).unwrap();
        println!(
            "{deg}°: worst {:.4} levels, bound {levels} ({:.1} %)",
            ratio * levels,
            100.0 * ratio
        );
        assert!(
            worst <= bound,
            "{deg}°: {worst} above the bound {levels}/255"
        );
        assert!(
            ratio > 0.98,
            "{deg}°: the bound is {:.1} % above the worst found",
            100.0 / ratio - 100.0
        );
    }
    // Random spans at or below each angle never exceed it either (the smallest angle of
    // the table at or above the span's).
    within_bound_on_random_spans(Method::CorrectedEuler, |s| {
        let c = num_traits::ToPrimitive::to_f64(&cos_ab(s)).unwrap();
        CE_TABLE
            .iter()
            .find(|(deg, _)| c >= f64::cos(f64::to_radians(*deg)) + 1e-12)
            .map(|(_, levels)| {
                Q::new(
                    ((levels * 1e6).round() as i64).into(),
                    255_000_000i64.into(),
                )
            })
    });
}

#[test]
fn sec_7_corrected_euler_one_level() {
    // Up to 31.0° within one level, up to 24.6° within half a level; at 31.1° and 24.8°
    // some pixel under some light is further off.
    let one = q(1, 255);
    let half = q(1, 510);
    assert!(worst_error_at_angle(Method::CorrectedEuler, half_tan_below(31.0), 64) <= one);
    assert!(worst_error_at_angle(Method::CorrectedEuler, half_tan_below(24.6), 64) <= half);
    assert!(worst_error_at_angle(Method::CorrectedEuler, half_tan_above(31.1), 64) > one);
    assert!(worst_error_at_angle(Method::CorrectedEuler, half_tan_above(24.8), 64) > half);
}

#[test]
fn sec_7_gouraud_angle_bound() {
    // |Ph − G| ≤ 1 − √((1+c)/2) = 1 − cos(θ/2) at every pixel of every span.
    within_bound_on_random_spans(Method::Gouraud, |s| {
        Some(Q::one() - ((Q::one() + cos_ab(s)) / q(2, 1)).sqrt())
    });
    // Equality at the middle pixel with L along N_a + N_b: Na = (3/5,0,4/5),
    // Nb = (−3/5,0,4/5), L = (0,0,1), n = 2: Ph = 1, G = 4/5, 1 − cos(θ/2) = 1/5.
    let s = Span::new(
        Stereo(1, 0, 3).unit(),
        Stereo(-1, 0, 3).unit(),
        Stereo(0, 0, 1).unit(),
        2,
    )
    .unwrap();
    let g = values(Method::Gouraud, &s);
    assert_eq!(s.p_at(1), q(4, 5));
    assert_eq!(s.q_at(1), q(16, 25));
    assert_eq!(q(1, 1) - g[1].clone(), q(1, 5));
    assert_eq!(((Q::one() + cos_ab(&s)) / q(2, 1)), q(16, 25));
    // At the table's angles, the worst light at every pixel of a 64-step span stays
    // within the bound and reaches it to 10^-6 (at the middle pixel).
    for (deg, _) in CE_TABLE {
        let m = half_tan_below(deg);
        let s = plane_span(m.clone(), 64);
        let bound = Q::one() - ((Q::one() + cos_ab(&s)) / q(2, 1)).sqrt();
        let worst = worst_error_at_angle(Method::Gouraud, m, 64);
        assert!(worst <= bound.clone() + tiny(), "{deg}°: {worst} > {bound}");
        assert!(
            bound.clone() - worst < q(1, 1_000_000),
            "{deg}°: not reached"
        );
    }
}

#[test]
fn sec_7_euler_angle_bound() {
    // |Ph − E| ≤ 1 − c at every pixel of every span, every n.
    within_bound_on_random_spans(Method::Euler, |s| Some(Q::one() - cos_ab(s)));
    // Equality at n = 1, pixel 1, L = N_a: E_1 = p_b + (1 − c)p_a with p_a = 1.
    let s = Span::new(
        Stereo(1, 2, 7).unit(),
        Stereo(-3, 1, 5).unit(),
        Stereo(1, 2, 7).unit(),
        1,
    )
    .unwrap();
    let e = values(Method::Euler, &s);
    assert_eq!(e[1].clone() - s.p_b.clone(), Q::one() - cos_ab(&s));
    // And at the table's angles no worst light exceeds 1 − c (n = 1 and n = 64).
    for deg in [5.0, 30.0, 60.0, 90.0] {
        for n in [1, 64] {
            let m = half_tan_below(deg);
            let s = plane_span(m.clone(), n);
            let worst = worst_error_at_angle(Method::Euler, m, n);
            assert!(worst <= Q::one() - cos_ab(&s) + tiny(), "{deg}° n = {n}");
        }
    }
}
