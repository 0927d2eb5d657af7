#!/usr/bin/env bash
# The whole test suite, as CI runs it: system packages, formatting, lints, every test.
# This is the one place where the project's checks are listed.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
# Mesa's drivers warn when no runtime folder is set (as under CI); give them a private one.
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
cargo fmt --all --check
# The kinematics core's layers (model -> solve -> analysis, io beside): no import or call
# goes up a layer beyond the exceptions it lists (docs/modules.md says why).
python3 scripts/layer-check.py
# ARCHITECTURE.md and docs/modules.md true: every module they name exists, every public
# module is named, and the rules the map states hold (no import circles, the shell imported
# only from above, the top-level folders reached by their owners, the crates' walls).
python3 scripts/architecture-check.py
cargo clippy --workspace --all-targets -- -D warnings
cargo test --workspace
# Every command README.md and the user guide show, with the program the tests just ran
# (`stewart_app::main`), built as `stewart`.
cargo build -p stewart_app --bin stewart
python3 tests/docs/commands.py --debug
# Every preset exported as an animated glTF scene, checked by the Khronos glTF-Validator.
bash scripts/gltf-check.sh --debug
# Every preset and CAD example as MJCF in MuJoCo and as URDF in yourdfpy (both from PyPI;
# skipped, saying so, where they cannot be installed): loops closed at every keyframe, the
# platform at the studio's pose, and driven by the studio's actuator values it settles there.
bash scripts/robot-check.sh --debug
# The Python package (a workspace of its own: it builds against Python): lints, then
# built and tested from a clean virtual environment.
cargo fmt --manifest-path crates/stewart_py/Cargo.toml --check
cargo clippy --manifest-path crates/stewart_py/Cargo.toml --all-targets -- -D warnings
bash scripts/python-check.sh
