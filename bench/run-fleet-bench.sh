#!/usr/bin/env bash
# A fleet on one DDS domain: N robots, each with its own scan_ingest,
# jump_filter, penetration_filter and map_publisher under the namespace
# robot<i> (rt/robot<i>/...), plus a recorder of its labelled scans. Each
# ingest runs the simulator (a hall scene with the given beams and rate, true
# poses, the tour repeated to last the run; seed i) for SECONDS, then stops.
#
# Checks: nothing lost (every service of every robot received and published
# what its ingest published) and no scan crossed between robots (each robot's
# recorded labels equal `scanfilter replay` of its own simulated scans).
# Reports: CPU per service (scanfilter_process_cpu_seconds_total over the
# run; the ingest's from /proc, its gauge is not refreshed while it plays),
# resident memory, and the end-to-end latency percentiles of each robot's
# penetration_filter from its histogram (linear within a bucket).
#
#   bench/run-fleet-bench.sh [--robots N] [--seconds S] [--rate HZ] [--beams B] [--no-labels]
#                            [--sample-every S] [--out DIR] [--profile FILE] [--filter-config FILE]
#   defaults: 4 robots, 60 s, 40 Hz, 360 beams, deploy/fastdds-loopback.xml, config/filter.yaml
#
# --sample-every S writes DIR/samples.tsv every S seconds (per process RSS and
# CPU, the window's end-to-end p99), which scripts/soak.sh summarises.
# --profile FILE runs every service with another Fast DDS profile (a
# transport setting against the shipped one: two runs at once, each in its
# own namespace, see the same machine load). --filter-config FILE runs both
# filters (and the offline replay the labels are checked against) with
# another filter config, for the same kind of pair.
# Runs in a private network namespace (root: unshare -n) on a random domain.
# Bounded: the run's SECONDS plus at most 60 s to match and 60 s to drain.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${BUILD_DIR:-$ROOT/build}"
if [ -z "${SCANFILTER_IN_NETNS:-}" ] && [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
  exec unshare -n env SCANFILTER_IN_NETNS=1 bash -c 'ip link set lo up && exec bash "$0" "$@"' "$0" "$@"
fi
ROBOTS=4 SECONDS_RUN=60 RATE=40 BEAMS=360 LABELS=1 SAMPLE_EVERY=0 OUT=""
PROFILES="$ROOT/deploy/fastdds-loopback.xml"
FILTER_CONFIG="$ROOT/config/filter.yaml"
while [ $# -gt 0 ]; do
  case "$1" in
    --robots) ROBOTS="$2"; shift 2 ;;
    --seconds) SECONDS_RUN="$2"; shift 2 ;;
    --rate) RATE="$2"; shift 2 ;;
    --beams) BEAMS="$2"; shift 2 ;;
    --no-labels) LABELS=0; shift ;;
    --sample-every) SAMPLE_EVERY="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --profile) PROFILES="$2"; shift 2 ;;
    --filter-config) FILTER_CONFIG="$2"; shift 2 ;;
    -h|--help) sed -n 2,28p "$0"; exit 0 ;;
    *) echo "run-fleet-bench.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done
for v in ROBOTS SECONDS_RUN RATE BEAMS SAMPLE_EVERY; do
  [[ "${!v}" =~ ^[0-9]+$ ]] || { echo "run-fleet-bench.sh: $v must be a whole number, got ${!v}" >&2; exit 2; }
done
[ "$ROBOTS" -ge 1 ] && [ "$ROBOTS" -le 6 ] || { echo "run-fleet-bench.sh: --robots 1-6 (ports and DDS peers), got $ROBOTS" >&2; exit 2; }
[ "$RATE" -ge 1 ] && [ "$BEAMS" -ge 16 ] && [ "$SECONDS_RUN" -ge 1 ] || { echo "run-fleet-bench.sh: rate, beams and seconds must be positive" >&2; exit 2; }
[ -f "$PROFILES" ] || { echo "run-fleet-bench.sh: no Fast DDS profile at $PROFILES" >&2; exit 2; }
PROFILES="$(cd "$(dirname "$PROFILES")" && pwd)/$(basename "$PROFILES")"  # the services run elsewhere
[ -f "$FILTER_CONFIG" ] || { echo "run-fleet-bench.sh: no filter config at $FILTER_CONFIG" >&2; exit 2; }
FILTER_CONFIG="$(cd "$(dirname "$FILTER_CONFIG")" && pwd)/$(basename "$FILTER_CONFIG")"

