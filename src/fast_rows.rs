//! The per-row set-up of a polygon's spans made cheap: for many rows at once
//! ([`Batch`]), or stepped down the polygon's edge ([`EdgeStepper`]).
//!
//! On the paper's polygons (rows of about six pixels) the set-up of a span costs more
//! than its pixels: two normalizations of the interpolated edge normals, the dot
//! products, a reciprocal. Two facts make it cheap.
//!
//! 1. **Three numbers per row.** With unit edge normals every quantity of the span's
//!    set-up is a function of `p_a`, `p_b`, `c = N_a·N_b` and `n`:
//!    `A = (p_b − p_a)/n`, `B = p_a`, `C = 2(1 − c)/n²`, `D = −2(1 − c)/n`, `E = 1`
//!    (`fast_rows_phong_from_span_invariants`), and corrected Euler is Gouraud plus a
//!    parabola, `p_i = p_a + i(p_b − p_a)/n + (1 − c)(p_a + p_b)·i(n − i)/(2n²)`
//!    (`fast_rows_ce_from_span_invariants`). This is [`RowSpan`].
//! 2. **Three polynomials per row.** Over a polygon the interpolated normal is an
//!    affine field `U(x, y) = n1·x + n2·y + n3` ([`Field`]). A row from `U_a = U(x, y)`
//!    to `U_b = U_a + n·n1` needs only `s = U_a·L`, `g = U_a·n1` and `q = U_a·U_a`
//!    ([`RowStart`]): `U_b·L = s + n(n1·L)`, `U_a·U_b = q + n·g`,
//!    `U_b·U_b = q + 2n·g + n²(n1·n1)` (`fast_rows_field_span_identities`). So a row
//!    costs three short dot products, two square roots and three divisions, and no
//!    vector is normalized.
//!
//! [`Batch`] computes the [`RowSpan`]s of [`BATCH`] rows in one pass over fixed
//! arrays, which LLVM vectorizes: the square roots and divisions of four (SSE) rows
//! go in one instruction; [`Field::for_each_row`] feeds a polygon's rows through it.
//! [`EdgeStepper`] instead steps `s`, `g`, `q` (and `h = U·n2`) from one row to the
//! next by forward differences (`edge_stepped_setup_exact`), the paper's
//! own device applied down the edge, and restarts from the field every
//! [`EdgeStepper::RESTART`] rows so that rounding cannot pile up.
//!
//! The span kernels then run on each row: [`RowSpan::corrected_euler`],
//! [`RowSpan::gouraud`], [`RowSpan::phong`] (the paper's Phong with unit edge
//! normals, eqs. 2–3), [`RowSpan::phong_rsqrt`]; and, without any per-row square
//! root, Phong of the field itself, [`RowStart::phong_field`] (the per-pixel normal
//! normalized at every pixel, as per-pixel Phong does, in closed form).
//!
//! Like [`crate::fast::FastSpan`]'s, these kernels do not check their input (a
//! non-finite field gives non-finite values; [`crate::Span`] is the checked path),
//! and each fills `out[..=n]`, panicking if `out` holds fewer than `n + 1` values.
//!
//! Error bounds (derived in `docs/float.md`, "The row set-up") are in
//! [`crate::tolerance::rows`]; tests against the exact run: `tests/fast.rs`.

/// An affine normal field over a polygon, `U(x, y) = n1·x + n2·y + n3` (Phong's
/// interpolated normal before normalization), and the light `L`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Field<F> {
    /// `∂U/∂x`.
    pub n1: [F; 3],
    /// `∂U/∂y`.
    pub n2: [F; 3],
    /// `U(0, 0)`.
    pub n3: [F; 3],
    /// The unit light `L`.
    pub l: [F; 3],
    /// `n1·L`.
    pub n1l: F,
    /// `n2·L`.
    pub n2l: F,
    /// `n1·n1`.
    pub n11: F,
    /// `n1·n2`.
    pub n12: F,
    /// `n2·n2`.
    pub n22: F,
}

/// A row's left end in the field: `s = U_a·L`, `g = U_a·n1`, `q = U_a·U_a`, with
/// `U_a` the (not normalized) normal at the row's first pixel.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct RowStart<F> {
    /// `U_a·L`.
    pub s: F,
    /// `U_a·n1`.
    pub g: F,
    /// `U_a·U_a`.
    pub q: F,
}

