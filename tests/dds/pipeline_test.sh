#!/usr/bin/env bash
# Integration tests of the DDS services: real processes on loopback, run in a
# private network namespace when possible (unshare -n), else on their own
# domain id with the loopback-only profile.
#
#   pipeline_test.sh BUILD_DIR SOURCE_DIR CASE
#   CASE: labels | metrics | prometheus | live | live_hold | upside_down | cyclone | cyclone_upside_down | bad_samples |
#         map | config | launcher
set -euo pipefail
BUILD="$1" SRC="$2" CASE="$3"
source "$(dirname "$0")/../lib/dds_test_workspace.sh"  # private network namespace, DOMAIN, WORK, PIDS, cleanup
source "$(dirname "$0")/../lib/service_checks.sh"  # scrape, metric, matched, wait_matched, fail
SF="$BUILD/tools/scanfilter"
FRAMES=300

start_filters() {
  "$BUILD/services/penetration_filter" --domain "$DOMAIN" --metrics-address 127.0.0.1:19473 > "$WORK/penetration.log" 2>&1 &
  PEN=$!; PIDS+=($PEN)
  "$BUILD/services/jump_filter" --domain "$DOMAIN" --metrics-address 127.0.0.1:19472 > "$WORK/jump.log" 2>&1 &
  JUMP=$!; PIDS+=($JUMP)
}

ingest_config() {  # log file, exit_at_end
  cat > "$WORK/ingest.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $SRC/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:19471}
source: {kind: log, path: $1, rate: max}
playback: {wait_for_subscribers: 1, wait_timeout_s: 30, exit_at_end: $2}
YAML
}

start_pipeline() {  # scans the recorder waits for: filters and recorder up and matched
  start_filters
  "$BUILD/dds_tools/scan_recorder" --domain "$DOMAIN" --count "$1" --timeout 60 -o "$WORK/live.scanlog.jsonl" \
    > "$WORK/recorder.log" 2>&1 &
  REC=$!; PIDS+=($REC)
  wait_jump_to_penetration
  wait_matched 19473 writer rt/labeled_scan  # the recorder (no metrics of its own)
}

run_ingest() {  # log file
  ingest_config "$1" true
  "$BUILD/services/scan_ingest" --config "$WORK/ingest.yaml" > "$WORK/ingest.log" 2>&1 || fail "scan_ingest exited non-zero"
}

prom_api() {  # PromQL: the query API's JSON reply, empty if Prometheus does not answer
  curl -s --max-time 5 "http://127.0.0.1:19090/api/v1/query" --data-urlencode "query=$1" || true
}

# 100 simulated hall scans published as a robot driver would (LaserScan +
# Odometry, ros_scan_publisher FLAGS...) into a live ingest whose `live`
# section holds MOUNT_KEYS; the recorder gets what comes out.
run_live() {  # MOUNT_KEYS [FLAGS...]
  local mount_keys=$1; shift
  LIVE=100
  "$SF" simulate --scene hall --seed 4 --max-frames $LIVE -o "$WORK/live_in.scanlog.jsonl" > /dev/null
  cat > "$WORK/ingest.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $SRC/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:19471}
source: {kind: live}
live: {scan_topic: scan, odom_topic: odom, $mount_keys, max_pose_gap_s: 0.2, reliable: true}
YAML
  start_pipeline $LIVE
  "$BUILD/services/scan_ingest" --config "$WORK/ingest.yaml" > "$WORK/ingest.log" 2>&1 &
  INGEST=$!; PIDS+=($INGEST)
  "$BUILD/dds_tools/ros_scan_publisher" --domain "$DOMAIN" --rate 50 --reliable "$@" \
    "$WORK/live_in.scanlog.jsonl" > "$WORK/publisher.log" 2>&1 || fail "ros_scan_publisher failed"
  wait "$REC" || fail "recorder did not get $LIVE scans; ingest: $(scrape 19471 | grep -E '^scanfilter_(scans|samples)' | tr '\n' ' ')"
  kill -TERM "$INGEST"; wait "$INGEST" || fail "scan_ingest exited non-zero"
}

# The live run's recorded scans (exactly what the ingest published: float32
# ranges and angles, exact stamps), replayed offline, get the same labels.
live_equals_offline_replay() {
  "$SF" replay "$WORK/live.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/relabelled.scanlog.jsonl" -q
  "$SF" diff "$WORK/relabelled.scanlog.jsonl" "$WORK/live.scanlog.jsonl" ||
    fail "live labels differ from the offline replay of the same scans"
}

prom_query() {  # PromQL: prints "value" of each series, one per line
  local reply
  reply=$(prom_api "$1")
  { grep -o '"value":\[[^]]*\]' <<<"$reply" | sed 's/.*,"\(.*\)"\]/\1/'; } || true
}

