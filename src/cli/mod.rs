//! Sub-commands of the CLI and their shared error type.

use phong_approx::conformance::shown;
use std::fmt;
use std::io::{ErrorKind, Write};
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};

/// Set once standard output's reader has gone away (a closed pipe, as in
/// `phong-approx span … | head`): the rest of the output is dropped and the command
/// ends with its own exit code, as if the reader had read everything.
static STDOUT_CLOSED: AtomicBool = AtomicBool::new(false);

/// Writes `text` to standard output.
///
/// A closed pipe is not an error (see [`STDOUT_CLOSED`]); any other failure (a full
/// disk, `/dev/full`) is bad output: exit code 2 with one line.
///
/// # Errors
/// A [`CliError`] with code 2 naming standard output and the failure.
pub fn out(text: fmt::Arguments<'_>) -> Result<(), CliError> {
    let mut w = Stdout;
    w.write_fmt(text)
        .and_then(|()| w.flush())
        .map_err(stdout_error)
}

/// A failure of standard output other than a closed pipe: bad output, exit code 2.
fn stdout_error(e: std::io::Error) -> CliError {
    CliError {
        message: format!("standard output: {e}"),
        code: 2,
        details: Vec::new(),
    }
}

/// `println!` through [`out`]: `outln!(…)?`.
macro_rules! outln {
    () => { $crate::cli::out(format_args!("\n")) };
    ($($t:tt)*) => { $crate::cli::out(format_args!("{}\n", format_args!($($t)*))) };
}

/// `print!` through [`out`].
macro_rules! outp {
    ($($t:tt)*) => { $crate::cli::out(format_args!($($t)*)) };
}

pub mod check;
pub mod compare;
pub mod gpu;
pub mod output;
pub mod reproduce;
pub mod setup;
pub mod skip;
pub mod span;
pub mod torus;
pub mod vectors;

/// A CLI failure: one line naming what was wrong, and the exit code.
#[derive(Debug, thiserror::Error)]
#[error("{message}")]
pub struct CliError {
    /// The message, e.g. `--na: component 2 'x' is not a number …`.
    pub message: String,
    /// 2 for bad input, 1 for a failed check.
    pub code: u8,
    /// Lines shown after the message, indented: a shader compiler's messages, whose
    /// line numbers and source excerpts need lines of their own.
    pub details: Vec<String>,
}

impl CliError {
    /// Bad input (exit code 2) about `arg`.
    pub fn arg(arg: &str, problem: impl fmt::Display) -> Self {
        CliError {
            message: format!("{arg}: {problem}"),
            code: 2,
            details: Vec::new(),
        }
    }

    /// The exit code.
    pub fn code(&self) -> u8 {
        self.code
    }
}

/// A value an argument's parser refused, in words: clap prints it after the
/// argument's name (`--steps: n must be between 1 and 16777216 (got 0)`).
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct BadValue(pub String);

impl From<String> for BadValue {
    fn from(s: String) -> Self {
        BadValue(s)
    }
}

impl From<&str> for BadValue {
    fn from(s: &str) -> Self {
        BadValue(s.to_string())
    }
}

/// Parses a whole number within `lo..=hi`; `what` names it in the range message
/// (empty for none). The value parser of every whole-number argument.
///
/// # Errors
/// Not a whole number, or out of range, in words.
pub fn whole(s: &str, lo: u32, hi: u32, what: &str) -> Result<u32, BadValue> {
    let v: u64 = s
        .trim()
        .parse()
        .map_err(|_| format!("'{}' is not a whole number", shown(s)))?;
    if v < u64::from(lo) || v > u64::from(hi) {
        let what = if what.is_empty() {
            String::new()
        } else {
            format!("{what} ")
        };
        return Err(BadValue::from(format!(
            "{what}must be between {lo} and {hi} (got {v})"
        )));
    }
    Ok(v as u32)
}

/// Parses a vector `X,Y,Z` of decimals or fractions, exactly. The value parser of
/// every vector argument.
///
/// # Errors
/// What [`phong_approx::parse::parse_vec3`] refuses, in words.
pub fn vector(s: &str) -> Result<phong_approx::Vec3<phong_approx::BigRational>, BadValue> {
    phong_approx::parse::parse_vec3(s).map_err(|e| BadValue(e.to_string()))
}

/// Parses a decimal or fraction, exactly, within `lo..=hi`; `why` is the message
/// where it is not. The value parser of every coefficient (`K_d`, `K_s`).
///
/// # Errors
/// Not a number, or `why`.
pub fn coefficient(
    s: &str,
    lo: i64,
    hi: i64,
    why: &str,
) -> Result<phong_approx::BigRational, BadValue> {
    let x = phong_approx::parse::parse_rational(s).map_err(|e| e.to_string())?;
    let (lo, hi) = (
        phong_approx::BigRational::from_integer(lo.into()),
        phong_approx::BigRational::from_integer(hi.into()),
    );
    if x < lo || x > hi {
        return Err(why.into());
    }
    Ok(x)
}

