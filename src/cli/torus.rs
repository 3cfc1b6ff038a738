//! The arguments `reproduce` and `compare` share: the image size and the torus radii
//! (with the run budget), and the error of a file that could not be written.

use super::BadValue;
use super::CliError;
use clap::Args;
use phong_approx::conformance::shown;
use std::path::Path;

/// The image size and torus radii, shared by `reproduce` and `compare`.
#[derive(Args, Debug)]
pub struct TorusArgs {
    /// Image size in pixels (each side 16 to 4096).
    #[arg(long, value_name = "WxH", default_value = "225x225", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Major and tube radius of the torus (0 < r < R).
    #[arg(long, value_name = "R,r", default_value = "1,0.4", value_parser = parse_radii)]
    pub radii: (f32, f32),
    /// Run even when the request exceeds the budget (more than 1024×1024 pixels, more
    /// than 200 frames of 512×512, or exact frames of more than 600,000 pixels in
    /// all), which would take many minutes to hours.
    #[arg(long)]
    pub yes: bool,
}

impl TorusArgs {
    /// Refuses, unless `--yes`, a run whose work exceeds the budget: `frames` frames
    /// and `exact_frames` exact frames of `size` pixels.
    ///
    /// # Errors
    /// A [`CliError`] naming the option and the limit.
    pub(crate) fn budget(
        &self,
        size: (u32, u32),
        frames: u32,
        exact_frames: u32,
    ) -> Result<(), CliError> {
        if self.yes {
            return Ok(());
        }
        let px = u64::from(size.0) * u64::from(size.1);
        if px > 1 << 20 {
            return Err(CliError::arg(
                "--size",
                format!("{}x{} is more than 1024×1024 pixels, which takes many minutes; pass --yes to run anyway", size.0, size.1),
            ));
        }
        if px * u64::from(frames) > 200 * 512 * 512 {
            return Err(CliError::arg(
                "--frames",
                format!("{frames} frames of {}x{} is more than 200 frames of 512×512, which takes many minutes; pass --yes to run anyway", size.0, size.1),
            ));
        }
        if px * u64::from(exact_frames) > 600_000 {
            return Err(CliError::arg(
                "--exact-frames",
                format!("{exact_frames} exact frames of {}x{} is more than 600,000 exact pixels (about a minute); pass --yes to run anyway", size.0, size.1),
            ));
        }
        Ok(())
    }
}

/// Parses `--size` (`WxH`, each 16 to 4096).
fn parse_size(s: &str) -> Result<(u32, u32), BadValue> {
    let bad = || format!("'{}' is not WxH, e.g. 200x200", shown(s));
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    if !(16..=4096).contains(&w) || !(16..=4096).contains(&h) {
        return Err(BadValue::from(format!(
            "{w}x{h} is out of range: width and height must be between 16 and 4096"
        )));
    }
    Ok((w, h))
}

/// Parses `--radii` (`R,r` with 0 < r < R).
fn parse_radii(s: &str) -> Result<(f32, f32), BadValue> {
    let bad = |why: &str| format!("'{}': {why}", shown(s));
    let (a, b) = s
        .split_once(',')
        .ok_or_else(|| bad("expected R,r, e.g. 1,0.4"))?;
    let big: f32 = a.trim().parse().map_err(|_| bad("R is not a number"))?;
    let small: f32 = b.trim().parse().map_err(|_| bad("r is not a number"))?;
    if !(big.is_finite() && small.is_finite() && small > 0.0 && big > small) {
        return Err(BadValue::from(bad("need 0 < r < R")));
    }
    Ok((big, small))
}

/// A [`CliError`] (code 2) naming `path` and the failure `e`.
pub(crate) fn io_err(path: &Path, e: impl std::fmt::Display) -> CliError {
    CliError {
        message: format!("{}: {e}", path.display()),
        code: 2,
        details: Vec::new(),
    }
}
