//! The operation graphs' per-case bounds (`phong_approx::tolerance::graph`,
//! `proofs/Graph.v`): `graph_sound` holds for every implementation of this binary —
//! the native `ieee` variants in `f32` and `f64`, the software GPUs under `shader` —
//! at every pixel of the profile spans and the published sets, against exact values.

use super::*;
use phong_approx::tolerance::graph::Model;
use phong_approx::tolerance::graphs::{model, pixel_bounds};

/// A software GPU's run of a method on a span.
type GpuRun = dyn Fn(Gpu, &Span<Q>) -> Vec<Q>;

/// The exact input `x` as an `f64` interval: `(x, x)` when `x` is an `f64`, else the
/// two neighbours of its nearest `f64`.
fn interval(x: &Q) -> (f64, f64) {
    let f = x.to_f64();
    if Q::from_float(f).as_ref() == Some(x) {
        (f, f)
    } else {
        (f.next_down(), f.next_up())
    }
}

/// `N_a`, `N_b`, `L` of `s` as the graphs' nine input intervals.
pub(super) fn inputs(s: &Span<Q>) -> [(f64, f64); 9] {
    let mut out = [(0.0, 0.0); 9];
    for (k, v) in [&s.na, &s.nb, &s.l].into_iter().enumerate() {
        for (c, x) in v.components().iter().enumerate() {
            out[3 * k + c] = interval(x);
        }
    }
    out
}

/// The graphs' bound at every pixel of `s` for `method` (any form).
fn graph_bound(method: Method, profile: Profile, format: Format, s: &Span<Q>) -> Option<Vec<f64>> {
    let m: Model = model(profile, format)?;
    pixel_bounds(method, Form::Any, s.n, &inputs(s), &m)
        .ok()
        .flatten()
}

/// The worst `|got − exact| / bound` over the pixels; panics where a pixel is over.
fn over(what: &str, got: &[Q], want: &[Q], bound: &[f64]) -> f64 {
    let mut worst = 0f64;
    for (i, ((g, w), b)) in got.iter().zip(want).zip(bound).enumerate() {
        let e = (g.clone() - w.clone()).abs().to_f64();
        assert!(
            e <= *b,
            "{what}: pixel {i}: error {e:e} > graph bound {b:e}"
        );
        worst = worst.max(e / b);
    }
    worst
}

/// The methods with operation graphs.
pub(super) const METHODS: [Method; 6] = [
    Method::Gouraud,
    Method::CorrectedEuler,
    Method::Euler,
    Method::Duff,
    Method::Phong,
    Method::SymmetricPhong,
];

/// The profile spans (with their cases) and every published case's span.
fn all_cases() -> Vec<(Option<Case>, Span<Q>)> {
    let mut cases: Vec<(Option<Case>, Span<Q>)> =
        spans().into_iter().map(|(c, s)| (Some(c), s)).collect();
    for set in phong_approx::testkit::SETS {
        cases.extend(published_spans(set).into_values().map(|s| (None, s)));
    }
    cases
}

/// The exact values of `method` on `s`: Phong's (and Duff's, symmetric Phong's) to
/// 2^-256, the others exactly.
pub(super) fn exact(method: Method, c: Option<&Case>, s: &Span<Q>) -> Vec<Q> {
    // Phong's exact values (Duff's and symmetric Phong's too) once per span.
    thread_local! {
        static PHONG: std::cell::RefCell<Option<(String, Vec<Q>)>> = const { std::cell::RefCell::new(None) };
    }
    match (method, c) {
        (Method::Phong | Method::Duff | Method::SymmetricPhong, _) => PHONG.with(|cell| {
            let key = s.to_string();
            let mut cell = cell.borrow_mut();
            match &*cell {
                Some((k, v)) if *k == key => v.clone(),
                _ => {
                    let v = phong_exact(s);
                    *cell = Some((key, v.clone()));
                    v
                }
            }
        }),
        (m, Some(c)) => exact_values(m, c, s).to_vec(),
        (m, None) => m.values(s).unwrap(),
    }
}

