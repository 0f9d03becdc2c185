#!/usr/bin/env bash
# Disk full while `gibench run` writes (docs/reliability.md, "Faults"). For each limit L (KiB) and
# with and without the history database, runs a small suite with every file it writes capped at
# L KiB: `ulimit -f` with SIGXFSZ ignored, so that a write past the cap fails (EFBIG) as one on a
# full disk does (ENOSPC), whatever file it is: an image, a store entry, a JSON file, the history
# database or a report page. Then checks that
#   - the run either completed or stopped with exit code 2 and one line "gibench: cannot write …"
#     (never a crash or an internal error);
#   - nothing partial is left that a later run would trust, and no temporary file at all
#     (scripts/check-run-integrity.py: JSON whole, EXRs whole, `store verify`, the database's
#     integrity check);
#   - the same command without the cap resumes and completes, with the same metric values as an
#     uninterrupted run;
#   - the cap stopped at least one run (else nothing above was tested), and one at each place
#     --expect-stops names: `job` (a job's files), `store` (a reference-store entry), `history`
#     (the history database), `report` (a report page), `results` (results.json, results.csv).
#
#   scripts/faults-disk-full.sh GIBENCH [--limits "2 4 8 16 32"] [--expect-stops "job store …"]
#       [--work DIR]
#
# Prints one line per case and a total with the stops per place; exits 1 when any case fails or
# an expected place saw no stop, 2 on bad arguments.
set -euo pipefail
script=faults-disk-full.sh
source "$(dirname "$0")/faults-common.sh"
faults_gibench "$@"
shift
limits="2 4 8 12 16 24 32 48"
expect_stops=""
work=""
while [ $# -gt 0 ]; do
  case "$1" in
    --limits) limits=$2; shift 2 ;;
    --expect-stops) expect_stops=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    *) faults_usage_error "unknown argument '$1'" ;;
  esac
done
for place in $expect_stops; do
  [[ " job store history report results " == *" $place "* ]] || faults_usage_error \
    "--expect-stops: unknown place '$place' (job, store, history, report, results)"
done
faults_work_dir disk-full
suite="$work/disk-full.toml"
cat >"$suite" <<'TOML'
name = "disk-full"
[defaults]
width = 32
height = 24
frames = 1
warmup = 0
metrics = ["relmse", "flip"]
[defaults.reference]
spp = 32
[[case]]
scene = "cornell"
technique = "direct"
[[case]]
scene = "cornell"
technique = "reference"
TOML

# An uninterrupted run, recorded in a database that each case with history starts from, so that
# a cap can fall on the append of a second run as well as on the creation of the file.
"$gibench" run "$suite" --out "$work/baseline" --store "$work/baseline-store" \
  --db "$work/baseline.sqlite" >/dev/null 2>&1
expected=$(metric_values "$work/baseline")

# The place a "cannot write" line of case directory $1 names (line $2), one of --expect-stops'
# words, or "elsewhere".
place_of() {
  case "$2" in
    *"history database '$1/history.sqlite'"*) echo history ;;
    *"'$1/store/"*) echo store ;;
    *"'$1/out/jobs/"*) echo job ;;
    *"'$1/out/report/"* | *"'$1/out/index.html'"*) echo report ;;
    *"'$1/out/results."*) echo results ;;
    *) echo elsewhere ;;
  esac
}

cases=0
failed=0
stopped=0
declare -A stops_at=()
for limit in $limits; do
  for history in with without; do
    cases=$((cases + 1))
    dir="$work/$limit-$history"
    args=(--out "$dir/out" --store "$dir/store")
    mkdir -p "$dir"
    if [ "$history" = with ]; then
      cp "$work/baseline.sqlite" "$dir/history.sqlite"
      args+=(--db "$dir/history.sqlite")
    else
      args+=(--no-history)
    fi
    status=0
    (trap '' XFSZ; ulimit -f "$limit"; exec "$gibench" run "$suite" "${args[@]}") \
      >"$dir.stdout" 2>"$dir.stderr" || status=$?
    problem=""
    error_line=$(grep '^gibench: ' "$dir.stderr" || true)
    if [ "$status" -ne 0 ]; then
      stopped=$((stopped + 1))
      place=$(place_of "$dir" "$error_line")
      stops_at[$place]=$((${stops_at[$place]:-0} + 1))
      if [ "$status" -ne 2 ]; then problem="exit $status, not 2"; fi
      if [ "$(printf '%s\n' "$error_line" | grep -c .)" -ne 1 ]; then
        problem="$problem; not one error line"
      elif ! printf '%s' "$error_line" | grep -q '^gibench: cannot write'; then
        problem="$problem; unexpected error: $error_line"
      fi
    fi
    db_args=()
    if [ "$history" = with ]; then
      db_args=(--db "$dir/history.sqlite")
      runs=$(recorded_runs "$dir/history.sqlite")
      if grep -q 'history database' <<<"$error_line" && [ "$runs" -ne 1 ]; then
        problem="$problem; the database holds $runs runs after its failed append, not 1"
      fi
    fi
    if ! integrity=$(python3 "$here/check-run-integrity.py" "$gibench" --out "$dir/out" \
                       --store "$dir/store" "${db_args[@]}" --no-temporaries); then
      problem="$problem; left behind: $integrity"
    fi
    if ! "$gibench" run "$suite" "${args[@]}" >"$dir.resume.stdout" 2>"$dir.resume.stderr"; then
      problem="$problem; the resumed run failed: $(tail -1 "$dir.resume.stderr")"
    elif [ "$(metric_values "$dir/out")" != "$expected" ]; then
      problem="$problem; the resumed run measured other values than an uninterrupted one"
    fi
    if [ "$status" -eq 0 ]; then outcome="completed"; else outcome="stopped: ${error_line#gibench: }"; fi
    if [ -n "$problem" ]; then
      failed=$((failed + 1))
      echo "FAIL limit $limit KiB, $history history: $outcome;${problem#;}"
    else
      echo "ok   limit $limit KiB, $history history: $outcome; nothing partial; resumed equal"
    fi
  done
done
per_place=""
for place in job store history report results elsewhere; do
  [ -z "${stops_at[$place]:-}" ] || per_place="$per_place, $place ${stops_at[$place]}"
done
echo "disk full: $cases cases, $stopped stopped by the cap${per_place:+ (${per_place#, })}," \
  "$failed failed"
if [ "$stopped" -eq 0 ]; then
  echo "FAIL the cap stopped no run: nothing was tested; give smaller --limits"
  failed=$((failed + 1))
fi
for place in $expect_stops; do
  if [ -z "${stops_at[$place]:-}" ]; then
    echo "FAIL no limit stopped a run at the $place (--expect-stops)"
    failed=$((failed + 1))
  fi
done
[ "$failed" -eq 0 ]
