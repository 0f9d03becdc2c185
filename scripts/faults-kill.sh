#!/usr/bin/env bash
# `gibench run` killed at random instants and inside its writes (docs/reliability.md, "Faults").
# Times an uninterrupted run of a small suite (fresh store and database), then
#   - K times: starts the run afresh and sends it SIGKILL at a uniformly random instant of that
#     time (a fixed seed makes the instants reproducible);
#   - once per write point (common/stall_point.h): starts the run afresh with GIB_STALL_AT naming
#     the point, and sends SIGKILL when the run reports that it holds there: a temporary file
#     complete but not yet renamed into place, a store entry staged but not published, the history
#     rows inserted but not committed. Random instants rarely land in these writes (results,
#     history and report take milliseconds of the run); this puts a kill inside each.
# After each kill it checks that
#   - nothing that a later run would trust is partial (scripts/check-run-integrity.py: JSON, HTML
#     and EXRs whole, `store verify`, the database's integrity check; temporary files of the
#     killed writes may remain, which nothing reads and `gibench store gc` collects);
#   - the same command resumes the run and completes, with the metric values of the uninterrupted
#     run, and the database then holds the run once.
# For a random kill, the last line the run printed before it says where the run was. A kill
# checks nothing unless it lands mid-run, so the script also fails when a kill in the first
# quarter of the uninterrupted run's time finds the run finished (such a kill missed it: the runs
# after the first, cold one took 0.6 of its time at least, never a quarter), when a run fails by
# itself, and when a run holds at another point than the one named.
#
#   scripts/faults-kill.sh GIBENCH [--kills K] [--seed S] [--points P1,P2,…|none] [--work DIR]
#
# --points defaults to every write of the suite's run (the list below). Prints one line per kill
# and a total; exits 1 when any kill fails, 2 on bad arguments.
set -euo pipefail
script=faults-kill.sh
source "$(dirname "$0")/faults-common.sh"
faults_gibench "$@"
shift
kills=50
seed=1
work=""
points="store-entry,write:reference.exr,write:entry.json,write:image.exr,write:timings.json"
points="$points,write:result.json,write:results.json,write:results.csv,history-commit"
points="$points,write:*.html,write:viewer.js,write:index.html"
while [ $# -gt 0 ]; do
  case "$1" in
    --kills) kills=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --points) points=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    *) faults_usage_error "unknown argument '$1'" ;;
  esac
done
faults_work_dir kill
suite="$work/kill.toml"
cat >"$suite" <<'TOML'
name = "kill"
[defaults]
width = 48
height = 32
frames = 2
warmup = 1
metrics = ["relmse", "flip"]
[defaults.reference]
spp = 64
[[case]]
scene = "cornell"
technique = "direct"
[[case]]
scene = "cornell"
technique = "stochastic_radiosity"
iterations = 20
[[case]]
scene = "cornell"
technique = "reference"
TOML

start=$(date +%s.%N)
"$gibench" run "$suite" --out "$work/baseline" --store "$work/baseline-store" \
  --db "$work/baseline.sqlite" >/dev/null 2>&1
