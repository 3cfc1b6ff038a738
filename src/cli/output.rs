//! Writing output files safely.
//!
//! Every file a command writes goes first to a new temporary file in the target
//! folder (created exclusively, so never through a symbolic link), and all of them are
//! renamed into place together when the command has succeeded ([`OutDir::commit`]).
//! The renames are all-or-nothing as far as the file system allows: the list of
//! renames is written first ([`JOURNAL`]), interrupts (SIGINT, SIGTERM, SIGHUP) are
//! held off while they run, and a run that was killed during them anyway is completed
//! by the next run in that folder before it does anything else. A failed or
//! interrupted run before the renames leaves the previous complete output; stale
//! temporary files of runs that died are removed by the next run.
//! A name that exists is replaced only if this tool wrote it before (the folder's
//! manifest, [`MANIFEST`], lists what it wrote) or with `--force`; a name that is a
//! symbolic link is never written through, and neither is an output folder that is a
//! symbolic link. Nothing of the user's is deleted. A run holds an advisory lock on
//! the folder ([`LOCK`]) from [`OutDir::open`] to the end of its commit, and removes
//! the lock file when it ends: a second run into the same folder meanwhile exits 2 at
//! once, naming the first, so the manifest is only ever read and written by one run
//! at a time. A journal left by a run that died replaces only names the manifest
//! lists. Names that start with a dot are written like any other. (`--report` files
//! are single files into any folder and take another route: `cli::check`.)

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

/// The list of renames of a commit under way (`TEMPORARY NAME` tab `FINAL NAME`, a line
/// each), written before the first rename and removed after the last.
pub const JOURNAL: &str = ".phong-approx-commit";

/// The file in an output folder that a run holds an exclusive advisory lock on
/// (`flock`) from [`OutDir::open`] to the end of its commit, so that two runs never
/// write into one folder at once; it holds the process id of the run that has it.
pub const LOCK: &str = ".phong-approx-lock";

static COUNTER: AtomicU64 = AtomicU64::new(0);

/// An output folder, with the files written so far waiting for [`OutDir::commit`].
pub struct OutDir {
    dir: PathBuf,
    force: bool,
    arg: &'static str,
    manifest: BTreeSet<String>,
    /// (temporary file, final name), in order of writing.
    pending: RefCell<Vec<(PathBuf, String)>>,
    /// The folder's lock, held while this lives ([`LOCK`]).
    _lock: fs::File,
}

