#!/usr/bin/env bash
# `stewart robot`'s MJCF and URDF for every preset and CAD example, checked in MuJoCo and
# yourdfpy from PyPI (tests/robot/check.py says what). Where those packages cannot be
# installed (no network to PyPI), it says so and skips.
#   bash scripts/robot-check.sh [--debug]     (the debug binary, as check.sh runs it)
set -euo pipefail
cd "$(dirname "$0")/.."
profile=release
[ "${1:-}" = "--debug" ] && profile=debug
if [ "$profile" = release ]; then cargo build --release -q -p stewart_app; fi
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
python3 -m venv "$dir/venv"
if ! "$dir/venv/bin/pip" install -q --disable-pip-version-check mujoco yourdfpy numpy >"$dir/pip.log" 2>&1; then
  echo "robot-check: SKIPPED: could not install mujoco and yourdfpy from PyPI:" >&2
  tail -n 3 "$dir/pip.log" >&2
  exit 0
fi
"$dir/venv/bin/python" tests/robot/check.py "target/$profile/stewart"
