//! The affine error forms (`phong_approx::tolerance::graph::affine`,
//! `proofs/GraphAffine.v`): the certificates the evaluator computes satisfy the
//! theorem's rules exactly, and binary32 runs stay within the bounds they give.

use super::graph::{exact, inputs, run_f32, METHODS};
use super::*;
use phong_approx::tolerance::graph::{affine, evaluate, read_to_nearest, Affine, Bounds, Op};
use phong_approx::tolerance::graphs::{method_graphs, model};

/// The rules of `proofs/GraphAffine.v` that the certificate test checks, as the file
/// states them (whitespace aside): an edit of one fails the test.
const GRAPH_AFFINE_V_RULES: [&str; 18] = [
    "forall u q, / hi b <= u <= / lo b -> lo j <= q <= hi j -> Rabs u * R0 a + Rabs (q * u) * R0 b + (F a + Rabs q * F b) * F b * (u * u) / (1 - Rabs u * F b) + dev (fun k => u * fm M a k - q * u * fm M b k) <= R0 j)",
    "(forall s, S j <= s <= hi j -> R0 a / (2 * s) + F a * F a / (2 * s * ((s + T j) * (s + T j))) + dev (fun k => fm M a k / (2 * s)) <= R0 j)",
    "| _ => v < 1 /\\ v * (m + E j) + eta <= (1 - v) * e j",
    "v * (2 + v) * (m + E j) + (1 + v) * (mag (lo a) (hi a) + E a) * eta + eta <= (1 - v * (2 + v)) * e j",
    "(w - 1) * sumR (fun i => mag (lo i) (hi i) + E i) l + INR m * w * eta + INR (k - 1) * w * nez (g j) <= e j",
    "let dev c := sumR (fun k => Rabs (c k - pm M j k) * e k) (seq 0 N) in",
    "let opaque d := d + sumR (fun k => Rabs (pm M j k) * e k) (seq 0 N) <= R0 j in",
    "| In _ | Cst _ => opaque 0",
    "| Add a b => R0 a + R0 b + dev (fun k => fm M a k + fm M b k) <= R0 j",
    "| Sub a b => R0 a + R0 b + dev (fun k => fm M a k - fm M b k) <= R0 j",
    "mag (lo b) (hi b) * R0 a + mag (lo a) (hi a) * R0 b + F a * F b + sumR (fun k => (Rabs (cen lo hi b * fm M a k + cen lo hi a * fm M b k - pm M j k) + rad lo hi b * Rabs (fm M a k) + rad lo hi a * Rabs (fm M b k)) * e k)",
    "(lo b = hi b /\\ E b = 0 /\\ R0 a / Rabs (lo b) + dev (fun k => fm M a k / lo b) <= R0 j)",
    "F b < lb /\\ opaque ((F a + mag (lo j) (hi j) * F b) / (lb - F b)))",
    "| Sqrt a => opaque (F a / (S j + T j))",
    "| Rsqrt a => opaque (F a / (2 * (S j * S j * S j)))",
    "| Sum l => sumR R0 l + dev (fun k => sumR (fun t => fm M t k) l) <= R0 j",
    "sumR (fun k => Rabs (fm M a k) * e k) (seq 0 N) + R0 a.",
    "Rabs (y j - x j) <= ferr N M R0 e j + Rmax (hir j - lo j) (hi j - lor j).",
];

fn q(x: f64) -> Q {
    Q::from_float(x).unwrap()
}

/// A form as a map from symbol to rational coefficient.
type Sparse = std::collections::BTreeMap<usize, Q>;

/// `fm M a`: node `a`'s stored form and 1 on itself.
fn fm(af: &Affine, a: usize) -> Sparse {
    let mut f: Sparse = af.forms[a].iter().map(|&(k, m)| (k, q(m))).collect();
    f.insert(a, Q::from_integer(1.into()));
    f
}

/// `Σ_k |c_k − p_k|·e_k` over the union of the two supports.
fn dev(c: &Sparse, p: &Sparse, e: &[Q]) -> Q {
    let keys: std::collections::BTreeSet<usize> = c.keys().chain(p.keys()).copied().collect();
    keys.into_iter()
        .map(|k| {
            let ck = c.get(&k).cloned().unwrap_or_else(Q::zero);
            let pk = p.get(&k).cloned().unwrap_or_else(Q::zero);
            (ck - pk).abs() * &e[k]
        })
        .sum()
}

