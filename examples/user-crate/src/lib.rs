//! Scan-line shading written from the paper, as a renderer would have it: Phong per
//! pixel with glam, and corrected Euler (eqs. 15–17) in `f32`. Its conformance tests
//! (`tests/conformance/`) use phong-approx's test kit.

use glam::Vec3;

/// Phong per pixel: the normal interpolated linearly, normalized, dotted with `l`;
/// `n + 1` values from `na` to `nb`.
pub fn phong(na: Vec3, nb: Vec3, l: Vec3, n: u32) -> Vec<f32> {
    (0..=n)
        .map(|i| na.lerp(nb, i as f32 / n as f32).normalize().dot(l))
        .collect()
}

/// Corrected Euler along the span (the paper's eqs. 2–3, 10–11, 14–17): two
/// additions per pixel, exact at both ends in exact arithmetic.
pub fn corrected_euler(na: Vec3, nb: Vec3, l: Vec3, n: u32) -> Vec<f32> {
    let nf = n as f32;
    let k = (nb - na) / nf;
    let (a, pa, pb) = (k.dot(l), na.dot(l), nb.dot(l));
    let (c, d) = (k.dot(k), 2.0 * k.dot(na));
    let di_a = a - pa / 2.0 * d;
    let di_b = a - pb / 2.0 * (2.0 * nf * c + d);
    let ds = (di_b - di_a) / nf;
    let eps = pa + nf * di_a + nf * (nf - 1.0) / 2.0 * ds - pb;
    let (mut p, mut t) = (pa, di_a - eps / nf);
    let mut out = Vec::with_capacity(n as usize + 1);
    out.push(p);
    for _ in 0..n {
        p += t;
        t += ds;
        out.push(p);
    }
    out
}
