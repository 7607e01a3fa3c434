#!/usr/bin/env bash
# The pipeline spread over three hosts built from network namespaces joined
# by veth links to a bridge: scan_ingest on the "robot", jump_filter and
# penetration_filter on the "edge", map_publisher and a scan_recorder on the
# "mapper". The services find each other from their YAML `service.discovery`
# section alone, in one of two ways:
#
#   three_hosts_test.sh BUILD_DIR SOURCE_DIR CASE
#   CASE: unicast           unicast initial peers (and, first, proof that
#                           without them nobody is found: no multicast)
#         discovery_server  Fast DDS Discovery Server clients of a primary (on
#                           the edge) and a backup (on the mapper); the primary
#                           is killed before the robot's ingest starts, which
#                           must then be discovered through the backup alone
#
# Each host gets its own /dev/shm (a tmpfs in a mount namespace per host):
# network namespaces do not separate /dev/shm, and Fast DDS's shared-memory
# transport must not be able to carry data between "hosts". The checks: every
# scan arrives with the offline replay's labels; the scans crossed the veth
# links (interface byte counters); on the edge the filters' data stayed in
# shared memory (no datagram as large as a scan crossed its loopback, captured
# with tcpdump, and its /dev/shm holds Fast DDS segments). Needs root (ip
# netns); exits 77 (ctest: skipped) without it.
set -euo pipefail
BUILD="$1" SRC="$2" CASE="$3"
SKIP=77
if [ "$(id -u)" != 0 ]; then
  echo "SKIP: needs root to create network namespaces (ip netns)"
  exit $SKIP
fi
for tool in ip ss nsenter unshare curl tcpdump fast-discovery-server; do
  command -v "$tool" > /dev/null || { echo "FAIL: $tool is not installed (scripts/install-deps.sh)"; exit 1; }
done

FRAMES=100
RATE=10.0                  # the log's pace x10: 1 s of data, for byte counters read around it
SUBNET=10.77.0             # private, and only inside this test's namespaces
ROBOT_IP=$SUBNET.1 EDGE_IP=$SUBNET.2 MAPPER_IP=$SUBNET.3
UNLISTED_IP=$SUBNET.9      # a second address of the robot's that no config lists
SERVER_PORT=11811          # fast-discovery-server's default port
DOMAIN=0                   # the namespaces are private: no other test can see this domain
# Unique per run, so that concurrent runs never share (or delete) a namespace.
PREFIX="sf$$"
HOSTS=(robot edge mapper)
SWITCH="${PREFIX}switch"
WORK=$(mktemp -d)
PIDS=()
declare -A HOLDER IP

cleanup() {
  for pid in "${PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  for pid in "${PIDS[@]}"; do wait "$pid" 2>/dev/null || true; done
  for ns in "${PREFIX}robot" "${PREFIX}edge" "${PREFIX}mapper" "$SWITCH"; do
    # Anything still in this run's namespaces was started by it: a namespace
    # outlives `ip netns del` while a process is in it.
    for pid in $(ip netns pids "$ns" 2>/dev/null); do kill -KILL "$pid" 2>/dev/null || true; done
    ip netns del "$ns" 2>/dev/null || true
  done
  rm -rf "$WORK"
}
trap cleanup EXIT

