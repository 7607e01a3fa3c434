#!/usr/bin/env bash
# DDS Security tests: the services with authentication (PKI-DH), access
# control (signed governance and permissions) and encryption (AES-GCM), on a
# keystore made at test time by deploy/security/make-keystore.sh with real
# openssl. Real processes on loopback, in a private network namespace when
# possible (unshare -n), else on their own domain id.
#
#   secure_pipeline_test.sh BUILD_DIR SOURCE_DIR CASE
#   CASE: labels | live | intruders | permissions | discovery_server | config
set -euo pipefail
BUILD="$1" SRC="$2" CASE="$3"
source "$(dirname "$0")/../lib/dds_test_workspace.sh"  # private network namespace, DOMAIN, WORK, PIDS, cleanup
source "$(dirname "$0")/../lib/service_checks.sh"  # scrape, metric, matched, wait_matched (watching WATCH), fail
SF="$BUILD/tools/scanfilter"
PROFILES="$SRC/deploy/fastdds-loopback.xml"
INJECT="$BUILD/tests/security/scan_injector"
RECORD="$BUILD/dds_tools/scan_recorder"
FRAMES=100
# Authentication handshakes make discovery slower than without security:
# bounds for matching and for a whole run.
MATCH_WAIT_S=40
RUN_TIMEOUT_S=120
# How long an intruder tries: several times what matching takes on this
# machine with security on (about 2 s), so a match would have happened; the
# valid-certificate control below shows it does within this time.
INTRUDE_S=10

# The keystore for this domain, and a rogue one: the same enclave names and
# topics, signed by other CAs (a certificate that looks right but is not ours).
bash "$SRC/deploy/security/make-keystore.sh" --domain "$DOMAIN" --days 2 "$WORK/keystore" > "$WORK/keystore.log" 2>&1 ||
  fail "make-keystore.sh failed: $(cat "$WORK/keystore.log")"
bash "$SRC/deploy/security/make-keystore.sh" --domain "$DOMAIN" --days 2 "$WORK/rogue" > "$WORK/rogue_keystore.log" 2>&1 ||
  fail "make-keystore.sh (rogue) failed"
ENCLAVES="$WORK/keystore/enclaves/scanfilter"
ROGUE="$WORK/rogue/enclaves/scanfilter"

received() {  # port service: scanfilter_scans_received_total, 0 when not counted yet (the page must answer)
  local page n
  page=$(scrape "$1")
  [ -n "$page" ] || fail "$2's metrics endpoint :$1 does not answer"
  n=$({ grep -E "^scanfilter_scans_received_total\\{service=\"$2\"\\} " <<<"$page" | awk '{print int($2)}'; } || true)
  echo "${n:-0}"
}

WATCH=()  # services that must stay up while we wait for them

# pid log what: the service logs "started:" within MATCH_WAIT_S, then stops
# cleanly on SIGTERM.
starts_and_stops() {
  local pid=$1 log=$2 what=$3 deadline=$((SECONDS + MATCH_WAIT_S))
  PIDS+=("$pid")
  until grep -qs "started:" "$log"; do
    kill -0 "$pid" 2>/dev/null || fail "$what did not start"
    [ "$SECONDS" -lt "$deadline" ] || fail "$what did not start within $MATCH_WAIT_S s"
    sleep 0.1
  done
  kill -TERM "$pid"; wait "$pid" || fail "$what exited non-zero"
}
config() {  # name metrics-port enclave [extra YAML lines]: a service config on this domain
  local name=$1 port=$2 enclave=$3
  shift 3
  {
    echo "service:"
    echo "  domain_id: $DOMAIN"
    echo "  profiles_file: $PROFILES"
    echo "  metrics_address: 127.0.0.1:$port"
    [ -z "$enclave" ] || echo "  security: {enclave: $enclave}"
    for line in "$@"; do echo "$line"; done
  } > "$WORK/$name.yaml"
}

FILTER_SECTION="filter: {config: $SRC/config/filter.yaml}"

