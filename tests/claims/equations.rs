//! The paper's equations 2–24 (set-up, Duff, the derivative, Euler and corrected Euler, symmetry, the adaptive δ test), checked exactly in rationals.

use super::*;

// ---- eqs. 2–4: the set-up --------------------------------------------------------

#[test]
fn eq_2_p_is_linear() {
    for_all_spans(CASES, |_, s| {
        for i in 0..=s.n {
            eq(
                &format!("N({i})·L vs A·i + B"),
                &s.normal_at(i).dot(&s.l),
                &s.p_at(i),
            )?;
        }
        let x = q(1, 3);
        let nx = s.na.add(&s.k.scale(&x));
        eq("N(1/3)·L", &nx.dot(&s.l), &(s.a.clone() * x + s.b.clone()))
    });
}

#[test]
fn eq_3_q_is_quadratic() {
    for_all_spans(CASES, |_, s| {
        for i in 0..=s.n {
            let ni = s.normal_at(i);
            eq(
                &format!("N({i})·N({i}) vs q({i})"),
                &ni.length_squared(),
                &s.q_at(i),
            )?;
        }
        let x = q(-5, 7);
        let nx = s.na.add(&s.k.scale(&x));
        let qx = s.c.clone() * x.clone() * x.clone() + s.d.clone() * x + s.e.clone();
        eq("q(−5/7)", &nx.length_squared(), &qx)
    });
}

#[test]
fn eq_3_e_is_one() {
    for_all_spans(CASES, |_, s| eq("E", &s.e, &Q::one()));
}

#[test]
fn eq_10_q_is_one_on_edges() {
    for_all_spans(CASES, |_, s| {
        eq("q(0)", &s.q_at(0), &Q::one())?;
        eq("q(n)", &s.q_at(s.n), &Q::one())
    });
}

#[test]
fn eq_4_phong_exact_on_edges() {
    for_all_spans(CASES, |_, s| {
        let v = values(Method::Phong, s);
        eq("phong(0)", &v[0], &s.p_a)?;
        eq("phong(n)", &v[s.n as usize], &s.p_b)
    });
}

// ---- eqs. 5–7: Duff --------------------------------------------------------------

#[test]
fn eq_5_7_duff_recurrence_exact() {
    for_all_spans(CASES, |_, s| {
        let mut r = Recurrence::new(s);
        for i in 0..=s.n {
            let x = qi(i);
            eq(
                &format!("p_{i}"),
                &r.p,
                &(s.a.clone() * x.clone() + s.b.clone()),
            )?;
            eq(&format!("q_{i}"), &r.q, &s.q_at(i))?;
            let dq = s.c.clone() * (qi(2 * i) + Q::one()) + s.d.clone();
            eq(&format!("dq_{i}"), &r.dq, &dq)?;
            r.step();
        }
        Ok(())
    });
}

#[test]
fn eq_7_duff_dq0_and_d2q() {
    for_all_spans(CASES, |_, s| {
        eq(
            "q(1) − q(0)",
            &(s.q_at(1) - s.q_at(0)),
            &(s.c.clone() + s.d.clone()),
        )?;
        for i in 0..s.n.saturating_sub(1) {
            let second = s.q_at(i + 2) - s.q_at(i + 1) * q(2, 1) + s.q_at(i);
            eq(&format!("Δ²q at {i}"), &second, &(s.c.clone() * q(2, 1)))?;
        }
        Ok(())
    });
}

#[test]
fn eq_5_7_duff_computes_phong() {
    for_all_spans(CASES, |_, s| {
        let duff = values(Method::Duff, s);
        let phong = values(Method::Phong, s);
        for i in 0..=s.n as usize {
            eq(&format!("duff vs phong at {i}"), &duff[i], &phong[i])?;
        }
        Ok(())
    });
}

// ---- eq. 9–11: derivatives -------------------------------------------------------

/// The derivative of eq. 9 at `x`: `(1/√q)(A − p/(2q)·q')`, `q' = 2Cx + D`.
pub(crate) fn eq9(s: &Span<Q>, x: &Q) -> Q {
    let p = s.a.clone() * x.clone() + s.b.clone();
    let qx = (s.c.clone() * x.clone() + s.d.clone()) * x.clone() + s.e.clone();
    let dq = s.c.clone() * q(2, 1) * x.clone() + s.d.clone();
    (s.a.clone() - p / (q(2, 1) * qx.clone()) * dq) / qx.sqrt()
}

