//! The proved bounds of a method under a profile in a format: its catalogue row's
//! theorems (`method/profiles.rs`), each the statement of a theorem of
//! `proofs/Profiles.v` (`tests/claims_index.rs` reads the statements and fails when a
//! constant there differs).

use super::{Profile, Proved};
use crate::Format;

/// The proved bounds of a profile for Gouraud (`g += dp`), corrected Euler (the
/// recurrence `p += t; t += ds`, and its closed form `p_a + i·(t_0 + (i−1)/2·ds)`)
/// and, under `ieee`, plain Euler (eqs. 12–14: the recurrence `E += s; s += ds` from
/// `s_0 = di_a`, and its closed form `p_a + i·(di_a + (i−1)/2·ds)`), in `format`; the largest of the forms a profile allows, so that every form
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
pub fn proved(method: crate::Method, profile: Profile, format: Format) -> Option<Vec<Proved>> {
    use crate::method::FloatBound;
    // The theorems are the catalogue row's ([`crate::method::ProfileBounds`]).
    let FloatBound::Proved(theorems) = method.info().profiles.float else {
        return None;
    };
    // The reference and fixed-point profiles have bounds of their own.
    if !matches!(profile, Profile::Ieee | Profile::Shader) {
        return None;
    }
    let forms: Vec<Proved> = theorems
        .iter()
        .filter(|t| t.profile == profile && t.format == format)
        .copied()
        .collect();
    (!forms.is_empty()).then_some(forms)
}
