#!/usr/bin/env bash
# Installs every Debian (bookworm) package GI Bench needs to build, test and run.
# Idempotent and non-interactive: packages already present are left alone, and
# `apt-get update` runs once, only when something is missing.
set -euo pipefail

packages=(
  # Toolchain
  build-essential cmake ninja-build pkg-config git clang-format python3
  # The sanitizer build (asan preset) and the fuzz targets: clang with its sanitizer and libFuzzer
  # runtimes
  clang libclang-rt-14-dev
  # Reference renderer
  libembree-dev libtbb-dev
  # Images and colour
  libopenimageio-dev openimageio-tools libopenexr-dev libopencolorio-dev
  # Maths, formats, command line
  libglm-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev libfmt-dev libtinyobjloader-dev libxxhash-dev
  # History database
  libsqlite3-dev
  # Headless OpenGL through EGL (GLVND) and Mesa's software rasterizer
  libegl-dev libopengl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  # Tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # Report tests: headless browser; xmllint validates the JUnit output against its schema
  chromium libxml2-utils
  # The cross-check against Cycles (scripts/cross-check-cycles.sh) and its test
  blender
  # Suites on Slurm (gibench run --slurm): the client, and a one-node cluster for the tests
  # (scripts/slurm-local.sh)
  slurm-client slurmctld slurmd munge
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present" >&2
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