/// Central difference of `p/√q` with step 2^-40: error O(h²) ≈ 2^-80 times the
/// third derivative, far below the 2^-50 tolerance used.
pub(crate) fn numeric_derivative(s: &Span<Q>, x: &Q) -> Q {
    let h = two_pow(-40);
    (phong_at(s, &(x.clone() + h.clone())) - phong_at(s, &(x.clone() - h.clone()))) / (h * q(2, 1))
}

#[test]
fn eq_9_derivative() {
    for_all_spans(24, |_, s| {
        // Third derivatives grow like (|k|/|N|)³; tolerate that scale.
        let tol = two_pow(-50) * (Q::one() + s.c.clone()) * q(1000, 1);
        for x in [q(0, 1), qi(s.n) / q(3, 1), qi(s.n)] {
            if s.q_at(0).is_zero() {
                continue;
            }
            let nd = numeric_derivative(s, &x);
            let f = eq9(s, &x);
            ensure((nd.clone() - f.clone()).abs() <= tol, || {
                format!("x = {x}: numeric {} vs eq. 9 {}", nd.to_f64(), f.to_f64())
            })?;
        }
        Ok(())
    });
}

pub(crate) trait ToF64 {
    fn to_f64(&self) -> f64;
}
impl ToF64 for Q {
    fn to_f64(&self) -> f64 {
        num_traits::ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }
}

#[test]
fn eq_10_11_dp_dq_at_edges() {
    for_all_spans(CASES, |_, s| {
        // Central differences are exact for polynomials of degree ≤ 2.
        let h = q(1, 3);
        let n = qi(s.n);
        let pd = |x: &Q| {
            let p = |y: Q| s.na.add(&s.k.scale(&y)).dot(&s.l);
            (p(x.clone() + h.clone()) - p(x.clone() - h.clone())) / (h.clone() * q(2, 1))
        };
        let qd = |x: &Q| {
            let qq = |y: Q| s.na.add(&s.k.scale(&y)).length_squared();
            (qq(x.clone() + h.clone()) - qq(x.clone() - h.clone())) / (h.clone() * q(2, 1))
        };
        eq("p'(0)", &pd(&Q::zero()), &s.a)?;
        eq("p'(n)", &pd(&n), &s.a)?;
        eq("q'(0) = dq_a", &qd(&Q::zero()), &s.dq_a)?;
        eq("q'(n) = dq_b", &qd(&n), &s.dq_b)
    });
}

#[test]
fn eq_10_11_edge_derivatives() {
    for_all_spans(CASES, |_, s| {
        // At the edges q = 1, so √q = 1 and eq. 9 is a rational expression.
        eq("eq. 9 at 0 vs di_a", &eq9(s, &Q::zero()), &s.di_a)?;
        eq("eq. 9 at n vs di_b", &eq9(s, &qi(s.n)), &s.di_b)?;
        // And the numeric derivative of p/√q agrees.
        let tol = two_pow(-50) * (Q::one() + s.c.clone()) * q(1000, 1);
        let nd = numeric_derivative(s, &Q::zero());
        ensure((nd.clone() - s.di_a.clone()).abs() <= tol, || {
            format!("numeric {} vs di_a {}", nd.to_f64(), s.di_a.to_f64())
        })
    });
}

// ---- eqs. 12–17: Euler and corrected Euler ---------------------------------------

#[test]
fn eq_13_slope_closed_form() {
    for_all_spans(CASES, |_, s| {
        let v = values(Method::Euler, s);
        for i in 0..s.n as usize {
            let si = s.di_a.clone() + qi(i as u32) * s.ds.clone();
            eq(
                &format!("p_{} − p_{i}", i + 1),
                &(v[i + 1].clone() - v[i].clone()),
                &si,
            )?;
        }
        Ok(())
    });
}

#[test]
fn eq_14_euler_closed_form() {
    for_all_spans(CASES, |_, s| {
        let v = values(Method::Euler, s);
        for (i, vi) in v.iter().enumerate() {
            let x = qi(i as u32);
            let closed = s.p_a.clone()
                + x.clone() * s.di_a.clone()
                + (x.clone() * x.clone() - x) / q(2, 1) * s.ds.clone();
            eq(&format!("p_{i}"), vi, &closed)?;
        }
        Ok(())
    });
}

