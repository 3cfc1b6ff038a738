//! The standard model of a float profile (`docs/float.md` §18.1) — one `κ` per class
//! of operation — and the value step `p/√q` on it (`proofs/PhongValue.v`), which the
//! derived ([`super::derived`]) and the composed ([`super::counts`]) bounds share.

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
    /// A square root (under `shader`, `1/inversesqrt`: 2 ulps and a 2.5-ulp division,
    /// `shader_sqrt_recip_rsqrt` and `shader_sqrt_recip_rsqrt_ap1`, proofs/ShaderSqrt.v).
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
        // sqrt inherited from 1/inversesqrt (2 ulp = 4, then the division, 5:
        // (1 + δ2)/(1 + δ1) − 1 is within 9u/(1 − 4u) ≤ (9 + 2^-18)u at u = 2^-24,
        // not 9u: `shader_sqrt_recip_rsqrt`, proofs/ShaderSqrt.v), denormals flushed
        // (2^-126).
        (Profile::Shader, Format::Binary32) => Some(Arith {
            u,
            input: 2.0,
            add: 2.0,
            mul: 2.0,
            div: 5.0,
            half: 7.0,
            sqrt: 9.0 + 1.0 / 262_144.0,
            eta: format.min_normal(),
        }),
        _ => None,
    }
}

/// `γ_w = w·u/(1 − w·u)`: the relative error of a product of factors `(1 + δ_j)`
/// whose `|δ_j| ≤ κ_j·u` sum to `Σκ_j = w`.
pub(super) fn gamma(w: f64, u: f64) -> f64 {
    w * u / (1.0 - w * u)
}

/// `phong_value_either` (`proofs/PhongValue.v`): from `|p̂ − p| ≤ e_p`, `|q̂ − q| ≤ e_q`,
/// `q ≥ q_min`, `|p| ≤ √q`, every way of `p̂/√q̂` or `p̂·(1/√q̂)` the profile allows is
/// within
/// `B·(1 + γ_f) + γ_f + 2(1 + B)·η/√(q_min − e_q) + (1 + e_p)(1 + κ_mul·u)·η + η`,
/// `B = e_p/√(q_min − e_q) + e_q/(√(q_min − e_q)·(√q_min + √(q_min − e_q)))`, `γ_f` for
/// the square root, the division (or the reciprocal and the product), `η` the absolute
/// error of one operation. `None` outside the theorem's conditions (`2e_q ≤ q_min`,
/// `γ_f`'s `κ·u ≤ 2^-10`, `1024·η ≤ √(q_min − e_q)`).
pub(super) fn value_step(a: &Arith, e_p: f64, e_q: f64, q_min: f64, eta: f64) -> Option<f64> {
    let u = a.u;
    if !(q_min > 0.0 && q_min.is_finite()) || e_q >= q_min / 2.0 {
        return None;
    }
    let g_f = gamma(a.ratio(), u);
    let lo = (q_min - e_q).sqrt();
    if a.ratio() * u > 2f64.powi(-10) || 1024.0 * eta > lo {
        return None;
    }
    let b_real = e_p / lo + e_q / (lo * (q_min.sqrt() + lo));
    // The square root's η relative to `√q̂ ≥ √(q_min − e_q)`, the reciprocal's times
    // `|p̂| ≤ 1 + e_p`, the last operation's own.
    let abs = 2.0 * (1.0 + b_real) * (eta / lo) + (1.0 + e_p) * eta * (1.0 + a.mul * u) + eta;
    let b = b_real * (1.0 + g_f) + g_f + abs;
    // This evaluation in f64 rounds too: a relative 2^-40 more covers it.
    Some(b * (1.0 + 2f64.powi(-40)))
}
