//! The fast kernels of `src/fast.rs` against the exact run (within the bounds of
//! `src/tolerance.rs`) and against their recurrence twins, in `f32` and `f64`, on the
//! edge cases and random spans; and the 4-ulp claim of the Phong kernels.

use crate::common;

use common::*;
use phong_approx::fast::{phong_rsqrt_f32, FastSpan};
use phong_approx::tolerance::{bound, fast_bound, fast_span_bound, Kernel, Shape};
use phong_approx::{Method, Real, Scalar, Span};

pub(crate) fn q_min(s: &Span<Q>) -> f64 {
    s.q_min().to_f64() * (1.0 - 1e-15)
}

pub(crate) fn err<T: Scalar>(a: &T, b: &Q) -> f64 {
    (a.to_rational().unwrap() - b.clone()).to_f64().abs()
}

macro_rules! kernel_tests {
    ($name:ident, $f:ident) => {
        #[test]
        fn $name() {
            let check = |c: &Case, s: &Span<Q>| -> Result<(), String> {
                let fs = s.cast::<$f>().unwrap();
                let fast = FastSpan::<$f>::from_span(&fs);
                let u = <$f as Scalar>::unit_roundoff();
                let qm = q_min(s);
                let mut out = vec![0 as $f; s.len()];
                type Run = fn(&FastSpan<$f>, &mut [$f]);
                let kernels: [(Method, Kernel, Run); 8] = [
                    (
                        Method::CorrectedEuler,
                        Kernel::CorrectedEuler,
                        FastSpan::<$f>::corrected_euler,
                    ),
                    (
                        Method::CorrectedEuler,
                        Kernel::CorrectedEulerSerial,
                        FastSpan::<$f>::corrected_euler_serial,
                    ),
                    (
                        Method::Gouraud,
                        Kernel::GouraudSerial,
                        FastSpan::<$f>::gouraud_serial,
                    ),
                    (
                        Method::Duff,
                        Kernel::DuffSerial,
                        FastSpan::<$f>::duff_serial,
                    ),
                    (Method::Euler, Kernel::Euler, FastSpan::<$f>::euler),
                    (Method::Gouraud, Kernel::Gouraud, FastSpan::<$f>::gouraud),
                    (Method::Phong, Kernel::Phong, FastSpan::<$f>::phong),
                    (
                        Method::SymmetricPhong,
                        Kernel::SymmetricPhong,
                        FastSpan::<$f>::symmetric_phong,
                    ),
                ];
                for (m, k, kernel) in kernels {
                    kernel(&fast, &mut out);
                    // No bound (q may round to zero: nearly opposite normals): nothing to
                    // check, and the twin may refuse the span with NotFiniteValue.
                    let (Some(b), Some(b_twin)) = (fast_bound(k, s.n, qm, u), bound(m, s.n, qm, u))
                    else {
                        continue;
                    };
                    let exact = exact_values(m, c, s);
                    let twin = m.values(&fs).map_err(|e| {
                        format!("{} {m} twin on a bounded span: {e}", stringify!($f))
                    })?;
                    for i in 0..s.len() {
                        let e = err(&out[i], &exact[i]);
                        ensure(e <= b, || {
                            format!(
                                "{} fast {m} pixel {i}: error {e:e} > {b:e} ({})",
                                stringify!($f),
                                c.why
                            )
                        })?;
                        let d = (f64::from(out[i]) - f64::from(twin[i])).abs();
                        ensure(d <= b + b_twin, || {
                            format!(
                                "{} fast {m} vs its recurrence twin at {i}: {d:e}",
                                stringify!($f)
                            )
                        })?;
                    }
                }
                Ok(())
            };
            for_all_spans(64, &check);
            for_targeted_spans(16, &check);
        }
    };
}

kernel_tests!(fast_kernels_match_exact_and_twins_f32, f32);
kernel_tests!(fast_kernels_match_exact_and_twins_f64, f64);

