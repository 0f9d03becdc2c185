#!/usr/bin/env bash
# Concurrent runs on one reference store and one history database (docs/reliability.md,
# "Faults"): in each round, N `gibench run` processes start at once on a suite whose jobs share
# references, with a fresh store. Checks that every run completes (no "database is locked"), that
# each run's results name the suite's five references, each rendered by exactly one process (the
# others wait for it and read it), that the database records every run, and that nothing is left
# damaged (scripts/check-run-integrity.py).
#
#   scripts/faults-concurrent-runs.sh GIBENCH [--runs N] [--rounds R] [--work DIR]
#
# Prints one line per round and a total; exits 1 when a round fails, 2 on bad arguments.
set -euo pipefail
script=faults-concurrent-runs.sh
source "$(dirname "$0")/faults-common.sh"
faults_gibench "$@"
shift
runs=4
rounds=3
work=""
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    *) faults_usage_error "unknown argument '$1'" ;;
  esac
done
faults_work_dir concurrent
suite="$work/concurrent.toml"
# Four cases, five references: the Cornell box's direct job asks for box-filtered references
# (docs/rendering.md, "Pixel sampling"), so its full reference is also the reference job's, and
# two jobs of every run need it; the chamber's direct job has its pixel-centre pair.
references=5
cat >"$suite" <<'TOML'
name = "concurrent"
[defaults]
width = 32
height = 24
frames = 1
warmup = 0
metrics = ["relmse"]
[defaults.reference]
spp = 64
[[case]]
scene = "cornell"
technique = "direct"
reference = { pixel_sampling = "area" }
[[case]]
scene = "cornell"
technique = "reference"
[[case]]
scene = "chamber"
technique = "direct"
[[case]]
scene = "furnace"
technique = "reference"
TOML

failed=0
for round in $(seq "$rounds"); do
  dir="$work/round-$round"
  mkdir -p "$dir"
  pids=()
  for k in $(seq "$runs"); do
    "$gibench" run "$suite" --out "$dir/out-$k" --store "$dir/store" --db "$dir/history.sqlite" \
      >"$dir/$k.stdout" 2>"$dir/$k.stderr" &
    pids+=($!)
  done
  problem=""
  for k in $(seq "$runs"); do
    if ! wait "${pids[$((k - 1))]}"; then
      problem="$problem; run $k failed: $(grep '^gibench: ' "$dir/$k.stderr" | head -1)"
    fi
  done
  if grep -l 'database is locked' "$dir"/*.stderr >/dev/null 2>&1; then
    problem="$problem; 'database is locked'"
  fi
  # Renders per store key, from the runs' results (a reference a run rendered is not a store
  # hit); then what is wrong with the keys: other than the suite's references, or not the same
  # in every run.
  check=$(python3 - "$dir" "$runs" "$references" <<'PY'
import collections, json, sys
directory, runs, references = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
count = collections.Counter()
keys_of_run = {}
for k in range(1, runs + 1):
    try:
        results = json.load(open(f"{directory}/out-{k}/results.json"))
    except OSError:
        continue
    keys_of_run[k] = set()
    for job in results["jobs"]:
        for field in ("reference", "full_reference"):
            reference = job.get(field)
            if reference:
                keys_of_run[k].add(reference["key"])
                count[reference["key"]] += 0 if reference["store_hit"] else 1
print(" ".join(str(count[key]) for key in sorted(count)))
problems = []
if len(count) != references:
    problems.append(f"the results name {len(count)} references, not {references}")
differing = [k for k, keys in keys_of_run.items() if keys != set(count)]
if differing:
    problems.append(f"runs {differing} name only some of them")
print("; ".join(problems))
PY
)
  renders=$(sed -n 1p <<<"$check")
  keys_problem=$(sed -n 2p <<<"$check")
  [ -z "$keys_problem" ] || problem="$problem; $keys_problem"
  for n in $renders; do
    if [ "$n" -ne 1 ]; then problem="$problem; a reference rendered $n times (per key: $renders)"; break; fi
  done
  recorded=$(recorded_runs "$dir/history.sqlite")
  if [ "$recorded" -ne "$runs" ]; then problem="$problem; $recorded runs recorded, not $runs"; fi
  for k in $(seq "$runs"); do
    shared=()  # the store and the database are shared: checked once
    if [ "$k" -eq 1 ]; then shared=(--store "$dir/store" --db "$dir/history.sqlite"); fi
    if ! integrity=$(python3 "$here/check-run-integrity.py" "$gibench" --out "$dir/out-$k" \
                       "${shared[@]}" --no-temporaries); then
      problem="$problem; run $k left: $integrity"
    fi
  done
  if [ -n "$problem" ]; then
    failed=$((failed + 1))
    echo "FAIL round $round: ${problem#; }"
  else
    echo "ok   round $round: $runs runs completed and recorded; renders per reference: $renders"
  fi
done
echo "concurrent runs: $rounds rounds of $runs, $failed failed"
[ "$failed" -eq 0 ]
