# Sourced by the DDS test scripts, first thing after their arguments are read.
#
# 1. Re-runs the calling script in a private network namespace with only `lo`
#    up (as root, where unshare works), so tests running at the same time
#    never see each other's participants; elsewhere the script stays on the
#    host and relies on its random domain and the loopback-only profile.
# 2. Gives the script a random DOMAIN, a scratch WORK directory and a PIDS
#    list whose processes are killed, and WORK removed, when it exits.
# Sourced, $0 and "$@" are the calling script's own.
if [ -z "${SCANFILTER_IN_NETNS:-}" ] && [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
  exec unshare -n env SCANFILTER_IN_NETNS=1 bash -c 'ip link set lo up && exec bash "$0" "$@"' "$0" "$@"
fi
# 3. TIME_FACTOR: scripts/sanitize.sh sets SCANFILTER_TEST_TIME_FACTOR, as the
#    instrumented services run several times slower; the limits that measure
#    their speed (how fast a service stops or starts) are multiplied by it.
#    Waits for a condition are not: they are bounded generously already.
TIME_FACTOR=${SCANFILTER_TEST_TIME_FACTOR:-1}
DOMAIN=$(( (RANDOM % 200) + 10 ))
WORK=$(mktemp -d)
PIDS=()
cleanup() {
  for pid in "${PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  # Reaped before WORK goes, so that none of them writes into it meanwhile.
  for pid in "${PIDS[@]}"; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$WORK"
}
trap cleanup EXIT
