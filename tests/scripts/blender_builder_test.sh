#!/usr/bin/env bash
# The Blender builder's mirrors, custom normals and absorbing glass rendered by Cycles against
# closed forms (tests/scripts/blender_builder_test.py says which).
#
#   tests/scripts/blender_builder_test.sh SOURCE_DIR
#
# Exits 77 (skipped) without Blender, unless GIB_REQUIRE_BLENDER=1.
set -euo pipefail
source_dir=$(realpath "$1")
work=$(mktemp -d "${TMPDIR:-/tmp}/gibench-blender-builder-test-XXXXXX")
trap 'rm -rf "$work"' EXIT

blender="${BLENDER:-blender}"
if ! command -v "$blender" >/dev/null; then
  missing="no Blender ('$blender' is not a program; scripts/install-deps.sh installs it)"
  if [ "${GIB_REQUIRE_BLENDER:-0}" = 1 ]; then
    echo "FAIL: GIB_REQUIRE_BLENDER=1 but $missing" >&2
    exit 1
  fi
  echo "SKIPPED: $missing; GIB_REQUIRE_BLENDER=1 makes this a failure"
  exit 77
fi
code=0
"$blender" -b --factory-startup --python-exit-code 3 \
  --python "$source_dir/tests/scripts/blender_builder_test.py" -- "$source_dir" "$work" \
  >"$work/log" 2>&1 || code=$?
grep -E '^(ok|FAIL|PASS)' "$work/log" || true
if [ "$code" -ne 0 ] || ! grep -q '^PASS$' "$work/log"; then
  echo "FAIL: Blender exited with $code; its log:" >&2
  tail -n 30 "$work/log" >&2
  exit 1
fi
