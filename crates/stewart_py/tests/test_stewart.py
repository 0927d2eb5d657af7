"""The Python package against the command line (to the bit), identities of its own, and
its refusals. The `stewart` binary is STEWART_BIN, or the workspace's target/release or
target/debug build."""

import csv
import io
import json
import os
import subprocess
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import stewart

ROOT = Path(__file__).resolve().parents[3]


def binary() -> str:
    given = os.environ.get("STEWART_BIN")
    if given:
        return given
    for build in ("release", "debug"):
        path = ROOT / "target" / build / "stewart"
        if path.exists():
            return str(path)
    raise RuntimeError("no stewart binary: build it (cargo build -p stewart_app) or set STEWART_BIN")


def cli(*args: str) -> str:
    done = subprocess.run([binary(), *args], capture_output=True, text=True, env={**os.environ, "LANG": "C.UTF-8"})
    assert done.returncode == 0, done.stderr
    return done.stdout


def columns(text: str, names) -> np.ndarray:
    rows = list(csv.DictReader(io.StringIO(text)))
    return np.array([[float(r[n]) for n in names] for r in rows])


def random_poses(n: int, z: float, reach: float, tilt: float, seed: int = 1) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return np.column_stack(
        [
            rng.uniform(-reach, reach, n),
            rng.uniform(-reach, reach, n),
            z + rng.uniform(-reach, reach, n),
            rng.uniform(-tilt, tilt, (n, 3)),
        ]
    )


def pose_csv(path: Path, poses: np.ndarray) -> None:
    # repr: the shortest text that reads back to the same float.
    lines = ["x,y,z,roll_deg,pitch_deg,yaw_deg"] + [",".join(repr(float(v)) for v in row) for row in poses]
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize(
    "preset,z,reach,tilt",
    [("paired", 0.8, 0.1, 10.0), ("servo-desk", None, 0.004, 4.0)],
)
def test_ik_gives_the_clis_numbers_to_the_bit(tmp_path, preset, z, reach, tilt):
    p = stewart.Platform.preset(preset)
    poses = random_poses(3001, z if z is not None else p.home[2], reach, tilt)
    pose_csv(tmp_path / "poses.csv", poses)
    text = cli("solve", "--preset", preset, "--poses", str(tmp_path / "poses.csv"))
    expected = columns(text, p.columns_names)
    got = p.ik(poses)
    assert got.shape == (3001, 6)
    assert got.dtype == np.float64
    assert np.array_equal(got.view(np.uint64), expected.view(np.uint64))


def test_fk_gives_the_clis_poses_to_the_bit(tmp_path):
    p = stewart.Platform.preset("paired")
    poses = random_poses(200, 0.8, 0.1, 10.0, seed=7)
    legs = p.ik(poses)
    lines = ["L1,L2,L3,L4,L5,L6"] + [",".join(repr(float(v)) for v in row) for row in legs]
    (tmp_path / "legs.csv").write_text("\n".join(lines) + "\n")
    text = cli("fk", "--preset", "paired", "--legs", str(tmp_path / "legs.csv"))
    expected = columns(text, ["x", "y", "z", "roll_deg", "pitch_deg", "yaw_deg"])
    got = p.fk(legs)
    assert np.array_equal(got.view(np.uint64), expected.view(np.uint64))
    # And forward kinematics undoes the inverse (independently of the CLI).
    assert np.max(np.abs(got - poses)) < 1e-9


def test_fk_of_servo_angles_undoes_ik():
    p = stewart.Platform.preset("servo-desk")
    poses = random_poses(50, p.home[2], 0.004, 4.0, seed=3)
    back = p.fk(p.ik(poses))
    assert np.max(np.abs(back - poses)) < 1e-9


def test_every_assembly_mode_has_the_legs_asked_for():
    p = stewart.Platform.preset("paired")
    legs = p.ik(np.array([[0.02, -0.01, 0.82, 3.0, -2.0, 5.0]]))
    modes = p.fk(legs, assembly_modes=True)
    assert len(modes) == 1 and modes[0].shape[1] == 6 and modes[0].shape[0] >= 2
    for pose in modes[0]:
        assert np.max(np.abs(p.ik(pose[None, :]) - legs)) < 1e-8


