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
  robot error, a refused plan, an interrupt); 2 usage error (unknown or malformed flag, missing
  argument, an output that is one of the inputs, a folder or a socket).
- Every message names the file, line or flag it is about, e.g.
  `armmimic-cli analyze: --threshold: 'abc' is not a whole number`. The library's errors carry
  the key of the setting they are about (`analysis.arm_length`), never a flag; the CLI puts the
  flag that sets it first: `armmimic-cli analyze: --arm-length: the bgsub engine needs an
  arm-length image (thesis 5.2.3)`. An engine parameter without a flag of its own is named as
  `--param` sets it (`--param lk.window_px: ...`).
- **Global options**, accepted before or after the subcommand: `-q` (quiet: only errors),
  `--progress` / `--no-progress` (default: a progress bar when stderr is a terminal),
  `--version`.
- `--help` works on every subcommand.
- **The end of a run** (unless `-q`): `analyze` prints its rows, how many are `ok` and `lost`,
  the time and the output; where rows were lost, a second line names the three most frequent
  reasons with their rows, the note the desktop application shows on each lost frame reduced to
  its reason (details in brackets dropped, numbers written as N): `analyze: lost rows: the
  forearm lies on pixels that show no arm now (81); the upper arm lies on pixels that show no arm
  now (6); re-acquiring (2)`.
