#!/usr/bin/env python3
"""Checks the relative links of the repository's Markdown files.

    python3 docs/check-links.py          (from anywhere inside the repository)

For every tracked *.md file (`git ls-files '*.md'`, without target/ and the fuzz
corpora) every relative link -- inline `[text](path)`, `[text](path#anchor)`,
`(#anchor)`, images `![alt](path)` and reference definitions `[ref]: path` -- must name
a file or directory that git tracks (a file that exists but is untracked is a 404 on
GitHub), and an `#anchor` into a Markdown file must be the GitHub slug of one of its
headings: the heading's text lowercased, every character that is not a letter, a mark,
a digit, `-`, `_` or a space removed, spaces turned into `-`, and a repeated slug
suffixed -1, -2, ... (github-slugger, which GitHub's anchors follow). Links to
http(s):, mailto: and other schemes are not checked; neither is anything inside fenced
code blocks, code spans or `$...$` / `$$...$$` math.

Prints each broken link as `file:line: link — reason` and exits 1 if there is any,
else prints a one-line summary and exits 0. Standard library only.
"""

import os
import re
import subprocess
import sys
import unicodedata
from urllib.parse import unquote


def repo_root():
    here = os.path.dirname(os.path.abspath(__file__))
    out = subprocess.run(["git", "rev-parse", "--show-toplevel"], cwd=here,
                         capture_output=True, text=True, check=True)
    return out.stdout.strip()


def tracked(root, pattern=None):
    args = ["git", "ls-files", "-z"] + ([pattern] if pattern else [])
    out = subprocess.run(args, cwd=root, capture_output=True, text=True, check=True)
    return [p for p in out.stdout.split("\0") if p]


def excluded(path):
    parts = path.split("/")
    return parts[0] == "target" or ("fuzz" in parts and any(
        p in ("corpus", "artifacts", "coverage") for p in parts))


# --- Masking what is not Markdown prose (keeping offsets and line numbers) -----------

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})(.*)$")


def blank_out(s):
    """`s` with every character but newlines replaced by a space."""
    return re.sub(r"[^\n]", " ", s)


def mask_fences(text):
    """The text with fenced code blocks blanked out (lines kept)."""
    out, fence = [], None
    for line in text.splitlines(keepends=True):
        body = line.rstrip("\n")
        if fence is None:
            m = FENCE.match(body)
            if m and not (m.group(1)[0] == "`" and "`" in m.group(2)):
                fence = (m.group(1)[0], len(m.group(1)))
                out.append(blank_out(line))
                continue
            out.append(line)
        else:
            m = FENCE.match(body)
            if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= fence[1] \
                    and not m.group(2).strip():
                fence = None
            out.append(blank_out(line))
    return "".join(out)


def mask_code_spans(text):
    """Code spans blanked out (a backtick run closes on a run of the same length)."""
    out, i, n = [], 0, len(text)
    while i < n:
        if text[i] == "\\" and i + 1 < n:
            out.append(text[i:i + 2])
            i += 2
            continue
        if text[i] != "`":
            out.append(text[i])
            i += 1
            continue
        j = i
        while j < n and text[j] == "`":
            j += 1
        run = j - i
        # The closing run: the next run of exactly `run` backticks, before a blank line.
        end = text.find("\n\n", j)
        end = n if end < 0 else end
        k, close = j, None
        while k < end:
            if text[k] == "`":
                m = k
                while m < n and text[m] == "`":
                    m += 1
                if m - k == run:
                    close = k
                    break
                k = m
            else:
                k += 1
        if close is None:
            out.append(text[i:j])
            i = j
        else:
            out.append(blank_out(text[i:close + run]))
            i = close + run
    return "".join(out)


MATH = re.compile(r"\$\$[\s\S]+?\$\$|\$(?=[^\s$])(?:\\.|[^$\\\n]|\n(?!\s*\n))*?"
                  r"(?:\\[^\s]|[^\s\\])\$(?!\d)")


def mask_math(text):
    return MATH.sub(lambda m: blank_out(m.group(0)), text)


def prose(text):
    return mask_math(mask_code_spans(mask_fences(text)))


# --- Headings and their GitHub slugs ---------------------------------------------------

ATX = re.compile(r"^ {0,3}(#{1,6})(?:[ \t]+(.*?))?(?:[ \t]+#+)?[ \t]*$")
SETEXT = re.compile(r"^ {0,3}(=+|-+)[ \t]*$")
NOT_PARAGRAPH = re.compile(r"^\s*$|^ {0,3}(#|>|[-*+][ \t]|\d+[.)][ \t]|\||<|={3,}|-{3,})")


def heading_text(src):
    """The plain text that GitHub renders for the Markdown of a heading."""
    codes = []

    def keep(m):
        codes.append(m.group(2).strip())
        return f"\0{len(codes) - 1}\0"

    t = re.sub(r"(`+)(.+?)\1", keep, src)                              # code spans
    t = re.sub(r"!\[([^\]]*)\]\([^)]*\)", r"\1", t)                    # images
    t = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", t)                     # links
    t = re.sub(r"\[([^\]]*)\]\[[^\]]*\]", r"\1", t)                    # reference links
    t = re.sub(r"<[^>\n]+>", "", t)                                    # HTML tags
    t = re.sub(r"(?<![\w\\])_+(?=\S)|(?<=\S)_+(?![\w])", "", t)        # _emphasis_
    t = re.sub(r"\\([!-/:-@\[-`{-~])", r"\1", t)                       # escapes
    return re.sub(r"\0(\d+)\0", lambda m: codes[int(m.group(1))], t)