duration=$(python3 -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$start" "$(date +%s.%N)")
seconds=$(printf '%.1f' "$duration")
early=$(python3 -c "import sys; print(float(sys.argv[1]) / 4)" "$duration")  # see the top
expected=$(metric_values "$work/baseline")
instants=$(python3 -c "
import random, sys
r = random.Random(int(sys.argv[1]))
print(' '.join(f'{r.uniform(0, float(sys.argv[2])):.3f}' for _ in range(int(sys.argv[3]))))" \
  "$seed" "$duration" "$kills")

failed=0
killed=0
n=0
# After kill number $n (described by $1, with the problems $2 seen so far), checks the run's
# directories, resumes it and compares.
check_and_resume() {
  local where=$1 problem=${2:-} dir="$work/kill-$n" integrity recorded
  if ! integrity=$(python3 "$here/check-run-integrity.py" "$gibench" --out "$dir/out" \
                     --store "$dir/store" --db "$dir/history.sqlite"); then
    problem="$problem; left damaged: $integrity"
  fi
  if ! "$gibench" run "$suite" "${args[@]}" >"$dir/resume.log" 2>&1; then
    problem="$problem; the resume failed: $(grep '^gibench: ' "$dir/resume.log" | head -1)"
  elif [ "$(metric_values "$dir/out")" != "$expected" ]; then
    problem="$problem; the resumed run measured other values than an uninterrupted one"
  else
    recorded=$(recorded_runs "$dir/history.sqlite")
    [ "$recorded" -eq 1 ] || problem="$problem; the database holds the run $recorded times"
  fi
  if [ -n "$problem" ]; then
    failed=$((failed + 1))
    echo "FAIL kill $n ($where): ${problem#; }"
  else
    echo "ok   kill $n ($where); nothing damaged; resumed equal"
  fi
  rm -rf "$dir"
}

# Starts kill number $n's run in the background ($pid); the environment is the caller's.
start_run() {
  n=$((n + 1))
  mkdir -p "$work/kill-$n"
  args=(--out "$work/kill-$n/out" --store "$work/kill-$n/store" --db "$work/kill-$n/history.sqlite")
  "$gibench" run "$suite" "${args[@]}" >"$work/kill-$n/run.log" 2>&1 &
  pid=$!
}

# The run's exit status says whether the kill landed: 137 (128 + SIGKILL) while it ran, 0 when it
# had finished.
for at in $instants; do
  start_run
  sleep "$at"
  kill -9 "$pid" 2>/dev/null || true
  status=0
  wait "$pid" 2>/dev/null || status=$?
  problem=""
  if [ "$status" -eq 137 ]; then
    killed=$((killed + 1))
    last=$(tail -c 300 "$work/kill-$n/run.log" | tr '\r' '\n' | grep . | tail -1 | cut -c1-90 || true)
    where="at ${at} s, killed after: ${last:-nothing printed yet}"
  else
    where="at ${at} s, finished before the kill with exit code $status"
    if [ "$status" -ne 0 ]; then
      problem="; the run failed by itself: $(grep '^gibench: ' "$work/kill-$n/run.log" | head -1)"
    elif awk -v at="$at" -v early="$early" 'BEGIN { exit !(at < early) }'; then
      problem="; a kill in the first quarter of the uninterrupted run's $seconds s missed it"
    fi
  fi
  check_and_resume "$where" "$problem"
done

at_points=0
IFS=, read -ra point_list <<<"${points/#none/}"
for point in "${point_list[@]}"; do
  GIB_STALL_AT="$point" start_run
  # The run holds at the point for a minute; a run that ends first never reached it.
  while kill -0 "$pid" 2>/dev/null && ! grep -q "^gibench: stalled at " "$work/kill-$n/run.log"; do
    sleep 0.02
  done
  if grep -q "^gibench: stalled at " "$work/kill-$n/run.log" && kill -9 "$pid" 2>/dev/null; then
    wait "$pid" 2>/dev/null || true
    at_points=$((at_points + 1))
    stalled=$(grep -m1 -o 'stalled at .*' "$work/kill-$n/run.log" | cut -c12-)
    problem=""
    # shellcheck disable=SC2053 # the point is a pattern, as GIB_STALL_AT reads it
    [[ "$stalled" == $point ]] || problem="; held at '$stalled', not at '$point'"
    check_and_resume "inside $stalled" "$problem"
  else
    wait "$pid" 2>/dev/null || true
    failed=$((failed + 1))
    echo "FAIL kill $n: the run never reached write point '$point'; name one it makes"
    rm -rf "$work/kill-$n"
  fi
done
echo "kill -9: $kills instants over a $seconds-second run ($killed killed mid-run)," \
  "$at_points inside writes, $failed failed"
[ "$failed" -eq 0 ]