start_filters() {  # the two filter stages, secured, matched with each other
  config jump_filter 19472 "$ENCLAVES/jump_filter" "$FILTER_SECTION"
  config penetration_filter 19473 "$ENCLAVES/penetration_filter" "$FILTER_SECTION"
  "$BUILD/services/penetration_filter" --config "$WORK/penetration_filter.yaml" > "$WORK/penetration.log" 2>&1 &
  PEN=$!; PIDS+=($PEN)
  "$BUILD/services/jump_filter" --config "$WORK/jump_filter.yaml" > "$WORK/jump.log" 2>&1 &
  JUMP=$!; PIDS+=($JUMP)
  WATCH=($PEN $JUMP)
  wait_matched 19472 writer rt/jump_filtered_scan
  wait_matched 19473 reader rt/jump_filtered_scan
}

start_recorder() {  # label enclave-or-empty count: a scan_recorder of rt/labeled_scan
  local label=$1 enclave=$2 count=$3
  local args=(--domain "$DOMAIN" --profiles-file "$PROFILES" --count "$count" --timeout "$RUN_TIMEOUT_S"
              -o "$WORK/$label.scanlog.jsonl")
  [ -z "$enclave" ] || args+=(--enclave "$enclave")
  "$RECORD" "${args[@]}" > "$WORK/$label.log" 2>&1 &
  PIDS+=($!)
  LAST_PID=$!
}

run_ingest() {  # log file: the secured ingest publishes every scan and exits
  config scan_ingest 19471 "$ENCLAVES/scan_ingest" \
    "source: {kind: log, path: $1, rate: max}" \
    "playback: {wait_for_subscribers: 1, wait_timeout_s: $MATCH_WAIT_S, exit_at_end: true}"
  timeout -k 5 "$RUN_TIMEOUT_S" "$BUILD/services/scan_ingest" --config "$WORK/scan_ingest.yaml" > "$WORK/ingest.log" 2>&1 ||
    fail "the secured scan_ingest exited non-zero"
}

inject() {  # label topic [enclave]: scan_injector for INTRUDE_S; sets INJECT_CODE and INJECT_OUT
  set +e
  INJECT_OUT=$(timeout -k 5 $((INTRUDE_S + 60)) "$INJECT" "$DOMAIN" "$PROFILES" "$2" "$INTRUDE_S" ${3:+"$3"} 2> "$WORK/inject_$1.log")
  INJECT_CODE=$?
  set -e
  echo "injector $1 on $2: exit $INJECT_CODE: $INJECT_OUT"
}

stop_recorder() {  # pid label: SIGTERM; sets RECORDED to what it says it recorded
  kill -TERM "$1" 2>/dev/null || true  # it may have reached its own --timeout
  wait "$1" || fail "recorder $2 exited non-zero"
  RECORDED=$(sed -n 's/^recorded \([0-9]*\) scans.*/\1/p' "$WORK/$2.log")
}

"$SF" simulate --scene hall --seed 4 --max-frames $FRAMES -o "$WORK/in.scanlog.jsonl" > /dev/null

case "$CASE" in
labels)
  # Secured end to end: every scan arrives with exactly the offline replay's labels.
  "$SF" replay "$WORK/in.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/offline.scanlog.jsonl" -q
  start_filters
  start_recorder secured "$ENCLAVES/recorder" $FRAMES
  REC=$LAST_PID
  wait_matched 19473 writer rt/labeled_scan
  run_ingest "$WORK/in.scanlog.jsonl"
  wait "$REC" || fail "the secured recorder did not get $FRAMES scans"
  "$SF" diff "$WORK/offline.scanlog.jsonl" "$WORK/secured.scanlog.jsonl" ||
    fail "secured labels differ from the offline replay"
  # Security on is said where an operator looks first: the start line (and systemd's STATUS).
  grep -q "started: .*, DDS Security on (enclave $ENCLAVES/scan_ingest)" "$WORK/ingest.log" ||
    fail "the secured ingest's start line does not say security is on: $(grep started: "$WORK/ingest.log")"
  ;;
