//! Squared corrected Euler: the paper's second open question (§7.1, b) — "maybe we
//! also could gain something if we computed (N·H)² in order to get rid of the square
//! root. The derivative will then be simpler."
//!
//! Corrected Euler's construction (eqs. 15–17) applied to `g = p²/q` instead of
//! `f = p/√q`, with `p(t) = B + A·t`, `q(t) = E + D·t + C·t²` (eqs. 2–3; `L` is the
//! half vector `H` for a specular term):
//!
//! - **the ends are exact and need no root**: `g_a = B²/E`, `g_b = p_b²/q_b`
//!   (`sq_starts_at_ga`, `sq_ends_at_gb`), for edge normals of any non-zero length;
//! - **the derivative is rational**: `g′ = p·(2A·q − p·q′)/q²`, `q′ = D + 2C·t`
//!   (`sq_derivative`); with unit edge normals `g′_a = 2·p_a·di_a` and
//!   `g′_b = 2·p_b·di_b`, twice `p` times corrected Euler's end slopes
//!   (`sq_unit_setup`);
//! - **two additions per pixel**, `g_{i+1} = g_i + t_i`, `t_{i+1} = t_i + ds`, with
//!   `ds = (g′_b − g′_a)/n`, `ε = g_a + n·g′_a + n(n−1)/2·ds − g_b`,
//!   `t_0 = g′_a − ε/n`, so `g_i = g_a + i·t_0 + i(i−1)/2·ds` (`sq_closed_form`);
//! - **specular without a root**: where `p > 0`, `(p/√q)^s = g^{s/2}` for even `s`
//!   (`sq_specular_even`); odd `s` needs one square root per pixel,
//!   `g^{(s−1)/2}·√g` (`sq_specular_odd`). The sign of `p` comes from its own
//!   recurrence `p_{i+1} = p_i + A` (a third addition, and only where the light can
//!   be behind the surface).
//! - A diffuse use is `√g = |p|/√q` (`sq_nonneg_value`): one square root per pixel,
//!   the cost Phong's normalization has and the linear methods avoid — so the method
//!   is for the specular term.
//!
//! Proved: `proofs/Squared.v`. Tested: `tests/squared.rs`.

use crate::error::{Input, SpanError};
use crate::scalar::{Real, Scalar};
use crate::vector::Vec3;

/// The set-up of one span of the squared method, in the paper's notation with `g` for
/// the squared cosine. No square root: every field is a field operation on the inputs.
#[derive(Clone, Debug, PartialEq)]
pub struct SquaredSpan<T> {
    /// Steps, `n ≥ 1`.
    pub n: u32,
    /// `A = k·H`, `k = (N_b − N_a)/n`: the step of `p` (eq. 2).
    pub a: T,
    /// `B = N_a·H = p_a` (eq. 2).
    pub b: T,
    /// `g_a = B²/E`, `E = N_a·N_a`: the exact squared cosine at the left edge.
    pub g_a: T,
    /// `g_b = p_b²/q_b`, `p_b = N_b·H`, `q_b = N_b·N_b`: at the right edge.
    pub g_b: T,
    /// `g′_a = B·(2A·E − B·D)/E²`, `D = 2k·N_a`: `g`'s slope at the left edge.
    pub dg_a: T,
    /// `g′_b = p_b·(2A·q_b − p_b·dq_b)/q_b²`, `dq_b = 2nC + D`, `C = k·k`.
    pub dg_b: T,
    /// `ds = (g′_b − g′_a)/n`, the step of the interpolated slope.
    pub ds: T,
    /// `ε = g_a + n·g′_a + n(n−1)/2·ds − g_b`, where plain Euler on `g` misses `g_b`.
    pub eps: T,
    /// `t_0 = g′_a − ε/n`, the corrected start slope.
    pub t0: T,
}

/// The catalogue's value of the squared method on `span` (its `l` the light or the
/// half vector): `v_i = sign(p_i)·√max(0, g_i)`, with `g_i` from
/// [`SquaredSpan::shade`] (two additions per pixel) and `p_i` from its own
/// recurrence `p_{i+1} = p_i + A`, `p_0 = B` (a third); `0` where `p_i = 0`. At the
/// ends of a span of unit edge normals it is `p_a` and `p_b`, Phong's values
/// (`sq_starts_at_ga`, `sq_ends_at_gb`, `sq_nonneg_value`). Its specular value
/// `max(0, v_i)^s` is `g_i^{s/2}` where `p_i > 0` ([`SquaredSpan::specular`] computes
/// it without the root for even `s`). One square root per pixel: the cost a
/// diffuse use has (module documentation).
///
/// # Errors
/// As [`SquaredSpan::of`]; [`SpanError::OutputLength`] if `out.len() ≠ n + 1`;
/// [`SpanError::NotFiniteValue`] where a float value overflows.
pub fn shade<T: Real>(span: &crate::Span<T>, out: &mut [T]) -> Result<(), SpanError> {
    let sq = SquaredSpan::of(span)?;
    sq.shade(out)?; // checks `out`'s length
    let mut p = sq.b.clone();
    for v in out.iter_mut() {
        *v = if *v > T::zero() && p != T::zero() {
            let r = v.sqrt();
            if p > T::zero() {
                r
            } else {
                T::zero() - r
            }
        } else {
            T::zero()
        };
        p.add_assign_ref(&sq.a);
    }
    span.check_finite(out)
}

