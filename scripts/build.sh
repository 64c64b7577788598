#!/usr/bin/env bash
# Installs missing packages, configures and builds armmimic.
#   scripts/build.sh [BUILD_DIR] [extra cmake args...]   (default BUILD_DIR: build)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
shift || true
scripts/deps.sh
if [[ ! -f "$BUILD_DIR/build.ninja" ]]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
elif (($# > 0)); then
  cmake "$BUILD_DIR" "$@" >/dev/null
fi
# 2 parallel jobs unless told otherwise: the GUI and test TUs need ~1 GB each.
cmake --build "$BUILD_DIR" -j "${ARMMIMIC_JOBS:-$(nproc)}"
