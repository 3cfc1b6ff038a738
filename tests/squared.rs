//! The squared method (`phong_approx::squared_corrected_euler`, the paper's §7.1
//! question b): corrected Euler's construction on `g = (N·H)²/(N·N)`, checked exactly
//! in rationals against values computed here from the inputs — the ends, the
//! derivative (as `2·f·f′ = 2pL/q²`, from Skip.v's `L`, not from the code's formula),
//! the closed form, the unit-normal relation to corrected Euler, the specular powers —
//! on unit and non-unit edge normals. Theorems: `proofs/Squared.v`.

use super::common::*;
use num_traits::{One, Signed, Zero};
use phong_approx::specular::power;
use phong_approx::squared_corrected_euler::SquaredSpan;
use phong_approx::{Scalar, Span, SpanError, Vec3};

/// `N_a`, `N_b`, `H` and `n`.
type Inputs = (Vec3<Q>, Vec3<Q>, Vec3<Q>, u32);

/// The inputs tried: the edge, targeted and seeded random unit spans (n ≤ 16; 256 in
/// the extensive tier), and each again with its edge normals scaled by 3 and 1/2 (not
/// unit: the method takes any length).
fn inputs() -> Vec<Inputs> {
    let spans = sample_spans(tiered(16, 256), tiered(24, 400));
    let mut out = Vec::new();
    for s in spans {
        out.push((s.na.clone(), s.nb.clone(), s.l.clone(), s.n));
        out.push((s.na.scale(&q(3, 1)), s.nb.scale(&q(1, 2)), s.l.clone(), s.n));
    }
    out
}

/// `p(t)`, `q(t)` and Skip.v's `L(t)` of the inputs, computed here.
struct Poly {
    a: Q,
    b: Q,
    c: Q,
    d: Q,
    e: Q,
}

impl Poly {
    fn of(na: &Vec3<Q>, nb: &Vec3<Q>, h: &Vec3<Q>, n: u32) -> Poly {
        let k = nb.sub(na).div(&q(n.into(), 1));
        Poly {
            a: k.dot(h),
            b: na.dot(h),
            c: k.dot(&k),
            d: q(2, 1) * k.dot(na),
            e: na.dot(na),
        }
    }
    fn p(&self, t: &Q) -> Q {
        &self.b + &self.a * t
    }
    fn q(&self, t: &Q) -> Q {
        &self.e + &self.d * t + &self.c * t * t
    }
    fn g(&self, t: &Q) -> Q {
        let p = self.p(t);
        &p * &p / self.q(t)
    }
    /// `g′ = 2·f·f′ = 2·p·L/q²` (`f′ = L/q^{3/2}`, proofs/Skip.v `f_derive`).
    fn dg(&self, t: &Q) -> Q {
        let l = (&self.a * &self.e - &self.b * &self.d / q(2, 1))
            + t * (&self.a * &self.d / q(2, 1) - &self.b * &self.c);
        let qt = self.q(t);
        q(2, 1) * self.p(t) * l / (&qt * &qt)
    }
}

fn run(s: &SquaredSpan<Q>) -> Vec<Q> {
    let mut out = vec![Q::zero(); s.n as usize + 1];
    s.shade(&mut out).unwrap();
    out
}

/// `sq_derivative` (proofs/Squared.v): the set-up's end slopes are `g′` at `0` and `n`,
/// where `g′` is computed here as `2·p·L/q²`.
#[test]
fn sq_derivative() {
    for (na, nb, h, n) in inputs() {
        let s = SquaredSpan::new(&na, &nb, &h, n).unwrap();
        let poly = Poly::of(&na, &nb, &h, n);
        assert_eq!(s.dg_a, poly.dg(&Q::zero()), "{na:?} {nb:?} {h:?} {n}");
        assert_eq!(s.dg_b, poly.dg(&q(n.into(), 1)), "{na:?} {nb:?} {h:?} {n}");
    }
}

/// `sq_starts_at_ga` (proofs/Squared.v): the recurrence's first value is
/// `(N_a·H)²/(N_a·N_a)`, for edge normals of any length.
#[test]
fn sq_starts_at_ga() {
    for (na, nb, h, n) in inputs() {
        let out = run(&SquaredSpan::new(&na, &nb, &h, n).unwrap());
        let pa = na.dot(&h);
        assert_eq!(out[0], &pa * &pa / na.dot(&na));
    }
}

