//! Phong's bound under `ieee` and `shader`, composed from Coq theorems
//! (`docs/float.md` §18.4): the counts of the computed `p` and `q` of each form
//! (`proofs/PhongCount.v` for any unit normals, `proofs/PhongCountD.v` read with the
//! span's `|N_b − N_a|`), the value step `p/√q` (`proofs/PhongValue.v`:
//! `phong_value_real` for real arithmetic, `phong_value_div` and `phong_value_recip`
//! for the two ways of the last operations, `phong_value_either` for both) and
//! normalize-then-dot (`proofs/PhongNormalize.v`), with the theorems' own constants
//! ([`PHONG_COUNTS`]; `tests/claims_index.rs` reads the statements and fails when one
//! differs).

use super::counts::setup_model;
use super::model::{value_step, Arith};

/// One form's count theorems: `|p̂ − p_i| ≤ (p.0·K1 + p.1·kd)·u`,
/// `|q̂ − q_i| ≤ (q.0·K1 + q.1·kd)·u` for any unit normals (`proofs/PhongCount.v`),
/// and, with `d ≥ |N_b − N_a|` (`0 ≤ d ≤ 2`, `proofs/PhongCountD.v`),
/// `|p̂ − p_i| ≤ ((pd.0 + pd.1·d)·K1 + (pd.2 + pd.3·d)·kd)·u`,
/// `|q̂ − q_i| ≤ ((qd.0 + qd.1·d + qd.2·d²)·K1 + (qd.3 + qd.4·d + qd.5·d²)·kd)·u`;
/// `K1 ≥ κ_in, κ_add, κ_mul, 1`, `kd` the division's `κ` (or, through `1/n`,
/// `(1 + 2^-20)·κ_mul + κ_div + 2^-36`). The same constants hold for `/n` either way.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhongCounts {
    /// The form, as the theorems name it (`horner`, `pixel`, `lerp`).
    pub form: &'static str,
    /// `p`'s `(α_K1, α_kd)` at any unit normals.
    pub p: (f64, f64),
    /// `q`'s `(β_K1, β_kd)` at any unit normals.
    pub q: (f64, f64),
    /// `p`'s constants with `d`: `(a0, a1, b0, b1)`.
    pub pd: (f64, f64, f64, f64),
    /// `q`'s constants with `d`: `(c0, c1, c2, e0, e1, e2)`.
    pub qd: (f64, f64, f64, f64, f64, f64),
}

/// The constants of `proofs/PhongCount.v` (`phong_horner_div_generic`,
/// `phong_horner_recip_generic`, `phong_pixel_div_generic`, `phong_pixel_recip_generic`,
/// `phong_lerp_div_generic`, `phong_lerp_recip_generic`) and `proofs/PhongCountD.v`
/// (`phong_horner_div_dist`, `phong_horner_recip_dist`, `phong_pixel_div_dist`,
/// `phong_pixel_recip_dist`, `phong_lerp_div_dist`, `phong_lerp_recip_dist`).
pub const PHONG_COUNTS: [PhongCounts; 3] = [
    PhongCounts {
        form: "horner",
        p: (20.03, 2.02),
        q: (78.11, 12.04),
        pd: (8.04, 6.01, 0.03, 1.01),
        qd: (10.13, 18.03, 8.01, 0.07, 2.02, 2.01),
    },
    PhongCounts {
        form: "pixel",
        p: (14.04, 2.04),
        q: (23.06, 4.06),
        pd: (6.02, 2.01, 0.02, 1.01),
        qd: (7.02, 4.01, 0.0, 0.02, 2.01, 0.0),
    },
    PhongCounts {
        form: "lerp",
        p: (14.04, 2.04),
        q: (23.06, 4.06),
        pd: (8.02, 0.0, 0.02, 1.01),
        qd: (11.02, 0.0, 0.0, 0.02, 2.01, 0.0),
    },
];

