#!/usr/bin/env bash
# Input speed, end to end: `solve --poses` and `fk --legs` on tables of 100 k and 1 M rows
# (targets for 1 M rows on a 2-core machine: solve under 5 s and 500 MB, fk under 10 s).
# The tables are the paired preset's own motion, sampled that finely, so every row is a
# reachable pose; time and peak memory come from GNU time.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q
S=target/release/stewart
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for rows in ${ROWS:-100000 1000000}; do
  "$S" solve --preset paired --set trajectory.samples="$rows" --out "$dir/table.csv"
  echo "$rows rows ($(du -h "$dir/table.csv" | cut -f1)):"
  /usr/bin/time -f "  solve --poses  %e s, peak %M KB" \
    "$S" solve --preset paired --poses "$dir/table.csv" --out "$dir/solved.csv"
  /usr/bin/time -f "  fk --legs      %e s, peak %M KB" \
    "$S" fk --preset paired --legs "$dir/table.csv" --out "$dir/poses.csv"
done
