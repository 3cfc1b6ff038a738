//! The published vector sets judged as a user's code is judged: the fast kernels on every vector path, every correct native variant under `ieee`, the software GPUs under `shader`, and the specular bound.

use super::*;

/// `FastSpan`'s kernels and `fast_rows::RowSpan`'s (set up from the span's own
/// floats) pass under `ieee` at every `n` from 1 to 40 (128 in the extensive tier)
/// and at `2^k − 1`, `2^k` up to 1024 (4096): their set-ups (the closed form of `ds`, Gouraud plus a parabola) are not the
/// graph of the theorems, so this is evidence, not proof (docs/float.md §18.3).
#[test]
fn fast_kernels_pass_under_ieee_at_every_n() {
    use phong_approx::fast::FastSpan;
    use phong_approx::fast_rows::RowSpan;
    use phong_approx::simd;
    let z = Stereo(0, 0, 1);
    let mut ns: Vec<u32> = (1..=tiered(40, 128)).collect();
    for k in tiered(7, 8)..=tiered(9, 12) {
        ns.extend([(1 << k) - 1, 1 << k]);
    }
    let shapes = [
        (z, Stereo(1, 0, 3), Stereo(2, 1, 5)),
        (z, Stereo(96, 0, 1), Stereo(0, 0, 1)),
        (Stereo(1, 2, 3), Stereo(-3, 1, 4), Stereo(1, 1, 2)),
        (z, Stereo(7, 3, 2), Stereo(3, -1, 5)),
    ];
    let mut checked = 0;
    let paths = simd::Path::supported_paths();
    let chosen = simd::path();
    // The largest difference between two paths' values, in ulps of the larger.
    let mut between_paths = 0.0f64;
    for &n in &ns {
        for &(na, nb, l) in &shapes {
            let c = Case {
                why: "fast kernels under ieee",
                na,
                nb,
                l,
                n,
            };
            let Some(s) = c.span() else { continue };
            macro_rules! run {
                ($f:ty) => {{
                    let u = <$f as Native>::U;
                    let fs = s.cast::<$f>().unwrap();
                    let fast = FastSpan::<$f>::from_span(&fs);
                    let dot = |a: [$f; 3], b: [$f; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
                    let v = |x: &phong_approx::Vec3<$f>| [x.x, x.y, x.z];
                    let (pa, pb, cw) = (dot(v(&fs.na), v(&fs.l)), dot(v(&fs.nb), v(&fs.l)), dot(v(&fs.na), v(&fs.nb)));
                    let inv_n = 1.0 / n as $f;
                    let omc = 1.0 - cw;
                    let row = RowSpan::<$f> {
                        p_a: pa,
                        p_b: pb,
                        omc,
                        inv_n,
                        a1: (pb - pa) * inv_n,
                        a2: 0.5 * omc * (pa + pb) * inv_n * inv_n,
                        n,
                    };
                    type Run = Box<dyn Fn(&mut [$f])>;
                    let kernels: Vec<(&str, Method, Run)> = vec![
                        ("FastSpan::corrected_euler", Method::CorrectedEuler, Box::new(move |o| fast.corrected_euler(o))),
                        ("FastSpan::corrected_euler_serial", Method::CorrectedEuler, Box::new(move |o| fast.corrected_euler_serial(o))),
                        ("FastSpan::gouraud", Method::Gouraud, Box::new(move |o| fast.gouraud(o))),
                        ("FastSpan::gouraud_serial", Method::Gouraud, Box::new(move |o| fast.gouraud_serial(o))),
                        ("FastSpan::euler", Method::Euler, Box::new(move |o| fast.euler(o))),
                        ("FastSpan::phong", Method::Phong, Box::new(move |o| fast.phong(o))),
                        ("FastSpan::adaptive", Method::Adaptive, Box::new(move |o| { fast.adaptive(1.0, o); })),
                        ("FastSpan::duff_serial", Method::Duff, Box::new(move |o| fast.duff_serial(o))),
                        ("FastSpan::symmetric_phong", Method::SymmetricPhong, Box::new(move |o| fast.symmetric_phong(o))),
                        ("RowSpan::corrected_euler", Method::CorrectedEuler, Box::new(move |o| row.corrected_euler(o))),
                        ("RowSpan::gouraud", Method::Gouraud, Box::new(move |o| row.gouraud(o))),
                        ("RowSpan::phong", Method::Phong, Box::new(move |o| row.phong(o))),
                    ];
                    for (name, m, run) in kernels {
                        let Some(b) = profile_bound_of(m, Profile::Ieee, &s, <$f as Native>::FORMAT) else {
                            continue;
                        };
                        let want = exact_values(m, &c, &s);
                        // Every vector path the CPU has (`phong_approx::simd`).
                        let mut first: Option<Vec<$f>> = None;
                        for &path in &paths {
                            simd::force(path).unwrap();
                            let mut out = vec![0.0 as $f; s.len()];
                            run(&mut out);
                            for (i, (g, w)) in out.iter().zip(want.iter()).enumerate() {
                                let e = (g.q() - w.clone()).abs().to_f64();
                                assert!(
                                    e <= b,
                                    "{name} ({}, {path} path): pixel {i} of n = {n}: {e:e} > ieee bound {b:e} ({:.2} of it)\ninputs: {c:?}",
                                    stringify!($f),
                                    e / b
                                );
                            }
                            match &first {
                                None => first = Some(out),
                                Some(f0) => {
                                    for (x, y) in f0.iter().zip(&out) {
                                        let d = (x.q() - y.q()).abs().to_f64() / (x.abs().max(y.abs()) as f64 * 2.0 * u).max(f64::MIN_POSITIVE);
                                        between_paths = between_paths.max(d);
                                    }
                                }
                            }
                            checked += 1;
                        }
                    }
                }};
            }
            run!(f32);
            run!(f64);
        }
    }
    simd::force(chosen).unwrap();
    let names: Vec<&str> = paths.iter().map(|p| p.name()).collect();
    println!(
        "fast kernels under ieee on the vector paths {}; largest difference between paths {between_paths} ulps",
        names.join(", ")
    );
    assert!(checked > 1000 * paths.len(), "{checked}");
    // docs/performance.md and `phong_approx::simd` promise the same bits on every path.
    assert_eq!(between_paths, 0.0, "the vector paths' values differ");
}

// ------------------------------------- the published sets, through the test kit

/// The exact spans of a published set's cases, by id.
pub(crate) fn published_spans(set: &str) -> std::collections::HashMap<String, Span<Q>> {
    let file = phong_approx::testkit::published(set).unwrap();
    file.cases
        .iter()
        .map(|c| {
            let s = phong_approx::conformance::integrity::case_span(c).unwrap();
            (c.id.clone(), s)
        })
        .collect()
}

/// `check` of the published set `set` for `method` under `profile`, on the `f32`
/// values `run` gives for each case id (through the test kit).
pub(crate) fn published_f32(
    set: &str,
    method: Method,
    profile: Profile,
    run: impl Fn(&str) -> Vec<Q>,
) -> phong_approx::testkit::Report {
    phong_approx::testkit::Suite::set(set)
        .method(method)
        .profile(profile)
        .check_f32(|x| run(x.id).iter().map(|y| y.to_f64() as f32).collect())
}

/// An implementation written here, by its method and name.
pub(crate) type Imp<T> = (
    Method,
    &'static str,
    fn(Variant, &Span<Q>) -> Vec<Q>,
    std::marker::PhantomData<T>,
);

pub(crate) fn implementations<T: Native + 'static>() -> Vec<Imp<T>> {
    use std::marker::PhantomData as P;
    vec![
        (Method::Gouraud, "g += dp", gouraud::<T>, P),
        (
            Method::CorrectedEuler,
            "p += t; t += ds",
            corrected_euler::<T>,
            P,
        ),
        (
            Method::CorrectedEuler,
            "closed form",
            corrected_euler_closed::<T>,
            P,
        ),
        (Method::Euler, "E += s; s += ds", euler::<T>, P),
        (Method::Euler, "closed form", euler_closed::<T>, P),
        (Method::Duff, "forward differences", duff::<T>, P),
        (
            Method::Phong,
            "Horner",
            |v, s| phong::<T>(PhongForm::Horner, v, s),
            P,
        ),
        (
            Method::Phong,
            "per-pixel normal",
            |v, s| phong::<T>(PhongForm::PerPixel, v, s),
            P,
        ),
        (
            Method::Phong,
            "normalize, then dot",
            |v, s| phong::<T>(PhongForm::NormalizeThenDot, v, s),
            P,
        ),
        (
            Method::SquaredCorrectedEuler,
            "g += t; t += ds; sign(p)·√g",
            squared::<T>,
            P,
        ),
    ]
}