#[test]
fn eq_14_arithmetic_series() {
    for_all_spans(CASES, |_, s| {
        let mut sum = Q::zero();
        for j in 0..s.n {
            sum += qi(j) * s.ds.clone();
        }
        let n = qi(s.n);
        eq(
            "Σ j·ds",
            &sum,
            &((n.clone() * n.clone() - n) / q(2, 1) * s.ds.clone()),
        )
    });
}

#[test]
fn eq_14_euler_end_value() {
    for_all_spans(CASES, |_, s| {
        let v = values(Method::Euler, s);
        eq("Euler p_n vs eq. 14", &v[s.n as usize], &s.p_n)
    });
}

#[test]
fn eq_15_euler_misses_pb() {
    // The span of Mortensen's counterexample: Na = (3/5, 0, 4/5), Nb = (−3/5, 0, 4/5),
    // L = (0, 0, 1), n = 2.
    let s = Span::new(
        Stereo(1, 0, 3).unit(),
        Stereo(-1, 0, 3).unit(),
        Stereo(0, 0, 1).unit(),
        2,
    )
    .unwrap();
    assert_eq!(s.di_a, q(36, 125));
    assert_eq!(s.ds, q(-36, 125));
    let v = values(Method::Euler, &s);
    assert_eq!(v[2], q(4, 5) + q(36, 125));
    assert_eq!(s.p_b, q(4, 5));
    assert_eq!(s.eps, q(36, 125));
    // And in general ε = p_n − p_b is what Euler misses by.
    for_all_spans(CASES, |_, s| {
        let v = values(Method::Euler, s);
        eq("ε", &(v[s.n as usize].clone() - s.p_b.clone()), &s.eps)
    });
}

#[test]
fn eq_16_17_corrected_is_euler_minus_linear_error() {
    for_all_spans(CASES, |_, s| {
        let e = values(Method::Euler, s);
        let c = values(Method::CorrectedEuler, s);
        for i in 0..=s.n as usize {
            let want = e[i].clone() - qi(i as u32) * s.eps.clone() / qi(s.n);
            eq(&format!("corrected p_{i}"), &c[i], &want)?;
        }
        Ok(())
    });
}

#[test]
fn eq_17_corrected_euler_starts_at_pa() {
    for_all_spans(CASES, |_, s| {
        eq("p_0", &values(Method::CorrectedEuler, s)[0], &s.p_a)
    });
}

#[test]
fn eq_17_corrected_euler_ends_at_pb() {
    for_all_spans(CASES, |_, s| {
        let v = values(Method::CorrectedEuler, s);
        eq("p_n", &v[s.n as usize], &s.p_b)?;
        // The text's dε = ε/N read as ε/n is the only reading that ends at p_b: with
        // any other divisor the end value moves by n·(ε/n − ε/N).
        Ok(())
    });
}

// ---- eqs. 18–22 ------------------------------------------------------------------

#[test]
fn eq_18_na_k_is_minus_nb_k() {
    for_all_spans(CASES, |_, s| eq("Na·k", &s.na.dot(&s.k), &-s.nb.dot(&s.k)));
}

#[test]
fn eq_19_dqb_via_nb() {
    for_all_spans(CASES, |_, s| {
        let want = q(2, 1) * qi(s.n) * s.c.clone() - q(2, 1) * s.k.dot(&s.nb);
        eq("dq_b", &s.dq_b, &want)
    });
}

#[test]
fn eq_20_n_k2_is_2k_nb() {
    for_all_spans(CASES, |_, s| {
        let n = qi(s.n);
        let nc = n.clone() * s.c.clone();
        eq("n·k²", &nc, &(q(2, 1) * (Q::one() - s.na.dot(&s.nb)) / n))?;
        eq("n·k² vs 2k·Nb", &nc, &(q(2, 1) * s.k.dot(&s.nb)))
    });
}

#[test]
fn eq_21_dqb_is_2k_nb() {
    for_all_spans(CASES, |_, s| {
        eq("dq_b", &s.dq_b, &(q(2, 1) * s.k.dot(&s.nb)))
    });
}

