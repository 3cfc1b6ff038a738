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
    /// Fixed point `Qm.f` as a hardware span unit runs it (`fixed:m.f`): the set-up
    /// (`p_a`, `t_0`, `ds`, or Gouraud's `dp`) computed exactly or far more precisely
    /// and rounded once to `f` fractional bits, then the loop in integer additions,
    /// exact, in registers of `m` integer bits (the sign included) that must not
    /// overflow (`docs/float.md` §14, `proofs/Fixed.v`).
    Fixed {
        /// Integer bits `m`, the sign included.
        int_bits: u32,
        /// Fractional bits `f`.
        frac_bits: u32,
    },
}

impl Profile {
    /// The float profiles, in the order of the docs (fixed point takes its format
    /// as parameters: [`Profile::Fixed`]).
    pub const ALL: [Profile; 3] = [Profile::Reference, Profile::Ieee, Profile::Shader];

    /// The profile's name as `--profile` takes it (`fixed:16.16` for `Q16.16`).
    pub fn name(self) -> String {
        match self {
            Profile::Reference => "reference".into(),
            Profile::Ieee => "ieee".into(),
            Profile::Shader => "shader".into(),
            Profile::Fixed {
                int_bits,
                frac_bits,
            } => format!("fixed:{int_bits}.{frac_bits}"),
        }
    }
}

impl fmt::Display for Profile {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name())
    }
}

impl FromStr for Profile {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        if let Some(q) = s.strip_prefix("fixed:") {
            let bits = q
                .split_once('.')
                .and_then(|(m, f)| Some((m.parse::<u32>().ok()?, f.parse::<u32>().ok()?)))
                .filter(|&(m, f)| (1..=64).contains(&m) && (1..=62).contains(&f) && m + f <= 128);
            return match bits {
                Some((int_bits, frac_bits)) => Ok(Profile::Fixed {
                    int_bits,
                    frac_bits,
                }),
                None => Err(format!(
                    "'{}' is not fixed:M.F with 1 ≤ M ≤ 64 integer bits and 1 ≤ F ≤ 62 fractional bits (e.g. fixed:16.16)",
                    crate::conformance::shown(s)
                )),
            };
        }
        Profile::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| {
                format!(
                    "unknown profile '{}' (expected reference, ieee, shader or fixed:M.F)",
                    crate::conformance::shown(s)
                )
            })
    }
}

/// The bound of `method` (Gouraud or corrected Euler) computed in fixed point
/// `Q int_bits.frac_bits` on a span of `n` steps (`proofs/Fixed.v`: with every set-up
/// value rounded once, `|e| ≤ h = 2^-(f+1)`, pixel `i` is off by at most
/// `h(1 + i + i(i−1)/2)` for corrected Euler and `h(1 + i)` for Gouraud, largest at
/// `i = n`), or `None` for another method, or when the registers may overflow: the
/// values reach `|p_i| ≤ 2.5` for corrected Euler (1 for Gouraud) plus the bound, and
/// the slope `|t_i| ≤ 28/n` (`|dp| ≤ 2/n`) plus `h(1 + n)`, and `m` integer bits hold
/// magnitudes below `2^(m−1)` (`docs/float.md` §14).
pub fn fixed_bound(method: crate::Method, n: u32, int_bits: u32, frac_bits: u32) -> Option<f64> {
    use crate::Method;
    if n == 0 {
        return None;
    }
    let h = 2f64.powi(-(frac_bits as i32) - 1);
    let nf = f64::from(n);
    let (bound, p_max, t_max) = match method {
        Method::CorrectedEuler => (h * (1.0 + nf + nf * (nf - 1.0) / 2.0), 2.5, 28.0 / nf),
        Method::Gouraud => (h * (1.0 + nf), 1.0, 2.0 / nf),
        _ => return None,
    };
    let needed = (p_max + bound).max(t_max + h * (1.0 + nf));
    // The f64 arithmetic above rounds: a relative 2^-40 covers it.
    (needed < 2f64.powi(int_bits as i32 - 1)).then_some(bound * (1.0 + 2f64.powi(-40)))
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
    if let Profile::Fixed { .. } = profile {
        return match method {
            crate::Method::CorrectedEuler => {
                Some(Status::Proved("fixed_point_corrected_euler_error"))
            }
            crate::Method::Gouraud => Some(Status::Proved("fixed_point_gouraud_error")),
            _ => None,
        };
    }
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
    if let Profile::Fixed {
        int_bits,
        frac_bits,
    } = profile
    {
        return fixed_bound(method, n, int_bits, frac_bits);
    }
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
        let q = Profile::Fixed {
            int_bits: 16,
            frac_bits: 16,
        };
        assert_eq!("fixed:16.16".parse::<Profile>(), Ok(q));
        assert_eq!(q.to_string(), "fixed:16.16");
        for bad in [
            "fixed:16",
            "fixed:0.16",
            "fixed:16.0",
            "fixed:a.b",
            "fixed:16.63",
        ] {
            assert!(bad.parse::<Profile>().is_err(), "{bad}");
        }
    }

    #[test]
    fn fixed_bounds_are_the_theorems_and_need_their_registers() {
        // h(1 + n + n(n−1)/2), h = 2^-17: at n = 4, 11·2^-17.
        let b = fixed_bound(Method::CorrectedEuler, 4, 16, 16).unwrap();
        assert!((b / 2f64.powi(-17) - 11.0).abs() < 1e-9);
        let g = fixed_bound(Method::Gouraud, 4, 16, 16).unwrap();
        assert!((g / 2f64.powi(-17) - 5.0).abs() < 1e-9);
        // Q3.f holds corrected Euler's values (|p| ≤ 2.5 < 4) but not its slope at
        // n = 1 (|t| ≤ 28); from n = 12 the slope is below 2.5 too.
        assert!(fixed_bound(Method::CorrectedEuler, 1, 3, 16).is_none());
        assert!(fixed_bound(Method::CorrectedEuler, 1, 6, 16).is_some());
        assert!(fixed_bound(Method::CorrectedEuler, 12, 3, 16).is_some());
        assert!(fixed_bound(Method::Phong, 4, 16, 16).is_none());
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
