#!/usr/bin/env bash
# Instruction counts per pixel for every f32 kernel, with valgrind's callgrind:
# repeatable for the same binary whatever else the machine is doing. Then the same
# for every method of benches/related.rs on one triangle with legs S (default 8, the
# paper's polygon size), with the stages of the per-row set-ups.
#   bash benches/callgrind.sh [N] [REPS] [S]
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-512}
reps=${2:-2000}
s=${3:-8}
command -v valgrind >/dev/null || { echo "valgrind is needed (apt-get install valgrind)" >&2; exit 2; }
cargo build --release --example kernel_counts --example row_counts -q
bin=target/release/examples/kernel_counts
count() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" "$1" "$n" "$2" 2>&1 \
    | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
base=$(count none "$reps")
echo "| kernel | instructions per pixel (f32, n = $n, set-up included) |"
echo "|---|---:|"
for k in gouraud_serial gouraud_fast euler_fast corrected_euler_serial corrected_euler_fast duff_serial phong_fast phong_rsqrt_simd symmetric_phong_fast; do
  c=$(count "$k" "$reps")
  python3 -c "print(f'| $k | {($c - $base) / ($reps * ($n + 1)):.2f} |')"
done

# One triangle with legs S: instructions per triangle and per pixel, set-up included.
tri=target/release/examples/row_counts
treps=$((reps * 10))
tcount() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$tri" "$1" "$s" "$treps" 2>&1 \
    | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
tbase=$(tcount none)
pixels=$((s * (s + 1) / 2))
echo
echo "| method (S = $s, $pixels pixels) | instructions per triangle | per pixel |"
echo "|---|---:|---:|"
for m in $("$tri" --list); do
  c=$(tcount "$m")
  python3 -c "t = ($c - $tbase) / $treps; print(f'| $m | {t:.0f} | {t / $pixels:.1f} |')"
done