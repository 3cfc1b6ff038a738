//! The escaping of TeX math in the docs that rustdoc embeds (build/math.rs, run by
//! build.rs): inside `$…$` and `$$…$$` every ASCII punctuation character gets a
//! backslash, so that rustdoc's Markdown gives KaTeX the TeX as written; code and the
//! text around the math are left alone. `docs/check-math.sh` checks the rendered pages.

#[path = "../build/math.rs"]
mod math;

use math::escape_math;

#[test]
fn tex_control_symbols_survive() {
    assert_eq!(escape_math(r"a $x\,y$ b"), r"a $x\\\,y$ b");
    assert_eq!(escape_math(r"$\{x\}$"), r"$\\\{x\\\}$");
    assert_eq!(escape_math(r"$a \\ b$"), r"$a \\\\ b$");
}

#[test]
fn emphasis_html_links_and_tables_are_escaped() {
    assert_eq!(escape_math("$a_i * b_j$"), r"$a\_i \* b\_j$");
    assert_eq!(escape_math("$a < b > c$"), r"$a \< b \> c$");
    assert_eq!(escape_math("$[0, 1]$"), r"$\[0\, 1\]$");
    assert_eq!(escape_math("| $|x|$ | y |"), r"| $\|x\|$ | y |");
    // Smart punctuation would make a curly quote and an en dash.
    assert_eq!(escape_math("$m' -- n$"), r"$m\' \-\- n$");
}

#[test]
fn text_outside_math_is_untouched() {
    let md = "*emph* and a_b, <b>, [link](../src/span.rs) and `code`\n";
    assert_eq!(escape_math(md), md);
    assert_eq!(escape_math("no math here"), "no math here");
}

#[test]
fn code_spans_are_untouched() {
    assert_eq!(escape_math("`$x_1$` and $x_1$"), r"`$x_1$` and $x\_1$");
    assert_eq!(escape_math("``a ` $b_c$`` $d_e$"), r"``a ` $b_c$`` $d\_e$");
}

#[test]
fn display_math_spans_lines() {
    let md = "text\n\n$$a = b\n- c_1\n= d,$$\n\nafter $e_f$\n";
    let want = "text\n\n$$a \\= b\n\\- c\\_1\n\\= d\\,$$\n\nafter $e\\_f$\n";
    assert_eq!(escape_math(md), want);
}

#[test]
fn blanks_at_a_math_line_end_do_not_make_a_line_break() {
    assert_eq!(escape_math("$$a  \nb$$"), "$$a \nb$$");
}

#[test]
fn math_does_not_cross_a_paragraph() {
    let md = "$$a_b\n\nc_d$$ and $e_f\n\ng_h$\n";
    assert_eq!(escape_math(md), md);
}

#[test]
fn fenced_code_blocks_are_untouched() {
    let md = "$a_b$\n\n```sh\necho \"$HOME\" $x_y$\n```\n\n~~~\n$$c_d$$\n~~~\n$e_f$\n";
    let want = "$a\\_b$\n\n```sh\necho \"$HOME\" $x_y$\n```\n\n~~~\n$$c_d$$\n~~~\n$e\\_f$\n";
    assert_eq!(escape_math(md), want);
    // An unclosed fence runs to the end.
    assert_eq!(escape_math("```\n$a_b$\n"), "```\n$a_b$\n");
}

#[test]
fn literal_dollars_are_untouched() {
    for md in [
        "costs $5 and $6 each",
        "a lone $ sign",
        "ends with $",
        "an escaped \\$x_y\\$ pair",
        "$ x_y$ opens with a blank",
        "$x_y $ closes after a blank",
    ] {
        assert_eq!(escape_math(md), md, "{md}");
    }
    // A `\$` inside math does not close it.
    assert_eq!(escape_math(r"$a\$b_c$"), r"$a\\\$b\_c$");
}

/// The embedded docs change only by backslashes inserted before ASCII punctuation.
#[test]
fn the_embedded_docs_gain_only_escapes() {
    for name in ["derivations", "errata", "float"] {
        let path = format!("{}/docs/{name}.md", env!("CARGO_MANIFEST_DIR"));
        let md = std::fs::read_to_string(&path).unwrap();
        let out = escape_math(&md);
        assert_eq!(out.matches('$').count(), md.matches('$').count(), "{name}");
        let (o, m): (Vec<char>, Vec<char>) = (out.chars().collect(), md.chars().collect());
        let (mut j, mut k, mut inserted) = (0, 0, 0);
        while j < o.len() {
            let escaped = o.get(j + 1).copied().filter(|c| c.is_ascii_punctuation());
            if o[j] == '\\' && escaped.is_some() && m.get(k).copied() == escaped {
                // An escape the build inserted: `\P` for the source's `P`.
                inserted += 1;
                j += 2;
                k += 1;
            } else {
                assert_eq!(Some(&o[j]), m.get(k), "{name}: char {j}");
                j += 1;
                k += 1;
            }
        }
        assert_eq!(k, m.len(), "{name}");
        assert!(inserted > 100, "{name}: only {inserted} escapes");
    }
}
