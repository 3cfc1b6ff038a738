//! Error bounds of the float runs against the exact run, in one place.
//!
//! A method run in a float type `T` (unit roundoff `u`: 2^-24 for `f32`, 2^-53 for
//! `f64`) on inputs rounded to `T` differs from the same method run exactly on the
//! exact inputs by at most [`bound`] at every pixel, for exact-unit inputs and
//! `1 ≤ n ≤ 4096`. Tested: `tests/float_bounds.rs`.
//!
//! Where the form comes from:
//! - the additive recurrences (Gouraud, Euler, corrected Euler) do one rounded
//!   addition into `p` per pixel and one into the slope; the slope's error is carried
//!   into `p` at every later step, and their set-up (`t_0`, `ds`) is accurate to a few
//!   `u` on the scale of the span, so the error grows linearly in `n`;
//! - Duff's `q` accumulates the same way, and the value `p/√q` turns an error `Δq`
//!   into at most `Δq/(2 q)` (because `|p| ≤ √q`), so Duff and symmetric Phong carry a
//!   factor `1/q_min`, where `q_min = min_i q_i = 1 − n²C/4` near the middle of the
//!   span (small only when the edge normals are far apart: 0.0076 at 170°);
//! - direct Phong normalizes at every pixel and its error does not grow with `n`;
//! - angular interpolation accumulates the angle by additions (linear in `n`); the
//!   tabled variant can land on the neighbouring table entry when the angle is within
//!   rounding of a half-step, so it may be off by one table step, `π/2/(size − 1)`.
//!
//! The constants are the measured worst case over the edge cases and hundreds of
//! random spans for `n` from 1 to 4096, times about two (measured: Phong ≤ 3u/q_min,
//! Duff ≤ 0.5·n·u/q_min, corrected Euler ≤ 0.5·n·u, angular ≤ 1.6·n·u).

use crate::method::Method;

/// The bound, in units of `u`, for `method` on a span of `n` steps whose smallest
/// `q_i` is `q_min` (1 when the edge normals are equal).
pub fn bound_in_u(method: Method, n: u32, q_min: f64) -> f64 {
    let n = f64::from(n);
    match method {
        Method::Phong => 8.0 / q_min,
        Method::Duff | Method::SymmetricPhong => (8.0 + n) / q_min,
        Method::Gouraud | Method::Euler | Method::CorrectedEuler | Method::Adaptive => 8.0 + n,
        Method::Angular | Method::AngularTable(_) => 16.0 + 2.0 * n,
    }
}

/// The absolute bound at unit roundoff `u` (see [`bound_in_u`]), plus one table step
/// for [`Method::AngularTable`].
pub fn bound(method: Method, n: u32, q_min: f64, u: f64) -> f64 {
    let table_step = match method {
        Method::AngularTable(size) => std::f64::consts::FRAC_PI_2 / f64::from(size.max(2) - 1),
        _ => 0.0,
    };
    bound_in_u(method, n, q_min) * u + table_step
}
