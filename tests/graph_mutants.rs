//! Bugs a few times larger than rounding fail (docs/float.md §19.6): each method's
//! first operation graph (Duff's and Phong's with `p/√q`, the Eulers' recurrences)
//! executed in binary32 with round to nearest — a correct implementation, which passes
//! — and with one planted bug, judged through the test kit on every published set.

use super::*;
use phong_approx::tolerance::graph::{Graph, Op};
use phong_approx::tolerance::graphs::{method_graphs, model};

/// Quake III's reciprocal square root: the magic constant and `steps` Newton steps.
pub(super) fn quake(x: f32, steps: u32) -> f32 {
    let mut y = f32::from_bits(0x5f37_59df_u32.wrapping_sub(x.to_bits() >> 1));
    for _ in 0..steps {
        y = y * (1.5 - 0.5 * x * y * y);
    }
    y
}

/// `1/√x` correctly rounded twice (a square root, then a division): the kernels'
/// legal reciprocal square root beside [`quake`].
pub(super) fn exact_rsqrt(x: f32) -> f32 {
    1.0 / x.sqrt()
}

/// The binary32 set-up the planted-`rsqrt` kernels share: `N_a`, `L` and
/// `k = (N_b − N_a)/n` rounded to `f32`, and a dot product in the written order.
pub(super) struct Setup32 {
    /// `N_a` in `f32`.
    pub(super) na: [f32; 3],
    /// `L` in `f32`.
    pub(super) l: [f32; 3],
    /// `k = (N_b − N_a)/n` in `f32`.
    pub(super) k: [f32; 3],
}

impl Setup32 {
    pub(super) fn of(s: &phong_approx::Span<Q>) -> Self {
        let v = |x: &phong_approx::Vec3<Q>| {
            [x.x.clone(), x.y.clone(), x.z.clone()].map(|c| f32::of(&c))
        };
        let (na, nb, l) = (v(&s.na), v(&s.nb), v(&s.l));
        let nf = s.n as f32;
        let k = [0, 1, 2].map(|j| (nb[j] - na[j]) / nf);
        Setup32 { na, l, k }
    }

    /// `a·b` summed left to right.
    pub(super) fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }
}

/// `x` rounded to binary16 (11 significant bits, to nearest even; the exponent range
/// of the values here is within binary16's normal range or flushed to its subnormal
/// spacing).
fn binary16(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let e = x.abs().log2().floor().max(-14.0);
    let ulp = 2f64.powf(e - 10.0);
    let q = x / ulp;
    let r = q.round();
    // Ties to even.
    let r = if (q - q.trunc()).abs() == 0.5 && r % 2.0 != 0.0 {
        r - q.signum()
    } else {
        r
    };
    r * ulp
}

