#!/usr/bin/env bash
# Starts the pipeline's processes (map_publisher, penetration_filter,
# jump_filter, scan_ingest) and a recorder of the labelled output, prints
# where the metrics and the output are, and stops them all by PID on Ctrl-C
# or when the ingest has published its whole source (the map publisher then
# saves the map).
#
#   deploy/run-pipeline.sh [--scene hall | --log FILE] [--rate recorded|max|FACTOR] [--out DIR] [--domain N]
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BIN="${BUILD_DIR:-$ROOT/build}"
SCENE=hall LOG="" RATE=recorded OUT="$ROOT/out" DOMAIN=0
while [ $# -gt 0 ]; do
  case "$1" in
    --scene) SCENE="$2"; shift 2 ;;
    --log) LOG="$2"; shift 2 ;;
    --rate) RATE="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --domain) DOMAIN="$2"; shift 2 ;;
    -h|--help) sed -n 2,8p "$0"; exit 0 ;;
    *) echo "unknown argument: $1 (see --help)" >&2; exit 2 ;;
  esac
done
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"  # absolute: the configs written below are read from $OUT
# The ingest's source, written as a config next to the output.
INGEST_CFG="$OUT/scan_ingest.yaml"
{
  echo "service: {domain_id: $DOMAIN, profiles_file: $ROOT/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:9471}"
  if [ -n "$LOG" ]; then
    echo "source: {kind: log, path: $(realpath "$LOG"), rate: $RATE}"
  else
    echo "source: {kind: simulator, scene: $SCENE, rate: $RATE}"
  fi
} > "$INGEST_CFG"

MAP_CFG="$OUT/map_publisher.yaml"
echo "service: {domain_id: $DOMAIN, profiles_file: $ROOT/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:9474}" > "$MAP_CFG"
echo "publishing: {save_path: $OUT/map}" >> "$MAP_CFG"

PIDS=()
stop_all() {
  for pid in "${PIDS[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${PIDS[@]}"; do wait "$pid" 2>/dev/null || true; done
}
trap 'stop_all; exit 130' INT TERM

"$BIN/services/map_publisher" --config "$MAP_CFG" > "$OUT/map_publisher.log" 2>&1 & PIDS+=($!)
"$BIN/services/penetration_filter" --domain "$DOMAIN" > "$OUT/penetration_filter.log" 2>&1 & PIDS+=($!)
"$BIN/services/jump_filter" --domain "$DOMAIN" > "$OUT/jump_filter.log" 2>&1 & PIDS+=($!)
"$BIN/tools/scan_recorder" --domain "$DOMAIN" --idle-exit 2 -o "$OUT/pipeline.labeled.scanlog.jsonl" \
  > "$OUT/scan_recorder.log" 2>&1 & RECORDER=$!
PIDS+=($RECORDER)

# Start the source only once every stage downstream is matched (each
# service's matched-endpoints gauge), so that no stage misses the first scans.
matched() {  # port topic: the service's matched readers on that topic's writer
  curl -s "http://127.0.0.1:$1/metrics" | grep '^scanfilter_dds_matched{' | grep 'endpoint="writer"' |
    grep -F "topic=\"$2\"" | awk '{print int($2)}'
}
for _ in $(seq 1 300); do
  [ "$(matched 9472 rt/jump_filtered_scan)" = 1 ] && [ "$(matched 9473 rt/labeled_scan)" = 1 ] && break
  sleep 0.1
done
"$BIN/services/scan_ingest" --config "$INGEST_CFG" > "$OUT/scan_ingest.log" 2>&1 & INGEST=$!
PIDS+=($INGEST)

echo "pipeline running on DDS domain $DOMAIN (localhost only); logs in $OUT/"
echo "metrics: http://127.0.0.1:9471/metrics (scan_ingest), :9472 (jump_filter), :9473 (penetration_filter), :9474 (map_publisher)"
echo "topics:  rt/posed_scan -> rt/jump_filtered_scan -> rt/labeled_scan and rt/scan_filtered (sensor_msgs/LaserScan) -> rt/map"
status=0
wait "$INGEST" || status=$?
wait "$RECORDER" || true  # it exits 2 s after the last scan arrived
stop_all
echo "scan_ingest exited with $status; labelled output: $OUT/pipeline.labeled.scanlog.jsonl; map: $OUT/map.png (+ .pgm/.yaml)"
exit "$status"
