#!/usr/bin/env bash
# Takes the screenshots of docs/user-guide.md: builds the application and its screenshot tour,
# then walks the workflow in a real window on a virtual X server (xvfb-run) with the sample scene.
#   scripts/screenshots.sh [BUILD_DIR] [REAL_DIR]     (default: build)
# REAL_DIR, when given, holds the real clip pose_squats.mp4 for the real-video walkthrough (the
# clip is not part of the project).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
real=()
[ -n "${2:-}" ] && real=("$2")
[ -f "$build/build.ninja" ] || cmake -S . -B "$build" -G Ninja
ninja -C "$build" -j2 armmimic-cli armmimic-screenshot-tour
if [ ! -f data/sample/scene.avi ]; then
  "$build/bin/armmimic-cli" synth arm data/sample
fi
unset QT_QPA_PLATFORM  # a real X window, not the offscreen platform
xvfb-run -a -s "-screen 0 1600x1000x24" \
  "$build/bin/armmimic-screenshot-tour" docs/images data/sample "${real[@]}"