/// What every span method needs of a row with unit edge normals
/// (`fast_rows_phong_from_span_invariants`).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct RowSpan<F> {
    /// `p_a = N_a·L`.
    pub p_a: F,
    /// `p_b = N_b·L`.
    pub p_b: F,
    /// `1 − c`, `c = N_a·N_b`.
    pub omc: F,
    /// `1/n` (1 for a one-pixel row, whose only value is `p_a`).
    pub inv_n: F,
    /// The Gouraud slope `a1 = (p_b − p_a)/n`, as `(p_b − p_a)·(1/n)`.
    pub a1: F,
    /// Corrected Euler's parabola `a2 = (1 − c)(p_a + p_b)/(2n²)`
    /// (`fast_rows_ce_from_span_invariants`), as `((0.5·(1 − c))·(p_a + p_b))·(1/n)·(1/n)`.
    pub a2: F,
    /// Steps `n` (pixels `0..=n`).
    pub n: u32,
}

/// Rows of fewer pixels than this run [`RowSpan::corrected_euler`] as the paper's
/// serial recurrence; longer rows in closed form, eight pixels a vector pass.
pub const SHORT: usize = 8;

/// How many rows [`Batch`] sets up at once: two SSE vectors (one AVX vector) of
/// `f32`.
pub const BATCH: usize = 8;

/// The [`RowSpan`]s of up to [`BATCH`] rows, as arrays (one lane per row), computed
/// in one pass that LLVM vectorizes across the rows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Batch<F> {
    /// `p_a` per row.
    pub p_a: [F; BATCH],
    /// `p_b` per row.
    pub p_b: [F; BATCH],
    /// `1 − c` per row.
    pub omc: [F; BATCH],
    /// `1/n` per row.
    pub inv_n: [F; BATCH],
    /// `a1` per row.
    pub a1: [F; BATCH],
    /// `a2` per row.
    pub a2: [F; BATCH],
    /// Steps per row.
    pub n: [u32; BATCH],
}

/// Forward differences down a polygon's edge: the [`RowStart`] of each row from the
/// previous row's, plus `h = U_a·n2` (`edge_stepped_setup_exact`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgeStepper<F> {
    /// The current row's start.
    pub start: RowStart<F>,
    /// `U_a·n2`.
    pub h: F,
    /// The current row's first pixel (field coordinates).
    pub x: F,
    /// The current row (field coordinates).
    pub y: F,
    /// Rows stepped since the last evaluation from the field.
    pub since_restart: u32,
}

