//! Error bounds of the float runs against the exact run, in one place.
//!
//! A method run in a binary float type (unit roundoff `u`: 2^-24 for `f32`, 2^-53 for
//! `f64`, round to nearest even) on exact-unit inputs rounded to that type differs
//! from the same method run exactly on the exact inputs by at most [`bound`] at every
//! pixel. Every constant below is *derived*, not measured: the derivation, one
//! section per method and kernel, following the operation order of the code, is in
//! `docs/float.md` (embedded in the crate docs as [`crate::float`]). For Gouraud and
//! corrected Euler the bound is a machine-checked theorem (Flocq, `proofs/Float.v`:
//! `float_gouraud_binary32`, `float_gouraud_binary64`,
//! `float_corrected_euler_binary32`, `float_corrected_euler_binary64`).
//!
//! The derivations take the standard model `fl(a ∘ b) = (a ∘ b)(1 + θ)`, `|θ| ≤ u`,
//! with the underflow terms (at most 2^-150 per operation in `f32`) folded into the
//! constant terms, and they hold while `n·u ≤ 2^-12` (every `n ≤ 4096` in `f32`, every
//! `n ≤ 2^24` in `f64`); outside that, and where a method's bound does not exist
//! (Duff and Phong when rounding can make `q` vanish), the functions return `None`.
//! Angular interpolation calls libm's `acos` and `cos`: its bound assumes both are
//! within one ulp (glibc's documented accuracy for `acos`, `cos`, `acosf`, `cosf`).
//!
//! Tested: `tests/float_bounds.rs` (every method, `f32` and `f64`, the edge cases,
//! random spans and a targeted search for the worst case) and `tests/fast.rs` (the
//! kernels of [`crate::fast`]).
//!
//! The related span methods (spherical, binary, Bishop–Weimer): [`related`]
//! (`docs/float.md` §16, tested in `tests/float_bounds_related.rs`).

pub mod graph;
pub mod graphs;
pub mod profile;
pub mod related;
pub mod rows;

use crate::method::{Bound, Method};

/// The largest `n·u` for which the derivations hold (their second-order terms are
/// folded into the constants under this condition).
pub const MAX_NU: f64 = 1.0 / 4096.0;

/// `π/√2`: `|acos x − acos y| ≤ (π/√2)·√|x − y|` on `[−1, 1]` (the worst pair is
/// `x = −1`, `y = 1`; `docs/float.md`, angular).
const ACOS_HOLDER: f64 = 2.2215;

/// Coefficients `(α, β)` of the fast kernels' bounds `(α·n + β)·u`, in one table (see
/// `docs/float.md` for each derivation; the methods' own are in their catalogue rows,
/// [`Bound`]).
mod coef {
    /// Fast kernels (`FastSpan`): corrected Euler, in closed form below
    /// `fast::STEPPED_FROM` pixels (48u, no growth in `n`), in 32 lanes from there.
    pub const FAST_CORRECTED_EULER: (f64, f64) = (0.07, 51.0);
    /// Fast kernels: Euler, in closed form (96u) or in 32 lanes.
    pub const FAST_EULER: (f64, f64) = (0.18, 101.0);
    /// Fast kernels: Gouraud, in closed form (15u) or in 32 lanes.
    pub const FAST_GOURAUD: (f64, f64) = (0.032, 15.0);
    /// Fast kernels: the serial corrected-Euler twin.
    pub const FAST_CORRECTED_EULER_SERIAL: (f64, f64) = (2.2, 41.0);
    /// Fast kernels: the serial Gouraud twin.
    pub const FAST_GOURAUD_SERIAL: (f64, f64) = (1.01, 12.0);
    /// Fast kernels: Duff's serial twin, `p` and `q`.
    pub const FAST_DUFF_P: (f64, f64) = (1.01, 22.0);
    /// Fast kernels: Duff's serial twin, `q`.
    pub const FAST_DUFF_Q: (f64, f64) = (3.01, 136.0);
    /// Fast kernels: closed-form `p = A·i + B` (absolute error).
    pub const FAST_P: f64 = 24.0;
    /// Fast kernels: closed-form `q = (C·i + D)·i + E` (absolute error).
    pub const FAST_Q: f64 = 91.0;
}

/// `n` as a float where the derivations hold (`1 ≤ n`, `n·u ≤` [`MAX_NU`]).
fn in_range(n: u32, u: f64) -> Option<f64> {
    let nf = f64::from(n);
    (n > 0 && u > 0.0 && nf * u <= MAX_NU).then_some(nf)
}

