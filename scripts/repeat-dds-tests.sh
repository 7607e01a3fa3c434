#!/usr/bin/env bash
# Runs the DDS integration tests N times in a row (default 30) on an existing
# build and prints the count of failures per test: a flaky test shows here.
#
#   bash scripts/repeat-dds-tests.sh [N]      (after scripts/build.sh)
set -uo pipefail
cd "$(dirname "$0")/.."
N=${1:-30}
BUILD_DIR=${BUILD_DIR:-build}
declare -A failures=()
failed_runs=0
for run in $(seq 1 "$N"); do
  out=$(ctest --test-dir "$BUILD_DIR" -R '^dds_' --timeout 180 2>&1)
  failed=$(sed -n 's/^[[:space:]]*[0-9]* - \(dds_[a-z_]*\) (.*/\1/p' <<<"$out")
  if [ -n "$failed" ]; then
    failed_runs=$((failed_runs + 1))
    for t in $failed; do failures[$t]=$(( ${failures[$t]:-0} + 1 )); done
  fi
  summary=$(grep "tests passed" <<<"$out")
  echo "run $run/$N: $summary${failed:+ (failed: $(tr '\n' ' ' <<<"$failed"))}"
done
echo "runs with a failure: $failed_runs of $N"
for t in "${!failures[@]}"; do echo "  $t failed ${failures[$t]} times"; done
[ "$failed_runs" -eq 0 ]
