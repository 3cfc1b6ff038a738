//! The `ieee` profile's bounds (`proofs/Profiles.v`): native `f32`/`f64` implementations written here from the definitions — other orders of the dot products, fused products, `1/n` once, the closed forms — within the proved bound of the exact values.

use super::*;

pub(crate) fn bound(alpha: f64, beta: f64, n: u32, u: f64) -> f64 {
    (alpha * f64::from(n) + beta) * u
}

/// The worst error of `got` against the exact values of `method` on `c`, in units of
/// the bound; panics with the case when a pixel is over.
pub(crate) fn within(what: &str, c: &Case, s: &Span<Q>, method: Method, got: &[Q], b: f64) -> f64 {
    let want = exact_values(method, c, s);
    assert_eq!(got.len(), want.len());
    let mut worst = 0f64;
    for (i, (g, w)) in got.iter().zip(want.iter()).enumerate() {
        let e = (g.clone() - w.clone()).abs().to_f64();
        worst = worst.max(e / b);
        assert!(
            e <= b,
            "{what}: pixel {i} of n = {}: error {e:e} > bound {b:e}\ninputs: {c:?}",
            c.n
        );
    }
    worst
}

/// The spans every profile test runs on: edge, targeted and (fixed-seed) random.
pub(crate) fn spans() -> Vec<(Case, Span<Q>)> {
    use proptest::strategy::{Strategy, ValueTree};
    let mut v: Vec<Case> = edge_cases();
    v.extend(targeted_cases());
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    for _ in 0..tiered(24, 48) {
        v.push(arb_case().new_tree(&mut runner).unwrap().current());
        v.push(arb_targeted().new_tree(&mut runner).unwrap().current());
    }
    v.into_iter()
        .filter_map(|c| c.span().map(|s| (c, s)))
        .collect()
}

// ---------------------------------------------------------------- ieee: native code

/// A native float type for the `ieee` variants.
pub(crate) trait Native:
    Copy + PartialOrd + std::ops::Add<Output = Self> + std::ops::Sub<Output = Self>
{
    fn of(x: &Q) -> Self;
    fn q(self) -> Q;
    fn from_u32(n: u32) -> Self;
    fn mul(self, b: Self) -> Self;
    fn div(self, b: Self) -> Self;
    fn fma(self, b: Self, c: Self) -> Self;
    fn sqrt(self) -> Self;
    const U: f64;
    const FORMAT: Format;
}

macro_rules! native {
    ($t:ty, $f:ident) => {
        impl Native for $t {
            fn of(x: &Q) -> Self {
                <$t as Scalar>::from_rational(x)
            }
            fn q(self) -> Q {
                Scalar::to_rational(&self).expect("finite")
            }
            fn from_u32(n: u32) -> Self {
                n as $t
            }
            fn mul(self, b: Self) -> Self {
                self * b
            }
            fn div(self, b: Self) -> Self {
                self / b
            }
            fn fma(self, b: Self, c: Self) -> Self {
                self.mul_add(b, c)
            }
            fn sqrt(self) -> Self {
                <$t>::sqrt(self)
            }
            const U: f64 = Format::$f.u();
            const FORMAT: Format = Format::$f;
        }
    };
}
native!(f32, Binary32);
native!(f64, Binary64);

/// How a variant sums a dot product.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Dot {
    /// `(z + y) + x`, each product rounded.
    Reversed,
    /// `fma(x, x', fma(y, y', z·z'))`.
    Fused,
    /// `x + (y + z)`.
    RightFirst,
}

pub(crate) fn dot<T: Native>(how: Dot, a: [T; 3], b: [T; 3]) -> T {
    match how {
        Dot::Reversed => a[2].mul(b[2]) + a[1].mul(b[1]) + a[0].mul(b[0]),
        Dot::Fused => a[0].fma(b[0], a[1].fma(b[1], a[2].mul(b[2]))),
        Dot::RightFirst => a[0].mul(b[0]) + (a[1].mul(b[1]) + a[2].mul(b[2])),
    }
}

