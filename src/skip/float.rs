//! The skip test's float form: decided in `f64` alone, with a margin for its own
//! rounding and for the method's float error, so that it never skips a span where an
//! implementation of the method has a specular level above 0.
//!
//! Every quantity is an interval `[lo, hi]` of `f64`. An operation on intervals rounds
//! each endpoint's result to nearest and then steps one float outward (`next_down`,
//! `next_up`): for any rounding to nearest `r = ∘(x)`, `pred(r) ≤ x ≤ succ(r)`
//! (Flocq's `pred_round_le_id`, `succ_round_ge_id`), so each interval holds the exact
//! result of the exact operation on any point of its operands' intervals. A result that
//! is not finite ends the test with "do not skip", which is always sound; while every
//! result is finite the float operations are Flocq's rounding of the real ones.
//!
//! The decision (`proofs/SkipFloat.v`: `float_skip_sound`, `float_quadratic_skip_sound`,
//! `float_squared_skip_sound`):
//! - **Phong's values** (Phong, Duff, symmetric Phong), `f(u) = p(u)/√q(u)` on the
//!   segment `N(u) = N_a + u·(N_b − N_a)`, `u ∈ [0, 1]` (the same values as `t = u·n`):
//!   `p = B + u·A'`, `q = E + u·D' + u²·C'`, `f′ ∝ L(u) = L₀ + u·L₁`. The candidates are
//!   `u = 0`, `u = 1`, and an interval holding every root of `L` in `[0, 1]`:
//!   `−L₀/L₁` where `L₁`'s interval excludes 0, else all of `[0, 1]`. On a candidate
//!   interval `U`, `f ≤ max(0, p(U).hi)/√q(U).lo` (`q(U).lo > 0` required).
//! - **The quadratic recurrences** (corrected Euler, Euler, Gouraud):
//!   `v(t) = p_a + t·s_0 + t(t − 1)/2·ds` with `p_a`, `s_0`, `ds` from the span's
//!   set-up formulas (eqs. 10–17) in intervals; candidates `0`, `n`, and the vertex
//!   `1/2 − s_0/ds` where `ds < 0` (all of `[0, n]` where `ds`'s sign is unknown).
//! - **The squared method**, `sign(p)·√max(0, g)` with `g` its quadratic
//!   `g_a + t·t_0 + t(t − 1)/2·ds`: `g`'s set-up (`SquaredSpan::new`'s formulas) in
//!   intervals, the quadratic's candidates as above, and the root of the largest
//!   rounded up: the value is at most that at every point.
//! - At each candidate's bound `F`, with the allowance `e` (the method's proved
//!   per-pixel error bound on the span, [`Margins::ieee`]) and the format's unit
//!   roundoff `u`: the test passes when `255·K_s·(F + e)^s·(1 + u)^{2s+2} < 1`, all in
//!   upward rounding. The last factor covers the implementation's own evaluation of
//!   `255·K_s·v^s` — any evaluation within that relative error: `s − 1` rounded
//!   products for the power, or (for `s ≥ 2`) a `pow` within 2 ulps, then `K_s` and
//!   `255`, each rounding within `1 + u` while no result underflows.
//!
//! What is proved (`float_skip_sound`): a skip guarantees, at every real point of the
//! span and for every value `v` within `e` of the method's exact value there, that
//! `255·K_s·max(0, v)^s·(1 + u)^{2s+2} < 1`. That `e` covers every `ieee`
//! implementation is `check`'s bound (its own theorems); that the factor covers the
//! implementation's power is the derivation above, not part of the theorem. Together:
//! the implementation's specular level is 0.

use super::{SkipError, MAX_SHININESS};
use crate::reference::radical::Valued;
use crate::Method;

/// An interval `[lo, hi]` of `f64`, `lo ≤ hi`, both finite.
#[derive(Clone, Copy, Debug, PartialEq)]
struct I {
    lo: f64,
    hi: f64,
}

/// The interval of a result whose endpoints' candidates are `xs` (each rounded to
/// nearest), each stepped one float outward; `None` where one is not finite. (The
/// smallest is stepped down once: `pred` is monotone, so `pred(min x) = min pred(x)`,
/// the model of `proofs/SkipFloat.v`; likewise `succ` of the largest.)
fn hull(xs: &[f64]) -> Option<I> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &x in xs {
        if !x.is_finite() {
            return None;
        }
        lo = lo.min(x);
        hi = hi.max(x);
    }
    let out = I {
        lo: lo.next_down(),
        hi: hi.next_up(),
    };
    (out.lo.is_finite() && out.hi.is_finite()).then_some(out)
}

