#!/usr/bin/env bash
# The hostile-input suite (tests/hostile) for longer than CI runs it: many random cases
# per property through the release binary. `HOSTILE_CASES` sets the count (default 1000);
# extra arguments go to the test harness (a test name filters).
set -euo pipefail
cd "$(dirname "$0")/.."
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
HOSTILE_CASES="${HOSTILE_CASES:-1000}" cargo test --release -p stewart_tests --test hostile -- "$@"
