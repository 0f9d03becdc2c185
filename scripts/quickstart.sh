#!/usr/bin/env bash
# The README's main job on a fresh Debian bookworm machine: install what is missing, build, run the
# smoke suite (the Cornell box: reference and `direct`) and write its results and HTML report.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
build/release/cli/gibench run suites/smoke.toml "$@"
