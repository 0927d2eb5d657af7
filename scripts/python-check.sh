#!/usr/bin/env bash
# The Python package as a user gets it: a clean virtual environment, `pip install
# ./crates/stewart_py` (maturin builds the wheel; numpy and pytest come from PyPI), then
# its pytest suite, which compares it with the `stewart` binary (STEWART_BIN, default the
# workspace's debug build that `cargo test` leaves).
set -euo pipefail
cd "$(dirname "$0")/.."
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
python3 -m venv "$dir/venv"
"$dir/venv/bin/pip" install -q --disable-pip-version-check "./crates/stewart_py[test]"
export STEWART_BIN="${STEWART_BIN:-$PWD/target/debug/stewart}"
[ -x "$STEWART_BIN" ] || cargo build -q -p stewart_app
# From elsewhere, so that the installed package is imported, not the source folder.
(cd "$dir" && "$dir/venv/bin/python" -m pytest -q "$OLDPWD/crates/stewart_py/tests")