fn linear((alpha, beta): (f64, f64), n: f64) -> f64 {
    alpha * n + beta
}

/// The bound of `p/√q` from absolute error bounds `e_p` on `p` and `e_q` on `q`
/// (both in units of `u`), `q ≥ q_min`, `|p| ≤ √q`, and `roundings` more rounded
/// operations (the square root, the division, …) on the value; `None` when `q` could
/// round to zero or below (`e_q·u ≥ q_min`).
///
/// `|p̂/√q̂ − p/√q| ≤ e_p/√(q(1−ρ)) + ((1−ρ)^(−1/2) − 1) + roundings·u·|p̂/√q̂|`, with
/// `ρ = e_q/q_min`.
pub(crate) fn ratio_bound(e_p: f64, e_q: f64, q_min: f64, roundings: f64, u: f64) -> Option<f64> {
    if !(q_min > 0.0 && q_min.is_finite()) {
        return None;
    }
    let rho = e_q * u / q_min;
    if rho >= 0.5 {
        return None;
    }
    let shrink = 1.0 / (1.0 - rho).sqrt();
    let p_term = e_p * u / q_min.sqrt() * shrink;
    let q_term = shrink - 1.0;
    let value = (1.0 + e_p * u / q_min.sqrt()) * shrink;
    Some(p_term + q_term + roundings * 1.0001 * u * value)
}

/// How far `acos` moves when its argument `p` (`|p| ≤ 1`) is off by at most `e`:
/// `e/√(1 − (|p| + e)²)` (the derivative's largest value on the interval) while
/// `|p| + e < 1`, and never more than `(π/√2)·√e` (Hölder). Without `p`, the latter.
fn acos_error(p: Option<f64>, e: f64) -> f64 {
    let holder = ACOS_HOLDER * e.sqrt();
    match p {
        // `p` is the f64 nearest the exact value: `f64::EPSILON` covers its rounding.
        Some(p) if p.abs() + e + f64::EPSILON < 1.0 => {
            let m = p.abs() + e + f64::EPSILON;
            (e / (1.0 - m * m).sqrt()).min(holder)
        }
        _ => holder,
    }
}

/// The bound of the angle interpolated by angular interpolation: the two `acos`
/// (their argument `p_a` or `p_b` off by `5u`, see [`acos_error`], plus one ulp of
/// `acos`, `2πu`), the step's two roundings and `rounded_adds` rounded additions of
/// the angle (each at most `πu`).
fn angle_bound(edges: Option<(f64, f64)>, rounded_adds: f64, u: f64) -> f64 {
    let e = 5.0 * u;
    let acos = match edges {
        Some((pa, pb)) => acos_error(Some(pa), e).max(acos_error(Some(pb), e)),
        None => acos_error(None, e),
    };
    acos + (2.0 + 2.0 + rounded_adds) * std::f64::consts::PI * u
}

/// The largest `|float − exact|` at any pixel of a span of `n` steps whose smallest
/// `q_i = N(i)·N(i)` is `q_min` (1 when the edge normals are equal), for a method
/// run through [`Method::run`] in a float type of unit roundoff `u`.
///
/// `None` where no bound is derived: `n·u > ` [`MAX_NU`], or `q` may round to zero
/// (Phong, Duff, symmetric Phong with `q_min` below about `100·n·u`), or the method's
/// bound needs more of the span than `n` and `q_min` (the related methods: use
/// [`span_bound`]).
///
/// For [`Method::Adaptive`] the bound is against the exact run of the method the
/// float run chose (the two runs may decide differently when `|δ·255·K_d|` is within
/// rounding of 1).
pub fn bound(method: Method, n: u32, q_min: f64, u: f64) -> Option<f64> {
    reference_bound(method, n, q_min, None, u)
}

