//! The scan line: every set-up quantity of the paper, computed once.
//!
//! A span runs from the left edge normal `N_a` to the right edge normal `N_b` in
//! `n ≥ 1` steps; its pixels are `i = 0..=n` (`n + 1` values) with the interpolated
//! normal `N(i) = N_a + i·k`, `k = (N_b − N_a)/n`. Every method reads its set-up
//! from a [`Span`]; none recomputes it.
//!
//! Derivations: `docs/derivations.md`. Proofs: `proofs/Span.v`, `proofs/Euler.v`.
//! Tests: `tests/claims/`.

use crate::error::{Input, SpanError};
use crate::scalar::{Real, Scalar};
use crate::vector::Vec3;

/// The largest `n` a span accepts: 2^24, the last integer up to which `f32` counts
/// exactly (and far beyond any scan line).
pub const MAX_STEPS: u32 = 1 << 24;

/// The set-up of one scan line in the paper's notation (eqs. 2–3, 10–11, 14–17, 23).
///
/// Built by [`Span::new`], which checks that `N_a`, `N_b` and `L` are finite, non-zero
/// and of unit length (exactly for rationals, within [`Scalar::unit_tolerance`] for
/// floats), that `N_b ≠ −N_a` and that `n ≥ 1`. Unit edge normals are what make
/// `E = 1` (eq. 3) and `dq_b = −dq_a` (eq. 22) true; [`Span::normalized`] normalizes
/// the inputs first, and [`Span::with_tolerance`] accepts a caller's tolerance (for
/// measuring float inputs against an exact run on the same, not-quite-unit, values).
///
/// Fields are the paper's quantities with the paper's names.
#[derive(Clone)]
pub struct Span<T> {
    /// Normal at the left edge, `N_a` (pixel 0).
    pub na: Vec3<T>,
    /// Normal at the right edge, `N_b` (pixel n).
    pub nb: Vec3<T>,
    /// Unit light vector `L` (or half vector `H` for specular).
    pub l: Vec3<T>,
    /// Number of steps `n = x_2 − x_1 ≥ 1`; the span has `n + 1` pixels.
    pub n: u32,
    /// `n` as a scalar.
    pub n_s: T,
    /// `k = (N_b − N_a)/n`, the normal's step per pixel (§2.1).
    ///
    /// Claims: `eq_18_na_k_is_minus_nb_k` (proofs/Span.v; tests/claims/).
    pub k: Vec3<T>,
    /// `A = k·L` (eq. 2), the slope of `p`.
    pub a: T,
    /// `B = N_a·L` (eq. 2).
    pub b: T,
    /// `C = k·k` (eq. 3).
    ///
    /// Claims: `eq_20_n_k2_is_2k_nb` (proofs/Span.v; tests/claims/).
    pub c: T,
    /// `D = 2 k·N_a` (eq. 3).
    pub d: T,
    /// `E = N_a·N_a` (eq. 3); 1 for a unit `N_a`.
    ///
    /// Claims: `eq_3_e_is_one` (proofs/Span.v; tests/claims/).
    pub e: T,
    /// `p_a = N_a·L`, the exact intensity at the left edge (eq. 10).
    pub p_a: T,
    /// `p_b = N_b·L`, the exact intensity at the right edge (eq. 11).
    pub p_b: T,
    /// `dq_a = D`, the slope of `q` at the left edge (eq. 10).
    ///
    /// Claims: `eq_10_11_dp_dq_at_edges` (proofs/Derivative.v; tests/claims/).
    pub dq_a: T,
    /// `dq_b = 2nC + D`, the slope of `q` at the right edge (eq. 11); equals `−dq_a`
    /// for unit edge normals (eq. 22), but is computed from its definition.
    ///
    /// Claims: `eq_19_dqb_via_nb`, `eq_21_dqb_is_2k_nb`, `eq_22_dqb_is_minus_dqa` (proofs/Span.v; tests/claims/).
    pub dq_b: T,
    /// `di_a = A − p_a/2 · dq_a`, the derivative of `p/√q` at the left edge (eq. 10).
    ///
    /// Claims: `eq_9_derivative` (proofs/Derivative.v; tests/claims/).
    pub di_a: T,
    /// `di_b = A − p_b/2 · dq_b`, the derivative of `p/√q` at the right edge (eq. 11).
    ///
    /// Claims: `eq_10_11_edge_derivatives` (proofs/Derivative.v; tests/claims/).
    pub di_b: T,
    /// `ds = (di_b − di_a)/n`, the step of the interpolated derivative (§3).
    ///
    /// With unit edge normals `ds = −(1 − N_a·N_b)(p_a + p_b)/n²`.
    ///
    /// Claims: `eq_11_ds_closed_form` (proofs/Span.v), `eq_11_ds_unit_closed_form` (proofs/ClosedForms.v); tests/claims/.
    pub ds: T,
    /// `p_n = p_a + n·di_a + (n² − n)/2 · ds`, where plain Euler ends (eq. 14).
    ///
    /// Claims: `eq_14_arithmetic_series`, `eq_14_euler_end_value` (proofs/Euler.v; tests/claims/).
    pub p_n: T,
    /// `ε = p_n − p_b`, plain Euler's error at the right edge (eq. 15).
    ///
    /// With unit edge normals `ε = (1 − N_a·N_b)((p_a − p_b)/2 + (p_a + p_b)/(2n))`, which
    /// tends to `(1 − N_a·N_b)(p_a − p_b)/2` as `n` grows, and is zero only when
    /// `N_a = N_b` or `n(p_a − p_b) + p_a + p_b = 0`.
    ///
    /// Claims: `eq_15_euler_misses_pb` (proofs/Euler.v), `eq_15_eps_closed_form`, `eq_15_eps_limit`, `eq_15_euler_misses_pb_general` (proofs/ClosedForms.v); tests/claims/.
    pub eps: T,
    /// `dε = ε/n`, the correction per step (eq. 17; the text prints `ε/N`).
    pub d_eps: T,
    /// `t_0 = di_a − dε`, the corrected start slope (eq. 17).
    pub t0: T,
    /// `dp = (p_b − p_a)/n`, the Gouraud (fence) slope along the span (eq. 23's `d_p`;
    /// not the `dp = A` of §2.1).
    pub dp: T,
}