/// Every implementation of this file — Gouraud, corrected Euler (recurrence and closed
/// form), Euler (recurrence and closed form), Duff, Phong (Horner, per-pixel normal,
/// normalize-then-dot), the squared method, each in three variants (orders, `mul_add`, reciprocals) —
/// passes `check` under `ieee` on every published set, in `f32` and `f64`, through
/// the test kit (the path a user's `cargo test` takes).
#[test]
fn correct_variants_pass_the_published_sets_under_ieee() {
    use phong_approx::testkit::Suite;
    let mut runs = 0;
    for set in phong_approx::testkit::SETS {
        let spans = published_spans(set);
        for v in VARIANTS {
            for (m, name, imp, _) in implementations::<f32>() {
                let r = published_f32(set, m, Profile::Ieee, |id| imp(v, &spans[id]));
                assert!(r.is_ok(), "{set} {m} {name} {v:?} f32:\n{r}");
                runs += 1;
            }
            for (m, name, imp, _) in implementations::<f64>() {
                let r = Suite::set(set)
                    .method(m)
                    .profile(Profile::Ieee)
                    .check_f64(|x| imp(v, &spans[x.id]).iter().map(|y| y.to_f64()).collect());
                assert!(r.is_ok(), "{set} {m} {name} {v:?} f64:\n{r}");
                runs += 1;
            }
        }
    }
    assert_eq!(runs, 3 * 3 * 10 * 2);
}

