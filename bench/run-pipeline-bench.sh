#!/usr/bin/env bash
# Runs build/bench/pipeline_bench in a private network namespace (root), or on
# the loopback-only profile otherwise. Bounded: about 2,000 + 4 x 200 scans.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
CMD=("$BUILD/bench/pipeline_bench" "$BUILD" "$ROOT/deploy/fastdds-loopback.xml" "$@")
if [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
  exec unshare -n bash -c 'ip link set lo up && exec "$@"' _ "${CMD[@]}"
fi
exec "${CMD[@]}"
