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
//! Phong, Duff and symmetric Phong have bounds composed from Coq theorems on the same
//! model ([`Arith`]): the counts of `p` and `q` (`proofs/PhongCount.v`,
//! `proofs/PhongCountD.v`, `proofs/DuffCount.v`), the value step
//! (`proofs/PhongValue.v`) and normalize-then-dot (`proofs/PhongNormalize.v`) —
//! [`phong_bound`], [`duff_bound`], [`symmetric_phong_bound`], `docs/float.md`
//! §18.4–18.5 — and the adaptive scheme its picks' theorems with the band of
//! [`adaptive_band`] (`proofs/AdaptiveDelta.v`): all labelled *proved*, and
//! [`status`] names the theorem. Angular interpolation
//! and the related methods have none: a case then fails naming that.
//!
//! Tested, with other implementations written from the definitions (other orders,
//! `mul_add`, reciprocals, the closed form, a software GPU that truncates, divides
//! within 2.5 ulp and flushes denormals), in `tests/profiles/`.

use crate::Format;

mod adaptive;
mod counts;
mod form;
mod labels;
mod model;
mod phong;
mod theorems;

pub use adaptive::{adaptive_band, delta_error};
pub use counts::{duff_bound, symmetric_phong_bound, DuffCounts, DUFF_COUNTS};
pub use form::{Form, UnknownForm};
pub use labels::{formula, ieee_table, status_summary, status_table};
pub use model::{arith, Arith};
pub use phong::{
    normalize_then_dot, phong_bound, phong_ieee, PhongCounts, NORMALIZE_EXTRA, PHONG_COUNTS,
};
pub use theorems::proved;

pub use crate::profile::{Profile, ProfileError, MAX_FRAC_BITS};

/// The bound of `method` computed in fixed point `Q int_bits.frac_bits` on a span of
/// `n` steps whose smallest `q` is `q_min` (only Duff's reads it), as a span unit of
/// `harness/hdl/` runs it: every set-up value rounded once to nearest, so off by at
/// most `h = 2^-(f+1)`, then exact integer loops (`proofs/Fixed.v`,
/// `proofs/Fixed.v`; largest at `i = n`):
/// - Gouraud `h(1 + n)`; Euler and corrected Euler `h(1 + n + n(n−1)/2)`;
/// - the adaptive choice: the larger of Gouraud's and corrected Euler's (each run is
///   judged against the exact run of the method it picked; [`fixed_adaptive_band`]);
/// - Duff's unit (a truncated square root and divider per pixel):
///   `(E_p + E_q/(2r) + 2h)/(r − 2h) + 2h` with `E_p = h(1 + n)`,
///   `E_q = h(1 + n + n(n−1)/2)`, `r = √(q_min − E_q)`, where `r > 2h`.
///
/// `None` for another method, where Duff's `r ≤ 2h`, or when the registers may
/// overflow: `m` integer bits hold magnitudes below `2^(m−1)`, and the values reach
/// the row's `value_max` (2.5 for corrected Euler, 5 for Euler, 1 for Gouraud and
/// Duff's `p` and `q`) plus the bound, the slopes its `slope_times_n / n` (Duff's `dq`:
/// `16/n`) plus `h(1 + n)` (`docs/float.md` §14). Rounded up.
pub fn fixed_bound(
    method: crate::Method,
    n: u32,
    q_min: f64,
    int_bits: u32,
    frac_bits: u32,
) -> Option<f64> {
    use crate::method::FixedBound;
    if n == 0 || !(1..=64).contains(&int_bits) || !(1..=MAX_FRAC_BITS).contains(&frac_bits) {
        return None;
    }
    let h = 2f64.powi(-(frac_bits as i32) - 1);
    let nf = f64::from(n);
    // Exact in f64 for n < 2^24: h is a power of two, the factors whole numbers.
    let (e_first, e_second) = (h * (1.0 + nf), h * (1.0 + nf + nf * (nf - 1.0) / 2.0));
    let fits = |needed: f64| needed < 2f64.powi(int_bits as i32 - 1);
    // The f64 arithmetic below rounds: a relative 2^-40 covers it.
    let up = |b: f64| b * (1.0 + 2f64.powi(-40));
    // The catalogue row says what the theorems prove of the method.
    match method.info().profiles.fixed {
        FixedBound::Proved {
            second_order,
            value_max,
            slope_times_n,
            ..
        } => {
            let bound = if second_order { e_second } else { e_first };
            fits((value_max + bound).max(slope_times_n / nf + e_first)).then(|| up(bound))
        }
        FixedBound::Picks { .. } => method.picks()?.iter().try_fold(0f64, |b, &m| {
            Some(b.max(fixed_bound(m, n, q_min, int_bits, frac_bits)?))
        }),
        FixedBound::Ratio { .. } => {
            // r rounded down: q_min − E_q and its root each lowered past their rounding.
            let gap = (q_min - e_second) - q_min.abs() * 2f64.powi(-52);
            if gap.is_nan() || gap <= 0.0 {
                return None;
            }
            let r = gap.sqrt() * (1.0 - 2f64.powi(-50));
            let den = (r - 2.0 * h) - r * 2f64.powi(-52);
            if den.is_nan() || den <= 0.0 {
                return None;
            }
            let bound = up((e_first + e_second / (2.0 * r) + 2.0 * h) / den + 2.0 * h);
            let needed = (1.0 + e_second).max(16.0 / nf + e_first).max(1.0 + bound);
            (bound.is_finite() && fits(needed)).then_some(bound)
        }
        FixedBound::None(_) => None,
    }
}