# Discovery is asymmetric: a writer may see its reader matched before the
# reader has matched the writer, and a volatile sample sent in between is
# lost. Where both ends export the gauge, wait for both.
wait_jump_to_penetration() {
  wait_matched 19472 writer rt/jump_filtered_scan
  wait_matched 19473 reader rt/jump_filtered_scan
}

"$SF" simulate --scene hall --seed 4 --max-frames $FRAMES -o "$WORK/in.scanlog.jsonl" > /dev/null

case "$CASE" in
labels)
  # Every scan arrives, in order, with exactly the offline replay's labels.
  "$SF" replay "$WORK/in.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/offline.scanlog.jsonl" -q
  start_pipeline $FRAMES
  run_ingest "$WORK/in.scanlog.jsonl"
  wait "$REC" || fail "recorder did not get $FRAMES scans"
  "$SF" diff "$WORK/offline.scanlog.jsonl" "$WORK/live.scanlog.jsonl" || fail "live labels differ from the offline replay"
  ;;
metrics)
  # Each endpoint's counters match what was sent; SIGTERM ends each service with 0 within a second.
  start_pipeline $FRAMES
  run_ingest "$WORK/in.scanlog.jsonl"
  wait "$REC" || fail "recorder did not get $FRAMES scans"
  for svc in jump_filter:19472 penetration_filter:19473; do
    name=${svc%%:*} port=${svc##*:}
    # A scan is counted as published once write() returned, which can be just
    # after the next process got it: give the counters (at most) 5 s to settle.
    deadline=$((SECONDS + 5))
    while :; do
      got=$(metric "$port" "scanfilter_scans_received_total\\{service=\"$name\"\\}")
      pub=$(metric "$port" "scanfilter_scans_published_total\\{service=\"$name\"\\}")
      [ "$got" = $FRAMES ] && [ "$pub" = $FRAMES ] && break
      [ "$SECONDS" -lt "$deadline" ] || fail "$name counted received=$got published=$pub, expected $FRAMES"
      sleep 0.1
    done
    page=$(scrape "$port")
    grep -q "^scanfilter_processing_seconds_bucket{service=\"$name\",le=\"1e-05\"}" <<<"$page" ||
      fail "$name has no processing histogram"
  done
  # The range-noise model step 1 judged the last scan with (beyond-the-paper.md, 18)
  # is the one the offline replay of the same scans ends with.
  offline=$("$SF" replay "$WORK/in.scanlog.jsonl" --config "$SRC/config/filter.yaml")
  offline_base=$(sed -n 's/^step 1 range noise: sigma(d) = \([0-9.]*\) mm .*/\1/p' <<<"$offline")
  page=$(scrape 19472)
  live_base=$(sed -n 's/^scanfilter_range_noise_base_metres{service="jump_filter"} \(.*\)/\1/p' <<<"$page")
  live_mm=$(awk -v b="${live_base:-nan}" 'BEGIN { printf "%.3f", 1000 * b }')
  [ -n "$offline_base" ] && [ "$live_mm" = "$offline_base" ] ||
    fail "jump_filter's range noise base ${live_base:-missing} m, the offline replay's ${offline_base:-missing} mm"
  # The removed-points counters equal the labels that came out (step 2's
  # rescue gives some jump points back, and counts them; its free-space
  # check removes some, counted as removed by penetration_filter).
  info=$("$SF" info "$WORK/live.scanlog.jsonl")
  out_jump=$(echo "$info" | sed -n 's/.* jump=\([0-9]*\).*/\1/p')
  out_mis=$(echo "$info" | sed -n 's/.* misdetected=\([0-9]*\).*/\1/p')
  jump=$(metric 19472 'scanfilter_points_removed_total\{reason="jump",service="jump_filter"\}')
  # Step 2's free-space check also marks jump points (beyond-the-paper.md, 17).
  free_space=$(metric 19473 'scanfilter_points_removed_total\{reason="jump",service="penetration_filter"\}')
  restored=$(metric 19473 'scanfilter_points_restored_total\{service="penetration_filter"\}')
  mis=$(metric 19473 'scanfilter_points_removed_total\{reason="misdetected",service="penetration_filter"\}')
  [ $(( ${jump:-0} + ${free_space:-0} - ${restored:-0} )) = "$out_jump" ] ||
    fail "jump: removed $jump + ${free_space:-0} by step 2 - restored $restored != $out_jump in the output"
  [ "${mis:-0}" = "$out_mis" ] || fail "misdetected: metrics ${mis:-0}, the output has $out_mis"
  for pid in $PEN $JUMP; do
    start=$(date +%s%N)
    kill -TERM "$pid"
    wait "$pid" || fail "service $pid exited non-zero after SIGTERM"
    elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
    [ "$elapsed_ms" -lt $((1000 * TIME_FACTOR)) ] || fail "service $pid took ${elapsed_ms} ms to stop"
  done
  ;;
prometheus)
  # The real Prometheus server scrapes all three services with the scrape
  # config from deploy/monitoring/ (its alert rules read from there); its
  # query API shows them up and the counters.
  command -v prometheus > /dev/null || fail "prometheus is not installed (scripts/install-deps.sh)"
  sed "s/:947\([1234]\)\"/:1947\1\"/g; s#^  - alerts.yml\$#  - $SRC/deploy/monitoring/alerts.yml#" \
    "$SRC/deploy/monitoring/prometheus.yml" > "$WORK/prometheus.yml"
  grep -q "^  - $SRC/deploy/monitoring/alerts.yml\$" "$WORK/prometheus.yml" || fail "the rule file path was not rewritten"
  prometheus --config.file="$WORK/prometheus.yml" --web.listen-address=127.0.0.1:19090 \
    --storage.tsdb.path="$WORK/tsdb" > "$WORK/prometheus.log" 2>&1 &
  PROM=$!; PIDS+=($PROM)
  start_filters
  wait_jump_to_penetration
  ingest_config "$WORK/in.scanlog.jsonl" false
  "$BUILD/services/scan_ingest" --config "$WORK/ingest.yaml" > "$WORK/ingest.log" 2>&1 &
  INGEST=$!; PIDS+=($INGEST)
  ok=""
  deadline=$((SECONDS + 40))
  while [ "$SECONDS" -lt "$deadline" ]; do
    up=$(prom_query 'sum(up{job="scanfilter"})')
    published=$(prom_query 'scanfilter_scans_published_total{service="penetration_filter"}')
    [ "$up" = 3 ] && [ "$published" = $FRAMES ] && ok=1 && break
    sleep 0.1
  done
  [ -n "$ok" ] || fail "Prometheus saw up=$up and penetration_filter published=$published (expected 3 and $FRAMES)"
  ingested=$(prom_query 'scanfilter_scans_published_total{service="scan_ingest"}')
  [ "$ingested" = $FRAMES ] || fail "Prometheus saw scan_ingest published=$ingested"
  # Every query of the Grafana dashboard is valid PromQL over these metrics.
  grep -o '"expr": "[^"]*"' "$SRC/deploy/monitoring/grafana-dashboard.json" | sed 's/"expr": "\(.*\)"/\1/' > "$WORK/exprs"
  [ -s "$WORK/exprs" ] || fail "no queries found in deploy/monitoring/grafana-dashboard.json"
  while read -r expr; do
    reply=$(prom_api "$expr")
    grep -q '"status":"success"' <<<"$reply" || fail "dashboard query rejected by Prometheus: $expr: $reply"
  done < "$WORK/exprs"
  for pid in $INGEST $PEN $JUMP; do kill -TERM "$pid"; wait "$pid" || fail "service $pid exited non-zero"; done
  kill -TERM "$PROM"; wait "$PROM" || true
  ;;