/// `sq_ends_at_gb` (proofs/Squared.v): the recurrence's last value, `n` additions
/// later, is `(N_b·H)²/(N_b·N_b)` exactly.
#[test]
fn sq_ends_at_gb() {
    for (na, nb, h, n) in inputs() {
        let out = run(&SquaredSpan::new(&na, &nb, &h, n).unwrap());
        let pb = nb.dot(&h);
        assert_eq!(out[n as usize], &pb * &pb / nb.dot(&nb), "n = {n}");
    }
}

/// `sq_closed_form` (proofs/Squared.v): `g_i = g_a + i·t_0 + i(i−1)/2·ds` at every
/// pixel of the recurrence.
#[test]
fn sq_closed_form() {
    for (na, nb, h, n) in inputs() {
        let s = SquaredSpan::new(&na, &nb, &h, n).unwrap();
        for (i, v) in run(&s).iter().enumerate() {
            let i = q(i as i64, 1);
            let want = &s.g_a + &i * &s.t0 + &i * (&i - Q::one()) / q(2, 1) * &s.ds;
            assert_eq!(*v, want);
        }
    }
}

/// `sq_unit_setup` (proofs/Squared.v): with unit edge normals the end slopes are
/// `2·p_a·di_a` and `2·p_b·di_b` — twice `p` times corrected Euler's (the span's
/// eqs. 10–11).
#[test]
fn sq_unit_setup() {
    for (na, nb, h, n) in inputs() {
        let Ok(span) = Span::new(na, nb, h, n) else {
            continue; // the scaled, non-unit copies
        };
        let s = SquaredSpan::of(&span).unwrap();
        assert_eq!(s.dg_a, q(2, 1) * &span.p_a * &span.di_a);
        assert_eq!(s.dg_b, q(2, 1) * &span.p_b * &span.di_b);
    }
}

/// `sq_specular_even` (proofs/Squared.v): for even `s` the specular base is `g^{s/2}`
/// with no root: exactly Phong's `(p/√q)^s = (p²/q)^{s/2}` where `g` is exact (the
/// ends), `0` where `p ≤ 0`.
#[test]
fn sq_specular_even() {
    for (na, nb, h, n) in inputs() {
        let s = SquaredSpan::new(&na, &nb, &h, n).unwrap();
        let poly = Poly::of(&na, &nb, &h, n);
        for sh in [2, 8, 32] {
            let mut out = vec![Q::zero(); n as usize + 1];
            s.specular(sh, &mut out).unwrap();
            for t in [0, n] {
                let tq = q(t.into(), 1);
                let want = if poly.p(&tq) > Q::zero() {
                    power(&poly.g(&tq), sh / 2)
                } else {
                    Q::zero()
                };
                assert_eq!(out[t as usize], want, "s = {sh}, pixel {t}");
            }
            // Where p ≤ 0 (its own recurrence) the base is 0.
            for (i, v) in out.iter().enumerate() {
                if poly.p(&q(i as i64, 1)) <= Q::zero() {
                    assert!(v.is_zero());
                }
            }
        }
    }
}

/// `sq_specular_odd` (proofs/Squared.v): for odd `s` the base is `g^{(s−1)/2}·√g`, one
/// root per pixel: at the ends, Phong's `(p/√q)^s`, compared in `f64` from the exact
/// `g` (the root of the nearest `f64` of `g`; both sides within a few ulps, checked
/// against `10⁻¹²` relative).
#[test]
fn sq_specular_odd() {
    use num_traits::ToPrimitive;
    for (na, nb, h, n) in inputs() {
        let s = SquaredSpan::new(&na, &nb, &h, n).unwrap();
        let poly = Poly::of(&na, &nb, &h, n);
        for sh in [1, 9, 33] {
            let mut out = vec![Q::zero(); n as usize + 1];
            s.specular(sh, &mut out).unwrap();
            for t in [0, n] {
                let tq = q(t.into(), 1);
                let f = |x: Q| ToPrimitive::to_f64(&x).unwrap();
                let (p, qq) = (f(poly.p(&tq)), f(poly.q(&tq)));
                let want = if p > 0.0 {
                    (p / qq.sqrt()).powi(sh as i32)
                } else {
                    0.0
                };
                let got = f(out[t as usize].clone());
                assert!(
                    (got - want).abs() <= 1e-12 * want.abs() + 1e-300,
                    "s = {sh}, pixel {t}: {got} against {want}"
                );
            }
        }
    }
}

