#!/usr/bin/env bash
# Installs the Debian 12 packages armmimic needs, if any is missing. Safe to run again.
set -euo pipefail

PACKAGES=(
  cmake ninja-build g++ pkg-config
  qt6-base-dev qt6-base-dev-tools qt6-serialport-dev qt6-charts-dev qt6-svg-dev qt6-qpa-plugins
  libqt6opengl6-dev libgl1-mesa-dev libglx-dev
  libopencv-dev libeigen3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
)
# Extra tools for the sanitizer/fuzz runs and the screenshots; installed with --with-extras.
EXTRAS=(clang libclang-rt-14-dev xvfb xauth locales)

wanted=("${PACKAGES[@]}")
if [[ "${1:-}" == "--with-extras" ]]; then wanted+=("${EXTRAS[@]}"); fi

missing=()
for p in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# A comma-decimal locale, so the tests can prove numbers are written with '.' whatever the locale.
ensure_test_locale() {
  [[ "${1:-}" == "--with-extras" ]] || return 0
  locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$' && return 0
  [[ $(id -u) -eq 0 ]] || return 0
  sed -i 's/^# *de_DE.UTF-8 UTF-8/de_DE.UTF-8 UTF-8/' /etc/locale.gen
  grep -q '^de_DE.UTF-8 UTF-8' /etc/locale.gen || echo 'de_DE.UTF-8 UTF-8' >> /etc/locale.gen
  locale-gen >/dev/null
}

if ((${#missing[@]} == 0)); then
  ensure_test_locale "${1:-}"
  exit 0
fi

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
ensure_test_locale "${1:-}"
