//! Duff's and symmetric Phong's bounds under `ieee` and `shader`, composed from Coq
//! theorems (`docs/float.md` §18.5): the counts of the computed `p` and `q`
//! (`proofs/DuffCount.v`) and the value step `p/√q` (`proofs/PhongValue.v`,
//! `phong_value_either`), with the theorems' own constants ([`DUFF_COUNTS`];
//! `tests/claims_index.rs` reads the statements and fails when one differs).

use super::model::{value_step, Arith};

/// The constants of `duff_div_generic` and `duff_recip_generic` (`proofs/DuffCount.v`):
/// after `i` steps of Duff's walk (eqs. 5–7) from the paper's set-up (§4, every dot
/// product in any order, products rounded or fused, `/n` as one division or `·(1/n)`),
/// `|p̂_i − p_i| ≤ (p.0·K1 + p.1·kd + p.2·i·κ_add)·u` and
/// `|q̂_i − q_i| ≤ (q.0·K1 + q.1·kd + q.2·i·κ_add)·u`, with `K1 ≥ κ_in, κ_add, κ_mul, 1`
/// and `kd` the division's `κ` (or, through `1/n`, `(1 + 2^-20)·κ_mul + κ_div + 2^-36`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DuffCounts {
    /// `p`'s `(α_K1, α_kd, α_step)`.
    pub p: (f64, f64, f64),
    /// `q`'s `(β_K1, β_kd, β_step)`.
    pub q: (f64, f64, f64),
}

/// `proofs/DuffCount.v`'s constants: `17.02·K1 + 2.02·kd + 1.001·i·κ_add` for `p`,
/// `65.05·K1 + 12.04·kd + 3.004·i·κ_add` for `q`.
pub const DUFF_COUNTS: DuffCounts = DuffCounts {
    p: (17.02, 2.02, 1.001),
    q: (65.05, 12.04, 3.004),
};

/// The count theorems' `(K1, kd)` for `a` (Phong's set-up, `proofs/PhongCount.v`, and
/// Duff's, `proofs/DuffCount.v`), the larger `kd` of the two ways of `/n`, where their
/// common conditions hold (`model_ok`: `K·u ≤ 2^-21`, `η·2^84 ≤ u`; the reciprocal's
/// `kd·u ≤ 2^-21`; `1 ≤ n ≤ 2^24`).
pub(super) fn setup_model(a: &Arith, n: u32) -> Option<(f64, f64)> {
    let k1 = a.input.max(a.add).max(a.mul).max(1.0);
    let k = k1.max(a.div);
    let kd_recip = (1.0 + 2f64.powi(-20)) * a.mul + a.div + 2f64.powi(-36);
    let ok = (1..=1 << 24).contains(&n)
        && a.div >= 1.0
        && k * a.u <= 2f64.powi(-21)
        && a.eta * 2f64.powi(84) <= a.u
        && kd_recip * a.u <= 2f64.powi(-21);
    ok.then_some((k1, kd_recip.max(a.div)))
}

/// [`setup_model`] with Duff's walk's condition `n·κ_add·u ≤ 2^-11`.
fn model(a: &Arith, n: u32) -> Option<(f64, f64)> {
    (f64::from(n) * a.add * a.u <= 2f64.powi(-11))
        .then(|| setup_model(a, n))
        .flatten()
}

/// `|p̂ − p|` and `|q̂ − q|` after `p_steps` and `q_steps` steps ([`DUFF_COUNTS`]).
fn errors(a: &Arith, (k1, kd): (f64, f64), p_steps: u32, q_steps: u32) -> (f64, f64) {
    let c = DUFF_COUNTS;
    let e = |(x, y, z): (f64, f64, f64), steps: u32| {
        (x * k1 + y * kd + z * f64::from(steps) * a.add) * a.u
    };
    (e(c.p, p_steps), e(c.q, q_steps))
}

/// Duff's forward differences (eqs. 5–7) under a profile: at every pixel `i ≤ n`, the
/// counts after `i` steps (`duff_div_generic`, `duff_recip_generic`, the larger way
/// of `/n`), then `phong_value_either`; the largest is at `i = n`. `None` outside the
/// theorems' conditions — `n·κ_add·u ≤ 2^-11` (binary32: `n ≤ 8192` under `ieee`,
/// `4096` under `shader`), `2e_q ≤ q_min` (normals that nearly cancel) — where no
/// bound is claimed. The composition is `duff_composed` (`proofs/Composed.v`).
pub fn duff_bound(a: &Arith, n: u32, q_min: f64) -> Option<f64> {
    let m = model(a, n)?;
    let (e_p, e_q) = errors(a, m, n, n);
    value_step(a, e_p, e_q, q_min, a.eta)
}

/// Symmetric Phong (§4) under a profile: `p` walks to pixel `i` as Duff's does, and
/// `√q_i` comes from the walk to `j = min(i, n − i)` (`q_j = q_i` for unit normals:
/// `symmetric_phong_div_generic`, `symmetric_phong_recip_generic`), then
/// `phong_value_either`. The bound grows with both walks, so on the pixels
/// `i_{k−1} ≤ i ≤ i_k` of the right half (`i_k = h + ⌈k(n − h)/8⌉`, `h = ⌊n/2⌋`, eight
/// pieces) it is at most the value step's with `p` walked `i_k` steps and `q` walked
/// `min(h, n − i_{k−1})`; the left half is within the first piece. The largest of the
/// eight. `None` as for [`duff_bound`]. The composition is `symmetric_phong_composed`
/// (`proofs/Composed.v`).
pub fn symmetric_phong_bound(a: &Arith, n: u32, q_min: f64) -> Option<f64> {
    let m = model(a, n)?;
    let h = n / 2;
    let at = |k: u32| h + (k * (n - h)).div_ceil(8);
    (1..=8u32)
        .map(|k| {
            let (e_p, e_q) = errors(a, m, at(k), h.min(n - at(k - 1)));
            value_step(a, e_p, e_q, q_min, a.eta)
        })
        .try_fold(0.0f64, |m, b| b.map(|b| m.max(b)))
}
