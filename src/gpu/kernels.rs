//! This repository's kernels (`harness/gpu/`): the paper's methods as a GPU programmer
//! writes them in WGSL and GLSL, two planted bugs for CI, and for each kernel its
//! source evaluated on the CPU in round-to-nearest `f32`, operation by operation in
//! the source's order, with no fused multiply-add ([`Kernel::cpu`]): what the driver
//! would give if it compiled each operation as written.

use crate::testkit::Inputs;
use crate::Method;

/// The language a kernel is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Language {
    /// WGSL, compiled by naga.
    Wgsl,
    /// GLSL 4.50, compiled by glslang to SPIR-V.
    Glsl,
}

/// One of this repository's kernels.
#[derive(Clone, Copy, Debug)]
pub struct Kernel {
    /// The file, from the repository's root.
    pub file: &'static str,
    /// Its text.
    pub text: &'static str,
    /// The method it computes.
    pub method: Method,
    /// WGSL or GLSL.
    pub language: Language,
    /// How it runs: a recurrence in one invocation per span, or one pixel per
    /// invocation.
    pub form: &'static str,
    /// A planted bug that every profile must reject.
    pub mutant: bool,
    cpu: fn(&Inputs<'_, f32>) -> Vec<f32>,
}

impl Kernel {
    /// The kernel's source evaluated on the CPU: round to nearest even, each operation
    /// in the source's order, no contraction; `inverseSqrt(x)` as `1/sqrt(x)` and
    /// `normalize(v)` as `v/sqrt(dot(v, v))`, each rounded.
    pub fn cpu(&self, s: &Inputs<'_, f32>) -> Vec<f32> {
        (self.cpu)(s)
    }

    /// The kernel's short name: its file name.
    pub fn name(&self) -> &'static str {
        self.file.rsplit('/').next().unwrap_or(self.file)
    }
}

macro_rules! kernel {
    ($file:literal, $method:ident, $lang:ident, $form:literal, $mutant:literal, $cpu:path) => {
        Kernel {
            file: concat!("harness/gpu/", $file),
            text: include_str!(concat!("../../harness/gpu/", $file)),
            method: Method::$method,
            language: Language::$lang,
            form: $form,
            mutant: $mutant,
            cpu: $cpu,
        }
    };
}

/// Every kernel of `harness/gpu/`: the correct ones, then the planted bugs.
pub const KERNELS: [Kernel; 17] = [
    kernel!(
        "gouraud.wgsl",
        Gouraud,
        Wgsl,
        "recurrence, one invocation per span",
        false,
        gouraud
    ),
    kernel!(
        "euler.wgsl",
        Euler,
        Wgsl,
        "recurrence, one invocation per span",
        false,
        euler
    ),
    kernel!(
        "euler_closed.wgsl",
        Euler,
        Wgsl,
        "closed form, one invocation per pixel",
        false,
        euler_closed
    ),
    kernel!(
        "corrected_euler.wgsl",
        CorrectedEuler,
        Wgsl,
        "recurrence, one invocation per span",
        false,
        corrected_euler
    ),
    kernel!(
        "corrected_euler_closed.wgsl",
        CorrectedEuler,
        Wgsl,
        "closed form, one invocation per pixel",
        false,
        corrected_euler_closed
    ),
    kernel!(
        "duff.wgsl",
        Duff,
        Wgsl,
        "forward differences, one invocation per span",
        false,
        duff
    ),
    kernel!(
        "phong.wgsl",
        Phong,
        Wgsl,
        "normalize(N_a + i k)·L, one invocation per pixel",
        false,
        phong
    ),
    kernel!(
        "phong_closed.wgsl",
        Phong,
        Wgsl,
        "Horner's closed form, one invocation per pixel",
        false,
        phong_closed
    ),
    kernel!(
        "symmetric_phong.wgsl",
        SymmetricPhong,
        Wgsl,
        "recurrence to the middle, one invocation per span",
        false,
        symmetric_phong
    ),
    kernel!(
        "adaptive.wgsl",
        Adaptive,
        Wgsl,
        "the δ test, then a recurrence, one invocation per span",
        false,
        adaptive
    ),
    kernel!(
        "squared_corrected_euler.wgsl",
        SquaredCorrectedEuler,
        Wgsl,
        "recurrence on g, then sign(p)·√max(0, g), one invocation per span",
        false,
        squared_corrected_euler
    ),
    kernel!(
        "gouraud.comp",
        Gouraud,
        Glsl,
        "recurrence, one invocation per span",
        false,
        gouraud
    ),
    kernel!(
        "corrected_euler.comp",
        CorrectedEuler,
        Glsl,
        "recurrence, one invocation per span",
        false,
        corrected_euler
    ),
    kernel!(
        "phong.comp",
        Phong,
        Glsl,
        "normalize(N_a + i k)·L, one invocation per pixel",
        false,
        phong
    ),
    kernel!(
        "mutants/corrected_euler_eps_n1.wgsl",
        CorrectedEuler,
        Wgsl,
        "planted bug: ε/(n+1)",
        true,
        corrected_euler_eps_n1
    ),
    kernel!(
        "mutants/corrected_euler_dq_sign.wgsl",
        CorrectedEuler,
        Wgsl,
        "planted bug: dq_b = 2nC − D",
        true,
        corrected_euler_dq_sign
    ),
    kernel!(
        "mutants/squared_no_sign.wgsl",
        SquaredCorrectedEuler,
        Wgsl,
        "planted bug: the value's sign dropped",
        true,
        squared_no_sign
    ),
];

