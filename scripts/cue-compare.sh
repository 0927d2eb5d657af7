#!/usr/bin/env bash
# Both cueing algorithms on the four recordings of examples/cueing/, for the seed and the
# paired presets at their default strokes: `stewart cue --compare` (the washout with its
# workspace limiter on, the model-predictive cueing with and without its look-ahead), then
# every planner cue through `stewart check` (stroke, leg speed and acceleration, joint
# cones, leg clearance), and the time of `stewart cue` on ten minutes of 100 Hz input.
# Writes the table to docs/cueing-comparison.md (or to $1).
#
#   bash scripts/cue-compare.sh
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/cueing-comparison.md}
cargo build --release -q -p stewart_app
stewart=target/release/stewart
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

recordings=(braking-step multisine-surge-sway slalom-yaw launch-and-brake)
for preset in seed paired; do
    for r in "${recordings[@]}"; do
        for preview in true false; do
            "$stewart" cue --preset "$preset" --input "examples/cueing/$r.csv" --compare \
                --format json --set "cueing.mpc_preview=$preview" \
                >"$work/$preset-$r-$preview.json"
        done
        # The planner's poses (with its look-ahead), checked against every limit.
        "$stewart" settings --preset "$preset" --as-coordinates --out "$work/$preset.toml"
        "$stewart" cue --preset "$preset" --input "examples/cueing/$r.csv" \
            --set cueing.algorithm=mpc --out "$work/$preset-$r-poses.csv" 2>/dev/null
        python3 - "$work/$preset.toml" "$preset-$r-poses.csv" "$work/$preset-$r-check.toml" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
# The scenario's own motion replaced by the cue's pose table.
text = re.sub(r"(?ms)^\[trajectory[^\n]*\n.*?(?=^\[|\Z)", "", text)
text += '\n[trajectory]\nkind = "pose_table"\nfile = "%s"\n' % sys.argv[2]
open(sys.argv[3], "w").write(text)
PY
        "$stewart" check --scenario "$work/$preset-$r-check.toml" --format json \
            >"$work/$preset-$r-check.json" || true
        # The seed's layout is singular everywhere (its own motion's check says so too):
        # every other finding is the cue's.
        python3 - "$work/$preset-$r-check.json" >"$work/$preset-$r-check.txt" <<'PY'
import json, sys
kinds = [f["kind"] for f in json.load(open(sys.argv[1]))["findings"]]
own = [k for k in kinds if k != "architecture_singular"]
print("clean" + (" (the layout's own singularity aside)" if kinds else "") if not own else "FOUND: " + ", ".join(own))
PY
    done
done

# Ten minutes of 100 Hz input: the multisine ten times over.
python3 - "$work/ten-minutes.csv" <<'PY'
import sys
rows = open("examples/cueing/multisine-surge-sway.csv").read().splitlines()
out = [rows[0]]
for lap in range(10):
    for line in rows[1 + (lap > 0):]:
        t, rest = line.split(",", 1)
        out.append("%.2f,%s" % (float(t) + 60 * lap, rest))
open(sys.argv[1], "w").write("\n".join(out) + "\n")
PY
start=$(date +%s.%N)
"$stewart" cue --preset seed --input "$work/ten-minutes.csv" --set cueing.algorithm=mpc \
    >/dev/null 2>&1
end=$(date +%s.%N)
seconds=$(python3 -c "print('%.1f' % ($end - $start))")

python3 - "$work" "$out" "$seconds" <<'PY'
import json, sys
work, out, seconds = sys.argv[1], sys.argv[2], sys.argv[3]
recordings = ["braking-step", "multisine-surge-sway", "slalom-yaw", "launch-and-brake"]
lines = [
    "# Model-predictive cueing against the classical washout",
    "",
    "Made by `bash scripts/cue-compare.sh` (`stewart cue --compare` on each recording of",
    "[`examples/cueing/`](../examples/cueing/), both presets at their default strokes and",
    "limits, the default `[cueing]` table: scale 0.5, tilt rate 3 °/s). The washout runs with",
    "its workspace limiter on. *MPC* is the planner as `stewart cue` runs it on a recording,",
    "looking ahead through it (`mpc_preview = true`); *MPC live* holds the last sample over",
    "its horizon, as it must on a live input. Felt quantities are computed from the poses",
    "alone, the same way for every algorithm (see `analysis::cueing::compare`).",
    "",
]
for preset in ["seed", "paired"]:
    lines += [f"## `{preset}`", "",
              "| recording | force RMSE x+y, m/s²: washout | MPC | change | MPC live | change | correlation x / y: washout | MPC | false tilt rate °/s: washout | MPC | MPC live | stroke used: washout | MPC | limiter s | planner failed / stops | `stewart check` of the MPC cue |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in recordings:
        d = json.load(open(f"{work}/{preset}-{r}-true.json"))
        live = json.load(open(f"{work}/{preset}-{r}-false.json"))["mpc"]
        w, m = d["washout"], d["mpc"]
        check = open(f"{work}/{preset}-{r}-check.txt").read().strip()
        def corr(c):
            return " / ".join("—" if v is None else "%.2f" % v for v in c["force_correlation"][:2])
        ch = lambda a: "%+.0f %%" % (100 * (a / w["force_rmse_xy_m_s2"] - 1))
        lines.append("| %s | %.3f | %.3f | %s | %.3f | %s | %s | %s | %.2f | %.2f | %.2f | %.0f %% | %.0f %% | %.2f | %d / %d | %s |" % (
            r, w["force_rmse_xy_m_s2"], m["force_rmse_xy_m_s2"], ch(m["force_rmse_xy_m_s2"]),
            live["force_rmse_xy_m_s2"], ch(live["force_rmse_xy_m_s2"]), corr(w), corr(m),
            w["false_tilt_rate_deg_s"], m["false_tilt_rate_deg_s"], live["false_tilt_rate_deg_s"],
            100 * w["stroke_used"], 100 * m["stroke_used"], w["limiter_s"],
            m["failed_solves"], m["stops"], check))
    lines.append("")
lines += [f"Ten minutes of 100 Hz input (the multisine ten times over) cued by the planner on the seed: {seconds} s (`stewart cue`, this machine).", ""]
open(out, "w").write("\n".join(lines))
print("\n".join(lines))
PY
