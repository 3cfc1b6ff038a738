#!/usr/bin/env bash
# SPDX-License-Identifier: MIT OR Apache-2.0
#
# Tests your C shading code on phong-approx's published vectors.
#
#   harness/c/run.sh YOUR_SOURCE.c [CHECKER] [--method M] [--precision f32|f64]
#                    [--form any|recurrence|closed] [--specular] [-- CHECK_OPTIONS...]
#
# YOUR_SOURCE.c holds your shading function and a main that calls pk_main
# (harness/c/phong_kit.h; harness/c/example_corrected_euler.c is one). It is built
# twice with phong_kit.c, found next to this script:
#   plain: -O2 -std=c99 -ffp-contract=off
#   fused: -O2 -std=c99 -ffp-contract=fast, and -mfma on x86-64 (where GCC fuses
#          only when FMA instructions are enabled)
# Each build shades every published set (typical, edge, paper) and
# `CHECKER check --vectors SET.json --results R.csv --method M --precision P` judges
# it, by its default profile (ieee: any order of operations, FMA, reciprocals).
# One line per set and build; the exit code is 0 if all pass, 1 if any fails, 2 for
# bad arguments, missing files or a build that does not compile.
#
#   CHECKER          the phong-approx binary (default: phong-approx on PATH,
#                    from `cargo install --path .` in the phong-approx repository)
#   --method M       the method your code implements (default corrected-euler)
#   --precision P    f32 (default) or f64: the shading function pk_main runs, and
#                    the checker's --precision
#   --form F         the form your code computes, for the profile's bound (check
#                    --form): any (default), recurrence or closed; a closed-form
#                    euler or corrected-euler is judged by the closed form's own bound
#   --specular       also check the specular part (pk_main --specular, check
#                    --specular) on the sets that have specular cases
#   -- OPTIONS       more options for `check`, e.g. `-- --profile reference`
#
# Environment: PHONG_KIT_VECTORS (the folder of SET.json and SET-inputs.csv;
# default: vectors/ of the repository this script is in), CC (default cc), CFLAGS
# (added to both builds' flags), LDLIBS (default -lm), PHONG_KIT_RESULTS (a folder
# to keep the results CSVs in, as SET-BUILD[-specular].csv).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
usage() {
  echo "usage: run.sh YOUR_SOURCE.c [CHECKER] [--method M] [--precision f32|f64] [--form any|recurrence|closed] [--specular] [-- CHECK_OPTIONS...]"
}
bad() { echo "run.sh: $*" >&2; exit 2; }

src= checker= method=corrected-euler precision=f32 form=any specular=0
check_extra=()
while [ $# -gt 0 ]; do
  case $1 in
    --method) [ $# -ge 2 ] || bad "--method needs a method name"; method=$2; shift 2 ;;
    --method=*) method=${1#*=}; shift ;;
    --precision) [ $# -ge 2 ] || bad "--precision needs f32 or f64"; precision=$2; shift 2 ;;
    --precision=*) precision=${1#*=}; shift ;;
    --form) [ $# -ge 2 ] || bad "--form needs any, recurrence or closed"; form=$2; shift 2 ;;
    --form=*) form=${1#*=}; shift ;;
    --specular) specular=1; shift ;;
    -h|--help) usage; exit 0 ;;
    --) shift; check_extra=("$@"); break ;;
    -*) usage >&2; bad "unknown option $1" ;;
    *)
      if [ -z "$src" ]; then src=$1
      elif [ -z "$checker" ]; then checker=$1
      else usage >&2; bad "one source file and one checker only (more sources: #include them)"
      fi
      shift ;;
  esac
done
[ -n "$src" ] || { usage >&2; exit 2; }
case $precision in f32|f64) ;; *) bad "--precision takes f32 or f64, not $precision" ;; esac
case $form in any|recurrence|closed) ;; *) bad "--form takes any, recurrence or closed, not $form" ;; esac
[ -f "$src" ] || bad "no such source file: $src"
[ -f "$here/phong_kit.c" ] && [ -f "$here/phong_kit.h" ] || bad "phong_kit.c and phong_kit.h are not next to run.sh ($here)"

if [ -z "$checker" ]; then
  checker=$(command -v phong-approx) ||
    bad "phong-approx is not on PATH: run \`cargo install --path .\` in the phong-approx repository, or give the checker's path after the source file"
