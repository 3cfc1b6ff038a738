#!/usr/bin/env bash
# SPDX-License-Identifier: MIT OR Apache-2.0
#
# Tests your hardware span unit (SystemVerilog) on phong-approx's published vectors.
#
#   harness/hdl/run.sh UNIT.sv --method M [--fixed M.F] [CHECKER]
#                      [--sets typical,edge,paper] [--mutant NAME] [--setup DIR]
#                      [--top MODULE]
#
# UNIT.sv holds your unit, with the common ports of docs/conformance.md ("Hardware
# span units"; harness/hdl/units/gouraud.sv is one) and the parameters M and F. It is
# linted alone, then connected by name to tb/top.sv (the ports with their documented
# widths) and built with Verilator and tb/tb.cpp, linked with the C kit
# (harness/c/phong_kit.c), once. For each set,
#   CHECKER setup --vectors SET.json --method M --fixed M.F
# gives every case's set-up, computed exactly and rounded once to nearest (raw
# integers); the testbench reads the set's inputs, SET-inputs.csv, with the kit
# (pk_run_f64: the case list, in order), looks each case's set-up up by its id (a
# set-up that does not match the inputs is refused), drives each case through the
# unit — random back-pressure on out_ready from a fixed seed, idle cycles between
# spans — and has the kit write the results; then
#   CHECKER check --vectors SET.json --results R.csv --method M --profile fixed:M.F
#                 --precision f64
# judges the n + 1 values of every case by the bound of proofs/Fixed.v (the values
# are raw * 2^-F printed with %.17g, exact when M + F <= 53). X and Z: each set is
# simulated twice with different random initial values (Verilator --x-initial unique
# --x-assign unique, +verilator+rand+reset+2), and outputs that differ are X reaching
# in_ready, out_valid, out_value or out_last; and Icarus Verilog simulates each set's
# first spans (up to 1024 pixels) in four states (tb/xz.sv), since Verilator turns Z
# into 0. A third run, out_ready always high, measures the unit's pace.
# One line per set; the exit code is 0 if all pass, 1 if any fails, 2 for bad
# arguments, a missing tool (verilator, make, a C and a C++ compiler, iverilog, vvp)
# or file, a unit that does not compile or whose ports are not the documented ones, a
# set-up that does not match the set's inputs (a case missing, another n), the cycle
# limit (the unit never takes a set-up, never asserts out_valid, or never out_last;
# tb/tb.cpp), or X/Z on the outputs.
#
#   CHECKER          the phong-approx binary (default: phong-approx on PATH,
#                    from `cargo install --path .` in the phong-approx repository)
#   --method M       the method your unit computes (required): gouraud, euler,
#                    corrected-euler, adaptive or duff (units/corrected_euler.sv is
#                    both euler and corrected-euler: the set-up differs)
#   --fixed M.F      the format: M integer bits (the sign included), F fractional
#                    bits, M + F <= 53 (default 8.40, the units' default parameters)
#   --sets LIST      the published sets to run, comma-separated (default all three)
#   --mutant NAME    plant a host-side set-up bug, to see that the sets catch it:
#                    eps-n1 (corrected Euler's t0 with eps/(n+1) for eps/n) or
#                    truncated-setup (the set-up taken at F + 8 bits and floored to F
#                    bits, where the theorems assume rounding to nearest)
#   --setup DIR      drive the unit with your host's set-up instead: DIR/SET-METHOD-setup.csv
#                    (the same CSV); each is compared with CHECKER setup's first, and
#                    the cases where they differ are counted (the theorems assume
#                    CHECKER setup's values: rounded once to nearest)
#   --top MODULE     the unit's module, when UNIT.sv has several top-level modules
#
# Environment: PHONG_KIT_VECTORS (the folder of SET.json and SET-inputs.csv; default:
# vectors/ of the repository this script is in), PHONG_HDL_RESULTS (a folder to keep each set's
# set-up and results CSVs in, as SET-METHOD-setup.csv and SET-METHOD.csv),
# PHONG_HDL_CACHE (a folder to keep Verilator's compiled runtime and the kit's object
# in between runs; ci.sh uses one), CXX (the C++ compiler Verilator's makefile uses; default g++), CC
# (the C compiler for harness/c/phong_kit.c, C99; default cc).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
usage() {
  echo "usage: run.sh UNIT.sv --method M [--fixed M.F] [CHECKER] [--sets typical,edge,paper] [--mutant eps-n1|truncated-setup] [--setup DIR] [--top MODULE]"
}
bad() { echo "run.sh: $*" >&2; exit 2; }

