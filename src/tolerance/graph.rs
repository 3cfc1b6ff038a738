//! Operation graphs and their running error bound, per case (`proofs/Graph.v`,
//! `graph_sound`; `docs/float.md` §19).
//!
//! A method's computation — set-up, recurrence, per-pixel value — is written once as
//! a [`Graph`]: a straight-line program of inputs, exact constants, additions,
//! subtractions, products, divisions, square roots, reciprocal square roots and sums
//! in any order. [`evaluate`] computes, for the case's own exact inputs, at every node
//! an interval `[lo, hi]` holding its exact value and a bound `err` on
//! `|computed − exact|` that holds for **every execution** of the graph in which each
//! operation's result is within `v·|x| + η` of its exact result `x` on the computed
//! operands (`ap1` of `proofs/FloatModelK.v`), each node with its own unit
//! `v = κ·u`: any rounding direction at every operation, products fused or not (an
//! exact product is within any bound), each [`Op::Sum`] summed in any order and
//! association, each [`Op::DivE`] a division or a reciprocal and a product. The rules
//! are `iv_ok` and `err_ok` of `proofs/Graph.v`, evaluated here in `f64` rounded
//! outward (every upper bound rounded up, every lower bound down), so that the values
//! computed satisfy the theorem's inequalities and `graph_sound` gives the bound.
//!
//! Tested: `tests/graph.rs` (the rules against exact rationals, executions that round
//! each operation to either neighbouring float, and `graph_sound` by name).

mod affine;
mod exact;
pub use affine::{affine, Affine, KEPT};
use exact::{exact_result, held_exactly};
pub use exact::{inputs_of, interval, read_distance, read_error, read_to_nearest};

/// A node's index in its graph.
pub type Id = usize;

/// One operation (`op` of `proofs/Graph.v`); operands are earlier nodes.
#[derive(Clone, Debug, PartialEq)]
pub enum Op {
    /// Input `i`: an exact real, read (rounded) into the format.
    In(usize),
    /// A constant the format holds exactly (checked): no rounding.
    Cst(f64),
    /// `a + b`.
    Add(Id, Id),
    /// `a − b`.
    Sub(Id, Id),
    /// `a·b` (fused into the addition that takes it or not).
    Mul(Id, Id),
    /// `a/b`, one division.
    Div(Id, Id),
    /// `a/b` as one division **or** as a reciprocal `1/b` then a product, each within
    /// the node's unit (`DivE` of `proofs/Graph.v`).
    DivE(Id, Id),
    /// `√a`.
    Sqrt(Id),
    /// `1/√a` (a GPU's `inverseSqrt`).
    Rsqrt(Id),
    /// A sum of the nodes in any order and association.
    Sum(Vec<Id>),
}

/// The class of an operation, which picks its `κ` in a [`Model`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// Reading an exact input into the format.
    Input,
    /// Additions, subtractions, sums.
    Add,
    /// Products.
    Mul,
    /// Divisions (and reciprocals).
    Div,
    /// A division by 2 (exact under `ieee`, a division under `shader`).
    Half,
    /// Square roots.
    Sqrt,
    /// Reciprocal square roots.
    Rsqrt,
    /// No rounding (constants).
    Exact,
}

/// One node: its operation and the class of its rounding.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// The operation.
    pub op: Op,
    /// Which `κ` of the model its rounding takes.
    pub class: Class,
}

/// A straight-line program, built node by node; every operand is an earlier node.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Graph {
    nodes: Vec<Node>,
    inputs: usize,
}

impl Graph {
    /// An empty graph.
    pub fn new() -> Self {
        Graph::default()
    }

    /// The nodes, in order.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// How many inputs the graph reads (one more than the largest input index).
    pub fn inputs(&self) -> usize {
        self.inputs
    }