- **Outputs** (angle files, images, `.val` programs, summaries, journals, logs) are written
  into what the path names, never over it:
  - a regular file, or a new one, is written to a temporary beside it and renamed into place,
    so an interrupted run never leaves half a file (a journal or log grows in place instead);
  - a symlink is followed (chains too), and its target is replaced in the target's own folder;
    the link stays;
  - a character device (`/dev/null`, a terminal) or a FIFO is written to directly, with no
    temporary file. A FIFO with no reader is waited for 5 s, then refused (exit 1). An angle
    file that ends early there cannot be rewritten: its last line is `# complete=no`;
  - a folder, a socket or a block device is refused, before any input is read: exit 2,
    `analyze: -o out.tsv: is a folder; an output must be a file, a character device or a FIFO`.
  - The temporary is `.NAME.armmimic-tmp.XXXXXX` beside the target `NAME` (six letters or digits;
    a video's ends in its extension, `.scene.avi.armmimic-tmp.XXXXXX.avi`), locked by its writer.
    A run killed with SIGKILL leaves it behind; the next run to the same output removes every
    file of exactly that pattern whose writer is gone, and no other file.
  - File errors say what is wrong: `permission denied`, `is a folder`, `not found`.
- **Port names** (`--port`) resolve like any path: `s6/puma` is relative to the current folder.
  A bare name with no slash is tried as `./NAME`, then as `/dev/NAME` (`ttyUSB0`), and a port
  that is not found is reported with every path tried. One program at a time per device,
  whatever name each gives it (a `puma-sim --link` symlink, `/dev/pts/N`): a second one is
  refused before it writes a byte, naming the process that has the device
  ([docs/link.md](link.md)).
- **No output replaces an input.** `analyze`, `background`, `plan` and `score --plot` refuse,
  before reading anything, an output that is the same file as one of their inputs (the video,
  `--background`, `--arm-length`, `--reference`, `--params-from`, `--list`, the images an earlier
  run's header names, `ANGLES.tsv`, `--profile`, `TRUTH.tsv`): exit 2, naming both. Files are
  compared by device and inode, so `./a.tsv` for `a.tsv`, a symlink or a hard link is caught
  too. `send` refuses a journal (`INPUT.journal`) that is its `--profile`; `synth` reads no
  file. The desktop application refuses its exports the same way.
- **Signals.** SIGINT (Ctrl-C), SIGTERM (`timeout`, systemd, GNU parallel, Slurm) and SIGHUP (a
  closed terminal) stop every command the same way, and the message names the signal
  (`analyze: interrupted (SIGTERM); 120 rows kept in a.tsv (marked complete=no)`). An angle file
  keeps the rows analysed so far in a valid file marked `complete=no`; an image, a `.val`
  program or a `synth` scene is written whole or not at all; no temporary file is left; the
  exit code is 1. `send` stops the stream (its journal lets `--resume` continue); `puma-sim`
  prints its final joints and exits 0. Further signals while a command is stopping change
  nothing (GNU parallel sends SIGTERM more than once).
- **Incomplete inputs.** A video that stops clearly short of the frame count its header
  announces (more than max(2 frames, 1 %) of it), or whose read fails, is incomplete: `analyze`
  keeps the rows read in a file marked `complete=no incomplete=REASON` and exits 1. Some
  containers announce an estimate, so a smaller shortfall at the very end is only a warning.
  `plan` and `send` warn when their angle file is marked `complete=no` (interrupted or
  incomplete) and refuse it with `--strict`, exit 1: the flags are right, the file's content is
  what is refused, as for any other bad file content.
- **Repeating a run.** The header of an angle file records the engine, every engine setting
  under its `ENGINE.KEY` name (the one `--param` takes, changed or not) and the inputs besides
  the video (`background`, `background_frames`, `arm_length`, `reference`, `model_dir`, `start`,
  `shoulder`, `elbow`, `wrist`, `roi`). `armmimic-cli analyze VIDEO -o NEW.tsv --params-from
  OLD.tsv` repeats that run on VIDEO; flags given as well override what the header says. The
  older keys (`threshold=45`, `window=15`, ...) stay in the header as before.
  - A path typed relative is recorded as typed and absolute (`background=bg.png
    background_abs=/lab/take1/bg.png`), so the run repeats from any folder. Each recorded path
    is looked for where it was (the absolute one), then beside OLD.tsv (a folder moved or
    copied whole), then in the current folder; one found nowhere is an error (exit 1) that
    names OLD.tsv, the key and every path tried, unless a flag given replaces it.
  - A header that names a key twice, or a key no version of armmimic writes, is refused like an
    unknown flag: exit 2, naming `OLD.tsv:LINE` and the key. Settings this version removed are
    skipped and named once; `complete=` and `incomplete=` say what happened to the run and are
    skipped too.
- **Text files** (angle files, VAL programs, controller profiles, truth files, `--list`) may
  start with a UTF-8 byte order mark and may end their lines with CRLF; angle files may also end
  them with a CR alone (old Mac editors). A message quotes at most the start of one line of a
  file, however long the line.
- Numbers on the command line use `.` decimals whatever the locale. Points are `X,Y` and
  rectangles `X,Y,W,H`, in full-image pixels.

## Many videos

`armmimic-cli analyze VIDEO... --output-dir DIR` (or `--list FILE`, one video per line) analyses
each video on its own into `DIR/NAME.tsv` and writes `DIR/summary.tsv`: one line per video with
`video`, `angles`, `frames`, `ok`, `lost`, `coverage` (ok / frames, 0..1), `seconds`, `status`
(`ok`, `failed`, `incomplete`, `interrupted`, `skipped`) and `error`; `incomplete` is a
truncated or damaged video whose rows were kept in a file marked `complete=no`. A failing video
does not stop the others;
the exit code is 0 only when every video was analysed, 1 otherwise, 2 for a usage error (found
before any video runs). [docs/batch.md](batch.md) shows how to spread the videos over the cores
of one machine or over many machines with GNU parallel or a Slurm job array.

## The desktop application's command line

```
armmimic [--help] [--version] [VIDEO...]
```

`armmimic VIDEO` opens a video (or image files, or a folder of images) at start. `--help` and
`--version` print and exit 0 without a display (they work over ssh or in a package check); an
unknown option prints the error and `Try 'armmimic --help'.` and exits 2. Qt's own options
(`-platform offscreen`, `-style fusion`, ...) are accepted. `--` ends the options.

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