impl OutDir {
    /// Creates `dir` if needed and checks that a file can be created in it (a
    /// temporary file of our own, removed at once).
    ///
    /// # Errors
    /// A [`CliError`] for `arg` when the folder cannot be created or written.
    pub fn open(dir: &Path, force: bool, arg: &'static str) -> Result<Self, CliError> {
        let name = shown(&dir.display().to_string());
        if fs::symlink_metadata(dir).is_ok_and(|m| m.file_type().is_symlink()) {
            return Err(CliError::arg(
                arg,
                format!("{name} is a symbolic link: not writing through it (give the folder it points to, or another folder)"),
            ));
        }
        fs::create_dir_all(dir)
            .map_err(|e| CliError::arg(arg, format!("cannot create {name}: {e}")))?;
        // Our own bookkeeping files must be regular files (or absent) before any work.
        for own in [MANIFEST, JOURNAL, LOCK] {
            if let Ok(m) = fs::symlink_metadata(dir.join(own)) {
                if !m.is_file() {
                    return Err(CliError::arg(
                        arg,
                        format!(
                            "{} exists and is not a regular file (remove it)",
                            shown(&dir.join(own).display().to_string())
                        ),
                    ));
                }
            }
        }
        let lock = lock_folder(dir, arg)?;
        let mut manifest = read_manifest(dir, arg)?;
        finish_interrupted_commit(dir, arg, &mut manifest)?;
        remove_stale_partials(dir);
        let manifest = manifest;
        let out = OutDir {
            dir: dir.to_path_buf(),
            force,
            arg,
            manifest,
            pending: RefCell::new(Vec::new()),
            _lock: lock,
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
        if !is_plain_output_name(name) {
            return Err(CliError::arg(
                self.arg,
                format!(
                    "'{}' is not a name an output can have here (a file name, not one of the folder's bookkeeping files {MANIFEST}, {JOURNAL}, {LOCK})",
                    shown(name)
                ),
            ));
        }
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

    /// Renames every written file into place and records them in the manifest: the
    /// journal of renames first, then the renames with interrupts held off, then the
    /// manifest, then the journal is removed (see the module docs).
    ///
    /// # Errors
    /// A [`CliError`] when the journal, a rename or the manifest cannot be written
    /// (the next run in the folder completes the renames of the journal).
    pub fn commit(mut self) -> Result<(), CliError> {
        let pending = std::mem::take(self.pending.get_mut());
        let journal: String = pending
            .iter()
            .map(|(tmp, name)| {
                let tmp = tmp.file_name().map(|t| t.to_string_lossy().into_owned());
                format!("{}\t{name}\n", tmp.unwrap_or_default())
            })
            .collect();
        let journal_tmp = self.temp_file("journal")?;
        fs::write(&journal_tmp, journal)
            .and_then(|()| fs::rename(&journal_tmp, self.dir.join(JOURNAL)))
            .map_err(|e| {
                CliError::arg(self.arg, format!("cannot write the commit journal: {e}"))
            })?;
        let _held = HeldSignals::new();
        let renames = pending.into_iter().map(|(tmp, name)| {
            let tmp = tmp.file_name().map(|t| t.to_string_lossy().into_owned());
            (tmp.unwrap_or_default(), name)
        });
        finish_commit(
            &self.dir,
            self.arg,
            &mut self.manifest,
            renames.collect(),
            false,
        )
    }
}

impl Drop for OutDir {
    /// Removes the lock file while still holding its lock (a run that opened it
    /// meanwhile takes the lock again on a new file, see `lock_folder`).
    fn drop(&mut self) {
        let _ = fs::remove_file(self.dir.join(LOCK));
    }
}

/// Takes the folder's lock ([`LOCK`]): the lock file is opened without following a
/// symbolic link and locked exclusively without waiting; when another run holds it,
/// a one-line refusal naming that run (its process id, as it wrote it).
fn lock_folder(dir: &Path, arg: &'static str) -> Result<fs::File, CliError> {
    use std::io::{Read, Seek, Write};
    use std::os::unix::fs::MetadataExt;
    use std::os::unix::fs::OpenOptionsExt;
    use std::os::unix::io::AsRawFd;
    let path = dir.join(LOCK);
    let mut tries = 0;
    let f = loop {
        let f = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .custom_flags(libc::O_NOFOLLOW)
            .open(&path)
            .map_err(|e| {
                CliError::arg(
                    arg,
                    format!("cannot open {}: {e}", shown(&path.display().to_string())),
                )
            })?;
        // SAFETY: flock on a descriptor this function owns; LOCK_NB never blocks.
        let r = unsafe { libc::flock(f.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) };
        // The run before removes the lock file when it ends ([`OutDir`]'s drop): a
        // lock taken on a file that is no longer the folder's is taken again.
        let current = match (f.metadata(), fs::symlink_metadata(&path)) {
            (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
            _ => false,
        };
        if r == 0 && !current && tries < 100 {
            tries += 1;
            continue;
        }
        break (f, r);
    };
    let r = f.1;
    let mut f = f.0;
    if r != 0 {
        let mut holder = String::new();
        let _ = Read::by_ref(&mut f).take(32).read_to_string(&mut holder);
        let holder = holder.trim();
        let who = if holder.chars().all(|c| c.is_ascii_digit()) && !holder.is_empty() {
            format!("another phong-approx run (process {holder})")
        } else {
            "another phong-approx run".to_string()
        };
        return Err(CliError::arg(
            arg,
            format!(
                "{} is being written by {who}: wait for it to finish, or choose another folder",
                shown(&dir.display().to_string())
            ),
        ));
    }
    let _ = f.set_len(0);
    let _ = f.rewind();
    let _ = write!(f, "{}", std::process::id());
    Ok(f)
}

/// The names the folder's manifest lists (empty when there is none).
fn read_manifest(dir: &Path, arg: &'static str) -> Result<BTreeSet<String>, CliError> {
    let path = dir.join(MANIFEST);
    Ok(match fs::symlink_metadata(&path) {
        Ok(m) if m.is_file() => read_capped(&path.display().to_string(), arg, 1 << 20)?
            .lines()
            .map(str::to_string)
            .collect(),
        _ => BTreeSet::new(),
    })
}

/// Renames each `(temporary name, final name)` in `dir` whose temporary file exists,
/// adds the final names to `manifest`, writes the manifest and removes the journal.
/// A journal left by a run that died (`from_journal`) is trusted only so far: a name
/// that exists is replaced only if the manifest lists it (the journal may come from
/// an unpacked archive or a copied folder, and name any file), and each rename
/// passed over is said on standard error.
fn finish_commit(
    dir: &Path,
    arg: &'static str,
    manifest: &mut BTreeSet<String>,
    renames: Vec<(String, String)>,
    from_journal: bool,
) -> Result<(), CliError> {
    for (tmp, name) in renames {
        // Only our own temporary files, to plain names in this folder (a name that
        // starts with a dot is a name like any other, but never one of our own
        // bookkeeping files).
        if !tmp.starts_with(".partial-") || !is_plain_output_name(&name) {
            continue;
        }
        if from_journal
            && !manifest.contains(&name)
            && fs::symlink_metadata(dir.join(&name)).is_ok()
        {
            super::report(&format!(
                "warning: a commit journal left in {} names {}, which phong-approx did not write: not replacing it",
                shown(&dir.display().to_string()),
                shown(&name)
            ));
            continue;
        }
        let from = dir.join(&tmp);
        if fs::symlink_metadata(&from).is_ok_and(|m| m.is_file()) {
            if fs::symlink_metadata(dir.join(&name)).is_ok_and(|m| m.file_type().is_symlink()) {
                continue;
            }
            fs::rename(&from, dir.join(&name)).map_err(|e| {
                CliError::arg(
                    arg,
                    format!(
                        "cannot move {} into place: {e}",
                        shown(&dir.join(&name).display().to_string())
                    ),
                )
            })?;
        }
        manifest.insert(name);
    }
    let list: String = manifest.iter().map(|n| format!("{n}\n")).collect();
    let manifest_tmp = dir.join(format!(
        ".partial-{}-{}.manifest",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    fs::write(&manifest_tmp, list)
        .and_then(|()| fs::rename(&manifest_tmp, dir.join(MANIFEST)))
        .map_err(|e| CliError::arg(arg, format!("cannot write the manifest: {e}")))?;
    match fs::remove_file(dir.join(JOURNAL)) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(CliError::arg(
            arg,
            format!("cannot remove the commit journal: {e}"),
        )),
        _ => Ok(()),
    }
}

/// Whether `name` may be an output's name: one path component (no `/`, not `.`,
/// `..` or empty) and none of the folder's bookkeeping files ([`MANIFEST`],
/// [`JOURNAL`], [`LOCK`], temporary `.partial-…` files).
fn is_plain_output_name(name: &str) -> bool {
    !(name.is_empty()
        || name == "."
        || name == ".."
        || name.contains('/')
        || name.contains('\0')
        || name == MANIFEST
        || name == JOURNAL
        || name == LOCK
        || name.starts_with(".partial-"))
}

/// Completes the renames of a commit that was killed while it ran (its journal is
/// still there), so the folder holds the whole new output, never a mix.
fn finish_interrupted_commit(
    dir: &Path,
    arg: &'static str,
    manifest: &mut BTreeSet<String>,
) -> Result<(), CliError> {
    let path = dir.join(JOURNAL);
    if !fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
        return Ok(());
    }
    let text = read_capped(&path.display().to_string(), arg, 1 << 20)?;
    let renames = text
        .lines()
        .filter_map(|l| l.split_once('\t'))
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect();
    finish_commit(dir, arg, manifest, renames, true)
}

/// Removes the temporary files (`.partial-PID-…`) that runs which died left behind:
/// those whose process is gone (a journal, if any, has been completed before).
fn remove_stale_partials(dir: &Path) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Some(pid) = name
            .strip_prefix(".partial-")
            .and_then(|r| r.split('-').next())
            .and_then(|p| p.parse::<u32>().ok())
        else {
            continue;
        };
        let alive = pid == std::process::id() || Path::new(&format!("/proc/{pid}")).exists();
        if !alive && e.file_type().is_ok_and(|t| t.is_file()) {
            let _ = fs::remove_file(e.path());
        }
    }
}

/// The signals a commit holds off.
const HELD: [libc::c_int; 3] = [libc::SIGINT, libc::SIGTERM, libc::SIGHUP];

/// The first held signal that arrived during a commit (0: none).
static ARRIVED: std::sync::atomic::AtomicI32 = std::sync::atomic::AtomicI32::new(0);

extern "C" fn note_signal(sig: libc::c_int) {
    let _ = ARRIVED.compare_exchange(0, sig, Ordering::SeqCst, Ordering::SeqCst);
}

/// Holds off SIGINT, SIGTERM and SIGHUP while it lives, for the whole process (every
/// thread): a handler notes the first that arrives, and when the hold ends the old
/// dispositions come back and that signal is raised again, so an interrupt cannot
/// land between two renames of a commit but still ends the program after it.
struct HeldSignals {
    old: Vec<(libc::c_int, libc::sigaction)>,
}

impl HeldSignals {
    fn new() -> Self {
        let mut old = Vec::new();
        for sig in HELD {
            // SAFETY: a zeroed sigaction with an empty mask and a handler that only
            // stores to an atomic is a valid, async-signal-safe disposition;
            // sigaction writes the previous one into `prev`.
            unsafe {
                let mut act: libc::sigaction = std::mem::zeroed();
                act.sa_sigaction = note_signal as extern "C" fn(libc::c_int) as usize;
                libc::sigemptyset(&mut act.sa_mask);
                let mut prev: libc::sigaction = std::mem::zeroed();
                if libc::sigaction(sig, &act, &mut prev) == 0 {
                    old.push((sig, prev));
                }
            }
        }
        HeldSignals { old }
    }
}

impl Drop for HeldSignals {
    fn drop(&mut self) {
        for (sig, prev) in &self.old {
            // SAFETY: restores the disposition saved by `new`.
            unsafe {
                libc::sigaction(*sig, prev, std::ptr::null_mut());
            }
        }
        let sig = ARRIVED.swap(0, Ordering::SeqCst);
        if sig != 0 {
            // SAFETY: raising a signal with its original disposition restored.
            unsafe {
                libc::raise(sig);
            }
        }
    }
}