/// Checks `loc_ok` and `aff_ok` of `proofs/GraphAffine.v` at every node, in rationals,
/// and that `err` is at least `ferr`; returns the number of nodes.
fn check_rules(
    g: &phong_approx::tolerance::graph::Graph,
    b: &Bounds,
    af: &Affine,
    what: &str,
) -> usize {
    let r = |v: &[f64]| v.iter().map(|&x| q(x)).collect::<Vec<Q>>();
    let (lo, hi, big_e, s, t) = (r(&b.lo), r(&b.hi), r(&b.err), r(&b.s), r(&b.t));
    let (e, rem) = (r(&af.e), r(&af.rem));
    let (zero, one, two) = (
        Q::zero(),
        Q::from_integer(1.into()),
        Q::from_integer(2.into()),
    );
    let mag = |a: usize| lo[a].abs().max(hi[a].abs());
    let cen = |a: usize| (&lo[a] + &hi[a]) / &two;
    let rad = |a: usize| (&hi[a] - &lo[a]) / &two;
    let ferr =
        |a: usize| -> Q { fm(af, a).iter().map(|(k, c)| c.abs() * &e[*k]).sum::<Q>() + &rem[a] };
    for (j, node) in g.nodes().iter().enumerate() {
        let what = format!("{what} node {j} {:?}", node.op);
        let (v, eta) = (q(b.v[j]), q(b.eta[j]));
        let m = mag(j);
        let me = &m + &big_e[j];
        // loc_ok
        assert!(e[j] >= zero, "{what}");
        let loc = match &node.op {
            Op::Cst(_) => true,
            Op::DivE(a, _) => {
                let w = &v * (&two + &v);
                w < one
                    && &v * &me + &eta <= (&one - &v) * &e[j]
                    && &w * &me + (&one + &v) * (mag(*a) + &big_e[*a]) * &eta + &eta
                        <= (&one - &w) * &e[j]
            }
            Op::Sum(l) => {
                let live = l
                    .iter()
                    .filter(|&&i| !(lo[i] == zero && hi[i] == zero && big_e[i] == zero))
                    .count();
                let m_ = live.max(1) - 1;
                let mut w = one.clone();
                for _ in 0..m_ {
                    w *= &one + &v;
                }
                let sm: Q = l.iter().map(|&i| mag(i) + &big_e[i]).sum();
                (&w - &one) * sm
                    + Q::from_integer((m_ as i64).into()) * &w * &eta
                    + Q::from_integer((l.len() as i64 - 1).into()) * &w * q(b.ez)
                    <= e[j]
            }
            _ => v < one && &v * &me + &eta <= (&one - &v) * &e[j],
        };
        assert!(loc, "loc_ok fails: {what}");
        // aff_ok
        let pm: Sparse = af.forms[j].iter().map(|&(k, c)| (k, q(c))).collect();
        assert!(
            af.forms[j].iter().all(|&(k, _)| k < j),
            "{what}: a form past the node"
        );
        let opaque = |d: Q| d + dev(&Sparse::new(), &pm, &e) <= rem[j];
        let lin = |terms: &[(usize, Q)]| {
            let mut c = Sparse::new();
            for (a, s) in terms {
                for (k, x) in fm(af, *a) {
                    *c.entry(k).or_insert_with(Q::zero) += x * s;
                }
            }
            c
        };
        let ok = match &node.op {
            Op::In(_) | Op::Cst(_) => opaque(zero.clone()),
            Op::Add(a, c) | Op::Sub(a, c) => {
                let sign = if matches!(node.op, Op::Add(..)) {
                    one.clone()
                } else {
                    -one.clone()
                };
                &rem[*a] + &rem[*c] + dev(&lin(&[(*a, one.clone()), (*c, sign)]), &pm, &e) <= rem[j]
            }
            Op::Mul(a, c) => {
                let (fa, fc) = (fm(af, *a), fm(af, *c));
                let keys: std::collections::BTreeSet<usize> = fa
                    .keys()
                    .chain(fc.keys())
                    .chain(pm.keys())
                    .copied()
                    .collect();
                let get = |f: &Sparse, k: usize| f.get(&k).cloned().unwrap_or_else(Q::zero);
                let d: Q = keys
                    .into_iter()
                    .map(|k| {
                        let (al, be, p) = (get(&fa, k), get(&fc, k), get(&pm, k));
                        ((cen(*c) * &al + cen(*a) * &be - p).abs()
                            + rad(*c) * al.abs()
                            + rad(*a) * be.abs())
                            * &e[k]
                    })
                    .sum();
                mag(*c) * &rem[*a] + mag(*a) * &rem[*c] + ferr(*a) * ferr(*c) + d <= rem[j]
            }
            Op::Div(a, c) | Op::DivE(a, c) => {
                let exact_divisor = lo[*c] == hi[*c]
                    && big_e[*c] == zero
                    && &rem[*a] / lo[*c].abs() + dev(&lin(&[(*a, one.clone() / &lo[*c])]), &pm, &e)
                        <= rem[j];
                let lb = lo[*c].abs().min(hi[*c].abs());
                let (fa, fc) = (ferr(*a), ferr(*c));
                // The linear rule: every term is convex in u and in q, so the largest
                // over the box [1/hi_c, 1/lo_c] × [lo_j, hi_j] is at a corner.
                let linear = fc < lb && {
                    let us = [&one / &hi[*c], &one / &lo[*c]];
                    let qs = [lo[j].clone(), hi[j].clone()];
                    us.iter().all(|u| {
                        qs.iter().all(|qq| {
                            let lhs = u.abs() * &rem[*a]
                                + (qq * u).abs() * &rem[*c]
                                + (&fa + qq.abs() * &fc) * &fc * (u * u) / (&one - u.abs() * &fc)
                                + dev(&lin(&[(*a, u.clone()), (*c, -(qq * u))]), &pm, &e);
                            lhs <= rem[j]
                        })
                    })
                };
                exact_divisor || (fc < lb && opaque((&fa + &m * &fc) / (&lb - &fc))) || linear
            }
            Op::Sqrt(a) => {
                // The linear rule: each term is monotone in s on [S_j, hi_j] (the
                // coefficients' terms |α/(2s) − M|: α/(2s) is), so its largest is at an
                // end; their sum is at most the sum of those.
                let fa = ferr(*a);
                let (lo_end, hi_end) = (
                    lin(&[(*a, &one / (&two * &s[j]))]),
                    lin(&[(*a, &one / (&two * &hi[j]))]),
                );
                let keys: std::collections::BTreeSet<usize> =
                    lo_end.keys().chain(pm.keys()).copied().collect();
                let get = |f: &Sparse, k: usize| f.get(&k).cloned().unwrap_or_else(Q::zero);
                let d: Q = keys
                    .into_iter()
                    .map(|k| {
                        let p = get(&pm, k);
                        (get(&lo_end, k) - &p)
                            .abs()
                            .max((get(&hi_end, k) - &p).abs())
                            * &e[k]
                    })
                    .sum();
                let st = &s[j] + &t[j];
                let linear =
                    &rem[*a] / (&two * &s[j]) + &fa * &fa / (&two * &s[j] * (&st * &st)) + d
                        <= rem[j];
                opaque(&fa / (&s[j] + &t[j])) || linear
            }
            Op::Rsqrt(a) => opaque(ferr(*a) / (&two * (&s[j] * &s[j] * &s[j]))),
            Op::Sum(l) => {
                let terms: Vec<(usize, Q)> = l.iter().map(|&i| (i, one.clone())).collect();
                l.iter().map(|&i| rem[i].clone()).sum::<Q>() + dev(&lin(&terms), &pm, &e) <= rem[j]
            }
        };
        assert!(ok, "aff_ok fails: {what}");
        assert!(q(af.err[j]) >= ferr(j), "{what}: err below ferr");
    }
    g.nodes().len()
}