/// `sq_nonneg_value` (proofs/Squared.v): `g ≥ 0` where it is exact and `√g = |p|/√q`
/// (the diffuse use, one root per pixel): at the ends, in rationals (`g_a·E = p_a²`
/// exactly).
#[test]
fn sq_nonneg_value() {
    for (na, nb, h, n) in inputs() {
        let s = SquaredSpan::new(&na, &nb, &h, n).unwrap();
        assert!(s.g_a >= Q::zero() && s.g_b >= Q::zero());
        let (pa, pb) = (na.dot(&h), nb.dot(&h));
        assert_eq!(&s.g_a * na.dot(&na), &pa * &pa);
        assert_eq!(&s.g_b * nb.dot(&nb), &pb * &pb);
    }
}

/// The method is generic: in `f32` and `f64` its set-up and loop run on the same
/// inputs and stay finite; in rationals it is exact (above); `SquaredSpan::of` of a
/// unit span is `SquaredSpan::new` of its inputs.
#[test]
fn the_squared_method_runs_in_every_scalar() {
    for (na, nb, h, n) in inputs() {
        let exact = SquaredSpan::new(&na, &nb, &h, n).unwrap();
        let cast = |v: &Vec3<Q>| v.cast::<f64>().unwrap();
        let f = SquaredSpan::new(&cast(&na), &cast(&nb), &cast(&h), n).unwrap();
        let mut out = vec![0f64; n as usize + 1];
        f.specular(8, &mut out).unwrap();
        assert!(out.iter().all(|v| v.is_finite()));
        let c32 = |v: &Vec3<Q>| v.cast::<f32>().unwrap();
        let f32s = SquaredSpan::new(&c32(&na), &c32(&nb), &c32(&h), n).unwrap();
        let mut out = vec![0f32; n as usize + 1];
        f32s.shade(&mut out).unwrap();
        assert!(out.iter().all(|v| v.is_finite()));
        assert!(Scalar::is_finite(&exact.t0));
    }
}

/// Bad input is a typed error: a zero or non-finite edge normal, `n = 0` or above the
/// cap, an output of the wrong length.
#[test]
fn squared_errors_are_typed() {
    let v = |x: i64, y: i64, z: i64| Vec3::new(q(x, 1), q(y, 1), q(z, 1));
    let (up, side) = (v(0, 0, 1), v(1, 0, 0));
    assert!(matches!(
        SquaredSpan::new(&v(0, 0, 0), &up, &up, 4),
        Err(SpanError::ZeroVector { .. })
    ));
    assert!(matches!(
        SquaredSpan::new(&up, &v(0, 0, 0), &up, 4),
        Err(SpanError::ZeroVector { .. })
    ));
    assert!(matches!(
        SquaredSpan::new(&up, &side, &up, 0),
        Err(SpanError::ZeroSteps)
    ));
    assert!(matches!(
        SquaredSpan::new(&up, &side, &up, (1 << 24) + 1),
        Err(SpanError::TooManySteps { .. })
    ));
    let nan = Vec3::new(f64::NAN, 0.0, 1.0);
    assert!(matches!(
        SquaredSpan::new(
            &nan,
            &Vec3::new(0.0, 0.0, 1.0),
            &Vec3::new(0.0, 0.0, 1.0),
            4
        ),
        Err(SpanError::NonFinite { .. })
    ));
    let s = SquaredSpan::new(&up, &side, &up, 4).unwrap();
    let mut short = vec![Q::zero(); 4];
    assert!(matches!(
        s.shade(&mut short),
        Err(SpanError::OutputLength { .. })
    ));
}

/// Rationals whose roots are known: `(x, √max(0, x))` for `x = ±r²`, `r` small
/// fractions (seeded, deterministic), and 0.
fn rooted() -> Vec<(Q, Q)> {
    let mut seed = 0x9e37_79b9_u64;
    let mut next = |m: u64| {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
        (seed >> 33) % m
    };
    let mut out = vec![(Q::zero(), Q::zero())];
    for _ in 0..60 {
        let r = q(next(40) as i64, 1 + next(12) as i64);
        let x = &r * &r;
        if next(4) == 0 {
            out.push((-x, Q::zero()));
        } else {
            out.push((x, r));
        }
    }
    out
}