DOMAIN=$(( (RANDOM % 200) + 10 ))
WORK=$(mktemp -d)
[ -n "$OUT" ] && mkdir -p "$OUT" && WORK="$(cd "$OUT" && pwd)"
PIDS=()
cleanup() {
  for pid in "${PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  [ -n "$OUT" ] || rm -rf "$WORK"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*"
  for f in "$WORK"/*.log; do [ -f "$f" ] && { echo "--- $f"; tail -n 5 "$f"; }; done
  exit 1
}
SF="$BUILD/tools/scanfilter"
SERVICES=(scan_ingest jump_filter penetration_filter map_publisher)
# Metrics ports: 20<robot><k>, k = 1 ingest, 2 jump, 3 penetration, 4 map.
port() { echo $((20000 + 10 * $1 + $2)); }

# The hall at BEAMS beams (angular step 360°/BEAMS) and RATE Hz, true poses
# (so a long run's map stays the hall's size), its tour repeated: one lap at
# 0.4 m/s takes about 1.5 min (LAP_S is a safe lower bound).
LAP_S=60
LAPS=$(( SECONDS_RUN / LAP_S + 2 ))
waypoints=$(sed -n 's/^  waypoints: \[\(.*\)\]$/\1/p' "$ROOT/config/scenes/hall.yaml")
[ -n "$waypoints" ] || fail "no waypoints line in config/scenes/hall.yaml"
tour="$waypoints"
for ((l = 1; l < LAPS; l++)); do tour="$tour, $waypoints"; done
step=$(awk -v b="$BEAMS" 'BEGIN { printf "%.10g", 360 / b }')
sed -e "s/^  beams: .*/  beams: $BEAMS/" -e "s/^  rate_hz: .*/  rate_hz: $RATE/" \
    -e "s/^  angular_accuracy_deg: .*/  angular_accuracy_deg: $step/" \
    -e "s/^  waypoints: .*/  waypoints: [$tour]/" -e "s/^name: .*/name: fleet_hall/" \
    "$ROOT/config/scenes/hall.yaml" > "$WORK/scene.yaml"
echo "odometry: {scale_error: 0, heading_drift_deg_per_m: 0}" >> "$WORK/scene.yaml"

scrape() { curl -s --max-time 2 "http://127.0.0.1:$1/metrics" || true; }
metric() {  # port regex: the value of the first matching sample
  local page
  page=$(scrape "$1")
  awk -v re="^$2 " '$0 ~ re {print $2; exit}' <<<"$page"
}
matched() {  # port endpoint topic
  local page
  page=$(scrape "$1")
  awk -v ep="endpoint=\"$2\"" -v topic="topic=\"$3\"" \
    'index($0, "scanfilter_dds_matched{") == 1 && index($0, ep) && index($0, topic) {print int($2)}' <<<"$page"
}
wait_matched() {  # port endpoint topic peers
  local deadline=$((SECONDS + 60)) n
  while :; do
    n=$(matched "$1" "$2" "$3")
    [ "${n:-0}" -ge "$4" ] && return 0
    [ "$SECONDS" -lt "$deadline" ] || fail "the $2 of $3 on :$1 matched ${n:-no} peers of $4 within 60 s"
    sleep 0.2
  done
}
cpu_of_pid() {  # pid: user+system CPU seconds from /proc
  awk -v hz="$(getconf CLK_TCK)" '{print ($14 + $15) / hz}' "/proc/$1/stat" 2>/dev/null || echo 0
}
rss_of_pid() {  # pid: resident bytes
  awk -v page="$(getconf PAGESIZE)" '{print $2 * page}' "/proc/$1/statm" 2>/dev/null || echo 0
}
# Percentile q of a Prometheus histogram given as "le count" lines (cumulative),
# linear within the bucket; "inf" beyond the last finite bound.
histogram_quantile() {  # q file-or-text
  awk -v q="$1" '
    { le[NR] = $1; c[NR] = $2 } END {
      total = c[NR]; if (total == 0) { print "nan"; exit }
      target = q * total; prev_le = 0; prev_c = 0
      for (i = 1; i <= NR; i++) {
        if (c[i] >= target) {
          if (le[i] == "+Inf") { print "inf"; exit }
          print prev_le + (le[i] - prev_le) * (target - prev_c) / (c[i] - prev_c); exit
        }
        prev_le = le[i]; prev_c = c[i]
      }
    }' <<<"$2"
}
latency_buckets() {  # port service: "le cumulative-count" lines of its end-to-end histogram
  local page
  page=$(scrape "$1")
  awk -v svc="service=\"$2\"" 'index($0, "scanfilter_end_to_end_latency_seconds_bucket{") == 1 && index($0, svc) {
      match($0, /le="[^"]*"/); le = substr($0, RSTART + 4, RLENGTH - 5); print le, $2 }' <<<"$page"
}

declare -A PID_OF
for ((r = 1; r <= ROBOTS; r++)); do
  ns=robot$r
  for k in 2 3 4; do
    svc=${SERVICES[$((k - 1))]}
    printf 'service: {domain_id: %s, namespace: %s, profiles_file: "%s", metrics_address: 127.0.0.1:%s, log_level: warn}\n' \
      "$DOMAIN" "$ns" "$PROFILES" "$(port "$r" "$k")" > "$WORK/$ns.$svc.yaml"
  done
  echo "filter: {config: \"$FILTER_CONFIG\"}" >> "$WORK/$ns.jump_filter.yaml"
  echo "filter: {config: \"$FILTER_CONFIG\"}" >> "$WORK/$ns.penetration_filter.yaml"
  cat > "$WORK/$ns.scan_ingest.yaml" <<YAML
service: {domain_id: $DOMAIN, namespace: $ns, profiles_file: "$PROFILES", metrics_address: 127.0.0.1:$(port "$r" 1)}
source: {kind: simulator, scene: $WORK/scene.yaml, seed: $r, rate: recorded}
playback: {wait_for_subscribers: 1, wait_timeout_s: 60, exit_at_end: true}
YAML
  for k in 4 3 2; do
    svc=${SERVICES[$((k - 1))]}
    "$BUILD/services/$svc" --config "$WORK/$ns.$svc.yaml" > "$WORK/$ns.$svc.log" 2>&1 &
    PID_OF[$ns.$svc]=$!; PIDS+=($!)
  done
  if [ "$LABELS" = 1 ]; then
    "$BUILD/dds_tools/scan_recorder" --domain "$DOMAIN" --namespace "$ns" --timeout $((SECONDS_RUN + 180)) \
      -o "$WORK/$ns.live.scanlog.jsonl" > "$WORK/$ns.recorder.log" 2>&1 &
    PID_OF[$ns.recorder]=$!; PIDS+=($!)
  fi
done
# Every hop of every robot matched at both ends (discovery is asymmetric).
labeled_readers=$((1 + LABELS))
for ((r = 1; r <= ROBOTS; r++)); do
  ns=robot$r
  wait_matched "$(port "$r" 2)" writer "rt/$ns/jump_filtered_scan" 1
  wait_matched "$(port "$r" 3)" reader "rt/$ns/jump_filtered_scan" 1
  wait_matched "$(port "$r" 3)" writer "rt/$ns/labeled_scan" "$labeled_readers"
  wait_matched "$(port "$r" 4)" reader "rt/$ns/labeled_scan" 1
done
sleep 1.5  # one more gauge period: every service's CPU gauge is fresh before the baseline

declare -A CPU0
for ((r = 1; r <= ROBOTS; r++)); do
  for k in 2 3 4; do
    svc=${SERVICES[$((k - 1))]}
    CPU0[robot$r.$svc]=$(metric "$(port "$r" "$k")" "scanfilter_process_cpu_seconds_total\\{service=\"$svc\"\\}")
  done
done
for ((r = 1; r <= ROBOTS; r++)); do
  ns=robot$r
  "$BUILD/services/scan_ingest" --config "$WORK/$ns.scan_ingest.yaml" > "$WORK/$ns.scan_ingest.log" 2>&1 &
  PID_OF[$ns.scan_ingest]=$!; PIDS+=($!)
done
# The run starts once every ingest has published its first scan (each
# waits for its jump_filter to match first).
deadline=$((SECONDS + 60))
for ((r = 1; r <= ROBOTS; r++)); do
  until [ "$(metric "$(port "$r" 1)" 'scanfilter_scans_published_total\{service="scan_ingest"\}')" != "" ] &&
        [ "$(metric "$(port "$r" 1)" 'scanfilter_scans_published_total\{service="scan_ingest"\}')" != 0 ]; do
    [ "$SECONDS" -lt "$deadline" ] || fail "robot$r's scan_ingest published nothing within 60 s"
    sleep 0.1
  done
done
START=$SECONDS START_NS=$(date +%s%N)
echo "fleet: $ROBOTS robots x 4 services on domain $DOMAIN, $BEAMS beams at $RATE Hz for $SECONDS_RUN s (work dir $WORK)"

# Sampling (soak): per process RSS and CPU, and the window's end-to-end p99.
if [ "$SAMPLE_EVERY" -gt 0 ]; then
  printf 't_s\trobot\tservice\trss_bytes\tcpu_s\n' > "$WORK/samples.tsv"
  printf 't_s\trobot\tscans\tp50_s\tp99_s\n' > "$WORK/latency.tsv"
fi
declare -A PREV_BUCKETS
sample() {
  local t=$((SECONDS - START)) r ns svc pid now diff
  for ((r = 1; r <= ROBOTS; r++)); do
    ns=robot$r
    for svc in "${SERVICES[@]}"; do
      pid=${PID_OF[$ns.$svc]}
      printf '%s\t%s\t%s\t%s\t%s\n' "$t" "$ns" "$svc" "$(rss_of_pid "$pid")" "$(cpu_of_pid "$pid")" >> "$WORK/samples.tsv"
    done
    now=$(latency_buckets "$(port "$r" 3)" penetration_filter)
    # This window's histogram: the difference of the cumulative counts.
    diff=$(paste -d' ' <(echo "$now") <(echo "${PREV_BUCKETS[$ns]:-$(awk '{print $1, 0}' <<<"$now")}") |
           awk '{print $1, $2 - $4}')
    PREV_BUCKETS[$ns]=$now
    printf '%s\t%s\t%s\t%s\t%s\n' "$t" "$ns" "$(awk 'END {print $2}' <<<"$diff")" \
      "$(histogram_quantile 0.5 "$diff")" "$(histogram_quantile 0.99 "$diff")" >> "$WORK/latency.tsv"
  done
}
next_sample=$((START + SAMPLE_EVERY))
declare -A CPU_INGEST
while [ $((SECONDS - START)) -lt "$SECONDS_RUN" ]; do
  for ((r = 1; r <= ROBOTS; r++)); do
    kill -0 "${PID_OF[robot$r.scan_ingest]}" 2>/dev/null || fail "robot$r's scan_ingest ended before $SECONDS_RUN s"
  done
  if [ "$SAMPLE_EVERY" -gt 0 ] && [ "$SECONDS" -ge "$next_sample" ]; then
    sample
    next_sample=$((next_sample + SAMPLE_EVERY))
  fi
  sleep 0.5
done
ELAPSED=$(awk -v a="$START_NS" -v b="$(date +%s%N)" 'BEGIN {printf "%.2f", (b - a) / 1e9}')
for ((r = 1; r <= ROBOTS; r++)); do
  CPU_INGEST[robot$r]=$(cpu_of_pid "${PID_OF[robot$r.scan_ingest]}")
  kill -TERM "${PID_OF[robot$r.scan_ingest]}"
done
declare -A PUBLISHED
for ((r = 1; r <= ROBOTS; r++)); do
  ns=robot$r
  wait "${PID_OF[$ns.scan_ingest]}" || fail "$ns's scan_ingest exited non-zero"
  PUBLISHED[$ns]=$(sed -n 's/.*published \([0-9]*\) scans.*/\1/p' "$WORK/$ns.scan_ingest.log")
  [ -n "${PUBLISHED[$ns]}" ] || fail "$ns's scan_ingest did not say how many scans it published"
done

# Nothing lost: every stage of every robot received and published them all.
for ((r = 1; r <= ROBOTS; r++)); do
  ns=robot$r n=${PUBLISHED[robot$r]}
  deadline=$((SECONDS + 60))
  while :; do
    j=$(metric "$(port "$r" 2)" 'scanfilter_scans_published_total\{service="jump_filter"\}')
    p=$(metric "$(port "$r" 3)" 'scanfilter_scans_published_total\{service="penetration_filter"\}')
    m=$(metric "$(port "$r" 4)" 'scanfilter_scans_received_total\{service="map_publisher"\}')
    [ "${j%.*}" = "$n" ] && [ "${p%.*}" = "$n" ] && [ "${m%.*}" = "$n" ] && break
    [ "$SECONDS" -lt "$deadline" ] || fail "$ns: ingest published $n, jump published $j, penetration published $p, map received $m"
    sleep 0.2
  done
  for k in 2 3; do
    svc=${SERVICES[$((k - 1))]}
    rejected=$(scrape "$(port "$r" "$k")" | awk '/^scanfilter_samples_rejected_total\{/ {s += $2} END {print s + 0}')
    [ "$rejected" = 0 ] || fail "$ns's $svc rejected or failed $rejected samples"
  done
done
sleep 1.5  # every gauge refreshed after the last scan

echo
echo "| robot | scans | service | CPU s | % of one core | CPU µs per scan | RSS MB |"
echo "|---|---|---|---|---|---|---|"
total_cpu=0
for ((r = 1; r <= ROBOTS; r++)); do
  ns=robot$r n=${PUBLISHED[$ns]}
  for k in 1 2 3 4; do
    svc=${SERVICES[$((k - 1))]}
    if [ "$k" = 1 ]; then
      cpu=${CPU_INGEST[$ns]} rss=""  # the ingest has exited (its RSS is in the samples when sampled)
    else
      cpu1=$(metric "$(port "$r" "$k")" "scanfilter_process_cpu_seconds_total\\{service=\"$svc\"\\}")
      cpu=$(awk -v a="$cpu1" -v b="${CPU0[$ns.$svc]}" 'BEGIN {print a - b}')
      rss=$(metric "$(port "$r" "$k")" "scanfilter_process_resident_memory_bytes\\{service=\"$svc\"\\}")
    fi
    total_cpu=$(awk -v a="$total_cpu" -v b="$cpu" 'BEGIN {print a + b}')
    awk -v ns="$ns" -v n="$n" -v svc="$svc" -v cpu="$cpu" -v t="$ELAPSED" -v rss="$rss" 'BEGIN {
      printf "| %s | %d | %s | %.2f | %.1f %% | %.0f | %s |\n", ns, n, svc, cpu, 100 * cpu / t, 1e6 * cpu / n,
             rss == "" ? "-" : sprintf("%.1f", rss / 1048576) }'
  done
