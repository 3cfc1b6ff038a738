//! The row set-ups of `src/fast_rows.rs` (docs/float.md §17): a polygon's normal field and a
//! row of it, the float run from the field's float inputs, the exact run from the
//! same inputs taken exactly (edge normals normalized with 2^-256 square roots, the
//! catalogue's methods run in rationals), within the bounds of `tolerance::rows`.

use crate::common;

use super::fast::{err, q_min};
use common::*;
use phong_approx::fast::FastSpan;
use phong_approx::fast_rows::{
    phong_field_rsqrt, Batch, EdgeStepper, Field, RowSpan, BATCH, SHORT,
};
use phong_approx::tolerance::rows::{
    direct_start, field_phong_bound, kernel_bound, span_error, stepped_start, RowKernel, RowShape,
    StartError, Stepped,
};
use phong_approx::tolerance::{fast_bound, Kernel};
use phong_approx::Vec3;
use phong_approx::{Method, Real, Scalar, Span};

/// A polygon's field `U(x, y) = n1·x + n2·y + n3`, the light, and one row of it:
/// first pixel `(x, y)`, `n` steps, reached by the edge steps `dxs` from
/// `(x − Σdx, y − dxs.len())` (the stepped set-up; the direct one ignores them).
/// Coordinates are whole or half pixels, so exact in both float types.
#[derive(Clone, Debug)]
struct FieldCase {
    why: &'static str,
    n1: [f64; 3],
    n2: [f64; 3],
    n3: [f64; 3],
    l: [f64; 3],
    x: f64,
    y: f64,
    n: u32,
    dxs: Vec<f64>,
}

fn unit3(v: [f64; 3]) -> [f64; 3] {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|c| c / len)
}

/// Rows enumerated on purpose: the paper's mesh, both sides of `SHORT`, one-pixel
/// rows, equal edge normals, light along and across the normal, normals far apart
/// along the row, a field that cancels (`|U|` well below its terms), long rows,
/// large coordinates, `n = 2^k ± 1`, and edge steps before, at and past a restart.
fn field_edge_cases() -> Vec<FieldCase> {
    let mesh = FieldCase {
        why: "mesh patch, 15° over 8 pixels",
        n1: [0.033, -0.004, -0.004],
        n2: [-0.002, 0.031, -0.006],
        n3: unit3([0.10, 0.05, 1.0]),
        l: unit3([-0.4, 0.4, 0.8]),
        x: 0.0,
        y: 3.0,
        n: 4,
        dxs: vec![],
    };
    let with = |why, f: &dyn Fn(&mut FieldCase)| {
        let mut c = mesh.clone();
        c.why = why;
        f(&mut c);
        c
    };
    let mut v = vec![mesh.clone()];
    v.push(with("one-pixel row", &|c| c.n = 0));
    v.push(with("the longest serial row (n + 1 = SHORT − 1)", &|c| {
        c.n = SHORT as u32 - 2
    }));
    v.push(with("the shortest closed-form row (n + 1 = SHORT)", &|c| {
        c.n = SHORT as u32 - 1
    }));
    v.push(with("equal edge normals (n1 = 0)", &|c| c.n1 = [0.0; 3]));
    v.push(with("light along the normal", &|c| c.l = c.n3));
    v.push(with("light across the normal", &|c| {
        c.l = unit3([1.0, 0.0, -0.1])
    }));
    v.push(with("normals 120° apart along the row", &|c| {
        c.n3 = [0.0, 0.0, 1.0];
        c.n1 = [0.2, 0.0, -0.25];
        c.n2 = [0.0, 0.01, 0.0];
        c.x = 0.0;
        c.y = 0.0;
        c.n = 8;
    }));
    v.push(with("the field cancels: |U| a sixth of its terms", &|c| {
        c.n3 = [1.0, 0.2, 0.1];
        c.n1 = [-0.0099, 0.001, 0.0005];
        c.n2 = [0.0, 0.0005, 0.0];
        c.x = 100.0;
        c.y = 0.0;
        c.n = 20;
    }));
    v.push(with("long row, n = 256", &|c| {
        c.n1 = [0.001, 0.0, -0.0003];
        c.n = 256;
    }));
    v.push(with("large coordinates", &|c| {
        c.n1 = [0.00003, -0.00001, 0.0];
        c.n2 = [0.0, 0.00002, -0.00001];
        c.x = 1500.5;
        c.y = -2000.0;
        c.n = 40;
    }));
    for n in [15, 16, 17, 31, 32, 33, 63, 64, 65] {
        v.push(with("n = 2^k − 1, 2^k, 2^k + 1", &move |c| c.n = n));
    }
    v.push(with("stepped: 7 rows (the most before a restart)", &|c| {
        c.dxs = vec![0.0, 1.0, -1.0, 2.0, 0.0, -2.0, 1.0];
        c.y = 10.0;
        c.x = 1.0;
    }));
    v.push(with("stepped: 8 rows (a restart)", &|c| {
        c.dxs = vec![1.0; 8];
        c.y = 10.0;
        c.x = 8.0;
    }));
    v.push(with("stepped: 20 rows, half-pixel moves", &|c| {
        c.dxs = (0..20).map(|k| [0.5, -1.5, 2.0, 0.0][k % 4]).collect();
        c.y = 25.0;
        c.x = 5.0;
    }));
    v.push(with("stepped down a steep field", &|c| {
        c.n2 = [0.09, -0.08, 0.05];
        c.dxs = vec![-2.0; 7];
        c.y = 7.0;
        c.x = -14.0;
    }));
    v
}