def test_check_is_the_clis_json_report():
    p = stewart.Platform.preset("paired")
    assert p.check() == json.loads(cli("check", "--preset", "paired", "--format", "json"))
    servo = stewart.Platform.preset("servo-desk")
    assert servo.check()["actuator"] == "rotary"


def test_the_trajectory_is_the_clis_sampled_motion():
    p = stewart.Platform.preset("figure8")
    times, poses = p.trajectory()
    text = cli("solve", "--preset", "figure8")
    assert np.array_equal(times, columns(text, ["t"])[:, 0])
    assert np.array_equal(poses, columns(text, ["x", "y", "z", "roll_deg", "pitch_deg", "yaw_deg"]))


def test_settings_change_the_platform_and_refusals_leave_it_alone():
    p = stewart.Platform.preset("paired")
    home = np.array([p.home])
    before = p.ik(home)
    p.set("geometry.base_radius", 1.2)
    assert p.get("geometry.base_radius") == 1.2
    assert np.all(p.ik(home) > before)
    with pytest.raises(stewart.ScenarioError, match="geometry.base_radius"):
        p.set("geometry.base_radius", -1.0)
    assert p.get("geometry.base_radius") == 1.2
    with pytest.raises(stewart.ScenarioError, match="unknown setting `geometry.nope`"):
        p.set("geometry.nope", 1.0)
    p.set("geometry.leg_max", 1.3)
    p.set("geometry.leg_max", None)
    assert p.get("geometry.leg_max") is None
    # Written out and read back: the same platform.
    again = stewart.Platform.from_file(_write(p.to_toml()))
    assert np.array_equal(again.ik(home), p.ik(home))


def test_a_link_template_is_held_to_the_links_grammar_where_it_is_written():
    p = stewart.Platform.preset("paired")
    p.set("link.format", "template:{a1:u8} ")
    with pytest.raises(stewart.ScenarioError, match="link.template"):
        p.set("link.template", "{a9:u8}")
    for not_text in (b"{a1:u8}", bytearray(b"{a1:u8}"), ["{a1:u8}"]):
        with pytest.raises(stewart.ScenarioError, match="text"):
            p.set("link.template", not_text)
    # Refused: the platform keeps the template it had, and what it writes reads back.
    assert p.get("link.template") == "{a1:u8} "
    again = stewart.Platform.from_file(_write(p.to_toml()))
    assert again.get("link.template") == "{a1:u8} "
    bad = p.to_toml().replace('"{a1:u8} "', '"{a9:u8}"')
    assert "{a9:u8}" in bad
    with pytest.raises(stewart.ScenarioError, match=r"line \d+.*link.template|link.template.*line \d+"):
        stewart.Platform.from_file(_write(bad))


def _write(text: str) -> str:
    import tempfile

    handle = tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False)
    handle.write(text)
    handle.close()
    return handle.name


def test_bad_input_is_a_clear_exception_never_a_crash(tmp_path):
    p = stewart.Platform.preset("paired")
    good = random_poses(10, 0.8, 0.05, 5.0)
    bad = good.copy()
    bad[7, 4] = np.nan
    with pytest.raises(ValueError, match=r"poses, row 7 \(from 0\), column pitch: NaN is not a finite number"):
        p.ik(bad)
    bad[7, 4] = np.inf
    with pytest.raises(ValueError, match="column pitch: inf is not a finite number"):
        p.ik(bad)
    with pytest.raises(ValueError, match=r"poses must be an \(n, 6\) array"):
        p.ik(good[:, :5])
    with pytest.raises(ValueError, match=r"poses must be an \(n, 6\) array"):
        p.ik(good[0])
    with pytest.raises(TypeError, match="poses must be float64, got float32"):
        p.ik(good.astype(np.float32))
    with pytest.raises(TypeError, match="poses must be float64, got int64"):
        p.ik(np.zeros((3, 6), dtype=np.int64))
    with pytest.raises(TypeError):
        p.ik("not an array")
    with pytest.raises(ValueError, match="values, row 0"):
        p.fk(np.array([[np.nan] * 6]))
    with pytest.raises(ValueError, match=r"out must have shape \(10, 6\)"):
        p.ik(good, out=np.empty((9, 6)))
    # An out of another dtype is named as such (not "'ndarray' is not an instance of 'ndarray'").
    with pytest.raises(TypeError, match="out must be a two-dimensional float64 array .* float32"):
        p.ik(good, out=np.empty((10, 6), dtype=np.float32))
    with pytest.raises(ValueError, match="pose must be six numbers"):
        p.jacobian([0, 0, 0.8])
    # A servo out of reach: the row and the servo, in the CLI's words.
    servo = stewart.Platform.preset("servo-desk")
    far = random_poses(20, servo.home[2], 0.004, 4.0)
    far[13] = [0.0, 0.0, 0.8, 0.0, 0.0, 0.0]
    with pytest.raises(stewart.UnreachableError, match=r"poses, row 13 \(from 0\): servo 1 cannot reach its platform joint") as e:
        servo.ik(far)
    assert (e.value.row, e.value.actuator) == (13, 1)
    with pytest.raises(stewart.ScenarioError, match="no preset is called `spiral`"):
        stewart.Platform.preset("spiral")
    (tmp_path / "s.toml").write_text(
        "[geometry]\nbase_radius = -1.0\nplatform_radius = 0.6\nhome_height = 0.8\n"
        "base_angles_deg = [0, 60, 120, 180, 240, 300]\nplatform_angles_deg = [30, 90, 150, 210, 270, 330]\n"
    )
    with pytest.raises(stewart.ScenarioError, match=r"s.toml, line 2, column 15: `base_radius` must be positive"):
        stewart.Platform.from_file(tmp_path / "s.toml")


