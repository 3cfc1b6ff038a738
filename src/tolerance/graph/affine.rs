//! Affine error forms over the local roundings (`proofs/GraphAffine.v`,
//! `graph_sound_affine`; `docs/float.md` §19.1).
//!
//! [`evaluate`](super::evaluate)'s running bound adds its operands' error bounds at
//! every operation, so a rounding that reaches a node along two paths with opposite
//! signs is counted twice although it cancels (corrected Euler's
//! `t0 = di_a − (p_n − p_b)/n`, Phong's lerp `(1 − t)N_a + t·N_b`). Here each node's
//! error is a form `Σ_k M_jk·δ_k + ρ_j` over the earlier nodes' local roundings `δ_k`
//! (each within `e_k`), plus the node's own rounding, with `|ρ_j| ≤ R_j`: a
//! coefficient is carried as a number, so a rounding's paths add before their
//! absolute value is taken. The rules are `loc_ok` and `aff_ok` of the proof; every
//! quantity is rounded outward as in [`evaluate`](super::evaluate).

use super::{add_up, corners, div_up, dn, mag, mul_up, sum_shape, up, Bounds, Graph, Id, Op};

/// How many earlier roundings a node's form keeps: the largest `|M_jk|·e_k`; the
/// others go to the remainder (a coefficient of 0 in `aff_ok`, whose whole term the
/// remainder then carries).
pub const KEPT: usize = 16;

/// A form: `(k, M_jk)` by increasing `k < j`.
type Form = Vec<(Id, f64)>;

/// Each node's affine certificate.
#[derive(Clone, Debug, PartialEq)]
pub struct Affine {
    /// `e_k`: a bound on the node's local rounding `δ_k` (`loc_ok`).
    pub e: Vec<f64>,
    /// `R_j`: the form's remainder (`aff_ok`).
    pub rem: Vec<f64>,
    /// `M_jk` for `k < j`, the others 0.
    pub forms: Vec<Form>,
    /// `Σ_k |M_jk|·e_k + e_j + R_j`, rounded up: the bound on `|computed − exact|`
    /// (`ferr` of the proof).
    pub err: Vec<f64>,
}

/// The operands' full coefficients (`fm`: 1 on the operand itself), each scaled by
/// an interval `[sl, sh]`, summed per symbol: `(k, lo, hi)` by increasing `k`.
fn combine(af: &Affine, terms: &[(Id, (f64, f64))]) -> Vec<(Id, f64, f64)> {
    let mut out: Vec<(Id, f64, f64)> = Vec::new();
    for &(t, (sl, sh)) in terms {
        let scaled = |c: f64| {
            let (a, b) = (c * sl, c * sh);
            (dn(a.min(b)), up(a.max(b)))
        };
        let own = std::iter::once((t, 1.0));
        for (k, c) in af.forms[t].iter().copied().chain(own) {
            if af.e[k] == 0.0 {
                continue;
            }
            let (l, h) = scaled(c);
            match out.binary_search_by_key(&k, |x| x.0) {
                Ok(i) => {
                    out[i].1 = dn(out[i].1 + l);
                    out[i].2 = up(out[i].2 + h);
                }
                Err(i) => out.insert(i, (k, l, h)),
            }
        }
    }
    out
}

/// Chooses the form from the propagated coefficients `c`: the [`KEPT`] largest
/// contributions at their midpoints, each charging `|c − M|·e` to the remainder, the
/// others dropped (`M = 0`, charging `|c|·e`). Returns the form and the charge.
fn choose(af: &Affine, c: Vec<(Id, f64, f64)>) -> (Form, f64) {
    let weight = |&(k, l, h): &(Id, f64, f64)| mul_up(mag(l, h), af.e[k]);
    // The KEPT-th largest weight: the entries above it are kept, and at it as many as
    // fit.
    let cut = if c.len() > KEPT {
        let mut w: Vec<f64> = c.iter().map(weight).collect();
        w.sort_by(|a, b| b.total_cmp(a));
        w[KEPT - 1]
    } else {
        f64::NEG_INFINITY
    };
    // How many entries at the cut still fit.
    let mut room = KEPT.saturating_sub(c.iter().filter(|x| weight(x) > cut).count());
    let (mut form, mut charge) = (Form::with_capacity(c.len().min(KEPT)), 0.0);
    for x @ &(k, l, h) in &c {
        let wx = weight(x);
        let at_cut = wx == cut && room > 0;
        room -= usize::from(at_cut);
        if wx > cut || at_cut {
            let m = 0.5 * l + 0.5 * h;
            let dev = up(h - m).max(up(m - l));
            charge = add_up(charge, mul_up(dev, af.e[k]));
            form.push((k, m));
        } else {
            charge = add_up(charge, wx);
        }
    }
    (form, charge)
}

