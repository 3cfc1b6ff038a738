//! The derived bound that remains: plain Euler's written derivation on the standard
//! model of a profile (`docs/float.md` §18.5), which the theorems replace under
//! `ieee` and `shader` and `docs/float.md` compares with.

use super::model::Arith;

/// The largest `n` of the derived bounds: `i` and `(i − 1)/2` are exact, and the
/// first-order derivations' second-order terms fit in their last factor `1.01`
/// (`n·κ·u ≤ 2^-8`).
fn derived_n(a: &Arith, n: u32) -> Option<f64> {
    let nf = f64::from(n);
    ((1..=1 << 24).contains(&n)
        && nf * a.setup() * a.u <= 2f64.powi(-8)
        && nf * a.u <= crate::tolerance::MAX_NU)
        .then_some(nf)
}

/// What flushed or subnormal results add to a span's value: at most `η` per
/// operation, carried by at most `n²` (the quadratic term's `i(i−1)/2`), for the at
/// most `64` operations of the set-up and a pixel.
fn eta_total(a: &Arith, nf: f64) -> f64 {
    64.0 * (nf * nf + nf + 1.0) * a.eta
}

/// Plain Euler (eqs. 12–14) under a profile, derived (`docs/float.md` §18.5): the
/// recurrence `E += s; s += ds` from `s_0 = di_a`, or the closed form
/// `p_a + i·(di_a + (i−1)/2·ds)`, on the paper's set-up (§4) in any order of each dot
/// product, fused or not, `/n` as a division or `·(1/n)`.
///
/// Not applied by `check` under any profile: under `ieee` and `shader` the theorems
/// of [`proved`](super::proved) cover the same forms (under `shader` with every division, the
/// halvings included, one 2.5-ulp division or a 2.5-ulp reciprocal and a product) and
/// are smaller at every `n` (`ieee`: `131.41·u` against about `244·u` at `n = 1`;
/// `shader`: `313.36·u` against about `899·u` at `n = 1`, `45,754·u` against
/// `47,176·u` at `n = 4096`). Kept as the derivation `docs/float.md` §18.5 compares
/// with.
///
/// §7's count, each rounding with the largest `κ` of the set-up: `113·κ_s` for the
/// set-up, `6·κ_half` for the two `p/2` (exact under `ieee`), then the larger of the
/// recurrence's `5.6·n·κ_add` and the closed form's `3.8·(2κ_mul + 2κ_add + κ_half)`.
pub fn euler_derived(a: &Arith, n: u32) -> Option<f64> {
    let nf = derived_n(a, n)?;
    let setup = 113.0 * a.setup() + 6.0 * a.half;
    let recurrence = 5.6 * nf * a.add;
    let closed = 3.8 * (2.0 * a.mul + 2.0 * a.add + a.half);
    Some((setup + recurrence.max(closed)) * 1.01 * a.u + eta_total(a, nf))
}