elif [[ $checker != */* ]]; then
  checker=$(command -v "$checker") || bad "no checker $checker on PATH"
fi
[ -x "$checker" ] || bad "the checker $checker is not an executable file"

vectors=${PHONG_KIT_VECTORS:-$here/../../vectors}
sets=(typical edge paper)
for set in "${sets[@]}"; do
  for f in "$set.json" "$set-inputs.csv"; do
    [ -f "$vectors/$f" ] || bad "no $vectors/$f (set PHONG_KIT_VECTORS to the folder of the vector files)"
  done
done
results=${PHONG_KIT_RESULTS:-}
if [ -n "$results" ]; then mkdir -p "$results"; fi

cc=${CC:-cc}
read -r -a extra <<< "${CFLAGS:-}"
read -r -a libs <<< "${LDLIBS--lm}"
plain_flags=(-O2 -std=c99 -ffp-contract=off)
fused_flags=(-O2 -std=c99 -ffp-contract=fast)
target=$("$cc" -dumpmachine 2>/dev/null || uname -m)
case $target in
  x86_64*|amd64*)
    if [ -r /proc/cpuinfo ] && ! grep -qw fma /proc/cpuinfo; then
      echo "run.sh: this CPU has no FMA instructions: the fused build is contracted without -mfma (GCC then fuses nothing)" >&2
    else
      fused_flags+=(-mfma)
    fi ;;
esac

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM

builds=(plain fused)
for build in "${builds[@]}"; do
  if [ "$build" = plain ]; then flags=("${plain_flags[@]}"); else flags=("${fused_flags[@]}"); fi
  if ! "$cc" "${flags[@]}" ${extra[@]+"${extra[@]}"} -I"$here" -o "$tmp/$build" \
      "$src" "$here/phong_kit.c" ${libs[@]+"${libs[@]}"}; then
    bad "building $src ($build: $cc ${flags[*]} ${extra[*]-}) failed"
  fi
done

echo "phong_kit: $src as $method in $precision, checked by $checker ($("$checker" --version 2>/dev/null || echo "version unknown"))"
echo "  plain: ${plain_flags[*]} ${extra[*]-}"
echo "  fused: ${fused_flags[*]} ${extra[*]-}"
failed=0 passed=0

# check_one SET BUILD PART: runs the build on the set and checks its results.
check_one() {
  local set=$1 build=$2 part=$3 label rc suffix=
  local opts=(--precision "$precision") copts=()
  if [ "$part" = specular ]; then opts+=(--specular); copts+=(--specular); suffix=-specular; fi
  label=$(printf '%-8s %-5s%s' "$set" "$build" "${suffix/-/ }")
  rc=0
  "$tmp/$build" "${opts[@]}" "$vectors/$set-inputs.csv" > "$tmp/r.csv" 2> "$tmp/err" || rc=$?
  if [ "$rc" -ne 0 ]; then
    printf '  %s FAIL: the program exited with %s: %s\n' "$label" "$rc" "$(head -n 1 "$tmp/err" | sed "s|$tmp/||")"
    failed=$((failed + 1))
    return
  fi
  if [ -n "$results" ]; then
    cp "$tmp/r.csv" "$results/$set-$build$suffix.csv"
  fi
  if [ "$part" = specular ] && [ "$(wc -l < "$tmp/r.csv")" -le 1 ]; then
    printf '  %s (no specular cases)\n' "$label"
    return
  fi
  rc=0
  "$checker" check --vectors "$vectors/$set.json" --results "$tmp/r.csv" --method "$method" \
    --precision "$precision" --form "$form" ${copts[@]+"${copts[@]}"} ${check_extra[@]+"${check_extra[@]}"} \
    > "$tmp/out" 2> "$tmp/err" || rc=$?
  if [ "$rc" -eq 0 ]; then
    printf '  %s pass: %s\n' "$label" "$(grep -m 1 '^overall: ' "$tmp/out" | sed 's/^overall: //')"
    passed=$((passed + 1))
  else
    printf '  %s FAIL: %s\n' "$label" "$(head -n 1 "$tmp/err" | sed 's/^phong-approx: //')"
    grep -m 1 '^overall: ' "$tmp/out" | sed 's/^/      /' || true
    grep -m 1 '^worst case ' "$tmp/out" | cut -c 1-300 | sed 's/^/      /' || true
    failed=$((failed + 1))
  fi
}

for set in "${sets[@]}"; do
  for build in "${builds[@]}"; do
    check_one "$set" "$build" diffuse
    if [ "$specular" -eq 1 ]; then check_one "$set" "$build" specular; fi
  done
done

if [ "$failed" -gt 0 ]; then
  echo "phong_kit: $failed of $((failed + passed)) runs FAIL ($method, $precision)"
  exit 1
fi
echo "phong_kit: all $passed runs pass ($method, $precision; ${#sets[@]} sets, plain and fused)"