live)
  # A robot driver's LaserScan + Odometry (best effort) into the live ingest:
  # every scan is posed at its stamp and comes out of the pipeline labelled.
  run_live "mount: [-0.05, 0.0, 3.141592653589793]"
  path_in=$("$SF" info "$WORK/live_in.scanlog.jsonl" | sed -n 's/.*path \([0-9.]*\) m/\1/p')
  path_out=$("$SF" info "$WORK/live.scanlog.jsonl" | sed -n 's/.*path \([0-9.]*\) m/\1/p')
  [ "$path_in" = "$path_out" ] || fail "poses differ: path $path_in m in, $path_out m out"
  info_out=$("$SF" info "$WORK/live.scanlog.jsonl")
  [[ "$info_out" =~ labels:\ *valid= ]] || fail "no labels in the output"
  # The driver's side is in the start line, as every stage's inputs are.
  grep -q "started: domain $DOMAIN, rt/scan and rt/odom -> rt/posed_scan" "$WORK/ingest.log" ||
    fail "the live ingest's start line does not name the driver's topics: $(grep started: "$WORK/ingest.log")"
  live_equals_offline_replay
  ;;
live_hold)
  # The live ingest holds while the jump_filter is gone (kill -9, back 7 s
  # later). The driver's scans of that time outlive their odometry (kept
  # 20 x max_pose_gap_s + max_pose_wait_s = 4.5 s of stamps: 2.25 s here, the
  # 10 Hz log played at 20 Hz; the hold begins once the write window of 64
  # fills or the lease of 3 s ends): they are counted as held_too_long, not
  # as no_pose (the odometry never stopped), dropped as they come, during
  # the hold, instead of piling up, and scans flow again after the restart.
  HOLD_FRAMES=300 HOLD_RATE=20
  "$SF" simulate --scene hall --seed 4 --max-frames $HOLD_FRAMES -o "$WORK/live_in.scanlog.jsonl" > /dev/null
  cat > "$WORK/ingest.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $SRC/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:19471}
