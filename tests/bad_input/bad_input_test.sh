#!/usr/bin/env bash
# Bad input for one program: each of seven bad files in place of the file it
# reads (eight for the programs that read logs). Every case must exit 1-125 (not 0, not a crash), print exactly one
# line (stdout and stderr together) that names the file, and leave no output
# file behind (nor a .partial/.tmp one). Cases: missing, directory, empty,
# truncated_gzip, binary, long_line (a 2 GB line, streamed through a FIFO so
# it needs neither the disk nor the memory), wrong_type (a value of the
# wrong type; the line must be named) and, for logs, cut_short (a plain log
# cut in its last scan; the line must be named, and the players refuse it
# before publishing anything).
#
#   bad_input_test.sh BUILD_DIR SOURCE_DIR PROGRAM
#   PROGRAM: info | replay | replay_config | map | map_config | render | diff | report_real | simulate_scene |
#            simulate_sensor | bench_accuracy_config | ros_scan_publisher | scan_ingest | scan_ingest_log |
#            jump_filter | penetration_filter | map_publisher
set -euo pipefail
BUILD="$1" SRC="$2" PROGRAM="$3"
# Programs that would reach DDS never see another test's participants.
if [ -z "${SCANFILTER_IN_NETNS:-}" ] && [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
  exec unshare -n env SCANFILTER_IN_NETNS=1 bash -c 'ip link set lo up && exec bash "$0" "$@"' "$0" "$@"
fi
WORK=$(mktemp -d)
FEEDER=""
cleanup() {
  if [ -n "$FEEDER" ]; then kill "$FEEDER" 2>/dev/null || true; fi
  rm -rf "$WORK"
}
trap cleanup EXIT
SF="$BUILD/tools/scanfilter"
LONG_LINE_BYTES=$((2 * 1024 * 1024 * 1024))
# A program must give up on a bad file well within this (s).
TIME_LIMIT=120

# --- the good files the bad ones stand in for
GOOD_LOG=$WORK/good.scanlog.jsonl
cat >"$GOOD_LOG" <<'LOG'
{"scanlog":1,"source":"bad_input_test","sensor":{"mount":[0.0,0.0,0.0],"direction":"ccw","range_min":0.05,"range_max":10.0,"angular_accuracy_deg":1.0}}
{"stamp":1.0,"pose":[0.0,0.0,0.0],"angle_min":-1.5,"angle_increment":0.5,"ranges":[1.0,1.1,1.2,2.5,2.4,2.0,3.0],"labels":[0,0,0,0,0,0,0]}
{"stamp":2.0,"pose":[0.1,0.0,0.0],"angle_min":-1.5,"angle_increment":0.5,"ranges":[1.0,1.1,1.2,2.5,2.4,2.0,3.0],"labels":[0,0,0,0,0,0,0]}
LOG
cp "$SRC/deploy/fastdds-loopback.xml" "$WORK/"

# --- the bad files
BAD=$WORK/bad
mkdir -p "$BAD"
make_bad_files() {  # kind: log | yaml (what the wrong-type file is)
  : >"$BAD/empty"
  mkdir -p "$BAD/directory"
  # A real compressed log cut short: the end of the gzip stream is missing.
  local gz=$WORK/whole.gz size
  { head -n 1 "$GOOD_LOG"
    for i in $(seq 400); do sed -n "2s/\"stamp\":1.0/\"stamp\":$i/p" "$GOOD_LOG"; done; } | gzip -9 >"$gz"
  size=$(stat -c %s "$gz")
  head -c $((size / 2)) "$gz" >"$BAD/truncated.gz"
  # An executable's bytes: NULs, control bytes, invalid UTF-8.
  head -c 65536 "$(command -v bash)" >"$BAD/binary"
  if [ "$1" = log ]; then
    sed '1s/"range_min":0.05/"range_min":"near"/' "$GOOD_LOG" >"$BAD/wrong_type"
    WRONG_LINE=1
    # A plain log cut short in its last scan, 400 good scans before it: a
    # player must refuse it before publishing any of them.
    { head -n 1 "$GOOD_LOG"
      for i in $(seq 400); do sed -n "2s/\"stamp\":1.0/\"stamp\":$i/p" "$GOOD_LOG"; done
      sed -n '2p' "$GOOD_LOG" | head -c 60; } >"$BAD/cut_short.scanlog.jsonl"
  fi
}

# A FIFO that a background writer fills with one 2 GB line; the writer dies
# (SIGPIPE) once the reader gives up, or at TIME_LIMIT if nobody opens it.
make_long_line() {
  rm -f "$BAD/long_line"
  mkfifo "$BAD/long_line"
  (timeout "$TIME_LIMIT" bash -c "head -c $LONG_LINE_BYTES /dev/zero | tr '\\0' 'x' >'$BAD/long_line'" 2>/dev/null || true) &
  FEEDER=$!
}

# The outputs a program could write; none may exist after a failure.
OUT=$WORK/out
outputs_left() {
  local left
  # Files only: an output directory made before the input failed holds nothing.
  left=$(find "$WORK" -maxdepth 1 -type f \( -name 'out*' -o -name '*.partial' -o -name '*.tmp' \) -print)
  [ -d "$OUT" ] && left+=$(find "$OUT" -mindepth 1 -print)
  printf '%s' "$left"
}

failures=0
check_case() {  # case file [need_line]: runs RUN with FILE set, checks the outcome
  local name=$1 file=$2 need_line=${3:-}
  rm -rf "$OUT" "$WORK"/out*
  [ "$name" = long_line ] && make_long_line
  local status=0 output
  output=$(FILE=$file timeout "$TIME_LIMIT" bash -c "$RUN" 2>&1) || status=$?
  if [ -n "$FEEDER" ]; then kill "$FEEDER" 2>/dev/null || true; wait "$FEEDER" 2>/dev/null || true; FEEDER=""; fi
  local lines problem=""
  lines=$(grep -c . <<<"$output" || true)
  # 126 and up: not runnable, or killed by a signal (a crash, the time limit).
  if [ "$status" -eq 0 ] || [ "$status" -ge 126 ]; then problem="exit status $status, expected a failure exit (1-125)"
  elif [ "$lines" -ne 1 ]; then problem="$lines lines of output, expected exactly one"
  elif ! grep -qF "$(basename "$file")" <<<"$output"; then problem="the message does not name $(basename "$file")"
  elif [ -n "$need_line" ] && ! grep -qE "$(basename "$file"):[0-9]+:" <<<"$output"; then problem="the message names no line"
  elif [ -n "$(outputs_left)" ]; then problem="output left behind: $(outputs_left)"
  fi
  if [ -n "$problem" ]; then
    echo "FAIL $PROGRAM $name: $problem"
    printf '  | %s\n' "$(head -c 2000 <<<"$output")"
    failures=$((failures + 1))
  else
    echo "ok   $PROGRAM $name: $output"
  fi
}

run_all() {  # wrong_type_file [cut_short_file]: every case; those two must name their line
  check_case missing "$BAD/missing"
  check_case directory "$BAD/directory"
  check_case empty "$BAD/empty"
  check_case truncated_gzip "$BAD/truncated.gz"
  check_case binary "$BAD/binary"
  check_case long_line "$BAD/long_line" line
  check_case wrong_type "$1" line
  if [ -n "${2:-}" ]; then check_case cut_short "$2" line; fi
}

# A service config whose `service:` section is fine and one key has the wrong type.
service_config() {  # name: config/<name>.yaml as it ships, profiles next to it
  sed 's#profiles_file: ../deploy/fastdds-loopback.xml#profiles_file: fastdds-loopback.xml#' "$SRC/config/$1.yaml"
}
wrong_type_yaml() {  # source-file 'sed expression' output
  sed "$2" "$1" >"$3"
  if cmp -s "$1" "$3"; then echo "FAIL $PROGRAM: the wrong-type edit '$2' changed nothing"; exit 1; fi
}

case "$PROGRAM" in
  info | replay | map | render | diff | report_real | ros_scan_publisher)
    make_bad_files log
    case "$PROGRAM" in
      info) RUN="'$SF' info \"\$FILE\"" ;;
      replay) RUN="'$SF' replay \"\$FILE\" -q -o '$WORK/out.scanlog.jsonl' --render '$WORK/out.png'" ;;
      map) RUN="'$SF' map \"\$FILE\" -o '$WORK/out'" ;;
      render) RUN="'$SF' render \"\$FILE\" -o '$WORK/out.png'" ;;
      # The file against itself: both are read to the end (a good file
      # beside it would end first and stop the comparison).
      diff) RUN="'$SF' diff \"\$FILE\" \"\$FILE\"" ;;
      report_real) RUN="'$SF' report-real \"\$FILE\" -o '$OUT'" ;;
      ros_scan_publisher)
        RUN="'$BUILD/dds_tools/ros_scan_publisher' \"\$FILE\" --profiles-file '$WORK/fastdds-loopback.xml' --domain 7" ;;
    esac
    run_all "$BAD/wrong_type" "$BAD/cut_short.scanlog.jsonl"
    ;;
  replay_config | map_config | bench_accuracy_config)
    make_bad_files yaml
    wrong_type_yaml "$SRC/config/filter.yaml" 's/^\(  alpha:\) *[0-9.]*/\1 steep/' "$BAD/wrong_type.yaml"
    case "$PROGRAM" in
      replay_config) RUN="'$SF' replay '$GOOD_LOG' --config \"\$FILE\" -q -o '$WORK/out.scanlog.jsonl'" ;;
      map_config) RUN="'$SF' map '$GOOD_LOG' --config \"\$FILE\" -o '$WORK/out'" ;;
      bench_accuracy_config)
        RUN="'$SF' bench-accuracy --config \"\$FILE\" --budget 1 --max-frames 2 --no-robustness -o '$OUT'" ;;
    esac
    run_all "$BAD/wrong_type.yaml"
    ;;
  simulate_scene)
    make_bad_files yaml
    wrong_type_yaml "$SRC/config/scenes/hall.yaml" 's/^\(  speed:\) *[0-9.]*/\1 brisk/' "$BAD/wrong_type.yaml"
    RUN="'$SF' simulate --scene \"\$FILE\" --max-frames 2 -o '$WORK/out.scanlog.jsonl'"
    run_all "$BAD/wrong_type.yaml"
    ;;
  simulate_sensor)
    make_bad_files yaml
    wrong_type_yaml "$SRC/config/sensors/tof.yaml" 's/^\(  beams:\) *[0-9]*/\1 many/' "$BAD/wrong_type.yaml"
    RUN="'$SF' simulate --sensor \"\$FILE\" --max-frames 2 -o '$WORK/out.scanlog.jsonl'"
    run_all "$BAD/wrong_type.yaml"
    ;;
  scan_ingest | jump_filter | penetration_filter | map_publisher)
    make_bad_files yaml
    service_config "$PROGRAM" >"$WORK/$PROGRAM.yaml"
    wrong_type_yaml "$WORK/$PROGRAM.yaml" 's/^\(  queue_depth:\) *[0-9]*/\1 deep/' "$BAD/wrong_type.yaml"
    RUN="'$BUILD/services/$PROGRAM' --config \"\$FILE\""
    run_all "$BAD/wrong_type.yaml"
    ;;
  scan_ingest_log)
    # The log a scan_ingest config names, bad in each way.
    make_bad_files log
    service_config scan_ingest >"$WORK/scan_ingest.yaml"
    RUN="sed -e 's#^\(  kind:\) *simulator#\1 log#' -e \"s#^\(  path:\) *\\\"\\\"#\1 \$FILE#\" '$WORK/scan_ingest.yaml' >'$WORK/ingest-log.yaml' && grep -q 'kind: log' '$WORK/ingest-log.yaml' && exec '$BUILD/services/scan_ingest' --config '$WORK/ingest-log.yaml'"
    run_all "$BAD/wrong_type" "$BAD/cut_short.scanlog.jsonl"
    ;;
  *)
    echo "unknown program $PROGRAM" >&2
    exit 2
    ;;
esac

if [ "$failures" -gt 0 ]; then
  echo "FAIL: $failures case(s) of $PROGRAM"
  exit 1
fi
echo "PASS: $PROGRAM, every bad input"