/// The `reference` profile's bound of `method`: its catalogue row's [`Bound`] (form
/// and constants, `Method::info().bound`) evaluated at `(n, q_min, shape, u)`, with
/// the whole [`Shape`] when the span is known. The other profiles' table is
/// [`profile::status`].
///
/// `None` where the form has no bound: `n·u >` [`MAX_NU`], `q` may round to zero
/// (the ratio and per-pixel forms with a small `q_min`), or a whole-span form without
/// the span.
pub fn reference_bound(
    method: Method,
    n: u32,
    q_min: f64,
    shape: Option<&Shape>,
    u: f64,
) -> Option<f64> {
    let nf = in_range(n, u)?;
    match method.info().bound {
        // Recurrences: docs/float.md §5 (Gouraud), §6 (corrected Euler), §7 (Euler).
        Bound::Linear { below, large } => {
            let coef = match large {
                Some(l) if n > 4096 => l,
                _ => below,
            };
            Some(linear(coef, nf) * u)
        }
        // Duff and symmetric Phong (§8).
        Bound::Ratio { p, q } => ratio_bound(linear(p, nf), linear(q, nf), q_min, 2.0, u),
        // Phong per pixel (§9): the normal off by `normal·u` moves `N·L/|N|` by at
        // most `normal·u/|N|`; evaluating it costs `eval·u` more.
        // The derivation's domain (docs/float.md §9): the normal's error `normal·u`
        // at most 4 % of `|N| ≥ √q_min`, where the unit vector moves by at most
        // `x/√(1 − x²) ≤ 1.001·x` for a relative error `x` (the 0.1 % in `normal`'s
        // constant); beyond it no bound of this form holds.
        Bound::PerPixel { normal, eval } => {
            (q_min > 0.0 && q_min.is_finite() && normal * u <= 0.04 * q_min.sqrt())
                .then(|| (normal / q_min.sqrt() + eval) * u)
        }
        // The adaptive scheme (§10).
        Bound::LargerOfPicks => {
            let [a, b] = method.picks()?;
            Some(reference_bound(a, n, q_min, None, u)?.max(reference_bound(b, n, q_min, None, u)?))
        }
        // Angular interpolation (§11): the angle's bound, then a table's step and its
        // own rounding when tabled.
        Bound::Angle { extra, table } => {
            Some(angle_bound(edges(shape), nf, u) + table.map_or(0.0, table_step) + extra * u)
        }
        // The related methods (§16).
        Bound::WholeSpan(form) => related::of(form, shape?, u),
        // The squared method (§19.7): its `ieee` graphs on the case.
        Bound::Graphs => {
            let format = [crate::Format::Binary32, crate::Format::Binary64]
                .into_iter()
                .find(|f| f.u() == u)?;
            graphs::profile_span_max(
                method,
                profile::Profile::Ieee,
                profile::Form::Any,
                shape?,
                format,
            )
        }
    }
}

/// Whether the adaptive test (eq. 24) is too close to call for an implementation:
/// `|255·K_d·δ|` (the exact `δ`) within `255·K_d·e_δ + 4u` of 1, where `e_δ =
/// 1.01·(b_G + b_CE) + 2u` bounds how far the implementation's own `δ̂` may be from
/// `δ` and `4u` the rounding of its product `255·K_d·δ̂` (docs/float.md §10).
///
/// Proved (`adaptive_acceptance_contains_every_run`, proofs/Profiles.v; test of the
/// same name in tests/profiles/) for an implementation whose `δ̂` is the rounded
/// difference of the two methods' values at the middle pixel, each within its bound
/// `b_G`, `b_CE`: outside this band it decides as the exact run does, so the set
/// `check` accepts — either method's values within the band, the exact run's pick
/// elsewhere — holds every output of the class. For `δ̂` computed as eq. 24 (at either
/// step eq. 23 gives) or as the closed form `ds/2·⌈n/2⌉⌊n/2⌋`,
/// `adaptive_acceptance_covers_computed_delta_generic_step` (proofs/AdaptiveDelta.v),
/// with the bounds and unit of [`profile::adaptive_band`], which every caller passes.
/// The band is widened by 4 `f64` ulps of 1, its own relative rounding, and `1e-25`
/// for a `δ` read from 30 significant digits (both sides evaluated in `f64`, each
/// within a few ulps of the exact value). Where this holds,
/// `check` accepts either method's values, `span`'s bound adds `|δ|`, and the test
/// kit's acceptance intervals take both methods'.
pub fn adaptive_too_close(delta: f64, kd: f64, b_g: f64, b_ce: f64, u: f64) -> bool {
    let e = 1.01 * (b_g + b_ce) + 2.0 * u;
    let slack = 4.0 * f64::EPSILON;
    ((255.0 * kd * delta).abs() - 1.0).abs()
        <= (255.0 * kd * e + 4.0 * u) * (1.0 + slack) + slack + 1e-25
}