source: {kind: live}
live: {scan_topic: scan, odom_topic: odom, mount: [-0.05, 0.0, 3.141592653589793], reliable: true}
YAML
  start_filters
  wait_jump_to_penetration
  "$BUILD/services/scan_ingest" --config "$WORK/ingest.yaml" > "$WORK/ingest.log" 2>&1 &
  INGEST=$!; PIDS+=($INGEST)
  wait_matched 19471 writer rt/posed_scan
  "$BUILD/dds_tools/ros_scan_publisher" --domain "$DOMAIN" --rate $HOLD_RATE --reliable \
    "$WORK/live_in.scanlog.jsonl" > "$WORK/publisher.log" 2>&1 &
  PUB=$!; PIDS+=($PUB)
  sleep 2
  kill -KILL "$JUMP"; wait "$JUMP" 2>/dev/null || true
  remaining=(); for pid in "${PIDS[@]}"; do [ "$pid" = "$JUMP" ] || remaining+=("$pid"); done; PIDS=("${remaining[@]}")
  sleep 7
  published_at_restart=$(metric 19471 'scanfilter_scans_published_total\{[^}]*\}')
  held_in_hold=$(metric 19471 'scanfilter_samples_rejected_total\{[^}]*reason="held_too_long"[^}]*\}')
  [ "${held_in_hold:-0}" -gt 0 ] || fail "no scan dropped as held too long during the hold (they would pile up)"
  "$BUILD/services/jump_filter" --domain "$DOMAIN" --metrics-address 127.0.0.1:19472 > "$WORK/jump2.log" 2>&1 &
  JUMP=$!; PIDS+=($JUMP)
  wait "$PUB" || fail "ros_scan_publisher failed"
  sleep 1
  held=$(metric 19471 'scanfilter_samples_rejected_total\{[^}]*reason="held_too_long"[^}]*\}')
  no_pose=$(metric 19471 'scanfilter_samples_rejected_total\{[^}]*reason="no_pose"[^}]*\}')
  published=$(metric 19471 'scanfilter_scans_published_total\{[^}]*\}')
  echo "live hold: published ${published_at_restart:-0} before the restart, ${published:-0} in all;" \
       "held_too_long ${held_in_hold} during the hold, ${held:-0} in all; no_pose ${no_pose:-0}"
  [ "${held:-0}" -gt 0 ] || fail "no scan counted as held too long in a 7 s hold"
  [ "${no_pose:-0}" = 0 ] || fail "$no_pose scans counted as without a pose; the odometry never stopped"
  [ "${published:-0}" -gt "${published_at_restart:-0}" ] || fail "no scan published after the jump_filter came back"
  kill -TERM "$INGEST"; wait "$INGEST" || fail "scan_ingest exited non-zero"
  grep -q "dropped 0 without a pose and ${held} held longer than their odometry is kept" "$WORK/ingest.log" ||
    fail "the ingest's last line does not count the held scans: $(tail -n 2 "$WORK/ingest.log")"
  ;;
upside_down)
  # A LiDAR mounted upside down (roll pi): its driver's counter-clockwise
  # angles turn clockwise about the base. The simulated hall's sensor is
  # such a clockwise one; published with its angles as recorded, into an
  # ingest told `upside_down: true`, every scan is posed, labelled exactly as
  # the offline replay labels the same scans, and nothing is lost.
  run_live "mount: [-0.05, 0.0, 3.141592653589793], upside_down: true" --upside-down
  info_out=$("$SF" info "$WORK/live.scanlog.jsonl")
  [[ "$info_out" =~ \],\ cw, ]] || fail "the ingest did not take the upside-down sensor as clockwise: $info_out"
  live_equals_offline_replay
  # Against the original log (double-precision ranges and angles, which the
  # float32 LaserScan rounds): the same labels but for rounding at thresholds.
  "$SF" replay "$WORK/live_in.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/original.scanlog.jsonl" -q
  differ=$("$SF" diff "$WORK/original.scanlog.jsonl" "$WORK/live.scanlog.jsonl" || true)
  echo "against the double-precision original: $differ"
  [[ "$differ" =~ differ\ in\ ([0-9]+)\ labels ]] && [ "${BASH_REMATCH[1]}" -le 5 ] ||
    fail "upside-down labels far from the original log's: $differ"
  ;;
