//! The `shader` profile's bounds (`proofs/Profiles.v`): a software GPU (`common::emu`) rounding every operation as far as the Vulkan/WGSL precision rules allow, by recurrence and closed form, each division by `n` or 2 either way.

use super::*;

// -------------------------------------------------------- shader: the software GPU

/// The `shader` arithmetic: binary32 results rounded in `dir` (flushed below `2^-126`
/// when `flush`), divisions two units toward zero from the nearest, products fused
/// into the addition that takes them when `fused`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Gpu {
    pub(crate) dir: Dir,
    pub(crate) flush: bool,
    pub(crate) fused: bool,
    /// The model's own adversary instead of a rounding mode ([`Adv`]).
    pub(crate) adv: Option<Adv>,
}

pub(crate) const F: Emu = BINARY32;

impl Gpu {
    pub(crate) fn r(&self, x: Q) -> Q {
        if let Some(a) = self.adv {
            return a.extreme(x, a.k_op);
        }
        let y = round_dir(&x, F, self.dir);
        self.flushed(y)
    }
    /// `y`, or 0 where it is below `2^-126` and this GPU flushes.
    fn flushed(&self, y: Q) -> Q {
        if self.flush && !y.is_zero() && y.abs() < common::emu::pow2(-126) {
            Q::zero()
        } else {
            y
        }
    }
    /// An input: the nearest float, as the host hands it over (both profiles start
    /// from the nearest floats of the inputs), flushed below `2^-126` when `flush`;
    /// the model's adversary moves it as any operation.
    pub(crate) fn input(&self, x: &Q) -> Q {
        if self.adv.is_some() {
            return self.r(x.clone());
        }
        let y = round_dir(x, F, Dir::Nearest);
        self.flushed(y)
    }
    pub(crate) fn add(&self, a: &Q, b: &Q) -> Q {
        self.r(a + b)
    }
    pub(crate) fn sub(&self, a: &Q, b: &Q) -> Q {
        self.r(a - b)
    }
    pub(crate) fn mul(&self, a: &Q, b: &Q) -> Q {
        self.r(a * b)
    }
    /// Within 2.5 ulps: the nearest, then two units toward zero.
    pub(crate) fn div(&self, a: &Q, b: &Q) -> Q {
        if let Some(adv) = self.adv {
            return adv.extreme(a / b, adv.k_div);
        }
        let y = toward_zero(&round_dir(&(a / b), F, Dir::Nearest), F, 2);
        self.r(y)
    }
    /// `a − x·y`, the product fused or rounded.
    pub(crate) fn fms(&self, x: &Q, y: &Q, a: &Q) -> Q {
        if self.fused {
            self.r(a - x * y)
        } else {
            self.sub(a, &self.mul(x, y))
        }
    }
    pub(crate) fn dot(&self, a: &[Q; 3], b: &[Q; 3]) -> Q {
        if self.fused {
            // fma(x, x', fma(y, y', z·z'))
            let z = self.mul(&a[2], &b[2]);
            let y = self.r(&a[1] * &b[1] + z);
            self.r(&a[0] * &b[0] + y)
        } else {
            let xy = self.add(&self.mul(&a[0], &b[0]), &self.mul(&a[1], &b[1]));
            self.add(&xy, &self.mul(&a[2], &b[2]))
        }
    }
}

pub(crate) const GPUS: [Gpu; 4] = [
    Gpu {
        dir: Dir::TowardZero,
        flush: true,
        fused: false,
        adv: None,
    },
    Gpu {
        dir: Dir::TowardZero,
        flush: true,
        fused: true,
        adv: None,
    },
    Gpu {
        dir: Dir::Down,
        flush: true,
        fused: false,
        adv: None,
    },
    Gpu {
        dir: Dir::Up,
        flush: false,
        fused: true,
        adv: None,
    },
];

