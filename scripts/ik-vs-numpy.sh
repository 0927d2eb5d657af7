#!/usr/bin/env bash
# Batch inverse kinematics against numpy, side by side in one run on this machine: the
# criterion benchmark `inverse_kinematics/batch_parallel_1M` (1 M poses, all cores) and
# numpy's closed form on the same poses (scripts/peer-ik-numpy.py). Needs numpy
# (pip install numpy; PYTHON=path/to/python picks the interpreter).
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHON="${PYTHON:-python3}"
ours=$(cargo bench -q -p stewart_kinematics --bench inverse_batch -- 'inverse_kinematics/batch_parallel_1M' 2>/dev/null \
  | awk '/thrpt:/ {print $4; exit}')
peer_line=$("$PYTHON" scripts/peer-ik-numpy.py)
peer=$(echo "$peer_line" | awk '{print $3}')
echo "stewart (batch_parallel_1M): $ours M poses/s"
echo "$peer_line"
echo "ratio: $(echo "scale=1; $ours / $peer" | bc)×"
