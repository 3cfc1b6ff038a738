//! Error bounds of the related span methods ([`crate::related`]) run in a float type
//! against their exact run, derived in `docs/float.md` §16 (one subsection per method,
//! following the operation order of the code).
//!
//! As for the paper's methods ([`super::span_bound`]): the float run rounds the exact
//! unit inputs to the float type and runs the method's code there; the exact run runs
//! the same code on the exact inputs in rationals (square roots and transcendental
//! functions to 2^-256). Each function returns `|float − exact|` at most, at every
//! pixel, or `None` where the derivation does not hold: `n·u >` [`super::MAX_NU`],
//! or the span is in a regime named in the function's documentation (a rounding that
//! can reach the quantity it rounds). Spherical interpolation calls libm's `acos`
//! and `cos`: its bound assumes both are within one ulp, as angular interpolation's
//! does (`docs/float.md` §11).
//!
//! The bounds are derived, not proved (`docs/float.md` §15); `tests/float_bounds_related.rs`
//! checks them on the edge, random and targeted spans of `tests/common` and searches for
//! counterexamples.

use super::{acos_error, in_range, ratio_bound, Shape};
use crate::method::WholeSpan;
use std::f64::consts::PI;

/// The constants of the three derivations, in units of `u` (`docs/float.md` §16).
mod k {
    /// `p̂_a`, `p̂_b`, `Ê` and the cosine `N̂_a·N̂_b`: rounded inputs (`2u`) and a dot
    /// product of three terms (`3u`) of unit vectors (§4).
    pub const DOT: f64 = 5.0;
    /// Spherical: the numerator `p_b − cos Ω·p_a` of `w·L`: `5 + 5 + 5` from the three
    /// inputs, one product and one subtraction (§16.1).
    pub const SPH_NU: f64 = 17.0;
    /// Spherical: one step `fl(fl(2cosΔ·I_k) − I_{k−1})`: `u·2|I|` and `u·|I|` (§16.1).
    pub const SPH_STEP: f64 = 3.0;
    /// Spherical, `N_a = N_b`: `|p̂_a − fl(ĉ·p̂_a)| ≤ (5 + 1)u` (§16.1).
    pub const SPH_EQUAL_NU: f64 = 6.0;
    /// `√2·acos(1 − h)/√h` for the `h ≤ 5u` of `N_a = N_b`: at most `2·1.001`, i.e.
    /// `acos(1 − h) ≤ 1.001·√(2h)` (§16.1).
    pub const ACOS_NEAR_ONE: f64 = 1.001;
    /// Binary: `p(i) = A·i + B` on the `Span` set-up: `14 + 5 + 2 + 1` (§16.2).
    pub const BIN_P: f64 = 22.0;
    /// Binary: `q(i) = (C·i + D)·i + E`: `36 + 28 + 5` and roundings `4 + 4 + 1 + 1`
    /// (§16.2).
    pub const BIN_Q: f64 = 79.0;
    /// Binary: `N(a)·N(b) = E + (a + b)D/2 + abC`: `5 + 28 + 36` from the set-up and
    /// roundings `4 + 3 + 4 + 1` (§16.2).
    pub const BIN_DOT: f64 = 81.0;
    /// Bishop–Weimer: `N̂_3 = N̂_a + k̂·n/2`, Euclidean: `1 + 3 + 1 + 1` (§16.3).
    pub const BW_N3: f64 = 6.0;
    /// Bishop–Weimer: `a = L·k` (the set-up's `A`, §4), times `n`.
    pub const BW_A: f64 = 14.0;
    /// Bishop–Weimer: `d = k·k` (the set-up's `C`, §4), times `n²`.
    pub const BW_D: f64 = 36.0;
    /// The last relative rounding-up of every bound: the bound's own evaluation in
    /// `f64`, the exact run's `2^-256`, underflow, and the second-order terms of the
    /// set-ups (each a product of two relative errors below `2^-10`).
    pub const SLACK: f64 = 1.01;
}

/// The smallest float above zero that `fl(1 − fl(x²))` can be, in units of `u`, for `x`
/// a float with `fl(x²) < 1`: the float below 1 is `1 − u`, and the subtraction is
/// exact (Sterbenz), so it is `u`.
const MIN_ONE_MINUS_SQUARE: f64 = 1.0;

