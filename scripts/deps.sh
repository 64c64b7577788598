#!/usr/bin/env bash
# Installs the Debian 12 packages armmimic needs, if any is missing. Safe to run again.
#   scripts/deps.sh [--cli] [--with-extras] [--with-lint] [--with-model]
#   (none)         what the whole build needs: CLI, GUI, tests, benchmarks and the .deb
#   --cli          only what armmimic-cli needs (scripts/demo.sh builds the CLI alone)
#   --with-extras  the sanitizer, fuzzing and screenshot tools too, and the lint tools
#   --with-lint    clang-format and clang-tidy (scripts/lint.sh)
#   --with-model   an optional extra beyond Debian packages: fetch the pose engine's model (MoveNet Lightning, from the npm package
#                  @vladmandic/human 3.3.6), check its SHA-256 and put it in .cache/armmimic
#                  (or $ARMMIMIC_MODEL_DIR), where armmimic finds it without flags
set -euo pipefail
cd "$(dirname "$0")/.."

CLI_ONLY=0
WITH_EXTRAS=0
WITH_LINT=0
WITH_MODEL=0
for arg in "$@"; do
  case "$arg" in
    --cli) CLI_ONLY=1 ;;
    --with-extras) WITH_EXTRAS=1 ;;
    --with-lint) WITH_LINT=1 ;;
    --with-model) WITH_MODEL=1 ;;
    *)
      echo "scripts/deps.sh: unknown option $arg (--cli, --with-extras, --with-lint, --with-model)" >&2
      exit 2
      ;;
  esac
done

# The pinned model: the package tarball and the two model files inside it.
MODEL_PACKAGE="@vladmandic/human@3.3.6"
MODEL_TARBALL_SHA256=425e9c51dbbca0c8934362b170cb0d54c2529c11c654b3c03092b16e9d6ad3f7
MODEL_JSON_SHA256=df8cbde44d00f533ccc4916a7c6ebc17316532fb3fadad114ec667fef22872e9
MODEL_BIN_SHA256=bf97bc10d9c8a11200b0190ed64ce039b6252f1aff7cb552aca99b3d191c2f34

fetch_model() {
  local dir="${ARMMIMIC_MODEL_DIR:-$PWD/.cache/armmimic}"
  if [[ -f "$dir/movenet-lightning.json" && -f "$dir/movenet-lightning.bin" ]] &&
     echo "$MODEL_JSON_SHA256  $dir/movenet-lightning.json" | sha256sum -c --status &&
     echo "$MODEL_BIN_SHA256  $dir/movenet-lightning.bin" | sha256sum -c --status; then
    return 0
  fi
  if ! command -v npm >/dev/null; then
    echo "armmimic: installing npm (to fetch the pose model)" >&2
    install_packages npm
  fi
  MODEL_TMP=$(mktemp -d)
  trap 'rm -rf "$MODEL_TMP"' EXIT
  local tmp="$MODEL_TMP"
  echo "armmimic: fetching the pose model ($MODEL_PACKAGE) into $dir" >&2
  (cd "$tmp" && npm pack --silent "$MODEL_PACKAGE" >/dev/null)
  local tarball
  tarball=$(ls "$tmp"/*.tgz)
  echo "$MODEL_TARBALL_SHA256  $tarball" | sha256sum -c --status || {
    echo "armmimic: $tarball does not have the pinned SHA-256 $MODEL_TARBALL_SHA256" >&2
    exit 1
  }
  tar -xzf "$tarball" -C "$tmp" package/models/movenet-lightning.json \
    package/models/movenet-lightning.bin package/LICENSE
  echo "$MODEL_JSON_SHA256  $tmp/package/models/movenet-lightning.json" | sha256sum -c --status &&
    echo "$MODEL_BIN_SHA256  $tmp/package/models/movenet-lightning.bin" | sha256sum -c --status || {
    echo "armmimic: the model files in $tarball do not have their pinned SHA-256" >&2
    exit 1
  }
  mkdir -p "$dir"
  cp "$tmp/package/models/movenet-lightning.json" "$tmp/package/models/movenet-lightning.bin" "$dir/"
  cp "$tmp/package/LICENSE" "$dir/LICENSE-vladmandic-human"
  cat > "$dir/README" <<'TXT'
MoveNet SinglePose Lightning v4 (Google, weights under the Apache License 2.0), in TensorFlow.js
graph-model format as shipped by the npm package @vladmandic/human 3.3.6 (MIT licence, in
LICENSE-vladmandic-human). Fetched and checked by armmimic's scripts/deps.sh --with-model.
TXT
}

# armmimic-cli: compiler, CMake, Qt Core + SerialPort (moc from qt6-base-dev-tools), OpenCV, Eigen.
CLI_PACKAGES=(
  cmake ninja-build g++ pkg-config
  qt6-base-dev qt6-base-dev-tools qt6-serialport-dev
  libopencv-dev libeigen3-dev
)
# The rest of the build: the GUI, the test and benchmark libraries, and the package tools
# (help2man makes the man pages; dpkg-dev and file let `cpack -G DEB` find library dependencies).
PACKAGES=(
  "${CLI_PACKAGES[@]}"
  qt6-charts-dev qt6-svg-dev qt6-qpa-plugins libqt6opengl6-dev libgl1-mesa-dev libglx-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  help2man dpkg-dev file
)
# Extra tools for the sanitizer/fuzz runs and the screenshots; installed with --with-extras.
EXTRAS=(clang libclang-rt-14-dev xvfb xauth)
# The format and tidy checks of scripts/lint.sh; installed with --with-lint or --with-extras.
LINT=(clang-format clang-tidy)

wanted=("${PACKAGES[@]}")
if ((CLI_ONLY)); then wanted=("${CLI_PACKAGES[@]}"); fi
if ((WITH_EXTRAS)); then wanted+=("${EXTRAS[@]}"); fi
if ((WITH_EXTRAS || WITH_LINT)); then wanted+=("${LINT[@]}"); fi

missing=()
for p in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
install_packages() {
  echo "armmimic: installing $*" >&2
  local sudo=""
  if [[ $(id -u) -ne 0 ]]; then
    if command -v sudo >/dev/null; then sudo="sudo"; else
      echo "armmimic: need root (or sudo) to install: $*" >&2
      exit 1
    fi
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "$@" >/dev/null
}

if ((${#missing[@]} > 0)); then install_packages "${missing[@]}"; fi
if ((WITH_MODEL)); then fetch_model; fi
