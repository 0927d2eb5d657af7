#!/usr/bin/env bash
# The Python package's batch against the Rust batch and numpy, side by side in one run:
# criterion's `inverse_kinematics/batch_parallel_1M` (into its buffer, and into a new Vec
# each time), then scripts/peer-ik-python.py
# (p.ik on the same 1 M poses, new array and out=, and numpy's closed form). Builds the
# package into .venv (scripts/setup.sh makes it).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x .venv/bin/python ] || bash scripts/setup.sh
.venv/bin/pip install -q --disable-pip-version-check ./crates/stewart_py
bench=$(cargo bench -q -p stewart_kinematics --bench inverse_batch -- 'inverse_kinematics/batch_parallel_1M' 2>/dev/null)
rust=$(echo "$bench" | awk '/batch_parallel_1M / || /batch_parallel_1M$/ {want=1} want && /time:/ {print $4; exit}')
fresh=$(echo "$bench" | awk '/new_output/ {want=1} want && /time:/ {print $4; exit}')
echo "Rust batch into its buffer (batch_parallel_1M): $rust ms"
echo "Rust batch into a new Vec (batch_parallel_1M_new_output): $fresh ms"
.venv/bin/python scripts/peer-ik-python.py
