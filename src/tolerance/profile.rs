//! Acceptance profiles: what a correct implementation may do, and the bounds that
//! hold for every implementation of that class (`docs/float.md` §18).
//!
//! A profile is a written model of an arithmetic: how each operation may round, in
//! which order sums may be taken, whether products may be fused. Its bounds are
//! proved for the whole class in Coq (`proofs/Profiles.v`, on the model of
//! `proofs/FloatModelK.v`) where this module says *proved*:
//!
//! | profile | format | Gouraud | corrected Euler | Euler |
//! |---|---|---|---|---|
//! | `ieee` | binary32 | `profile_ieee_gouraud_binary32` | `profile_ieee_corrected_euler_binary32`, `profile_ieee_corrected_euler_closed_binary32` | `profile_ieee_euler_binary32`, `profile_ieee_euler_closed_binary32` |
//! | `ieee` | binary64 | `profile_ieee_gouraud_binary64`, `profile_ieee_gouraud_binary64_large` | `profile_ieee_corrected_euler_binary64`, `profile_ieee_corrected_euler_binary64_large`, `profile_ieee_corrected_euler_closed_binary64`, `profile_ieee_corrected_euler_closed_binary64_large` | `profile_ieee_euler_binary64`, `profile_ieee_euler_binary64_large`, `profile_ieee_euler_closed_binary64`, `profile_ieee_euler_closed_binary64_large` |
//! | `shader` | binary32 | `profile_shader_gouraud_recip_binary32`, `profile_shader_gouraud_binary32` | `profile_shader_corrected_euler_recip_binary32`, `profile_shader_corrected_euler_binary32`, `profile_shader_corrected_euler_closed_binary32`, `profile_shader_corrected_euler_closed_recip_binary32`, `profile_shader_corrected_euler_closed_half_binary32`, `profile_shader_corrected_euler_closed_half_recip_binary32` | `profile_shader_euler_recip_binary32`, `profile_shader_euler_binary32`, `profile_shader_euler_closed_binary32`, `profile_shader_euler_closed_recip_binary32`, `profile_shader_euler_closed_half_binary32`, `profile_shader_euler_closed_half_recip_binary32` |
//!
//! (The `shader` theorems named `_recip` take every division — by `n`, by 2, and the
//! closed forms' halving of `i − 1` — as one 2.5-ulp division or as a 2.5-ulp
//! reciprocal then a product, either way at each division; the others one 2.5-ulp
//! division each; the `_half` ones let the closed forms halve `i − 1` in floats. Every
//! corrected-Euler theorem takes the coefficient `n(n−1)/2` of `p_n` exact: [`proved`].)
//!
//! Phong, Duff, symmetric Phong and the adaptive scheme have *derived* bounds under
//! `ieee` and `shader` (written derivations on the same model, [`Arith`]:
//! [`phong_derived`], [`duff_derived`], [`symmetric_phong_derived`], `docs/float.md`
//! §18.4–18.5, attacked by
//! `tests/profiles.rs`; [`euler_derived`] is plain Euler's, which the theorems now
//! replace under both profiles); [`status`] says which kind a bound is. Angular
//! interpolation and the related methods have none: a case then fails naming that.
//!
//! Tested, with other implementations written from the definitions (other orders,
//! `mul_add`, reciprocals, the closed form, a software GPU that truncates, divides
//! within 2.5 ulp and flushes denormals), in `tests/profiles.rs`.

use std::fmt;
use std::str::FromStr;

/// The most fractional bits of `fixed:M.F`: a fixed-point value below 4 (every
/// method's values are) with `F ≤ 51` fractional bits is exact in `f64`, as which
/// `check` reads results, so its verdict is on the exact error.
pub const MAX_FRAC_BITS: u32 = 51;

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
    /// any direction (nearest or toward zero), division within 2.5 ulp, `sqrt` as
    /// `1/inversesqrt`, denormal inputs and results flushed to zero, any order of
    /// each dot product and sum, fused or not. The Coq theorems (Gouraud, corrected
    /// Euler and plain Euler, the recurrences and the closed forms) take every
    /// division — by `n`, by 2, the closed forms' `(i−1)/2` — as one 2.5-ulp division
    /// or a 2.5-ulp reciprocal then a product; corrected Euler's `n(n−1)/2` (in `p_n`)
    /// must be formed exactly (an integer converted, or `n·(n−1)·0.5` with a literal
    /// `0.5`), not by a 2.5-ulp `/2` nor with a computed `1/2`. The derived bounds
    /// (Phong, Duff) cover `·(1/n)` too.
    Shader,
    /// Fixed point `Qm.f` as a hardware span unit runs it (`fixed:m.f`): the set-up
    /// (`p_a`, `t_0`, `ds`, or Gouraud's `dp`) computed exactly and rounded once **to
    /// nearest** at `f ≤` [`MAX_FRAC_BITS`] fractional bits (the theorems' hypothesis
    /// `|e| ≤ 2^-(f+1)`: a truncated set-up, off by up to `2^-f`, is not covered),
    /// then the loop in integer additions,
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

