#!/usr/bin/env bash
# One step of `git bisect run`: build the checked-out commit, run a suite (or the part of it that
# --only selects), and diff the results against a known-good results.json, confirming every
# timing change by interleaved A/B renders of the good build and this one.
#
#   scripts/bisect-step.sh GOOD_RESULTS SUITE.toml [gibench run options, e.g. --only 'cornell-direct/*']
#
# Exit codes are those `git bisect run` expects: 0 this commit is good, 1 it regressed, 125 it
# cannot be tested (it does not build, the suite does not run, gibench cannot diff, or a timing
# could not be confirmed: `gibench diff --confirm` exit 4, a build that cannot render a job, so
# the commit is neither good nor bad). Copy this script and the suite file out of the tree first:
# bisect checks out commits that may lack them.
#
# Timings: `gibench diff --confirm` reruns each job whose frame time changed with the good run's
# build and this commit's build alternately (A B A B …, enough pairs for the significance), so
# a slowdown is called only when it survives on this machine, now (docs/harness.md, "Timing
# verdicts"). The good build is the commit recorded in GOOD_RESULTS, built once into
# $GIB_BISECT_BUILD-good-<commit> (a git worktree), unless GIB_BISECT_GOOD_GIBENCH names it.
#
# Environment:
#   GIB_BISECT_BUILD         where to build (default build/bisect in the work tree; only gibench)
#   GIB_BISECT_GIBENCH       a gibench to use for every commit instead of building one (to bisect
#                            a change of suites or data under one build; the script's own test)
#   GIB_BISECT_GOOD_GIBENCH  the good run's build, instead of building its commit
#   GIB_BISECT_CONFIRM=0     diff without confirming timings (then a timing change is at most
#                            "unconfirmed", never a regression)
#   GIB_BISECT_PAIRS=N       A/B pairs per confirmed job (default: `gibench diff`'s own choice)
# References come from the usual store, so commits that do not change the reference renderer
# reuse one render.
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

# Builds gibench of the tree at $1 into $2; returns non-zero when it does not build.
build_gibench() {
  mkdir -p "$(dirname "$2")"
  cmake -S "$1" -B "$2" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGIB_BUILD_TESTS=OFF \
    -DGIB_BUILD_BENCH=OFF >"$2.log" 2>&1 && cmake --build "$2" --target gibench >>"$2.log" 2>&1
}

if [ -n "${GIB_BISECT_GIBENCH:-}" ]; then
  gibench=$(realpath "$GIB_BISECT_GIBENCH")
else
  echo "bisect-step: building $commit in $build" >&2
  if ! build_gibench "$root" "$build"; then
    echo "bisect-step: $commit does not build (log: $build.log); skipping it" >&2
    exit 125
  fi
  gibench="$build/cli/gibench"
fi

# The good run's build, for the A/B confirmation of timings (by this commit's gibench, when it is
# recent enough to have `diff --confirm`).
confirm=()
if [ "${GIB_BISECT_CONFIRM:-1}" != 0 ] && ! "$gibench" diff --help 2>/dev/null | grep -q -- --confirm; then
  echo "bisect-step: $commit's gibench cannot confirm timings (no diff --confirm)" >&2
elif [ "${GIB_BISECT_CONFIRM:-1}" != 0 ]; then
  good_build=${GIB_BISECT_GOOD_GIBENCH:-}
  if [ -z "$good_build" ] && [ -n "${GIB_BISECT_GIBENCH:-}" ]; then good_build=$gibench; fi
  if [ -z "$good_build" ]; then
    good_commit=$(python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))["run"]; print("" if r["git_dirty"] else r["git_commit"])' "$good" 2>/dev/null)
    if [ -n "$good_commit" ] && git -C "$root" cat-file -e "$good_commit^{commit}" 2>/dev/null; then
      good_dir="$build-good-${good_commit:0:12}"
      if [ ! -x "$good_dir/build/cli/gibench" ]; then
        echo "bisect-step: building the good run's commit ${good_commit:0:12} once, in $good_dir" >&2
        rm -rf "$good_dir/src"
        git -C "$root" worktree add --force --detach "$good_dir/src" "$good_commit" >/dev/null 2>&1 &&
          build_gibench "$good_dir/src" "$good_dir/build" ||
          echo "bisect-step: the good commit does not build (log: $good_dir/build.log)" >&2
      fi
      [ -x "$good_dir/build/cli/gibench" ] && good_build="$good_dir/build/cli/gibench"
    fi
  fi
  if [ -n "$good_build" ]; then
    confirm=(--confirm --base-gibench "$good_build" --new-gibench "$gibench")
    [ -n "${GIB_BISECT_PAIRS:-}" ] && confirm+=(--pairs "$GIB_BISECT_PAIRS")
  else
    echo "bisect-step: no build of the good run (uncommitted or unknown commit): timings are" \
      "not confirmed; set GIB_BISECT_GOOD_GIBENCH" >&2
  fi
fi

run=$(mktemp -d "${TMPDIR:-/tmp}/gibench-bisect-XXXXXX")
trap 'rm -rf "$run"' EXIT
if ! "$gibench" run "$suite" --out "$run/run" --no-history "$@"; then
  echo "bisect-step: the suite does not run at $commit; skipping it" >&2
  exit 125
fi
"$gibench" diff "$good" "$run/run/results.json" "${confirm[@]}"
status=$?
case $status in
  0) echo "bisect-step: $commit is good" >&2; exit 0 ;;
  1) echo "bisect-step: $commit regressed" >&2; exit 1 ;;
  4) echo "bisect-step: a timing could not be confirmed at $commit (a build could not render its" \
       "job; see above); skipping it" >&2
     exit 125 ;;
  *) echo "bisect-step: gibench diff could not compare at $commit (exit $status); skipping it" >&2
     exit 125 ;;
esac
