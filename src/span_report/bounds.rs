//! The float bounds `span` prints for its span, per profile and format
//! (`error_bound`), and how each is known (`error_bound_status`).

use super::*;

/// A positive `x` as a decimal of three significant digits, rounded up (the slack
/// `1e-12` covers the rounding of the scaling in `f64`).
fn round_up_3(x: f64) -> String {
    let mut e = x.log10().floor() as i32;
    let mut m = (x * (1.0 + 1e-12) / 10f64.powi(e - 2)).ceil() as u64;
    if m >= 1000 {
        m = m.div_ceil(10);
        e += 1;
    }
    format!("{}.{:02}e{e}", m / 100, m % 100)
}

/// The bounds per profile: `reference` (this crate's own operation order,
/// [`crate::tolerance::span_bound`]), `ieee` and `shader` (for every implementation of
/// the profile, [`crate::tolerance::profile`]; `shader` only for `f32`). `None`
/// where none is derived or proved, and for every profile with `normalize`, whose
/// float normalization no derivation covers.
pub(super) fn error_bounds(r: &Request, format: crate::Format) -> ErrorBounds {
    use crate::tolerance::profile::{profile_span_bound, Form, Profile};
    let shape = (!r.normalize)
        .then(|| Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok())
        .flatten()
        .map(|s| crate::tolerance::Shape::of(&s));
    let of = |m: Method, p: Profile| -> Option<f64> {
        let shape = shape.as_ref()?;
        match p {
            Profile::Reference => crate::tolerance::span_bound(m, shape, format.u()),
            // The adaptive scheme's band takes its picks' formulas; the other methods
            // the smaller of the formula and the operation graphs' at each pixel, the
            // largest over the pixels.
            p if m.picks().is_some() => profile_span_bound(m, p, Form::Any, shape, format),
            p => crate::tolerance::graphs::profile_span_max(m, p, Form::Any, shape, format),
        }
    };
    // The adaptive scheme where its test is too close to call
    // (`tolerance::adaptive_too_close`): the float run may pick the other method, whose values differ from the exact pick's
    // by at most `|δ|` (eq. 24's δ is the largest difference, `eq_24_delta_is_max_difference`),
    // so the bound against the exact run's pick is the larger bound plus `|δ|`.
    let delta = (r.method.picks().is_some() && !r.normalize)
        .then(|| Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok())
        .flatten()
        .map(|s| {
            let d = crate::adaptive::decide(&s, &r.kd);
            (d.delta.to_f64().abs(), r.kd.to_f64())
        });
    let bound = |p: Profile| -> Option<String> {
        let b = of(r.method, p)?;
        let b = match delta {
            Some((d, kd)) => {
                let [ma, mb] = r.method.picks()?;
                let (ba, bb) = (of(ma, p)?, of(mb, p)?);
                let (wa, wb, u) = crate::tolerance::profile::adaptive_band(p, format, ba, bb);
                if crate::tolerance::adaptive_too_close(d, kd, wa, wb, u) {
                    ba.max(bb) + d * (1.0 + 1e-12)
                } else {
                    b
                }
            }
            None => b,
        };
        Some(round_up_3(b))
    };
    ErrorBounds {
        reference: bound(Profile::Reference),
        ieee: bound(Profile::Ieee),
        shader: (format == crate::Format::Binary32).then(|| bound(Profile::Shader)),
    }
}

/// The labels of the bounds `printed` ([`error_bounds`]): the reference profile's from the
/// catalogue (Gouraud and corrected Euler proved in this crate's order,
/// `proofs/Float.v`; the others derived in their `docs/float.md` section), the
/// acceptance profiles' from [`crate::tolerance::profile::status`]; `None` where no
/// bound is printed.
pub(super) fn error_bound_status(
    r: &Request,
    format: crate::Format,
    printed: &ErrorBounds,
) -> ErrorBounds {
    use crate::tolerance::profile::{status, Profile, Status};
    use crate::Format;
    let label = |p: Profile, shown: &Option<String>| -> Option<String> {
        shown.as_ref()?;
        let s = match p {
            // Proved in this crate's order where the catalogue row names the
            // theorems (`proofs/Float.v`, n ≤ 4096); derived in its section otherwise.
            Profile::Reference => match (r.method.info().profiles.reference, format) {
                (Some([b32, _]), Format::Binary32) if r.n <= 4096 => Status::Proved(b32),
                (Some([_, b64]), Format::Binary64) if r.n <= 4096 => Status::Proved(b64),
                // The `ieee` graphs' bound (this crate's run is an `ieee` one).
                _ if r.method.info().bound == crate::method::Bound::Graphs => {
                    status(r.method, Profile::Ieee, format)?
                }
                _ => {
                    return Some(format!(
                        "derived (docs/float.md {})",
                        r.method.info().float_section
                    ))
                }
            },
            p => status(r.method, p, format)?,
        };
        Some(s.label())
    };
    ErrorBounds {
        reference: label(Profile::Reference, &printed.reference),
        ieee: label(Profile::Ieee, &printed.ieee),
        shader: printed.shader.as_ref().map(|s| label(Profile::Shader, s)),
    }
}
