//! Acceptance profiles: what a correct implementation may do, and the bounds that
//! hold for every implementation of that class (`docs/float.md` §18).
//!
//! A profile is a written model of an arithmetic: how each operation may round, in
//! which order sums may be taken, whether products may be fused. Its bounds are
//! proved for the whole class in Coq (`proofs/Profiles.v`, on the model of
//! `proofs/FloatModelK.v`) where this module says *proved*:
//!
//! | profile | format | Gouraud | corrected Euler |
//! |---|---|---|---|
//! | `ieee` | binary32 | `profile_ieee_gouraud_binary32` | `profile_ieee_corrected_euler_binary32`, `profile_ieee_corrected_euler_closed_binary32` |
//! | `ieee` | binary64 | `profile_ieee_gouraud_binary64`, `profile_ieee_gouraud_binary64_large` | `profile_ieee_corrected_euler_binary64`, `profile_ieee_corrected_euler_binary64_large`, `profile_ieee_corrected_euler_closed_binary64`, `profile_ieee_corrected_euler_closed_binary64_large` |
//! | `shader` | binary32 | `profile_shader_gouraud_binary32` | `profile_shader_corrected_euler_binary32` |
//!
//! Phong under `ieee` has a *derived* bound ([`phong_ieee`], `docs/float.md` §18.4,
//! tested by `tests/profiles.rs::phong_ieee_derived_binary32`/`_binary64`); [`status`]
//! says which kind a bound is. Other methods have no bound under `ieee` or `shader` yet.
//!
//! Tested, with other implementations written from the definitions (other orders,
//! `mul_add`, reciprocals, the closed form, a software GPU that truncates, divides
//! within 2.5 ulp and flushes denormals), in `tests/profiles.rs`.

use std::fmt;
use std::str::FromStr;

/// An arithmetic profile (`docs/float.md` §18.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Profile {
    /// This crate's own `f32`/`f64` code: its operation order, round to nearest
    /// even, no fused multiply-add (the bounds of [`crate::tolerance::bound`]).
    Reference,
    /// IEEE binary32/binary64 with round to nearest, but any order of each dot
    /// product and of `p_n`'s three-term sum, fused multiply-add anywhere, and a
    /// division by `n` or 2 through a reciprocal.
    Ieee,
    /// The Vulkan/WGSL precision rules for 32-bit floats: add, sub and mul rounded in
    /// any direction (nearest or toward zero), division within 2.5 ulp, denormal
    /// inputs and results flushed to zero, reassociation and fusion as in `Ieee`.
    Shader,
}

impl Profile {
    /// Every profile, in the order of the docs.
    pub const ALL: [Profile; 3] = [Profile::Reference, Profile::Ieee, Profile::Shader];

    /// The profile's name as `--profile` takes it.
    pub fn name(self) -> &'static str {
        match self {
            Profile::Reference => "reference",
            Profile::Ieee => "ieee",
            Profile::Shader => "shader",
        }
    }
}

impl fmt::Display for Profile {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Profile {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        Profile::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| {
                format!(
                    "unknown profile '{}' (expected reference, ieee or shader)",
                    crate::conformance::shown(s)
                )
            })
    }
}

/// A bound `(α·n + β)·u` proved for a class of implementations, with the largest `n`
/// it is proved for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Proved {
    /// `α`.
    pub alpha: f64,
    /// `β`.
    pub beta: f64,
    /// The largest `n` of the theorem.
    pub max_n: u32,
    /// The theorem's name in `proofs/Profiles.v`.
    pub theorem: &'static str,
}

impl Proved {
    /// The bound at `n` for unit roundoff `u`, or `None` past the proved range.
    pub fn at(&self, n: u32, u: f64) -> Option<f64> {
        (n >= 1 && n <= self.max_n).then(|| (self.alpha * f64::from(n) + self.beta) * u)
    }
}

/// binary32's unit roundoff.
const U32: f64 = 1.0 / 16_777_216.0;