/// A planted bug.
#[derive(Clone, Copy, Debug)]
enum Bug {
    /// Every square root as `1/quake(x)` with this many Newton steps.
    Quake(u32),
    /// The named set-up quantity rounded to binary16.
    Half(&'static str),
    /// The named set-up quantity times `1 + 10⁻⁵`.
    Bias(&'static str),
    /// A small term of the set-up dropped: corrected Euler's correction `dε`
    /// (`t0 = di_a`), Euler's `p_a/2·dq_a` (`di_a = A`), Duff's and symmetric Phong's
    /// `C` in `dq_0 = C + D`, Phong's `C·i²` (Horner's `q = D·i + E`).
    Drop(&'static str),
    /// A set-up quantity replaced by its value in exact arithmetic on unit inputs,
    /// which differs from the computed one by rounding only: `E = 1`, `dq_b = −D`
    /// (eq. 22). No sound bound can reject these everywhere (printed, not asserted).
    Exact(&'static str),
}

/// The binary32 round-to-nearest run of `g` (its first way) on the float inputs,
/// with `bug` planted.
fn run(
    g: &Graph,
    pixels: &[usize],
    setup: &[(&'static str, usize)],
    x_in: &[f32; 9],
    bug: Option<Bug>,
) -> Vec<f32> {
    let named = |name: &str| setup.iter().find(|(k, _)| *k == name).map(|&(_, j)| j);
    let mut y = vec![0f32; g.nodes().len()];
    for (j, node) in g.nodes().iter().enumerate() {
        let mut v = match &node.op {
            Op::In(i) => x_in[*i],
            Op::Cst(c) => *c as f32,
            Op::Add(a, b) => y[*a] + y[*b],
            Op::Sub(a, b) => y[*a] - y[*b],
            Op::Mul(a, b) => y[*a] * y[*b],
            Op::Div(a, b) | Op::DivE(a, b) => y[*a] / y[*b],
            Op::Sqrt(a) => match bug {
                Some(Bug::Quake(steps)) => 1.0 / quake(y[*a], steps),
                _ => y[*a].sqrt(),
            },
            Op::Rsqrt(a) => 1.0 / y[*a].sqrt(),
            Op::Sum(l) => l.iter().map(|&t| y[t]).sum(),
        };
        match bug {
            Some(Bug::Half(name)) if named(name) == Some(j) => v = binary16(f64::from(v)) as f32,
            Some(Bug::Bias(name)) if named(name) == Some(j) => {
                v = (f64::from(v) * (1.0 + 1e-5)) as f32
            }
            Some(Bug::Exact("E")) if named("E") == Some(j) => v = 1.0,
            Some(Bug::Exact("dq_b")) if named("dq_b") == Some(j) => v = -y[named("D").unwrap()],
            Some(Bug::Drop("t0")) if named("t0") == Some(j) => v = y[named("di_a").unwrap()],
            Some(Bug::Drop("di_a")) if named("di_a") == Some(j) => v = y[named("A").unwrap()],
            Some(Bug::Drop("C")) if named("C") == Some(j) => v = 0.0,
            _ => {}
        }
        y[j] = v;
    }
    pixels.iter().map(|&p| y[p]).collect()
}

/// Each method's bugs: a Quake `rsqrt` (one and two Newton steps) where it takes a
/// square root, a binary16 set-up quantity, a relative bias of `10⁻⁵` in one, and a
/// dropped rounding-sensitive term.
fn bugs(method: Method) -> Vec<Bug> {
    match method {
        Method::Duff | Method::SymmetricPhong | Method::Phong => vec![
            Bug::Quake(1),
            Bug::Quake(2),
            Bug::Half("C"),
            Bug::Bias("A"),
            Bug::Drop("C"),
            Bug::Exact("E"),
        ],
        Method::Euler => vec![
            Bug::Half("ds"),
            Bug::Bias("di_a"),
            Bug::Drop("di_a"),
            Bug::Exact("dq_b"),
        ],
        _ => vec![
            Bug::Half("ds"),
            Bug::Bias("di_a"),
            Bug::Drop("t0"),
            Bug::Exact("dq_b"),
        ],
    }
}

/// Every planted bug fails `check` on at least one published set under `ieee`, and
/// Duff with the two-step Quake `rsqrt` under `shader` too; the same runs without a
/// bug pass every set under both. Prints which bugs each set catches.
#[test]
fn planted_bugs_fail_a_published_set() {
    use phong_approx::testkit::Suite;
    let m = model(Profile::Ieee, Format::Binary32).unwrap();
    let mut missed = Vec::new();
    for method in [
        Method::Duff,
        Method::Phong,
        Method::SymmetricPhong,
        Method::Euler,
        Method::CorrectedEuler,
    ] {
        let judge = |bug: Option<Bug>, profile: Profile| -> Vec<&'static str> {
            phong_approx::testkit::SETS
                .iter()
                .copied()
                .filter(|set| {
                    let r = Suite::set(set)
                        .method(method)
                        .profile(profile)
                        .check_f32(|x| {
                            let f = &method_graphs(method, Form::Any, x.n, &m).unwrap()[0];
                            let mut x_in = [0f32; 9];
                            for (k, v) in [x.na, x.nb, x.l].iter().enumerate() {
                                x_in[3 * k..3 * k + 3].copy_from_slice(v);
                            }
                            run(&f.graph, &f.pixels[0], &f.setup, &x_in, bug)
                        });
                    !r.is_ok()
                })
                .collect()
        };
        for profile in [Profile::Ieee, Profile::Shader] {
            assert!(
                judge(None, profile).is_empty(),
                "{method} without a bug fails {profile}"
            );
        }
        for bug in bugs(method) {
            let caught = judge(Some(bug), Profile::Ieee);
            println!("{method} {bug:?}: fails ieee on {caught:?}");
            if caught.is_empty() && !matches!(bug, Bug::Exact(_)) {
                missed.push(format!("{method} {bug:?}"));
            }
        }
    }
    let duff_shader = {
        let bug = Some(Bug::Quake(2));
        phong_approx::testkit::SETS.iter().any(|set| {
            !Suite::set(set)
                .method(Method::Duff)
                .profile(Profile::Shader)
                .check_f32(|x| {
                    let f = &method_graphs(Method::Duff, Form::Any, x.n, &m).unwrap()[0];
                    let mut x_in = [0f32; 9];
                    for (k, v) in [x.na, x.nb, x.l].iter().enumerate() {
                        x_in[3 * k..3 * k + 3].copy_from_slice(v);
                    }
                    run(&f.graph, &f.pixels[0], &f.setup, &x_in, bug)
                })
                .is_ok()
        })
    };
    assert!(
        duff_shader,
        "Duff with the two-step Quake rsqrt passes every set under shader"
    );
    assert!(
        missed.is_empty(),
        "bugs every published set accepts under ieee: {missed:?}"
    );
}
