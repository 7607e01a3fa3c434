#!/usr/bin/env bash
# The alert rules of deploy/monitoring/ in a real Prometheus server scraping
# the four real services: each alert that the services' metrics can drive
# here fires when its cause happens, and the healthy pipeline fires none of
# them. Runs in a private network namespace when possible (unshare -n).
#
#   alerts_test.sh BUILD_DIR SOURCE_DIR
#   ALERT_FOR_S=10 alerts_test.sh ...   every `for:` 10 s (the shipped
#                                       ServiceDown's), to measure with it
#
# Prometheus gets a test copy of the shipped rules with shorter waits, made
# by checked substitutions (each must match exactly the lines it names):
#   - every alert's `for:` becomes ALERT_FOR_S (default 1) seconds (the
#     shipped ones are 0 s to 1 min);
#   - the end-to-end latency budget becomes 10 us, under any real DDS hop, so
#     that the latency alert fires on the real histograms of a healthy run;
#   - the map's unsaved limit becomes 5 s instead of 10 min.
# The order: a healthy stream (only the latency alert, by the budget above),
# malformed samples (SamplesRejected), the map's folder removed
# (MapNotSaved), the stream stopped (NoScans on all four), jump_filter killed
# with SIGKILL (ServiceDown; with the upstream-presence gauge of the services
# also UpstreamNotAlive), each within a bounded wait.
set -euo pipefail
BUILD="$1" SRC="$2"
source "$(dirname "$0")/../lib/dds_test_workspace.sh"  # private network namespace, DOMAIN, WORK, PIDS, cleanup
source "$(dirname "$0")/../lib/service_checks.sh"  # matched, wait_matched (its fail is replaced below)
PROM_URL=http://127.0.0.1:19090
fail() {
  {
    echo "FAIL: $*"
    echo "--- firing alerts:"; firing_alerts || true
    for f in "$WORK"/*.log; do
      if [ -f "$f" ]; then echo "--- $f"; tail -n 20 "$f"; fi
    done
  } >&2
  exit 1
}
command -v prometheus > /dev/null || fail "prometheus is not installed (scripts/install-deps.sh)"

ALERT_FOR_S=${ALERT_FOR_S:-1}
[[ "$ALERT_FOR_S" =~ ^[0-9]+$ ]] || fail "ALERT_FOR_S: whole seconds expected, got $ALERT_FOR_S"
# How long the test waits for a condition (an alert, a match) at most: the
# alerts here need one scrape, one evaluation and their `for`; a loaded
# 2-core machine gets 10x that.
WAIT_S=$((30 + ALERT_FOR_S))
MATCH_WAIT_S=$WAIT_S  # wait_matched
STREAM_HZ=20        # scans per second of the robot driver (ros_scan_publisher)
STREAM_FRAMES=2400  # at most 2 min of scans: the stream is stopped well before
SHIPPED_RULES="$SRC/deploy/monitoring/alerts.yml"

# sed_checked FILE EXPECTED_LINES PATTERN REPLACEMENT: replaces (sed -E,
# delimiter |) PATTERN in FILE, and fails unless exactly EXPECTED_LINES lines
# match it (a pattern that no longer matches the shipped file must not leave
# the test on the shipped values).
sed_checked() {
  local file=$1 expected=$2 pattern=$3 replacement=$4 matching
  matching=$(grep -cE "$pattern" "$file" || true)
  [ "$matching" = "$expected" ] ||
    fail "test copy of $(basename "$file"): $matching lines match '$pattern', expected $expected"
  sed -i -E "s|$pattern|$replacement|" "$file"
}

# The test copy of the rules.
RULES="$WORK/alerts.yml"
cp "$SHIPPED_RULES" "$RULES"
shipped=$(cat "$SHIPPED_RULES")
alert_count=$(grep -c '^      - alert: ' <<<"$shipped")
[ "$alert_count" -ge 6 ] || fail "only $alert_count alerts in $SHIPPED_RULES"
sed_checked "$RULES" "$alert_count" '^        for: [0-9]+[smh]$' "        for: ${ALERT_FOR_S}s"
sed_checked "$RULES" 1 '^        expr: vector\(0\.025\)$' '        expr: vector(0.00001)'
sed_checked "$RULES" 1 '^        expr: vector\(600\)$' '        expr: vector(5)'
promtool check rules "$RULES" > /dev/null || fail "the test copy of the rules does not load"

# The test copy of the scrape config: the services on 1947x, the rules above.
PROM_CONFIG="$WORK/prometheus.yml"
cp "$SRC/deploy/monitoring/prometheus.yml" "$PROM_CONFIG"
sed_checked "$PROM_CONFIG" 4 '"127\.0\.0\.1:947([1-4])"' '"127.0.0.1:1947\1"'
sed_checked "$PROM_CONFIG" 1 '^  - alerts\.yml$' "  - $RULES"

# One alert per line, "NAME SERVICE", of the firing alerts in
# /api/v1/alerts (labels are sorted, alertname first; only labels carry a
# "service" key).
firing_alerts() {
  local reply
  reply=$(curl -s --max-time 5 "$PROM_URL/api/v1/alerts" || true)
  sed 's/{"labels":/\n&/g' <<<"$reply" |
    sed -n '/"state":"firing"/s/^{"labels":{"alertname":"\([^"]*\)".*"service":"\([^"]*\)".*/\1 \2/p' | sort
}

# wait_firing NAME SERVICE: until that alert fires for that service;
# WAITED_MS: how long that took.
wait_firing() {
  local start_ms deadline alerts
  start_ms=$(date +%s%3N)
  deadline=$((SECONDS + WAIT_S))
  while :; do
    alerts=$(firing_alerts)
    grep -qx "$1 $2" <<<"$alerts" && break
    [ "$SECONDS" -lt "$deadline" ] || fail "$1 did not fire for $2 within $WAIT_S s"
    sleep 0.1
  done
  WAITED_MS=$(( $(date +%s%3N) - start_ms ))
}

# wait_only_firing EXPECTED: until the firing alerts are exactly EXPECTED
# (lines "NAME SERVICE", sorted).
wait_only_firing() {
  local deadline alerts
  deadline=$((SECONDS + WAIT_S))
  while :; do
    alerts=$(firing_alerts)
    [ "$alerts" = "$1" ] && return 0
    [ "$SECONDS" -lt "$deadline" ] || fail "after $WAIT_S s the firing alerts are:
$alerts
expected:
$1"
    sleep 0.2
  done
}

prom_query() {  # PromQL: the value of each series, one per line
  local reply
  reply=$(curl -s --max-time 5 "$PROM_URL/api/v1/query" --data-urlencode "query=$1" || true)
  { grep -o '"value":\[[^]]*\]' <<<"$reply" | sed 's/.*,"\(.*\)"\]/\1/'; } || true
}

# wait_query PROMQL VALUE WHAT: until the query's value is VALUE.
wait_query() {
  local deadline got
  deadline=$((SECONDS + WAIT_S))
  while :; do
    got=$(prom_query "$1")
    [ "$got" = "$2" ] && return 0
    [ "$SECONDS" -lt "$deadline" ] || fail "$3: after $WAIT_S s '$1' is '${got:-nothing}', expected $2"
    sleep 0.2
  done
}

# Prometheus, then the four services and a robot driver's stream.
prometheus --config.file="$PROM_CONFIG" --web.listen-address=127.0.0.1:19090 \
  --storage.tsdb.path="$WORK/tsdb" > "$WORK/prometheus.log" 2>&1 &
PROM=$!; PIDS+=($PROM)

PROFILES="$SRC/deploy/fastdds-loopback.xml"
mkdir "$WORK/maps"
cat > "$WORK/map.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $PROFILES, metrics_address: 127.0.0.1:19474}
publishing: {rate_hz: 5, save_path: $WORK/maps/map, save_period_s: 1}
YAML
cat > "$WORK/ingest.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $PROFILES, metrics_address: 127.0.0.1:19471}
source: {kind: live}
live: {scan_topic: scan, odom_topic: odom, mount: [-0.05, 0.0, 3.141592653589793], max_pose_gap_s: 0.2, reliable: true}
YAML
"$BUILD/services/map_publisher" --config "$WORK/map.yaml" > "$WORK/map.log" 2>&1 &
MAP=$!; PIDS+=($MAP)
"$BUILD/services/penetration_filter" --domain "$DOMAIN" --metrics-address 127.0.0.1:19473 > "$WORK/penetration.log" 2>&1 &
PEN=$!; PIDS+=($PEN)
"$BUILD/services/jump_filter" --domain "$DOMAIN" --metrics-address 127.0.0.1:19472 > "$WORK/jump.log" 2>&1 &
JUMP=$!; PIDS+=($JUMP)
"$BUILD/services/scan_ingest" --config "$WORK/ingest.yaml" > "$WORK/ingest.log" 2>&1 &
INGEST=$!; PIDS+=($INGEST)
wait_matched 19472 writer rt/jump_filtered_scan
wait_matched 19473 reader rt/jump_filtered_scan
wait_matched 19473 writer rt/labeled_scan
wait_matched 19474 reader rt/labeled_scan
wait_matched 19471 writer rt/posed_scan
wait_matched 19472 reader rt/posed_scan

"$BUILD/tools/scanfilter" simulate --scene hall --seed 4 --max-frames $STREAM_FRAMES -o "$WORK/stream.scanlog.jsonl" > /dev/null
"$BUILD/dds_tools/ros_scan_publisher" --domain "$DOMAIN" --rate $STREAM_HZ --reliable "$WORK/stream.scanlog.jsonl" \
  > "$WORK/publisher.log" 2>&1 &
DRIVER=$!; PIDS+=($DRIVER)

# 1. Healthy: all four up, scans coming out of every stage, rules without
# errors, the map saved; only the latency alert fires (its budget is 10 us
# here), for both filters and the map publisher, which observe the end-to-end latency.
wait_query 'sum(up{job="scanfilter"})' 4 "the four services up"
wait_query 'count(increase(scanfilter_scans_published_total{service=~"scan_ingest|jump_filter|penetration_filter"}[5s]) > 0)
            + count(increase(scanfilter_map_scans_integrated_total[5s]) > 0)' 4 "scans out of every stage"
wait_query 'scanfilter_map_saves_total >= bool 5' 1 "five saves of the map"
healthy="ScanfilterEndToEndLatencyOverBudget jump_filter
ScanfilterEndToEndLatencyOverBudget map_publisher
ScanfilterEndToEndLatencyOverBudget penetration_filter"
wait_only_firing "$healthy"
# The services' own `service` label is kept as it is (honor_labels).
renamed=$(prom_query 'count({job="scanfilter",exported_service!=""})')
[ -z "$renamed" ] || fail "$renamed series have an exported_service label: the scrape config renamed the services' labels"
rules=$(curl -s --max-time 5 "$PROM_URL/api/v1/rules" || true)
ok_rules=$(grep -o '"health":"ok"' <<<"$rules" | wc -l)
rule_count=$(grep -cE '^      - (alert|record): ' <<<"$shipped")
[ "$ok_rules" = "$rule_count" ] || fail "$ok_rules of $rule_count rules evaluate without error: $rules"
saved_age=$(prom_query 'time() - scanfilter_map_last_save_timestamp_seconds')
echo "healthy: only the latency alert fires (test budget 10 us); the map was saved ${saved_age} s ago"

# 2. Malformed samples into the jump_filter.
"$BUILD/tests/bad_sample_sender" "$DOMAIN" "$PROFILES" > "$WORK/sender.log" 2>&1 || fail "bad_sample_sender failed"
wait_firing ScanfilterSamplesRejected jump_filter
echo "SamplesRejected fired ${WAITED_MS} ms after the bad samples were acknowledged"

# 3. The map's folder disappears: saves fail, the publisher keeps running.
# Renamed away in one step: `rm -rf` races the publisher, which may write a
# new file into the folder between rm's unlinks and its rmdir.
mv "$WORK/maps" "$WORK/maps.removed"
wait_firing ScanfilterMapNotSaved map_publisher
echo "MapNotSaved fired ${WAITED_MS} ms after the map's folder was removed (test limit 5 s)"
kill -0 "$MAP" 2> /dev/null || fail "map_publisher ended when a save failed"
grep -q "saving the map to .* failed" "$WORK/map.log" || fail "map_publisher did not log the failed save"

# 4. The robot driver stops: no scans anywhere.
stopped_ms=$(date +%s%3N)
# (The driver may have ended its finite stream already: then kill finds no one.)
kill -TERM "$DRIVER" 2> /dev/null || true; wait "$DRIVER" || true
for svc in scan_ingest jump_filter penetration_filter map_publisher; do
  wait_firing ScanfilterNoScans "$svc"
done
echo "NoScans fired for all four $(( $(date +%s%3N) - stopped_ms )) ms after the stream stopped (window 5 s)"
alerts=$(firing_alerts)
if grep -q '^ScanfilterServiceDown ' <<<"$alerts"; then fail "a service is down before any was killed"; fi

# 5. SIGKILL the jump_filter.
kill -KILL "$JUMP"
killed_ms=$(date +%s%3N)
wait_firing ScanfilterServiceDown jump_filter
down_ms=$(( $(date +%s%3N) - killed_ms ))
echo "ServiceDown fired ${down_ms} ms after kill -9 of jump_filter (for: ${ALERT_FOR_S}s, scrape and evaluation every 1 s)"
alerts=$(firing_alerts)
down=$(grep '^ScanfilterServiceDown ' <<<"$alerts" || true)
[ "$down" = "ScanfilterServiceDown jump_filter" ] || fail "ServiceDown fires for: $down"
# The upstream-presence gauge (scanfilter_upstream_alive) where the services export it.
if [ -n "$(prom_query 'count(scanfilter_upstream_alive)')" ]; then
  wait_firing ScanfilterUpstreamNotAlive penetration_filter
  echo "UpstreamNotAlive fired for penetration_filter ${WAITED_MS} ms after ServiceDown"
else
  echo "UpstreamNotAlive not exercised: these services export no scanfilter_upstream_alive (promtool tests cover the rule)"
fi

for pid in $INGEST $PEN $MAP; do kill -TERM "$pid"; done
wait "$INGEST" || fail "scan_ingest exited non-zero"
wait "$PEN" || fail "penetration_filter exited non-zero"
# Its save at shutdown cannot be written either (the folder is gone): that
# one still ends it non-zero.
if wait "$MAP"; then fail "map_publisher exited 0 though its final save failed"; fi
kill -TERM "$PROM"; wait "$PROM" || true
echo "PASS: alerts"