live)
  # A robot driver with its own enclave (driver: publishes rt/scan and
  # rt/odom only) feeds the secured live ingest; every scan comes out
  # labelled as the offline replay of what the ingest published labels it.
  start_filters
  start_recorder secured "$ENCLAVES/recorder" $FRAMES
  REC=$LAST_PID
  wait_matched 19473 writer rt/labeled_scan
  config scan_ingest 19471 "$ENCLAVES/scan_ingest" "source: {kind: live}" \
    "live: {scan_topic: scan, odom_topic: odom, mount: [0.0, 0.0, 0.0], max_pose_gap_s: 0.2, reliable: true}"
  "$BUILD/services/scan_ingest" --config "$WORK/scan_ingest.yaml" > "$WORK/ingest.log" 2>&1 &
  INGEST=$!; PIDS+=($INGEST)
  WATCH+=($INGEST)
  wait_matched 19472 reader rt/posed_scan
  timeout -k 5 "$RUN_TIMEOUT_S" "$BUILD/dds_tools/ros_scan_publisher" --domain "$DOMAIN" --profiles-file "$PROFILES" \
    --enclave "$ENCLAVES/driver" --rate 50 --reliable "$WORK/in.scanlog.jsonl" > "$WORK/publisher.log" 2>&1 ||
    fail "ros_scan_publisher with the driver enclave failed"
  wait "$REC" || fail "the secured recorder did not get $FRAMES scans from the live ingest"
  kill -TERM "$INGEST"; wait "$INGEST" || fail "scan_ingest exited non-zero"
  "$SF" replay "$WORK/secured.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/relabelled.scanlog.jsonl" -q
  "$SF" diff "$WORK/relabelled.scanlog.jsonl" "$WORK/secured.scanlog.jsonl" ||
    fail "secured live labels differ from the offline replay of the same scans"
  ;;
intruders)
  # Participants without a valid certificate - none at all, or one from
  # another CA - neither read rt/labeled_scan nor get a scan into
  # rt/posed_scan, while the secured pipeline runs beside them.
  start_filters
  start_recorder plain "" 0
  PLAIN=$LAST_PID
  start_recorder rogue "$ROGUE/recorder" 0
  ROGUE_REC=$LAST_PID
  for who in plain:"" rogue:"$ROGUE/scan_ingest"; do
    inject "${who%%:*}" rt/posed_scan "${who#*:}"
    [ "$INJECT_CODE" = 0 ] || fail "the ${who%%:*} injector could not even run (exit $INJECT_CODE): $INJECT_OUT"
    [[ "$INJECT_OUT" =~ ^matched\ 0,\ written\ [1-9] ]] || fail "the ${who%%:*} injector matched a reader: $INJECT_OUT"
  done
  n=$(received 19472 jump_filter)
  [ "$n" = 0 ] || fail "jump_filter received $n scans from participants without a valid certificate"
  # The positive control: the secured ingest and recorder on the same run.
  start_recorder secured "$ENCLAVES/recorder" $FRAMES
  REC=$LAST_PID
  wait_matched 19473 writer rt/labeled_scan
  # It matched the secured recorder alone: the two without a valid
  # certificate have been up since before the injectors ran.
  n=$(matched 19473 writer rt/labeled_scan)
  [ "${n:-0}" = 1 ] || fail "penetration_filter's rt/labeled_scan writer matched ${n:-0} readers, expected 1 (the secured recorder)"
  run_ingest "$WORK/in.scanlog.jsonl"
  wait "$REC" || fail "the secured recorder did not get $FRAMES scans"
  n=$(received 19472 jump_filter)
  [ "$n" = $FRAMES ] || fail "jump_filter received $n scans from the secured ingest, expected $FRAMES"
  for who in plain rogue; do
    pid=$PLAIN
    [ "$who" = rogue ] && pid=$ROGUE_REC
    stop_recorder "$pid" "$who"
    [ "$RECORDED" = 0 ] || fail "the $who recorder without a valid certificate read ${RECORDED:-?} labelled scans"
    [ ! -e "$WORK/$who.scanlog.jsonl" ] || fail "the $who recorder wrote a scan log"
  done
  # And the injector itself delivers when its certificate is valid: a
  # "matched 0" above is the security's doing, not the tool's.
  inject valid rt/posed_scan "$ENCLAVES/scan_ingest"
  [[ "$INJECT_OUT" =~ ^matched\ [1-9] ]] || fail "the injector with the scan_ingest enclave did not match: $INJECT_OUT"
  deadline=$((SECONDS + 10))
  while n=$(received 19472 jump_filter); [ "$n" -le $FRAMES ]; do
    [ "$SECONDS" -lt "$deadline" ] || fail "jump_filter got nothing from the injector with a valid certificate"
    sleep 0.1
  done
  ;;
