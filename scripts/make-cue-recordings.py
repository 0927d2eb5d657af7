#!/usr/bin/env python3
"""Make the vehicle-motion recordings of examples/cueing/, inputs for
`stewart cue --input FILE` (motion cueing by classical washout).
Python 3 standard library only, no randomness: the files come out the same, byte for byte,
on every run. Run from the repository root: python3 scripts/make-cue-recordings.py

Each file is the CSV that crates/stewart_app/src/vehicle_in/table.rs reads: the header
`t,ax,ay,az,wx,wy,wz`, then one row every 10 ms (100 Hz) from t = 0 to the end inclusive.
t in seconds; ax, ay, az the vehicle's specific force along its own x (forward), y (left),
z (up), in m/s², gravity excluded; wx, wy, wz its rotation rates about those axes in degrees
per second (right-handed: +wx rolls the right side down, +wy pitches the nose down, +wz yaws
to the left). A smooth step below is a raised cosine, 0.5 - 0.5 cos(pi u) for u in 0..1.

  braking-step.csv           12 s. At rest 1 s; braking: ax ramps to -6 m/s^2 over 0.15 s,
                             is held 3 s and released to 0 over 0.3 s (the car has stopped);
                             at rest to the end. The body pitches 1 deg nose down over 0.3 s
                             at the onset and back over 0.3 s at the release (wy blips of
                             +-5.2 deg/s peak).
  multisine-surge-sway.csv   60 s. ax and ay each a sum of 8 equal sines, Schroeder phases,
                             frequencies spread log-uniformly over 0.1 .. 2 Hz (16 in all,
                             alternately to ax and ay, each rounded to a multiple of 1/60 Hz
                             so it runs whole cycles), each axis scaled to an RMS of 1.5 m/s^2
                             before a 2 s fade in and out at the ends; az and the rates 0.
  slalom-yaw.csv             40 s. A car at 15 m/s through a slalom: wz = 25 deg/s sin(2 pi 0.5 t),
                             ay = v wz (wz in rad/s, peak 6.54 m/s^2), the body rolling
                             0.03 rad * ay / peak (outward) with wx its exact derivative; all
                             under a 2 s fade in and out; ax, az, wy 0.
  launch-and-brake.csv       30 s. At rest 1 s; launch: ax rises to +4 m/s^2 over 0.3 s, then
                             4 exp(-s/3) (s from the end of the rise) tapered smoothly to 0
                             over s = 6 .. 8 s; cruise 4 s; braking: ax to -7 m/s^2 over
                             0.2 s, held 3.5 s, released over 0.2 s; at rest to the end.
"""
import math
import os

RATE_HZ = 100
OUT_DIR = os.path.join("examples", "cueing")
COLUMNS = ("t", "ax", "ay", "az", "wx", "wy", "wz")
DEG = 180.0 / math.pi


def num(v, decimals=6):
    """A value in fixed point, at most `decimals` decimals, trailing zeros dropped."""
    text = f"{v:.{decimals}f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def smooth(u):
    """The raised-cosine step: 0 for u <= 0, 1 for u >= 1."""
    if u <= 0.0:
        return 0.0
    if u >= 1.0:
        return 1.0
    return 0.5 - 0.5 * math.cos(math.pi * u)


def smooth_rate(u, width):
    """d/dt of smooth((t - t0) / width)."""
    if u <= 0.0 or u >= 1.0:
        return 0.0
    return 0.5 * math.pi / width * math.sin(math.pi * u)


def pulse(t, start, rise, hold, fall):
    """0 before `start`, a smooth rise over `rise` s to 1, held `hold` s, a smooth fall over
    `fall` s back to 0."""
    up = smooth((t - start) / rise)
    down = smooth((t - start - rise - hold) / fall)
    return up - down


def fade(t, duration, width=2.0):
    """The envelope fading in over the first `width` s and out over the last, and its
    time derivative."""
    if t < width:
        return smooth(t / width), smooth_rate(t / width, width)
    if t > duration - width:
        u = (duration - t) / width
        return smooth(u), -smooth_rate(u, width)
    return 1.0, 0.0


