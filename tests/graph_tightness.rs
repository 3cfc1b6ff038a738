//! How sharp the bound `check` applies under `ieee` and `shader` is, against code that
//! can exist (docs/float.md §19.5): the methods' operation graphs executed in binary32,
//! every operation rounded as a legal implementation rounds it — under `ieee` to
//! nearest, with the order of each sum, the fusion of its products and the way of each
//! division (`/b` or `·(1/b)`) chosen to push the error; under `shader` each addition
//! and product to either neighbouring float, each division 2 ulps and each
//! `inverseSqrt` 2 ulps from the exact result (within the 2.5 and 2 ulps the
//! specifications allow) and results below `2^-126` flushed to zero (both profiles
//! read each input as its nearest float, as they start from), each choice in
//! the direction that moves the target pixel the same way (the sign of its
//! sensitivity, from the exact values). Every form of the method is run, for three
//! target pixels and both directions; the case's ratio is the worst
//! `|result − exact| / bound` over its pixels.

use super::graph::{inputs, METHODS};
use super::*;
use phong_approx::tolerance::graph::{evaluate, Graph, Model, Op};
use phong_approx::tolerance::graphs::{method_graphs, model, profile_pixel_bounds};

/// The binary32 floats next to the real `t` (given in `f64`, in which every binary32
/// operation's exact result on binary32 operands is exact or correctly rounded):
/// `(below, above)`, equal when `t` is a binary32.
fn neighbours(t: f64) -> (f64, f64) {
    let f = t as f32;
    let ff = f64::from(f);
    if ff == t {
        (ff, ff)
    } else if ff < t {
        (ff, f64::from(f.next_up()))
    } else {
        (f64::from(f.next_down()), ff)
    }
}

/// `k` binary32 ulps from the nearest float to `t`, toward `dir` (±1).
fn ulps_from(t: f64, k: u32, dir: f64) -> f64 {
    let mut f = t as f32;
    for _ in 0..k {
        f = if dir > 0.0 {
            f.next_up()
        } else {
            f.next_down()
        };
    }
    f64::from(f)
}

/// The sensitivity of `target` to a change at every node (reverse mode at `mid`, the
/// midpoints of the evaluator's intervals: near the exact values, which is all the
/// signs of the sensitivities need; the errors are measured against the method's exact
/// values, [`ratio`]).
fn sensitivities(g: &Graph, mid: &[f64], target: usize) -> Vec<f64> {
    let mut adj = vec![0f64; g.nodes().len()];
    adj[target] = 1.0;
    for j in (0..=target).rev() {
        let a = adj[j];
        if a == 0.0 {
            continue;
        }
        match &g.nodes()[j].op {
            Op::Add(x, y) => {
                adj[*x] += a;
                adj[*y] += a;
            }
            Op::Sub(x, y) => {
                adj[*x] += a;
                adj[*y] -= a;
            }
            Op::Mul(x, y) => {
                adj[*x] += a * mid[*y];
                adj[*y] += a * mid[*x];
            }
            Op::Div(x, y) | Op::DivE(x, y) => {
                adj[*x] += a / mid[*y];
                adj[*y] -= a * mid[*x] / (mid[*y] * mid[*y]);
            }
            Op::Sqrt(x) => adj[*x] += a / (2.0 * mid[*x].sqrt()),
            Op::Rsqrt(x) => adj[*x] -= a / (2.0 * mid[*x] * mid[*x].sqrt()),
            Op::Sum(l) => {
                for &t in l {
                    adj[t] += a;
                }
            }
            Op::In(_) | Op::Cst(_) => {}
        }
    }
    adj
}