/// `|a| ≤ √b` for rationals, exactly (`a² ≤ b`).
fn within_root(a: &Q, b: &Q) -> bool {
    a * a <= *b
}

/// `sq_root_holder` (proofs/Squared.v): `|√max(0, x) − √max(0, y)| ≤ √|x − y|`, exactly
/// on rationals with known roots (squared: `(√x⁺ − √y⁺)² ≤ |x − y|`).
#[test]
fn sq_root_holder() {
    let xs = rooted();
    for (x, rx) in &xs {
        for (y, ry) in &xs {
            let d = (x - y).abs();
            assert!(within_root(&(rx - ry), &d), "x = {x}, y = {y}");
        }
    }
}

/// `sq_root_lipschitz` (proofs/Squared.v): for `y > 0`,
/// `|√max(0, x) − √y| ≤ |x − y|/√y`, exactly (times `√y`, which is known).
#[test]
fn sq_root_lipschitz() {
    let xs = rooted();
    for (x, rx) in &xs {
        for (y, ry) in xs.iter().filter(|(y, _)| *y > Q::zero()) {
            assert!((rx - ry).abs() * ry <= (x - y).abs(), "x = {x}, y = {y}");
        }
    }
}

/// `sgnv p r` of proofs/Squared.v: `r` where `p > 0`, `−r` where `p < 0`, else 0.
fn sgnv(p: &Q, r: &Q) -> Q {
    if *p > Q::zero() {
        r.clone()
    } else if *p < Q::zero() {
        -r.clone()
    } else {
        Q::zero()
    }
}

/// `sq_signed_value_error` (proofs/Squared.v): a computed value `sgnv(p̃, r̃)` against
/// the exact `sgnv(p, √max(0, g))`, with `e`, `e_p` the errors of `g̃`, `p̃`, `R` the
/// root's error and `r̃` within `k·√max(0, g̃) + η` of `√max(0, g̃)`: both
/// conclusions, exactly, over rooted `g`, `g̃`, signs of `p` and `p̃` on either side of
/// zero and the root's rounding at its extremes.
#[test]
fn sq_signed_value_error() {
    let xs = rooted();
    let (k, eta) = (q(1, 64), q(1, 1000));
    let ps = [q(-3, 10), q(-1, 100), Q::zero(), q(1, 100), q(2, 5)];
    for (g, rg) in xs.iter().step_by(3) {
        for (gt, rgt) in xs.iter().step_by(5) {
            let r = (rgt - rg).abs();
            for rt in [
                rgt.clone(),
                rgt * (Q::one() + &k) + &eta,
                rgt * (Q::one() - &k) - &eta,
            ] {
                for p in &ps {
                    for pt in &ps {
                        let ep = (pt - p).abs();
                        let err = (sgnv(pt, &rt) - sgnv(p, rg)).abs();
                        if ep < p.abs() {
                            assert!(err <= &r + &k * (rg + &r) + &eta, "kept sign");
                        }
                        let all = (Q::one() + &k) * (rg + &r) + rg + &eta;
                        assert!(err <= all, "g = {g}, g̃ = {gt}, p = {p}, p̃ = {pt}");
                    }
                }
            }
        }
    }
}