/// `|√a − √b|` for `|a − b| ≤ e`, `b = r² ≥ 0`: `e/(r + √(r² − e))`, never more than
/// `√e`.
fn sqrt_error(r: f64, e: f64) -> f64 {
    let lower = (r * r - e).max(0.0).sqrt();
    if r + lower > 0.0 {
        (e / (r + lower)).min(e.sqrt())
    } else {
        e.sqrt()
    }
}

/// `sin²Ω`, `sin Ω` and `cos Ω` of a shape, `Ω ∈ [0, π]` the angle between `N_a` and `N_b`.
fn angle(shape: &Shape) -> (f64, f64, f64) {
    let c = shape.cos_omega.clamp(-1.0, 1.0);
    let s2 = shape.sin2_omega.clamp(0.0, 1.0);
    let s = s2.sqrt();
    (s2, s, c)
}

/// The whole-span bound its catalogue row names ([`crate::method::Bound::WholeSpan`]):
/// [`spherical`], [`binary`] or [`bishop_weimer`]; `None` where the derivation does
/// not hold for this shape.
pub fn of(form: WholeSpan, shape: &Shape, u: f64) -> Option<f64> {
    match form {
        WholeSpan::Spherical => spherical(shape, u),
        WholeSpan::Binary => binary(shape, u),
        WholeSpan::BishopWeimer => bishop_weimer(shape, u),
    }
}

/// Kuijk & Blake's spherical interpolation,
/// [`crate::related::spherical::shade`]: `docs/float.md` §16.1.
///
/// The set-up `cos Ω`, `sin Ω`, `w·L`, `Δ = acos(cos Ω)/n`, `cos Δ`, `sin Δ` and the
/// first value `I_1`, then the Chebyshev recurrence `I_{k+1} = 2cosΔ·I_k − I_{k−1}`,
/// whose error at pixel `m` is the first two values' errors times at most `m`, plus
/// every later step's (the perturbation `2|δcos Δ|·|I|` of the coefficient and the
/// step's roundings `3u|I|`) times at most `m − j`: `B = (n e_1 + (n − 1) e_0 + K) /
/// (1 − K)` with `K = n(n−1)/2·(2δ_c + 3u)` (the `n²` growth of the recurrence).
///
/// `None` when `n·u >` [`super::MAX_NU`], when `K ≥ 1/2`, or when `0 < sin²Ω ≤
/// 2·e_{s²}` (`e_{s²} ≈ 12u`: normals within about `5√u` of equal or opposite, where
/// the float `1 − cos²Ω` may round to zero or to a few `u`, and `w·L = ν/sin Ω`
/// divides by it). `N_a = N_b` (`sin²Ω = 0`) has a bound of its own (the exact run
/// is the constant `p_a`). Assumes libm's `acos` and `cos` within one ulp (§11).
pub fn spherical(shape: &Shape, u: f64) -> Option<f64> {
    let nf = in_range(shape.n, u)?;
    let (s2, s, c) = angle(shape);
    // |w·L| ≤ √(1 − p_a²): the sinusoid's amplitude is at most 1 (the f64 p_a is the
    // nearest to the exact one; 1e-15 covers that under the root).
    let w_max = ((1.0 - shape.p_a * shape.p_a).max(0.0) + 1e-15)
        .sqrt()
        .min(1.0);
    let e_in = k::DOT * u;
    let (e1, dc) = if s2 == 0.0 {
        spherical_equal_normals(nf, e_in, u)
    } else {
        spherical_first_value(nf, s2, s, c, w_max, e_in, u)?
    };
    let kk = nf * (nf - 1.0) / 2.0 * (2.0 * dc + k::SPH_STEP * 1.0001 * u);
    if kk >= 0.5 {
        return None;
    }
    let b = (nf * e1 + (nf - 1.0) * e_in + kk) / (1.0 - kk);
    Some(k::SLACK * b.max(e_in))
}