/// `count` seeded random rows: mesh-like fields (gradients up to 0.05 per pixel) and
/// coarse ones (up to 0.3), lights anywhere, rows of 0–64 steps (one in twenty to
/// 200), 0–20 edge steps of whole or half pixels; one in four targeted at a field that
/// cancels.
fn field_random_cases(count: usize) -> Vec<FieldCase> {
    struct Rng(u64);
    impl Rng {
        fn f(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        fn r3(&mut self, s: f64) -> [f64; 3] {
            [0, 1, 2].map(|_| (2.0 * self.f() - 1.0) * s)
        }
        fn half(&mut self, s: f64) -> f64 {
            ((2.0 * self.f() - 1.0) * s * 2.0).round() / 2.0
        }
    }
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut v = Vec::new();
    while v.len() < count {
        let g = if v.len() % 3 == 0 { 0.3 } else { 0.05 };
        let (n1, n2) = (rng.r3(g), rng.r3(g));
        let mut n3 = unit3(rng.r3(1.0));
        let l = unit3(rng.r3(1.0));
        let x = rng.half(40.0);
        let y = rng.half(40.0).round();
        let n = if rng.f() < 0.05 {
            (rng.f() * 200.0) as u32
        } else {
            (rng.f() * 64.0) as u32
        };
        let k = (rng.f() * 21.0) as usize;
        let dxs: Vec<f64> = (0..k).map(|_| rng.half(2.0)).collect();
        // Targeted, one case in four: a field that nearly cancels at the row's start
        // (|U_a| a small fraction of its terms), where the bounds grow as T/ℓ.
        let targeted = v.len() % 4 == 1;
        if targeted {
            let small = 0.02 + 0.2 * rng.f();
            let dir = unit3(rng.r3(1.0));
            n3 = [0, 1, 2].map(|j| -(n1[j] * x + n2[j] * y) + small * dir[j]);
        }
        v.push(FieldCase {
            why: if targeted {
                "targeted: the field cancels"
            } else {
                "random"
            },
            n1,
            n2,
            n3,
            l,
            x,
            y,
            n,
            dxs,
        });
    }
    v
}

fn qf(v: f64) -> Q {
    Q::from_float(v).expect("finite")
}

fn qv(v: [f64; 3]) -> Vec3<Q> {
    Vec3::new(qf(v[0]), qf(v[1]), qf(v[2]))
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The exact run of one row: the field at pixel `j`, its unit edge normals' span,
/// and the magnitudes the bounds read.
struct ExactRow {
    /// `U_a + j·n1` for every pixel.
    u: Vec<Vec3<Q>>,
    l: Vec3<Q>,
    /// The unit span `U_a/|U_a|` to `U_b/|U_b|` (`None` for a one-pixel row).
    span: Option<Span<Q>>,
    shape: RowShape,
}

/// The exact row of a case whose inputs are `c`'s rounded by `round` (to the float
/// type under test); `None` where the field vanishes at an edge.
fn exact_row(c: &FieldCase, round: &dyn Fn(f64) -> f64) -> Option<ExactRow> {
    let r3 = |v: [f64; 3]| v.map(round);
    let (n1, n2, n3, l) = (r3(c.n1), r3(c.n2), r3(c.n3), r3(c.l));
    let (qn1, qn2, qn3, ql) = (qv(n1), qv(n2), qv(n3), qv(l));
    let (x, y) = (qf(c.x), qf(c.y));
    let ua = qn1.scale(&x).add(&qn2.scale(&y)).add(&qn3);
    let u: Vec<Vec3<Q>> = (0..=c.n).map(|j| ua.add(&qn1.scale(&qi(j)))).collect();
    let ub = u[c.n as usize].clone();
    let (la2, lb2) = (ua.length_squared(), ub.length_squared());
    if la2 == Q::from_integer(0.into()) || lb2 == Q::from_integer(0.into()) {
        return None;
    }
    let na = ua.div(&Real::sqrt(&la2));
    let nb = ub.div(&Real::sqrt(&lb2));
    let span = if c.n == 0 {
        None
    } else {
        Some(Span::with_tolerance(na, nb, ql.clone(), c.n, &q(1, 1 << 10)).ok()?)
    };
    // Magnitudes, rounded up (lengths in denominators rounded down).
    let up = 1.0 + 1e-12;
    let mu = norm([0, 1, 2].map(|j| (n1[j] * c.x).abs() + (n2[j] * c.y).abs() + n3[j].abs())) * up;
    let shape = RowShape {
        mu,
        n1: norm(n1) * up,
        len_a: la2.to_f64().sqrt() * (1.0 - 1e-12),
        len_b: lb2.to_f64().sqrt() * (1.0 - 1e-12),
        lambda: norm(l) * up,
        n: c.n,
    };
    Some(ExactRow {
        u,
        l: ql,
        span,
        shape,
    })
}

impl ExactRow {
    /// The exact values of a span method, `N_a·L` on a one-pixel row.
    fn values(&self, m: Method) -> Option<Vec<Q>> {
        match &self.span {
            Some(s) => m.values(s).ok(),
            None => Some(vec![self.span_pa()]),
        }
    }

    fn span_pa(&self) -> Q {
        let la = Real::sqrt(&self.u[0].length_squared());
        self.u[0].dot(&self.l) / la
    }

    /// Phong of the field: `U_j·L/|U_j|` at every pixel.
    fn field_phong(&self) -> Option<Vec<Q>> {
        self.u
            .iter()
            .map(|u| {
                let q2 = u.length_squared();
                (q2 != Q::from_integer(0.into())).then(|| u.dot(&self.l) / Real::sqrt(&q2))
            })
            .collect()
    }

    /// The least `q` of the unit span (1 on a one-pixel row).
    fn q_min(&self) -> f64 {
        self.span.as_ref().map_or(1.0, q_min)
    }

    /// The least `|U_j|²` over the row, rounded down.
    fn field_q_min(&self) -> f64 {
        self.u
            .iter()
            .map(|u| u.length_squared().to_f64())
            .fold(f64::INFINITY, f64::min)
            * (1.0 - 1e-12)
    }

    /// `μ` at a point of the field (for the stepped rows).
    fn mu_at(c: &FieldCase, round: &dyn Fn(f64) -> f64, x: f64, y: f64) -> f64 {
        let r3 = |v: [f64; 3]| v.map(round);
        let (n1, n2, n3) = (r3(c.n1), r3(c.n2), r3(c.n3));
        norm([0, 1, 2].map(|j| (n1[j] * x).abs() + (n2[j] * y).abs() + n3[j].abs())) * (1.0 + 1e-12)
    }
}

/// The `Stepped` description of how `c`'s row is reached, with `k` the steps since
/// the stepper last evaluated the field.
fn stepped_shape(c: &FieldCase, round: &dyn Fn(f64) -> f64, k: u32) -> Stepped {
    let n1 = norm(c.n1.map(round));
    let n2 = norm(c.n2.map(round));
    let steps = c.dxs.len();
    let (mut x, mut y) = (c.x - c.dxs.iter().sum::<f64>(), c.y - steps as f64);
    let mut m = ExactRow::mu_at(c, round, x, y);
    for dx in &c.dxs {
        x += dx;
        y += 1.0;
        m = m.max(ExactRow::mu_at(c, round, x, y));
    }
    let dmax = c.dxs.iter().fold(0.0f64, |a, d| a.max(d.abs()));
    Stepped {
        k,
        sigma: (dmax * n1 + n2) * (1.0 + 1e-12),
        m,
        n2: n2 * (1.0 + 1e-12),
    }
}

/// Checks `got` against `exact` within `bound` at every pixel.
fn within(what: &str, got: &[f64], exact: &[Q], bound: f64) -> Result<(), String> {
    for (i, (g, e)) in got.iter().zip(exact).enumerate() {
        let err = (qf(*g) - e.clone()).to_f64().abs();
        ensure(err <= bound, || {
            format!("{what} pixel {i}: error {err:e} > bound {bound:e}")
        })?;
    }
    Ok(())
}

macro_rules! row_tests {
    ($name:ident, $f:ident) => {
        /// Every row kernel of `fast_rows` in this type against the exact run, within
        /// its derived bound, on the enumerated and the seeded rows; the direct,
        /// batched and edge-stepped set-ups, and Phong of the field.
        #[test]
        fn $name() {
            let round = |v: f64| v as $f as f64;
            let u = <$f as Scalar>::unit_roundoff();
            let mut checked = 0;
            let mut cases = field_edge_cases();
            // 60 seeded rows in the default tier, 320 in the extensive tier.
            cases.extend(field_random_cases(tiered(60, 320)));
            for c in &cases {
                let fail = |e: String| panic!("{} ({}): {e}\ninputs: {c:?}", stringify!($f), c.why);
                let Some(ex) = exact_row(c, &round) else {
                    continue;
                };
                let a = |v: [f64; 3]| v.map(|x| x as $f);
                let f = Field::<$f>::new(a(c.n1), a(c.n2), a(c.n3), a(c.l));
                let (x, y) = (c.x as $f, c.y as $f);
                let row = f.row(x, y, c.n);
                // The batched set-up is the direct one, bit for bit, in every lane.
                let lanes = Batch::<$f>::set_up(&f, &[x; BATCH], &[y; BATCH], &[c.n; BATCH]);
                for r in 0..BATCH {
                    if lanes.get(r) != row {
                        fail(format!("batch lane {r} differs from Field::row"));
                    }
                }
                // The stepped set-up reaches the same row.
                let steps = c.dxs.len();
                let mut st = EdgeStepper::<$f>::new(
                    &f,
                    (c.x - c.dxs.iter().sum::<f64>()) as $f,
                    (c.y - steps as f64) as $f,
                );
                for dx in &c.dxs {
                    st.step(&f, *dx as $f);
                }
                if (st.x, st.y) != (x, y) {
                    fail(format!("stepper at ({}, {})", st.x, st.y));
                }
                let stepped_row = st.start.span(&f, c.n);
                let starts: [(&str, StartError, _); 2] = [
                    ("direct", direct_start(&ex.shape), row),
                    (
                        "stepped",
                        stepped_start(&ex.shape, &stepped_shape(c, &round, st.since_restart)),
                        stepped_row,
                    ),
                ];
                let mut out = vec![0 as $f; c.n as usize + 1];
                let exact_of =
                    [Method::CorrectedEuler, Method::Gouraud, Method::Phong].map(|m| ex.values(m));
                for (how, e_start, rs) in starts {
                    let Some(e) = span_error(&ex.shape, &e_start, u) else {
                        continue;
                    };
                    let lam = ex.shape.lambda;
                    type Run = fn(&RowSpan<$f>, &mut [$f]);
                    let kernels: [(RowKernel, usize, Run); 3] = [
                        (RowKernel::CorrectedEuler, 0, RowSpan::<$f>::corrected_euler),
                        (RowKernel::Gouraud, 1, RowSpan::<$f>::gouraud),
                        (RowKernel::Phong, 2, RowSpan::<$f>::phong),
                    ];
                    for (k, which, run) in kernels {
                        let (Some(b), Some(exact)) = (
                            kernel_bound(k, c.n, &e, lam, ex.q_min(), u),
                            &exact_of[which],
                        ) else {
                            continue;
                        };
                        run(&rs, &mut out);
                        let got: Vec<f64> = out.iter().map(|v| f64::from(*v)).collect();
                        within(&format!("{how} {k:?}"), &got, exact, b).unwrap_or_else(fail);
                        checked += 1;
                    }
                    rsqrt_row_check!(
                        $f,
                        rs,
                        k_bound = kernel_bound(RowKernel::PhongRsqrt, c.n, &e, lam, ex.q_min(), u),
                        exact_of[2],
                        out,
                        how,
                        fail,
                        checked
                    );
                }
                // Phong of the field, from the direct and the stepped starts.
                let Some(exact) = ex.field_phong() else {
                    continue;
                };
                let qm = ex.field_q_min();
                let field_starts = [
                    ("direct", direct_start(&ex.shape), f.start(x, y)),
                    (
                        "stepped",
                        stepped_start(&ex.shape, &stepped_shape(c, &round, st.since_restart)),
                        st.start,
                    ),
                ];
                for (how, e_start, start) in field_starts {
                    if let Some(b) = field_phong_bound(&ex.shape, &e_start, qm, false, u) {
                        start.phong_field(&f, c.n, &mut out);
                        let got: Vec<f64> = out.iter().map(|v| f64::from(*v)).collect();
                        within(&format!("{how} field Phong"), &got, &exact, b).unwrap_or_else(fail);
                        checked += 1;
                    }
                    field_rsqrt_check!(
                        $f,
                        start,
                        f,
                        c,
                        field_phong_bound(&ex.shape, &e_start, qm, true, u),
                        exact,
                        out,
                        how,
                        fail,
                        checked
                    );
                }
            }
            // Most rows give several kernel checks (fewer seeded rows by default).
            let want = tiered(600, 1000);
            assert!(checked > want, "only {checked} rows checked");
        }
    };
}

/// The `rsqrt` kernels exist in `f32` only.
macro_rules! rsqrt_row_check {
    (f32, $rs:ident, k_bound = $b:expr, $exact:expr, $out:ident, $how:ident, $fail:ident, $checked:ident) => {
        if let (Some(b), Some(exact)) = ($b, &$exact) {
            $rs.phong_rsqrt(&mut $out);
            let got: Vec<f64> = $out.iter().map(|v| f64::from(*v)).collect();
            within(&format!("{} Phong rsqrt", $how), &got, exact, b).unwrap_or_else($fail);
            $checked += 1;
        }
    };
    (f64, $($rest:tt)*) => {};
}

macro_rules! field_rsqrt_check {
    (f32, $start:ident, $f:ident, $c:ident, $b:expr, $exact:ident, $out:ident, $how:ident, $fail:ident, $checked:ident) => {
        if let Some(b) = $b {
            phong_field_rsqrt(&$start, &$f, $c.n, &mut $out);
            let got: Vec<f64> = $out.iter().map(|v| f64::from(*v)).collect();
            within(&format!("{} field Phong rsqrt", $how), &got, &$exact, b).unwrap_or_else($fail);
            $checked += 1;
        }
    };
    (f64, $($rest:tt)*) => {};
}

row_tests!(row_kernels_match_exact_f32, f32);
row_tests!(row_kernels_match_exact_f64, f64);

// ---------------------------------------------------------------------------------
// The claims of proofs/FastSetup.v, one test per theorem, exactly in rationals.

/// `1 − N_a·N_b` of a span.
fn omc(s: &Span<Q>) -> Q {
    qi(1) - s.na.dot(&s.nb)
}

/// eqs. 11–17: corrected Euler is Gouraud plus the parabola
/// `(1 − c)(p_a + p_b)·i(n − i)/(2n²)`, at every pixel of every exact unit span.
#[test]
fn fast_rows_ce_from_span_invariants() {
    for_all_spans(128, |_, s| {
        let ce = Method::CorrectedEuler
            .values(s)
            .map_err(|e| e.to_string())?;
        let n = qi(s.n);
        for (i, v) in ce.iter().enumerate() {
            let i = qi(i as u32);
            let want = s.p_a.clone()
                + i.clone() * (s.p_b.clone() - s.p_a.clone()) / n.clone()
                + omc(s) * (s.p_a.clone() + s.p_b.clone()) * i.clone() * (n.clone() - i)
                    / (qi(2) * n.clone() * n.clone());
            eq("corrected Euler", v, &want)?;
        }
        Ok(())
    });
}

/// eqs. 2–3: `A = (p_b − p_a)/n`, `B = p_a`, `C = 2(1 − c)/n²`, `D = −2(1 − c)/n`,
/// `E = 1` on every exact unit span, as the span's own set-up computes them.
#[test]
fn fast_rows_phong_from_span_invariants() {
    for_all_spans(128, |_, s| {
        let n = qi(s.n);
        eq("A", &s.a, &((s.p_b.clone() - s.p_a.clone()) / n.clone()))?;
        eq("B", &s.b, &s.p_a)?;
        eq("C", &s.c, &(qi(2) * omc(s) / (n.clone() * n.clone())))?;
        eq("D", &s.d, &(-(qi(2) * omc(s)) / n))?;
        eq("E", &s.e, &qi(1))
    });
}

/// Seeded rational vectors: components `k/64` with `|k| ≤ 64·scale`.
fn rational_vectors(count: usize, seed: u64) -> Vec<[Vec3<Q>; 4]> {
    let mut state = seed;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    (0..count)
        .map(|_| {
            [0; 4].map(|_| {
                let mut c = || q((next() % 257) as i64 - 128, 64);
                Vec3::new(c(), c(), c())
            })
        })
        .collect()
}

/// From `s = U·L`, `g = U·n1`, `q = U·U` alone: `U_b·L`, `U·U_b` and `U_b·U_b` of
/// `U_b = U + m·n1` exactly, and the normalized ends' `p_a`, `p_b`, `c` (square roots
/// to 2^-256; checked to 2^-200), as `RowStart::span` computes them.
#[test]
fn fast_rows_field_span_identities() {
    let tiny = q(1, 1) / Q::from_integer(num_bigint::BigInt::from(1) << 200);
    for [u, n1, l, mv] in rational_vectors(200, 0x2545_f491_4f6c_dd1d) {
        let m = mv.x.clone();
        let ub = u.add(&n1.scale(&m));
        let (s, g, qq) = (u.dot(&l), u.dot(&n1), u.dot(&u));
        let ok = |what: &str, a: &Q, b: &Q| {
            assert!(
                a == b,
                "{what}: {a} ≠ {b} (U = {u:?}, n1 = {n1:?}, m = {m})"
            )
        };
        ok("U_b·L", &ub.dot(&l), &(s.clone() + m.clone() * n1.dot(&l)));
        ok("U·U_b", &u.dot(&ub), &(qq.clone() + m.clone() * g.clone()));
        ok(
            "U_b·U_b",
            &ub.dot(&ub),
            &(qq.clone() + qi(2) * m.clone() * g.clone() + m.clone() * m.clone() * n1.dot(&n1)),
        );
        let qb = ub.dot(&ub);
        if qq == qi(0) || qb == qi(0) {
            continue;
        }
        let (ra, rb) = (Real::sqrt(&qq), Real::sqrt(&qb));
        let (na, nb) = (u.div(&ra), ub.div(&rb));
        let close = |what: &str, a: Q, b: Q| {
            let d = a.clone() - b.clone();
            let d = if d < qi(0) { -d } else { d };
            assert!(d < tiny, "{what}: {a} vs {b}");
        };
        close("|N_a| = 1", na.dot(&na), qi(1));
        close("p_a", na.dot(&l), s.clone() / ra.clone());
        close("c", na.dot(&nb), u.dot(&ub) / (ra * rb));
    }
}

/// Forward differences down an edge equal the direct evaluation of `U·L`, `U·n1`,
/// `U·n2`, `U·U` at every row, for any sequence of x moves: in rationals through the
/// theorem's recurrence, and in the crate's `EdgeStepper<f64>` on inputs small enough
/// (multiples of 1/64, below 2 in size, whole or half-pixel moves) that no operation
/// rounds, where it must agree with the field bit for bit.
#[test]
fn edge_stepped_setup_exact() {
    for (t, [n1, n2, n3, l]) in rational_vectors(100, 0x9e37_79b9_7f4a_7c15)
        .into_iter()
        .enumerate()
    {
        let dxs: Vec<Q> = (0..20)
            .map(|k| q(((k * 7 + t) % 9) as i64 - 4, 2))
            .collect();
        let at = |x: &Q, y: &Q| n1.scale(x).add(&n2.scale(y)).add(&n3);
        let state = |x: &Q, y: &Q| {
            let u = at(x, y);
            [u.dot(&l), u.dot(&n1), u.dot(&n2), u.dot(&u)]
        };
        let (mut x, mut y) = (q(-3, 2), q(5, 1));
        let mut st = state(&x, &y);
        // The f64 stepper on the same (exactly representable) inputs.
        let f64v = |v: &Vec3<Q>| [v.x.to_f64(), v.y.to_f64(), v.z.to_f64()];
        let field = Field::<f64>::new(f64v(&n1), f64v(&n2), f64v(&n3), f64v(&l));
        let mut e = EdgeStepper::<f64>::new(&field, x.to_f64(), y.to_f64());
        for dx in &dxs {
            let [s, g, h, qq] = st.clone();
            let c = |a: &Vec3<Q>, b: &Vec3<Q>| a.dot(b);
            st = [
                s + dx.clone() * c(&n1, &l) + c(&n2, &l),
                g.clone() + dx.clone() * c(&n1, &n1) + c(&n1, &n2),
                h.clone() + dx.clone() * c(&n1, &n2) + c(&n2, &n2),
                qq + qi(2) * (dx.clone() * g + h)
                    + dx.clone() * dx.clone() * c(&n1, &n1)
                    + qi(2) * dx.clone() * c(&n1, &n2)
                    + c(&n2, &n2),
            ];
            x += dx.clone();
            y += qi(1);
            assert_eq!(st, state(&x, &y), "rationals, case {t} at ({x}, {y})");
            e.step(&field, dx.to_f64());
            let direct = field.start(x.to_f64(), y.to_f64());
            assert_eq!(e.start, direct, "EdgeStepper<f64>, case {t} at ({x}, {y})");
            assert_eq!(qf(e.start.q), st[3], "EdgeStepper<f64> q, case {t}");
        }
    }
}

/// One Newton step `r(3 − q·r²)/2` on `r = (1 + e)/√q` leaves relative error
/// `−(3/2·e² + 1/2·e³)`, at most `7/4·e²` for `|e| ≤ 1/2` (on square `q`, where `√q`
/// is rational), and the `rsqrt` kernels are within their derived bounds
/// (`phong_rsqrt_within_its_derived_bound`, `row_kernels_match_exact_f32`).
#[test]
fn rsqrt_newton_step_error() {
    for sq in [q(1, 1), q(3, 7), q(25, 4), q(1, 1000)] {
        let qq = sq.clone() * sq.clone();
        for k in -64..=64 {
            let e = q(k, 128);
            let r = (qi(1) + e.clone()) / sq.clone();
            let newton = r.clone() * (qi(3) - qq.clone() * r.clone() * r) / qi(2);
            let e2 = e.clone() * e.clone();
            let rel = q(3, 2) * e2.clone() + q(1, 2) * e2.clone() * e.clone();
            assert_eq!(
                newton,
                (qi(1) - rel.clone()) / sq.clone(),
                "q = {qq}, e = {e}"
            );
            let abs = if rel < qi(0) { -rel } else { rel };
            assert!(abs <= q(7, 4) * e2, "q = {qq}, e = {e}");
        }
    }
}

/// Every row length from 1 pixel to `STEPPED_FROM + 3·LANES` (224) — every remainder of the 8-, 32- and 64-pixel
/// chunks and of the 32-lane recurrence, on both sides of `fast::STEPPED_FROM` — on
/// every vector path this CPU has: each kernel fills exactly `out[..=n]`, leaves the
/// room after it alone, stays within its bound of the exact run, and gives the same
/// bits on every path.
#[test]
fn every_row_length_on_every_path() {
    use phong_approx::fast::{LANES, STEPPED_FROM};
    use phong_approx::simd::{self, Path};
    let (na, nb, l) = (Stereo(0, 0, 1), Stereo(1, 0, 3), Stereo(2, 1, 5));
    let paths = Path::supported_paths();
    let chosen = simd::path();
    type Run = fn(&FastSpan<f32>, &mut [f32]);
    let kernels: [(Method, Kernel, Run); 5] = [
        (
            Method::CorrectedEuler,
            Kernel::CorrectedEuler,
            FastSpan::<f32>::corrected_euler,
        ),
        (Method::Euler, Kernel::Euler, FastSpan::<f32>::euler),
        (Method::Gouraud, Kernel::Gouraud, FastSpan::<f32>::gouraud),
        (Method::Phong, Kernel::Phong, FastSpan::<f32>::phong),
        (
            Method::SymmetricPhong,
            Kernel::SymmetricPhong,
            FastSpan::<f32>::symmetric_phong,
        ),
    ];
    // Both sides of the threshold, and every remainder of the lanes past it.
    let longest = (STEPPED_FROM + 3 * LANES) as u32;
    for n in 1..longest {
        let c = Case {
            why: "every row length",
            na,
            nb,
            l,
            n,
        };
        let s = c.span().expect("a unit span");
        let f = FastSpan::<f32>::from_span(&s.cast::<f32>().unwrap());
        let u = f64::from(f32::EPSILON) / 2.0;
        for (m, k, run) in kernels {
            let b = fast_bound(k, n, q_min(&s), u).expect("a bounded span");
            let exact = exact_values(m, &c, &s);
            let mut first: Option<Vec<f32>> = None;
            for &path in &paths {
                simd::force(path).unwrap();
                let mut out = vec![-7.0f32; n as usize + 5];
                run(&f, &mut out);
                assert!(
                    out[n as usize + 1..].iter().all(|&v| v == -7.0),
                    "{m} on the {path} path wrote past pixel n = {n}"
                );
                for i in 0..=n as usize {
                    let e = err(&out[i], &exact[i]);
                    assert!(
                        e <= b,
                        "{m} on the {path} path, n = {n}, pixel {i}: {e:e} > {b:e}"
                    );
                }
                match &first {
                    None => first = Some(out),
                    Some(f0) => assert!(
                        f0.iter().zip(&out).all(|(x, y)| x.to_bits() == y.to_bits()),
                        "{m}, n = {n}: the {path} path's bits differ from the {} path's",
                        paths[0]
                    ),
                }
            }
        }
    }
    simd::force(chosen).unwrap();
}