unit= checker= method= fixed=8.40 sets_arg=typical,edge,paper mutant= top= own=
while [ $# -gt 0 ]; do
  case $1 in
    --method) [ $# -ge 2 ] || bad "--method needs a method name"; method=$2; shift 2 ;;
    --method=*) method=${1#*=}; shift ;;
    --fixed) [ $# -ge 2 ] || bad "--fixed needs a format M.F"; fixed=$2; shift 2 ;;
    --fixed=*) fixed=${1#*=}; shift ;;
    --sets) [ $# -ge 2 ] || bad "--sets needs a list of sets"; sets_arg=$2; shift 2 ;;
    --sets=*) sets_arg=${1#*=}; shift ;;
    --mutant) [ $# -ge 2 ] || bad "--mutant needs eps-n1 or truncated-setup"; mutant=$2; shift 2 ;;
    --mutant=*) mutant=${1#*=}; shift ;;
    --setup) [ $# -ge 2 ] || bad "--setup needs the folder of your set-up CSVs"; own=$2; shift 2 ;;
    --setup=*) own=${1#*=}; shift ;;
    --top) [ $# -ge 2 ] || bad "--top needs a module name"; top=$2; shift 2 ;;
    --top=*) top=${1#*=}; shift ;;
    -h|--help) usage; exit 0 ;;
    -*) usage >&2; bad "unknown option $1" ;;
    *)
      if [ -z "$unit" ]; then unit=$1
      elif [ -z "$checker" ]; then checker=$1
      else usage >&2; bad "one unit file and one checker only (more modules: put them in the unit's file)"
      fi
      shift ;;
  esac
done
[ -n "$unit" ] || { usage >&2; exit 2; }
[ -n "$method" ] || bad "--method is required: gouraud, euler, corrected-euler, adaptive or duff"
case $method in gouraud|euler|corrected-euler|adaptive|duff) ;;
  *) bad "--method takes gouraud, euler, corrected-euler, adaptive or duff, not $method" ;;
esac
[[ $fixed =~ ^([0-9]+)\.([0-9]+)$ ]] || bad "--fixed takes M.F (e.g. 8.40), not $fixed"
int_bits=$((10#${BASH_REMATCH[1]})) frac_bits=$((10#${BASH_REMATCH[2]}))
width=$((int_bits + frac_bits))
[ "$int_bits" -ge 1 ] && [ "$frac_bits" -ge 1 ] || bad "--fixed needs M >= 1 and F >= 1 (got $fixed)"
[ "$width" -le 53 ] ||
  bad "--fixed $fixed: M + F = $width bits; at most 53, so that a double holds every raw * 2^-F exactly"
case $mutant in
  ''|truncated-setup) ;;
  eps-n1) [ "$method" = corrected-euler ] || bad "--mutant eps-n1 plants a bug in corrected Euler's set-up: use it with --method corrected-euler" ;;
  *) bad "--mutant takes eps-n1 or truncated-setup, not $mutant (RTL mutants: give the mutant's file as UNIT.sv)" ;;
esac
sets=()
IFS=, read -r -a listed <<< "$sets_arg"
for set in "${listed[@]}"; do
  case $set in typical|edge|paper) sets+=("$set") ;;
    *) bad "--sets takes typical, edge and paper, comma-separated, not '$set'" ;;
  esac
