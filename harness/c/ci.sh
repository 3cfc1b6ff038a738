#!/usr/bin/env bash
# SPDX-License-Identifier: MIT OR Apache-2.0
#
# The C stage of this repository's CI:
#
#   harness/c/ci.sh [CHECKER]     (default: $PHONG_APPROX_BIN, else target/release/phong-approx)
#
# 1. Builds methods.c (gouraud, euler, corrected-euler, phong, duff and
#    squared-corrected-euler in float and
#    double, against phong_kit.h) twice — plain, and with fused multiply-adds
#    (-ffp-contract=fast, with -mfma on x86-64, where GCC fuses only when FMA
#    instructions are enabled) — with -Wall -Wextra -Werror.
# 2. Checks that phong_kit reads every input as the vector file's f32 and f64 forms,
#    bit for bit (methods inputs, compared with SET.json); that bad input (9 kinds) is
#    one line on stderr and exit 2; and, where /dev/full exists, that a write that
#    fails (the results mid-run and at the last flush, in f32 and f64, the usage,
#    methods inputs) exits non-zero with one line saying "No space left on device".
# 3. For f32 and f64, every published set and every method: the plain build under
#    the reference profile and the default ieee profile, the fused build under ieee
#    (each method has an ieee bound: proved for gouraud, euler and corrected-euler,
#    composed from proved theorems for phong and duff, from its operation graph for
#    the squared method); the same for the specular part of the sets that have one.
#    The fused f32 build must differ from the plain one somewhere. A build with a
#    planted bug (the squared method's sign dropped) must fail a set.
# 4. The user's route: run.sh on example_corrected_euler.c must pass (and declared
#    --form recurrence too, but not --form closed), and on a copy
#    with the first step corrected by ε/(n+1) instead of ε/n (made here, in a
#    temporary folder) must fail.
# 5. The kit's version and its old API: pk_version() is PK_VERSION (tests/version.c),
#    which heads CHANGELOG.md; tests/old_client.c, written against kit 0.1.0's
#    exact_input.h as harness.c used it, builds against today's deprecated shim with
#    -std=c99 -Wall -Wextra -Werror -Wno-deprecated-declarations, exits 2 on a bad
#    fraction, and prints the same inputs (%a) and corrected-Euler values as methods.c
#    through phong_kit, bit for bit, on every set; without -Wno-deprecated-declarations
#    it and a file using each of the shim's functions do not compile, each function
#    reported deprecated (the entry points naming their phong_kit replacement).
#
# PHONG_KIT_VECTORS overrides the folder of the vector files, as for run.sh.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bin=${1:-${PHONG_APPROX_BIN:-$here/../../target/release/phong-approx}}
[ -x "$bin" ] || { echo "ci.sh: no checker at $bin (build it: cargo build --release)" >&2; exit 2; }
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
vectors=${PHONG_KIT_VECTORS:-$here/../../vectors}
sets=(typical edge paper)
methods=(gouraud euler corrected-euler phong duff squared-corrected-euler)

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM

# 1. methods.c, plain and fused.
warn=(-Wall -Wextra -Werror)
fused=(-ffp-contract=fast)
case $(cc -dumpmachine 2>/dev/null || uname -m) in x86_64*|amd64*) fused+=(-mfma) ;; esac
cc -O2 -std=c99 -ffp-contract=off "${warn[@]}" -o "$tmp/plain" "$here/methods.c" "$here/phong_kit.c" -lm
cc -O2 -std=c99 "${fused[@]}" "${warn[@]}" -o "$tmp/fused" "$here/methods.c" "$here/phong_kit.c" -lm

# 2. phong_kit's floats and doubles are the vector files' nearest-f32 and nearest-f64
# forms, bit for bit.
for set in "${sets[@]}"; do
  "$tmp/plain" inputs "$vectors/$set-inputs.csv" > "$tmp/inputs.csv"
  python3 - "$vectors/$set.json" "$tmp/inputs.csv" <<'PY'
