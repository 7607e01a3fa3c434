#!/usr/bin/env bash
# Crashes and restarts: a 40 Hz stream (the simulated hall at 4x its 10 Hz)
# through all four services; each is killed with SIGKILL in turn mid-stream
# and restarted with the same command, as systemd would. Checks that the
# others keep running, the stream resumes, the lost scans stay within what
# the design promises, the labels of every scan that came out equal an
# offline replay of exactly those scans (with the penetration filter's cache
# emptied where the live one restarted), and the final map equals the map
# built offline from the scans the map publisher integrated. Prints the
# figures docs/operations.md quotes.
#
#   kill_restart_test.sh BUILD_DIR SOURCE_DIR
set -Eeuo pipefail
BUILD="$1" SRC="$2"
if [ -z "${SCANFILTER_IN_NETNS:-}" ] && [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
  exec unshare -n env SCANFILTER_IN_NETNS=1 bash -c 'ip link set lo up && exec bash "$0" "$@"' "$0" "$@"
fi
DOMAIN=$(( (RANDOM % 200) + 10 ))
WORK=$(mktemp -d)
declare -A PID PORT=([scan_ingest]=19471 [jump_filter]=19472 [penetration_filter]=19473 [map_publisher]=19474)
cleanup() {
  for pid in "${PID[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  # Reaped before WORK goes: the map publisher saves into it every 0.5 s.
  for pid in "${PID[@]}"; do wait "$pid" 2>/dev/null || true; done
  [ -n "${KEEP_WORK:-}" ] || rm -rf "$WORK"
}
trap cleanup EXIT
fail() {  # the failing check, the tail of every process log; the work dir is kept for a look
  trap - ERR
  echo "FAIL: $*"
  for f in "$WORK"/*.log "$WORK"/*.diff; do
    if [ -f "$f" ]; then echo "--- $f"; tail -n 25 "$f"; fi
  done
  KEEP_WORK=1
  echo "work dir kept: $WORK"
  exit 1
}
# Any other command failing (set -e) is a failed check too: say which.
trap 'fail "line $LINENO: \`$BASH_COMMAND\` exited $?"' ERR
SF="$BUILD/tools/scanfilter"
CHECK="$BUILD/tests/recovery/recovery_check"
# 76 s of the hall at 10 Hz (its path ends at 793 frames), replayed at 4x: 19 s
# of stream at 40 Hz plus the holds. The ingest's kill at 460 leaves 300 scans
# (7.5 s) of room: the waits between kills (a restart, discovery's 3 s lease)
# let the paced stream run on past the nominal kill points on a loaded machine.
FRAMES=760
SPEED=4.0
QUEUE=16     # queue_depth of every stream: the flow-control window W, and what the loss bound is made of
# Kills, in stream order, each once the ingest has published this many scans;
# the map publisher's instead as soon as the restarted penetration filter has
# published (the window where the publisher may have got nothing from it yet).
KILLS=(jump_filter:100 penetration_filter:220 map_publisher:pen_restarted scan_ingest:460)

scrape() { curl -s --max-time 2 "http://127.0.0.1:$1/metrics" || true; }

gauge() {  # port metric-name-with-labels (exact): prints the value, empty if absent
  local page
  page=$(scrape "$1")
  awk -v m="$2" 'index($0, m " ") == 1 {print int($2)}' <<<"$page"
}

wait_for() {  # description seconds command...: until the command succeeds
  local what=$1 limit=$2; shift 2
  local deadline=$((SECONDS + limit))
  until "$@"; do
    [ "$SECONDS" -lt "$deadline" ] || fail "$what: not within $limit s"
    sleep 0.1
  done
}

matched_at_least() {  # port endpoint topic n
  local v
  v=$(gauge "$1" "scanfilter_dds_matched{endpoint=\"$2\",service=\"$(svc_of "$1")\",topic=\"$3\"}")
  [ "${v:-0}" -ge "$4" ]
}
svc_of() { for s in "${!PORT[@]}"; do [ "${PORT[$s]}" = "$1" ] && echo "$s"; done; return 0; }

published() {  # scans the ingest has published so far, across its restarts (its progress file)
  sed -n 's/^published_scans: //p' "$WORK/ingest.progress" 2>/dev/null || echo 0
}
published_at_least() { [ "$(published)" -ge "$1" ]; }
pen_restarted() {  # the restarted penetration filter has published a scan
  [ "$(gauge 19473 'scanfilter_scans_published_total{service="penetration_filter"}')" -ge 1 ] 2>/dev/null
}

service_line() {  # name: the `service:` flow mapping of its config
  echo "service: {domain_id: $DOMAIN, profiles_file: $SRC/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:${PORT[$1]}, queue_depth: $QUEUE$2}"
}

write_configs() {
  { service_line scan_ingest ""
    echo "source: {kind: log, path: $WORK/in.scanlog.jsonl, rate: $SPEED}"
    echo "playback: {wait_for_subscribers: 1, wait_timeout_s: 30, exit_at_end: true, progress_path: $WORK/ingest.progress}"
  } > "$WORK/scan_ingest.yaml"
  { service_line jump_filter ", required_readers: 1"; echo "filter: {config: $SRC/config/filter.yaml}"; } > "$WORK/jump_filter.yaml"
  # Two readers of rt/labeled_scan must get every scan: the map publisher and the recorder.
  { service_line penetration_filter ", required_readers: 2"; echo "filter: {config: $SRC/config/filter.yaml}"; } \
    > "$WORK/penetration_filter.yaml"
  { service_line map_publisher ""
    echo "publishing: {rate_hz: 5, save_path: $WORK/map, save_period_s: 0.5, load_on_start: true}"
  } > "$WORK/map_publisher.yaml"
}

start() {  # name: the same command every time, as a systemd unit's ExecStart; its log appended
  "$BUILD/services/$1" --config "$WORK/$1.yaml" >> "$WORK/$1.log" 2>&1 &
  PID[$1]=$!
}

alive() { kill -0 "${PID[$1]}" 2>/dev/null; }

"$SF" simulate --scene hall --seed 4 --max-frames $FRAMES -o "$WORK/in.scanlog.jsonl" > /dev/null
write_configs
t0=$SECONDS
start map_publisher
start penetration_filter
start jump_filter
"$BUILD/dds_tools/scan_recorder" --domain "$DOMAIN" --queue-depth $QUEUE --idle-exit 10 --timeout 200 \
  -o "$WORK/live.scanlog.jsonl" > "$WORK/recorder.log" 2>&1 &
REC=$!; PID[recorder]=$REC
wait_for "jump_filter matched the penetration_filter" 20 matched_at_least 19473 reader rt/jump_filtered_scan 1
wait_for "penetration_filter matched the map_publisher and the recorder" 20 matched_at_least 19473 writer rt/labeled_scan 2
wait_for "map_publisher matched the penetration_filter" 20 matched_at_least 19474 reader rt/labeled_scan 1
start scan_ingest

declare -A UPSTREAM_DOWN_SEEN
for kill in "${KILLS[@]}"; do
  name=${kill%%:*} at=${kill##*:}
  if [ "$at" = pen_restarted ]; then
    wait_for "the restarted penetration_filter to publish before killing $name" 30 pen_restarted
  else
    wait_for "the stream reached scan $at before killing $name" 60 published_at_least "$at"
    # ...and flows end to end: the map publisher is getting scans again (after
    # a restart the stages upstream hold until discovery drops the dead process).
    base=$(gauge 19474 'scanfilter_scans_received_total{service="map_publisher"}')
    map_flowing() { [ "$(gauge 19474 'scanfilter_scans_received_total{service="map_publisher"}')" -ge $(( ${base:-0} + 20 )) ]; }
    wait_for "the map publisher to get scans before killing $name" 30 map_flowing
  fi
  alive "$name" || fail "$name exited before its kill (the stream is at scan $(published) of $FRAMES)"
  for other in "${!PORT[@]}"; do
    [ "$other" = "$name" ] || alive "$other" || [ "$other" = scan_ingest ] || fail "$other died before $name was killed"
  done
  kill -KILL "${PID[$name]}"
  wait "${PID[$name]}" 2>/dev/null || true
  echo "killed $name at scan $(published) ($((SECONDS - t0)) s)"
  if [ "$name" = jump_filter ]; then
    # Downstream sees its upstream go: discovery drops the dead writer when
    # its participant's lease (3 s in the shipped profile) runs out; gauge 0.
    down() { [ "$(gauge 19473 'scanfilter_upstream_alive{service="penetration_filter",topic="rt/jump_filtered_scan"}')" = 0 ]; }
    wait_for "penetration_filter's scanfilter_upstream_alive to drop to 0" $((10 * ${SCANFILTER_TEST_TIME_FACTOR:-1})) down
    UPSTREAM_DOWN_SEEN[$name]=1
  fi
  sleep 0.5  # systemd's RestartSec is 100 ms by default; a little longer
  start "$name"
  for other in "${!PORT[@]}"; do
    [ "$other" = "$name" ] || [ "$other" = scan_ingest ] || alive "$other" || fail "$other died after $name was killed"
  done
  if [ "$name" = jump_filter ]; then
    up() { [ "$(gauge 19473 'scanfilter_upstream_alive{service="penetration_filter",topic="rt/jump_filtered_scan"}')" = 1 ]; }
    wait_for "penetration_filter's scanfilter_upstream_alive back to 1" 20 up
  fi
  [ "$name" = penetration_filter ] && continue  # the next kill waits for it to publish
  # The stream resumes through the restarted service: the ingest gets further
  # (or to the end of the log, when the waits let it run close to it).
  resumed_at=$(( $(published) + 20 ))
  [ "$resumed_at" -le $FRAMES ] || resumed_at=$FRAMES
  wait_for "the stream to resume after restarting $name" 30 published_at_least "$resumed_at"
done

# The (restarted) ingest publishes the rest of the log and exits 0.
deadline=$((SECONDS + 90))
while alive scan_ingest; do
  [ "$SECONDS" -lt "$deadline" ] || fail "scan_ingest did not finish the log"
  sleep 0.2
done
wait "${PID[scan_ingest]}" || fail "scan_ingest exited non-zero"
[ "$(published)" = $FRAMES ] || fail "the ingest's progress says $(published) of $FRAMES published"
wait "$REC" || fail "scan_recorder failed"
for s in jump_filter penetration_filter map_publisher; do alive "$s" || fail "$s died"; done
kill -TERM "${PID[map_publisher]}"; wait "${PID[map_publisher]}" || fail "map_publisher exited non-zero"
echo "stream done in $((SECONDS - t0)) s"

# Upstream presence: a log line on each change (the jump_filter's kill: lost, then alive again).
pen_log=$(cat "$WORK/penetration_filter.log")
grep -q "upstream of rt/jump_filtered_scan lost" <<<"$pen_log" || fail "no log line for the lost upstream"
n_alive=$(grep -c "upstream of rt/jump_filtered_scan alive" <<<"$pen_log" || true)
[ "$n_alive" -ge 2 ] || fail "expected the upstream to come alive twice (start, restart), saw $n_alive"

# Lost scans: sequence numbers missing from the recording, as contiguous runs.
"$CHECK" sequences "$WORK/in.scanlog.jsonl" "$WORK/live.scanlog.jsonl" > "$WORK/sequences" || fail "recovery_check sequences"
recorded=$(wc -l < "$WORK/sequences")
runs=$(awk -v n=$FRAMES 'BEGIN {prev = -1}
  { if ($1 > prev + 1) printf "%d-%d(%d) ", prev + 1, $1 - 1, $1 - prev - 1; prev = $1 }
  END { if (prev < n - 1) printf "%d-%d(%d) ", prev + 1, n - 1, n - 1 - prev }' "$WORK/sequences")
lost=$((FRAMES - recorded))
echo "recorded $recorded of $FRAMES scans; lost $lost: ${runs:-none}"
# The design's bound per killed stage: its reader queue (2W) + the scan in
# hand + its writer's unacknowledged window (W) + the upstream writer's
# window written before discovery dropped the dead reader (W); the map
# publisher's kill loses no scan of the stream (the penetration filter holds).
per_kill=$((4 * QUEUE + 1))
[ "$lost" -le $((3 * per_kill)) ] || fail "lost $lost scans, more than 3 x $per_kill"
n_runs=$(wc -w <<<"$runs")
[ "$n_runs" -le 3 ] || fail "scans lost in $n_runs places, expected at most one per killed stage"

# Labels: the penetration filter restarted with an empty cache at scan F.
# Offline, the recording replayed in two parts (an empty cache at F too)
# must give exactly the live labels; replayed in one piece, the difference
# is what the empty cache cost.
first_pen=$(sed -n 's/.*first scan since start: sequence \([0-9]*\).*/\1/p' "$WORK/penetration_filter.log" | tail -n 1)
[ -n "$first_pen" ] || fail "no restart line in penetration_filter.log"
split=$(awk -v f="$first_pen" '$1 >= f {print NR - 1; exit}' "$WORK/sequences")
head -n 1 "$WORK/live.scanlog.jsonl" > "$WORK/before.scanlog.jsonl"
cp "$WORK/before.scanlog.jsonl" "$WORK/after.scanlog.jsonl"
sed -n "2,$((split + 1))p" "$WORK/live.scanlog.jsonl" >> "$WORK/before.scanlog.jsonl"
sed -n "$((split + 2)),\$p" "$WORK/live.scanlog.jsonl" >> "$WORK/after.scanlog.jsonl"
for part in before after; do
  # A restart before the first recorded scan leaves "before" empty: nothing to compare there.
  [ "$(wc -l < "$WORK/$part.scanlog.jsonl")" -gt 1 ] || continue
  "$SF" replay "$WORK/$part.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/$part.offline.scanlog.jsonl" -q
  "$SF" diff "$WORK/$part.offline.scanlog.jsonl" "$WORK/$part.scanlog.jsonl" > "$WORK/$part.diff" ||
    fail "live labels $part the penetration_filter's restart (scan $first_pen) differ from the offline replay: $(cat "$WORK/$part.diff")"
done
"$SF" replay "$WORK/live.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/whole.offline.scanlog.jsonl" -q
cost=$("$SF" diff "$WORK/whole.offline.scanlog.jsonl" "$WORK/live.scanlog.jsonl" || true)
echo "penetration_filter restarted at scan $first_pen with an empty cache; against a replay that kept its cache: $cost"

# Map: the saved map equals the offline map of exactly the scans the map
# publisher integrated: all that came out of the penetration filter but those
# after its last save before the kill and before the first one the restarted
# publisher got.
map_log=$(cat "$WORK/map_publisher.log")
saved_last=$(sed -n 's/.*continuing from .* the last sequence \([0-9]*\)).*/\1/p' <<<"$map_log" | head -n 1)
saved_scans=$(sed -n 's/.*continuing from .*, \([0-9]*\) scans, the last sequence.*/\1/p' <<<"$map_log" | head -n 1)
first_map=$(sed -n 's/.*first scan integrated since start: sequence \([0-9]*\).*/\1/p' <<<"$map_log" | sed -n 2p)
[ -n "$saved_last" ] && [ -n "$saved_scans" ] && [ -n "$first_map" ] ||
  fail "map_publisher did not log where it continued (saved $saved_last, $saved_scans scans, first $first_map)"
# The dead penetration filter's last scans reached its two readers in order
# but not equally far: the map may hold scans the recorder lost (or lack some
# it got). The saved count says how many: they are the first (last) ones of the
# run lost at that kill, and their labels are the offline replay's (which
# equals the live labels, checked above).
recorded_upto=$(awk -v a="$saved_last" '$1 <= a' "$WORK/sequences" | wc -l)
map_extra=$((saved_scans - recorded_upto))
last_before=$(awk -v f="$first_pen" '$1 < f {last = $1} END {print last}' "$WORK/sequences")
awk -v f="$first_pen" '$1 < f' "$WORK/sequences" > "$WORK/map_before.seq"
if [ "$map_extra" -gt 0 ]; then seq $((last_before + 1)) $((last_before + map_extra)) >> "$WORK/map_before.seq"
elif [ "$map_extra" -lt 0 ]; then head -n "$map_extra" "$WORK/map_before.seq" > "$WORK/map_before.tmp" && mv "$WORK/map_before.tmp" "$WORK/map_before.seq"
fi
[ "$map_extra" -le 0 ] || [ $((last_before + map_extra)) -lt "$first_pen" ] ||
  fail "the saved map holds $map_extra scans more than were recorded up to scan $saved_last, beyond the lost run"
{ head -n 1 "$WORK/in.scanlog.jsonl"
  awk 'NR == FNR {want[$1 + 2] = 1; next} want[FNR]' "$WORK/map_before.seq" "$WORK/in.scanlog.jsonl"
} > "$WORK/map_before.scanlog.jsonl"
"$SF" replay "$WORK/map_before.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/map_integrated.scanlog.jsonl" -q
awk -v f="$first_pen" 'NR == FNR {seq[FNR + 1] = $1; next} FNR > 1 && seq[FNR] >= f' \
  "$WORK/sequences" "$WORK/live.scanlog.jsonl" >> "$WORK/map_integrated.scanlog.jsonl"
"$CHECK" sequences "$WORK/in.scanlog.jsonl" "$WORK/map_integrated.scanlog.jsonl" > "$WORK/map_sequences" ||
  fail "recovery_check sequences (map)"
map_lost=$(awk -v a="$saved_last" -v b="$first_map" '$1 > a && $1 < b' "$WORK/map_sequences" | wc -l)
result=$("$CHECK" map "$WORK/in.scanlog.jsonl" "$WORK/map_integrated.scanlog.jsonl" "$WORK/map_publisher.yaml" \
           "$WORK/map" $((saved_last + 1)) "$first_map") || fail "recovery_check map failed"
echo "map_publisher: saved $saved_scans scans up to scan $saved_last ($map_extra not recorded), resumed at scan" \
     "$first_map: $map_lost scans not in the map; $result"
[[ "$result" =~ ^cells:\ 0\ differ ]] || fail "the saved map differs from the offline map of the scans it integrated"
final_scans=$(sed -n 's/^scans_integrated: //p' "$WORK/map.progress")
[[ "$result" =~ offline\ scans:\ $final_scans\; ]] ||
  fail "the map says it integrated $final_scans scans, the offline map of those it got has other: $result"
echo "total $((SECONDS - t0)) s"
echo "PASS: kill_restart"
