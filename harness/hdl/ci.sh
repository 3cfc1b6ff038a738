#!/usr/bin/env bash
# SPDX-License-Identifier: MIT OR Apache-2.0
#
# The hardware stage of this repository's CI:
#
#   harness/hdl/ci.sh [CHECKER]     (default: $PHONG_APPROX_BIN, else target/release/phong-approx)
#
# 1. Lints every unit in units/ with `verilator --lint-only -Wall` (no warning at
#    8.40, the default, nor at 16.16) and checks that each planted bug in mutants/ (a
#    one-line sed script on its unit) changes one line of it, marked PLANTED, and that
#    docs/conformance.md shows units/gouraud.sv as it is.
# 2. run.sh: every unit passes every published set — gouraud, euler and
#    corrected-euler (both units/corrected_euler.sv), adaptive and duff, at 8.40, where
#    every published case has a bound (duff's included).
# 3. Every planted bug fails at least one set (exit 1, never 2): the host-side set-up
#    bugs of run.sh --mutant (eps-n1; truncated-setup on Gouraud and corrected Euler)
#    and each RTL mutant in mutants/ (the pixel count off by one either way; Duff's
#    divider and square root one iteration short).
# 4. run.sh's own failure modes: a planted bug in the example (pixel 0 skipped) fails
#    naming a case; a file that does not compile, wrong ports (a width, a name, a
#    missing parameter), a unit that never asserts out_valid, an X and a Z on
#    out_value, a set-up of another set (typical's set-up with edge's inputs), a
#    missing tool and bad arguments each exit 2 with one message.
# Prints its time. Verilator's compiled runtime and the C kit's object are kept for
# the run (PHONG_HDL_CACHE), so each model costs the unit's own C++ only.
#
# PHONG_KIT_VECTORS overrides the folder of the vector files, as for run.sh.
set -euo pipefail

start=$SECONDS
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bin=${1:-${PHONG_APPROX_BIN:-$here/../../target/release/phong-approx}}
[ -x "$bin" ] || { echo "ci.sh: no checker at $bin (build it: cargo build --release)" >&2; exit 2; }
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
docs=$here/../../docs/conformance.md
vectors=${PHONG_KIT_VECTORS:-$here/../../vectors}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM
export PHONG_HDL_CACHE=$tmp/cache
fail() { echo "ci.sh: $*" >&2; exit 1; }

# 1. Lint, the mutants' one line, the documented example.
for unit in "$here"/units/*.sv; do
  for format in "8 40" "16 16"; do
    set -- $format
    if ! verilator --lint-only -Wall -GM="$1" -GF="$2" "$unit" > "$tmp/lint.log" 2>&1 || [ -s "$tmp/lint.log" ]; then
      cat "$tmp/lint.log" >&2
      fail "units/${unit##*/} is not clean under verilator --lint-only -Wall at $1.$2"
    fi
  done
done
# Each planted bug is a one-line sed script on its unit (mutants/NAME.sed, named
# UNIT_what): applied here into $tmp/mutants/NAME.sv, it must change exactly the one
# line it names, mark it PLANTED, and lint.
mkdir -p "$tmp/mutants"
for script in "$here"/mutants/*.sed; do
  name=$(basename "$script" .sed)
  unit=
  case $name in
    corrected_euler_*) unit=$here/units/corrected_euler.sv ;;
    gouraud_*) unit=$here/units/gouraud.sv ;;
    duff_*) unit=$here/units/duff.sv ;;
    adaptive_*) unit=$here/units/adaptive.sv ;;
  esac
  [ -n "$unit" ] && [ -f "$unit" ] || fail "mutants/$name.sed: no unit it applies to"
  sed -f "$script" "$unit" > "$tmp/mutants/$name.sv"
  diff "$unit" "$tmp/mutants/$name.sv" > "$tmp/diff" || true
  if [ "$(grep -c '^[<>]' "$tmp/diff")" -ne 2 ] || ! grep -q '^>.*PLANTED' "$tmp/diff"; then
    cat "$tmp/diff" >&2
    fail "mutants/$name.sed does not change exactly one line of units/${unit##*/}, marked PLANTED (has the unit changed?)"
  fi
  verilator --lint-only -Wall -Wno-DECLFILENAME "$tmp/mutants/$name.sv" > "$tmp/lint.log" 2>&1 || { cat "$tmp/lint.log" >&2; fail "mutants/$name.sed gives a unit that does not lint"; }
