//! The exact and MPFR runs of `span`: every digit printed known (exact runs retried
//! with more bits, MPFR refused beyond its precision), levels decided or `None`.
//! [`exact_run`] is the one exact path of the crate (the published vectors and
//! `check`'s recomputation take it too).

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

/// The bits the edge angles `acos p_a`, `acos p_b` of a `normalize` run are known to,
/// from `p`'s error 2^-(b − 18) ([`exact_bits`]): `acos` moves by `e/sin θ`, or at most
/// `2.23·√e`.
fn normalized_angle_bits(span: &Span<BigRational>, b: i64) -> i64 {
    // sin²θ ≥ 1 − (|p| + e)² at both ends (the f64 rounding of p is far above e).
    let s2 = [&span.p_a, &span.p_b]
        .iter()
        .map(|p| 1.0 - (p.to_f64().abs() + 1e-30).powi(2))
        .fold(f64::INFINITY, f64::min);
    let by_slope = if s2 > 0.0 {
        b - 19 - (-0.5 * s2.log2()).ceil() as i64
    } else {
        0
    };
    by_slope.max((b - 18) / 2 - 2)
}

/// `α/π` for an edge of the request whose cosine `p = N·L/(|N||L|)` has `p²` in
/// `{0, ¼, ½, ¾, 1}`, else `None`. Those are the only angles of a rational multiple of
/// π whose cosine has a rational square (Niven's theorem applied to `cos 2α = 2p² − 1`),
/// so only there can a table position be exactly a midpoint, where no precision
/// decides it; there it is computed exactly instead.
fn niven_angle(n: &Vec3<BigRational>, l: &Vec3<BigRational>) -> Option<BigRational> {
    use num_traits::Signed;
    let q = |a: i64, b: i64| BigRational::new(a.into(), b.into());
    let x = n.dot(l);
    let p2 = x.clone() * x.clone() / (n.dot(n) * l.dot(l));
    let a = [
        (q(1, 1), q(0, 1)),
        (q(3, 4), q(1, 6)),
        (q(1, 2), q(1, 4)),
        (q(1, 4), q(1, 3)),
        (q(0, 1), q(1, 2)),
    ]
    .into_iter()
    .find(|(c2, _)| *c2 == p2)
    .map(|(_, a)| a)?;
    Some(if x.is_negative() { q(1, 1) - a } else { a })
}

/// Settles the tabled cosine's index at every pixel (`values` from the exact run at
/// this thread's accuracy 2^-b, `table` the run's table): where both edge angles are
/// rational multiples of π ([`niven_angle`]) the positions are exact rationals and each
/// index is taken from them; elsewhere every position must lie farther than its error
/// from a midpoint `k + ½` between two entries. The error: the angles are within
/// 2^-b (`acos` of exact `p`) or 2^-[`normalized_angle_bits`] (`normalize`) and `π/2`
/// within 2^-b, so `α·(size − 1)/(π/2)` is within `2·(size − 1)·2^-bits`; 4× that is
/// used.
///
/// # Errors
/// The first pixel whose index is not decided at this accuracy.
fn settle_table(
    r: &Request,
    span: &Span<BigRational>,
    size: u32,
    values: &mut [BigRational],
) -> Result<(), usize> {
    use crate::angular::{table_positions, CosTable};
    use num_traits::Signed;
    let Ok(table) = CosTable::<BigRational>::new(size) else {
        return Ok(());
    };
    let last = BigRational::from_integer((size - 1).into());
    if let (Some(a), Some(b)) = (niven_angle(&r.na, &r.l), niven_angle(&r.nb, &r.l)) {
        let n = BigRational::from_integer(r.n.into());
        let two_last = last.clone() * BigRational::from_integer(2.into());
        for (i, v) in values.iter_mut().enumerate() {
            let t = BigRational::from_integer(i.into()) / n.clone();
            let pos = two_last.clone() * (a.clone() + t * (b.clone() - a.clone()));
            *v = table.values[table.index(&pos)].clone();
        }
        return Ok(());
    }
    let b = i64::from(crate::reference::transcendental::bits());
    let bits = if r.normalize {
        normalized_angle_bits(span, b).min(b)
    } else {
        b
    };
    let e = last.clone()
        * BigRational::new(
            8.into(),
            num_bigint::BigInt::from(1) << bits.max(0) as usize,
        );
    let half = BigRational::new(1.into(), 2.into());
    for (i, pos) in table_positions(span, &table).iter().enumerate() {
        let x = pos.clone() + half.clone();
        let k = x.round();
        let inside = k >= BigRational::from_integer(1.into()) && k <= last;
        if inside && (x - k.clone()).abs() <= e {
            // Exactly on the midpoint (decided in rationals), the index is k; else the
            // position is only close to it, and more bits decide its side.
            match (!r.normalize)
                .then(|| exact_midpoint(&span.p_a, &span.p_b, r.n, i, size - 1))
                .flatten()
            {
                Some(true) => {
                    let j = k.to_integer().to_string().parse::<usize>().unwrap_or(0);
                    values[i] = table.values[j.min(size as usize - 1)].clone();
                }
                _ => return Err(i),
            }
        }
    }
    Ok(())
}

