//! Reading numbers exactly: decimals (`0.6`, `-1e-3`) and fractions (`2/3`) become
//! exact rationals, so the exact scalar sees exactly what was typed and the float
//! scalars get the nearest float to it.

use crate::vector::Vec3;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;
use thiserror::Error;

/// Why a number or vector could not be read.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum ParseError {
    /// Not a decimal or fraction.
    #[error("'{0}' is not a number (write a decimal like 0.6 or -1e-3, or a fraction like 2/3)")]
    NotANumber(String),
    /// A fraction with denominator zero.
    #[error("'{0}' has a zero denominator")]
    ZeroDenominator(String),
    /// An exponent too large to be meant.
    #[error("'{0}' has an exponent outside ±1000")]
    ExponentRange(String),
    /// Longer than [`MAX_NUMBER_CHARS`] characters.
    #[error("a number of {0} characters is longer than {max} (write it as a fraction of shorter numbers)", max = MAX_NUMBER_CHARS)]
    TooLong(usize),
    /// Not three comma-separated components.
    #[error("expected three components x,y,z, got {0}")]
    Arity(usize),
    /// A component failed to parse.
    #[error("component {index} {source}")]
    Component {
        /// 1-based component index.
        index: usize,
        /// What was wrong with it.
        source: Box<ParseError>,
    },
}

/// The longest number read: digits beyond a few hundred are not meant, and the
/// exact arithmetic on them would take time and memory in proportion.
pub const MAX_NUMBER_CHARS: usize = 400;

/// Parses a decimal (`0.6`, `-1e-3`, `+2.`, `.5E2`) or a fraction of two decimals
/// (`2/3`, `1/1e3`) exactly.
///
/// # Errors
/// [`ParseError`] for anything else, a zero denominator, `|exponent| > 1000`, or more
/// than [`MAX_NUMBER_CHARS`] characters
/// (`inf` and `nan` are not numbers here).
pub fn parse_rational(s: &str) -> Result<BigRational, ParseError> {
    let t = s.trim();
    if t.chars().count() > MAX_NUMBER_CHARS {
        return Err(ParseError::TooLong(t.chars().count()));
    }
    let not_a_number = || ParseError::NotANumber(crate::error::shown(s));
    if let Some((a, b)) = t.split_once('/') {
        let num = parse_decimal(a.trim()).ok_or_else(not_a_number)?;
        let den = parse_decimal(b.trim()).ok_or_else(not_a_number)?;
        let (num, den) = (num?, den?);
        if den.is_zero() {
            return Err(ParseError::ZeroDenominator(crate::error::shown(s)));
        }
        return Ok(num / den);
    }
    parse_decimal(t).ok_or_else(not_a_number)?
}

/// `None` when `t` is not of decimal form; `Some(Err)` for an absurd exponent.
fn parse_decimal(t: &str) -> Option<Result<BigRational, ParseError>> {
    let (neg, body) = match t.as_bytes().first()? {
        b'-' => (true, &t[1..]),
        b'+' => (false, &t[1..]),
        _ => (false, t),
    };
    let (mant, exp) = match body.bytes().position(|c| c == b'e' || c == b'E') {
        Some(p) => (&body[..p], Some(&body[p + 1..])),
        None => (body, None),
    };
    let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
    if int.is_empty() && frac.is_empty() {
        return None;
    }
    if !int.bytes().chain(frac.bytes()).all(|c| c.is_ascii_digit()) {
        return None;
    }
    let mut e: i64 = match exp {
        None => 0,
        Some(x) => {
            let digits = x.strip_prefix(['+', '-']).unwrap_or(x);
            if digits.is_empty() || !digits.bytes().all(|c| c.is_ascii_digit()) {
                return None;
            }
            match x.parse::<i64>() {
                Ok(v) if v.abs() <= 1000 => v,
                _ => return Some(Err(ParseError::ExponentRange(t.to_string()))),
            }
        }
    };
    e -= frac.len() as i64;
    // Up to 38 digits fit a u128 (the vectors' values carry 30).
    let m: BigInt = if int.len() + frac.len() <= 38 {
        let fold = |a: u128, c: u8| a * 10 + u128::from(c - b'0');
        BigInt::from(int.bytes().chain(frac.bytes()).fold(0u128, fold))
    } else {
        format!("{int}{frac}").parse().ok()?
    };
    let m = if neg { -m } else { m };
    if e >= 0 {
        return Some(Ok(BigRational::from_integer(
            m * BigInt::from(10).pow(e as u32),
        )));
    }
    Some(Ok(over_power_of_ten(m, (-e) as u32)))
}

