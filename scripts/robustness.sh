#!/usr/bin/env bash
# The robustness benchmark (docs/accuracy.md): builds the `robustness` program and runs every arm
# engine in every calibration mode over randomised scenes.
#   scripts/robustness.sh [--build DIR] [--out DIR] [--update-docs] [robustness options...]
# Without options: the 210 held-out scenes (70 per tier). `--set tuning` runs 60 tuning scenes
# (a minute or two). Other options go to the program (`build/bench/robustness --help`).
# --update-docs writes the run's table (and, for the tuning set, the breakdown by scene feature)
# into docs/accuracy.md; only the standard runs (--set and --threads may be given).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=build
OUT=""
SET=heldout
UPDATE=no
STANDARD=yes
args=()
while (($# > 0)); do
  case "$1" in
    --build) BUILD="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    --update-docs) UPDATE=yes; shift ;;
    --set) SET="$2"; args+=("$1" "$2"); shift 2 ;;
    --threads) args+=("$1" "$2"); shift 2 ;;
    -h | --help) args+=("$1"); shift ;;
    *) STANDARD=no; args+=("$1"); shift ;;
  esac
done
if [[ ! -f "$BUILD/build.ninja" && ! -f "$BUILD/Makefile" ]]; then
  echo "robustness: $BUILD is not a configured build folder; run scripts/build.sh $BUILD first" >&2
  exit 2
fi
if [[ "$UPDATE" == yes && "$STANDARD" == no ]]; then
  echo "robustness: --update-docs records the standard runs only (--set and --threads)" >&2
  exit 2
fi
cmake --build "$BUILD" --target robustness -j "${ARMMIMIC_JOBS:-2}" >/dev/null
OUT="${OUT:-$BUILD/robustness-$SET}"
"$BUILD/bench/robustness" --out "$OUT" "${args[@]}"
[[ "$UPDATE" == yes ]] || exit 0

# Replaces the lines between <!-- robustness:KEY --> and <!-- /robustness:KEY --> with a file.
splice() {
  local doc=docs/accuracy.md key="$1" src="$2"
  grep -qx "<!-- robustness:$key -->" "$doc" || { echo "robustness: no $key block in $doc" >&2; exit 1; }
  awk -v begin="<!-- robustness:$key -->" -v end="<!-- /robustness:$key -->" -v src="$src" '
    $0 == begin { print; while ((getline line < src) > 0) print line; skip = 1; next }
    $0 == end { skip = 0 }
    !skip { print }' "$doc" >"$doc.tmp"
  mv "$doc.tmp" "$doc"
}
splice "$SET:table" "$OUT/table.md"
# The breakdown by scene feature is published for the tuning set only: engine work starts from
# it, and never from the held-out scenes.
[[ "$SET" == tuning ]] && splice "$SET:features" "$OUT/features.md"
echo "robustness: docs/accuracy.md updated ($SET)" >&2
