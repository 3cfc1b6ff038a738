//! Writing output files safely.
//!
//! Every file a command writes goes first to a new temporary file in the target
//! folder (created exclusively, so never through a symbolic link), and all of them are
//! renamed into place together when the command has succeeded ([`OutDir::commit`]):
//! an interrupted or failed run leaves the previous complete output, never a mix.
//! A name that exists is replaced only if this tool wrote it before (the folder's
//! manifest, [`MANIFEST`], lists what it wrote) or with `--force`; a name that is a
//! symbolic link is never written through. Nothing of the user's is deleted.

use super::{read_capped, CliError};
use phong_approx::conformance::shown;
use std::cell::RefCell;
use std::collections::BTreeSet;
use std::fs::{self, OpenOptions};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// The file in an output folder that lists (one name a line) the files this tool
/// wrote there, which it may therefore replace.
pub const MANIFEST: &str = ".phong-approx-written";

static COUNTER: AtomicU64 = AtomicU64::new(0);

/// An output folder, with the files written so far waiting for [`OutDir::commit`].
pub struct OutDir {
    dir: PathBuf,
    force: bool,
    arg: &'static str,
    manifest: BTreeSet<String>,
    /// (temporary file, final name), in order of writing.
    pending: RefCell<Vec<(PathBuf, String)>>,
}

impl OutDir {
    /// Creates `dir` if needed and checks that a file can be created in it (a
    /// temporary file of our own, removed at once).
    ///
    /// # Errors
    /// A [`CliError`] for `arg` when the folder cannot be created or written.
    pub fn open(dir: &Path, force: bool, arg: &'static str) -> Result<Self, CliError> {
        let name = shown(&dir.display().to_string());
        fs::create_dir_all(dir)
            .map_err(|e| CliError::arg(arg, format!("cannot create {name}: {e}")))?;
        let manifest_path = dir.join(MANIFEST);
        let manifest = match fs::symlink_metadata(&manifest_path) {
            Ok(m) if m.is_file() => {
                read_capped(&manifest_path.display().to_string(), arg, 1 << 20)?
                    .lines()
                    .map(str::to_string)
                    .collect()
            }
            _ => BTreeSet::new(),
        };
        let out = OutDir {
            dir: dir.to_path_buf(),
            force,
            arg,
            manifest,
            pending: RefCell::new(Vec::new()),
        };
        let probe = out.temp_file("probe")?;
        let _ = fs::remove_file(probe);
        Ok(out)
    }

    /// A new, empty temporary file in the folder, created exclusively; its name ends
    /// with `name`, so that writers that go by the extension (PNG, SVG) see it.
    fn temp_file(&self, name: &str) -> Result<PathBuf, CliError> {
        loop {
            let k = COUNTER.fetch_add(1, Ordering::Relaxed);
            let p = self
                .dir
                .join(format!(".partial-{}-{k}.{name}", std::process::id()));
            match OpenOptions::new().write(true).create_new(true).open(&p) {
                Ok(_) => return Ok(p),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(e) => {
                    return Err(CliError::arg(
                        self.arg,
                        format!(
                            "cannot write in {}: {e}",
                            shown(&self.dir.display().to_string())
                        ),
                    ))
                }
            }
        }
    }

    /// Checks that `name` may be written: not a symbolic link, and either absent,
    /// written by this tool before, or `--force`.
    ///
    /// # Errors
    /// A [`CliError`] naming the file and what to do.
    pub fn check(&self, name: &str) -> Result<(), CliError> {
        let target = self.dir.join(name);
        match fs::symlink_metadata(&target) {
            Err(_) => Ok(()),
            Ok(m) if m.file_type().is_symlink() => Err(CliError::arg(
                self.arg,
                format!(
                    "{} is a symbolic link: not writing through it (remove it or choose another folder)",
                    shown(&target.display().to_string())
                ),
            )),
            Ok(m) if !m.is_file() => Err(CliError::arg(
                self.arg,
                format!(
                    "{} exists and is not a regular file",
                    shown(&target.display().to_string())
                ),
            )),
            Ok(_) if self.force || self.manifest.contains(name) => Ok(()),
            Ok(_) => Err(CliError::arg(
                self.arg,
                format!(
                    "{} exists and was not written by phong-approx: pass --force to replace it, or choose another folder",
                    shown(&target.display().to_string())
                ),
            )),
        }
    }

    /// Checks every name first (so that a refusal comes before any work).
    ///
    /// # Errors
    /// As [`OutDir::check`].
    pub fn check_all<'a>(&self, names: impl IntoIterator<Item = &'a str>) -> Result<(), CliError> {
        names.into_iter().try_for_each(|n| self.check(n))
    }

    /// A temporary path to write `name` to; it takes its place at [`OutDir::commit`].
    ///
    /// # Errors
    /// As [`OutDir::check`], or when the temporary file cannot be created.
    pub fn path_for(&self, name: &str) -> Result<PathBuf, CliError> {
        self.check(name)?;
        let p = self.temp_file(name)?;
        self.pending
            .borrow_mut()
            .push((p.clone(), name.to_string()));
        Ok(p)
    }

    /// Writes `name` with `text` (through a temporary file).
    ///
    /// # Errors
    /// As [`OutDir::path_for`], or the write's own failure.
    pub fn write(&self, name: &str, text: &str) -> Result<(), CliError> {
        let p = self.path_for(name)?;
        fs::write(&p, text).map_err(|e| {
            CliError::arg(
                self.arg,
                format!(
                    "cannot write {}: {e}",
                    shown(&self.dir.join(name).display().to_string())
                ),
            )
        })
    }

    /// The folder.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Renames every written file into place and records them in the manifest.
    ///
    /// # Errors
    /// A [`CliError`] when a rename fails (the files renamed before it stay).
    pub fn commit(mut self) -> Result<(), CliError> {
        let pending = std::mem::take(self.pending.get_mut());
        for (_, name) in &pending {
            self.manifest.insert(name.clone());
        }
        for (tmp, name) in pending {
            fs::rename(&tmp, self.dir.join(&name)).map_err(|e| {
                CliError::arg(
                    self.arg,
                    format!(
                        "cannot move {} into place: {e}",
                        shown(&self.dir.join(&name).display().to_string())
                    ),
                )
            })?;
        }
        // Last: a run cut short before this leaves files the manifest does not list,
        // which the next run then refuses to replace without --force (the safe side).
        let list: String = self.manifest.iter().map(|n| format!("{n}\n")).collect();
        let manifest_tmp = self.temp_file("manifest")?;
        fs::write(&manifest_tmp, list)
            .and_then(|()| fs::rename(&manifest_tmp, self.dir.join(MANIFEST)))
            .map_err(|e| CliError::arg(self.arg, format!("cannot write the manifest: {e}")))
    }
}

impl Drop for OutDir {
    /// Removes the temporary files of a run that did not commit.
    fn drop(&mut self) {
        for (tmp, _) in self.pending.get_mut().drain(..) {
            let _ = fs::remove_file(tmp);
        }
    }
}
