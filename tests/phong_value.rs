//! Phong under the κ model (docs/float.md §18.4), each test named like its theorem:
//! - the counts (`proofs/PhongCount.v`): `p̂` and `q̂` of Horner's closed form, the
//!   per-pixel normal and the lerp, dividing by `n` or through `1/n`, within the
//!   theorems' constants of the exact `p_i` and `q_i`; attacked by native `ieee` code
//!   in `f32` and `f64`, every dot-product order of [`super::Dot`], fused or not, on
//!   the Phong spans of `tests/profiles/` (nearly opposite normals included), the
//!   errors exact (rationals);
//! - the value step (`proofs/PhongValue.v`): from `p̂` and `q̂`
//! within `e_p` and `e_q` of `p` and `q`, the computed `p̂/√q̂` or `p̂·(1/√q̂)` is within
//! the theorems' bounds of `p/√q`, each operation anywhere its model allows.
//!
//! The attack is the model at its corners: `p̂ = p ± e_p`, `q̂ = q ± e_q`, and the
//! square root, the division (or the reciprocal and the product) each their exact
//! result times `1 ± κ·u`, plus or minus `η`, every combination of signs, on spans of
//! `q` down to `q_min = 10^-4` and `|p| = √q` (where the first step is tight). The
//! right-hand sides are the Coq statements', written here again. Evaluated in `f64`:
//! the values are at most about 100 and the bounds at least `10^-9`, so `f64`'s own
//! rounding (about `10^-14` here) is covered by a relative slack of `10^-9`; a bound
//! that the corners break by more fails.

/// `(κ_sqrt, κ_div, κ_mul)` of `ieee` and of `shader` (docs/float.md §18.1).
const MODELS: [(f64, f64, f64); 2] = [(1.0, 1.0, 1.0), (9.0 + 1.0 / 262_144.0, 5.0, 2.0)];

/// binary32's unit roundoff and a coarser one (the theorems hold for every `u`;
/// binary64's is too fine to attack in `f64` itself).
const US: [f64; 2] = [1.0 / 16_777_216.0, 1.0 / 65_536.0];

/// `η`: none, binary32's `64·4097` flushed results, and one large enough that the
/// theorems' absolute terms are seen.
const ETAS: [f64; 3] = [0.0, 64.0 * 4097.0 / 8.507_059_173_023_462e37, 1e-12];

const SLACK: f64 = 1e-9;

/// One attacked case: exact `p`, `q`, `q_min` and the error budgets `e_p`, `e_q`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Case {
    pub(super) p: f64,
    pub(super) q: f64,
    pub(super) q_min: f64,
    pub(super) ep: f64,
    pub(super) eq: f64,
}

/// Cases within every theorem's hypotheses: `q_min ≤ q`, `|p| ≤ min(1, √q)`,
/// `2·e_q ≤ q_min`.
fn cases(u: f64) -> Vec<Case> {
    let mut out = Vec::new();
    for q_min in [1e-4f64, 1e-2, 0.3, 1.0] {
        for q in [q_min, 2.0 * q_min, 1.0, 9.0] {
            if q < q_min {
                continue;
            }
            let top = q.sqrt().min(1.0);
            for p in [top, -top, 0.5 * top, 0.0] {
                for ep in [0.0, 3.0 * u, 300.0 * u] {
                    for eq in [0.0, 9.0 * u, 900.0 * u, q_min / 2.0] {
                        if 2.0 * eq > q_min {
                            continue;
                        }
                        out.push(Case {
                            p,
                            q,
                            q_min,
                            ep,
                            eq,
                        });
                    }
                }
            }
        }
    }
    out
}

/// `phong_value_real`'s right-hand side `B`.
fn b_real(c: &Case) -> f64 {
    let lo = (c.q_min - c.eq).sqrt();
    c.ep / lo + c.eq / (lo * (c.q_min.sqrt() + lo))
}

