#!/usr/bin/env bash
# The set-point sender's timing: period error and wake-up lateness (mean, p99, max) at
# 500 Hz and 1 kHz over UDP loopback, first on an idle machine, then while the viewer
# renders the seed platform continuously (under Xvfb, on the software GPU). The viewer's
# CPU use during the second run is printed to show it was busy.
#   SECONDS_PER_RATE=10 bash scripts/bench-link.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q
S=target/release/stewart
SECS=${SECONDS_PER_RATE:-10}
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
echo "# idle machine"
$S link --bench --duration "$SECS"
echo "# while the viewer renders (1280x720, seed preset playing)"
shot=$(mktemp --suffix=.png)
xvfb-run -a -s "-screen 0 1600x900x24" $S view --preset seed --size 1280x720 \
  --screenshot "$shot" --frames 100000 >/dev/null 2>&1 &
runner=$!
sleep 6
viewer=$(pgrep -n -f "stewart view --preset seed" || true)
[ -n "$viewer" ] || { echo "the viewer did not start" >&2; kill $runner 2>/dev/null; exit 1; }
ticks=$(getconf CLK_TCK)
cpu_before=$(awk '{print $14+$15}' /proc/$viewer/stat)
t0=$(date +%s.%N)
$S link --bench --duration "$SECS"
t1=$(date +%s.%N)
cpu_after=$(awk '{print $14+$15}' /proc/$viewer/stat)
kill "$viewer" 2>/dev/null || true
wait $runner 2>/dev/null || true
rm -f "$shot"
awk -v a="$cpu_before" -v b="$cpu_after" -v t0="$t0" -v t1="$t1" -v hz="$ticks" -v n="$(nproc)" \
  'BEGIN { printf "# the viewer used %.0f%% of one core on average (%d cores) during the run\n", 100*(b-a)/hz/(t1-t0), n }'
