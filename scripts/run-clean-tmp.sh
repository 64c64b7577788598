#!/usr/bin/env bash
# Runs a command with TMPDIR set to a fresh, empty folder and fails when anything is left in that
# folder afterwards: the test suite must remove every file it makes, its own and those of the
# programs it runs. What was left is listed, then removed with the folder.
#   scripts/run-clean-tmp.sh COMMAND [ARGS...]     e.g. scripts/run-clean-tmp.sh scripts/test.sh
set -euo pipefail
if (($# == 0)); then
  echo "usage: scripts/run-clean-tmp.sh COMMAND [ARGS...]" >&2
  exit 2
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/armmimic-clean-tmp.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
# Open like /tmp (sticky, everyone may enter): some tests run the program as another user.
chmod 1777 "$tmp"
rc=0
TMPDIR="$tmp" "$@" || rc=$?
left=$(find "$tmp" -mindepth 1 -maxdepth 3 | sort)
if [[ -n "$left" ]]; then
  echo "run-clean-tmp: '$*' left files in its TMPDIR ($(du -sh "$tmp" | cut -f1)):" >&2
  echo "$left" | head -n 100 | sed -e "s|^$tmp/|  |" >&2
  (($(echo "$left" | wc -l) > 100)) && echo "  ..." >&2
  exit $((rc == 0 ? 1 : rc))
fi
exit "$rc"
