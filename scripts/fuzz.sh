#!/usr/bin/env bash
# Builds and runs the libFuzzer targets of fuzz/ (docs/reliability.md, "Fuzzing").
#
#   scripts/fuzz.sh [--seconds N] [--seed S] [--jobs J] [--fork W] [--build-dir DIR] [--run-only]
#                   [--merge] [TARGET ...]
#
# Every target by default (`scripts/fuzz.sh --list` names them). Each runs N seconds (default 60)
# on its checked-in corpus fuzz/corpus/<target>/ (suite_file also on the shipped suites), with its
# dictionary fuzz/dictionaries/ where there is one; inputs it finds are kept in DIR/fuzz/<target>/corpus, and a crash, hang, leak or
# out-of-memory input in DIR/fuzz/<target>/artifacts. --jobs J runs that many targets at once;
# --fork W runs each target in W worker processes (libFuzzer's -fork=W), for a slow target.
# --merge adds the found inputs that reach new coverage to the checked-in corpus (libFuzzer's
# -merge=1), for a maintainer to review and commit. The build is the clang sanitizer build (the
# asan preset, build/asan) unless --build-dir names another; --run-only skips building.
# libFuzzer's random seed is S (default: drawn at random), printed with each target's outcome:
# --seed S repeats a run's random choices on the same corpus.
# Prints one line per target (executions, coverage, seed, crashes) and exits 1 when any target
# found something, 2 on bad arguments. A target has found something when libFuzzer failed or
# when anything is in its artifacts directory afterwards, whatever run put it there (libFuzzer
# also saves inputs it does not stop for, such as slow units): a finding stays a failure until
# its input is dealt with (kept as a regression-* corpus file) and removed from there.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=60
seed=$((RANDOM * 32768 + RANDOM + 1))  # 1 to 2^30 (libFuzzer would draw one of its own for 0)
jobs=1
fork=0
build_dir=build/asan
run_only=0
merge=0
targets=()
usage() { echo "fuzz.sh: $1; see the usage at the top of scripts/fuzz.sh" >&2; exit 2; }
all_targets() { for f in fuzz/*_fuzzer.cpp; do basename "$f" _fuzzer.cpp; done; }
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) [[ "${2:-}" =~ ^[1-9][0-9]*$ ]] || usage "--seconds takes a positive integer"
               seconds=$2; shift 2 ;;
    --seed) [[ "${2:-}" =~ ^[1-9][0-9]{0,9}$ ]] && [ "$2" -lt 2147483648 ] ||
              usage "--seed takes a positive integer below 2^31"
            seed=$2; shift 2 ;;
    --jobs) [[ "${2:-}" =~ ^[1-9][0-9]*$ ]] || usage "--jobs takes a positive integer"
            jobs=$2; shift 2 ;;
    --fork) [[ "${2:-}" =~ ^[1-9][0-9]*$ ]] || usage "--fork takes a positive integer"
            fork=$2; shift 2 ;;
    --build-dir) [ -n "${2:-}" ] || usage "--build-dir takes a directory"
                 build_dir=$2; shift 2 ;;
    --run-only) run_only=1; shift ;;
    --merge) merge=1; shift ;;
    --list) all_targets; exit 0 ;;
    -*) usage "unknown option '$1'" ;;
    *) [ -f "fuzz/$1_fuzzer.cpp" ] || usage "unknown fuzz target '$1' (known: $(all_targets | xargs))"
       targets+=("$1"); shift ;;
  esac
done
if [ ${#targets[@]} -eq 0 ]; then mapfile -t targets < <(all_targets); fi

if [ "$run_only" = 0 ]; then
  scripts/install-deps.sh
  build_targets=()
  for t in "${targets[@]}"; do build_targets+=("gib_fuzz_$t"); done
  scripts/build.sh asan "${build_targets[@]}"
fi

# One target: libFuzzer writes new inputs into the first corpus directory only, so the checked-in
# one (second) is read, never changed. The RSS limit leaves room for the sanitizers' shadow
# memory; an input that takes over 10 s is a hang.
run_target() {
  local t=$1 work="$build_dir/fuzz/$1"
  local binary="$build_dir/fuzz/gib_fuzz_$t"
  [ -x "$binary" ] || { echo "fuzz.sh: $binary is missing; build it (drop --run-only)" >&2; return 2; }
  mkdir -p "$work/corpus" "$work/artifacts"
  local dict=()
  local dict_file="fuzz/dictionaries/$t.dict"
  [ "$t" = history_row ] && dict_file=fuzz/dictionaries/results_json.dict  # rows hold results
  [ -f "$dict_file" ] && dict=("-dict=$dict_file")
  # Shipped files that are seeds as they stand, read in place rather than copied.
  local seeds=("fuzz/corpus/$t")
  [ "$t" = suite_file ] && seeds+=(suites suites/figures)
  local log="$work/last-run.log"
  local status=0
  local workers=()
  [ "$fork" -gt 0 ] && workers=("-fork=$fork")
  ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}" \
    "$binary" -seed="$seed" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
    -print_final_stats=1 -artifact_prefix="$work/artifacts/" "${workers[@]}" "${dict[@]}" \
    "$work/corpus" "${seeds[@]}" >"$log" 2>&1 || status=$?
  local runs cov
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  # Fork mode prints no final statistics; its progress lines begin "#<executions>: cov: …".
  [ -n "$runs" ] || runs=$(grep -o '^#[0-9]*: cov' "$log" | tail -1 | grep -o '[0-9]*' || true)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || true)
  if [ "$fork" -gt 0 ] && [ "$status" -eq 0 ]; then
    # Fork mode's "cov" counts features; the edges are those its corpus reaches, replayed once.
    cov=$("$binary" -runs=0 "$work/corpus" 2>&1 | grep -o 'INITED cov: [0-9]*' | grep -o '[0-9]*$' ||
            true)
  fi
  local artifacts
  artifacts=$(find "$work/artifacts" -mindepth 1 -maxdepth 1 -printf '%f ')
  if [ "$status" -ne 0 ] || [ -n "$artifacts" ]; then
    echo "fuzz $t: FOUND a problem after ${runs:-?} executions (exit $status, seed $seed);" \
      "in $work/artifacts: ${artifacts:-nothing}; log $log" >&2
    grep -m3 -E 'ERROR|SUMMARY|uncaught|terminate' "$log" >&2 || tail -5 "$log" >&2
    return 1
  fi
  echo "fuzz $t: ${runs:-0} executions in ${seconds} s (seed $seed), coverage ${cov:-0} edges," \
    "no crash"
  if [ "$merge" = 1 ]; then
    "$binary" -merge=1 "fuzz/corpus/$t" "$work/corpus" >"$work/merge.log" 2>&1
    echo "fuzz $t: merged into fuzz/corpus/$t ($(grep -o 'added [0-9]* new units' "$work/merge.log" || echo 'nothing new'))"
  fi
}

failed=0
running=0
for t in "${targets[@]}"; do
  run_target "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n || failed=1; running=$((running - 1)); fi
done
while [ "$running" -gt 0 ]; do wait -n || failed=1; running=$((running - 1)); done
exit "$failed"