impl PhongCounts {
    /// `(e_p, e_q)` in units of `u`: the smaller of the two theorems for each, with
    /// `(k1, kd)` and `d ≥ |N_b − N_a|` (taken at most 2, which any unit normals
    /// satisfy).
    pub fn errors(&self, (k1, kd): (f64, f64), d: f64) -> (f64, f64) {
        let d = d.clamp(0.0, 2.0);
        let free_p = self.p.0 * k1 + self.p.1 * kd;
        let free_q = self.q.0 * k1 + self.q.1 * kd;
        let (a0, a1, b0, b1) = self.pd;
        let (c0, c1, c2, e0, e1, e2) = self.qd;
        let dist_p = (a0 + a1 * d) * k1 + (b0 + b1 * d) * kd;
        let dist_q = (c0 + c1 * d + c2 * d * d) * k1 + (e0 + e1 * d + e2 * d * d) * kd;
        (free_p.min(dist_p), free_q.min(dist_q))
    }
}

/// Phong under a profile: every implementation that computes `p_i = N_i·L` and
/// `q_i = N_i·N_i` from the unit inputs read into the format by Horner's closed form
/// (`(A·i + B)`, `(C·i + D)·i + E`), the per-pixel normal `N_a + i·k` or the lerp
/// `(1 − t)·N_a + t·N_b` (`t = i/n`), with `k = (N_b − N_a)/n` (or `·(1/n)`), every
/// dot product in any order, every product rounded or fused, then `p/√q`,
/// `p·(1/√q)`, or — the per-pixel normal or the lerp — normalize-then-dot
/// `(N·(1/√q))·L`. Each form's counts — the smaller of `PhongCount.v`'s and
/// `PhongCountD.v`'s with `dn ≥ |N_b − N_a|` ([`crate::tolerance::Shape::dn`]; 2 for
/// any unit normals), the larger `kd` of the two ways of `/n` — and the largest over
/// the forms, then `phong_value_either`, plus [`normalize_then_dot`]'s term
/// (`phong_normalize_dot_unit`: the value step's bound with the same `e_p`, `e_q` and
/// that term; `pixel_ok_exact_dot`, `lerp_ok_exact_dot` give its `e_p`). `None`
/// outside the theorems' conditions (`model_ok`, `n ≤ 2^24`; `2e_q ≤ q_min`: normals
/// that nearly cancel; `1024·η ≤ q_min − e_q`). The composition is itself a theorem:
/// `phong_composed` and `phong_composed_normalize` (`proofs/Composed.v`).
pub fn phong_bound(a: &Arith, n: u32, q_min: f64, dn: f64) -> Option<f64> {
    if dn.is_nan() {
        return None;
    }
    let m = setup_model(a, n)?;
    let (e_p, e_q) = PHONG_COUNTS.iter().fold((0f64, 0f64), |(p, q), c| {
        let (ep, eq) = c.errors(m, dn);
        (p.max(ep * a.u), q.max(eq * a.u))
    });
    let value = value_step(a, e_p, e_q, q_min, a.eta)?;
    // Normalize-then-dot is within the value step's bound plus its own term
    // (`phong_normalize_dot_unit`), under its size condition.
    (1024.0 * a.eta <= q_min - e_q).then(|| value + normalize_then_dot(a))
}

/// What normalize-then-dot adds to the value step (`phong_normalize_dot_unit`, the
/// instance of `phong_normalize_dot` with `L` a unit vector read into the format,
/// `proofs/PhongNormalize.v`): the products `N_j·(1/√q̂)` and the dot product with
/// `L` after them, `1.03·λ·(κ_mul·u + κ_mul·u + 2κ_add·u) + 2λη + 8η`,
/// `λ = 1 + κ_in·u + 2η` (`|L|` read into the format), rounded up.
pub fn normalize_then_dot(a: &Arith) -> f64 {
    let u = a.u;
    let lam = 1.0 + a.input * u + 2.0 * a.eta;
    let extra = NORMALIZE_EXTRA * lam * (2.0 * a.mul * u + 2.0 * a.add * u)
        + 2.0 * lam * a.eta
        + 8.0 * a.eta;
    extra * (1.0 + 2f64.powi(-40))
}

/// `phong_normalize_dot_unit`'s factor `103/100` on the last products' roundings.
pub const NORMALIZE_EXTRA: f64 = 1.03;

/// [`phong_bound`] under `ieee` in `format` (`dn ≥ |N_b − N_a|`, 2 for any unit
/// normals).
pub fn phong_ieee(n: u32, q_min: f64, dn: f64, format: crate::Format) -> Option<f64> {
    phong_bound(&super::arith(super::Profile::Ieee, format)?, n, q_min, dn)
}