/// `v` for `arg` if it is within `lo..=hi` (a bound another argument sets), in
/// [`whole`]'s words otherwise.
///
/// # Errors
/// A [`CliError`] naming `arg` and the range.
pub fn within(arg: &str, v: u32, lo: u32, hi: u32) -> Result<u32, CliError> {
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(CliError::arg(
            arg,
            format!("must be between {lo} and {hi} (got {v})"),
        ))
    }
}

/// Writes one line `phong-approx: MESSAGE` to standard error. Never panics: when
/// standard error itself cannot be written (`2>/dev/full`, a closed pipe) there is no
/// one left to tell, and the exit code says it.
pub fn report(message: &str) {
    let _ = writeln!(
        std::io::stderr().lock(),
        "phong-approx: {}",
        one_line(message)
    );
}

/// [`report`]'s line, then `details`, each line indented and made printable.
pub fn report_details(message: &str, details: &[String]) {
    report(message);
    let mut err = std::io::stderr().lock();
    for l in details {
        let _ = writeln!(err, "  {}", one_line(l));
    }
}

/// Prints clap's error as one line and exits with 2; help and version go to standard
/// output as clap prints them and exit 0, or 2 when standard output cannot take them
/// (a full disk). A bare `phong-approx` (no subcommand) is one line too.
pub fn clap_error(e: clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let text = e.render().to_string();
            let mut lock = std::io::stdout().lock();
            match lock.write_all(text.as_bytes()).and_then(|()| lock.flush()) {
                Ok(()) => ExitCode::SUCCESS,
                // A reader that went away has what it wanted (`--help | head`).
                Err(err) if err.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
                Err(err) => {
                    report(&format!("standard output: {err}"));
                    ExitCode::from(2)
                }
            }
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            report("a subcommand is needed: span, reproduce, compare, vectors or check (see phong-approx --help)");
            ExitCode::from(2)
        }
        _ => {
            report(&clap_message(&e));
            ExitCode::from(2)
        }
    }
}

/// A clap error as one line in the crate's words: `--arg: why` for a value the
/// argument refused (its parser's own message, or the values it takes), else clap's
/// message without its usage lines.
pub fn clap_message(e: &clap::Error) -> String {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    let arg = match e.get(ContextKind::InvalidArg) {
        Some(ContextValue::String(a)) => a.split(' ').next().unwrap_or(a).to_string(),
        _ => "argument".to_string(),
    };
    match e.kind() {
        ErrorKind::ValueValidation => {
            let why = std::error::Error::source(e)
                .map_or_else(|| e.kind().to_string(), |s| s.to_string());
            format!("{arg}: {why}")
        }
        ErrorKind::InvalidValue => {
            let value = match e.get(ContextKind::InvalidValue) {
                Some(ContextValue::String(v)) => shown(v),
                _ => String::new(),
            };
            let valid = match e.get(ContextKind::ValidValue) {
                Some(ContextValue::Strings(v)) => v.join(", "),
                _ => String::new(),
            };
            if valid.is_empty() {
                format!("{arg}: '{value}' is not a valid value here")
            } else {
                format!("{arg}: unknown value '{value}' (expected one of {valid})")
            }
        }
        _ => {
            let text = e.render().to_string();
            let line: Vec<&str> = text
                .lines()
                .map(str::trim)
                .filter(|l| {
                    !l.is_empty()
                        && !l.starts_with("Usage:")
                        && !l.starts_with("For more information")
                })
                .collect();
            let line = line.join(" ");
            line.strip_prefix("error: ").unwrap_or(&line).to_string()
        }
    }
}

/// Reads the file `path` (`-` for standard input) through a byte limit: whatever it
/// is (a file, a pipe, a FIFO, a device such as `/dev/zero`), reading stops after
/// `cap` bytes and the input is refused. A FIFO is opened without waiting for a writer,
/// so one that has none reads as empty instead of blocking.
///
/// # Errors
/// A [`CliError`] for `arg` (code 2): the file cannot be opened or read, is larger than
/// `cap`, or is not UTF-8.
pub fn read_capped(path: &str, arg: &str, cap: u64) -> Result<String, CliError> {
    use std::io::Read;
    let fail = |e: &dyn fmt::Display| CliError::arg(arg, format!("{}: {e}", shown(path)));
    let mut reader: Box<dyn Read> = if path == "-" {
        Box::new(std::io::stdin())
    } else {
        Box::new(open_nonblocking(path).map_err(|e| fail(&e))?)
    };
    let mut bytes = Vec::new();
    (&mut reader)
        .take(cap + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| fail(&e))?;
    if bytes.len() as u64 > cap {
        return Err(fail(&format!(
            "larger than {} MiB (reading stopped there)",
            cap >> 20
        )));
    }
    String::from_utf8(bytes).map_err(|e| {
        fail(&format!(
            "not UTF-8 text (byte {})",
            e.utf8_error().valid_up_to()
        ))
    })
}