/// `graph_sound` (`proofs/Graph.v`): every native `ieee` implementation of this binary
/// (Gouraud, corrected Euler and Euler as recurrences and closed forms, Duff, Phong's
/// three forms, the squared method; three orders of the dot products, fused or not, `/n` either way), in
/// `f32` and `f64`, is within the graphs' bound at every pixel of the profile spans and
/// of every published case up to n = 64 (256 in the extensive tier); and the
/// software GPUs under `shader`.
#[test]
fn graph_sound() {
    let cases = all_cases();
    let mut worst: std::collections::BTreeMap<String, f64> = Default::default();
    let mut runs = 0;
    for (c, s) in &cases {
        if s.n > tiered(64, 256) {
            continue;
        }
        macro_rules! native_runs {
            ($t:ty, $f:ident) => {
                for (m, name, imp, _) in implementations::<$t>() {
                    let Some(b) = graph_bound(m, Profile::Ieee, Format::$f, s) else {
                        continue;
                    };
                    let want = exact(m, c.as_ref(), s);
                    for v in VARIANTS {
                        let got = imp(v, s);
                        let what = format!("{m} {name} {v:?} {}: {s}", stringify!($t));
                        let r = over(&what, &got, &want, &b);
                        let key = format!("ieee {} {m}", stringify!($t));
                        let w = worst.entry(key).or_default();
                        *w = w.max(r);
                        runs += 1;
                    }
                }
            };
        }
        native_runs!(f32, Binary32);
        // binary64 in the extensive tier.
        if extensive() {
            native_runs!(f64, Binary64);
        }
        // The squared method's fast kernel (`fast::FastSquared`) on every vector path
        // this CPU has.
        macro_rules! fast_squared {
            ($t:ty, $f:ident) => {
                let m = Method::SquaredCorrectedEuler;
                if let Some(b) = graph_bound(m, Profile::Ieee, Format::$f, s) {
                    let want = exact(m, c.as_ref(), s);
                    let vec = |x: &phong_approx::Vec3<Q>| {
                        [x.x.clone(), x.y.clone(), x.z.clone()].map(|x| <$t as Native>::of(&x))
                    };
                    let fast = phong_approx::fast::FastSquared::<$t>::new(
                        vec(&s.na),
                        vec(&s.nb),
                        vec(&s.l),
                        s.n,
                    );
                    let chosen = phong_approx::simd::path();
                    for path in phong_approx::simd::Path::supported_paths() {
                        phong_approx::simd::force(path).unwrap();
                        let mut out = vec![0.0 as $t; s.n as usize + 1];
                        fast.shade(&mut out);
                        let got: Vec<Q> = out.iter().map(|x| x.q()).collect();
                        let what = format!("FastSquared {} ({path}): {s}", stringify!($t));
                        let r = over(&what, &got, &want, &b);
                        let w = worst
                            .entry(format!("ieee {} FastSquared", stringify!($t)))
                            .or_default();
                        *w = w.max(r);
                        runs += 1;
                    }
                    phong_approx::simd::force(chosen).unwrap();
                }
            };
        }
        fast_squared!(f32, Binary32);
        fast_squared!(f64, Binary64);
        for &g in &GPUS[..tiered(1, 4)] {
            let gpu_imps: [(Method, &GpuRun); 7] = [
                (Method::Gouraud, &|g, s| {
                    gpu_recurrence(Method::Gouraud, g, Division::Reciprocal, s)
                }),
                (Method::CorrectedEuler, &|g, s| {
                    gpu_recurrence(Method::CorrectedEuler, g, Division::Once, s)
                }),
                (Method::Euler, &gpu_euler),
                (Method::Duff, &|g, s| {
                    gpu_duff_or_phong(g, s, false, Division::Once)
                }),
                (Method::Phong, &|g, s| {
                    gpu_duff_or_phong(g, s, true, Division::Once)
                }),
                (Method::SquaredCorrectedEuler, &|g, s| {
                    gpu_squared(g, s, Division::Once)
                }),
                (Method::SquaredCorrectedEuler, &|g, s| {
                    gpu_squared(g, s, Division::Reciprocal)
                }),
            ];
            for (m, imp) in gpu_imps {
                let Some(b) = graph_bound(m, Profile::Shader, Format::Binary32, s) else {
                    continue;
                };
                let want = exact(m, c.as_ref(), s);
                let got = imp(g, s);
                let r = over(&format!("{m} {g:?}: {s}"), &got, &want, &b);
                let w = worst.entry(format!("shader {m}")).or_default();
                *w = w.max(r);
                runs += 1;
            }
        }
    }
    for (k, w) in &worst {
        println!("{k}: worst error {w:.3} of the graph bound");
    }
    assert!(runs > 1000, "{runs}");
}

/// The squared method's fast kernel (`fast::FastSquared`) on rows long enough for its
/// lanes (`fast::STEPPED_FROM` pixels and more: the graph `lanes`) and just short of
/// them (`closed`), in `f32` and `f64` on every vector path: within the graphs' `ieee`
/// bound at every pixel (`graph_sound`; `graph_sound` above takes rows up to n = 64).
#[test]
fn the_squared_fast_kernel_is_within_the_graph_bound_on_long_rows() {
    let z = Stereo(0, 0, 1);
    let shapes = [
        (z, Stereo(1, 0, 3), Stereo(2, 1, 5)),
        (Stereo(1, 2, 3), Stereo(-3, 1, 4), Stereo(1, 1, 2)),
        (z, Stereo(7, 3, 2), Stereo(3, -1, 5)),
    ];
    let from = phong_approx::fast::STEPPED_FROM as u32;
    let mut ns = vec![from - 2, from - 1, from, from + 37];
    if extensive() {
        ns.extend([1000, 4096]);
    }
    let m = Method::SquaredCorrectedEuler;
    let chosen = phong_approx::simd::path();
    let mut worst = 0f64;
    let mut runs = 0;
    for n in ns {
        for &(na, nb, l) in &shapes {
            let c = Case {
                why: "squared fast kernel, long rows",
                na,
                nb,
                l,
                n,
            };
            let Some(s) = c.span() else { continue };
            let want = exact(m, Some(&c), &s);
            macro_rules! run {
                ($t:ty, $f:ident) => {
                    let b = graph_bound(m, Profile::Ieee, Format::$f, &s).expect("a bound");
                    let vec = |x: &phong_approx::Vec3<Q>| {
                        [&x.x, &x.y, &x.z].map(|x| <$t as Native>::of(x))
                    };
                    let fast = phong_approx::fast::FastSquared::<$t>::new(
                        vec(&s.na),
                        vec(&s.nb),
                        vec(&s.l),
                        n,
                    );
                    for path in phong_approx::simd::Path::supported_paths() {
                        phong_approx::simd::force(path).unwrap();
                        let mut out = vec![0.0 as $t; n as usize + 1];
                        fast.shade(&mut out);
                        let got: Vec<Q> = out.iter().map(|x| x.q()).collect();
                        let what = format!("FastSquared {} ({path}), n = {n}: {s}", stringify!($t));
                        worst = worst.max(over(&what, &got, &want, &b));
                        runs += 1;
                    }
                };
            }
            run!(f32, Binary32);
            run!(f64, Binary64);
        }
    }
    phong_approx::simd::force(chosen).unwrap();
    let paths: Vec<&str> = phong_approx::simd::Path::supported_paths()
        .iter()
        .map(|p| p.name())
        .collect();
    println!(
        "FastSquared on long rows, vector paths {}: worst error {worst:.3} of the graph bound",
        paths.join(", ")
    );
    assert!(runs >= 24, "{runs}");
}

