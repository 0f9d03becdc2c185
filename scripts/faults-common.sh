# What the fault scripts (scripts/faults-*.sh) and scripts/verify-false-failure-rate.sh share;
# sourced, not run. Each script sets `script` (its name, for messages) before sourcing this, then
# calls faults_gibench "$@" and shifts the binary off.

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# One line naming the problem and where to look, exit code 2.
faults_usage_error() {
  echo "$script: $1; see the usage at the top of scripts/$script" >&2
  exit 2
}

# Reads the gibench binary (the first argument) into `gibench`; the caller shifts it off.
faults_gibench() {
  [ $# -ge 1 ] || faults_usage_error "give the gibench binary"
  gibench=$(realpath "$1")
}

# Makes `work` exist: the directory given with --work (kept), or a temporary one removed at exit.
faults_work_dir() {
  if [ -z "$work" ]; then
    work=$(mktemp -d "${TMPDIR:-/tmp}/gibench-$1-XXXXXX")
    trap 'rm -rf "$work"' EXIT
  fi
  mkdir -p "$work"
}

# The metric values of every job of the run in directory $1, one "job metric value" line each:
# equal for two runs that measured the same.
metric_values() {
  python3 -c '
import json, sys
for job in json.load(open(sys.argv[1]))["jobs"]:
    for name, value in sorted((job.get("metrics") or {}).items()):
        print(job["id"], name, repr(value))' "$1/results.json"
}

# The number of runs the history database $1 records.
recorded_runs() {
  python3 -c 'import sqlite3, sys; print(sqlite3.connect(sys.argv[1]).execute("SELECT count(*) FROM runs").fetchone()[0])' "$1"
}
