#!/usr/bin/env bash
# Instruction counts per pixel for every f32 kernel, with valgrind's callgrind:
# repeatable for the same binary whatever else the machine is doing.
#   bash benches/callgrind.sh [N] [REPS]
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-512}
reps=${2:-2000}
command -v valgrind >/dev/null || { echo "valgrind is needed (apt-get install valgrind)" >&2; exit 2; }
cargo build --release --example kernel_counts -q
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
