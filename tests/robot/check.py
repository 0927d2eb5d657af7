#!/usr/bin/env python3
"""`stewart robot`'s MJCF and URDF checked by the tools their users load them with.

For every preset and CAD example: the studio's own numbers come from `stewart solve`
(poses and actuator values per sample) and `stewart settings` (the pivot); then

- MJCF, in MuJoCo (`mujoco`): the file loads; at every keyframe each rod's far end lies on
  its platform joint and the equality constraints' residuals are at most 1e-9 m; the
  platform body's pose is the studio's to 1e-9 m; the controls are the studio's leg
  lengths (servo angles); driven from home by the studio's actuator values, ramped, with
  gravity off, the platform settles on the studio's pose within 0.1 mm and 0.05 degrees
  (an architecturally singular layout, such as the seed's, is reported, not required to);
- URDF, with `yourdfpy`: the file loads; for every row of the joint-state table each
  `tip{k}` lies on `platform_joint{k}` to 1e-9 m and `platform` is at the studio's pose.

    python3 tests/robot/check.py STEWART_BINARY
"""

import csv
import io
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

EVERY = 7
TOL = 1e-9
SETTLE_M = 1e-4
SETTLE_DEG = 0.05


def run(stewart, *args):
    return subprocess.run([stewart, *args], check=True, capture_output=True, text=True).stdout