fail() {
  echo "FAIL: $*"
  for service in robot:9471 edge:9472 edge:9473 mapper:9474; do  # who matched whom
    page=$(scrape "${service%%:*}" "${service##*:}")
    grep "^scanfilter_dds_matched" <<<"$page" || true
  done
  for f in "$WORK"/*.log; do
    if [ -f "$f" ]; then echo "--- $f"; tail -n 20 "$f"; fi
  done
  exit 1
}

SF="$BUILD/tools/scanfilter"

# --- the hosts -------------------------------------------------------------
# A switch namespace holding a bridge; each host's eth0 is a veth whose other
# end is a bridge port. The links are created inside the namespaces, so the
# test's own (root) network namespace is never touched.
ip netns add "$SWITCH"
ip -n "$SWITCH" link add br0 type bridge
ip -n "$SWITCH" link set br0 up
IP[robot]=$ROBOT_IP IP[edge]=$EDGE_IP IP[mapper]=$MAPPER_IP
for host in "${HOSTS[@]}"; do
  ns="${PREFIX}$host"
  ip netns add "$ns"
  ip -n "$ns" link set lo up
  ip -n "$SWITCH" link add "$host" type veth peer name eth0 netns "$ns"
  ip -n "$SWITCH" link set "$host" master br0 up
  ip -n "$ns" addr add "${IP[$host]}/24" dev eth0
  ip -n "$ns" link set eth0 up
  # A process that holds the host's mount namespace, with /dev/shm a tmpfs of
  # its own; every program of the host is started inside it with nsenter.
  ip netns exec "$ns" unshare -m --propagation private \
    sh -c 'mount -t tmpfs -o size=256m tmpfs /dev/shm && echo ready > "$0" && exec sleep 600' "$WORK/$host.ready" &
  HOLDER[$host]=$!; PIDS+=($!)
done
for host in "${HOSTS[@]}"; do
  deadline=$((SECONDS + 10))
  until [ -s "$WORK/$host.ready" ]; do
    [ "$SECONDS" -lt "$deadline" ] || fail "the $host host's mount namespace did not come up"
    sleep 0.05
  done
done

on() {  # host command...: runs it on that host (its network and its /dev/shm)
  local host=$1; shift
  nsenter -t "${HOLDER[$host]}" -m -n -- "$@"
}

start() {  # host log command...: starts it on that host in the background; STARTED is its PID
  local host=$1 log=$2; shift 2
  # Not `on ... &`: that would background a subshell, and its PID is not the program's.
  nsenter -t "${HOLDER[$host]}" -m -n -- "$@" > "$log" 2>&1 &
  STARTED=$!; PIDS+=($!)
}

counter() {  # host interface rx|tx: bytes through that interface so far
  on "$1" cat "/sys/class/net/$2/statistics/$3_bytes"
}

scrape() {  # host port: that service's metrics page, empty if it does not answer
  on "$1" curl -s --max-time 2 "http://127.0.0.1:$2/metrics" || true
}

matched() {  # host port endpoint topic: the service's gauge of matched peers (updated every second)
  local page
  page=$(scrape "$1" "$2")
  awk -v ep="endpoint=\"$3\"" -v topic="topic=\"$4\"" \
    'index($0, "scanfilter_dds_matched{") == 1 && index($0, ep) && index($0, topic) {print int($2)}' <<<"$page"
}

wait_matched() {  # host port endpoint topic count: until that many peers matched; 30 s at most
  local deadline=$((SECONDS + 30)) n
  while :; do
    n=$(matched "$1" "$2" "$3" "$4")
    [ "${n:-0}" -ge "$5" ] && return 0
    [ "$SECONDS" -lt "$deadline" ] || fail "the $3 of $4 on $1:$2 matched ${n:-no} peers, not $5, within 30 s"
    sleep 0.1
  done
}

# --- the services' configs -------------------------------------------------
discovery_of() {  # host: the service.discovery section for this case
  local host=$1 peers=()
  for other in "${HOSTS[@]}"; do [ "$other" = "$host" ] || peers+=("${IP[$other]}"); done
  case "$CASE" in
  unicast) echo "{interfaces: [${IP[$host]}], peers: [${peers[0]}, ${peers[1]}]}" ;;
  discovery_server) echo "{interfaces: [${IP[$host]}], servers: [\"$EDGE_IP:$SERVER_PORT\", \"$MAPPER_IP:$SERVER_PORT\"]}" ;;
  esac
}

service_section() {  # host metrics_port [discovery]: the common section of a service on that host
  local discovery=${3-$(discovery_of "$1")}
  echo "service: {domain_id: $DOMAIN, profiles_file: $SRC/deploy/fastdds-loopback.xml, metrics_address: 127.0.0.1:$2,"
  echo "          discovery: $discovery}"
}

for svc in jump_filter:9472 penetration_filter:9473; do
  { service_section edge "${svc##*:}"; echo "filter: {config: $SRC/config/filter.yaml}"; } > "$WORK/${svc%%:*}.yaml"
done
{ service_section mapper 9474; echo "publishing: {rate_hz: 5}"; } > "$WORK/map_publisher.yaml"
if [ "$CASE" = discovery_server ]; then
  # The recorder takes the other way to a Discovery Server: no servers in its
  # config, ROS_DISCOVERY_SERVER in its environment (positions = server ids).
  service_section mapper 0 "{interfaces: [$MAPPER_IP]}" > "$WORK/recorder.yaml"
  RECORDER_ENV=(env "ROS_DISCOVERY_SERVER=$EDGE_IP:$SERVER_PORT;$MAPPER_IP:$SERVER_PORT")
else
  service_section mapper 0 > "$WORK/recorder.yaml"
  RECORDER_ENV=(env)
fi
ingest_config() {  # file discovery wait_timeout_s
  { service_section robot 9471 "$2"
    echo "source: {kind: log, path: $WORK/in.scanlog.jsonl, rate: $RATE}"
    echo "playback: {wait_for_subscribers: 1, wait_timeout_s: $3, exit_at_end: true}"; } > "$1"
}
ingest_config "$WORK/ingest.yaml" "$(discovery_of robot)" 30

"$SF" simulate --scene hall --seed 4 --max-frames $FRAMES -o "$WORK/in.scanlog.jsonl" > /dev/null
"$SF" replay "$WORK/in.scanlog.jsonl" --config "$SRC/config/filter.yaml" -o "$WORK/offline.scanlog.jsonl" -q

# --- the run ---------------------------------------------------------------
if [ "$CASE" = discovery_server ]; then
  # What `fastdds discovery -i ID -l ADDRESS -p PORT -x XML` runs (that
  # wrapper would keep the server as its child, out of reach of a kill by
  # PID), with deploy/'s server profile bound to the host's address.
  for server in 0:edge 1:mapper; do
    id=${server%%:*} host=${server##*:}
    sed "s/127\.0\.0\.1/${IP[$host]}/g" "$SRC/deploy/fastdds-discovery-server.xml" > "$WORK/server$id.xml"
    start "$host" "$WORK/server$id.log" fast-discovery-server -i "$id" -l "${IP[$host]}" -p $SERVER_PORT \
      -x "$WORK/server$id.xml"
    [ "$id" != 0 ] || PRIMARY=$STARTED
  done
fi

start edge "$WORK/jump.log" "$BUILD/services/jump_filter" --config "$WORK/jump_filter.yaml"
start edge "$WORK/penetration.log" "$BUILD/services/penetration_filter" --config "$WORK/penetration_filter.yaml"
start mapper "$WORK/map.log" "$BUILD/services/map_publisher" --config "$WORK/map_publisher.yaml"
start mapper "$WORK/recorder.log" "${RECORDER_ENV[@]}" "$BUILD/dds_tools/scan_recorder" --config "$WORK/recorder.yaml" \
  --count $FRAMES --timeout 120 -o "$WORK/live.scanlog.jsonl"
REC=$STARTED

# Discovery is asymmetric (a writer may match before its reader does): wait
# for both ends where both export the gauge. labeled_scan has two readers.
wait_matched edge 9472 writer rt/jump_filtered_scan 1
wait_matched edge 9473 reader rt/jump_filtered_scan 1
wait_matched edge 9473 writer rt/labeled_scan 2
wait_matched mapper 9474 reader rt/labeled_scan 1

if [ "$CASE" = unicast ]; then
  # A participant that lists no peers, at an address of the robot that no
  # one lists as a peer either, must find nobody: discovery is the peers'
  # doing, not multicast's.
  ip -n "${PREFIX}robot" addr add "$UNLISTED_IP/24" dev eth0
  ingest_config "$WORK/lonely.yaml" "{interfaces: [$UNLISTED_IP]}" 3
  set +e
  on robot "$BUILD/services/scan_ingest" --config "$WORK/lonely.yaml" > "$WORK/lonely.log" 2>&1
  code=$?
  set -e
  [ "$code" = 1 ] && grep -q "0 of 1 subscribers matched" "$WORK/lonely.log" ||
    fail "an ingest without peers did not fail to find the jump_filter (exit $code)"
  echo "without peers: an ingest on the robot at an unlisted address found no reader within 3 s, as it must"
else
  kill -KILL "$PRIMARY"
  wait "$PRIMARY" 2>/dev/null || true
  sockets=$(on edge ss -Huln)
  ! grep -qF "$EDGE_IP:$SERVER_PORT " <<<"$sockets" || fail "the primary server still listens: $sockets"
  echo "primary Discovery Server ($EDGE_IP:$SERVER_PORT) killed; only the backup ($MAPPER_IP:$SERVER_PORT) is left"
fi

# The ingest publishes at ten times the recorded pace (1 s for the log), so
# that the byte counters can be read again after discovery, around the data.
# Every datagram on the edge's loopback from before the first scan to after
# the last (headers only: the sizes are what is checked).
start edge "$WORK/tcpdump.log" tcpdump -i lo -nn -U -s 64 -Z root -w "$WORK/edge_lo.pcap"
TCPDUMP=$STARTED
deadline=$((SECONDS + 10))
until grep -q "listening on lo" "$WORK/tcpdump.log"; do
  [ "$SECONDS" -lt "$deadline" ] || fail "tcpdump on the edge's loopback did not start: $(cat "$WORK/tcpdump.log")"
  sleep 0.01
done
robot_tx0=$(counter robot eth0 tx) mapper_rx0=$(counter mapper eth0 rx)
start robot "$WORK/ingest.log" timeout -k 5 90 "$BUILD/services/scan_ingest" --config "$WORK/ingest.yaml"
INGEST=$STARTED
deadline=$((SECONDS + 40))
while :; do
  # Whether it runs, asked before its log is read: a start it logged before
  # ending is then in the log, and an ended ingest without one never started.
  alive=1
  kill -0 "$INGEST" 2>/dev/null || alive=0
  ingest_log=$(cat "$WORK/ingest.log")
  grep -q "\[info\] started:" <<<"$ingest_log" && break
  [ "$alive" = 1 ] || fail "scan_ingest on the robot ended before it started publishing"
  [ "$SECONDS" -lt "$deadline" ] || fail "scan_ingest on the robot did not find its readers within 40 s"
  sleep 0.01
done
edge_lo0=$(counter edge lo tx) robot_data0=$(counter robot eth0 tx)
wait "$INGEST" || fail "scan_ingest on the robot exited non-zero"
wait "$REC" || fail "the recorder on the mapper did not get $FRAMES scans"
kill -INT "$TCPDUMP" 2>/dev/null || true
wait "$TCPDUMP" 2>/dev/null || true
edge_lo=$(( $(counter edge lo tx) - edge_lo0 )) robot_data=$(( $(counter robot eth0 tx) - robot_data0 ))
robot_tx=$(( $(counter robot eth0 tx) - robot_tx0 ))
mapper_rx=$(( $(counter mapper eth0 rx) - mapper_rx0 ))
edge_shm=$(on edge ls /dev/shm)

# --- the checks ------------------------------------------------------------
"$SF" diff "$WORK/offline.scanlog.jsonl" "$WORK/live.scanlog.jsonl" ||
  fail "the labels that reached the mapper differ from the offline replay"
info=$("$SF" info "$WORK/live.scanlog.jsonl")
beams=$(sed -n 's/^scans: *[0-9]* (\([0-9]*\)-.*/\1/p' <<<"$info")  # the fewest in a scan
[ -n "$beams" ] || fail "no beam count in: $info"
# The least the scans can weigh on the wire: their ranges (float64 in a LabeledScan).
payload=$(( FRAMES * beams * 8 ))
echo "labels: $FRAMES scans of $beams beams each equal the offline replay's"
echo "bytes over the ingest's run: robot eth0 sent $robot_tx, mapper eth0 received $mapper_rx;" \
  "the scans' ranges alone are $payload"
echo "bytes while the scans flowed: robot eth0 sent $robot_data, edge loopback carried $edge_lo"
[ "$robot_tx" -ge "$payload" ] || fail "the robot sent $robot_tx bytes over eth0, less than the scans' $payload"
[ "$mapper_rx" -ge "$payload" ] || fail "the mapper received $mapper_rx bytes over eth0, less than the scans' $payload"
# The jump_filter -> penetration_filter stream stayed in shared memory: over
# UDP each scan would cross the edge's loopback as a datagram of at least its
# ranges (one datagram: Fast DDS fragments only beyond 64 kB). The loopback
# does carry discovery: participant announcements (~500 bytes) to each port
# of the initial peers' range, whose bytes grow with how long the scans take
# to flow (twice as long under ThreadSanitizer: a byte count against what
# the robot sent failed there with no scan on the loopback), so sizes are
# checked, not bytes.
scan_bytes=$(( beams * 8 ))
# (|| true: a capture cut short mid-record still lists what it holds; an empty one fails below)
sizes=$({ tcpdump -nn -r "$WORK/edge_lo.pcap" 2> /dev/null || true; } | sed -n 's/.* UDP, length \([0-9]*\)$/\1/p')
datagrams=$(grep -c . <<<"$sizes" || true)
large=$(awk -v min="$scan_bytes" '$1 >= min' <<<"$sizes" | grep -c . || true)
largest=$(sort -n <<<"$sizes" | tail -n 1)
echo "edge loopback while the scans flowed: $datagrams UDP datagrams, the largest ${largest:-0} bytes;" \
  "$large of at least a scan's ranges ($scan_bytes bytes)"
[ "$datagrams" -gt 0 ] || fail "tcpdump saw no datagram on the edge's loopback (discovery runs there): capture broken?"
[ "$large" -eq 0 ] || fail "$large datagrams of a scan's size crossed the edge's loopback: the filters talked over UDP"
grep -q "^fastrtps_" <<<"$edge_shm" || fail "no Fast DDS segments in the edge's /dev/shm: $edge_shm"
robot_shm=$(on robot ls /dev/shm)
[ -z "$(comm -12 <(sort <<<"$robot_shm") <(sort <<<"$edge_shm"))" ] || fail "the robot and the edge share /dev/shm files"

# Discovery time: from the ingest's "waiting for readers" line to its
# "started" line, less the fixed settle pause it takes after matching.
stamp_ms() {  # message prefix: the time of the ingest's first log line starting with it, in ms
  local at
  at=$(sed -n "s/^\[\([0-9-]* [0-9:.]*\)\] \[scan_ingest\] \[info\] $1.*/\1/p" "$WORK/ingest.log")
  [ -n "$at" ] || { fail "no '$1' line in the ingest's log"; } >&2
  date -d "${at%%$'\n'*}" +%s%3N
}
SETTLE_MS=300  # kDiscoverySettle (common/dds typed_writer.hpp)
discovery_ms=$(( $(stamp_ms started:) - $(stamp_ms "log source; waiting") - SETTLE_MS ))
echo "discovery ($CASE): the robot's scan_ingest matched the edge's jump_filter in $discovery_ms ms"
echo "PASS: $CASE"
