#!/usr/bin/env bash
# Installs what is missing, builds and runs every test. Usage: scripts/test.sh [preset]
# (release by default; `asan` runs the same tests under AddressSanitizer + UBSan).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
scripts/install-deps.sh
scripts/build.sh "$preset"
# The report's browser test fails rather than skips when Chromium is missing: install-deps put it
# there, so its absence here is a broken setup.
GIB_REQUIRE_BROWSER=1 ctest --preset "$preset" -j"$(nproc)"
