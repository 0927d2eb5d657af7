#!/usr/bin/env python3
"""The peer of `stewart render` for export timing: the seed trajectory drawn as a 3-D
Stewart platform with matplotlib (Agg) and written as numbered PNG frames at 1280x720,
the way the MATLAB teaching script's users would do it in Python.

Usage: peer-export-matplotlib.py POSES.csv OUT_FOLDER
POSES.csv is `stewart solve --preset seed` output (t,x,y,z,roll_deg,pitch_deg,yaw_deg,...).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

# The seed geometry (docs/guide/file-format.md, "The model").
R_BASE, R_PLATFORM = 1.0, 0.6
BASE_DEG = [0, 60, 120, 180, 240, 300]
PLATFORM_DEG = [30, 90, 150, 210, 270, 330]


def ring(radius, degrees):
    a = np.radians(degrees)
    return np.stack([radius * np.cos(a), radius * np.sin(a), np.zeros(6)], axis=1)


def rotation(roll, pitch, yaw):
    r, p, y = np.radians([roll, pitch, yaw])
    rz = np.array([[math.cos(y), -math.sin(y), 0], [math.sin(y), math.cos(y), 0], [0, 0, 1]])
    ry = np.array([[math.cos(p), 0, math.sin(p)], [0, 1, 0], [-math.sin(p), 0, math.cos(p)]])
    rx = np.array([[1, 0, 0], [0, math.cos(r), -math.sin(r)], [0, math.sin(r), math.cos(r)]])
    return rz @ ry @ rx


def main():
    poses_csv, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    with open(poses_csv) as f:
        rows = list(csv.DictReader(f))
    base = ring(R_BASE, BASE_DEG)
    platform = ring(R_PLATFORM, PLATFORM_DEG)
    fig = plt.figure(figsize=(12.8, 7.2), dpi=100)
    ax = fig.add_subplot(projection="3d")
    for k, row in enumerate(rows):
        p = np.array([float(row["x"]), float(row["y"]), float(row["z"])])
        rot = rotation(float(row["roll_deg"]), float(row["pitch_deg"]), float(row["yaw_deg"]))
        top = p + platform @ rot.T
        ax.cla()
        ax.add_collection3d(Poly3DCollection([base], facecolor="0.6", alpha=0.5))
        ax.add_collection3d(Poly3DCollection([top], facecolor="tab:red", alpha=0.7))
        for i in range(6):
            ax.plot(*zip(base[i], top[i]), color="tab:blue", linewidth=4)
        ax.scatter(*np.concatenate([base, top]).T, color="0.2", s=30)
        ax.set_xlim(-1.2, 1.2)
        ax.set_ylim(-1.2, 1.2)
        ax.set_zlim(0, 1.2)
        ax.view_init(elev=20, azim=135 - 90)
        fig.savefig(os.path.join(out, f"frame_{k:05d}.png"))
    plt.close(fig)


if __name__ == "__main__":
    main()
