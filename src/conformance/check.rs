//! Checking an implementation's results against a vector file: reading them
//! (`check/results.rs`: CSV or JSON, streaming), the tolerance they are judged by
//! (`check/tolerance.rs`), and the verdict on each case (here: the bound a profile gives the
//! case, the adaptive scheme's band, the levels, absolute errors and ulps).

mod results;
mod tolerance;

pub use results::{
    denote, parse_results_json, InputError, Results, MAX_CSV_LINE, MAX_RESULTS_BYTES,
};
#[cfg(feature = "csv")]
pub use results::{parse_results, parse_results_csv};
pub use tolerance::{Advice, Tolerance, ToleranceError, Unbounded};

use super::vectors::{Case, Expected, VectorFile};
use crate::method::Method;
use crate::quantize::level;
use tolerance::exceeds;

/// The comparison of one case.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseReport {
    /// Case id.
    pub id: String,
    /// The case's position in the vector file's `cases` (its id's index).
    pub case: usize,
    /// Pixels.
    pub pixels: usize,
    /// Largest |level − expected level|.
    pub max_levels: u32,
    /// Mean |level − expected level|.
    pub mean_levels: f64,
    /// Largest |value − expected|.
    pub max_abs: f64,
    /// Largest |value − expected| in ulps of the case's scale (the largest
    /// `|expected value|` of the span; [`Tolerance::Ulps`]), in the format
    /// [`CaseReport::format`] names.
    pub max_ulps: f64,
    /// The format whose ulps `max_ulps` counts.
    pub format: crate::Format,
    /// The case's scale, the largest `|expected value|` of the span: its ulp is the
    /// unit of `max_ulps` ([`Tolerance::Ulps`]).
    pub scale: f64,
    /// The pixel where the tolerance is exceeded most (relative to it), if any.
    pub worst_pixel: usize,
    /// How much of the tolerance the worst pixel uses: `|value − expected|` over the
    /// allowed absolute error (or levels over allowed levels, ulps over allowed ulps);
    /// above 1 the case fails. Infinite where a value is missing or not finite, or no
    /// bound holds.
    pub ratio: f64,
    /// The allowed absolute error, where the tolerance is one (a profile's bound, the
    /// reference bound, [`Tolerance::Abs`]).
    pub allowed_abs: Option<f64>,
    /// The allowed absolute error at [`CaseReport::worst_pixel`]: its own where the
    /// bounds are per pixel (else [`CaseReport::allowed_abs`]), so that
    /// [`CaseReport::ratio`] is that pixel's error over it.
    pub worst_allowed: Option<f64>,
    /// The tolerance applied (as an absolute value, or levels), or why there is none
    /// ([`CaseReport::unbounded`]'s reason, without advice).
    pub allowed: String,
    /// Why the case has no bound, where it has none (it then fails).
    pub unbounded: Option<Unbounded>,
    /// Whether every pixel is within the tolerance.
    pub pass: bool,
    /// The first pixel whose result is NaN or infinite (it fails, whatever the
    /// tolerance), if any.
    pub not_finite: Option<usize>,
    /// The time the verdict on this case took (seconds; the JUnit report's `time`).
    pub seconds: f64,
}

/// Why [`check_in`] cannot judge a file, naming the input at fault.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum JudgeError {
    /// The tolerance means nothing ([`Tolerance::validate`]).
    #[error(transparent)]
    Tolerance(#[from] ToleranceError),
    /// The vector file holds no expectations of the method.
    #[error("the vector file has no method '{key}'")]
    Method {
        /// The method's key in the vector files.
        key: String,
    },
    /// The span shapes handed in are not the file's: one per case is needed
    /// ([`shapes`]).
    #[error("{shapes} span shapes for {cases} cases: not this file's")]
    Shapes {
        /// How many were handed in.
        shapes: usize,
        /// How many cases the file holds.
        cases: usize,
    },
}

/// What a verdict judges by — one request, taken by [`check`], [`check_in`],
/// [`super::judgement::judge`], the test kit and `gpu-check`: the method (its key in
/// the vector files is [`Criteria::key`]), the tolerance, the part (diffuse, or the
/// specular `max(0, method(N·H))^s`) and the implementation's format, whose ulps
/// [`Tolerance::Ulps`] and the report count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Criteria {
    /// The method the results are of.
    pub method: Method,
    /// How close they must be.
    pub tolerance: Tolerance,
    /// Whether they are the specular part.
    pub specular: bool,
    /// The implementation's format.
    pub format: crate::Format,
}

