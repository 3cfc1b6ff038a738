//! The derived bounds: written derivations on the standard model of a profile
//! (`docs/float.md` §18.4–18.5) for the methods with no theorem under `ieee` and
//! `shader` — Phong, Duff, symmetric Phong — and plain Euler's, kept for comparison.

use super::Profile;
use crate::Format;

/// The standard model of a float profile (`docs/float.md` §18.1): every operation's
/// result is within `κ·u·|y| + η` of its exact value `y` on the computed operands,
/// with one `κ` per class of operation (in units of `u`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arith {
    /// The unit roundoff of the format.
    pub u: f64,
    /// Rounding an exact input to the format.
    pub input: f64,
    /// An addition or subtraction (a fused multiply-add rounds once, as an addition).
    pub add: f64,
    /// A product.
    pub mul: f64,
    /// One division (a reciprocal `1/x` is one).
    pub div: f64,
    /// A division by 2 (or a product by `0.5`): exact under `ieee`, a division (or a
    /// computed `1/2` and a product) under `shader`.
    pub half: f64,
    /// A square root (under `shader`, `1/inversesqrt`: 2 ulps and a 2.5-ulp division).
    pub sqrt: f64,
    /// The absolute error of one operation near zero (subnormals, or flushed results).
    pub eta: f64,
}

impl Arith {
    /// A division by `n` as a division or as `1/n` and a product.
    pub fn div_n(&self) -> f64 {
        self.div + self.mul
    }

    /// The largest `κ` of the set-up (inputs, additions, products, divisions by `n`).
    pub fn setup(&self) -> f64 {
        self.input.max(self.add).max(self.mul).max(self.div_n())
    }

    /// The value `p/√q` from `p` and `q`: the square root, a division (or `1/√q`) and a
    /// product.
    pub fn ratio(&self) -> f64 {
        self.sqrt + self.div + self.mul
    }
}

/// The standard model of `profile` in `format` (binary32 or
/// binary64 for `ieee`, binary32 for `shader`), or `None` (`reference` is one
/// implementation, not a model; fixed point has its own bounds).
pub fn arith(profile: Profile, format: Format) -> Option<Arith> {
    let u = format.u();
    match (profile, format) {
        (Profile::Ieee, Format::Binary32 | Format::Binary64) => Some(Arith {
            u,
            input: 1.0,
            add: 1.0,
            mul: 1.0,
            div: 1.0,
            half: 0.0,
            sqrt: 1.0,
            // Half the smallest subnormal.
            eta: format.eta(),
        }),
        // Vulkan/WGSL: add, sub, mul faithful (2 units of u), division 2.5 ulp (5),
        // sqrt inherited from 1/inversesqrt (2 ulp = 4, then the division, 5),
        // denormals flushed (2^-126).
        (Profile::Shader, Format::Binary32) => Some(Arith {
            u,
            input: 2.0,
            add: 2.0,
            mul: 2.0,
            div: 5.0,
            half: 7.0,
            sqrt: 9.0,
            eta: format.min_normal(),
        }),
        _ => None,
    }
}

/// `γ_w = w·u/(1 − w·u)`: the relative error of a product of factors `(1 + δ_j)`
/// whose `|δ_j| ≤ κ_j·u` sum to `Σκ_j = w`.
fn gamma(w: f64, u: f64) -> f64 {
    w * u / (1.0 - w * u)
}

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

/// Duff's forward differences (eqs. 5–7) under a profile, derived (`docs/float.md`
/// §18.5): §8's `e_p = 20·κ_s + 1.01·n·κ_add` and `e_q = 118·κ_s + 3.01·n·κ_add`,
/// then `p/√q` with the square root, a division (or `1/√q`) and a product. `None`
/// where `q` may lose half of itself.
pub fn duff_derived(a: &Arith, n: u32, q_min: f64) -> Option<f64> {
    duff_steps(a, n, n, n, q_min)
}

/// Symmetric Phong (§4) under a profile, derived (`docs/float.md` §18.5): `p` walks
/// to pixel `i` as Duff's does, but `√q_i` comes from the walk from the left edge to
/// `min(i, n − i) ≤ h = ⌊n/2⌋`. §8's `e_p` and `e_q` grow with the steps walked, and
/// the value's bound with both, so on the pixels `i_{k−1} ≤ i ≤ i_k` of the right half
/// (`i_k = h + ⌈k(n − h)/8⌉`, eight pieces) it is at most Duff's with `p` walked `i_k`
/// steps and `q` walked `min(h, n − i_{k−1})`; the left half is within the first
/// piece. The largest of the eight.
pub fn symmetric_phong_derived(a: &Arith, n: u32, q_min: f64) -> Option<f64> {
    let h = n / 2;
    let at = |k: u32| h + (k * (n - h)).div_ceil(8);
    (1..=8u32)
        .map(|k| duff_steps(a, n, at(k), h.min(n - at(k - 1)), q_min))
        .try_fold(0.0f64, |m, b| b.map(|b| m.max(b)))
}

/// §8's bound with `p` walked `p_steps` and `q` walked `q_steps` steps of a span of
/// `n` (the set-up terms taken at their largest, `i = n`).
fn duff_steps(a: &Arith, n: u32, p_steps: u32, q_steps: u32, q_min: f64) -> Option<f64> {
    let nf = derived_n(a, n)?;
    let e_p = 20.0 * a.setup() + 1.01 * f64::from(p_steps.min(n)) * a.add;
    let e_q = 118.0 * a.setup() + 3.01 * f64::from(q_steps.min(n)) * a.add;
    let b = crate::tolerance::ratio_bound(e_p, e_q, q_min, a.ratio(), a.u)?;
    Some(b * 1.01 + eta_total(a, nf) / q_min.sqrt())
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
    if e_q >= q_min / 2.0 {
        return None;
    }
    let g_f = gamma(a.ratio(), u);
    let lo = (q_min - e_q).sqrt();
    // `phong_value_either`'s size conditions (w·u ≤ 2^-10, 1024·η ≤ √(q_min − e_q)).
    if a.ratio() * u > 2f64.powi(-10) || 1024.0 * eta > lo {
        return None;
    }
    let b_real = e_p / lo + e_q / (lo * (q_min.sqrt() + lo));
    // `phong_value_either`'s absolute terms: the square root's η relative to
    // `√q̂ ≥ √(q_min − e_q)`, the reciprocal's times `|p̂| ≤ 1 + e_p`, the last
    // operation's own (each operation's η at most `eta`).
    let abs = 2.0 * (1.0 + b_real) * (eta / lo) + (1.0 + e_p) * eta * (1.0 + a.mul * u) + eta;
    let b = b_real * (1.0 + g_f) + g_f + abs;
    // This evaluation in f64 rounds too: a relative 2^-40 more covers it.
    Some(b * (1.0 + 2f64.powi(-40)))
}

/// [`phong_derived`] under `ieee` in `format`.
/// `dn ≥ |N_b − N_a|` (2 for any unit normals).
pub fn phong_ieee(n: u32, q_min: f64, dn: f64, format: Format) -> Option<f64> {
    phong_derived(&arith(Profile::Ieee, format)?, n, q_min, dn)
}
