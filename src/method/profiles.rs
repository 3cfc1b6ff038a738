//! The catalogue's columns for the bounds beyond the `reference` profile: how each
//! method is bounded under `ieee` and `shader` and in fixed point, and which theorems
//! prove its `reference` bound — as data in its row ([`super::Info::profiles`]), so
//! that a new method does not compile until its row says what it has under every
//! profile. `tolerance::profile` evaluates these rows; its theorem table holds the
//! proved constants.

/// How a method is bounded beyond the `reference` profile's derivation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfileBounds {
    /// The Coq theorems of its `reference` bound in binary32 and binary64
    /// (`proofs/Float.v`, `n ≤ 4096`), or `None` where that bound is derived only.
    pub reference: Option<[&'static str; 2]>,
    /// Under the float profiles, `ieee` and `shader`.
    pub float: FloatBound,
    /// Under fixed point (`fixed:M.F`).
    pub fixed: FixedBound,
    /// The names of the method's operation graphs — the forms `tolerance::graphs`
    /// writes, in its order —, whose per-pixel bound (`proofs/Graph.v`,
    /// `graph_sound`) `check` applies under `ieee` and `shader` where it is below the
    /// theorems' and whose labels name them; empty where it has none (the adaptive
    /// scheme is judged by its picks; angular interpolation and the related methods
    /// have none).
    pub graphs: &'static [&'static str],
}

/// A method's bound under `ieee` and `shader`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FloatBound {
    /// Coq theorems of `proofs/Profiles.v`, per profile, format and form (the
    /// largest applies: `tolerance::profile::proved`).
    Proved(&'static [Proved]),
    /// Coq theorems of the computed `p` and `q` (`proofs/DuffCount.v`) composed with
    /// the value step `p/√q` (`proofs/PhongValue.v`), evaluated on the profile's
    /// standard model (`tolerance::profile::duff_bound`, `symmetric_phong_bound`).
    Composed {
        /// The theorems: the counts with `/n` as a division, through `·(1/n)`, and the
        /// value step.
        theorems: &'static [&'static str],
        /// The section that composes them (`docs/float.md §18.5`).
        section: &'static str,
        /// Its form: [`DerivedForm::Ratio`] or [`DerivedForm::HalfRatio`].
        form: DerivedForm,
    },
    /// Per pixel from the method's operation graphs alone (`proofs/Graph.v`,
    /// `graph_sound`, on the case's own inputs), the value's last step composed by a
    /// theorem: no formula in `n` and `q_min`, so a case the graphs do not bound (a
    /// span past `tolerance::graphs::MAX_GRAPH_STEPS`, a divisor that may vanish) has
    /// no bound.
    Graphs {
        /// The composing theorem (`sq_signed_value_error`).
        theorem: &'static str,
        /// The theorem of the root's rounding where a profile takes a square root as
        /// `1/inverseSqrt` (`shader`: `sq_shader_root_rounding`).
        shader_root: &'static str,
        /// The section that derives the composition (`docs/float.md §19.7`).
        section: &'static str,
    },
    /// No bound: why.
    None(&'static str),
}

/// The form of a derived or composed profile bound (`docs/float.md` §18.4–18.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DerivedForm {
    /// The normal interpolated and normalized per pixel (`phong_bound`).
    PerPixel,
    /// `p/√q` of two recurrences (`duff_bound`).
    Ratio,
    /// `p/√q` with `q`'s square root walked from both ends
    /// (`symmetric_phong_bound`).
    HalfRatio,
    /// The larger of the proved bounds of the methods it picks between
    /// ([`super::Info::picks`]).
    LargerOfPicks,
}

/// A method's bound in fixed point (`proofs/Fixed.v`, `docs/float.md` §14): the set-up
/// rounded once to nearest, then an exact integer recurrence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FixedBound {
    /// Proved: pixel `i` is off by at most `h(1 + i)` (a first-order recurrence) or
    /// `h(1 + i + i(i−1)/2)` (second order), `h = 2^-(f+1)`.
    Proved {
        /// The theorem.
        theorem: &'static str,
        /// Whether the recurrence is of second order (a slope stepped too).
        second_order: bool,
        /// The largest `|value|` on exact unit inputs.
        value_max: f64,
        /// The largest `|slope|` times `n`.
        slope_times_n: f64,
    },
    /// Duff's unit (`proofs/Fixed.v`): `p` and `q` by the loops above, then a
    /// square root and a divider each truncated to within one unit of the last place;
    /// the bound needs the span's `q_min` (`tolerance::profile::fixed_bound`).
    Ratio {
        /// The theorem.
        theorem: &'static str,
    },
    /// The adaptive choice (`proofs/Fixed.v`): eq. 24's test in exact integers on
    /// the rounded set-up, then the loop of the method it picks, judged by that
    /// method's bound; either pick passes where the rounded `δ` may fall on either side.
    Picks {
        /// The theorem of the choice.
        theorem: &'static str,
    },
    /// No theorem: why.
    None(&'static str),
}