/// `sq_shader_root_rounding` (proofs/Squared.v): a root taken as `1/inverseSqrt(x)`,
/// `r̃` within `κ_r·u/√x + η` of `1/√x` and `ṽ` within `κ_d·u·|1/r̃| + η′` of `1/r̃`,
/// is within `(κ_d·u + a)/(1 − a)·√x + η′ + √x_min` of `√x` (`a = κ_r·u + 3η`), and a
/// flushed operand `x < x_min` read as 0 within the same: exactly, over rooted
/// `x ∈ (0, 9]` with `r̃` and `ṽ` at their extremes, where `√x = 3` meets the bound
/// with equality (so a smaller `k` fails here).
#[test]
fn sq_shader_root_rounding() {
    // `u` large, so that the extremes are far apart; `κ`s of the shader model.
    let (u, kr, kd) = (q(1, 1000), q(4, 1), q(5, 1));
    let (eta, eta2, root_min) = (q(1, 10_000), q(1, 20_000), q(1, 1000));
    let xmin = &root_min * &root_min;
    let a = &kr * &u + q(3, 1) * &eta;
    let k = (&kd * &u + &a) / (Q::one() - &a);
    let mut tight = false;
    let roots = [
        q(1, 2000),
        q(1, 1000),
        q(1, 7),
        q(1, 2),
        Q::one(),
        q(5, 3),
        q(3, 1),
    ];
    for s in &roots {
        let bound = &k * s + &eta2 + &root_min;
        for s1 in [-1, 0, 1] {
            let rt = Q::one() / s + q(s1, 1) * (&kr * &u / s + &eta);
            for s2 in [-1, 0, 1] {
                let inv = Q::one() / &rt;
                let v = &inv + q(s2, 1) * (&kd * &u * inv.abs() + &eta2);
                let err = (&v - s).abs();
                assert!(err <= bound, "√x = {s}, r̃ = {rt}, ṽ = {v}: {err} > {bound}");
                tight |= err == &bound - &root_min;
            }
        }
        // The flushed case: an operand below x_min read as 0.
        if s * s < xmin {
            assert!(s.clone() <= bound, "flushed √x = {s}");
        }
    }
    assert!(tight, "no extreme met the bound");
}

/// The catalogue's value (`Method::SquaredCorrectedEuler`, `sign(p)·√max(0, g)`) and
/// the specular path (`SquaredSpan::specular`, `g^{s/2}` with no root for even `s`)
/// agree: `max(0, v_i)^s` is the specular value at every pixel, `s = 0` included (1
/// everywhere), in `f64` within a relative `10^-12` (both round; the exact claim is
/// `sq_specular_even`, `sq_specular_odd`).
#[test]
fn the_catalogue_value_and_the_specular_path_agree() {
    let mut spans = 0;
    for (na, nb, h, n) in inputs() {
        let Ok(exact) = Span::new(na, nb, h, n) else {
            continue; // the scaled, non-unit copies
        };
        let span = exact.cast::<f64>().unwrap();
        let v = phong_approx::Method::SquaredCorrectedEuler
            .values(&span)
            .unwrap();
        let sq = SquaredSpan::of(&span).unwrap();
        for s in [0, 1, 2, 7, 32] {
            let mut spec = vec![0f64; n as usize + 1];
            sq.specular(s, &mut spec).unwrap();
            for (i, (x, y)) in v.iter().zip(&spec).enumerate() {
                let want = power(x, s);
                assert!(
                    (want - y).abs() <= 1e-12 * want.abs().max(1e-300) + 1e-300,
                    "s = {s}, pixel {i}: {want:e} against {y:e}"
                );
            }
        }
        spans += 1;
    }
    assert!(spans > 10, "{spans}");
}

