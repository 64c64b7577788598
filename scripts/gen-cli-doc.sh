#!/usr/bin/env bash
# Regenerates docs/cli.md from armmimic-cli's own --help texts, so the page never drifts from
# the program. Usage: scripts/gen-cli-doc.sh [--check] [path/to/armmimic-cli]
# --check writes nothing and fails (exit 1, with the diff) when docs/cli.md is out of date; the
# test suite runs it so the page cannot drift.
set -euo pipefail
cd "$(dirname "$0")/.."
check=no
if [[ "${1:-}" == "--check" ]]; then
  check=yes
  shift
fi
CLI="${1:-build/bin/armmimic-cli}"
out=docs/cli.md
tmp=$(mktemp)
{
  cat <<'HEAD'
# armmimic-cli

The command-line twin of the desktop application. It fills the same option structs as the GUI,
so both write the same files for the same options. This page is generated from the program's
own `--help` texts by `scripts/gen-cli-doc.sh`.

## Conventions

- **Exit codes:** 0 ok; 1 runtime failure (unreadable video, bad file content, port error,
  robot error, a refused plan); 2 usage error (unknown or malformed flag, missing argument).
- Every message names the file, line or flag it is about, e.g.
  `armmimic-cli analyze: --threshold: 'abc' is not a whole number`.
- **Global options**, accepted before or after the subcommand: `-q` (quiet: only errors),
  `--progress` / `--no-progress` (default: a progress bar when stderr is a terminal),
  `--version`.
- `--help` works on every subcommand.
- Outputs (angle files, images, `.val` programs) are written to a temporary file beside the
  target and renamed into place: an interrupted run never leaves half a file.
- Numbers on the command line use `.` decimals whatever the locale. Points are `X,Y` and
  rectangles `X,Y,W,H`, in full-image pixels.

## A whole run

```sh
armmimic-cli synth arm scene/ --seed 7
armmimic-cli background scene/scene.avi -o bg.png --frames 45
armmimic-cli analyze scene/scene.avi -o angles.tsv --engine bgsub \
    --background bg.png --arm-length scene/armlength.png --start 45
armmimic-cli score scene/truth.tsv angles.tsv --plot err.png
armmimic-cli plan angles.tsv -o arm.val
armmimic-cli puma-sim --link /tmp/puma &
armmimic-cli send arm.val --port /tmp/puma
armmimic-cli mimic scene/scene.avi --realtime --engine bgsub --background bg.png \
    --arm-length scene/armlength.png --start 45 --port /tmp/puma -o live.tsv
```

## Commands

HEAD
  echo '```'
  "$CLI" --help
  echo '```'
  for cmd in background analyze synth "synth arm" "synth marker" score plan send mimic puma-sim; do
    echo
    echo "### $cmd"
    echo
    echo '```'
    # shellcheck disable=SC2086
    "$CLI" $cmd --help
    echo '```'
  done
} > "$tmp"
if [[ $check == yes ]]; then
  if ! diff -u "$out" "$tmp"; then
    rm -f "$tmp"
    echo "$out is out of date: run scripts/gen-cli-doc.sh and commit the result" >&2
    exit 1
  fi
  rm -f "$tmp"
  echo "$out is up to date"
  exit 0
fi
mv "$tmp" "$out"
echo "wrote $out"