fn check<T: Scalar>(v: &Vec3<T>, input: Input) -> Result<(), SpanError> {
    for (component, c) in v.components().into_iter().enumerate() {
        if !c.is_finite() {
            return Err(SpanError::NonFinite { input, component });
        }
    }
    if v.length_squared() == T::zero() {
        return Err(SpanError::ZeroVector { input });
    }
    Ok(())
}

impl<T: Scalar> SquaredSpan<T> {
    /// Sets up the span from edge normals of any non-zero length, the half vector `H`
    /// (any length: `g` scales with `|H|²`) and `n ≥ 1` steps.
    ///
    /// # Errors
    /// [`SpanError`] naming an input that is not finite or is zero (`H` may be zero:
    /// then `g = 0`), or `n` outside 1 to [`crate::span::MAX_STEPS`].
    pub fn new(na: &Vec3<T>, nb: &Vec3<T>, h: &Vec3<T>, n: u32) -> Result<Self, SpanError> {
        check(na, Input::Na)?;
        check(nb, Input::Nb)?;
        for (component, c) in h.components().into_iter().enumerate() {
            if !c.is_finite() {
                return Err(SpanError::NonFinite {
                    input: Input::L,
                    component,
                });
            }
        }
        crate::span::check_steps(n)?;
        let two = T::one() + T::one();
        let n_s = T::from_i64(i64::from(n));
        let k = nb.sub(na).div(&n_s);
        let a = k.dot(h);
        let b = na.dot(h);
        let c = k.dot(&k);
        let d = two.clone() * k.dot(na);
        let e = na.dot(na);
        let p_b = nb.dot(h);
        let q_b = nb.dot(nb);
        let dq_b = two.clone() * n_s.clone() * c + d.clone();
        let g_a = b.clone() * b.clone() / e.clone();
        let g_b = p_b.clone() * p_b.clone() / q_b.clone();
        let dg_a =
            b.clone() * (two.clone() * a.clone() * e.clone() - b.clone() * d) / (e.clone() * e);
        let dg_b = p_b.clone() * (two * a.clone() * q_b.clone() - p_b * dq_b) / (q_b.clone() * q_b);
        let ds = (dg_b.clone() - dg_a.clone()) / n_s.clone();
        let tri = T::from_i64(i64::from(n) * (i64::from(n) - 1) / 2);
        let eps = g_a.clone() + n_s.clone() * dg_a.clone() + tri * ds.clone() - g_b.clone();
        let t0 = dg_a.clone() - eps.clone() / n_s;
        Ok(SquaredSpan {
            n,
            a,
            b,
            g_a,
            g_b,
            dg_a,
            dg_b,
            ds,
            eps,
            t0,
        })
    }

    /// The span of `span`'s inputs (its `l` is the half vector).
    ///
    /// # Errors
    /// As [`SquaredSpan::new`] (a [`crate::Span`]'s inputs always pass).
    pub fn of(span: &crate::Span<T>) -> Result<Self, SpanError> {
        Self::new(&span.na, &span.nb, &span.l, span.n)
    }

    /// Fills `out[i]` with `g_i` of `g_{i+1} = g_i + t_i`, `t_{i+1} = t_i + ds`,
    /// `g_0 = g_a`: two additions per pixel (corrected Euler's loop, eqs. 16–17, on
    /// `g`).
    ///
    /// # Errors
    /// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
    pub fn shade(&self, out: &mut [T]) -> Result<(), SpanError> {
        if out.len() != self.n as usize + 1 {
            return Err(SpanError::OutputLength {
                expected: self.n as usize + 1,
                got: out.len(),
            });
        }
        crate::euler::recurrence(self.g_a.clone(), self.t0.clone(), &self.ds, out);
        Ok(())
    }

    /// Fills `out[i]` with the specular base `max(0, N·H/|N|)^s` from `g_i`: `0` where
    /// `p_i = B + i·A ≤ 0` (its own recurrence) or `g_i ≤ 0`, else `g_i^{s/2}` for even
    /// `s` (no root) and `g_i^{(s−1)/2}·√g_i` for odd `s` (one root per pixel); `1`
    /// everywhere for `s = 0` (as [`crate::specular::power`]: `max(0, v)^0 = 1`).
    /// Wherever `p_i ≠ 0` this is `max(0, v_i)^s` of the catalogue's value
    /// ([`shade`]).
    ///
    /// # Errors
    /// [`SpanError::OutputLength`] if `out.len() ≠ n + 1`.
    pub fn specular(&self, shininess: u32, out: &mut [T]) -> Result<(), SpanError>
    where
        T: Real,
    {
        self.shade(out)?;
        // `max(0, v)^0 = 1` everywhere, as `specular::power` has it.
        if shininess == 0 {
            out.fill(T::one());
            return Ok(());
        }
        // The exponent's parity is the span's, not the pixel's: decided once.
        let (half, odd) = (shininess / 2, !shininess.is_multiple_of(2));
        let mut p = self.b.clone();
        for g in out.iter_mut() {
            *g = if p > T::zero() && *g > T::zero() {
                let even = crate::specular::power(g, half);
                if odd {
                    even * g.sqrt()
                } else {
                    even
                }
            } else {
                T::zero()
            };
            p.add_assign_ref(&self.a);
        }
        Ok(())
    }
}
