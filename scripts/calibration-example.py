#!/usr/bin/env python3
"""Make the calibration example of docs/guide/analysis.md and tests/cli/calibrate.rs, independently of
the Rust code: a built `paired` platform (its joints moved by up to 4 mm, its legs'
length readings off by up to 3 mm), 60 poses measured with noise (10 µm in position,
0.002° in angle: a laser tracker), and the leg lengths commanded for them.

Writes tests/cli/calibration/paired_measurements.csv and paired_as_built.csv (the truth:
both plates' joints and the offsets). Run from the repository root: python3 scripts/calibration-example.py
"""
import math
import random

BASE = [
    (0.984807753012208, 0.17364817766693033, 0.0),
    (-0.3420201433256687, 0.9396926207859084, 0.0),
    (-0.6427876096865394, 0.766044443118978, 0.0),
    (-0.6427876096865395, -0.7660444431189779, 0.0),
    (-0.34202014332566855, -0.9396926207859084, 0.0),
    (0.984807753012208, -0.1736481776669304, 0.0),
]
PLATFORM = [
    (0.3856725658119236, 0.4596266658713868, 0.0),
    (0.20521208599540128, 0.563815572471545, 0.0),
    (-0.5908846518073247, 0.10418890660015816, 0.0),
    (-0.5908846518073247, -0.10418890660015828, 0.0),
    (0.2052120859954014, -0.563815572471545, 0.0),
    (0.38567256581192355, -0.45962666587138684, 0.0),
]


def rotation(roll, pitch, yaw):
    """Rz(yaw) Ry(pitch) Rx(roll), angles in radians, as rows."""
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ]


def main():
    rng = random.Random(2026)
    moved = lambda p: tuple(v + rng.uniform(-0.004, 0.004) for v in p)
    base = [moved(b) for b in BASE]
    platform = [moved(a) for a in PLATFORM]
    offsets = [rng.uniform(-0.003, 0.003) for _ in range(6)]
    with open("tests/cli/calibration/paired_as_built.csv", "w") as f:
        f.write("leg,bx,by,bz,ax,ay,az,offset\n")
        for i in range(6):
            values = list(base[i]) + list(platform[i]) + [offsets[i]]
            f.write(f"{i + 1}," + ",".join(f"{v:.9f}" for v in values) + "\n")
    with open("tests/cli/calibration/paired_measurements.csv", "w") as f:
        f.write("x,y,z,roll_deg,pitch_deg,yaw_deg,L1,L2,L3,L4,L5,L6\n")
        for _ in range(60):
            pose = [rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), 0.8 + rng.uniform(-0.15, 0.15)]
            angles = [rng.uniform(-15.0, 15.0) for _ in range(3)]
            r = rotation(*(math.radians(a) for a in angles))
            legs = []
            for i in range(6):
                q = [pose[k] + sum(r[k][j] * platform[i][j] for j in range(3)) for k in range(3)]
                length = math.dist(q, base[i])
                legs.append(length - offsets[i])
            measured = [v + rng.gauss(0.0, 10e-6) for v in pose]
            measured += [a + rng.gauss(0.0, 0.002) for a in angles]
            f.write(",".join(f"{v:.6f}" for v in measured) + "," + ",".join(f"{v:.6f}" for v in legs) + "\n")


main()