/// How shader source divides: by `n` (`k`, `ds`, `ε/n`, `dp`) and by 2 (`p_a/2`,
/// `p_b/2`, and the closed forms' `(i−1)/2` when halved in floats).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Division {
    /// One division within 2.5 ulp each (`x/n`, `x/2`).
    Once,
    /// `x·(1/n)` and `x·(1/2)`: each reciprocal a 2.5-ulp division (`1/2` computed,
    /// not the literal `0.5`), then a product.
    Reciprocal,
    /// Each division its own way: `x·(1/n)` for the divisions by `n`, a 2.5-ulp `x/2`
    /// for the halvings.
    Mixed,
}

impl Gpu {
    /// `x/m` divided as `how` says (`halving`: a division by 2).
    pub(crate) fn over(&self, how: Division, x: &Q, m: &Q, halving: bool) -> Q {
        let reciprocal = match how {
            Division::Once => false,
            Division::Reciprocal => true,
            Division::Mixed => !halving,
        };
        if reciprocal {
            self.mul(x, &self.div(&q(1, 1), m))
        } else {
            self.div(x, m)
        }
    }
}

/// The set-up on the GPU model, dividing as `how` says.
pub(crate) struct GpuSetup {
    pub(crate) pa: Q,
    pub(crate) dp: Q,
    pub(crate) dia: Q,
    pub(crate) ds: Q,
    pub(crate) t0: Q,
}

