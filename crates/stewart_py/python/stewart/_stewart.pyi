"""Type stubs of the compiled module (the kinematics core): what editors complete."""

from os import PathLike
from typing import Any, Dict, List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

Array = npt.NDArray[np.float64]
ArrayLike = Union[Array, Sequence[Sequence[float]]]

class Platform:
    """A Gough–Stewart platform and its motion (a scenario of the studio)."""

    @staticmethod
    def preset(name: str) -> "Platform":
        """A shipped preset (`stewart.presets()` lists them); `ScenarioError` otherwise."""
    @staticmethod
    def from_file(path: Union[str, PathLike[str]]) -> "Platform":
        """A scenario file (TOML); errors name the file, line and key."""
    def set(self, key: str, value: Union[float, bool, str, None]) -> None:
        """Change one setting by its key (`stewart settings` lists them); `None` switches
        an optional one off. A refused value raises `ScenarioError` and changes nothing."""
    def get(self, key: str) -> Union[float, str, None]:
        """The value of a setting (`None` when off or not applying); `link.*` keys give
        their number or word."""
    @property
    def name(self) -> str:
        """The scenario's name."""
    @property
    def actuator(self) -> Literal["linear", "rotary"]:
        """Linear legs or rotary servos."""
    @property
    def columns_names(self) -> List[str]:
        """`L1…L6` (metres) or `theta1…theta6` (degrees)."""
    @property
    def home(self) -> List[float]:
        """The home pose: x, y, z (m), roll, pitch, yaw (°)."""
    def to_toml(self) -> str:
        """The scenario as TOML text."""
    def ik(self, poses: ArrayLike, out: Optional[Array] = None) -> Array:
        """Leg lengths (m) or servo angles (°) of `(n, 6)` poses (x, y, z in m; roll,
        pitch, yaw in °), on all cores with the GIL released; into `out` when given.
        Positions beyond ±1000 m and angles beyond ±3600° are refused (ValueError), as a
        pose table is."""
    @overload
    def fk(self, values: ArrayLike, assembly_modes: Literal[False] = ...) -> Array: ...
    @overload
    def fk(self, values: ArrayLike, assembly_modes: Literal[True]) -> List[Array]: ...
    def fk(self, values: ArrayLike, assembly_modes: bool = False) -> Union[Array, List[Array]]:
        """Poses of `(n, 6)` actuator values, each row started from the previous pose; or
        every assembly mode of each row."""
    def jacobian(self, pose: Sequence[float]) -> Array:
        """The actuators' 6×6 Jacobian at a pose (rates per twist about the pivot point);
        `SingularError` where a leg has zero length."""
    def condition(self, pose: Sequence[float]) -> float:
        """The normalised condition number at a pose (infinite when singular)."""
    def check(self) -> Dict[str, Any]:
        """The pre-flight check of the motion (`stewart check --format json`)."""
    def workspace(
        self,
        orientation: Tuple[float, float, float] = ...,
        resolution: int = ...,
        budget: bool = ...,
    ) -> Dict[str, Any]:
        """Reachable positions at a fixed orientation: volume, volume_error, extent.
        Refused when estimated over the budget (two minutes, 2 GB) unless `budget=False`;
        Ctrl-C stops it."""
    def trajectory(self) -> Tuple[Array, Array]:
        """The sampled motion: times `(n,)` and poses `(n, 6)`."""

def calibrate(
    platform: Platform, measured: ArrayLike, hold: Sequence[str] = ...
) -> Tuple[Platform, Dict[str, Any]]:
    """Joints and actuator offsets from `(n, 12)` measurements (pose, then the six values
    commanded); returns the calibrated platform and a report."""

def cue(platform: Platform, vehicle: ArrayLike) -> Array:
    """Platform poses `(n, 6)` from vehicle motion `(n, 7)`: t, ax, ay, az (m/s²), wx, wy,
    wz (°/s), by the platform's `[cueing]` table (washout or model-predictive), as
    `stewart cue` writes them."""

def cue_compare(platform: Platform, vehicle: ArrayLike) -> Dict[str, Any]:
    """Both cueing algorithms on `vehicle` and their measures: `{"washout": {...},
    "mpc": {...}}`, as `stewart cue --compare --format json`."""

def presets() -> List[str]:
    """The names of the shipped presets."""
