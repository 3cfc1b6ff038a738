//! The squared method's fast `f32`/`f64` kernel: the operations of
//! [`crate::squared_corrected_euler::SquaredSpan`] in its order — so the same bits,
//! and the same operation graph and bound (`docs/float.md` §19.7) — with the root, the
//! sign and the specular power taken in a second pass that vectorizes.
//!
//! The first pass is the recurrence itself: `g += t; t += ds` (eqs. 16–17 on
//! `g = p²/q`) and `p += A`, two additions a pixel and a third for the sign, a chain
//! from one pixel to the next. It stores `sign(p)·g` where `g > 0` and `p ≠ 0`, else
//! 0. The second pass takes, pixel by pixel and independently, `sign(y)·√|y|` (the
//! value `sign(p)·√max(0, g)`) or the specular `g^{s/2}` by the repeated squaring of
//! [`crate::specular::power`], in eight-pixel chunks on the chosen vector path
//! ([`crate::simd`]). The closed form `g_a + i·t_0 + i(i − 1)/2·ds` would vectorize
//! the first pass too, but its rounding is not the recurrence's: no graph of the
//! method bounds it, so no kernel here takes it.
//!
//! Tested: `tests/squared.rs` (the same bits as [`SquaredSpan`] on every path, and
//! within the graph's bound at every pixel). Measured: `benches/paths.rs`.
//!
//! [`SquaredSpan`]: crate::squared_corrected_euler::SquaredSpan

/// The set-up of the squared method for the fast kernel: `A`, `B = p_a`, `g_a`,
/// `ds` and `t_0` of [`crate::squared_corrected_euler::SquaredSpan::new`], computed
/// by its operations in its order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FastSquared<F> {
    /// Steps `n`.
    pub n: u32,
    /// `A = k·H`, the step of `p`.
    pub a: F,
    /// `B = p_a = N_a·H`.
    pub b: F,
    /// `g_a = B²/E`, the first value.
    pub g_a: F,
    /// `ds = (g′_b − g′_a)/n`.
    pub ds: F,
    /// `t_0 = g′_a − ε/n` (eq. 17 on `g`).
    pub t0: F,
}

macro_rules! squared_impl {
    ($f:ident) => {
        impl FastSquared<$f> {
            /// The set-up from edge normals `N_a`, `N_b` of any non-zero length, the
            /// light (or half vector) `H` and `n ≥ 1` steps: no square root, five
            /// divisions. Unchecked: a zero edge normal or `n = 0` gives non-finite
            /// values (use [`crate::squared_corrected_euler::SquaredSpan::new`] for
            /// typed errors).
            #[inline]
            pub fn new(na: [$f; 3], nb: [$f; 3], h: [$f; 3], n: u32) -> Self {
                let dot = |u: [$f; 3], v: [$f; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
                let nf = n as $f;
                let k = [
                    (nb[0] - na[0]) / nf,
                    (nb[1] - na[1]) / nf,
                    (nb[2] - na[2]) / nf,
                ];
                let a = dot(k, h);
                let b = dot(na, h);
                let c = dot(k, k);
                let d = 2.0 * dot(k, na);
                let e = dot(na, na);
                let p_b = dot(nb, h);
                let q_b = dot(nb, nb);
                let dq_b = 2.0 * nf * c + d;
                let g_a = b * b / e;
                let g_b = p_b * p_b / q_b;
                // g′ = p·(2A·q − p·q′)/q² at each end.
                let dg_a = b * (2.0 * a * e - b * d) / (e * e);
                let dg_b = p_b * (2.0 * a * q_b - p_b * dq_b) / (q_b * q_b);
                let ds = (dg_b - dg_a) / nf;
                let tri = (i64::from(n) * (i64::from(n) - 1) / 2) as $f;
                let eps = g_a + nf * dg_a + tri * ds - g_b;
                let t0 = dg_a - eps / nf;
                FastSquared {
                    n,
                    a,
                    b,
                    g_a,
                    ds,
                    t0,
                }
            }

            /// The first pass: `out[i] = y(g_i, p_i)` by the recurrences
            /// `g += t; t += ds` and `p += A`.
            #[inline(always)]
            fn walk(&self, out: &mut [$f], y: impl Fn($f, $f) -> $f) {
                let (mut g, mut t, mut p) = (self.g_a, self.t0, self.b);
                for o in out.iter_mut() {
                    *o = y(g, p);
                    g += t;
                    t += self.ds;
                    p += self.a;
                }
            }

            /// The value `sign(p_i)·√max(0, g_i)` at `i = 0..out.len()` (0 where
            /// `p_i = 0`): [`crate::squared_corrected_euler::shade`]'s bits.
            pub fn shade(&self, out: &mut [$f]) {
                self.walk(out, |g, p| {
                    if g > 0.0 && p != 0.0 {
                        if p > 0.0 {
                            g
                        } else {
                            -g
                        }
                    } else {
                        0.0
                    }
                });
                crate::simd::dispatch(|_| {
                    for o in out.iter_mut() {
                        *o = o.abs().sqrt().copysign(*o);
                    }
                })
            }

            /// The specular term `max(0, v_i)^shininess = g_i^{s/2}` where `p_i > 0`
            /// (else 0; 1 everywhere for `s = 0`):
            /// [`crate::squared_corrected_euler::SquaredSpan::specular`]'s bits.
            pub fn specular(&self, shininess: u32, out: &mut [$f]) {
                if shininess == 0 {
                    out.fill(1.0);
                    return;
                }
                self.walk(out, |g, p| if p > 0.0 && g > 0.0 { g } else { 0.0 });
                let (half, odd) = (shininess / 2, !shininess.is_multiple_of(2));
                crate::simd::dispatch(|_| {
                    let mut chunks = out.chunks_exact_mut(8);
                    for ch in &mut chunks {
                        let g: [$f; 8] = std::array::from_fn(|j| ch[j]);
                        ch.copy_from_slice(&power_w(g, half, odd));
                    }
                    for o in chunks.into_remainder() {
                        *o = power_w([*o], half, odd)[0];
                    }
                })
            }
        }
    };
}

squared_impl!(f32);
squared_impl!(f64);

/// `g^half` (then times `√g` where `odd`) in each of `W` lanes, by
/// [`crate::specular::power`]'s repeated squaring in its order: the exponent's bits
/// are the span's, so every lane takes the same steps and the loop over lanes
/// vectorizes.
#[inline(always)]
fn power_w<F, const W: usize>(g: [F; W], half: u32, odd: bool) -> [F; W]
where
    F: Copy + std::ops::Mul<Output = F> + num_traits::Float,
{
    let mut base = g;
    let mut acc = [F::one(); W];
    let mut e = half;
    while e > 0 {
        if e & 1 == 1 {
            for j in 0..W {
                acc[j] = acc[j] * base[j];
            }
        }
        e >>= 1;
        if e > 0 {
            for j in 0..W {
                base[j] = base[j] * base[j];
            }
        }
    }
    if odd {
        for j in 0..W {
            acc[j] = acc[j] * g[j].sqrt();
        }
    }
    acc
}
