//! The conformance kit: published test vectors and a checker, for implementations in
//! other languages and number types to run in their CI.
//!
//! - [`vectors`]: the `typical`, `edge` and `paper` sets, generated from the exact
//!   references (committed under `vectors/`, with a JSON Schema).
//! - [`check`]: reading an implementation's results and comparing them, with
//!   per-method default tolerances from [`crate::tolerance`].
//! - [`report`]: the verdict as JUnit XML or JSON, for other languages' CI.
//!
//! How to use it from C or a shader harness: `docs/conformance.md`.

pub mod check;
pub mod integrity;
pub mod report;
pub mod vectors;

/// The longest piece of untrusted text a message shows.
pub const SHOWN_CHARS: usize = 80;

/// Untrusted text as a message may show it: at most [`SHOWN_CHARS`] characters (then
/// `…`), with control and other non-printable characters (and a byte-order mark)
/// escaped as `\u{…}`, so that no input can flood or drive the terminal.
pub fn shown(s: &str) -> String {
    let mut out = String::new();
    for (k, c) in s.chars().enumerate() {
        if k == SHOWN_CHARS {
            out.push('…');
            break;
        }
        if c.is_control() || c == '\u{feff}' || c == '\u{202e}' {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    out
}
