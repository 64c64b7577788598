#!/usr/bin/env bash
# Makes the Debian package from an existing build and checks what it holds: both programs, the
# desktop entry, the icon and both man pages.
#   scripts/package.sh [--install-check] [BUILD_DIR]   (default: build)
# --install-check also installs it with apt (root), starts both programs from /usr/bin (with no
# display), and removes it again: for CI's fresh machine. By hand, install it with
#   apt install ./BUILD_DIR/armmimic_<version>_<arch>.deb
set -euo pipefail
cd "$(dirname "$0")/.."
install_check=no
if [[ "${1:-}" == "--install-check" ]]; then
  install_check=yes
  shift
fi
BUILD_DIR="${1:-build}"
[[ -f "$BUILD_DIR/CPackConfig.cmake" ]] || {
  echo "package.sh: $BUILD_DIR is not a configured build folder (scripts/build.sh $BUILD_DIR)" >&2
  exit 2
}
cmake --build "$BUILD_DIR" -j "${ARMMIMIC_JOBS:-$(nproc)}" >&2
rm -f "$BUILD_DIR"/armmimic_*.deb
(cd "$BUILD_DIR" && cpack -G DEB >/dev/null)
deb=$(ls "$BUILD_DIR"/armmimic_*.deb)
contents=$(dpkg-deb -c "$deb")
missing=()
for f in ./usr/bin/armmimic ./usr/bin/armmimic-cli ./usr/share/applications/armmimic.desktop \
  ./usr/share/icons/hicolor/scalable/apps/armmimic.svg ./usr/share/man/man1/armmimic-cli.1.gz \
  ./usr/share/man/man1/armmimic.1.gz; do
  grep -q " $f\$" <<<"$contents" || missing+=("$f")
done
if ((${#missing[@]} > 0)); then
  echo "package.sh: $deb lacks ${missing[*]}" >&2
  exit 1
fi
echo "$deb: $(du -k "$deb" | cut -f1) KiB; depends: $(dpkg-deb -f "$deb" Depends)"

if [[ $install_check == yes ]]; then
  if dpkg-query -W -f='${Status}' armmimic 2>/dev/null | grep -q "install ok installed"; then
    echo "package.sh: armmimic is installed already; not touching it" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq "./$deb" >/dev/null
  rc=0
  (cd / && env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM /usr/bin/armmimic --version &&
    /usr/bin/armmimic-cli --help >/dev/null && man -w armmimic-cli >/dev/null) || rc=$?
  apt-get remove -y -qq armmimic >/dev/null
  if ((rc != 0)); then
    echo "package.sh: the installed programs did not start (exit $rc)" >&2
    exit 1
  fi
  echo "$deb: installs with apt, both programs start from /usr/bin, removed again"
fi