cyclone|cyclone_upside_down)
  # Another vendor's DDS (Cyclone, localhost only) drives the live ingest and
  # subscribes to the filtered LaserScan, the labelled scan and the map; in
  # cyclone_upside_down the ingest is told the sensor is mounted upside down
  # (the driver's own angles must come back unchanged either way).
  upside_down=false
  [ "$CASE" = cyclone_upside_down ] && upside_down=true
  export CYCLONEDDS_URI='<CycloneDDS><Domain id="any"><General><Interfaces><NetworkInterface address="127.0.0.1" multicast="false"/></Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>20</MaxAutoParticipantIndex><Peers><Peer Address="127.0.0.1"/></Peers></Discovery></Domain></CycloneDDS>'
  start_filters
  cat > "$WORK/ingest.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $SRC/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:19471}
source: {kind: live}
live: {scan_topic: scan, odom_topic: odom, mount: [0.0, 0.0, 0.0], upside_down: $upside_down, reliable: true}
YAML
  printf 'service: {domain_id: %s, profiles_file: %s, metrics_address: 127.0.0.1:19474}\npublishing: {rate_hz: 5}\n' \
    "$DOMAIN" "$SRC/deploy/fastdds-loopback.xml" > "$WORK/map.yaml"
  "$BUILD/services/map_publisher" --config "$WORK/map.yaml" > "$WORK/map.log" 2>&1 &
  PIDS+=($!)
  wait_jump_to_penetration
  "$BUILD/services/scan_ingest" --config "$WORK/ingest.yaml" > "$WORK/ingest.log" 2>&1 &
  INGEST=$!; PIDS+=($INGEST)
  "$BUILD/tests/cyclone_peer" "$DOMAIN" 50 > "$WORK/cyclone.log" 2>&1 || fail "the Cyclone DDS peer did not get what the pipeline sends"
  cat "$WORK/cyclone.log"
  kill -TERM "$INGEST"; wait "$INGEST" || fail "scan_ingest exited non-zero"
  ;;
bad_samples)
  # Malformed samples from the wire are counted by reason, logged once per
  # kind, and dropped; the service keeps running and filters the next scan.
  start_pipeline 1
  "$BUILD/tests/bad_sample_sender" "$DOMAIN" "$SRC/deploy/fastdds-loopback.xml" > "$WORK/sender.log" 2>&1 ||
    fail "bad_sample_sender failed"
  wait "$REC" || fail "the good scan after the bad ones did not come through"
  for reason in length_mismatch nan_pose zero_increment too_many_beams empty; do
    n=$(metric 19472 "scanfilter_samples_rejected_total\\{reason=\"$reason\",service=\"jump_filter\"\\}")
    [ "${n:-0}" = 1 ] || fail "jump_filter counted ${n:-0} '$reason' samples, expected 1"
    grep -q "first '$reason'" "$WORK/jump.log" || fail "no log line for '$reason'"
  done
  kill -0 "$JUMP" || fail "jump_filter died"
  ;;
map)
  # The map publisher: a subscriber that joins after the map was published
  # gets it at once (transient local), and the map it saves on SIGTERM has
  # exactly the cells `scanfilter map` builds offline from the same log.
  start_filters
  cat > "$WORK/map.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $SRC/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:19474}
publishing: {rate_hz: 5, save_path: $WORK/live_map, save_period_s: 1000}
YAML
  "$BUILD/services/map_publisher" --config "$WORK/map.yaml" > "$WORK/map.log" 2>&1 &
  MAP=$!; PIDS+=($MAP)
  wait_jump_to_penetration
  wait_matched 19473 writer rt/labeled_scan
  wait_matched 19474 reader rt/labeled_scan
  run_ingest "$WORK/in.scanlog.jsonl"
  deadline=$((SECONDS + 20))
  while :; do
    mapped=$(metric 19474 'scanfilter_scans_received_total\{service="map_publisher"\}')
    [ "$mapped" = $FRAMES ] && break
    [ "$SECONDS" -lt "$deadline" ] || fail "map_publisher received ${mapped:-no} scans of $FRAMES within 20 s"
    sleep 0.1
  done
  sleep 0.5  # one more publishing period after the last scan
  # Its latencies and integration time, metered like a filter stage's: one observation a scan.
  for histogram in processing_seconds hop_latency_seconds end_to_end_latency_seconds; do
    n=$(metric 19474 "scanfilter_${histogram}_count\\{service=\"map_publisher\"\\}")
    [ "$n" = $FRAMES ] || fail "map_publisher's scanfilter_${histogram} holds ${n:-no} observations, expected $FRAMES"
  done
  probe=$("$BUILD/tests/map_probe" "$DOMAIN" "$SRC/deploy/fastdds-loopback.xml") || fail "the late subscriber got no map"
  echo "late subscriber: $probe"
  read -r width height resolution occupied <<< "$probe"
  [ "$width" -gt 100 ] && [ "$height" -gt 100 ] && [ "$resolution" = 0.050 ] && [ "$occupied" -gt 100 ] ||
    fail "implausible map: $probe"
  kill -TERM "$MAP"; wait "$MAP" || fail "map_publisher exited non-zero"
  "$SF" map "$WORK/in.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/offline_map" > /dev/null
  # The live state file carries the map publisher's note (which scans it holds) after the cells.
  cells=$(stat -c %s "$WORK/offline_map.logodds")
  cmp -n "$cells" "$WORK/live_map.logodds" "$WORK/offline_map.logodds" || fail "live and offline maps differ"
  note=$(tail -c +$((cells + 1)) "$WORK/live_map.logodds")
  grep -q "^scans_integrated: " <<<"$note" || fail "no scan count after the live map's cells: '$note'"
  cmp "$WORK/live_map.pgm" "$WORK/offline_map.pgm" || fail "live and offline PGMs differ"
  ;;
