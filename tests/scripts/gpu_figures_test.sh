#!/usr/bin/env bash
# scripts/gpu-figures.sh --quick on this machine's GL renderer (llvmpipe in CI): it writes
# <renderer>.md named after the renderer gibench recorded, with the renderer in it, a row with a
# number for every technique of the catalogue, and the papers' numbers beside ours. Bad input (an
# unknown option, no --out) is one line on stderr, exit 2 and no directory made.
#
#   tests/scripts/gpu_figures_test.sh GIBENCH GIB_REALTIME_BENCH SOURCE_DIR
set -euo pipefail
gibench=$(realpath "$1")
bench=$(realpath "$2")
script="$(realpath "$3")/scripts/gpu-figures.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/gibench-gpu-figures-test-XXXXXX")
trap 'rm -rf "$work"' EXIT

failed=0
check() {  # check DESCRIPTION COMMAND...: runs the command, reports a failure and goes on
  local what=$1
  shift
  if ! "$@"; then
    echo "FAIL: $what" >&2
    failed=1
  fi
}

# Bad input: exit 2, one line, nothing made.
bad_input() {
  local status=0
  "$script" "$@" --gibench "$gibench" --bench "$bench" >"$work/stdout" 2>"$work/stderr" || status=$?
  if [ "$status" -eq 2 ] && [ "$(wc -l <"$work/stderr")" -eq 1 ] && [ ! -s "$work/stdout" ] &&
    [ ! -e "$work/bad" ]; then
    return 0
  fi
  echo "exit $status, stderr:" >&2
  cat "$work/stderr" >&2
  return 1
}
check "an unknown option is one line and exit 2" bad_input --out "$work/bad" --frames 3
check "a missing --out is one line and exit 2" bad_input --quick
check "--out without its value is one line and exit 2" bad_input --quick --out

out="$work/out"
"$script" --quick --out "$out" --gibench "$gibench" --bench "$bench"

# The table is named after the renderer gibench recorded, and names it.
renderer=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["run"]["gl_renderer"])' \
  "$out/gpu-figures-quick/results.json")
slug=$(printf '%s' "$renderer" | tr 'A-Z' 'a-z' | sed -E 's/[^a-z0-9]+/-/g; s/^-+//; s/-+$//')
table="$out/$slug.md"
check "the table $table exists" test -s "$table"
[ -s "$table" ] || exit 1
check "the table names the renderer '$renderer'" grep -qF "| GL renderer | $renderer |" "$table"

# A row with a number (ms) for every technique of the catalogue.
number='[0-9][0-9,]*(\.[0-9]+)?'
while read -r technique; do
  check "a frame time of $technique" grep -qE "^\| $technique \| [^|]+ \| $number \|" "$table"
done < <("$gibench" list techniques | awk '/^[a-z]/ && $1 != "reference" { print $1 }')

# The ray-casting table (book Ch. 5): a row of M rays/s for Embree and for the BVH.
check "the ray-casting table's Embree row" grep -qE "^\| cornell \| primary \| 32 \| embree \| — \| $number \|" "$table"
check "the ray-casting table's BVH row" grep -qE "^\| cornell \| primary \| 32 \| bvh \| 0 \| $number \|" "$table"

# The papers' numbers beside ours: the header, and a row with both numbers.
check "the papers' column" grep -qF "| job | quantity | ours | paper | ours/paper | unit | source |" "$table"
check "a paper's number beside ours" grep -qE "^\| [^|]+ \| [^|]+ \| $number \| $number \| [^|]+ \| ms \|" "$table"
exit "$failed"