/// The error of `I_1` and of `cos Δ` for `N_a ≠ ±N_b` (`docs/float.md` §16.1).
fn spherical_first_value(
    nf: f64,
    s2: f64,
    s: f64,
    c: f64,
    w_max: f64,
    e_in: f64,
    u: f64,
) -> Option<(f64, f64)> {
    // ĉ off by 5u; 1 − ĉ·ĉ off by 2|c|·5u, the product's and the subtraction's
    // roundings.
    let e_s2 = (2.0 * c.abs() * k::DOT + 1.0 + s2) * u + e_in * e_in;
    if s2 <= 2.0 * e_s2 {
        return None;
    }
    let s_low = (s2 - e_s2).sqrt() * (1.0 - u);
    let e_s = sqrt_error(s, e_s2) + u * s;
    // w·L = ν/sin Ω, |ν| = |w·L| sin Ω.
    let e_nu = k::SPH_NU * u;
    let mut e_w = (e_nu + w_max * e_s) / s_low;
    e_w += u * (w_max + e_w);
    // Δ = acos(ĉ)/n: acos's argument off by 5u (Hölder at ±1, §11), libm's acos one
    // ulp, the division one rounding.
    let omega = s.atan2(c);
    let e_acos = acos_error(Some(c), e_in);
    let e_alpha = e_acos + 2.0 * u * (omega + e_acos).min(PI);
    let delta = omega / nf;
    let e_delta = e_alpha / nf + u * (delta + e_alpha / nf);
    // cos Δ̂: cos is 1-Lipschitz with |sin| ≤ sin Δ + e_Δ between, plus one ulp.
    let sd = delta.sin();
    let dc = (sd + e_delta).min(1.0) * e_delta + 2.0 * u;
    // sin Δ = √(1 − cos²Δ) from ĉ_d.
    let e_s2d = 2.0 * dc + dc * dc + u * (1.0 + sd * sd);
    let e_sd_core = sqrt_error(sd, e_s2d);
    let e_sd = e_sd_core + u * (sd + e_sd_core);
    // I_1 = p_a·cos Δ + (w·L)·sin Δ: the two products' errors and three roundings.
    let first = e_in * (1.0 + dc) + dc;
    let second = e_w * (sd + e_sd) + w_max * e_sd;
    let roundings = u * (1.0 + (w_max + e_w) * (sd + e_sd) + 1.0 + first + second);
    Some((first + second + roundings, dc))
}

/// The error of `I_1` and of `cos Δ` for `N_a = N_b` (`docs/float.md` §16.1): the
/// rounded inputs coincide, `|1 − ĉ| ≤ 5u`, and either the float run takes the
/// constant branch too or `ŝ ≥ √u` bounds `|ŵ| ≤ 6.02√u`.
fn spherical_equal_normals(nf: f64, e_in: f64, u: f64) -> (f64, f64) {
    let w_hat =
        k::SPH_EQUAL_NU * u * (1.0 + 2.0 * u) / ((MIN_ONE_MINUS_SQUARE * u).sqrt() * (1.0 - u));
    // Ω̂ = acos(ĉ)(1 + 2u) ≤ 1.001·√(2·5u)·(1 + 2u); Δ̂ = Ω̂/n (1 + u).
    let omega_hat = k::ACOS_NEAR_ONE * (2.0 * e_in).sqrt() * (1.0 + 3.0 * u);
    let delta_hat = omega_hat / nf;
    // 1 − ĉ_d ≤ Δ̂²/2 + 2u, and ĉ_d ≤ 1 + 2u.
    let dc = delta_hat * delta_hat / 2.0 + 2.0 * u;
    let sd_hat = ((2.0 * dc + u) * (1.0 + u)).sqrt() * (1.0 + u);
    let second = w_hat * sd_hat;
    let first = e_in * (1.0 + dc) + dc;
    let roundings = u * (2.0 + second + first);
    (first + second + roundings, dc)
}