config)
  # A broken config stops each service with a non-zero exit and names the key.
  for svc in scan_ingest jump_filter penetration_filter map_publisher; do
    sed 's/^  queue_depth: 64/  queue_depht: 64/' "$SRC/config/$svc.yaml" > "$WORK/$svc.yaml"
    grep -q queue_depht "$WORK/$svc.yaml" || printf 'service:\n  queue_depht: 64\n' > "$WORK/$svc.yaml"
    sed -i "s#profiles_file: ../deploy#profiles_file: $SRC/deploy#; s#config: filter.yaml#config: $SRC/config/filter.yaml#" "$WORK/$svc.yaml"
    set +e
    out=$("$BUILD/services/$svc" --config "$WORK/$svc.yaml" 2>&1)
    code=$?
    set -e
    [ "$code" -ne 0 ] || fail "$svc accepted a broken config"
    grep -q "service.queue_depht: unknown key (did you mean queue_depth?)" <<<"$out" ||
      fail "$svc did not name the bad key and the one meant: $out"
  done
  # A path or value that cannot work is reported at the line that gave it,
  # and the service exits before publishing anything: "svc.yaml:LINE: KEY: ...".
  refused() {  # svc sed-expression expected-text
    sed "s#profiles_file: ../deploy#profiles_file: $SRC/deploy#; s#config: filter.yaml#config: $SRC/config/filter.yaml#; $2" \
      "$SRC/config/$1.yaml" > "$WORK/$1.yaml"
    set +e
    out=$("$BUILD/services/$1" --config "$WORK/$1.yaml" 2>&1)
    code=$?
    set -e
    [ "$code" -ne 0 ] || fail "$1 accepted $2"
    [[ "$out" == *"$WORK/$1.yaml:"*": $3"* ]] || fail "$1 with $2 did not say \"$3\" at its line: $out"
  }
  refused scan_ingest 's#^  kind: simulator#  kind: log#; s#^  path: ""#  path: /nonexistent.jsonl#' \
    "source.path: no such file: /nonexistent.jsonl"
  refused scan_ingest 's#^  scene: hall#  scene: kitchen#' "source.scene: kitchen: no such scene"
  refused scan_ingest 's#^  wait_timeout_s: 30.0#  wait_timeout_s: -1#' "playback.wait_timeout_s: expected 0-86400 (s), got -1"
  refused jump_filter "s#config: $SRC/config/filter.yaml#config: filtr.yaml#" "filter.config: no such file: $WORK/filtr.yaml"
  refused map_publisher 's#^  save_path: ""#  save_path: /nonexistent/map#' \
    "publishing.save_path: no such folder: /nonexistent (the map is saved as map.pgm/.yaml/.png in it)"
  ;;
