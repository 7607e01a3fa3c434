#!/usr/bin/env bash
# Runs build/bench/pipeline_bench in a private network namespace (root), or on
# the loopback-only profile otherwise. Bounded: about 2,000 + 4 x 200 scans
# (twice that with --secure).
#
#   bench/run-pipeline-bench.sh [--secure] [pipeline_bench options]
#   --secure: the same measurements again, in the same run, with DDS Security
#             on every participant (a keystore made for the run with
#             deploy/security/make-keystore.sh), and a plain / secured table.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
BENCH_DOMAIN=42  # pipeline_bench's kDomain
SECURE_ARGS=()
if [ "${1:-}" = --secure ]; then
  shift
  KEYSTORE=$(mktemp -d)
  trap 'rm -rf "$KEYSTORE"' EXIT
  MAKE=(bash "$ROOT/deploy/security/make-keystore.sh" --domain "$BENCH_DOMAIN")
  "${MAKE[@]}" "$KEYSTORE" > /dev/null
  # The bench's own participants: the source/subscriber, and the bare-hop echo.
  "${MAKE[@]}" --add-enclave /scanfilter/bench_source --publish "posed_scan bench_ping" \
    --subscribe "labeled_scan bench_pong" "$KEYSTORE" > /dev/null
  "${MAKE[@]}" --add-enclave /scanfilter/bench_echo --publish "bench_pong" --subscribe "bench_ping" "$KEYSTORE" > /dev/null
  SECURE_ARGS=(--keystore "$KEYSTORE" --filter-config "$ROOT/config/filter.yaml")
fi
CMD=("$BUILD/bench/pipeline_bench" "$BUILD" "$ROOT/deploy/fastdds-loopback.xml" "${SECURE_ARGS[@]}" "$@")
if [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
  # Not exec: the keystore is removed when the bench ends.
  unshare -n bash -c 'ip link set lo up && exec "$@"' _ "${CMD[@]}"
  exit $?
fi
"${CMD[@]}"
