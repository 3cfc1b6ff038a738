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
//! each path is judged under the `ieee` profile by `tests/profiles/` all the same.
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

/// Why a vector path cannot be taken.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum PathError {
    /// A name that is no path.
    #[error("unknown vector path '{}' (expected baseline, avx2 or avx512)", crate::error::shown(.0))]
    Unknown(String),
    /// A path this CPU lacks, and the paths it has.
    #[error("this CPU cannot take the {path} path (it has {})", .has.join(", "))]
    Unsupported {
        /// The path asked for.
        path: Path,
        /// The names of the paths this CPU has.
        has: Vec<&'static str>,
    },
    /// `PHONG_APPROX_SIMD` names no path this CPU can take.
    #[error("PHONG_APPROX_SIMD: {0}")]
    Env(Box<PathError>),
}

impl PathError {
    fn unsupported(path: Path) -> Self {
        PathError::Unsupported {
            path,
            has: Path::supported_paths().iter().map(|p| p.name()).collect(),
        }
    }
}

impl FromStr for Path {
    type Err = PathError;
    fn from_str(s: &str) -> Result<Path, PathError> {
        Path::ALL
            .into_iter()
            .find(|p| p.name() == s.trim())
            .ok_or_else(|| PathError::Unknown(s.to_string()))
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
pub fn from_env() -> Result<Option<Path>, PathError> {
    let Some(v) = std::env::var_os("PHONG_APPROX_SIMD") else {
        return Ok(None);
    };
    let v = v.to_string_lossy();
    if v.trim().is_empty() {
        return Ok(None);
    }
    let p = v.parse::<Path>().map_err(|e| PathError::Env(Box::new(e)))?;
    if !p.supported() {
        return Err(PathError::Env(Box::new(PathError::unsupported(p))));
    }
    Ok(Some(p))
}

/// Runs `body` compiled for the chosen path's target features, handing it the path
/// (so that it can pick its chunk width): the one place where the kernels of
/// [`crate::fast`] and [`crate::fast_rows`] enter a vector path. `body` is inlined into
/// a function compiled with the path's features (`#[target_feature]`), so its loops
/// vectorize for that width; on the baseline it runs as it is.
#[inline(always)]
pub fn dispatch<R, F: FnOnce(Path) -> R>(body: F) -> R {
    #[cfg(target_arch = "x86_64")]
    {
        #[target_feature(enable = "avx2,fma")]
        unsafe fn avx2<R, F: FnOnce(Path) -> R>(body: F) -> R {
            body(Path::Avx2)
        }
        #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
        unsafe fn avx512<R, F: FnOnce(Path) -> R>(body: F) -> R {
            body(Path::Avx512)
        }
        let wide: unsafe fn(F) -> R = match path() {
            Path::Avx2 => avx2::<R, F>,
            Path::Avx512 => avx512::<R, F>,
            Path::Baseline => return body(Path::Baseline),
        };
        // SAFETY: `path()` is `Avx2` only where the CPU has AVX2 and FMA, and `Avx512`
        // only where it has AVX-512 F and VL besides (`Path::supported`: `best` picks
        // among the supported paths, and `force` and `from_env` refuse the others).
        return unsafe { wide(body) };
    }
    #[allow(unreachable_code)]
    body(Path::Baseline)
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
pub fn force(p: Path) -> Result<Path, PathError> {
    if !p.supported() {
        return Err(PathError::unsupported(p));
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
