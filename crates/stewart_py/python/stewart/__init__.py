"""Gough–Stewart platforms from Python, on the Stewart-platform studio's Rust core.

    >>> import numpy as np, stewart
    >>> p = stewart.Platform.preset("paired")
    >>> legs = p.ik(np.array([[0.0, 0.0, 0.8, 0.0, 0.0, 0.0]]))   # x, y, z (m), roll, pitch, yaw (°)
    >>> poses = p.fk(legs)                                          # back to the pose

Arrays are float64 with one pose (or one set of six actuator values) per row; leg lengths
are in metres, servo angles in degrees. Batches run on all cores with the GIL released.
"""

from ._errors import (
    CalibrationError,
    ForwardError,
    ScenarioError,
    SingularError,
    StewartError,
    UnreachableError,
)
from ._stewart import Platform, calibrate, cue, cue_compare, presets

__all__ = [
    "Platform",
    "calibrate",
    "cue",
    "cue_compare",
    "presets",
    "StewartError",
    "ScenarioError",
    "UnreachableError",
    "ForwardError",
    "CalibrationError",
    "SingularError",
]
