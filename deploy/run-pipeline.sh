#!/usr/bin/env bash
# Starts the pipeline's processes (map_publisher, penetration_filter,
# jump_filter, scan_ingest) and a recorder of the labelled output, prints
# where the metrics and the output are, and stops them all by PID on Ctrl-C
# or when the ingest has published its whole source and the recorder holds
# every scan it published (the map publisher then saves the map). Exits
# non-zero when the ingest failed or scans were lost on the way.
#
#   deploy/run-pipeline.sh [--scene hall | --log FILE] [--rate recorded|max|FACTOR] [--out DIR] [--domain N]
#
# The source starts once the stages downstream are matched, or after
# MATCH_TIMEOUT_S (default 30) seconds, saying what is missing.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BIN="${BUILD_DIR:-$ROOT/build}"
SCENE=hall LOG="" RATE=recorded OUT="$ROOT/out" DOMAIN=0
MATCH_TIMEOUT_S=${MATCH_TIMEOUT_S:-30}
while [ $# -gt 0 ]; do
  case "$1" in
    --scene) SCENE="$2"; shift 2 ;;
    --log) LOG="$2"; shift 2 ;;
    --rate) RATE="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --domain) DOMAIN="$2"; shift 2 ;;
    -h|--help) sed -n 2,12p "$0"; exit 0 ;;
    *) echo "unknown argument: $1 (see --help)" >&2; exit 2 ;;
  esac
done
# The arguments are checked before anything starts: an error names the
# argument the user typed, not the generated config it would land in.
bad_argument() { echo "$1 (see --help)" >&2; exit 2; }
[[ "$MATCH_TIMEOUT_S" =~ ^[0-9]+$ ]] || bad_argument "MATCH_TIMEOUT_S: whole seconds expected, got $MATCH_TIMEOUT_S"
if [ -n "$LOG" ]; then
  [ -e "$LOG" ] || bad_argument "--log: no such file: $LOG"
  # The ingest reads a log twice (checked through, then played): a pipe cannot be.
  [ -f "$LOG" ] || bad_argument "--log: not a regular file (a pipe or device; write it to a file first): $LOG"
elif [ ! -f "$SCENE" ] && [ ! -f "$ROOT/config/scenes/$SCENE.yaml" ]; then
  bad_argument "--scene: neither a scene file nor a built-in scene ($(cd "$ROOT/config/scenes" && ls *.yaml | sed 's/\.yaml$//' | paste -sd ' ')), got $SCENE"
fi
positive_number() { awk -v x="$1" 'BEGIN { exit !(x ~ /^[0-9]*\.?[0-9]+$/ && x + 0 > 0) }'; }
[[ "$RATE" =~ ^(recorded|max)$ ]] || positive_number "$RATE" ||
  bad_argument "--rate: expected recorded, max or a speed factor > 0, got $RATE"