/// `m/10^k` in lowest terms without a general gcd: the only common factors are the
/// 2s and 5s of `m` (at most `k` of each), taken out directly.
fn over_power_of_ten(m: BigInt, k: u32) -> BigRational {
    use num_integer::Integer;
    if m.is_zero() {
        return BigRational::zero();
    }
    let twos = m.trailing_zeros().map_or(0, |t| t.min(u64::from(k)) as u32);
    let mut m = m >> twos;
    let five = BigInt::from(5);
    let mut fives = 0;
    while fives < k {
        let (q, r) = m.div_rem(&five);
        if !r.is_zero() {
            break;
        }
        m = q;
        fives += 1;
    }
    let den = (BigInt::from(1) << (k - twos)) * five.pow(k - fives);
    BigRational::new_raw(m, den)
}

/// Parses `x,y,z` into an exact vector.
///
/// # Errors
/// [`ParseError::Arity`] unless there are exactly three components, or
/// [`ParseError::Component`] naming the first bad one.
pub fn parse_vec3(s: &str) -> Result<Vec3<BigRational>, ParseError> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() != 3 {
        return Err(ParseError::Arity(if s.trim().is_empty() {
            0
        } else {
            parts.len()
        }));
    }
    let mut c = parts.iter().enumerate().map(|(i, p)| {
        parse_rational(p).map_err(|e| ParseError::Component {
            index: i + 1,
            source: Box::new(e),
        })
    });
    let x = c.next().expect("three")?;
    let y = c.next().expect("three")?;
    let z = c.next().expect("three")?;
    Ok(Vec3::new(x, y, z))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn decimals_and_fractions_are_exact() {
        assert_eq!(parse_rational("0.6").unwrap(), q(3, 5));
        assert_eq!(parse_rational("-1e-3").unwrap(), q(-1, 1000));
        assert_eq!(parse_rational("2/3").unwrap(), q(2, 3));
        assert_eq!(parse_rational(" .5E2 ").unwrap(), q(50, 1));
        assert_eq!(parse_rational("+2.").unwrap(), q(2, 1));
        assert_eq!(parse_rational("1/1e3").unwrap(), q(1, 1000));
        assert_eq!(parse_rational("-0.125/0.5").unwrap(), q(-1, 4));
    }

    /// The gcd-free reduction gives the lowest terms `Ratio::new` (a general gcd)
    /// gives, numerator and denominator alike, for digits with many 2s and 5s, long
    /// digit strings past `u128` and zero.
    #[test]
    fn decimals_are_in_lowest_terms() {
        let cases = [
            "0",
            "-0.000",
            "0.5",
            "0.25",
            "-0.0625",
            "0.2",
            "0.04",
            "0.8",
            "12.5",
            "0.000000000000000000000000000000000000000000001024",
            "0.123456789012345678901234567890",
            "-0.999999999999999999999999999999",
            "0.000000000000000000000000000000390625",
            "123456789012345678901234567890123456789012.5e-7",
            "1e-30",
            "2.5e-3",
            "7.8125e-3",
            "0.1000",
            "100e-2",
        ];
        for t in cases {
            let v = parse_rational(t).unwrap();
            let neg = t.starts_with('-');
            let body = t.trim_start_matches('-');
            let (mant, exp) = body.split_once('e').unwrap_or((body, "0"));
            let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
            let e: i32 = exp.parse::<i32>().unwrap() - frac.len() as i32;
            let m: BigInt = format!("{int}{frac}").parse().unwrap();
            let m = if neg { -m } else { m };
            let ten = BigInt::from(10);
            let expect = if e >= 0 {
                BigRational::new(m * ten.pow(e as u32), 1.into())
            } else {
                BigRational::new(m, ten.pow((-e) as u32))
            };
            assert_eq!(
                (v.numer(), v.denom()),
                (expect.numer(), expect.denom()),
                "{t}"
            );
        }
    }

    #[test]
    fn bad_numbers_are_named() {
        for bad in [
            "", "abc", "1..2", "nan", "inf", "1e", "e5", "--1", "1/2/3", "0x10", "1,5",
        ] {
            assert!(parse_rational(bad).is_err(), "{bad:?} parsed");
        }
        assert_eq!(
            parse_rational("1/0"),
            Err(ParseError::ZeroDenominator("1/0".into()))
        );
        assert!(matches!(
            parse_rational("1e99999"),
            Err(ParseError::ExponentRange(_))
        ));
        assert_eq!(parse_vec3("1,2"), Err(ParseError::Arity(2)));
        assert!(matches!(
            parse_vec3("1,x,2"),
            Err(ParseError::Component { index: 2, .. })
        ));
    }
}
