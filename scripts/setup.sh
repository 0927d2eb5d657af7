#!/usr/bin/env bash
# Install the system packages the project needs, when they are missing (Debian; run as
# root or with sudo available). Safe to run again: it does nothing when all are present.
set -euo pipefail
cd "$(dirname "$0")/.."

# Every system package the build, the program and the tests need.
PACKAGES=(gcc g++ libc6-dev pkg-config ca-certificates                  # g++: tests build the firmware header as C++ too
  mesa-vulkan-drivers libvulkan1 libegl1 libegl-mesa0 libgl1-mesa-dri   # software GPU (lavapipe) for headless rendering
  ffmpeg                                                                 # MP4 export, ffprobe in tests
  fonts-dejavu-core                                                      # text in PDF and PNG plots, labels and readouts
  fonts-wqy-microhei                                                     # Chinese text (1.6 MB): titles now, the Chinese interface next
  poppler-utils                                                          # pdftoppm: tests open exported PDFs
  xvfb xauth                                                             # a virtual display for the viewer's smoke test
  time                                                                   # GNU time: peak memory in scripts/bench-inputs.sh
  libudev-dev                                                            # serial port and gamepad discovery (serialport, gilrs)
  socat                                                                  # a pseudo-terminal pair stands in for a serial cable in tests
  nodejs                                                                 # the Khronos glTF-Validator (npm) checks exported glTF
)

# Python 3 with venv (the Python package is built and tested in a virtual environment);
# a Python already installed some other way (pyenv) is used as it is.
if ! python3 -c "import venv, ensurepip" 2>/dev/null; then
  PACKAGES+=(python3 python3-venv)
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
command -v cargo >/dev/null || { echo "setup: cargo not found: install Rust 1.95 (rustup) first" >&2; exit 1; }

# What the Python part needs from PyPI, in the project's own virtual environment `.venv`
# (`pip install ./crates/stewart_py` there builds and installs the package).
if [ ! -x .venv/bin/python ] || ! .venv/bin/python -c "import numpy, pytest, maturin" 2>/dev/null; then
  echo "setup: preparing .venv (numpy, pytest, maturin from PyPI)"
  python3 -m venv .venv
  .venv/bin/pip install -q --disable-pip-version-check numpy pytest "maturin>=1.7,<2"
fi