/// `graph_sound_affine` (`proofs/GraphAffine.v`): the affine certificate
/// (`tolerance::graph::affine`, in `f64` rounded outward) satisfies `loc_ok` and
/// `aff_ok` **exactly** — checked in rationals as the `.v` states them
/// ([`GRAPH_AFFINE_V_RULES`], each found in the file) — at every node of every
/// method's graphs under `ieee` (binary32; binary64 in the extensive tier) and
/// `shader`, on the inputs and on the inputs as read, for the profile spans and the
/// published cases up to n = 4 (16 in the extensive tier); and a binary32 run to
/// nearest from the inputs is within its bound at every pixel of the published cases
/// up to n = 64 (256).
#[test]
fn graph_sound_affine() {
    let v_file =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/proofs/GraphAffine.v"))
            .unwrap();
    let flat = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    let text = flat(&v_file);
    for rule in GRAPH_AFFINE_V_RULES {
        assert!(
            text.contains(&flat(rule)),
            "proofs/GraphAffine.v no longer states: {rule}"
        );
    }
    let mut cases: Vec<Span<Q>> = spans().into_iter().map(|(_, s)| s).collect();
    for set in phong_approx::testkit::SETS {
        cases.extend(published_spans(set).into_values());
    }
    let profiles = [
        (Profile::Ieee, Format::Binary32),
        (Profile::Shader, Format::Binary32),
        (Profile::Ieee, Format::Binary64),
    ];
    let (mut nodes, mut forms) = (0usize, 0usize);
    for s in cases
        .iter()
        .filter(|s| s.n <= tiered(4, 16))
        .step_by(tiered(3, 1))
    {
        for &(profile, format) in &profiles[..tiered(2, 3)] {
            let m = model(profile, format).unwrap();
            let mut sets = vec![inputs(s).to_vec()];
            if let Some(read) = read_to_nearest(&inputs(s), format) {
                sets.push(read);
            }
            for method in METHODS {
                for f in method_graphs(method, Form::Any, s.n, &m).unwrap() {
                    for ins in &sets {
                        let Ok(b) = evaluate(&f.graph, ins, &m) else {
                            continue;
                        };
                        let Some(af) = affine(&f.graph, &b) else {
                            continue;
                        };
                        forms += af.forms.iter().filter(|x| !x.is_empty()).count();
                        let what = format!("{method} {profile} {format:?} {}: {s}", f.name);
                        nodes += check_rules(&f.graph, &b, &af, &what);
                    }
                }
            }
        }
    }
    println!("{nodes} nodes' affine certificates checked exactly, {forms} non-empty forms");
    assert!(
        nodes > tiered(5_000, 50_000) && forms > nodes / 4,
        "{nodes} {forms}"
    );
    // Runs to nearest against the affine bound alone.
    let m = model(Profile::Ieee, Format::Binary32).unwrap();
    let mut px = 0usize;
    for set in phong_approx::testkit::SETS {
        for s in published_spans(set)
            .into_values()
            .filter(|s| s.n <= tiered(64, 256))
        {
            let ins = inputs(&s);
            for method in METHODS {
                let want = exact(method, None, &s);
                for f in method_graphs(method, Form::Any, s.n, &m).unwrap() {
                    let Ok(b) = evaluate(&f.graph, &ins, &m) else {
                        continue;
                    };
                    let Some(af) = affine(&f.graph, &b) else {
                        continue;
                    };
                    let y = run_f32(&f.graph, &ins);
                    for (i, &p) in f.pixels.iter().flat_map(|w| w.iter().enumerate()) {
                        let got = (q(f64::from(y[p])) - &want[i]).abs();
                        assert!(
                            got <= q(af.err[p]),
                            "{method} {} pixel {i}: {} > {}: {s}",
                            f.name,
                            got.to_f64(),
                            af.err[p]
                        );
                        px += 1;
                    }
                }
            }
        }
    }
    println!("{px} pixels of runs to nearest within the affine bound");
    assert!(px > 10_000, "{px}");
}