/// The proved bounds of a profile for Gouraud (`g += dp`) and corrected Euler (the
/// recurrence `p += t; t += ds`, and its closed form `p_a + i·(t_0 + (i−1)/2·ds)`),
/// in the format of unit roundoff `u`; the largest of the forms a profile allows, so
/// that every form passes. `None` for a method, profile or format with no theorem.
pub fn proved(method: crate::Method, profile: Profile, u: f64) -> Option<Vec<Proved>> {
    use crate::Method;
    let b32 = u == U32;
    let b64 = u == f64::EPSILON / 2.0;
    let p = |alpha, beta, max_n, theorem| Proved {
        alpha,
        beta,
        max_n,
        theorem,
    };
    match (method, profile) {
        (Method::Gouraud, Profile::Ieee) if b32 => Some(vec![p(
            1.0006,
            11.001,
            4096,
            "profile_ieee_gouraud_binary32",
        )]),
        (Method::Gouraud, Profile::Ieee) if b64 => Some(vec![p(
            1.0006,
            11.001,
            1 << 24,
            "profile_ieee_gouraud_binary64_large",
        )]),
        (Method::Gouraud, Profile::Shader) if b32 => Some(vec![p(
            2.0012,
            24.002,
            4096,
            "profile_shader_gouraud_binary32",
        )]),
        (Method::CorrectedEuler, Profile::Ieee) if b32 => Some(vec![
            p(2.2, 51.21, 4096, "profile_ieee_corrected_euler_binary32"),
            p(
                0.0,
                59.61,
                4096,
                "profile_ieee_corrected_euler_closed_binary32",
            ),
        ]),
        (Method::CorrectedEuler, Profile::Ieee) if b64 => Some(vec![
            p(
                2.2,
                51.21,
                1 << 24,
                "profile_ieee_corrected_euler_binary64_large",
            ),
            p(
                0.0,
                59.61,
                1 << 24,
                "profile_ieee_corrected_euler_closed_binary64_large",
            ),
        ]),
        (Method::CorrectedEuler, Profile::Shader) if b32 => Some(vec![p(
            4.4,
            109.7,
            4096,
            "profile_shader_corrected_euler_binary32",
        )]),
        _ => None,
    }
}

/// The proved bound of `method` under `profile` at `n` in the format of unit
/// roundoff `u`: the largest over the forms the profile allows (the recurrence and,
/// for corrected Euler under `ieee`, the closed form), or `None` where no theorem
/// covers it.
pub fn proved_bound(method: crate::Method, profile: Profile, n: u32, u: f64) -> Option<f64> {
    let forms = proved(method, profile, u)?;
    forms
        .iter()
        .map(|f| f.at(n, u))
        .try_fold(0.0f64, |m, b| b.map(|b| m.max(b)))
}

/// Phong under `ieee`, derived (`docs/float.md` §18.4; not a Coq theorem): every
/// implementation that computes `p_i = N_i·L` and `q_i = N_i·N_i` from the nearest
/// floats of the inputs by any of the catalogued forms — Horner's `(A·i + B)` and
/// `(C·i + D)·i + E` with `A = k·L`, `C = k·k`, `D = 2k·N_a`, `E = N_a·N_a`,
/// `k = (N_b − N_a)/n` (or `·(1/n)`); the per-pixel normal `N_a + i·k` or
/// `(1 − t)·N_a + t·N_b`, `t = i/n` — in any order of each dot product, fused or
/// not, and then `p/√q`, `p·(1/√q)` or the dot product of `N·(1/√q)` with `L`.
///
/// Every computed product or sum is its exact value with at most 11 (for `p`) and 15
/// (for `q`) factors `(1 + δ)`, `|δ| ≤ u`, on each monomial, so it is off by at most
/// `γ_k` times the sum of the monomials' absolute values: at most `3` for `p`
/// (`(1 + 2t)`, `|N_a| = |N_b| = |L| = 1`) and `9` for `q` (`(1 + 2t)²`). With
/// `e_p = 3γ_11 + η`, `e_q = 9γ_15 + η`, `q̂ ≥ q_min − e_q` and `|p| ≤ √q`:
///
/// `|v̂ − v| ≤ (e_p/√(q_min − e_q) + e_q/(√(q_min − e_q)·(√q_min + √(q_min − e_q))))·(1 + γ_3) + γ_3 + η`,
///
/// the last factor for the square root, the division (or the reciprocal and the
/// product). `None` where `q` may round to half of `q_min` (`e_q ≥ q_min/2`: normals
/// that nearly cancel, where no bound of this form holds) or `n > 2^24` (`i` must be
/// exact).
pub fn phong_ieee(n: u32, q_min: f64, u: f64) -> Option<f64> {
    if !(q_min > 0.0 && q_min.is_finite()) || n == 0 || n > 1 << 24 {
        return None;
    }
    let gamma = |k: f64| k * u / (1.0 - k * u);
    // Underflow: each of the at most 64 roundings of a pixel's computation may be off
    // by half the smallest subnormal instead of relatively.
    let eta = if u == U32 {
        64.0 * 2f64.powi(-150)
    } else {
        64.0 * 2f64.powi(-1074)
    };
    let e_p = 3.0 * gamma(11.0) + eta;
    let e_q = 9.0 * gamma(15.0) + eta;
    if e_q >= q_min / 2.0 {
        return None;
    }
    let lo = (q_min - e_q).sqrt();
    let b = (e_p / lo + e_q / (lo * (q_min.sqrt() + lo))) * (1.0 + gamma(3.0)) + gamma(3.0) + eta;
    // This evaluation in f64 rounds too: a relative 2^-40 more covers it.
    Some(b * (1.0 + 2f64.powi(-40)))
}