type V = [f32; 3];

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn div(a: V, x: f32) -> V {
    [a[0] / x, a[1] / x, a[2] / x]
}
fn scale(x: f32, a: V) -> V {
    [x * a[0], x * a[1], x * a[2]]
}
fn dot(a: V, b: V) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The set-up every Euler kernel writes (corrected_euler.wgsl, lines up to `ds`).
struct Setup {
    nf: f32,
    pa: f32,
    pb: f32,
    dia: f32,
    ds: f32,
}

fn setup(s: &Inputs<'_, f32>, dq_sign: f32) -> Setup {
    let nf = s.n as f32;
    let k = div(sub(s.nb, s.na), nf);
    let a = dot(k, s.l);
    let c = dot(k, k);
    let d = 2.0 * dot(k, s.na);
    let pa = dot(s.na, s.l);
    let pb = dot(s.nb, s.l);
    let dqb = if dq_sign > 0.0 {
        2.0 * nf * c + d
    } else {
        2.0 * nf * c - d
    };
    let dia = a - 0.5 * pa * d;
    let dib = a - 0.5 * pb * dqb;
    let ds = (dib - dia) / nf;
    Setup {
        nf,
        pa,
        pb,
        dia,
        ds,
    }
}

/// `n(n−1)/2` as the kernels form it: an integer, converted.
fn tri(n: u32) -> f32 {
    ((u64::from(n) * u64::from(n.saturating_sub(1))) / 2) as f32
}

fn t0(s: &Inputs<'_, f32>, u: &Setup, eps_div: f32) -> f32 {
    let pn = u.pa + u.nf * u.dia + tri(s.n) * u.ds;
    u.dia - (pn - u.pb) / eps_div
}

fn euler_loop(n: u32, p0: f32, t0: f32, ds: f32) -> Vec<f32> {
    let (mut p, mut t) = (p0, t0);
    (0..=n)
        .map(|_| {
            let v = p;
            p += t;
            t += ds;
            v
        })
        .collect()
}

fn gouraud(s: &Inputs<'_, f32>) -> Vec<f32> {
    let nf = s.n as f32;
    let pa = dot(s.na, s.l);
    let pb = dot(s.nb, s.l);
    let dp = (pb - pa) / nf;
    let mut g = pa;
    (0..=s.n)
        .map(|_| {
            let v = g;
            g += dp;
            v
        })
        .collect()
}

fn euler(s: &Inputs<'_, f32>) -> Vec<f32> {
    let u = setup(s, 1.0);
    euler_loop(s.n, u.pa, u.dia, u.ds)
}

fn corrected_euler(s: &Inputs<'_, f32>) -> Vec<f32> {
    let u = setup(s, 1.0);
    euler_loop(s.n, u.pa, t0(s, &u, u.nf), u.ds)
}

fn corrected_euler_eps_n1(s: &Inputs<'_, f32>) -> Vec<f32> {
    let u = setup(s, 1.0);
    euler_loop(s.n, u.pa, t0(s, &u, u.nf + 1.0), u.ds)
}

fn corrected_euler_dq_sign(s: &Inputs<'_, f32>) -> Vec<f32> {
    let u = setup(s, -1.0);
    euler_loop(s.n, u.pa, t0(s, &u, u.nf), u.ds)
}

fn euler_closed(s: &Inputs<'_, f32>) -> Vec<f32> {
    let u = setup(s, 1.0);
    (0..=s.n)
        .map(|i| {
            let h = ((i as i32 - 1) as f32 * 0.5) * u.ds;
            u.pa + i as f32 * (u.dia + h)
        })
        .collect()
}

