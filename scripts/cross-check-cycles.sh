#!/usr/bin/env bash
# Cross-checks GI Bench's reference path tracer against Blender's Cycles on one scene: renders it
# with both at the same size and sample count, and prints side by side their per-channel image
# means, the worst 16x16 block difference of the means, FLIP between them, their times and, with
# --truth-spp, each one's MSE against a long render of another seed and the efficiency
# 1/(MSE·time). Two unbiased renderers of one scene agree on the means up to their noise.
#
#   scripts/cross-check-cycles.sh SCENE [--scene-set key=value ...] [--width W] [--height H]
#                                 [--spp N] [--seed S] [--truth-spp N] [--replicas K] [--out DIR]
#                                 [--cycles-no-light-sampling] [--own-truth] [--light-paths MODE]
#                                 [--lens-radius R --focus-distance D]
#
# The truth is a Cycles render when the scene maps exactly onto Cycles; when it does not (the
# exporter's warnings say what differs: Phong lobes, a spot fall-off, a medium, the caustics of a
# spot or sun lamp, which Cycles cannot reach), the two images estimate different integrals, so
# each renderer's MSE is taken against a long render of its own.
# --own-truth measures each renderer against a long render of its own for an exact scene too:
# its MSE is then its noise alone, without the small systematic difference between the renderers
# (which the means and the worst block show). --replicas K is passed to `gibench render` (its
# default: 4 replicas, the error bars' cost), and so is --light-paths auto|off (its default: auto,
# light tracing of the caustics' paths where the scene has mirrors or glass; off: camera paths
# only, a path tracer as Cycles is). --lens-radius R --focus-distance D give both renderers the
# thin lens (docs/rendering.md, "Depth of field: the thin lens"; Cycles' depth of field).
#
# --cycles-no-light-sampling renders both Cycles images with emissive meshes left to BSDF
# sampling: noisier, but free of the slight darkening of Cycles' light sampling at grazing angles
# (docs/cycles-cross-check.md).
#
# SCENE is what `gibench render --scene` takes. gibench is $GIBENCH or build/release/cli/gibench
# (this script builds nothing); Blender is $BLENDER or `blender` on the PATH. Images, the exported
# script and the logs stay in DIR (default: a new directory under /tmp). Bad input: one line on
# stderr, exit code 2.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
me="cross-check-cycles"

fail() {
  echo "$me: $1" >&2
  exit 2
}

usage="usage: scripts/cross-check-cycles.sh SCENE [--scene-set key=value ...] [--width W]"
usage+=" [--height H] [--spp N] [--seed S] [--truth-spp N] [--replicas K] [--out DIR]"
usage+=" [--cycles-no-light-sampling] [--own-truth] [--light-paths MODE]"
usage+=" [--lens-radius R --focus-distance D]"
scene=""
scene_set=()
width=256
height=192
spp=64
seed=0
truth_spp=0
replicas=0
out=""
own_truth=0
cycles_options=()
gibench_options=()
while [ $# -gt 0 ]; do
  case "$1" in
    --cycles-no-light-sampling)
      cycles_options=(--no-light-sampling)
      shift
      ;;
    --own-truth)
      own_truth=1
      shift
      ;;
    --scene-set | --width | --height | --spp | --seed | --truth-spp | --replicas | --out | \
      --light-paths | --lens-radius | --focus-distance)
      [ $# -ge 2 ] || fail "$1 needs a value; $usage"
      case "$1" in
        --scene-set) scene_set+=(--scene-set "$2") ;;
        --width) width="$2" ;;
        --height) height="$2" ;;
        --spp) spp="$2" ;;
        --seed) seed="$2" ;;
        --truth-spp) truth_spp="$2" ;;
        --replicas) replicas="$2" ;;
        --out) out="$2" ;;
        --light-paths) gibench_options+=(--light-paths "$2") ;;
        # The thin lens: the scene's camera for both renderers, so it goes with the scene.
        --lens-radius | --focus-distance) scene_set+=("$1" "$2") ;;
      esac
      shift 2
      ;;
    -h | --help)
      echo "$usage"
      exit 0
      ;;
    -*) fail "unknown option '$1'; $usage" ;;
    *)
      [ -z "$scene" ] || fail "two scenes given ('$scene', '$1'); $usage"
      scene="$1"
      shift
      ;;
  esac
done
[ -n "$scene" ] || fail "no scene given; $usage"
for pair in "width:$width" "height:$height" "spp:$spp"; do
  [[ "${pair#*:}" =~ ^[1-9][0-9]*$ ]] || fail "--${pair%%:*} '${pair#*:}' must be a positive integer"