impl Profile {
    /// Checks that the profile is one the bounds take and `check` can judge: a
    /// fixed-point format of 1 to 64 integer bits and 1 to 51 fractional bits (what
    /// `fixed:M.F` parses: results are read as `f64`, which holds a fixed-point value
    /// below 4 exactly only up to 51 fractional bits); the float profiles always are.
    ///
    /// # Errors
    /// A one-line message naming the widths.
    pub fn validate(&self) -> Result<(), String> {
        match *self {
            Profile::Fixed {
                int_bits,
                frac_bits,
            } if !((1..=64).contains(&int_bits) && (1..=MAX_FRAC_BITS).contains(&frac_bits)) => Err(format!(
                "fixed point needs 1 ≤ M ≤ 64 integer bits and 1 ≤ F ≤ {MAX_FRAC_BITS} fractional bits (got M = {int_bits}, F = {frac_bits})"
            )),
            _ => Ok(()),
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
                .filter(|&(m, f)| (1..=64).contains(&m) && (1..=MAX_FRAC_BITS).contains(&f));
            return match bits {
                Some((int_bits, frac_bits)) => Ok(Profile::Fixed {
                    int_bits,
                    frac_bits,
                }),
                None => Err(format!(
                    "'{}' is not fixed:M.F with 1 ≤ M ≤ 64 integer bits and 1 ≤ F ≤ {MAX_FRAC_BITS} fractional bits (e.g. fixed:16.16; results are read as f64, exact up to 51 fractional bits)",
                    crate::error::shown(s)
                )),
            };
        }
        Profile::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| {
                format!(
                    "unknown profile '{}' (expected reference, ieee, shader or fixed:M.F)",
                    crate::error::shown(s)
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
    if n == 0 || !(1..=64).contains(&int_bits) || !(1..=MAX_FRAC_BITS).contains(&frac_bits) {
        return None;
    }
    let h = 2f64.powi(-(frac_bits as i32) - 1);
    let nf = f64::from(n);
    let (bound, p_max, t_max) = match method {
        Method::CorrectedEuler => (h * (1.0 + nf + nf * (nf - 1.0) / 2.0), 2.5, 28.0 / nf),
        Method::Gouraud => (h * (1.0 + nf), 1.0, 2.0 / nf),
        // `Fixed.v` proves only the two above.
        Method::Phong
        | Method::Duff
        | Method::SymmetricPhong
        | Method::Euler
        | Method::Adaptive
        | Method::Angular
        | Method::AngularTable(_)
        | Method::Spherical
        | Method::Binary
        | Method::BishopWeimer => return None,
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

/// The form of a method an implementation declares (`check --form`,
/// `testkit::Suite::form`): the profile's bound then covers that form alone and is
/// the largest of that form's theorems only. A closed form's error does not grow with
/// `n` and a recurrence's does, so the bound `check` applies to an undeclared
/// implementation — the largest over every form — is the recurrence's at large `n`:
/// at `n = 4095` corrected Euler's closed form is judged by `(2.2·n + 51.21)·u =
/// 9060·u` under `ieee`, and by its own theorem's `59.61·u` once declared
/// (`docs/float.md` §18.6). Only Euler and corrected Euler have theorems for both
/// forms ([`Form::applies_to`]); for the other methods only [`Form::Any`] is accepted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Form {
    /// Any form the profile covers: the largest of their bounds (the default).
    #[default]
    Any,
    /// The recurrence, the paper's loop: `p += t; t += ds` (corrected Euler, eqs.
    /// 15–20) or `E += s; s += ds` (Euler, eqs. 12–14).
    Recurrence,
    /// The closed form in `i`, no loop-carried sum: `p_a + i·(t_0 + (i − 1)/2·ds)`
    /// (corrected Euler) or `p_a + i·(di_a + (i − 1)/2·ds)` (Euler).
    Closed,
}

impl Form {
    /// Every form, `Any` first.
    pub const ALL: [Form; 3] = [Form::Any, Form::Recurrence, Form::Closed];

    /// The form's name as `--form` takes it.
    pub fn name(self) -> &'static str {
        match self {
            Form::Any => "any",
            Form::Recurrence => "recurrence",
            Form::Closed => "closed",
        }
    }

    /// Whether a profile's theorems tell `method`'s forms apart: Euler and corrected
    /// Euler, whose recurrences and closed forms each have theorems. A declared form
    /// other than [`Form::Any`] is refused for the other methods.
    pub fn applies_to(method: crate::Method) -> bool {
        use crate::Method;
        match method {
            Method::Euler | Method::CorrectedEuler => true,
            Method::Gouraud
            | Method::Phong
            | Method::Duff
            | Method::SymmetricPhong
            | Method::Adaptive
            | Method::Angular
            | Method::AngularTable(_)
            | Method::Spherical
            | Method::Binary
            | Method::BishopWeimer => false,
        }
    }

    /// Whether a theorem's bound `(α·n + β)·u` is of this form: a closed form's has
    /// `α = 0`, a recurrence's grows with `n`.
    fn covers(self, p: &Proved) -> bool {
        match self {
            Form::Any => true,
            Form::Recurrence => p.alpha > 0.0,
            Form::Closed => p.alpha == 0.0,
        }
    }
}

impl fmt::Display for Form {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A `--form` that is not one of [`Form::ALL`]'s names.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown form {0:?}: expected any, recurrence or closed")]
pub struct UnknownForm(pub String);

impl FromStr for Form {
    type Err = UnknownForm;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Form::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| UnknownForm(s.to_string()))
    }
}

/// The proved bounds of a profile for Gouraud (`g += dp`), corrected Euler (the
/// recurrence `p += t; t += ds`, and its closed form `p_a + i·(t_0 + (i−1)/2·ds)`)
/// and, under `ieee`, plain Euler (eqs. 12–14: the recurrence `E += s; s += ds` from
/// `s_0 = di_a`, and its closed form `p_a + i·(di_a + (i−1)/2·ds)`), in the format of
/// unit roundoff `u`; the largest of the forms a profile allows, so that every form
/// passes. `None` for a method, profile or format with no theorem.
///
/// Plain Euler under `ieee`: `profile_ieee_euler_binary32` and
/// `profile_ieee_euler_closed_binary32` (`n ≤ 4096`), `profile_ieee_euler_binary64_large`
/// and `profile_ieee_euler_closed_binary64_large` (`n ≤ 2^24`; their `n ≤ 4096`
/// instances are `profile_ieee_euler_binary64` and `profile_ieee_euler_closed_binary64`),
/// against the exact plain-Euler run, for every order, fusion and `/n` or `·(1/n)` of
/// the `ieee` profile (its `κ_div = 2 + 2^-20` covers the reciprocal).
///
/// Under `shader` (binary32, `n ≤ 4096`), for each method every form its guarantee
/// promises, the largest applied: the recurrence with every division (by `n`, and
/// `p_a/2`, `p_b/2`) one 2.5-ulp division (`profile_shader_gouraud_binary32`,
/// `profile_shader_corrected_euler_binary32`, `profile_shader_euler_binary32`) or
/// each either that or a 2.5-ulp reciprocal then a product (`κ_div = 7 + 2^-20`:
/// `profile_shader_gouraud_recip_binary32` `(2.0012·n + 28.0014)·u`,
/// `profile_shader_corrected_euler_recip_binary32` `(4.4·n + 124.31)·u`,
/// `profile_shader_euler_recip_binary32` `(11.1·n + 288.11)·u`); the closed forms with
/// `(i−1)/2` exact (`profile_shader_corrected_euler_closed_binary32` `126.5·u`,
/// `profile_shader_corrected_euler_closed_recip_binary32` `141.11·u`,
/// `profile_shader_euler_closed_binary32` `277.9·u`,
/// `profile_shader_euler_closed_recip_binary32` `308.11·u`) or halved in floats —
/// `c = (i−1)/2` then `c·ds`, or `(i−1)·ds` then halved
/// (`profile_shader_corrected_euler_closed_half_binary32` `131.5·u`,
/// `profile_shader_corrected_euler_closed_half_recip_binary32` `148.11·u`,
/// `profile_shader_euler_closed_half_binary32` `281.65·u`,
/// `profile_shader_euler_closed_half_recip_binary32` `313.36·u`, the `_recip` ones
/// with the halving also through a computed `1/2`). So the bound applied is
/// `(2.0012·n + 28.0014)·u` for Gouraud, `max(4.4·n + 124.31, 148.11)·u` for corrected
/// Euler and `max(11.1·n + 288.11, 313.36)·u` for plain Euler. Every theorem takes
/// `n`, `2n` (a float product `2·n` is exact in any rounding) and corrected Euler's
/// `n(n−1)/2` (the coefficient of `ds` in `p_n`) exact: `n(n−1)/2` formed as an
/// integer and converted (exact: `n(n−1) < 2^24`) or as `n·(n−1)·0.5` with a literal
/// `0.5`. Not covered by any theorem: `n(n−1)/2` formed by a 2.5-ulp `/2` or with a
/// computed `1/2`.
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
        // Under `shader` the `_recip` recurrence first: it covers both ways of
        // dividing, so it names the bound ([`status`]); every form is listed, so that
        // [`proved_bound`] takes the largest.
        (Method::Gouraud, Profile::Shader) if b32 => Some(vec![
            p(
                2.0012,
                28.0014,
                4096,
                "profile_shader_gouraud_recip_binary32",
            ),
            p(2.0012, 24.002, 4096, "profile_shader_gouraud_binary32"),
        ]),
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
        (Method::CorrectedEuler, Profile::Shader) if b32 => Some(vec![
            p(
                4.4,
                124.31,
                4096,
                "profile_shader_corrected_euler_recip_binary32",
            ),
            p(4.4, 109.7, 4096, "profile_shader_corrected_euler_binary32"),
            p(
                0.0,
                126.5,
                4096,
                "profile_shader_corrected_euler_closed_binary32",
            ),
            p(
                0.0,
                141.11,
                4096,
                "profile_shader_corrected_euler_closed_recip_binary32",
            ),
            p(
                0.0,
                131.5,
                4096,
                "profile_shader_corrected_euler_closed_half_binary32",
            ),
            p(
                0.0,
                148.11,
                4096,
                "profile_shader_corrected_euler_closed_half_recip_binary32",
            ),
        ]),
        (Method::Euler, Profile::Ieee) if b32 => Some(vec![
            p(5.55, 121.41, 4096, "profile_ieee_euler_binary32"),
            p(0.0, 131.41, 4096, "profile_ieee_euler_closed_binary32"),
        ]),
        (Method::Euler, Profile::Ieee) if b64 => Some(vec![
            p(5.55, 121.41, 1 << 24, "profile_ieee_euler_binary64_large"),
            p(
                0.0,
                131.41,
                1 << 24,
                "profile_ieee_euler_closed_binary64_large",
            ),
        ]),
        (Method::Euler, Profile::Shader) if b32 => Some(vec![
            p(11.1, 288.11, 4096, "profile_shader_euler_recip_binary32"),
            p(11.1, 257.9, 4096, "profile_shader_euler_binary32"),
            p(0.0, 277.9, 4096, "profile_shader_euler_closed_binary32"),
            p(
                0.0,
                308.11,
                4096,
                "profile_shader_euler_closed_recip_binary32",
            ),
            p(
                0.0,
                281.65,
                4096,
                "profile_shader_euler_closed_half_binary32",
            ),
            p(
                0.0,
                313.36,
                4096,
                "profile_shader_euler_closed_half_recip_binary32",
            ),
        ]),
        // The formats and profiles the theorems are not stated for (the reference and
        // fixed-point profiles have bounds of their own).
        (Method::Gouraud | Method::CorrectedEuler | Method::Euler, _) => None,
        // No theorem: a derived bound ([`status`]) or none under these profiles.
        (
            Method::Phong
            | Method::Duff
            | Method::SymmetricPhong
            | Method::Adaptive
            | Method::Angular
            | Method::AngularTable(_)
            | Method::Spherical
            | Method::Binary
            | Method::BishopWeimer,
            _,
        ) => None,
    }
}