#[test]
fn eq_22_dqb_is_minus_dqa() {
    for_all_spans(CASES, |_, s| eq("dq_b", &s.dq_b, &-s.dq_a.clone()));
}

#[test]
fn eq_11_ds_closed_form() {
    for_all_spans(CASES, |_, s| {
        let want = s.d.clone() * (s.p_a.clone() + s.p_b.clone()) / (q(2, 1) * qi(s.n));
        eq("ds", &s.ds, &want)
    });
}

// ---- §4: symmetry ----------------------------------------------------------------

#[test]
fn sec_4_q_is_symmetric() {
    for_all_spans(CASES, |_, s| {
        for i in 0..=s.n {
            eq(
                &format!("q({i}) vs q(n − {i})"),
                &s.q_at(i),
                &s.q_at(s.n - i),
            )?;
        }
        let qx = |x: Q| (s.c.clone() * x.clone() + s.d.clone()) * x + s.e.clone();
        let x = q(1, 7);
        eq("q(1/7)", &qx(x.clone()), &qx(qi(s.n) - x))
    });
}

#[test]
fn sec_4_dq_zero_at_middle() {
    for_all_spans(CASES, |_, s| {
        let n = qi(s.n);
        let two = q(2, 1);
        eq(
            "q'(n/2)",
            &(two.clone() * s.c.clone() * n.clone() / two.clone() + s.d.clone()),
            &Q::zero(),
        )?;
        let mid = (n - Q::one()) / two.clone();
        eq(
            "dq at (n−1)/2",
            &(s.c.clone() * (two * mid + Q::one()) + s.d.clone()),
            &Q::zero(),
        )
    });
}

#[test]
fn sec_4_q_minimum_at_middle() {
    for_all_spans(CASES, |_, s| {
        let half = qi(s.n) / q(2, 1);
        let qx = |x: Q| (s.c.clone() * x.clone() + s.d.clone()) * x + s.e.clone();
        let qmid = qx(half.clone());
        for i in 0..=s.n {
            let x = qi(i);
            let vertex =
                qmid.clone() + s.c.clone() * (x.clone() - half.clone()) * (x - half.clone());
            eq(&format!("q({i}) vertex form"), &s.q_at(i), &vertex)?;
            ensure(qmid <= s.q_at(i), || format!("q(n/2) > q({i})"))?;
        }
        Ok(())
    });
}

#[test]
fn sec_4_duff_q_is_symmetric() {
    for_all_spans(CASES, |_, s| {
        let mut r = Recurrence::new(s);
        let mut qs = Vec::new();
        for _ in 0..=s.n {
            qs.push(r.q.clone());
            r.step();
        }
        for i in 0..=s.n as usize {
            eq(
                &format!("Duff q_{i} vs q_(n−{i})"),
                &qs[i],
                &qs[s.n as usize - i],
            )?;
        }
        Ok(())
    });
}

#[test]
fn sec_4_symmetric_phong_equals_phong() {
    for_all_spans(CASES, |_, s| {
        let sym = values(Method::SymmetricPhong, s);
        let phong = values(Method::Phong, s);
        for i in 0..=s.n as usize {
            eq(&format!("pixel {i}"), &sym[i], &phong[i])?;
        }
        Ok(())
    });
}

// ---- eqs. 23–24: the adaptive test ------------------------------------------------

#[test]
fn eq_23_m_is_half_n_minus_1() {
    for_all_spans(CASES, |_, s| {
        let d = adaptive::decide(s, &Q::one());
        match d.m {
            Some(m) => eq("m", &m, &((qi(s.n) - Q::one()) / q(2, 1))),
            None => ensure(s.ds.is_zero(), || "m is None but ds ≠ 0".into()),
        }
    });
}

#[test]
fn eq_23_truncated_step_is_ceil_half() {
    for_all_spans(CASES, |_, s| {
        let d = adaptive::decide(s, &Q::one());
        match d.step {
            Some(step) => ensure(step == s.n.div_ceil(2), || {
                format!("step {step} for n = {}", s.n)
            }),
            None => ensure(s.ds.is_zero(), || "step is None but ds ≠ 0".into()),
        }
    });
}

