//! A kernel's code for the device: WGSL text, SPIR-V words, or GLSL compiled by
//! glslang, read from a file with its size capped.

use super::*;

/// A kernel's code, ready for the device.
#[derive(Clone, Debug)]
pub enum Source {
    /// WGSL source text.
    Wgsl(String),
    /// SPIR-V words (from glslang, or a `.spv` file).
    SpirV(Vec<u32>),
}

impl Source {
    /// Reads a kernel: `.wgsl` as WGSL, `.spv` as SPIR-V, `.comp` or `.glsl` as GLSL
    /// compiled by `glslangValidator -V` (which must be on `PATH`; Debian:
    /// `glslang-tools`). At most [`MAX_SOURCE_BYTES`].
    ///
    /// # Errors
    /// [`GpuError::Source`] for an unreadable or oversized file or an unknown
    /// extension, [`GpuError::Compile`] with glslang's messages.
    pub fn from_file(path: &Path) -> Result<Source, GpuError> {
        let shown = path.display().to_string();
        let err = |message: String| GpuError::Source {
            path: shown.clone(),
            message,
        };
        let meta = std::fs::metadata(path).map_err(|e| err(format!("cannot read it: {e}")))?;
        if !meta.is_file() {
            return Err(err("not a regular file".into()));
        }
        if meta.len() > MAX_SOURCE_BYTES {
            return Err(err(format!(
                "{} bytes, more than the {MAX_SOURCE_BYTES} a kernel may have",
                meta.len()
            )));
        }
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        match ext {
            "wgsl" => {
                let text = std::fs::read_to_string(path)
                    .map_err(|e| err(format!("cannot read it as UTF-8 text: {e}")))?;
                Ok(Source::Wgsl(text))
            }
            "spv" => {
                let bytes = std::fs::read(path).map_err(|e| err(format!("cannot read it: {e}")))?;
                spirv_words(&bytes, &shown).map(Source::SpirV)
            }
            "comp" | "glsl" => glslang(path, &shown),
            _ => Err(err(format!(
                "unknown kernel extension '{}' (expected .wgsl, .spv, or .comp/.glsl for GLSL)",
                crate::error::shown(ext)
            ))),
        }
    }

    /// GLSL text compiled by `glslangValidator -V` (see [`Source::from_file`]).
    ///
    /// # Errors
    /// As [`Source::from_file`].
    pub fn glsl(text: &str, name: &str) -> Result<Source, GpuError> {
        let dir = private_dir(name)?;
        let file = dir.path().join("kernel.comp");
        std::fs::write(&file, text)
            .map_err(|e| GpuError::Source {
                path: name.into(),
                message: format!("cannot write a temporary file: {e}"),
            })
            .and_then(|()| glslang(&file, name))
    }
}

/// A new private temporary folder (random name, created exclusively, mode 0700,
/// removed when dropped) for glslang's input and output: nothing in it can be a
/// file or link planted by someone else.
fn private_dir(name: &str) -> Result<tempfile::TempDir, GpuError> {
    tempfile::Builder::new()
        .prefix("phong-approx-glslang-")
        .tempdir()
        .map_err(|e| GpuError::Source {
            path: name.into(),
            message: format!("cannot make a temporary folder: {e}"),
        })
}

/// SPIR-V bytes as words (little-endian, the magic number checked); a refusal names
/// the kernel `path`.
fn spirv_words(bytes: &[u8], path: &str) -> Result<Vec<u32>, GpuError> {
    let bad = |message: String| GpuError::Source {
        path: path.into(),
        message,
    };
    if !bytes.len().is_multiple_of(4) || bytes.len() < 20 {
        return Err(bad(format!(
            "{} bytes is not a SPIR-V module (a header of 5 words, then whole words)",
            bytes.len()
        )));
    }
    let words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    if words[0] != 0x0723_0203 {
        return Err(bad(format!(
            "not a SPIR-V module (magic number 0x{:08x}, expected 0x07230203)",
            words[0]
        )));
    }
    Ok(words)
}

/// Compiles a GLSL compute shader with `glslangValidator -V` into SPIR-V.
fn glslang(path: &Path, shown: &str) -> Result<Source, GpuError> {
    let dir = private_dir(shown)?;
    let out = dir.path().join("kernel.spv");
    let run = std::process::Command::new("glslangValidator")
        .arg("-V")
        .arg("-S")
        .arg("comp")
        .arg(path)
        .arg("-o")
        .arg(&out)
        .output();
    let run = match run {
        Ok(r) => r,
        Err(e) => {
            return Err(GpuError::Source {
                path: shown.into(),
                message: format!(
                "GLSL needs glslangValidator on PATH (Debian: apt-get install glslang-tools): {e}"
            ),
            })
        }
    };
    if !run.status.success() {
        let text = String::from_utf8_lossy(&run.stdout).to_string()
            + &String::from_utf8_lossy(&run.stderr);
        // glslang names the file it was given on each line; keep the lines that say
        // something, with their line numbers.
        let message: Vec<String> = text
            .lines()
            .filter(|l| !l.trim().is_empty() && l.trim() != path.display().to_string())
            .map(|l| l.replace(&path.display().to_string(), shown))
            .collect();
        return Err(GpuError::Compile {
            path: shown.into(),
            message: message.join("\n"),
        });
    }
    let bytes = std::fs::read(&out).map_err(|e| GpuError::Source {
        path: shown.into(),
        message: format!("glslang's output cannot be read: {e}"),
    })?;
    spirv_words(&bytes, shown).map(Source::SpirV)
}
