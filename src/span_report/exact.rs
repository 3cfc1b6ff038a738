//! The exact and MPFR runs of `span`: every digit printed known (exact runs retried
//! with more bits, MPFR refused beyond its precision), levels decided or `None`.
//! [`exact_run`] is the one exact path of the crate (the published vectors and
//! `check`'s recomputation take it too).

#[cfg(feature = "mpfr")]
use super::decide::mpfr_decisions;
use super::decide::{normalized_angle_bits, settle_adaptive, settle_table};
use super::*;

/// Where the digits asked for are more than is known: the first such pixel and how
/// many significant digits of it are known.
struct Short {
    pixel: usize,
    known: usize,
}

impl Short {
    fn error(&self, bits: i64) -> ReportError {
        let message = if self.known == 0 {
            format!(
                "no digit of pixel {} is known: computed to 2^-{bits}, the value lies within that of 0 or of a change of its leading digit",
                self.pixel
            )
        } else {
            format!(
                "only {} significant digits of pixel {} are known (these values are computed to 2^-{bits}); ask for at most that many",
                self.known, self.pixel
            )
        };
        ReportError::new(Field::Digits, message)
    }
}

/// Where a value of exactly 0 is the method's exact value, not a rounded one: a tabled
/// cosine's last entry, and a pixel whose exact value is Phong's `p/√q` ([`crate::method::PhongPixels::exact_at`])
/// with `p = 0` on the exact span. With `normalize` the span's inputs are themselves
/// rounded, and only the end pixels keep an exact zero (`N_a·L = 0` or `N_b·L = 0` on
/// the inputs as given: normalizing scales a dot product, it cannot make it zero).
fn exact_zeros(r: &Request) -> impl Fn(usize) -> bool + '_ {
    use num_traits::Zero;
    let phong = r.method.info().phong_pixels;
    let span = (!r.normalize)
        .then(|| Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok())
        .flatten();
    move |i: usize| {
        let Ok(i) = u32::try_from(i) else {
            return false;
        };
        // A tabled cosine of 0 is the table's last entry, cos 90° = 0, held exactly
        // (`angular::CosTable::new`).
        if phong == crate::method::PhongPixels::Table {
            return true;
        }
        match &span {
            Some(s) => phong.exact_at(s, i).is_some_and(|(p, _)| p.is_zero()),
            None => {
                let end = (i == 0).then_some(&r.na).or((i == r.n).then_some(&r.nb));
                end.is_some_and(|n| phong.at(r.n, i) && n.dot(&r.l).is_zero())
            }
        }
    }
}

/// Checks that every value's digits are known: a value's digits are printed only if
/// its lower and upper ends (±2^-bits) print the same. A value of 0 is printed as `0`
/// only where it is exactly zero (`exact_zero(pixel)`); elsewhere a computed 0 is a
/// value within 2^-bits of zero like any other, whose first digit is not known.
fn check_digits<T: Real>(
    r: &Request,
    values: &[T],
    bits: i64,
    exact_zero: impl Fn(usize) -> bool,
) -> Result<(), Short> {
    use num_traits::One;
    if bits < 4 {
        return Err(Short { pixel: 0, known: 0 });
    }
    let e = BigRational::new(
        num_bigint::BigInt::one(),
        num_bigint::BigInt::one() << (bits as usize),
    );
    for (i, v) in values.iter().enumerate() {
        let Some(v) = v.to_rational() else {
            continue;
        };
        if num_traits::Zero::is_zero(&v) && exact_zero(i) {
            continue;
        }
        let (lo, hi) = (v.clone() - e.clone(), v.clone() + e.clone());
        if lo.to_decimal(r.digits) != hi.to_decimal(r.digits) {
            // About log10(|v|/e) digits are known: search down from just above that
            // (not from the digits asked for, which may be thousands).
            let guess = ((v.to_f64().abs().max(f64::MIN_POSITIVE).log2() + bits as f64)
                * std::f64::consts::LOG10_2)
                .max(0.0) as usize
                + 2;
            let known = (1..r.digits.min(guess + 1))
                .rev()
                .find(|&d| lo.to_decimal(d) == hi.to_decimal(d))
                .unwrap_or(0);
            return Err(Short { pixel: i, known });
        }
    }
    Ok(())
}

