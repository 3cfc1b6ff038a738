#!/usr/bin/env bash
# Builds the C harness twice — plain, and with fused multiply-adds
# (`-mfma -ffp-contract=fast`: on x86-64 GCC fuses only when FMA instructions are
# enabled) — runs it on every published set for the paper's methods, and checks the
# results with `phong-approx check`: the plain build under the reference profile and
# under the default ieee profile, the fused build under ieee, for every method (each
# has an ieee bound: proved for gouraud and corrected-euler, derived for euler, phong
# and duff). The two builds must differ somewhere.
set -euo pipefail
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cc -O2 -std=c99 -Wall -Wextra -Werror -o "$tmp/plain" harness/c/harness.c -lm
cc -O2 -std=c99 -Wall -Wextra -Werror -mfma -ffp-contract=fast -o "$tmp/fused" harness/c/harness.c -lm
bin=${PHONG_APPROX_BIN:-target/release/phong-approx}
# exact_input.h rounds each exact fraction once: its floats and doubles are the
# vector files' nearest-f32 and nearest-f64 forms, bit for bit.
for set in typical edge paper; do
  "$tmp/plain" inputs < "vectors/$set-inputs.csv" > "$tmp/inputs.csv"
  python3 - "vectors/$set.json" "$tmp/inputs.csv" <<'PY'
import csv, json, struct, sys
# A shortest round-trip f32 decimal, to its f32 (through the double, which is far
# closer to it than half an f32 ulp, so the second rounding cannot move it).
f32 = lambda s: struct.unpack("f", struct.pack("f", float(s)))[0]
cases = {c["id"]: c for c in json.load(open(sys.argv[1]))["cases"]}
bad = 0
for row in csv.DictReader(open(sys.argv[2])):
    c, j = cases[row["case"]], int(row["component"])
    v = [c["na"], c["nb"], c["l"]][j // 3]
    want32, want64 = f32(v["f32"][j % 3]), float(v["f64"][j % 3])
    got32, got64 = float.fromhex(row["f32"]), float.fromhex(row["f64"])
    if got32 != want32 or got64 != want64:
        bad += 1
        print(f"{row['case']} component {j}: {got32!r}/{got64!r}, want {want32!r}/{want64!r}")
sys.exit(1 if bad else 0)
PY
done
echo "  exact_input.h: every input rounds to the vector files' f32 and f64"
differ=0
for set in typical edge paper; do
  for m in gouraud euler corrected-euler phong duff; do
    "$tmp/plain" "$m" < "vectors/$set-inputs.csv" > "$tmp/plain.csv"
    "$bin" check --vectors "vectors/$set.json" --results "$tmp/plain.csv" --method "$m" \
      --profile reference > "$tmp/out" || { cat "$tmp/out"; echo "plain $set $m failed" >&2; exit 1; }
    "$bin" check --vectors "vectors/$set.json" --results "$tmp/plain.csv" --method "$m" \
      > "$tmp/out" || { cat "$tmp/out"; echo "plain $set $m failed under ieee" >&2; exit 1; }
    "$tmp/fused" "$m" < "vectors/$set-inputs.csv" > "$tmp/fused.csv"
    "$bin" check --vectors "vectors/$set.json" --results "$tmp/fused.csv" --method "$m" \
      --profile ieee > "$tmp/out" || { cat "$tmp/out"; echo "fused $set $m failed" >&2; exit 1; }
    cmp -s "$tmp/plain.csv" "$tmp/fused.csv" || differ=$((differ + 1))
    echo "  $set $m: pass"
  done
done
if [ "$differ" -eq 0 ]; then
  echo "the fused build gave the same results as the plain one: no FMA was used" >&2
  exit 1
fi
echo "C harness: every set and method passes; the fused build differs on $differ of 15 set-method pairs"