impl FixedBound {
    /// The theorem, where one bounds the method.
    pub fn theorem(&self) -> Option<&'static str> {
        match *self {
            FixedBound::Proved { theorem, .. }
            | FixedBound::Ratio { theorem }
            | FixedBound::Picks { theorem } => Some(theorem),
            FixedBound::None(_) => None,
        }
    }
}

/// A bound `(α·n + β)·u` proved for a class of implementations (a float profile, a
/// format, one form of the method), with the largest `n` it is proved for: the
/// statement of a theorem of `proofs/Profiles.v` (`tests/claims_index.rs` reads the
/// statements and fails when a constant here differs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Proved {
    /// The profile: [`Profile::Ieee`] or [`Profile::Shader`].
    pub profile: Profile,
    /// The format.
    pub format: crate::Format,
    /// `α`.
    pub alpha: f64,
    /// `β`.
    pub beta: f64,
    /// The largest `n` of the theorem.
    pub max_n: u32,
    /// The theorem's name in `proofs/Profiles.v`.
    pub theorem: &'static str,
    /// Whether the theorem is of the closed form in `i` (no loop-carried sum; its
    /// bound does not grow with `n`), not of the recurrence: what a declared form
    /// (`check --form`) selects.
    pub closed: bool,
}

impl Proved {
    /// The bound at `n` in `format` (`(α·n + β)·u`), or `None` past the proved range.
    pub fn at(&self, n: u32, format: crate::Format) -> Option<f64> {
        (n >= 1 && n <= self.max_n).then(|| (self.alpha * f64::from(n) + self.beta) * format.u())
    }
}

const fn p(
    profile: Profile,
    format: crate::Format,
    (alpha, beta): (f64, f64),
    max_n: u32,
    theorem: &'static str,
) -> Proved {
    Proved {
        profile,
        format,
        alpha,
        beta,
        max_n,
        theorem,
        closed: false,
    }
}

/// [`p`] for a theorem of the closed form.
const fn closed(
    profile: Profile,
    format: crate::Format,
    constants: (f64, f64),
    max_n: u32,
    theorem: &'static str,
) -> Proved {
    Proved {
        closed: true,
        ..p(profile, format, constants, max_n, theorem)
    }
}

use crate::profile::Profile;
use crate::Format::{Binary32 as B32, Binary64 as B64};
use Profile::{Ieee, Shader};

/// Gouraud's (`g += dp`): under `shader` the `_recip` recurrence first — it covers both ways of dividing, so it names the bound.
pub const GOURAUD_THEOREMS: &[Proved] = &[
    p(
        Ieee,
        B32,
        (1.0006, 11.001),
        4096,
        "profile_ieee_gouraud_binary32",
    ),
    p(
        Ieee,
        B64,
        (1.0006, 11.001),
        1 << 24,
        "profile_ieee_gouraud_binary64_large",
    ),
    p(
        Shader,
        B32,
        (2.0012, 28.0014),
        4096,
        "profile_shader_gouraud_recip_binary32",
    ),
    p(
        Shader,
        B32,
        (2.0012, 24.002),
        4096,
        "profile_shader_gouraud_binary32",
    ),
];

/// Corrected Euler's: the recurrence `p += t; t += ds` and its closed form `p_a + i·(t_0 + (i−1)/2·ds)`; under `shader` each with `/n` or `·(1/n)`, and the closed forms with `(i−1)/2` exact or halved in floats (`_half`).
pub const CORRECTED_EULER_THEOREMS: &[Proved] = &[
    p(
        Ieee,
        B32,
        (2.2, 51.21),
        4096,
        "profile_ieee_corrected_euler_binary32",
    ),
    closed(
        Ieee,
        B32,
        (0.0, 59.61),
        4096,
        "profile_ieee_corrected_euler_closed_binary32",
    ),
    p(
        Ieee,
        B64,
        (2.2, 51.21),
        1 << 24,
        "profile_ieee_corrected_euler_binary64_large",
    ),
    closed(
        Ieee,
        B64,
        (0.0, 59.61),
        1 << 24,
        "profile_ieee_corrected_euler_closed_binary64_large",
    ),
    p(
        Shader,
        B32,
        (4.4, 124.31),
        4096,
        "profile_shader_corrected_euler_recip_binary32",
    ),
    p(
        Shader,
        B32,
        (4.4, 109.7),
        4096,
        "profile_shader_corrected_euler_binary32",
    ),
    closed(
        Shader,
        B32,
        (0.0, 126.5),
        4096,
        "profile_shader_corrected_euler_closed_binary32",
    ),
    closed(
        Shader,
        B32,
        (0.0, 141.11),
        4096,
        "profile_shader_corrected_euler_closed_recip_binary32",
    ),
    closed(
        Shader,
        B32,
        (0.0, 131.5),
        4096,
        "profile_shader_corrected_euler_closed_half_binary32",
    ),
    closed(
        Shader,
        B32,
        (0.0, 148.11),
        4096,
        "profile_shader_corrected_euler_closed_half_recip_binary32",
    ),
];

