#!/usr/bin/env bash
# The main job on a fresh machine: install what is missing, build, render the Cornell box
# reference, and print where the EXR and the PNG are.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
mkdir -p out
build/release/cli/gibench render --scene cornell --spp "${GIB_SPP:-256}" --out out/cornell.exr
