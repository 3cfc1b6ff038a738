//! The squared method's graphs and its value's last step (`docs/float.md` §19.7): the
//! set-up of [`crate::squared_corrected_euler::SquaredSpan::new`] in its order (each
//! dot product in any order, `/n` either way), then `g_i` and `p_i` in one of three
//! ways ([`Walk`]): the recurrences `g += t; t += ds` from `g_a` and `p += A` from `B`
//! (`recurrence`, [`crate::squared_corrected_euler`]); or the fast kernel's
//! ([`crate::fast::FastSquared`]), `p_i = B + i·A` with `g_i` by the closed form
//! `g_a + i·(t_0 + (i − 1)·(ds/2))` (`closed`, its rows shorter than
//! [`crate::fast::STEPPED_FROM`]) or by the recurrence in [`crate::fast::LANES`] lanes
//! (`lanes`, its longer rows); the value `sign(p̃)·√max(0, g̃)` is composed from the graph's
//! bounds on `g_i` and `p_i` by `sq_signed_value_error` (`proofs/Squared.v`), not by
//! a node: its root may be of zero and its sign may flip.

use super::super::graph::{Bounds, Graph, Id, Model};
use super::{recurrence, Setup};

/// How an implementation walks `g_i` and `p_i` from the set-up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Walk {
    /// `g += t; t += ds` and `p += A`, pixel after pixel.
    Recurrence,
    /// `g_i = g_a + i·(t_0 + (i − 1)·(ds/2))`, `p_i = B + i·A`, each pixel on its own.
    Closed,
    /// `g` by the recurrence in [`crate::fast::LANES`] lanes (lane `j` from the closed
    /// form at `j`, stepping `L·(t_0 + ds·(j + (L − 1)/2))` then `L²·ds`, `L` the
    /// lanes), `p_i = B + i·A`.
    Lanes,
}

/// The closed form `g_a + x·(t_0 + (x − 1)·h)` at the exact index `x`, `h = ds/2`.
fn closed_at(g: &mut Graph, x: f64, g_a: Id, t0: Id, h: Id) -> Id {
    let c = g.cst(x - 1.0);
    let m = g.mul(c, h);
    let slope = g.add(t0, m);
    let xc = g.cst(x);
    let step = g.mul(xc, slope);
    g.add(g_a, step)
}

/// The pixels' `g_i` and `p_i` nodes of the squared method on `n` steps, walked as
/// `walk` says.
pub(super) fn squared(g: &mut Graph, s: &Setup, n: u32, walk: Walk) -> (Vec<Id>, Vec<Id>) {
    let two = g.cst(2.0);
    let q_b = g.dot(s.nb, s.nb);
    let bb = g.mul(s.b, s.b);
    let g_a = g.div(bb, s.e);
    let pp = g.mul(s.p_b, s.p_b);
    let g_b = g.div(pp, q_b);
    // g′ = p·(2A·q − p·q′)/q² at each end.
    let slope = |g: &mut Graph, p: Id, q: Id, dq: Id| {
        let two_a = g.mul(two, s.a);
        let two_aq = g.mul(two_a, q);
        let p_dq = g.mul(p, dq);
        let inner = g.sub(two_aq, p_dq);
        let num = g.mul(p, inner);
        let qq = g.mul(q, q);
        g.div(num, qq)
    };
    let dg_a = slope(g, s.b, s.e, s.d);
    let dg_b = slope(g, s.p_b, q_b, s.dq_b);
    let ddg = g.sub(dg_b, dg_a);
    let ds = g.div_either(ddg, s.n);
    let tri = g.cst((f64::from(n) * (f64::from(n) - 1.0) / 2.0).floor());
    let n_dga = g.mul(s.n, dg_a);
    let tri_ds = g.mul(tri, ds);
    let g_n = g.sum(&[g_a, n_dga, tri_ds]);
    let eps = g.sub(g_n, g_b);
    let d_eps = g.div_either(eps, s.n);
    let t0 = g.sub(dg_a, d_eps);
    if walk == Walk::Recurrence {
        let values = recurrence(g, n, g_a, t0, Some(ds));
        let signs = recurrence(g, n, s.b, s.a, None);
        return (values, signs);
    }
    let signs = (0..=n)
        .map(|i| {
            let ic = g.cst(f64::from(i));
            let step = g.mul(ic, s.a);
            g.add(s.b, step)
        })
        .collect();
    let h = g.half(ds);
    let values = if walk == Walk::Closed {
        (0..=n)
            .map(|i| closed_at(g, f64::from(i), g_a, t0, h))
            .collect()
    } else {
        let lanes = crate::fast::LANES as u32;
        let l = f64::from(lanes);
        let ll = g.cst(l * l);
        let dsl = g.mul(ll, ds);
        let lc = g.cst(l);
        let mut values = vec![g_a; n as usize + 1];
        for j in 0..lanes.min(n + 1) {
            let x = f64::from(j);
            let mut v = closed_at(g, x, g_a, t0, h);
            let c = g.cst(x + (l - 1.0) * 0.5);
            let m = g.mul(ds, c);
            let slope = g.add(t0, m);
            let mut t = g.mul(lc, slope);
            let mut i = j;
            loop {
                values[i as usize] = v;
                i += lanes;
                if i > n {
                    break;
                }
                v = g.add(v, t);
                t = g.add(t, dsl);
            }
        }
        values
    };
    (values, signs)
}