def is_removed(c):
    if c in " -":
        return False
    cat = unicodedata.category(c)
    if cat[0] in "LM" or cat in ("Nd", "Nl", "Pc"):
        return False
    if cat[0] in "SPCZ" or cat == "No":
        return not c.isalpha()
    return False


def github_slug(text):
    return "".join(c for c in text.lower() if not is_removed(c)).replace(" ", "-")


def anchors(text):
    """The anchors of the headings of a Markdown text, as GitHub makes them."""
    seen = {}
    result = set()
    lines = mask_fences(text).split("\n")
    for i, line in enumerate(lines):
        m = ATX.match(line)
        if m and not line.startswith("    "):
            raw = m.group(2) or ""
        elif (i > 0 and SETEXT.match(line) and not NOT_PARAGRAPH.match(lines[i - 1])
              and not line.startswith("    ")):
            raw = lines[i - 1].strip()
        else:
            continue
        base = github_slug(heading_text(raw.strip()))
        slug = base
        while slug in seen:
            seen[base] += 1
            slug = f"{base}-{seen[base]}"
        seen[slug] = 0
        result.add(slug)
    # Explicit anchors: <a name="x"> / id="x".
    for m in re.finditer(r"<a\s[^>]*\b(?:name|id)\s*=\s*[\"']([^\"']+)[\"']", text):
        result.add(m.group(1))
    return result


# --- Links -----------------------------------------------------------------------------

SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def inline_links(text):
    """(offset, destination) of every inline link or image `[...](dest)` in `text`."""
    i, n = 0, len(text)
    while True:
        i = text.find("](", i)
        if i < 0:
            return
        # The `[` that opens the text (brackets may nest); none means no link.
        depth, k = 0, i
        while k >= 0:
            c = text[k]
            if c == "]" and (k == 0 or text[k - 1] != "\\"):
                depth += 1
            elif c == "[" and (k == 0 or text[k - 1] != "\\"):
                depth -= 1
                if depth == 0:
                    break
            elif c == "\n" and k + 1 < n and text[k + 1] == "\n":
                k = -1
                break
            k -= 1
        j = i + 2
        if k < 0:
            i = j
            continue
        while j < n and text[j] in " \t\n":
            j += 1
        if j < n and text[j] == "<":
            e = text.find(">", j)
            if e < 0:
                i = j
                continue
            dest = text[j + 1:e]
        else:
            depth, e = 0, j
            while e < n and not text[e].isspace():
                c = text[e]
                if c == "\\":
                    e += 2
                    continue
                if c == "(":
                    depth += 1
                elif c == ")":
                    if depth == 0:
                        break
                    depth -= 1
                e += 1
            dest = text[j:e]
        yield k, dest
        i = j


REF_DEF = re.compile(r"^ {0,3}\[([^\]]+)\]:[ \t]*<?([^\s>]+)>?", re.M)


def links(text):
    for off, dest in inline_links(text):
        yield off, dest
    for m in REF_DEF.finditer(text):
        yield m.start(2), m.group(2)


def main():
    root = repo_root()
    files = set(tracked(root))
    dirs = {os.path.dirname(p) for p in files}
    for d in list(dirs):
        while d:
            d = os.path.dirname(d)
            dirs.add(d)
    mds = sorted(p for p in tracked(root, "*.md") if not excluded(p))
    cache = {}

    def anchors_of(path):
        if path not in cache:
            with open(os.path.join(root, path), encoding="utf-8") as f:
                cache[path] = anchors(f.read())
        return cache[path]

    broken, checked = [], 0
    for md in mds:
        with open(os.path.join(root, md), encoding="utf-8") as f:
            text = f.read()
        masked = prose(text)
        for off, dest in sorted(links(masked)):
            if not dest or SCHEME.match(dest) or dest.startswith("//"):
                continue
            checked += 1
            line = masked.count("\n", 0, off) + 1
            path, _, frag = dest.partition("#")
            path = unquote(path.split("?", 1)[0])
            frag = unquote(frag)
            reason = None
            if path:
                if path.startswith("/"):
                    target = os.path.normpath(path.lstrip("/"))
                else:
                    target = os.path.normpath(os.path.join(os.path.dirname(md), path))
                if target.startswith(".."):
                    reason = "points outside the repository"
                elif target == ".":
                    target = ""
                if reason is None and target not in files and target not in dirs:
                    if os.path.exists(os.path.join(root, target)):
                        reason = f"{target} exists but is not tracked by git"
                    else:
                        reason = f"no such file: {target}"
            else:
                target = md
            if reason is None and frag and target.endswith(".md") and target in files:
                if frag not in anchors_of(target):
                    reason = f"no heading with the anchor #{frag} in {target}"
            if reason:
                broken.append(f"{md}:{line}: {dest} — {reason}")
    for b in broken:
        print(b)
    if broken:
        print(f"{len(broken)} broken link(s) of {checked} relative links in {len(mds)} "
              "Markdown files")
        return 1
    print(f"links OK: {checked} relative links in {len(mds)} Markdown files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
