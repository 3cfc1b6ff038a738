//! Error bounds of the row set-ups of [`crate::fast_rows`] and the kernels run on
//! them, against the exact run, derived in `docs/float.md` §17 ("The row set-up"),
//! one step per operation of the code.
//!
//! The float run evaluates the polygon's field `U(x, y) = n1·x + n2·y + n3` in the
//! float type, from float inputs; the exact run takes the same inputs exactly, the
//! edge normals `N_a = U_a/|U_a|` and `N_b = U_b/|U_b|` (square roots to 2^-256) and
//! the method's exact values on that unit span. Every bound is first-order in `u`
//! with the second-order terms absorbed by rounding up (`docs/float.md` §2); it is
//! `None` where the relative errors it is built from are not small (more than
//! 2^-10), where the derivation would not hold.
//!
//! The magnitudes the bounds depend on are facts of the exact inputs
//! ([`RowShape`]): `μ = |(|n1_j x| + |n2_j y| + |n3_j|)_j|` (how large the terms of
//! `U_a` are), `ν = n|n1|`, `T = μ + ν`, the edge normals' lengths `ℓ_a`, `ℓ_b`, and
//! `λ = |L|`. On a mesh `T/ℓ` is close to 1; it grows where the field cancels.
//!
//! `tests/fast.rs` checks every bound on edge, random and targeted rows.

use super::ratio_bound;

/// The exact magnitudes a row's bound depends on (`docs/float.md` §17).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowShape {
    /// `μ`: the Euclidean length of `(|n1_j x| + |n2_j y| + |n3_j|)_j` at the row's
    /// first pixel.
    pub mu: f64,
    /// `|n1|`.
    pub n1: f64,
    /// `|U_a|`.
    pub len_a: f64,
    /// `|U_b|`.
    pub len_b: f64,
    /// `|L|`.
    pub lambda: f64,
    /// Steps.
    pub n: u32,
}

impl RowShape {
    /// `ν = n|n1|`.
    pub fn nu(&self) -> f64 {
        f64::from(self.n) * self.n1
    }

    /// `T = μ + ν`.
    pub fn t(&self) -> f64 {
        self.mu + self.nu()
    }
}

/// Absolute errors of a row's start `s = U_a·L`, `g = U_a·n1`, `q = U_a·U_a`, in
/// units of `u`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StartError {
    /// Of `s`.
    pub s: f64,
    /// Of `g`.
    pub g: f64,
    /// Of `q`.
    pub q: f64,
}

/// The start evaluated from the field ([`crate::fast_rows::Field::start`]): `U_a`
/// within `3uμ`, then three dot products (`3u` of their terms' sizes each):
/// `6μλ`, `6μ|n1|`, `9μ²` (§17.1).
pub fn direct_start(r: &RowShape) -> StartError {
    StartError {
        s: 6.0 * r.mu * r.lambda,
        g: 6.0 * r.mu * r.n1,
        q: 9.0 * r.mu * r.mu,
    }
}

/// How a row was reached by [`crate::fast_rows::EdgeStepper`] (§17.4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stepped {
    /// Steps since the start was evaluated from the field.
    pub k: u32,
    /// `σ ≥ |dx·n1 + n2|` for every step taken (`max|dx|·|n1| + |n2|`).
    pub sigma: f64,
    /// `M`: at least `μ` at every row stepped through (the first included).
    pub m: f64,
    /// `|n2|`.
    pub n2: f64,
}

/// The start reached by `k` forward-difference steps from one evaluated from the
/// field (§17.4): the first start's error, plus per step `(5σ + M)` on `s` (times
/// `λ`), `g` (times `|n1|`) and `h` (times `|n2|`); on `q` the increment uses the
/// stepped `g` and `h`, so its error grows with the square of the steps.
pub fn stepped_start(r: &RowShape, st: &Stepped) -> StartError {
    let k = f64::from(st.k);
    let (s, m) = (st.sigma, st.m);
    let per = 5.0 * s + m;
    // Σ_{j<k} 2(|dx|Δg_j + Δh_j) ≤ 2σ·Σ_j (6M + j·per) over the steps, with
    // Δg_j/|n1|, Δh_j/|n2| ≤ 6M + j·per; plus per step the roundings of the
    // increment (4σM in 2(dx·g + h), 7σ² in the constant part, 2σM + σ² in their
    // sum) and of the addition to q (M²).
    let cross = 2.0 * s * (6.0 * m * k + per * k * (k - 1.0) / 2.0);
    let round = k * (6.0 * m * s + 8.0 * s * s + m * m);
    StartError {
        s: 6.0 * m * r.lambda + k * per * r.lambda,
        g: 6.0 * m * r.n1 + k * per * r.n1,
        q: 9.0 * m * m + cross + round,
    }
}

/// Absolute errors of a row's `p_a`, `p_b` and `1 − c`, in units of `u`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpanSetupError {
    /// Of `p_a`.
    pub p_a: f64,
    /// Of `p_b`.
    pub p_b: f64,
    /// Of `1 − c`.
    pub omc: f64,
}