impl Criteria {
    /// Diffuse results of `method` judged by `tolerance`, in the format it names
    /// (`f32` where it names none).
    pub fn new(method: Method, tolerance: Tolerance) -> Self {
        Criteria {
            method,
            tolerance,
            specular: false,
            format: tolerance.format().unwrap_or(crate::Format::Binary32),
        }
    }

    /// The same criteria for the specular part (`true`) or the diffuse one.
    pub fn specular(self, specular: bool) -> Self {
        Criteria { specular, ..self }
    }

    /// The same criteria for an implementation in `format`.
    pub fn in_format(self, format: crate::Format) -> Self {
        Criteria { format, ..self }
    }

    /// The method's key in the vector files
    /// ([`crate::conformance::vectors::method_key`]).
    pub fn key(&self) -> String {
        super::vectors::method_key(self.method)
    }
}

/// Compares `results` with the vector file's expectations by `criteria`.
///
/// # Errors
/// A [`JudgeError`]: the method is not in the file, or the tolerance is not valid
/// ([`Tolerance::validate`]).
pub fn check(
    vectors: &VectorFile,
    results: &Results,
    criteria: &Criteria,
) -> Result<Vec<CaseReport>, JudgeError> {
    check_in(vectors, &shapes(vectors), results, criteria)
}

/// The shape of each case's exact span, in the file's case order: read once from the
/// cases' exact inputs ([`super::integrity::case_span`]) and handed to [`check_in`] for
/// the bounds (`q_min`, `n`, the related methods' whole-span facts). `None` for a case
/// whose inputs are not an exact unit span (no bound reads it; its case fails).
/// [`super::integrity::validate`] returns the same while it checks a file.
pub fn shapes(vectors: &VectorFile) -> Vec<Option<crate::tolerance::Shape>> {
    vectors
        .cases
        .iter()
        .map(|c| {
            super::integrity::case_span(c)
                .ok()
                .map(|span| crate::tolerance::Shape::of(&span))
        })
        .collect()
}

/// [`check`] with the shapes of the file's spans read once ([`shapes`]).
///
/// # Errors
/// As [`check`], and [`JudgeError::Shapes`] where `shapes` are not the file's.
pub fn check_in(
    vectors: &VectorFile,
    shapes: &[Option<crate::tolerance::Shape>],
    results: &Results,
    criteria: &Criteria,
) -> Result<Vec<CaseReport>, JudgeError> {
    let Criteria {
        method,
        tolerance: tol,
        specular,
        format,
    } = *criteria;
    let key = criteria.key();
    let method_key = key.as_str();
    tol.validate().map_err(JudgeError::Tolerance)?;
    if shapes.len() != vectors.cases.len() {
        return Err(JudgeError::Shapes {
            shapes: shapes.len(),
            cases: vectors.cases.len(),
        });
    }
    let mut reports = Vec::new();
    for (k, (c, shape)) in vectors.cases.iter().zip(shapes).enumerate() {
        let exp: &Expected = if specular {
            let Some(sp) = &c.specular else { continue };
            sp.expected.get(method_key)
        } else {
            c.expected.get(method_key)
        }
        .ok_or_else(|| JudgeError::Method {
            key: method_key.to_string(),
        })?;
        // A case the results lack has no values: it fails, as a missing pixel does.
        let got = results.get(&c.id).map_or(&[][..], Vec::as_slice);
        let start = std::time::Instant::now();
        let case = Judging {
            c,
            k,
            shape: shape.as_ref(),
            tol,
            format,
        };
        let mut r = match (!specular)
            .then(|| adaptive_either(&case, got, method))
            .flatten()
        {
            Some(r) => r,
            None => case_report(&case, exp, got, method, specular),
        };
        r.seconds = start.elapsed().as_secs_f64();
        reports.push(r);
    }
    Ok(reports)
}

/// A case being judged: the case, its position, the shape of its exact span (`None`
/// where its inputs are not an exact unit span), the tolerance and the
/// implementation's format.
struct Judging<'a> {
    c: &'a Case,
    /// Its position in the file.
    k: usize,
    shape: Option<&'a crate::tolerance::Shape>,
    tol: Tolerance,
    format: crate::Format,
}