done
[[ "$truth_spp" =~ ^[0-9]+$ ]] || fail "--truth-spp '$truth_spp' must be a non-negative integer"
[[ "$replicas" =~ ^[0-9]+$ ]] || fail "--replicas '$replicas' must be a non-negative integer"
# Cycles' seeds are 0 to 2^31 - 1, and the truth takes the next one.
[[ "$seed" =~ ^[0-9]{1,10}$ ]] && [ "$seed" -lt 2147483647 ] ||
  fail "--seed '$seed' must be an integer from 0 to 2147483646 (Cycles' seeds)"

gibench="${GIBENCH:-$root/build/release/cli/gibench}"
[ -x "$gibench" ] ||
  fail "no gibench at '$gibench'; build it (scripts/build.sh release gibench) or set GIBENCH"
blender="${BLENDER:-blender}"
command -v "$blender" >/dev/null ||
  fail "no Blender ('$blender' is not a program); install it (scripts/install-deps.sh) or set BLENDER"
command -v python3 >/dev/null || fail "python3 is missing; install it (scripts/install-deps.sh)"

if [ -z "$out" ]; then
  out="$(mktemp -d /tmp/cross-check-cycles.XXXXXX)"
  # A directory of our own making is not left behind by a failed check.
  trap 'code=$?; [ "$code" -eq 0 ] || rm -rf "$out"' EXIT
else
  mkdir -p "$out" 2>/dev/null || fail "cannot create --out '$out'; choose another directory"
fi

# Runs a step whose output goes to its log; on failure, its last line (gibench's own one-line
# reason for bad input) is passed on with the step's exit code.
step() {
  local log="$1"
  shift
  local code=0
  "$@" >"$log" 2>&1 || code=$?
  if [ "$code" -ne 0 ]; then
    echo "$me: $(grep -v '^$' "$log" | tail -n 1) (log: $log)" >&2
    exit "$code"
  fi
}

# 1. The scene as a Blender script: this also refuses an unknown scene or parameter before any
#    rendering. Its warnings (what Cycles cannot reproduce) are shown.
step "$out/export.log" "$gibench" export-blender --scene "$scene" "${scene_set[@]}" \
  --width "$width" --height "$height" --spp "$spp" --seed "$seed" --out "$out/scene.py"
exact=1
if grep 'warning' "$out/export.log" >&2; then exact=0; fi

now() { date +%s.%N; }
since() { python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.3f}')" "$1" "$(now)"; }

# 2. GI Bench's reference. Its time is the renderer's own (scene setup and BVH included, file
#    writing excluded), recorded in the EXR's metadata to the millisecond; wall time is the
#    fallback.
start="$(now)"
step "$out/gibench.log" "$gibench" render --scene "$scene" "${scene_set[@]}" --width "$width" \
  --height "$height" --spp "$spp" --seed "$seed" --replicas "$replicas" "${gibench_options[@]}" \
  --out "$out/gibench.exr"
gibench_wall="$(since "$start")"
metadata() { oiiotool --info -v "$out/gibench.exr" 2>/dev/null | sed -n "s|^ *gibench/$1: \"\(.*\)\"$|\1|p" || true; }
gibench_seconds="$(metadata render_seconds)"
gibench_sampler="$(metadata sampler), $(metadata replicas) replicas"
light_paths="$(metadata light_paths)"
[ -z "$light_paths" ] || gibench_sampler+=", light paths $light_paths"
gibench_clock="its reported render time"
if [ -z "$gibench_seconds" ]; then
  gibench_seconds="$gibench_wall"
  gibench_clock="wall time of the gibench process"
fi

# 3. Cycles. Blender reports its render time ("Time: MM:SS.ss (Saving: …)": scene sync, BVH and
#    path tracing, not Blender's start-up nor the file's writing); wall time is the fallback.
blender_seconds() {
  python3 - "$1" <<'EOF'
import re, sys
text = open(sys.argv[1], errors="replace").read()
found = re.findall(r"^ ?Time: ([0-9:.]+) \(Saving", text, re.M)
if found:
    seconds = 0.0
    for part in found[-1].split(":"):
        seconds = seconds * 60 + float(part)
    print(f"{seconds:.3f}")
EOF
}
cycles() {
  local exr="$1" log="$2"
  shift 2
  local start
  start="$(now)"
  step "$log" "$blender" -b --factory-startup --python-exit-code 3 --python "$out/scene.py" \
    -- "$exr" "${cycles_options[@]}" "$@"
  cycles_wall="$(since "$start")"
  cycles_seconds="$(blender_seconds "$log")"
  cycles_clock="Blender's reported render time"
  if [ -z "$cycles_seconds" ]; then
    cycles_seconds="$cycles_wall"
    cycles_clock="wall time of the blender process"
  fi
}
cycles "$out/cycles.exr" "$out/cycles.log"