/// What the adaptive unit's `δ̂` may be off by: `h(2k + k(k − 1)/2)`, `k = ⌈n/2⌉`,
/// `h = 2^-(f+1)` (`fixed_point_adaptive_delta_error`, `proofs/Fixed.v`). Where
/// `|255·|δ| − 1| ≤ 255·e_δ` the unit may pick either method
/// (`fixed_point_adaptive_decision`); exact in `f64` for `n < 2^24`.
pub fn fixed_adaptive_band(n: u32, frac_bits: u32) -> f64 {
    let k = f64::from(n.div_ceil(2));
    2f64.powi(-(frac_bits.min(MAX_FRAC_BITS) as i32) - 1) * (2.0 * k + k * (k - 1.0) / 2.0)
}

pub use crate::method::Proved;

/// The proved bound of `method` under `profile` at `n` in `format`: the largest over the forms the profile allows (every theorem
/// [`proved`] lists: the recurrences, the closed forms, and under `shader` the ways
/// of dividing and of halving), or `None` where no theorem covers it.
pub fn proved_bound(
    method: crate::Method,
    profile: Profile,
    n: u32,
    format: Format,
) -> Option<f64> {
    proved_bound_in(method, profile, Form::Any, n, format)
}

/// [`proved_bound`] for an implementation of the declared `form`: the largest over
/// that form's theorems only; `None` where the form has none.
pub fn proved_bound_in(
    method: crate::Method,
    profile: Profile,
    form: Form,
    n: u32,
    format: Format,
) -> Option<f64> {
    let forms = proved_in(method, profile, form, format)?;
    forms
        .iter()
        .map(|f| f.at(n, format))
        .try_fold(0.0f64, |m, b| b.map(|b| m.max(b)))
}

/// The theorems of [`proved`] that cover the declared `form` (all of them for
/// [`Form::Any`]); `None` where none does, or where the method's forms are not told
/// apart ([`Form::applies_to`]) and the form is not `Any`.
pub fn proved_in(
    method: crate::Method,
    profile: Profile,
    form: Form,
    format: Format,
) -> Option<Vec<Proved>> {
    if form != Form::Any && !Form::applies_to(method) {
        return None;
    }
    let forms: Vec<Proved> = proved(method, profile, format)?
        .into_iter()
        .filter(|p| form.covers(p))
        .collect();
    (!forms.is_empty()).then_some(forms)
}

/// The graph theorems applied besides `graph_sound` where the inputs are read to
/// nearest (`Status::PerPixel`'s third field): the affine forms, and both bounds from
/// the inputs as read.
pub const GRAPH_THEOREMS_READ: [&str; 3] = [
    "graph_sound_affine",
    "graph_sound_read",
    "graph_sound_affine_read",
];