/// How the graphs' bounds compare with the profiles' formulas on the published sets
/// (printed; asserts only that the graphs' are never above the formulas' by more than
/// the 2^-20 of their rounding).
#[test]
fn graph_bounds_against_the_formulas() {
    for set in phong_approx::testkit::SETS {
        let spans = published_spans(set);
        for m in METHODS {
            for (profile, format) in [
                (Profile::Ieee, Format::Binary32),
                (Profile::Shader, Format::Binary32),
            ] {
                let (mut lo, mut hi, mut none) = (f64::INFINITY, 0f64, 0);
                for s in spans.values() {
                    let old = profile_bound_of(m, profile, s, format);
                    let new = graph_bound(m, profile, format, s)
                        .map(|b| b.into_iter().fold(0f64, f64::max));
                    match (old, new) {
                        (Some(o), Some(n)) => {
                            lo = lo.min(o / n);
                            hi = hi.max(o / n);
                        }
                        _ => none += 1,
                    }
                }
                println!(
                    "{set} {m} {profile}: formula / graph {lo:.2}–{hi:.2}; {none} without both"
                );
            }
        }
    }
}

/// A binary32 run of `g` to nearest, in the graph's order (each sum left to right,
/// each division one division), from the inputs `x`.
pub(super) fn run_f32(g: &phong_approx::tolerance::graph::Graph, x: &[(f64, f64)]) -> Vec<f32> {
    use phong_approx::tolerance::graph::Op;
    let mut y: Vec<f32> = Vec::with_capacity(g.nodes().len());
    for node in g.nodes() {
        let v = match &node.op {
            Op::In(i) => x[*i].0 as f32,
            Op::Cst(c) => *c as f32,
            Op::Add(a, b) => y[*a] + y[*b],
            Op::Sub(a, b) => y[*a] - y[*b],
            Op::Mul(a, b) => y[*a] * y[*b],
            Op::Div(a, b) | Op::DivE(a, b) => y[*a] / y[*b],
            Op::Sqrt(a) => y[*a].sqrt(),
            Op::Rsqrt(a) => 1.0 / y[*a].sqrt(),
            Op::Sum(l) => l.iter().skip(1).fold(y[l[0]], |s, &t| s + y[t]),
        };
        y.push(v);
    }
    y
}

/// `graph_sound_read` (`proofs/Graph.v`): under `ieee` and `shader` an implementation
/// reads each input as its nearest binary32, which `read_to_nearest` gives (checked against the
/// exact input in rationals: strictly nearer than both neighbours); the method's exact
/// value at those inputs (Phong's to 2^-256) lies in the certificate's interval on
/// them, and its distance to the exact value at the exact inputs is within
/// `read_error` less the error part; a binary32 run of each form from those inputs is
/// within `read_error` at every pixel, under both profiles' models. On every published
/// case up to n = 64 (256 in the extensive tier).
#[test]
fn graph_sound_read() {
    use phong_approx::tolerance::graph::{evaluate, read_error, read_to_nearest};
    use phong_approx::tolerance::graphs::method_graphs;
    let models = [Profile::Ieee, Profile::Shader].map(|p| model(p, Format::Binary32).unwrap());
    let (mut checked, mut read_cases) = (0usize, 0usize);
    for set in phong_approx::testkit::SETS {
        for s in published_spans(set)
            .into_values()
            .filter(|s| s.n <= tiered(64, 256))
        {
            let ins = inputs(&s);
            let Some(read) = read_to_nearest(&ins, Format::Binary32) else {
                continue;
            };
            read_cases += 1;
            let exact_in: Vec<Q> = [&s.na, &s.nb, &s.l]
                .iter()
                .flat_map(|v| v.components().into_iter().cloned())
                .collect();
            for (x, &(f, _)) in exact_in.iter().zip(&read) {
                let f32v = f as f32;
                let d = (Q::from_float(f).unwrap() - x).abs();
                for g in [f32v.next_up(), f32v.next_down()] {
                    let dg = (Q::from_float(f64::from(g)).unwrap() - x).abs();
                    assert!(
                        d < dg,
                        "{f} is not the nearest binary32 to {}: {s}",
                        x.to_f64()
                    );
                }
            }
            let r = |k: usize| Q::from_float(read[k].0).unwrap();
            let v = |k: usize| phong_approx::Vec3::new(r(k), r(k + 1), r(k + 2));
            let tol = Q::new(1.into(), 1000.into());
            let sr = Span::with_tolerance(v(0), v(3), v(6), s.n, &tol).unwrap();
            for method in METHODS {
                let at_x = exact(method, None, &s);
                // The method's own algorithm at the inputs as read (symmetric Phong
                // mirrors its left half's roots, which |N_a| ≠ |N_b| tells from Phong).
                let at_read = method.values(&sr).unwrap();
                for (m, f) in models.iter().flat_map(|m| {
                    method_graphs(method, Form::Any, s.n, m)
                        .unwrap()
                        .into_iter()
                        .map(move |f| (m, f))
                }) {
                    let (Ok(b), Ok(br)) =
                        (evaluate(&f.graph, &ins, m), evaluate(&f.graph, &read, m))
                    else {
                        continue;
                    };
                    let y = run_f32(&f.graph, &read);
                    for (i, &p) in f.pixels.iter().flat_map(|w| w.iter().enumerate()) {
                        let q = |x: f64| Q::from_float(x).unwrap();
                        let what = format!("{method} {} pixel {i}: {s}", f.name);
                        assert!(
                            q(br.lo[p]) <= at_read[i] && at_read[i] <= q(br.hi[p]),
                            "{what}"
                        );
                        let bound = read_error(&b, &br, p);
                        let shift = (&at_read[i] - &at_x[i]).abs();
                        assert!(
                            shift <= q(bound) - q(br.err[p]),
                            "{what}: the inputs' shift"
                        );
                        let got = (q(f64::from(y[p])) - &at_x[i]).abs();
                        assert!(got <= q(bound), "{what}: a run to nearest");
                        checked += 1;
                    }
                }
            }
        }
    }
    println!("{read_cases} cases read to nearest, {checked} pixels");
    assert!(
        read_cases > tiered(20, 60) && checked > 20_000,
        "{read_cases} {checked}"
    );
}