done
awk '/<!-- example unit: begin -->/ { on = 1; next } /<!-- example unit: end -->/ { on = 0 }
     on && !/^```/ { print }' "$docs" > "$tmp/documented.sv"
cmp -s "$tmp/documented.sv" "$here/units/gouraud.sv" ||
  fail "docs/conformance.md's example unit is not units/gouraud.sv (update the section \"Hardware span units\")"
echo "  lint: every unit clean under verilator -Wall at 8.40 and 16.16; each mutant is its unit with one planted line; the documented example is units/gouraud.sv"

# 2. Every unit, every set.
pass() { # file method
  local rc=0
  bash "$here/run.sh" "$here/$1" --method "$2" "$bin" > "$tmp/out" 2> "$tmp/err" || rc=$?
  if [ "$rc" -ne 0 ]; then
    cat "$tmp/out" "$tmp/err" >&2
    fail "run.sh $1 --method $2 exited with $rc: a unit of this repository fails"
  fi
  echo "  $2 ($1) at 8.40: $(grep -c ' pass: ' "$tmp/out") of 3 sets pass; $(grep -m 1 -o '(unit: [^)]*)' "$tmp/out" | sed 's/^(unit: //; s/)$//') on typical"
}
pass units/gouraud.sv gouraud
pass units/corrected_euler.sv euler
pass units/corrected_euler.sv corrected-euler
pass units/adaptive.sv adaptive
pass units/duff.sv duff

# 3. Every planted bug fails at least one set, and run.sh runs to its end (exit 1).
fails() { # label, run.sh arguments...
  local label=$1 rc=0
  shift
  bash "$here/run.sh" "$@" "$bin" > "$tmp/out" 2> "$tmp/err" || rc=$?
  if [ "$rc" -ne 1 ] || ! grep -q ' FAIL: ' "$tmp/out"; then
    cat "$tmp/out" "$tmp/err" >&2
    fail "$label: run.sh exited with $rc; a planted bug must fail at least one set (exit 1)"
  fi
  echo "  $label: fails $(grep -c ' FAIL: ' "$tmp/out") of 3 sets ($(grep -m 1 ' FAIL: ' "$tmp/out" | sed 's/^ *//' | cut -c 1-110))"
}
fails "eps/(n+1) for eps/n (host set-up, corrected Euler)" "$here/units/corrected_euler.sv" --method corrected-euler --mutant eps-n1
fails "set-up truncated, not rounded (corrected Euler)" "$here/units/corrected_euler.sv" --method corrected-euler --mutant truncated-setup
fails "set-up truncated, not rounded (Gouraud)" "$here/units/gouraud.sv" --method gouraud --mutant truncated-setup
fails "mutants/gouraud_n_pixels.sed (n pixels)" "$tmp/mutants/gouraud_n_pixels.sv" --method gouraud
fails "mutants/corrected_euler_n2_pixels.sed (n + 2 pixels)" "$tmp/mutants/corrected_euler_n2_pixels.sv" --method corrected-euler
fails "mutants/duff_divider_short.sed (quotient's last bit dropped)" "$tmp/mutants/duff_divider_short.sv" --method duff
fails "mutants/duff_root_short.sed (root's last bit dropped)" "$tmp/mutants/duff_root_short.sv" --method duff

# 4. run.sh's failure modes, on copies of the example with one line changed.
plant() { # name, sed script: a copy of units/gouraud.sv in $tmp/NAME.sv
  sed "$2" "$here/units/gouraud.sv" > "$tmp/$1.sv"
  if cmp -s "$here/units/gouraud.sv" "$tmp/$1.sv"; then
    fail "could not plant $1 in units/gouraud.sv (its line changed?)"
  fi
}
exits2() { # what, pattern stderr must match, run.sh arguments...
  local what=$1 pattern=$2 rc=0
  shift 2
  bash "$here/run.sh" "$@" > "$tmp/out" 2> "$tmp/err" || rc=$?
  if [ "$rc" -ne 2 ] || ! grep -Eq -- "$pattern" "$tmp/err"; then
    cat "$tmp/out" "$tmp/err" >&2
    fail "run.sh on $what exited with $rc, not 2 with /$pattern/ on stderr"
  fi
  echo "  run.sh on $what: exit 2, $(head -n 1 "$tmp/err" | sed "s|$tmp/||g" | cut -c 1-150)"
}

plant skip0 's/      g  <= in_p0;/      g  <= in_p0 + in_dp;/'
rc=0
bash "$here/run.sh" "$tmp/skip0.sv" --method gouraud "$bin" > "$tmp/out" 2> "$tmp/err" || rc=$?
if [ "$rc" -ne 1 ] || [ "$(grep -cE ' FAIL: .*worst: (typical|edge|paper)-[0-9]+ ' "$tmp/out")" -ne 3 ]; then
  cat "$tmp/out" "$tmp/err" >&2
  fail "run.sh let the example with pixel 0 skipped through, or failed it without naming a case (exit $rc)"
fi
echo "  run.sh on the example with pixel 0 skipped: every set fails naming its worst case ($(grep -m 1 -o 'worst: [a-z]*-[0-9]*' "$tmp/out"), ...)"

plant syntax 's/^endmodule/endmodul/'
exits2 "a file that does not compile" 'syntax\.sv:[0-9]+:[0-9]+: syntax error' "$tmp/syntax.sv" --method gouraud "$bin"
grep -q 'does not compile' "$tmp/err" || fail "run.sh on a file that does not compile did not say so"
plant width 's/input  logic \[15:0\]           in_n,/input  logic [7:0]            in_n,/'
exits2 "in_n of 8 bits" "the unit's ports are not the documented ones" "$tmp/width.sv" --method gouraud "$bin"
grep -q "%Warning-WIDTH: phong_hdl_top.sv:[0-9]*:[0-9]*: .*'in_n'" "$tmp/err" || fail "run.sh on in_n of 8 bits did not show Verilator's message"
plant rename 's/in_dq0,/in_dq,/'
exits2 "in_dq for in_dq0" "the unit's ports are not the documented ones" "$tmp/rename.sv" --method gouraud "$bin"
grep -q "Pin not found: 'in_dq0'" "$tmp/err" || fail "run.sh on a renamed port did not show Verilator's message"
plant noparam 's/parameter int F = 40/parameter int G = 40/; s/M+F-1/M+G-1/g; s/M + F;/M + G;/'
exits2 "a unit without the parameter F" "the unit's ports are not the documented ones" "$tmp/noparam.sv" --method gouraud "$bin"
plant never "s/assign out_valid = busy;/assign out_valid = 1'b0;/"
exits2 "a unit that never asserts out_valid" 'case typical-001: no pixel for [0-9]+ cycles .*out_valid stayed low.*the cycle limit' \
  "$tmp/never.sv" --method gouraud "$bin"
plant xval 's/      g  <= in_p0;/      g  <= g;/'
exits2 "an unloaded register on out_value (X)" 'X or Z' "$tmp/xval.sv" --method gouraud "$bin"
plant zval "s/assign out_value = g;/assign out_value = (left == 16'd0) ? 'z : g;/"
exits2 "Z on out_value with pixel n" 'X or Z .* four-state' "$tmp/zval.sv" --method gouraud "$bin"
# A set-up of another set: typical.json (whose set-up run.sh makes) with edge's inputs.
mkdir "$tmp/mixed"
cp "$vectors/typical.json" "$tmp/mixed/typical.json"
cp "$vectors/edge-inputs.csv" "$tmp/mixed/typical-inputs.csv"
PHONG_KIT_VECTORS=$tmp/mixed exits2 "typical's set-up with edge's inputs" 'typical: case edge-001 of .* is not in the set-up' \
  "$here/units/gouraud.sv" --method gouraud --sets typical "$bin"

# A missing tool: every command on PATH but verilator.
mkdir "$tmp/path"
IFS=: read -r -a dirs <<< "$PATH"
for d in "${dirs[@]}"; do
  for f in "$d"/*; do
    n=${f##*/}
    case $n in verilator*) continue ;; esac
    if [ -x "$f" ] && [ ! -e "$tmp/path/$n" ]; then ln -s "$f" "$tmp/path/$n"; fi
  done
done
PATH=$tmp/path exits2 "a PATH without verilator" 'verilator is not on PATH' "$here/units/gouraud.sv" --method gouraud "$bin"
exits2 "no --method" '--method is required' "$here/units/gouraud.sv" "$bin"
exits2 "--fixed 20.40" 'at most 53' "$here/units/gouraud.sv" --method gouraud --fixed 20.40 "$bin"
exits2 "--mutant eps-n1 on Gouraud" 'use it with --method corrected-euler' "$here/units/gouraud.sv" --method gouraud --mutant eps-n1 "$bin"
echo "hdl ci: every unit passes every set; every planted bug fails; run.sh's failure modes exit as documented ($((SECONDS - start)) s)"