import csv, json, struct, sys
# A shortest round-trip f32 decimal, to its f32 (through the double, which is far
# closer to it than half an f32 ulp, so the second rounding cannot move it).
f32 = lambda s: struct.unpack("f", struct.pack("f", float(s)))[0]
cases = {c["id"]: c for c in json.load(open(sys.argv[1]))["cases"]}
seen, bad = set(), 0
for row in csv.DictReader(open(sys.argv[2])):
    c = cases[row["case"]]
    name, axis = row["component"].split("_")
    v = c["specular"]["h"] if name == "h" else c[name]
    text = v[row["precision"]]["xyz".index(axis)]
    want = f32(text) if row["precision"] == "f32" else float(text)
    got = float.fromhex(row["value"])
    if got != want or str(got) != str(want):  # str: -0.0 is not 0.0
        bad += 1
        print(f"{row['case']} {row['component']} {row['precision']}: {got!r}, want {want!r}")
    seen.add((row["case"], row["component"], row["precision"]))
want = sum((12 if "specular" in c else 9) * 2 for c in cases.values())
if len(seen) != want:
    bad += 1
    print(f"{len(seen)} inputs read, the vector file has {want}")
sys.exit(1 if bad else 0)
PY
done
echo "  phong_kit: every input is the vector files' f32 and f64, bit for bit"

# Bad input: one line on stderr and exit 2, never a crash or a partial silent run.
good="$vectors/paper-inputs.csv"
head -n 1 "$good" > "$tmp/header.csv"
row=$(sed -n 2p "$good")
bad_input() { # name, file
  local rc=0
  "$tmp/plain" corrected-euler "$2" > "$tmp/bad.out" 2> "$tmp/bad.err" || rc=$?
  if [ "$rc" -ne 2 ] || [ "$(wc -l < "$tmp/bad.err")" -ne 1 ]; then
    echo "phong_kit on $1: exit $rc, stderr:" >&2; cat "$tmp/bad.err" >&2; exit 1
  fi
}
bad_input "a missing file" "$tmp/no-such-file.csv"
: > "$tmp/empty.csv"; bad_input "an empty file" "$tmp/empty.csv"
echo "case,n,na_x" > "$tmp/old.csv"; bad_input "a header without the hex columns" "$tmp/old.csv"
{ cat "$tmp/header.csv"; echo "$row" | awk -F, 'BEGIN{OFS=","} {$2=0; print}'; } > "$tmp/n0.csv"
bad_input "n = 0" "$tmp/n0.csv"
{ cat "$tmp/header.csv"; echo "$row" | awk -F, 'BEGIN{OFS=","} {$2=2000000; print}'; } > "$tmp/nbig.csv"
bad_input "n past the kit's cap" "$tmp/nbig.csv"
{ cat "$tmp/header.csv"; echo "$row" | awk -F, 'BEGIN{OFS=","} {$16="0x7fc00000"; print}'; } > "$tmp/nan.csv"
bad_input "a NaN bit pattern" "$tmp/nan.csv"
{ cat "$tmp/header.csv"; echo "$row" | awk -F, 'BEGIN{OFS=","} {$16="0x3f8"; print}'; } > "$tmp/short.csv"
bad_input "a short hex cell" "$tmp/short.csv"
{ cat "$tmp/header.csv"; echo "$row" | cut -d, -f1-10; } > "$tmp/cut.csv"
bad_input "a row with missing columns" "$tmp/cut.csv"
{ cat "$tmp/header.csv"; head -c 20000 /dev/zero | tr '\0' 'a'; echo; } > "$tmp/long.csv"
bad_input "a line past the kit's cap" "$tmp/long.csv"
echo "  phong_kit: bad input (9 kinds) is one line and exit 2"