done
all_scans=0
for ((r = 1; r <= ROBOTS; r++)); do all_scans=$((all_scans + ${PUBLISHED[robot$r]})); done
awk -v c="$total_cpu" -v t="$ELAPSED" -v n="$all_scans" 'BEGIN {
  printf "all services: %.1f CPU s in %.1f s = %.2f cores; %.0f µs of CPU per scan through the four services\n", c, t, c / t, 1e6 * c / n }'
echo
echo "| robot | scans | end-to-end p50 | p99 | hop p99 (penetration_filter in) |"
echo "|---|---|---|---|---|"
for ((r = 1; r <= ROBOTS; r++)); do
  ns=robot$r
  b=$(latency_buckets "$(port "$r" 3)" penetration_filter)
  page=$(scrape "$(port "$r" 3)")
  hop=$(awk 'index($0, "scanfilter_hop_latency_seconds_bucket{") == 1 {
      match($0, /le="[^"]*"/); print substr($0, RSTART + 4, RLENGTH - 5), $2 }' <<<"$page")
  awk -v ns="$ns" -v n="${PUBLISHED[$ns]}" -v p50="$(histogram_quantile 0.5 "$b")" -v p99="$(histogram_quantile 0.99 "$b")" \
      -v h99="$(histogram_quantile 0.99 "$hop")" 'BEGIN {
      printf "| %s | %d | %.2f ms | %.2f ms | %.2f ms |\n", ns, n, 1e3 * p50, 1e3 * p99, 1e3 * h99 }'