/// `graph_sound` and `also`, in order.
pub(crate) fn graph_theorems(also: &[&'static str]) -> Vec<&'static str> {
    std::iter::once("graph_sound")
        .chain(also.iter().copied())
        .collect()
}

/// `a`, `a and b`, `a, b and c`.
pub(crate) fn and_list(names: &[impl AsRef<str>]) -> String {
    let n: Vec<&str> = names.iter().map(AsRef::as_ref).collect();
    match n.split_last() {
        None => String::new(),
        Some((last, [])) => (*last).to_string(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
    }
}

/// How a profile's bound for a method is known.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// A Coq theorem (its name): every bound of the `ieee`, `shader` and fixed-point
    /// profiles is proved or composed from proved theorems.
    Proved(&'static str),
    /// A Coq theorem (its name) and, at each pixel where it is smaller, the bound of
    /// the method's operation graphs (their names: the catalogue row's `graphs`;
    /// `tolerance::graphs`, `proofs/Graph.v`'s `graph_sound`): the `ieee` and `shader`
    /// bounds of the methods whose catalogue row has graphs.
    /// The third field names the graph theorems applied besides `graph_sound` (the
    /// affine forms, `graph_sound_affine` of `proofs/GraphAffine.v`; and where an
    /// implementation reads each input to nearest, `ieee` and `shader`, the bounds
    /// from the inputs as read: `graph_sound_read`, `graph_sound_affine_read`).
    PerPixel(
        &'static str,
        &'static [&'static str],
        &'static [&'static str],
    ),
    /// The bound of the method's operation graphs alone (their names), per pixel,
    /// composed with the value's last step by a theorem (its name): the squared
    /// method's `sign(p)·√max(0, g)` (`sq_signed_value_error`); the third field names
    /// a second composing theorem where the profile needs one (under `shader`, the
    /// rounding of a root taken as `1/inverseSqrt`: `sq_shader_root_rounding`).
    Graphs(&'static str, &'static [&'static str], Option<&'static str>),
}

impl Status {
    /// `proved (theorem)`, as the docs and `span` label a bound.
    pub fn label(&self) -> String {
        match self {
            Status::Proved(t) => format!("proved ({t})"),
            Status::PerPixel(t, graphs, also) => format!(
                "proved ({t}; per pixel the smallest with {} on the {} {})",
                and_list(&graph_theorems(also)),
                if graphs.len() == 1 { "graph" } else { "graphs" },
                graphs.join(", ")
            ),
            Status::Graphs(t, graphs, also) => format!(
                "proved (graph_sound on the {} {}, composed by {t}{})",
                if graphs.len() == 1 { "graph" } else { "graphs" },
                graphs.join(", "),
                also.map_or(String::new(), |a| format!(" and {a}"))
            ),
        }
    }

    /// The theorem named first.
    pub fn theorem(&self) -> &'static str {
        match *self {
            Status::Proved(t) | Status::PerPixel(t, ..) | Status::Graphs(t, ..) => t,
        }
    }
}

/// Whether and how `method` has a bound under `profile` in `format` (`None`: no
/// bound, a case then fails naming that), read from the method's catalogue row
/// ([`crate::method::ProfileBounds`]): a method's row states what it has under fixed
/// point and under `ieee` and `shader` (angular interpolation, whose `acos` and `cos`
/// no profile bounds, and the related methods, whose bounds follow this crate's own
/// evaluation, have none).
pub fn status(method: crate::Method, profile: Profile, format: Format) -> Option<Status> {
    use crate::method::{DerivedForm, FloatBound};
    let row = method.info().profiles;
    if let Profile::Fixed { .. } = profile {
        return row.fixed.theorem().map(Status::Proved);
    }
    // The methods with operation graphs: per pixel, the smaller with theirs.
    let per_pixel = |t: &'static str| {
        if !row.graphs.is_empty() && arith(profile, format).is_some() {
            // Under `ieee` and `shader` every input is read to nearest
            // (`graph_sound_read`, `graph_sound_affine_read`).
            let also: &'static [&'static str] =
                if matches!(profile, Profile::Ieee | Profile::Shader) {
                    &GRAPH_THEOREMS_READ
                } else {
                    &GRAPH_THEOREMS_READ[..1]
                };
            Status::PerPixel(t, row.graphs, also)
        } else {
            Status::Proved(t)
        }
    };
    match row.float {
        // A float profile's theorems ([`proved`]), the first form's name.
        FloatBound::Proved(_) => {
            proved(method, profile, format).map(|forms| per_pixel(forms[0].theorem))
        }
        // The larger of the picks' proved bounds, composed with the band's theorems:
        // both picks must be proved.
        FloatBound::Composed {
            theorems,
            form: DerivedForm::LargerOfPicks,
            ..
        } => method
            .picks()?
            .iter()
            .all(|&m| proved(m, profile, format).is_some())
            .then(|| arith(profile, format).map(|_| Status::Proved(theorems[0])))
            .flatten(),
        // Composed from theorems where the profile has a standard model: the counts'.
        FloatBound::Composed { theorems, .. } => {
            arith(profile, format).map(|_| per_pixel(theorems[0]))
        }
        // The graphs alone, where the profile has a model.
        FloatBound::Graphs {
            theorem,
            shader_root,
            ..
        } => (!row.graphs.is_empty())
            .then(|| {
                // Under `shader` the root is `1/inverseSqrt`, whose rounding has its
                // own theorem (docs/float.md §19.7).
                let also = (profile == Profile::Shader).then_some(shader_root);
                arith(profile, format).map(|_| Status::Graphs(theorem, row.graphs, also))
            })
            .flatten(),
        FloatBound::None(_) => None,
    }
}

