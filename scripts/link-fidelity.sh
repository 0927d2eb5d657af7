#!/usr/bin/env bash
# What the link sends against what `check` approved: the paired preset streamed as a dry
# run (text lines, µm) at 200 Hz and 1 kHz with the default limits, compared with `solve`
# at the same times (the largest difference once armed, before the stop, µm); and the way
# home of the seed preset after its motion (the last home frame against the home values).
#   bash scripts/link-fidelity.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q
S=target/release/stewart
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
$S solve --preset paired > "$tmp/solved.csv"
for rate in 200 1000; do
  $S link --preset paired --dry-run --rate "$rate" --format text 2>/dev/null > "$tmp/sent.txt"
  python3 - "$tmp/solved.csv" "$tmp/sent.txt" "$rate" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
step = float(rows[1]["t"]) - float(rows[0]["t"])
by_k = {round(float(r["t"]) / step): [float(r[f"L{i}"]) * 1e6 for i in range(1, 7)] for r in rows}
worst, n = 0.0, 0
for line in open(sys.argv[2]):
    t, text = line.rstrip("\n").split("\t")
    t = float(t)
    if not text.startswith("S,") or t < 2.5:
        continue  # before the arming ramp is over, or not a set-point
    k = round(t / step)
    if abs(k * step - t) > 1e-9 or k not in by_k:
        continue
    values = [int(v) for v in text.split(",")[2:]]
    worst = max(worst, max(abs(a - b) for a, b in zip(values, by_k[k])))
    n += 1
print(f"paired at {sys.argv[3]} Hz: {n} set-points compared after the ramp, largest difference from solve {worst:.3f} µm")
PY
done
$S link --preset seed --dry-run --rate 200 --format text 2>"$tmp/seed.err" > "$tmp/seed.txt"
python3 - "$tmp/seed.txt" "$tmp/seed.err" <<'PY'
import sys
lines = [l.rstrip("\n").split("\t") for l in open(sys.argv[1])]
first = [int(v) for v in lines[0][1].split(",")[2:]]
homes = [(float(t), [int(v) for v in x.split(",")[2:]]) for t, x in lines if x.startswith("H,")]
t_last, last = homes[-1]
t_stop = next(float(t) for t, x in lines if x.startswith("E,"))
print(f"seed at 200 Hz: way home from {t_stop:.3f} s to {t_last:.3f} s ({t_last - t_stop:.2f} s); last home frame {last} µm, home {first} µm: {max(abs(a - b) for a, b in zip(last, first))} µm apart")
PY
grep -o "last note: [^;]*" "$tmp/seed.err" || true