/// The bits known of the exact values ([`Method::exact_bits`]). Rational methods on
/// exact inputs are exact (`None`: every digit is known).
///
/// With `normalize` the inputs are normalized through square roots accurate to
/// 2^-b (`b` = [`crate::reference::transcendental::bits`], 256 unless the run asks
/// for more), so `p_a`, `p_b` and every dot product are off by at most 2^-(b − 18):
/// what the exact run's own accounting allows for an error of 2^-(b − 6), less 16
/// bits, and at most `b − 76` bits (180 at the default). Angular interpolation takes
/// `acos p`, which moves by `e/sin θ` (or at most `2.23·√e`, acos being ½-Hölder with
/// constant `π/√2`) when `p` moves by `e`: `max(b − 19 − ⌈log2(1/sin θ)⌉, (b − 18)/2 − 2)`
/// bits.
fn exact_bits(r: &Request, span: &Span<BigRational>) -> Option<i64> {
    if !r.normalize {
        return r.method.exact_bits(span);
    }
    let b = i64::from(crate::reference::transcendental::bits());
    let own = r
        .method
        .exact_bits(span)
        .map_or(b - 76, |own| (own - 16).min(b - 76));
    if !matches!(r.method, Method::Angular) {
        return Some(own);
    }
    Some(own.min(normalized_angle_bits(span, b)))
}

/// Why an exact attempt at some accuracy is not enough: digits not known, or a
/// tabled cosine's index not decided (its pixel).
enum Retry {
    Short(Short, i64),
    Index(usize),
}

/// The bits known of MPFR values at `precision` bits: every operation is correctly
/// rounded, and the recurrences' rounding grows at most like `n²` steps of the
/// unit roundoff (docs/float.md §6–8), plus `q_bits` for the Phong-valued methods and
/// what [`Method::exact_bits`] says the exact run loses for the others (`span`, the
/// exact span of the request); 8 bits of margin.
#[cfg(feature = "mpfr")]
fn mpfr_bits(r: &Request, span: Option<&Span<BigRational>>, precision: u32, q_bits: i64) -> i64 {
    let n_bits = 64 - u64::from(r.n + 1).leading_zeros() as i64;
    // In MPFR `q` is rounded too: the Phong-valued methods lose all of `q_bits`;
    // the others what the exact run loses (`Method::exact_bits`).
    let loss = if r.method.is_phong_valued() {
        q_bits
    } else {
        span.map_or(0, |s| r.method.exact_bits(s).map_or(0, |b| 250 - b))
    };
    let known = i64::from(precision) - 8 - 2 * n_bits - loss;
    // A root of a recurrence's value (the catalogue's `Roots::SignedRootOfG`: the
    // squared method's `√max(0, g)`): an error `δ` of `g` moves the root by up to `√δ`
    // (`sq_root_holder`), half the bits.
    if r.method.info().roots == crate::method::Roots::SignedRootOfG {
        known / 2 - 1
    } else {
        known
    }
}

/// The levels of an exact `normalize` run: from `values` (known to `2^-bits`) where
/// that decides them, else exactly for the normalized inputs
/// ([`crate::reference::radical`]) at the pixels whose value is known in closed form:
/// Phong's `p/√q` where the method's is, Gouraud's, Euler's and corrected Euler's
/// everywhere; undecided (`None`) elsewhere.
fn normalized_levels(r: &Request, values: &[BigRational], bits: i64) -> Vec<Option<u8>> {
    use crate::method::PhongPixels;
    use crate::reference::radical::{normalized_levels, Valued};
    use num_traits::Zero;
    let phong = r.method.info().phong_pixels;
    let cross = Vec3::new(
        r.na.y.clone() * r.nb.z.clone() - r.na.z.clone() * r.nb.y.clone(),
        r.na.z.clone() * r.nb.x.clone() - r.na.x.clone() * r.nb.z.clone(),
        r.na.x.clone() * r.nb.y.clone() - r.na.y.clone() * r.nb.x.clone(),
    );
    // Parallel edge normals: every untabled method is the constant p_a there.
    let parallel = cross.length_squared().is_zero()
        && r.na.dot(&r.nb) > BigRational::zero()
        && !matches!(phong, PhongPixels::None | PhongPixels::Table);
    let field = r.method.info().closed_form;
    let e = BigRational::new(
        1.into(),
        num_bigint::BigInt::from(1) << bits.max(0) as usize,
    );
    let one = BigRational::from_integer(1.into());
    normalized_levels(
        |i| {
            if parallel || phong.at(r.n, i) {
                Some(Valued::Phong)
            } else {
                field
            }
        },
        (&r.na, &r.nb, &r.l),
        r.n,
        &one,
        values,
        &e,
    )
}