/// Every pixel node's interval holds the method's exact value: the graphs compute the
/// method (the paper's set-up and loops), so `graph_sound`'s bound is on the right
/// quantity. On the profile spans and every published case up to n = 64 (256 in the
/// extensive tier).
#[test]
fn graph_exact_values_are_the_methods() {
    use phong_approx::tolerance::graph::evaluate;
    use phong_approx::tolerance::graphs::method_graphs;
    let cases = all_cases();
    let mut checked = 0;
    for (c, s) in cases.iter().filter(|(_, s)| s.n <= tiered(64, 256)) {
        for profile in [Profile::Ieee, Profile::Shader] {
            let m = model(profile, Format::Binary32).unwrap();
            for method in METHODS {
                let want = exact(method, c.as_ref(), s);
                for f in method_graphs(method, Form::Any, s.n, &m).unwrap() {
                    let Ok(b) = evaluate(&f.graph, &inputs(s), &m) else {
                        continue;
                    };
                    for (i, &p) in f.pixels.iter().flat_map(|w| w.iter().enumerate()) {
                        // Phong's exact values are to 2^-256; the intervals are wider.
                        let (lo, hi) = (
                            Q::from_float(b.lo[p]).unwrap(),
                            Q::from_float(b.hi[p]).unwrap(),
                        );
                        assert!(
                            lo <= want[i] && want[i] <= hi,
                            "{method} {} pixel {i}: [{}, {}] misses {}: {s}",
                            f.name,
                            b.lo[p],
                            b.hi[p],
                            want[i].to_f64()
                        );
                        checked += 1;
                    }
                }
            }
        }
    }
    assert!(checked > 100_000, "{checked}");
}

/// Duff with a Quake-style reciprocal square root (`0x5f3759df`, two Newton steps,
/// about 78u relative in binary32: outside `ieee` and `shader`) is over the graphs'
/// bound at some pixel of some published case under both profiles, where the same
/// kernel with `1/√q` is within it everywhere; with the profiles' formulas it passed
/// every published set (docs/float.md §19).
#[test]
fn quake_rsqrt_duff_exceeds_the_graph_bound() {
    use super::graph_mutants::{exact_rsqrt, Setup32};
    fn quake(x: f32) -> f32 {
        super::graph_mutants::quake(x, 2)
    }
    // Duff's forward differences in f32 (eqs. 5–7), value p·rsqrt(q).
    fn duff32(s: &Span<Q>, rsqrt: fn(f32) -> f32) -> Vec<Q> {
        let Setup32 { na, l, k } = Setup32::of(s);
        let dot = Setup32::dot;
        let (a, c, d) = (dot(k, l), dot(k, k), 2.0 * dot(k, na));
        let (mut p, mut q, mut dq, d2q) = (dot(na, l), dot(na, na), c + d, c + c);
        (0..=s.n)
            .map(|_| {
                let out = (p * rsqrt(q)).q();
                p += a;
                q += dq;
                dq += d2q;
                out
            })
            .collect()
    }
    for profile in [Profile::Ieee, Profile::Shader] {
        let mut caught = 0;
        for set in phong_approx::testkit::SETS {
            for s in published_spans(set).values() {
                let Some(b) = graph_bound(Method::Duff, profile, Format::Binary32, s) else {
                    continue;
                };
                let want = phong_exact(s);
                let err = |got: Vec<Q>| {
                    got.iter()
                        .zip(&want)
                        .zip(&b)
                        .map(|((g, w), b)| (g.clone() - w.clone()).abs().to_f64() / b)
                        .fold(0f64, f64::max)
                };
                assert!(
                    err(duff32(s, exact_rsqrt)) <= 1.0,
                    "{profile} {s}: 1/√q over the bound"
                );
                if err(duff32(s, quake)) > 1.0 {
                    caught += 1;
                }
            }
        }
        println!(
            "{profile}: the Quake rsqrt Duff is over the graph bound on {caught} published cases"
        );
        assert!(
            caught > 0,
            "{profile}: the Quake rsqrt Duff is within the graph bound on every published case"
        );
    }
}