/// Plain Euler's (eqs. 12–14): the recurrence `E += s; s += ds` from `s_0 = di_a` and its closed form `p_a + i·(di_a + (i−1)/2·ds)`, against the exact plain-Euler run; under `shader` as corrected Euler's.
pub const EULER_THEOREMS: &[Proved] = &[
    p(
        Ieee,
        B32,
        (5.55, 121.41),
        4096,
        "profile_ieee_euler_binary32",
    ),
    closed(
        Ieee,
        B32,
        (0.0, 131.41),
        4096,
        "profile_ieee_euler_closed_binary32",
    ),
    p(
        Ieee,
        B64,
        (5.55, 121.41),
        1 << 24,
        "profile_ieee_euler_binary64_large",
    ),
    closed(
        Ieee,
        B64,
        (0.0, 131.41),
        1 << 24,
        "profile_ieee_euler_closed_binary64_large",
    ),
    p(
        Shader,
        B32,
        (11.1, 288.11),
        4096,
        "profile_shader_euler_recip_binary32",
    ),
    p(
        Shader,
        B32,
        (11.1, 257.9),
        4096,
        "profile_shader_euler_binary32",
    ),
    closed(
        Shader,
        B32,
        (0.0, 277.9),
        4096,
        "profile_shader_euler_closed_binary32",
    ),
    closed(
        Shader,
        B32,
        (0.0, 308.11),
        4096,
        "profile_shader_euler_closed_recip_binary32",
    ),
    closed(
        Shader,
        B32,
        (0.0, 281.65),
        4096,
        "profile_shader_euler_closed_half_binary32",
    ),
    closed(
        Shader,
        B32,
        (0.0, 313.36),
        4096,
        "profile_shader_euler_closed_half_recip_binary32",
    ),
];

/// The theorems Duff's `ieee` and `shader` bounds rest on (`proofs/DuffCount.v`,
/// `proofs/PhongValue.v`): the counts either way of `/n`, the value step.
pub const DUFF_THEOREMS: &[&str] = &[
    "duff_div_generic",
    "duff_recip_generic",
    "phong_value_either",
];

/// The theorems Phong's `ieee` and `shader` bounds rest on (`proofs/PhongCountD.v`,
/// `proofs/PhongCount.v`, `proofs/PhongValue.v`, `proofs/PhongNormalize.v`): the
/// counts of each form with the span's `|N_b − N_a|` and for any unit normals, either
/// way of `/n`, the value step, normalize-then-dot.
pub const PHONG_THEOREMS: &[&str] = &[
    "phong_horner_div_dist",
    "phong_horner_recip_dist",
    "phong_pixel_div_dist",
    "phong_pixel_recip_dist",
    "phong_lerp_div_dist",
    "phong_lerp_recip_dist",
    "phong_horner_div_generic",
    "phong_horner_recip_generic",
    "phong_pixel_div_generic",
    "phong_pixel_recip_generic",
    "phong_lerp_div_generic",
    "phong_lerp_recip_generic",
    "phong_value_either",
    "phong_normalize_dot_unit",
    "pixel_ok_exact_dot",
    "lerp_ok_exact_dot",
];

/// The theorems the adaptive scheme's `ieee` and `shader` verdicts rest on, beside
/// its picks' own (`proofs/AdaptiveDelta.v`, `proofs/Profiles.v`): outside the band
/// of `tolerance::adaptive_too_close` every implementation decides as the exact run
/// does, whether its `δ̂` is the crate's closed form, eq. 24 written out, or the
/// difference of the two methods' values at the middle pixel.
pub const ADAPTIVE_THEOREMS: &[&str] = &[
    "adaptive_acceptance_covers_computed_delta_generic_step",
    "adaptive_acceptance_covers_computed_delta_generic",
    "adaptive_acceptance_contains_every_run",
];

/// The theorems symmetric Phong's `ieee` and `shader` bounds rest on.
pub const SYMMETRIC_PHONG_THEOREMS: &[&str] = &[
    "symmetric_phong_div_generic",
    "symmetric_phong_recip_generic",
    "phong_value_either",
];