def test_arrays_are_read_in_place_and_written_in_place():
    p = stewart.Platform.preset("paired")
    poses = random_poses(1000, 0.8, 0.1, 10.0)
    out = np.empty((1000, 6))
    returned = p.ik(poses, out=out)
    assert returned is out
    # A strided view (every other row) is copied once and gives the same numbers.
    wide = np.repeat(poses, 2, axis=0)[::2]
    assert not wide.flags["C_CONTIGUOUS"]
    assert np.array_equal(p.ik(wide), out)
    # Lists are taken as arrays.
    assert np.array_equal(p.ik(poses[:3].tolist()), out[:3])


def test_the_gil_is_released_during_a_batch():
    p = stewart.Platform.preset("paired")
    poses = random_poses(3_000_000, 0.8, 0.1, 10.0)
    out = np.empty_like(poses)
    p.ik(poses, out=out)  # warm: pages touched
    start = time.perf_counter()
    p.ik(poses, out=out)
    alone = time.perf_counter() - start
    ticks = []
    worker = threading.Thread(target=p.ik, args=(poses,), kwargs={"out": out})
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    gaps = np.diff(ticks)
    # Held, the main thread would stall for the whole batch; released, it runs on.
    assert len(ticks) > 100 and gaps.max() < 0.5 * alone, (gaps.max(), alone)


def test_the_jacobian_is_the_derivative_of_the_lengths():
    p = stewart.Platform.preset("paired")
    pose = np.array([0.02, -0.01, 0.82, 3.0, -2.0, 5.0])
    j = p.jacobian(pose)
    assert j.shape == (6, 6)
    h = 1e-6
    for axis in range(3):
        step = np.zeros(6)
        step[axis] = h
        rate = (p.ik((pose + step)[None]) - p.ik((pose - step)[None]))[0] / (2 * h)
        assert np.max(np.abs(rate - j[:, axis])) < 1e-7
    assert 1.0 < p.condition(pose) < 100.0


def test_the_workspace_holds_home():
    p = stewart.Platform.preset("paired")
    w = p.workspace(resolution=48)
    assert w["volume"] > 0 and w["volume_error"] < w["volume"]
    (x, y, z) = w["extent"]
    assert x[0] < 0 < x[1] and y[0] < 0 < y[1] and z[0] < p.home[2] < z[1]


def test_calibration_finds_leg_offsets():
    p = stewart.Platform.preset("paired")
    poses = random_poses(40, 0.8, 0.08, 8.0, seed=11)
    offsets = np.array([0.002, -0.001, 0.0015, 0.0, -0.002, 0.001])
    # The built legs are longer than commanded by `offsets`.
    commanded = p.ik(poses) - offsets
    calibrated, report = stewart.calibrate(p, np.hstack([poses, commanded]), hold=["base", "platform"])
    assert np.max(np.abs(np.array(report["offsets"]) - offsets)) < 1e-9
    assert report["rms_after"] < 1e-9 < report["rms_before"]
    assert isinstance(calibrated, stewart.Platform)
    with pytest.raises(ValueError, match="hold: `legs` is not one of"):
        stewart.calibrate(p, np.hstack([poses, commanded]), hold=["legs"])