/// What the bounds read of a span: `n`, `q_min` (rounded down) and the edge
/// intensities `p_a`, `p_b` (angular interpolation's `acos` is ill-conditioned near
/// ±1, so its bound is smaller when they are known).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape {
    /// Steps.
    pub n: u32,
    /// `min_i q_i`, rounded down.
    pub q_min: f64,
    /// `N_a·L`.
    pub p_a: f64,
    /// `N_b·L`.
    pub p_b: f64,
    /// `cos Ω = N_a·N_b` (to nearest), for the related methods ([`related`]).
    pub cos_omega: f64,
    /// `sin² Ω = 1 − (N_a·N_b)²`, computed exactly and then rounded; `0` exactly
    /// when `N_a = ±N_b` and positive otherwise ([`related`]).
    pub sin2_omega: f64,
    /// `|N_b − N_a|`, rounded up (Phong's derived profile bound,
    /// [`profile::phong_bound`]).
    pub dn: f64,
    /// `N_a`, `N_b`, `L` as intervals of `f64` (exact where the input is an `f64`):
    /// the inputs of the operation graphs' bounds ([`graphs::pixel_bounds`]).
    pub inputs: [(f64, f64); 9],
}

impl Shape {
    /// The shape of an exact span.
    pub fn of(span: &crate::Span<crate::BigRational>) -> Self {
        use crate::Scalar;
        use num_traits::{One, Zero};
        // q_min rounded down; p to nearest (acos_error allows for that).
        let cos_omega = span.na.dot(&span.nb);
        let sin2 = crate::BigRational::one() - cos_omega.clone() * cos_omega.clone();
        // A positive sin²Ω too small for f64 stays positive (the bounds then refuse
        // the span rather than take it for N_a = N_b).
        let sin2_omega = if sin2.is_zero() {
            0.0
        } else {
            sin2.to_f64().max(f64::MIN_POSITIVE)
        };
        Shape {
            inputs: graph::inputs_of(&span.na, &span.nb, &span.l),
            n: span.n,
            q_min: span.q_min().to_f64() * (1.0 - 1e-15),
            p_a: span.p_a.to_f64(),
            p_b: span.p_b.to_f64(),
            cos_omega: cos_omega.to_f64(),
            sin2_omega,
            dn: {
                // |N_b − N_a|² exactly, then each rounding (to nearest, 2^-53) made up.
                let d = [
                    &span.nb.x - &span.na.x,
                    &span.nb.y - &span.na.y,
                    &span.nb.z - &span.na.z,
                ];
                let d2 = d
                    .iter()
                    .map(|c| c * c)
                    .fold(crate::BigRational::zero(), |a, b| a + b);
                // A nonzero |N_b − N_a|² below f64's normal range stays above its
                // square root's (2^-511), not 0.
                let up = (d2.to_f64() * (1.0 + 2f64.powi(-50))).sqrt() * (1.0 + 2f64.powi(-50));
                if d2.is_zero() {
                    0.0
                } else {
                    up.max(2f64.powi(-511))
                }
            },
        }
    }
}

/// [`bound`] for a known span: the same derivation with what the method's bound
/// reads of the span (tighter for angular interpolation; the only bound of the
/// related methods).
pub fn span_bound(method: Method, shape: &Shape, u: f64) -> Option<f64> {
    reference_bound(method, shape.n, shape.q_min, Some(shape), u)
}

fn edges(shape: Option<&Shape>) -> Option<(f64, f64)> {
    shape.map(|s| (s.p_a, s.p_b))
}

/// The bound of a specular value `max(0, v)^s` from the bound `b` of the base value
/// `v` (`0 ≤ v ≤ v_max`): an error `e ≤ b` in `v` moves `v^s` by at most
/// `s·(v_max + b)^(s−1)·b` (the mean value theorem), and evaluating the power adds a
/// relative `γ_s` (`s − 1` products in any order, or a `pow` within an ulp) of at
/// most `(v_max + b)^s`. The values may exceed 1 (corrected Euler reaches about
/// 1.19), so the factor is taken at `v_max`, not at 1. Attacked by
/// `tests/profiles/published.rs::specular_bound_holds`.
///
/// Each of the `s − 1` products may also underflow, off by half the smallest subnormal
/// `η` ([`crate::Format::eta`]: `2^-150` in binary32, `2^-1075` in binary64) instead of relatively, which the
/// later products carry at most `max(1, v_max + b)^s` times: `s·η·max(1, v_max + b)^s`
/// more (a large `s` on a small value underflows to zero: this is that term).
pub fn specular_bound(b: f64, s: f64, v_max: f64, format: crate::Format) -> f64 {
    let u = format.u();
    let g = s * u / (1.0 - s * u);
    let eta = format.eta();
    let top = (v_max + b).max(1.0).powf(s);
    (s * (v_max + b).powf(s - 1.0) * b + g * (v_max + b).powf(s) + s * eta * top) * (1.0 + 1e-12)
}

