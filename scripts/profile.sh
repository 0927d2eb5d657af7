#!/usr/bin/env bash
# Where the CPU time goes, by perf: `scripts/profile.sh solve` profiles `solve --poses`
# on a 1 M-row table (ROWS to change), `scripts/profile.sh export` the seed's 1001 frames
# at 1280x720 to PNG files. Builds the `profiling` profile (release with line tables),
# records with call graphs and prints the hottest symbols, then the share of each
# thread (lavapipe's rasteriser threads are named llvmpipe-N). Needs perf
# (Debian: linux-perf) and a kernel that lets users profile (perf_event_paranoid ≤ 2).
set -euo pipefail
cd "$(dirname "$0")/.."
what="${1:-}"
case "$what" in
  solve|export) ;;
  *) echo "usage: scripts/profile.sh solve|export" >&2; exit 2 ;;
esac
command -v perf >/dev/null || { echo "profile: perf not found (apt-get install linux-perf)" >&2; exit 1; }
cargo build --profile profiling -q -p stewart_app
S="$PWD/target/profiling/stewart"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$dir}"
if [ "$what" = solve ]; then
  "$S" solve --preset paired --set trajectory.samples="${ROWS:-1000000}" --out "$dir/table.csv"
  run=("$S" solve --preset paired --poses "$dir/table.csv" --out "$dir/solved.csv")
else
  run=("$S" render --preset seed --out "$dir/frames")
fi
/usr/bin/time -f "wall %e s, user %U s, system %S s" perf record -q -g -F 999 -o "$dir/perf.data" "${run[@]}" 2>&1 | grep -v "^\[" || true
perf report -i "$dir/perf.data" --no-children --sort dso,sym --stdio -g none 2>/dev/null | grep '%' | head -25
echo "--- by thread"
perf report -i "$dir/perf.data" --no-children --sort comm --stdio -g none 2>/dev/null | grep '%' | head -8