/// The proved bound of `method` under `profile` at `n` in the format of unit
/// roundoff `u`: the largest over the forms the profile allows (every theorem
/// [`proved`] lists: the recurrences, the closed forms, and under `shader` the ways
/// of dividing and of halving), or `None` where no theorem covers it.
pub fn proved_bound(method: crate::Method, profile: Profile, n: u32, u: f64) -> Option<f64> {
    proved_bound_in(method, profile, Form::Any, n, u)
}

/// [`proved_bound`] for an implementation of the declared `form`: the largest over
/// that form's theorems only; `None` where the form has none.
pub fn proved_bound_in(
    method: crate::Method,
    profile: Profile,
    form: Form,
    n: u32,
    u: f64,
) -> Option<f64> {
    let forms = proved_in(method, profile, form, u)?;
    forms
        .iter()
        .map(|f| f.at(n, u))
        .try_fold(0.0f64, |m, b| b.map(|b| m.max(b)))
}

/// The theorems of [`proved`] that cover the declared `form` (all of them for
/// [`Form::Any`]); `None` where none does, or where the method's forms are not told
/// apart ([`Form::applies_to`]) and the form is not `Any`.
pub fn proved_in(
    method: crate::Method,
    profile: Profile,
    form: Form,
    u: f64,
) -> Option<Vec<Proved>> {
    if form != Form::Any && !Form::applies_to(method) {
        return None;
    }
    let forms: Vec<Proved> = proved(method, profile, u)?
        .into_iter()
        .filter(|p| form.covers(p))
        .collect();
    (!forms.is_empty()).then_some(forms)
}

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