permissions)
  # A valid certificate without a grant for a topic: Fast DDS refuses the
  # participant's own writer (or reader) on it, and nothing reaches the
  # jump_filter; with the grant (the scan_ingest enclave) the same tool delivers.
  start_filters
  for who in recorder:rt/posed_scan map_publisher:rt/posed_scan jump_filter:rt/labeled_scan driver:rt/posed_scan; do
    inject "${who%%:*}" "${who#*:}" "$ENCLAVES/${who%%:*}"
    [ "$INJECT_CODE" = 3 ] || fail "the ${who%%:*} enclave was not refused a writer on ${who#*:} (exit $INJECT_CODE): $INJECT_OUT"
    [[ "$INJECT_OUT" =~ refused:\ cannot\ create\ a\ writer\ on\ ${who#*:} ]] ||
      fail "unexpected refusal for ${who%%:*}: $INJECT_OUT"
  done
  # A reader without a grant: the map_publisher's enclave may not read rt/posed_scan.
  set +e
  out=$(timeout -k 5 60 "$RECORD" --domain "$DOMAIN" --profiles-file "$PROFILES" --topic posed_scan --timeout 5 \
          --enclave "$ENCLAVES/map_publisher" -o "$WORK/denied.scanlog.jsonl" 2>&1)
  code=$?
  set -e
  echo "recorder with the map_publisher enclave on rt/posed_scan: exit $code: $out"
  [ "$code" = 1 ] && grep -q "cannot create a reader on rt/posed_scan" <<<"$out" ||
    fail "the map_publisher enclave was not refused a reader on rt/posed_scan"
  n=$(received 19472 jump_filter)
  [ "$n" = 0 ] || fail "jump_filter received $n scans from enclaves without the grant"
  inject scan_ingest rt/posed_scan "$ENCLAVES/scan_ingest"
  [ "$INJECT_CODE" = 0 ] && [[ "$INJECT_OUT" =~ ^matched\ [1-9] ]] ||
    fail "the scan_ingest enclave could not publish on rt/posed_scan: $INJECT_OUT"
  deadline=$((SECONDS + 10))
  while n=$(received 19472 jump_filter); [ "$n" = 0 ]; do
    [ "$SECONDS" -lt "$deadline" ] || fail "jump_filter got nothing from the scan_ingest enclave"
    sleep 0.1
  done
  ;;
discovery_server)
  # Fast DDS 2.9 cannot secure a Discovery Server: a service with both
  # configured stops at once with a message that says so, whichever way the
  # server was configured (ROS_DISCOVERY_SERVER, the XML profile, or
  # service.discovery.servers).
  config jump_filter 19472 "$ENCLAVES/jump_filter" "$FILTER_SECTION"
  # Into the profile's own discovery_config (it sets the participant lease):
  # a second discovery_config element would not parse.
  grep -q "<discovery_config>" "$PROFILES" || fail "$PROFILES has no discovery_config to extend"
  sed "s#<discovery_config>#<discovery_config>\n            <discoveryProtocol>CLIENT</discoveryProtocol>\n            <discoveryServersList>\n              <RemoteServer prefix=\"44.53.00.5f.45.50.52.4f.53.49.4d.41\">\n                <metatrafficUnicastLocatorList><locator><udpv4><address>127.0.0.1</address><port>11811</port></udpv4></locator></metatrafficUnicastLocatorList>\n              </RemoteServer>\n            </discoveryServersList>#" \
    "$PROFILES" > "$WORK/client-profiles.xml"
  grep -q "<discoveryProtocol>CLIENT" "$WORK/client-profiles.xml" || fail "could not write the client profile"
  sed "s#profiles_file: .*#profiles_file: $WORK/client-profiles.xml#" "$WORK/jump_filter.yaml" > "$WORK/jump_client.yaml"
  sed 's#^  security:#  discovery: {servers: ["127.0.0.1:11811"]}\n  security:#' "$WORK/jump_filter.yaml" > "$WORK/jump_keys.yaml"
  grep -q "servers:" "$WORK/jump_keys.yaml" || fail "could not write the service.discovery.servers config"
  for how in env profile keys; do
    set +e
    case "$how" in
      env) out=$(ROS_DISCOVERY_SERVER=127.0.0.1:11811 timeout -k 5 60 "$BUILD/services/jump_filter" --config "$WORK/jump_filter.yaml" 2>&1) ;;
      profile) out=$(timeout -k 5 60 "$BUILD/services/jump_filter" --config "$WORK/jump_client.yaml" 2>&1) ;;
      keys) out=$(timeout -k 5 60 "$BUILD/services/jump_filter" --config "$WORK/jump_keys.yaml" 2>&1) ;;
    esac
    code=$?
    set -e
    echo "security + discovery server ($how): exit $code: $out"
    [ "$code" != 0 ] && [ "$code" != 124 ] || fail "jump_filter ran with security and a Discovery Server ($how), exit $code"
    grep -q "DDS Security and a Discovery Server are both configured" <<<"$out" ||
      fail "no clear message for security + Discovery Server ($how)"
  done
  # Each alone starts: the refusal is the combination's.
  config jump_plain 19472 "" "$FILTER_SECTION"
  for how in env profile; do
    if [ "$how" = env ]; then
      ROS_DISCOVERY_SERVER=127.0.0.1:11811 "$BUILD/services/jump_filter" --config "$WORK/jump_plain.yaml" > "$WORK/ds_$how.log" 2>&1 &
    else
      sed "s#profiles_file: .*#profiles_file: $WORK/client-profiles.xml#" "$WORK/jump_plain.yaml" > "$WORK/jump_plain_client.yaml"
      "$BUILD/services/jump_filter" --config "$WORK/jump_plain_client.yaml" > "$WORK/ds_$how.log" 2>&1 &
    fi
    starts_and_stops $! "$WORK/ds_$how.log" "jump_filter with a Discovery Server ($how) and no security"
  done
  # And the secured service without a Discovery Server starts.
  "$BUILD/services/jump_filter" --config "$WORK/jump_filter.yaml" > "$WORK/secured.log" 2>&1 &
  starts_and_stops $! "$WORK/secured.log" "the secured jump_filter"
  ;;
