#!/usr/bin/env bash
# scripts/fuzz.sh --run-only on a fake libFuzzer target (no sanitizer build needed): the seed it
# passes is the one it prints, given or drawn; a run fails when the target fails, and when the
# target exits 0 but left an input in its artifacts directory (as libFuzzer does for a slow
# unit); a finding left there fails every later run until it is removed.
#
#   tests/scripts/fuzz_script_test.sh SOURCE_DIR
set -euo pipefail
source_dir=$(realpath "$1")
work=$(mktemp -d "${TMPDIR:-/tmp}/gibench-fuzz-script-test-XXXXXX")
trap 'rm -rf "$work"' EXIT
target=exr  # any target of fuzz/: the script checks the name
artifacts="$work/build/fuzz/$target/artifacts"

fail() {
  echo "FAIL: $1" >&2
  exit 1
}

# The fake target: records its -seed, and as FAKE says, finishes cleanly, saves a slow unit and
# exits 0, or saves a crash and exits 1.
mkdir -p "$work/build/fuzz"
cat >"$work/build/fuzz/gib_fuzz_$target" <<'SH'
#!/usr/bin/env bash
for arg in "$@"; do
  case "$arg" in
    -seed=*) echo "${arg#-seed=}" >"$SEED_FILE" ;;
    -artifact_prefix=*) prefix=${arg#-artifact_prefix=} ;;
  esac
done
echo "#2 INITED cov: 10 ft: 10 corp: 1/1b"
echo "stat::number_of_executed_units: 7"
case "$FAKE" in
  slow) echo "Slowest unit: 10 s:" && echo x >"${prefix}slow-unit-0a1b" ;;
  crash) echo "==1==ERROR: AddressSanitizer: heap-buffer-overflow" && echo y >"${prefix}crash-2c3d" &&
         exit 1 ;;
esac
exit 0
SH
chmod +x "$work/build/fuzz/gib_fuzz_$target"

# Runs fuzz.sh on the fake target; sets `status`, `output` (stdout and stderr) and `seed` (the
# one the target received).
fuzz() {
  local mode=$1
  shift
  rm -f "$work/seed"
  status=0
  output=$(FAKE="$mode" SEED_FILE="$work/seed" "$source_dir/scripts/fuzz.sh" --run-only \
             --build-dir "$work/build" --seconds 1 "$@" "$target" 2>&1) || status=$?
  seed=$(cat "$work/seed" 2>/dev/null || echo none)
}

fuzz clean --seed 1234
[ "$status" -eq 0 ] || fail "a clean run exited $status: $output"
[ "$seed" = 1234 ] || fail "--seed 1234 passed -seed=$seed"
grep -q "(seed 1234)" <<<"$output" || fail "the seed is not printed: $output"

fuzz clean
[ "$status" -eq 0 ] && [[ "$seed" =~ ^[1-9][0-9]*$ ]] || fail "no seed drawn (-seed=$seed), exit $status"
grep -q "(seed $seed)" <<<"$output" || fail "the drawn seed $seed is not printed: $output"

fuzz crash
[ "$status" -eq 1 ] || fail "a crash: exit $status, not 1"
grep -q "FOUND a problem .*seed $seed.*crash-2c3d" <<<"$output" ||
  fail "a crash not reported with its seed and input: $output"
rm -f "$artifacts"/*

fuzz slow
[ "$status" -eq 1 ] || fail "an input saved by a target that exited 0: exit $status, not 1"
grep -q "FOUND a problem .*exit 0, seed $seed.*slow-unit-0a1b" <<<"$output" ||
  fail "a saved input not reported with its seed: $output"

fuzz clean
[ "$status" -eq 1 ] || fail "a clean run beside an earlier finding: exit $status, not 1"
rm -f "$artifacts"/*
fuzz clean
[ "$status" -eq 0 ] || fail "a clean run once the finding is removed: exit $status: $output"
echo "PASS"