    fn push(&mut self, op: Op, class: Class) -> Id {
        let j = self.nodes.len();
        let ok = |a: &Id| *a < j;
        debug_assert!(match &op {
            Op::In(_) | Op::Cst(_) => true,
            Op::Add(a, b) | Op::Sub(a, b) | Op::Mul(a, b) | Op::Div(a, b) | Op::DivE(a, b) =>
                ok(a) && ok(b),
            Op::Sqrt(a) | Op::Rsqrt(a) => ok(a),
            Op::Sum(l) => !l.is_empty() && l.iter().all(ok),
        });
        if let Op::In(i) = op {
            self.inputs = self.inputs.max(i + 1);
        }
        self.nodes.push(Node { op, class });
        j
    }

    /// Input `i`, read into the format.
    pub fn input(&mut self, i: usize) -> Id {
        self.push(Op::In(i), Class::Input)
    }
    /// An exact constant.
    pub fn cst(&mut self, c: f64) -> Id {
        self.push(Op::Cst(c), Class::Exact)
    }
    /// `a + b`.
    pub fn add(&mut self, a: Id, b: Id) -> Id {
        self.push(Op::Add(a, b), Class::Add)
    }
    /// `a − b`.
    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        self.push(Op::Sub(a, b), Class::Add)
    }
    /// `a·b`.
    pub fn mul(&mut self, a: Id, b: Id) -> Id {
        self.push(Op::Mul(a, b), Class::Mul)
    }
    /// `a/b`, one division.
    pub fn div(&mut self, a: Id, b: Id) -> Id {
        self.push(Op::Div(a, b), Class::Div)
    }
    /// `a/b` either way: a division, or `1/b` and a product.
    pub fn div_either(&mut self, a: Id, b: Id) -> Id {
        self.push(Op::DivE(a, b), Class::Div)
    }
    /// `a/2` either way, in the class [`Class::Half`].
    pub fn half(&mut self, a: Id) -> Id {
        let two = self.cst(2.0);
        self.push(Op::DivE(a, two), Class::Half)
    }
    /// `√a`.
    pub fn sqrt(&mut self, a: Id) -> Id {
        self.push(Op::Sqrt(a), Class::Sqrt)
    }
    /// `1/√a`.
    pub fn rsqrt(&mut self, a: Id) -> Id {
        self.push(Op::Rsqrt(a), Class::Rsqrt)
    }
    /// A sum in any order.
    pub fn sum(&mut self, terms: &[Id]) -> Id {
        self.push(Op::Sum(terms.to_vec()), Class::Add)
    }
    /// A three-term dot product: the products (rounded or fused) summed in any order.
    pub fn dot(&mut self, a: [Id; 3], b: [Id; 3]) -> Id {
        let t = [0, 1, 2].map(|c| self.mul(a[c], b[c]));
        self.sum(&t)
    }
}

/// The model a graph is evaluated in: the unit roundoff, the absolute error of one
/// operation near zero, and one `κ` per [`Class`] (`docs/float.md` §18.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Model {
    /// The unit roundoff `u`.
    pub u: f64,
    /// `η`: what one operation may add near zero (subnormals, flushing).
    pub eta: f64,
    /// `κ` of reading an input.
    pub input: f64,
    /// `κ` of an addition or subtraction.
    pub add: f64,
    /// `κ` of a product.
    pub mul: f64,
    /// `κ` of a division or reciprocal.
    pub div: f64,
    /// `κ` of a division by 2.
    pub half: f64,
    /// `κ` of a square root.
    pub sqrt: f64,
    /// `κ` of a reciprocal square root.
    pub rsqrt: f64,
    /// Whether a square root is `1/inverseSqrt` (the GPU specifications' `sqrt`):
    /// the method graphs then build it as a reciprocal square root and a division.
    pub sqrt_is_recip_rsqrt: bool,
    /// Whether every implementation reads each input as its nearest number of the
    /// format (`ieee` and `shader`: both start from the nearest floats of the inputs):
    /// the bound may then start from the inputs as read ([`read_to_nearest`],
    /// `graph_sound_read` of `proofs/Graph.v`).
    pub inputs_to_nearest: bool,
    /// The largest finite value of the format: a node whose interval reaches past it
    /// may overflow, and has no bound.
    pub max: f64,
    /// Whether a constant `c` is held exactly by the format (checked per [`Op::Cst`]).
    pub format: crate::Format,
}

