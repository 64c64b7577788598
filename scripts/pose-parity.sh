#!/usr/bin/env bash
# Makes the pose parity tests' reference files (tests/engines/data/*parity_*.tsv): the network
# inputs of some frames (the real clip's and a generated scene's for MoveNet, by the pose_inputs
# tool; the real clip's in the crops the engine places for BlazePose, by blazepose_inputs) are
# written outside the repository, run through TensorFlow.js (WASM, one thread) by
# scripts/pose-reference.js and scripts/blazepose-reference.js, and only the numbers are kept.
#   scripts/pose-parity.sh [BUILD_DIR] [REAL_DIR]   (defaults: build, ../shared/real)
# Installs @tensorflow/tfjs-core, -converter and -backend-wasm 4.22.0 into a scratch folder
# ($ARMMIMIC_TFJS_DIR, default /tmp/armmimic-tfjs) with npm; runs offline after that.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${1:-build}"
REAL="${2:-../shared/real}"
MODEL_DIR="${ARMMIMIC_MODEL_DIR:-$PWD/.cache/armmimic}"
TFJS="${ARMMIMIC_TFJS_DIR:-/tmp/armmimic-tfjs}"
# Frames of pose_squats.mp4 (5 fps, 65 frames) and of `armmimic-cli synth arm --seed 1`
# (motion from frame 105).
REAL_FRAMES=(0 4 8 12 16 20 24 28 32 36 40 44 48 52 56 60)
SYNTH_FRAMES=(110 140 170 200 230 250)

cmake --build "$BUILD_DIR" --target pose_inputs blazepose_inputs >/dev/null
if [[ ! -d "$TFJS/node_modules/@tensorflow/tfjs-backend-wasm" ]]; then
  mkdir -p "$TFJS"
  npm install --silent --no-audit --no-fund --prefix "$TFJS" @tensorflow/tfjs-core@4.22.0 \
    @tensorflow/tfjs-converter@4.22.0 @tensorflow/tfjs-backend-wasm@4.22.0 >/dev/null
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
TOOL="$BUILD_DIR/tests/engines/pose_inputs"
mapfile -t synth < <("$TOOL" "$TMP" synth 1 "${SYNTH_FRAMES[@]}")
NODE_PATH="$TFJS/node_modules" node scripts/pose-reference.js "$MODEL_DIR" \
  tests/engines/data/pose_parity_synth.tsv "${synth[@]}"
if [[ -f "$REAL/pose_squats.mp4" ]]; then
  mapfile -t real < <("$TOOL" "$TMP" video "$REAL/pose_squats.mp4" "${REAL_FRAMES[@]}")
  NODE_PATH="$TFJS/node_modules" node scripts/pose-reference.js "$MODEL_DIR" \
    tests/engines/data/pose_parity_real.tsv "${real[@]}"
  # BlazePose on the same frames, each in the crop the pose engine places on it.
  mapfile -t blaze < <(ARMMIMIC_MODEL_DIR="$MODEL_DIR" "$BUILD_DIR/tests/engines/blazepose_inputs" \
    "$TMP" "$REAL/pose_squats.mp4" "${REAL_FRAMES[@]}")
  NODE_PATH="$TFJS/node_modules" node scripts/blazepose-reference.js "$MODEL_DIR" \
    tests/engines/data/blazepose_parity_real.tsv "${blaze[@]}"
else
  echo "scripts/pose-parity.sh: $REAL/pose_squats.mp4 not found: only the generated scene's" \
    "MoveNet reference was made" >&2
fi
ls -l tests/engines/data/*parity_*.tsv
