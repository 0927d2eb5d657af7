#!/usr/bin/env bash
# Export speed, side by side in one run on this machine: `stewart render` and the
# matplotlib peer (scripts/peer-export-matplotlib.py) each write the seed trajectory's
# 1001 frames at 1280x720 as PNG files. Needs matplotlib and numpy (pip install
# matplotlib numpy; PYTHON=path/to/python picks the interpreter).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q
PYTHON="${PYTHON:-python3}"
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
target/release/stewart solve --preset seed --out "$dir/poses.csv"
start=$(date +%s.%N)
target/release/stewart render --preset seed --out "$dir/stewart" 2>/dev/null
ours=$(echo "$(date +%s.%N) - $start" | bc)
start=$(date +%s.%N)
"$PYTHON" scripts/peer-export-matplotlib.py "$dir/poses.csv" "$dir/matplotlib"
peer=$(echo "$(date +%s.%N) - $start" | bc)
frames=$(ls "$dir/stewart" | wc -l)
peer_frames=$(ls "$dir/matplotlib" | wc -l)
echo "stewart render:   $frames frames in $ours s ($(du -sh "$dir/stewart" | cut -f1))"
echo "matplotlib (Agg): $peer_frames frames in $peer s ($(du -sh "$dir/matplotlib" | cut -f1))"
echo "ratio: $(echo "scale=2; $peer / $ours" | bc)×"