/// The most `4·(size − 1)·n'` [`exact_midpoint`] takes on (the power's exponent: the
/// rationals it builds have about that many times the digits of `p`).
const MIDPOINT_EXPONENT: u64 = 1 << 18;

/// Whether the angle of pixel `i`, `α_i = ((n − i)α_a + i·α_b)/n` with `cos α = p`
/// (exact rationals in `[−1, 1]`), is exactly a midpoint between two table angles,
/// `(2k + 1)·π/(4·last)`, `last = size − 1`; `None` where that costs more than
/// [`MIDPOINT_EXPONENT`] allows. With `d = gcd(i, n)`, `n' = n/d`, `i' = i/d`: a
/// midpoint gives `4·last·((n' − i')α_a + i'α_b) = (2k + 1)·n'·π`, so `z_a^{4·last·(n' −
/// i')}·z_b^{4·last·i'} = (−1)^{n'}` with `z = e^{iα} = p + i·√(1 − p²)`; conversely that
/// equality puts `α_i` on a grid of spacing `2π/(4·last·n')` through the midpoint, and
/// the caller has `α_i` far closer than that to it. The powers are `A + i·s·B` with `A`,
/// `B` rational (Chebyshev: `s = sin α`), and the equality is decided in rationals.
fn exact_midpoint(pa: &BigRational, pb: &BigRational, n: u32, i: usize, last: u32) -> Option<bool> {
    use num_integer::Integer;
    use num_traits::{One, Signed, Zero};
    let i = u64::try_from(i).ok()?;
    let d = i.gcd(&u64::from(n)).max(1);
    let (n1, i1) = (u64::from(n) / d, i / d);
    let m = 4 * u64::from(last);
    if m.checked_mul(n1)? > MIDPOINT_EXPONENT {
        return None;
    }
    let one = BigRational::one();
    // (p + i·s)^e as (A, B) with s² = 1 − p² (binary powering).
    let power = |p: &BigRational, e: u64| -> (BigRational, BigRational) {
        let s2 = one.clone() - p.clone() * p.clone();
        let mul = |(a1, b1): &(BigRational, BigRational), (a2, b2): &(BigRational, BigRational)| {
            (
                a1.clone() * a2.clone() - s2.clone() * b1.clone() * b2.clone(),
                a1.clone() * b2.clone() + b1.clone() * a2.clone(),
            )
        };
        let (mut acc, mut base, mut e) = (
            (one.clone(), BigRational::zero()),
            (p.clone(), one.clone()),
            e,
        );
        while e > 0 {
            if e & 1 == 1 {
                acc = mul(&acc, &base);
            }
            e >>= 1;
            if e > 0 {
                base = mul(&base, &base);
            }
        }
        acc
    };
    let (aa, ba) = power(pa, m * (n1 - i1));
    let (ab, bb) = power(pb, m * i1);
    let (ra, rb) = (
        one.clone() - pa.clone() * pa.clone(),
        one.clone() - pb.clone() * pb.clone(),
    );
    // x = y·√r, exactly (r ≥ 0).
    let sign = |x: &BigRational| {
        if x.is_zero() {
            0
        } else if x.is_positive() {
            1
        } else {
            -1
        }
    };
    let eq_root = |x: &BigRational, y: &BigRational, r: &BigRational| {
        let sy = if r.is_zero() { 0 } else { sign(y) };
        sign(x) == sy && x.clone() * x.clone() == y.clone() * y.clone() * r.clone()
    };
    // Real part: A_a·A_b − s_a·s_b·B_a·B_b = (−1)^{n'}.
    let target = if n1 % 2 == 0 {
        one.clone()
    } else {
        -one.clone()
    };
    let real = eq_root(
        &(aa.clone() * ab.clone() - target),
        &(ba.clone() * bb.clone()),
        &(ra.clone() * rb.clone()),
    );
    // Imaginary part: s_a·B_a·A_b + s_b·A_a·B_b = 0, i.e. B_a·A_b·√r_a = −A_a·B_b·√r_b.
    let (p, q) = (ba * ab, -(aa * bb));
    let sp = if ra.is_zero() { 0 } else { sign(&p) };
    let sq = if rb.is_zero() { 0 } else { sign(&q) };
    let imag = sp == sq && p.clone() * p * ra == q.clone() * q * rb;
    Some(real && imag)
}