/// One `ieee` implementation: its dot products, whether it divides by `n` through
/// `1/n`, and whether it fuses the products that feed an addition.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Variant {
    pub(crate) dot: Dot,
    pub(crate) reciprocal: bool,
    pub(crate) fused: bool,
}

pub(crate) const VARIANTS: [Variant; 3] = [
    Variant {
        dot: Dot::Reversed,
        reciprocal: false,
        fused: false,
    },
    Variant {
        dot: Dot::Fused,
        reciprocal: true,
        fused: true,
    },
    Variant {
        dot: Dot::RightFirst,
        reciprocal: true,
        fused: false,
    },
];

/// The set-up of `proofs/Profiles.v` (the paper's eqs. 2–3, 10–11, 14–17) in `T`.
pub(crate) struct Setup<T> {
    pub(crate) pa: T,
    pub(crate) dp: T,
    pub(crate) dia: T,
    pub(crate) ds: T,
    pub(crate) t0: T,
}

pub(crate) fn setup<T: Native>(v: Variant, s: &Span<Q>) -> Setup<T> {
    let vec = |x: &phong_approx::Vec3<Q>| [T::of(&x.x), T::of(&x.y), T::of(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let nf = T::from_u32(s.n);
    let inv = T::from_u32(1).div(nf);
    let over_n = |x: T| if v.reciprocal { x.mul(inv) } else { x.div(nf) };
    let two = T::from_u32(2);
    let k = [0, 1, 2].map(|j| over_n(nb[j] - na[j]));
    let a = dot(v.dot, k, l);
    let pa = dot(v.dot, na, l);
    let pb = dot(v.dot, nb, l);
    let c = dot(v.dot, k, k);
    let d = two.mul(dot(v.dot, k, na));
    let two_n_c = two.mul(nf).mul(c);
    let dqb = two_n_c + d;
    let half = |x: T| x.div(two);
    // a − (pa/2)·d: fused as fma(−pa/2, d, a).
    let fms = |x: T, y: T, z: T| {
        if v.fused {
            (T::from_u32(0) - x).fma(y, z)
        } else {
            z - x.mul(y)
        }
    };
    let dia = fms(half(pa), d, a);
    let dib = fms(half(pb), dqb, a);
    let ds = over_n(dib - dia);
    let tri = T::from_u32(s.n).mul(T::from_u32(s.n - 1)).div(two);
    let pn = if v.fused {
        tri.fma(ds, nf.fma(dia, pa))
    } else {
        pa + (nf.mul(dia) + tri.mul(ds))
    };
    let eps = pn - pb;
    let t0 = dia - over_n(eps);
    let dp = over_n(pb - pa);
    Setup {
        pa,
        dp,
        dia,
        ds,
        t0,
    }
}

pub(crate) fn gouraud<T: Native>(v: Variant, s: &Span<Q>) -> Vec<Q> {
    let st = setup::<T>(v, s);
    let mut g = st.pa;
    let mut out = vec![g.q()];
    for _ in 0..s.n {
        g = g + st.dp;
        out.push(g.q());
    }
    out
}

/// The second-order recurrence `p += t; t += ds` from `p_a` and the slope `t`:
/// `n + 1` values.
pub(crate) fn second_order<T: Native>(pa: T, mut t: T, ds: T, n: u32) -> Vec<Q> {
    let mut p = pa;
    let mut out = vec![p.q()];
    for _ in 0..n {
        p = p + t;
        t = t + ds;
        out.push(p.q());
    }
    out
}

pub(crate) fn corrected_euler<T: Native>(v: Variant, s: &Span<Q>) -> Vec<Q> {
    let st = setup::<T>(v, s);
    second_order(st.pa, st.t0, st.ds, s.n)
}

/// Corrected Euler by its closed form `p_a + i·(t_0 + (i−1)/2·ds)`, fused or not.
pub(crate) fn corrected_euler_closed<T: Native>(v: Variant, s: &Span<Q>) -> Vec<Q> {
    let st = setup::<T>(v, s);
    let two = T::from_u32(2);
    (0..=s.n)
        .map(|i| {
            let fi = T::from_u32(i);
            let h = (fi - T::from_u32(1)).div(two).mul(st.ds);
            let g = st.t0 + h;
            pa_plus_i_times(v, st.pa, fi, g).q()
        })
        .collect()
}

/// `p_a + i·g`, the product fused into the addition or rounded.
pub(crate) fn pa_plus_i_times<T: Native>(v: Variant, pa: T, i: T, g: T) -> T {
    if v.fused {
        i.fma(g, pa)
    } else {
        pa + i.mul(g)
    }
}

pub(crate) fn ieee<T: Native>(theorem: &str, method: Method) {
    let (alpha, beta) = common::coq::constants(theorem);
    let (mut checked, mut worst) = (0, 0f64);
    for (c, s) in spans() {
        let b = bound(alpha, beta, s.n, T::U);
        for v in VARIANTS {
            let got = match method {
                Method::Gouraud => gouraud::<T>(v, &s),
                Method::Euler => euler::<T>(v, &s),
                _ => corrected_euler::<T>(v, &s),
            };
            worst = worst.max(within(&format!("{theorem} {v:?}"), &c, &s, method, &got, b));
            checked += 1;
        }
    }
    assert!(checked > 100, "{checked}");
    eprintln!("{theorem}: {checked} runs, worst {worst:.3} of the bound");
}

#[test]
fn profile_ieee_gouraud_binary32() {
    ieee::<f32>("profile_ieee_gouraud_binary32", Method::Gouraud);
}

#[test]
fn profile_ieee_gouraud_binary64() {
    ieee::<f64>("profile_ieee_gouraud_binary64", Method::Gouraud);
}

#[test]
fn profile_ieee_corrected_euler_binary32() {
    ieee::<f32>(
        "profile_ieee_corrected_euler_binary32",
        Method::CorrectedEuler,
    );
}

#[test]
fn profile_ieee_corrected_euler_binary64() {
    ieee::<f64>(
        "profile_ieee_corrected_euler_binary64",
        Method::CorrectedEuler,
    );
}

/// Plain Euler (eqs. 12–14), the recurrence `E += s; s += ds` from `s_0 = di_a`, in
/// the three variants, against the exact plain-Euler run.
#[test]
fn profile_ieee_euler_binary32() {
    ieee::<f32>("profile_ieee_euler_binary32", Method::Euler);
}

/// As [`profile_ieee_euler_binary32`] in binary64.
#[test]
fn profile_ieee_euler_binary64() {
    ieee::<f64>("profile_ieee_euler_binary64", Method::Euler);
}

/// The closed form of corrected Euler (`p_a + i·(t_0 + (i−1)/2·ds)`) or of plain Euler
/// (`p_a + i·(di_a + (i−1)/2·ds)`) in the three variants, within `beta·u` of the
/// method's exact run.
pub(crate) fn closed<T: Native>(theorem: &str, method: Method) {
    let (_, beta) = common::coq::constants(theorem);
    let (mut checked, mut worst) = (0, 0f64);
    for (c, s) in spans() {
        for v in VARIANTS {
            let got = match method {
                Method::Euler => euler_closed::<T>(v, &s),
                _ => corrected_euler_closed::<T>(v, &s),
            };
            let w = within(
                &format!("{theorem} {v:?}"),
                &c,
                &s,
                method,
                &got,
                beta * T::U,
            );
            worst = worst.max(w);
            checked += 1;
        }
    }
    assert!(checked > 100, "{checked}");
    eprintln!("{theorem}: {checked} runs, worst {worst:.3} of the bound");
}

#[test]
fn profile_ieee_corrected_euler_closed_binary32() {
    closed::<f32>(
        "profile_ieee_corrected_euler_closed_binary32",
        Method::CorrectedEuler,
    );
}

#[test]
fn profile_ieee_corrected_euler_closed_binary64() {
    closed::<f64>(
        "profile_ieee_corrected_euler_closed_binary64",
        Method::CorrectedEuler,
    );
}

/// Plain Euler by its closed form `p_a + i·(di_a + (i−1)/2·ds)`, fused or not, in the
/// three variants: within `131.41·u` of the exact plain-Euler run at every `n`.
#[test]
fn profile_ieee_euler_closed_binary32() {
    closed::<f32>("profile_ieee_euler_closed_binary32", Method::Euler);
}

/// As [`profile_ieee_euler_closed_binary32`] in binary64.
#[test]
fn profile_ieee_euler_closed_binary64() {
    closed::<f64>("profile_ieee_euler_closed_binary64", Method::Euler);
}

/// Long spans in `f64` (the `_large` theorems hold up to `2^24` pixels; here `2^16`
/// in the default tier, `2^20` in the extensive tier), every variant; the exact value
/// at every 4099th pixel and the last (the exact comparison is the cost).
pub(crate) fn large(theorem: &str, method: Method, closed: bool) {
    let (alpha, beta) = common::coq::constants(theorem);
    let n = tiered(1 << 16, 1 << 20);
    for (na, nb, l) in [
        (Stereo(0, 0, 1), Stereo(1, 0, 3), Stereo(2, 1, 5)),
        (Stereo(0, 0, 1), Stereo(96, 0, 1), Stereo(0, 0, 1)),
    ] {
        let c = Case {
            why: "long span",
            na,
            nb,
            l,
            n,
        };
        let s = c.span().unwrap();
        // Exactly: Gouraud p_a + i·dp, corrected Euler p_a + i·(t_0 + (i−1)/2·ds),
        // Euler p_a + i·(di_a + (i−1)/2·ds).
        let exact = |i: u32| {
            let x = qi(i);
            let start = if method == Method::Euler {
                s.di_a.clone()
            } else {
                s.t0.clone()
            };
            if method == Method::Gouraud {
                s.p_a.clone() + x * s.dp.clone()
            } else {
                let h = (x.clone() - q(1, 1)) / q(2, 1) * s.ds.clone();
                s.p_a.clone() + x * (start + h)
            }
        };
        let b = bound(alpha, beta, n, f64::U);
        let mut worst = 0f64;
        for v in VARIANTS {
            let got: Vec<(u32, f64)> = if closed {
                let st = setup::<f64>(v, &s);
                let start = if method == Method::Euler {
                    st.dia
                } else {
                    st.t0
                };
                (0..=n)
                    .filter(|i| i % 4099 == 0 || *i == n)
                    .map(|i| {
                        let fi = f64::from(i);
                        let g = start + (fi - 1.0) / 2.0 * st.ds;
                        (
                            i,
                            if v.fused {
                                fi.mul_add(g, st.pa)
                            } else {
                                st.pa + fi * g
                            },
                        )
                    })
                    .collect()
            } else {
                let all = match method {
                    Method::Gouraud => gouraud::<f64>(v, &s),
                    Method::Euler => euler::<f64>(v, &s),
                    _ => corrected_euler::<f64>(v, &s),
                };
                all.into_iter()
                    .enumerate()
                    .filter(|(i, _)| i % 4099 == 0 || *i == n as usize)
                    .map(|(i, x)| (i as u32, x.to_f64()))
                    .collect()
            };
            for (i, g) in got {
                let e = (g.q() - exact(i)).abs().to_f64();
                worst = worst.max(e / b);
                assert!(e <= b, "{theorem} {v:?} pixel {i} of {n}: {e:e} > {b:e}");
            }
        }
        eprintln!("{theorem}: n = {n}, worst {worst:.3} of the bound");
    }
}

#[test]
fn profile_ieee_gouraud_binary64_large() {
    large(
        "profile_ieee_gouraud_binary64_large",
        Method::Gouraud,
        false,
    );
}

#[test]
fn profile_ieee_corrected_euler_binary64_large() {
    large(
        "profile_ieee_corrected_euler_binary64_large",
        Method::CorrectedEuler,
        false,
    );
}

#[test]
fn profile_ieee_corrected_euler_closed_binary64_large() {
    large(
        "profile_ieee_corrected_euler_closed_binary64_large",
        Method::CorrectedEuler,
        true,
    );
}

#[test]
fn profile_ieee_euler_binary64_large() {
    large("profile_ieee_euler_binary64_large", Method::Euler, false);
}

#[test]
fn profile_ieee_euler_closed_binary64_large() {
    large(
        "profile_ieee_euler_closed_binary64_large",
        Method::Euler,
        true,
    );
}

/// The squared method (`squared_corrected_euler`) as a native implementation: its
/// set-up in the variant's orders (fused where a product feeds an addition), the loops
/// `g += t; t += ds` and `p += A`, then `sign(p)·√max(0, g)` with one rounded root.
pub(crate) fn squared<T: Native>(v: Variant, s: &Span<Q>) -> Vec<Q> {
    squared_with::<T>(v, s, None)
}

/// A bug planted in [`squared`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum SquaredBug {
    /// The value's sign ignored: `√max(0, g)` everywhere.
    NoSign,
    /// Plain Euler on `g`: `t_0 = g′_a`, `ε` dropped.
    NoCorrection,
    /// `A` biased by a relative `10^-5`.
    BiasedA,
}

/// [`squared`] with a bug planted, or none.
pub(crate) fn squared_with<T: Native>(v: Variant, s: &Span<Q>, bug: Option<SquaredBug>) -> Vec<Q> {
    let vec = |x: &phong_approx::Vec3<Q>| [T::of(&x.x), T::of(&x.y), T::of(&x.z)];
    let (na, nb, l) = (vec(&s.na), vec(&s.nb), vec(&s.l));
    let (zero, two) = (T::from_u32(0), T::from_u32(2));
    let nf = T::from_u32(s.n);
    let inv = T::from_u32(1).div(nf);
    let over_n = |x: T| if v.reciprocal { x.mul(inv) } else { x.div(nf) };
    let k = [0, 1, 2].map(|j| over_n(nb[j] - na[j]));
    let mut a = dot(v.dot, k, l);
    if bug == Some(SquaredBug::BiasedA) {
        a = a.mul(T::of(&q(100_001, 100_000)));
    }
    let b = dot(v.dot, na, l);
    let c = dot(v.dot, k, k);
    let d = two.mul(dot(v.dot, k, na));
    let e = dot(v.dot, na, na);
    let pb = dot(v.dot, nb, l);
    let qb = dot(v.dot, nb, nb);
    let dqb = two.mul(nf).mul(c) + d;
    let ga = b.mul(b).div(e);
    let gb = pb.mul(pb).div(qb);
    // g′ = p·(2A·q − p·q′)/(q·q); fused: fma(−p, q′, 2A·q).
    let slope = |p: T, q: T, dq: T| {
        let two_aq = two.mul(a).mul(q);
        let inner = if v.fused {
            (zero - p).fma(dq, two_aq)
        } else {
            two_aq - p.mul(dq)
        };
        p.mul(inner).div(q.mul(q))
    };
    let (dga, dgb) = (slope(b, e, d), slope(pb, qb, dqb));
    let ds = over_n(dgb - dga);
    let tri = T::from_u32(s.n).mul(T::from_u32(s.n - 1)).div(two);
    let gn = if v.fused {
        tri.fma(ds, nf.fma(dga, ga))
    } else {
        ga + (nf.mul(dga) + tri.mul(ds))
    };
    let t0 = if bug == Some(SquaredBug::NoCorrection) {
        dga
    } else {
        dga - over_n(gn - gb)
    };
    let (mut g, mut t, mut p) = (ga, t0, b);
    let mut out = Vec::with_capacity(s.n as usize + 1);
    for _ in 0..=s.n {
        let r = if g > zero { g.sqrt() } else { zero };
        let value = if p > zero || bug == Some(SquaredBug::NoSign) {
            r
        } else if p < zero {
            zero - r
        } else {
            zero
        };
        out.push(value.q());
        g = g + t;
        t = t + ds;
        p = p + a;
    }
    out
}