def test_the_guides_python_example_runs():
    text = (ROOT / "docs/guide/python.md").read_text()
    start = text.index("```python\nimport numpy as np\nimport stewart\n")
    code = text[start + len("```python\n") : text.index("```", start + 3)]
    scope = {}
    exec(compile(code, "docs/guide/python.md", "exec"), scope)
    assert scope["legs"].shape == (2, 6)
    assert np.max(np.abs(scope["back"] - scope["poses"])) < 1e-9
    assert scope["report"]["scenario"] == "paired"
    assert np.max(np.abs(scope["fit"]["offsets"])) < 1e-9


def test_column_major_arrays_are_read_as_rows():
    # Fortran order (`np.asfortranarray`, `loadtxt(...).T` of a transposed file, data from
    # MATLAB or pandas) is contiguous too, but column after column: read as rows anyway.
    p = stewart.Platform.preset("paired")
    poses = random_poses(500, 0.8, 0.1, 10.0)
    legs = p.ik(poses)
    fortran = np.asfortranarray(poses)
    assert fortran.flags["F_CONTIGUOUS"] and not fortran.flags["C_CONTIGUOUS"]
    assert np.array_equal(p.ik(fortran), legs)
    transposed = np.ascontiguousarray(poses.T).T  # what loadtxt(...).T gives
    assert np.array_equal(p.ik(transposed), legs)
    near = p.ik(random_poses(200, 0.8, 0.03, 3.0))
    back = p.fk(near)
    assert np.array_equal(p.fk(np.asfortranarray(near)), back)
    # A NaN in a Fortran-ordered array: its own row and column are named.
    bad = np.asfortranarray(poses)
    bad[123, 4] = np.nan
    with pytest.raises(ValueError, match=r"poses, row 123 \(from 0\), column pitch: NaN"):
        p.ik(bad)
    # Calibration takes (n, 12) rows the same way.
    measured = np.column_stack([poses[:40], legs[:40]])
    plain = stewart.calibrate(p, measured)[1]
    column_major = stewart.calibrate(p, np.asfortranarray(measured))[1]
    assert plain["rms_after"] == column_major["rms_after"]


def test_the_accepted_ranges_and_singular_poses_are_the_command_lines():
    p = stewart.Platform.preset("paired")
    poses = random_poses(10, 0.8, 0.05, 5.0)
    # Finite but far outside: refused as `solve --poses` refuses the same table row.
    for column, value, name in [(0, 1e155, "x"), (2, -1000.5, "z"), (5, 3600.5, "yaw")]:
        far = poses.copy()
        far[6, column] = value
        with pytest.raises(ValueError, match=rf"poses, row 6 \(from 0\), column {name}: .* is outside the accepted range"):
            p.ik(far)
    with pytest.raises(ValueError, match="pose, x: 1e\\+?200 is outside the accepted range"):
        p.jacobian([1e200, 0, 0.8, 0, 0, 0])
    # Calibration's measured poses likewise.
    measured = np.column_stack([poses, p.ik(poses)])
    measured[4, 1] = 2000.0
    with pytest.raises(ValueError, match=r"measured, row 4 \(from 0\), column y: 2000 is outside the accepted range"):
        stewart.calibrate(p, measured)
    # The range's ends are accepted, with finite lengths.
    assert np.isfinite(p.ik(np.array([[1000.0, -1000.0, 1000.0, 3600.0, -3600.0, 3600.0]]))).all()
    # A pose where leg 1's joints meet: no Jacobian, said so (not a matrix of NaN).
    home = np.array(p.home)
    legs = p.ik(home[None, :])[0]
    base = stewart.Platform.preset("paired")
    # Lower the platform straight down by leg 1's length along its own direction: the
    # pose whose platform joint 1 sits on base joint 1 (found by the Jacobian's first row).
    row = p.jacobian(home)[0]
    lowered = home.copy()
    lowered[:3] -= legs[0] * row[:3]
    with pytest.raises(stewart.SingularError, match="leg 1 has zero length") as e:
        base.jacobian(lowered)
    assert e.value.actuator == 1