/// Opens `path` for reading; on Unix with `O_NONBLOCK` (so opening a FIFO does not wait
/// for a writer), which is then cleared so that reads wait for data as usual.
fn open_nonblocking(path: &str) -> std::io::Result<std::fs::File> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        use std::os::unix::io::AsRawFd;
        let f = std::fs::OpenOptions::new()
            .read(true)
            .custom_flags(libc::O_NONBLOCK)
            .open(path)?;
        let fd = f.as_raw_fd();
        // SAFETY: `fd` is the open descriptor of `f`, which outlives both calls;
        // F_GETFL/F_SETFL only read and set its status flags.
        let flags = unsafe { libc::fcntl(fd, libc::F_GETFL) };
        if flags < 0 || unsafe { libc::fcntl(fd, libc::F_SETFL, flags & !libc::O_NONBLOCK) } < 0 {
            return Err(std::io::Error::last_os_error());
        }
        Ok(f)
    }
    #[cfg(not(unix))]
    {
        std::fs::File::open(path)
    }
}

/// A message as one safe line: control characters escaped, at most 1000 characters.
/// (Echoed input is already cut to 80 characters where it is quoted.)
pub fn one_line(s: &str) -> String {
    let mut out = String::new();
    for (k, c) in s.chars().enumerate() {
        if k == 1000 {
            out.push('…');
            break;
        }
        if c.is_control() {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    out
}

/// `check --profile`'s long help: the profiles, then how each method's bound is known
/// under each, from the one table of labels (`tolerance::profile::status_summary`).
pub fn profile_help() -> String {
    format!(
        "The arithmetic profile the results are judged by (docs/float.md §18): ieee (the default: IEEE f32/f64 with round to nearest, any order within each dot product and p_n's sum, FMA, reciprocals), shader (Vulkan/WGSL 32-bit rules: truncation, 2.5-ulp division, flushed denormals; f32), reference (this crate's own operation order, round to nearest, no FMA: the bounds of every method, angular and the related methods included) or fixed:M.F (a set-up rounded once to nearest at F ≤ 51 fractional bits, an exact integer loop in M-bit registers). Bounds: {}; reference: every method, proved for gouraud and corrected-euler in this crate's order, derived for the others. The default (ieee) bounds, u = 2^-24 for f32 and 2^-53 for f64: {} (docs/conformance.md §3 has them with values).",
        phong_approx::tolerance::profile::status_summary(),
        ieee_formulas()
    )
}

/// The `ieee` profile's bound for each method with one, `method formula`, from
/// [`phong_approx::tolerance::profile::formula`].
fn ieee_formulas() -> String {
    use phong_approx::tolerance::profile::{formula, Profile};
    phong_approx::Method::ALL
        .iter()
        .filter_map(|&m| {
            formula(m, Profile::Ieee, phong_approx::Format::Binary32)
                .map(|f| format!("{} {f}", m.name()))
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// A judgement the library refused, as the flag at fault: `tolerance` names the flag the
/// tolerance came from (`--tolerance` or `--profile`).
pub fn judge_error(e: phong_approx::conformance::check::JudgeError, tolerance: &str) -> CliError {
    use phong_approx::conformance::check::JudgeError as E;
    match e {
        E::Tolerance(_) => CliError::arg(tolerance, e),
        E::Method { .. } => CliError::arg("--method", e),
        // The shapes are read from the same file the command loaded.
        E::Shapes { .. } => CliError {
            message: e.to_string(),
            code: 2,
            details: Vec::new(),
        },
    }
}

/// `--method`'s help: every method of the catalogue by name, in its order.
pub fn methods_help() -> String {
    format!(
        "A method of the catalogue: {}",
        phong_approx::method::names()
    )
}

/// Standard output as an [`std::io::Write`], with [`out`]'s rules: a closed pipe
/// drops the rest silently ([`STDOUT_CLOSED`]), any other failure is an error.
struct Stdout;

impl Write for Stdout {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if STDOUT_CLOSED.load(Ordering::Relaxed) {
            return Ok(buf.len());
        }
        match std::io::stdout().lock().write_all(buf) {
            Err(e) if e.kind() == ErrorKind::BrokenPipe => {
                STDOUT_CLOSED.store(true, Ordering::Relaxed);
                Ok(buf.len())
            }
            r => r.map(|()| buf.len()),
        }
    }

    fn flush(&mut self) -> std::io::Result<()> {
        match std::io::stdout().lock().flush() {
            Err(e) if e.kind() == ErrorKind::BrokenPipe => {
                STDOUT_CLOSED.store(true, Ordering::Relaxed);
                Ok(())
            }
            r => r,
        }
    }
}

/// Writes `value` to standard output as pretty JSON and a newline, streamed in
/// pieces of 64 KiB (a report of 2^24 values is never one string in memory).
///
/// # Errors
/// A [`CliError`] with code 2 when standard output fails.
pub fn write_json(value: &impl serde::Serialize) -> Result<(), CliError> {
    let mut w = std::io::BufWriter::with_capacity(1 << 16, Stdout);
    serde_json::to_writer_pretty(&mut w, value)
        .map_err(std::io::Error::from)
        .and_then(|()| w.write_all(b"\n"))
        .and_then(|()| w.flush())
        .map_err(stdout_error)
}
