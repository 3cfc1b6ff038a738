//! The derived bounds: written derivations on the standard model of a profile
//! (`docs/float.md` §18.4–18.5) for the method whose bound is not a theorem under
//! `ieee` and `shader` at every span — Phong — and plain Euler's, kept for comparison;
//! the standard model itself ([`Arith`]).

use super::model::{arith, gamma, value_step, Arith};
use super::Profile;
use crate::Format;

/// The largest `n` of the derived bounds: `i` and `(i − 1)/2` are exact, and the
/// first-order derivations' second-order terms fit in their last factor `1.01`
/// (`n·κ·u ≤ 2^-8`).
fn derived_n(a: &Arith, n: u32) -> Option<f64> {
    let nf = f64::from(n);
    ((1..=1 << 24).contains(&n)
        && nf * a.setup() * a.u <= 2f64.powi(-8)
        && nf * a.u <= crate::tolerance::MAX_NU)
        .then_some(nf)
}

/// What flushed or subnormal results add to a span's value: at most `η` per
/// operation, carried by at most `n²` (the quadratic term's `i(i−1)/2`), for the at
/// most `64` operations of the set-up and a pixel.
fn eta_total(a: &Arith, nf: f64) -> f64 {
    64.0 * (nf * nf + nf + 1.0) * a.eta
}

/// Plain Euler (eqs. 12–14) under a profile, derived (`docs/float.md` §18.5): the
/// recurrence `E += s; s += ds` from `s_0 = di_a`, or the closed form
/// `p_a + i·(di_a + (i−1)/2·ds)`, on the paper's set-up (§4) in any order of each dot
/// product, fused or not, `/n` as a division or `·(1/n)`.
///
/// Not applied by `check` under any profile: under `ieee` and `shader` the theorems
/// of [`proved`](super::proved) cover the same forms (under `shader` with every division, the
/// halvings included, one 2.5-ulp division or a 2.5-ulp reciprocal and a product) and
/// are smaller at every `n` (`ieee`: `131.41·u` against about `244·u` at `n = 1`;
/// `shader`: `313.36·u` against about `899·u` at `n = 1`, `45,754·u` against
/// `47,176·u` at `n = 4096`). Kept as the derivation `docs/float.md` §18.5 compares
/// with.
///
/// §7's count, each rounding with the largest `κ` of the set-up: `113·κ_s` for the
/// set-up, `6·κ_half` for the two `p/2` (exact under `ieee`), then the larger of the
/// recurrence's `5.6·n·κ_add` and the closed form's `3.8·(2κ_mul + 2κ_add + κ_half)`.
pub fn euler_derived(a: &Arith, n: u32) -> Option<f64> {
    let nf = derived_n(a, n)?;
    let setup = 113.0 * a.setup() + 6.0 * a.half;
    let recurrence = 5.6 * nf * a.add;
    let closed = 3.8 * (2.0 * a.mul + 2.0 * a.add + a.half);
    Some((setup + recurrence.max(closed)) * 1.01 * a.u + eta_total(a, nf))
}

