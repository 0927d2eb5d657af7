#!/usr/bin/env python3
"""docs/cue-step.svg: the translational channel's response to a step of specific force,
as `stewart cue` computes it, beside the closed form computed here independently.

A vehicle at rest feels 1 m/s² forward from t = 0 for 8 s. With translation_scale = 1,
tilt off and the default high-passes (ω = 2.5 rad/s, ζ = 1, ω_b = 0.5 rad/s) the platform
moves x(t) = L⁻¹{1/((s+ω)²(s+ω_b))} = (e^{−ω_b t} − e^{−ω t})/(ω−ω_b)² − t e^{−ω t}/(ω−ω_b).
Usage: python3 scripts/cue-step-figure.py [path/to/stewart] (default target/release/stewart).
"""
import math
import os
import subprocess
import sys
import tempfile

stewart = sys.argv[1] if len(sys.argv) > 1 else "target/release/stewart"
w, wb = 2.5, 0.5
with tempfile.TemporaryDirectory() as d:
    vehicle = os.path.join(d, "step.csv")
    with open(vehicle, "w") as f:
        f.write("t,ax,ay,az,wx,wy,wz\n")
        for k in range(0, 401):
            f.write(f"{k * 0.02:.2f},1,0,0,0,0,0\n")
    out = subprocess.run(
        [stewart, "cue", "--preset", "seed", "--input", vehicle,
         "--set", "cueing.translation_scale=1", "--set", "cueing.tilt=false"],
        check=True, capture_output=True, text=True).stdout
rows = [list(map(float, line.split(","))) for line in out.strip().split("\n")[1:]]
t = [r[0] for r in rows]
x = [r[1] for r in rows]

def exact(s):
    return (math.exp(-wb * s) - math.exp(-w * s)) / (w - wb) ** 2 - s * math.exp(-w * s) / (w - wb)

worst = max(abs(a - exact(s)) for s, a in zip(t, x))
W, H, L, R, T, B = 680, 380, 70, 20, 40, 55
xmax, ymin, ymax = 8.0, -0.02, 0.12
px = lambda s: L + (W - L - R) * s / xmax
py = lambda v: T + (H - T - B) * (ymax - v) / (ymax - ymin)
svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" font-family="DejaVu Sans, Arial, sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>',
       f'<text x="{L}" y="22" font-size="13" font-weight="bold">Step of 1 m/s² forward: platform x (m)</text>']
for k in range(0, 9):
    s = float(k)
    svg.append(f'<line x1="{px(s):.1f}" y1="{T}" x2="{px(s):.1f}" y2="{H - B}" stroke="#e6e6e6"/>')
    svg.append(f'<text x="{px(s):.1f}" y="{H - B + 16}" text-anchor="middle">{k}</text>')
for k in range(-1, 7):
    v = 0.02 * k
    svg.append(f'<line x1="{L}" y1="{py(v):.1f}" x2="{W - R}" y2="{py(v):.1f}" stroke="#e6e6e6"/>')
    svg.append(f'<text x="{L - 6}" y="{py(v) + 4:.1f}" text-anchor="end">{v:.2f}</text>')
svg.append(f'<line x1="{L}" y1="{py(0):.1f}" x2="{W - R}" y2="{py(0):.1f}" stroke="#888"/>')
svg.append(f'<text x="{(L + W - R) / 2}" y="{H - 14}" text-anchor="middle">time (s)</text>')
line = " ".join(f"{px(s):.2f},{py(exact(s)):.2f}" for s in [i * 0.01 for i in range(0, 801)])
svg.append(f'<polyline points="{line}" fill="none" stroke="#0072B2" stroke-width="2"/>')
for s, a in list(zip(t, x))[::8]:
    svg.append(f'<circle cx="{px(s):.2f}" cy="{py(a):.2f}" r="3" fill="none" stroke="#D55E00" stroke-width="1.5"/>')
lx, ly = W - R - 300, T + 12
svg.append(f'<line x1="{lx}" y1="{ly}" x2="{lx + 24}" y2="{ly}" stroke="#0072B2" stroke-width="2"/>')
svg.append(f'<text x="{lx + 30}" y="{ly + 4}">closed form L⁻¹{{1/((s+ω)²(s+ω_b))}}</text>')
svg.append(f'<circle cx="{lx + 12}" cy="{ly + 20}" r="3" fill="none" stroke="#D55E00" stroke-width="1.5"/>')
svg.append(f'<text x="{lx + 30}" y="{ly + 24}">stewart cue (every 8th sample)</text>')
svg.append(f'<text x="{lx + 30}" y="{ly + 42}" fill="#555">largest difference {worst:.1e} m</text>')
svg.append('</svg>')
os.makedirs("docs", exist_ok=True)
with open("docs/cue-step.svg", "w") as f:
    f.write("\n".join(svg) + "\n")
print(f"docs/cue-step.svg: {len(t)} samples, largest difference from the closed form {worst:.2e} m, peak {max(x):.4f} m")