/// The fast kernel (`phong_approx::fast::FastSquared`): its set-up is the generic
/// run's operations in its order (the same bits, in `f32` and `f64`); its values and
/// specular terms, by the closed forms, are those of the generic run's recurrence
/// (`Method::SquaredCorrectedEuler`, `SquaredSpan::specular`) within `f64`'s rounding
/// (`sq_closed_form`: exactly equal in rationals), and the same bits on every vector
/// path this CPU has; unit and non-unit edge normals. (Its error against the exact
/// value, in `f32` and `f64`: `graph_sound`, `tests/graph.rs`.)
#[test]
fn the_fast_kernel_is_the_generic_run_in_closed_form_on_every_path() {
    use phong_approx::fast::FastSquared;
    use phong_approx::simd::{self, Path};
    let chosen = simd::path();
    let mut checked = 0;
    macro_rules! run {
        ($t:ty) => {
            for (na, nb, h, n) in inputs() {
                let conv = |v: &Vec3<Q>| v.components().map(|x| <$t as Scalar>::from_rational(x));
                let (a3, b3, h3) = (conv(&na), conv(&nb), conv(&h));
                let vec = |x: [$t; 3]| Vec3::new(x[0], x[1], x[2]);
                let Ok(sq) = SquaredSpan::<$t>::new(&vec(a3), &vec(b3), &vec(h3), n) else {
                    continue;
                };
                let fast = FastSquared::<$t>::new(a3, b3, h3, n);
                let bits = |x: &$t| x.to_bits();
                assert_eq!(
                    [fast.a, fast.b, fast.g_a, fast.ds, fast.t0].map(|x| x.to_bits()),
                    [&sq.a, &sq.b, &sq.g_a, &sq.ds, &sq.t0].map(bits),
                    "set-up of {na:?} {nb:?} {h:?} n = {n}"
                );
                let len = n as usize + 1;
                // The generic run's value `sign(p)·√max(0, g)` from its own `g_i`, `p_i`.
                let mut g = vec![0.0 as $t; len];
                sq.shade(&mut g).unwrap();
                let mut p = sq.b;
                let value: Vec<$t> = g
                    .iter()
                    .map(|&g| {
                        let v = if g > 0.0 && p != 0.0 { g.sqrt().copysign(p) } else { 0.0 };
                        p += sq.a;
                        v
                    })
                    .collect();
                let mut first: Option<Vec<Vec<u64>>> = None;
                for path in Path::supported_paths() {
                    simd::force(path).unwrap();
                    let mut runs = Vec::new();
                    let mut got = vec![0.0 as $t; len];
                    fast.shade(&mut got);
                    if <$t>::EPSILON < 1e-10 {
                        for (i, (x, y)) in got.iter().zip(&value).enumerate() {
                            let (x, y) = (f64::from(*x), f64::from(*y));
                            assert!((x - y).abs() <= 1e-6, "value at pixel {i} on {path}, n = {n}: {x:e} against {y:e}");
                        }
                    }
                    runs.push(got);
                    for s in [0, 1, 2, 7, 32, 128] {
                        let (mut want, mut got) = (vec![0.0 as $t; len], vec![0.0 as $t; len]);
                        sq.specular(s, &mut want).unwrap();
                        fast.specular(s, &mut got);
                        if <$t>::EPSILON < 1e-10 {
                            for (i, (x, y)) in got.iter().zip(&want).enumerate() {
                                let (x, y) = (f64::from(*x), f64::from(*y));
                                let tol = 1e-9 * f64::from(s.max(1)) * (1.0 + y.abs());
                                assert!((x - y).abs() <= tol, "specular s = {s} at pixel {i} on {path}, n = {n}: {x:e} against {y:e}");
                            }
                        }
                        runs.push(got);
                    }
                    let runs: Vec<Vec<u64>> = runs.iter().map(|r| r.iter().map(|x| u64::from(x.to_bits())).collect()).collect();
                    match &first {
                        None => first = Some(runs),
                        Some(f0) => assert_eq!(f0, &runs, "the paths' bits differ, n = {n}"),
                    }
                    checked += 1;
                }
            }
        };
    }
    run!(f32);
    run!(f64);
    simd::force(chosen).unwrap();
    assert!(checked > 50, "{checked}");
}

