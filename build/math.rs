//! The TeX math of the Markdown docs that `src/lib.rs` embeds, made safe for rustdoc.
//!
//! GitHub renders `$…$` (inline) and `$$…$$` (display) math in Markdown; rustdoc does not,
//! and its Markdown parser (CommonMark with tables and smart punctuation) rewrites the TeX
//! before any script can see it: `\,` becomes `,`, `*` and `_` start emphasis, `<` starts
//! HTML, `'` becomes a curly quote, a `|` splits a table cell, a `-` at the start of a
//! line starts a list. `escape_math` puts a backslash before every ASCII punctuation
//! character inside a math segment, which CommonMark turns back into that one character,
//! so the text of the generated HTML holds the TeX exactly as written and KaTeX's
//! auto-render (docs/katex-header.html) can typeset it. Everything outside math is left
//! as it is.
//!
//! What counts as math, after GitHub's rules:
//! - fenced code blocks (``` or ~~~) and code spans are never math;
//! - `\$` outside math is a literal dollar;
//! - `$$` opens display math that ends at the next `$$`, possibly lines later;
//! - `$` followed by a non-blank opens inline math that ends at the next unescaped `$`
//!   not preceded by a blank and not followed by a digit;
//! - neither crosses a blank line (the end of a paragraph); an opening delimiter with no
//!   closing one is a literal dollar.
//!
//! Indented (four-space) code blocks are not recognised: the embedded docs use fences.
//!
//! A module of build.rs and of tests/doc_math.rs (`#[path]`), so it uses only `std`.

/// The Markdown `md` with the TeX of every math segment backslash-escaped for rustdoc.
pub fn escape_math(md: &str) -> String {
    let mut out = String::with_capacity(md.len() + md.len() / 4);
    // Start of the text not yet written, and the fence (character, length) we are in.
    let mut text_start = 0;
    let mut pos = 0;
    let mut fence: Option<(u8, usize)> = None;
    for line in md.split_inclusive('\n') {
        let line_start = pos;
        pos += line.len();
        match fence {
            Some((ch, len)) => {
                if fence_of(line).is_some_and(|(c, l)| c == ch && l >= len && fence_is_bare(line)) {
                    fence = None;
                }
                out.push_str(line);
                text_start = pos;
            }
            None => {
                if let Some(f) = fence_of(line) {
                    escape_text(&md[text_start..line_start], &mut out);
                    out.push_str(line);
                    fence = Some(f);
                    text_start = pos;
                }
            }
        }
    }
    escape_text(&md[text_start..], &mut out);
    out
}

/// The fence that `line` starts with, if any: its character and length (at least 3).
fn fence_of(line: &str) -> Option<(u8, usize)> {
    let t = line.trim_start().as_bytes();
    let ch = *t.first()?;
    if ch != b'`' && ch != b'~' {
        return None;
    }
    let len = t.iter().take_while(|&&c| c == ch).count();
    // A backtick fence's info string cannot contain a backtick (that is a code span).
    let info_ok = ch == b'~' || !t[len..].contains(&b'`');
    (len >= 3 && info_ok).then_some((ch, len))
}

/// Whether a fence line has nothing after its fence (a closing fence).
fn fence_is_bare(line: &str) -> bool {
    let t = line.trim();
    t.bytes().all(|c| c == b'`') || t.bytes().all(|c| c == b'~')
}

/// Escapes the math in `t`, a run of Markdown with no fenced code, onto `out`.
fn escape_text(t: &str, out: &mut String) {
    let b = t.as_bytes();
    let mut i = 0;
    let mut copied = 0;
    while i < b.len() {
        match b[i] {
            // A Markdown escape outside math, e.g. `\$`: both characters stay as they are.
            b'\\' => i += 2,
            b'`' => {
                let run = run_len(b, i, b'`');
                let end = paragraph_end(b, i);
                i = find_run(b, i + run, end, run).map_or(i + run, |j| j + run);
            }
            b'$' => {
                let open = if b.get(i + 1) == Some(&b'$') { 2 } else { 1 };
                match math_end(b, i, open) {
                    Some(close) => {
                        out.push_str(&t[copied..i + open]);
                        escape_tex(&t[i + open..close], out);
                        out.push_str(&t[close..close + open]);
                        i = close + open;
                        copied = i;
                    }
                    None => i += open,
                }
            }
            _ => i += 1,
        }
    }
    out.push_str(&t[copied..]);
}

/// Where the math opened by the `open` dollars at `i` closes (the index of its closing
/// delimiter), or `None` if those dollars are literal.
fn math_end(b: &[u8], i: usize, open: usize) -> Option<usize> {
    let start = i + open;
    let end = paragraph_end(b, start);
    if open == 1 && b.get(start).is_none_or(|c| c.is_ascii_whitespace()) {
        return None;
    }
    let mut j = start;
    while j < end {
        match b[j] {
            b'\\' => j += 2,
            b'$' if open == 2 && b.get(j + 1) == Some(&b'$') => return Some(j),
            b'$' if open == 1 => {
                let ok = j > start
                    && !b[j - 1].is_ascii_whitespace()
                    && !b.get(j + 1).is_some_and(|c| c.is_ascii_digit());
                return ok.then_some(j);
            }
            _ => j += 1,
        }
    }
    None
}

/// Writes the TeX `s` so that CommonMark reads it back as `s`: a backslash before every
/// ASCII punctuation character, and no run of blanks at a line end (a hard line break).
fn escape_tex(s: &str, out: &mut String) {
    for c in s.chars() {
        if c == '\n' {
            let kept = out.trim_end_matches([' ', '\t']).len();
            if out.len() > kept + 1 {
                out.truncate(kept + 1);
            }
        } else if c.is_ascii_punctuation() {
            out.push('\\');
        }
        out.push(c);
    }
}

/// The length of the run of `c` starting at `i`.
fn run_len(b: &[u8], i: usize, c: u8) -> usize {
    b[i..].iter().take_while(|&&x| x == c).count()
}

/// The start of a run of exactly `run` backticks in `b[from..end]`.
fn find_run(b: &[u8], from: usize, end: usize, run: usize) -> Option<usize> {
    let mut j = from;
    while j < end {
        if b[j] == b'`' {
            let r = run_len(b, j, b'`');
            if r == run {
                return Some(j);
            }
            j += r;
        } else {
            j += 1;
        }
    }
    None
}

/// The index of the blank line that ends the paragraph containing `from` (or the end).
fn paragraph_end(b: &[u8], from: usize) -> usize {
    let mut j = from;
    while let Some(k) = b[j..].iter().position(|&c| c == b'\n') {
        let next = j + k + 1;
        let rest = &b[next..];
        let line = rest
            .iter()
            .position(|&c| c == b'\n')
            .map_or(rest, |e| &rest[..e]);
        if line.iter().all(|c| c.is_ascii_whitespace()) {
            return next;
        }
        j = next;
    }
    b.len()
}
