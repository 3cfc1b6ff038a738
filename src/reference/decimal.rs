//! Decimal strings for exact rationals, correctly rounded to a number of significant
//! digits (round half to even).

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// `x` written with `digits` significant decimal digits, correctly rounded (half to
/// even). Plain notation when the exponent is between −7 and 20, scientific (`1.5e-9`)
/// otherwise. `digits` of 0 is treated as 1.
pub fn rational_to_decimal(x: &BigRational, digits: usize) -> String {
    let digits = digits.max(1);
    if x.is_zero() {
        return "0".to_string();
    }
    let neg = x.is_negative();
    let a = x.abs();
    // Estimate the decimal exponent e with 10^e <= a < 10^(e+1), then fix it up.
    let ndig = |v: &BigInt| v.to_string().len() as i64;
    let mut e = ndig(a.numer()) - ndig(a.denom());
    let pow10 = |k: i64| -> BigRational {
        if k >= 0 {
            BigRational::from_integer(BigInt::from(10).pow(k as u32))
        } else {
            BigRational::new(BigInt::from(1), BigInt::from(10).pow((-k) as u32))
        }
    };
    while a < pow10(e) {
        e -= 1;
    }
    while a >= pow10(e + 1) {
        e += 1;
    }
    let scaled = &a * pow10(digits as i64 - 1 - e);
    let mut m = round_half_even(&scaled);
    if m == BigInt::from(10).pow(digits as u32) {
        m /= 10;
        e += 1;
    }
    let s = m.to_string();
    let body = if (-7..=20).contains(&e) {
        if e >= 0 {
            let int_len = (e + 1) as usize;
            if s.len() <= int_len {
                format!("{}{}", s, "0".repeat(int_len - s.len()))
            } else {
                format!("{}.{}", &s[..int_len], &s[int_len..])
            }
        } else {
            format!("0.{}{}", "0".repeat((-e - 1) as usize), s)
        }
    } else if s.len() > 1 {
        format!("{}.{}e{}", &s[..1], &s[1..], e)
    } else {
        format!("{}e{}", s, e)
    };
    if neg {
        format!("-{body}")
    } else {
        body
    }
}

fn round_half_even(x: &BigRational) -> BigInt {
    let (q, r) = x.numer().div_rem(x.denom());
    let twice: BigInt = &r * 2;
    match twice.cmp(x.denom()) {
        std::cmp::Ordering::Less => q,
        std::cmp::Ordering::Greater => q + 1,
        std::cmp::Ordering::Equal => {
            if q.is_even() {
                q
            } else {
                q + 1
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn known_expansions() {
        assert_eq!(rational_to_decimal(&q(1, 3), 5), "0.33333");
        assert_eq!(rational_to_decimal(&q(-2, 3), 4), "-0.6667");
        assert_eq!(rational_to_decimal(&q(5, 1), 3), "5.00");
        assert_eq!(rational_to_decimal(&q(1, 8), 2), "0.12");
        assert_eq!(rational_to_decimal(&q(3, 8), 2), "0.38");
        assert_eq!(rational_to_decimal(&q(999_999, 1_000_000), 3), "1.00");
        assert_eq!(rational_to_decimal(&q(1, 1_000_000_000), 2), "1.0e-9");
        assert_eq!(rational_to_decimal(&q(12345, 1), 2), "12000");
        assert_eq!(rational_to_decimal(&q(0, 1), 9), "0");
    }
}
