#!/usr/bin/env python3
"""The Python package's batch inverse kinematics on the poses of the Rust benchmark
(`inverse_kinematics/batch_parallel_1M`: the seed platform, 1 M poses), best of seven,
into a new array and into `out=`; then numpy's closed form (scripts/peer-ik-numpy.py's
formula) on the same poses in the same run, and that both agree. Needs the `stewart`
package and numpy in the interpreter that runs it.
"""
import math
import time

import numpy as np

import stewart

N = 1_000_000
t = np.arange(N) * 1e-3
poses = np.column_stack(
    [
        0.15 * np.sin(1.3 * t),
        0.15 * np.cos(0.7 * t),
        0.8 + 0.08 * np.sin(0.5 * t),
        6.0 * np.sin(0.9 * t),
        4.0 * np.cos(1.1 * t),
        8.0 * np.sin(0.3 * t),
    ]
)
p = stewart.Platform.preset("seed")


def best_of(run, times=7):
    run()
    best = math.inf
    for _ in range(times):
        start = time.perf_counter()
        run()
        best = min(best, time.perf_counter() - start)
    return best


out = np.empty((N, 6))
fresh = best_of(lambda: p.ik(poses))
into = best_of(lambda: p.ik(poses, out=out))

base_deg = np.array([0, 60, 120, 180, 240, 300], dtype=float)
b = np.stack([np.cos(np.radians(base_deg)), np.sin(np.radians(base_deg)), np.zeros(6)], axis=1)
a = 0.6 * np.stack([np.cos(np.radians(base_deg + 30)), np.sin(np.radians(base_deg + 30)), np.zeros(6)], axis=1)


def closed_form():
    x, y, z = poses[:, 0], poses[:, 1], poses[:, 2]
    roll, pitch, yaw = (np.radians(poses[:, k]) for k in (3, 4, 5))
    sr, cr, sp, cp, sy, cy = np.sin(roll), np.cos(roll), np.sin(pitch), np.cos(pitch), np.sin(yaw), np.cos(yaw)
    ax, ay = a[:, 0], a[:, 1]
    lx = x[:, None] + (cy * cp)[:, None] * ax + (cy * sp * sr - sy * cr)[:, None] * ay - b[:, 0]
    ly = y[:, None] + (sy * cp)[:, None] * ax + (sy * sp * sr + cy * cr)[:, None] * ay - b[:, 1]
    lz = z[:, None] + (-sp)[:, None] * ax + (cp * sr)[:, None] * ay
    return np.sqrt(lx * lx + ly * ly + lz * lz)


numpy_time = best_of(closed_form, 5)
gap = np.max(np.abs(closed_form() - out))
print(f"stewart.Platform.ik, new array: {N / fresh / 1e6:.1f} M poses/s ({fresh * 1e3:.1f} ms)")
print(f"stewart.Platform.ik, out=:      {N / into / 1e6:.1f} M poses/s ({into * 1e3:.1f} ms)")
print(f"numpy {np.__version__} closed form: {N / numpy_time / 1e6:.2f} M poses/s ({numpy_time * 1e3:.1f} ms); largest difference {gap:.1e} m")