impl I {
    fn pt(x: f64) -> Option<I> {
        x.is_finite().then_some(I { lo: x, hi: x })
    }
    fn add(self, o: I) -> Option<I> {
        hull(&[self.lo + o.lo, self.hi + o.hi])
    }
    fn sub(self, o: I) -> Option<I> {
        hull(&[self.lo - o.hi, self.hi - o.lo])
    }
    fn mul(self, o: I) -> Option<I> {
        hull(&[
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ])
    }
    /// `None` where `o` holds 0.
    fn div(self, o: I) -> Option<I> {
        if o.lo <= 0.0 && o.hi >= 0.0 {
            return None;
        }
        hull(&[
            self.lo / o.lo,
            self.lo / o.hi,
            self.hi / o.lo,
            self.hi / o.hi,
        ])
    }
    /// The intersection with `[a, b]`; `None` where empty.
    fn meet(self, a: f64, b: f64) -> Option<I> {
        let (lo, hi) = (self.lo.max(a), self.hi.min(b));
        (lo <= hi).then_some(I { lo, hi })
    }
    fn dot(a: [I; 3], b: [I; 3]) -> Option<I> {
        a[0].mul(b[0])?.add(a[1].mul(b[1])?)?.add(a[2].mul(b[2])?)
    }
}

fn vec(v: [f64; 3]) -> Option<[I; 3]> {
    Some([I::pt(v[0])?, I::pt(v[1])?, I::pt(v[2])?])
}

fn vsub(a: [I; 3], b: [I; 3]) -> Option<[I; 3]> {
    Some([a[0].sub(b[0])?, a[1].sub(b[1])?, a[2].sub(b[2])?])
}

/// A span's float inputs: the edge normals, the half vector `H` and `n` steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloatSpan {
    /// `N_a`.
    pub na: [f64; 3],
    /// `N_b`.
    pub nb: [f64; 3],
    /// `H` (the span's `L` for its specular term).
    pub h: [f64; 3],
    /// Steps, `n ≥ 1`.
    pub n: u32,
}

/// What the float decision must cover beyond the exact value: the method's error `e`
/// at every pixel and the implementation format's unit roundoff `u`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Margins {
    /// An upper bound of `|v − exact|` at every pixel, for every implementation covered.
    pub allowance: f64,
    /// The unit roundoff of the implementation's format (`2^-24` for `binary32`).
    pub u: f64,
}

impl Margins {
    /// The margins of every `ieee` implementation of `method` in `format` on the exact
    /// span `span` (its `l` the half vector): the largest per-pixel `ieee` bound
    /// ([`crate::tolerance::graphs::profile_span_max`], the bound `check` uses) and
    /// `format`'s unit roundoff. `None` where no proved bound covers the span.
    pub fn ieee(
        method: Method,
        span: &crate::Span<crate::BigRational>,
        format: crate::Format,
    ) -> Option<Margins> {
        use crate::tolerance::{graphs, profile, Shape};
        let shape = Shape::of(span);
        let e = graphs::profile_span_max(
            method,
            profile::Profile::Ieee,
            profile::Form::Any,
            &shape,
            format,
        )?;
        Some(Margins {
            allowance: e,
            u: format.u(),
        })
    }
}

/// The upper bound of Phong's `f = p/√q` over `[0, 1]` (positive part), or `None`
/// where the intervals cannot bound it.
fn phong_max(s: &FloatSpan) -> Option<f64> {
    let (na, nb, h) = (vec(s.na)?, vec(s.nb)?, vec(s.h)?);
    let dn = vsub(nb, na)?;
    let a = I::dot(dn, h)?;
    let b = I::dot(na, h)?;
    let c = I::dot(dn, dn)?;
    let d = I::dot(dn, na)?.mul(I::pt(2.0)?)?;
    let e = I::dot(na, na)?;
    let half = I::pt(0.5)?;
    let l0 = a.mul(e)?.sub(b.mul(d)?.mul(half)?)?;
    let l1 = a.mul(d)?.mul(half)?.sub(b.mul(c)?)?;
    let mut candidates = vec![I::pt(0.0)?, I::pt(1.0)?];
    if l1.lo > 0.0 || l1.hi < 0.0 {
        if let Some(r) = I::pt(0.0)?.sub(l0)?.div(l1)?.meet(0.0, 1.0) {
            candidates.push(r);
        }
    } else {
        candidates.push(I { lo: 0.0, hi: 1.0 });
    }
    let mut best = 0f64;
    for u in candidates {
        let p = b.add(u.mul(a)?)?;
        let q = e.add(u.mul(d)?)?.add(u.mul(u)?.mul(c)?)?;
        if q.lo <= 0.0 {
            return None;
        }
        if p.hi > 0.0 {
            let root = q.lo.sqrt().next_down();
            if root <= 0.0 {
                return None;
            }
            best = best.max(I::pt(p.hi)?.div(I::pt(root)?)?.hi);
        }
    }
    Some(best)
}

