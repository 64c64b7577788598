#!/usr/bin/env bash
# Makes the Debian packages from an existing build and checks what they hold:
#   armmimic_<version>_<arch>.deb (cpack -G DEB): both programs, the desktop entry, the icon and
#     both man pages; it recommends armmimic-models;
#   armmimic-models_<version>_all.deb: the pinned pose models that scripts/models.sh lists, taken
#     from where scripts/deps.sh --with-model put and checked them (.cache/armmimic, or
#     $ARMMIMIC_MODEL_DIR), installed in /usr/share/armmimic/models (where the programs look
#     without flags), with their licences in /usr/share/doc/armmimic-models/copyright.
# Then both are unpacked into a throwaway folder (dpkg -x) and the unpacked armmimic-cli runs the
# pose engine on a generated scene with no flag naming the model, and an empty home.
#   scripts/package.sh [--install-check] [--without-models] [BUILD_DIR]   (default: build)
# Missing or altered model files are an error naming them and the command that fetches them;
# --without-models makes armmimic alone.
# --install-check also installs them with apt (root), starts both programs from /usr/bin (with no
# display), runs the installed pose engine as above, and removes them again: for CI's fresh
# machine. By hand, install them with
#   apt install ./BUILD_DIR/armmimic_<version>_<arch>.deb ./BUILD_DIR/armmimic-models_<version>_all.deb
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/models.sh
source scripts/models.sh
install_check=no
with_models=yes
BUILD_DIR=build
for arg in "$@"; do
  case "$arg" in
    --install-check) install_check=yes ;;
    --without-models) with_models=no ;;
    -*)
      echo "package.sh: unknown option $arg (--install-check, --without-models)" >&2
      exit 2
      ;;
    *) BUILD_DIR="$arg" ;;
  esac
done
[[ -f "$BUILD_DIR/CPackConfig.cmake" ]] || {
  echo "package.sh: $BUILD_DIR is not a configured build folder (scripts/build.sh $BUILD_DIR)" >&2
  exit 2
}
MODEL_DIR="${ARMMIMIC_MODEL_DIR:-$PWD/.cache/armmimic}"
if [[ $with_models == yes ]]; then
  problems=$(model_files_problems "$MODEL_DIR")
  if [[ -n "$problems" ]]; then
    echo "package.sh: cannot make armmimic-models: ${problems//$'\n'/; }; fetch the models with" \
      "scripts/deps.sh --with-model, or pass --without-models to make armmimic alone" >&2
    exit 1
  fi
fi

cmake --build "$BUILD_DIR" -j "${ARMMIMIC_JOBS:-$(nproc)}" >&2
rm -f "$BUILD_DIR"/armmimic_*.deb "$BUILD_DIR"/armmimic-models_*.deb
(cd "$BUILD_DIR" && cpack -G DEB >/dev/null)
deb=$(ls "$BUILD_DIR"/armmimic_*.deb)

