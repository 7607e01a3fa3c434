# Checks shared by prefix_install_test.sh and deb_test.sh (sourced; they
# define fail()).

# The installed files that every install must have, relative to the prefix
# (BIN_DIR, CONF_DIR, UNIT_DIR are set by the caller).
check_installed_files() {
  local f
  for f in scanfilter scanfilter-scan-ingest scanfilter-jump-filter scanfilter-penetration-filter \
           scanfilter-map-publisher scanfilter-scan-recorder scanfilter-ros-scan-publisher; do
    [ -x "$BIN_DIR/$f" ] || fail "not installed: $BIN_DIR/$f"
  done
  for f in scan_ingest.yaml jump_filter.yaml penetration_filter.yaml map_publisher.yaml filter.yaml \
           fastdds-loopback.xml; do
    [ -f "$CONF_DIR/$f" ] || fail "not installed: $CONF_DIR/$f"
  done
  for f in scanfilter-scan-ingest.service scanfilter-jump-filter.service scanfilter-penetration-filter.service \
           scanfilter-map-publisher.service scanfilter.target; do
    [ -f "$UNIT_DIR/$f" ] || fail "not installed: $UNIT_DIR/$f"
  done
}

# Nothing installed names the source or build tree: not the binaries (their
# default paths), not the configs, not the units.
check_no_tree_paths() {  # dirs...
  local dir hits
  for dir in "$@"; do
    hits=$(grep -l -a -r -F "$dir" "$BIN_DIR"/scanfilter* "$CONF_DIR" "$UNIT_DIR"/scanfilter*) || true
    [ -z "$hits" ] || fail "installed files name $dir: $hits"
  done
  hits=$(grep -l -r -F "../deploy" "$CONF_DIR") || true
  [ -z "$hits" ] || fail "installed configs still point at ../deploy: $hits"
}

# Each installed service's default --config is its installed config.
check_default_configs() {
  local name help
  for name in scan_ingest jump_filter penetration_filter map_publisher; do
    help=$("$BIN_DIR/scanfilter-${name//_/-}" --help)
    grep -q -F -- "--config TEXT=$CONF_DIR/$name.yaml" <<<"$help" ||
      fail "scanfilter-${name//_/-} --help: default config is not $CONF_DIR/$name.yaml: $(grep -F -- --config <<<"$help")"
  done
}

# systemd-analyze verify (the units parse, their binaries exist) and
# security --offline=yes (the exposure score, at most MAX_EXPOSURE) on
# every installed unit.
MAX_EXPOSURE=2.0
check_units() {
  local unit out score
  for unit in "$UNIT_DIR"/scanfilter*.service "$UNIT_DIR"/scanfilter.target; do
    out=$(systemd-analyze verify "$unit" 2>&1) || fail "systemd-analyze verify $unit: $out"
    [ -z "$out" ] || fail "systemd-analyze verify $unit complains: $out"
  done
  for unit in "$UNIT_DIR"/scanfilter*.service; do
    out=$(systemd-analyze security --offline=yes "$unit" 2>&1) || true
    score=$(sed -n 's/.*Overall exposure level for [^:]*: \([0-9.]*\) .*/\1/p' <<<"$out")
    [ -n "$score" ] || fail "systemd-analyze security --offline=yes $unit gave no score: $out"
    echo "exposure $(basename "$unit"): $score"
    awk -v s="$score" -v max="$MAX_EXPOSURE" 'BEGIN { exit !(s <= max) }' ||
      fail "$(basename "$unit"): exposure $score above $MAX_EXPOSURE"
  done
}
