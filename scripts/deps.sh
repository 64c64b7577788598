#!/usr/bin/env bash
# Installs the Debian 12 packages armmimic needs, if any is missing. Safe to run again.
#   scripts/deps.sh                 what the whole build needs (CLI, GUI, tests, benchmarks, .deb)
#   scripts/deps.sh --cli           only what armmimic-cli needs (scripts/demo.sh)
#   scripts/deps.sh --with-extras   the whole build, the sanitizer/fuzz/screenshot tools and the
#                                   optional extras below
set -euo pipefail

# armmimic-cli: compiler, CMake, Qt Core + SerialPort (moc from qt6-base-dev-tools), OpenCV, Eigen.
CLI_PACKAGES=(
  cmake ninja-build g++ pkg-config
  qt6-base-dev qt6-base-dev-tools qt6-serialport-dev
  libopencv-dev libeigen3-dev
)
# The rest of the build: the GUI, the test and benchmark libraries, and the package tools
# (help2man makes the man page; dpkg-dev and file let `cpack -G DEB` find library dependencies).
PACKAGES=(
  "${CLI_PACKAGES[@]}"
  qt6-charts-dev qt6-qpa-plugins libqt6opengl6-dev libgl1-mesa-dev libglx-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  help2man dpkg-dev file
)
# Extra tools for the sanitizer/fuzz runs and the screenshots; installed with --with-extras.
EXTRAS=(clang libclang-rt-14-dev xvfb xauth)

# Optional extras: anything beyond Debian packages (downloaded models, data) goes here, in its
# own function called below for --with-extras only. armmimic-cli's demo and the test suite
# never need them.
install_optional_extras() {
  :
}

case "${1:-}" in
  --cli) wanted=("${CLI_PACKAGES[@]}") ;;
  --with-extras) wanted=("${PACKAGES[@]}" "${EXTRAS[@]}") ;;
  "") wanted=("${PACKAGES[@]}") ;;
  *)
    echo "deps.sh: unknown option $1 (usage: scripts/deps.sh [--cli | --with-extras])" >&2
    exit 2
    ;;
esac

missing=()
for p in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} > 0)); then
  echo "armmimic: installing ${missing[*]}" >&2
  SUDO=""
  if [[ $(id -u) -ne 0 ]]; then
    if command -v sudo >/dev/null; then SUDO="sudo"; else
      echo "armmimic: need root (or sudo) to install: ${missing[*]}" >&2
      exit 1
    fi
  fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [[ "${1:-}" == "--with-extras" ]]; then install_optional_extras; fi