/// `p/√q` exactly (to 2^-256) from the `f32` set-up's own coefficients, and the size
/// of the terms that make it (`(|A|·i + |B|)/√q`), whose ulp is the unit of the claim.
fn phong_from_setup(f: &FastSpan<f32>, i: u32) -> (Q, f64) {
    let r = |x: f32| <f32 as Scalar>::to_rational(&x).unwrap();
    let x = qi(i);
    let p = r(f.a) * x.clone() + r(f.b);
    let qq = (r(f.c) * x.clone() + r(f.d)) * x + r(f.e);
    let v = p / qq.clone().sqrt();
    let xf = f64::from(i);
    let qf = qq.to_f64();
    // κ = (|C|i² + |D|i + |E|)/q: how much q's own evaluation cancels (1 for close
    // normals, about 260 for normals 170° apart).
    let kappa =
        (f64::from(f.c.abs()) * xf * xf + f64::from(f.d.abs()) * xf + f64::from(f.e.abs())) / qf;
    let mag = (f64::from(f.a.abs()) * xf + f64::from(f.b.abs())) / qf.sqrt() * kappa;
    (v, mag)
}

fn f32_ulp(x: f64) -> f64 {
    let a = (x.abs() as f32).max(f32::MIN_POSITIVE);
    f64::from(f32::from_bits(a.to_bits() + 1)) - f64::from(a)
}

#[test]
fn phong_kernels_are_within_4_ulps() {
    for_all_spans(64, |c, s| {
        let fast = FastSpan::<f32>::from_span(&s.cast::<f32>().unwrap());
        let mut a = vec![0f32; s.len()];
        let mut b = vec![0f32; s.len()];
        fast.phong(&mut a);
        phong_rsqrt_f32(&fast, &mut b);
        for i in 0..s.len() {
            let (v, mag) = phong_from_setup(&fast, i as u32);
            let ulp = f32_ulp(mag.max(v.to_f64().abs()));
            for (name, got) in [("sqrt", a[i]), ("rsqrt", b[i])] {
                let e = err(&got, &v) / ulp;
                ensure(e <= 4.0, || {
                    format!("{name} Phong pixel {i}: {e:.2} ulps ({})", c.why)
                })?;
            }
        }
        Ok(())
    });
}

/// Adaptive and angular fast kernels against the crate's own methods in the same
/// type: the same decision (or one within rounding of the threshold) and values within
/// the method's bound.
#[test]
fn adaptive_and_angular_fast_kernels() {
    let table: Vec<f32> = phong_approx::angular::CosTable::<f32>::new(256)
        .unwrap()
        .values;
    for_all_spans(64, |c, s| {
        let fs = s.cast::<f32>().unwrap();
        let f = FastSpan::<f32>::from_span(&fs);
        let u = <f32 as Scalar>::unit_roundoff();
        let mut out = vec![0f32; s.len()];
        // Adaptive: the fast decision agrees with eq. 24 exactly unless |δ·255| is
        // within rounding of 1.
        let gouraud = f.adaptive(1.0, &mut out);
        let exact = phong_approx::adaptive::decide(s, &Q::from_integer(1.into()));
        let exact_gouraud = exact.choice == phong_approx::adaptive::Choice::Gouraud;
        let margin = (exact.delta.to_f64() * 255.0).abs() - 1.0;
        ensure(gouraud == exact_gouraud || margin.abs() < 1e-3, || {
            format!("adaptive decision ({})", c.why)
        })?;
        let want = exact_values(
            if gouraud {
                Method::Gouraud
            } else {
                Method::CorrectedEuler
            },
            c,
            s,
        );
        let b = fast_bound(Kernel::Adaptive, s.n, 1.0, u).unwrap();
        for i in 0..s.len() {
            ensure(err(&out[i], &want[i]) <= b, || {
                format!("adaptive pixel {i} ({})", c.why)
            })?;
        }
        // Angular: the closed-form angle is within the angular bound.
        f.angular(&mut out);
        let want = exact_values(Method::Angular, c, s);
        let b = fast_span_bound(Kernel::Angular, &Shape::of(s), u).unwrap();
        for i in 0..s.len() {
            ensure(err(&out[i], &want[i]) <= b, || {
                format!("angular pixel {i} ({})", c.why)
            })?;
        }
        // Tabled: equal to the crate's table method in f32, or one table step away.
        f.angular_table(&table, &mut out);
        let want = Method::AngularTable(256).values(&fs).unwrap();
        for i in 0..s.len() {
            let d = (out[i] - want[i]).abs();
            ensure(d <= 0.0063, || {
                format!("angular table pixel {i}: {d} ({})", c.why)
            })?;
        }
        Ok(())
    });
}