impl Model {
    /// The `κ` of a class.
    pub fn kappa(&self, class: Class) -> f64 {
        match class {
            Class::Input => self.input,
            Class::Add => self.add,
            Class::Mul => self.mul,
            Class::Div => self.div,
            Class::Half => self.half,
            Class::Sqrt => self.sqrt,
            Class::Rsqrt => self.rsqrt,
            Class::Exact => 0.0,
        }
    }
}

/// Why a graph has no bound on a case (the theorem's conditions fail).
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum GraphError {
    /// A divisor's interval, widened by its error, may reach zero.
    #[error("node {node}: the divisor may be zero within its error")]
    DivisorMayVanish {
        /// The division.
        node: Id,
    },
    /// A square root's (or reciprocal square root's) argument may be too close to
    /// zero, or negative, within its error.
    #[error("node {node}: the square root's argument may reach zero within its error")]
    RootMayVanish {
        /// The root.
        node: Id,
    },
    /// A constant the format does not hold exactly.
    #[error("node {node}: the constant is not exact in the format")]
    InexactConstant {
        /// The constant.
        node: Id,
    },
    /// A value (or its bound) past the format's largest finite value.
    #[error("node {node}: the value may overflow the format")]
    Overflow {
        /// The node.
        node: Id,
    },
    /// The squared method's value, composed outside its graph, needs `|g̃| ≤ 9` for
    /// the root's rounding (`docs/float.md` §19.7), which the node's interval and
    /// error do not show.
    #[error("node {node}: the squared value may exceed 9, past the root's derived rounding")]
    SquaredOutOfRange {
        /// The `g_i` node.
        node: Id,
    },
    /// An input index with no interval, or an interval that is not one.
    #[error("node {node}: input {input} has no valid interval")]
    Input {
        /// The node.
        node: Id,
        /// The input index.
        input: usize,
    },
}

/// Each node's certificate: the interval of its exact value and its error bound.
#[derive(Clone, Debug, PartialEq)]
pub struct Bounds {
    /// Lower ends of the exact values' intervals.
    pub lo: Vec<f64>,
    /// Upper ends.
    pub hi: Vec<f64>,
    /// Bounds on `|computed − exact|`, for every execution the model allows.
    pub err: Vec<f64>,
    /// `S j` of the theorem: a positive lower bound of the exact root of a
    /// [`Op::Sqrt`] (of the computed and the exact operand's of an [`Op::Rsqrt`]); 0
    /// elsewhere.
    pub s: Vec<f64>,
    /// `T j`: a lower bound (≥ 0) of the computed operand's root of an [`Op::Sqrt`]; 0
    /// elsewhere.
    pub t: Vec<f64>,
    /// Each node's unit `v` (`nv`): `κ·u` in the relative model, 0 in the ulp model.
    pub v: Vec<f64>,
    /// Each node's absolute term `η` (`neta`): the format's `η` in the relative model,
    /// `κ/2` ulps of the largest result the operation can have, plus it, in the ulp
    /// model.
    pub eta: Vec<f64>,
    /// `nez` of every sum that rounds: how far an addition of an exact zero may move
    /// the other operand — the format's `η` (a subnormal flushed to zero; 0 would do
    /// where nothing flushes, a float plus 0 being that float). An exact node's is 0.
    pub ez: f64,
}

// Outward rounding: the operations of f64 round to nearest, so the neighbouring float
// on the chosen side bounds the exact result.
fn up(x: f64) -> f64 {
    x.next_up()
}
fn dn(x: f64) -> f64 {
    x.next_down()
}
fn add_up(a: f64, b: f64) -> f64 {
    up(a + b)
}
fn mul_up(a: f64, b: f64) -> f64 {
    up(a * b)
}
fn div_up(a: f64, b: f64) -> f64 {
    up(a / b)
}

