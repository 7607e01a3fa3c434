#!/usr/bin/env bash
# Runs an installed scanfilter the way its systemd units say, on a scan log,
# and checks what comes out. Used by prefix_install_test.sh and deb_test.sh;
# run it in a private network namespace (the installed configs use the
# default domain and ports).
#
#   run_installed_pipeline.sh UNIT_DIR BIN_DIR MAP_BASE LOG WORK [--as-unit-user] [--hide DIR]...
#
# - Starts the four services from UNIT_DIR/scanfilter-*.service: the command
#   of ExecStart= exactly, from /, with an empty environment (as systemd
#   would), as the unit's User= with --as-unit-user; map_publisher first,
#   scan_ingest last (the units' After= order).
# - Each --hide DIR is covered by an empty read-only tmpfs in the services'
#   own mount namespace: an installed service must not need the source or
#   build tree.
# - Publishes LOG as the robot's driver would (BIN_DIR/scanfilter-ros-scan-publisher
#   into the live scan_ingest of the installed config) and records the
#   labelled output (BIN_DIR/scanfilter-scan-recorder).
# - Stops the services with SIGTERM (each must exit 0) and checks the map the
#   map publisher saved at MAP_BASE.{pgm,yaml,png,logodds}.
set -euo pipefail
UNITS="$1" BIN="$2" MAP_BASE="$3" LOG="$4" WORK="$5"
shift 5
AS_UNIT_USER=0
HIDE=()
while [ $# -gt 0 ]; do
  case "$1" in
    --as-unit-user) AS_UNIT_USER=1; shift ;;
    --hide) HIDE+=("$2"); shift 2 ;;
    *) echo "unknown argument $1"; exit 2 ;;
  esac
done
# Bounds on waiting (a loaded machine): discovery, and the recorder's end.
MATCH_TIMEOUT_S=30
RECORD_TIMEOUT_S=120
# The driver's pace (scans/s): well within what the pipeline keeps up with.
PUBLISH_RATE_HZ=20

PIDS=()
declare -A PID_OF
cleanup() {
  for pid in "${PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*"
  for f in "$WORK"/*.log; do
    if [ -f "$f" ]; then echo "--- $f"; tail -n 20 "$f"; fi
  done
  exit 1
}

unit_key() {  # unit-file key: its value; exactly one such line expected
  local values
  values=$(sed -n "s/^$2=//p" "$1")
  [ "$(grep -c . <<<"$values")" = 1 ] || fail "$1: expected one $2= line, got: $values"
  echo "$values"
}

# The unit's command as systemd runs it: from /, with nothing inherited from
# this environment, as the unit's user, the hidden trees covered.
start_unit() {  # service name (scanfilter-NAME.service)
  local unit="$UNITS/scanfilter-$1.service" command user
  [ -f "$unit" ] || fail "no unit $unit"
  command=$(unit_key "$unit" ExecStart)
  local -a argv
  read -ra argv <<<"$command"
  [[ "${argv[0]}" == "$BIN"/* && -x "${argv[0]}" ]] || fail "$unit: ExecStart ${argv[0]} is not an installed binary in $BIN"
  local -a as_user=()
  if [ "$AS_UNIT_USER" = 1 ]; then
    user=$(unit_key "$unit" User)
    as_user=(setpriv "--reuid=$user" "--regid=$user" --init-groups --)
  fi
  # shellcheck disable=SC2016  # expanded by the inner shell
  (cd / && exec unshare -m bash -c 'for d in "${@:2:$1}"; do mount -t tmpfs -o ro,size=4k none "$d"; done
                                    shift $(($1 + 1)); exec "$@"' \
     _ "${#HIDE[@]}" "${HIDE[@]}" env -i PATH=/usr/bin:/bin "${as_user[@]}" "${argv[@]}") \
     > "$WORK/$1.log" 2>&1 &
  PID_OF[$1]=$!
  PIDS+=($!)
}

scrape() {  # port: the metrics page, empty if it does not answer (captured: no curl into grep under pipefail)
  curl -s --max-time 2 "http://127.0.0.1:$1/metrics" || true
}
matched() {  # port endpoint topic: that endpoint's matched peers
  local page
  page=$(scrape "$1")
  awk -v ep="endpoint=\"$2\"" -v topic="topic=\"$3\"" \
    'index($0, "scanfilter_dds_matched{") == 1 && index($0, ep) && index($0, topic) {print int($2)}' <<<"$page"
}
wait_matched() {  # port endpoint topic count
  local deadline=$((SECONDS + MATCH_TIMEOUT_S)) n
  while :; do
    n=$(matched "$1" "$2" "$3")
    [ "${n:-0}" -ge "$4" ] && return 0
    [ "$SECONDS" -lt "$deadline" ] || fail "the $2 of $3 on :$1 matched ${n:-nothing} of $4 within $MATCH_TIMEOUT_S s"
    sleep 0.2
  done
}

# The installed configs' metrics ports (config/*.yaml): 9471 scan_ingest,
# 9472 jump_filter, 9473 penetration_filter, 9474 map_publisher.
start_unit map-publisher
start_unit penetration-filter
start_unit jump-filter
wait_matched 9472 writer rt/jump_filtered_scan 1
wait_matched 9473 reader rt/jump_filtered_scan 1
wait_matched 9474 reader rt/labeled_scan 1
"$BIN/scanfilter-scan-recorder" -o "$WORK/labelled.scanlog.jsonl" --idle-exit 3 --timeout "$RECORD_TIMEOUT_S" \
  > "$WORK/recorder.log" 2>&1 &
RECORDER=$!; PIDS+=($RECORDER)
wait_matched 9473 writer rt/labeled_scan 2
start_unit scan-ingest
wait_matched 9471 writer rt/posed_scan 1
"$BIN/scanfilter-ros-scan-publisher" --rate "$PUBLISH_RATE_HZ" "$LOG" > "$WORK/publisher.log" 2>&1 ||
  fail "scanfilter-ros-scan-publisher failed"
wait "$RECORDER" || fail "scanfilter-scan-recorder exited non-zero"

sent=$(grep -c '"ranges"' "$LOG") || true
recorded=$(grep -c '"ranges"' "$WORK/labelled.scanlog.jsonl") || true
echo "recorded $recorded labelled scans of $sent published"
# The driver publishes best effort (as drivers do) and the ingest drops the
# scans before the first odometry: most, not all, arrive.
[ "${recorded:-0}" -ge $((sent / 2)) ] || fail "only ${recorded:-0} of $sent scans came out labelled"

for name in scan-ingest jump-filter penetration-filter map-publisher; do
  kill -TERM "${PID_OF[$name]}"
  wait "${PID_OF[$name]}" || fail "$name exited $? after SIGTERM"
done
PIDS=()
for ext in pgm yaml png logodds; do
  [ -s "$MAP_BASE.$ext" ] || fail "the map publisher saved no $MAP_BASE.$ext"
done
echo "map saved: $MAP_BASE.{pgm,yaml,png,logodds} ($(stat -c %U "$MAP_BASE.pgm"))"
for name in scan-ingest jump-filter penetration-filter map-publisher; do
  errors=$(grep -E '\[(error|critical)\]' "$WORK/$name.log") || true
  [ -z "$errors" ] || fail "$name logged errors: $errors"
done