/// The software GPUs pass `check` under `shader` on every published set: Gouraud,
/// corrected Euler and Euler (the recurrences with one 2.5-ulp division each and
/// with reciprocals, and the closed forms halving `(i−1)/2` in floats through a
/// computed `1/2`), Duff and Phong (Horner). The default tier runs the truncating,
/// flushing, unfused GPU; the extensive tier all four.
#[test]
fn the_software_gpus_pass_the_published_sets_under_shader() {
    let gpus = if extensive() { &GPUS[..] } else { &GPUS[..1] };
    let recurrence = |method: Method, how: Division| {
        move |g: Gpu, s: &Span<Q>| gpu_recurrence(method, g, how, s)
    };
    let closed = |method: Method, halving: Halving| {
        move |g: Gpu, s: &Span<Q>| gpu_closed(method, g, Division::Reciprocal, halving, s)
    };
    type GpuImp = Box<dyn Fn(Gpu, &Span<Q>) -> Vec<Q>>;
    let imps: Vec<(Method, GpuImp)> = vec![
        (
            Method::Gouraud,
            Box::new(recurrence(Method::Gouraud, Division::Once)),
        ),
        (
            Method::Gouraud,
            Box::new(recurrence(Method::Gouraud, Division::Reciprocal)),
        ),
        (
            Method::CorrectedEuler,
            Box::new(recurrence(Method::CorrectedEuler, Division::Once)),
        ),
        (
            Method::CorrectedEuler,
            Box::new(recurrence(Method::CorrectedEuler, Division::Reciprocal)),
        ),
        (
            Method::CorrectedEuler,
            Box::new(closed(Method::CorrectedEuler, Halving::Last)),
        ),
        (Method::Euler, Box::new(gpu_euler)),
        (
            Method::Euler,
            Box::new(recurrence(Method::Euler, Division::Reciprocal)),
        ),
        (
            Method::Euler,
            Box::new(closed(Method::Euler, Halving::First)),
        ),
        (
            Method::Duff,
            Box::new(|g, s| gpu_duff_or_phong(g, s, false, Division::Once)),
        ),
        (
            Method::Phong,
            Box::new(|g, s| gpu_duff_or_phong(g, s, true, Division::Once)),
        ),
    ];
    for set in phong_approx::testkit::SETS {
        let spans = published_spans(set);
        for &g in gpus {
            for (m, imp) in &imps {
                let r = published_f32(set, *m, Profile::Shader, |id| imp(g, &spans[id]));
                assert!(r.is_ok(), "{set} {m} {g:?}:\n{r}");
            }
        }
    }
}

