#!/usr/bin/env bash
# The README's main job on a fresh Debian bookworm machine: install what is missing, build the
# command line alone (the tests and benchmarks are scripts/test.sh's), run the smoke suite (the
# Cornell box: reference, `direct` and `stochastic_radiosity`) and write its results and HTML
# report.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release gibench
build/release/cli/gibench run suites/smoke.toml "$@"
