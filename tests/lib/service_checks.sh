# Sourced by shell tests that run services: reading their Prometheus
# endpoints, and failing with the tail of every log in $WORK.
scrape() { curl -s --max-time 2 "http://127.0.0.1:$1/metrics" || true; }
matched() {  # port endpoint topic: peers matched by that endpoint (scanfilter_dds_matched)
  local page
  page=$(scrape "$1")
  awk -v ep="endpoint=\"$2\"" -v topic="topic=\"$3\"" \
    'index($0, "scanfilter_dds_matched{") == 1 && index($0, ep) && index($0, topic) {print int($2)}' <<<"$page"
}
fail() {
  echo "FAIL: $*"
  for f in "$WORK"/*.log; do
    if [ -f "$f" ]; then echo "--- $f"; tail -n 20 "$f"; fi
  done
  exit 1
}
