//! Fast `f32`/`f64` span kernels: the same mathematical quantities as the paper's
//! recurrences, computed the way today's CPUs like.
//!
//! The recurrences of the paper (`p += t; t += ds`) are kept as they are in
//! [`crate::euler`], [`crate::corrected_euler`], … — they are the reference an
//! incremental implementation must match. Their loop carries a dependency from one
//! pixel to the next, so it runs at the latency of a float addition per pixel and
//! cannot use SIMD. The kernels here evaluate the same quadratics in closed form,
//! `p_i = p_a + i·t_0 + i(i − 1)/2·ds` (eq. 14 with `t_0` for `di_a`), so every pixel
//! is independent and LLVM vectorizes the loop — or, on long rows, run the paper's
//! recurrence in [`LANES`] independent lanes, each stepping [`LANES`] pixels at a time
//! (two additions a pixel, no product); the Phong kernel evaluates `p_i/√q_i`
//! with `p` and `q` in closed form (eqs. 2–3). The loop is compiled for three vector
//! paths — the x86-64 baseline, AVX2 with FMA, AVX-512 — one of which is chosen at run
//! time ([`crate::simd`]); every path gives the same bits.
//!
//! The set-up ([`FastSpan::new`]) uses one reciprocal `1/n` instead of several
//! divisions, `dq_b = −dq_a` (eq. 22) and the closed form `ds = D(p_a + p_b)/(2n)`
//! (`eq_11_ds_closed_form`), which need unit edge normals; the kernels do not check
//! their input (use [`crate::Span`] for that, or [`FastSpan::from_span`]).
//!
//! Tested against the exact run and the recurrence twins: `tests/fast.rs`.
//! Measured: `benches/`, `docs/performance.md`.

use crate::span::Span;

mod rsqrt;
mod squared;
pub use rsqrt::{phong_rsqrt_coefficients, phong_rsqrt_f32};
pub use squared::FastSquared;

/// The set-up of a span for the fast kernels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FastSpan<F> {
    /// Steps `n`.
    pub n: u32,
    /// `A = k·L`.
    pub a: F,
    /// `B = p_a = N_a·L`.
    pub b: F,
    /// `C = k·k`.
    pub c: F,
    /// `D = 2k·N_a`.
    pub d: F,
    /// `E = N_a·N_a`.
    pub e: F,
    /// `p_b = N_b·L`.
    pub p_b: F,
    /// `di_a = A − p_a·D/2` (eq. 10).
    pub di_a: F,
    /// `ds = D(p_a + p_b)/(2n)`.
    pub ds: F,
    /// `t_0 = di_a − ε/n` (eq. 17).
    pub t0: F,
    /// The Gouraud slope `(p_b − p_a)/n`.
    pub dp: F,
}

