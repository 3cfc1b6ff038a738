//! The inputs and the operations the evaluator knows exactly (`docs/float.md` §19.1):
//! exact inputs as `f64` intervals, the inputs as an implementation that rounds to
//! nearest reads them (`graph_sound_read` of `proofs/Graph.v`), and the operations
//! whose result every rounding returns unchanged (`exact_op_model`).

use super::{add_up, up, Bounds, Id, Model, Op};

/// An exact rational as an `f64` interval: `(x, x)` when `x` is an `f64`, else the
/// two neighbours of its nearest `f64`.
pub fn interval(x: &crate::BigRational) -> (f64, f64) {
    use crate::Scalar;
    let f = x.to_f64();
    match crate::BigRational::from_float(f) {
        Some(q) if q == *x => (f, f),
        _ => (f.next_down(), f.next_up()),
    }
}

/// The inputs as an implementation that rounds each to nearest reads them, where
/// that is one number for each: the intervals of the exact inputs (as
/// [`inputs_of`] gives them) whose two ends round to the same number of the format,
/// zero or normal (a flushing implementation reads a subnormal as 0), and no exact
/// input halfway between two of its numbers (which a tie rule may round either way).
/// Binary32: the interval's ends are `f64`s, so the nearest `f32` of the
/// exact input and that of its nearest `f64` (reading through binary64 first) are
/// both the ends' common one. Binary64: only inputs that are already `f64`s (each
/// read exactly). `None` where some input's nearest number is not known this way.
pub fn read_to_nearest(inputs: &[(f64, f64)], format: crate::Format) -> Option<Vec<(f64, f64)>> {
    inputs
        .iter()
        .map(|&(l, h)| {
            let x = match format {
                crate::Format::Binary32 => {
                    let (a, b) = (l as f32, h as f32);
                    let tie = l == h && {
                        let f = f64::from(a);
                        let other = if f < l { a.next_up() } else { a.next_down() };
                        f != l && (f64::from(other) - l).abs() == (f - l).abs()
                    };
                    // A subnormal is left out: a flushing implementation reads it as 0.
                    let x = f64::from(a);
                    (a == b && held_exactly(x, format) && !tie).then_some(x)?
                }
                crate::Format::Binary64 => (l == h && held_exactly(l, format)).then_some(l)?,
                crate::Format::Binary16 => return None,
            };
            Some((x, x))
        })
        .collect()
}

/// `N_a`, `N_b`, `L` as the method graphs' nine input intervals.
pub fn inputs_of(
    na: &crate::Vec3<crate::BigRational>,
    nb: &crate::Vec3<crate::BigRational>,
    l: &crate::Vec3<crate::BigRational>,
) -> [(f64, f64); 9] {
    let mut out = [(0.0, 0.0); 9];
    for (k, v) in [na, nb, l].into_iter().enumerate() {
        for (c, x) in [&v.x, &v.y, &v.z].into_iter().enumerate() {
            out[3 * k + c] = interval(x);
        }
    }
    out
}

/// `graph_sound_read` (`proofs/Graph.v`): the error at node `p` of an execution that
/// reads the inputs as the numbers `read` was evaluated on, from the exact value at
/// the exact inputs `exact` was evaluated on — `read`'s error plus the distance
/// between the two intervals of exact values, rounded up.
pub fn read_error(exact: &Bounds, read: &Bounds, p: Id) -> f64 {
    add_up(read.err[p], read_distance(exact, read, p))
}

/// The distance term of `graph_sound_read` and `graph_sound_affine_read` at node `p`:
/// how far the exact value at the inputs `read` was evaluated on may be from the
/// exact value at the exact inputs, the largest gap between the two intervals,
/// rounded up.
pub fn read_distance(exact: &Bounds, read: &Bounds, p: Id) -> f64 {
    up(read.hi[p] - exact.lo[p])
        .max(up(exact.hi[p] - read.lo[p]))
        .max(0.0)
}

/// Whether every rounding of `x` to `format` is `x` itself, flushing included: `x` is
/// a number of the format, zero or normal (`exact_op_model`).
pub(super) fn held_exactly(x: f64, format: crate::Format) -> bool {
    (x == 0.0 || x.abs() >= format.min_normal()) && format.holds(x)
}

/// The exact result of an addition, subtraction, product or sum (any order) whose
/// operands are known exactly (a point interval, no error), when every way of
/// computing it is exact: each result (for a sum, each partial sum of every order) is
/// a number the format holds — zero or normal, so that flushing does not move it.
/// Such a node rounds nothing, under every profile (each rounds these operations to
/// a neighbouring float, which is the result itself).
pub(super) fn exact_result(
    op: &Op,
    lo: &[f64],
    hi: &[f64],
    err: &[f64],
    model: &Model,
) -> Option<f64> {
    let known = |a: &Id| (lo[*a] == hi[*a] && err[*a] == 0.0).then_some(lo[*a]);
    let held = |r: f64| held_exactly(r, model.format);
    // `a + b` computed in f64 and checked exact (two-sum), then held by the format.
    let add = |a: f64, b: f64| {
        let s = a + b;
        let bb = s - a;
        let exact = (a - (s - bb)) + (b - bb) == 0.0;
        (exact && s.is_finite() && held(s)).then_some(s)
    };
    match op {
        Op::Add(a, b) => add(known(a)?, known(b)?),
        Op::Sub(a, b) => add(known(a)?, -known(b)?),
        Op::Mul(a, b) => {
            let (x, y) = (known(a)?, known(b)?);
            let p = x * y;
            // The residual x·y − p is exact in f64 (a fused multiply-add) unless it is
            // below f64's subnormals, which |p| ≥ 2^-960 rules out.
            let exact =
                x == 0.0 || y == 0.0 || (p.abs() >= 2f64.powi(-960) && x.mul_add(y, -p) == 0.0);
            (p.is_finite() && exact && held(p)).then_some(p)
        }
        Op::Sum(l) if l.len() <= 3 => {
            let t: Vec<f64> = l.iter().map(known).collect::<Option<_>>()?;
            match t.len() {
                1 => Some(t[0]),
                2 => add(t[0], t[1]),
                _ => {
                    for (i, k) in [(0, 1), (0, 2), (1, 2)] {
                        add(t[i], t[k])?;
                    }
                    add(add(t[0], t[1])?, t[2])
                }
            }
        }
        _ => None,
    }
}