/// `γ_w = w·u/(1 − w·u)`.
fn gamma(w: f64, u: f64) -> f64 {
    w * u / (1.0 - w * u)
}

/// `phong_value_div`'s right-hand side, `w = κ_sqrt + κ_div`.
fn rhs_div(c: &Case, (ks, kd, _): (f64, f64, f64), u: f64, eta: f64) -> f64 {
    let b = b_real(c);
    let g = gamma(ks + kd, u);
    let eps = eta / (c.q_min - c.eq).sqrt();
    b * (1.0 + g) + g + (2.0 * (1.0 + b) * eps + eta)
}

/// `phong_value_recip`'s (and `phong_value_either`'s) right-hand side,
/// `w = κ_sqrt + κ_div + κ_mul`.
pub(super) fn rhs_recip(c: &Case, (ks, kd, km): (f64, f64, f64), u: f64, eta: f64) -> f64 {
    let b = b_real(c);
    let g = gamma(ks + kd + km, u);
    let eps = eta / (c.q_min - c.eq).sqrt();
    b * (1.0 + g) + g + (2.0 * (1.0 + b) * eps + ((1.0 + c.ep) * eta * (1.0 + km * u) + eta))
}

const SIGNS: [f64; 2] = [-1.0, 1.0];

/// Every corner of the inputs: `(p̂, q̂)`.
fn inputs(c: &Case) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for sp in SIGNS {
        for sq in SIGNS {
            out.push((c.p + sp * c.ep, c.q + sq * c.eq));
        }
    }
    out
}

/// An operation of the model at a corner: `x·(1 + s·k·u) + t·η`.
fn op(x: f64, k: f64, u: f64, eta: f64, s: f64, t: f64) -> f64 {
    x + s * k * u * x.abs() + t * eta
}

/// Every corner of `p̂/√q̂` in the model.
fn div_values(ph: f64, qh: f64, (ks, kd, _): (f64, f64, f64), u: f64, eta: f64) -> Vec<f64> {
    let mut out = Vec::new();
    for [s1, t1, s2, t2] in corners::<4>() {
        let s = op(qh.sqrt(), ks, u, eta, s1, t1);
        out.push(op(ph / s, kd, u, eta, s2, t2));
    }
    out
}

/// Every corner of `p̂·(1/√q̂)` in the model.
fn recip_values(ph: f64, qh: f64, (ks, kd, km): (f64, f64, f64), u: f64, eta: f64) -> Vec<f64> {
    let mut out = Vec::new();
    for [s1, t1, s2, t2, s3, t3] in corners::<6>() {
        let s = op(qh.sqrt(), ks, u, eta, s1, t1);
        let r = op(1.0 / s, kd, u, eta, s2, t2);
        out.push(op(ph * r, km, u, eta, s3, t3));
    }
    out
}

/// Every vector of `K` signs.
fn corners<const K: usize>() -> Vec<[f64; K]> {
    (0..1u32 << K)
        .map(|m| std::array::from_fn(|j| SIGNS[(m >> j & 1) as usize]))
        .collect()
}

/// The largest `|v̂ − p/√q|` over the corners, divided by `bound`, over every case,
/// model, format and `η`; panics on a case above `1 + SLACK`.
fn attack(
    what: &str,
    values: impl Fn(f64, f64, (f64, f64, f64), f64, f64) -> Vec<f64>,
    bound: impl Fn(&Case, (f64, f64, f64), f64, f64) -> f64,
) -> f64 {
    let mut worst = 0.0f64;
    for model in MODELS {
        for u in US {
            for eta in ETAS {
                for c in cases(u) {
                    let lo = (c.q_min - c.eq).sqrt();
                    assert!((model.0 + model.1 + model.2) * u <= 1.0 / 1024.0);
                    assert!(1024.0 * eta <= lo);
                    let want = c.p / c.q.sqrt();
                    let b = bound(&c, model, u, eta);
                    for (ph, qh) in inputs(&c) {
                        for v in values(ph, qh, model, u, eta) {
                            let err = (v - want).abs();
                            assert!(
                                err <= b * (1.0 + SLACK),
                                "{what}: {c:?}, model {model:?}, u {u:e}, η {eta:e}: \
                                 p̂ {ph:e}, q̂ {qh:e}, v̂ {v:e}: error {err:e} > bound {b:e}"
                            );
                            worst = worst.max(err / b);
                        }
                    }
                }
            }
        }
    }
    worst
}