/// Ouyang & Maynard's binary interpolation, [`crate::related::binary::shade`]:
/// `docs/float.md` §16.2.
///
/// The segment ends are Phong values `p/√q` (the bound of Duff's value, §8, with
/// `e_p = 22u`, `e_q = 79u`); each of the `⌊log₂ n⌋` halving levels `j` takes
/// `cos(θ/2^j) = √((1 + cos(θ/2^{j−1}))/2)` and multiplies a sum of two earlier values
/// by `1/(2cos(θ/2^j))`, so the earlier error is divided by `cos(θ/2^j) ≥ cos(Ω/2^j)`
/// (the angle `θ` of any segment is at most `Ω`) and the factor's relative error is
/// added: `E_j = (E_{j−1} + u(1 + E_{j−1}))(1 + ρ_j)/cos(Ω/2^j) + ρ_j + u`. Over all
/// levels the product of the `1/cos` is at most `Ω/sin Ω`.
///
/// `None` when `n·u >` [`super::MAX_NU`], when `q` may round to zero (`79u ≥
/// q_min/2`, as Duff), or when a level's cosine is not known to better than half of
/// itself (normals close to opposite, `cos(Ω/2)` of the order of the error of
/// `cos θ`, about `160u/q_min`).
pub fn binary(shape: &Shape, u: f64) -> Option<f64> {
    in_range(shape.n, u)?;
    let q_min = shape.q_min;
    let mut e_val = ratio_bound(k::BIN_P, k::BIN_Q, q_min, 2.0, u)?;
    let (_, s, c) = angle(shape);
    let omega = s.atan2(c) * (1.0 + 1e-12);
    // cos θ at the segment's ends, N(a)·N(b)/√(q(a)q(b)): the dot product, the
    // denominator's relative error (two q's, a product and a root), the division.
    let delta = k::BIN_Q * u / q_min;
    let rho_den = delta + 1.5 * u + 2.0 * delta * u;
    if rho_den >= 0.5 {
        return None;
    }
    let mut e_cos = (k::BIN_DOT * u / q_min + rho_den) / (1.0 - rho_den);
    e_cos += u * (1.0 + e_cos);
    let depth = 31 - shape.n.leading_zeros();
    for j in 1..=depth {
        let low = (omega / f64::from(1u32 << j)).min(PI / 2.0).cos() * (1.0 - 1e-12);
        // ĥ = fl(1 + ĉ)/2, ĉ_j = fl(√ĥ).
        let eta = (e_cos + 2.0 * u) / 2.0;
        e_cos = sqrt_error(low, eta) + u;
        if e_cos >= low / 2.0 {
            return None;
        }
        // The factor 1/(2ĉ_j), one rounding.
        let rho = (1.0 + e_cos / (low - e_cos)) * (1.0 + u) - 1.0;
        let spread = (e_val + u * (1.0 + e_val)) * (1.0 + rho) / low + rho;
        e_val = (spread + u) / (1.0 - u);
    }
    Some(k::SLACK * e_val)
}