/// One legal binary32 execution of `g`, each choice pushing the target's error toward
/// `sign` (`adj`: the target's sensitivities). Returns every node's value.
fn execute(g: &Graph, x_in: &[f64; 9], adj: &[f64], sign: f64, shader: bool) -> Vec<f64> {
    let mut y = vec![0f64; g.nodes().len()];
    // The float a legal implementation may return for the exact result `t` of node
    // `j`, pushed toward the target's `sign`: `kind` 0 faithful (shader) or nearest
    // (ieee), 2 for 2-ulp operations (shader's division and inverseSqrt).
    let pick = |t: f64, j: usize, ulps: u32| -> f64 {
        let dir = sign * adj[j].signum();
        if !shader {
            return f64::from(t as f32);
        }
        let v = if ulps == 0 {
            let (lo, hi) = neighbours(t);
            if dir > 0.0 {
                hi
            } else {
                lo
            }
        } else {
            ulps_from(t, ulps, dir)
        };
        // Flushing a result below the normal range to zero is allowed.
        if v.abs() < 2f64.powi(-126) && (0.0 - t) * dir > (v - t) * dir {
            0.0
        } else {
            v
        }
    };
    for (j, node) in g.nodes().iter().enumerate() {
        let push = sign * adj[j];
        y[j] = match &node.op {
            Op::In(i) => {
                // Both profiles read the nearest float of each input; under `shader` a
                // subnormal one may be flushed to zero.
                let v = f64::from(x_in[*i] as f32);
                let dir = sign * adj[j].signum();
                if shader && v != 0.0 && v.abs() < 2f64.powi(-126) && -v * dir > 0.0 {
                    0.0
                } else {
                    v
                }
            }
            Op::Cst(c) => *c,
            Op::Add(a, b) | Op::Sub(a, b) => {
                let sub = matches!(node.op, Op::Sub(..));
                let both = |u: f64, w: f64| if sub { u - w } else { u + w };
                // Each operand that is a product may be kept exact inside the addition
                // (a fused multiply-add: one product per addition).
                let exact_of = |t: usize| match g.nodes()[t].op {
                    Op::Mul(c, d) => Some(y[c] * y[d]),
                    _ => None,
                };
                let t = both(y[*a], y[*b]);
                let mut best = pick(t, j, 0);
                let fused = [
                    exact_of(*a).map(|ea| both(ea, y[*b])),
                    exact_of(*b).map(|eb| both(y[*a], eb)),
                ];
                for f in fused.into_iter().flatten() {
                    let v = pick(f, j, 0);
                    if (v - t) * push > (best - t) * push {
                        best = v;
                    }
                }
                best
            }
            Op::Mul(a, b) => pick(y[*a] * y[*b], j, 0),
            Op::Div(a, b) => pick(y[*a] / y[*b], j, if shader { 2 } else { 0 }),
            Op::DivE(a, b) => {
                let t = y[*a] / y[*b];
                let direct = pick(t, j, if shader { 2 } else { 0 });
                // The reciprocal, then the product.
                let r = if shader {
                    ulps_from(1.0 / y[*b], 2, sign * adj[j].signum() * y[*a].signum())
                } else {
                    f64::from((1.0 / y[*b]) as f32)
                };
                let recip = pick(y[*a] * r, j, 0);
                if (recip - t) * push > (direct - t) * push {
                    recip
                } else {
                    direct
                }
            }
            Op::Sqrt(a) => pick(y[*a].sqrt(), j, 0),
            Op::Rsqrt(a) => pick(1.0 / y[*a].sqrt(), j, 2),
            Op::Sum(l) => sum(g, &y, l, |t| pick(t, j, 0), push),
        };
    }
    y
}

/// A three-term sum in the order and fusion that pushes most toward `push`: each
/// pairing, each product (where a term is a product) rounded or kept exact inside
/// the addition that takes it (a fused multiply-add).
fn sum(g: &Graph, y: &[f64], l: &[usize], round: impl Fn(f64) -> f64, push: f64) -> f64 {
    // A term's values: rounded as computed, and exact where it is a product.
    let forms = |t: usize| -> Vec<f64> {
        match g.nodes()[t].op {
            Op::Mul(a, b) => {
                let (x, y2) = (y[a], y[b]);
                vec![y[t], x * y2]
            }
            _ => vec![y[t]],
        }
    };
    let exact: f64 = l
        .iter()
        .map(|&t| match g.nodes()[t].op {
            Op::Mul(a, b) => y[a] * y[b],
            _ => y[t],
        })
        .sum();
    let mut best = f64::NAN;
    let k = l.len();
    let orders: Vec<[usize; 3]> = if k == 3 {
        vec![[0, 1, 2], [0, 2, 1], [1, 2, 0]]
    } else {
        return round(l.iter().map(|&t| y[t]).sum());
    };
    for o in orders {
        for f0 in forms(l[o[0]]) {
            for f1 in forms(l[o[1]]) {
                // At most one exact product per addition (an FMA has one product).
                if f0 != y[l[o[0]]] && f1 != y[l[o[1]]] {
                    continue;
                }
                let r = round(f0 + f1);
                for f2 in forms(l[o[2]]) {
                    let v = round(r + f2);
                    if best.is_nan() || (v - exact) * push > (best - exact) * push {
                        best = v;
                    }
                }
            }
        }
    }
    best
}