/// The rules of `proofs/Graph.v` this file checks, as the `.v` states them: the test
/// below fails when one of them is no longer in the file.
const GRAPH_V_RULES: [&str; 17] = [
    "let m := (length (filter (live lo hi E) l) - 1)%nat in",
    "+ INR m * w * eta + INR (k - 1) * w * nez (g j) <= E j",
    "let eta := neta (g j) in",
    "| In _ => v * m + eta <= E j",
    "| Add a b | Sub a b => E a + E b + v * (m + E a + E b) + eta <= E j",
    "let d := mag (lo a) (hi a) * E b + mag (lo b) (hi b) * E a + E a * E b in",
    "let d := (E a + m * E b) / (lb - E b) in",
    "d + v * (2 + v) * (m + d) + (1 + v) * (mag (lo a) (hi a) + E a) * eta + eta <= E j",
    "E a <= S j * S j /\\ 0 <= T j /\\ T j * T j <= lo a - E a /\\",
    "let d := E a / (S j + T j) in",
    "E a <= lo a - S j * S j /\\",
    "let d := E a / (2 * (S j * S j * S j)) in",
    "sumR E l + (w - 1) * sumR (fun i => mag (lo i) (hi i) + E i) l",
    "| Sqrt a => 0 < S j /\\ S j * S j <= lo a /\\ lo j <= S j /\\ 0 <= hi j /\\ hi a <= hi j * hi j",
    "| Rsqrt a => 0 < S j /\\ S j * S j <= lo a /\\ 0 < lo j /\\ lo j * lo j * hi a <= 1 /\\ 1 <= hi j * S j",
    // `graph::read_error`: the read certificate's error plus the intervals' distance.
    "Rabs (y j - x j) <= Er j + Rmax (hir j - lo j) (hi j - lor j)",
    // The exact nodes and inputs (`graph::exact`): nv = 0, neta = 0.
    "ap1 0 0 (round radix2 (FLT_exp emin prec) rnd x) x",
];