#[test]
fn phong_value_real() {
    let worst = attack(
        "phong_value_real",
        |ph, qh, _, _, _| vec![ph / qh.sqrt()],
        |c, _, _, _| b_real(c),
    );
    // At |p| = √q = √q_min, p̂ = p + e_p, q̂ = q − e_q the bound is reached.
    assert!(worst >= 0.999, "the corners reach {worst} of the bound");
}

#[test]
fn phong_value_div() {
    let worst = attack("phong_value_div", div_values, rhs_div);
    assert!(worst >= 0.9, "the corners reach {worst} of the bound");
}

#[test]
fn phong_value_recip() {
    let worst = attack("phong_value_recip", recip_values, rhs_recip);
    assert!(worst >= 0.9, "the corners reach {worst} of the bound");
}

/// Either form under the reciprocal form's bound, which is the larger.
#[test]
fn phong_value_either() {
    let both = |ph, qh, m, u, eta| {
        let mut v = div_values(ph, qh, m, u, eta);
        v.extend(recip_values(ph, qh, m, u, eta));
        v
    };
    let worst = attack("phong_value_either", both, rhs_recip);
    assert!(worst >= 0.9, "the corners reach {worst} of the bound");
    for model in MODELS {
        for c in cases(US[0]) {
            assert!(rhs_div(&c, model, US[0], ETAS[2]) <= rhs_recip(&c, model, US[0], ETAS[2]));
        }
    }
}

// ------------------------------------------------------------------ the counts

use super::{dot, phong_spans, tiered, Dot, Native, Q};
use num_traits::Signed;
use num_traits::Zero;
use phong_approx::Format;
use phong_approx::Scalar;
use phong_approx::Span;

/// The forms of `proofs/PhongCount.v`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Form {
    /// `horner_ok`: `p̂ = A·i + B`, `q̂ = (C·i + D)·i + E`.
    Horner,
    /// `pixel_ok`: `N = N_a + i·k`, `p̂ = N·L`, `q̂ = N·N`.
    Pixel,
    /// `lerp_ok`: `t = i/n`, `N = (1 − t)·N_a + t·N_b`, `p̂ = N·L`, `q̂ = N·N`.
    Lerp,
}

/// The theorems' constants `(α_p, β_p, α_q, β_q)`: `|p̂ − p_i| ≤ (α_p·K1 + β_p·kd)·u`,
/// `|q̂ − q_i| ≤ (α_q·K1 + β_q·kd)·u` (written from the statements of
/// `proofs/PhongCount.v`).
fn constants(form: Form) -> (f64, f64, f64, f64) {
    match form {
        Form::Horner => (20.03, 2.02, 78.11, 12.04),
        Form::Pixel | Form::Lerp => (14.04, 2.04, 23.06, 4.06),
    }
}

/// `proofs/PhongCountD.v`'s bounds at `d ≥ |N_b − N_a|` (written from the
/// statements): `(p's K1 factor, p's kd factor, q's K1 factor, q's kd factor)`.
fn dist_constants(form: Form, d: f64) -> (f64, f64, f64, f64) {
    match form {
        Form::Horner => (
            8.04 + 6.01 * d,
            0.03 + 1.01 * d,
            10.13 + 18.03 * d + 8.01 * d * d,
            0.07 + 2.02 * d + 2.01 * d * d,
        ),
        Form::Pixel => (
            6.02 + 2.01 * d,
            0.02 + 1.01 * d,
            7.02 + 4.01 * d,
            0.02 + 2.01 * d,
        ),
        Form::Lerp => (8.02, 0.02 + 1.01 * d, 11.02, 0.02 + 2.01 * d),
    }
}