/// `n` in `1..=MAX_STEPS`, or the error that names it.
pub(crate) fn check_steps(n: u32) -> Result<(), SpanError> {
    if n == 0 {
        return Err(SpanError::ZeroSteps);
    }
    if n > MAX_STEPS {
        return Err(SpanError::TooManySteps {
            max: MAX_STEPS,
            got: n,
        });
    }
    Ok(())
}

fn check_vector<T: Scalar>(v: &Vec3<T>, input: Input, tol: &T) -> Result<(), SpanError> {
    for (component, c) in v.components().into_iter().enumerate() {
        if !c.is_finite() {
            return Err(SpanError::NonFinite { input, component });
        }
    }
    let len2 = v.length_squared();
    if len2.is_zero() || !len2.is_finite() {
        // A non-finite square (overflow) is as unusable as zero.
        return Err(if len2.is_zero() {
            SpanError::ZeroVector { input }
        } else {
            SpanError::NotUnit {
                input,
                length_squared: len2.to_decimal(6),
                deviation: "not finite".to_string(),
                tolerance: tol.to_f64(),
            }
        });
    }
    let deviation = (len2.clone() - T::one()).magnitude();
    if deviation > *tol {
        return Err(SpanError::NotUnit {
            input,
            length_squared: len2.to_decimal(6),
            deviation: deviation.to_decimal(3),
            tolerance: tol.to_f64(),
        });
    }
    Ok(())
}

/// One line: the inputs (exact fractions for rationals) and `n`, e.g.
/// `N_a = (0, 0, 1), N_b = (3/5, 0, 4/5), L = (0, 0, 1), n = 4` — what a shrunk
/// property-test failure shows.
impl<T: Scalar> std::fmt::Display for Span<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let v = |v: &Vec3<T>| {
            let [x, y, z] = v.components().map(Scalar::exact_text);
            format!("({x}, {y}, {z})")
        };
        write!(
            f,
            "N_a = {}, N_b = {}, L = {}, n = {}",
            v(&self.na),
            v(&self.nb),
            v(&self.l),
            self.n
        )
    }
}

/// The inputs only, on one line (the derived quantities follow from them):
/// `Span { N_a = (…), N_b = (…), L = (…), n = 4 }`.
impl<T: Scalar> std::fmt::Debug for Span<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Span {{ {self} }}")
    }
}

impl<T: Scalar> Span<T> {
    /// Sets up the span from unit `N_a`, `N_b`, `L` and `n ≥ 1` steps.
    ///
    /// # Errors
    /// [`SpanError`] naming the input that is non-finite, zero, not unit, or `n = 0`,
    /// (`N_b = −N_a` is accepted: every method whose values are defined on such a span
    /// computes them; the methods that normalize refuse the pixel where the
    /// interpolated normal is zero, [`Span::check_nonzero_normal`].)
    pub fn new(na: Vec3<T>, nb: Vec3<T>, l: Vec3<T>, n: u32) -> Result<Self, SpanError> {
        Self::with_tolerance(na, nb, l, n, &T::unit_tolerance())
    }