/// Settles a `normalize` run's adaptive decision exactly
/// ([`crate::reference::radical::normalized_adaptive_gouraud`]): where the run's
/// approximate square roots picked the other method, the values are those of the
/// method the exact test picks, on the same span.
fn settle_adaptive(
    r: &Request,
    span: &Span<BigRational>,
    d: &mut Decision<BigRational>,
    values: &mut [BigRational],
) -> Result<(), ReportError> {
    use crate::adaptive::Choice;
    if !r.normalize {
        return Ok(());
    }
    let exact =
        if crate::reference::radical::normalized_adaptive_gouraud((&r.na, &r.nb, &r.l), r.n, &r.kd)
        {
            Choice::Gouraud
        } else {
            Choice::CorrectedEuler
        };
    if exact != d.choice {
        d.choice = exact;
        match exact {
            Choice::Gouraud => crate::gouraud::shade(span, values),
            Choice::CorrectedEuler => crate::corrected_euler::shade(span, values),
        }
        .map_err(|e| span_error(e, r.normalize))?;
    }
    Ok(())
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
    i64::from(precision) - 8 - 2 * n_bits - loss
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

/// The decisions an MPFR run takes from rounded values, checked against the exact
/// ones: the adaptive choice (eq. 24 in rationals, or in `Q(√a, √b, √c)` with
/// `normalize`) must be the exact one, and every tabled cosine's position must lie
/// farther than its error (`2^-bits`, [`mpfr_bits`], times `8·(size − 1)`) from a
/// midpoint between two entries; else the values are not the method's to the digits
/// claimed, and the run is refused (the exact run decides them).
#[cfg(feature = "mpfr")]
fn mpfr_decisions(
    r: &Request,
    span: &Span<crate::reference::mpfr::Mpfr>,
    exact: Option<&Span<BigRational>>,
    decision: Option<&Decision<crate::reference::mpfr::Mpfr>>,
    bits: i64,
    precision: u32,
) -> Result<(), ReportError> {
    use crate::adaptive::Choice;
    use num_traits::Signed;
    let refuse = |what: String| {
        Err(ReportError::new(
            Field::Arithmetic,
            format!("{what} at {precision} bits of MPFR: the exact run decides it (the exact number type), or ask for more bits"),
        ))
    };
    if let Some(d) = decision {
        let gouraud = match exact {
            Some(x) => crate::adaptive::decide(x, &r.kd).choice == Choice::Gouraud,
            None => crate::reference::radical::normalized_adaptive_gouraud(
                (&r.na, &r.nb, &r.l),
                r.n,
                &r.kd,
            ),
        };
        let want = if gouraud {
            Choice::Gouraud
        } else {
            Choice::CorrectedEuler
        };
        if d.choice != want {
            return refuse(format!(
                "eq. 24's test picks {} where the exact test picks {} (255·|δ| is within the rounding of 1)",
                d.choice.name(),
                want.name()
            ));
        }
    }
    if let Method::AngularTable(size) = r.method {
        use crate::angular::{table_positions, CosTable};
        let Ok(table) = CosTable::<crate::reference::mpfr::Mpfr>::new(size) else {
            return Ok(());
        };
        let last = BigRational::from_integer((size - 1).into());
        let e = last.clone()
            * BigRational::new(
                8.into(),
                num_bigint::BigInt::from(1) << bits.max(0) as usize,
            );
        let half = BigRational::new(1.into(), 2.into());
        for (i, pos) in table_positions(span, &table).iter().enumerate() {
            let Some(x) = pos.to_rational().map(|p| p + half.clone()) else {
                continue;
            };
            let k = x.round();
            let inside = k >= BigRational::from_integer(1.into()) && k <= last;
            if inside && (x - k).abs() <= e {
                return refuse(format!(
                    "the cosine table's entry at pixel {i} is not decided (its angle is within the rounding of a midpoint between two table angles)"
                ));
            }
        }
    }
    Ok(())
}

#[cfg(not(feature = "mpfr"))]
pub(super) fn run_mpfr(_r: &Request, _precision: u32) -> Result<Outcome, ReportError> {
    Err(ReportError::new(Field::Arithmetic, "mpfr is not in this build").or(Remedy::BuildWithMpfr))
}