/// Bishop & Weimer along a span, [`crate::related::bishop_weimer::shade`]:
/// `docs/float.md` §16.3.
///
/// The expansion about the middle pixel has the exact coefficients `t_0 = c/√i`
/// (Phong's value there), `t_2 = a/√i` and `t_5 = −cd/(2i√i)`, with `i = cos²(Ω/2)`,
/// `|a| ≤ 2 sin(Ω/2)/n`, `d = 4sin²(Ω/2)/n²`; the exact `g = 2k·N(n/2)` is 0 and its
/// float value (`≤ 48u/n`) only adds first-order terms. The errors of the coefficients
/// reach pixel `x` (relative to the middle) as `e_0 + e_2|x| + e_5x²`, `|x| ≤ n/2`;
/// the evaluation of the start value and slope and the forward differences add
/// `u(n²/2·max|ΔI| + n·max|I|)`. Every term is a multiple of `u` times a power of
/// `1/cos(Ω/2)` and of `tan(Ω/2)`; the growth in `n` is linear (the coefficients'
/// errors are `O(u/n)` and `O(u/n²)`, as the coefficients are).
///
/// `None` when `n·u >` [`super::MAX_NU`] or when the relative error of the
/// denominator `8i²√i` may exceed `2^-10` (about `30u/cos(Ω/2)`: normals within
/// about `4·10^-3` rad, in `f32`, or `7·10^-12` rad, in `f64`, of opposite).
pub fn bishop_weimer(shape: &Shape, u: f64) -> Option<f64> {
    let nf = in_range(shape.n, u)?;
    let (s2, _, c) = angle(shape);
    // ν² = cos²(Ω/2) = (1 + c)/2, σ² = sin²(Ω/2) = (1 − c)/2, the small one from
    // sin²Ω to keep its relative accuracy.
    let (nu2, sigma2) = if c >= 0.0 {
        ((1.0 + c) / 2.0, s2 / (2.0 * (1.0 + c)))
    } else {
        (s2 / (2.0 * (1.0 - c)), (1.0 - c) / 2.0)
    };
    let nu = (nu2 * (1.0 - 1e-12)).sqrt();
    let sigma = (sigma2 * (1.0 + 1e-12)).sqrt().min(1.0);
    if nu.is_nan() || nu <= 0.0 {
        return None;
    }
    // Set-up (§16.3): N̂_3 off by 6u; c = L·N_3, i = N_3·N_3, g = 2k·N_3.
    let e_c = (k::BW_N3 + 4.0 * nu) * u;
    let rel_i = (2.0 * k::BW_N3 / nu + 3.0) * u;
    let rel_s = rel_i / 2.0 + u;
    let e_a = k::BW_A * u / nf;
    let e_d = k::BW_D * u / (nf * nf);
    let g_hat = 2.0 * (2.0 * nu + 10.0 * sigma * nu + 12.0 * sigma) * u / nf;
    let rel_d5 = 2.0 * rel_i + rel_s + 2.0 * u;
    if rel_d5 > 1.0 / 1024.0 {
        return None;
    }
    // t_0 = c/√i, |t_0| ≤ 1.
    let e_t0 = e_c / nu + rel_s + u;
    // t_2 = (2a·i − c·g)/(2i√i).
    let a_max = 2.0 * sigma / nf;
    let e_n2 = 2.0 * e_a * nu2
        + 2.0 * a_max * nu2 * rel_i
        + 2.0 * u * a_max * nu2
        + (nu + e_c) * g_hat
        + 2.0 * u * a_max * nu2;
    let rel_d2 = rel_i + rel_s + u;
    let t2_max = a_max / nu;
    let e_t2 = e_n2 / (2.0 * nu2 * nu) + t2_max * (rel_d2 + u);
    // t_5 = (3c·g² − 4c·d·i − 4a·g·i)/(8i²√i).
    let d_max = 4.0 * sigma2 / (nf * nf);
    let y_max = 4.0 * nu * d_max * nu2;
    let e_y =
        4.0 * (e_c * d_max * nu2 + nu * e_d * nu2 + nu * d_max * rel_i * nu2) + 2.0 * u * y_max;
    let e_x = 3.0 * (nu + e_c) * g_hat * g_hat;
    let e_z = 4.0 * (a_max + e_a) * g_hat * nu2 * (1.0 + rel_i);
    let e_n5 = e_x + e_y + e_z + 2.0 * u * (y_max + e_x + e_y + e_z);
    let t5_max = 2.0 * sigma2 / (nf * nf * nu2);
    let e_t5 = e_n5 / (8.0 * nu2 * nu2 * nu) + t5_max * (rel_d5 + u);
    // The coefficients' errors at |x| ≤ n/2.
    let half = nf / 2.0;
    let setup = e_t0 + half * e_t2 + half * half * e_t5;
    // Sizes: τ = tan(Ω/2); |I| ≤ 1 + τ + τ²/2, |ΔI| ≤ (2τ + 2τ²(n + 1)/n)/n.
    let tau = sigma / nu;
    let v_max = 1.0 + tau + tau * tau / 2.0;
    let dv_max = (2.0 * tau + 2.0 * tau * tau * (nf + 1.0) / nf) / nf;
    // Start value t_5x_0² + t_2x_0 + t_0 (four roundings) and slope t_5(2x_0 + 1) + t_2
    // (two, carried n times).
    let eval_v0 = u * (1.5 * tau * tau + 2.0 * tau + v_max);
    let eval_dv0 = u * (4.0 * tau * tau + 2.0 * tau);
    // Forward differences: I += ΔI (n roundings), ΔI += 2t_5 (n²/2).
    let sweep = u * (nf * nf / 2.0 * dv_max + nf * v_max);
    Some(k::SLACK * (setup + eval_v0 + eval_dv0 + sweep))
}
