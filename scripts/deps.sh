#!/usr/bin/env bash
# Installs the Debian 12 packages armmimic needs, if any is missing. Safe to run again.
#   scripts/deps.sh [--with-extras] [--with-model]
#   --with-extras  the sanitizer, fuzzing and screenshot tools too
#   --with-model   fetch the pose engine's model (MoveNet Lightning, from the npm package
#                  @vladmandic/human 3.3.6), check its SHA-256 and put it in .cache/armmimic
#                  (or $ARMMIMIC_MODEL_DIR), where armmimic finds it without flags
set -euo pipefail
cd "$(dirname "$0")/.."

WITH_EXTRAS=0
WITH_MODEL=0
for arg in "$@"; do
  case "$arg" in
    --with-extras) WITH_EXTRAS=1 ;;
    --with-model) WITH_MODEL=1 ;;
    *) echo "scripts/deps.sh: unknown option $arg (--with-extras, --with-model)" >&2; exit 2 ;;
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

PACKAGES=(
  cmake ninja-build g++ pkg-config
  qt6-base-dev qt6-base-dev-tools qt6-serialport-dev qt6-charts-dev qt6-qpa-plugins
  libqt6opengl6-dev libgl1-mesa-dev libglx-dev
  libopencv-dev libeigen3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
)
# Extra tools for the sanitizer/fuzz runs and the screenshots; installed with --with-extras.
EXTRAS=(clang libclang-rt-14-dev xvfb xauth locales)

wanted=("${PACKAGES[@]}")
if ((WITH_EXTRAS)); then wanted+=("${EXTRAS[@]}"); fi

missing=()
for p in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# A comma-decimal locale, so the tests can prove numbers are written with '.' whatever the locale.
ensure_test_locale() {
  ((WITH_EXTRAS)) || return 0
  locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$' && return 0
  [[ $(id -u) -eq 0 ]] || return 0
  sed -i 's/^# *de_DE.UTF-8 UTF-8/de_DE.UTF-8 UTF-8/' /etc/locale.gen
  grep -q '^de_DE.UTF-8 UTF-8' /etc/locale.gen || echo 'de_DE.UTF-8 UTF-8' >> /etc/locale.gen
  locale-gen >/dev/null
}

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
ensure_test_locale
if ((WITH_MODEL)); then fetch_model; fi