/// The certificate the evaluator computes (`tolerance::graph::evaluate`, in `f64`
/// rounded outward) satisfies `iv_ok` and `err_ok` of `proofs/Graph.v` **exactly**,
/// checked here in rationals rule by rule as the `.v` states them
/// ([`GRAPH_V_RULES`], each found in the file), at every node of every method's graphs
/// under `ieee` (binary32, binary64) and `shader` on the profile spans up to n = 16 and
/// the published cases up to n = 16 (n = 4 in the default tier: exact arithmetic on
/// every node is slow): so `graph_sound` applies to what `check` uses.
#[test]
fn graph_certificates_satisfy_the_theorems_rules() {
    use phong_approx::tolerance::graph::{evaluate, read_to_nearest, Op};
    use phong_approx::tolerance::graphs::method_graphs;
    let v_file =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/proofs/Graph.v")).unwrap();
    let flat = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    let text = flat(&v_file);
    for rule in GRAPH_V_RULES {
        assert!(
            text.contains(&flat(rule)),
            "proofs/Graph.v no longer states: {rule}"
        );
    }
    let r = |x: f64| Q::from_float(x).unwrap();
    let mag = |l: &Q, h: &Q| l.abs().max(h.abs());
    let mut cases: Vec<Span<Q>> = spans().into_iter().map(|(_, s)| s).collect();
    for set in phong_approx::testkit::SETS {
        cases.extend(published_spans(set).into_values());
    }
    let (mut nodes, mut exact_nodes) = (0usize, 0usize);
    let limit = tiered(4, 16);
    // The default tier: every fifth case, binary64 only in the extensive tier.
    let step = tiered(5, 1);
    for s in cases.iter().filter(|s| s.n <= limit).step_by(step) {
        let x_in = {
            let mut v = Vec::new();
            for vec in [&s.na, &s.nb, &s.l] {
                v.extend(vec.components().into_iter().cloned());
            }
            v
        };
        let profiles = [
            (Profile::Ieee, Format::Binary32),
            (Profile::Shader, Format::Binary32),
            (Profile::Ieee, Format::Binary64),
        ];
        for &(profile, format) in &profiles[..tiered(2, 3)] {
            let m = model(profile, format).unwrap();
            // The exact inputs, and the inputs as read to nearest, whose
            // certificate `graph_sound_read` takes with those as the exact inputs.
            let mut sets = vec![(inputs(s).to_vec(), x_in.clone())];
            if let Some(read) = m
                .inputs_to_nearest
                .then(|| read_to_nearest(&inputs(s), format))
                .flatten()
            {
                let xr = read.iter().map(|&(x, _)| r(x)).collect();
                sets.push((read, xr));
            }
            for method in METHODS {
                for f in method_graphs(method, Form::Any, s.n, &m).unwrap() {
                    for (ins, x_in) in &sets {
                        let Ok(b) = evaluate(&f.graph, ins, &m) else {
                            continue;
                        };
                        let [lo, hi, e, sj, tj]: [Vec<Q>; 5] = [
                            b.lo.iter().map(|&x| r(x)).collect(),
                            b.hi.iter().map(|&x| r(x)).collect(),
                            b.err.iter().map(|&x| r(x)).collect(),
                            b.s.iter().map(|&x| r(x)).collect(),
                            b.t.iter().map(|&x| r(x)).collect(),
                        ];
                        let (zero, one, two) = (
                            Q::zero(),
                            Q::from_integer(1.into()),
                            Q::from_integer(2.into()),
                        );
                        for (j, node) in f.graph.nodes().iter().enumerate() {
                            // The node's own unit and absolute term (`nv`, `neta`): the
                            // relative model's κ·u and η, or the ulp model's 0 and κ/2 ulps.
                            let (v, eta) = (r(b.v[j]), r(b.eta[j]));
                            assert!(v >= zero && eta >= zero);
                            if b.v[j] > 0.0 {
                                assert!(v >= r(m.kappa(node.class)) * r(m.u) && b.eta[j] >= m.eta);
                            } else if b.eta[j] == 0.0 && !matches!(node.op, Op::Cst(_)) {
                                // An exact node (`exact_op_model`): its operands (or input) known
                                // exactly, and its result — for a sum, each partial sum of every
                                // order — a number the format holds, zero or normal.
                                let held = |x: &Q| {
                                    let f = x.to_f64();
                                    r(f) == *x
                                        && format.holds(f)
                                        && (f == 0.0 || f.abs() >= format.min_normal())
                                };
                                let known = |a: usize| lo[a] == hi[a] && e[a] == Q::zero();
                                let operands: Vec<usize> = match &node.op {
                                    Op::In(_) => vec![],
                                    Op::Add(a, c) | Op::Sub(a, c) | Op::Mul(a, c) => vec![*a, *c],
                                    Op::Sum(l) if l.len() <= 3 => l.clone(),
                                    op => panic!("{j}: {op:?} taken as exact"),
                                };
                                assert!(operands.iter().all(|&a| known(a)), "{j}: operands");
                                exact_nodes += 1;
                                assert!(lo[j] == hi[j] && e[j] == Q::zero() && held(&lo[j]), "{j}");
                                if let Op::In(i) = node.op {
                                    assert_eq!(lo[j], x_in[i], "{j}: input read exactly");
                                }
                                if let Op::Sum(l) = &node.op {
                                    for (a, c) in [(0, 1), (0, 2), (1, 2)] {
                                        if c < l.len() {
                                            assert!(
                                                held(&(&lo[l[a]] + &lo[l[c]])),
                                                "{j}: a partial sum"
                                            );
                                        }
                                    }
                                }
                            } else if let Op::Sum(l) = &node.op {
                                // The ulp model of a sum: κ/2 ulps at a bound M of every partial
                                // sum of every order, sm + (k − 2)·η' ≤ M (sm: the terms'
                                // magnitudes and errors), and η.
                                let sm: Q = l.iter().map(|&i| mag(&lo[i], &hi[i]) + &e[i]).sum();
                                let big =
                                    sm + Q::from_integer((l.len().max(2) as i64 - 2).into()) * &eta;
                                let ulps =
                                    m.kappa(node.class) / 2.0 * format.ulp(big.to_f64().next_up());
                                assert!(b.eta[j] >= ulps + m.eta, "{j}: {} < {ulps}", b.eta[j]);
                            } else if !matches!(node.op, Op::Cst(_)) {
                                // κ/2 ulps of a bound on the result's magnitude (at least
                                // the exact value's), and η.
                                let ulps = m.kappa(node.class) / 2.0
                                    * format.ulp(b.lo[j].abs().max(b.hi[j].abs()));
                                assert!(b.eta[j] >= ulps + m.eta, "{j}: {} < {ulps}", b.eta[j]);
                            }
                            let mj = mag(&lo[j], &hi[j]);
                            let ok_iv =
                                |lj: &Q, hj: &Q, ps: &[Q]| ps.iter().all(|p| lj <= p && p <= hj);
                            let tail = |d: &Q| {
                                d.clone() + v.clone() * (mj.clone() + d.clone()) + eta.clone()
                            };
                            let what = format!("{method} {} node {j} {:?}: {s}", f.name, node.op);
                            assert!(lo[j] <= hi[j] && e[j] >= zero, "{what}");
                            let (iv, er) = match &node.op {
                                Op::In(i) => (
                                    lo[j] <= x_in[*i] && x_in[*i] <= hi[j],
                                    v.clone() * mj.clone() + eta.clone() <= e[j],
                                ),
                                Op::Cst(c) => (lo[j] <= r(*c) && r(*c) <= hi[j], true),
                                Op::Add(a, c) | Op::Sub(a, c) => {
                                    let iv = if matches!(node.op, Op::Add(..)) {
                                        lo[j] <= &lo[*a] + &lo[*c] && &hi[*a] + &hi[*c] <= hi[j]
                                    } else {
                                        lo[j] <= &lo[*a] - &hi[*c] && &hi[*a] - &lo[*c] <= hi[j]
                                    };
                                    let d = &e[*a] + &e[*c];
                                    (iv, tail(&d) <= e[j])
                                }
                                Op::Mul(a, c) => {
                                    let ps = [
                                        &lo[*a] * &lo[*c],
                                        &lo[*a] * &hi[*c],
                                        &hi[*a] * &lo[*c],
                                        &hi[*a] * &hi[*c],
                                    ];
                                    let d = mag(&lo[*a], &hi[*a]) * &e[*c]
                                        + mag(&lo[*c], &hi[*c]) * &e[*a]
                                        + &e[*a] * &e[*c];
                                    (ok_iv(&lo[j], &hi[j], &ps), tail(&d) <= e[j])
                                }
                                Op::Div(a, c) | Op::DivE(a, c) => {
                                    let sign = lo[*c] > zero || hi[*c] < zero;
                                    let ps = [
                                        &lo[*a] / &lo[*c],
                                        &lo[*a] / &hi[*c],
                                        &hi[*a] / &lo[*c],
                                        &hi[*a] / &hi[*c],
                                    ];
                                    let lb = lo[*c].abs().min(hi[*c].abs());
                                    let d = (&e[*a] + &mj * &e[*c]) / (&lb - &e[*c]);
                                    let mut er = e[*c] < lb && tail(&d) <= e[j];
                                    if matches!(node.op, Op::DivE(..)) {
                                        let second = &d
                                            + &v * (&two + &v) * (&mj + &d)
                                            + (&one + &v) * (mag(&lo[*a], &hi[*a]) + &e[*a]) * &eta
                                            + &eta;
                                        er = er && second <= e[j];
                                    }
                                    (sign && ok_iv(&lo[j], &hi[j], &ps), er)
                                }
                                Op::Sqrt(a) => (
                                    sj[j] > zero
                                        && &sj[j] * &sj[j] <= lo[*a]
                                        && lo[j] <= sj[j]
                                        && hi[j] >= zero
                                        && hi[*a] <= &hi[j] * &hi[j],
                                    e[*a] <= &sj[j] * &sj[j]
                                        && tj[j] >= zero
                                        && &tj[j] * &tj[j] <= &lo[*a] - &e[*a]
                                        && tail(&(&e[*a] / (&sj[j] + &tj[j]))) <= e[j],
                                ),
                                Op::Rsqrt(a) => (
                                    sj[j] > zero
                                        && &sj[j] * &sj[j] <= lo[*a]
                                        && lo[j] > zero
                                        && &lo[j] * &lo[j] * &hi[*a] <= one
                                        && &hi[j] * &sj[j] >= one,
                                    e[*a] <= &lo[*a] - &sj[j] * &sj[j]
                                        && tail(&(&e[*a] / (&two * (&sj[j] * &sj[j] * &sj[j]))))
                                            <= e[j],
                                ),
                                Op::Sum(l) => {
                                    // `live`: the terms not known to be 0; m = live − 1
                                    // additions round, each addition of a zero moves by
                                    // `nez` (the format's η) at most.
                                    let k = l.len();
                                    let live = l
                                        .iter()
                                        .filter(|&&i| {
                                            !(lo[i] == zero && hi[i] == zero && e[i] == zero)
                                        })
                                        .count();
                                    let m_ = live.max(1) - 1;
                                    let mut w = one.clone();
                                    for _ in 0..m_ {
                                        w *= &one + &v;
                                    }
                                    // (An exact node's additions are all exact: nez = 0.)
                                    assert_eq!(b.ez, m.eta, "nez is the format's η");
                                    let exact_node = b.v[j] == 0.0 && b.eta[j] == 0.0;
                                    let ez = if exact_node { Q::zero() } else { r(b.ez) };
                                    let se: Q = l.iter().map(|&i| e[i].clone()).sum();
                                    let sm: Q =
                                        l.iter().map(|&i| mag(&lo[i], &hi[i]) + &e[i]).sum();
                                    let bound = se
                                        + (&w - &one) * sm
                                        + Q::from_integer((m_ as i64).into()) * &w * &eta
                                        + Q::from_integer((k as i64 - 1).into()) * &w * &ez;
                                    let iv = lo[j] <= l.iter().map(|&i| lo[i].clone()).sum::<Q>()
                                        && l.iter().map(|&i| hi[i].clone()).sum::<Q>() <= hi[j];
                                    (iv, bound <= e[j])
                                }
                            };
                            assert!(iv, "iv_ok fails: {what}");
                            assert!(er, "err_ok fails: {what}");
                            nodes += 1;
                        }
                    }
                }
            }
        }
    }
    println!("{nodes} nodes' certificates checked exactly, {exact_nodes} of them exact");
    assert!(exact_nodes > 0);
    assert!(nodes > tiered(5_000, 100_000), "{nodes}");
}

