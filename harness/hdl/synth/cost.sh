#!/usr/bin/env bash
# SPDX-License-Identifier: MIT OR Apache-2.0
#
# The hardware cost of the span units of harness/hdl/units/: cells, LUTs, clock rate
# and cycles, as the Markdown block of docs/performance.md ("Hardware: the span units
# in cells, LUTs and clock rate").
#
#   harness/hdl/synth/cost.sh            print the block
#   harness/hdl/synth/cost.sh --write    replace the block in docs/performance.md
#   harness/hdl/synth/cost.sh --check    regenerate it and fail (exit 1, with a diff)
#                                        if docs/performance.md's block differs
#
# For each harness/hdl/units/NAME.sv (module NAME), at the M and F its file declares
# as defaults:
#   1. Icarus Verilog, cycles.sv: the cycles to pixel 0, of one span and of a span in
#      a stream, at n = 8 and n = 64 (measured even where Yosys fails).
#   2. Yosys, generic: read_verilog -sv; chparam -set M m -set F f NAME;
#      synth -top NAME: the cells, and the flip-flops among them.
#   3. Yosys, iCE40: synth_ice40 -top NAME on the unit alone: SB_LUT4, SB_CARRY, SB_DFF*.
#   4. nextpnr-ice40 --hx8k --package ct256 --seed 1 --freq 12, on the unit inside a
#      ten-pin wrapper (cost.py wrapper: the units' 407 pins at 8.40 are more than the
#      HX8K's IO sites): the post-route maximum frequency of clk.
# The units are measured two at a time. The block carries the line
#   sources: SHA256
# the SHA-256 of the unit files sorted by name (bytewise) and concatenated, so that a
# test can tell, without these tools, whether the block is the current files':
#   cd harness/hdl/units && LC_ALL=C ls *.sv | LC_ALL=C sort | xargs cat | sha256sum
# The numbers depend on the tools' versions, which the block names; --check on other
# versions may differ in the LUT counts and the clock.
#
# Needs yosys, nextpnr-ice40, iverilog/vvp, python3, sha256sum. Exit: 0 done; 1 the
# block differs (--check), or a unit did not synthesize, place or simulate (its row
# says why; the rest of the block is still made); 2 bad arguments or a missing tool.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
units_dir=$root/harness/hdl/units
doc=$root/docs/performance.md

mode=print
case ${1:-} in
  '') ;;
  --write) mode=write ;;
  --check) mode=check ;;
  -h|--help) sed -n '3,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
  *) echo "usage: cost.sh [--write|--check]" >&2; exit 2 ;;
