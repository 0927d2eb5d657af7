#!/usr/bin/env python3
"""The peer of the batch inverse-kinematics benchmark: the seed platform's leg lengths for
1 M poses in numpy's closed form (vectorised over poses, as a numpy user writes it), on
the same spread of poses as `cargo bench -p stewart_kinematics --bench inverse_batch`.
Prints the best of five runs in poses per second. Needs numpy (pip install numpy).
"""
import math
import time

import numpy as np

N = 1_000_000
# The seed: base joints on a 1 m circle at 0, 60, …, platform joints on a 0.6 m circle at
# 30, 90, …; pivot at the platform centre.
base_deg = np.array([0, 60, 120, 180, 240, 300], dtype=float)
plat_deg = base_deg + 30.0
b = np.stack([np.cos(np.radians(base_deg)), np.sin(np.radians(base_deg)), np.zeros(6)], axis=1)
a = 0.6 * np.stack([np.cos(np.radians(plat_deg)), np.sin(np.radians(plat_deg)), np.zeros(6)], axis=1)

t = np.arange(N) * 1e-3
x = 0.15 * np.sin(1.3 * t)
y = 0.15 * np.cos(0.7 * t)
z = 0.8 + 0.08 * np.sin(0.5 * t)
roll = np.radians(6.0 * np.sin(0.9 * t))
pitch = np.radians(4.0 * np.cos(1.1 * t))
yaw = np.radians(8.0 * np.sin(0.3 * t))


def legs():
    sr, cr = np.sin(roll), np.cos(roll)
    sp, cp = np.sin(pitch), np.cos(pitch)
    sy, cy = np.sin(yaw), np.cos(yaw)
    # Rows of R = Rz(yaw) Ry(pitch) Rx(roll), each (N, 1) against the joints' (6,):
    # leg_i = p + R a_i - b_i, component by component, (N, 6) each.
    ax, ay = a[:, 0], a[:, 1]  # the seed's platform joints lie at z = 0
    lx = x[:, None] + (cy * cp)[:, None] * ax + (cy * sp * sr - sy * cr)[:, None] * ay - b[:, 0]
    ly = y[:, None] + (sy * cp)[:, None] * ax + (sy * sp * sr + cy * cr)[:, None] * ay - b[:, 1]
    lz = z[:, None] + (-sp)[:, None] * ax + (cp * sr)[:, None] * ay
    return np.sqrt(lx * lx + ly * ly + lz * lz)


best = math.inf
for _ in range(5):
    start = time.perf_counter()
    lengths = legs()
    best = min(best, time.perf_counter() - start)
print(f"numpy {np.__version__}: {N / best / 1e6:.2f} M poses/s (best of 5: {best * 1e3:.1f} ms for {N} poses; "
      f"first lengths {lengths[0, 0]:.6f} m)")
