#!/usr/bin/env bash
# One step of `git bisect run`: build the checked-out commit, run a suite (or the part of it that
# --only selects), and diff the results against a known-good results.json.
#
#   scripts/bisect-step.sh GOOD_RESULTS SUITE.toml [gibench run options, e.g. --only 'cornell-direct/*']
#
# Exit codes are those `git bisect run` expects: 0 this commit is good, 1 it regressed, 125 it
# cannot be tested (it does not build, the suite does not run, or gibench cannot diff). Copy this
# script and the suite file out of the tree first: bisect checks out commits that may lack them.
# The build goes to $GIB_BISECT_BUILD (default build/bisect in the work tree; only gibench is
# built), the run to a temporary directory; references come from the usual store, so commits that
# do not change the reference renderer reuse one render.
set -uo pipefail

if [ $# -lt 2 ]; then
  echo "usage: bisect-step.sh GOOD_RESULTS SUITE.toml [gibench run options]" >&2
  exit 125
fi
good=$(realpath "$1")
suite=$(realpath "$2")
shift 2
root=$(git rev-parse --show-toplevel) || exit 125
build=${GIB_BISECT_BUILD:-$root/build/bisect}
commit=$(git -C "$root" rev-parse --short=12 HEAD)

echo "bisect-step: building $commit in $build" >&2
if ! cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGIB_BUILD_TESTS=OFF \
       -DGIB_BUILD_BENCH=OFF >"$build.log" 2>&1 ||
   ! cmake --build "$build" --target gibench >>"$build.log" 2>&1; then
  echo "bisect-step: $commit does not build (log: $build.log); skipping it" >&2
  exit 125
fi

mkdir -p "$(dirname "$build")"
run=$(mktemp -d "${TMPDIR:-/tmp}/gibench-bisect-XXXXXX")
trap 'rm -rf "$run"' EXIT
if ! "$build/cli/gibench" run "$suite" --out "$run/run" --no-history "$@"; then
  echo "bisect-step: the suite does not run at $commit; skipping it" >&2
  exit 125
fi
"$build/cli/gibench" diff "$good" "$run/run/results.json"
status=$?
case $status in
  0) echo "bisect-step: $commit is good" >&2; exit 0 ;;
  1) echo "bisect-step: $commit regressed" >&2; exit 1 ;;
  *) echo "bisect-step: gibench diff could not compare at $commit (exit $status); skipping it" >&2
     exit 125 ;;
esac
