#!/usr/bin/env bash
# tests/scripts/retry_on_lsan_tracer_crash.sh on fake test commands: one that fails once with
# LeakSanitizer's tracer crash and then passes is run twice and passes; one that always fails
# so is run twice and fails; any other failure (a sanitizer's finding, an assertion) is run once
# and keeps its exit status; a passing command is run once, its stdout and stderr apart.
#
#   tests/scripts/retry_on_lsan_tracer_crash_test.sh SOURCE_DIR
set -euo pipefail
wrapper="$(realpath "$1")/tests/scripts/retry_on_lsan_tracer_crash.sh"
work=$(mktemp -d "${TMPDIR:-/tmp}/gibench-lsan-retry-test-XXXXXX")
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $1" >&2
  exit 1
}

# A fake test: counts its runs in $work/runs, prints "run N" on stdout and "diagnostic N" on
# stderr; on the runs listed in FAILING_RUNS it prints MESSAGE (on STREAM) and exits with CODE.
cat >"$work/fake-test" <<'SH'
#!/usr/bin/env bash
n=$(($(cat "$RUNS" 2>/dev/null || echo 0) + 1))
echo "$n" >"$RUNS"
echo "run $n"
echo "diagnostic $n" >&2
if [[ " $FAILING_RUNS " == *" $n "* ]]; then
  if [ "$STREAM" = stdout ]; then echo "$MESSAGE"; else echo "$MESSAGE" >&2; fi
  exit "$CODE"
fi
SH
chmod +x "$work/fake-test"
tracer="Tracer caught signal 11: addr=0x45e3 pc=0x7f00 sp=0x7e00"

# Runs the wrapper on the fake test; sets `status`, `runs`, `out`, `err`.
wrapped() {
  local failing=$1 stream=$2 message=$3 code=$4
  rm -f "$work/runs"
  status=0
  RUNS="$work/runs" FAILING_RUNS="$failing" STREAM="$stream" MESSAGE="$message" CODE="$code" \
    "$wrapper" "$work/fake-test" >"$work/out" 2>"$work/err" || status=$?
  runs=$(cat "$work/runs")
  out=$(cat "$work/out")
  err=$(cat "$work/err")
}

# Fails unless the last wrapped run exited `want_status` after `want_runs` runs of the test.
expect() {
  local want_status=$1 want_runs=$2 what=$3
  [ "$status" -eq "$want_status" ] && [ "$runs" -eq "$want_runs" ] ||
    fail "$what: exit $status after $runs runs, not $want_status after $want_runs"
}

wrapped "1" stderr "$tracer" 1
expect 0 2 "a tracer crash then a pass"
grep -q "running the test once more" <<<"$err" || fail "the rerun is not announced: $err"
[ "$out" = $'run 1\nrun 2' ] || fail "stdout of both runs not passed through: $out"

wrapped "1" stdout "$tracer" 1
expect 0 2 "a tracer crash reported on stdout"

wrapped "1 2" stderr "$tracer" 23
expect 23 2 "a tracer crash twice"

wrapped "1" stderr "ERROR: AddressSanitizer: heap-use-after-free on address 0x6020" 1
expect 1 1 "an AddressSanitizer finding"

wrapped "1" stdout "[  FAILED  ] Suite.Test (12 ms)" 3
expect 3 1 "a failed assertion"

wrapped "" stderr "" 0
expect 0 1 "a pass"
[ "$out" = "run 1" ] && [ "$err" = "diagnostic 1" ] ||
  fail "stdout and stderr not kept apart: stdout '$out', stderr '$err'"
echo "PASS"