/// The catalogue's `graphs` fact is what `tolerance::graphs` writes: a method has
/// operation graphs exactly where its row names them, under those names, so its label
/// names `graph_sound` and its graphs (`tolerance::profile::Status::PerPixel`, or
/// `Status::Graphs` where they are its only bound) exactly
/// where `check` applies them.
#[test]
fn the_catalogue_names_the_methods_with_graphs() {
    use phong_approx::tolerance::graphs::method_graphs;
    use phong_approx::tolerance::profile::{status, Status};
    let m = model(Profile::Ieee, Format::Binary32).unwrap();
    for method in Method::ALL {
        let graphs = method_graphs(method, Form::Any, 4, &m);
        let has = graphs.is_some();
        let names: Vec<String> = graphs.iter().flatten().map(|g| g.name.clone()).collect();
        assert_eq!(names, method.info().profiles.graphs, "{method}");
        // Distinct names, and distinct graphs under them (a name the builder does
        // not tell apart would build another form's graph twice).
        for (i, a) in graphs.iter().flatten().enumerate() {
            for b in graphs.iter().flatten().skip(i + 1) {
                assert_ne!(a.name, b.name, "{method}");
                assert!(
                    a.graph.nodes() != b.graph.nodes(),
                    "{method}: {} and {}",
                    a.name,
                    b.name
                );
            }
        }
        for profile in [Profile::Ieee, Profile::Shader] {
            if let Some(st) = status(method, profile, Format::Binary32) {
                assert_eq!(
                    matches!(st, Status::PerPixel(_, g, _) | Status::Graphs(_, g, _) if g == names),
                    has,
                    "{method} {profile}"
                );
                if has {
                    for name in &names {
                        assert!(st.label().contains(name.as_str()), "{method} {profile}");
                    }
                }
            }
        }
    }
}