/// Phong under a profile, derived (`docs/float.md` §18.4): every implementation that
/// computes `p_i = N_i·L` and `q_i = N_i·N_i` from the inputs by any of the catalogued
/// forms — Horner's `(A·i + B)` and `(C·i + D)·i + E` with `A = k·L`, `C = k·k`,
/// `D = 2k·N_a`, `E = N_a·N_a`, `k = (N_b − N_a)/n` (or `·(1/n)`); the per-pixel
/// normal `N_a + i·k` or `(1 − t)·N_a + t·N_b`, `t = i/n` — in any order of each dot
/// product, fused or not, and then `p/√q`, `p·(1/√q)` or the dot product of
/// `N·(1/√q)` with `L`.
///
/// Every computed product or sum is its exact value with, on each monomial, factors
/// `(1 + δ_j)` whose `κ_j` sum to at most `w_p` (for `p`) and `w_q` (for `q`) — 11
/// and 15 under `ieee`, 25 and 36 under `shader` — so it is off by at most
/// `γ_w` times the sum of the monomials' absolute values: at most `3` for `p`
/// (`(1 + 2t)`, `|N_a| = |N_b| = |L| = 1`) and `9` for `q` (`(1 + 2t)²`). Or, with
/// `d ≥ |N_b − N_a|` (`dn`): every rounding after the inputs' acts on `N_b − N_a` as
/// one quantity, so the sums are `1 + t·d` and `(1 + t·d)²`, and the inputs' own
/// roundings add at most `2γ_in(1 + γ_{w_p})` to `p` and `4γ_in(1 + d)(1 + γ_{w_q})² +
/// 4γ_in²(1 + γ_{w_q})³` to `q` (the difference of two rounded inputs, `|N| ≤ 1 + t·d`,
/// Cauchy–Schwarz); the smaller of the two forms is taken for each (`e_p`, `e_q`, plus
/// `η'`). With `q̂ ≥ q_min − e_q` and `|p| ≤ √q`:
///
/// `|v̂ − v| ≤ B·(1 + γ_f) + γ_f + 2(1 + B)·η'/√(q_min − e_q) + (1 + e_p)(1 + κ_mul·u)·η' + η'`,
/// `B = e_p/√(q_min − e_q) + e_q/(√(q_min − e_q)·(√q_min + √(q_min − e_q)))`,
///
/// `γ_f` for the square root, the division (or the reciprocal and the product). That
/// step, from `e_p` and `e_q` to the value, is a theorem for `p̂/√q̂` and `p̂·(1/√q̂)`
/// (`phong_value_real`, `phong_value_div`, `phong_value_recip`, `phong_value_either` in
/// `proofs/PhongValue.v`, with their size conditions checked here). The worst-case
/// counts `3γ_{w_p}`, `9γ_{w_q}` are at least the proved ones of Horner's closed form,
/// the per-pixel normal and the lerp (`phong_horner_div_generic`,
/// `phong_horner_recip_generic`, `phong_pixel_div_generic`, `phong_pixel_recip_generic`,
/// `phong_lerp_div_generic`, `phong_lerp_recip_generic` in `proofs/PhongCount.v`), so
/// at `dn = 2` the bound is a theorem for those forms; the counts read with `dn`, and
/// normalize-then-dot, are derived, so the bound is labelled *derived*.
///
/// `None` where `q` may round to half of `q_min` (`e_q ≥ q_min/2`: normals that
/// nearly cancel, where no bound of this form holds), where `1024·η' > √(q_min − e_q)`
/// (the theorems' size condition) or `n > 2^24` (`i` must be exact).
pub fn phong_derived(a: &Arith, n: u32, q_min: f64, dn: f64) -> Option<f64> {
    if !(q_min > 0.0 && q_min.is_finite()) || n == 0 || n > 1 << 24 || dn.is_nan() {
        return None;
    }
    let u = a.u;
    // The longest chains of roundings: k = (N_b − N_a)/n, the normal N_a + i·k (or
    // (1 − t)·N_a + t·N_b, the same count), its products and three-term sums.
    let w_k = a.input + a.add + a.div_n();
    let w_n = w_k + a.mul + a.add;
    let w_p = w_n + a.input + a.mul + 2.0 * a.add + a.mul;
    let w_q = 2.0 * w_n + a.mul + 2.0 * a.add;
    // Underflow or flushing: at most η per rounding, carried by at most i ≤ n.
    let eta = 64.0 * (f64::from(n) + 1.0) * a.eta;
    let (g_p, g_q, g_in) = (gamma(w_p, u), gamma(w_q, u), gamma(a.input, u));
    let d = dn.max(0.0);
    let e_p = (3.0 * g_p).min((1.0 + d) * g_p + 2.0 * g_in * (1.0 + g_p)) + eta;
    let inputs_q =
        4.0 * g_in * (1.0 + d) * (1.0 + g_q).powi(2) + 4.0 * g_in * g_in * (1.0 + g_q).powi(3);
    let e_q = (9.0 * g_q).min((1.0 + d).powi(2) * g_q + inputs_q) + eta;
    value_step(a, e_p, e_q, q_min, eta)
}

/// [`phong_derived`] under `ieee` in `format`.
/// `dn ≥ |N_b − N_a|` (2 for any unit normals).
pub fn phong_ieee(n: u32, q_min: f64, dn: f64, format: Format) -> Option<f64> {
    phong_derived(&arith(Profile::Ieee, format)?, n, q_min, dn)
}
