//! The squared method's graph and its value's last step (`docs/float.md` §19.7): the
//! set-up of [`crate::squared_corrected_euler::SquaredSpan::new`] in its order (each
//! dot product in any order, `/n` either way), `g += t; t += ds` from `g_a`, and
//! `p += A` from `B`; the value `sign(p̃)·√max(0, g̃)` is composed from the graph's
//! bounds on `g_i` and `p_i` by `sq_signed_value_error` (`proofs/Squared.v`), not by
//! a node: its root may be of zero and its sign may flip.

use super::super::graph::{Bounds, Graph, Id, Model};
use super::{recurrence, Setup};

/// The pixels' `g_i` and `p_i` nodes of the squared method on `n` steps.
pub(super) fn squared(g: &mut Graph, s: &Setup, n: u32) -> (Vec<Id>, Vec<Id>) {
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
    let values = recurrence(g, n, g_a, t0, Some(ds));
    let signs = recurrence(g, n, s.b, s.a, None);
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