esac
[ $# -le 1 ] || { echo "usage: cost.sh [--write|--check]" >&2; exit 2; }

for tool in yosys nextpnr-ice40 iverilog vvp python3 sha256sum; do
  command -v "$tool" > /dev/null || { echo "cost.sh: $tool is not on PATH" >&2; exit 2; }
done

export LC_ALL=C
mapfile -t files < <(cd "$units_dir" && ls -- *.sv | sort)
[ ${#files[@]} -gt 0 ] || { echo "cost.sh: no unit in $units_dir" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

device_flags="--hx8k --package ct256"
seed=1
freq=12
{
  echo "units=${files[*]%.sv}"
  echo "sha256=$(cd "$units_dir" && cat -- "${files[@]}" | sha256sum | cut -d' ' -f1)"
  echo "yosys=$(yosys -V | sed 's/ (git sha1 [^)]*)//; s/ (.*//')"
  echo "nextpnr=$(nextpnr-ice40 --version 2>&1 | sed -n 's/^nextpnr-ice40 -- .*(Version \(.*\))$/nextpnr-ice40 \1/p')"
  echo "iverilog=$(iverilog -V 2>&1 | sed -n 1p | sed 's/ version / /; s/ *(.*//')"
  echo "device=$device_flags"
  echo "device_name=HX8K (ct256)"
  echo "seed=$seed"
  echo "freq=$freq"
} > "$work/meta"

# measure NAME: writes $work/NAME.row (key=value lines): the cycles (or
# cycles_error=...), then the synthesis and the clock (or error=... at the first step
# that failed).
measure() {
  local name=$1 src=$units_dir/$1.sv d=$work/$1 row=$work/$1.row
  mkdir -p "$d"
  : > "$row"
  fail() { echo "error=$1" >> "$row"; }
  local m f
  m=$(sed -n 's/.*parameter[[:space:]]\{1,\}int[[:space:]]\{1,\}M[[:space:]]*=[[:space:]]*\([0-9]\{1,\}\).*/\1/p' "$src" | sed -n 1p)
  f=$(sed -n 's/.*parameter[[:space:]]\{1,\}int[[:space:]]\{1,\}F[[:space:]]*=[[:space:]]*\([0-9]\{1,\}\).*/\1/p' "$src" | sed -n 1p)
  if [ -z "$m" ] || [ -z "$f" ]; then
    fail "no default \`parameter int M\` and \`F\` in $name.sv"; echo "cycles_error=-" >> "$row"; return
  fi
  echo "format=$m.$f" >> "$row"
  if ! grep -Eq "^[[:space:]]*module[[:space:]]+$name([^A-Za-z0-9_$]|\$)" "$src"; then
    fail "no module $name in $name.sv"; echo "cycles_error=-" >> "$row"; return
  fi

  # 1. Cycles.
  local n out cycles_ok=1
  if ! iverilog -g2012 -DCOST_UNIT="$name" -Pcost_cycles.M="$m" -Pcost_cycles.F="$f" \
      -o "$d/cycles" "$here/cycles.sv" "$src" > "$d/iverilog.log" 2>&1; then
    echo "cycles_error=iverilog failed ($(grep -v 'sorry' "$d/iverilog.log" | sed -n 1p | sed "s|$root/||"))" >> "$row"
    cycles_ok=0
  fi
  for n in 8 64; do
    [ "$cycles_ok" = 1 ] || break
    out=$(vvp -n "$d/cycles" "+n=$n" 2>&1 | grep '^cycles: ' || true)
    if [[ $out =~ ^cycles:\ latency\ ([0-9]+)\ single\ ([0-9]+)\ period\ ([0-9]+)$ ]]; then
      { echo "latency$n=${BASH_REMATCH[1]}"; echo "single$n=${BASH_REMATCH[2]}"; echo "period$n=${BASH_REMATCH[3]}"; } >> "$row"
    else
      echo "cycles_error=simulation at n = $n: ${out:-no result}" >> "$row"
      cycles_ok=0
    fi
  done

  # 2. Yosys, generic.
  if ! yosys -q -l "$d/generic.log" -p "read_verilog -sv $src; chparam -set M $m -set F $f $name; synth -top $name; write_json $d/generic.json" > /dev/null 2>&1; then
    fail "does not synthesize (Yosys: $(grep -m 1 'ERROR' "$d/generic.log" | sed "s|$root/||"))"; return
  fi
  local cells ff latch pins
  read -r cells ff latch pins < <(python3 "$here/cost.py" count-generic "$d/generic.json" "$name")
  [ "$latch" = 0 ] || { fail "Yosys infers $latch latch cells"; return; }
  { echo "cells=$cells"; echo "ff=$ff"; echo "pins=$pins"; } >> "$row"

  # 3. Yosys, iCE40, the unit alone.
  if ! yosys -q -l "$d/ice40.log" -p "read_verilog -sv $src; chparam -set M $m -set F $f $name; synth_ice40 -top $name -json $d/ice40.json" > /dev/null 2>&1; then
    fail "synth_ice40 failed ($(grep -m 1 'ERROR' "$d/ice40.log" | sed "s|$root/||"))"; return
  fi
  local lut carry dff other
  read -r lut carry dff other < <(python3 "$here/cost.py" count-ice40 "$d/ice40.json" "$name")
  [ "$other" = - ] || { fail "synth_ice40 made cells other than LUT, carry and flip-flop: $other"; return; }
  { echo "lut=$lut"; echo "carry=$carry"; echo "dff=$dff"; } >> "$row"

  # 4. Place and route, in the wrapper.
  local used
  used=$(python3 "$here/cost.py" used-inputs "$d/generic.json" "$name")
  # shellcheck disable=SC2086
  python3 "$here/cost.py" wrapper "$name" "$m" "$f" $used > "$d/wrap.sv"
  if ! yosys -q -l "$d/wrap.log" -p "read_verilog -sv $src $d/wrap.sv; synth_ice40 -top cost_wrap_$name -json $d/wrap.json" > /dev/null 2>&1; then
    fail "synth_ice40 of the wrapper failed ($(grep -m 1 'ERROR' "$d/wrap.log" | sed "s|$root/||"))"; return
  fi
  # shellcheck disable=SC2086
  if ! nextpnr-ice40 $device_flags --json "$d/wrap.json" --seed "$seed" --freq "$freq" \
      --pcf-allow-unconstrained --report "$d/report.json" > "$d/pnr.log" 2>&1; then
    fail "nextpnr-ice40 failed ($(grep -m 1 -E 'ERROR' "$d/pnr.log"))"; return
  fi
  # The critical path's first and last cells, from the last report (post-route).
  awk '/Critical path report for clock/ { n++; f = 1; next } /Critical path report for cross-domain/ { f = 0 }
       f { print n "\t" $0 }' "$d/pnr.log" > "$d/crit"
  local last
  last=$(cut -f1 "$d/crit" | tail -n 1)
  echo "crit_from=$(awk -F'\t' -v n="$last" '$1 == n && / Source / { print $2; exit }' "$d/crit" | sed 's/.* Source //')" >> "$row"
  echo "crit_to=$(awk -F'\t' -v n="$last" '$1 == n && / Setup / { s = $2 } END { print s }' "$d/crit" | sed 's/.* Setup //')" >> "$row"
  echo "lc=$(sed -n 's/.*ICESTORM_LC: *\([0-9]*\)\/.*/\1/p' "$d/pnr.log" | tail -n 1)" >> "$row"
  echo "used=$used" >> "$row"
  echo "io_sites=$(sed -n 's/.*SB_IO: *[0-9]*\/ *\([0-9]*\).*/\1/p' "$d/pnr.log" | tail -n 1)" >> "$row"
  local mhz
  mhz=$(python3 "$here/cost.py" fmax "$d/report.json")
  echo "fmax=$mhz" >> "$row"
}
export -f measure
export work units_dir root here device_flags seed freq

start=$SECONDS
printf '%s\n' "${files[@]%.sv}" | xargs -P 2 -I{} bash -c 'set -euo pipefail; measure "$1"' _ {} || true
for name in "${files[@]%.sv}"; do
  # A step that stopped measure without a row's error (a helper failed: its message
  # is on stderr above).
  if ! grep -q -e '^error=' -e '^fmax=' "$work/$name.row" 2> /dev/null ||
     ! grep -q -e '^cycles_error=' -e '^period64=' "$work/$name.row"; then
    echo "error=the measurement stopped (see cost.sh's messages)" >> "$work/$name.row"
  fi
done
python3 "$here/cost.py" render "$work" > "$work/block.md"
echo "cost.sh: ${#files[@]} units in $((SECONDS - start)) s" >&2

failed=$(grep -l -e '^error=' -e '^cycles_error=' "$work"/*.row 2> /dev/null | sed 's|.*/||; s|\.row$||' | tr '\n' ' ' || true)

status=0
case $mode in
  print) cat "$work/block.md" ;;
  write)
    python3 "$here/cost.py" splice "$doc" "$work/block.md"
    echo "cost.sh: wrote the block of docs/performance.md" >&2 ;;
  check)
    python3 "$here/cost.py" extract "$doc" > "$work/old.md"
    if ! diff -u --label "docs/performance.md (the block)" --label "cost.sh (regenerated)" "$work/old.md" "$work/block.md"; then
      echo "cost.sh: docs/performance.md's hardware table is not the current one: run harness/hdl/synth/cost.sh --write" >&2
      status=1
    fi ;;
esac
if [ -n "$failed" ]; then
  echo "cost.sh: failed: $failed(see the table's rows)" >&2
  status=1
fi
exit $status