    /// [`Span::new`] with a caller's tolerance on `|v·v − 1|` for the three vectors.
    ///
    /// # Errors
    /// As [`Span::new`].
    pub fn with_tolerance(
        na: Vec3<T>,
        nb: Vec3<T>,
        l: Vec3<T>,
        n: u32,
        tol: &T,
    ) -> Result<Self, SpanError> {
        check_vector(&na, Input::Na, tol)?;
        check_vector(&nb, Input::Nb, tol)?;
        check_vector(&l, Input::L, tol)?;
        check_steps(n)?;
        Ok(Self::setup(na, nb, l, n))
    }

    /// The set-up formulas, in the order the paper gives them.
    fn setup(na: Vec3<T>, nb: Vec3<T>, l: Vec3<T>, n: u32) -> Self {
        let one = T::one();
        let two = one.clone() + one.clone();
        let n_s = T::from_i64(i64::from(n));
        // §2.1: N = k x + m with k = (N_b − N_a)/n, m = N_a.
        let k = nb.sub(&na).div(&n_s);
        // Eq. 2: p = A x + B.
        let a = k.dot(&l);
        let b = na.dot(&l);
        // Eq. 3: q = C x² + D x + E.
        let c = k.dot(&k);
        let d = two.clone() * k.dot(&na);
        let e = na.dot(&na);
        // Eqs. 10–11: edge intensities, slopes of q and derivatives of p/√q (q = 1).
        let p_a = b.clone();
        let p_b = nb.dot(&l);
        let dq_a = d.clone();
        let dq_b = two.clone() * n_s.clone() * c.clone() + d.clone();
        let di_a = a.clone() - p_a.clone() / two.clone() * dq_a.clone();
        let di_b = a.clone() - p_b.clone() / two.clone() * dq_b.clone();
        // §3: s_0 = di_a, ds = (di_b − di_a)/n.
        let ds = (di_b.clone() - di_a.clone()) / n_s.clone();
        // Eq. 14: where plain Euler ends.
        let tri = T::from_i64(i64::from(n) * (i64::from(n) - 1) / 2);
        let p_n = p_a.clone() + n_s.clone() * di_a.clone() + tri * ds.clone();
        // Eqs. 15, 17: ε, dε = ε/n, t_0.
        let eps = p_n.clone() - p_b.clone();
        let d_eps = eps.clone() / n_s.clone();
        let t0 = di_a.clone() - d_eps.clone();
        // Eq. 23's d_p: the Gouraud slope along the span.
        let dp = (p_b.clone() - p_a.clone()) / n_s.clone();
        Span {
            na,
            nb,
            l,
            n,
            n_s,
            k,
            a,
            b,
            c,
            d,
            e,
            p_a,
            p_b,
            dq_a,
            dq_b,
            di_a,
            di_b,
            ds,
            p_n,
            eps,
            d_eps,
            t0,
            dp,
        }
    }

    /// Number of pixels, `n + 1`.
    pub fn len(&self) -> usize {
        self.n as usize + 1
    }

    /// Always `false`: a span has at least two pixels.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// `p(i) = A·i + B = N(i)·L` (eq. 2), the unnormalized dot product at pixel `i`.
    ///
    /// Claims: `eq_2_p_is_linear` (proofs/Span.v; tests/claims/).
    pub fn p_at(&self, i: u32) -> T {
        self.a.clone() * T::from_i64(i64::from(i)) + self.b.clone()
    }

    /// `q(i) = C·i² + D·i + E = N(i)·N(i)` (eq. 3).
    ///
    /// Claims: `eq_3_q_is_quadratic`, `eq_10_q_is_one_on_edges`, `sec_4_q_minimum_at_middle` (proofs/Span.v, proofs/Symmetry.v; tests/claims/).
    pub fn q_at(&self, i: u32) -> T {
        let x = T::from_i64(i64::from(i));
        (self.c.clone() * x.clone() + self.d.clone()) * x + self.e.clone()
    }

    /// `q_min = min_i q(i)` over the pixels `i = 0..=n`: the smallest squared length
    /// of an interpolated normal, on which the float bounds of the normalizing
    /// methods depend (`src/tolerance.rs`). `q` is a parabola (eq. 3), so only the
    /// two pixels around its vertex `−D/(2C)` and the two ends are evaluated.
    pub fn q_min(&self) -> T {
        let n = i64::from(self.n);
        let mut at = vec![0, n];
        if self.c > T::zero() {
            let two = T::one() + T::one();
            let vertex = -self.d.clone() / (two * self.c.clone());
            let v = vertex.floor_i64();
            at.extend([v, v.saturating_add(1)]);
        }
        at.into_iter()
            .map(|i| self.q_at(i.clamp(0, n) as u32))
            .reduce(|a, b| if b < a { b } else { a })
            .expect("two pixels at least")
    }

