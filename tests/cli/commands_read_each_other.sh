#!/usr/bin/env bash
# What one command writes, every other reads: `scanfilter replay` of a log
# whose stamps step back (the Intel CARMEN log, line 5647) writes them in file
# order, and info, render, diff and map read that output, count the
# regression and carry on.
#
#   commands_read_each_other.sh SCANFILTER LOG
set -euo pipefail
SF="$1" LOG="$2"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$SF" replay "$LOG" -o "$WORK/out.scanlog.jsonl" -q 2> "$WORK/replay.err" || fail "replay: $(cat "$WORK/replay.err")"
info=$("$SF" info "$WORK/out.scanlog.jsonl" 2>&1) || fail "info refused replay's output: $info"
[[ "$info" =~ stamps:\ +([0-9]+)\ earlier ]] || fail "info does not report stamp regressions: $info"
[ "${BASH_REMATCH[1]}" -ge 1 ] || fail "info counted no stamp regression in a log that has one"
render=$("$SF" render "$WORK/out.scanlog.jsonl" -o "$WORK/out.png" 2>&1) || fail "render refused: $render"
[ -s "$WORK/out.png" ] || fail "render wrote no picture"
diff_out=$("$SF" diff "$WORK/out.scanlog.jsonl" "$WORK/out.scanlog.jsonl" 2>&1) || fail "diff refused: $diff_out"
map_out=$("$SF" map "$WORK/out.scanlog.jsonl" -o "$WORK/map" 2>&1) || fail "map refused: $map_out"
again=$("$SF" replay "$WORK/out.scanlog.jsonl" -o "$WORK/again.scanlog.jsonl" -q 2>&1) || fail "replay of replay: $again"
same=$("$SF" diff "$WORK/out.scanlog.jsonl" "$WORK/again.scanlog.jsonl" 2>&1) || fail "a second replay labels differently: $same"
echo "PASS: $info"
