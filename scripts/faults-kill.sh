#!/usr/bin/env bash
# `gibench run` killed at random instants (docs/reliability.md, "Faults"). Times an uninterrupted
# run of a small suite (fresh store and database), then K times: starts the run afresh, sends it
# SIGKILL at a uniformly random instant of that time (a fixed seed makes the instants
# reproducible), and checks that
#   - nothing that a later run would trust is partial (scripts/check-run-integrity.py: JSON and
#     EXRs whole, `store verify`, the database's integrity check; temporary files of the killed
#     writes may remain, which nothing reads and `gibench store gc` collects);
#   - the same command resumes the run and completes, with the metric values of the uninterrupted
#     run, and the database then holds the run once.
# The last line the run printed before the kill says where it was (rendering a reference, a
# technique job, writing results, history, report).
#
#   scripts/faults-kill.sh GIBENCH [--kills K] [--seed S] [--work DIR]
#
# Prints one line per kill and a total; exits 1 when any kill fails, 2 on bad arguments.
set -euo pipefail
script=faults-kill.sh
source "$(dirname "$0")/faults-common.sh"
faults_gibench "$@"
shift
kills=50
seed=1
work=""
while [ $# -gt 0 ]; do
  case "$1" in
    --kills) kills=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
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
expected=$(metric_values "$work/baseline")
instants=$(python3 -c "
import random, sys
r = random.Random(int(sys.argv[1]))
print(' '.join(f'{r.uniform(0, float(sys.argv[2])):.3f}' for _ in range(int(sys.argv[3]))))" \
  "$seed" "$duration" "$kills")

failed=0
killed=0
n=0
for at in $instants; do
  n=$((n + 1))
  dir="$work/kill-$n"
  mkdir -p "$dir"
  args=(--out "$dir/out" --store "$dir/store" --db "$dir/history.sqlite")
  "$gibench" run "$suite" "${args[@]}" >"$dir/run.log" 2>&1 &
  pid=$!
  sleep "$at"
  where="finished before the kill"
  if kill -9 "$pid" 2>/dev/null; then
    killed=$((killed + 1))
    last=$(tail -c 300 "$dir/run.log" | tr '\r' '\n' | grep . | tail -1 | cut -c1-90 || true)
    where="killed after: ${last:-nothing printed yet}"
  fi
  wait "$pid" 2>/dev/null || true
  problem=""
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
    echo "FAIL kill $n at ${at} s ($where): ${problem#; }"
  else
    echo "ok   kill $n at ${at} s ($where); nothing damaged; resumed equal"
  fi
  rm -rf "$dir"
done
echo "kill -9: $kills instants over a ${duration%.*}-second run, $killed killed mid-run, $failed failed"
[ "$failed" -eq 0 ]
