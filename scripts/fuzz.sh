#!/usr/bin/env bash
# Builds every libFuzzer target (fuzz/, clang, ASan + UBSan) and runs each for
# SECONDS seconds, one after the other (one job: the machine is shared).
# Exits non-zero if any target crashed, leaked, timed out or had a sanitizer
# report; the reproducer is kept under $FUZZ_BUILD_DIR/artifacts/<target>/.
#
#   bash scripts/fuzz.sh SECONDS [TARGET...]      (SECONDS 0: build only)
#   RUNS=1000000 bash scripts/fuzz.sh 1200 carmen_reader_fuzz   # a documented long run
#
# Seeds come from fuzz/corpus/<target>/ (never written to); what a run finds
# goes to $FUZZ_BUILD_DIR/corpus/<target>/ and is kept for the next run.
# A summary line per target: executions, coverage (libFuzzer's cov: and ft:).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD

if [ $# -lt 1 ] || ! [[ $1 =~ ^[0-9]+$ ]]; then
  echo "usage: bash scripts/fuzz.sh SECONDS [TARGET...]" >&2
  exit 2
fi
SECONDS_PER_TARGET=$1
shift
BUILD=${FUZZ_BUILD_DIR:-build-fuzz}
JOBS=${JOBS:-2}
# A target's single input may take this long before it counts as a hang (s).
PER_INPUT_TIMEOUT=${PER_INPUT_TIMEOUT:-10}
# Memory one fuzzing process may use before it counts as a crash (MB).
RSS_LIMIT_MB=${RSS_LIMIT_MB:-2048}

if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DSCANFILTER_FUZZ=ON -DSANITIZE=address,undefined \
    -DSCANFILTER_BUILD_TESTS=OFF -DSCANFILTER_BUILD_BENCH=OFF >/dev/null
fi
cmake --build "$BUILD" -j"$JOBS" --target fuzzers
if [ "$SECONDS_PER_TARGET" -eq 0 ]; then
  echo "fuzz.sh: built every fuzz target in $BUILD"
  exit 0
fi

if [ $# -gt 0 ]; then
  TARGETS=("$@")
else
  mapfile -t TARGETS < <(ls fuzz/corpus)
fi

failed=()
summary=()
for target in "${TARGETS[@]}"; do
  binary=$BUILD/fuzz/$target
  [ -x "$binary" ] || { echo "fuzz.sh: no fuzz target $target" >&2; exit 2; }
  work=$BUILD/corpus/$target
  artifacts=$BUILD/artifacts/$target
  log=$BUILD/logs/$target.log
  mkdir -p "$work" "$artifacts" "$(dirname "$log")"
  runs=()
  [ -n "${RUNS:-}" ] && runs=(-runs="$RUNS")
  echo "fuzz.sh: $target for ${SECONDS_PER_TARGET} s${RUNS:+ or $RUNS runs}"
  status=0
  # halt_on_error and abort: a UBSan report ends the run as a crash would.
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:abort_on_error=1 \
  ASAN_OPTIONS=abort_on_error=1 \
    "$binary" -max_total_time="$SECONDS_PER_TARGET" "${runs[@]}" -timeout="$PER_INPUT_TIMEOUT" \
      -rss_limit_mb="$RSS_LIMIT_MB" -print_final_stats=1 -artifact_prefix="$artifacts/" \
      "$work" "$ROOT/fuzz/corpus/$target" >"$log" 2>&1 || status=$?
  log_text=$(cat "$log")
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' <<<"$log_text" | tail -1)
  last_status=$(grep -E '^#[0-9]+' <<<"$log_text" | tail -1 || true)
  cov=$(grep -oE 'cov: [0-9]+' <<<"$last_status" | tail -1 || true)
  ft=$(grep -oE 'ft: [0-9]+' <<<"$last_status" | tail -1 || true)
  reported=$(grep -E 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|SUMMARY: ' <<<"$log_text" | head -3 || true)
  if [ "$status" -ne 0 ] || [ -n "$reported" ]; then
    failed+=("$target")
    echo "fuzz.sh: $target FAILED (exit $status); log $log; reproducer in $artifacts/" >&2
    grep -E 'ERROR:|runtime error:|SUMMARY:|terminate called|what\(\):' <<<"$log_text" | head -5 >&2 || true
    summary+=("$target: FAILED executions=${execs:-?} ${cov:-} ${ft:-}")
  else
    summary+=("$target: ok executions=${execs:-?} ${cov:-} ${ft:-}")
  fi
done

echo "fuzz.sh summary (${SECONDS_PER_TARGET} s per target):"
printf '  %s\n' "${summary[@]}"
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: ${#failed[@]} target(s) failed: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz.sh: ${#TARGETS[@]} target(s), no crash"
