//! Phong, Duff and symmetric Phong under `ieee` and `shader`: the composed bounds (`docs/float.md` §18.4–18.5) against native and software-GPU implementations, and the GPU's square root.

use super::*;

/// The forms of Phong that `phong_ieee` covers (docs/float.md §18.4).
#[derive(Clone, Copy, Debug)]
pub(crate) enum PhongForm {
    /// Horner's closed form `(A·i + B)/√((C·i + D)·i + E)` (`FastSpan::phong`'s).
    Horner,
    /// The per-pixel normal `N_a + i·k`, then `p/√q`.
    PerPixel,
    /// `(1 − t)·N_a + t·N_b`, `t = i/n`, normalized by `1/√q`, dotted with `L`.
    NormalizeThenDot,
}

pub(crate) fn phong<T: Native>(form: PhongForm, v: Variant, s: &Span<Q>) -> Vec<Q> {
    let one = T::from_u32(1);
    let ratio = |p: T, q: T| {
        if v.reciprocal {
            p.mul(one.div(q.sqrt()))
        } else {
            p.div(q.sqrt())
        }
    };
    // Horner and the per-pixel normal: `p̂` and `q̂` as the count theorems' tests
    // compute them, then the value.
    let counted = |form| {
        phong_value::pq::<T>(form, v.dot, v.fused, v.reciprocal, s)
            .into_iter()
            .map(|(p, q)| ratio(p, q).q())
            .collect()
    };
    match form {
        PhongForm::Horner => counted(phong_value::Form::Horner),
        PhongForm::PerPixel => counted(phong_value::Form::Pixel),
        PhongForm::NormalizeThenDot => {
            let vec = |x: &phong_approx::Vec3<Q>| [T::of(&x.x), T::of(&x.y), T::of(&x.z)];
            let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
            let nf = T::from_u32(s.n);
            let inv = one.div(nf);
            let over_n = |x: T| if v.reciprocal { x.mul(inv) } else { x.div(nf) };
            let axpy = |a: T, x: T, y: T| if v.fused { a.fma(x, y) } else { a.mul(x) + y };
            (0..=s.n)
                .map(|i| {
                    let t = over_n(T::from_u32(i));
                    let nn = [0, 1, 2].map(|j| axpy(t, nb[j], (one - t).mul(na[j])));
                    let r = one.div(dot(v.dot, nn, nn).sqrt());
                    dot(v.dot, nn.map(|x| x.mul(r)), l).q()
                })
                .collect()
        }
    }
}

/// Phong's exact value `p_i/√q_i` on the exact span, to 2^-256 (the square root of
/// the exact `q_i`, `phong_approx::reference::transcendental`).
pub(crate) fn phong_exact(s: &Span<Q>) -> Vec<Q> {
    use phong_approx::reference::transcendental::sqrt;
    (0..=s.n).map(|i| s.p_at(i) / sqrt(&s.q_at(i))).collect()
}

/// Spans for Phong: the profile spans, the two reported closed-form rejections
/// (nearly opposite normals, `n = 255`) and nearly opposite spans of growing
/// closeness at `n = 2^k − 1`, `2^k`.
pub(crate) fn phong_spans() -> Vec<Span<Q>> {
    let v = |x: [(i64, i64); 3]| {
        phong_approx::Vec3::new(q(x[0].0, x[0].1), q(x[1].0, x[1].1), q(x[2].0, x[2].1))
    };
    let mut out: Vec<Span<Q>> = spans().into_iter().map(|(_, s)| s).collect();
    let z = v([(0, 1), (0, 1), (1, 1)]);
    let reported = [
        (
            v([(8, 801), (-7, 20025), (-20024, 20025)]),
            v([(6, 7), (-2, 7), (3, 7)]),
        ),
        (
            v([(192, 9217), (0, 1), (-9215, 9217)]),
            v([(1, 1), (0, 1), (0, 1)]),
        ),
    ];
    for (nb, l) in reported {
        out.push(Span::new(z.clone(), nb, l, 255).unwrap());
    }
    // N_b = (2m, 0, 1 − m²)/(1 + m²) reflected to near −N_a: m = 1/(2^j).
    for j in 2..tiered(9, 12) {
        let m = q(1, 1 << j);
        let den = Q::from_integer(1.into()) + m.clone() * m.clone();
        let nb = phong_approx::Vec3::new(
            q(2, 1) * m.clone() / den.clone(),
            q(0, 1),
            (m.clone() * m.clone() - Q::from_integer(1.into())) / den,
        );
        for n in [15, 16, 255, 256] {
            out.push(Span::new(z.clone(), nb.clone(), v([(3, 5), (0, 1), (4, 5)]), n).unwrap());
        }
    }
    out
}