/// The bound a profile (or the reference bounds) gives `method` on the case, before
/// the specular power: `None` for the other tolerances and where no bound holds.
/// Specular cases shade `N·H`, not `N·L`, so the reference bound takes no edge values
/// there.
fn case_bound(j: &Judging, method: Method, specular: bool) -> Option<f64> {
    use crate::tolerance::profile::{profile_bound_in, profile_span_bound};
    let (c, shape) = (j.c, j.shape);
    // The one q_min: the exact span's, rounded down (`Shape::of`); only where the
    // span could not be built, the vector file's, which is to nearest, a relative
    // 2^-40 lower (below the span's: `integrity` holds it within 10^-12 of it).
    let q_min = shape.map_or(c.q_min * (1.0 - 2f64.powi(-40)), |s| s.q_min);
    match j.tol {
        // The reference profile: the crate's own bounds. Specular cases shade N·H:
        // the span's edge values are N·L's, so the bound takes n and q_min only (q
        // does not depend on the light).
        Tolerance::Profile {
            profile: crate::tolerance::profile::Profile::Reference,
            format,
            ..
        } => match shape {
            // A bound from the case's own inputs (the squared method's, its `ieee`
            // graphs': docs/float.md §19.7) takes the light the case shades, `H` for
            // the specular part.
            Some(shape) if method.info().bound == crate::method::Bound::Graphs => {
                let light = if specular {
                    Some(half_vector(c)?)
                } else {
                    None
                };
                crate::tolerance::graphs::profile_pixel_bounds(
                    method,
                    crate::tolerance::profile::Profile::Ieee,
                    crate::tolerance::profile::Form::Any,
                    shape,
                    light,
                    format,
                )
                .map(|b| b.into_iter().fold(0f64, f64::max))
            }
            Some(shape) if !specular => crate::tolerance::span_bound(method, shape, format.u()),
            _ => crate::tolerance::bound(method, c.n, q_min, format.u()),
        },
        // The case's exact span gives Phong's derived bound its |N_b − N_a|.
        Tolerance::Profile {
            profile,
            format,
            form,
        } => match shape {
            Some(shape) => profile_span_bound(method, profile, form, shape, format),
            None => profile_bound_in(method, profile, form, c.n, q_min, format),
        },
        _ => None,
    }
}

/// The case's exact half vector `H` as the graphs' three input intervals, if it has
/// a specular part whose `H` is exact.
fn half_vector(c: &Case) -> Option<[(f64, f64); 3]> {
    let h = super::vectors::exact_input(&c.specular.as_ref()?.h)?;
    Some([&h.x, &h.y, &h.z].map(crate::tolerance::graph::interval))
}

/// The adaptive scheme where its test is too close to call: when `|255·δ|` (the
/// case's exact `δ`, eq. 24, `K_d = 1`) is within `255·e_δ` of 1 — `e_δ` what an
/// implementation's own `δ` may be off by — a correct float run may pick either
/// method, and lands up to `|δ|` (one level) from the exact run's pick. The case then
/// passes when the results are within Gouraud's bound of the exact Gouraud run, or
/// within corrected Euler's bound of the exact corrected-Euler run (one method for the
/// whole span, as an implementation runs it); `None` elsewhere (judged as usual).
///
/// `e_δ`: [`crate::tolerance::adaptive_too_close`].
fn adaptive_either(j: &Judging, got: &[f64], method: Method) -> Option<CaseReport> {
    let [ma, mb] = method.picks()?;
    let c = j.c;
    let delta: f64 = c.delta.parse().ok()?;
    // Only where the profile bounds the adaptive scheme at all.
    case_bound(j, method, false)?;
    let (ba, bb) = (case_bound(j, ma, false)?, case_bound(j, mb, false)?);
    let profile = match j.tol {
        Tolerance::Profile { profile, .. } => profile,
        _ => crate::tolerance::profile::Profile::Reference,
    };
    // The band's bounds (Gouraud's raised where the theorem needs it); each method's
    // values are judged by its own bound, which every run of the class meets.
    let close = if let crate::tolerance::profile::Profile::Fixed { frac_bits, .. } = profile {
        // The unit's δ̂ is exact integer arithmetic on the rounded set-up: off by at
        // most e_δ (`fixed_point_adaptive_delta_error`); 10^-14 covers reading δ.
        let e = crate::tolerance::profile::fixed_adaptive_band(c.n, frac_bits);
        ((255.0 * delta).abs() - 1.0).abs() <= 255.0 * e * (1.0 + 2f64.powi(-40)) + 1e-14
    } else {
        let (band_a, band_b, u) =
            crate::tolerance::profile::adaptive_band(profile, j.format, ba, bb);
        crate::tolerance::adaptive_too_close(delta, 1.0, band_a, band_b, u)
    };
    if !close {
        return None;
    }
    let mut best: Option<CaseReport> = None;
    for m in [ma, mb] {
        let key = crate::conformance::vectors::method_key(m);
        let exp = c.expected.get(&key)?;
        let mut r = case_report(j, exp, got, m, false);
        r.allowed = format!(
            "{} as {key} (|255δ| = {:.6} is within rounding of 1: either method passes)",
            r.allowed,
            (255.0 * delta).abs()
        );
        if r.pass {
            return Some(r);
        }
        best.get_or_insert(r);
    }
    best
}

