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
elif grep -q '^ARMMIMIC_CLI_ONLY:BOOL=ON' "$BUILD_DIR/CMakeCache.txt"; then
  # scripts/demo.sh configured the CLI alone; the whole build reuses what it compiled.
  cmake "$BUILD_DIR" -DARMMIMIC_CLI_ONLY=OFF "$@" >/dev/null
elif (($# > 0)); then
  cmake "$BUILD_DIR" "$@" >/dev/null
fi
# 2 parallel jobs unless told otherwise: the GUI and test TUs need ~1 GB each.
cmake --build "$BUILD_DIR" -j "${ARMMIMIC_JOBS:-$(nproc)}"