/// The worst fraction of the applied bound that the legal executions reach on `s`
/// for `method` under `profile` (binary32), or `None` where there is no bound.
fn ratio(method: Method, profile: Profile, s: &Span<Q>) -> Option<f64> {
    let shape = phong_approx::tolerance::Shape::of(s);
    let bound = profile_pixel_bounds(method, profile, Form::Any, &shape, None, Format::Binary32)?;
    let m: Model = model(profile, Format::Binary32)?;
    let iv = inputs(s);
    let x_in: [f64; 9] = iv.map(|(l, h)| (l + h) / 2.0);
    let n = s.n as usize;
    // The method's exact values (Phong's square roots to 2^-256): the graphs' pixel
    // intervals hold them but are wide on long recurrences (outward rounding widens
    // every step), so their midpoints are no measure of an error there.
    let exact: Vec<f64> = method.values(s).ok()?.iter().map(|v| v.to_f64()).collect();
    let mut worst = 0f64;
    for f in method_graphs(method, Form::Any, s.n, &m)? {
        let Ok(b) = evaluate(&f.graph, &iv, &m) else {
            continue;
        };
        let mid: Vec<f64> = b.lo.iter().zip(&b.hi).map(|(l, h)| (l + h) / 2.0).collect();
        for pixels in &f.pixels {
            // The targets: the last pixel, the middle one, and the one whose bound is
            // largest relative to the applied bound's.
            let widest = (0..=n)
                .max_by(|&i, &k| b.err[pixels[i]].total_cmp(&b.err[pixels[k]]))
                .unwrap_or(n);
            // Every pixel of a short span; else the last, the middle, the quarters and
            // the one with the largest bound.
            let targets: Vec<usize> = if n <= 16 {
                (0..=n).collect()
            } else {
                vec![n, n / 2, n / 4, 3 * n / 4, widest]
            };
            for target in targets {
                let adj = sensitivities(&f.graph, &mid, pixels[target]);
                for sign in [1.0, -1.0] {
                    let y = execute(&f.graph, &x_in, &adj, sign, profile == Profile::Shader);
                    for (i, &p) in pixels.iter().enumerate() {
                        let e = (y[p] - exact[i]).abs();
                        if e.is_finite() {
                            worst = worst.max(e / bound[i]);
                        }
                    }
                }
            }
        }
    }
    Some(worst)
}

/// The ratios per method and profile over `spans`: (the largest over the cases with
/// n ≤ 64, the largest, the median over the cases with a non-zero error, cases).
fn stats(method: Method, profile: Profile, spans: &[Span<Q>]) -> (f64, f64, f64, usize) {
    let mut short = 0f64;
    let mut all = Vec::new();
    for s in spans {
        if let Some(r) = ratio(method, profile, s) {
            // A legal execution beyond the bound would be a false rejection.
            assert!(
                r <= 1.0,
                "{method} {profile}: a legal binary32 execution is {r} × the bound on the span n = {} \
                 (N_a {:?}, N_b {:?}, L {:?})",
                s.n,
                [&s.na.x, &s.na.y, &s.na.z].map(|v| v.to_f64()),
                [&s.nb.x, &s.nb.y, &s.nb.z].map(|v| v.to_f64()),
                [&s.l.x, &s.l.y, &s.l.z].map(|v| v.to_f64())
            );
            if s.n <= 64 {
                short = short.max(r);
            }
            all.push(r);
        }
    }
    let worst = all.iter().copied().fold(0f64, f64::max);
    let mut nz: Vec<f64> = all.iter().copied().filter(|&r| r > 0.0).collect();
    nz.sort_by(f64::total_cmp);
    let median = nz.get(nz.len() / 2).copied().unwrap_or(0.0);
    (short, worst, median, all.len())
}