/// The shape of a sum's rule (`err_ok` of `proofs/Graph.v`, `loc_ok` of
/// `GraphAffine.v`): its `k` terms, the `m = live − 1` additions that may round (a
/// term known to be 0 — interval `[0, 0]`, no error — adds without rounding,
/// `sum_exec_err`) and `w = (1 + v)^m`, rounded up.
fn sum_shape(terms: &[Id], lo: &[f64], hi: &[f64], err: &[f64], v: f64) -> (usize, usize, f64) {
    let live = terms
        .iter()
        .filter(|&&t| !(lo[t] == 0.0 && hi[t] == 0.0 && err[t] == 0.0))
        .count();
    let m = live.max(1) - 1;
    let w = (0..m).fold(1.0, |w, _| mul_up(w, add_up(1.0, v)));
    (terms.len(), m, w)
}

/// `mag lo hi = max(|lo|, |hi|)` (exact).
fn mag(lo: f64, hi: f64) -> f64 {
    lo.abs().max(hi.abs())
}

/// `d + v·(m + d) + η`, rounded up: the common tail of every rule.
fn rounded(d: f64, v: f64, m: f64, eta: f64) -> f64 {
    add_up(add_up(d, mul_up(v, add_up(m, d))), eta)
}

/// The smallest and the largest of four corner values, outward.
fn corners(f: impl Fn(f64, f64) -> f64, a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let c = [f(a.0, b.0), f(a.0, b.1), f(a.1, b.0), f(a.1, b.1)];
    let lo = c.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = c.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (dn(lo), up(hi))
}

/// A positive `s` with `s·s ≤ x` (rounded), or `None` for `x ≤ 0`.
fn root_below(x: f64) -> Option<f64> {
    if x.is_nan() || x <= 0.0 {
        return None;
    }
    let mut s = dn(x.sqrt());
    while s > 0.0 && mul_up(s, s) > x {
        s = dn(s);
    }
    (s > 0.0).then_some(s)
}

