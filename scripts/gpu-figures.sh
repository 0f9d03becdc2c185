#!/usr/bin/env bash
# One command for a GPU's figures (docs/harness.md, "GPU figures"): on the GL renderer this
# machine gives (GIBENCH_GL_DEVICE chooses one, as for gibench), it runs every technique's frame
# benchmark and the figure suites' timing jobs, and writes DIR/<renderer>.md: the renderer and
# driver, the program's version, each technique's frame time, and the per-pass times of the
# timing jobs with each paper's number beside ours. Commit a GPU's table as docs/gpu/<renderer>.md.
#
#   scripts/gpu-figures.sh [--quick] --out DIR [--gibench PATH] [--bench PATH]
#
#   --out DIR       where everything goes (made if missing; rerun with the same DIR to resume the
#                   suite's run): bench.json and bench.log, the suite gpu-figures.toml, its run
#                   directory gpu-figures/ (results.json, the report), its reference store, the
#                   ray-casting bench raycast/ (raycast.json, its page) and the table
#                   <renderer>.md
#   --quick         one benchmark per technique, for one iteration, and one timing job for one
#                   frame: tests the script
#   --gibench PATH  default build/release/cli/gibench
#   --bench PATH    gib_realtime_bench; default build/release/bench/gib_realtime_bench
#
# The timing jobs are the figure suites' jobs with a paper time, copied with their settings
# (resolution, frames, iterations) into one suite by scripts/gpu_figures_suite.py, their
# references at 1 spp (a job is timed before its reference is fetched).
#
# Budget (the issue: under 8 minutes on an H100). About 50 benchmarks, each 0.5 s of measured
# frames (Google Benchmark's default minimum) after its set-up (the scene, the technique's
# preparation, two warm-up frames), and 18 timing jobs with the figure suites' frames (2 to 16)
# and iterations (up to 200), each with its scene, BVH, preparation, 1-spp references and
# images, then one report: a minute or two of each on a GPU, under 5 minutes in all. On llvmpipe
# most of the time goes to set-up and preprocessing (the light path maps' thousands of shadow
# maps, the GPU irradiance cache's record views) that a GPU does in seconds; the times measured
# there are in docs/harness.md, "GPU figures".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: scripts/gpu-figures.sh [--quick] --out DIR [--gibench PATH] [--bench PATH]"

fail() {
  echo "gpu-figures.sh: $1" >&2
  exit 2
}
progress() { echo "gpu-figures: $*" >&2; }

quick="" out="" gibench="$root/build/release/cli/gibench"
bench="$root/build/release/bench/gib_realtime_bench"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --out | --gibench | --bench)
      case "${2:---}" in --*) fail "$1 needs a value; $usage" ;; esac
      case "$1" in
        --out) out=$2 ;;
        --gibench) gibench=$2 ;;
        --bench) bench=$2 ;;
      esac
      shift
      ;;
    -h | --help)
      echo "$usage"
      exit 0
      ;;
    *) fail "unknown option '$1'; $usage" ;;
  esac
  shift
done
[ -n "$out" ] || fail "--out DIR is missing: where the table and the run go; $usage"
[ ! -e "$out" ] || [ -d "$out" ] || fail "--out $out is not a directory; give a new or existing directory"
[ -x "$gibench" ] || fail "gibench not found at $gibench; build it (ninja -C build/release gibench) or give --gibench PATH"
[ -x "$bench" ] || fail "gib_realtime_bench not found at $bench; build it (ninja -C build/release gib_realtime_bench) or give --bench PATH"
command -v python3 >/dev/null || fail "python3 not found; install it (scripts/install-deps.sh)"

mkdir -p "$out"
out=$(cd "$out" && pwd)
table="$root/scripts/gpu_figures_table.py"
name="gpu-figures${quick:+-quick}"
# Google Benchmark's minimum time per benchmark (seconds): its default, or one iteration.
min_time=0.5
[ -z "$quick" ] || min_time=0.01

# 1. Every technique's frame (or iteration) benchmark, or the first of each with --quick.
mapfile -t techniques < <("$gibench" list techniques | awk '/^[a-z]/ && $1 != "reference" { print $1 }')
[ ${#techniques[@]} -gt 0 ] || fail "gibench list techniques named none; check $gibench"
filter=$(python3 "$table" bench-filter "${techniques[@]}")
if [ -n "$quick" ]; then
  filter=$("$bench" --benchmark_list_tests --benchmark_filter="$filter" |
    python3 "$table" bench-filter --first "${techniques[@]}")
fi
count=$("$bench" --benchmark_list_tests --benchmark_filter="$filter" | wc -l)
progress "[1/4] gib_realtime_bench: $count benchmarks of ${#techniques[@]} techniques (log: $out/bench.log)"
# One line per benchmark as it ends (its name and time); the whole output in bench.log.
set +e
stdbuf -oL "$bench" --benchmark_filter="$filter" --benchmark_min_time="$min_time" \
  --benchmark_out="$out/bench.json" --benchmark_out_format=json 2>&1 |
  tee "$out/bench.log" | awk '/^BM_/ { print "  " $1 "  " $2 " " $3; fflush() }' >&2
status=${PIPESTATUS[0]}
set -e
if [ "$status" -ne 0 ]; then
  progress "gib_realtime_bench failed (exit $status): $(tail -n 1 "$out/bench.log")"
  exit 1
fi
renderer=$(python3 "$table" renderer "$out/bench.json")
progress "GL renderer: $renderer"

# 2. The figure suites' timing jobs, at the papers' settings, references at 1 spp.
job_ids=$(python3 "$root/scripts/gpu_figures_suite.py" "$root/suites/figures" "$out/$name.toml" ${quick:+--quick})
only=()
while read -r id; do only+=(--only "$id"); done <<<"$job_ids"
progress "[2/4] gibench run: $((${#only[@]} / 2)) timing jobs of the figure suites (run: $out/$name)"
# gibench's line for each job as it ends; the whole log in run.log. Exit status 1: some jobs
# failed (the table marks them); 2: bad input or no GL (its one line says which).
set +e
"$gibench" run "$out/$name.toml" --out "$out/$name" --store "$out/store" --no-history "${only[@]}" 2>&1 |
  tee "$out/run.log" | grep --line-buffered -E '^\[[0-9]+/[0-9]+\] .*: (done|failed)' | sed -u 's/^/  /' >&2
status=${PIPESTATUS[0]}
set -e
if [ "$status" -ne 0 ] && [ "$status" -ne 1 ]; then
  progress "gibench run failed (exit $status): $(tail -n 1 "$out/run.log")"
  exit "$status"
fi

# 3. Ray casting against Embree (book Ch. 5): the chamber at every detail at 512², each kind of
# rays; with --quick the Cornell box at 16².
raycast_args=(--scene chamber --sweep detail=1,2,3,4,5 --width 512 --height 512 --repeats 5)
[ -z "$quick" ] || raycast_args=(--scene cornell --width 16 --height 16 --repeats 1)
progress "[3/4] gibench raycast-bench ${raycast_args[*]} (log: $out/raycast.log)"
if ! "$gibench" raycast-bench "${raycast_args[@]}" --out "$out/raycast" >"$out/raycast.log" 2>&1; then
  progress "gibench raycast-bench failed: $(tail -n 1 "$out/raycast.log")"
  exit 1
fi

# 4. The table.
written=$(python3 "$table" markdown "$out/bench.json" "$out/$name" "$out" "${techniques[@]}" \
  --raycast "$out/raycast/raycast.json" ${quick:+--quick})
progress "[4/4] wrote $written"
exit "$status"