def test_a_fifo_is_refused_at_once_and_a_long_computation_gives_way_to_ctrl_c_and_other_threads(tmp_path):
    import _thread

    # A FIFO is not a file: refused by name at once, never waited on.
    fifo = tmp_path / "scenario.toml"
    os.mkfifo(fifo)
    start = time.perf_counter()
    with pytest.raises(stewart.ScenarioError, match="FIFO"):
        stewart.Platform.from_file(fifo)
    assert time.perf_counter() - start < 5.0
    # A long workspace stops within moments of Ctrl-C, and another thread runs all along
    # (the GIL is free).
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.01)

    other = threading.Thread(target=tick)
    other.start()
    p = stewart.Platform.preset("paired")
    threading.Timer(0.5, _thread.interrupt_main).start()
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        p.workspace(resolution=4096, budget=False)
    waited = time.perf_counter() - start
    stop.set()
    other.join()
    assert 0.4 < waited < 5.0, waited
    assert len(ticks) > 20


def test_settings_change_while_a_batch_runs_and_link_keys_read_back():
    p = stewart.Platform.preset("paired")
    poses = random_poses(2_000_000, 0.8, 0.1, 10.0)
    worker = threading.Thread(target=p.ik, args=(poses,))
    worker.start()
    # Not "Already borrowed": a batch works on the platform as it was when it started.
    changes = 0
    while worker.is_alive() or changes == 0:
        p.set("geometry.base_radius", 1.1 if changes % 2 == 0 else 1.0)
        changes += 1
    worker.join()
    p.set("geometry.base_radius", 1.1)
    assert p.get("geometry.base_radius") == 1.1
    p.set("link.rate_hz", 250)
    assert p.get("link.rate_hz") == 250.0
    assert p.get("link.transport") == "file"
    assert p.get("link.port") is None
    assert p.get("link.reversed.2") is False
    with pytest.raises(stewart.ScenarioError, match="unknown setting `link.nope`"):
        p.get("link.nope")


def test_cueing_gives_the_clis_poses_and_comparison_for_either_algorithm():
    recording = ROOT / "examples" / "cueing" / "braking-step.csv"
    vehicle = np.loadtxt(recording, delimiter=",", skiprows=1)
    for algorithm in ("washout", "mpc"):
        p = stewart.Platform.preset("paired")
        p.set("cueing.algorithm", algorithm)
        assert p.get("cueing.algorithm") == algorithm
        poses = stewart.cue(p, vehicle)
        expected = columns(
            cli("cue", "--preset", "paired", "--input", str(recording), "--set", f"cueing.algorithm={algorithm}"),
            ["x", "y", "z", "roll_deg", "pitch_deg", "yaw_deg"],
        )
        # The CLI writes the shortest text that reads back to the same float.
        assert np.array_equal(poses, expected)
    compared = stewart.cue_compare(stewart.Platform.preset("paired"), vehicle)
    cli_json = json.loads(cli("cue", "--preset", "paired", "--input", str(recording), "--compare", "--format", "json"))
    for algorithm in ("washout", "mpc"):
        assert compared[algorithm] == cli_json[algorithm]
    assert compared["mpc"]["force_rmse_xy_m_s2"] < 0.7 * compared["washout"]["force_rmse_xy_m_s2"]
    # Bad input: one clear error naming the row.
    backwards = vehicle.copy()
    backwards[5, 0] = 0.0
    with pytest.raises(ValueError, match="vehicle, row 5"):
        stewart.cue(p, backwards)
    bad = vehicle.copy()
    bad[7, 2] = np.nan
    with pytest.raises(ValueError, match="vehicle, row 7 .*column ay"):
        stewart.cue(p, bad)
    huge = vehicle.copy()
    huge[3, 1] = 1e300
    with pytest.raises(ValueError, match="vehicle, row 3 .*column ax"):
        stewart.cue(p, huge)
    # The one range rule of vehicle motion: what a game's datagram may carry.
    hard = vehicle.copy()
    hard[4, 6] = 2e5
    with pytest.raises(ValueError, match="vehicle, row 4 .*column wz"):
        stewart.cue(p, hard)
    # A recording of no rows is refused, as `stewart cue` refuses it.
    with pytest.raises(ValueError, match="no rows"):
        stewart.cue(stewart.Platform.preset("seed"), np.zeros((0, 7)))
    with pytest.raises(ValueError, match="must be `washout` or `mpc`"):
        p.set("cueing.algorithm", "fuzzy")