/// The upper bound of the quadratic recurrence's `v` over `[0, n]` (positive part).
fn quadratic_max(s: &FloatSpan, valued: Valued) -> Option<f64> {
    // The set-up of `Span::setup`, operation for operation (eqs. 2–3, 10–17).
    let Polys {
        n,
        two,
        a,
        b: p_a,
        d,
        p_b,
        dq_b,
        ..
    } = Polys::of(s)?;
    let di_a = a.sub(p_a.div(two)?.mul(d)?)?;
    let di_b = a.sub(p_b.div(two)?.mul(dq_b)?)?;
    let ds = di_b.sub(di_a)?.div(n)?;
    let (s0, ds) = match valued {
        Valued::Gouraud => (p_b.sub(p_a)?.div(n)?, I::pt(0.0)?),
        Valued::Euler => (di_a, ds),
        Valued::CorrectedEuler => {
            let m = u64::from(s.n);
            let tri = I::pt((m * (m - 1) / 2) as f64)?;
            let p_n = p_a.add(n.mul(di_a)?)?.add(tri.mul(ds)?)?;
            let eps = p_n.sub(p_b)?;
            (di_a.sub(eps.div(n)?)?, ds)
        }
        _ => return None,
    };
    quad_top(p_a, s0, ds, n)
}

/// `n`, `2` and the polynomials' coefficients of a span in intervals (eqs. 2–3):
/// `k = (N_b − N_a)/n`, `A = k·H`, `B = N_a·H`, `C = k·k`, `D = 2·k·N_a`,
/// `E = N_a·N_a`, `p_b = N_b·H`, `q_b = N_b·N_b`, `q′_b = 2n·C + D`, the first steps
/// of both set-ups ([`quadratic_max`], [`squared_max`]).
struct Polys {
    n: I,
    two: I,
    a: I,
    b: I,
    d: I,
    e: I,
    p_b: I,
    q_b: I,
    dq_b: I,
}

impl Polys {
    fn of(s: &FloatSpan) -> Option<Polys> {
        let (na, nb, h) = (vec(s.na)?, vec(s.nb)?, vec(s.h)?);
        let n = I::pt(f64::from(s.n))?;
        let two = I::pt(2.0)?;
        let k = {
            let d = vsub(nb, na)?;
            [d[0].div(n)?, d[1].div(n)?, d[2].div(n)?]
        };
        let c = I::dot(k, k)?;
        let d = two.mul(I::dot(k, na)?)?;
        Some(Polys {
            n,
            two,
            a: I::dot(k, h)?,
            b: I::dot(na, h)?,
            d,
            e: I::dot(na, na)?,
            p_b: I::dot(nb, h)?,
            q_b: I::dot(nb, nb)?,
            dq_b: two.mul(n)?.mul(c)?.add(d)?,
        })
    }
}

/// The upper bound (from 0) of `v(t) = p_a + t·s_0 + t(t − 1)/2·ds` over `[0, n]`
/// for every `p_a`, `s_0`, `ds` in the intervals: `v`'s upper end at the candidates
/// `0`, `n` and the vertex `1/2 − s_0/ds` met with `[0, n]` where `ds < 0` (all of
/// `[0, n]` where `ds`'s sign is unknown).
fn quad_top(p_a: I, s0: I, ds: I, n: I) -> Option<f64> {
    let half = I::pt(0.5)?;
    let mut candidates = vec![I::pt(0.0)?, n];
    if ds.hi < 0.0 {
        if let Some(t) = half.sub(s0.div(ds)?)?.meet(0.0, n.hi) {
            candidates.push(t);
        }
    } else if ds.lo < 0.0 {
        candidates.push(I { lo: 0.0, hi: n.hi });
    }
    let mut best = 0f64;
    for t in candidates {
        let tm1 = t.sub(I::pt(1.0)?)?;
        let v = p_a.add(t.mul(s0)?)?.add(t.mul(tm1)?.mul(half)?.mul(ds)?)?;
        best = best.max(v.hi);
    }
    Some(best)
}

