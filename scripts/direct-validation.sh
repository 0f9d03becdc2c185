#!/usr/bin/env bash
# Reproduces docs/direct-validation.md: `direct` on the Cornell box against the reference
# restricted to its path class (LE|LDE), for each shadow filter and a growing number of light
# samples, with error maps that show where shadow-map artefacts remain.
# Usage: scripts/direct-validation.sh [OUT_DIR] (default out/direct-validation); GIB_SIZE, GIB_SPP.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out/direct-validation}"
size="${GIB_SIZE:-512}"
spp="${GIB_SPP:-1024}"
gibench=build/release/cli/gibench
mkdir -p "$out"
$gibench render --scene cornell --max-bounces 1 --spp "$spp" --width "$size" --height "$size" \
  --out "$out/reference.exr" | grep rendered
printf '%-6s %8s %10s %8s %9s %10s %12s\n' shadow samples relmse mape flip_mean frame_ms shadow_map_ms
for shadow in hard pcf vsm; do
  for samples in 1 4 16 64 256; do
    name="${shadow}_${samples}"
    $gibench render --scene cornell --technique direct --set shadow="$shadow" \
      --set light_samples="$samples" --width "$size" --height "$size" --warmup 1 --frames 3 \
      --timings-json "$out/$name.json" --out "$out/$name.exr" > "$out/$name.txt"
    maps=()
    [ "$samples" = 256 ] && maps=(--maps "$out/maps_$shadow")
    $gibench compare "$out/reference.exr" "$out/$name.exr" --metrics relmse,mape,flip --json \
      "${maps[@]}" > "$out/$name.compare.json"
    python3 - "$out/$name.compare.json" "$out/$name.json" "$shadow" "$samples" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))["metrics"]
t = {p["name"]: p for p in json.load(open(sys.argv[2]))["passes"]}
print(f'{sys.argv[3]:<6} {sys.argv[4]:>8} {m["relmse"]:10.5f} {m["mape"]:8.4f} {m["flip_mean"]:9.4f} '
      f'{t["frame"]["median_ms"]:10.1f} {t["shadow map"]["median_ms"]:12.1f}')
PY
  done
done