fn corrected_euler_closed(s: &Inputs<'_, f32>) -> Vec<f32> {
    let u = setup(s, 1.0);
    let t0 = t0(s, &u, u.nf);
    (0..=s.n)
        .map(|i| {
            let h = ((i as i32 - 1) as f32 * 0.5) * u.ds;
            u.pa + i as f32 * (t0 + h)
        })
        .collect()
}

/// Duff's set-up: `k`, `A`, `C`, `D`.
fn duff_setup(s: &Inputs<'_, f32>) -> (f32, f32, f32) {
    let k = div(sub(s.nb, s.na), s.n as f32);
    (dot(k, s.l), dot(k, k), 2.0 * dot(k, s.na))
}

fn duff(s: &Inputs<'_, f32>) -> Vec<f32> {
    let (a, c, d) = duff_setup(s);
    let (mut p, mut q, mut dq) = (dot(s.na, s.l), dot(s.na, s.na), c + d);
    (0..=s.n)
        .map(|_| {
            let v = p * (1.0 / q.sqrt());
            p += a;
            q += dq;
            dq += 2.0 * c;
            v
        })
        .collect()
}

fn phong(s: &Inputs<'_, f32>) -> Vec<f32> {
    let k = div(sub(s.nb, s.na), s.n as f32);
    (0..=s.n)
        .map(|i| {
            let normal = add(s.na, scale(i as f32, k));
            let unit = div(normal, dot(normal, normal).sqrt());
            dot(unit, s.l)
        })
        .collect()
}

fn phong_closed(s: &Inputs<'_, f32>) -> Vec<f32> {
    let k = div(sub(s.nb, s.na), s.n as f32);
    let (a, b) = (dot(k, s.l), dot(s.na, s.l));
    let (c, d, e) = (dot(k, k), 2.0 * dot(k, s.na), dot(s.na, s.na));
    (0..=s.n)
        .map(|i| {
            let x = i as f32;
            let q = (c * x + d) * x + e;
            (a * x + b) / q.sqrt()
        })
        .collect()
}

fn symmetric_phong(s: &Inputs<'_, f32>) -> Vec<f32> {
    let n = s.n as usize;
    let half = n / 2;
    let (a, c, d) = duff_setup(s);
    let mut out = vec![f32::NAN; n + 1];
    let (mut q, mut dq) = (dot(s.na, s.na), c + d);
    for j in 0..=half {
        out[n - j] = q.sqrt();
        q += dq;
        dq += 2.0 * c;
    }
    let mut p = dot(s.na, s.l);
    for i in 0..=n {
        let r = if i <= half { out[n - i] } else { out[i] };
        out[i] = p / r;
        p += a;
    }
    out
}

fn adaptive(s: &Inputs<'_, f32>) -> Vec<f32> {
    let u = setup(s, 1.0);
    let t0 = t0(s, &u, u.nf);
    let dp = (u.pb - u.pa) / u.nf;
    let mut gouraud = true;
    if u.ds != 0.0 {
        let m = (dp - t0) / u.ds;
        let j = (m.trunc() + 1.0).clamp(0.0, u.nf);
        let tj = tri(j as u32);
        let delta = j * dp - (j * t0 + tj * u.ds);
        gouraud = (delta * 255.0).abs() < 1.0;
    }
    let (mut p, mut t) = (u.pa, t0);
    (0..=s.n)
        .map(|_| {
            let v = p;
            if gouraud {
                p += dp;
            } else {
                p += t;
                t += u.ds;
            }
            v
        })
        .collect()
}

/// squared_corrected_euler.wgsl (and its mutant without the sign), operation by
/// operation: its set-up is `SquaredSpan::new`'s order, as
/// [`crate::fast::FastSquared::new`] computes it, then the recurrences.
fn squared(s: &Inputs<'_, f32>, signed: bool) -> Vec<f32> {
    let fs = crate::fast::FastSquared::<f32>::new(s.na, s.nb, s.l, s.n);
    let (a, ds) = (fs.a, fs.ds);
    let (mut g, mut t, mut p) = (fs.g_a, fs.t0, fs.b);
    (0..=s.n)
        .map(|_| {
            let mut v = if g > 0.0 { g.sqrt() } else { 0.0 };
            if signed && p < 0.0 {
                v = -v;
            }
            if signed && p == 0.0 {
                v = 0.0;
            }
            g += t;
            t += ds;
            p += a;
            v
        })
        .collect()
}

fn squared_corrected_euler(s: &Inputs<'_, f32>) -> Vec<f32> {
    squared(s, true)
}

fn squared_no_sign(s: &Inputs<'_, f32>) -> Vec<f32> {
    squared(s, false)
}