/// The specular bound (`tolerance::specular_bound`) on top of the `ieee` bound of
/// corrected Euler holds for `max(0, v)^s` computed by `s − 1` products (left to
/// right, and by squaring) and by `powi`, in `f32` and `f64`, on spans whose values
/// exceed 1 (up to about 1.19, where the factor `s·v_max^(s−1)` is largest) and on the
/// profile spans up to `n = 32` (128 in the extensive tier), for `s` from 1 to 128; exact
/// values `max(0, CE_i)^s` in rationals.
#[test]
fn specular_bound_holds() {
    use phong_approx::tolerance::specular_bound;
    use std::ops::Mul;
    fn pow_by_products<T: Copy + Mul<Output = T>>(x: T, s: u32, squaring: bool) -> T {
        if squaring {
            let (mut r, mut b, mut e) = (None::<T>, x, s);
            while e > 0 {
                if e & 1 == 1 {
                    r = Some(r.map_or(b, |r| r * b));
                }
                e >>= 1;
                if e > 0 {
                    b = b * b;
                }
            }
            r.unwrap()
        } else {
            (1..s).fold(x, |acc, _| acc * x)
        }
    }
    let mut all: Vec<Span<Q>> = spans()
        .into_iter()
        .map(|(_, s)| s)
        .filter(|s| s.n <= tiered(32, 128))
        .collect();
    // Normals 90° apart with L halfway: corrected Euler's values rise to about 1.19.
    let z = Stereo(0, 0, 1);
    for n in [2, 3, 7, 64, 255] {
        for (nb, l) in [
            (Stereo(1, 0, 1), Stereo(1, 0, 3)),
            (Stereo(5, 0, 2), Stereo(3, 1, 7)),
        ] {
            let c = Case {
                why: "values above 1",
                na: z,
                nb,
                l,
                n,
            };
            all.extend(c.span());
        }
    }
    let (mut checked, mut above_one, mut worst) = (0, 0, 0f64);
    for s in &all {
        let exact = Method::CorrectedEuler.values(s).unwrap();
        let v_max = exact
            .iter()
            .map(|x| x.to_f64().max(0.0))
            .fold(0.0, f64::max)
            * (1.0 + 1e-12);
        if v_max > 1.0 {
            above_one += 1;
        }
        // The bound of the values, once per span and format (it does not depend on `s`).
        let bound_32 = profile_bound_of(Method::CorrectedEuler, Profile::Ieee, s, Format::Binary32);
        let bound_64 = profile_bound_of(Method::CorrectedEuler, Profile::Ieee, s, Format::Binary64);
        for sh in [1u32, 3, 16, 128] {
            let want: Vec<Q> = exact
                .iter()
                .map(|x| {
                    let x = if x.is_positive() {
                        x.clone()
                    } else {
                        Q::zero()
                    };
                    num_traits::pow(x, sh as usize)
                })
                .collect();
            macro_rules! run {
                ($t:ty, $bound:expr) => {{
                    let Some(b) = $bound else {
                        continue;
                    };
                    let bs = specular_bound(b, f64::from(sh), v_max, <$t as Native>::FORMAT);
                    for v in &VARIANTS[..2] {
                        let v = *v;
                        let base: Vec<$t> = corrected_euler::<$t>(v, s).iter().map(|x| x.to_f64() as $t).collect();
                        for how in 0..3 {
                            for (i, (x, w)) in base.iter().zip(&want).enumerate() {
                                let x = x.max(0.0);
                                let y = match how {
                                    0 => pow_by_products(x, sh, false),
                                    1 => pow_by_products(x, sh, true),
                                    _ => x.powi(sh as i32),
                                };
                                let e = (y.q() - w.clone()).abs().to_f64();
                                worst = worst.max(e / bs);
                                assert!(e <= bs, "{} s = {sh}, way {how}, {v:?}: pixel {i} of n = {}: {e:e} > {bs:e}", stringify!($t), s.n);
                            }
                        }
                        checked += 1;
                    }
                }};
            }
            run!(f32, bound_32);
            run!(f64, bound_64);
        }
    }
    assert!(checked > 500 && above_one >= 5, "{checked} {above_one}");
    eprintln!("specular: {checked} runs, {above_one} spans above 1, worst {worst:.3} of the bound");
}

/// Bugs planted in the squared method's native `f32` implementation fail a published
/// set under `ieee` (so its graph bound can fail): the sign ignored, plain Euler on `g`
/// (no correction), `A` biased by `10^-5`; the same code without the bug passes
/// (`correct_variants_pass_the_published_sets_under_ieee`).
#[test]
fn planted_squared_bugs_fail_a_published_set() {
    for bug in [
        SquaredBug::NoSign,
        SquaredBug::NoCorrection,
        SquaredBug::BiasedA,
    ] {
        let failed: Vec<&str> = phong_approx::testkit::SETS
            .into_iter()
            .filter(|set| {
                let spans = published_spans(set);
                let r = published_f32(set, Method::SquaredCorrectedEuler, Profile::Ieee, |id| {
                    squared_with::<f32>(VARIANTS[0], &spans[id], Some(bug))
                });
                !r.is_ok()
            })
            .collect();
        println!("{bug:?}: fails {failed:?}");
        assert!(!failed.is_empty(), "{bug:?} passes every published set");
    }
}
