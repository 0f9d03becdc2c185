#!/usr/bin/env bash
# Configures and builds one CMake preset (default: release), all of it or the given targets.
#   scripts/build.sh [preset] [target ...]        e.g. scripts/build.sh release gibench
# GIB_WERROR=1 turns warnings into errors (CI's release build).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
shift || true
werror=OFF
if [ "${GIB_WERROR:-0}" = 1 ]; then werror=ON; fi
cmake --preset "$preset" -DGIB_WERROR="$werror" >/dev/null
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build --preset "$preset" "${targets[@]}" -- -j"$(nproc)"
