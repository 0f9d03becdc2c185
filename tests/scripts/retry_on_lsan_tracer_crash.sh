#!/usr/bin/env bash
# Runs a test command of the sanitizer build, and runs it once more only when it failed with
# LeakSanitizer's own tracer crashing at exit ("Tracer caught signal 11"): clang 14's runtime
# under glibc 2.36 can record a garbage dynamic-TLS block and die in its leak check after the
# test's work passed (docs/architecture.md, "Build and continuous integration"). Any other
# failure is final, and so is the rerun's outcome. Output passes through unchanged (stdout to
# stdout, stderr to stderr), so GoogleTest's test listing still reads clean.
#
#   tests/scripts/retry_on_lsan_tracer_crash.sh COMMAND [ARG ...]
#
# Exits with the command's status (the rerun's when there was one). tests/CMakeLists.txt puts it
# in front of the sanitizer build's tests, but never the fuzz (Fuzz.*) or fault (Faults.*) tests:
# a rerun there would search or kill elsewhere and hide what the first run found.
set -uo pipefail
[ $# -ge 1 ] || { echo "retry_on_lsan_tracer_crash.sh: give the command to run" >&2; exit 2; }
log=$(mktemp "${TMPDIR:-/tmp}/gibench-lsan-retry-XXXXXX")
trap 'rm -f "$log"' EXIT

# One run of the command, its stdout and stderr also appended to $log; returns its status.
run_once() {
  local status out_pid err_pid
  : >"$log"
  exec {out}> >(tee -a "$log")
  out_pid=$!
  exec {err}> >(tee -a "$log" >&2)
  err_pid=$!
  "$@" 1>&"$out" 2>&"$err"
  status=$?
  exec {out}>&- {err}>&-
  wait "$out_pid" "$err_pid"
  return "$status"
}

run_once "$@" && exit 0
status=$?
# The tracer's own report, from the test process or from a gibench it ran (whose stderr a test
# may print on stdout).
grep -q 'Tracer caught signal 11' "$log" || exit "$status"
echo "retry_on_lsan_tracer_crash.sh: exit $status with LeakSanitizer's tracer crash" \
  "(\"Tracer caught signal 11\"); running the test once more" >&2
run_once "$@"