macro_rules! rows_impl {
    ($f:ident) => {
        #[inline(always)]
        fn dot(u: [$f; 3], v: [$f; 3]) -> $f {
            u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
        }

        impl Field<$f> {
            /// The field `n1·x + n2·y + n3` lit by `L`, with its five constant dot
            /// products.
            pub fn new(n1: [$f; 3], n2: [$f; 3], n3: [$f; 3], l: [$f; 3]) -> Self {
                Field {
                    n1,
                    n2,
                    n3,
                    l,
                    n1l: dot(n1, l),
                    n2l: dot(n2, l),
                    n11: dot(n1, n1),
                    n12: dot(n1, n2),
                    n22: dot(n2, n2),
                }
            }

            /// The field of a triangle's vertex normals, `U(v_i) = N_i`, in
            /// coordinates relative to its first vertex `v_0` (`U(0, 0) = N_0`): one
            /// reciprocal of the doubled area. `None` for a degenerate triangle.
            pub fn from_triangle(
                v: [[$f; 2]; 3],
                normals: [[$f; 3]; 3],
                l: [$f; 3],
            ) -> Option<Self> {
                let (e1, e2) = (
                    [v[1][0] - v[0][0], v[1][1] - v[0][1]],
                    [v[2][0] - v[0][0], v[2][1] - v[0][1]],
                );
                let det = e1[0] * e2[1] - e2[0] * e1[1];
                if det == 0.0 || !det.is_finite() {
                    return None;
                }
                let inv = 1.0 / det;
                let (n0, n1, n2) = (normals[0], normals[1], normals[2]);
                let d1 = [n1[0] - n0[0], n1[1] - n0[1], n1[2] - n0[2]];
                let d2 = [n2[0] - n0[0], n2[1] - n0[1], n2[2] - n0[2]];
                let gx = |j: usize| (d1[j] * e2[1] - d2[j] * e1[1]) * inv;
                let gy = |j: usize| (d2[j] * e1[0] - d1[j] * e2[0]) * inv;
                Some(Self::new(
                    [gx(0), gx(1), gx(2)],
                    [gy(0), gy(1), gy(2)],
                    n0,
                    l,
                ))
            }

            /// `U(x, y)`.
            #[inline(always)]
            pub fn at(&self, x: $f, y: $f) -> [$f; 3] {
                let (a, b, c) = (self.n1, self.n2, self.n3);
                [
                    a[0] * x + b[0] * y + c[0],
                    a[1] * x + b[1] * y + c[1],
                    a[2] * x + b[2] * y + c[2],
                ]
            }

            /// The [`RowStart`] of the row whose first pixel is at `(x, y)`, from the
            /// field.
            #[inline(always)]
            pub fn start(&self, x: $f, y: $f) -> RowStart<$f> {
                let u = self.at(x, y);
                RowStart {
                    s: dot(u, self.l),
                    g: dot(u, self.n1),
                    q: dot(u, u),
                }
            }

            /// The [`RowSpan`] of the row of `n + 1` pixels from `(x, y)`: the same
            /// operations, in the same order, as one lane of [`Batch::set_up`].
            #[inline(always)]
            pub fn row(&self, x: $f, y: $f, n: u32) -> RowSpan<$f> {
                self.start(x, y).span(self, n)
            }
        }

        impl RowStart<$f> {
            /// The row's [`RowSpan`] (`fast_rows_field_span_identities`): `U_b·L`,
            /// `U_a·U_b` and `U_b·U_b` from `s`, `g`, `q`; two square roots and three
            /// divisions.
            #[inline(always)]
            pub fn span(&self, f: &Field<$f>, n: u32) -> RowSpan<$f> {
                // Through `i32` (exact below 2^31; rows are far shorter): SSE2 converts
                // four `i32` at once, but has no unsigned conversion.
                let nf = n as i32 as $f;
                let (ra, rb, s_b, w) = self.roots(f, nf);
                let (p_a, p_b) = (self.s * ra, s_b * rb);
                let omc = 1.0 - w * ra * rb;
                let inv_n = 1.0 / nf.max(1.0);
                RowSpan {
                    p_a,
                    p_b,
                    omc,
                    inv_n,
                    a1: (p_b - p_a) * inv_n,
                    a2: 0.5 * omc * (p_a + p_b) * inv_n * inv_n,
                    n,
                }
            }

            /// `1/|U_a|`, `1/|U_b|`, `U_b·L`, `U_a·U_b`.
            #[inline(always)]
            fn roots(&self, f: &Field<$f>, nf: $f) -> ($f, $f, $f, $f) {
                let s_b = self.s + nf * f.n1l;
                let w = self.q + nf * self.g;
                let q_b = w + nf * (self.g + nf * f.n11);
                (1.0 / self.q.sqrt(), 1.0 / q_b.sqrt(), s_b, w)
            }

            /// Phong of the field along the row, in closed form: pixel `i` has
            /// `U = U_a + i·n1`, so `(s + i·n1·L)/√(q + i(2g + i·n1·n1))` (eqs. 2–3
            /// with the unnormalized edge normals `U_a`, `U_a + n·n1`): the normal
            /// normalized at every pixel, with no per-row square root. Fills
            /// `out[..=n]`.
            #[inline]
            pub fn phong_field(&self, f: &Field<$f>, n: u32, out: &mut [$f]) {
                crate::fast::closed_phong(
                    [f.n1l, self.s, f.n11, 2.0 * self.g, self.q],
                    &mut out[..=n as usize],
                );
            }
        }

        impl RowSpan<$f> {
            /// Corrected Euler as Gouraud plus a parabola
            /// (`fast_rows_ce_from_span_invariants`):
            /// `p_a + i·(a1 + (n − i)·a2)`, `a1 = (p_b − p_a)/n`,
            /// `a2 = (1 − c)(p_a + p_b)/(2n²)`: on rows of [`SHORT`] pixels or more
            /// in closed form, every pixel independent; on shorter rows by the
            /// paper's recurrence. Fills `out[..=n]`.
            #[inline]
            pub fn corrected_euler(&self, out: &mut [$f]) {
                let out = &mut out[..=self.n as usize];
                let (p_a, a1, a2, nf) = (self.p_a, self.a1, self.a2, self.n as $f);
                if out.len() < SHORT {
                    // The paper's recurrence (eqs. 16–17), `p += t; t += ds` with
                    // `t_0 = a1 + (n − 1)·a2`, `ds = −2·a2`: two additions a pixel,
                    // cheaper than a vector pass on a row this short.
                    let (mut p, mut t, ds) = (p_a, a1 + (nf - 1.0) * a2, -2.0 * a2);
                    for o in out.iter_mut() {
                        *o = p;
                        p += t;
                        t += ds;
                    }
                } else {
                    crate::fast::each_index(out, |x| p_a + x * (a1 + (nf - x) * a2));
                }
            }

            /// Gouraud: `p_a + i(p_b − p_a)/n`. Fills `out[..=n]`.
            #[inline]
            pub fn gouraud(&self, out: &mut [$f]) {
                let (p_a, a1) = (self.p_a, self.a1);
                crate::fast::each_index(&mut out[..=self.n as usize], |x| p_a + x * a1);
            }

            /// The coefficients `A`, `B`, `C`, `D`, `E` of eqs. 2–3
            /// (`fast_rows_phong_from_span_invariants`).
            #[inline(always)]
            pub fn abcde(&self) -> [$f; 5] {
                let omc2 = 2.0 * self.omc * self.inv_n;
                [self.a1, self.p_a, omc2 * self.inv_n, -omc2, 1.0]
            }

            /// The paper's Phong with unit edge normals, `(A i + B)/√(C i² + D i + 1)`,
            /// with `sqrt` and a division. Fills `out[..=n]`.
            #[inline]
            pub fn phong(&self, out: &mut [$f]) {
                crate::fast::closed_phong(self.abcde(), &mut out[..=self.n as usize]);
            }
        }

        impl Batch<$f> {
            /// The [`RowSpan`]s of the rows whose first pixels are at `(x[r], y[r])`
            /// with `n[r]` steps: each lane does exactly what [`Field::row`] does, so
            /// the results are the same bits, and the square roots and divisions of
            /// four (SSE), eight (AVX2, AVX-512 for `f64`) rows go in one instruction,
            /// on the vector path chosen at run time ([`crate::simd`]). Lanes a caller does not use may
            /// hold anything (their results are not read).
            #[inline]
            pub fn set_up(
                f: &Field<$f>,
                x: &[$f; BATCH],
                y: &[$f; BATCH],
                n: &[u32; BATCH],
            ) -> Self {
                // The eight rows in one AVX2 `f32` vector, or one AVX-512 `f64` vector.
                crate::simd::dispatch(|_| Self::set_up_lanes(f, x, y, n))
            }

            /// The rows lane by lane, for the vectorizer.
            #[inline(always)]
            fn set_up_lanes(
                f: &Field<$f>,
                x: &[$f; BATCH],
                y: &[$f; BATCH],
                n: &[u32; BATCH],
            ) -> Self {
                let mut b = Batch {
                    p_a: [0.0; BATCH],
                    p_b: [0.0; BATCH],
                    omc: [0.0; BATCH],
                    inv_n: [0.0; BATCH],
                    a1: [0.0; BATCH],
                    a2: [0.0; BATCH],
                    n: *n,
                };
                for r in 0..BATCH {
                    let row = f.row(x[r], y[r], n[r]);
                    b.p_a[r] = row.p_a;
                    b.p_b[r] = row.p_b;
                    b.omc[r] = row.omc;
                    b.inv_n[r] = row.inv_n;
                    b.a1[r] = row.a1;
                    b.a2[r] = row.a2;
                }
                b
            }

            /// Row `r` of the batch.
            #[inline(always)]
            pub fn get(&self, r: usize) -> RowSpan<$f> {
                RowSpan {
                    p_a: self.p_a[r],
                    p_b: self.p_b[r],
                    omc: self.omc[r],
                    inv_n: self.inv_n[r],
                    a1: self.a1[r],
                    a2: self.a2[r],
                    n: self.n[r],
                }
            }
        }

        impl Field<$f> {
            /// Every row of `rows` (first pixel `x`, row `y`, steps `n`), set up
            /// [`BATCH`] at a time by [`Batch::set_up`], then handed to
            /// `each(index, row)` in order: the batched set-up as a renderer uses it,
            /// with no allocation.
            #[inline]
            pub fn for_each_row(
                &self,
                rows: impl IntoIterator<Item = ($f, $f, u32)>,
                mut each: impl FnMut(usize, &RowSpan<$f>),
            ) {
                let (mut x, mut y, mut n) = ([0.0; BATCH], [0.0; BATCH], [0u32; BATCH]);
                let (mut k, mut done) = (0, 0);
                let mut flush =
                    |k: usize, x: &[$f; BATCH], y: &[$f; BATCH], n: &[u32; BATCH], done: usize| {
                        let b = Batch::<$f>::set_up(self, x, y, n);
                        for r in 0..k {
                            each(done + r, &b.get(r));
                        }
                    };
                for (xr, yr, nr) in rows {
                    (x[k], y[k], n[k]) = (xr, yr, nr);
                    k += 1;
                    if k == BATCH {
                        flush(k, &x, &y, &n, done);
                        done += k;
                        k = 0;
                    }
                }
                if k > 0 {
                    flush(k, &x, &y, &n, done);
                }
            }
        }

        impl EdgeStepper<$f> {
            /// Rows stepped before the state is evaluated from the field again: the
            /// forward differences' rounding grows with the square of the rows
            /// stepped (`docs/float.md`), so it is cut off here.
            pub const RESTART: u32 = 8;

            /// The stepper at the row whose first pixel is at `(x, y)`, evaluated from
            /// the field.
            #[inline]
            pub fn new(f: &Field<$f>, x: $f, y: $f) -> Self {
                let u = f.at(x, y);
                EdgeStepper {
                    start: f.start(x, y),
                    h: dot(u, f.n2),
                    x,
                    y,
                    since_restart: 0,
                }
            }

            /// Moves to the next row, whose first pixel is `dx` pixels right of this
            /// one's (`dx` a whole number, often 0 or ±1):
            /// `s += dx·n1·L + n2·L`, `g += dx·n1·n1 + n1·n2`,
            /// `h += dx·n1·n2 + n2·n2`,
            /// `q += 2(dx·g + h) + dx²·n1·n1 + 2dx·n1·n2 + n2·n2`
            /// (`edge_stepped_setup_exact`); every [`Self::RESTART`] rows the state
            /// is evaluated from the field instead.
            #[inline]
            pub fn step(&mut self, f: &Field<$f>, dx: $f) {
                let (x, y) = (self.x + dx, self.y + 1.0);
                if self.since_restart + 1 >= Self::RESTART {
                    *self = Self::new(f, x, y);
                    return;
                }
                let RowStart { s, g, q } = self.start;
                let h = self.h;
                self.start = RowStart {
                    s: s + (dx * f.n1l + f.n2l),
                    g: g + (dx * f.n11 + f.n12),
                    q: q + (2.0 * (dx * g + h) + (dx * (dx * f.n11 + 2.0 * f.n12) + f.n22)),
                };
                self.h = h + (dx * f.n12 + f.n22);
                (self.x, self.y) = (x, y);
                self.since_restart += 1;
            }
        }
    };
}

mod f32_impl {
    use super::*;
    rows_impl!(f32);
}

mod f64_impl {
    use super::*;
    rows_impl!(f64);
}

/// [`RowSpan::phong`] with `rsqrtps` and one Newton step
/// ([`crate::fast::phong_rsqrt_f32`]; `rsqrt_newton_step_error`).
pub fn phong_rsqrt(r: &RowSpan<f32>, out: &mut [f32]) {
    crate::fast::phong_rsqrt_coefficients(r.abcde(), &mut out[..=r.n as usize]);
}

/// [`RowStart::phong_field`] with `rsqrtps` and one Newton step.
pub fn phong_field_rsqrt(start: &RowStart<f32>, f: &Field<f32>, n: u32, out: &mut [f32]) {
    crate::fast::phong_rsqrt_coefficients(
        [f.n1l, start.s, f.n11, 2.0 * start.g, start.q],
        &mut out[..=n as usize],
    );
}

impl RowSpan<f32> {
    /// [`phong_rsqrt`] as a method.
    #[inline]
    pub fn phong_rsqrt(&self, out: &mut [f32]) {
        phong_rsqrt(self, out)
    }
}

#[cfg(test)]
mod tests;
