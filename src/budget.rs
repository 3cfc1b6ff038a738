//! The budgets of exact work: what an exact run costs, estimated before any of it is
//! done, so that `check`'s recomputation of a modified vector file and `span --scalar
//! exact` refuse what would take minutes instead of starting it.

use crate::vector::Vec3;
use crate::BigRational;

/// The most exact work `check` does to recompute a modified file's expectations,
/// and `span --scalar exact` does without `--yes` ([`exact_work`] units of about 8 µs
/// on one core of the reference machine): about half a minute.
pub const MAX_RECOMPUTED_WORK: u64 = 1 << 22;

/// The size of exact inputs: the most bits of a numerator plus its denominator among
/// the components.
pub fn input_bits(vectors: &[&Vec3<BigRational>]) -> u64 {
    vectors
        .iter()
        .flat_map(|v| v.components())
        .map(|c| c.numer().bits() + c.denom().bits())
        .max()
        .unwrap_or(0)
}

/// The exact work of running `method` on a span of `n` steps whose inputs have
/// `input_bits` ([`input_bits`]) with values to `digits` significant digits, in units
/// of about 8 µs (corrected Euler's cost per pixel in exact arithmetic). Measured in
/// release on 2 cores at `n = 4096` (`docs/performance.md`, "Exact runs"): per pixel,
/// the rational methods cost one unit, Phong, Duff, symmetric Phong and angular about
/// 15, spherical and Bishop–Weimer about 19, binary about 270 (a square root per
/// segment point); the cost grows with the size of the inputs `z = 1 + input_bits/64`
/// as `z^1.6` (the reductions of ever larger fractions: about ×14 for 80-digit and ×45
/// for 190-digit fractions; measured 22 s for corrected Euler at `n = 65536` with
/// 188-digit fractions, estimated 24 s) and, for the methods with square roots, `acos`
/// or `cos`, with the square of the bits the digits need beyond 2^-256.
pub fn exact_work(method: crate::Method, n: u32, input_bits: u64, digits: usize) -> u64 {
    let per_pixel = method.info().exact_cost;
    let precision = if method.is_rational() {
        1
    } else {
        let b = (digits as f64 / std::f64::consts::LOG10_2) as u64 + 64;
        let r = b.max(256).div_ceil(256);
        r * r
    };
    // A tabled cosine builds its table of `size` exact cosines first (per case).
    let table = match method {
        crate::Method::AngularTable(size) => u64::from(size).saturating_mul(TABLE_ENTRY_WORK),
        _ => 0,
    };
    (u64::from(n) + 1)
        .saturating_mul(per_pixel)
        .saturating_mul(size_factor(input_bits))
        .saturating_add(table)
        .saturating_mul(precision)
}

/// One exact cosine of a table ([`crate::angular::CosTable`]), as angular's per-pixel
/// cosine: 15 units.
pub const TABLE_ENTRY_WORK: u64 = 15;

/// `⌈z^1.6⌉` for inputs of `input_bits`, `z = 1 + input_bits/64` (see [`exact_work`]).
fn size_factor(input_bits: u64) -> u64 {
    let z = 1.0 + input_bits as f64 / 64.0;
    z.powf(1.6).ceil().min(1e15) as u64
}

/// What `check` spends on each case of a modified file besides its exact run: reading
/// and checking its inputs, the span, `q_min`, the adaptive test, the expectations'
/// decimals and levels, the comparison (measured: 20,000 cases of `n = 1` take 12.5 s
/// for corrected Euler and 18.4 s for Phong, 78 and 115 units a case; their runs are 2
/// and 30 of that).
pub const CASE_WORK: u64 = 85;

/// The extra exact work of a case's specular expectations `max(0, v)^s` on a span of `n`
/// steps: per pixel the exact power, its decimals and its level, which grow as `s^1.85`
/// (the fractions' size times the multiplications' cost): `⌈s^1.85/15⌉` units per
/// pixel, times the inputs' size factor. Measured for corrected Euler on the typical
/// set's inputs (size factor 3): 25.6 s a pixel at `s = 10000` (estimated 40 s),
/// 0.36 s at `s = 1000` (0.57 s), 19.5 ms at `s = 200` (29 ms).
pub fn specular_work(n: u32, s: u32, input_bits: u64) -> u64 {
    let per_pixel = (f64::from(s).powf(1.85) / 15.0).ceil() as u64;
    (u64::from(n) + 1)
        .saturating_mul(per_pixel.max(1))
        .saturating_mul(size_factor(input_bits))
}
