#!/usr/bin/env bash
# Values that look like input but say nothing are refused with a message
# that names what was expected, instead of a result that means nothing:
# a diff of two logs without labels, a config key given twice (yaml-cpp
# takes the first), negative numbers where only positive ones mean
# anything, and a recorder that received nothing (no file, and it says so).
#
#   values_refused.sh BUILD_DIR
set -euo pipefail
BUILD="$1"
# The recorder starts a DDS participant: it sees no other test's.
if [ -z "${SCANFILTER_IN_NETNS:-}" ] && [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
  exec unshare -n env SCANFILTER_IN_NETNS=1 bash -c 'ip link set lo up && exec bash "$0" "$@"' "$0" "$@"
fi
SF="$BUILD/tools/scanfilter"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# expect_refused CODE TEXT CMD...: CMD exits with CODE and says TEXT.
expect_refused() {
  local code=$1 text=$2 out rc=0
  shift 2
  out=$("$@" 2>&1) || rc=$?
  [ "$rc" = "$code" ] || fail "$* exited $rc, expected $code: $out"
  [[ "$out" == *"$text"* ]] || fail "$* does not say \"$text\": $out"
}

"$SF" simulate --scene hall --seed 1 --max-frames 5 -o "$WORK/a.scanlog.jsonl" > /dev/null
expect_refused 105 "--seed: expected a seed: a whole number >= 0, got -1" \
  "$SF" simulate --scene hall --seed -1 -o "$WORK/x.scanlog.jsonl"

# A pipe: the reader would open it again from its start, and wait for ever.
mkfifo "$WORK/pipe"
(timeout 20 cat "$WORK/a.scanlog.jsonl" > "$WORK/pipe" 2>/dev/null || true) &
FEEDER=$!
expect_refused 2 "pipe: not a regular file" timeout 10 "$SF" info "$WORK/pipe"
kill "$FEEDER" 2>/dev/null || true
wait "$FEEDER" 2>/dev/null || true
"$SF" simulate --scene office --seed 1 --max-frames 5 -o "$WORK/b.scanlog.jsonl" > /dev/null
expect_refused 2 "neither log carries labels" "$SF" diff "$WORK/a.scanlog.jsonl" "$WORK/b.scanlog.jsonl"
"$SF" replay -q "$WORK/a.scanlog.jsonl" -o "$WORK/a.labelled.jsonl"
expect_refused 1 "scan 0: 360 vs 0 labels" "$SF" diff "$WORK/a.labelled.jsonl" "$WORK/a.scanlog.jsonl"

printf 'jump_filter:\n  alpha: 0.6\n  alpha: 50\n' > "$WORK/twice.yaml"
expect_refused 2 "twice.yaml:3: jump_filter.alpha: duplicate key (first on line 2)" \
  "$SF" replay -q --config "$WORK/twice.yaml" "$WORK/a.scanlog.jsonl"
expect_refused 105 "--carmen-range-max: expected a number from 0.01 to 10000 (m), got -1" \
  "$SF" info --carmen-range-max -1 "$WORK/a.scanlog.jsonl"

if [ -x "$BUILD/dds_tools/scan_recorder" ]; then
  REC="$BUILD/dds_tools/scan_recorder"
  expect_refused 105 "--domain: Value 300 not in range 0 to 232" "$REC" -o "$WORK/r.jsonl" --domain 300
  expect_refused 105 "--count: expected a scan count: a whole number >= 0, got -1" "$REC" -o "$WORK/r.jsonl" --count -1
  expect_refused 105 "--rate: expected a number >= 0 (scans per second), got -5" \
    "$BUILD/dds_tools/ros_scan_publisher" --rate -5 "$WORK/a.scanlog.jsonl"
  # Nothing published: the recorder ends at its timeout and says no file was written.
  # A domain of its own: without a private network namespace (not root) a
  # demo on the default domain 0 could be publishing.
  out=$("$REC" -o "$WORK/none.jsonl" --timeout 1 --domain $((RANDOM % 100 + 100)) 2>&1) ||
    fail "the recorder failed with nothing to record: $out"
  [[ "$out" == *"recorded 0 scans; nothing written to $WORK/none.jsonl"* ]] || fail "recorder: $out"
  [ ! -e "$WORK/none.jsonl" ] || fail "the recorder wrote a file without a scan"
fi
echo "PASS"