pub(crate) fn phong_ieee<T: Native>(what: &str) {
    use phong_approx::tolerance::{profile::phong_ieee, Shape};
    let (mut checked, mut refused, mut worst) = (0, 0, 0f64);
    // Up to n = 256 in the default tier, 1024 in the extensive tier (the exact square
    // root of every pixel is the cost; the reported spans are n = 255).
    for s in phong_spans()
        .into_iter()
        .filter(|s| s.n <= tiered(256, 1024))
    {
        let shape = Shape::of(&s);
        let Some(b) = phong_ieee(s.n, shape.q_min, shape.dn, T::FORMAT) else {
            refused += 1;
            continue;
        };
        let want = phong_exact(&s);
        for form in [
            PhongForm::Horner,
            PhongForm::PerPixel,
            PhongForm::NormalizeThenDot,
        ] {
            for v in VARIANTS {
                let got = phong::<T>(form, v, &s);
                for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                    let e = (g.clone() - w.clone()).abs().to_f64();
                    worst = worst.max(e / b);
                    assert!(
                        e <= b,
                        "{what} {form:?} {v:?}: pixel {i} of n = {}: error {e:e} > bound {b:e} (q_min {:e})",
                        s.n,
                        shape.q_min
                    );
                }
                checked += 1;
            }
        }
    }
    assert!(
        checked > 100,
        "{checked} checked, {refused} without a bound"
    );
    // The derivation is loose (it allows for every form at once): report how loose.
    eprintln!(
        "{what}: {checked} runs, worst error {worst:.3} of the bound, {refused} spans without one"
    );
}

/// Phong's derived `ieee` bound (`phong_approx::tolerance::profile::phong_ieee`,
/// docs/float.md §18.4) holds for Horner's closed form, the per-pixel normal and
/// normalize-then-dot, each with three orders, fused or not, with and without
/// reciprocals, in binary32.
#[test]
fn phong_ieee_derived_binary32() {
    phong_ieee::<f32>("phong_ieee_derived_binary32");
}

/// As [`phong_ieee_derived_binary32`], in binary64, including the two closed-form
/// spans that the reference bound rejected (25,000 u against 1,600 u).
#[test]
fn phong_ieee_derived_binary64() {
    phong_ieee::<f64>("phong_ieee_derived_binary64");
}

// ---------- Duff (composed from theorems), Phong (derived) under ieee and shader, §18.4–18.5

/// The bound `check` applies to `method` under `profile` on `s` (`None`: no bound).
pub(crate) fn profile_bound_of(
    method: Method,
    profile: Profile,
    s: &Span<Q>,
    format: Format,
) -> Option<f64> {
    profile_bound_in(method, profile, Form::Any, s, format)
}

/// [`profile_bound_of`] for an implementation that declares its form.
pub(crate) fn profile_bound_in(
    method: Method,
    profile: Profile,
    form: Form,
    s: &Span<Q>,
    format: Format,
) -> Option<f64> {
    let shape = phong_approx::tolerance::Shape::of(s);
    phong_approx::tolerance::profile::profile_span_bound(method, profile, form, &shape, format)
}

/// Plain Euler (eqs. 12–14) as the recurrence `E += s; s += ds` from `s_0 = di_a`.
pub(crate) fn euler<T: Native>(v: Variant, s: &Span<Q>) -> Vec<Q> {
    let st = setup::<T>(v, s);
    second_order(st.pa, st.dia, st.ds, s.n)
}

