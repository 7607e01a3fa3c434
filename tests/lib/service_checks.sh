# Sourced by shell tests that run services: reading their Prometheus
# endpoints, waiting for DDS matches, and failing with the tail of every log
# in $WORK. Pages are captured before they are searched: under pipefail,
# piping curl into a grep that quits at its first match fails at random
# (curl gets SIGPIPE).
scrape() {  # port: the service's metrics page, empty if it does not answer
  curl -s --max-time 2 "http://127.0.0.1:$1/metrics" || true
}
metric() {  # port name-and-labels-regex: prints the value (integer part), nothing if absent
  local page
  page=$(scrape "$1")
  { grep -E -m 1 "^$2 " <<<"$page" | awk '{print int($2)}'; } || true
}
matched() {  # port endpoint topic: peers matched by that endpoint (scanfilter_dds_matched, updated every second)
  local page
  page=$(scrape "$1")
  awk -v ep="endpoint=\"$2\"" -v topic="topic=\"$3\"" \
    'index($0, "scanfilter_dds_matched{") == 1 && index($0, ep) && index($0, topic) {print int($2)}' <<<"$page"
}
# port endpoint topic [count]: until that endpoint has matched that many peers
# (1), for MATCH_WAIT_S seconds at most (20); fails at once if a PID in the
# WATCH array (when the test sets one) has died.
wait_matched() {
  local deadline=$((SECONDS + ${MATCH_WAIT_S:-20})) n want=${4:-1} pid
  while :; do
    for pid in ${WATCH[@]+"${WATCH[@]}"}; do kill -0 "$pid" 2>/dev/null || fail "service $pid died"; done
    n=$(matched "$1" "$2" "$3")
    [ "${n:-0}" -ge "$want" ] && return 0
    [ "$SECONDS" -lt "$deadline" ] ||
      fail "the $2 of $3 on :$1 matched ${n:-no} peers within ${MATCH_WAIT_S:-20} s, expected $want"
    sleep 0.1
  done
}
fail() {  # the failing check, then the tail of every log in $WORK and one level below
  echo "FAIL: $*"
  for f in "$WORK"/*.log "$WORK"/*/*.log; do
    if [ -f "$f" ]; then echo "--- $f"; tail -n 20 "$f"; fi
  done
  exit 1
}