/// The errors of [`crate::fast_rows::RowStart::span`] from those of its start
/// (§17.2): `U_b·L`, `U_a·U_b`, `U_b·U_b`, the two reciprocal square roots and the
/// products; `None` if a relative error would exceed 2^-10.
pub fn span_error(r: &RowShape, e: &StartError, u: f64) -> Option<SpanSetupError> {
    let (nu, t, lam) = (r.nu(), r.t(), r.lambda);
    let nf = f64::from(r.n);
    let (la, lb) = (r.len_a, r.len_b);
    if !(la > 0.0 && lb > 0.0) {
        return None;
    }
    let s_b = e.s + (4.0 * nu + t) * lam;
    let w = e.q + nf * e.g + 2.0 * t * t;
    let q_b = e.q + 2.0 * nf * e.g + 9.0 * t * t;
    // Relative errors of 1/|U_a|, 1/|U_b|: half the square's, a square root and a
    // division.
    let ra = e.q / (2.0 * la * la) + 2.0;
    let rb = q_b / (2.0 * lb * lb) + 2.0;
    let small = 1.0 / 1024.0;
    if !((ra * u) < small && (rb * u) < small && (e.s / la * u) < small) {
        return None;
    }
    Some(SpanSetupError {
        p_a: e.s / la + lam * (ra + 1.0),
        p_b: s_b / lb + lam * (rb + 1.0),
        omc: w / (la * lb) + ra + rb + 4.0,
    })
}

/// The kernels run on a row's [`crate::fast_rows::RowSpan`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RowKernel {
    /// [`crate::fast_rows::RowSpan::corrected_euler`].
    CorrectedEuler,
    /// [`crate::fast_rows::RowSpan::gouraud`].
    Gouraud,
    /// [`crate::fast_rows::RowSpan::phong`].
    Phong,
    /// [`crate::fast_rows::phong_rsqrt`].
    PhongRsqrt,
}

/// The absolute error of a kernel's values on a row of `n` steps whose set-up is
/// within `e` (§17.3), with `q_min` the least `q` of the exact unit span (Phong only)
/// and `lambda = |L|`. The propagated part is the largest derivative of the exact
/// values in `p_a`, `p_b`, `1 − c` (`fast_rows_ce_from_span_invariants`) times the
/// errors; the evaluation part counts the kernel's roundings.
pub fn kernel_bound(
    k: RowKernel,
    n: u32,
    e: &SpanSetupError,
    lambda: f64,
    q_min: f64,
    u: f64,
) -> Option<f64> {
    let slack = 1.0 + 1.0 / 256.0;
    let big = e.p_a.max(e.p_b);
    let v = match k {
        // ∂/∂p_a ≤ (1 − t) + (1 − c)t(1 − t)/2, ∂/∂1−c ≤ |p_a + p_b|/8; the closed
        // form's 16 roundings, or on a row shorter than `fast_rows::SHORT` the
        // recurrence's (21 + 2.2n).
        RowKernel::CorrectedEuler => {
            let nf = f64::from(n);
            let eval = if (n as usize) + 1 < crate::fast_rows::SHORT {
                21.0 + 2.2 * nf
            } else {
                16.0
            };
            big + (e.p_a + e.p_b) / 4.0 + lambda * e.omc / 4.0 + eval * lambda
        }
        RowKernel::Gouraud => big + 9.0 * lambda,
        RowKernel::Phong | RowKernel::PhongRsqrt => {
            let e_p = big + 9.0 * lambda;
            let e_q = e.omc / 2.0 + 31.0;
            let roundings = if k == RowKernel::Phong { 2.0 } else { 9.4 };
            // §8's form is for |p| ≤ √q: p over λ, the result times λ.
            return ratio_bound(e_p / lambda, e_q, q_min, roundings, u)
                .map(|b| slack * b * lambda + u);
        }
    };
    Some((slack * v + 1.0) * u)
}

/// Phong of the field along the row ([`crate::fast_rows::RowStart::phong_field`],
/// or with `rsqrt`) from a start within `e` (§17.5): `p = s + x·n1·L` within
/// `e.s + (4ν + T)λ`, `q = q_a + x(2g + x·n1·n1)` within `e.q + 2n·e.g + 9T²`,
/// `q_min` the least `|U|²` over the row's pixels, and §8's ratio.
pub fn field_phong_bound(
    r: &RowShape,
    e: &StartError,
    q_min: f64,
    rsqrt: bool,
    u: f64,
) -> Option<f64> {
    let (nu, t, lam) = (r.nu(), r.t(), r.lambda);
    let nf = f64::from(r.n);
    let e_p = e.s + (4.0 * nu + t) * lam;
    let e_q = e.q + 2.0 * nf * e.g + 9.0 * t * t;
    let roundings = if rsqrt { 9.4 } else { 2.0 };
    // §8's form is for |p| ≤ √q: divide p by λ, multiply the result back.
    ratio_bound(e_p / lam, e_q, q_min, roundings, u).map(|b| (1.0 + 1.0 / 256.0) * b * lam + u)
}
