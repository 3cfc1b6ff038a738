#!/usr/bin/env bash
# Checks that the TeX math of docs/{derivations,errata,float}.md renders in the crate's
# rustdoc pages: builds the docs with docs/katex-header.html pointed at a local copy of
# KaTeX (the same version, from npm, so the header's SRI hashes are checked too), then
# docs/check-math.mjs opens each page in headless Chromium and fails on a KaTeX error,
# on a `$` left in the text, or on a formula whose TeX differs from the source's.
# Screenshots of a table and a display formula per page go to target/math-check/.
#
# Needs node/npm and Chromium (`apt-get install chromium`); KaTeX and playwright-core are
# installed under $MATHCHECK_DIR (default /tmp/mathcheck), not in the repository.
# Environment: CARGO (default cargo), CHROMIUM (default /usr/bin/chromium).
set -euo pipefail
cd "$(dirname "$0")/.."

tools=${MATHCHECK_DIR:-/tmp/mathcheck}
version=$(grep -o 'katex@[0-9][0-9.]*' docs/katex-header.html | head -n1 | cut -d@ -f2)
export CHROMIUM=${CHROMIUM:-/usr/bin/chromium}
if [ ! -x "$CHROMIUM" ]; then
  echo "no Chromium at $CHROMIUM (apt-get install chromium)" >&2
  exit 2
fi
have=$(node -p "try { require('$tools/node_modules/katex/package.json').version } catch { '' }")
if [ "$have" != "$version" ] || [ ! -d "$tools/node_modules/playwright-core" ]; then
  mkdir -p "$tools"
  npm install --prefix "$tools" --no-save --no-audit --no-fund "katex@$version" playwright-core
fi

header=$(mktemp --suffix=.html)
trap 'rm -f "$header"' EXIT
sed "s#https://cdn.jsdelivr.net/npm/katex@$version/dist/#/katex/#g" docs/katex-header.html >"$header"
RUSTDOCFLAGS="--html-in-header $header -D warnings" ${CARGO:-cargo} doc --no-deps --lib

node docs/check-math.mjs target/doc "$tools/node_modules/katex/dist" "$tools/node_modules" \
  target/math-check