/// The upper bound of the squared method's `√max(0, g)` over `[0, n]` (its value
/// `sign(p)·√max(0, g)` is at most that): `g`'s set-up
/// ([`crate::squared_corrected_euler::SquaredSpan::new`]'s formulas) in intervals,
/// the largest of its quadratic at the candidates ([`quad_top`]), then its root
/// rounded up. `None` where a divisor's interval holds 0 or a result is not finite.
fn squared_max(s: &FloatSpan) -> Option<f64> {
    let Polys {
        n,
        two,
        a,
        b,
        d,
        e,
        p_b,
        q_b,
        dq_b,
    } = Polys::of(s)?;
    let g_a = b.mul(b)?.div(e)?;
    let g_b = p_b.mul(p_b)?.div(q_b)?;
    // g′ = p·(2A·q − p·q′)/(q·q) at each end.
    let slope = |p: I, q: I, dq: I| -> Option<I> {
        let inner = two.mul(a)?.mul(q)?.sub(p.mul(dq)?)?;
        p.mul(inner)?.div(q.mul(q)?)
    };
    let dg_a = slope(b, e, d)?;
    let dg_b = slope(p_b, q_b, dq_b)?;
    let ds = dg_b.sub(dg_a)?.div(n)?;
    let m = u64::from(s.n);
    let tri = I::pt((m * (m - 1) / 2) as f64)?;
    let g_n = g_a.add(n.mul(dg_a)?)?.add(tri.mul(ds)?)?;
    let t0 = dg_a.sub(g_n.sub(g_b)?.div(n)?)?;
    let top = quad_top(g_a, t0, ds, n)?;
    // The root rounded to nearest, then one float up: at least √top.
    let root = if top > 0.0 { top.sqrt().next_up() } else { 0.0 };
    root.is_finite().then_some(root)
}

/// `255·K_s·(F + e)^s·(1 + u)^{2s+2} < 1` in upward rounding (`F, e, K_s ≥ 0`).
fn below_one(f: f64, m: Margins, ks: f64, shininess: u32) -> bool {
    // One float up from the nearest: above the exact result, an underflow to 0 included.
    let up = |x: f64| x.next_up();
    let pow = |x: f64, e: u32| {
        let (mut acc, mut base, mut left) = (1.0f64, x, e);
        while left > 0 {
            if left & 1 == 1 {
                acc = up(acc * base);
            }
            left >>= 1;
            if left > 0 {
                base = up(base * base);
            }
        }
        acc
    };
    let v = up(f + m.allowance);
    let total = up(up(up(255.0 * ks) * pow(v, shininess)) * pow(up(1.0 + m.u), 2 * shininess + 2));
    total.is_finite() && total < 1.0
}

/// The float skip test of `method` on the float span `span`: whether, for every
/// implementation within `margins` of the method's exact value on these inputs, the
/// specular level `K_s·max(0, v)^s` is 0 at every pixel (the module's documentation
/// says how). `Ok(false)` where the intervals cannot decide — a conservative answer,
/// never a wrong skip.
///
/// `K_s ≤ 1` keeps every partial product of an implementation's power above `1/255`
/// wherever its level could reach 1, so the relative margin `(1 + u)^{2s+2}` is not
/// undone by an underflow.
///
/// # Errors
/// [`SkipError`]: a shininess outside `1..=MAX_SHININESS`; [`SkipError::FloatInput`]
/// for a `K_s` outside `[0, 1]`, margins or inputs that are not finite, or `n` outside
/// `1..=MAX_STEPS`; [`SkipError::NormalVanishes`] for a zero edge normal;
/// [`SkipError::Unsupported`] for a method with no test.
pub fn float_skips(
    method: Method,
    span: &FloatSpan,
    ks: f64,
    shininess: u32,
    margins: Margins,
) -> Result<bool, SkipError> {
    if !(1..=MAX_SHININESS).contains(&shininess) {
        return Err(SkipError::Shininess(shininess));
    }
    let bad = |why| Err(SkipError::FloatInput(why));
    if !(0.0..=1.0).contains(&ks) {
        return bad("K_s must be in [0, 1]");
    }
    let finite_nonneg = |x: f64| x.is_finite() && x >= 0.0;
    if !finite_nonneg(margins.allowance) || !finite_nonneg(margins.u) || margins.u >= 0.5 {
        return bad("the margins must be finite, at least 0, and u below 1/2");
    }
    if !(1..=crate::span::MAX_STEPS).contains(&span.n) {
        return bad("n must be 1 to 2^24");
    }
    if [span.na, span.nb, span.h]
        .iter()
        .flatten()
        .any(|x| !x.is_finite())
    {
        return bad("the inputs must be finite");
    }
    if span.na == [0.0; 3] || span.nb == [0.0; 3] {
        return Err(SkipError::NormalVanishes);
    }
    let max = match method.info().closed_form {
        Some(v @ (Valued::Gouraud | Valued::Euler | Valued::CorrectedEuler)) => {
            quadratic_max(span, v)
        }
        Some(Valued::Phong) => phong_max(span),
        None if method.is_phong_valued() => phong_max(span),
        None if method.info().roots == crate::method::Roots::SignedRootOfG => squared_max(span),
        _ => return Err(SkipError::Unsupported(method)),
    };
    Ok(max.is_some_and(|f| below_one(f, margins, ks, shininess)))
}