/// How a profile's bound for a method is known.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// A Coq theorem of `proofs/Profiles.v` (its name).
    Proved(&'static str),
    /// A written derivation (the `docs/float.md` section), attacked by the searches of
    /// `tests/profiles.rs`.
    Derived(&'static str),
}

/// Whether and how `method` has a bound under `profile` in the format of unit
/// roundoff `u` (`None`: no bound, a case then fails naming that).
pub fn status(method: crate::Method, profile: Profile, u: f64) -> Option<Status> {
    if let Some(forms) = proved(method, profile, u) {
        return Some(Status::Proved(forms[0].theorem));
    }
    match (method, profile) {
        (crate::Method::Phong, Profile::Ieee) if u == U32 || u == f64::EPSILON / 2.0 => {
            Some(Status::Derived("docs/float.md §18.4"))
        }
        _ => None,
    }
}

/// The bound of `method` under `profile` (not `Reference`, whose bounds are
/// [`crate::tolerance::bound`]) on a span of `n` steps and smallest `q_i` `q_min`, in
/// the format of unit roundoff `u`: the proved bound ([`proved_bound`]) or the derived
/// one ([`phong_ieee`]); `None` where neither covers it.
pub fn profile_bound(
    method: crate::Method,
    profile: Profile,
    n: u32,
    q_min: f64,
    u: f64,
) -> Option<f64> {
    match status(method, profile, u)? {
        Status::Proved(_) => proved_bound(method, profile, n, u),
        Status::Derived(_) => match method {
            crate::Method::Phong => phong_ieee(n, q_min, u),
            _ => None,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Method;

    #[test]
    fn names_round_trip() {
        for p in Profile::ALL {
            assert_eq!(p.name().parse::<Profile>(), Ok(p));
        }
        assert!("gpu".parse::<Profile>().is_err());
    }

    #[test]
    fn proved_bounds_are_the_theorems() {
        let u32_ = f64::from(f32::EPSILON) / 2.0;
        let u64_ = f64::EPSILON / 2.0;
        // (1.0006·100 + 11.001)·u
        let g = proved_bound(Method::Gouraud, Profile::Ieee, 100, u32_).unwrap();
        assert!((g / u32_ - 111.061).abs() < 1e-9);
        // Corrected Euler: the larger of the recurrence and the closed form.
        let c = proved_bound(Method::CorrectedEuler, Profile::Ieee, 1, u32_).unwrap();
        assert!((c / u32_ - 59.61).abs() < 1e-9);
        let c = proved_bound(Method::CorrectedEuler, Profile::Ieee, 100, u64_).unwrap();
        assert!((c / u64_ - 271.21).abs() < 1e-9);
        // binary32 stops at 4096; binary64 goes to 2^24; shader is binary32 only.
        assert!(proved_bound(Method::Gouraud, Profile::Ieee, 4097, u32_).is_none());
        assert!(proved_bound(Method::Gouraud, Profile::Ieee, 1 << 24, u64_).is_some());
        assert!(proved_bound(Method::Gouraud, Profile::Shader, 10, u64_).is_none());
        assert!(proved_bound(Method::Phong, Profile::Ieee, 10, u32_).is_none());
        assert!(proved_bound(Method::Gouraud, Profile::Ieee, 0, u32_).is_none());
    }
}