def write(name, duration, sample):
    """Write `name`: one row per sample of `sample(t) -> (ax, ay, az, wx, wy, wz)`."""
    n = round(duration * RATE_HZ)
    lines = [",".join(COLUMNS)]
    for k in range(n + 1):
        t = k / RATE_HZ
        lines.append(",".join([num(t, 2)] + [num(v) for v in sample(t)]))
    path = os.path.join(OUT_DIR, name)
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    return path


def braking_step(t):
    onset, rise, hold, release = 1.0, 0.15, 3.0, 0.3
    ax = -6.0 * pulse(t, onset, rise, hold, release)
    # The dive: 1 deg nose down over 0.3 s from the onset, back over 0.3 s from the release.
    dive_deg, dive_s = 1.0, 0.3
    released = onset + rise + hold
    wy = dive_deg * (smooth_rate((t - onset) / dive_s, dive_s)
                     - smooth_rate((t - released) / dive_s, dive_s))
    return ax, 0.0, 0.0, 0.0, wy, 0.0


def multisine_components(duration, count=8, f_lo=0.1, f_hi=2.0, rms=1.5):
    """Two lists of (amplitude, frequency, phase), for ax and ay."""
    total = 2 * count
    grid = 1.0 / duration
    freqs = [round(f_lo * (f_hi / f_lo) ** (i / (total - 1)) / grid) * grid
             for i in range(total)]
    assert len(set(round(f / grid) for f in freqs)) == total, "frequencies collide"
    amplitude = rms / math.sqrt(count / 2.0)
    axes = []
    for offset in (0, 1):
        mine = freqs[offset::2]
        # Schroeder's phases for equal amplitudes: -pi k (k - 1) / N, k = 1 .. N.
        axes.append([(amplitude, f, -math.pi * k * (k - 1) / count)
                     for k, f in enumerate(mine, start=1)])
    return axes


MULTISINE_S = 60.0
MULTISINE = multisine_components(MULTISINE_S)


def multisine(t):
    env, _ = fade(t, MULTISINE_S)
    ax, ay = (env * sum(a * math.sin(2.0 * math.pi * f * t + p) for a, f, p in comps)
              for comps in MULTISINE)
    return ax, ay, 0.0, 0.0, 0.0, 0.0


SLALOM_S = 40.0


def slalom(t, v=15.0, f=0.5, yaw_deg_s=25.0, roll_rad=0.03):
    env, env_rate = fade(t, SLALOM_S)
    w = 2.0 * math.pi * f
    s, c = math.sin(w * t), math.cos(w * t)
    wz = yaw_deg_s * env * s
    ay = v * wz / DEG
    # Roll angle roll_rad * ay / peak = roll_rad * env * s; its exact derivative.
    wx = roll_rad * (env_rate * s + env * w * c) * DEG
    return 0.0, ay, 0.0, wx, 0.0, wz


def launch_and_brake(t):
    start, rise, peak, tau = 1.0, 0.3, 4.0, 3.0
    taper_from, taper_to = 6.0, 8.0
    s = t - start - rise
    if t < start + rise:
        ax = peak * smooth((t - start) / rise)
    else:
        ax = peak * math.exp(-s / tau) * (1.0 - smooth((s - taper_from) / (taper_to - taper_from)))
    launch_end = start + rise + taper_to
    brake_start = launch_end + 4.0
    ax += -7.0 * pulse(t, brake_start, 0.2, 3.5, 0.2)
    return ax, 0.0, 0.0, 0.0, 0.0, 0.0


def main():
    os.makedirs(OUT_DIR, exist_ok=True)
    for name, duration, sample in (
        ("braking-step.csv", 12.0, braking_step),
        ("multisine-surge-sway.csv", MULTISINE_S, multisine),
        ("slalom-yaw.csv", SLALOM_S, slalom),
        ("launch-and-brake.csv", 30.0, launch_and_brake),
    ):
        print(write(name, duration, sample))


if __name__ == "__main__":
    main()
