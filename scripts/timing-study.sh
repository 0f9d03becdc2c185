#!/usr/bin/env bash
# Measures how `gibench diff` judges timings on this machine (docs/harness.md, "Timing verdicts").
#
#   scripts/timing-study.sh noise RUNS            false positives: RUNS smoke runs of one build,
#                                                 every ordered pair diffed with default settings
#   scripts/timing-study.sh power TRIALS FROM TO  true positives: per trial a run of the smoke
#                                                 suite's `direct` jobs with light_samples=FROM and
#                                                 one with TO, diffed with --confirm
#
# Everything goes to a temporary store and history database; the counts of each verdict are
# printed at the end (and every diff is kept in $GIB_STUDY_KEEP when it is set). OLD_GIBENCH, when
# set, also diffs every pair of the noise study with that (earlier) build, for the rate before.
# GIBENCH chooses the build (default build/release/cli/gibench).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-}
gibench=$(realpath "${GIBENCH:-build/release/cli/gibench}")
work=$(mktemp -d "${TMPDIR:-/tmp}/gibench-timing-study-XXXXXX")
trap 'rm -rf "$work"' EXIT
keep=${GIB_STUDY_KEEP:-$work/diffs}
mkdir -p "$keep"
export GIBENCH_STORE="$work/store"

# Counts the timing verdicts of every diff JSON in $1, for jobs matching the glob $2.
count() {
  python3 - "$1" "$2" <<'PY'
import fnmatch, glob, json, sys
from collections import Counter
verdicts, evidence, diffs, failed = Counter(), Counter(), 0, 0
for path in sorted(glob.glob(sys.argv[1] + "/*.json")):
    diff = json.load(open(path))
    diffs += 1
    timings = [t for t in diff["timings"] if fnmatch.fnmatch(t["job"], sys.argv[2])]
    failed += any(t["verdict"] == "regressed" for t in timings)
    for t in timings:
        verdicts[t["verdict"]] += 1
        evidence[t.get("evidence", "frames (Mann-Whitney)")] += 1
total = sum(verdicts.values())
print(f"{diffs} diffs, {total} timing comparisons")
for verdict, n in sorted(verdicts.items()):
    print(f"  {verdict:<12} {n:5d}  ({100 * n / max(total, 1):.1f}%)")
print("  evidence: " + ", ".join(f"{k} {v}" for k, v in sorted(evidence.items())))
print(f"  diffs calling a timing regression: {failed} of {diffs}")
PY
}

case "$mode" in
  noise)
    runs=${2:?usage: timing-study.sh noise RUNS}
    for i in $(seq 1 "$runs"); do
      echo "run $i of $runs" >&2
      "$gibench" run suites/smoke.toml --out "$work/run-$i" --db "$work/history.sqlite" >/dev/null 2>&1
    done
    for i in $(seq 1 "$runs"); do
      for j in $(seq 1 "$runs"); do
        [ "$i" = "$j" ] && continue
        "$gibench" diff "$work/run-$i" "$work/run-$j" --json --db "$work/history.sqlite" \
          >"$keep/$i-$j.json" || true
        if [ -n "${OLD_GIBENCH:-}" ]; then
          mkdir -p "$keep/old"
          "$OLD_GIBENCH" diff "$work/run-$i" "$work/run-$j" --json --db "$work/history.sqlite" \
            >"$keep/old/$i-$j.json" || true
        fi
      done
    done
    echo "== this build ($gibench), default settings"
    count "$keep" '*'
    if [ -n "${OLD_GIBENCH:-}" ]; then
      echo "== $OLD_GIBENCH"
      count "$keep/old" '*'
    fi
    ;;
  power)
    trials=${2:?usage: timing-study.sh power TRIALS FROM TO}
    from=${3:?usage: timing-study.sh power TRIALS FROM TO}
    to=${4:?usage: timing-study.sh power TRIALS FROM TO}
    sed "s/light_samples = 16/light_samples = $from/" suites/smoke.toml >"$work/base.toml"
    sed "s/light_samples = 16/light_samples = $to/" suites/smoke.toml >"$work/new.toml"
    for i in $(seq 1 "$trials"); do
      echo "trial $i of $trials" >&2
      "$gibench" run "$work/base.toml" --only 'cornell-direct/*' --out "$work/base-$i" \
        --no-history >/dev/null 2>&1
      "$gibench" run "$work/new.toml" --only 'cornell-direct/*' --out "$work/new-$i" \
        --no-history >/dev/null 2>&1
      "$gibench" diff "$work/base-$i" "$work/new-$i" --confirm --json >"$keep/$i.json" \
        2>"$keep/$i.log" || true
    done
    echo "== light_samples $from -> $to, with --confirm"
    count "$keep" 'cornell-direct/*'
    ;;
  *)
    echo "usage: timing-study.sh noise RUNS | power TRIALS FROM TO" >&2
    exit 2
    ;;
esac