/// The most bits an exact run takes to decide a level near a boundary (2^-1024).
const LEVEL_BITS: u32 = 1024;

/// An exact run with every printed digit known: the values, the adaptive decision,
/// the levels (`None` where undecided), the bits the values are known to (`None`:
/// exact).
pub struct ExactRun {
    /// The exact run's values (within 2^-`bits` of the method's exact values).
    pub values: Vec<BigRational>,
    /// Each value to the request's digits, every digit known (a value is `0` only
    /// where it is exactly zero).
    pub decimals: Vec<String>,
    /// The 8-bit levels, `None` where the run does not decide them.
    pub levels: Vec<Option<u8>>,
    /// The bits the values are known to (`None`: exact).
    pub bits: Option<i64>,
    decision: Option<Decision<BigRational>>,
}

/// Runs `r` in exact arithmetic (its `arithmetic` is not read) with square roots,
/// `acos` and `cos` to more bits (from 2^-256 up to 2^-`MAX_BITS`) until every
/// value's `r.digits` significant digits are known, and up to 2^-1024 while a level
/// is within the values' error of a boundary; the one path `span --scalar
/// exact`, the published vectors and `check`'s recomputation of a modified file take.
///
/// # Errors
/// A [`ReportError`]: inputs the span refuses, or digits not known at 2^-`MAX_BITS`.
pub fn exact_run(r: &Request) -> Result<ExactRun, ReportError> {
    use crate::reference::transcendental::{with_bits, BITS, MAX_BITS};
    digits_within_reach(r)?;
    let mut b = BITS;
    loop {
        let attempt = with_bits(b, || -> Result<Result<ExactRun, Retry>, ReportError> {
            let (span, mut values, mut decision) = compute::<BigRational>(r)?;
            if let Some(d) = decision.as_mut() {
                settle_adaptive(r, &span, d, &mut values)?;
            }
            if let Method::AngularTable(size) = r.method {
                if let Err(pixel) = settle_table(r, &span, size, &mut values) {
                    return Ok(Err(Retry::Index(pixel)));
                }
            }
            let known = exact_bits(r, &span);
            if let Some(bits) = known {
                if let Err(short) = check_digits(r, &values, bits, exact_zeros(r)) {
                    return Ok(Err(Retry::Short(short, bits)));
                }
            }
            // Phong-valued methods: the exact level of p/√q decided with rationals
            // only; with normalize, in Q(√a, √b, √c) where the approximate value
            // does not decide it.
            let one = BigRational::from_integer(1.into());
            let levels = if r.normalize {
                normalized_levels(r, &values, known.unwrap_or(0))
            } else {
                r.method.exact_levels(&span, &values, &one)
            };
            let decimals = values.iter().map(|v| v.to_decimal(r.digits)).collect();
            Ok(Ok(ExactRun {
                values,
                decimals,
                levels,
                bits: known,
                decision,
            }))
        })?;
        match attempt {
            // A level within the run's error of a boundary: decided, if at all, by a
            // few more bits (up to 2^-LEVEL_BITS; closer than that it stays undecided:
            // `span` prints `?`, the vectors refuse the case).
            Ok(o) if o.levels.iter().any(Option::is_none) && b < LEVEL_BITS => b *= 2,
            Ok(o) => return Ok(o),
            Err(Retry::Index(pixel)) if b >= MAX_BITS => {
                return Err(ReportError::new(
                    Field::Span,
                    format!(
                        "the cosine table's entry at pixel {pixel} is not decided: its angle is within the run's error of the midpoint between two table angles even at the most bits an exact run takes (2^-{MAX_BITS})"
                    ),
                ))
            }
            Err(Retry::Index(_)) => b = (2 * b).min(MAX_BITS),
            Err(Retry::Short(short, bits)) if b >= MAX_BITS => return Err(short.error(bits)),
            Err(Retry::Short(short, _)) => {
                let missing = r.digits.saturating_sub(short.known) as f64;
                let more = (missing / std::f64::consts::LOG10_2).ceil() as u32 + 16;
                b = (b + more).max(2 * b).min(MAX_BITS);
            }
        }
    }
}

