//! The MPFR references (feature `mpfr`): the same generic recurrences at 256 bits
//! agree with the exact rational run, and the MPFR Phong value gives the exact 8-bit
//! level decided with rationals.
#![cfg(feature = "mpfr")]

use crate::common;
use crate::runner;

use common::*;
use num_traits::Signed;
use phong_approx::quantize::level;
use phong_approx::reference::level::phong_level_exact;
use phong_approx::reference::mpfr::{with_precision, Mpfr};
use phong_approx::{Method, Scalar};

fn close(a: &Mpfr, b: &Q, bits: i32) -> bool {
    let d = (a.to_rational().unwrap() - b.clone()).abs();
    d <= Q::new(1.into(), num_bigint::BigInt::from(2).pow(bits as u32))
}

#[test]
fn recurrences_in_mpfr_agree_with_exact() {
    with_precision(256, || {
        for_all_spans(32, |c, s| {
            let m = s.cast::<Mpfr>().unwrap();
            for method in Method::ALL {
                let got = method.values(&m).unwrap();
                let want = method.values(s).unwrap();
                // The table variant may pick a neighbouring entry only at an exact
                // tie; the others agree to far below 2^-200.
                for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                    if !close(g, w, 200) && !matches!(method, Method::AngularTable(_)) {
                        return Err(format!(
                            "{method} pixel {i}: {} vs {}",
                            g.to_f64(),
                            w.to_f64()
                        ));
                    }
                }
            }
            let _ = c;
            Ok(())
        });
    });
}

/// The MPFR Phong levels at 256 bits against the exact levels decided in rationals, on
/// every span of `for_all_spans` and on a value exactly on a level boundary.
#[test]
fn mpfr_phong_levels_are_the_exact_levels() {
    // p_b = N_b·L = 2/3 = 170/255 exactly, q_b = 1: the exact level is 170, and a
    // 256-bit value of 2/3 may fall either side of the boundary.
    let on_boundary = Case {
        why: "Phong value exactly on a level boundary",
        na: Stereo(-6, -27, 1),
        nb: Stereo(-10, 10, 10),
        l: Stereo(-3, 12, 17),
        n: 1,
    };
    let s = on_boundary.span().unwrap();
    assert_eq!(s.p_b, Q::new(2.into(), 3.into()));
    with_precision(256, || {
        mpfr_levels_match(&s).unwrap();
        for_all_spans(32, |_, s| mpfr_levels_match(s));
    });
}

/// The MPFR Phong levels of `s` against the exact ones: equal wherever the MPFR value
/// is farther than 2^-240 from a level boundary (it is within 2^-250 of the exact
/// value, so the level is decided there), and at most one apart where it is not.
fn mpfr_levels_match(s: &phong_approx::Span<Q>) -> Result<(), String> {
    let m = s.cast::<Mpfr>().unwrap();
    let v = Method::Phong.values(&m).unwrap();
    let eps = Q::new(1.into(), num_bigint::BigInt::from(2).pow(240));
    for i in 0..=s.n {
        let exact = phong_level_exact(&s.p_at(i), &s.q_at(i)).unwrap();
        let got = level(&v[i as usize]);
        let scaled = v[i as usize].to_rational().unwrap() * Q::from_integer(255.into());
        let frac = scaled.clone() - scaled.floor();
        let undecided = frac < eps || Q::from_integer(1.into()) - frac < eps;
        if (!undecided && got != exact) || got.abs_diff(exact) > 1 {
            return Err(format!("pixel {i}: mpfr level {got}, exact {exact}"));
        }
    }
    Ok(())
}

#[test]
fn precision_is_respected() {
    let s = edge_cases()[3].span().unwrap();
    let lo = with_precision(64, || {
        Method::Phong.values(&s.cast::<Mpfr>().unwrap()).unwrap()
    });
    let hi = with_precision(512, || {
        Method::Phong.values(&s.cast::<Mpfr>().unwrap()).unwrap()
    });
    assert_eq!(lo[5].0.prec(), 64);
    assert_eq!(hi[5].0.prec(), 512);
    let exact = Method::Phong.values(&s).unwrap();
    assert!(close(&hi[5], &exact[5], 250));
    assert!(
        !close(&lo[5], &exact[5], 80),
        "64 bits cannot be 2^-80-accurate here"
    );
}

#[test]
fn cli_mpfr_agrees_with_exact() {
    let run = |scalar: &str| {
        let out = runner::bin()
            .args([
                "span",
                "--method",
                "phong",
                "--na",
                "0,3/5,4/5",
                "--nb",
                "2/7,3/7,6/7",
                "--light",
                "2/3,1/3,2/3",
                "--steps",
                "8",
                "--scalar",
                scalar,
            ])
            .args(if scalar == "mpfr" {
                &["--precision", "300"][..]
            } else {
                &[]
            })
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice::<serde_json::Value>(&out.stdout).unwrap()
    };
    let m = run("mpfr");
    let e = run("exact");
    assert_eq!(m["precision"], 300);
    assert_eq!(m["values"], e["values"]);
    assert_eq!(m["levels"], e["levels"]);
}

/// The squared method (`squared_corrected_euler`) is generic over MPFR too: at 256 bits
/// its values agree with the exact rational run to 2^-200. Each operation errs by at
/// most 2^-256 relative; the set-up's 40-odd operations and the loop's 2n ≤ 128
/// additions act on magnitudes below 2^16 (unit inputs, `n ≤ 64` for these spans:
/// `|g'| ≤ 8` (`2·|p|·|di|`, `|di| ≤ |A| + |D|/2 ≤ 4`), `|ds|`, `|ε|`, `|t_0|` and the values below `n²·4`), so the error stays
/// below `2^-256·2^16·2^8`.
#[test]
fn the_squared_method_in_mpfr_agrees_with_exact() {
    use phong_approx::squared_corrected_euler::SquaredSpan;
    with_precision(256, || {
        for_all_spans(32, |_, s| {
            let exact = SquaredSpan::of(s).map_err(|e| e.to_string())?;
            let m = s.cast::<Mpfr>().unwrap();
            let big = SquaredSpan::of(&m).map_err(|e| e.to_string())?;
            let (mut want, mut got) = (
                vec![Q::from_integer(0.into()); s.n as usize + 1],
                vec![Mpfr::from_i64(0); s.n as usize + 1],
            );
            exact.shade(&mut want).map_err(|e| e.to_string())?;
            big.shade(&mut got).map_err(|e| e.to_string())?;
            for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                if !close(g, w, 200) {
                    return Err(format!("pixel {i}: {} vs {}", g.to_f64(), w.to_f64()));
                }
            }
            Ok(())
        });
    });
}