    /// The interpolated normal `N(i) = N_a + i·k` (§2.1).
    pub fn normal_at(&self, i: u32) -> Vec3<T> {
        self.na.add(&self.k.scale(&T::from_i64(i64::from(i))))
    }

    /// `true` when `N_b = −N_a` (exactly, in `T`).
    pub fn is_opposite(&self) -> bool {
        self.na.add(&self.nb).length_squared().is_zero()
    }

    /// For the methods that divide by `|N(i)|`: the interpolated normal is zero only
    /// when `N_b = −N_a`, at the middle pixel `n/2` of an even `n`.
    ///
    /// # Errors
    /// [`SpanError::ZeroNormal`] naming that pixel.
    pub fn check_nonzero_normal(&self) -> Result<(), SpanError> {
        if self.is_opposite() && self.n.is_multiple_of(2) {
            Err(SpanError::ZeroNormal {
                pixel: self.n as usize / 2,
                n: self.n,
            })
        } else {
            Ok(())
        }
    }

    /// Checks that every value of `out` is finite (for the methods that divide by
    /// `√q`, which floats can round to zero).
    ///
    /// # Errors
    /// [`SpanError::NotFiniteValue`] naming the first pixel that is not.
    pub fn check_finite(&self, out: &[T]) -> Result<(), SpanError> {
        match out.iter().position(|v| !v.is_finite()) {
            None => Ok(()),
            Some(pixel) => Err(SpanError::NotFiniteValue { pixel, n: self.n }),
        }
    }

    /// Checks that `out` holds exactly `n + 1` values.
    ///
    /// # Errors
    /// [`SpanError::OutputLength`] otherwise.
    pub fn check_output(&self, out: &[T]) -> Result<(), SpanError> {
        if out.len() == self.len() {
            Ok(())
        } else {
            Err(SpanError::OutputLength {
                expected: self.len(),
                got: out.len(),
            })
        }
    }

    /// The same span with its inputs converted to another scalar type (exactly for
    /// exact targets, rounded to nearest for floats) and the set-up recomputed there,
    /// without the unit-length check (rounded unit vectors are not exactly unit).
    pub fn cast<U: Scalar>(&self) -> Option<Span<U>> {
        // `self` was built by a constructor, so `1 ≤ n ≤ MAX_STEPS` holds.
        Some(Span::<U>::setup(
            self.na.cast()?,
            self.nb.cast()?,
            self.l.cast()?,
            self.n,
        ))
    }
}

impl<T: Real> Span<T> {
    /// Normalizes `N_a`, `N_b` and `L`, then sets up the span.
    ///
    /// # Errors
    /// As [`Span::new`], except that non-unit lengths are accepted.
    pub fn normalized(na: Vec3<T>, nb: Vec3<T>, l: Vec3<T>, n: u32) -> Result<Self, SpanError> {
        for (v, input) in [(&na, Input::Na), (&nb, Input::Nb), (&l, Input::L)] {
            // Only finiteness and a non-zero component are checked here: the squared
            // length of (1e-170, 0, 1e-170) underflows in f64, but the vector is
            // normalized after scaling by its largest component below.
            for (component, c) in v.components().into_iter().enumerate() {
                if !c.is_finite() {
                    return Err(SpanError::NonFinite { input, component });
                }
            }
            if v.components().iter().all(|c| c.is_zero()) {
                return Err(SpanError::ZeroVector { input });
            }
        }
        // Exact types normalize through a 2^-256-accurate square root, so the result
        // is unit only to about that accuracy: accept 2^-240 there.
        let mut tol = T::unit_tolerance();
        if tol.is_zero() {
            tol = T::one()
                / T::from_i64(1 << 60)
                / T::from_i64(1 << 60)
                / T::from_i64(1 << 60)
                / T::from_i64(1 << 60);
        }
        // Divide by the largest component first, so that the square of the length
        // neither overflows (1e308 in f64) nor vanishes (1e-100 in exact arithmetic,
        // whose square root works in fixed point): it lies in [1, 3] then.
        let scaled = |v: &Vec3<T>| {
            let m = v
                .components()
                .into_iter()
                .map(Scalar::magnitude)
                .fold(T::zero(), |a, b| if b > a { b } else { a });
            v.div(&m).normalize()
        };
        Self::with_tolerance(scaled(&na), scaled(&nb), scaled(&l), n, &tol)
    }
}