/// The squared method's exact levels (`Method::exact_levels`, `exact_power_levels`)
/// are decided in rationals at every pixel (`method::Roots::SignedRootOfG`), not
/// within the root's 2^-256: with `K_d` chosen so that `K_d·v_i` lies within about
/// 2^-300 of a level boundary at an inner pixel, every level is decided and equals the
/// largest `ℓ` with `ℓ² ≤ 255²·K_d²·g_i` (`p_i > 0`), computed here from `g_i` of the
/// closed form (`sq_closed_form`) and `p_i = B + i·A`; the specular levels likewise
/// from `ℓ² ≤ 255²·g_i^s`.
#[test]
fn the_levels_are_decided_exactly_at_a_boundary() {
    use num_bigint::BigInt;
    use phong_approx::Method;
    let level = |x: &Q| -> u8 {
        // The largest ℓ ≤ 255 with ℓ² ≤ x (x = 255²·v², v ≥ 0).
        (0..=255u32)
            .rev()
            .find(|&l| Q::from_integer((l * l).into()) <= *x)
            .unwrap() as u8
    };
    let mut near = 0;
    for (na, nb, h, n) in inputs() {
        let Ok(span) = Span::new(na, nb, h, n) else {
            continue;
        };
        if n < 2 || near == tiered(12, 1000) {
            continue;
        }
        let sq = SquaredSpan::of(&span).unwrap();
        let g_at = |i: u32| {
            let i = q(i.into(), 1);
            &sq.g_a + &i * &sq.t0 + &i * (&i - Q::one()) / q(2, 1) * &sq.ds
        };
        let p_at = |i: u32| &sq.b + q(i.into(), 1) * &sq.a;
        let i = n / 2;
        let (g, p) = (g_at(i), p_at(i));
        if !(g.is_positive() && p.is_positive()) {
            continue;
        }
        // r ≈ √g within 2^-300, then K_d = 100/(255·r): K_d·√g_i = (100/255)(1 + δ).
        let scale = BigInt::from(1) << 300usize;
        let (num, den) = (g.numer().clone(), g.denom().clone());
        let r = Q::new((num * &den * &scale * &scale).sqrt(), den * &scale);
        let kd = q(100, 255) / r;
        let values = Method::SquaredCorrectedEuler.values(&span).unwrap();
        let got = Method::SquaredCorrectedEuler.exact_levels(&span, &values, &kd);
        let big = Q::from_integer((255 * 255).into());
        for (j, lv) in got.iter().enumerate() {
            let (g, p) = (g_at(j as u32), p_at(j as u32));
            let want = if g.is_positive() && p.is_positive() {
                level(&(&big * &kd * &kd * &g))
            } else {
                0
            };
            assert_eq!(*lv, Some(want), "pixel {j} of {span}");
        }
        for s in [1, 2, 7] {
            let spec = Method::SquaredCorrectedEuler.exact_power_levels(&span, &values, s);
            for (j, lv) in spec.iter().enumerate() {
                let (g, p) = (g_at(j as u32), p_at(j as u32));
                let want = if g.is_positive() && p.is_positive() {
                    level(&(&big * num_traits::Pow::pow(&g, s)))
                } else {
                    0
                };
                assert_eq!(*lv, Some(want), "s = {s}, pixel {j} of {span}");
            }
        }
        near += 1;
    }
    assert!(near >= 12, "{near}");
}

/// `sq_skip_sound` (proofs/Squared.v): where the skip test of the squared method
/// (`skip::specular_skips`, its quadratic `g`'s candidates compared as squares) says
/// skip, the specular term `255·K_s·max(0, v)^s = 255·K_s·g^{s/2}` (`p > 0`) is below
/// one level at every pixel and half-pixel, exactly: `(255·K_s)²·g(t)^s < 1`, with
/// `g(t)` from the closed form computed here. Both answers occur.
#[test]
fn sq_skip_sound() {
    use phong_approx::skip::specular_skips;
    use phong_approx::Method;
    let (mut skipped, mut shaded) = (0, 0);
    for (na, nb, h, n) in inputs() {
        let Ok(span) = Span::new(na, nb, h, n) else {
            continue;
        };
        let sq = SquaredSpan::of(&span).unwrap();
        let g = |t: &Q| &sq.g_a + t * &sq.t0 + t * (t - Q::one()) / q(2, 1) * &sq.ds;
        let p = |t: &Q| &sq.b + t * &sq.a;
        for ks in [Q::one(), q(1, 2), q(1, 10)] {
            for s in [1, 2, 8, 32, 128] {
                if !specular_skips(Method::SquaredCorrectedEuler, &span, &ks, s).unwrap() {
                    shaded += 1;
                    continue;
                }
                skipped += 1;
                let k2 = q(255, 1) * &ks * q(255, 1) * &ks;
                for j in 0..=2 * n {
                    let t = q(j.into(), 2);
                    let (gt, pt) = (g(&t), p(&t));
                    if gt.is_positive() && pt.is_positive() {
                        // A float filter far from 1 (its relative error is below
                        // 2^-40 here), else the exact comparison.
                        let f = (&k2 * Q::one()).to_f64() * gt.to_f64().powi(s as i32);
                        if f > 0.5 {
                            assert!(
                                &k2 * power(&gt, s) < Q::one(),
                                "t = {t}, K_s = {ks}, s = {s}: {span}"
                            );
                        }
                    }
                }
            }
        }
    }
    assert!(
        skipped > 10 && shaded > 10,
        "{skipped} skipped, {shaded} shaded"
    );
}