#[test]
fn short_spans_and_leftovers() {
    // Every length from 1 to 19 (all remainders of 4- and 8-wide chunks), and the
    // extra room in `out` is left alone.
    let s = Span::new(
        Stereo(0, 0, 1).unit(),
        Stereo(1, 0, 3).unit(),
        Stereo(2, 1, 5).unit(),
        1,
    )
    .unwrap();
    for n in 1..20u32 {
        let mut s2 = s.clone();
        s2 = Span::new(s2.na, s2.nb, s2.l, n).unwrap();
        let f = FastSpan::<f32>::from_span(&s2.cast::<f32>().unwrap());
        let mut out = vec![-7.0f32; n as usize + 4];
        phong_rsqrt_f32(&f, &mut out);
        assert!(out[n as usize + 1..].iter().all(|&v| v == -7.0), "n = {n}");
        let exact = Method::Phong.values(&s2).unwrap();
        for i in 0..=n as usize {
            assert!(err(&out[i], &exact[i]) < 1e-5, "n = {n}, pixel {i}");
        }
        f.corrected_euler(&mut out);
        assert_eq!(out[0], f.b);
    }
}

/// `phong_rsqrt_f32` against the exact Phong values on the inputs, within the derived
/// bound of `Kernel::PhongRsqrt` (docs/float.md §12), on the edge, random and targeted
/// spans.
#[test]
fn phong_rsqrt_within_its_derived_bound() {
    let check = |c: &Case, s: &Span<Q>| -> Result<(), String> {
        let Some(b) = fast_bound(Kernel::PhongRsqrt, s.n, q_min(s), f32::unit_roundoff()) else {
            return Ok(());
        };
        let fast = FastSpan::<f32>::from_span(&s.cast::<f32>().unwrap());
        let mut out = vec![0f32; s.len()];
        phong_rsqrt_f32(&fast, &mut out);
        let exact = exact_values(Method::Phong, c, s);
        for i in 0..s.len() {
            let e = err(&out[i], &exact[i]);
            ensure(e <= b, || {
                format!("rsqrt Phong pixel {i}: {e:e} > {b:e} ({})", c.why)
            })?;
        }
        Ok(())
    };
    for_all_spans(64, check);
    for_targeted_spans(16, check);
}

/// `FastSpan::delta` (the closed form of eq. 24's δ that `FastSpan::adaptive` decides
/// with) is the reference δ of `adaptive::decide` on the exact inputs, within `10u`.
#[test]
fn fast_delta_is_the_reference_delta() {
    macro_rules! check {
        ($f:ident) => {{
            let check = |c: &Case, s: &Span<Q>| -> Result<(), String> {
                let fast = FastSpan::<$f>::from_span(&s.cast::<$f>().unwrap());
                let exact = phong_approx::adaptive::decide(s, &Q::from_integer(1.into())).delta;
                let u = <$f as Scalar>::unit_roundoff();
                let e = err(&fast.delta(), &exact);
                ensure(e <= 10.0 * u, || {
                    format!("{} δ off by {:.1}u ({})", stringify!($f), e / u, c.why)
                })
            };
            for_all_spans(64, check);
            for_targeted_spans(16, check);
        }};
    }
    check!(f32);
    check!(f64);
}
