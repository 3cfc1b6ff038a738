//! The adaptive scheme's test too close to call (`docs/float.md` §10, §18.5): how far
//! an implementation's own `δ̂` may be from the exact `δ`, whichever way it computes it
//! (`proofs/AdaptiveDelta.v`), and the bounds the band and the verdict take so that
//! `adaptive_acceptance_covers_computed_delta_generic` holds (in binary32 with its
//! constants: `adaptive_acceptance_covers_computed_delta`; at the applied `ieee`
//! bounds, `adaptive_delta_conditions_at_profile_bounds`: eq. 24's `83u` needs the
//! raised Gouraud bound below `n = 6`); eq. 24 at either step eq. 23 may give in floats,
//! `⌈n/2⌉` or `⌊n/2⌋`: `adaptive_acceptance_covers_computed_delta_generic_step`,
//! `adaptive_acceptance_covers_computed_delta_step`).

use super::model::{arith, Arith};
use super::Profile;
use crate::Format;

/// `fast_delta_err` and `eq24_delta_err` of `proofs/AdaptiveDelta.v` on the standard
/// model `a` (the larger of the two; `eq24_shared_delta_err` is below the second):
/// how far `δ̂` may be from `δ` when it is computed as the crate's closed form
/// `ds/2·⌊n/2⌋·⌈n/2⌉` (any association) or as eq. 24 written out,
/// `j·dp − (j·t_0 + (j² − j)/2·ds)`, on Gouraud's and corrected Euler's set-ups
/// (`/n` either way: the larger `κ` of a division). Evaluated on the model the band's
/// theorem is instantiated with: `a` rescaled to the unit `u'` of [`adaptive_band`]
/// (every `κ` divided by `u'/u`, the same `κ·u`). Rounded up.
pub fn delta_error(a: &Arith) -> f64 {
    let a = &rescaled(a);
    let (u, eta) = (a.u, a.eta);
    let k1 = a.input.max(a.add).max(a.mul).max(1.0);
    let kd = a
        .div
        .max((1.0 + 2f64.powi(-20)) * a.mul + a.div + 2f64.powi(-36));
    let (v, d) = (k1 * u, kd * u);
    let eds = 92.11 * v + 18.06 * d;
    let fast = eds / 8.0 + 3.004 * v * (0.25 + eds / 8.0) + 562_949_986_975_745.0 * eta;
    let epg =
        (2.0 * a.input * u + a.mul * u + 2.0 * a.add * u) * (1.0 + 2f64.powi(-17)) + 18.0 * eta;
    let edp = (a.add * u + kd * u) * (2.0 + 2f64.powi(-16)) + 16_777_218.0 * eta;
    let epc = 5.002 * v + 0.001 * d;
    let er = 20.04 * v + 5.01 * d;
    let eg = edp + 2.0 * epg;
    let ec = er + 2.0 * epc + eds / 8.0;
    let (ma, mb, mc) = (2.0 + eg, 3.0 + 2.0 * epc + eds / 2.0 + er, 1.0 + eds / 2.0);
    let e4 = eg
        + ec
        + (v * ma + eta)
        + (v * mb + eta)
        + (v * mc + eta)
        + (v * (mb + mc + (v * mb + eta) + (v * mc + eta)) + eta);
    let eq24 = e4 + v * (0.25 + e4) + eta;
    fast.max(eq24) * (1.0 + 2f64.powi(-40))
}

/// The model the band's theorem is instantiated with: `a` with every addition and
/// product within one unit `u' = max(κ_mul, 1)·u` (`shader`: `2u`), every `κ` divided
/// by `u'/u` (the same `κ·u`). [`delta_error`] is evaluated on it, and its unit is
/// [`adaptive_band`]'s `u'`.
fn rescaled(a: &Arith) -> Arith {
    let c = a.mul.max(1.0);
    Arith {
        u: a.u * c,
        input: a.input / c,
        add: a.add / c,
        mul: a.mul / c,
        div: a.div / c,
        half: a.half / c,
        sqrt: a.sqrt / c,
        eta: a.eta,
    }
}

/// The bounds and unit the adaptive band takes under `profile` in `format`, from the
/// picks' bounds `b_g` (Gouraud) and `b_ce` (corrected Euler): `(b_g', b_ce, u')`.
///
/// `u'` is the model's unit with every addition and product within `1·u'` (`ieee`:
/// `u`; `shader`, whose sums and products are 2-ulp: `2u`, the model rescaled with
/// the same `κ·u`), so the test's two products `255·K_d·δ̂` are within `3u'`, as the
/// theorem asks. `b_g'` is `b_g` raised, where needed, until the band's
/// `1.01·(b_g' + b_ce) + 2u'` covers [`delta_error`] — the theorem's condition; a run
/// within `b_g` is within `b_g'`. The `reference` profile (the crate's own `f32` and
/// `f64` code, one `ieee` implementation) takes `ieee`'s model; where a format has
/// no model, the bounds are returned unchanged with `u`.
pub fn adaptive_band(profile: Profile, format: Format, b_g: f64, b_ce: f64) -> (f64, f64, f64) {
    let model = match profile {
        Profile::Reference | Profile::Ieee => arith(Profile::Ieee, format),
        Profile::Shader => arith(Profile::Shader, format),
        Profile::Fixed { .. } => None,
    };
    let Some(a) = model else {
        return (b_g, b_ce, format.u());
    };
    let u1 = rescaled(&a).u;
    let need = ((delta_error(&a) - 2.0 * u1) / 1.01 - b_ce) * (1.0 + 2f64.powi(-40));
    (b_g.max(need), b_ce, u1)
}
