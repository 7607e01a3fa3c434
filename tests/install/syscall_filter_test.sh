#!/usr/bin/env bash
# The units' SystemCallFilter= against what the services really call. systemd
# is not PID 1 on the test machine, so the units' seccomp filter cannot be
# applied there; instead each service runs a scan log through the pipeline
# (start, discovery, processing, metrics scrapes, the map saved, sd_notify
# with the watchdog, SIGTERM)
# under strace, and every system call it made must be one its unit allows
# (the unit's allow and deny lists expanded by this systemd's
# `systemd-analyze syscall-filter`). A call outside the filter would fail
# with EPERM under systemd (SystemCallErrorNumber=EPERM).
#
#   syscall_filter_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD="$(cd "$1" && pwd)" SRC="$(cd "$2" && pwd)"
for tool in strace systemd-analyze; do
  command -v "$tool" > /dev/null || { echo "SKIP: $tool is missing (scripts/install-deps.sh installs it)"; exit 77; }
done
if [ -z "${SCANFILTER_IN_NETNS:-}" ] && [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
  exec unshare -n env SCANFILTER_IN_NETNS=1 bash -c 'ip link set lo up && exec bash "$0" "$@"' "$0" "$@"
fi
DOMAIN=$(( (RANDOM % 200) + 10 ))
WORK=$(mktemp -d)
PIDS=()
LISTENER=""
declare -A PID_OF TRACER_OF  # per service: its PID under strace, and strace's
cleanup() {
  # The services first: killing strace detaches it, and its tracee lives on.
  for pid in "${PID_OF[@]}" "${PIDS[@]}" $LISTENER; do kill -KILL "$pid" 2>/dev/null || true; done
  # Our own children reaped before WORK goes (the services are strace's: a
  # tracer ends after its tracee), so that none writes into it meanwhile.
  for pid in "${TRACER_OF[@]}" "${PIDS[@]}" $LISTENER; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$WORK"
}
trap cleanup EXIT
source "$(dirname "$0")/../lib/service_checks.sh"  # scrape, matched, wait_matched, fail
# Bound on waiting for discovery (strace slows everything down).
MATCH_WAIT_S=60

# The system calls of a filter's entries (@groups expanded, recursively).
expand_filter() {  # entries...
  local entry out line
  for entry in "$@"; do
    if [[ "$entry" == @* ]]; then
      out=$(systemd-analyze syscall-filter "$entry") || fail "systemd-analyze syscall-filter $entry: $out"
      while read -r line; do
        [[ -z "$line" || "$line" == \#* || "$line" == "$entry" ]] && continue
        expand_filter "$line"
      done <<<"$out"
    else
      echo "$entry"
    fi
  done
}

# What the unit's SystemCallFilter= lines allow: the first list minus every
# ~list (systemd's order for an allow list followed by deny lists).
allowed_by_unit() {  # unit file
  local lines line allowed denied=""
  lines=$(sed -n 's/^SystemCallFilter=//p' "$1")
  [ -n "$lines" ] || fail "$1 has no SystemCallFilter="
  allowed=""
  while read -r line; do
    if [[ "$line" == "~"* ]]; then
      # shellcheck disable=SC2086  # the list's words
      denied+=$'\n'$(expand_filter ${line#\~})
    else
      [ -z "$allowed" ] || fail "$1: more than one allow list; this test reads one"
      # shellcheck disable=SC2086
      allowed=$(expand_filter $line)
    fi
  done <<<"$lines"
  comm -23 <(sort -u <<<"$allowed") <(sort -u <<<"$denied" | sed '/^$/d')
}

traced() {  # name binary args...: runs it under strace in the background (PID_OF[name] is the service's PID)
  local name=$1; shift
  strace -f -qq -o "$WORK/$name.strace" "$@" > "$WORK/$name.log" 2>&1 &
  local tracer=$! pid=""
  PIDS+=("$tracer")
  # The child running the binary, matched by its command line: strace forks
  # short-lived children of its own at start (probing ptrace and seccomp),
  # and taking one of those for the service left the service unkilled and
  # failed the SIGTERM below at random.
  for _ in $(seq 1 100); do
    pid=$(pgrep -P "$tracer" -f -- "^$1( |\$)") && break
    sleep 0.1
  done
  [ -n "$pid" ] || fail "$name did not start under strace"
  PID_OF[$name]=$pid
  TRACER_OF[$name]=$tracer
}

# The notify socket and watchdog the units give them, so that sd_notify's
# calls are traced too: a listener that reads and drops the messages.
export NOTIFY_SOCKET="$WORK/notify.sock" WATCHDOG_USEC=2000000
python3 -c 'import socket, sys
s = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM); s.bind(sys.argv[1])
while True: s.recv(4096)' "$NOTIFY_SOCKET" &
LISTENER=$!

PROFILES="$SRC/deploy/fastdds-loopback.xml"
"$BUILD/tools/scanfilter" simulate --scene hall --seed 7 --max-frames 40 -o "$WORK/in.scanlog.jsonl" > /dev/null
cat > "$WORK/map.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $PROFILES, metrics_address: 127.0.0.1:19474}
publishing: {save_path: $WORK/map, save_period_s: 0.5}
YAML
cat > "$WORK/ingest.yaml" <<YAML
service: {domain_id: $DOMAIN, profiles_file: $PROFILES, metrics_address: 127.0.0.1:19471}
source: {kind: log, path: $WORK/in.scanlog.jsonl, rate: max}
playback: {wait_for_subscribers: 1, wait_timeout_s: $MATCH_WAIT_S, exit_at_end: true}
YAML
traced map_publisher "$BUILD/services/map_publisher" --config "$WORK/map.yaml"
traced penetration_filter "$BUILD/services/penetration_filter" --domain "$DOMAIN" --metrics-address 127.0.0.1:19473
traced jump_filter "$BUILD/services/jump_filter" --domain "$DOMAIN" --metrics-address 127.0.0.1:19472
wait_matched 19472 writer rt/jump_filtered_scan
wait_matched 19473 reader rt/jump_filtered_scan
wait_matched 19473 writer rt/labeled_scan
wait_matched 19474 reader rt/labeled_scan
traced scan_ingest "$BUILD/services/scan_ingest" --config "$WORK/ingest.yaml"
wait "${TRACER_OF[scan_ingest]}" || fail "scan_ingest exited non-zero"
deadline=$((SECONDS + MATCH_WAIT_S))
until [ -s "$WORK/map.pgm" ]; do
  [ "$SECONDS" -lt "$deadline" ] || fail "the map publisher saved no map within $MATCH_WAIT_S s"
  sleep 0.2
done
for name in jump_filter penetration_filter map_publisher; do
  kill -TERM "${PID_OF[$name]}"
  wait "${TRACER_OF[$name]}" || fail "$name exited non-zero after SIGTERM"
done
PIDS=()

declare -A UNIT=([scan_ingest]=scan-ingest [jump_filter]=jump-filter [penetration_filter]=penetration-filter
                 [map_publisher]=map-publisher)
for name in scan_ingest jump_filter penetration_filter map_publisher; do
  unit="$SRC/deploy/systemd/scanfilter-${UNIT[$name]}.service.in"
  allowed=$(allowed_by_unit "$unit")
  # "PID name(args" and "PID <... name resumed>": the call's name.
  used=$(sed -nE 's/^[0-9]+ +(<\.\.\. )?([a-z0-9_]+)[( ].*/\2/p' "$WORK/$name.strace" | sort -u)
  [ "$(grep -c . <<<"$used")" -ge 20 ] || fail "$name: strace recorded too few calls to judge: $used"
  outside=$(comm -23 <(echo "$used") <(echo "$allowed"))
  [ -z "$outside" ] || fail "$name called what $(basename "$unit") forbids: $(tr '\n' ' ' <<<"$outside")"
  echo "$name: $(grep -c . <<<"$used") distinct system calls, all allowed by $(basename "$unit" .in)"
done
echo PASS
