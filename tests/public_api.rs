//! The library's public interface, listed from the source and compared with the
//! checked-in `docs/public-api.txt`: a public item added, removed or changed (a
//! function's parameters, a field, an enum's variant) fails this test until the
//! listing is regenerated (`PHONG_APPROX_BLESS=1 cargo test --test claims public_api`)
//! and the change is named in CHANGELOG.md (the semver policy: README.md, "Versions
//! and upgrades").
//!
//! The listing is made from the text of `src/` (the command line, `src/cli/` and
//! `src/main.rs`, apart; unit tests apart): every `pub` item with its signature
//! joined onto one line, every `pub` field with its type, every variant of a `pub`
//! enum. It lists a public item of a private module too: more than the reachable
//! interface, never less.

use std::fs;
use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The library's source files, sorted, relative to the repository.
fn library_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                if p.file_name().is_some_and(|n| n != "cli") {
                    walk(&p, out);
                }
            } else if p.extension().is_some_and(|x| x == "rs")
                && p.file_name().is_some_and(|n| n != "main.rs")
            {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(&root().join("src"), &mut out);
    out.sort();
    out
}

/// Whitespace folded to single spaces.
fn fold(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The public items of one file's text, one line each.
fn items(text: &str) -> Vec<String> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    // The enclosing public struct or enum: (name, indentation, is an enum).
    let mut within: Option<(String, usize, bool)> = None;
    // The enclosing `impl` block's header, for its methods.
    let mut imp: Option<String> = None;
    let mut k = 0;
    while k < lines.len() {
        let line = lines[k];
        let t = line.trim_start();
        let indent = line.len() - t.len();
        // Unit tests end the public part of a file.
        if t.starts_with("#[cfg(test)]")
            && lines
                .get(k + 1)
                .is_some_and(|n| n.trim_start().starts_with("mod tests"))
        {
            break;
        }
        if indent == 0 && t.starts_with("impl") && t.trim_end().ends_with('{') {
            imp = Some(fold(t.trim_end_matches('{')));
        } else if indent == 0 && t.starts_with('}') {
            imp = None;
        }
        if let Some((name, at, is_enum)) = &within {
            if indent == *at && t.starts_with('}') {
                within = None;
            } else if indent == at + 4 && !t.starts_with("//") && !t.starts_with("#[") {
                if *is_enum && t.starts_with(|c: char| c.is_ascii_uppercase()) {
                    let v = t.trim_end_matches([',', '{', ' ']);
                    out.push(format!("{name}::{}", fold(v)));
                } else if let Some(f) = t.strip_prefix("pub ") {
                    if f.starts_with(|c: char| c.is_ascii_lowercase() || c == '_')
                        && f.contains(':')
                    {
                        out.push(format!("{name}.{}", fold(f.trim_end_matches(','))));
                    }
                }
            }
        }
        let kinds = [
            "fn ",
            "struct ",
            "enum ",
            "trait ",
            "const ",
            "static ",
            "type ",
            "mod ",
            "use ",
            "union ",
            "unsafe fn ",
            "const fn ",
        ];
        if let Some(rest) = t.strip_prefix("pub ") {
            if kinds.iter().any(|kd| rest.starts_with(kd)) {
                // The signature, joined until its body or its end.
                let mut sig = t.to_string();
                let mut j = k;
                while !(sig.contains('{') || sig.trim_end().ends_with(';')) && j + 1 < lines.len() {
                    j += 1;
                    sig.push(' ');
                    sig.push_str(lines[j].trim());
                }
                let sig = sig.split('{').next().unwrap_or("").trim_end_matches(';');
                match (&imp, indent > 0) {
                    (Some(h), true) => out.push(format!("{h}: {}", fold(sig))),
                    _ => out.push(fold(sig)),
                }
                let name = |kw: &str| {
                    rest.strip_prefix(kw).map(|r| {
                        r.split(|c: char| !(c.is_alphanumeric() || c == '_'))
                            .next()
                            .unwrap_or("")
                            .to_string()
                    })
                };
                if let Some(n) = name("struct ") {
                    if t.trim_end().ends_with('{') {
                        within = Some((n, indent, false));
                    }
                } else if let Some(n) = name("enum ") {
                    if t.trim_end().ends_with('{') {
                        within = Some((n, indent, true));
                    }
                }
            }
        }
        k += 1;
    }
    out
}

/// The whole listing: a line `path: item` per public item.
fn listing() -> String {
    let mut s = String::new();
    for f in library_files() {
        let rel = f.strip_prefix(root()).unwrap().display().to_string();
        for item in items(&fs::read_to_string(&f).unwrap()) {
            s += &format!("{rel}: {item}\n");
        }
    }
    s
}

#[test]
fn the_public_api_listing_is_current() {
    let path = root().join("docs/public-api.txt");
    let now = listing();
    if std::env::var_os("PHONG_APPROX_BLESS").is_some() {
        fs::write(&path, &now).unwrap();
        return;
    }
    let was = fs::read_to_string(&path).unwrap_or_default();
    if was != now {
        let old: std::collections::BTreeSet<&str> = was.lines().collect();
        let new: std::collections::BTreeSet<&str> = now.lines().collect();
        let gone: Vec<&&str> = old.difference(&new).take(20).collect();
        let added: Vec<&&str> = new.difference(&old).take(20).collect();
        panic!(
            "the public API changed (docs/public-api.txt):\nremoved or changed:\n{}\nadded or changed:\n{}\nif intended: PHONG_APPROX_BLESS=1 cargo test --test claims public_api, and name the change in CHANGELOG.md",
            gone.iter().map(|l| format!("  - {l}")).collect::<Vec<_>>().join("\n"),
            added.iter().map(|l| format!("  + {l}")).collect::<Vec<_>>().join("\n"),
        );
    }
}

#[test]
fn the_listing_sees_items_fields_variants_and_signatures() {
    let text = "pub struct S {\n    pub a: u32,\n    b: u8,\n}\n\nimpl S {\n    pub fn get(&self) -> u32 {\n        self.a\n    }\n}\n\npub enum E {\n    /// doc\n    One,\n    Two { x: u8 },\n}\n\npub fn f(\n    a: u32,\n    b: u8,\n) -> u32 {\n    a\n}\npub(crate) fn g() {}\n#[cfg(test)]\nmod tests {\n    pub fn h() {}\n}\n";
    assert_eq!(
        items(text),
        [
            "pub struct S",
            "S.a: u32",
            "impl S: pub fn get(&self) -> u32",
            "pub enum E",
            "E::One",
            "E::Two { x: u8 }",
            "pub fn f( a: u32, b: u8, ) -> u32",
        ]
    );
}
