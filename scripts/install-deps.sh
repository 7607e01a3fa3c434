#!/usr/bin/env bash
# Installs every Debian package scanfilter needs to build, test and run.
# Idempotent: packages already present are left as they are. Needs root (or sudo).
set -euo pipefail

PACKAGES=(
  # build
  build-essential cmake ninja-build ccache pkg-config git
  # core library
  libeigen3-dev libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libspdlog-dev
  libpng-dev zlib1g-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # DDS services (issue 3 and later)
  libfastrtps-dev libfastcdr-dev fastddsgen fastdds-tools prometheus-cpp-dev
  cyclonedds-dev cyclonedds-tools prometheus iproute2 util-linux curl tcpdump
  # systemd units and the .deb (issue 11): sd_notify, systemd-analyze,
  # dpkg-shlibdeps for cpack's dependency list, the notify test, the
  # system-call filter test
  libsystemd-dev systemd dpkg-dev adduser python3 strace
  # DDS Security keystores (deploy/security/make-keystore.sh, tests/security/)
  openssl
  # fuzzing (scripts/fuzz.sh: libFuzzer, ASan, UBSan)
  clang libclang-rt-14-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  # Captured first: under pipefail, piping dpkg-query into a grep that quits
  # at its first match can fail (dpkg-query gets SIGPIPE).
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null) || true
  grep -q "install ok installed" <<<"$status" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