/// Evaluates `graph` on exact inputs given as intervals `[lo, hi]` (one per input
/// index; an exact input is `(x, x)` when `x` is an `f64`): each node's interval and
/// error bound by the rules of `proofs/Graph.v` (`iv_ok`, `err_ok`), rounded outward.
///
/// # Errors
/// A [`GraphError`] naming the first node where the theorem's conditions fail.
pub fn evaluate(graph: &Graph, inputs: &[(f64, f64)], model: &Model) -> Result<Bounds, GraphError> {
    let len = graph.nodes.len();
    let (mut lo, mut hi, mut err) = (
        Vec::with_capacity(len),
        Vec::with_capacity(len),
        Vec::<f64>::with_capacity(len),
    );
    let (mut sj, mut tj) = (vec![0.0; len], vec![0.0; len]);
    let (mut vj, mut etaj) = (vec![0.0; len], vec![0.0; len]);
    let eta = model.eta;
    let ez = model.eta;
    for (j, node) in graph.nodes.iter().enumerate() {
        let v = mul_up(model.kappa(node.class), model.u);
        // The ulp model's η for a result of magnitude at most `mag`: κ/2 ulps of the
        // format there, and the format's η (flushing).
        let ulp_eta = |mag: f64| {
            add_up(
                mul_up(model.kappa(node.class) / 2.0, model.format.ulp(up(mag))),
                eta,
            )
        };
        // Of the two models, the one giving the smaller bound: `(E, v, η)`.
        let best = |d: f64, m: f64| {
            let rel = rounded(d, v, m, eta);
            let ue = ulp_eta(add_up(m, d));
            let abs = rounded(d, 0.0, m, ue);
            if abs < rel {
                (abs, 0.0, ue)
            } else {
                (rel, v, eta)
            }
        };
        let mut node_v = (v, eta);
        if let Some(r) = exact_result(&node.op, &lo, &hi, &err, model) {
            // Operands known exactly and a result the format holds (normal, or zero):
            // every rounding returns it (`exact_op_model`).
            lo.push(r);
            hi.push(r);
            err.push(0.0);
            (vj[j], etaj[j]) = (0.0, 0.0);
            continue;
        }
        let (l, h, e) = match &node.op {
            Op::In(i) => {
                let &(l, h) = inputs
                    .get(*i)
                    .filter(|(l, h)| l.is_finite() && h.is_finite() && l <= h)
                    .ok_or(GraphError::Input { node: j, input: *i })?;
                if l == h && held_exactly(l, model.format) {
                    // A value the format holds, zero or normal (flushing moves only
                    // subnormals), is read exactly, by any rounding (`exact_op_model`).
                    node_v = (0.0, 0.0);
                    (l, h, 0.0)
                } else {
                    let (e, nv, ne) = best(0.0, mag(l, h));
                    node_v = (nv, ne);
                    (l, h, e)
                }
            }
            Op::Cst(c) => {
                if !model.format.holds(*c) {
                    return Err(GraphError::InexactConstant { node: j });
                }
                node_v = (0.0, 0.0);
                (*c, *c, 0.0)
            }
            Op::Add(a, b) | Op::Sub(a, b) => {
                let (l, h) = if matches!(node.op, Op::Add(..)) {
                    (dn(lo[*a] + lo[*b]), up(hi[*a] + hi[*b]))
                } else {
                    (dn(lo[*a] - hi[*b]), up(hi[*a] - lo[*b]))
                };
                let d = add_up(err[*a], err[*b]);
                let (e, nv, ne) = best(d, mag(l, h));
                node_v = (nv, ne);
                (l, h, e)
            }
            Op::Mul(a, b) => {
                let (l, h) = corners(|x, y| x * y, (lo[*a], hi[*a]), (lo[*b], hi[*b]));
                let (ma, mb) = (mag(lo[*a], hi[*a]), mag(lo[*b], hi[*b]));
                let d = add_up(
                    add_up(mul_up(ma, err[*b]), mul_up(mb, err[*a])),
                    mul_up(err[*a], err[*b]),
                );
                let (e, nv, ne) = best(d, mag(l, h));
                node_v = (nv, ne);
                (l, h, e)
            }
            Op::Div(a, b) | Op::DivE(a, b) => {
                let (bl, bh) = (lo[*b], hi[*b]);
                if !(bl > 0.0 || bh < 0.0) {
                    return Err(GraphError::DivisorMayVanish { node: j });
                }
                let (l, h) = corners(|x, y| x / y, (lo[*a], hi[*a]), (bl, bh));
                let m = mag(l, h);
                let lb = bl.abs().min(bh.abs());
                let gap = dn(lb - err[*b]);
                if gap.is_nan() || gap <= 0.0 {
                    return Err(GraphError::DivisorMayVanish { node: j });
                }
                let d = div_up(add_up(err[*a], mul_up(m, err[*b])), gap);
                let mut e = rounded(d, v, m, eta);
                if matches!(node.op, Op::Div(..)) {
                    let (e2, nv, ne) = best(d, m);
                    e = e2;
                    node_v = (nv, ne);
                } else {
                    // The reciprocal and the product (`DivE` in proofs/Graph.v):
                    // d + v(2 + v)(m + d) + (1 + v)(|a| + E_a)η + η.
                    let ya = add_up(mag(lo[*a], hi[*a]), err[*a]);
                    let two_v = mul_up(v, add_up(2.0, v));
                    let recip = add_up(
                        add_up(
                            add_up(d, mul_up(two_v, add_up(m, d))),
                            mul_up(add_up(1.0, v), mul_up(ya, eta)),
                        ),
                        eta,
                    );
                    e = e.max(recip);
                }
                (l, h, e)
            }
            Op::Sqrt(a) => {
                let s = root_below(lo[*a]).ok_or(GraphError::RootMayVanish { node: j })?;
                if err[*a].is_nan() || err[*a] > dn(s * s) {
                    return Err(GraphError::RootMayVanish { node: j });
                }
                let h = {
                    let mut h = up(hi[*a].max(0.0).sqrt());
                    while dn(h * h) < hi[*a] {
                        h = up(h);
                    }
                    h
                };
                // √y_a ≥ s2 with s2² ≤ lo_a − E_a (0 where that is not positive):
                // |√y_a − √x_a| = |y_a − x_a|/(√y_a + √x_a) ≤ E_a/(s + s2).
                let s2 = root_below(dn(lo[*a] - err[*a])).unwrap_or(0.0);
                (sj[j], tj[j]) = (s, s2);
                let d = div_up(err[*a], dn(s + s2));
                let (e, nv, ne) = best(d, mag(s, h));
                node_v = (nv, ne);
                (s, h, e)
            }
            Op::Rsqrt(a) => {
                let s = root_below(dn(lo[*a] - err[*a]))
                    .ok_or(GraphError::RootMayVanish { node: j })?;
                // lo ≤ 1/√hi_a: lo·lo·hi_a ≤ 1.
                let mut l = dn(1.0 / hi[*a].sqrt());
                while l > 0.0 && mul_up(mul_up(l, l), hi[*a]) > 1.0 {
                    l = dn(l);
                }
                if l.is_nan() || l <= 0.0 {
                    return Err(GraphError::RootMayVanish { node: j });
                }
                // hi ≥ 1/s: hi·s ≥ 1.
                let mut h = up(1.0 / s);
                while dn(h * s) < 1.0 {
                    h = up(h);
                }
                sj[j] = s;
                let d = div_up(err[*a], dn(2.0 * dn(dn(s * s) * s)));
                let (e, nv, ne) = best(d, h);
                node_v = (nv, ne);
                (l, h, e)
            }
            Op::Sum(terms) => {
                let (mut l, mut h, mut se, mut sm) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
                for &t in terms {
                    l = dn(l + lo[t]);
                    h = up(h + hi[t]);
                    se = add_up(se, err[t]);
                    sm = add_up(sm, add_up(mag(lo[t], hi[t]), err[t]));
                }
                let (k, m, w) = sum_shape(terms, &lo, &hi, &err, v);
                let zeros = mul_up(mul_up((k - 1) as f64, w), ez);
                let mut e = add_up(
                    add_up(
                        add_up(se, mul_up(up(w - 1.0), sm)),
                        mul_up(mul_up(m as f64, w), eta),
                    ),
                    zeros,
                );
                // The ulp model: every partial sum is at most sm + (k − 2)·η' ≤ M, with
                // η' the rounding at M: the smallest such M of a few tries.
                let extra = |mm: f64| add_up(sm, mul_up((k.max(2) - 2) as f64, ulp_eta(mm)));
                let mut mm = sm;
                for _ in 0..4 {
                    if extra(mm) <= mm {
                        break;
                    }
                    mm = extra(mm);
                }
                let ue = ulp_eta(mm);
                let partial = extra(mm);
                let abs = add_up(add_up(se, mul_up(m as f64, ue)), mul_up((k - 1) as f64, ez));
                if partial <= mm && abs < e {
                    e = abs;
                    node_v = (0.0, ue);
                }
                (l, h, e)
            }
        };
        if !(l.is_finite() && h.is_finite() && e.is_finite()) || mag(l, h) + e > model.max {
            return Err(GraphError::Overflow { node: j });
        }
        lo.push(l);
        hi.push(h);
        err.push(e);
        (vj[j], etaj[j]) = node_v;
    }
    Ok(Bounds {
        lo,
        hi,
        err,
        s: sj,
        t: tj,
        v: vj,
        eta: etaj,
        ez,
    })
}