/// `κ` and `η` of the implementation's root `fl(√x)` against `√x` (`x ≥ 0` the
/// computed `max(0, g̃)`): `|fl(√x) − √x| ≤ k·√x + η`. One square root: `k = κ·u`. As
/// `1/inverseSqrt(x)` (the model's `sqrt_is_recip_rsqrt`): `inverseSqrt` within
/// `κ_r·u/√x + η`, `η·√x ≤ 3η` for `x ≤ 9`, then the division's `κ_d·u`, so
/// `k = (κ_d·u + κ_r·u + 3η)/(1 − κ_r·u − 3η)` (`sq_shader_root_rounding`,
/// docs/float.md §19.7); both with the last operation's `η`, and, where the model
/// flushes (`η > 0`), `√` of the format's smallest normal: a root whose operand below
/// it is read as 0 is off by at most that (the same theorem's other case).
fn root_rounding(model: &Model) -> (f64, f64) {
    let up = f64::next_up;
    let flushed = if model.eta > 0.0 {
        up(model.format.min_normal().sqrt())
    } else {
        0.0
    };
    let eta = up(model.eta + flushed);
    if model.sqrt_is_recip_rsqrt {
        let r = up(up(model.rsqrt * model.u) + up(3.0 * model.eta));
        let num = up(up(up(model.div * model.u) + r));
        (up(num / (1.0 - r).next_down()), eta)
    } else {
        (up(model.sqrt * model.u), eta)
    }
}

/// The bound on `|ṽ_i − v_i|` of the value `sign(p)·√max(0, g)` at a pixel whose
/// `g_i` and `p_i` nodes are `g` and `p` in `b`: `sq_signed_value_error` with
/// `R = min(√e, e/√g_lo)` (`sq_root_holder`, `sq_root_lipschitz`), `√max(0, g)`
/// at most `√max(0, g_hi)`, and the sign kept where `|p| > e_p` on the whole
/// interval; every step rounded up. `None` where the values `|g̃| ≤ 9` the root's
/// rounding assumes are not known.
pub(super) fn signed_root(b: &Bounds, g: Id, p: Id, model: &Model) -> Option<f64> {
    let up = f64::next_up;
    let (e, ep) = (b.err[g], b.err[p]);
    let (g_lo, g_hi) = (b.lo[g], b.hi[g]);
    if !(e.is_finite() && ep.is_finite()) || up(g_hi.max(0.0) + e) > 9.0 {
        return None;
    }
    let mut r = up(e.sqrt());
    if g_lo > 0.0 {
        let s = g_lo.sqrt().next_down();
        if s > 0.0 {
            r = r.min(up(e / s));
        }
    }
    let root = up(g_hi.max(0.0).sqrt());
    let (k, eta) = root_rounding(model);
    let kept = b.lo[p] > ep || b.hi[p] < -ep;
    let bound = if kept {
        up(up(r + up(k * up(root + r))) + eta)
    } else {
        up(up(up(up(1.0 + k) * up(root + r)) + root) + eta)
    };
    Some(bound)
}
