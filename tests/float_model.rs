//! The model is the code: the operation sequence that `proofs/Float.v` proves the
//! bounds of, run in an independent software model of binary32 and binary64, gives
//! the same bits as the crate's `f32`/`f64` code (`Span`'s set-up, then the
//! Gouraud and corrected-Euler loops) on thousands of random and worst-case spans.
//!
//! The model computes every operation exactly in rationals and rounds the result with
//! [`round`] below: round to nearest, ties to even, with the format's precision and
//! subnormals (`2^emin` is the smallest subnormal) — written here from the IEEE 754
//! definition, not taken from the crate. The sequence is the one stated in
//! `proofs/Float.v` (and `docs/float.md`): inputs rounded, `dot` as `(x + y) + z`,
//! `k = (N_b − N_a)/n`, eqs. 2–3, 10–11, 14–17 in the code's order, then
//! `p += t; t += ds` and `g += dp`.

use crate::common;

use common::*;
use num_traits::Zero;
use phong_approx::{BigRational, Method, Real, Scalar, Span, Vec3};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

use common::emu::{pow2, round, Format, BINARY32, BINARY64};

/// The model's arithmetic: exact operation, then one rounding.
struct Model(Format);

impl Model {
    fn r(&self, x: BigRational) -> BigRational {
        round(&x, self.0)
    }
    fn add(&self, a: &BigRational, b: &BigRational) -> BigRational {
        self.r(a + b)
    }
    fn sub(&self, a: &BigRational, b: &BigRational) -> BigRational {
        self.r(a - b)
    }
    fn mul(&self, a: &BigRational, b: &BigRational) -> BigRational {
        self.r(a * b)
    }
    fn div(&self, a: &BigRational, b: &BigRational) -> BigRational {
        self.r(a / b)
    }
    fn dot(&self, u: &[BigRational; 3], v: &[BigRational; 3]) -> BigRational {
        let xy = self.add(&self.mul(&u[0], &v[0]), &self.mul(&u[1], &v[1]));
        self.add(&xy, &self.mul(&u[2], &v[2]))
    }
}

