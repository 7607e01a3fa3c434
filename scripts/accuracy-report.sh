#!/usr/bin/env bash
# Regenerates every measured part of docs/accuracy.md: the two-step filter's
# own tables (the scenes' own sensors, the sensor presets, sensors near the
# presets), the comparison with the baselines (tables, P/R charts, frames
# figure, robustness) and the real-recording report (tables, maps, the
# multi-view consistency of every filter). Builds first. Takes about 15
# minutes on 2 cores.
#   bash scripts/accuracy-report.sh
# The generated blocks sit between `<!-- generated:NAME -->` and
# `<!-- end generated:NAME -->` in docs/accuracy.md; the prose around them is
# written by hand from these numbers.
set -euo pipefail
cd "$(dirname "$0")/.."
REAL=${REAL_DATA:-../shared/data/real}
# The real recordings are not in the repository (README, "Real recordings"):
# say so now, not after ten minutes of simulation.
for log in "$REAL"/carmen/{intel,freiburg-079,aces,csail}-corrected.log.gz "$REAL"/mines_urg04lx/exp{1,2}.dat; do
  [ -f "$log" ] || { echo "accuracy-report: $log: no such file; the real recordings go in $REAL" \
    "(README.md says where to get them; REAL_DATA=DIR for another folder)" >&2; exit 1; }
done
bash scripts/install-deps.sh
bash scripts/build.sh
BIN=${BUILD_DIR:-build}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

"$BIN/bench/accuracy_table" > "$WORK/table.md"
"$BIN/bench/accuracy_table" --sensor tof,triangulation > "$WORK/table-sensors.md"
"$BIN/bench/sensor_robustness" > "$WORK/sensor-robustness.md"
"$BIN/tools/scanfilter" bench-accuracy --config config/filter.yaml -o "$WORK/compare"
"$BIN/tools/scanfilter" report-real --config config/filter.yaml --literal-config config/filter-paper-literal.yaml \
  "$REAL"/carmen/*.log.gz "$REAL"/mines_urg04lx/*.dat -o "$WORK/real" --image-prefix images/

cp "$WORK"/compare/*.png "$WORK"/real/*.png docs/images/

# Replaces the block NAME of docs/accuracy.md with the file FILE.
splice() {
  local name=$1 file=$2
  grep -q "<!-- generated:$name -->" docs/accuracy.md || { echo "docs/accuracy.md: no block $name" >&2; exit 1; }
  awk -v name="$name" -v file="$file" '
    $0 == "<!-- generated:" name " -->" { print; while ((getline line < file) > 0) print line; skip = 1; next }
    $0 == "<!-- end generated:" name " -->" { skip = 0 }
    !skip { print }' docs/accuracy.md > "$WORK/accuracy.md"
  mv "$WORK/accuracy.md" docs/accuracy.md
}
splice table "$WORK/table.md"
splice table-sensors "$WORK/table-sensors.md"
splice sensor-robustness "$WORK/sensor-robustness.md"
splice comparison "$WORK/compare/accuracy-comparison.md"
splice real "$WORK/real/real-recordings.md"
splice real-consistency "$WORK/real/real-consistency.md"
echo "docs/accuracy.md and docs/images/ regenerated"