#[test]
fn eq_24_gouraud_minus_corrected_euler() {
    for_all_spans(CASES, |_, s| {
        let g = values(Method::Gouraud, s);
        let c = values(Method::CorrectedEuler, s);
        for i in 0..=s.n {
            let want = s.ds.clone() / q(2, 1) * qi(i) * (qi(s.n) - qi(i));
            eq(
                &format!("G − CE at {i}"),
                &(g[i as usize].clone() - c[i as usize].clone()),
                &want,
            )?;
        }
        Ok(())
    });
}

#[test]
fn eq_24_delta_closed_form() {
    for_all_spans(CASES, |_, s| {
        let m = s.n.div_ceil(2);
        let want = s.ds.clone() / q(2, 1) * qi(m) * (qi(s.n) - qi(m));
        eq("δ", &adaptive::delta_at(s, m), &want)?;
        eq("decide's δ", &adaptive::decide(s, &Q::one()).delta, &want)
    });
}

#[test]
fn eq_24_delta_is_max_difference() {
    for_all_spans(CASES, |_, s| {
        let g = values(Method::Gouraud, s);
        let c = values(Method::CorrectedEuler, s);
        let d = adaptive::decide(s, &Q::one());
        let max = (0..=s.n as usize)
            .map(|i| (g[i].clone() - c[i].clone()).abs())
            .max()
            .unwrap();
        eq("|δ| vs max |G − CE|", &d.delta.abs(), &max)?;
        if let Some(step) = d.step {
            let at = g[step as usize].clone() - c[step as usize].clone();
            eq("δ vs G − CE at the step", &d.delta, &at)?;
        }
        Ok(())
    });
}

#[test]
fn eq_24_delta_test_does_not_imply_same_levels() {
    // Two values less than one level apart that straddle a level boundary.
    let g = q(1, 255);
    let c = q(1, 255) - q(1, 1000);
    assert!((g.clone() - c.clone()).abs() * q(255, 1) < Q::one());
    assert_ne!(level(&g), level(&c));
}

#[test]
fn eq_24_delta_test_fails_on_concrete_span() {
    // Na = (0, 3/5, 4/5), Nb = (0, 8/17, 15/17), L = (0, 0, 1), n = 2, K_d = 1.
    let s = Span::new(
        Stereo(0, 1, 3).unit(),
        Stereo(0, 1, 4).unit(),
        Stereo(0, 0, 1).unit(),
        2,
    )
    .unwrap();
    assert_eq!(s.nb.y, q(8, 17));
    let d = adaptive::decide(&s, &Q::one());
    assert_eq!(
        d.choice,
        Choice::Gouraud,
        "|δ·255| = {}",
        d.delta.clone() * q(255, 1)
    );
    assert_eq!((d.delta.clone() * q(255, 1)).abs(), q(36465, 57800));
    let g = values(Method::Gouraud, &s);
    let c = values(Method::CorrectedEuler, &s);
    assert_eq!(g[1], q(143, 170));
    assert_eq!(c[1], q(48763, 57800));
    assert_eq!((level(&g[1]), level(&c[1])), (214, 215));
}

/// `floor(255·v)` without clamping.
pub(crate) fn raw_level(v: &Q) -> Q {
    (v.clone() * q(255, 1)).floor()
}

#[test]
fn eq_24_large_delta_implies_different_levels() {
    for_all_spans(CASES, |_, s| {
        let d = adaptive::decide(s, &Q::one());
        if (d.delta.clone() * q(255, 1)).abs() >= Q::one() {
            let step = d.step.expect("δ ≠ 0 needs ds ≠ 0") as usize;
            let g = values(Method::Gouraud, s);
            let c = values(Method::CorrectedEuler, s);
            ensure(raw_level(&g[step]) != raw_level(&c[step]), || {
                format!("|δ·255| ≥ 1 but equal levels at {step}")
            })?;
        }
        Ok(())
    });
    // The generic statement on random pairs one or more levels apart.
    proptest::proptest!(|(a in -100_000i64..100_000, gap in 1_000i64..50_000)| {
        let g = q(a, 25_500);
        let c = g.clone() + q(gap, 1_000 * 255);
        proptest::prop_assert!(raw_level(&g) != raw_level(&c));
    });
}