/// Normals 179.4° apart (`N_b = (2m, 0, m² − 1)/(1 + m²)`, `m = 1/191`, `q_min` about
/// `2.7·10⁻⁵`) at n = 2 and n = 8: under `shader` the formulas give Phong (and some of
/// the others) no bound (`q` may lose half of itself), the operation graphs bound
/// Phong, Duff and symmetric Phong, and every software GPU is within it at every pixel.
#[test]
fn near_opposite_shader_spans_have_bounds() {
    use phong_approx::tolerance::graphs::profile_pixel_bounds;
    let m = q(1, 191);
    let one = Q::from_integer(1.into());
    let den = &one + &m * &m;
    let v = |x: Q, y: Q, z: Q| phong_approx::Vec3::new(x, y, z);
    let na = v(Q::zero(), Q::zero(), one.clone());
    let nb = v(q(2, 1) * &m / &den, Q::zero(), (&m * &m - &one) / &den);
    let l = v(q(3, 5), Q::zero(), q(4, 5));
    let (mut bounded, mut unbounded) = (0, 0);
    for n in [2, 8] {
        let s = Span::new(na.clone(), nb.clone(), l.clone(), n).unwrap();
        let shape = phong_approx::tolerance::Shape::of(&s);
        let imps: [(Method, &GpuRun); 3] = [
            (Method::Phong, &|g, s| {
                gpu_duff_or_phong(g, s, true, Division::Once)
            }),
            (Method::Duff, &|g, s| {
                gpu_duff_or_phong(g, s, false, Division::Once)
            }),
            (Method::SymmetricPhong, &|g, s| {
                gpu_symmetric_phong(g, s, Division::Once)
            }),
        ];
        for (method, imp) in imps {
            let formula = phong_approx::tolerance::profile::profile_span_bound(
                method,
                Profile::Shader,
                Form::Any,
                &shape,
                Format::Binary32,
            );
            unbounded += usize::from(formula.is_none());
            let b = profile_pixel_bounds(
                method,
                Profile::Shader,
                Form::Any,
                &shape,
                None,
                Format::Binary32,
            )
            .unwrap_or_else(|| panic!("{method} n = {n}: no bound"));
            let want = phong_exact(&s);
            for &g in &GPUS {
                over(&format!("{method} {g:?} n = {n}"), &imp(g, &s), &want, &b);
            }
            bounded += 1;
        }
    }
    assert_eq!(bounded, 6);
    // Where the formulas refused (Phong at both n, among others), the graphs bound.
    assert!(unbounded >= 2, "{unbounded}");
}

/// The report `cargo xtask counts-vs-graphs` (docs/float.md §19.3): per method, profile
/// and format, on the published sets and the searched spans (the edge and targeted
/// spans and 48 seeded `arb_targeted` ones, n ≤ 4096), the pixels where §18's formula
/// (the count theorems) is below the graphs' bound — where `check`'s per-pixel minimum
/// takes the formula —, the largest ratio there, and the cases where only one of
/// them gives a bound.
// Called by the `xtask` program only (the test binary has no caller).
#[cfg_attr(test, allow(dead_code))]
pub(crate) fn counts_vs_graphs() {
    use phong_approx::tolerance::profile::profile_span_bound;
    use proptest::strategy::{Strategy, ValueTree};
    let mut spans: Vec<Span<Q>> = Vec::new();
    for set in phong_approx::testkit::SETS {
        let mut v: Vec<(String, Span<Q>)> = published_spans(set).into_iter().collect();
        v.sort_by(|a, b| a.0.cmp(&b.0));
        spans.extend(v.into_iter().map(|(_, s)| s));
    }
    let mut cases = edge_cases();
    cases.extend(targeted_cases());
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    for _ in 0..48 {
        cases.push(arb_targeted().new_tree(&mut runner).unwrap().current());
    }
    spans.extend(cases.iter().filter_map(|c| c.span()));
    spans.retain(|s| s.n <= phong_approx::tolerance::graphs::MAX_GRAPH_STEPS);
    println!(
        "| method | profile | format | cases | pixels | formula smaller at (pixels, cases) | largest graphs ÷ formula there | graphs only | formula only |"
    );
    println!("|---|---|---|---:|---:|---:|---:|---:|---:|");
    for format in [Format::Binary32, Format::Binary64] {
        for method in METHODS {
            for profile in [Profile::Ieee, Profile::Shader] {
                let Some(m) = model(profile, format) else {
                    continue;
                };
                let (mut cases, mut px, mut wins, mut won) = (0, 0, 0, 0);
                let (mut worst, mut g_only, mut f_only) = (1f64, 0, 0);
                for s in &spans {
                    let shape = phong_approx::tolerance::Shape::of(s);
                    let f = profile_span_bound(method, profile, Form::Any, &shape, format);
                    let g = pixel_bounds(method, Form::Any, s.n, &inputs(s), &m)
                        .ok()
                        .flatten();
                    match (f, g) {
                        (Some(f), Some(g)) => {
                            cases += 1;
                            px += g.len();
                            let here = g.iter().filter(|&&x| f < x).count();
                            wins += here;
                            won += usize::from(here > 0);
                            worst = g.iter().fold(worst, |w, &x| w.max(x / f));
                        }
                        (None, Some(_)) => g_only += 1,
                        (Some(_), None) => f_only += 1,
                        (None, None) => {}
                    }
                }
                println!(
                    "| {method} | {profile} | {format:?} | {cases} | {px} | {wins}, {won} | {worst:.2} | {g_only} | {f_only} |"
                );
            }
        }
    }
}