def rotation(roll, pitch, yaw):
    """R = Rz(yaw) Ry(pitch) Rx(roll), radians."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch),
                              math.sin(pitch), math.cos(yaw), math.sin(yaw))
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def angle_between(a, b):
    """The angle of the rotation taking b to a, degrees."""
    c = (np.trace(a.T @ b) - 1.0) / 2.0
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


class Studio:
    """What the studio says of one scenario: per sample its time, pose and actuators."""

    def __init__(self, stewart, source):
        text = run(stewart, "solve", *source)
        rows = list(csv.DictReader(io.StringIO(text)))
        self.rotary = "theta1" in rows[0]
        self.times, self.frames, self.actuators = [], [], []
        pivot = [0.0, 0.0, 0.0]
        for line in run(stewart, "settings", *source).splitlines():
            for i in range(3):
                if line.startswith(f"pivot.offset_m[{i}]"):
                    pivot[i] = float(line.split()[1])
        c = np.array(pivot)
        for r in rows:
            p = np.array([float(r["x"]), float(r["y"]), float(r["z"])])
            rot = rotation(*(math.radians(float(r[k])) for k in ("roll_deg", "pitch_deg", "yaw_deg")))
            # The platform frame: where the pose puts it, about the pivot.
            self.frames.append((p + c - rot @ c, rot))
            self.times.append(float(r["t"]))
            if self.rotary:
                self.actuators.append([math.radians(float(r[f"theta{k}"])) for k in range(1, 7)])
            else:
                self.actuators.append([float(r[f"L{k}"]) for k in range(1, 7)])
        report = json.loads(subprocess.run([stewart, "check", *source, "--format", "json"],
                                           capture_output=True, text=True).stdout)
        self.singular = bool(report.get("architecture", {}).get("singular"))


def check_mjcf(mujoco, path, studio, name, failures):
    model = mujoco.MjModel.from_xml_path(path)
    data = mujoco.MjData(model)
    leg = "servo" if studio.rotary else "leg"
    tips = [model.site(f"{leg}{k}_tip").id for k in range(1, 7)]
    joints = [model.site(f"platform_joint{k}").id for k in range(1, 7)]
    platform = model.body("platform").id
    worst = {"loop": 0.0, "residual": 0.0, "pose": 0.0, "ctrl": 0.0}
    if model.nkey != len(range(0, len(studio.times), EVERY)):
        failures.append(f"{name}: {model.nkey} keyframes for {len(studio.times)} samples")
        return
    for key, i in enumerate(range(0, len(studio.times), EVERY)):
        mujoco.mj_resetDataKeyframe(model, data, key)
        mujoco.mj_forward(model, data)
        for t, j in zip(tips, joints):
            worst["loop"] = max(worst["loop"], np.linalg.norm(data.site_xpos[t] - data.site_xpos[j]))
        equality = data.efc_type[: data.nefc] == mujoco.mjtConstraint.mjCNSTR_EQUALITY
        if equality.any():
            worst["residual"] = max(worst["residual"], np.abs(data.efc_pos[: data.nefc][equality]).max())
        centre, rot = studio.frames[i]
        worst["pose"] = max(worst["pose"], np.linalg.norm(data.xpos[platform] - centre),
                            np.abs(data.xmat[platform].reshape(3, 3) - rot).max())
        worst["ctrl"] = max(worst["ctrl"], np.abs(data.ctrl - studio.actuators[i]).max())
        if abs(model.key_time[key] - studio.times[i]) > 1e-12:
            failures.append(f"{name}: keyframe {key} at {model.key_time[key]} s, sample at {studio.times[i]} s")
    for what, value in worst.items():
        if value > TOL:
            failures.append(f"{name}: MJCF keyframes' worst {what} error {value:.3g}")
    print(f"  {name}: MJCF {model.nkey} keyframes, loops {worst['loop']:.1e} m, "
          f"residuals {worst['residual']:.1e} m, pose {worst['pose']:.1e}, ctrl {worst['ctrl']:.1e}")
    settle(mujoco, model, data, studio, name, failures)


def settle(mujoco, model, data, studio, name, failures):
    """From home, the controls ramped to the trajectory's first sample, then played along
    the trajectory (the studio's actuator values, interpolated) to the sample farthest
    from home, then held: the platform must settle on the studio's pose there."""
    home = np.array([model.qpos0[model.jnt_qposadr[model.actuator_trnid[a, 0]]] for a in range(6)])
    values = np.array(studio.actuators)
    far = int(np.abs(values - home).max(axis=1).argmax())
    ramp, hold = 1.0, 3.0
    # The control at each time: the ramp from home, then the trajectory up to `far`.
    times = np.concatenate([[0.0], ramp + np.array(studio.times[: far + 1]) - studio.times[0]])
    controls = np.vstack([home, values[: far + 1]])
    model.opt.gravity[:] = 0.0
    mujoco.mj_resetData(model, data)
    end = times[-1] + hold
    while data.time < end:
        t = data.time
        if t < ramp:
            a = t / ramp
            a = a * a * (3 - 2 * a)
            data.ctrl[:] = home + a * (values[0] - home)
        else:
            data.ctrl[:] = [np.interp(t, times[1:], controls[1:, a]) for a in range(6)]
        mujoco.mj_step(model, data)
    platform = model.body("platform").id
    centre, rot = studio.frames[far]
    metres = np.linalg.norm(data.xpos[platform] - centre)
    degrees = angle_between(data.xmat[platform].reshape(3, 3), rot)
    words = (f"  {name}: driven along the trajectory to t = {studio.times[far]} s and held 3 s, settled "
             f"{metres * 1e3:.2g} mm and {degrees:.2g} deg from the studio's pose")
    if studio.singular:
        legs = np.abs(data.actuator_length - values[far]).max()
        print(words + f", its legs at their lengths to {legs:.1g} m (architecturally singular: "
              "the platform moves where no leg sees it, so nothing holds it there)")
    else:
        print(words)
        if metres > SETTLE_M or degrees > SETTLE_DEG:
            failures.append(words.strip())


def check_urdf(yourdfpy, path, states, studio, name, failures):
    import xml.etree.ElementTree as ET
    meshes = [m.get("filename") for m in ET.parse(path).iter("mesh")]
    for f in meshes:
        if not (f.startswith("file:///") and os.path.isfile(f.removeprefix("file://"))):
            failures.append(f"{name}: URDF mesh {f} is not a file:// URI of an existing file")
    robot = yourdfpy.URDF.load(path, load_meshes=bool(meshes), build_collision_scene_graph=False,
                               load_collision_meshes=False)
    rows = list(csv.DictReader(open(states)))
    keys = list(range(0, len(studio.times), EVERY))
    if len(rows) != len(keys):
        failures.append(f"{name}: {len(rows)} joint-state rows for {len(keys)} samples")
        return
    worst_tip, worst_pose = 0.0, 0.0
    for row, i in zip(rows, keys):
        cfg = {k: float(v) for k, v in row.items() if k != "t"}
        robot.update_cfg(cfg)
        for k in range(1, 7):
            tip = robot.get_transform(f"tip{k}", "base")[:3, 3]
            joint = robot.get_transform(f"platform_joint{k}", "base")[:3, 3]
            worst_tip = max(worst_tip, np.linalg.norm(tip - joint))
        t = robot.get_transform("platform", "base")
        centre, rot = studio.frames[i]
        worst_pose = max(worst_pose, np.linalg.norm(t[:3, 3] - centre), np.abs(t[:3, :3] - rot).max())
        if abs(float(row["t"]) - studio.times[i]) > 1e-12:
            failures.append(f"{name}: joint-state row at {row['t']} s, sample at {studio.times[i]} s")
    if worst_tip > TOL or worst_pose > TOL:
        failures.append(f"{name}: URDF tips {worst_tip:.3g} m off their joints, platform {worst_pose:.3g} off")
    print(f"  {name}: URDF {len(rows)} rows, tips {worst_tip:.1e} m from their platform joints, "
          f"platform pose {worst_pose:.1e}")


def examples(stewart, failures):
    """The guide's two scripts (examples/robot/) on the servo desk: the URDF's tips on
    their joints, and MuJoCo's own picture of the MJCF (offscreen through EGL), which must
    show the platform's blue."""
    here = os.path.dirname(os.path.abspath(__file__))
    scripts = os.path.join(here, "..", "..", "examples", "robot")
    with tempfile.TemporaryDirectory() as out:
        urdf, states, xml, png = (os.path.join(out, n) for n in ("r.urdf", "r.csv", "r.xml", "r.png"))
        run(stewart, "robot", "--preset", "servo-desk", "--format", "urdf", "--out", urdf, "--joint-states", states)
        said = subprocess.run([sys.executable, os.path.join(scripts, "urdf_states.py"), urdf, states],
                              check=True, capture_output=True, text=True).stdout
        gap = float(said.split("within ")[1].split(" m")[0])
        print("  examples/robot/urdf_states.py: " + said.splitlines()[0])
        if gap > TOL:
            failures.append(f"urdf_states.py: {said}")
        run(stewart, "robot", "--preset", "servo-desk", "--format", "mjcf", "--out", xml, "--every", "25")
        env = dict(os.environ, MUJOCO_GL=os.environ.get("MUJOCO_GL", "egl"))
        subprocess.run([sys.executable, os.path.join(scripts, "mujoco_picture.py"), xml, png, "5"],
                       check=True, capture_output=True, text=True, env=env)
        blue = blue_share(png)
        print(f"  examples/robot/mujoco_picture.py: MuJoCo's picture, {blue:.1%} of it the platform's blue")
        if blue < 0.01:
            failures.append(f"mujoco_picture.py: the picture shows no platform ({blue:.1%} blue)")


def blue_share(path):
    """The share of an 8-bit RGB PNG's pixels (as mujoco_picture.py writes them) that are
    the platform's blue."""
    import struct
    import zlib
    data = open(path, "rb").read()
    width, height = struct.unpack(">II", data[16:24])
    at, idat = 8, b""
    while at < len(data):
        (length,) = struct.unpack(">I", data[at:at + 4])
        if data[at + 4:at + 8] == b"IDAT":
            idat += data[at + 8:at + 8 + length]
        at += 12 + length
    raw = np.frombuffer(zlib.decompress(idat), dtype=np.uint8).reshape(height, 1 + 3 * width)
    rgb = raw[:, 1:].reshape(height, width, 3).astype(int)
    blue = (rgb[..., 2] > rgb[..., 0] + 60) & (rgb[..., 2] > 120)
    return blue.mean()


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    stewart = os.path.abspath(sys.argv[1])
    import mujoco
    import yourdfpy
    presets = run(stewart, "robot", "--help").split("A shipped preset: ")[1].split("\n")[0]
    sources = [("--preset", p.strip(" .")) for p in presets.split(",")]
    sources += [("--scenario", "examples/cad/seed-cad.toml"), ("--scenario", "examples/cad/servo-cad.toml")]
    failures = []
    with tempfile.TemporaryDirectory() as out:
        for source in sources:
            name = os.path.basename(source[1]).removesuffix(".toml")
            studio = Studio(stewart, source)
            xml, urdf, states = (os.path.join(out, f"{name}.{e}") for e in ("xml", "urdf", "csv"))
            every = ("--every", str(EVERY))
            run(stewart, "robot", *source, "--format", "mjcf", "--out", xml, *every)
            run(stewart, "robot", *source, "--format", "urdf", "--out", urdf, "--joint-states", states, *every)
            check_mjcf(mujoco, xml, studio, name, failures)
            check_urdf(yourdfpy, urdf, states, studio, name, failures)
    examples(stewart, failures)
    if failures:
        print("robot-check: FAILED\n" + "\n".join(failures))
        sys.exit(1)
    print(f"robot-check: {len(sources)} scenarios, MJCF in MuJoCo {mujoco.__version__} and URDF in yourdfpy: all within limits")


if __name__ == "__main__":
    main()