done

if [ "$LABELS" = 1 ]; then
  for ((r = 1; r <= ROBOTS; r++)); do
    ns=robot$r
    kill -TERM "${PID_OF[$ns.recorder]}"
    wait "${PID_OF[$ns.recorder]}" || true
    "$SF" simulate --scene "$WORK/scene.yaml" --seed "$r" --max-frames "${PUBLISHED[$ns]}" -o "$WORK/$ns.in.scanlog.jsonl" > /dev/null
    "$SF" replay "$WORK/$ns.in.scanlog.jsonl" --config "$FILTER_CONFIG" -o "$WORK/$ns.offline.scanlog.jsonl" -q
    "$SF" diff "$WORK/$ns.offline.scanlog.jsonl" "$WORK/$ns.live.scanlog.jsonl" > "$WORK/$ns.diff.txt" 2>&1 ||
      fail "$ns: live labels differ from its own offline replay: $(cat "$WORK/$ns.diff.txt")"
    echo "$ns: ${PUBLISHED[$ns]} scans, labels equal its own offline replay"
  done
fi
for ((r = 1; r <= ROBOTS; r++)); do
  for svc in jump_filter penetration_filter map_publisher; do kill -TERM "${PID_OF[robot$r.$svc]}" 2>/dev/null || true; done
done
for ((r = 1; r <= ROBOTS; r++)); do
  for svc in jump_filter penetration_filter map_publisher; do
    wait "${PID_OF[robot$r.$svc]}" || fail "robot$r's $svc exited non-zero"
  done
done
PIDS=()
echo "PASS: fleet of $ROBOTS, nothing lost"