/// `Σ_k |M_jk|·e_k`, rounded up.
fn form_size(af: &Affine, form: &Form) -> f64 {
    form.iter()
        .fold(0.0, |s, &(k, m)| add_up(s, mul_up(m.abs(), af.e[k])))
}

/// The local rounding bound `e_j` of `loc_ok`, from the running certificate `b`.
fn local(graph: &Graph, b: &Bounds, j: Id) -> Option<f64> {
    let (v, eta) = (b.v[j], b.eta[j]);
    let me = add_up(mag(b.lo[j], b.hi[j]), b.err[j]);
    let one = |v: f64| {
        let den = dn(1.0 - v);
        (den > 0.0).then(|| div_up(add_up(mul_up(v, me), eta), den))
    };
    Some(match &graph.nodes()[j].op {
        Op::Cst(_) => 0.0,
        Op::DivE(a, _) => {
            let w = mul_up(v, add_up(2.0, v));
            let den = dn(1.0 - w);
            if den <= 0.0 {
                return None;
            }
            let ya = add_up(mag(b.lo[*a], b.hi[*a]), b.err[*a]);
            let recip = add_up(
                add_up(mul_up(w, me), mul_up(add_up(1.0, v), mul_up(ya, eta))),
                eta,
            );
            one(v)?.max(div_up(recip, den))
        }
        Op::Sum(l) => {
            // As the running bound's sum rule: m = live − 1 rounded additions, each
            // addition of a zero within `ez`.
            let (k, m, w) = sum_shape(l, &b.lo, &b.hi, &b.err, v);
            let sm = l.iter().fold(0.0, |s, &t| {
                add_up(s, add_up(mag(b.lo[t], b.hi[t]), b.err[t]))
            });
            add_up(
                add_up(mul_up(up(w - 1.0), sm), mul_up(mul_up(m as f64, w), eta)),
                mul_up(mul_up((k - 1) as f64, w), b.ez),
            )
        }
        _ => one(v)?,
    })
}

/// `Σ_k |M_k|·e_k + R` of a candidate `(form, R)`.
fn size(af: &Affine, c: &(Form, f64)) -> f64 {
    add_up(form_size(af, &c.0), c.1)
}

/// A division `a/c` linearly (`div_lin` of the proof): `u = 1/x_c` in
/// `[1/hi_c, 1/lo_c]`, `q = x_a/x_c` in the node's interval; every term at its largest
/// over that box. `None` where `F_c` does not keep the divisor from zero.
fn div_linear(af: &Affine, b: &Bounds, j: Id, a: Id, c: Id) -> Option<(Form, f64)> {
    let (fa, fc) = (af.err[a], af.err[c]);
    let lb = b.lo[c].abs().min(b.hi[c].abs());
    if fc.is_nan() || fc >= lb {
        return None;
    }
    let u = (dn(1.0 / b.hi[c]), up(1.0 / b.lo[c]));
    let qu = corners(|x, y| x * y, (b.lo[j], b.hi[j]), u);
    let (um, qum, qm) = (mag(u.0, u.1), mag(qu.0, qu.1), mag(b.lo[j], b.hi[j]));
    let den = dn(1.0 - mul_up(um, fc));
    if den.is_nan() || den <= 0.0 {
        return None;
    }
    let second = div_up(
        mul_up(mul_up(add_up(fa, mul_up(qm, fc)), fc), mul_up(um, um)),
        den,
    );
    let (f, ch) = choose(af, combine(af, &[(a, u), (c, (-qu.1, -qu.0))]));
    let r = add_up(
        add_up(
            add_up(mul_up(um, af.rem[a]), mul_up(qum, af.rem[c])),
            second,
        ),
        ch,
    );
    r.is_finite().then_some((f, r))
}

/// A square root of `a` linearly (`sqrt_lin` of the proof): `s = √x_a` in
/// `[S_j, hi_j]`, every term at its largest there (at `s = S_j`).
fn sqrt_linear(af: &Affine, b: &Bounds, j: Id, a: Id) -> Option<(Form, f64)> {
    let (s, t, h) = (b.s[j], b.t[j], b.hi[j]);
    if s.is_nan() || h.is_nan() || s <= 0.0 || h < s {
        return None;
    }
    let coef = (dn(1.0 / up(2.0 * h)), up(1.0 / dn(2.0 * s)));
    let fa = af.err[a];
    let st = dn(s + t);
    let second = div_up(mul_up(fa, fa), dn(dn(2.0 * s) * dn(st * st)));
    let (f, ch) = choose(af, combine(af, &[(a, coef)]));
    let r = add_up(add_up(div_up(af.rem[a], dn(2.0 * s)), second), ch);
    r.is_finite().then_some((f, r))
}