launcher)
  # deploy/run-pipeline.sh (what scripts/demo.sh runs) starts the ingest as
  # soon as the stages downstream are matched - seconds, not its 30 s timeout -
  # exits 0, and records every scan with the offline replay's labels.
  LAUNCH=100
  "$SF" simulate --scene hall --seed 4 --max-frames $LAUNCH -o "$WORK/launch_in.scanlog.jsonl" > /dev/null
  "$SF" replay "$WORK/launch_in.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/launch_offline.scanlog.jsonl" -q
  launch() {  # log rate out-dir: deploy/run-pipeline.sh on that log; sets out and code
    set +e
    out=$(BUILD_DIR="$BUILD" timeout -k 10 120 bash "$SRC/deploy/run-pipeline.sh" --log "$1" --rate "$2" --out "$3" \
            --domain "$DOMAIN" 2>&1)
    code=$?
    set -e
  }
  launched_ms=$(date +%s%3N)
  launch "$WORK/launch_in.scanlog.jsonl" max "$WORK/launch"
  echo "$out"
  [ "$code" = 0 ] || fail "run-pipeline.sh exited with $code"
  # Its own account: every stage matched, and how long that took.
  grep -q "^stages matched: waited [0-9.]* s" <<<"$out" || fail "run-pipeline.sh did not report the stages matched"
  waited=$(sed -n 's/^stages matched: waited \([0-9]*\)\.[0-9] s.*/\1/p' <<<"$out")
  [ -n "$waited" ] && [ "$waited" -lt $((5 * TIME_FACTOR)) ] || fail "run-pipeline.sh waited ${waited:-?} s for the stages to match"
  # The ingest's own start time (its first log line), independent of that.
  first=$(sed -n '1s/^\[\([0-9-]* [0-9:.]*\)\] \[scan_ingest\] \[info\] .*/\1/p' "$WORK/launch/scan_ingest.log")
  [ -n "$first" ] || fail "no start line in scan_ingest.log"
  started_after_ms=$(( $(date -d "$first" +%s%3N) - launched_ms ))
  echo "scan_ingest started ${started_after_ms} ms after the launch"
  [ "$started_after_ms" -lt $((8000 * TIME_FACTOR)) ] || fail "scan_ingest started ${started_after_ms} ms after the launch"
  info=$("$SF" info "$WORK/launch/pipeline.labeled.scanlog.jsonl")
  grep -q "^scans: *$LAUNCH " <<<"$info" && grep -q "labels: $LAUNCH scans" <<<"$info" ||
    fail "the labelled output is not $LAUNCH labelled scans: $info"
  "$SF" diff "$WORK/launch_offline.scanlog.jsonl" "$WORK/launch/pipeline.labeled.scanlog.jsonl" ||
    fail "the launcher's labels differ from the offline replay"
  grep -q "^scan_ingest published $LAUNCH scans; the recorder holds $LAUNCH$" <<<"$out" ||
    fail "run-pipeline.sh did not report $LAUNCH scans published and recorded"
  grep -q "^labelled output: $WORK/launch/pipeline.labeled.scanlog.jsonl$" <<<"$out" ||
    fail "run-pipeline.sh did not say where the labelled output is"
  # Its arguments are checked before anything starts, naming the argument.
  launch "$WORK/launch_in.scanlog.jsonl" fast "$WORK/bad_rate"
  [ "$code" = 2 ] && [[ "$out" == "--rate: expected recorded, max or a speed factor > 0, got fast"* ]] ||
    fail "run-pipeline.sh --rate fast: exit $code: $out"
  [ ! -e "$WORK/bad_rate" ] || fail "run-pipeline.sh --rate fast made its output directory"
  # An ingest that fails: its reason in the launcher's own output, and no
  # output named that was not written.
  head -c 20000 "$WORK/launch_in.scanlog.jsonl" > "$WORK/cut.scanlog.jsonl"
  launch "$WORK/cut.scanlog.jsonl" max "$WORK/cut"
  [ "$code" = 2 ] || fail "run-pipeline.sh on a log cut short exited with $code: $out"
  [[ "$out" == *"scan_ingest failed (exit 2): $WORK/cut.scanlog.jsonl:"*"a file cut short?) (see $WORK/cut/scan_ingest.log)"* ]] ||
    fail "run-pipeline.sh did not say why the ingest failed: $out"
  [[ "$out" != *"labelled output:"* && "$out" != *"map: "* ]] || fail "run-pipeline.sh named outputs it did not write: $out"
  [ ! -e "$WORK/cut/pipeline.labeled.scanlog.jsonl" ] || fail "a log cut short was published in part"
  # A log that pauses (the robot's logging stopped for a while), replayed at
  # its recorded pace: the pause is no end of the source, every scan is
  # recorded (the recorder once stopped 2 s after the last scan it got), and
  # the ingest says why it waits: the pause, with the scan period before it
  # (0.1 s), is longer than the default playback.wait_notice_s, 5 s.
  PAUSED=20 PAUSE_S=6
  "$SF" simulate --scene hall --seed 5 --max-frames $PAUSED -o "$WORK/paused_src.scanlog.jsonl" > /dev/null
  paused_copy() {  # SECONDS OUT: the log with every scan after its first half that much later
    # Line 1 is the header; a scan line's first key is its stamp, `{"stamp":S,...`.
    awk -F'"stamp":' -v half=$((PAUSED / 2)) -v pause="$1" '
      NR > half + 1 { split($2, value, ","); $0 = $1 "\"stamp\":" sprintf("%.9f", value[1] + pause) substr($2, length(value[1]) + 1) }
      { print }' "$WORK/paused_src.scanlog.jsonl" > "$2"
  }
  paused_copy "$PAUSE_S" "$WORK/paused.scanlog.jsonl"
  paused_info=$("$SF" info "$WORK/paused.scanlog.jsonl") || fail "the paused log does not read"
  grep -q "^scans: *$PAUSED " <<<"$paused_info" || fail "the paused log is not $PAUSED scans: $paused_info"
  # The pause is in: the log lasts longer than it (the scans alone take 2 s at 10 Hz).
  paused_s=$(sed -n 's/^duration: *\([0-9]*\).*/\1/p' <<<"$paused_info")
  [ "${paused_s:-0}" -ge "$PAUSE_S" ] || fail "the paused log has no $PAUSE_S s pause: $paused_info"
  launch "$WORK/paused.scanlog.jsonl" recorded "$WORK/paused"
  [ "$code" = 0 ] || fail "run-pipeline.sh on a log with a $PAUSE_S s pause exited with $code: $out"
  grep -q "^scan_ingest published $PAUSED scans; the recorder holds $PAUSED$" <<<"$out" ||
    fail "run-pipeline.sh on a log with a $PAUSE_S s pause: $out"
  info=$("$SF" info "$WORK/paused/pipeline.labeled.scanlog.jsonl")
  grep -q "^scans: *$PAUSED " <<<"$info" && grep -q "labels: $PAUSED scans" <<<"$info" ||
    fail "the labelled output of the paused log is not $PAUSED labelled scans: $info"
  ingest_log=$(cat "$WORK/paused/scan_ingest.log")
  notices=$(grep -c "waiting [0-9.]* s for scan $((PAUSED / 2)): the recording pauses $PAUSE_S\.1 s before it" <<<"$ingest_log" || true)
  [ "$notices" = 1 ] || fail "scan_ingest did not say once that it waits for the pause: $ingest_log"
  waits=$(grep -c "waiting [0-9.]* s for scan" <<<"$ingest_log" || true)
  [ "$waits" = 1 ] || fail "scan_ingest announced waits where the log has no pause: $ingest_log"
  # A pause of an hour (the csail CARMEN log's stamps jump 10,000 s): SIGTERM
  # during the wait ends the ingest at once, with the scans before it published.
  paused_copy 3600 "$WORK/hour.scanlog.jsonl"
  cat > "$WORK/hour_ingest.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $SRC/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:19471}