/// `|N_b − N_a|` of an exact span, rounded up (computed here, not by the library).
fn distance(s: &Span<Q>) -> f64 {
    let d2 = [
        s.nb.x.clone() - s.na.x.clone(),
        s.nb.y.clone() - s.na.y.clone(),
        s.nb.z.clone() - s.na.z.clone(),
    ]
    .iter()
    .map(|c| c.clone() * c.clone())
    .fold(Q::from_integer(0.into()), |a, b| a + b);
    ((d2.to_f64() * (1.0 + 1e-15)).sqrt() * (1.0 + 1e-15)).min(2.0)
}

/// `p̂_i` and `q̂_i` of `form` in `T` (also `phong`'s in `tests/profiles/`), the dot products summed as `how`, the products
/// that feed an addition fused or not, `/n` as a division or `·(1/n)`.
pub(super) fn pq<T: Native>(
    form: Form,
    how: Dot,
    fused: bool,
    recip: bool,
    s: &Span<Q>,
) -> Vec<(T, T)> {
    let vec = |x: &phong_approx::Vec3<Q>| [T::of(&x.x), T::of(&x.y), T::of(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let nf = T::from_u32(s.n);
    let one = T::from_u32(1);
    let inv = one.div(nf);
    let over_n = |x: T| if recip { x.mul(inv) } else { x.div(nf) };
    let axpy = |a: T, x: T, y: T| if fused { a.fma(x, y) } else { a.mul(x) + y };
    let k = [0, 1, 2].map(|j| over_n(nb[j] - na[j]));
    let (a, b) = (dot(how, k, l), dot(how, na, l));
    let (c, d, e) = (
        dot(how, k, k),
        T::from_u32(2).mul(dot(how, k, na)),
        dot(how, na, na),
    );
    (0..=s.n)
        .map(|i| {
            let fi = T::from_u32(i);
            match form {
                Form::Horner => (axpy(a, fi, b), axpy(axpy(c, fi, d), fi, e)),
                Form::Pixel | Form::Lerp => {
                    let nn = normal(form, fused, recip, s, i);
                    (dot(how, nn, l), dot(how, nn, nn))
                }
            }
        })
        .collect()
}

/// The computed normal of pixel `i` of the per-pixel form (`N_a + i·k`) or the lerp
/// (`(1 − t)·N_a + t·N_b`) in `T`, as [`pq`] computes it.
pub(super) fn normal<T: Native>(
    form: Form,
    fused: bool,
    recip: bool,
    s: &Span<Q>,
    i: u32,
) -> [T; 3] {
    let vec = |x: &phong_approx::Vec3<Q>| [T::of(&x.x), T::of(&x.y), T::of(&x.z)];
    let (na, nb) = (vec(&s.na), vec(&s.nb));
    let nf = T::from_u32(s.n);
    let one = T::from_u32(1);
    let inv = one.div(nf);
    let over_n = |x: T| if recip { x.mul(inv) } else { x.div(nf) };
    let axpy = |a: T, x: T, y: T| if fused { a.fma(x, y) } else { a.mul(x) + y };
    let fi = T::from_u32(i);
    match form {
        Form::Lerp => {
            let t = over_n(fi);
            [0, 1, 2].map(|j| axpy(t, nb[j], (one - t).mul(na[j])))
        }
        _ => [0, 1, 2].map(|j| axpy(fi, over_n(nb[j] - na[j]), na[j])),
    }
}

/// Every variant of `form` in `f32` and `f64` within the theorem's constants under
/// `ieee` (`K1 = 1`; `kd = 1` for one division, `(1 + 2^-20) + 1 + 2^-36` through
/// `1/n`), at every pixel of every Phong span; returns the largest fraction of a
/// bound reached.
fn counts(theorem: &str, form: Form, recip: bool) -> f64 {
    counts_with(theorem, form, recip, tiered(64, 1024), |_| constants(form))
}

/// [`counts`] against the constants `of` a span gives.
fn counts_with(
    theorem: &str,
    form: Form,
    recip: bool,
    max_n: u32,
    of: impl Fn(&Span<Q>) -> (f64, f64, f64, f64),
) -> f64 {
    let kd = if recip {
        1.0 + 2f64.powi(-20) + 1.0 + 2f64.powi(-36)
    } else {
        1.0
    };
    let mut worst = 0.0f64;
    let mut checked = 0usize;
    // The spans up to n = 64 (1024 in the extensive tier): every pixel is checked
    // exactly, in 12 variants.
    for s in phong_spans().into_iter().filter(|s| s.n <= max_n) {
        let (ap, bp, aq, bq) = of(&s);
        let exact: Vec<(Q, Q)> = (0..=s.n).map(|i| (s.p_at(i), s.q_at(i))).collect();
        let mut judge = |got: Vec<(Q, Q)>, u: f64, what: String| {
            let (bound_p, bound_q) = ((ap + bp * kd) * u, (aq + bq * kd) * u);
            for (i, ((gp, gq), (p, q))) in got.into_iter().zip(&exact).enumerate() {
                let ep = (gp - p).abs().to_f64();
                let eq = (gq - q).abs().to_f64();
                assert!(
                    ep <= bound_p && eq <= bound_q,
                    "{theorem} {what}: pixel {i} of n = {}: |p̂ − p| = {:.3}u (bound {:.3}u), \
                     |q̂ − q| = {:.3}u (bound {:.3}u)",
                    s.n,
                    ep / u,
                    bound_p / u,
                    eq / u,
                    bound_q / u
                );
                worst = worst.max(ep / bound_p).max(eq / bound_q);
                checked += 1;
            }
        };
        for how in [Dot::Reversed, Dot::Fused, Dot::RightFirst] {
            for fused in [false, true] {
                let what = format!("{how:?}, fused {fused}");
                let to_q =
                    |v: Vec<(f32, f32)>| v.into_iter().map(|(p, q)| (p.q(), q.q())).collect();
                judge(
                    to_q(pq::<f32>(form, how, fused, recip, &s)),
                    f32::U,
                    format!("f32 {what}"),
                );
                let to_q =
                    |v: Vec<(f64, f64)>| v.into_iter().map(|(p, q)| (p.q(), q.q())).collect();
                judge(
                    to_q(pq::<f64>(form, how, fused, recip, &s)),
                    f64::U,
                    format!("f64 {what}"),
                );
            }
        }
    }
    assert!(checked > 10_000, "{checked}");
    eprintln!("{theorem}: {checked} pixels, worst {worst:.3} of the bounds");
    worst
}

#[test]
fn phong_horner_div_generic() {
    counts("phong_horner_div_generic", Form::Horner, false);
}

#[test]
fn phong_horner_recip_generic() {
    counts("phong_horner_recip_generic", Form::Horner, true);
}

#[test]
fn phong_pixel_div_generic() {
    counts("phong_pixel_div_generic", Form::Pixel, false);
}

#[test]
fn phong_pixel_recip_generic() {
    counts("phong_pixel_recip_generic", Form::Pixel, true);
}

#[test]
fn phong_lerp_div_generic() {
    counts("phong_lerp_div_generic", Form::Lerp, false);
}

#[test]
fn phong_lerp_recip_generic() {
    counts("phong_lerp_recip_generic", Form::Lerp, true);
}

/// [`counts`] against `proofs/PhongCountD.v`'s bound at the span's own
/// `|N_b − N_a|`; returns the largest fraction reached.
fn counts_dist(theorem: &str, form: Form, recip: bool) -> f64 {
    // The same pixels as `counts` in the default tier; up to n = 256 in the extensive
    // tier (the `_generic` tests take the longer spans).
    counts_with(theorem, form, recip, tiered(64, 256), |s| {
        dist_constants(form, distance(s))
    })
}

#[test]
fn phong_horner_div_dist() {
    counts_dist("phong_horner_div_dist", Form::Horner, false);
}

#[test]
fn phong_horner_recip_dist() {
    counts_dist("phong_horner_recip_dist", Form::Horner, true);
}

#[test]
fn phong_pixel_div_dist() {
    counts_dist("phong_pixel_div_dist", Form::Pixel, false);
}

#[test]
fn phong_pixel_recip_dist() {
    counts_dist("phong_pixel_recip_dist", Form::Pixel, true);
}

#[test]
fn phong_lerp_div_dist() {
    counts_dist("phong_lerp_div_dist", Form::Lerp, false);
}

#[test]
fn phong_lerp_recip_dist() {
    counts_dist("phong_lerp_recip_dist", Form::Lerp, true);
}

/// The bound `check` applies to Phong under `ieee` and `shader`
/// (`tolerance::profile::phong_bound`) is the composition of the theorems, written
/// out here from their statements: for each form of `proofs/PhongCount.v` the
/// smaller of its count and `proofs/PhongCountD.v`'s at `d`, the larger over the
/// forms, the larger `kd` of the two ways of `/n`, then `phong_value_either` and
/// normalize-then-dot's term (`proofs/PhongNormalize.v`) — at
/// every `n`, `q_min` and `d` sampled, equal to a relative `10^-9` (so neither looser
/// than the theorems nor below them).
#[test]
fn the_applied_phong_bounds_are_the_composed_theorems() {
    use phong_approx::tolerance::profile::{arith, phong_bound, Profile};
    use phong_approx::Format;
    let mut compared = 0;
    for (profile, format, k1, (ks, kd, km)) in [
        (Profile::Ieee, Format::Binary32, 1.0, (1.0, 1.0, 1.0)),
        (Profile::Ieee, Format::Binary64, 1.0, (1.0, 1.0, 1.0)),
        (
            Profile::Shader,
            Format::Binary32,
            2.0,
            (9.0 + 1.0 / 262_144.0, 5.0, 2.0),
        ),
    ] {
        let a = arith(profile, format).unwrap();
        let u = format.u();
        // kd of the reciprocal forms, the larger.
        let kdn = kd + (1.0 + 2f64.powi(-20)) * km + 2f64.powi(-36);
        for d in [0.0, 1e-6, 0.01, 0.3, 1.0, 1.7, 2.0] {
            let (ep, eq) = [Form::Horner, Form::Pixel, Form::Lerp].iter().fold(
                (0f64, 0f64),
                |(ep, eq), &form| {
                    let (ap, bp, aq, bq) = constants(form);
                    let (dp, dpk, dq, dqk) = dist_constants(form, d);
                    let p = ((ap * k1 + bp * kdn).min(dp * k1 + dpk * kdn)) * u;
                    let q = ((aq * k1 + bq * kdn).min(dq * k1 + dqk * kdn)) * u;
                    (ep.max(p), eq.max(q))
                },
            );
            for n in [1, 2, 7, 64, 255, 1024, 4096] {
                for q_min in [1e-3, 0.01, 0.1, 0.5, 1.0] {
                    let applied = phong_bound(&a, n, q_min, d);
                    if 2.0 * eq > q_min {
                        assert!(applied.is_none(), "{profile:?} {format:?} d = {d}");
                        continue;
                    }
                    let c = Case {
                        p: 1.0,
                        q: q_min,
                        q_min,
                        ep,
                        eq,
                    };
                    // `phong_normalize_dot_unit`: normalize-then-dot adds its term to
                    // `phong_value_recip`'s (κ_in = κ_add = κ_mul = k1 here).
                    let (eta, lam) = (a.eta, 1.0 + k1 * u + 2.0 * a.eta);
                    let normalize =
                        1.03 * lam * (k1 * u + k1 * u + 2.0 * k1 * u) + 2.0 * lam * eta + 8.0 * eta;
                    let theorem = rhs_recip(&c, (ks, kd, km), u, eta) + normalize;
                    let applied = applied.unwrap();
                    assert!(
                        applied >= theorem && applied <= theorem * (1.0 + 1e-9),
                        "{profile:?} {format:?} n = {n}, q_min = {q_min}, d = {d}: applied {applied:e}, theorem {theorem:e}"
                    );
                    compared += 1;
                }
            }
        }
    }
    assert!(compared > 600, "{compared}");
}

/// The variants of the per-pixel normal and the lerp: `(form, fused, recip)`.
fn normal_variants() -> Vec<(Form, bool, bool)> {
    let mut out = Vec::new();
    for form in [Form::Pixel, Form::Lerp] {
        for fused in [false, true] {
            for recip in [false, true] {
                out.push((form, fused, recip));
            }
        }
    }
    out
}

/// `pixel_ok_exact_dot` and `lerp_ok_exact_dot` (`proofs/PhongNormalize.v`): the
/// forms' `p̂` may be the *exact* dot product of the computed normal with `L̂`, so
/// their count bounds hold for it — checked here exactly (rationals) on every pixel
/// of the Phong spans, `f32` and `f64`, against `proofs/PhongCount.v`'s constants.
fn exact_dot(theorem: &str, form: Form) {
    let mut checked = 0;
    for s in phong_spans().into_iter().filter(|s| s.n <= tiered(64, 256)) {
        for (f, fused, recip) in normal_variants().into_iter().filter(|v| v.0 == form) {
            let (ap, bp, _, _) = constants(f);
            let kd = if recip {
                2.0 + 2f64.powi(-20) + 2f64.powi(-36)
            } else {
                1.0
            };
            for (u, l, nn) in [
                (
                    f32::U,
                    [s.l.x.clone(), s.l.y.clone(), s.l.z.clone()].map(|x| f32::of(&x).q()),
                    (0..=s.n)
                        .map(|i| normal::<f32>(f, fused, recip, &s, i).map(|x| x.q()))
                        .collect::<Vec<_>>(),
                ),
                (
                    f64::U,
                    [s.l.x.clone(), s.l.y.clone(), s.l.z.clone()].map(|x| f64::of(&x).q()),
                    (0..=s.n)
                        .map(|i| normal::<f64>(f, fused, recip, &s, i).map(|x| x.q()))
                        .collect(),
                ),
            ] {
                for (i, n) in nn.iter().enumerate() {
                    let exact = n[0].clone() * l[0].clone()
                        + n[1].clone() * l[1].clone()
                        + n[2].clone() * l[2].clone();
                    let e = (exact - s.p_at(i as u32)).abs().to_f64();
                    let b = (ap + bp * kd) * u;
                    assert!(e <= b, "{theorem} {f:?} fused {fused} recip {recip}: pixel {i} of n = {}: {:.3}u > {:.3}u", s.n, e / u, b / u);
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 5_000, "{checked}");
}

#[test]
fn pixel_ok_exact_dot() {
    exact_dot("pixel_ok_exact_dot", Form::Pixel);
}

#[test]
fn lerp_ok_exact_dot() {
    exact_dot("lerp_ok_exact_dot", Form::Lerp);
}

/// `phong_normalize_dot` (`unit = false`: `λ = |L̂|`, computed here) and
/// `phong_normalize_dot_unit` (`λ = 1 + κ_in·u + 2η`): normalize-then-dot —
/// `q̂ = N̂·N̂`, `r = 1/√q̂`, `w = N̂·r`, `v̂ = w·L̂` — of the per-pixel normal and the
/// lerp, native `ieee` code in `f32` and `f64`, every dot order, fused or not, `/n`
/// either way, within `phong_value_recip`'s bound (`e_p`, `e_q` the forms' counts)
/// plus `1.03·λ·(κ_mul·u + κ_mul·u + 2κ_add·u) + 2λη + 8η`, every pixel of the Phong
/// spans against the exact `p_i/√q_i`. Returns the largest fraction reached.
fn normalize_dot(theorem: &str, unit: bool, max_n: u32) -> f64 {
    let mut worst = 0f64;
    let mut checked = 0;
    // Each pixel takes an exact square root: short spans.
    for s in phong_spans().into_iter().filter(|s| s.n <= max_n) {
        let want = super::phong_exact(&s);
        let q_min = (0..=s.n).map(|i| s.q_at(i)).min().unwrap().to_f64() * (1.0 - 1e-12);
        for (form, fused, recip) in normal_variants() {
            for how in [Dot::Reversed, Dot::Fused, Dot::RightFirst] {
                let mut judge = |got: Vec<Q>, u: f64, eta: f64, lam_l: f64| {
                    let (ap, bp, aq, bq) = constants(form);
                    let kd = if recip {
                        2.0 + 2f64.powi(-20) + 2f64.powi(-36)
                    } else {
                        1.0
                    };
                    let (ep, eq) = ((ap + bp * kd) * u, (aq + bq * kd) * u);
                    let lam = if unit { 1.0 + u + 2.0 * eta } else { lam_l };
                    let extra = 1.03 * lam * (4.0 * u) + 2.0 * lam * eta + 8.0 * eta;
                    for (i, (g, w)) in got.into_iter().zip(&want).enumerate() {
                        if 2.0 * eq > q_min {
                            return;
                        }
                        let c = Case {
                            p: s.p_at(i as u32).to_f64(),
                            q: s.q_at(i as u32).to_f64(),
                            q_min,
                            ep,
                            eq,
                        };
                        let b = rhs_recip(&c, (1.0, 1.0, 1.0), u, eta) + extra;
                        let e = (g - w.clone()).abs().to_f64();
                        assert!(
                            e <= b,
                            "{theorem} {form:?} {how:?} fused {fused} recip {recip}: pixel {i} of n = {}: {e:e} > {b:e}",
                            s.n
                        );
                        worst = worst.max(e / b);
                        checked += 1;
                    }
                };
                fn run<T: Native>(
                    s: &Span<Q>,
                    form: Form,
                    how: Dot,
                    fused: bool,
                    recip: bool,
                ) -> (Vec<Q>, f64) {
                    let l = [s.l.x.clone(), s.l.y.clone(), s.l.z.clone()].map(|x| T::of(&x));
                    let one = T::from_u32(1);
                    let v = (0..=s.n)
                        .map(|i| {
                            let nn = normal::<T>(form, fused, recip, s, i);
                            let r = one.div(dot(how, nn, nn).sqrt());
                            dot(how, nn.map(|x| x.mul(r)), l).q()
                        })
                        .collect();
                    // |L̂| rounded up.
                    let l2 = l
                        .iter()
                        .map(|x| x.q() * x.q())
                        .fold(Q::zero(), |a, b| a + b);
                    (v, (l2.to_f64() * (1.0 + 1e-15)).sqrt() * (1.0 + 1e-15))
                }
                let (v, lam) = run::<f32>(&s, form, how, fused, recip);
                judge(v, f32::U, Format::Binary32.eta(), lam);
                let (v, lam) = run::<f64>(&s, form, how, fused, recip);
                judge(v, f64::U, Format::Binary64.eta(), lam);
            }
        }
    }
    assert!(checked > 2_000, "{checked}");
    eprintln!("{theorem}: {checked} pixels, worst {worst:.3} of the bound");
    worst
}

#[test]
fn phong_normalize_dot() {
    normalize_dot("phong_normalize_dot", false, tiered(8, 64));
}

#[test]
fn phong_normalize_dot_unit() {
    normalize_dot("phong_normalize_dot_unit", true, tiered(16, 64));
}
