#!/usr/bin/env bash
# Soak: the four services of one robot at 40 Hz (360-beam simulated hall) for
# MINUTES, sampled every SAMPLE_S seconds (default 10): resident memory and
# CPU of each process, end-to-end latency p50/p99 of each window. Reports
# each service's resident-memory growth from the first minute's end to the
# last sample and the spread of the windows' p99; fails when a service grew
# by 2 % or more, or a scan was lost (bench/run-fleet-bench.sh checks every
# stage's counters). Not part of the regular test run (docs/reliability.md).
#
#   scripts/soak.sh MINUTES [OUT_DIR]     e.g. scripts/soak.sh 30 out/soak
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
MINUTES="${1:-}"
OUT="${2:-$ROOT/out/soak}"
SAMPLE_S="${SAMPLE_S:-10}"
[[ "$MINUTES" =~ ^[0-9]+$ ]] && [ "$MINUTES" -ge 2 ] ||
  { echo "usage: scripts/soak.sh MINUTES [OUT_DIR] (MINUTES: whole minutes, at least 2; got '${MINUTES}')" >&2; exit 2; }
[[ "$SAMPLE_S" =~ ^[0-9]+$ ]] && [ "$SAMPLE_S" -ge 1 ] || { echo "SAMPLE_S: whole seconds >= 1, got $SAMPLE_S" >&2; exit 2; }
# Memory is compared from here on: the first minute holds start-up (DDS
# discovery, the penetration cache and map filling up to their steady size).
WARMUP_S=60
MAX_GROWTH_PERCENT=2
mkdir -p "$OUT"
bash "$ROOT/bench/run-fleet-bench.sh" --robots 1 --seconds $((MINUTES * 60)) --rate 40 --beams 360 --no-labels \
  --sample-every "$SAMPLE_S" --out "$OUT" | tee "$OUT/fleet.txt"

echo
echo "Resident memory after the first minute (${WARMUP_S} s) and at the end:"
echo "| service | RSS at ${WARMUP_S} s | RSS at the end | growth | CPU over the run |"
echo "|---|---|---|---|---|"
summary=$(awk -F'\t' -v warm="$WARMUP_S" -v max="$MAX_GROWTH_PERCENT" 'NR > 1 {
    svc = $3
    if ($1 >= warm && !(svc in first)) { first[svc] = $4; t0[svc] = $1; c0[svc] = $5 }
    last[svc] = $4; t1[svc] = $1; c1[svc] = $5
  } END {
    bad = 0
    for (svc in first) {
      g = 100 * (last[svc] - first[svc]) / first[svc]
      printf "| %s | %.1f MB | %.1f MB | %+.2f %% | %.1f %% of a core |\n", svc, first[svc] / 1048576, last[svc] / 1048576, g,
             100 * (c1[svc] - c0[svc]) / (t1[svc] - t0[svc])
      if (g >= max) bad = 1
    }
    if (bad) print "GROWTH"
  }' "$OUT/samples.tsv")
echo "$summary" | grep -v '^GROWTH$'
echo
echo "End-to-end latency per ${SAMPLE_S} s window after the first minute:"
p99s=$(awk -F'\t' -v warm="$WARMUP_S" 'NR > 1 && $1 >= warm && $3 > 0 {print $5}' "$OUT/latency.tsv" | sort -g)
scans=$(awk -F'\t' -v warm="$WARMUP_S" 'NR > 1 && $1 >= warm {s += $3} END {print s + 0}' "$OUT/latency.tsv")
awk -v scans="$scans" '{v[NR] = $1} END {
    printf "%d windows, %d scans; p99 min %.2f ms, median %.2f ms, max %.2f ms\n", NR, scans, 1e3 * v[1],
           1e3 * v[int((NR + 1) / 2)], 1e3 * v[NR] }' <<<"$p99s"
if grep -q '^GROWTH$' <<<"$summary"; then
  echo "FAIL: a service's resident memory grew by ${MAX_GROWTH_PERCENT} % or more after the first minute"
  exit 1
fi
echo "PASS: soak of $MINUTES min (samples in $OUT/samples.tsv and $OUT/latency.tsv)"
