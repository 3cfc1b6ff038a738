//! Phong in `f32` with an approximate reciprocal square root: [`phong_rsqrt_f32`] and
//! [`phong_rsqrt_coefficients`], SSE `rsqrtps` and one Newton step (re-exported by
//! [`crate::fast`]).

#[cfg(not(target_arch = "x86_64"))]
use super::closed_phong;
#[cfg(target_arch = "x86_64")]
use super::copy_short;
use super::FastSpan;

/// Phong in `f32` with an approximate reciprocal square root (`rsqrtps`, 12 bits)
/// refined by one Newton step (about 22 bits), four pixels at a time with SSE on
/// x86-64; elsewhere it falls back to [`FastSpan::phong`].
///
/// Error: within 4 `f32` ulps of `p/√q` computed exactly from the same set-up, the
/// ulp taken at `(|A|i + |B|)/√q · κ`, where `κ = (|C|i² + |D|i + E)/q` is the
/// cancellation in `q` (1 for the close normals of a mesh; about 260 for normals 170°
/// apart, where no evaluation of `q` from `C`, `D`, `E` can do better); tested in
/// `tests/fast.rs`, as is [`FastSpan::phong`] under the same claim.
pub fn phong_rsqrt_f32(s: &FastSpan<f32>, out: &mut [f32]) {
    #[cfg(target_arch = "x86_64")]
    {
        // SSE is part of the x86-64 baseline: no runtime detection is needed.
        // SAFETY: the intrinsics only read and write the local vectors and `out`
        // through bounds-checked slices of exactly four elements.
        unsafe { phong_rsqrt_sse([s.a, s.b, s.c, s.d, s.e], &mut out[..=s.n as usize]) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    s.phong(out)
}

/// [`phong_rsqrt_f32`] for the coefficients `[A, B, C, D, E]` of eqs. 2–3, filling
/// all of `out`.
pub fn phong_rsqrt_coefficients(c: [f32; 5], out: &mut [f32]) {
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: as in `phong_rsqrt_f32`.
        unsafe { phong_rsqrt_sse(c, out) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    closed_phong(c, out)
}

#[cfg(target_arch = "x86_64")]
#[inline]
unsafe fn phong_rsqrt_sse(coef: [f32; 5], out: &mut [f32]) {
    use std::arch::x86_64::*;
    let [sa, sb, sc, sd, se] = coef;
    let (a, b, c, d, e) = (
        _mm_set1_ps(sa),
        _mm_set1_ps(sb),
        _mm_set1_ps(sc),
        _mm_set1_ps(sd),
        _mm_set1_ps(se),
    );
    let half = _mm_set1_ps(0.5);
    let three = _mm_set1_ps(3.0);
    let step = _mm_set1_ps(4.0);
    // Four pixels from the index vector `x`: p·r with r ≈ 1/√q from `rsqrtps`, then
    // one Newton step, r·(3 − q·r²)/2.
    let four = |x: __m128| {
        let p = _mm_add_ps(_mm_mul_ps(a, x), b);
        let q = _mm_add_ps(_mm_mul_ps(_mm_add_ps(_mm_mul_ps(c, x), d), x), e);
        let r = _mm_rsqrt_ps(q);
        let r = _mm_mul_ps(
            _mm_mul_ps(half, r),
            _mm_sub_ps(three, _mm_mul_ps(q, _mm_mul_ps(r, r))),
        );
        let mut tmp = [0f32; 4];
        _mm_storeu_ps(tmp.as_mut_ptr(), _mm_mul_ps(p, r));
        tmp
    };
    let mut x = _mm_setr_ps(0.0, 1.0, 2.0, 3.0);
    let mut chunks = out.chunks_exact_mut(4);
    for chunk in &mut chunks {
        chunk.copy_from_slice(&four(x));
        x = _mm_add_ps(x, step);
    }
    // The partial chunk as a whole one (the lanes past the row are dropped), so the
    // last pixels take the same operations as the others.
    let rem = chunks.into_remainder();
    if !rem.is_empty() {
        copy_short(rem, &four(x)[..rem.len()]);
    }
}
