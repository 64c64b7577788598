#!/usr/bin/env bash
# The lint gate: clang-format and clang-tidy on armmimic's C++ sources; any finding fails it.
#   scripts/lint.sh [--all | --base REV] [--format | --tidy] [--build DIR] [--jobs N]
#   (default)     the files changed since the commit named in .ci/lint-base (committed, staged,
#                 unstaged or untracked), so a fresh clone checks a well-defined set
#   --all         every file
#   --base REV    the files changed since REV
#   --format      only the format check: clang-format --dry-run -Werror with .clang-format, on
#                 every C++ file in the repository (src, include, tests, bench)
#   --tidy        only the tidy check: clang-tidy with .clang-tidy, every warning an error, on
#                 the non-GUI sources src/{core,engines,synth,robot,sim,serial,live,cli}; it
#                 reads DIR/compile_commands.json (default build; any configured build folder)
#   --jobs N      parallel clang-format/clang-tidy processes (default: nproc)
# For tidy, a changed header brings in every non-GUI source that includes it by name, and a
# change to .clang-tidy or to this script brings in every non-GUI source.
# Each violation is printed as FILE:LINE:COLUMN with the check's name; the exit status is 0 when
# clean, 1 on a violation and 2 on a usage error or a missing tool or build folder.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD

mode=changed
base=""
do_format=1
do_tidy=1
build=build
jobs=$(nproc)
usage() {
  echo "usage: scripts/lint.sh [--all | --base REV] [--format | --tidy] [--build DIR] [--jobs N]" >&2
  exit 2
}
while (($# > 0)); do
  case "$1" in
    --all) mode=all ;;
    --base) [[ $# -ge 2 ]] || usage; base="$2"; shift ;;
    --format) do_tidy=0 ;;
    --tidy) do_format=0 ;;
    --build) [[ $# -ge 2 ]] || usage; build="$2"; shift ;;
    --jobs) [[ "${2:-}" =~ ^[1-9][0-9]*$ ]] || usage; jobs="$2"; shift ;;
    -h | --help) sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "lint: unknown option $1" >&2; usage ;;
  esac
  shift
done

for tool in clang-format clang-tidy; do
  if ! command -v "$tool" >/dev/null; then
    echo "lint: $tool not found (scripts/deps.sh --with-lint installs it)" >&2
    exit 2
  fi
done

CXX_RE='\.(cpp|cc|h|hpp)$'
TIDY_RE='^src/(core|engines|synth|robot|sim|serial|live|cli)/.*\.cpp$'

# The candidate files, relative to the repository root.
if [[ $mode == changed ]]; then
  if [[ -n $base ]] && ! git rev-parse -q --verify "$base^{commit}" >/dev/null; then
    echo "lint: --base $base: no such commit" >&2
    exit 2
  fi
  if [[ -z $base ]]; then base=$(grep -v '^#' .ci/lint-base | tr -d '[:space:]'); fi
  if ! git rev-parse -q --verify "$base^{commit}" >/dev/null; then
    echo "lint: base $base is not in this clone (a shallow clone?); checking every file" >&2
    mode=all
  fi
fi
if [[ $mode == all ]]; then
  mapfile -t changed < <(git ls-files)
  echo "lint: every file"
else
  mapfile -t changed < <({ git diff --name-only --diff-filter=d "$base" --;
    git ls-files --others --exclude-standard; } | sort -u)
  echo "lint: ${#changed[@]} file(s) changed since $(git rev-parse --short "$base")"
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0

if ((do_format)); then
  printf '%s\n' "${changed[@]}" | grep -E "$CXX_RE" | grep -v '^build' >"$tmp/format" || true
  n=$(wc -l <"$tmp/format")
  echo "lint: clang-format on $n file(s)"
  # One process per file so that each file's findings stay together in the output.
  if ((n > 0)) && ! xargs -a "$tmp/format" -P "$jobs" -n 1 \
      clang-format --dry-run -Werror --style=file 2>"$tmp/format.out"; then
    cat "$tmp/format.out" >&2
    bad=$(grep -oE '^[^:]+:[0-9]+:[0-9]+: error' "$tmp/format.out" | cut -d: -f1 | sort -u)
    echo "lint: clang-format: $(grep -c ': error:' "$tmp/format.out") violation(s) in" \
      "$(echo "$bad" | wc -l) file(s); fix with: clang-format -i" $bad >&2
    failed=1
  fi
fi

if ((do_tidy)); then
  db="$build/compile_commands.json"
  if [[ ! -f $db ]]; then
    echo "lint: $db not found: configure a build first (cmake --preset dev, or scripts/build.sh)" >&2
    exit 2
  fi
  git ls-files | grep -E "$TIDY_RE" | sort >"$tmp/tidy-all"
  if [[ $mode == all ]] || printf '%s\n' "${changed[@]}" | grep -qxE '\.clang-tidy|scripts/lint\.sh'; then
    cp "$tmp/tidy-all" "$tmp/tidy"
  else
    printf '%s\n' "${changed[@]}" | grep -E "$TIDY_RE" >"$tmp/tidy" || true
    # A changed header: every non-GUI source that includes it by its file name.
    for h in $(printf '%s\n' "${changed[@]}" | grep -E '\.(h|hpp)$' || true); do
      name=$(basename "$h")
      xargs -a "$tmp/tidy-all" grep -lE "^#include [<\"]([^\">]*/)?${name//./\\.}[\">]" \
        >>"$tmp/tidy" || true
    done
    sort -u -o "$tmp/tidy" "$tmp/tidy"
  fi
  # Every source must be in the compile database (a new file needs a re-run of cmake).
  sed -n 's/^ *"file": "\(.*\)",\{0,1\}$/\1/p' "$db" | sed "s|^$ROOT/||" | sort -u >"$tmp/db"
  missing=$(comm -23 "$tmp/tidy" "$tmp/db")
  if [[ -n $missing ]]; then
    echo "lint: not in $db (re-run cmake on $build):" $missing >&2
    exit 2
  fi
  n=$(wc -l <"$tmp/tidy")
  echo "lint: clang-tidy on $n non-GUI source(s), $jobs at a time"
  mkdir -p "$tmp/tidy.out"
  start=$(date +%s)
  # Each file's report goes to its own log, printed whole, so that parallel runs do not mix.
  xargs -a "$tmp/tidy" -P "$jobs" -I{} sh -c \
    'log="$2/$(echo "$1" | tr / _).log"
     clang-tidy -p "$0" --quiet --warnings-as-errors="*" "$1" >"$log" 2>&1 || echo "$1" >>"$log.failed"' \
    "$build" {} "$tmp/tidy.out" || true
  echo "lint: clang-tidy took $(($(date +%s) - start)) s"
  if compgen -G "$tmp/tidy.out/*.failed" >/dev/null; then
    for f in "$tmp"/tidy.out/*.failed; do
      grep -vE '^[0-9]+ warnings? (and [0-9]+ errors? )?generated\.$' "${f%.failed}" >&2 || true
    done
    cat "$tmp"/tidy.out/*.log | grep -oE '\[[a-z0-9.,-]+\]$' | sort | uniq -c | sort -rn \
      >"$tmp/checks" || true
    echo "lint: clang-tidy: findings in $(ls "$tmp"/tidy.out/*.failed | wc -l) source(s):" >&2
    sed 's/^/  /' "$tmp/checks" >&2
    failed=1
  fi
fi

if ((failed)); then
  echo "lint: FAILED" >&2
  exit 1
fi
echo "lint: clean"
