//! The decisions an exact or MPFR run takes from values known only to finite
//! precision — a tabled cosine's index, the adaptive test's choice — made exactly:
//! proved on their side of the boundary, decided in rationals (or in `Q(√a, √b, √c)`),
//! or left to more bits ([`super::exact::exact_run`] retries; an MPFR run is refused).

use super::*;

/// The bits the edge angles `acos p_a`, `acos p_b` of a `normalize` run are known to,
/// from `p`'s error 2^-(b − 18) (`exact::exact_bits`): `acos` moves by `e/sin θ`, or at most
/// `2.23·√e`.
pub(super) fn normalized_angle_bits(span: &Span<BigRational>, b: i64) -> i64 {
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
pub(super) fn settle_table(
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

/// The most bits [`exact_midpoint`] lets its powers grow to (`4·(size − 1)·n'` times
/// the bits of the edge cosines' numerators and denominators): about 2^23 bits, a
/// second or so of integer arithmetic.
const MIDPOINT_BITS: u64 = 1 << 23;

/// Whether the angle of pixel `i`, `α_i = ((n − i)α_a + i·α_b)/n` with `cos α = p`
/// (exact rationals in `[−1, 1]`), is exactly a midpoint between two table angles,
/// `(2k + 1)·π/(4·last)`, `last = size − 1`, for a pixel whose position the caller
/// already knows to lie within far less than a table step of one; `None` where that
/// costs more than [`MIDPOINT_BITS`] allows. With `d = gcd(i, n)`, `n' = n/d`, `i' = i/d`: a midpoint
/// gives `4·last·((n' − i')α_a + i'α_b) = (2k + 1)·n'·π`, so `z_a^{e_a}·z_b^{e_b} =
/// (−1)^{n'}` with `z = e^{iα} = p + i·√(1 − p²)`, `e_a = 4·last·(n' − i')`, `e_b =
/// 4·last·i'`; conversely that equality puts `α_i` on a grid of spacing
/// `2π/(4·last·n')` through the midpoint, and the caller has `α_i` far closer than
/// that to it. With `p = a/d`, `z^e = (A + i·√R·B)/d^e`, `R = d² − a²`, `A`, `B`
/// integers (Chebyshev), and the equality is decided in integers. A pixel at an edge
/// (`i' = 0` or `i' = n'`) is a midpoint only where its cosine is in `{0, ±½, ±1}`
/// (Niven: a rational cosine of a rational multiple of π), so no power is taken there.
fn exact_midpoint(pa: &BigRational, pb: &BigRational, n: u32, i: usize, last: u32) -> Option<bool> {
    use num_bigint::BigInt;
    use num_integer::Integer;
    use num_traits::{One, Signed, Zero};
    let i = u64::try_from(i).ok()?;
    let g = i.gcd(&u64::from(n)).max(1);
    let (n1, i1) = (u64::from(n) / g, i / g);
    let m = 4 * u64::from(last);
    let q = |a: i64, b: i64| BigRational::new(a.into(), b.into());
    if i1 == 0 || i1 == n1 {
        // α_i = α_a (or α_b): a rational multiple of π only at Niven's cosines.
        let p = if i1 == 0 { pa } else { pb };
        let a = [
            (q(1, 1), q(0, 1)),
            (q(1, 2), q(1, 3)),
            (q(0, 1), q(1, 2)),
            (q(-1, 2), q(2, 3)),
            (q(-1, 1), q(1, 1)),
        ]
        .into_iter()
        .find(|(c, _)| c == p)
        .map(|(_, a)| a);
        return Some(a.is_some_and(|a| {
            let pos = BigRational::from_integer((2 * last).into()) * a + q(1, 2);
            pos.is_integer()
        }));
    }
    let (ea, eb) = (m.checked_mul(n1 - i1)?, m.checked_mul(i1)?);
    let bits = |p: &BigRational| p.numer().bits() + p.denom().bits();
    if ea
        .checked_mul(bits(pa))?
        .checked_add(eb.checked_mul(bits(pb))?)?
        > MIDPOINT_BITS
    {
        return None;
    }
    // (a + i·√R)^e as (A, B): A + i·√R·B, R = d² − a² (binary powering, integers only).
    let power = |a: &BigInt, r: &BigInt, e: u64| -> (BigInt, BigInt) {
        let mul = |(a1, b1): &(BigInt, BigInt), (a2, b2): &(BigInt, BigInt)| {
            (a1 * a2 - r * b1 * b2, a1 * b2 + b1 * a2)
        };
        let (mut acc, mut base, mut e) = (
            (BigInt::one(), BigInt::zero()),
            (a.clone(), BigInt::one()),
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
    let (na, da) = (pa.numer().clone(), pa.denom().clone());
    let (nb, db) = (pb.numer().clone(), pb.denom().clone());
    let (ra, rb) = (&da * &da - &na * &na, &db * &db - &nb * &nb);
    let (aa, ba) = power(&na, &ra, ea);
    let (ab, bb) = power(&nb, &rb, eb);
    let scale = num_traits::pow::pow(da, ea as usize) * num_traits::pow::pow(db, eb as usize);
    let sign = |x: &BigInt| {
        if x.is_zero() {
            0
        } else if x.is_positive() {
            1
        } else {
            -1
        }
    };
    // x = y·√r exactly (r ≥ 0).
    let eq_root = |x: &BigInt, y: &BigInt, r: &BigInt| {
        let sy = if r.is_zero() { 0 } else { sign(y) };
        sign(x) == sy && x * x == y * y * r
    };
    // Real part: A_a·A_b − √(R_a·R_b)·B_a·B_b = (−1)^{n'}·d_a^{e_a}·d_b^{e_b}.
    let target = if n1 % 2 == 0 { scale } else { -scale };
    let real = eq_root(&(&aa * &ab - target), &(&ba * &bb), &(&ra * &rb));
    // Imaginary part: √R_a·B_a·A_b = −√R_b·A_a·B_b.
    let (p, q2) = (&ba * &ab, -(&aa * &bb));
    let sp = if ra.is_zero() { 0 } else { sign(&p) };
    let sq = if rb.is_zero() { 0 } else { sign(&q2) };
    let imag = sp == sq && &p * &p * &ra == &q2 * &q2 * &rb;
    Some(real && imag)
}

/// Settles a `normalize` run's adaptive decision exactly
/// ([`crate::reference::radical::normalized_adaptive_gouraud`]): where the run's
/// approximate square roots picked the other method, the values are those of the
/// method the exact test picks, on the same span.
pub(super) fn settle_adaptive(
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

/// The decisions an MPFR run takes from rounded values, checked against the exact
/// ones: the adaptive choice (eq. 24 in rationals, or in `Q(√a, √b, √c)` with
/// `normalize`) must be the exact one, and every tabled cosine's position must lie
/// farther than its error (`2^-bits`, `exact::mpfr_bits`, times `8·(size − 1)`) from a
/// midpoint between two entries; else the values are not the method's to the digits
/// claimed, and the run is refused (the exact run decides them).
#[cfg(feature = "mpfr")]
pub(super) fn mpfr_decisions(
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

#[cfg(test)]
mod tests {
    use super::*;

    fn q(a: i64, b: i64) -> BigRational {
        BigRational::new(a.into(), b.into())
    }

    #[test]
    fn midpoints_are_decided_in_integers() {
        // acos(3/5) + acos(4/5) = π/2: pixel 8 of 16 is at π/4, position 127.5 of the
        // 256-entry table. (The answer means something only for a pixel whose position
        // is already known to lie near a midpoint, as `settle_table` asks.)
        assert_eq!(exact_midpoint(&q(3, 5), &q(4, 5), 16, 8, 255), Some(true));
        // The same angle for the other pairs of steps that reach it: 2 of 4, 4 of 8.
        assert_eq!(exact_midpoint(&q(3, 5), &q(4, 5), 4, 2, 255), Some(true));
        assert_eq!(exact_midpoint(&q(4, 5), &q(3, 5), 8, 4, 255), Some(true));
        // At an edge only the cosines 0, ±½, ±1 are rational multiples of π, and their
        // positions (0, 85·2, 255, …) are entries: never a midpoint.
        for p in [q(1, 2), q(0, 1), q(-1, 2), q(1, 1), q(3, 5)] {
            assert_eq!(exact_midpoint(&p, &q(4, 5), 16, 0, 255), Some(false), "{p}");
            assert_eq!(
                exact_midpoint(&q(4, 5), &p, 16, 16, 255),
                Some(false),
                "{p}"
            );
        }
        // Powers past the budget are not taken.
        let big = BigRational::new(1.into(), num_bigint::BigInt::from(10).pow(400u32));
        assert_eq!(exact_midpoint(&big, &q(4, 5), 4096, 1, 255), None);
    }
}
