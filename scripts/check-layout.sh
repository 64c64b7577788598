#!/usr/bin/env bash
# The house's layout rules, checked on the source tree (ctest runs it as Layout.HouseRules):
#   scripts/check-layout.sh [SOURCE_DIR]
# - no source file (src, include, tests, bench) is over 500 lines;
# - a file over 400 lines, or with a function over 80 lines, says why in its opening comment, on
#   a line starting with "// Length:" (one short sentence: why it is one piece);
# - nothing outside src/engines/<engine>/ (and tests/engines/<engine>/) includes that engine's
#   private headers. The headers of src/engines/common/ are included only from the engine
#   folders (src/engines/*/, tests/engines/*/); common/ reaches the engines through
#   common/engine_internal.h, never through an engine's own headers;
# - core, engines, robot and synth include no Qt.
# Every violation is printed as FILE:LINE: message, and the exit status is then 1.
set -euo pipefail
ROOT="$(cd "${1:-$(dirname "$0")/..}" && pwd)"
cd "$ROOT"

# Files left out of the length rules for now, each with its reason. Keep this list empty.
NOT_YET=(
)

mapfile -t files < <(find src include tests bench -type f \( -name '*.cpp' -o -name '*.h' \) |
  LC_ALL=C sort)

awk -v max_lines=500 -v reason_lines=400 -v reason_function_lines=80 \
  -v not_yet="${NOT_YET[*]}" '
function fail(line, msg) {
  print cur ":" line ": " msg
  failures++
}

# "a/b/../c.h" -> "a/c.h"
function normalize(path,    parts, n, i, out, k) {
  n = split(path, parts, "/")
  k = 0
  for (i = 1; i <= n; i++) {
    if (parts[i] == "." || parts[i] == "") continue
    if (parts[i] == ".." && k > 0 && out[k] != "..") { k--; continue }
    out[++k] = parts[i]
  }
  path = ""
  for (i = 1; i <= k; i++) path = path (i > 1 ? "/" : "") out[i]
  return path
}

# Where `#include "inc"` lands: the including file'"'"'s folder, then src/engines/ (the engines'"'"'
# include root). Empty when it is none of the checked files (a public or generated header).
function resolve(inc,    dir, cand) {
  dir = cur
  sub(/\/[^\/]*$/, "", dir)
  cand = normalize(dir "/" inc)
  if (cand in known) return cand
  cand = normalize("src/engines/" inc)
  if (cand in known) return cand
  return ""
}

function finish_file() {
  if (cur == "" || skip_lengths) return
  if (lines > max_lines) {
    fail(max_lines + 1, lines " lines, over the limit of " max_lines ": split it along a seam")
  }
  if (reason) return
  if (lines > reason_lines) {
    fail(1, lines " lines, over " reason_lines ", and no \"// Length:\" reason in its opening comment")
  }
  for (i = 1; i <= n_long; i++) {
    fail(long_line[i], "function " long_name[i] " is " long_len[i] " lines, over " \
         reason_function_lines ", and no \"// Length:\" reason in its opening comment")
  }
}

BEGIN {
  for (i = 1; i < ARGC; i++) known[ARGV[i]] = 1
  n = split(not_yet, list, " ")
  for (i = 1; i <= n; i++) exempt[list[i]] = 1
  failures = 0
}

function start_file() {
  cur = FILENAME
  lines = 0
  reason = 0
  in_opening = 1
  n_long = 0
  in_fn = 0
  in_head = 0
  prev = ""
  skip_lengths = (cur in exempt)
  qt_free = cur ~ /^(src|include\/armmimic)\/(core|engines|robot|synth)\//
}

FNR == 1 {
  finish_file()
  start_file()
}

{
  lines = FNR
  line = $0
}

# The opening comment: the comment lines before the first other line.
in_opening {
  if (line ~ /^\/\//) {
    if (line ~ /^\/\/ Length: *[^ ]/) reason = 1
  } else {
    in_opening = 0
  }
}

# Includes.
line ~ /^[ \t]*#[ \t]*include/ {
  if (qt_free && line ~ /^[ \t]*#[ \t]*include[ \t]*[<"](Q[A-Za-z]|Qt[A-Za-z]*\/)/) {
    fail(FNR, "includes Qt (" line "); core, engines, robot and synth are Qt-free")
  }
  if (match(line, /"[^"]+"/)) {
    target = resolve(substr(line, RSTART + 1, RLENGTH - 2))
    if (target ~ /^src\/engines\/[^\/]+\//) {
      engine = target
      sub(/^src\/engines\//, "", engine)
      sub(/\/.*/, "", engine)
      if (engine == "common") {
        if (cur !~ /^(src|tests)\/engines\/[^\/]+\//) {
          fail(FNR, "includes " target ": common/ is private to the engine folders")
        }
      } else if (index(cur, "src/engines/" engine "/") != 1 &&
                 index(cur, "tests/engines/" engine "/") != 1) {
        fail(FNR, "includes " target ", a private header of the " engine \
             " engine, from outside its folder")
      }
    }
  }
}

# Function lengths: a definition starts at column 0 (or 2, inside a class) with a head that ends
# in "{", and ends at the first "}" in the same column. clang-format'"'"'s layout makes this
# reliable enough for a length rule.
{
  if (in_fn) {
    if (index(line, indent "}") == 1) {
      if (FNR - start + 1 > reason_function_lines) {
        n_long++
        long_line[n_long] = start
        long_name[n_long] = name
        long_len[n_long] = FNR - start + 1
      }
      in_fn = 0
    }
  } else {
    if (!in_head) {
      cont = prev ~ /([,(&|+*\/=?-]|[^:]:)[ \t]*$/ && prev !~ /^[ \t]*\/\// &&
             prev !~ /^ *(public|private|protected|default|case .*):[ \t]*$/
      if (!cont && line ~ /^(  )?[A-Za-z_~]/ &&
          line !~ /^ *(namespace|class|struct|enum|union|extern|if|for|while|switch|else|do|case|return|template|using|typedef)([ ({]|$)/) {
        in_head = 1
        start = FNR
        indent = substr(line, 1, match(line, /[^ ]/) - 1)
        head = line
      }
    } else {
      head = head " " line
    }
    if (in_head) {
      if (line ~ /\{[ \t]*$/) {
        before = head
        sub(/\(.*/, "", before)
        if (head ~ /\(/ && before !~ /=/) {
          name = before
          sub(/.*[ *&]/, "", name)
          in_fn = 1
        }
        in_head = 0
      } else if (line ~ /[;}][ \t]*$/ || FNR - start > 8) {
        in_head = 0
      }
    }
  }
  prev = line
}

END {
  finish_file()
  if (failures) {
    print "layout: " failures " violation(s)"
    exit 1
  }
  print "layout: " (ARGC - 1) " files follow the house rules"
}
' "${files[@]}"