/// The bound of `method` under `profile` (not `Reference`, whose bounds are
/// [`crate::tolerance::bound`]) on a span of `n` steps and smallest `q_i` `q_min`, in
/// `format`: the proved bound ([`proved_bound`]) or the derived
/// or composed one ([`phong_bound`], [`duff_bound`]); `None` where none covers it. For any
/// unit normals; [`profile_span_bound`] reads more of a known span.
pub fn profile_bound(
    method: crate::Method,
    profile: Profile,
    n: u32,
    q_min: f64,
    format: Format,
) -> Option<f64> {
    profile_bound_in(method, profile, Form::Any, n, q_min, format)
}

/// [`profile_bound`] for an implementation that declares its `form` ([`Form`]).
pub fn profile_bound_in(
    method: crate::Method,
    profile: Profile,
    form: Form,
    n: u32,
    q_min: f64,
    format: Format,
) -> Option<f64> {
    bound_with(method, profile, form, n, q_min, 2.0, format)
}

/// [`profile_bound`] for a known span: Phong's derived bound with the span's own
/// `|N_b − N_a|` ([`crate::tolerance::Shape::dn`]; up to 3× tighter on the close
/// normals of a mesh, [`phong_bound`]).
/// With a declared `form` ([`Form`]), the bound of that form alone: `None` where the
/// form has no theorem (Gouraud's closed form, a fixed-point closed form) or the
/// method's forms are not told apart.
pub fn profile_span_bound(
    method: crate::Method,
    profile: Profile,
    form: Form,
    shape: &crate::tolerance::Shape,
    format: Format,
) -> Option<f64> {
    bound_with(
        method,
        profile,
        form,
        shape.n,
        shape.q_min,
        shape.dn,
        format,
    )
}

fn bound_with(
    method: crate::Method,
    profile: Profile,
    form: Form,
    n: u32,
    q_min: f64,
    dn: f64,
    format: Format,
) -> Option<f64> {
    // A declared form narrows only the bounds whose theorems tell forms apart.
    if form != Form::Any && !Form::applies_to(method) {
        return None;
    }
    if let Profile::Fixed {
        int_bits,
        frac_bits,
    } = profile
    {
        // `Fixed.v` proves the loops: an exact integer recurrence.
        return (form != Form::Closed)
            .then(|| fixed_bound(method, n, q_min, int_bits, frac_bits))
            .flatten();
    }
    use crate::method::{DerivedForm, FloatBound};
    status(method, profile, format)?;
    match method.info().profiles.float {
        FloatBound::Proved(_) => proved_bound_in(method, profile, form, n, format),
        // No formula in n and q_min: per case only (`tolerance::graphs`).
        FloatBound::Graphs { .. } | FloatBound::None(_) => None,
        FloatBound::Composed { form, .. } => {
            let a = arith(profile, format)?;
            match form {
                DerivedForm::PerPixel => phong_bound(&a, n, q_min, dn),
                DerivedForm::Ratio => duff_bound(&a, n, q_min),
                DerivedForm::HalfRatio => symmetric_phong_bound(&a, n, q_min),
                DerivedForm::LargerOfPicks => method.picks()?.iter().try_fold(0f64, |b, &m| {
                    Some(b.max(proved_bound(m, profile, n, format)?))
                }),
            }
        }
    }
}