source: {kind: log, path: $WORK/hour.scanlog.jsonl, rate: recorded}
playback: {wait_for_subscribers: 0, exit_at_end: true}
YAML
  "$BUILD/services/scan_ingest" --config "$WORK/hour_ingest.yaml" > "$WORK/hour_ingest.log" 2>&1 &
  HOUR=$!; PIDS+=($HOUR)
  deadline=$((SECONDS + 30))
  until grep -q "waiting [0-9.]* s for scan $((PAUSED / 2)): the recording pauses 3600.1 s" "$WORK/hour_ingest.log"; do
    [ "$SECONDS" -lt "$deadline" ] || fail "scan_ingest did not announce the hour's wait: $(cat "$WORK/hour_ingest.log")"
    sleep 0.1
  done
  stop_ms=$(date +%s%3N)
  kill -TERM "$HOUR"
  # Polled, not waited for: an ingest that sleeps on must fail the test, not hang it.
  while kill -0 "$HOUR" 2>/dev/null && [ $(( $(date +%s%3N) - stop_ms )) -lt $((3000 * TIME_FACTOR)) ]; do sleep 0.05; done
  kill -0 "$HOUR" 2>/dev/null && fail "scan_ingest still runs $((3 * TIME_FACTOR)) s after SIGTERM in a wait"
  stopped_ms=$(( $(date +%s%3N) - stop_ms ))
  set +e
  wait "$HOUR"
  code=$?
  set -e
  echo "scan_ingest stopped within ${stopped_ms} ms of SIGTERM in an hour's wait"
  [ "$code" = 0 ] || fail "scan_ingest exited with $code on SIGTERM in a wait: $(cat "$WORK/hour_ingest.log")"
  grep -q "published $((PAUSED / 2)) scans" "$WORK/hour_ingest.log" ||
    fail "scan_ingest did not publish the $((PAUSED / 2)) scans before the wait: $(cat "$WORK/hour_ingest.log")"
  ;;
*) echo "unknown case $CASE"; exit 2 ;;
esac
echo "PASS: $CASE"