/// The set-up quantities and the two loops, as the model computes them.
struct Modelled {
    setup: Vec<(&'static str, BigRational)>,
    gouraud: Vec<BigRational>,
    corrected_euler: Vec<BigRational>,
}

fn model(
    f: Format,
    na: &Vec3<BigRational>,
    nb: &Vec3<BigRational>,
    l: &Vec3<BigRational>,
    n: u32,
) -> Modelled {
    let m = Model(f);
    let v = |x: &Vec3<BigRational>| [m.r(x.x.clone()), m.r(x.y.clone()), m.r(x.z.clone())];
    let (na, nb, l) = (v(na), v(nb), v(l));
    let int = |i: i64| BigRational::from_integer(i.into());
    let nf = int(i64::from(n));
    let two = int(2);
    let k = [0, 1, 2].map(|j| m.div(&m.sub(&nb[j], &na[j]), &nf));
    let a = m.dot(&k, &l);
    let pa = m.dot(&na, &l);
    let c = m.dot(&k, &k);
    let d = m.mul(&two, &m.dot(&k, &na));
    let pb = m.dot(&nb, &l);
    let dqb = m.add(&m.mul(&(&two * &nf), &c), &d);
    let dia = m.sub(&a, &m.mul(&m.div(&pa, &two), &d));
    let dib = m.sub(&a, &m.mul(&m.div(&pb, &two), &dqb));
    let ds = m.div(&m.sub(&dib, &dia), &nf);
    let tri = int(i64::from(n) * (i64::from(n) - 1) / 2);
    let pn = m.add(&m.add(&pa, &m.mul(&nf, &dia)), &m.mul(&tri, &ds));
    let eps = m.sub(&pn, &pb);
    let deps = m.div(&eps, &nf);
    let t0 = m.sub(&dia, &deps);
    let dp = m.div(&m.sub(&pb, &pa), &nf);
    let (mut g, mut p, mut s) = (pa.clone(), pa.clone(), t0.clone());
    let (mut gouraud, mut corrected_euler) = (Vec::new(), Vec::new());
    for _ in 0..=n {
        gouraud.push(g.clone());
        corrected_euler.push(p.clone());
        g = m.add(&g, &dp);
        p = m.add(&p, &s);
        s = m.add(&s, &ds);
    }
    Modelled {
        setup: vec![
            ("k.x", k[0].clone()),
            ("k.y", k[1].clone()),
            ("k.z", k[2].clone()),
            ("A", a),
            ("p_a", pa),
            ("C", c),
            ("D", d),
            ("p_b", pb),
            ("dq_b", dqb),
            ("di_a", dia),
            ("di_b", dib),
            ("ds", ds),
            ("p_n", pn),
            ("eps", eps),
            ("d_eps", deps),
            ("t0", t0),
            ("dp", dp),
        ],
        gouraud,
        corrected_euler,
    }
}

/// The crate's run in `T`, bit for bit against the model in `f`.
fn compare<T: Real>(f: Format, c: &Case) -> Result<(), String> {
    let Some(exact) = c.span() else {
        return Ok(());
    };
    let want = model(f, &exact.na, &exact.nb, &exact.l, exact.n);
    let s: Span<T> = exact.cast::<T>().expect("finite");
    let q = |x: &T| x.to_rational().expect("finite");
    let got_setup = [
        &s.k.x, &s.k.y, &s.k.z, &s.a, &s.p_a, &s.c, &s.d, &s.p_b, &s.dq_b, &s.di_a, &s.di_b, &s.ds,
        &s.p_n, &s.eps, &s.d_eps, &s.t0, &s.dp,
    ];
    for ((name, w), g) in want.setup.iter().zip(got_setup) {
        if q(g) != *w {
            return Err(format!(
                "{} set-up {name}: code {g:?}, model {}",
                T::NAME,
                w.to_f64()
            ));
        }
    }
    for (method, model_values) in [
        (Method::Gouraud, &want.gouraud),
        (Method::CorrectedEuler, &want.corrected_euler),
    ] {
        let got = method.values(&s).map_err(|e| e.to_string())?;
        for (i, (g, w)) in got.iter().zip(model_values).enumerate() {
            if q(g) != *w {
                return Err(format!(
                    "{} {method} pixel {i}: code {g:?}, model {}",
                    T::NAME,
                    w.to_f64()
                ));
            }
        }
    }
    Ok(())
}

/// The rounding function itself, on values whose rounding is known: halfway cases
/// (ties to even), the subnormal range, and agreement with the hardware conversion
/// of an `f64` to `f32` (the one place the platform's rounding is used, as a check).
#[test]
fn model_rounding_is_ieee_round_to_nearest_even() {
    let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    // 1 + 2^-24 is halfway between 1 and 1 + 2^-23: ties to even gives 1.
    assert_eq!(round(&(q(1, 1) + pow2(-24)), BINARY32), q(1, 1));
    // 1 + 3·2^-24 is halfway between 1 + 2^-23 and 1 + 2^-22: even is 1 + 2^-22.
    assert_eq!(
        round(&(q(1, 1) + pow2(-24) * q(3, 1)), BINARY32),
        q(1, 1) + pow2(-22)
    );
    // Smallest subnormal, and half of it (ties to even: 0), and 3/4 of it (rounds up).
    assert_eq!(round(&pow2(-149), BINARY32), pow2(-149));
    assert!(round(&pow2(-150), BINARY32).is_zero());
    assert_eq!(round(&(pow2(-150) * q(3, 2)), BINARY32), pow2(-149));
    assert_eq!(
        round(&q(-1, 3), BINARY64),
        BigRational::from_float(-1.0f64 / 3.0).unwrap()
    );
    let mut runner = TestRunner::deterministic();
    for _ in 0..20_000 {
        let bits = any::<u64>().new_tree(&mut runner).unwrap().current();
        let x = f64::from_bits(bits);
        if !x.is_finite() || x.abs() > 3.0e38 {
            continue;
        }
        let exact = BigRational::from_float(x).unwrap();
        let hw = BigRational::from_float(x as f32).unwrap();
        assert_eq!(round(&exact, BINARY32), hw, "f64 {x:e} ({bits:#x}) to f32");
        assert_eq!(
            round(&exact, BINARY64),
            exact,
            "f64 {x:e} is a binary64 number"
        );
    }
}

fn check_cases<T: Real>(f: Format, cases: &[Case]) {
    for c in cases {
        if let Err(e) = compare::<T>(f, c) {
            panic!("{e}\ninputs: {c:?}");
        }
    }
}

fn search<T: Real>(f: Format, strategy: impl Strategy<Value = Case>, cases: u32) {
    let mut runner = runner(cases, "proptest-regressions/float_model.txt");
    if let Err(e) = runner.run(&strategy, |c| {
        compare::<T>(f, &c).map_err(|e| TestCaseError::fail(format!("{e}\ninputs: {c:?}")))
    }) {
        panic!("{e}");
    }
}

#[test]
fn binary32_model_matches_the_code_on_edge_and_targeted_spans() {
    let mut cases = edge_cases();
    cases.extend(targeted_cases());
    check_cases::<f32>(BINARY32, &cases);
}

#[test]
fn binary64_model_matches_the_code_on_edge_and_targeted_spans() {
    let mut cases = edge_cases();
    cases.extend(targeted_cases());
    check_cases::<f64>(BINARY64, &cases);
}

#[test]
fn binary32_model_matches_the_code_on_random_spans() {
    search::<f32>(BINARY32, arb_case(), 2000);
    search::<f32>(BINARY32, arb_targeted(), 64);
}

#[test]
fn binary64_model_matches_the_code_on_random_spans() {
    search::<f64>(BINARY64, arb_case(), 2000);
    search::<f64>(BINARY64, arb_targeted(), 64);
}
