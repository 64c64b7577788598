#!/usr/bin/env bash
# Makes the BlazePose parity test's reference file (tests/engines/data/blazepose_parity_real.tsv):
# BlazePose's inputs for some frames of the real clip, each in the crop the pose engine places
# on it (the blazepose_inputs tool, written outside the repository), run through TensorFlow.js
# (WASM, one thread) by scripts/blazepose-reference.js; only the landmark numbers are kept.
#   scripts/blazepose-parity.sh [BUILD_DIR] [REAL_DIR]   (defaults: build, ../shared/real)
# Installs @tensorflow/tfjs-core, -converter and -backend-wasm 4.22.0 into a scratch folder
# ($ARMMIMIC_TFJS_DIR, default /tmp/armmimic-tfjs) with npm; runs offline after that.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
REAL="${2:-../shared/real}"
MODEL_DIR="${ARMMIMIC_MODEL_DIR:-$PWD/.cache/armmimic}"
TFJS="${ARMMIMIC_TFJS_DIR:-/tmp/armmimic-tfjs}"
# Frames of pose_squats.mp4 (5 fps, 65 frames).
FRAMES=(0 4 8 12 16 20 24 28 32 36 40 44 48 52 56 60)

[[ -f "$REAL/pose_squats.mp4" ]] || {
  echo "scripts/blazepose-parity.sh: $REAL/pose_squats.mp4 not found" >&2
  exit 1
}
cmake --build "$BUILD_DIR" --target blazepose_inputs >/dev/null
if [[ ! -d "$TFJS/node_modules/@tensorflow/tfjs-backend-wasm" ]]; then
  mkdir -p "$TFJS"
  npm install --silent --no-audit --no-fund --prefix "$TFJS" @tensorflow/tfjs-core@4.22.0 \
    @tensorflow/tfjs-converter@4.22.0 @tensorflow/tfjs-backend-wasm@4.22.0 >/dev/null
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mapfile -t inputs < <(ARMMIMIC_MODEL_DIR="$MODEL_DIR" "$BUILD_DIR/tests/engines/blazepose_inputs" \
  "$TMP" "$REAL/pose_squats.mp4" "${FRAMES[@]}")
NODE_PATH="$TFJS/node_modules" node scripts/blazepose-reference.js "$MODEL_DIR" \
  tests/engines/data/blazepose_parity_real.tsv "${inputs[@]}"
ls -l tests/engines/data/blazepose_parity_real.tsv