macro_rules! fast_impl {
    ($f:ident) => {
        impl FastSpan<$f> {
            /// The set-up from unit `N_a`, `N_b`, `L` and `n ≥ 1` steps, with one
            /// reciprocal. Unchecked: non-unit input gives meaningless (but finite for
            /// finite input) values, `n = 0` gives non-finite ones.
            #[inline]
            pub fn new(na: [$f; 3], nb: [$f; 3], l: [$f; 3], n: u32) -> Self {
                let dot = |u: [$f; 3], v: [$f; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
                let nf = n as $f;
                let inv_n = 1.0 / nf;
                let k = [
                    (nb[0] - na[0]) * inv_n,
                    (nb[1] - na[1]) * inv_n,
                    (nb[2] - na[2]) * inv_n,
                ];
                let a = dot(k, l);
                let b = dot(na, l);
                let c = dot(k, k);
                let d = 2.0 * dot(k, na);
                let p_b = dot(nb, l);
                let di_a = a - b * 0.5 * d;
                let ds = d * (b + p_b) * 0.5 * inv_n;
                // ε = p_n − p_b with p_n from eq. 14.
                let eps = b + nf * di_a + (nf * (nf - 1.0) * 0.5) * ds - p_b;
                FastSpan {
                    n,
                    a,
                    b,
                    c,
                    d,
                    e: dot(na, na),
                    p_b,
                    di_a,
                    ds,
                    t0: di_a - eps * inv_n,
                    dp: (p_b - b) * inv_n,
                }
            }

            /// The set-up of a checked [`Span`].
            pub fn from_span(s: &Span<$f>) -> Self {
                let v = |x: &crate::Vec3<$f>| [x.x, x.y, x.z];
                Self::new(v(&s.na), v(&s.nb), v(&s.l), s.n)
            }

            /// Corrected Euler, `p_i = p_a + i·(t_0 + (i − 1)/2·ds)`: in closed form on
            /// a row of fewer than [`STEPPED_FROM`] pixels, else by the paper's
            /// recurrence in [`LANES`] lanes (eqs. 16–17; docs/float.md §12). Fills
            /// `out[..=n]`; `out` must hold at least `n + 1` values (extra
            /// values are left alone).
            #[inline]
            pub fn corrected_euler(&self, out: &mut [$f]) {
                quadratic(self.b, self.t0, self.ds, &mut out[..=self.n as usize]);
            }

            /// Plain Euler (eq. 14 at every pixel), in closed form or in lanes as
            /// [`Self::corrected_euler`].
            #[inline]
            pub fn euler(&self, out: &mut [$f]) {
                quadratic(self.b, self.di_a, self.ds, &mut out[..=self.n as usize]);
            }

            /// Gouraud (fence), `p_a + i·dp`: in closed form on a row of fewer than
            /// [`STEPPED_FROM`] pixels, else by `g += dp` in [`LANES`] lanes
            /// (docs/float.md §12).
            #[inline]
            pub fn gouraud(&self, out: &mut [$f]) {
                linear_impl(self.b, self.dp, &mut out[..=self.n as usize]);
            }

            /// Phong in closed form: `(A·i + B)/√(C·i² + D·i + E)`, with `sqrt` and a
            /// division (both correctly rounded, vectorized by LLVM).
            #[inline]
            pub fn phong(&self, out: &mut [$f]) {
                closed_phong_impl(
                    [self.a, self.b, self.c, self.d, self.e],
                    &mut out[..=self.n as usize],
                );
            }

            /// The adaptive test of eqs. 23–24 without eq. 23's division: the largest
            /// difference between Gouraud and corrected Euler is
            /// `δ = ds/2 · ⌈n/2⌉·⌊n/2⌋` (`eq_24_delta_closed_form`). Shades with
            /// Gouraud when `|δ·255·K_d| < 1`, else corrected Euler; returns `true`
            /// for Gouraud.
            #[inline]
            pub fn adaptive(&self, kd: $f, out: &mut [$f]) -> bool {
                let gouraud = (self.delta() * 255.0 * kd).abs() < 1.0;
                if gouraud {
                    self.gouraud(out);
                } else {
                    self.corrected_euler(out);
                }
                gouraud
            }

            /// Eq. 24's `δ` without eq. 23's division: `ds/2 · ⌊n/2⌋·⌈n/2⌉`
            /// (`eq_24_delta_closed_form`), within `10u` of the exact `δ` of the exact
            /// inputs (the set-up's `68u/n²` on `ds` times `n²/8`, and three
            /// roundings; tested against `adaptive::decide` in `tests/fast.rs`).
            #[inline]
            pub fn delta(&self) -> $f {
                let (lo, hi) = ((self.n / 2) as $f, self.n.div_ceil(2) as $f);
                0.5 * self.ds * lo * hi
            }

            /// Angular interpolation (the second source) with every pixel's angle in
            /// closed form, `α_i = α_a + i·(α_b − α_a)/n`, and its cosine.
            #[inline]
            pub fn angular(&self, out: &mut [$f]) {
                let alpha_a = self.b.clamp(-1.0, 1.0).acos();
                let alpha_b = self.p_b.clamp(-1.0, 1.0).acos();
                let d_alpha = (alpha_b - alpha_a) / self.n as $f;
                each_x(&mut out[..=self.n as usize], |x| {
                    (alpha_a + x * d_alpha).cos()
                });
            }

            /// [`Self::angular`] with the cosine read from a table over 0–90° of
            /// `table.len()` entries (the second source: 256), nearest entry; angles
            /// past 90° read the last entry (`cos 90° = 0`).
            #[inline]
            pub fn angular_table(&self, table: &[$f], out: &mut [$f]) {
                let alpha_a = self.b.clamp(-1.0, 1.0).acos();
                let alpha_b = self.p_b.clamp(-1.0, 1.0).acos();
                let d_alpha = (alpha_b - alpha_a) / self.n as $f;
                let last = table.len().saturating_sub(1);
                let per_radian = last as $f / std::$f::consts::FRAC_PI_2;
                for (i, o) in out[..=self.n as usize].iter_mut().enumerate() {
                    let pos = (alpha_a + i as $f * d_alpha) * per_radian + 0.5;
                    *o = table[(pos.max(0.0) as usize).min(last)];
                }
            }

            /// The paper's corrected-Euler inner loop, serial: `p += t; t += ds`
            /// (eqs. 16–17), with this set-up. For measuring against
            /// [`Self::corrected_euler`].
            #[inline]
            pub fn corrected_euler_serial(&self, out: &mut [$f]) {
                let (mut p, mut t, ds) = (self.b, self.t0, self.ds);
                for o in out[..=self.n as usize].iter_mut() {
                    *o = p;
                    p += t;
                    t += ds;
                }
            }

            /// Gouraud as a serial forward difference: `g += dp`.
            #[inline]
            pub fn gouraud_serial(&self, out: &mut [$f]) {
                let (mut g, dp) = (self.b, self.dp);
                for o in out[..=self.n as usize].iter_mut() {
                    *o = g;
                    g += dp;
                }
            }

            /// Duff's serial forward differences with a square root per pixel
            /// (eqs. 5–7).
            #[inline]
            pub fn duff_serial(&self, out: &mut [$f]) {
                let (mut p, mut q, mut dq) = (self.b, self.e, self.c + self.d);
                let (dp, d2q) = (self.a, 2.0 * self.c);
                for o in out[..=self.n as usize].iter_mut() {
                    *o = p / q.sqrt();
                    p += dp;
                    q += dq;
                    dq += d2q;
                }
            }

            /// Phong with `√q` for the first half of the span only, mirrored (§4).
            #[inline]
            pub fn symmetric_phong(&self, out: &mut [$f]) {
                let n = self.n as usize;
                let half = n / 2;
                let (a, b, c, d, e) = (self.a, self.b, self.c, self.d, self.e);
                let out = &mut out[..=n];
                // 1/√q_i into the left half, then the right half as its mirror image
                // (q_i = q_{n−i}), then the factor p_i everywhere.
                let (left, right) = out.split_at_mut(half + 1);
                each_x(left, |x| 1.0 / ((c * x + d) * x + e).sqrt());
                let skip = usize::from(n % 2 == 0);
                for (o, m) in right.iter_mut().zip(left.iter().rev().skip(skip)) {
                    *o = *m;
                }
                scale_x(out, |x| a * x + b);
            }
        }

        /// `0, 1, 2, …, 63`: the offsets of the pixels of a chunk, or the lanes.
        const OFF: [$f; 64] = {
            let mut a = [0.0; 64];
            let mut j = 0;
            while j < 64 {
                a[j] = j as $f;
                j += 1;
            }
            a
        };

        /// Calls `g(&mut out[i], i)` with `i` as a float, eight pixels at a time: the
        /// index is a float base plus constant offsets (exact below 2^24), so no
        /// integer-to-float conversion stands in the way of vectorization.
        #[inline(always)]
        fn chunked(out: &mut [$f], g: impl Fn(&mut $f, $f)) {
            let mut chunks = out.chunks_exact_mut(8);
            let mut base: $f = 0.0;
            for ch in &mut chunks {
                for j in 0..8 {
                    g(&mut ch[j], base + OFF[j]);
                }
                base += 8.0;
            }
            for (j, o) in chunks.into_remainder().iter_mut().enumerate() {
                g(o, base + OFF[j]);
            }
        }

        /// `out[i] = f(i)` on the chosen vector path ([`crate::simd::path`]): the
        /// same loop, [`each_x_w`], compiled for the baseline, for AVX2 with FMA, or
        /// for AVX-512.
        #[inline(always)]
        fn each_x(out: &mut [$f], f: impl Fn($f) -> $f) {
            // A short row is faster inline on the baseline: the wide paths are calls
            // (a function compiled for other features is not inlined into this one),
            // and a row of fewer than `WIDE_FROM` pixels fills few wide vectors
            // (benches/paths.rs). Every path gives the same bits.
            if out.len() < WIDE_FROM {
                return each_x_w::<8>(out, f);
            }
            // Eight-pixel chunks (one AVX2 `f32` vector) but on AVX-512: sixteen.
            crate::simd::dispatch(|p| match p {
                crate::simd::Path::Avx512 => each_x_16(out, f),
                _ => each_x_w::<8>(out, f),
            })
        }

        /// [`each_x_w`] in sixteen-pixel chunks (one AVX-512 `f32` vector), the
        /// last fifteen pixels or fewer in eight-pixel chunks (a short row is not one
        /// wide partial chunk and a copy).
        #[inline(always)]
        fn each_x_16(out: &mut [$f], f: impl Fn($f) -> $f) {
            let wide = out.len() / 16 * 16;
            let (head, tail) = out.split_at_mut(wide);
            let off: [$f; 16] = std::array::from_fn(|j| j as $f);
            let mut base: $f = 0.0;
            for ch in head.chunks_exact_mut(16) {
                for j in 0..16 {
                    ch[j] = f(base + off[j]);
                }
                base += 16.0;
            }
            each_x_w::<8>(tail, |x| f(base + x))
        }

        /// `out[i] = f(i)`, `W` pixels at a time as [`chunked`]; every pixel's value
        /// is `f` of its exact index, whatever `W`.
        #[inline(always)]
        fn each_x_w<const W: usize>(out: &mut [$f], f: impl Fn($f) -> $f) {
            let off: [$f; W] = std::array::from_fn(|j| j as $f);
            let mut chunks = out.chunks_exact_mut(W);
            let mut base: $f = 0.0;
            for ch in &mut chunks {
                for j in 0..W {
                    ch[j] = f(base + off[j]);
                }
                base += W as $f;
            }
            // A partial chunk of four pixels or more (all of a short row) as a whole
            // one into a buffer, one vector pass; fewer one at a time, cheaper than a
            // pass for one to three pixels.
            let rem = chunks.into_remainder();
            if rem.len() >= 4 {
                let tmp: [$f; W] = std::array::from_fn(|j| f(base + off[j]));
                copy_short(rem, &tmp[..rem.len()]);
            } else {
                for (j, o) in rem.iter_mut().enumerate() {
                    *o = f(base + off[j]);
                }
            }
        }

        /// `out[i] *= f(i)`, chunked.
        #[inline(always)]
        fn scale_x(out: &mut [$f], f: impl Fn($f) -> $f) {
            chunked(out, |o, x| *o *= f(x));
        }

        /// `(A i + B)/√(C i² + D i + E)` for `i = 0..len`.
        #[inline(always)]
        fn closed_phong_impl(c: [$f; 5], out: &mut [$f]) {
            let [a, b, c, d, e] = c;
            each_x(out, |x| (a * x + b) / ((c * x + d) * x + e).sqrt());
        }

        /// `p0 + i·(t + (i − 1)/2·ds)` for `i = 0..len`: in closed form on a row
        /// shorter than [`STEPPED_FROM`], else by [`stepped`] on the chosen path.
        #[inline(always)]
        fn quadratic_impl(p0: $f, t: $f, ds: $f, out: &mut [$f]) {
            if out.len() < STEPPED_FROM {
                let half_ds = 0.5 * ds;
                return each_x(out, |x| p0 + x * (t + (x - 1.0) * half_ds));
            }
            stepped_on_path(p0, t, ds, out)
        }

        /// [`stepped`] on the chosen path: out of line, so that the short rows'
        /// closed form stays small enough to inline where it is called.
        #[inline(never)]
        fn stepped_on_path(p0: $f, t: $f, ds: $f, out: &mut [$f]) {
            crate::simd::dispatch(|_| stepped(p0, t, ds, out))
        }

        /// `p0 + i·dp` for `i = 0..len`: in closed form on a row shorter than
        /// [`STEPPED_FROM`], else by [`stepped_linear`] on the chosen path.
        #[inline(always)]
        fn linear_impl(p0: $f, dp: $f, out: &mut [$f]) {
            if out.len() < STEPPED_FROM {
                return each_x(out, |x| p0 + x * dp);
            }
            stepped_linear_on_path(p0, dp, out)
        }

        /// [`stepped_linear`] on the chosen path, out of line as [`stepped_on_path`].
        #[inline(never)]
        fn stepped_linear_on_path(p0: $f, dp: $f, out: &mut [$f]) {
            crate::simd::dispatch(|_| stepped_linear(p0, dp, out))
        }

        /// Gouraud's `g += dp` taken [`LANES`] pixels at a step, in [`LANES`] lanes:
        /// lane `j` starts at the closed form `p0 + j·dp` and adds `L·dp` (exact: `L`
        /// is a power of two) a step. One addition a pixel; the same bits on every
        /// path. Error: docs/float.md §12 (`(0.032n + 15)u`).
        #[inline(always)]
        fn stepped_linear(p0: $f, dp: $f, out: &mut [$f]) {
            let mut p = [0.0; LANES];
            for j in 0..LANES {
                p[j] = p0 + OFF[j] * dp;
            }
            let dpl = LANES as $f * dp;
            let mut chunks = out.chunks_exact_mut(LANES);
            for ch in &mut chunks {
                for j in 0..LANES {
                    ch[j] = p[j];
                    p[j] += dpl;
                }
            }
            for (o, v) in chunks.into_remainder().iter_mut().zip(p) {
                *o = v;
            }
        }

        /// The paper's recurrence `p += t; t += ds` (eqs. 16–17) taken [`LANES`]
        /// pixels at a step, in [`LANES`] lanes: lane `j` holds the pixels
        /// `j, j + L, j + 2L, …` (`L = LANES`), starts from the closed form at `j`, and
        /// steps by its own forward differences,
        /// `p_{i+L} − p_i = L·(t + ds·(j + (L − 1)/2))` for the first step and
        /// `L²·ds` between steps (exact: `L` is a power of two). Two additions a pixel
        /// and no product, where the closed form takes three additions and two
        /// products; each lane's additions depend on that lane alone, so the loop
        /// runs at the width of the vector unit. The lanes are the same on every
        /// path, so every path gives the same bits. Error: docs/float.md §12
        /// (`(0.07n + 51)u` for corrected Euler).
        #[inline(always)]
        fn stepped(p0: $f, t: $f, ds: $f, out: &mut [$f]) {
            let half_ds = 0.5 * ds;
            let l = LANES as $f;
            let (mut p, mut tl) = ([0.0; LANES], [0.0; LANES]);
            for j in 0..LANES {
                let x = OFF[j];
                p[j] = p0 + x * (t + (x - 1.0) * half_ds);
                tl[j] = l * (t + ds * (x + (l - 1.0) * 0.5));
            }
            let dsl = l * l * ds;
            let mut chunks = out.chunks_exact_mut(LANES);
            for ch in &mut chunks {
                for j in 0..LANES {
                    ch[j] = p[j];
                    p[j] += tl[j];
                    tl[j] += dsl;
                }
            }
            for (o, v) in chunks.into_remainder().iter_mut().zip(p) {
                *o = v;
            }
        }
    };
}

/// The shortest row the wide vector paths take (`simd::Path::Avx2`, `Avx512`):
/// shorter ones run the baseline loop inline.
pub const WIDE_FROM: usize = 32;

/// The shortest row (in pixels, `n + 1`) that the Gouraud, corrected Euler and Euler
/// kernels take by their recurrences in [`LANES`] lanes; shorter rows take the closed
/// form (docs/float.md §12; the same bits on every vector path either way). Below four
/// steps of the lanes, filling the lanes (a closed form and a first step for each of
/// 32) costs about what the closed form of the whole row does.
pub const STEPPED_FROM: usize = 128;

/// The lanes of the stepped recurrence: 32 pixels a step (four AVX2 vectors of `f32`,
/// eight SSE2 ones, two AVX-512 ones).
pub const LANES: usize = 32;

/// `dst.copy_from_slice(src)` for the at most seven values of a partial chunk, as
/// fixed-size copies: a copy of variable length is a call to `memcpy`, which costs
/// more than the eight values it follows on a short row.
#[inline(always)]
fn copy_short<F: Copy>(dst: &mut [F], src: &[F]) {
    macro_rules! fixed {
        ($($k:literal)*) => {
            match dst.len() {
                $($k => dst[..$k].copy_from_slice(&src[..$k]),)*
                _ => dst.copy_from_slice(src),
            }
        };
    }
    fixed!(1 2 3 4 5 6 7)
}

/// The chunked loops, for both float types.
pub(crate) trait Kernels: Sized {
    fn quad(p0: Self, t: Self, ds: Self, out: &mut [Self]);
    fn each(out: &mut [Self], f: impl Fn(Self) -> Self);
    fn map(out: &mut [Self], f: impl Fn(Self, Self) -> Self);
    fn phong5(c: [Self; 5], out: &mut [Self]);
}

macro_rules! kernels_for {
    ($f:ident, $m:ident) => {
        mod $m {
            use super::*;
            fast_impl!($f);
            impl Kernels for $f {
                #[inline(always)]
                fn quad(p0: $f, t: $f, ds: $f, out: &mut [$f]) {
                    quadratic_impl(p0, t, ds, out)
                }
                #[inline(always)]
                fn each(out: &mut [$f], f: impl Fn($f) -> $f) {
                    each_x(out, f)
                }
                #[inline(always)]
                fn map(out: &mut [$f], f: impl Fn($f, $f) -> $f) {
                    crate::simd::dispatch(|_| chunked(out, |o, x| *o = f(*o, x)))
                }
                #[inline(always)]
                fn phong5(c: [$f; 5], out: &mut [$f]) {
                    closed_phong_impl(c, out)
                }
            }
        }
    };
}

kernels_for!(f32, f32_impl);
kernels_for!(f64, f64_impl);

#[inline]
fn quadratic<F: Kernels>(p0: F, t: F, ds: F, out: &mut [F]) {
    F::quad(p0, t, ds, out)
}

/// `out[i] = f(i)` with `i` as a float, eight pixels at a time (vectorized).
#[inline(always)]
pub(crate) fn each_index<F: Kernels>(out: &mut [F], f: impl Fn(F) -> F) {
    F::each(out, f)
}

/// `out[i] = f(out[i], i)` with `i` as a float, eight pixels at a time on the chosen
/// vector path.
#[inline(always)]
pub(crate) fn map_index<F: Kernels>(out: &mut [F], f: impl Fn(F, F) -> F) {
    F::map(out, f)
}

/// `out[i] = (A i + B)/√(C i² + D i + E)` for the coefficients `[A, B, C, D, E]`
/// (eqs. 2–3), vectorized, with `sqrt` and a division.
#[inline(always)]
pub(crate) fn closed_phong<F: Kernels>(c: [F; 5], out: &mut [F]) {
    F::phong5(c, out)
}
