#!/usr/bin/env bash
# Configures and builds scanfilter (Release) into build/. Used by the two
# README commands; at most 2 parallel jobs (CI has 2 cores).
#   bash scripts/build.sh              everything (the tests, benchmarks, tools)
#   bash scripts/build.sh TARGET...    only those targets (the demo's programs);
#                                      a later full build reuses what they built
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
GENERATOR=()
command -v ninja >/dev/null && GENERATOR=(-G Ninja)
cmake -S . -B "$BUILD_DIR" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
TARGETS=()
[ $# -gt 0 ] && TARGETS=(--target "$@")
cmake --build "$BUILD_DIR" --parallel 2 "${TARGETS[@]}"
