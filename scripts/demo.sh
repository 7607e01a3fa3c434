#!/usr/bin/env bash
# The README's main command: builds scanfilter, simulates the built-in demo
# scene (the paper's hall), runs the two-step filter over it and shows the
# result: a before/after picture and the accuracy table. Output in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
SCENE=${SCENE:-hall}
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p out
BIN=${BUILD_DIR:-build}/tools/scanfilter
"$BIN" simulate --scene "$SCENE" --seed 1 -o "out/$SCENE.scanlog.jsonl"
"$BIN" replay "out/$SCENE.scanlog.jsonl" --config config/filter.yaml \
  -o "out/$SCENE.filtered.scanlog.jsonl" --render "out/$SCENE-before-after.png"
echo
echo "Open out/$SCENE-before-after.png: every return on the left (coloured by truth),"
echo "the filter's labels on the right (kept = black, jump = red, misdetected = blue)."
