#!/usr/bin/env bash
# How often `gibench store verify` fails an intact entry (docs/harness.md, "Reference store"):
# stores N references of one scene that differ only in their seed (so each is an independent,
# intact entry), verifies every one at each fresh-render spp given, and prints the failures. At
# family-wise significance α an intact entry should fail with probability at most α; the counts
# are binomial, so 4 of 300 at α = 0.01 is within expectation (one-sided binomial p 0.35); each
# line gives that p: the chance of at least as many failures were each entry to fail with
# probability α.
#
#   scripts/verify-false-failure-rate.sh GIBENCH [--entries N] [--scene S] [--size WxH]
#       [--stored-spp S] [--verify-spp "32 64 128"] [--significance A] [--max-failures F]
#       [--work DIR]
#
# Prints one line per verify spp; exits 1 when an entry was not verified or, with --max-failures,
# when more than F entries failed at a verify spp (choose F from the binomial tail: F = 1 of 3
# entries at α = 0.01 fails an intact store with probability 3·10⁻⁴), 2 on bad arguments.
set -euo pipefail
script=verify-false-failure-rate.sh
source "$(dirname "$0")/faults-common.sh"
faults_gibench "$@"
shift
entries=100
scene=cornell
size=32x24
stored_spp=64
verify_spp="32 64 128"
significance=0.01
max_failures=""
work=""
while [ $# -gt 0 ]; do
  case "$1" in
    --entries) entries=$2; shift 2 ;;
    --scene) scene=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --stored-spp) stored_spp=$2; shift 2 ;;
    --verify-spp) verify_spp=$2; shift 2 ;;
    --significance) significance=$2; shift 2 ;;
    --max-failures) max_failures=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    *) faults_usage_error "unknown argument '$1'" ;;
  esac
done
[[ "$entries" =~ ^[1-9][0-9]*$ ]] || faults_usage_error "--entries takes a positive integer"
[[ "$size" =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || faults_usage_error "--size takes WxH, e.g. 32x24"
[[ "$max_failures" =~ ^[0-9]*$ ]] || faults_usage_error "--max-failures takes a count"
faults_work_dir verify-rate

# One suite, one reference case per seed: the run stores N entries.
suite="$work/entries.toml"
{
  echo "name = \"verify-rate\""
  echo "[defaults]"
  echo "width = ${size%x*}"
  echo "height = ${size#*x}"
  echo "metrics = [\"relmse\"]"
  for seed in $(seq 1 "$entries"); do
    echo "[[case]]"
    echo "name = \"seed-$seed\""
    echo "scene = \"$scene\""
    echo "technique = \"reference\""
    echo "reference = { spp = $stored_spp, seed = $seed }"
  done
} >"$suite"
"$gibench" run "$suite" --out "$work/run" --store "$work/store" --no-history >"$work/run.log" 2>&1 ||
  { tail -3 "$work/run.log" >&2; exit 1; }

exceeded=0
for spp in $verify_spp; do
  # --allow-few-samples: below 32 spp is what this script measures.
  summary=$("$gibench" store verify --store "$work/store" --spp "$spp" --allow-few-samples \
              --significance "$significance" | tail -1 || true)
  failed=$(grep -o '[0-9]* failed' <<<"$summary" | grep -o '[0-9]*' || true)
  verified=$(grep -o '^[0-9]* verified' <<<"$summary" | grep -o '[0-9]*' || true)
  if [ "${verified:-0}" != "$entries" ]; then
    echo "$script: store verify verified ${verified:-no} entries of $entries: $summary" >&2
    exit 1
  fi
  p=$(python3 -c '
import math, sys
n, k, a = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
print(f"{sum(math.comb(n, i) * a**i * (1 - a)**(n - i) for i in range(k, n + 1)):.2g}")' \
      "$verified" "$failed" "$significance")
  echo "$scene $size stored at $stored_spp spp, verified at $spp spp: $failed of $verified" \
    "intact entries failed (significance $significance; one-sided binomial p $p)"
  if [ -n "$max_failures" ] && [ "$failed" -gt "$max_failures" ]; then
    echo "$script: $failed intact entries failed at $spp spp, more than --max-failures" \
      "$max_failures (one-sided binomial p $p)" >&2
    exceeded=1
  fi
done
[ "$exceeded" -eq 0 ]
