#!/usr/bin/env bash
# The viewer's frame time without a GPU: the seed playing at 1280x720 under Xvfb on the
# software rasteriser (lavapipe), measured by `stewart view --frame-stats` for SECONDS
# (default 20). Prints the adaptive quality's figures and, beside them, the full picture
# on every frame (STEWART_VIEW_QUALITY=full); exits 1 when the adaptive mean is over
# 33 ms or its 95th percentile over 50 ms. Needs xvfb-run (Debian: xvfb).
# Arguments after SECONDS go to `stewart view` (default `--preset seed`), for example
# `--preset seed --workspace`, or `--scenario big-cad-part.toml`.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
shift || true
view_args=("$@")
[ ${#view_args[@]} -gt 0 ] || view_args=(--preset seed)
command -v xvfb-run >/dev/null || { echo "frame-time: xvfb-run not found (apt-get install xvfb)" >&2; exit 1; }
cargo build --release -q -p stewart_app
S="$PWD/target/release/stewart"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export XDG_RUNTIME_DIR="$dir/run" STEWART_CONFIG_DIR="$dir/config"
mkdir -m 700 "$XDG_RUNTIME_DIR"
# One run: the viewer for $seconds, closed by SIGTERM as by its close button (the
# statistics are printed when the window closes).
measure() {
  STEWART_VIEW_QUALITY="$1" xvfb-run -a -s "-screen 0 1920x1080x24" bash -c '
    S=$0 dir=$1 seconds=$2; shift 2
    "$S" view --fresh --size 1280x720 --frame-stats "$@" 2>"$dir/stats" &
    pid=$!; sleep "$seconds"; kill -TERM "$pid"; wait "$pid"' "$S" "$dir" "$seconds" "${view_args[@]}"
  grep "frames:" "$dir/stats"
}
echo "adaptive (the default):"
adaptive=$(measure adaptive)
echo "  $adaptive"
echo "full picture every frame:"
echo "  $(measure full)"
# "total mean 28.46 ms, 95th percentile 36.51 ms"
read -r mean p95 < <(sed -E 's/.*total mean ([0-9.]+) ms, 95th percentile ([0-9.]+) ms.*/\1 \2/' <<<"$adaptive")
if awk -v m="$mean" -v p="$p95" 'BEGIN { exit !(m <= 33 && p <= 50) }'; then
  echo "adaptive: mean $mean ms <= 33, 95th percentile $p95 ms <= 50: fluid"
else
  echo "adaptive: mean $mean ms or 95th percentile $p95 ms over 33 / 50 ms" >&2
  exit 1
fi
