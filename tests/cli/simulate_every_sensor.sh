#!/usr/bin/env bash
# `scanfilter simulate` puts every sensor preset on a scene, at its own or a
# given angular step, logs drifting odometry unless told to log the true
# poses, and refuses an unknown sensor; replay reads what it writes, and
# info and replay report the artefacts' causes.
#
#   simulate_every_sensor.sh SCANFILTER
set -euo pipefail
SF="$1"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

check() {  # check SENSOR BEAMS [ARGS...]: BEAMS a scan in the log
  local sensor="$1" beams="$2"
  shift 2
  local log="$WORK/$sensor-$beams.scanlog.jsonl"
  "$SF" simulate --scene hall --sensor "$sensor" --seed 2 --max-frames 3 -o "$log" "$@" > /dev/null ||
    fail "simulate --sensor $sensor $*"
  local info
  info=$("$SF" info "$log")
  [[ "$info" == *"($beams-$beams beams)"* ]] || fail "$sensor: expected $beams beams: $info"
  [[ "$info" == *"sensor $sensor"* ]] || fail "$sensor: the header does not name the sensor: $info"
  "$SF" replay "$log" -q || fail "replay of the $sensor log"
}
check tof 1440
check tof 720 --beams 720
check triangulation 360

"$SF" simulate --scene office --max-frames 2 -o "$WORK/own.scanlog.jsonl" > /dev/null
[[ $(head -1 "$WORK/own.scanlog.jsonl") == *"odometry drift 1 %, 0.5°/m"* ]] || fail "drift is not on by default"
"$SF" simulate --scene office --max-frames 2 --true-poses -o "$WORK/true.scanlog.jsonl" > /dev/null
[[ $(head -1 "$WORK/true.scanlog.jsonl") == *"true poses"* ]] || fail "--true-poses does not log the true poses"

# Every artefact carries its cause: info counts them, replay scores each.
"$SF" simulate --scene office --seed 2 --max-frames 30 -o "$WORK/causes.scanlog.jsonl" > /dev/null
info=$("$SF" info "$WORK/causes.scanlog.jsonl")
[[ "$info" =~ through\ a\ pane=([0-9]+) ]] || fail "info does not count the causes: $info"
[ "${BASH_REMATCH[1]}" -gt 0 ] || fail "the office's partition transmitted nothing in 30 scans: $info"
replayed=$("$SF" replay "$WORK/causes.scanlog.jsonl")
[[ "$replayed" == *"recall by cause"*"through a pane"* ]] || fail "replay does not score the causes: $replayed"

set +e
out=$("$SF" simulate --scene hall --sensor sonar -o "$WORK/x.scanlog.jsonl" 2>&1)
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "an unknown sensor exits $rc, not 2"
[[ "$out" == *"not a built-in sensor (tof, triangulation)"* ]] || fail "the error does not offer the presets: $out"
echo "PASS"