/// The fractional bits of a fixed-point profile whose Duff bound fails on the case
/// for its `q_min` alone (with registers as wide as any: `fixed_bound`'s `r ≤ 2h`).
fn duff_q_min_too_small(j: &Judging, method: Method) -> Option<u32> {
    let Tolerance::Profile {
        profile: crate::tolerance::profile::Profile::Fixed { frac_bits, .. },
        ..
    } = j.tol
    else {
        return None;
    };
    let q_min = j.shape?.q_min;
    (method == Method::Duff
        && crate::tolerance::profile::fixed_bound(method, j.c.n, q_min, 64, frac_bits).is_none())
    .then_some(frac_bits)
}

fn case_report(
    j: &Judging,
    exp: &Expected,
    got: &[f64],
    method: Method,
    specular: bool,
) -> CaseReport {
    use crate::tolerance::profile::Profile;
    let (c, tol, format) = (j.c, j.tol, j.format);
    // The expected decimals as the nearest f64, read once (the verdict reads them
    // again, exactly, only where f64 cannot decide: `exceeds`).
    let expected: Vec<f64> = exp
        .values
        .iter()
        .map(|x| x.parse::<f64>().unwrap_or(f64::NAN))
        .collect();
    // Specular raises the value v ≥ 0 to the power s: an error e in v moves v^s by at
    // most s·(v + e)^(s−1)·e (mean value theorem), and evaluating the power adds a
    // relative γ_s (s − 1 products, or a pow within an ulp). The values may exceed 1
    // (corrected Euler reaches about 1.19), so the factor is taken at the case's
    // largest base value, v_max = max (v^s)^(1/s). Specular cases shade N·H with a
    // unit H, so the diffuse bounds hold with H for L.
    let spec = specular.then(|| {
        let s = c.specular.as_ref().map_or(1, |sp| sp.s.max(1));
        let v_max = expected
            .iter()
            .filter(|x| !x.is_nan())
            .map(|&x| x.max(0.0).powf(1.0 / f64::from(s)) * (1.0 + 1e-12))
            .fold(0.0, f64::max);
        (f64::from(s), v_max)
    });
    let raise = |b: f64, format| match spec {
        None => b,
        Some((s, v_max)) => crate::tolerance::specular_bound(b, s, v_max, format),
    };
    // Under `ieee` and `shader`, a bound per pixel where the operation graphs give one
    // (`tolerance::graphs::profile_pixel_bounds`: the smaller of the formula and the
    // graphs' at each pixel); the adaptive scheme is judged by its picks' formulas.
    let per_pixel = match (tol, j.shape) {
        (
            Tolerance::Profile {
                profile: profile @ (Profile::Ieee | Profile::Shader),
                format,
                form,
            },
            Some(shape),
        ) if method.picks().is_none() && !(specular && profile == Profile::Shader) => {
            let light = specular.then(|| half_vector(c)).flatten();
            (light.is_some() || !specular)
                .then(|| {
                    crate::tolerance::graphs::profile_pixel_bounds(
                        method, profile, form, shape, light, format,
                    )
                })
                .flatten()
                .map(|b| {
                    b.into_iter()
                        .map(|b| raise(b, format))
                        .collect::<Vec<f64>>()
                })
        }
        _ => None,
    };
    let allowed_abs = match tol {
        _ if per_pixel.is_some() => per_pixel
            .as_ref()
            .map(|b| b.iter().copied().fold(0f64, f64::max)),
        Tolerance::Abs(x) => Some(x),
        // The power is not in the shader profile's model (Vulkan's pow is exp2 of a
        // log2, with errors relative to neither), nor in fixed point's: diffuse only.
        Tolerance::Profile {
            profile: Profile::Shader | Profile::Fixed { .. },
            ..
        } if specular => None,
        // No bound (n too long for the precision, or q may round to zero): the case
        // cannot pass on the profile's tolerance.
        Tolerance::Profile { format, .. } => {
            case_bound(j, method, specular).map(|b| raise(b, format))
        }
        _ => None,
    };
    let unbounded = matches!(tol, Tolerance::Profile { .. }) && allowed_abs.is_none();
    let (mut max_levels, mut sum_levels, mut max_abs, mut max_ulps) = (0u32, 0u64, 0f64, 0f64);
    let (mut worst, mut worst_used, mut pass) = (0usize, f64::NEG_INFINITY, true);
    let mut ratio = 0f64;
    // The worst pixel's own allowance (per pixel where the bounds are).
    let mut worst_allowed = allowed_abs;
    // Ulps are counted at the case's scale (Tolerance::Ulps).
    let scale = expected
        .iter()
        .filter(|v| !v.is_nan())
        .fold(0f64, |m, v| m.max(v.abs()));
    let mut not_finite = None;
    // The vector file was validated, so both lists have n + 1 values; a shorter list
    // would end the comparison early, so it fails.
    if got.len() != exp.values.len() || exp.levels.len() != exp.values.len() {
        pass = false;
        ratio = f64::INFINITY;
    }
    for (i, (&g, ((ev, &e), &el))) in got
        .iter()
        .zip(exp.values.iter().zip(&expected).zip(&exp.levels))
        .enumerate()
    {
        if !g.is_finite() {
            pass = false;
            if not_finite.is_none() {
                not_finite = Some(i);
                worst = i;
                worst_used = f64::INFINITY;
                ratio = f64::INFINITY;
            }
            continue;
        }
        let d = (g - e).abs();
        // No method comes near 16 times its exact value in magnitude: such a result
        // fails whatever the tolerance (levels clamp, so they alone would pass 1e300).
        let implausible = g.abs() > 16.0 * e.abs().max(1.0);
        let dl = u32::from(level(&g).abs_diff(el));
        let du = d / format.ulp(scale.max(e.abs()));
        max_levels = max_levels.max(dl);
        sum_levels += u64::from(dl);
        max_abs = max_abs.max(d);
        max_ulps = max_ulps.max(du);
        // This pixel's bound: its own where the bounds are per pixel.
        let allowed_abs = per_pixel
            .as_ref()
            .and_then(|b| b.get(i).copied())
            .or(allowed_abs);
        // How much of its own tolerance this pixel uses (0/0, an exact value under a
        // zero tolerance, uses none).
        let used = match tol {
            Tolerance::Levels(n) => f64::from(dl) / f64::from(n),
            Tolerance::Ulps(n) => du / n,
            _ => d / allowed_abs.unwrap_or(0.0),
        };
        let used = if used.is_nan() { 0.0 } else { used };
        // Bounds and their comparison, decided exactly where f64 cannot decide them.
        let over = match (tol, allowed_abs) {
            (Tolerance::Levels(n), _) => dl > n,
            (Tolerance::Ulps(n), _) => du > n,
            (_, None) => d > 0.0,
            (_, Some(b)) => exceeds(g, e, ev, b),
        };
        if over || d.is_nan() || unbounded || implausible {
            pass = false;
        }
        // The worst pixel is the one over its own tolerance most, relative to it, so
        // that the ratio reported is that pixel's.
        if used > worst_used {
            worst_used = used;
            worst = i;
            ratio = used;
            worst_allowed = allowed_abs;
        }
        if implausible || d.is_nan() {
            ratio = f64::INFINITY;
            worst_used = f64::INFINITY;
        }
    }
    // A list of the wrong length, or no bound: no finite ratio.
    if unbounded || got.len() != exp.values.len() || exp.levels.len() != exp.values.len() {
        ratio = f64::INFINITY;
    }
    // 0/0 (an exact result under a zero tolerance) uses none of it.
    if ratio.is_nan() {
        ratio = 0.0;
    }
    let why = unbounded.then(|| {
        tolerance::why_unbounded(tol, method, specular, || duff_q_min_too_small(j, method))
    });
    let allowed = match (&why, tol) {
        (Some(why), _) => why.to_string(),
        (None, Tolerance::Levels(n)) => format!("{n} levels"),
        (None, Tolerance::Ulps(n)) => format!("{n} ulps"),
        (None, _) => format!("{:.3e}", allowed_abs.unwrap_or(0.0)),
    };
    CaseReport {
        id: c.id.clone(),
        case: j.k,
        pixels: got.len(),
        max_levels,
        mean_levels: sum_levels as f64 / got.len().max(1) as f64,
        max_abs,
        max_ulps,
        format,
        scale,
        worst_pixel: worst,
        ratio,
        allowed_abs,
        worst_allowed,
        allowed,
        unbounded: why,
        pass,
        not_finite,
        seconds: 0.0,
    }
}