# 4. The truth: a long Cycles render with the next seed, independent of both; and, for a scene
#    Cycles renders differently, a long GI Bench render of the next seed as GI Bench's own.
truth_args=()
if [ "$truth_spp" -gt 0 ]; then
  (cycles "$out/truth.exr" "$out/truth.log" --spp "$truth_spp" --seed "$((seed + 1))")
  gibench_truth="$out/truth.exr"
  if [ "$exact" -eq 0 ] || [ "$own_truth" -eq 1 ]; then
    gibench_truth="$out/gibench-truth.exr"
    step "$out/gibench-truth.log" "$gibench" render --scene "$scene" "${scene_set[@]}" \
      --width "$width" --height "$height" --spp "$truth_spp" --seed "$((seed + 1))" \
      --replicas 1 "${gibench_options[@]}" --out "$gibench_truth"
  fi
  step "$out/gibench-truth.json" "$gibench" compare "$gibench_truth" "$out/gibench.exr" \
    --metrics mse --json
  step "$out/cycles-truth.json" "$gibench" compare "$out/truth.exr" "$out/cycles.exr" \
    --metrics mse --json
  truth_args=("$out/gibench-truth.json" "$out/cycles-truth.json")
fi

# 5. The two against each other, and the table.
step "$out/compare.json" "$gibench" compare "$out/gibench.exr" "$out/cycles.exr" \
  --metrics flip,block_bias --json
python3 - "$scene ${scene_set[*]}" "$width" "$height" "$spp" "$seed" "$truth_spp" "$out" \
  "$gibench_seconds" "$gibench_clock" "$cycles_seconds" "$cycles_clock" "$out/compare.json" \
  "$gibench_sampler" "$exact" "$own_truth" "${truth_args[@]}" <<'EOF'
import json, sys

(scene, width, height, spp, seed, truth_spp, out, g_time, g_clock, c_time, c_clock,
 compare, g_sampler, exact, own_truth) = sys.argv[1:16]
truth = sys.argv[16:]
exact = exact == "1"
own_truth = own_truth == "1"
g_time, c_time = float(g_time), float(c_time)
both = json.load(open(compare))
means = both["means"]
scene = " ".join(scene.replace("--scene-set ", "").split())


def relative(g, c):
    return f"{100 * (c / g - 1):+.3f}%" if g else "n/a"


print(f"cross-check of {scene} at {width}x{height}, {spp} spp, seed {seed}: GI Bench reference "
      f"({g_sampler}) vs Cycles (files in {out})")
if not exact:
    print("the scene is not mapped exactly onto Cycles (the warnings above): the means and blocks "
          "differ by design")
print(f"{'':<28}{'GI Bench':>14}{'Cycles':>14}  Cycles/GI Bench - 1")
for c, name in enumerate("RGB"):
    g, y = means["reference"][c], means["test"][c]
    print(f"{'mean ' + name:<28}{g:>14.6g}{y:>14.6g}  {relative(g, y)}")
print(f"{'worst 16x16 block mean':<28}{'':>28}  {100 * both['metrics']['block_bias']:.3f}% "
      "(largest |difference| of a channel's block means; blocks under 1% of the image mean "
      "left out)")
print(f"{'FLIP between them':<28}{'':>28}  {both['metrics']['flip_mean']:.5f} (mean LDR-FLIP)")
print(f"{'time (s)':<28}{g_time:>14.3f}{c_time:>14.3f}  GI Bench: {g_clock}; Cycles: {c_clock}")
if truth:
    g_mse = json.load(open(truth[0]))["metrics"]["mse"]
    c_mse = json.load(open(truth[1]))["metrics"]["mse"]
    whose = "Cycles" if exact and not own_truth else "each renderer's own"
    print(f"{'MSE vs truth':<28}{g_mse:>14.6g}{c_mse:>14.6g}  truth: {whose}, {truth_spp} spp, "
          f"seed {int(seed) + 1}")
    g_eff, c_eff = 1 / (g_mse * g_time), 1 / (c_mse * c_time)
    print(f"{'efficiency 1/(MSE·time)':<28}{g_eff:>14.6g}{c_eff:>14.6g}  GI Bench/Cycles = "
          f"{g_eff / c_eff:.3f}")
EOF
if [ ${#cycles_options[@]} -gt 0 ]; then
  echo "Cycles lit emissive meshes by BSDF sampling alone (--cycles-no-light-sampling)"
fi