pub(super) fn run_exact(r: &Request) -> Result<Outcome, ReportError> {
    let run = exact_run(r)?;
    // Fractions only where the values are the exact rationals: a rational method on
    // the inputs as given (normalizing takes square roots, so the values are then
    // approximations of irrational numbers).
    let fractions = (r.method.is_rational() && !r.normalize)
        .then(|| run.values.iter().map(ToString::to_string).collect());
    let mut o = outcome(r, run.values, run.decision, Some(run.levels));
    o.fractions = fractions;
    o.values = Values::eager(run.decimals);
    Ok(o)
}

/// The digits asked of a method whose exact values are not rational: at most what
/// 2^-`MAX_BITS` gives, refused before any work.
fn digits_within_reach(r: &Request) -> Result<(), ReportError> {
    use crate::reference::transcendental::MAX_BITS;
    let most = (f64::from(MAX_BITS - 64) * std::f64::consts::LOG10_2) as usize;
    if !r.method.is_rational() && r.digits > most {
        return Err(ReportError::new(
            Field::Digits,
            format!(
                "at most {most} significant digits of {} are computed (its square roots, acos and cos to 2^-{}); ask for at most that many",
                r.method,
                MAX_BITS
            ),
        ));
    }
    Ok(())
}

#[cfg(feature = "mpfr")]
pub(super) fn run_mpfr(r: &Request, precision: u32) -> Result<Outcome, ReportError> {
    use crate::reference::mpfr::{with_precision, Mpfr};
    with_precision(precision, || {
        let (span, values, decision) = compute::<Mpfr>(r)?;
        let exact = if r.normalize {
            None
        } else {
            Span::new(r.na.clone(), r.nb.clone(), r.l.clone(), r.n).ok()
        };
        let bits = mpfr_bits(
            r,
            exact.as_ref(),
            precision,
            crate::method::log2_recip(span.q_min().to_f64()),
        );
        mpfr_decisions(r, &span, exact.as_ref(), decision.as_ref(), bits, precision)?;
        check_digits(r, &values, bits, exact_zeros(r)).map_err(|s| s.error(bits))?;
        // A level is printed only where it is known: decided exactly where the value
        // is (Phong's p/√q, p_a), else only where its error cannot cross a boundary.
        let rationals: Vec<BigRational> = values.iter().filter_map(|v| v.to_rational()).collect();
        let levels = match &exact {
            Some(x) if rationals.len() == values.len() => {
                let one = BigRational::from_integer(1.into());
                r.method.levels_within(x, &rationals, &one, Some(bits))
            }
            _ => {
                let e = BigRational::new(
                    1.into(),
                    num_bigint::BigInt::from(1) << bits.max(0) as usize,
                );
                values
                    .iter()
                    .map(|v| {
                        v.to_rational()
                            .and_then(|x| crate::reference::level::level_within(&x, &e))
                    })
                    .collect()
            }
        };
        // Formatted here, within the precision the values were computed at.
        let mut o = outcome(r, values, decision, Some(levels));
        o.values = Values::eager(o.values.iter().collect());
        Ok(o)
    })
}

#[cfg(not(feature = "mpfr"))]
pub(super) fn run_mpfr(_r: &Request, _precision: u32) -> Result<Outcome, ReportError> {
    Err(ReportError::new(Field::Arithmetic, "mpfr is not in this build").or(Remedy::BuildWithMpfr))
}