/// The sharpness targets of docs/float.md §19.5 on the published sets: per method and
/// profile, the worst legal error reaches at least 1/4 of the applied bound on some
/// case with n ≤ 64, at least 1/10 on some case, and its median over the cases with
/// a non-zero error is at least 1/10 of it. The default tier runs the `paper` set
/// (spans up to n = 256), the extensive tier every set and prints the table.
#[test]
fn legal_executions_reach_the_bounds() {
    let sets: &[&str] = if extensive() {
        &phong_approx::testkit::SETS
    } else {
        &["paper"]
    };
    let mut rows = Vec::new();
    let mut failures = Vec::new();
    for &set in sets {
        let spans: Vec<Span<Q>> = {
            let mut v: Vec<(String, Span<Q>)> = published_spans(set).into_iter().collect();
            v.sort_by(|a, b| a.0.cmp(&b.0));
            v.into_iter()
                .map(|(_, s)| s)
                .filter(|s| s.n <= tiered(256, 4096))
                .collect()
        };
        for method in METHODS {
            for profile in [Profile::Ieee, Profile::Shader] {
                let (short, worst, median, cases) = stats(method, profile, &spans);
                rows.push(format!(
                    "| {set} | {method} | {profile} | {cases} | {:.2} | {:.2} | {:.2} |",
                    short, worst, median
                ));
                let want = [0.25, 0.1, 0.1];
                let got = [short, worst, median];
                if got.iter().zip(&want).any(|(g, w)| g < w) {
                    failures.push(format!("{set} {method} {profile}: {got:.3?} < {want:?}"));
                }
            }
        }
    }
    println!("| set | method | profile | cases | max r, n ≤ 64 | max r | median r |");
    println!("|---|---|---|---:|---:|---:|---:|");
    for r in &rows {
        println!("{r}");
    }
    assert!(
        failures.is_empty(),
        "below the targets:\n{}",
        failures.join("\n")
    );
}

/// The spans the bounds are searched on beside the published sets (docs/float.md
/// §19.5): the edge and targeted spans of `tests/common` — n from 1 to 4096, normals
/// 170° to 179.7° apart, a light along the span, grazing light, `N_a = N_b` — and
/// seeded random spans of `arb_targeted` (near-opposite normals at any `n` next to a
/// power of two), up to n = 16 in the default tier and 4096 in the extensive one.
fn searched_spans() -> Vec<Span<Q>> {
    use proptest::strategy::{Strategy, ValueTree};
    let mut cases = edge_cases();
    cases.extend(targeted_cases());
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    for _ in 0..tiered(8, 48) {
        cases.push(arb_targeted().new_tree(&mut runner).unwrap().current());
    }
    cases
        .iter()
        .filter_map(|c| c.span())
        .filter(|s| s.n <= tiered(16, 4096))
        .collect()
}

/// The sharpness target on the searched spans (docs/float.md §19.5): per method and
/// profile, the worst legal error reaches at least 1/10 of the applied bound on some
/// searched span. The extensive tier prints the table's rows.
#[test]
fn legal_executions_reach_the_bounds_on_searched_spans() {
    let spans = searched_spans();
    assert!(spans.len() >= tiered(8, 40), "{} spans", spans.len());
    let mut failures = Vec::new();
    println!("| method | profile | spans | max r, n ≤ 64 | max r | median r |");
    println!("|---|---|---:|---:|---:|---:|");
    for method in METHODS {
        for profile in [Profile::Ieee, Profile::Shader] {
            let (short, worst, median, cases) = stats(method, profile, &spans);
            println!("| {method} | {profile} | {cases} | {short:.2} | {worst:.2} | {median:.2} |");
            if worst < 0.1 {
                failures.push(format!("{method} {profile}: max r {worst:.3} < 0.1"));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "below the target:\n{}",
        failures.join("\n")
    );
}
