"""Open an exported glTF animation in Blender (headless) and check it plays the trajectory.

    stewart render --preset seed --out seed.glb
    stewart solve --preset seed --out seed-legs.csv
    blender -b --python scripts/blender-check.py -- seed.glb seed-legs.csv [picture.png]

Blender's own glTF importer (io_scene_gltf2, shipped with Debian's blender 3.4) reads the
file; the check finds every node (`stewart`, `base`, `platform`, `leg{k}_cylinder`,
`leg{k}_rod`), confirms the animation was imported, and at every 25th row of the solved
CSV sets Blender's clock to that time and compares the distance between each leg's two
objects (world space, after Blender's own y-up conversion) with the leg length `stewart
solve` gives. With a third argument it also renders that moment (Cycles, CPU) to a PNG.
Exits 1 on any mismatch. Linear legs only (servo scenarios have horns instead).
"""

import csv
import math
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1 :]
glb, legs_csv = argv[0], argv[1]
png = argv[2] if len(argv) > 2 else None

# Debian's blender 3.4 importer still says `numpy.bool`, which NumPy 1.24 (Debian's) no
# longer has: give it the builtin it always meant.
try:
    import numpy

    if "bool" not in numpy.__dict__:
        numpy.bool = bool
except ImportError:
    sys.exit("blender-check: Blender's glTF importer needs NumPy (Debian: python3-numpy)")

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=glb)
scene = bpy.context.scene
objects = {o.name: o for o in scene.objects}
wanted = ["stewart", "base", "platform"] + [
    f"leg{k}_{part}" for k in range(1, 7) for part in ("cylinder", "rod")
]
missing = [n for n in wanted if n not in objects]
if missing:
    sys.exit(f"blender-check: nodes missing after import: {missing}")
if not bpy.data.actions:
    sys.exit("blender-check: no animation was imported")
fps = scene.render.fps / scene.render.fps_base
# The first key's frame: where the importer put time 0.
start = min(a.frame_range[0] for a in bpy.data.actions)

with open(legs_csv, newline="") as f:
    rows = list(csv.DictReader(f))
t0 = float(rows[0]["t"])
worst = 0.0
checked = 0
for row in rows[::25]:
    frame = (float(row["t"]) - t0) * fps + start
    whole = math.floor(frame)
    scene.frame_set(whole, subframe=frame - whole)
    for k in range(1, 7):
        a = objects[f"leg{k}_cylinder"].matrix_world.translation
        b = objects[f"leg{k}_rod"].matrix_world.translation
        worst = max(worst, abs((a - b).length - float(row[f"L{k}"])))
    checked += 1
print(
    f"blender-check: {glb}: {len(bpy.data.actions)} actions, frames "
    f"{start:g}.. at {fps:g} fps; {checked} moments, "
    f"largest leg-length difference {worst:.2e} m"
)
if worst > 1e-4:
    sys.exit("blender-check: the legs in Blender are not the solved lengths")

if png:
    moment = (float(rows[len(rows) // 3]["t"]) - t0) * fps + start
    scene.frame_set(int(moment))
    bpy.ops.object.light_add(type="SUN", rotation=(0.7, 0.2, 0.6))
    bpy.context.object.data.energy = 4.0
    bpy.ops.object.camera_add(location=(3.1, -3.1, 2.3))
    camera = bpy.context.object
    target = bpy.data.objects.new("look-at", None)
    target.location = (0.0, 0.0, 0.4)
    scene.collection.objects.link(target)
    track = camera.constraints.new(type="TRACK_TO")
    track.target = target
    scene.camera = camera
    world = bpy.data.worlds.new("world")
    world.color = (0.9, 0.9, 0.92)
    scene.world = world
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 24
    scene.cycles.use_denoising = False
    scene.render.resolution_x, scene.render.resolution_y = 800, 500
    scene.render.filepath = png
    bpy.ops.render.render(write_still=True)
    print(f"blender-check: rendered {png}")
