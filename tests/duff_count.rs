//! The theorems of `proofs/DuffCount.v` — the computed `p` and `q` of Duff's forward
//! differences (eqs. 5–7) and of symmetric Phong (§4) in the κ model — attacked by
//! native `ieee` code: the paper's set-up with every dot order of this binary, fused
//! or not, `/n` as a division or through `1/n`, then Duff's walk, in `f32` and `f64`,
//! on the Phong spans; each pixel's error exact (rationals). One test per theorem,
//! named like it; and the bounds `check` applies, composed from them with
//! `phong_value_either`, checked against the composition written out here.

use super::phong_value::{rhs_recip, Case};
use super::{dot, phong_spans, tiered, Dot, Native, Q};
use num_traits::Signed;
use phong_approx::tolerance::profile::{
    arith, duff_bound, symmetric_phong_bound, Profile, DUFF_COUNTS,
};
use phong_approx::{Format, Scalar, Span};

/// The statements' constants, written from `proofs/DuffCount.v` (not read from the
/// library, whose table `tests/claims_index.rs` compares with the statements):
/// `|p̂_i − p_i| ≤ (17.02·K1 + 2.02·kd + 1.001·i·κ_add)·u`,
/// `|q̂_i − q_i| ≤ (65.05·K1 + 12.04·kd + 3.004·i·κ_add)·u`.
const P: (f64, f64, f64) = (17.02, 2.02, 1.001);
const Q_: (f64, f64, f64) = (65.05, 12.04, 3.004);

