"""The package's exceptions; raised from the Rust core with the same located messages
as the command line's."""


class StewartError(Exception):
    """Base class of every error the package raises."""


class ScenarioError(StewartError, ValueError):
    """A scenario or setting that cannot be used: the message names the file, line and key."""


class UnreachableError(StewartError, ValueError):
    """A pose a servo cannot reach: `row` (from 0) and `actuator` (from 1) say which."""

    def __init__(self, message: str, row: int, actuator: int) -> None:
        super().__init__(message)
        self.row = row
        self.actuator = actuator


class ForwardError(StewartError, ValueError):
    """Forward kinematics found no pose for a row of actuator values (`row`, from 0)."""

    def __init__(self, message: str, row: int) -> None:
        super().__init__(message)
        self.row = row


class CalibrationError(StewartError, ValueError):
    """Calibration could not be done with these measurements."""


class SingularError(StewartError, ValueError):
    """A pose at which the Jacobian is undefined: leg `actuator` (from 1) has zero length."""

    def __init__(self, message: str, actuator: int) -> None:
        super().__init__(message)
        self.actuator = actuator