/// `graph_sound_affine_read` (`proofs/GraphAffine.v`): from the inputs as read to
/// nearest (`read_to_nearest`), a binary32 run of each form is within the affine bound
/// on those inputs plus the distance between the two certificates' intervals
/// (`read_distance`), at every pixel of the published cases up to n = 64 (256 in the
/// extensive tier), under both profiles' models; and that bound is below the running
/// bound's (`read_error`) at some pixel — the forms see what the running bound does not.
#[test]
fn graph_sound_affine_read() {
    use phong_approx::tolerance::graph::{read_distance, read_error};
    let (mut px, mut sharper) = (0usize, 0usize);
    for profile in [Profile::Ieee, Profile::Shader] {
        let m = model(profile, Format::Binary32).unwrap();
        for set in phong_approx::testkit::SETS {
            for s in published_spans(set)
                .into_values()
                .filter(|s| s.n <= tiered(64, 256))
            {
                let ins = inputs(&s);
                let Some(read) = read_to_nearest(&ins, Format::Binary32) else {
                    continue;
                };
                for method in METHODS {
                    let want = exact(method, None, &s);
                    for f in method_graphs(method, Form::Any, s.n, &m).unwrap() {
                        let (Ok(b), Ok(br)) =
                            (evaluate(&f.graph, &ins, &m), evaluate(&f.graph, &read, &m))
                        else {
                            continue;
                        };
                        let Some(af) = affine(&f.graph, &br) else {
                            continue;
                        };
                        let y = run_f32(&f.graph, &read);
                        for (i, &p) in f.pixels.iter().flat_map(|w| w.iter().enumerate()) {
                            let bound = (af.err[p] + read_distance(&b, &br, p)).next_up();
                            let got = (q(f64::from(y[p])) - &want[i]).abs();
                            assert!(
                                got <= q(bound),
                                "{method} {profile} {} pixel {i}: {} > {bound}: {s}",
                                f.name,
                                got.to_f64()
                            );
                            sharper += usize::from(bound < read_error(&b, &br, p));
                            px += 1;
                        }
                    }
                }
            }
        }
    }
    println!("{px} pixels from the inputs as read, {sharper} where the forms are sharper");
    assert!(px > 20_000 && sharper > px / 10, "{px} {sharper}");
}