[[ "$DOMAIN" =~ ^[0-9]+$ ]] && [ "$DOMAIN" -le 232 ] || bad_argument "--domain: expected a DDS domain id 0-232, got $DOMAIN"
DOMAIN=$((10#$DOMAIN))  # 010 is 10, as the services read it
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"  # absolute: the configs written below are read from $OUT
# A run's outputs are this run's: an earlier run's in the same folder would
# be named below as if this one had written them.
rm -f "$OUT/pipeline.labeled.scanlog.jsonl" "$OUT"/map.{png,pgm,yaml}
# The ingest's source, written as a config next to the output.
INGEST_CFG="$OUT/scan_ingest.yaml"
{
  echo "service: {domain_id: $DOMAIN, profiles_file: $ROOT/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:9471}"
  if [ -n "$LOG" ]; then
    echo "source: {kind: log, path: $(realpath "$LOG"), rate: $RATE}"
  else
    echo "source: {kind: simulator, scene: $SCENE, rate: $RATE}"
  fi
  # rt/posed_scan has one reader, the jump_filter; by the time the ingest
  # starts below it has normally matched it already.
  echo "playback: {wait_for_subscribers: 1, wait_timeout_s: 30, exit_at_end: true}"
} > "$INGEST_CFG"

MAP_CFG="$OUT/map_publisher.yaml"
echo "service: {domain_id: $DOMAIN, profiles_file: $ROOT/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:9474}" > "$MAP_CFG"
echo "publishing: {save_path: $OUT/map}" >> "$MAP_CFG"

PIDS=()
declare -A PID_OF
stop_all() {
  for pid in "${PIDS[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${PIDS[@]}"; do wait "$pid" 2>/dev/null || true; done
  PIDS=()
}
# Whatever ends this script (the end, an error, Ctrl-C, a closed pipe on its
# output) stops what it started.
trap stop_all EXIT
trap 'exit 130' INT TERM HUP
trap 'exit 141' PIPE

started() {  # name: remembers the PID of the process just started in the background
  PID_OF[$1]=$!
  PIDS+=($!)
}
"$BIN/services/map_publisher" --config "$MAP_CFG" > "$OUT/map_publisher.log" 2>&1 & started map_publisher
"$BIN/services/penetration_filter" --domain "$DOMAIN" > "$OUT/penetration_filter.log" 2>&1 & started penetration_filter
"$BIN/services/jump_filter" --domain "$DOMAIN" > "$OUT/jump_filter.log" 2>&1 & started jump_filter
# No idle exit: a recorded source may pause for as long as its log did.
# The recorder runs until stopped below, once it holds what the ingest published.
RECORDER_PROGRESS_S=0.2  # how often the recorder says how many scans it holds
# After the ingest ended, how long the scans still in the filters' queues
# may take to reach the recorder: well under a second at any rate; the rest
# is for a loaded machine.
RECORDER_DRAIN_TIMEOUT_S=30
"$BIN/dds_tools/scan_recorder" --domain "$DOMAIN" --progress-every "$RECORDER_PROGRESS_S" \
  -o "$OUT/pipeline.labeled.scanlog.jsonl" > "$OUT/scan_recorder.log" 2>&1 & started scan_recorder

# Start the source only once every stage downstream is matched, so that no
# stage misses the first scans. Each need: the service whose metrics endpoint
# (port) has the gauge scanfilter_dds_matched (updated every second), its
# endpoint and topic, how many peers it needs, and who those peers are. Both
# ends of a hop where both have metrics: discovery is asymmetric, and a scan
# sent before the reader has matched the writer is lost.
NEEDS=(
  "9472 jump_filter writer rt/jump_filtered_scan 1 penetration_filter"
  "9473 penetration_filter reader rt/jump_filtered_scan 1 jump_filter"
  "9473 penetration_filter writer rt/labeled_scan 2 map_publisher,scan_recorder"
  "9474 map_publisher reader rt/labeled_scan 1 penetration_filter"
)
matched() {  # port endpoint topic: that gauge's value; empty if the service's metrics do not answer (yet)
  local page
  page=$(curl -s --max-time 1 "http://127.0.0.1:$1/metrics") || return 0  # captured: no `curl | grep` under pipefail
  awk -v ep="endpoint=\"$2\"" -v topic="topic=\"$3\"" \
    'index($0, "scanfilter_dds_matched{") == 1 && index($0, ep) && index($0, topic) { print int($2) }' <<<"$page"
}
running() {  # name: whether that process is still running
  kill -0 "${PID_OF[$1]}" 2>/dev/null
}
logs_of() {  # comma-separated names: their log files
  local name logs=""
  for name in ${1//,/ }; do logs+="${logs:+, }$OUT/$name.log"; done
  echo "$logs"
}
what_is_missing() {  # prints one line per unmet need; nothing once all are met
  local line port svc endpoint topic need peers n peer_kind peer
  for line in "${NEEDS[@]}"; do
    read -r port svc endpoint topic need peers <<<"$line"
    peer_kind=readers
    [ "$endpoint" = writer ] || peer_kind=writers
    n=$(matched "$port" "$endpoint" "$topic")
    if ! running "$svc"; then
      echo "$svc exited (see $OUT/$svc.log)"
    elif [ -z "$n" ]; then
      echo "no metrics from $svc on :$port yet (see $OUT/$svc.log)"
    elif [ "$n" -lt "$need" ]; then
      echo "$topic: $svc's $endpoint has $n of $need $peer_kind matched (${peers//,/ and }; see $(logs_of "$peers"))"
    fi
  done
  for peer in map_publisher scan_recorder; do
    running "$peer" || echo "$peer exited (see $OUT/$peer.log)"
  done
}
wait_start=$(date +%s%N)
deadline=$(( wait_start + MATCH_TIMEOUT_S * 1000000000 ))
while :; do
  missing=$(what_is_missing | awk '!seen[$0]++')
  [ -z "$missing" ] && break
  if [[ "$missing" == *" exited (see "* ]]; then  # it will not match any more
    missing=$(grep -F " exited (see " <<<"$missing")
    break
  fi
  [ "$(date +%s%N)" -lt "$deadline" ] || break
  sleep 0.1
done
waited_ms=$(( ($(date +%s%N) - wait_start) / 1000000 ))
waited="$(( waited_ms / 1000 )).$(( waited_ms % 1000 / 100 ))"
if [ -z "$missing" ]; then
  echo "stages matched: waited $waited s (rt/jump_filtered_scan: penetration_filter; rt/labeled_scan: map_publisher and scan_recorder); starting scan_ingest"
else
  echo "WARNING: waited $waited s (MATCH_TIMEOUT_S=$MATCH_TIMEOUT_S) and still missing:"
  sed 's/^/  - /' <<<"$missing"
  echo "starting scan_ingest anyway: a stage not matched yet misses the first scans"
fi
"$BIN/services/scan_ingest" --config "$INGEST_CFG" > "$OUT/scan_ingest.log" 2>&1 & started scan_ingest
INGEST=${PID_OF[scan_ingest]}

echo "pipeline running on DDS domain $DOMAIN (localhost only); logs in $OUT/"
echo "metrics: http://127.0.0.1:9471/metrics (scan_ingest), :9472 (jump_filter), :9473 (penetration_filter), :9474 (map_publisher)"
echo "topics:  rt/posed_scan -> rt/jump_filtered_scan -> rt/labeled_scan and rt/scan_filtered (sensor_msgs/LaserScan) -> rt/map"
status=0
wait "$INGEST" || status=$?
# What the ingest published (its last log line says) and what the recorder
# holds: its progress while it runs, the line it ends with once its file is
# in place (only that one counts at the end: a recorder that failed to
# write its file printed progress all the same).
published=$(sed -n 's/.*\] published \([0-9]*\) scans$/\1/p' "$OUT/scan_ingest.log" | tail -n 1)
recorder_says() {  # PATTERN with one group, the count: its last match in the recorder's log
  sed -n "s/$1/\\1/p" "$OUT/scan_recorder.log" | tail -n 1
}
if [ "$status" = 0 ] && [ -n "$published" ]; then
  drain_deadline=$((SECONDS + RECORDER_DRAIN_TIMEOUT_S))
  while running scan_recorder && [ "$SECONDS" -lt "$drain_deadline" ]; do
    holds=$(recorder_says '^progress: \([0-9]*\) scans recorded$')
    [ "${holds:-0}" -ge "$published" ] && break
    sleep 0.1
  done
fi
stop_all  # the recorder writes its last scans, puts its file in place and says how many
recorded=$(recorder_says '^recorded \([0-9]*\) scans.*')  # "-> FILE", or "; nothing written" for 0
if [ "$status" = 0 ]; then
  echo "scan_ingest published ${published:-an unknown number of} scans; the recorder holds ${recorded:-none}"
else
  # Its reason, here rather than only in its log: the last error it logged.
  reason=$(sed -n 's/^.*\] \[error\] //p' "$OUT/scan_ingest.log" | tail -n 1)
  echo "scan_ingest failed (exit $status): ${reason:-no error logged} (see $OUT/scan_ingest.log)"
fi
# Only what is there: a run that failed early wrote neither.
[ -f "$OUT/pipeline.labeled.scanlog.jsonl" ] && echo "labelled output: $OUT/pipeline.labeled.scanlog.jsonl"
[ -f "$OUT/map.png" ] && echo "map: $OUT/map.png (+ .pgm/.yaml)"
# (Ended by the ingest's failure, its status stands; by Ctrl-C, the traps' 130.)
if [ "$status" = 0 ]; then
  if [ -z "$published" ]; then
    echo "ERROR: scan_ingest did not say how many scans it published (see $OUT/scan_ingest.log)" >&2
    status=1
  elif [ -z "$recorded" ]; then
    echo "ERROR: the recorder did not finish its file (see $OUT/scan_recorder.log)" >&2
    status=1
  elif [ "$recorded" != "$published" ]; then
    echo "ERROR: $recorded of $published published scans reached the recorder (see the logs in $OUT/)" >&2
    status=1
  fi
fi
exit "$status"
