//! Each method's operation graphs (`docs/float.md` §19): the paper's set-up (eqs. 2–3,
//! 10–11, 14–17, in [`crate::span::Span`]'s order) and every form an implementation
//! of the class may compute, written once as [`Graph`]s whose per-pixel nodes
//! [`evaluate`] bounds for the case's own inputs.
//!
//! A method's bound on a case is, at each pixel, the largest over its forms' graphs
//! (an implementation computes one of them); each graph's bound is `graph_sound`'s
//! (`proofs/Graph.v`). Inputs: `N_a` (0–2), `N_b` (3–5), `L` (6–8).

use super::graph::{affine, evaluate, read_distance, read_error, Graph, GraphError, Id, Model};
use super::profile::Form;
use crate::Method;

mod squared;
use squared::Walk;

/// One form of a method: its graph and the node of each pixel's value.
#[derive(Clone, Debug)]
pub struct MethodGraph {
    /// The form's name (`recurrence`, `closed`, `horner/div`, …).
    pub name: String,
    /// The graph.
    pub graph: Graph,
    /// Per way of the last operations (`p/√q`, `p·(1/√q)`, …; one for the other
    /// methods), the node whose value is pixel `i`'s, for `i = 0..=n`: the ways share
    /// the graph's other nodes, and an implementation computes one of them.
    pub pixels: Vec<Vec<Id>>,
    /// The set-up's nodes by the paper's names (`A`, `B`, `C`, `D`, `E`, `p_a`, `p_b`,
    /// `dq_b`, `di_a`, `ds`, `t0`, `dp`): what a test plants a bug in.
    pub setup: Vec<(&'static str, Id)>,
    /// The squared method's `p_i` nodes, `i = 0..=n`: its value is then
    /// `sign(p_i)·√max(0, g_i)` with `g_i` the pixel's node, composed outside the
    /// graph ([`pixel_bounds`], `sq_signed_value_error`); `None` for the others.
    pub signs: Option<Vec<Id>>,
}

/// The set-up's nodes, in the paper's names.
struct Setup {
    n: Id,
    na: [Id; 3],
    nb: [Id; 3],
    l: [Id; 3],
    k: [Id; 3],
    a: Id,
    b: Id,
    c: Id,
    d: Id,
    e: Id,
    p_a: Id,
    p_b: Id,
    dq_b: Id,
    di_a: Id,
    ds: Id,
    t0: Id,
    dp: Id,
}

/// A form's pixels' nodes (per way) and, for the squared method, its signs' nodes.
type Built = (Vec<Vec<Id>>, Option<Vec<Id>>);

/// The paper's set-up (`Span::new`'s formulas and order): every division by `n` either
/// way, the halvings of `p_a` and `p_b` in the class `Half`, `p_n`'s three terms in any
/// order with `n(n−1)/2` exact.
fn setup(g: &mut Graph, n: u32) -> Setup {
    let na = [0, 1, 2].map(|c| g.input(c));
    let nb = [3, 4, 5].map(|c| g.input(c));
    let l = [6, 7, 8].map(|c| g.input(c));
    let nn = g.cst(f64::from(n));
    let k = [0, 1, 2].map(|c| {
        let diff = g.sub(nb[c], na[c]);
        g.div_either(diff, nn)
    });
    let a = g.dot(k, l);
    let b = g.dot(na, l);
    let c = g.dot(k, k);
    let kna = g.dot(k, na);
    let two = g.cst(2.0);
    let d = g.mul(two, kna);
    let e = g.dot(na, na);
    let p_a = b;
    let p_b = g.dot(nb, l);
    let dq_a = d;
    let two_n = g.cst(2.0 * f64::from(n));
    let two_n_c = g.mul(two_n, c);
    let dq_b = g.add(two_n_c, d);
    let half_pa = g.half(p_a);
    let t_a = g.mul(half_pa, dq_a);
    let di_a = g.sub(a, t_a);
    let half_pb = g.half(p_b);
    let t_b = g.mul(half_pb, dq_b);
    let di_b = g.sub(a, t_b);
    let ddi = g.sub(di_b, di_a);
    let ds = g.div_either(ddi, nn);
    let tri = g.cst((f64::from(n) * (f64::from(n) - 1.0) / 2.0).floor());
    let n_dia = g.mul(nn, di_a);
    let tri_ds = g.mul(tri, ds);
    let p_n = g.sum(&[p_a, n_dia, tri_ds]);
    let eps = g.sub(p_n, p_b);
    let d_eps = g.div_either(eps, nn);
    let t0 = g.sub(di_a, d_eps);
    let dpb = g.sub(p_b, p_a);
    let dp = g.div_either(dpb, nn);
    Setup {
        n: nn,
        na,
        nb,
        l,
        k,
        a,
        b,
        c,
        d,
        e,
        p_a,
        p_b,
        dq_b,
        di_a,
        ds,
        t0,
        dp,
    }
}

/// A second-order recurrence `v += s; s += ds` from `(v0, s0)`: corrected Euler's
/// (`t_0`) and Euler's (`di_a`) loops, and Gouraud's with `ds` absent.
fn recurrence(g: &mut Graph, n: u32, v0: Id, s0: Id, ds: Option<Id>) -> Vec<Id> {
    let (mut v, mut s) = (v0, s0);
    let mut out = vec![v];
    for _ in 0..n {
        v = g.add(v, s);
        if let Some(ds) = ds {
            s = g.add(s, ds);
        }
        out.push(v);
    }
    out
}

/// How a closed form forms `(i − 1)/2 · ds`.
#[derive(Clone, Copy)]
enum Halving {
    /// `(i − 1)·0.5` exact, then the product.
    Exact,
    /// `c = (i − 1)/2` by a division (either way), then `c·ds`.
    Coefficient,
    /// `(i − 1)·ds`, then halved (either way).
    Product,
}

/// `p_a + i·(s0 + (i − 1)/2·ds)`: corrected Euler's (`s0 = t_0`) and Euler's
/// (`s0 = di_a`) closed forms.
fn closed(g: &mut Graph, n: u32, p_a: Id, s0: Id, ds: Id, how: Halving) -> Vec<Id> {
    let mut out = vec![p_a];
    for i in 1..=n {
        let fi = f64::from(i);
        let c_ds = match how {
            Halving::Exact => {
                let c = g.cst((fi - 1.0) / 2.0);
                g.mul(c, ds)
            }
            Halving::Coefficient => {
                let m = g.cst(fi - 1.0);
                let c = g.half(m);
                g.mul(c, ds)
            }
            Halving::Product => {
                let m = g.cst(fi - 1.0);
                let m_ds = g.mul(m, ds);
                g.half(m_ds)
            }
        };
        let slope = g.add(s0, c_ds);
        let ic = g.cst(fi);
        let step = g.mul(ic, slope);
        out.push(g.add(p_a, step));
    }
    out
}

/// `√x` as the model computes a square root: one operation, or `1/inverseSqrt(x)`.
fn root(g: &mut Graph, model: &Model, x: Id) -> Id {
    if model.sqrt_is_recip_rsqrt {
        let one = g.cst(1.0);
        let r = g.rsqrt(x);
        g.div(one, r)
    } else {
        g.sqrt(x)
    }
}

/// `1/√x`: `1/√x` by a division, or (where the model has it) `inverseSqrt(x)`.
fn recip_roots(g: &mut Graph, model: &Model, x: Id) -> Vec<Id> {
    let one = g.cst(1.0);
    let s = root(g, model, x);
    let mut ways = vec![g.div(one, s)];
    if model.sqrt_is_recip_rsqrt {
        ways.push(g.rsqrt(x));
    }
    ways
}

/// The ways of `p/√q`: `p/√q`, `p·(1/√q)` (and `p·inverseSqrt(q)` where the model has
/// it), each as a node of `g`.
fn values(g: &mut Graph, model: &Model, p: Id, q: Id) -> Vec<Id> {
    let s = root(g, model, q);
    let mut ways = vec![g.div(p, s)];
    for r in recip_roots(g, model, q) {
        ways.push(g.mul(p, r));
    }
    ways
}

/// The longest span the graphs bound, `n ≤ 4096` (the published sets' longest): one
/// form's graph is about 45 nodes a pixel, built and evaluated one form at a time;
/// longer spans keep the formulas' bounds (bounded memory and time).
pub const MAX_GRAPH_STEPS: u32 = 4096;

/// The forms of `method` in `form` on a span of `n` steps, each a graph and its
/// pixels' nodes; `None` where the method has no operation graph here (angular
/// interpolation, the related methods, the adaptive scheme, which is judged by its
/// picks) or the declared form is not one of its graphs.
pub fn method_graphs(
    method: Method,
    form: Form,
    n: u32,
    model: &Model,
) -> Option<Vec<MethodGraph>> {
    let mut out = Vec::new();
    for_each_graph(method, form, n, model, |g| {
        out.push(g);
        Ok::<(), GraphError>(())
    })
    .ok()??;
    Some(out)
}

/// [`method_graphs`] one form at a time: `f` takes each form's graph, which is
/// dropped before the next is built. `Ok(None)` where the method has no graph here;
/// the first error `f` returns.
///
/// # Errors
/// What `f` returns.
pub fn for_each_graph<E>(
    method: Method,
    form: Form,
    n: u32,
    model: &Model,
    mut f: impl FnMut(MethodGraph) -> Result<(), E>,
) -> Result<Option<()>, E> {
    let make = |name: &str, build: &dyn Fn(&mut Graph, &Setup) -> Built| {
        let mut g = Graph::new();
        let s = setup(&mut g, n);
        let (pixels, signs) = build(&mut g, &s);
        let setup = vec![
            ("A", s.a),
            ("B", s.b),
            ("C", s.c),
            ("D", s.d),
            ("E", s.e),
            ("p_a", s.p_a),
            ("p_b", s.p_b),
            ("dq_b", s.dq_b),
            ("di_a", s.di_a),
            ("ds", s.ds),
            ("t0", s.t0),
            ("dp", s.dp),
        ];
        MethodGraph {
            name: name.to_string(),
            graph: g,
            pixels,
            setup,
            signs,
        }
    };
    let mut add = |name: &str, build: &dyn Fn(&mut Graph, &Setup) -> Vec<Vec<Id>>| {
        f(make(name, &|g, s| (build(g, s), None)))
    };
    // The forms' names are the catalogue's (`Info::profiles.graphs`), in its order.
    let names = method.info().profiles.graphs;
    let recur = !matches!(form, Form::Closed);
    let closed_ok = !matches!(form, Form::Recurrence);
    match method {
        Method::Gouraud if form == Form::Any => {
            add(names[0], &|g, s| vec![recurrence(g, n, s.p_a, s.dp, None)])?;
        }
        Method::CorrectedEuler | Method::Euler => {
            let euler = method == Method::Euler;
            if recur {
                add(names[0], &|g, s| {
                    let s0 = if euler { s.di_a } else { s.t0 };
                    vec![recurrence(g, n, s.p_a, s0, Some(s.ds))]
                })?;
            }
            if closed_ok {
                let halvings = [Halving::Exact, Halving::Coefficient, Halving::Product];
                for (name, how) in names[1..].iter().zip(halvings) {
                    add(name, &|g, s| {
                        let s0 = if euler { s.di_a } else { s.t0 };
                        vec![closed(g, n, s.p_a, s0, s.ds, how)]
                    })?;
                }
            }
        }
        Method::Duff | Method::SymmetricPhong if form == Form::Any => {
            let symmetric = method == Method::SymmetricPhong;
            add(names[0], &|g, s| duff(g, model, s, n, symmetric))?;
        }
        Method::Phong if form == Form::Any => {
            for &pq in names {
                add(pq, &|g, s| phong(g, model, s, n, pq))?;
            }
        }
        Method::SquaredCorrectedEuler if form == Form::Any => {
            let walks = [Walk::Recurrence, Walk::Closed, Walk::Lanes];
            for (name, walk) in names.iter().zip(walks) {
                f(make(name, &|g, s| {
                    let (values, signs) = squared::squared(g, s, n, walk);
                    (vec![values], Some(signs))
                }))?;
            }
        }
        _ => return Ok(None),
    }
    Ok(Some(()))
}

/// Duff's forward differences (eqs. 5–7): `p += A`, `q += dq`, `dq += 2C` from
/// `p_0 = B`, `q_0 = E`, `dq_0 = C + D`; the value by each way: `p/√q`, `p·(1/√q)`
/// and, where the model has it, `p·inverseSqrt(q)`. Symmetric Phong (§4) takes the
/// roots of the left half for the right: `√q_i = √q_{n−i}`.
fn duff(g: &mut Graph, model: &Model, s: &Setup, n: u32, symmetric: bool) -> Vec<Vec<Id>> {
    let dq0 = g.add(s.c, s.d);
    let d2q = g.add(s.c, s.c);
    let (mut p, mut q, mut dq) = (s.b, s.e, dq0);
    let last = if symmetric { n / 2 } else { n };
    let mut ps = Vec::new();
    let mut qs = Vec::new();
    for i in 0..=n {
        ps.push(p);
        if i <= last {
            qs.push(q);
        }
        p = g.add(p, s.a);
        if i < last {
            q = g.add(q, dq);
            dq = g.add(dq, d2q);
        }
    }
    let one = g.cst(1.0);
    let ways = if model.sqrt_is_recip_rsqrt { 3 } else { 2 };
    let nu = n as usize;
    (0..ways)
        .map(|way| {
            // The roots (or reciprocal roots) of the mirrored half are the same nodes.
            let roots: Vec<Id> = qs
                .iter()
                .map(|&q| match way {
                    0 => root(g, model, q),
                    1 => {
                        let r = root(g, model, q);
                        g.div(one, r)
                    }
                    _ => g.rsqrt(q),
                })
                .collect();
            (0..=nu)
                .map(|i| {
                    let r = roots[if i < roots.len() { i } else { nu - i }];
                    if way == 0 {
                        g.div(ps[i], r)
                    } else {
                        g.mul(ps[i], r)
                    }
                })
                .collect()
        })
        .collect()
}

/// Phong's forms (`docs/float.md` §18.4): `p` and `q` by Horner (`A·i + B`,
/// `(C·i + D)·i + E`), by the per-pixel normal `N_a + i·k`, or by the lerp
/// `(1 − t)·N_a + t·N_b` with `t = i/n` either way; then each way: `p/√q`,
/// `p·(1/√q)`, `p·inverseSqrt(q)` (where the model has it), and, for a normal,
/// normalize then dot: `(N·(1/√q))·L`.
fn phong(g: &mut Graph, model: &Model, s: &Setup, n: u32, pq: &str) -> Vec<Vec<Id>> {
    let one = g.cst(1.0);
    let mut ways: Vec<Vec<Id>> = Vec::new();
    for i in 0..=n {
        let ic = g.cst(f64::from(i));
        let normal = match pq {
            "pixel" => Some([0, 1, 2].map(|c| {
                let ik = g.mul(ic, s.k[c]);
                g.add(s.na[c], ik)
            })),
            "lerp" => {
                let t = g.div_either(ic, s.n);
                let omt = g.sub(one, t);
                Some([0, 1, 2].map(|c| {
                    let a = g.mul(omt, s.na[c]);
                    let b = g.mul(t, s.nb[c]);
                    g.add(a, b)
                }))
            }
            _ => None,
        };
        let (p, q) = match normal {
            Some(nv) => (g.dot(nv, s.l), g.dot(nv, nv)),
            None => {
                let ai = g.mul(s.a, ic);
                let p = g.add(ai, s.b);
                let ci = g.mul(s.c, ic);
                let cid = g.add(ci, s.d);
                let cidi = g.mul(cid, ic);
                (p, g.add(cidi, s.e))
            }
        };
        let mut v = values(g, model, p, q);
        if let Some(nv) = normal {
            // Normalize, then dot.
            let sq = root(g, model, q);
            let r = g.div(one, sq);
            let w = nv.map(|c| g.mul(c, r));
            v.push(g.dot(w, s.l));
        }
        if ways.is_empty() {
            ways = vec![Vec::with_capacity(n as usize + 1); v.len()];
        }
        for (way, node) in ways.iter_mut().zip(v) {
            way.push(node);
        }
    }
    ways
}

/// The bound of `method` in `form` at every pixel of the case with exact inputs in the
/// intervals `inputs` (`N_a`, `N_b`, `L`), `n` steps: the largest over its forms'
/// graphs, pixel by pixel. `Ok(None)` where the method has no graph here or `n` is
/// above [`MAX_GRAPH_STEPS`].
///
/// # Errors
/// The first form's [`GraphError`] (the case then has no bound from the graphs).
pub fn pixel_bounds(
    method: Method,
    form: Form,
    n: u32,
    inputs: &[(f64, f64); 9],
    model: &Model,
) -> Result<Option<Vec<f64>>, GraphError> {
    if n > MAX_GRAPH_STEPS {
        return Ok(None);
    }
    // Under a model whose implementations read each input to nearest, the inputs as
    // they are read (where each is one known number and some differs from the exact).
    let read = model
        .inputs_to_nearest
        .then(|| super::graph::read_to_nearest(inputs, model.format))
        .flatten()
        .filter(|r| r[..] != inputs[..]);
    let mut worst = vec![0f64; n as usize + 1];
    let found = for_each_graph(method, form, n, model, |f| {
        let b = evaluate(&f.graph, inputs, model)?;
        let from_read = read
            .as_ref()
            .and_then(|r| evaluate(&f.graph, r, model).ok());
        // The affine forms (`graph_sound_affine`, `graph_sound_affine_read`), where
        // their conditions hold.
        let (aff, aff_read) = match &f.signs {
            Some(_) => (None, None),
            None => (
                affine(&f.graph, &b),
                from_read.as_ref().and_then(|br| affine(&f.graph, br)),
            ),
        };
        for way in &f.pixels {
            for (i, (w, &p)) in worst.iter_mut().zip(way).enumerate() {
                let e = match &f.signs {
                    // The squared method's value, composed from `g_i` and `p_i`.
                    Some(signs) => squared::signed_root(&b, p, signs[i], model)
                        .ok_or(GraphError::SquaredOutOfRange { node: p })?,
                    // The smallest of the bounds from the exact inputs (`graph_sound`,
                    // `graph_sound_affine`) and from the inputs as read
                    // (`graph_sound_read`, `graph_sound_affine_read`).
                    None => {
                        let mut e = b.err[p];
                        if let Some(a) = &aff {
                            e = e.min(a.err[p]);
                        }
                        if let Some(br) = &from_read {
                            e = e.min(read_error(&b, br, p));
                            if let Some(a) = &aff_read {
                                e = e.min((a.err[p] + read_distance(&b, br, p)).next_up());
                            }
                        }
                        e
                    }
                };
                *w = w.max(e);
            }
        }
        Ok(())
    })?;
    Ok(found.map(|()| worst))
}

/// The largest over the pixels of [`profile_pixel_bounds`] without a vector of them
/// where the graphs do not apply (a method without graphs, or `n` above
/// [`MAX_GRAPH_STEPS`]: the formula alone): `span`'s `error_bound`.
pub fn profile_span_max(
    method: Method,
    profile: super::profile::Profile,
    form: Form,
    shape: &super::Shape,
    format: crate::Format,
) -> Option<f64> {
    if shape.n > MAX_GRAPH_STEPS || method.info().profiles.graphs.is_empty() {
        return super::profile::profile_span_bound(method, profile, form, shape, format);
    }
    profile_pixel_bounds(method, profile, form, shape, None, format)
        .map(|b| b.into_iter().fold(0f64, f64::max))
}

/// The graph model of an acceptance profile in `format` (`docs/float.md` §18.1, the
/// constants of [`super::profile::arith`]); under `shader` a square root is
/// `1/inverseSqrt` (2 ulps, `κ = 4`, then a 2.5-ulp division) and `inverseSqrt` is an
/// operation an implementation may call. `None` where the profile has no model
/// (`reference`, fixed point, binary16).
pub fn model(profile: super::profile::Profile, format: crate::Format) -> Option<Model> {
    let a = super::profile::arith(profile, format)?;
    let shader = profile == super::profile::Profile::Shader;
    Some(Model {
        u: a.u,
        eta: a.eta,
        input: a.input,
        add: a.add,
        mul: a.mul,
        div: a.div,
        half: if shader { a.div } else { a.half },
        sqrt: a.sqrt,
        rsqrt: if shader { 4.0 } else { a.sqrt },
        sqrt_is_recip_rsqrt: shader,
        // Both profiles' implementations start from the nearest floats of the inputs
        // (docs/conformance.md: `shader` is "the same" as `ieee` there).
        inputs_to_nearest: true,
        max: format.max(),
        format,
    })
}

/// The bound of `method` under `profile` at every pixel of the span of `shape`, in
/// `format`: at each pixel the smaller of the profile's formula
/// ([`super::profile::profile_span_bound`], the count theorems) and the operation
/// graphs' bound ([`pixel_bounds`], `graph_sound`) — both proved, so their minimum is
/// a bound. `light` replaces `L` by another unit vector (the half vector `H` of a
/// specular case). `None` where neither gives one; the formula alone where the
/// method has no graph or the graphs none on this case (a divisor or a root that may
/// vanish).
pub fn profile_pixel_bounds(
    method: Method,
    profile: super::profile::Profile,
    form: Form,
    shape: &super::Shape,
    light: Option<[(f64, f64); 3]>,
    format: crate::Format,
) -> Option<Vec<f64>> {
    let formula = super::profile::profile_span_bound(method, profile, form, shape, format);
    let mut inputs = shape.inputs;
    if let Some(h) = light {
        inputs[6..].copy_from_slice(&h);
    }
    let graph = model(profile, format).and_then(|m| {
        pixel_bounds(method, form, shape.n, &inputs, &m)
            .ok()
            .flatten()
    });
    match (formula, graph) {
        (Some(f), Some(g)) => Some(g.into_iter().map(|x| x.min(f)).collect()),
        (Some(f), None) => Some(vec![f; shape.n as usize + 1]),
        // (Callers that want one number for a long span: [`profile_span_max`].)
        (None, g) => g,
    }
}
