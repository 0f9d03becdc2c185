#!/usr/bin/env bash
# Installs what is missing, builds and runs every test. Usage: scripts/test.sh [preset]
# (release by default; `asan` runs the same tests under AddressSanitizer + UBSan).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
scripts/install-deps.sh
scripts/build.sh "$preset"
# The report's browser test fails rather than skips when Chromium is missing: install-deps put it
# there, so its absence here is a broken setup; so does the JUnit schema test without xmllint.
# Likewise the Slurm test where it can start its one-node cluster (as root, as CI runs;
# scripts/slurm-local.sh).
slurm_required=0
if [ "$(id -u)" -eq 0 ]; then slurm_required=1; fi
GIB_REQUIRE_BROWSER=1 GIB_REQUIRE_XMLLINT=1 GIB_REQUIRE_SLURM=$slurm_required ctest --preset "$preset" -j"$(nproc)"