# Fails naming the files of `expected` that package $1 lacks.
check_contents() {
  local pkg="$1" contents f missing=()
  shift
  contents=$(dpkg-deb -c "$pkg")
  for f in "$@"; do
    grep -q " $f\$" <<<"$contents" || missing+=("$f")
  done
  if ((${#missing[@]} > 0)); then
    echo "package.sh: $pkg lacks ${missing[*]}" >&2
    exit 1
  fi
}
check_contents "$deb" ./usr/bin/armmimic ./usr/bin/armmimic-cli ./usr/lib/armmimic/armmimic-cvio.so \
  ./usr/share/applications/armmimic.desktop ./usr/share/icons/hicolor/scalable/apps/armmimic.svg \
  ./usr/share/man/man1/armmimic-cli.1.gz ./usr/share/man/man1/armmimic.1.gz
echo "$deb: $(du -k "$deb" | cut -f1) KiB; depends: $(dpkg-deb -f "$deb" Depends);" \
  "recommends: $(dpkg-deb -f "$deb" Recommends)"

# A licence's text as a copyright-file paragraph body (blank lines become " .").
indented() { sed -e 's/^[[:space:]]*$/./' -e 's/^/ /' "$1"; }

# The machine-readable copyright file (Debian copyright format 1.0) of armmimic-models: one
# paragraph per model file (its npm package, the tarball's and its own SHA-256, its licence) and
# per package licence file, then the licences' texts.
models_copyright() {
  local line file source sha licence holder what tarball_sha pkg_licence pkg_holder name
  echo "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/"
  echo "Upstream-Name: armmimic-models"
  local field="Source:"  # one URL a line; the field's name on the first
  for line in "${MODEL_SOURCES[@]}"; do
    IFS='|' read -r source _ <<<"$line"
    echo "$field https://www.npmjs.com/package/${source%@*}/v/${source##*@}"
    field=""
  done
  echo "Comment: The pose models armmimic runs, unmodified, checked against the SHA-256s"
  echo " pinned in armmimic's scripts/models.sh."
  for line in "${MODEL_FILES[@]}"; do
    IFS='|' read -r file source sha licence holder what <<<"$line"
    local entry
    for entry in "${MODEL_SOURCES[@]}"; do
      [[ "${entry%%|*}" == "$source" ]] && IFS='|' read -r _ tarball_sha pkg_licence pkg_holder <<<"$entry"
    done
    name=$(model_licence_name "$source")
    echo
    echo "Files: usr/share/armmimic/models/$file"
    echo "Copyright: $holder"
    echo "License: $licence"
    echo "Comment: $what."
    echo " Upstream: the npm package ${source%@*}, version ${source##*@}, file package/models/$file."
    echo " SHA-256 of the package's tarball: $tarball_sha"
    echo " SHA-256 of the file: $sha"
    echo " The npm package itself is distributed by $pkg_holder under the $pkg_licence licence"
    echo " (/usr/share/doc/armmimic-models/$name)."
  done
  for line in "${MODEL_SOURCES[@]}"; do
    IFS='|' read -r source _ pkg_licence pkg_holder <<<"$line"
    echo
    echo "Files: usr/share/doc/armmimic-models/$(model_licence_name "$source")"
    echo "Copyright: $pkg_holder"
    echo "License: $pkg_licence"
  done
  # Each licence once: a reference to Debian's copy when it has one, else the package's text.
  local seen=" "
  licence_paragraph() {
    [[ "$seen" == *" $1 "* ]] && return 0
    seen+="$1 "
    echo
    echo "License: $1"
    if [[ -f "/usr/share/common-licenses/$1" ]]; then
      echo " On Debian systems, the complete text of the $1 licence is in"
      echo " /usr/share/common-licenses/$1."
    elif [[ -n "$2" ]]; then
      indented "$2"
    else
      echo "package.sh: no text for the licence $1 (scripts/models.sh)" >&2
      exit 1
    fi
  }
  for line in "${MODEL_SOURCES[@]}"; do
    IFS='|' read -r source _ pkg_licence _ <<<"$line"
    licence_paragraph "$pkg_licence" "$MODEL_DIR/$(model_licence_name "$source")"
  done
  for line in "${MODEL_FILES[@]}"; do
    IFS='|' read -r _ _ _ licence _ <<<"$line"
    licence_paragraph "$licence" ""
  done
}

# armmimic-models_<version>_all.deb from the checked files, laid out as the main package is.
build_models_deb() {
  local stage="$BUILD_DIR/armmimic-models-root" line file source
  rm -rf "$stage"
  mkdir -p "$stage/DEBIAN" "$stage/usr/share/armmimic/models" "$stage/usr/share/doc/armmimic-models"
  for line in "${MODEL_FILES[@]}"; do
    install -m 0644 "$MODEL_DIR/${line%%|*}" "$stage/usr/share/armmimic/models/"
  done
  for line in "${MODEL_SOURCES[@]}"; do
    source="${line%%|*}"
    install -m 0644 "$MODEL_DIR/$(model_licence_name "$source")" "$stage/usr/share/doc/armmimic-models/"
  done
  models_copyright >"$stage/usr/share/doc/armmimic-models/copyright"
  chmod 0644 "$stage/usr/share/doc/armmimic-models/copyright"
  (cd "$stage" && find usr -type f -print0 | sort -z | xargs -0 md5sum) >"$stage/DEBIAN/md5sums"
  cat >"$stage/DEBIAN/control" <<CONTROL
Package: armmimic-models
Version: $(dpkg-deb -f "$deb" Version)
Architecture: all
Maintainer: $(dpkg-deb -f "$deb" Maintainer)
Installed-Size: $(du -sk "$stage/usr" | cut -f1)
Section: $(dpkg-deb -f "$deb" Section)
Priority: optional
Enhances: armmimic
Description: pose network models for armmimic
 The pinned pose networks that armmimic's pose engine and auto-calibration run
 (MoveNet SinglePose Lightning v4), installed in /usr/share/armmimic/models,
 where armmimic and armmimic-cli find them without flags. The files are taken
 unmodified from the npm packages named in the copyright file, which also
 gives their licences and SHA-256 checksums.
CONTROL
  chmod -R u=rwX,go=rX "$stage"
  models_deb="$BUILD_DIR/armmimic-models_$(dpkg-deb -f "$deb" Version)_all.deb"
  dpkg-deb --root-owner-group -Zxz --build "$stage" "$models_deb" >/dev/null
  rm -rf "$stage"
  local expected=(./usr/share/doc/armmimic-models/copyright)
  for line in "${MODEL_FILES[@]}"; do expected+=("./usr/share/armmimic/models/${line%%|*}"); done
  check_contents "$models_deb" "${expected[@]}"
  echo "$models_deb: $(du -k "$models_deb" | cut -f1) KiB; ${#MODEL_FILES[@]} model files in" \
    "/usr/share/armmimic/models, licences in /usr/share/doc/armmimic-models/copyright"
}

# Runs the pose engine of the armmimic-cli at $1, with each network, on a generated scene in
# folder $2, with no model flag, no model folder in the environment and an empty home; prints how
# many frames each found the arm in.
run_pose_without_flags() {
  local cli="$1" tmp="$2" net ok report=""
  mkdir -p "$tmp/home"
  "$cli" -q synth arm "$tmp/scene" --seed 2 --frames 12 >&2 || return 1
  for net in movenet blazepose; do
    (cd "$tmp" && env -u ARMMIMIC_MODEL_DIR -u XDG_CACHE_HOME HOME="$tmp/home" \
      "$cli" -q analyze scene/scene.avi -o "$net.tsv" --engine pose --network "$net" --side left \
      --start 105 >&2) || return 1
    ok=$(awk -F'\t' '$3 == "ok"' "$tmp/$net.tsv" | wc -l)
    if ((ok == 0)); then
      echo "package.sh: $cli's pose engine ($net) found no arm in $tmp/scene/scene.avi" >&2
      return 1
    fi
    report+="${report:+, }$net $ok of 12 frames ok"
  done
  echo "$report"
}

if [[ $with_models == yes ]]; then
  build_models_deb
  unpacked=$(mktemp -d)
  trap 'rm -rf "$unpacked"' EXIT
  dpkg -x "$deb" "$unpacked/root"
  dpkg -x "$models_deb" "$unpacked/root"
  frames=$(run_pose_without_flags "$unpacked/root/usr/bin/armmimic-cli" "$unpacked")
  echo "unpacked with dpkg -x: armmimic-cli found the models in its own ../share/armmimic/models" \
    "without flags; $frames"
  rm -rf "$unpacked"
fi

if [[ $install_check == yes ]]; then
  packages=(armmimic)
  files=("./$deb")
  if [[ $with_models == yes ]]; then
    packages+=(armmimic-models)
    files+=("./$models_deb")
  fi
  for p in "${packages[@]}"; do
    if dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      echo "package.sh: $p is installed already; not touching it" >&2
      exit 1
    fi
  done
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq "${files[@]}" >/dev/null
  rc=0
  (cd / && env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM /usr/bin/armmimic --version &&
    /usr/bin/armmimic-cli --help >/dev/null && man -w armmimic-cli >/dev/null) || rc=$?
  if ((rc == 0)) && [[ $with_models == yes ]]; then
    installed=$(mktemp -d)
    frames=$(run_pose_without_flags /usr/bin/armmimic-cli "$installed") || rc=$?
    rm -rf "$installed"
  fi
  apt-get remove -y -qq "${packages[@]}" >/dev/null
  if ((rc != 0)); then
    echo "package.sh: the installed programs did not start or run (exit $rc)" >&2
    exit 1
  fi
  echo "${files[*]}: install with apt, both programs start from /usr/bin," \
    "${frames:+the pose engine runs from the installed models without flags ($frames), }removed again"
fi