done
[ ${#sets[@]} -gt 0 ] || bad "--sets names no set"
if [ -n "$own" ]; then
  [ -z "$mutant" ] || bad "--setup and --mutant do not go together"
  for set in "${sets[@]}"; do
    [ -f "$own/$set-$method-setup.csv" ] || bad "--setup $own: no $own/$set-$method-setup.csv"
  done
fi
[ -f "$unit" ] || bad "no such unit file: $unit"
for f in tb/top.sv tb/tb.cpp tb/xz.sv; do
  [ -f "$here/$f" ] || bad "$f is not next to run.sh ($here)"
done
kit=$here/../c
for f in phong_kit.c phong_kit.h; do
  [ -f "$kit/$f" ] || bad "no $kit/$f: the testbench links the C kit, harness/c/$f of the repository run.sh is in"
done

# The tools: none is optional.
command -v verilator > /dev/null ||
  bad "verilator is not on PATH (Debian/Ubuntu: apt-get install verilator; version 5 is tested)"
command -v make > /dev/null || bad "make is not on PATH (Verilator's build needs it)"
command -v iverilog > /dev/null && command -v vvp > /dev/null ||
  bad "iverilog (Icarus Verilog) is not on PATH: the four-state X/Z check needs it (Debian/Ubuntu: apt-get install iverilog)"
cxx=${CXX:-g++}
command -v "$cxx" > /dev/null || bad "the C++ compiler $cxx is not on PATH (Verilator's build needs it; set CXX)"
cc=${CC:-cc}
command -v "$cc" > /dev/null || bad "the C compiler $cc is not on PATH (the testbench links harness/c/phong_kit.c; set CC)"

if [ -z "$checker" ]; then
  checker=$(command -v phong-approx) ||
    bad "phong-approx is not on PATH: run \`cargo install --path .\` in the phong-approx repository, or give the checker's path after the unit file"
elif [[ $checker != */* ]]; then
  checker=$(command -v "$checker") || bad "no checker $checker on PATH"
fi
[ -x "$checker" ] || bad "the checker $checker is not an executable file"

vectors=${PHONG_KIT_VECTORS:-$here/../../vectors}
for set in "${sets[@]}"; do
  [ -f "$vectors/$set.json" ] || bad "no $vectors/$set.json (set PHONG_KIT_VECTORS to the folder of the vector files)"
  [ -f "$vectors/$set-inputs.csv" ] || bad "no $vectors/$set-inputs.csv (set PHONG_KIT_VECTORS to the folder of the vector files)"
done
results=${PHONG_HDL_RESULTS:-}
if [ -n "$results" ]; then mkdir -p "$results"; fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM

# The unit's module: the one top-level module of UNIT.sv, or --top.
if [ -z "$top" ]; then
  sed 's://.*$::' "$unit" > "$tmp/unit.nocomments"
  modules=$(sed -n 's/^[[:space:]]*module[[:space:]]\{1,\}\([A-Za-z_][A-Za-z0-9_$]*\).*/\1/p' "$tmp/unit.nocomments" | sort -u)
  tops=()
  for m in $modules; do
    # Instantiated by another module of the file: `m #(` or `m name (`.
    if ! grep -Eq "^[[:space:]]*$m[[:space:]]*(#|[A-Za-z_][A-Za-z0-9_]*[[:space:]]*\()" "$tmp/unit.nocomments"; then
      tops+=("$m")
    fi
  done
  case ${#tops[@]} in
    0) bad "no module in $unit" ;;
    1) top=${tops[0]} ;;
    *) bad "$unit has several top-level modules (${tops[*]}): name the unit with --top" ;;
  esac
fi

# Verilator's messages name files by the paths given: keep the user's.
shown() { sed "s|$tmp/||g"; }
# blocks FILE PATTERN: Verilator's messages (a %-line and its indented lines) whose
# first line matches PATTERN.
blocks() {
  awk -v pat="$2" '/^%/ { keep = ($0 ~ pat) } keep { print }' "$1"
}

# 1. The unit alone, at its own default parameters: does it compile?
lint=(--lint-only -Wno-fatal -Wno-lint -Wno-style --top-module "$top")
if ! verilator "${lint[@]}" "$unit" > "$tmp/lint.log" 2>&1; then
  echo "run.sh: $unit does not compile (verilator --lint-only --top-module $top):" >&2
  shown < "$tmp/lint.log" | grep -v '^ *\.\.\. See the manual' >&2
  exit 2
fi

# 2. The unit on the testbench's ports, by name, at M.F: are its ports the
# documented ones? (A port missing, another name, another width, an extra port, or
# no parameter M or F.) Any message about the connection is a no.
cp "$here/tb/top.sv" "$tmp/phong_hdl_top.sv"
ports_rc=0
verilator --lint-only -Wno-fatal -Wno-lint -Wno-style -Wwarn-WIDTH -Wwarn-PINMISSING \
  -Wwarn-PINCONNECTEMPTY --top-module phong_hdl_top -GM="$int_bits" -GF="$frac_bits" \
  -DPHONG_HDL_UNIT="$top" "$tmp/phong_hdl_top.sv" "$unit" > "$tmp/ports.log" 2>&1 || ports_rc=$?
blocks "$tmp/ports.log" 'phong_hdl_top\.sv:' > "$tmp/ports.msg"
if [ -s "$tmp/ports.msg" ]; then
  echo "run.sh: the unit's ports are not the documented ones (docs/conformance.md, \"Hardware span units\"; module $top with parameters M and F):" >&2
  shown < "$tmp/ports.msg" >&2
  exit 2
fi
if [ "$ports_rc" -ne 0 ]; then
  echo "run.sh: $unit does not compile with M = $int_bits, F = $frac_bits (verilator --lint-only):" >&2
  shown < "$tmp/ports.log" | grep -v '^ *\.\.\. See the manual' >&2
  exit 2
fi

# 3. The model: Verilator and tb/tb.cpp, with the C kit compiled as C99, built once
# for every set. PHONG_HDL_CACHE keeps the kit's object, keyed by the C compiler's
# version, the flags and the kit's sources.
mkdir "$tmp/kit"
cp "$kit/phong_kit.c" "$kit/phong_kit.h" "$tmp/kit/"
kit_flags=(-std=c99 -O2)
kit_cache=
if [ -n "${PHONG_HDL_CACHE:-}" ]; then
  key=$( { "$cc" --version 2> /dev/null | sed -n 1p; echo "${kit_flags[*]}"; cat "$tmp/kit/phong_kit.c" "$tmp/kit/phong_kit.h"; } | cksum | cut -d' ' -f1)
  kit_cache=$PHONG_HDL_CACHE/phong_kit-$key.o
fi
if [ -n "$kit_cache" ] && [ -f "$kit_cache" ]; then
  cp "$kit_cache" "$tmp/kit/phong_kit.o"
else
  if ! "$cc" "${kit_flags[@]}" -c -o "$tmp/kit/phong_kit.o" "$tmp/kit/phong_kit.c" > "$tmp/kit.log" 2>&1; then
    echo "run.sh: $cc could not compile harness/c/phong_kit.c:" >&2
    shown < "$tmp/kit.log" >&2
    exit 2
  fi
  if [ -n "$kit_cache" ]; then
    mkdir -p "$PHONG_HDL_CACHE"
    { cp "$tmp/kit/phong_kit.o" "$kit_cache.tmp.$$" && mv -f "$kit_cache.tmp.$$" "$kit_cache"; } 2> /dev/null ||
      rm -f "$kit_cache.tmp.$$"
  fi
fi
vflags=(--cc --exe -Wno-fatal -Wno-lint -Wno-style --prefix Vunit --top-module phong_hdl_top
  -GM="$int_bits" -GF="$frac_bits" -DPHONG_HDL_UNIT="$top" --x-assign unique --x-initial unique
  -CFLAGS "-DPHONG_W=$width -DPHONG_F=$frac_bits -I$tmp/kit" --Mdir "$tmp/obj" -o tb)
make_flags=(OPT_FAST=-O1 OPT_SLOW=-O0 OPT_GLOBAL=-O1 "CXX=$cxx")
if ! verilator "${vflags[@]}" "$tmp/phong_hdl_top.sv" "$unit" "$here/tb/tb.cpp" "$tmp/kit/phong_kit.o" > "$tmp/build.log" 2>&1; then
  echo "run.sh: verilator could not make a model of $unit:" >&2
  shown < "$tmp/build.log" >&2
  exit 2
fi
# Verilator's runtime (verilated.o, verilated_threads.o) is the same for every unit:
# PHONG_HDL_CACHE keeps it, keyed by the Verilator and compiler versions and flags.
runtime=(verilated.o verilated_threads.o)
cache=
if [ -n "${PHONG_HDL_CACHE:-}" ]; then
  key=$( { verilator --version; "$cxx" --version | sed -n 1p; echo "${make_flags[*]}"; } | cksum | cut -d' ' -f1)
  cache=$PHONG_HDL_CACHE/runtime-$key
  if [ -d "$cache" ]; then
    for o in "${runtime[@]}"; do
      # Newer than the fresh Vunit.mk, on which make makes them depend.
      if [ -f "$cache/$o" ]; then cp "$cache/$o" "$tmp/obj/$o" && touch "$tmp/obj/$o"; fi
    done
  fi
fi
if ! make -s -C "$tmp/obj" -f Vunit.mk -j 2 "${make_flags[@]}" > "$tmp/make.log" 2>&1; then
  echo "run.sh: building the model of $unit failed:" >&2
  shown < "$tmp/make.log" | tail -n 40 >&2
  exit 2
fi
if [ -n "$cache" ] && [ ! -d "$cache" ]; then
  mkdir -p "$PHONG_HDL_CACHE"
  if mkdir "$cache.tmp.$$" 2> /dev/null; then
    for o in "${runtime[@]}"; do cp -p "$tmp/obj/$o" "$cache.tmp.$$/"; done
    mv -T "$cache.tmp.$$" "$cache" 2> /dev/null || rm -rf "$cache.tmp.$$"
  fi
fi

# 4. The four-state model (Icarus Verilog), for X and Z: Verilator has two states.
if ! iverilog -g2012 -DPHONG_HDL_UNIT="$top" -Pphong_hdl_xz.M="$int_bits" -Pphong_hdl_xz.F="$frac_bits" \
    -o "$tmp/xz" "$here/tb/xz.sv" "$unit" > "$tmp/xz.log" 2>&1; then
  echo "run.sh: iverilog could not build the four-state X/Z check of $unit:" >&2
  shown < "$tmp/xz.log" | grep -v 'sorry: .* ignored' >&2
  exit 2
fi

what="$unit (module $top) as $method at $int_bits.$frac_bits"
if [ -n "$mutant" ]; then what="$what, with the planted set-up bug $mutant"; fi
echo "phong hdl: $what, checked by $checker ($("$checker" --version 2>/dev/null || echo "version unknown"))"
echo "  $(verilator --version), $(iverilog -V 2>&1 | sed -n 1p | sed 's/ version / /; s/ *(.*//'); out_ready random (seed 1); X/Z: two runs with different initial values, and four-state simulation of each set's first 1024 pixels"
failed=0 passed=0

# setup SET METHOD FRAC_BITS OUT: the set-up CSV from the checker.
setup() {
  local rc=0
  "$checker" setup --vectors "$vectors/$1.json" --method "$2" --fixed "$int_bits.$3" > "$4" 2> "$tmp/setup.err" || rc=$?
  if [ "$rc" -ne 0 ]; then
    bad "$checker setup --vectors $vectors/$1.json --method $2 --fixed $int_bits.$3 exited with $rc: $(head -n 1 "$tmp/setup.err")"
  fi
}

for set in "${sets[@]}"; do
  label=$(printf '%-8s' "$set")
  tb_extra=()
  case $mutant in
    '')
      setup "$set" "$method" "$frac_bits" "$tmp/setup.csv"
      if [ -n "$own" ]; then
        # Yours against the rounded set-up, case by case and column by column.
        compared=$(awk -F, '
          FNR == 1 { for (i = 1; i <= NF; i++) col[FILENAME, $i] = i; next }
          { sub(/\r$/, "") }
          FILENAME == ARGV[1] { ref[$col[ARGV[1], "case"]] = $0; order[++nref] = $col[ARGV[1], "case"]; next }
          { mine[$col[ARGV[2], "case"]] = $0 }
          END {
            split("n p0 dp t0 ds q0 dq0 d2q", names, " ")
            for (k = 1; k <= nref; k++) {
              id = order[k]
              if (!(id in mine)) { print "missing " id; exit }
              split(ref[id], a, ","); split(mine[id], b, ",")
              d = 0
              for (j = 1; j <= 8; j++) {
                if (!((ARGV[2], names[j]) in col)) { print "column " names[j]; exit }
                x = b[col[ARGV[2], names[j]]] - a[col[ARGV[1], names[j]]]
                if (x < 0) x = -x
                if (x > 0) d = 1
                if (x > worst) worst = x
              }
              differ += d
            }
            printf "ok %d %d %.0f\n", differ, nref, worst
          }' "$tmp/setup.csv" "$own/$set-$method-setup.csv")
        case $compared in
          missing*) bad "$own/$set-$method-setup.csv has no case ${compared#missing }" ;;
          column*) bad "$own/$set-$method-setup.csv has no column ${compared#column } (the header is case,n,p0,dp,t0,ds,q0,dq0,d2q)" ;;
        esac
        set -- $compared
        if [ "$2" -eq 0 ]; then
          printf '  %-8s your set-up: every case equals the rounded set-up\n' "$set"
        else
          printf '  %-8s your set-up: %s of %s cases differ from the rounded set-up (by up to %s × 2^-%s): the theorems do not cover them\n' \
            "$set" "$2" "$3" "$4" "$frac_bits"
        fi
        cp "$own/$set-$method-setup.csv" "$tmp/setup.csv"
      fi ;;
    truncated-setup|eps-n1)
      # The set-up at F + 8 bits (phong-approx setup takes F <= 48), brought to F by tb.
      extra=8
      if [ $((frac_bits + extra)) -gt 48 ]; then extra=$((48 - frac_bits)); fi
      [ "$extra" -ge 1 ] || bad "--mutant $mutant needs the set-up at more than F = $frac_bits bits (phong-approx setup takes at most 48)"
      [ $((width + extra)) -le 63 ] || bad "--mutant $mutant needs M + F + $extra <= 63"
      setup "$set" "$method" $((frac_bits + extra)) "$tmp/setup.csv"
      tb_extra=(--extra-bits "$extra")
      if [ "$mutant" = truncated-setup ]; then
        tb_extra+=(--truncate)
      else
        setup "$set" euler $((frac_bits + extra)) "$tmp/euler-setup.csv"
        tb_extra+=(--eps-n1 "$tmp/euler-setup.csv")
      fi ;;
  esac
  if [ -n "$results" ]; then cp "$tmp/setup.csv" "$results/$set-$method-setup.csv"; fi

  # Two runs: the same stimulus, different random initial values.
  verdict=
  for run in 1 2; do
    rc=0
    "$tmp/obj/tb" "$vectors/$set-inputs.csv" "$tmp/setup.csv" "$tmp/r$run.csv" --trace "$tmp/t$run.csv" ${tb_extra[@]+"${tb_extra[@]}"} \
      "+verilator+seed+$((run * 11))" +verilator+rand+reset+2 > "$tmp/tb.out" 2> "$tmp/tb.err" || rc=$?
    case $rc in
      0) ;;
      1) verdict=$(head -n 1 "$tmp/tb.err" | sed 's/^tb: //'); break ;;
      2)
        echo "run.sh: $set: $(head -n 1 "$tmp/tb.err" | sed "s/^tb: //; s|$tmp/||g")" >&2
        exit 2 ;;
      *)
        echo "run.sh: $set: the testbench exited with $rc: $(head -n 1 "$tmp/tb.err" | sed "s/^tb: //; s|$tmp/||g")" >&2
        exit 2 ;;
    esac
  done
  if [ -n "$verdict" ]; then
    printf '  %s FAIL: %s\n' "$label" "$verdict"
    failed=$((failed + 1))
    continue
  fi
  if ! cmp -s "$tmp/t1.csv" "$tmp/t2.csv"; then
    # The first case and signal that differ.
    # (paste writes a file, not a pipe: awk stops at the first difference, and
    # a writer still writing would die of SIGPIPE under pipefail.)
    paste -d, "$tmp/t1.csv" "$tmp/t2.csv" > "$tmp/t12.csv"
    diff_at=$(awk -F, 'NR == 1 { next }
      { for (i = 2; i <= 5; i++) if ($i != $(i + 5)) { split("- in_ready out_valid out_value out_last", s, " ");
        print $1 " (" s[i] ")"; exit } }' "$tmp/t12.csv")
    echo "run.sh: $set: X or Z reaches the outputs: case $diff_at differs between two runs with different random initial values (an unreset register or an X/Z value that reaches the output)" >&2
    exit 2
  fi
  # Four states: the set's first spans, up to 1024 pixels, from the set-up as
  # published (a --mutant's changes are the testbench's).
  if [ -n "$mutant" ]; then setup "$set" "$method" "$frac_bits" "$tmp/plain-setup.csv"; else cp "$tmp/setup.csv" "$tmp/plain-setup.csv"; fi
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    total < 1024 { print $c["case"], $c["n"], $c["p0"], $c["dp"], $c["t0"], $c["ds"], $c["q0"], $c["dq0"], $c["d2q"]; total += $c["n"] + 1 }' \
    "$tmp/plain-setup.csv" > "$tmp/stimulus.txt"
  vvp -n "$tmp/xz" "+stimulus=$tmp/stimulus.txt" > "$tmp/xz.out" 2>&1 || true
  if ! grep -q '^xz: ok: ' "$tmp/xz.out"; then
    echo "run.sh: $set: X or Z on the outputs in four-state simulation (iverilog): $(grep -m 1 '^xz: ' "$tmp/xz.out" | sed 's/^xz: //' || head -n 1 "$tmp/xz.out")" >&2
    exit 2
  fi
  if [ -n "$results" ]; then cp "$tmp/r1.csv" "$results/$set-$method.csv"; fi
  # The unit's own pace: out_ready always high, no idle cycles.
  "$tmp/obj/tb" "$vectors/$set-inputs.csv" "$tmp/setup.csv" "$tmp/r3.csv" ${tb_extra[@]+"${tb_extra[@]}"} --ready-percent 100 --no-gaps \
    --stats > /dev/null 2> "$tmp/stats" || true
  pace=$(sed -n 's/^tb: .* (\([0-9.]*\) cycles a pixel); pixel 0 valid \([0-9]*\) to \([0-9]*\) cycles.*/\1 cycles a pixel, pixel 0 after \2-\3 cycles/p' "$tmp/stats")
  pace=$(echo "$pace" | sed -E 's/after ([0-9]+)-\1 /after \1 /; s/after 1 cycles/after 1 cycle/')

  rc=0
  "$checker" check --vectors "$vectors/$set.json" --results "$tmp/r1.csv" --method "$method" \
    --profile "fixed:$int_bits.$frac_bits" --precision f64 > "$tmp/out" 2> "$tmp/err" || rc=$?
  if [ "$rc" -eq 0 ]; then
    printf '  %s pass: %s (unit: %s)\n' "$label" "$(grep -m 1 '^overall: ' "$tmp/out" | sed 's/^overall: //')" "$pace"
    passed=$((passed + 1))
  else
    printf '  %s FAIL: %s\n' "$label" "$(head -n 1 "$tmp/err" | sed "s/^phong-approx: //; s|$tmp/r1.csv|results.csv|")"
    grep -m 1 '^overall: ' "$tmp/out" | sed 's/^/      /' || true
    grep -m 1 '^worst case ' "$tmp/out" | cut -c 1-300 | sed 's/^/      /' || true
    failed=$((failed + 1))
  fi
done

if [ "$failed" -gt 0 ]; then
  echo "phong hdl: $failed of $((failed + passed)) sets FAIL ($method at $int_bits.$frac_bits)"
  exit 1
fi
if [ "$passed" -eq 1 ]; then summary="the set passes"; else summary="all $passed sets pass"; fi
echo "phong hdl: $summary ($method at $int_bits.$frac_bits, fixed:$int_bits.$frac_bits profile)"
