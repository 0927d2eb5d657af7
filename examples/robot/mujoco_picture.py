#!/usr/bin/env python3
"""Load an MJCF file written by `stewart robot --format mjcf`, put the model at one of
its keyframes (the studio's pose, every loop closed) and save what MuJoCo's own renderer
draws from the file's `overview` camera as a PNG.

    MUJOCO_GL=egl python3 mujoco_picture.py RIG.xml PICTURE.png [KEYFRAME]

Needs `pip install mujoco numpy`; `MUJOCO_GL=egl` (or `osmesa`) renders without a
window.
"""

import struct
import sys
import zlib

import mujoco


def save_png(path, rgb):
    """An RGB array (height, width, 3; uint8) as a PNG file."""
    height, width, _ = rgb.shape
    raw = b"".join(b"\0" + rgb[row].tobytes() for row in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    model = mujoco.MjModel.from_xml_path(sys.argv[1])
    data = mujoco.MjData(model)
    key = int(sys.argv[3]) if len(sys.argv) == 4 else 0
    mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_forward(model, data)
    with mujoco.Renderer(model, height=540, width=720) as renderer:
        renderer.update_scene(data, camera="overview")
        save_png(sys.argv[2], renderer.render())
    print(f"{sys.argv[2]}: keyframe {model.key(key).name} of {model.nkey}")


if __name__ == "__main__":
    main()