/// One step of a cosine table of `size` entries over 0–90°: the largest difference
/// between neighbouring entries, and so what reading the neighbour costs.
pub fn table_step(size: u32) -> f64 {
    std::f64::consts::FRAC_PI_2 / f64::from(size.max(2) - 1)
}

/// The fast kernels of [`crate::fast::FastSpan`], whose set-up (one reciprocal, the
/// closed form of `ds`) and evaluation order differ from [`Method::shade`]'s.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kernel {
    /// `FastSpan::corrected_euler` (closed form, or the recurrence in 32 lanes).
    CorrectedEuler,
    /// `FastSpan::corrected_euler_serial` (`p += t; t += ds`).
    CorrectedEulerSerial,
    /// `FastSpan::euler` (closed form, or the recurrence in 32 lanes).
    Euler,
    /// `FastSpan::gouraud` (closed form, or `g += dp` in 32 lanes).
    Gouraud,
    /// `FastSpan::gouraud_serial` (`g += dp`).
    GouraudSerial,
    /// `FastSpan::adaptive`, against the exact run of the method it chose.
    Adaptive,
    /// `FastSpan::phong` (closed-form `p`, `q`; `sqrt` and a division).
    Phong,
    /// `fast::phong_rsqrt_f32` (`rsqrtps`, relative error ≤ 1.5·2^-12 by Intel's
    /// documentation, and one Newton step).
    PhongRsqrt,
    /// `FastSpan::symmetric_phong`.
    SymmetricPhong,
    /// `FastSpan::duff_serial`.
    DuffSerial,
    /// `FastSpan::angular` (closed-form angle).
    Angular,
}

/// [`bound`] for a fast kernel (with the span's `p_a`, `p_b` when known, as in
/// [`span_bound`]).
pub fn fast_bound(kernel: Kernel, n: u32, q_min: f64, u: f64) -> Option<f64> {
    fast_method_bound(kernel, n, q_min, None, u)
}

/// [`fast_bound`] for a known span.
pub fn fast_span_bound(kernel: Kernel, shape: &Shape, u: f64) -> Option<f64> {
    fast_method_bound(
        kernel,
        shape.n,
        shape.q_min,
        Some((shape.p_a, shape.p_b)),
        u,
    )
}

fn fast_method_bound(
    kernel: Kernel,
    n: u32,
    q_min: f64,
    edges: Option<(f64, f64)>,
    u: f64,
) -> Option<f64> {
    let nf = in_range(n, u)?;
    let lin = |c: (f64, f64)| Some(linear(c, nf) * u);
    let fast_phong = |extra: f64| ratio_bound(coef::FAST_P, coef::FAST_Q, q_min, extra, u);
    match kernel {
        Kernel::CorrectedEuler => lin(coef::FAST_CORRECTED_EULER),
        Kernel::CorrectedEulerSerial => lin(coef::FAST_CORRECTED_EULER_SERIAL),
        Kernel::Euler => lin(coef::FAST_EULER),
        Kernel::Gouraud => lin(coef::FAST_GOURAUD),
        Kernel::GouraudSerial => lin(coef::FAST_GOURAUD_SERIAL),
        Kernel::Adaptive => {
            Some(linear(coef::FAST_CORRECTED_EULER, nf).max(linear(coef::FAST_GOURAUD, nf)) * u)
        }
        Kernel::Phong => fast_phong(2.0),
        Kernel::SymmetricPhong => fast_phong(3.0),
        // 1.5·(1.5·2^-12)² + the Newton step's five roundings + the product.
        Kernel::PhongRsqrt => fast_phong(3.4 * (2f64.powi(-24) / u) + 6.0),
        Kernel::DuffSerial => ratio_bound(
            linear(coef::FAST_DUFF_P, nf),
            linear(coef::FAST_DUFF_Q, nf),
            q_min,
            2.0,
            u,
        ),
        Kernel::Angular => Some(angle_bound(edges, 2.0, u) + 2.0 * u),
    }
}
