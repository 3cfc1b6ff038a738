#!/usr/bin/env bash
# Builds the fuzz targets with libFuzzer's coverage instrumentation on stable Rust
# (the flags cargo-fuzz passes with `--sanitizer none`; no nightly needed) and runs
# each for SECONDS seconds (default 60), all at once, from its committed corpus in
# corpus/TARGET.
# Prints executions and crashes per target; exits non-zero if any target crashed.
#
#   bash fuzz/run.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")"
secs=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(results_parser vectors_parser span_args)
host=$(rustc -vV | sed -n 's/^host: //p')
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks"
# An explicit --target keeps these flags off build scripts and proc macros.
cargo build --release --quiet --target "$host" --bins
# The targets run at once (each on one thread; 3 on 2 cores) and report in order.
# One target: its corpus copied (the committed one stays as it is), libFuzzer's log in
# $2, its exit status in $2.rc.
fuzz_one() {
  local t=$1 log=$2 work
  work=$(mktemp -d)
  cp -r "corpus/$t/." "$work/" 2>/dev/null || true
  local rc=0
  "target/$host/release/$t" "$work" -max_total_time="$secs" -rss_limit_mb=2048 \
    -timeout=10 -artifact_prefix="artifacts/$t/" -print_final_stats=1 >"$log" 2>&1 || rc=$?
  echo "$rc" >"$log.rc"
  rm -rf "$work"
}
logs=$(mktemp -d)
for t in "${targets[@]}"; do
  mkdir -p "corpus/$t" "artifacts/$t"
  fuzz_one "$t" "$logs/$t" &
done
wait
status=0
for t in "${targets[@]}"; do
  log="$logs/$t"
  crashes=0
  if [ "$(cat "$log.rc" 2>/dev/null || echo 1)" != 0 ]; then
    crashes=1
    status=1
  fi
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  echo "fuzz $t: ${execs:-0} executions in ${secs} s, crashes: $crashes"
  if [ "$crashes" -ne 0 ]; then
    grep -E "panicked|ERROR|SUMMARY" "$log" | head -20
    ls "artifacts/$t"
  fi
done
rm -rf "$logs"
exit $status