pub(crate) fn gpu_setup(g: Gpu, s: &Span<Q>, how: Division) -> GpuSetup {
    let vec = |x: &phong_approx::Vec3<Q>| [g.input(&x.x), g.input(&x.y), g.input(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let nf = qi(s.n);
    let two = q(2, 1);
    let over_n = |x: &Q| g.over(how, x, &nf, false);
    let half = |x: &Q| g.over(how, x, &two, true);
    let k = [0, 1, 2].map(|j| over_n(&g.sub(&nb[j], &na[j])));
    let a = g.dot(&k, &l);
    let pa = g.dot(&na, &l);
    let pb = g.dot(&nb, &l);
    let c = g.dot(&k, &k);
    let d = g.mul(&two, &g.dot(&k, &na));
    let dqb = if g.fused {
        g.r(&two * &nf * &c + &d)
    } else {
        g.add(&g.mul(&(&two * &nf), &c), &d)
    };
    let dia = g.fms(&half(&pa), &d, &a);
    let dib = g.fms(&half(&pb), &dqb, &a);
    let ds = over_n(&g.sub(&dib, &dia));
    // n(n−1)/2 exact, formed as an integer and converted: every theorem assumes it.
    let tri = qi(s.n) * qi(s.n - 1) / q(2, 1);
    let pn = if g.fused {
        g.r(&tri * &ds + g.r(&nf * &dia + &pa))
    } else {
        g.add(&g.add(&pa, &g.mul(&nf, &dia)), &g.mul(&tri, &ds))
    };
    let eps = g.sub(&pn, &pb);
    let t0 = g.sub(&dia, &over_n(&eps));
    let dp = over_n(&g.sub(&pb, &pa));
    GpuSetup {
        pa,
        dp,
        dia,
        ds,
        t0,
    }
}

pub(crate) fn shader(theorem: &str, method: Method) {
    shader_by(theorem, method, &[Division::Once]);
}

/// The recurrence of `method` on the four software GPUs, dividing in each of `ways`,
/// within `(α·n + β)·u` of the exact run.
pub(crate) fn shader_by(theorem: &str, method: Method, ways: &[Division]) {
    let (alpha, beta) = common::coq::constants(theorem);
    let u = f32::U;
    // The software GPU is slow: the spans up to n = 256 in the default tier.
    let most = tiered(256, 4096);
    let (mut checked, mut worst) = (0, 0f64);
    for (c, s) in spans().into_iter().filter(|(c, _)| c.n <= most) {
        let b = bound(alpha, beta, s.n, u);
        for g in GPUS {
            for &how in ways {
                let out = gpu_recurrence(method, g, how, &s);
                let what = format!("{theorem} {g:?} {how:?}");
                worst = worst.max(within(&what, &c, &s, method, &out, b));
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "{checked}");
    eprintln!("{theorem}: {checked} runs, worst {worst:.3} of the bound");
}

/// Gouraud (`g += dp`), corrected Euler (`p += t; t += ds` from `t_0`) or plain Euler
/// (the same from `s_0 = di_a`) on the GPU model, dividing as `how` says.
pub(crate) fn gpu_recurrence(method: Method, g: Gpu, how: Division, s: &Span<Q>) -> Vec<Q> {
    let st = gpu_setup(g, s, how);
    let mut out = vec![st.pa.clone()];
    let start = if method == Method::Euler {
        st.dia
    } else {
        st.t0
    };
    let (mut p, mut t) = (st.pa, start);
    for _ in 0..s.n {
        if method == Method::Gouraud {
            p = g.add(&p, &st.dp);
        } else {
            p = g.add(&p, &t);
            t = g.add(&t, &st.ds);
        }
        out.push(p.clone());
    }
    out
}

/// How a closed form takes `(i−1)/2·ds`.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Halving {
    /// `(i−1)/2` exact (`(i−1)·0.5` with the literal `0.5`), then its product with
    /// `ds`, fused into the addition or rounded.
    Exact,
    /// `c = (i−1)/2` halved in floats (a division, or `·(1/2)` with `1/2` computed),
    /// then `c·ds`, fused into the addition or rounded.
    First,
    /// `y = (i−1)·ds`, then `y/2` halved in floats.
    Last,
}

/// Corrected Euler's closed form `p_a + i·(t_0 + (i−1)/2·ds)`, or plain Euler's
/// `p_a + i·(di_a + (i−1)/2·ds)`, on the GPU model: the set-up dividing as `how`
/// says, `(i−1)/2·ds` as `halving` says (halved as `how` says), the product by `i`
/// fused into the addition of `p_a` or rounded.
pub(crate) fn gpu_closed(
    method: Method,
    g: Gpu,
    how: Division,
    halving: Halving,
    s: &Span<Q>,
) -> Vec<Q> {
    let st = gpu_setup(g, s, how);
    let start = if method == Method::Euler {
        &st.dia
    } else {
        &st.t0
    };
    let two = q(2, 1);
    (0..=s.n)
        .map(|i| {
            let x = qi(i);
            let im1 = qi(i) - q(1, 1);
            let gi = match halving {
                Halving::Exact | Halving::First => {
                    let c = match halving {
                        Halving::Exact => im1 * q(1, 2),
                        _ => g.over(how, &im1, &two, true),
                    };
                    if g.fused {
                        g.r(start + &c * &st.ds)
                    } else {
                        g.add(start, &g.mul(&c, &st.ds))
                    }
                }
                Halving::Last => g.add(start, &g.over(how, &g.mul(&im1, &st.ds), &two, true)),
            };
            if g.fused {
                g.r(&st.pa + &x * &gi)
            } else {
                g.add(&st.pa, &g.mul(&x, &gi))
            }
        })
        .collect()
}

/// `method`'s closed form on the four software GPUs in each of `ways` (a division
/// and a halving), within `β·u` of the exact run at every `n`. The per-pixel
/// divisions are slow to emulate: in the default tier each span and GPU takes one of
/// `ways` in turn (so every way runs on every GPU, on a share of the spans), in the
/// extensive tier all of them up to n = 64 and in turn on the longer spans (all of
/// them on every span took 500 s of CPU in the eight closed-form tests, half the
/// extensive tier's; up to n = 1024, 222 s; up to n = 256, about 220 s of wall time
/// on two cores, more than CI's budget allows).
pub(crate) fn shader_closed(theorem: &str, method: Method, ways: &[(Division, Halving)]) {
    let (_, beta) = common::coq::constants(theorem);
    let most = tiered(256, 4096);
    let (mut checked, mut worst) = (0, 0f64);
    let spans = spans().into_iter().filter(|(c, _)| c.n <= most);
    for (j, (c, s)) in spans.enumerate() {
        for (k, g) in GPUS.into_iter().enumerate() {
            let turn = [ways[(j + k) % ways.len()]];
            let every_way = extensive() && c.n <= 64;
            for &(how, halving) in if every_way { ways } else { &turn[..] } {
                let out = gpu_closed(method, g, how, halving, &s);
                let what = format!("{theorem} {g:?} {how:?} {halving:?}");
                worst = worst.max(within(&what, &c, &s, method, &out, beta * f32::U));
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "{checked}");
    eprintln!("{theorem}: {checked} runs, worst {worst:.3} of the bound");
}

#[test]
fn profile_shader_gouraud_binary32() {
    shader("profile_shader_gouraud_binary32", Method::Gouraud);
}

#[test]
fn profile_shader_corrected_euler_binary32() {
    shader(
        "profile_shader_corrected_euler_binary32",
        Method::CorrectedEuler,
    );
}

/// Plain Euler on the four software GPUs (each division by `n` and by 2 one division
/// within 2.5 ulp, as the theorem takes it; `·(1/n)` is the derived bound's, in
/// [`profile_shader_derived_binary32`]).
#[test]
fn profile_shader_euler_binary32() {
    shader("profile_shader_euler_binary32", Method::Euler);
}

/// The ways of dividing the `_recip` theorems cover besides one 2.5-ulp division
/// each (all three in the extensive tier).
pub(crate) fn reciprocal_ways() -> &'static [Division] {
    tiered(
        &[Division::Reciprocal, Division::Mixed][..],
        &[Division::Once, Division::Reciprocal, Division::Mixed][..],
    )
}

/// Gouraud on the four software GPUs with `dp = (p_b − p_a)·(1/n)`, the reciprocal a
/// 2.5-ulp division then a product, and with one 2.5-ulp division.
#[test]
fn profile_shader_gouraud_recip_binary32() {
    shader_by(
        "profile_shader_gouraud_recip_binary32",
        Method::Gouraud,
        &[Division::Reciprocal, Division::Once],
    );
}

/// Corrected Euler's recurrence on the software GPUs with every division by `n` and
/// by 2 through a 2.5-ulp reciprocal and a product (`1/2` computed), or `·(1/n)` with
/// a 2.5-ulp `/2`; `n(n−1)/2` exact.
#[test]
fn profile_shader_corrected_euler_recip_binary32() {
    shader_by(
        "profile_shader_corrected_euler_recip_binary32",
        Method::CorrectedEuler,
        reciprocal_ways(),
    );
}

/// Plain Euler's recurrence on the software GPUs, dividing as in
/// [`profile_shader_corrected_euler_recip_binary32`].
#[test]
fn profile_shader_euler_recip_binary32() {
    shader_by(
        "profile_shader_euler_recip_binary32",
        Method::Euler,
        reciprocal_ways(),
    );
}

/// Corrected Euler by its closed form on the software GPUs: one 2.5-ulp division
/// each, `(i−1)/2` exact, fused or not; `126.5·u` at every `n`.
#[test]
fn profile_shader_corrected_euler_closed_binary32() {
    shader_closed(
        "profile_shader_corrected_euler_closed_binary32",
        Method::CorrectedEuler,
        &[(Division::Once, Halving::Exact)],
    );
}

/// As [`profile_shader_corrected_euler_closed_binary32`], every division through a
/// 2.5-ulp reciprocal and a product, or mixed.
#[test]
fn profile_shader_corrected_euler_closed_recip_binary32() {
    let ways: Vec<_> = reciprocal_ways()
        .iter()
        .map(|&how| (how, Halving::Exact))
        .collect();
    shader_closed(
        "profile_shader_corrected_euler_closed_recip_binary32",
        Method::CorrectedEuler,
        &ways,
    );
}

/// Plain Euler by its closed form on the software GPUs: one 2.5-ulp division each,
/// `(i−1)/2` exact, fused or not; `277.9·u` at every `n`.
#[test]
fn profile_shader_euler_closed_binary32() {
    shader_closed(
        "profile_shader_euler_closed_binary32",
        Method::Euler,
        &[(Division::Once, Halving::Exact)],
    );
}

/// As [`profile_shader_euler_closed_binary32`], every division through a 2.5-ulp
/// reciprocal and a product, or mixed.
#[test]
fn profile_shader_euler_closed_recip_binary32() {
    let ways: Vec<_> = reciprocal_ways()
        .iter()
        .map(|&how| (how, Halving::Exact))
        .collect();
    shader_closed(
        "profile_shader_euler_closed_recip_binary32",
        Method::Euler,
        &ways,
    );
}

/// The ways of halving `(i−1)/2·ds` in floats, for each way of dividing in `ways`.
pub(crate) fn halved(ways: &[Division]) -> Vec<(Division, Halving)> {
    ways.iter()
        .flat_map(|&how| [(how, Halving::First), (how, Halving::Last)])
        .collect()
}

/// Corrected Euler's closed form with `(i−1)/2` halved in floats by a 2.5-ulp
/// division — `c = (i−1)/2` then `c·ds`, or `(i−1)·ds` then `/2` — and one 2.5-ulp
/// division each in the set-up; `131.5·u`.
#[test]
fn profile_shader_corrected_euler_closed_half_binary32() {
    shader_closed(
        "profile_shader_corrected_euler_closed_half_binary32",
        Method::CorrectedEuler,
        &halved(&[Division::Once]),
    );
}

/// As [`profile_shader_corrected_euler_closed_half_binary32`], every division (the
/// halving included, through a computed `1/2`) a 2.5-ulp reciprocal and a product,
/// or mixed; `148.11·u`.
#[test]
fn profile_shader_corrected_euler_closed_half_recip_binary32() {
    shader_closed(
        "profile_shader_corrected_euler_closed_half_recip_binary32",
        Method::CorrectedEuler,
        &halved(reciprocal_ways()),
    );
}

/// Plain Euler's closed form with `(i−1)/2` halved in floats, as in
/// [`profile_shader_corrected_euler_closed_half_binary32`]; `281.65·u`.
#[test]
fn profile_shader_euler_closed_half_binary32() {
    shader_closed(
        "profile_shader_euler_closed_half_binary32",
        Method::Euler,
        &halved(&[Division::Once]),
    );
}

/// As [`profile_shader_euler_closed_half_binary32`], every division (the halving
/// included) a 2.5-ulp reciprocal and a product, or mixed; `313.36·u`.
#[test]
fn profile_shader_euler_closed_half_recip_binary32() {
    shader_closed(
        "profile_shader_euler_closed_half_recip_binary32",
        Method::Euler,
        &halved(reciprocal_ways()),
    );
}

/// The model's own roundings are what the profile allows: toward zero never moves
/// away from zero, the 2.5-ulp division is within 2.5 ulps, flushing only touches
/// values below `2^-126`. (The GPU model is checked before it is trusted.)
#[test]
fn the_gpu_model_rounds_as_the_shader_profile_allows() {
    let g = GPUS[0];
    for (a, b) in [(1i64, 3i64), (-2, 7), (10, 9), (1, 1000)] {
        let x = q(a, b);
        let rz = g.r(x.clone());
        assert!(rz.abs() <= x.abs());
        let d = g.div(&q(a, 1), &q(b, 1));
        let ulp = common::emu::ulp(&x, F);
        assert!(
            (d.clone() - x.clone()).abs() <= ulp * q(5, 2),
            "{a}/{b}: {d}"
        );
        assert!(d != round_dir(&x, F, Dir::Nearest));
    }
    let tiny = common::emu::pow2(-130);
    assert!(g.r(tiny.clone()).is_zero());
    assert!(!GPUS[3].r(tiny).is_zero());
}

// ------------------------------------------- Phong under ieee (derived, §18.4)

/// `proofs/ShaderSqrt.v`, `shader_sqrt_recip_rsqrt`: a square root taken as
/// `1/inverseSqrt(x)` — `inverseSqrt` within `4u` relative, the reciprocal within `5u` —
/// is within `(9 + 2^-18)u·√x` for `u ≤ 2^-24`. Checked exactly in rationals on
/// `x = s²` at the extreme and at sampled relative errors `d1`, `d2`
/// (`y/√x = (1 + d2)/(1 + d1)`): every one within the constant, and the extreme one
/// above `9u` (so `9`, the sum of the two, is not a bound). The constant and the two
/// hypotheses are read from the statement: they must be the checker's `κ_sqrt`
/// (`tolerance::profile::arith`) and the graph model's `κ` of `inverseSqrt` and of a
/// division under `shader`.
#[test]
fn shader_sqrt_recip_rsqrt() {
    let st = common::coq::statement("proofs/ShaderSqrt.v", "shader_sqrt_recip_rsqrt");
    for part in [
        "0 <= u <= / 16777216",
        "Rabs (r - / sqrt x) <= 4 * u * Rabs (/ sqrt x)",
        "Rabs (y - / r) <= 5 * u * Rabs (/ r)",
        "Rabs (y - sqrt x) <= (9 + / 262144) * u * sqrt x",
    ] {
        assert!(
            st.contains(part),
            "ShaderSqrt.v's statement changed: no {part:?} in {st}"
        );
    }
    let kappa = 9.0 + 1.0 / 262_144.0;
    let a = phong_approx::tolerance::profile::arith(Profile::Shader, Format::Binary32).unwrap();
    assert_eq!(a.sqrt, kappa, "model.rs's κ_sqrt and ShaderSqrt.v");
    let m = phong_approx::tolerance::graphs::model(Profile::Shader, Format::Binary32).unwrap();
    assert_eq!(
        (m.rsqrt, m.div),
        (4.0, 5.0),
        "the graph model's inverseSqrt and division"
    );
    assert!(m.sqrt_is_recip_rsqrt);
    let u = q(1, 1 << 24);
    let k = Q::from_integer(9.into()) + q(1, 262_144);
    let mut worst = Q::zero();
    for s in [q(1, 1), q(3, 7), q(12_345, 4), q(1, 1 << 20)] {
        for i in -4i64..=4 {
            for j in -5i64..=5 {
                // d1 = i·u, d2 = j·u, and two sampled points between the integers.
                for (d1, d2) in [
                    (u.clone() * q(i, 1), u.clone() * q(j, 1)),
                    (u.clone() * q(i * 7, 8), u.clone() * q(j * 3, 4)),
                ] {
                    let r = (q(1, 1) + d1.clone()) / s.clone();
                    let y = (q(1, 1) + d2) / r;
                    let err = (y - s.clone()).abs() / (u.clone() * s.clone());
                    assert!(err <= k, "s = {s}, d1 = {d1}: {} u", err.to_f64());
                    if err > worst {
                        worst = err;
                    }
                }
            }
        }
    }
    assert!(
        worst > Q::from_integer(9.into()),
        "the extreme reaches past 9u: {}",
        worst.to_f64()
    );
}

/// `proofs/ShaderSqrt.v`, `shader_sqrt_recip_rsqrt_ap1`: the same in the `ap1` form of
/// `FloatModelK.v` with `η = 0` — what a node of the standard model takes. The software
/// GPUs' square roots (`1/inverseSqrt` at their allowed extremes) on values across the
/// binary32 range are within it.
#[test]
fn shader_sqrt_recip_rsqrt_ap1() {
    let st = common::coq::statement("proofs/ShaderSqrt.v", "shader_sqrt_recip_rsqrt_ap1");
    for part in [
        "ap1 (4 * u) 0 r (/ sqrt x)",
        "ap1 (5 * u) 0 y (/ r)",
        "ap1 ((9 + / 262144) * u) 0 y (sqrt x)",
    ] {
        assert!(
            st.contains(part),
            "ShaderSqrt.v's statement changed: no {part:?} in {st}"
        );
    }
    use phong_approx::reference::transcendental::sqrt;
    let bound = (9.0 + 1.0 / 262_144.0) * f32::U;
    let mut checked = 0;
    for g in GPUS {
        for (a, b) in [
            (2i64, 1i64),
            (1, 3),
            (7, 5),
            (1, 1000),
            (1 << 40, 3),
            (5, 1 << 40),
        ] {
            let x = q(a, b);
            let got = g.sqrt(&x);
            let want = sqrt(&x);
            let rel = ((got - want.clone()) / want).abs().to_f64();
            assert!(rel <= bound, "{a}/{b}: {rel:e} > {bound:e}");
            checked += 1;
        }
    }
    assert_eq!(checked, 24);
}
