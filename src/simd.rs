//! The vector path of the fast kernels ([`crate::fast`], [`crate::fast_rows`]), chosen
//! once at run time: the x86-64 baseline (SSE2: four `f32` lanes), AVX2 with FMA
//! (eight), or AVX-512 (sixteen); elsewhere the portable path.
//!
//! The kernels are written once, as loops over fixed-size chunks that LLVM
//! vectorizes; each path compiles the same loop under its own `#[target_feature]`
//! (`std::arch` and `is_x86_feature_detected!`, as `memchr` and `simd-adler32` do — a
//! crate such as `multiversion` would generate the same three clones and a dispatch
//! table, for one `match` here). Every path evaluates every pixel with the same
//! operations in the same order: no path contracts a product and a sum into a fused
//! multiply-add (Rust never does so unasked), so their values are the same bits, and
//! each path is judged under the `ieee` profile by `tests/profiles.rs` all the same.
//!
//! The choice: the best path the CPU has, or the one the environment variable
//! `PHONG_APPROX_SIMD` names (`baseline`, `avx2`, `avx512`; [`from_env`]: the command
//! line refuses an unknown name or a path the CPU lacks, the library then takes the
//! best path), or the one [`force`] sets (tests and benchmarks run every path so).

use std::fmt;
use std::str::FromStr;
use std::sync::atomic::{AtomicU8, Ordering};

/// A vector path of the fast kernels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Path {
    /// The x86-64 baseline (SSE2), or the portable path on other architectures.
    Baseline,
    /// AVX2 and FMA: eight `f32` (four `f64`) lanes.
    Avx2,
    /// AVX-512 (F, VL): sixteen `f32` (eight `f64`) lanes.
    Avx512,
}

impl Path {
    /// Every path, narrowest first.
    pub const ALL: [Path; 3] = [Path::Baseline, Path::Avx2, Path::Avx512];

    /// `baseline`, `avx2` or `avx512`.
    pub fn name(self) -> &'static str {
        match self {
            Path::Baseline => "baseline",
            Path::Avx2 => "avx2",
            Path::Avx512 => "avx512",
        }
    }

    /// Whether this CPU can take the path.
    pub fn supported(self) -> bool {
        match self {
            Path::Baseline => true,
            #[cfg(target_arch = "x86_64")]
            Path::Avx2 => {
                std::arch::is_x86_feature_detected!("avx2")
                    && std::arch::is_x86_feature_detected!("fma")
            }
            #[cfg(target_arch = "x86_64")]
            Path::Avx512 => {
                Path::Avx2.supported()
                    && std::arch::is_x86_feature_detected!("avx512f")
                    && std::arch::is_x86_feature_detected!("avx512vl")
            }
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// The paths this CPU can take, narrowest first.
    pub fn supported_paths() -> Vec<Path> {
        Path::ALL.into_iter().filter(|p| p.supported()).collect()
    }

    /// The widest path this CPU can take.
    pub fn best() -> Path {
        Path::supported_paths().pop().unwrap_or(Path::Baseline)
    }
}

impl fmt::Display for Path {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Path {
    type Err = String;
    fn from_str(s: &str) -> Result<Path, String> {
        Path::ALL
            .into_iter()
            .find(|p| p.name() == s.trim())
            .ok_or_else(|| {
                format!(
                    "unknown vector path '{}' (expected baseline, avx2 or avx512)",
                    crate::error::shown(s)
                )
            })
    }
}

/// The chosen path, `1 + ` its index in [`Path::ALL`]; 0 until chosen.
static CHOSEN: AtomicU8 = AtomicU8::new(0);

/// The path the kernels take (see the module's documentation).
#[inline]
pub fn path() -> Path {
    match CHOSEN.load(Ordering::Relaxed) {
        1 => Path::Baseline,
        2 => Path::Avx2,
        3 => Path::Avx512,
        _ => choose(),
    }
}

#[cold]
fn choose() -> Path {
    let p = from_env().ok().flatten().unwrap_or_else(Path::best);
    store(p);
    p
}

/// The path `PHONG_APPROX_SIMD` names: `None` when it is unset or empty. The kernels
/// ignore a value this returns an error for (they take [`Path::best`]); the command
/// line refuses it with this one-line message and exit 2, so that a run never takes
/// another path than the one asked for without a word.
///
/// # Errors
/// An unknown name, or a path this CPU cannot take (naming the ones it can).
pub fn from_env() -> Result<Option<Path>, String> {
    let Some(v) = std::env::var_os("PHONG_APPROX_SIMD") else {
        return Ok(None);
    };
    let v = v.to_string_lossy();
    if v.trim().is_empty() {
        return Ok(None);
    }
    let p = v
        .parse::<Path>()
        .map_err(|e| format!("PHONG_APPROX_SIMD: {e}"))?;
    if !p.supported() {
        let has: Vec<&str> = Path::supported_paths().iter().map(|p| p.name()).collect();
        return Err(format!(
            "PHONG_APPROX_SIMD={p}: this CPU cannot take the {p} path (it has {})",
            has.join(", ")
        ));
    }
    Ok(Some(p))
}

fn store(p: Path) {
    let k = Path::ALL.iter().position(|q| *q == p).unwrap_or(0);
    CHOSEN.store(k as u8 + 1, Ordering::Relaxed);
}

/// Makes every kernel, in every thread, take `p` from now on, and returns the path
/// taken before: for tests and benchmarks that run each path in turn. Every path
/// gives the same values, so a kernel running meanwhile in another thread stays
/// right.
///
/// # Errors
/// The path's name when this CPU cannot take it (nothing changes).
pub fn force(p: Path) -> Result<Path, String> {
    if !p.supported() {
        return Err(format!("this CPU cannot take the {p} path"));
    }
    let before = path();
    store(p);
    Ok(before)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_the_baseline_is_always_there() {
        for p in Path::ALL {
            assert_eq!(p.name().parse::<Path>(), Ok(p));
        }
        assert!("sse9".parse::<Path>().is_err());
        assert!(Path::supported_paths().contains(&Path::Baseline));
        assert!(Path::best().supported());
    }
}