/// Plain Euler by its closed form `p_a + i·(di_a + (i−1)/2·ds)`, fused or not.
pub(crate) fn euler_closed<T: Native>(v: Variant, s: &Span<Q>) -> Vec<Q> {
    let st = setup::<T>(v, s);
    let half = T::of(&q(1, 2));
    (0..=s.n)
        .map(|i| {
            let fi = T::from_u32(i);
            let g = if v.fused {
                (fi - T::from_u32(1)).mul(half).fma(st.ds, st.dia)
            } else {
                st.dia + (fi - T::from_u32(1)).mul(half).mul(st.ds)
            };
            pa_plus_i_times(v, st.pa, fi, g).q()
        })
        .collect()
}

/// Duff's forward differences (eqs. 5–7): `p += A; q += dq; dq += 2C` from `p = B`,
/// `q = E`, `dq = C + D`, then `p/√q` (or `p·(1/√q)` with reciprocals).
pub(crate) fn duff<T: Native>(v: Variant, s: &Span<Q>) -> Vec<Q> {
    let vec = |x: &phong_approx::Vec3<Q>| [T::of(&x.x), T::of(&x.y), T::of(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let nf = T::from_u32(s.n);
    let one = T::from_u32(1);
    let inv = one.div(nf);
    let over_n = |x: T| if v.reciprocal { x.mul(inv) } else { x.div(nf) };
    let k = [0, 1, 2].map(|j| over_n(nb[j] - na[j]));
    let a = dot(v.dot, k, l);
    let c = dot(v.dot, k, k);
    let d = T::from_u32(2).mul(dot(v.dot, k, na));
    let (mut p, mut qq, mut dq) = (dot(v.dot, na, l), dot(v.dot, na, na), c + d);
    let two_c = T::from_u32(2).mul(c);
    let mut out = Vec::with_capacity(s.n as usize + 1);
    for i in 0..=s.n {
        let value = if v.reciprocal {
            p.mul(one.div(qq.sqrt()))
        } else {
            p.div(qq.sqrt())
        };
        out.push(value.q());
        if i < s.n {
            p = p + a;
            qq = qq + dq;
            dq = dq + two_c;
        }
    }
    out
}

/// Runs `imp`, in each of `ways`, on every profile span (Phong's spans for the
/// Phong-valued methods) of at most `most` steps against the bound of `method` under
/// `profile` in the format of unit roundoff `u`; the exact values from the exact run.
/// Returns the runs checked, the spans without a bound and the worst error in units
/// of the bound.
pub(crate) fn search<W: Copy + std::fmt::Debug>(
    what: &str,
    (method, profile, format, most): (Method, Profile, Format, u32),
    ways: &[W],
    imp: impl Fn(W, &Span<Q>) -> Vec<Q>,
) -> (usize, usize, f64) {
    let (mut checked, mut refused, mut worst) = (0, 0, 0f64);
    let all: Vec<Span<Q>> = if method.is_phong_valued() {
        phong_spans()
    } else {
        spans().into_iter().map(|(_, s)| s).collect()
    };
    for s in all.into_iter().filter(|s| s.n <= most) {
        let Some(b) = profile_bound_of(method, profile, &s, format) else {
            refused += 1;
            continue;
        };
        let want = if method.is_phong_valued() {
            phong_exact(&s)
        } else {
            method.values(&s).unwrap()
        };
        for &w in ways {
            let got = imp(w, &s);
            for (i, (g, x)) in got.iter().zip(&want).enumerate() {
                let e = (g.clone() - x.clone()).abs().to_f64();
                worst = worst.max(e / b);
                assert!(
                    e <= b,
                    "{what} {w:?} under {profile}: pixel {i} of n = {}: error {e:e} > bound {b:e}",
                    s.n
                );
            }
            checked += 1;
        }
    }
    eprintln!("{what}: {checked} runs, worst {worst:.3} of the bound, {refused} spans without one");
    (checked, refused, worst)
}

/// [`search`] under `ieee` with the native variants.
pub(crate) fn ieee_derived<T: Native>(
    what: &str,
    method: Method,
    imp: impl Fn(Variant, &Span<Q>) -> Vec<Q>,
) {
    let (checked, refused, _) = search(
        what,
        (method, Profile::Ieee, T::FORMAT, u32::MAX),
        &VARIANTS,
        imp,
    );
    assert!(
        checked > 100,
        "{checked} checked, {refused} without a bound"
    );
}

/// Duff's `ieee` bound (`duff_bound`, composed from `proofs/DuffCount.v` and
/// `phong_value_either`, docs/float.md §18.5) holds for the forward differences with
/// three orders of the set-up's dot products, `/n` or `·(1/n)`, `p/√q` or `p·(1/√q)`,
/// binary32 and binary64.
#[test]
fn profile_ieee_duff_bound() {
    ieee_derived::<f32>("duff f32", Method::Duff, duff::<f32>);
    ieee_derived::<f64>("duff f64", Method::Duff, duff::<f64>);
}

// The shader profile's derived bounds, on the software GPU.

impl Gpu {
    /// `√x` as the shader rules allow it: `1/inversesqrt(x)`, the inverse square root
    /// two units toward zero from the nearest (2 ulps), then the 2.5-ulp division.
    pub(crate) fn sqrt(&self, x: &Q) -> Q {
        use phong_approx::reference::transcendental::sqrt;
        if let Some(a) = self.adv {
            if !x.is_positive() {
                return Q::zero();
            }
            return a.extreme(sqrt(x), a.k_sqrt);
        }
        let x = self.r(x.clone());
        if !x.is_positive() {
            return Q::zero();
        }
        let inv = q(1, 1) / sqrt(&x);
        let rs = self.r(toward_zero(&round_dir(&inv, F, Dir::Nearest), F, 2));
        self.div(&q(1, 1), &rs)
    }
}

/// Euler on the GPU model (the recurrence, one 2.5-ulp division each).
pub(crate) fn gpu_euler(g: Gpu, s: &Span<Q>) -> Vec<Q> {
    gpu_recurrence(Method::Euler, g, Division::Once, s)
}

/// Duff (and, with `horner`, Phong's closed form) on the GPU model.
pub(crate) fn gpu_duff_or_phong(g: Gpu, s: &Span<Q>, horner: bool, how: Division) -> Vec<Q> {
    let vec = |x: &phong_approx::Vec3<Q>| [g.input(&x.x), g.input(&x.y), g.input(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let nf = qi(s.n);
    let k = [0, 1, 2].map(|j| g.over(how, &g.sub(&nb[j], &na[j]), &nf, false));
    let (a, b) = feeds(Role::P, || (g.dot(&k, &l), g.dot(&na, &l)));
    let (c, d, e) = feeds(Role::Q, || {
        let c = g.dot(&k, &k);
        (c.clone(), g.mul(&q(2, 1), &g.dot(&k, &na)), g.dot(&na, &na))
    });
    let axpy = |x: &Q, y: &Q, z: &Q| {
        if g.fused {
            g.r(x * y + z)
        } else {
            g.add(&g.mul(x, y), z)
        }
    };
    let (mut p, mut qq, mut dq) = (b.clone(), e.clone(), feeds(Role::Q, || g.add(&c, &d)));
    let two_c = feeds(Role::Q, || g.mul(&q(2, 1), &c));
    let mut out = Vec::with_capacity(s.n as usize + 1);
    for i in 0..=s.n {
        let x = qi(i);
        let (pi, qi_) = if horner {
            (
                feeds(Role::P, || axpy(&a, &x, &b)),
                feeds(Role::Q, || axpy(&axpy(&c, &x, &d), &x, &e)),
            )
        } else {
            (p.clone(), qq.clone())
        };
        let root = feeds(Role::Q, || g.sqrt(&qi_));
        out.push(feeds(Role::P, || g.div(&pi, &root)));
        if !horner && i < s.n {
            p = feeds(Role::P, || g.add(&p, &a));
            feeds(Role::Q, || {
                qq = g.add(&qq, &dq);
                dq = g.add(&dq, &two_c);
            });
        }
    }
    out
}

/// How a Phong computes each pixel, for the adversary: the forms docs/float.md §18.4
/// covers besides Horner's closed form.
#[derive(Clone, Copy, Debug)]
pub(crate) enum GpuPhong {
    /// `N_i = N_a + i·k`, `p_i/√q_i`.
    PerPixel,
    /// `N_i = (1 − t)·N_a + t·N_b` with `t = i/n`, `p_i·(1/√q_i)`.
    Lerp,
    /// `N_i = N_a + i·k`, then `(N_i·(1/√q_i))·L`.
    NormalizeThenDot,
}

/// Phong per pixel on the GPU model, in the form `form`.
pub(crate) fn gpu_phong_form(g: Gpu, s: &Span<Q>, form: GpuPhong, how: Division) -> Vec<Q> {
    let vec = |x: &phong_approx::Vec3<Q>| [g.input(&x.x), g.input(&x.y), g.input(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let nf = qi(s.n);
    let one = q(1, 1);
    let k = [0, 1, 2].map(|j| g.over(how, &g.sub(&nb[j], &na[j]), &nf, false));
    let axpy = |x: &Q, y: &Q, z: &Q| {
        if g.fused {
            g.r(x * y + z)
        } else {
            g.add(&g.mul(x, y), z)
        }
    };
    (0..=s.n)
        .map(|i| {
            let x = qi(i);
            let normal = match form {
                GpuPhong::PerPixel | GpuPhong::NormalizeThenDot => {
                    [0, 1, 2].map(|j| axpy(&k[j], &x, &na[j]))
                }
                GpuPhong::Lerp => {
                    let t = g.over(how, &x, &nf, false);
                    let omt = g.sub(&one, &t);
                    [0, 1, 2].map(|j| axpy(&t, &nb[j], &g.mul(&omt, &na[j])))
                }
            };
            let root = feeds(Role::Q, || g.sqrt(&g.dot(&normal, &normal)));
            feeds(Role::P, || match form {
                GpuPhong::PerPixel => g.div(&g.dot(&normal, &l), &root),
                GpuPhong::Lerp => g.mul(&g.dot(&normal, &l), &g.div(&one, &root)),
                GpuPhong::NormalizeThenDot => {
                    let r = g.div(&one, &root);
                    g.dot(&normal.map(|c| g.mul(&c, &r)), &l)
                }
            })
        })
        .collect()
}

/// Symmetric Phong on the GPU model: Duff's forward differences walked to the middle
/// pixel for `√q_i`, reused as `√q_{n−i}` on the right half (§4), `p` by additions.
pub(crate) fn gpu_symmetric_phong(g: Gpu, s: &Span<Q>, how: Division) -> Vec<Q> {
    let vec = |x: &phong_approx::Vec3<Q>| [g.input(&x.x), g.input(&x.y), g.input(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let nf = qi(s.n);
    let k = [0, 1, 2].map(|j| g.over(how, &g.sub(&nb[j], &na[j]), &nf, false));
    let (a, b) = feeds(Role::P, || (g.dot(&k, &l), g.dot(&na, &l)));
    let half = (s.n / 2) as usize;
    let root = feeds(Role::Q, || {
        let c = g.dot(&k, &k);
        let d = g.mul(&q(2, 1), &g.dot(&k, &na));
        let (mut qq, mut dq) = (g.dot(&na, &na), g.add(&c, &d));
        let two_c = g.mul(&q(2, 1), &c);
        let mut root = Vec::with_capacity(half + 1);
        for _ in 0..=half {
            root.push(g.sqrt(&qq));
            qq = g.add(&qq, &dq);
            dq = g.add(&dq, &two_c);
        }
        root
    });
    let mut p = b;
    let n = s.n as usize;
    feeds(Role::P, || {
        (0..=n)
            .map(|i| {
                let v = g.div(&p, &root[i.min(n - i)]);
                p = g.add(&p, &a);
                v
            })
            .collect()
    })
}

/// [`search`] under `shader` with the software GPUs, on the spans up to `n = 256`
/// (1024 in the extensive tier: the emulated arithmetic is slow).
pub(crate) fn shader_derived(what: &str, method: Method, imp: impl Fn(Gpu, &Span<Q>) -> Vec<Q>) {
    let most = tiered(256, 1024);
    let (checked, _, _) = search(
        what,
        (method, Profile::Shader, Format::Binary32, most),
        &GPUS,
        imp,
    );
    assert!(checked > 40, "{checked}");
}

/// Duff's `shader` bound (composed from `proofs/DuffCount.v` and
/// `phong_value_either`) and Phong's derived one hold on the software GPUs. (Plain
/// Euler's `shader` bound is proved: the `profile_shader_euler_*` tests above, with
/// `·(1/n)` and a computed `1/2` in the `_recip` ones.)
#[test]
fn profile_shader_derived_binary32() {
    shader_derived("duff", Method::Duff, |g, s| {
        gpu_duff_or_phong(g, s, false, Division::Once)
    });
    shader_derived("phong (Horner)", Method::Phong, |g, s| {
        gpu_duff_or_phong(g, s, true, Division::Once)
    });
}

/// The GPU model's square root is within the shader profile's `κ_sqrt = 9` units.
#[test]
fn the_gpu_square_root_is_within_the_profile() {
    use phong_approx::reference::transcendental::sqrt;
    for (a, b) in [(2i64, 1i64), (1, 3), (7, 5), (1, 1000)] {
        let x = q(a, b);
        let got = GPUS[0].sqrt(&x);
        let want = sqrt(&x);
        let rel = ((got - want.clone()) / want).abs().to_f64();
        assert!(rel <= 9.0 * f32::U, "{a}/{b}: {rel:e}");
    }
}

// ------------------------------------------- the crate's fast kernels under ieee

/// The squared method on the GPU model: its set-up (`SquaredSpan::new`'s order, every
/// division 2.5 ulps, `/n` as `how` says, products fused where `g` fuses), the loops
/// `g += t; t += ds` and `p += A`, then `sign(p)·√max(0, g)` with the shader's root
/// (`1/inverseSqrt`).
pub(crate) fn gpu_squared(g: Gpu, s: &Span<Q>, how: Division) -> Vec<Q> {
    let vec = |x: &phong_approx::Vec3<Q>| [g.input(&x.x), g.input(&x.y), g.input(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let (nf, two) = (qi(s.n), q(2, 1));
    let k = [0, 1, 2].map(|j| g.over(how, &g.sub(&nb[j], &na[j]), &nf, false));
    let a = g.dot(&k, &l);
    let b = g.dot(&na, &l);
    let c = g.dot(&k, &k);
    let d = g.mul(&two, &g.dot(&k, &na));
    let e = g.dot(&na, &na);
    let pb = g.dot(&nb, &l);
    let qb = g.dot(&nb, &nb);
    let dqb = g.add(&g.mul(&g.mul(&two, &nf), &c), &d);
    let ga = g.div(&g.mul(&b, &b), &e);
    let gb = g.div(&g.mul(&pb, &pb), &qb);
    let slope = |p: &Q, qq: &Q, dq: &Q| {
        let two_aq = g.mul(&g.mul(&two, &a), qq);
        let inner = g.fms(p, dq, &two_aq);
        g.div(&g.mul(p, &inner), &g.mul(qq, qq))
    };
    let (dga, dgb) = (slope(&b, &e, &d), slope(&pb, &qb, &dqb));
    let ds = g.over(how, &g.sub(&dgb, &dga), &nf, false);
    let tri = qi(s.n) * qi(s.n.saturating_sub(1)) / q(2, 1);
    let gn = g.add(&g.add(&ga, &g.mul(&nf, &dga)), &g.mul(&tri, &ds));
    let t0 = g.sub(&dga, &g.over(how, &g.sub(&gn, &gb), &nf, false));
    let (mut gv, mut t, mut p) = (ga, t0, b);
    let mut out = Vec::with_capacity(s.n as usize + 1);
    for _ in 0..=s.n {
        let r = g.sqrt(&gv);
        out.push(if p.is_positive() {
            r
        } else if p.is_negative() {
            -r
        } else {
            Q::zero()
        });
        gv = g.add(&gv, &t);
        t = g.add(&t, &ds);
        p = g.add(&p, &a);
    }
    out
}
