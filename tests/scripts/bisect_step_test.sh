#!/usr/bin/env bash
# scripts/bisect-step.sh on a synthetic history: eight commits of a suite, the fifth of which
# makes the one job four times the work (light_samples 8 → 32). `git bisect run` with the step
# must stop at the fifth commit, the slowdown confirmed by interleaved A/B renders, and at no
# other. One build of gibench serves every commit (GIB_BISECT_GIBENCH): what changes is the
# suite, as a change in the code would change the work. Then a good build that cannot render the
# job: the timing cannot be confirmed, so the step must skip the commit (125), not call it good.
#
#   tests/scripts/bisect_step_test.sh GIBENCH SOURCE_DIR
set -euo pipefail
gibench=$(realpath "$1")
source_dir=$(realpath "$2")
work=$(mktemp -d "${TMPDIR:-/tmp}/gibench-bisect-test-XXXXXX")
trap 'rm -rf "$work"' EXIT
export GIBENCH_STORE="$work/store"

repo="$work/repo"
mkdir -p "$repo"
cd "$repo"
git init -q
git config user.email "bisect@test"
git config user.name "bisect test"
for i in 1 2 3 4 5 6 7 8; do
  samples=8
  [ "$i" -ge 5 ] && samples=32
  cat >suite.toml <<SUITE
name = "bisect-probe"
[defaults]
width = 64
height = 64
metrics = ["relmse"]
frames = 6
warmup = 1
[defaults.reference]
spp = 16
[[case]]
scene = "cornell"
technique = "direct"
set = { light_samples = $samples }
SUITE
  echo "$i" >commit-number
  git add suite.toml commit-number
  git commit -q -m "commit $i"
done
first=$(git rev-list --max-parents=0 HEAD)
last=$(git rev-parse HEAD)
expected=$(git log --format=%H --grep='^commit 5$')

git checkout -q "$first"
"$gibench" run suite.toml --out "$work/good" --no-history >/dev/null 2>&1
git checkout -q "$last"
cp "$source_dir/scripts/bisect-step.sh" "$work/bisect-step.sh"

git bisect start "$last" "$first" >/dev/null
# Nine pairs: the fewest whose test reaches 1% (one timed job); a fourfold slowdown needs no more.
GIB_BISECT_GIBENCH="$gibench" GIB_BISECT_PAIRS=9 git bisect run "$work/bisect-step.sh" "$work/good/results.json" \
  "$repo/suite.toml" >"$work/bisect.log" 2>&1 || true
found=$(git rev-parse refs/bisect/bad)
git bisect reset >/dev/null 2>&1
if [ "$found" != "$expected" ]; then
  echo "bisect stopped at $(git log -1 --format=%s "$found"), expected commit 5; its log:"
  cat "$work/bisect.log"
  exit 1
fi
grep -q "interleaved A/B" "$work/bisect.log" || {
  echo "the regression was not confirmed by interleaved A/B runs:"
  cat "$work/bisect.log"
  exit 1
}

# A good build that cannot render (one that fails every `gibench render`, as a build lacking the
# job's technique would): `gibench diff --confirm` exits 4 and the step skips the commit.
broken="$work/broken-gibench"
printf '#!/bin/sh\necho "no such technique" >&2\nexit 2\n' >"$broken"
chmod +x "$broken"
step_status=0
GIB_BISECT_GIBENCH="$gibench" GIB_BISECT_GOOD_GIBENCH="$broken" GIB_BISECT_PAIRS=2 \
  "$work/bisect-step.sh" "$work/good/results.json" "$repo/suite.toml" >"$work/skip.log" 2>&1 ||
  step_status=$?
if [ "$step_status" != 125 ] || ! grep -q "gibench: could not confirm" "$work/skip.log" ||
  ! grep -q "a timing could not be confirmed" "$work/skip.log"; then
  echo "a step whose timing could not be confirmed exited $step_status, expected 125; its log:"
  cat "$work/skip.log"
  exit 1
fi
echo "bisect found commit 5, the one that made the job slower, and skips a commit it cannot confirm"