# A write that fails says why, in one line: /dev/full is a full disk.
if [ -w /dev/full ]; then
  full() { # what, command...
    local what=$1 rc=0
    shift
    "$@" > /dev/full 2> "$tmp/full.err" || rc=$?
    if [ "$rc" -eq 0 ] || [ "$(wc -l < "$tmp/full.err")" -ne 1 ] ||
        ! grep -q 'No space left on device' "$tmp/full.err"; then
      echo "ci.sh: $what to /dev/full: exit $rc, stderr:" >&2; cat "$tmp/full.err" >&2; exit 1
    fi
  }
  { cat "$tmp/header.csv"; echo "$row" | awk -F, 'BEGIN{OFS=","} {$2=1; print}'; } > "$tmp/n1.csv"
  full "a set's results (failing mid-run)" "$tmp/plain" corrected-euler "$vectors/typical-inputs.csv"
  full "a set's f64 results" "$tmp/plain" phong --precision f64 "$vectors/typical-inputs.csv"
  full "two pixels' results (failing at the last flush)" "$tmp/plain" corrected-euler "$tmp/n1.csv"
  full "the usage" "$tmp/plain" corrected-euler --help
  full "methods inputs" "$tmp/plain" inputs "$vectors/typical-inputs.csv"
  echo "  phong_kit: a write to /dev/full (5 kinds) is one line, \"No space left on device\", and a non-zero exit"
else
  echo "  phong_kit: no writable /dev/full here: the write-failure checks are skipped"
fi

# 3. check BUILD PROFILE PRECISION SET METHOD [--specular]
check() {
  local build=$1 profile=$2 precision=$3 set=$4 method=$5 part=${6:-}
  if ! "$bin" check --vectors "$vectors/$set.json" --results "$tmp/$build.csv" --method "$method" \
      --precision "$precision" --profile "$profile" ${part:+"$part"} > "$tmp/out" 2>&1; then
    cat "$tmp/out"
    echo "$build $precision $set $method ${part:+specular }failed under $profile" >&2
    exit 1
  fi
}

differ=0 differ64=0
for precision in f32 f64; do
  for set in "${sets[@]}"; do
    spec=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "s") c = i; next }
                    $c != "" { n++ } END { print n + 0 }' "$vectors/$set-inputs.csv")
    for m in "${methods[@]}"; do
      parts=("")
      if [ "$spec" -gt 0 ]; then parts+=(--specular); fi
      for part in "${parts[@]}"; do
        "$tmp/plain" "$m" --precision "$precision" $part "$vectors/$set-inputs.csv" > "$tmp/plain.csv"
        "$tmp/fused" "$m" --precision "$precision" $part "$vectors/$set-inputs.csv" > "$tmp/fused.csv"
        check plain reference "$precision" "$set" "$m" $part
        check plain ieee "$precision" "$set" "$m" $part
        check fused ieee "$precision" "$set" "$m" $part
        if ! cmp -s "$tmp/plain.csv" "$tmp/fused.csv"; then
          if [ "$precision" = f32 ] && [ -z "$part" ]; then differ=$((differ + 1)); fi
          if [ "$precision" = f64 ] && [ -z "$part" ]; then differ64=$((differ64 + 1)); fi
        fi
      done
      echo "  $precision $set $m: pass${parts[1]:+ (and specular, $spec cases)}"
    done
  done
done
if [ "$differ" -eq 0 ]; then
  echo "the fused build gave the same f32 results as the plain one: no FMA was used" >&2
  exit 1