/// Duff's walk in `T` from the paper's set-up (`A = k·L`, `B = N_a·L`, `C = k·k`,
/// `D = 2(k·N_a)`, `E = N_a·N_a`, `k = (N_b − N_a)/n` or `·(1/n)`), the dot products
/// summed as `how`: `p_{j+1} = p_j + A`, `q_{j+1} = q_j + dq_j`, `dq_{j+1} = dq_j + d²q`
/// from `dq_0 = C + D`, `d²q = C + C` (`two_c`: `2·C`, the same value in IEEE).
fn walk<T: Native>(how: Dot, recip: bool, two_c: bool, s: &Span<Q>) -> Vec<(T, T)> {
    let vec = |x: &phong_approx::Vec3<Q>| [T::of(&x.x), T::of(&x.y), T::of(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let nf = T::from_u32(s.n);
    let inv = T::from_u32(1).div(nf);
    let k = [0, 1, 2].map(|j| {
        let d = nb[j] - na[j];
        if recip {
            d.mul(inv)
        } else {
            d.div(nf)
        }
    });
    let (a, b) = (dot(how, k, l), dot(how, na, l));
    let c = dot(how, k, k);
    let d = T::from_u32(2).mul(dot(how, k, na));
    let e = dot(how, na, na);
    let d2q = if two_c { T::from_u32(2).mul(c) } else { c + c };
    let (mut p, mut q, mut dq) = (b, e, c + d);
    let mut out = Vec::with_capacity(s.n as usize + 1);
    for _ in 0..=s.n {
        out.push((p, q));
        p = p + a;
        q = q + dq;
        dq = dq + d2q;
    }
    out
}

/// Every variant in `f32` and `f64` within the theorem's constants under `ieee`
/// (`K1 = κ_add = 1`; `kd = 1` for one division, `(1 + 2^-20) + 1 + 2^-36` through
/// `1/n`), at every pixel of every Phong span: Duff's (`p` and `q` after `i` steps) or,
/// `symmetric`, symmetric Phong's (`q` walked `j = min(i, n − i)` steps against
/// `q_i`, equal to `q_j` on these unit normals). Returns the largest fraction reached.
fn counts(theorem: &str, recip: bool, symmetric: bool) -> f64 {
    let kd = if recip {
        1.0 + 2f64.powi(-20) + 1.0 + 2f64.powi(-36)
    } else {
        1.0
    };
    let bound =
        |(x, y, z): (f64, f64, f64), steps: u32, u: f64| (x + y * kd + z * f64::from(steps)) * u;
    let mut worst = 0.0f64;
    let mut checked = 0usize;
    for s in phong_spans()
        .into_iter()
        .filter(|s| s.n <= tiered(64, 1024))
    {
        let n = s.n;
        // The exact values once per span (every variant is judged against them).
        let exact: Vec<(Q, Q)> = (0..=n).map(|i| (s.p_at(i), s.q_at(i))).collect();
        for i in 0..=n as usize {
            assert_eq!(
                exact[i].1,
                exact[n as usize - i].1,
                "q is symmetric on unit normals"
            );
        }
        let mut judge = |got: Vec<(Q, Q)>, u: f64, what: String| {
            for i in 0..=n {
                let j = if symmetric { i.min(n - i) } else { i };
                let (p, q) = &exact[i as usize];
                let (gp, _) = &got[i as usize];
                let (_, gq) = &got[j as usize];
                let ep = (gp - p).abs().to_f64();
                let eq = (gq - q).abs().to_f64();
                let (bp, bq) = (bound(P, i, u), bound(Q_, j, u));
                assert!(
                    ep <= bp && eq <= bq,
                    "{theorem} {what}: pixel {i} of n = {n}: |p̂ − p| = {:.3}u (bound {:.3}u), \
                     |q̂ − q| = {:.3}u (bound {:.3}u)",
                    ep / u,
                    bp / u,
                    eq / u,
                    bq / u
                );
                worst = worst.max(ep / bp).max(eq / bq);
                checked += 1;
            }
        };
        for how in [Dot::Reversed, Dot::Fused, Dot::RightFirst] {
            for two_c in [false, true] {
                let what = format!("{how:?}, 2C as a product {two_c}");
                let v32 = walk::<f32>(how, recip, two_c, &s);
                judge(
                    v32.into_iter().map(|(p, q)| (p.q(), q.q())).collect(),
                    f32::U,
                    format!("f32 {what}"),
                );
                let v64 = walk::<f64>(how, recip, two_c, &s);
                judge(
                    v64.into_iter().map(|(p, q)| (p.q(), q.q())).collect(),
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
fn duff_div_generic() {
    counts("duff_div_generic", false, false);
}

#[test]
fn duff_recip_generic() {
    counts("duff_recip_generic", true, false);
}

#[test]
fn symmetric_phong_div_generic() {
    counts("symmetric_phong_div_generic", false, true);
}

#[test]
fn symmetric_phong_recip_generic() {
    counts("symmetric_phong_recip_generic", true, true);
}

/// A count model `(K1, κ_add, κ_div, κ_mul)`.
type Counts = (f64, f64, f64, f64);
/// The value step's `(κ_sqrt, κ_div, κ_mul)`.
type Value = (f64, f64, f64);

/// The models of the profiles as the theorems take them.
const MODELS: [(Profile, Format, Counts, Value); 3] = [
    (
        Profile::Ieee,
        Format::Binary32,
        (1.0, 1.0, 1.0, 1.0),
        (1.0, 1.0, 1.0),
    ),
    (
        Profile::Ieee,
        Format::Binary64,
        (1.0, 1.0, 1.0, 1.0),
        (1.0, 1.0, 1.0),
    ),
    (
        Profile::Shader,
        Format::Binary32,
        (2.0, 2.0, 5.0, 2.0),
        (9.0 + 1.0 / 262_144.0, 5.0, 2.0),
    ),
];

/// The theorems composed at pixel `i` (`p` walked `i` steps, `q` walked `j`): the
/// counts with the larger `kd` of the two ways of `/n`, then `phong_value_either`'s
/// right-hand side (written out in `tests/phong_value.rs`), at `|p| = √q = √q_min`.
fn composed(
    (k1, add, div, mul): Counts,
    value: Value,
    u: f64,
    eta: f64,
    (i, j): (u32, u32),
    q_min: f64,
) -> Option<f64> {
    let kd = div.max((1.0 + 2f64.powi(-20)) * mul + div + 2f64.powi(-36));
    let e =
        |(x, y, z): (f64, f64, f64), steps: u32| (x * k1 + y * kd + z * f64::from(steps) * add) * u;
    let (ep, eq) = (e(P, i), e(Q_, j));
    (2.0 * eq <= q_min).then(|| {
        rhs_recip(
            &Case {
                p: q_min.sqrt(),
                q: q_min,
                q_min,
                ep,
                eq,
            },
            value,
            u,
            eta,
        )
    })
}

/// The bounds `check` applies to Duff and symmetric Phong under `ieee` and `shader`
/// are at least the theorems composed at every pixel — for symmetric Phong each pixel
/// `i` with its own walks `i` and `min(i, n − i)`, so the eight pieces of
/// `symmetric_phong_bound` are checked against every pixel — and the library's
/// constants are the ones written here.
#[test]
fn the_applied_duff_bounds_are_the_composed_theorems() {
    assert_eq!((DUFF_COUNTS.p, DUFF_COUNTS.q), (P, Q_));
    for (profile, format, model, value) in MODELS {
        let a = arith(profile, format).unwrap();
        let u = format.u();
        for n in [1u32, 2, 3, 7, 8, 64, 255, 1024, 4095, 4096] {
            for q_min in [1e-3, 0.01, 0.1, 0.5, 1.0] {
                let theorem = |i: u32, j: u32| composed(model, value, u, a.eta, (i, j), q_min);
                let duff = duff_bound(&a, n, q_min);
                match (duff, theorem(n, n)) {
                    (Some(applied), Some(t)) => assert!(
                        applied >= t,
                        "duff {profile:?} {format:?} n = {n}, q_min = {q_min}: {applied:e} < {t:e}"
                    ),
                    (None, None) => {}
                    (d, t) => panic!("duff {profile:?} {format:?} n = {n}: {d:?} against {t:?}"),
                }
                let sym = symmetric_phong_bound(&a, n, q_min);
                let mut worst = Some(0.0f64);
                for i in 0..=n {
                    worst = match (worst, theorem(i, i.min(n - i))) {
                        (Some(w), Some(t)) => Some(w.max(t)),
                        _ => None,
                    };
                }
                match (sym, worst) {
                    (Some(applied), Some(w)) => assert!(
                        applied >= w,
                        "symmetric {profile:?} {format:?} n = {n}, q_min = {q_min}: {applied:e} < {w:e}"
                    ),
                    (None, None) => {}
                    // No bound only where some pixel's composition has none.
                    (b, w) => panic!("symmetric {profile:?} {format:?} n = {n}: {b:?} against {w:?}"),
                }
            }
        }
    }
}
