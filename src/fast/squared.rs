//! The squared method's fast `f32`/`f64` kernel: the set-up of
//! [`crate::squared_corrected_euler::SquaredSpan::new`] by its operations in its order
//! (the same bits), then `g_i` by corrected Euler's kernel on `g = p²/q`
//! ([`super::FastSpan::corrected_euler`]'s loop: the closed form
//! `g_a + i·(t_0 + (i − 1)·(ds/2))` on a row shorter than [`super::STEPPED_FROM`], the
//! recurrence in [`super::LANES`] lanes on a longer one), then at every pixel on its
//! own `p_i = B + i·A` and the value `sign(p_i)·√max(0, g_i)`, or for the specular
//! term `g_i^{s/2}` by the repeated squaring of [`crate::specular::power`] in a pass
//! of eight-pixel chunks; every loop on the chosen vector path ([`crate::simd`]).
//!
//! These are the operations of the method's operation graphs `closed` and `lanes`
//! (`tolerance::graphs`, `docs/float.md` §19.7), so its `ieee` bound covers the
//! kernel; [`SquaredSpan`]'s recurrence pixel after pixel is the graph `recurrence`.
//!
//! Tested: `tests/squared.rs` (the set-up's bits, the values against the recurrence,
//! the same bits on every path) and `tests/graph.rs` (`graph_sound`: within the bound
//! at every pixel). Measured: `benches/specular.rs`.
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

            /// `out[i] = y(g_i, p_i)`: `g_i` by corrected Euler's kernel
            /// ([`super::FastSpan::corrected_euler`]'s loop: the closed form on a
            /// short row, the recurrence in lanes on a long one), then `p_i` by its
            /// closed form, every pixel on its own.
            #[inline(always)]
            fn each(&self, out: &mut [$f], y: impl Fn($f, $f) -> $f) {
                let (a, b) = (self.a, self.b);
                super::quadratic(self.g_a, self.t0, self.ds, out);
                super::map_index(out, |g, x| y(g, b + x * a))
            }

            /// The value `sign(p_i)·√max(0, g_i)` at `i = 0..out.len()` (0 where
            /// `p_i = 0`), [`crate::squared_corrected_euler::shade`]'s value.
            pub fn shade(&self, out: &mut [$f]) {
                self.each(out, |g, p| {
                    if g > 0.0 && p != 0.0 {
                        g.sqrt().copysign(p)
                    } else {
                        0.0
                    }
                })
            }

            /// The specular term `max(0, v_i)^shininess = g_i^{s/2}` where `p_i > 0`
            /// (else 0; 1 everywhere for `s = 0`), as
            /// [`crate::squared_corrected_euler::SquaredSpan::specular`] computes it
            /// from its `g_i`.
            pub fn specular(&self, shininess: u32, out: &mut [$f]) {
                if shininess == 0 {
                    out.fill(1.0);
                    return;
                }
                self.each(out, |g, p| if p > 0.0 && g > 0.0 { g } else { 0.0 });
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
            for b in &mut base {
                *b = *b * *b;
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