/// The affine certificate of `graph` on the running certificate `b` (which
/// [`evaluate`](super::evaluate) computed on the same graph and inputs). `None` where
/// a rule's condition fails (a divisor that the affine bound does not keep from zero,
/// a unit of 1 or more): the running bound then stands alone.
pub fn affine(graph: &Graph, b: &Bounds) -> Option<Affine> {
    let len = graph.nodes().len();
    let mut af = Affine {
        e: Vec::with_capacity(len),
        rem: Vec::with_capacity(len),
        forms: Vec::with_capacity(len),
        err: Vec::with_capacity(len),
    };
    let pt = |x: f64| (x, x);
    for (j, node) in graph.nodes().iter().enumerate() {
        let e = local(graph, b, j)?;
        let (form, rem) = match &node.op {
            Op::In(_) | Op::Cst(_) => (Form::new(), 0.0),
            Op::Add(a, c) | Op::Sub(a, c) => {
                let s = if matches!(node.op, Op::Add(..)) {
                    1.0
                } else {
                    -1.0
                };
                let (f, ch) = choose(&af, combine(&af, &[(*a, pt(1.0)), (*c, pt(s))]));
                (f, add_up(add_up(af.rem[*a], af.rem[*c]), ch))
            }
            Op::Mul(a, c) => {
                let (ia, ic) = ((b.lo[*a], b.hi[*a]), (b.lo[*c], b.hi[*c]));
                let (f, ch) = choose(&af, combine(&af, &[(*a, ic), (*c, ia)]));
                let r = add_up(
                    add_up(
                        mul_up(mag(ic.0, ic.1), af.rem[*a]),
                        mul_up(mag(ia.0, ia.1), af.rem[*c]),
                    ),
                    mul_up(af.err[*a], af.err[*c]),
                );
                (f, add_up(r, ch))
            }
            Op::Div(a, c) | Op::DivE(a, c) => {
                let x = b.lo[*c];
                if x == b.hi[*c] && b.err[*c] == 0.0 && x != 0.0 {
                    // A divisor known exactly: linear.
                    let inv = (dn(1.0 / x), up(1.0 / x));
                    let (f, ch) = choose(&af, combine(&af, &[(*a, inv)]));
                    (f, add_up(div_up(af.rem[*a], dn(x.abs())), ch))
                } else {
                    let lb = b.lo[*c].abs().min(b.hi[*c].abs());
                    let gap = dn(lb - af.err[*c]);
                    if gap.is_nan() || gap <= 0.0 {
                        return None;
                    }
                    let m = mag(b.lo[j], b.hi[j]);
                    let d = div_up(add_up(af.err[*a], mul_up(m, af.err[*c])), gap);
                    let opaque = (Form::new(), d);
                    match div_linear(&af, b, j, *a, *c) {
                        Some(lin) if size(&af, &lin) < size(&af, &opaque) => lin,
                        _ => opaque,
                    }
                }
            }
            Op::Sqrt(a) => {
                let opaque = (Form::new(), div_up(af.err[*a], dn(b.s[j] + b.t[j])));
                match sqrt_linear(&af, b, j, *a) {
                    Some(lin) if size(&af, &lin) < size(&af, &opaque) => lin,
                    _ => opaque,
                }
            }
            Op::Rsqrt(a) => {
                let s = b.s[j];
                (Form::new(), div_up(af.err[*a], dn(2.0 * dn(dn(s * s) * s))))
            }
            Op::Sum(l) => {
                let terms: Vec<(Id, (f64, f64))> = l.iter().map(|&t| (t, pt(1.0))).collect();
                let (f, ch) = choose(&af, combine(&af, &terms));
                let r = l.iter().fold(0.0, |s, &t| add_up(s, af.rem[t]));
                (f, add_up(r, ch))
            }
        };
        let err = add_up(add_up(form_size(&af, &form), e), rem);
        if !(err.is_finite() && rem.is_finite()) {
            return None;
        }
        af.e.push(e);
        af.rem.push(rem);
        af.forms.push(form);
        af.err.push(err);
    }
    Some(af)
}