fi
pairs=$(( ${#methods[@]} * ${#sets[@]} ))
echo "  methods.c: every set and method passes in f32 and f64; the fused build differs on $differ of $pairs f32 and $differ64 of $pairs f64 set-method pairs"
# A planted bug: the squared method without its value's sign fails a set.
cc -O2 -std=c99 -ffp-contract=off -DPK_PLANT_SQUARED_NO_SIGN "${warn[@]}" -o "$tmp/planted" \
  "$here/methods.c" "$here/phong_kit.c" -lm
failed=0
for set in "${sets[@]}"; do
  "$tmp/planted" squared-corrected-euler "$vectors/$set-inputs.csv" > "$tmp/planted.csv"
  if ! "$bin" check --vectors "$vectors/$set.json" --results "$tmp/planted.csv" \
      --method squared-corrected-euler --precision f32 > /dev/null 2>&1; then
    failed=$((failed + 1))
  fi
done
if [ "$failed" -eq 0 ]; then
  echo "ci.sh: the squared method without its sign passed every set" >&2
  exit 1
fi
echo "  methods.c: the squared method without its sign fails $failed of ${#sets[@]} sets"

# 4. The user's route, as the README gives it.
CFLAGS="${warn[*]}" bash "$here/run.sh" "$here/example_corrected_euler.c" "$bin" --method corrected-euler
sed 's|t0 = dia - eps / nf;|t0 = dia - eps / (nf + 1);|' "$here/example_corrected_euler.c" > "$tmp/planted.c"
if cmp -s "$here/example_corrected_euler.c" "$tmp/planted.c"; then
  echo "ci.sh: could not plant ε/(n+1) in example_corrected_euler.c (its line changed?)" >&2
  exit 1
fi
rc=0
CFLAGS="${warn[*]}" bash "$here/run.sh" "$tmp/planted.c" "$bin" --method corrected-euler > "$tmp/out" || rc=$?
if [ "$rc" -ne 1 ] || grep -q ' pass: ' "$tmp/out"; then
  cat "$tmp/out"
  echo "ci.sh: run.sh let the planted ε/(n+1) through (exit $rc)" >&2
  exit 1
fi
echo "  run.sh: the planted ε/(n+1) fails every set and build ($(grep -c ' FAIL: ' "$tmp/out") of 6)"
# The declared form: the example is a recurrence, so it passes declared as one and
# fails declared closed (the closed form's bound does not grow with n; edge's n = 4096
# spans exceed it); an unknown form is bad input.
CFLAGS="${warn[*]}" bash "$here/run.sh" "$here/example_corrected_euler.c" "$bin" --form recurrence > "$tmp/out"
rc=0
CFLAGS="${warn[*]}" bash "$here/run.sh" "$here/example_corrected_euler.c" "$bin" --form closed > "$tmp/out" || rc=$?
if [ "$rc" -ne 1 ]; then
  cat "$tmp/out"
  echo "ci.sh: run.sh --form closed passed a recurrence (exit $rc)" >&2
  exit 1
fi
rc=0
bash "$here/run.sh" "$here/example_corrected_euler.c" "$bin" --form bogus 2> "$tmp/err" || rc=$?
[ "$rc" -eq 2 ] || { cat "$tmp/err"; echo "ci.sh: run.sh --form bogus exited $rc, not 2" >&2; exit 1; }
echo "  run.sh --form: the recurrence passes declared recurrence, fails declared closed ($(grep -c ' FAIL: ' "$tmp/out") of 6), an unknown form exits 2"

# 5. The kit's version, and kit 0.1.0's API through the deprecated exact_input.h.
cc -O2 -std=c99 "${warn[@]}" -I"$here" -o "$tmp/version" "$here/tests/version.c" "$here/phong_kit.c" -lm
version=$("$tmp/version") || { echo "ci.sh: pk_version() is not PK_VERSION" >&2; exit 1; }
first=$(grep -m 1 '^## ' "$here/CHANGELOG.md" || true)
if [ "${first%% *}" != "##" ] || [ "$(echo "$first" | cut -d' ' -f2)" != "[$version]" ]; then
  echo "ci.sh: harness/c/CHANGELOG.md does not begin with the section of PK_VERSION ($version)" >&2
  exit 1
fi
echo "  phong_kit $version: pk_version() is PK_VERSION, the first section of CHANGELOG.md"

old=(-O2 -std=c99 -ffp-contract=off "${warn[@]}" -I"$here")
cc "${old[@]}" -Wno-deprecated-declarations -o "$tmp/old_client" "$here/tests/old_client.c" \
  "$here/phong_kit.c" -lm
same() { # what, old output, new output
  if [ "$(wc -l < "$2")" -le 1 ] || ! cmp -s "$2" "$3"; then
    echo "ci.sh: old_client.c and methods.c differ on $1 (< old, > new):" >&2
    diff "$2" "$3" | head -n 10 >&2
    exit 1
  fi
}
for set in "${sets[@]}"; do
  "$tmp/old_client" inputs < "$vectors/$set-inputs.csv" > "$tmp/old.csv"
  "$tmp/plain" inputs "$vectors/$set-inputs.csv" > "$tmp/new.csv"
  sort -o "$tmp/old.csv" "$tmp/old.csv"
  sort -o "$tmp/new.csv" "$tmp/new.csv"
  same "$set's inputs" "$tmp/old.csv" "$tmp/new.csv"
  "$tmp/old_client" corrected-euler < "$vectors/$set-inputs.csv" > "$tmp/old.csv"
  "$tmp/plain" corrected-euler --precision f32 "$vectors/$set-inputs.csv" > "$tmp/new.csv"
  same "$set's corrected Euler" "$tmp/old.csv" "$tmp/new.csv"
done
{ cat "$tmp/header.csv"; echo "$row" | awk -F, 'BEGIN{OFS=","} {$3="1/0"; print}'; } > "$tmp/frac.csv"
rc=0
"$tmp/old_client" corrected-euler < "$tmp/frac.csv" > /dev/null 2> "$tmp/frac.err" || rc=$?
if [ "$rc" -ne 2 ] || ! grep -q 'not exact inputs' "$tmp/frac.err"; then
  echo "ci.sh: old_client.c on the fraction 1/0: exit $rc, stderr:" >&2; cat "$tmp/frac.err" >&2; exit 1
fi
echo "  exact_input.h (deprecated): old_client.c builds, refuses 1/0, and gives methods.c's inputs and corrected Euler bit for bit"

# Without -Wno-deprecated-declarations, -Werror stops every use of the shim (LC_ALL=C:
# the compiler's quotes are ASCII).
rc=0
LC_ALL=C cc "${old[@]}" -o "$tmp/old_strict" "$here/tests/old_client.c" "$here/phong_kit.c" -lm \
  2> "$tmp/strict.err" || rc=$?
if [ "$rc" -eq 0 ]; then
  echo "ci.sh: old_client.c compiles without -Wno-deprecated-declarations: exact_input.h is not marked deprecated" >&2
  exit 1
fi
for use in exact_input_f32:pk_run_f32 exact_input_f64:pk_run_f64 exact_input:pk_run_f32; do
  if ! grep -q "'${use%%:*}' is deprecated: .*${use#*:}" "$tmp/strict.err"; then
    echo "ci.sh: the strict build of old_client.c does not report ${use%%:*} as deprecated (with ${use#*:}):" >&2
    head -n 20 "$tmp/strict.err" >&2
    exit 1
  fi
done
names=$(sed -n 's/^static inline [^(]*[ *]\(exact_[a-z0-9_]*\)(.*{.*$/\1/p' "$here/exact_input.h" | sort -u)
{
  echo '#include "exact_input.h"'
  echo 'void (*const every_function[])(void) = {'
  for f in $names; do echo "    (void (*)(void))$f,"; done
  echo '};'
} > "$tmp/every.c"
cc "${old[@]}" -Wno-deprecated-declarations -c -o "$tmp/every.o" "$tmp/every.c"
rc=0
LC_ALL=C cc "${old[@]}" -c -o "$tmp/every.o" "$tmp/every.c" 2> "$tmp/every.err" || rc=$?
reported=$(grep -o "'exact_[a-z0-9_]*' is deprecated" "$tmp/every.err" | sort -u | wc -l)
if [ "$rc" -eq 0 ] || [ "$reported" -ne "$(echo "$names" | wc -w)" ] || [ "$reported" -lt 12 ]; then
  echo "ci.sh: $reported of exact_input.h's $(echo "$names" | wc -w) functions are reported deprecated (exit $rc):" >&2
  head -n 20 "$tmp/every.err" >&2
  exit 1
fi
echo "  exact_input.h (deprecated): old_client.c does not compile without -Wno-deprecated-declarations; all $reported of the shim's functions are reported deprecated"
echo "C harness: every set, method and precision passes; the example passes and its planted bug fails; the old API still builds and agrees"
