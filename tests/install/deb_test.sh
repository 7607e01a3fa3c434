#!/usr/bin/env bash
# The .deb: built with cpack from the build tree, installed on this machine
# with dpkg -i, its four services started as their installed units say (as
# the unit's user, from the installed configs, the source and build trees
# hidden from them) on a scan log, then purged: nothing may be left (files,
# state, user, group). Needs root and dpkg (skipped otherwise, exit 77); the
# build-tree binaries other tests run read the source tree only, so an
# installed package does not change what they do.
#
#   deb_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD="$(cd "$1" && pwd)" SRC="$(cd "$2" && pwd)"
[ "$(id -u)" = 0 ] || { echo "SKIP: installing a .deb needs root"; exit 77; }
for tool in dpkg dpkg-deb cpack setpriv systemd-analyze; do
  command -v "$tool" > /dev/null || { echo "SKIP: $tool is missing (scripts/install-deps.sh installs it)"; exit 77; }
done
if [ -z "${SCANFILTER_IN_NETNS:-}" ]; then
  unshare -n true 2>/dev/null || { echo "SKIP: cannot create a private network namespace (unshare -n)"; exit 77; }
  exec unshare -n env SCANFILTER_IN_NETNS=1 bash -c 'ip link set lo up && exec bash "$0" "$@"' "$0" "$@"
fi
HERE="$(cd "$(dirname "$0")" && pwd)"
WORK=$(mktemp -d /tmp/scanfilter-deb-test.XXXXXX)
installed() {
  local status
  status=$(dpkg-query -W -f='${Status}' scanfilter 2>/dev/null) || true
  [ "$status" = "install ok installed" ]
}
purge() { dpkg --purge scanfilter > "$WORK/purge.log" 2>&1; }
cleanup() {
  if [ -n "${INSTALLED_BY_US:-}" ]; then purge || cat "$WORK/purge.log"; fi
  rm -rf "$WORK"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }
# shellcheck source=install_checks.sh
. "$HERE/install_checks.sh"

status=$(dpkg-query -W -f='${Status}' scanfilter 2>/dev/null) || true
[ -z "$status" ] || [ "$status" = "unknown ok not-installed" ] ||
  fail "a scanfilter package is already on this machine ($status); this test installs and purges its own"

# The package.
out=$(cpack --config "$BUILD/CPackConfig.cmake" -B "$WORK/package" 2>&1) || fail "cpack: $out"
deb=$(ls "$WORK"/package/scanfilter_*.deb)
control=$(dpkg-deb -f "$deb")
grep -q '^Depends: .*adduser' <<<"$control" || fail "the package does not depend on adduser: $control"
grep -q '^Depends: .*libfastrtps' <<<"$control" || fail "dpkg-shlibdeps found no Fast DDS dependency: $control"
conffiles=$(dpkg-deb --ctrl-tarfile "$deb" | tar -xO ./conffiles)
grep -qx /etc/scanfilter/jump_filter.yaml <<<"$conffiles" || fail "the configs are not conffiles: $conffiles"
echo "package: $(basename "$deb"), $(stat -c %s "$deb") bytes"

# Installed.
INSTALLED_BY_US=1
out=$(dpkg -i "$deb" 2>&1) || fail "dpkg -i: $out"
installed || fail "dpkg -i succeeded but the package is not installed"
BIN_DIR=/usr/bin CONF_DIR=/etc/scanfilter UNIT_DIR=/usr/lib/systemd/system
check_installed_files
check_no_tree_paths "$SRC" "$BUILD"
check_default_configs
check_units
getent passwd scanfilter > /dev/null || fail "postinst created no scanfilter user"
[ "$(stat -c '%U:%G %a' /var/lib/scanfilter)" = "scanfilter:scanfilter 750" ] ||
  fail "/var/lib/scanfilter: $(stat -c '%U:%G %a' /var/lib/scanfilter), expected scanfilter:scanfilter 750"

"$BUILD/tools/scanfilter" simulate --scene hall --seed 6 --max-frames 50 -o "$WORK/in.scanlog.jsonl" > /dev/null
if [[ "$BUILD" == "$SRC"/* ]]; then hide=(--hide "$SRC"); else hide=(--hide "$BUILD" --hide "$SRC"); fi
mkdir "$WORK/run"
bash "$HERE/run_installed_pipeline.sh" "$UNIT_DIR" "$BIN_DIR" /var/lib/scanfilter/map "$WORK/in.scanlog.jsonl" \
  "$WORK/run" --as-unit-user "${hide[@]}"
[ "$(stat -c %U /var/lib/scanfilter/map.pgm)" = scanfilter ] || fail "the map was not saved by the scanfilter user"

shm=$(find /dev/shm -user scanfilter) || true
[ -z "$shm" ] || fail "the stopped services left shared memory behind: $shm"

# Purged: nothing left.
purge || fail "dpkg --purge: $(cat "$WORK/purge.log")"
INSTALLED_BY_US=
status=$(dpkg-query -W -f='${Status}' scanfilter 2>/dev/null) || true
[ -z "$status" ] || [ "$status" = "unknown ok not-installed" ] || fail "after purge dpkg still knows scanfilter: $status"
left=$(ls -d /usr/bin/scanfilter* /etc/scanfilter /var/lib/scanfilter /usr/lib/systemd/system/scanfilter* \
         /usr/share/doc/scanfilter 2>/dev/null) || true
[ -z "$left" ] || fail "left after purge: $left"
! getent passwd scanfilter > /dev/null || fail "the scanfilter user is left after purge"
! getent group scanfilter > /dev/null || fail "the scanfilter group is left after purge"
echo "purged: no files, state, user or group left"
echo PASS
