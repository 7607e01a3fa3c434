#!/usr/bin/env bash
# `cmake --install BUILD --prefix P` into a scratch prefix: the files land,
# nothing installed names the source or build tree, the installed services
# default to P/etc/scanfilter, the units verify, and the four services started
# as their units say (from P, with the source and build trees hidden from them)
# filter a scan log and save the map in P/var/lib/scanfilter.
#
#   prefix_install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD="$(cd "$1" && pwd)" SRC="$(cd "$2" && pwd)"
if [ -z "${SCANFILTER_IN_NETNS:-}" ]; then
  # Root: a private network namespace; otherwise a user namespace too (the
  # tmpfs that hides the trees needs one).
  as_root=()
  [ "$(id -u)" = 0 ] || as_root=(-r)
  unshare "${as_root[@]}" -n true 2>/dev/null ||
    { echo "SKIP: cannot create a private network namespace (unshare -n) to run the services in"; exit 77; }
  exec unshare "${as_root[@]}" -n env SCANFILTER_IN_NETNS=1 bash -c 'ip link set lo up && exec bash "$0" "$@"' "$0" "$@"
fi
HERE="$(cd "$(dirname "$0")" && pwd)"
WORK=$(mktemp -d /tmp/scanfilter-prefix-test.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# shellcheck source=install_checks.sh
. "$HERE/install_checks.sh"

PREFIX="$WORK/prefix"
out=$(cmake --install "$BUILD" --prefix "$PREFIX" 2>&1) || fail "cmake --install: $out"
BIN_DIR="$PREFIX/bin" CONF_DIR="$PREFIX/etc/scanfilter" UNIT_DIR="$PREFIX/lib/systemd/system"
check_installed_files
check_no_tree_paths "$SRC" "$BUILD"
check_default_configs
check_units

"$BUILD/tools/scanfilter" simulate --scene hall --seed 5 --max-frames 50 -o "$WORK/in.scanlog.jsonl" > /dev/null
if [[ "$BUILD" == "$SRC"/* ]]; then
  hide=(--hide "$SRC")  # a tmpfs over SRC hides BUILD within it too
else
  hide=(--hide "$BUILD" --hide "$SRC")
fi
mkdir "$WORK/run"
bash "$HERE/run_installed_pipeline.sh" "$UNIT_DIR" "$BIN_DIR" "$PREFIX/var/lib/scanfilter/map" \
  "$WORK/in.scanlog.jsonl" "$WORK/run" "${hide[@]}"
echo PASS