config)
  # A broken enclave stops the service at start (exit 2) naming the key and the file.
  cp -r "$ENCLAVES/jump_filter" "$WORK/broken_enclave"
  rm "$WORK/broken_enclave/permissions.p7s"
  for enclave in "$WORK/broken_enclave" "$WORK/no_such_enclave"; do
    config jump_filter 19472 "$enclave" "$FILTER_SECTION"
    set +e
    out=$(timeout -k 5 60 "$BUILD/services/jump_filter" --config "$WORK/jump_filter.yaml" 2>&1)
    code=$?
    set -e
    echo "enclave $enclave: exit $code: $out"
    [ "$code" = 2 ] || fail "jump_filter accepted the enclave $enclave (exit $code)"
    grep -q "service.security.enclave" <<<"$out" || fail "the error does not name service.security.enclave: $out"
    if [ "$enclave" = "$WORK/broken_enclave" ] && ! grep -q "lacks $WORK/broken_enclave/permissions.p7s" <<<"$out"; then
      fail "the error does not name the missing permissions.p7s: $out"
    fi
  done
  # A tool given a broken enclave on its command line says which file is missing.
  set +e
  out=$(timeout -k 5 60 "$RECORD" --domain "$DOMAIN" --timeout 1 --enclave "$WORK/broken_enclave" -o "$WORK/x.jsonl" 2>&1)
  code=$?
  set -e
  [ "$code" = 1 ] && grep -q "permissions.p7s" <<<"$out" || fail "scan_recorder with a broken enclave: exit $code: $out"
  # A certificate from another CA than the enclave's identity CA: the participant is refused at start.
  cp -r "$ENCLAVES/jump_filter" "$WORK/mixed_enclave"
  cp "$ROGUE/jump_filter/cert.pem" "$ROGUE/jump_filter/key.pem" "$WORK/mixed_enclave/"
  config jump_filter 19472 "$WORK/mixed_enclave" "$FILTER_SECTION"
  set +e
  out=$(timeout -k 5 60 "$BUILD/services/jump_filter" --config "$WORK/jump_filter.yaml" 2>&1)
  code=$?
  set -e
  echo "certificate from another CA: exit $code: $(tail -n 1 <<<"$out")"
  [ "$code" = 1 ] && grep -q "cannot create a DDS participant.*DDS Security is on" <<<"$out" ||
    fail "jump_filter started with a certificate from another CA (exit $code): $out"
  ;;
*) echo "unknown case $CASE"; exit 2 ;;
esac
echo "PASS: $CASE"