/// The standard model of `profile` in the format of unit roundoff `u` (binary32 or
/// binary64 for `ieee`, binary32 for `shader`), or `None` (`reference` is one
/// implementation, not a model; fixed point has its own bounds).
pub fn arith(profile: Profile, u: f64) -> Option<Arith> {
    let b32 = u == U32;
    let b64 = u == f64::EPSILON / 2.0;
    match profile {
        Profile::Ieee if b32 || b64 => Some(Arith {
            u,
            input: 1.0,
            add: 1.0,
            mul: 1.0,
            div: 1.0,
            half: 0.0,
            sqrt: 1.0,
            // Half the smallest subnormal.
            eta: if b32 {
                2f64.powi(-150)
            } else {
                2f64.powi(-1075)
            },
        }),
        // Vulkan/WGSL: add, sub, mul faithful (2 units of u), division 2.5 ulp (5),
        // sqrt inherited from 1/inversesqrt (2 ulp = 4, then the division, 5),
        // denormals flushed (2^-126).
        Profile::Shader if b32 => Some(Arith {
            u,
            input: 2.0,
            add: 2.0,
            mul: 2.0,
            div: 5.0,
            half: 7.0,
            sqrt: 9.0,
            eta: 2f64.powi(-126),
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
        && nf * a.u <= super::MAX_NU)
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
/// of [`proved`] cover the same forms (under `shader` with every division, the
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
    let b = super::ratio_bound(e_p, e_q, q_min, a.ratio(), a.u)?;
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
/// `|v̂ − v| ≤ (e_p/√(q_min − e_q) + e_q/(√(q_min − e_q)·(√q_min + √(q_min − e_q))))·(1 + γ_f) + γ_f + η'`,
///
/// `γ_f` for the square root, the division (or the reciprocal and the product).
/// `None` where `q` may round to half of `q_min` (`e_q ≥ q_min/2`: normals that
/// nearly cancel, where no bound of this form holds) or `n > 2^24` (`i` must be
/// exact).
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
    let b = (e_p / lo + e_q / (lo * (q_min.sqrt() + lo))) * (1.0 + g_f) + g_f + eta;
    // This evaluation in f64 rounds too: a relative 2^-40 more covers it.
    Some(b * (1.0 + 2f64.powi(-40)))
}

/// [`phong_derived`] under `ieee` in the format of unit roundoff `u`.
/// `dn ≥ |N_b − N_a|` (2 for any unit normals).
pub fn phong_ieee(n: u32, q_min: f64, dn: f64, u: f64) -> Option<f64> {
    phong_derived(&arith(Profile::Ieee, u)?, n, q_min, dn)
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

impl Status {
    /// `proved (theorem)` or `derived (section)`, as the docs and `span` label a bound.
    pub fn label(&self) -> String {
        match self {
            Status::Proved(t) => format!("proved ({t})"),
            Status::Derived(d) => format!("derived ({d})"),
        }
    }
}

/// The columns of [`status_table`]: the profiles and formats with bounds.
const COLUMNS: [(&str, Profile, f64); 4] = [
    ("ieee, binary32", Profile::Ieee, 1.0 / 16_777_216.0),
    ("ieee, binary64", Profile::Ieee, f64::EPSILON / 2.0),
    ("shader, binary32", Profile::Shader, 1.0 / 16_777_216.0),
    (
        "fixed:M.F",
        Profile::Fixed {
            int_bits: 16,
            frac_bits: 16,
        },
        0.0,
    ),
];

/// How each method's bound is known under each profile, as a Markdown table made from
/// [`status`] (the one source of the labels: docs/conformance.md holds this table,
/// `tests/coverage.rs` checks it is the current one): a row per method with a bound
/// under some profile.
pub fn status_table() -> String {
    let mut s = String::from("| method |");
    for (name, ..) in COLUMNS {
        s += &format!(" {name} |");
    }
    s += "\n|---|";
    s += &"---|".repeat(COLUMNS.len());
    s += "\n";
    for m in crate::Method::ALL {
        let cells: Vec<Option<Status>> = COLUMNS.iter().map(|&(_, p, u)| status(m, p, u)).collect();
        if cells.iter().all(Option::is_none) {
            continue;
        }
        s += &format!("| `{}` |", m.name());
        for c in cells {
            let label = c.map_or("none".to_string(), |c| match c {
                Status::Proved(t) => format!("proved (`{t}`)"),
                Status::Derived(d) => format!("derived ({d})"),
            });
            s += &format!(" {label} |");
        }
        s += "\n";
    }
    s
}

/// A profile's bound for `method` in the format of unit roundoff `u`, in words: the
/// proved forms `(α·n + β)·u` (the largest applies), or the section of the derivation
/// for the derived bounds (which depend on the span's `q_min` too).
pub fn formula(method: crate::Method, profile: Profile, u: f64) -> Option<String> {
    match status(method, profile, u)? {
        Status::Proved(_) => {
            let mut forms: Vec<String> = proved(method, profile, u)?
                .iter()
                .map(|f| {
                    if f.alpha == 0.0 {
                        format!("{}·u", f.beta)
                    } else {
                        format!("({}·n + {})·u", f.alpha, f.beta)
                    }
                })
                .collect();
            forms.dedup();
            Some(if forms.len() == 1 {
                forms.remove(0)
            } else {
                format!("max({})", forms.join(", "))
            })
        }
        Status::Derived(section) => Some(match method {
            crate::Method::Adaptive => "the larger of Gouraud's and corrected Euler's".into(),
            _ => format!("from n and q_min ({section})"),
        }),
    }
}

/// The bounds `check` applies by default — the `ieee` profile's, in binary32 and
/// binary64 — as a Markdown table made from [`formula`], [`profile_bound`] and
/// [`status`] (docs/conformance.md §3 holds it, `tests/coverage.rs` checks it is the
/// current one), with each bound's value in units of `u` on two spans: `n = 8`,
/// `q_min = 1` and `n = 256`, `q_min = 1/4`.
pub fn ieee_table() -> String {
    let spans = [(8u32, 1.0f64), (256, 0.25)];
    let mut s = String::from(
        "| method | `ieee` bound on the error at each pixel | binary32, n = 8, q_min = 1 | binary32, n = 256, q_min = 1/4 | binary64, n = 256, q_min = 1/4 | status (binary32) |\n|---|---|---|---|---|---|\n",
    );
    let (u32_, u64_) = (U32, f64::EPSILON / 2.0);
    for m in crate::Method::ALL {
        let Some(f) = formula(m, Profile::Ieee, u32_) else {
            continue;
        };
        let at = |n: u32, q: f64, u: f64| {
            profile_bound(m, Profile::Ieee, n, q, u).map_or("none".to_string(), |b| {
                // In units of u, rounded up to 4 significant digits.
                let x = b / u;
                let d = (3 - x.log10().floor() as i32).max(0) as usize;
                let e = 10f64.powi(-(d as i32));
                format!("{:.d$}·u", (x / e).ceil() * e)
            })
        };
        let label = status(m, Profile::Ieee, u32_).map_or(String::new(), |st| match st {
            Status::Proved(t) => format!("proved (`{t}`)"),
            Status::Derived(d) => format!("derived ({d})"),
        });
        s += &format!(
            "| `{}` | {f} | {} | {} | {} | {label} |\n",
            m.name(),
            at(spans[0].0, spans[0].1, u32_),
            at(spans[1].0, spans[1].1, u32_),
            at(spans[1].0, spans[1].1, u64_),
        );
    }
    s
}

/// One line per profile naming the methods whose bound is proved and those whose
/// bound is derived (the `--profile` help of `check`, from [`status`]).
pub fn status_summary() -> String {
    let mut parts = Vec::new();
    for (name, p, u) in COLUMNS {
        let (mut proved, mut derived) = (Vec::new(), Vec::new());
        for m in crate::Method::ALL {
            match status(m, p, u) {
                Some(Status::Proved(_)) => proved.push(m.name().into_owned()),
                Some(Status::Derived(_)) => derived.push(m.name().into_owned()),
                None => {}
            }
        }
        let mut line = format!("{name}: proved for {}", list(&proved));
        if !derived.is_empty() {
            line += &format!(", derived for {}", list(&derived));
        }
        parts.push(line);
    }
    parts.join("; ")
}

fn list(names: &[String]) -> String {
    if names.is_empty() {
        "none".into()
    } else {
        names.join(", ")
    }
}

/// Whether and how `method` has a bound under `profile` in the format of unit
/// roundoff `u` (`None`: no bound, a case then fails naming that).
///
/// This is the table of the profiles' bounds, one row per method: a method without a
/// row here has no bound under `ieee`, `shader` or fixed point (angular
/// interpolation, whose `acos` and `cos` no profile bounds, and the related methods,
/// whose bounds follow this crate's own evaluation).
pub fn status(method: crate::Method, profile: Profile, u: f64) -> Option<Status> {
    use crate::Method;
    let fixed = matches!(profile, Profile::Fixed { .. });
    // A float profile's theorems ([`proved`]), the first form's name.
    let theorem = || proved(method, profile, u).map(|forms| Status::Proved(forms[0].theorem));
    // A derivation, where the profile has a standard model in this format.
    let derived = |section| arith(profile, u).map(|_| Status::Derived(section));
    // One row per method, no wildcard: a new method does not compile until its row
    // says what it has under fixed point and under `ieee` and `shader`.
    match (method, fixed) {
        (Method::Gouraud, true) => Some(Status::Proved("fixed_point_gouraud_error")),
        (Method::CorrectedEuler, true) => Some(Status::Proved("fixed_point_corrected_euler_error")),
        (Method::Gouraud | Method::CorrectedEuler | Method::Euler, false) => theorem(),
        (Method::Phong, false) => derived("docs/float.md §18.4"),
        (Method::Duff | Method::SymmetricPhong, false) => derived("docs/float.md §18.5"),
        // The larger of the two proved bounds, against the exact run of the method
        // the implementation chose (docs/float.md §10, §18.5).
        (Method::Adaptive, false) => proved(Method::Gouraud, profile, u)
            .and(proved(Method::CorrectedEuler, profile, u))
            .and_then(|_| derived("docs/float.md §18.5")),
        // Fixed point: the theorems of `Fixed.v` cover Gouraud and corrected Euler.
        (
            Method::Euler
            | Method::Phong
            | Method::Duff
            | Method::SymmetricPhong
            | Method::Adaptive,
            true,
        ) => None,
        // No profile bounds `acos` and `cos` (docs/float.md §18.5, "Not covered").
        (Method::Angular | Method::AngularTable(_), _) => None,
        // Their bounds follow this crate's own evaluation (docs/float.md §16).
        (Method::Spherical | Method::Binary | Method::BishopWeimer, _) => None,
    }
}

/// The bound of `method` under `profile` (not `Reference`, whose bounds are
/// [`crate::tolerance::bound`]) on a span of `n` steps and smallest `q_i` `q_min`, in
/// the format of unit roundoff `u`: the proved bound ([`proved_bound`]) or the derived
/// one ([`phong_derived`], [`duff_derived`]); `None` where neither covers it. For any
/// unit normals; [`profile_span_bound`] reads more of a known span.
pub fn profile_bound(
    method: crate::Method,
    profile: Profile,
    n: u32,
    q_min: f64,
    u: f64,
) -> Option<f64> {
    bound_with(method, profile, Form::Any, n, q_min, 2.0, u)
}

/// [`profile_bound`] for a known span: Phong's derived bound with the span's own
/// `|N_b − N_a|` ([`crate::tolerance::Shape::dn`]; up to 3× tighter on the close
/// normals of a mesh, [`phong_derived`]).
/// With a declared `form` ([`Form`]), the bound of that form alone: `None` where the
/// form has no theorem (Gouraud's closed form, a fixed-point closed form) or the
/// method's forms are not told apart.
pub fn profile_span_bound(
    method: crate::Method,
    profile: Profile,
    form: Form,
    shape: &crate::tolerance::Shape,
    u: f64,
) -> Option<f64> {
    if form != Form::Any && !Form::applies_to(method) {
        return None;
    }
    bound_with(method, profile, form, shape.n, shape.q_min, shape.dn, u)
}

fn bound_with(
    method: crate::Method,
    profile: Profile,
    form: Form,
    n: u32,
    q_min: f64,
    dn: f64,
    u: f64,
) -> Option<f64> {
    use crate::Method;
    if let Profile::Fixed {
        int_bits,
        frac_bits,
    } = profile
    {
        // `Fixed.v` proves the loops: an exact integer recurrence.
        return (form != Form::Closed)
            .then(|| fixed_bound(method, n, int_bits, frac_bits))
            .flatten();
    }
    match status(method, profile, u)? {
        Status::Proved(_) => proved_bound_in(method, profile, form, n, u),
        Status::Derived(_) => {
            let a = arith(profile, u)?;
            match method {
                Method::Phong => phong_derived(&a, n, q_min, dn),
                Method::Duff => duff_derived(&a, n, q_min),
                Method::SymmetricPhong => symmetric_phong_derived(&a, n, q_min),
                Method::Adaptive => Some(
                    proved_bound(Method::Gouraud, profile, n, u)?.max(proved_bound(
                        Method::CorrectedEuler,
                        profile,
                        n,
                        u,
                    )?),
                ),
                // Proved, not derived ([`status`]), or no bound under a profile.
                Method::Gouraud
                | Method::CorrectedEuler
                | Method::Euler
                | Method::Angular
                | Method::AngularTable(_)
                | Method::Spherical
                | Method::Binary
                | Method::BishopWeimer => None,
            }
        }
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
            "fixed:3.60",
            "fixed:8.54",
            "fixed:1.52",
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

    #[test]
    fn euler_is_proved_under_ieee() {
        let u32_ = f64::from(f32::EPSILON) / 2.0;
        let u64_ = f64::EPSILON / 2.0;
        // The larger of the recurrence (5.55·n + 121.41) and the closed form (131.41).
        let e = proved_bound(Method::Euler, Profile::Ieee, 1, u32_).unwrap();
        assert!((e / u32_ - 131.41).abs() < 1e-9);
        let e = proved_bound(Method::Euler, Profile::Ieee, 2, u32_).unwrap();
        assert!((e / u32_ - 132.51).abs() < 1e-9);
        let e = proved_bound(Method::Euler, Profile::Ieee, 100, u64_).unwrap();
        assert!((e / u64_ - 676.41).abs() < 1e-9);
        assert!(proved_bound(Method::Euler, Profile::Ieee, 4097, u32_).is_none());
        assert!(proved_bound(Method::Euler, Profile::Ieee, 1 << 24, u64_).is_some());
        assert!(proved_bound(Method::Euler, Profile::Ieee, (1 << 24) + 1, u64_).is_none());
        assert_eq!(
            status(Method::Euler, Profile::Ieee, u32_),
            Some(Status::Proved("profile_ieee_euler_binary32"))
        );
        assert_eq!(
            status(Method::Euler, Profile::Ieee, u64_),
            Some(Status::Proved("profile_ieee_euler_binary64_large"))
        );
        // `check` applies exactly the theorems' bound, and it is below the derivation
        // it replaces wherever both exist.
        for (u, ns) in [
            (u32_, vec![1, 2, 3, 255, 256, 4095, 4096]),
            (u64_, vec![1, 2, 4096, 4097, 1 << 20, 1 << 24]),
        ] {
            let a = arith(Profile::Ieee, u).unwrap();
            for n in ns {
                let p = proved_bound(Method::Euler, Profile::Ieee, n, u).unwrap();
                assert_eq!(
                    profile_bound(Method::Euler, Profile::Ieee, n, 1.0, u),
                    Some(p)
                );
                assert!(p < euler_derived(&a, n).unwrap(), "{n}");
            }
        }
    }

    #[test]
    fn shader_bounds_are_the_largest_of_every_form() {
        let u32_ = f64::from(f32::EPSILON) / 2.0;
        // Every shader theorem of each method, the `_recip` recurrence first.
        let theorems: [(Method, &[&str]); 3] = [
            (
                Method::Gouraud,
                &[
                    "profile_shader_gouraud_recip_binary32",
                    "profile_shader_gouraud_binary32",
                ],
            ),
            (
                Method::CorrectedEuler,
                &[
                    "profile_shader_corrected_euler_recip_binary32",
                    "profile_shader_corrected_euler_binary32",
                    "profile_shader_corrected_euler_closed_binary32",
                    "profile_shader_corrected_euler_closed_recip_binary32",
                    "profile_shader_corrected_euler_closed_half_binary32",
                    "profile_shader_corrected_euler_closed_half_recip_binary32",
                ],
            ),
            (
                Method::Euler,
                &[
                    "profile_shader_euler_recip_binary32",
                    "profile_shader_euler_binary32",
                    "profile_shader_euler_closed_binary32",
                    "profile_shader_euler_closed_recip_binary32",
                    "profile_shader_euler_closed_half_binary32",
                    "profile_shader_euler_closed_half_recip_binary32",
                ],
            ),
        ];
        for (m, names) in theorems {
            let forms = proved(m, Profile::Shader, u32_).unwrap();
            let got: Vec<&str> = forms.iter().map(|f| f.theorem).collect();
            assert_eq!(got, names, "{m}");
            assert_eq!(
                status(m, Profile::Shader, u32_),
                Some(Status::Proved(names[0])),
                "{m}"
            );
            // The bound applied is never below any form's theorem, and is one of them.
            for n in 1..=4096 {
                let b = profile_bound(m, Profile::Shader, n, 1.0, u32_).unwrap();
                assert_eq!(Some(b), proved_bound(m, Profile::Shader, n, u32_));
                let each: Vec<f64> = forms.iter().map(|f| f.at(n, u32_).unwrap()).collect();
                assert!(each.iter().all(|&x| x <= b), "{m} {n}");
                assert!(each.contains(&b), "{m} {n}");
            }
            assert!(profile_bound(m, Profile::Shader, 4097, 1.0, u32_).is_none());
            assert!(proved(m, Profile::Shader, f64::EPSILON / 2.0).is_none());
        }
        let at = |m, n| proved_bound(m, Profile::Shader, n, u32_).unwrap() / u32_;
        // Gouraud: the `_recip` recurrence, (2.0012·n + 28.0014)·u.
        assert!((at(Method::Gouraud, 1) - 30.0026).abs() < 1e-9);
        assert!((at(Method::Gouraud, 100) - 228.1214).abs() < 1e-9);
        // Corrected Euler: the halved closed form through reciprocals (148.11) up to
        // n = 5, then the `_recip` recurrence (4.4·n + 124.31).
        assert!((at(Method::CorrectedEuler, 1) - 148.11).abs() < 1e-9);
        assert!((at(Method::CorrectedEuler, 5) - 148.11).abs() < 1e-9);
        assert!((at(Method::CorrectedEuler, 6) - 150.71).abs() < 1e-9);
        assert!((at(Method::CorrectedEuler, 100) - 564.31).abs() < 1e-9);
        // Plain Euler: 313.36 up to n = 2, then (11.1·n + 288.11).
        assert!((at(Method::Euler, 1) - 313.36).abs() < 1e-9);
        assert!((at(Method::Euler, 2) - 313.36).abs() < 1e-9);
        assert!((at(Method::Euler, 3) - 321.41).abs() < 1e-9);
        assert!((at(Method::Euler, 100) - 1398.11).abs() < 1e-9);
        // The derivation plain Euler's theorems replace is larger at every n.
        let a = arith(Profile::Shader, u32_).unwrap();
        for n in 1..=4096 {
            let p = proved_bound(Method::Euler, Profile::Shader, n, u32_).unwrap();
            assert!(p < euler_derived(&a, n).unwrap(), "{n}");
        }
        // The adaptive scheme takes the larger of Gouraud's and corrected Euler's.
        assert_eq!(
            profile_bound(Method::Adaptive, Profile::Shader, 1, 1.0, u32_),
            Some(148.11 * u32_)
        );
    }

    /// A declared form takes that form's theorems alone: corrected Euler's closed form
    /// at `n = 4095` under `ieee` binary32 is `59.61·u`, its recurrence
    /// `(2.2·4095 + 51.21)·u`, undeclared the larger; only Euler and corrected Euler
    /// tell their forms apart; fixed point proves the loop only.
    #[test]
    fn a_declared_form_takes_its_own_theorems() {
        let u32_ = U32;
        let ce = |form| proved_bound_in(Method::CorrectedEuler, Profile::Ieee, form, 4095, u32_);
        assert_eq!(ce(Form::Closed), Some(59.61 * u32_));
        assert_eq!(ce(Form::Recurrence), Some((2.2 * 4095.0 + 51.21) * u32_));
        assert_eq!(ce(Form::Any), ce(Form::Recurrence));
        // At n = 1 the closed form's constant is the larger: undeclared takes it.
        let ce1 = |form| proved_bound_in(Method::CorrectedEuler, Profile::Ieee, form, 1, u32_);
        assert_eq!(ce1(Form::Any), Some(59.61 * u32_));
        assert_eq!(ce1(Form::Recurrence), Some((2.2 + 51.21) * u32_));
        // Under shader the closed forms' four theorems, the largest.
        let sh = proved_bound_in(Method::Euler, Profile::Shader, Form::Closed, 4095, u32_);
        assert_eq!(sh, Some(313.36 * u32_));
        for m in Method::ALL {
            assert_eq!(
                Form::applies_to(m),
                matches!(m, Method::Euler | Method::CorrectedEuler),
                "{m}"
            );
            if !Form::applies_to(m) {
                for form in [Form::Recurrence, Form::Closed] {
                    assert!(
                        proved_in(m, Profile::Ieee, form, u32_).is_none(),
                        "{m} {form}"
                    );
                }
            }
        }
        use crate::reference::unit::unit_from_ints;
        let span = crate::Span::new(
            unit_from_ints(0, 0, 1),
            unit_from_ints(1, 0, 3),
            unit_from_ints(0, 0, 1),
            8,
        )
        .unwrap();
        let shape = crate::tolerance::Shape::of(&span);
        let fixed = Profile::Fixed {
            int_bits: 16,
            frac_bits: 16,
        };
        let b = |form| profile_span_bound(Method::CorrectedEuler, fixed, form, &shape, u32_);
        assert!(b(Form::Any).is_some());
        assert_eq!(b(Form::Recurrence), b(Form::Any));
        assert_eq!(b(Form::Closed), None);
        assert_eq!(
            profile_span_bound(Method::Phong, Profile::Ieee, Form::Closed, &shape, u32_),
            None
        );
        for form in Form::ALL {
            assert_eq!(form.name().parse::<Form>(), Ok(form));
        }
        assert!("horner".parse::<Form>().is_err());
    }
}
