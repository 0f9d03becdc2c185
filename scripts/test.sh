#!/usr/bin/env bash
# Installs what is missing, builds and runs every test. Usage: scripts/test.sh [preset]
# (release by default; `asan` runs the same tests under AddressSanitizer + UBSan).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
scripts/install-deps.sh
scripts/build.sh "$preset"
ctest --preset "$preset" -j"$(nproc)"
