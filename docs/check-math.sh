#!/usr/bin/env bash
# Checks that the TeX math of docs/{derivations,errata,float}.md renders in the crate's
# rustdoc pages: builds the docs with docs/katex-header.html pointed at a local copy of
# KaTeX (the same version, from npm, so the header's SRI hashes are checked too), then
# docs/check-math.mjs opens each page in headless Chromium and fails on a KaTeX error,
# on a `$` left in the text, or on a formula whose TeX differs from the source's.
# Screenshots of a table and a display formula per page go to target/math-check/.
#
# Needs node/npm and Chromium (`apt-get install chromium nodejs npm`); KaTeX and
# playwright-core are installed under $MATHCHECK_DIR (default /tmp/mathcheck), not in the
# repository.
# Environment: CARGO (default cargo), CHROMIUM (default /usr/bin/chromium),
# MATHCHECK_OPTIONAL=1 to skip (exit 0, printing "skipped: ...") when Chromium, node or
# npm is missing; without it a missing tool is an error (exit 2).
# Exit status: 0 passed (or skipped), 1 a formula does not render, 2 the check could not run.
set -euo pipefail
cd "$(dirname "$0")/.."

tools=${MATHCHECK_DIR:-/tmp/mathcheck}
version=$(grep -o 'katex@[0-9][0-9.]*' docs/katex-header.html | head -n1 | cut -d@ -f2)
if [ -z "$version" ]; then
  echo "error: no katex@<version> in docs/katex-header.html" >&2
  exit 2
fi
export CHROMIUM=${CHROMIUM:-/usr/bin/chromium}
missing=()
[ -x "$CHROMIUM" ] || missing+=("Chromium (no executable $CHROMIUM; apt-get install chromium, or set CHROMIUM)")
command -v node >/dev/null 2>&1 || missing+=("node (apt-get install nodejs)")
command -v npm >/dev/null 2>&1 || missing+=("npm (apt-get install npm)")
if [ ${#missing[@]} -gt 0 ]; then
  if [ "${MATHCHECK_OPTIONAL:-0}" = 1 ]; then
    printf 'skipped: the math check needs %s\n' "${missing[@]}"
    exit 0
  fi
  printf 'error: the math check needs %s\n' "${missing[@]}" >&2
  echo "(set MATHCHECK_OPTIONAL=1 to skip the check when these are missing)" >&2
  exit 2
fi
have=$(node -p "try { require('$tools/node_modules/katex/package.json').version } catch { '' }")
if [ "$have" != "$version" ] || [ ! -d "$tools/node_modules/playwright-core" ]; then
  mkdir -p "$tools"
  if ! npm install --prefix "$tools" --no-save --no-audit --no-fund --loglevel=error \
    "katex@$version" playwright-core; then
    echo "error: npm could not install katex@$version and playwright-core into $tools" >&2
    exit 2
  fi
fi

header=$(mktemp --suffix=.html)
trap 'rm -f "$header"' EXIT
sed "s#https://cdn.jsdelivr.net/npm/katex@$version/dist/#/katex/#g" docs/katex-header.html >"$header"
RUSTDOCFLAGS="--html-in-header $header -D warnings" ${CARGO:-cargo} doc --no-deps --lib

node docs/check-math.mjs target/doc "$tools/node_modules/katex/dist" "$tools/node_modules" \
  target/math-check
