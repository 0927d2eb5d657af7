#!/usr/bin/env python3
"""Make the example CAD parts of examples/cad/, one of each mesh format the `[appearance]`
table reads, each drawn in its part's frame (see crates/stewart_kinematics/src/model/appearance.rs).
Python 3 standard library only; the files come out the same, byte for byte, on every run.
Run from the repository root: python3 scripts/make-cad-examples.py

Each part, its file, its units and its frame (x, y, z: the part's local axes):

  base.stl       binary STL, millimetres (scale = "mm"). The base plate: a hexagon of
                 circumradius 1100 mm, its corners at 30°, 90°, ..., 330° (so its edges face
                 the base joints at 0°, 60°, ...), 40 mm thick with its TOP face at z = 0
                 (it spans z = -40..0), with six bolt holes of radius 35 mm through it, their
                 centres at radius 700 mm at 30°, 90°, ..., 330°. Frame: the base frame
                 (origin at the base centre, z up).
  platform.obj   Wavefront OBJ + platform.mtl, millimetres (scale = "mm"). The moving plate:
                 a hexagon of circumradius 720 mm, corners at 0°, 60°, ..., 300°, 30 mm thick
                 with its BOTTOM face at z = 0 (z = 0..30), material `plate` (orange), and a
                 round boss on top at the centre, radius 120 mm, z = 30..50, material `boss`
                 (dark grey). One closed body. Frame: the platform frame (origin at the
                 platform centre, z up).
  cylinder.glb   glTF 2.0 binary, metres (scale = "m"). A hydraulic cylinder's body: origin
                 at the leg's base joint, +y along the leg; a foot of radius 0.03 m from
                 y = 0 to 0.04 and a tube of radius 0.045 m from y = 0.04 to 0.50. One
                 closed body, one node, steel-grey PBR material.
  rod.stl        ASCII STL ("solid rod" ... "endsolid rod"), millimetres (scale = "mm"). The
                 piston rod: origin at the leg's platform joint, +y along the leg AWAY from
                 the base, so the rod reaches down along -y: a rod-end eye of radius 30 mm
                 from y = -30 to 0 and the rod of radius 22 mm from y = -760 to -30.
  horn.glb       glTF 2.0 binary whose mesh is modelled in millimetres under a root node
                 that scales it by 0.001 (so the file is in metres: scale = "m"). A hobby
                 servo's horn: origin on the shaft's centre, +x along the horn towards its
                 tip, +z along the shaft. A hub of radius 5 mm about the z axis (z = -2.5..2.5)
                 and an arm 3 mm thick (z = -1.5..1.5) from x = 0 to x = 25 mm, 8 mm wide at
                 the shaft narrowing to 5 mm at its rounded tip. Two closed bodies that overlap.

Every body is closed (each edge shared by exactly two triangles, in opposite directions),
its triangles wound counter-clockwise seen from outside, and its normals pointing out.
Circles have 64 segments.
"""
import json
import math
import os
import struct

OUT = os.path.join("examples", "cad")
SEGMENTS = 64


# ---------------------------------------------------------------------------------------
# An indexed triangle mesh: positions, a normal per vertex, triangles (and a material
# per triangle, for the OBJ).


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def unit(a):
    n = math.sqrt(dot(a, a))
    return (a[0] / n, a[1] / n, a[2] / n)


class Mesh:
    def __init__(self):
        self.positions = []
        self.normals = []
        self.triangles = []
        self.materials = []
        self.material = None

    def vertex(self, p, n=(0.0, 0.0, 0.0)):
        self.positions.append(tuple(float(c) for c in p))
        self.normals.append(tuple(float(c) for c in n))
        return len(self.positions) - 1

    def triangle(self, a, b, c, outward):
        """Add the triangle a b c, wound so that its normal points along `outward`."""
        pa, pb, pc = self.positions[a], self.positions[b], self.positions[c]
        n = cross(sub(pb, pa), sub(pc, pa))
        d = dot(n, outward)
        area = math.sqrt(dot(n, n))
        assert area > 1e-12 and abs(d) > 0.5 * area * math.sqrt(dot(outward, outward)), "bad triangle"
        self.triangles.append((a, b, c) if d > 0 else (a, c, b))
        self.materials.append(self.material)


def lathe(mesh, profile, point, normal, segments=SEGMENTS):
    """A solid of revolution: `profile` is a list of (radius, axial) points going from the
    axis round the outside of the section and back to the axis; point(r, a, t) and
    normal(nr, na, t) map section coordinates at angle t to 3D. Each profile segment gets
    its own ring of vertices (flat in the axial direction, smooth around)."""
    angles = [2 * math.pi * i / segments for i in range(segments)]
    for (r0, a0), (r1, a1) in zip(profile, profile[1:]):
        length = math.hypot(r1 - r0, a1 - a0)
        nr, na = (a1 - a0) / length, -(r1 - r0) / length  # outward, for this traversal
        rings = []
        for r, a in ((r0, a0), (r1, a1)):
            if r == 0:
                rings.append([mesh.vertex(point(0.0, a, 0.0), normal(nr, na, 0.0))] * segments)
            else:
                rings.append([mesh.vertex(point(r, a, t), normal(nr, na, t)) for t in angles])
        for i in range(segments):
            j = (i + 1) % segments
            tm = 2 * math.pi * (i + 0.5) / segments
            out = normal(nr, na, tm)
            a, b = rings[0][i], rings[0][j]
            c, d = rings[1][i], rings[1][j]
            if r0 != 0:
                mesh.triangle(a, b, d, out)
            if r1 != 0:
                mesh.triangle(a, d, c, out)


def annulus_fan(mesh, outer, outer_angles, inner, inner_angles, up):
    """Triangulate the flat region between a convex loop `outer` (vertex ids, in order of
    angle seen from the hole's centre) and a circle `inner` (vertex ids) inside it, with no
    vertex added on the outer loop: each circle segment is fanned to the outer vertex
    nearest it in angle, and a triangle fills each step from one outer vertex to the next."""
    n = len(inner)

    def gap(a, b):
        return abs((a - b + math.pi) % (2 * math.pi) - math.pi)

    owner = []
    for i in range(n):
        mid = inner_angles[i] + gap(inner_angles[(i + 1) % n], inner_angles[i]) / 2
        owner.append(min(range(len(outer)), key=lambda k: gap(outer_angles[k], mid)))
    assert sorted(set(owner)) == list(range(len(outer))), "an outer vertex owns no segment"
    for i in range(n):
        mesh.triangle(inner[i], outer[owner[i]], inner[(i + 1) % n], up)
        prev = owner[i - 1]
        if prev != owner[i]:
            assert owner[i] == (prev + 1) % len(outer), "outer vertices out of order"
            mesh.triangle(inner[i], outer[prev], outer[owner[i]], up)


def polar(r, deg):
    t = math.radians(deg)
    return (r * math.cos(t), r * math.sin(t))


# ---------------------------------------------------------------------------------------
# The parts.


def base_plate():
    """Hexagon R 1100 mm, corners at 30 + 60k degrees, z = -40..0, six holes r 35 at 700 mm.
    Split into six kites (centre, edge midpoint, corner, edge midpoint), each holding one
    hole; each kite's face is fanned between its four corners and the hole's circle."""
    mesh = Mesh()
    radius, thickness, hole_r, hole_at = 1100.0, 40.0, 35.0, 700.0
    apothem = radius * math.cos(math.radians(30))
    for z, up in ((0.0, (0, 0, 1)), (-thickness, (0, 0, -1))):
        centre = mesh.vertex((0.0, 0.0, z))
        corners = [mesh.vertex(polar(radius, 30 + 60 * k) + (z,)) for k in range(6)]
        mids = [mesh.vertex(polar(apothem, 60 * k) + (z,)) for k in range(6)]  # mid k: corners k-1, k
        for k in range(6):
            theta = 30 + 60 * k
            hx, hy = polar(hole_at, theta)
            kite = [centre, mids[k], corners[k], mids[(k + 1) % 6]]
            kite_angles = []
            for v in kite:
                px, py, _ = mesh.positions[v]
                kite_angles.append(math.atan2(py - hy, px - hx))
            angles = [2 * math.pi * i / SEGMENTS for i in range(SEGMENTS)]
            circle = [mesh.vertex((hx + hole_r * math.cos(t), hy + hole_r * math.sin(t), z)) for t in angles]
            # the kite's angles seen from the hole increase from the centre round: centre
            # at theta+180, mid k at ~theta-75, corner at theta, mid k+1 at ~theta+75
            annulus_fan(mesh, kite, kite_angles, circle, angles, up)
    # hole walls: normals point into the hole (out of the solid)
    for k in range(6):
        hx, hy = polar(hole_at, 30 + 60 * k)
        ring = []
        for z in (0.0, -thickness):
            ring.append([mesh.vertex((hx + hole_r * math.cos(2 * math.pi * i / SEGMENTS),
                                      hy + hole_r * math.sin(2 * math.pi * i / SEGMENTS), z))
                         for i in range(SEGMENTS)])
        for i in range(SEGMENTS):
            j = (i + 1) % SEGMENTS
            t = 2 * math.pi * (i + 0.5) / SEGMENTS
            inward = (-math.cos(t), -math.sin(t), 0.0)
            mesh.triangle(ring[0][i], ring[0][j], ring[1][j], inward)
            mesh.triangle(ring[0][i], ring[1][j], ring[1][i], inward)
    # side walls: each hexagon edge in two halves, at its midpoint
    for k in range(6):
        a, m, b = polar(radius, 30 + 60 * (k - 1)), polar(apothem, 60 * k), polar(radius, 30 + 60 * k)
        out = polar(1.0, 60 * k) + (0.0,)
        for p, q in ((a, m), (m, b)):
            v = [mesh.vertex(p + (0.0,)), mesh.vertex(q + (0.0,)),
                 mesh.vertex(q + (-thickness,)), mesh.vertex(p + (-thickness,))]
            mesh.triangle(v[0], v[1], v[2], out)
            mesh.triangle(v[0], v[2], v[3], out)
    return mesh


def platform_plate():
    """Hexagon R 720 mm, corners at 60k degrees, z = 0..30 (material plate), with a boss
    r 120 mm, z = 30..50 (material boss), as one closed body."""
    mesh = Mesh()
    radius, thickness, boss_r, boss_h = 720.0, 30.0, 120.0, 20.0
    angles = [2 * math.pi * i / SEGMENTS for i in range(SEGMENTS)]
    mesh.material = "plate"
    # bottom face
    bottom = [mesh.vertex(polar(radius, 60 * k) + (0.0,)) for k in range(6)]
    centre = mesh.vertex((0.0, 0.0, 0.0))
    for k in range(6):
        mesh.triangle(centre, bottom[(k + 1) % 6], bottom[k], (0, 0, -1))
    # top face, between the hexagon and the boss's foot
    top = [mesh.vertex(polar(radius, 60 * k) + (thickness,)) for k in range(6)]
    foot = [mesh.vertex((boss_r * math.cos(t), boss_r * math.sin(t), thickness)) for t in angles]
    annulus_fan(mesh, top, [math.radians(60 * k) for k in range(6)], foot, angles, (0, 0, 1))
    # side walls
    for k in range(6):
        j = (k + 1) % 6
        out = polar(1.0, 60 * k + 30) + (0.0,)
        mesh.triangle(bottom[k], bottom[j], top[j], out)
        mesh.triangle(bottom[k], top[j], top[k], out)
    # the boss: its wall and its top
    mesh.material = "boss"
    lip = [mesh.vertex((boss_r * math.cos(t), boss_r * math.sin(t), thickness + boss_h)) for t in angles]
    for i in range(SEGMENTS):
        j = (i + 1) % SEGMENTS
        t = 2 * math.pi * (i + 0.5) / SEGMENTS
        out = (math.cos(t), math.sin(t), 0.0)
        mesh.triangle(foot[i], foot[j], lip[j], out)
        mesh.triangle(foot[i], lip[j], lip[i], out)
    cap = mesh.vertex((0.0, 0.0, thickness + boss_h))
    for i in range(SEGMENTS):
        mesh.triangle(cap, lip[i], lip[(i + 1) % SEGMENTS], (0, 0, 1))
    return mesh


def along_y(r, a, t):
    return (r * math.sin(t), a, r * math.cos(t))


def along_z(r, a, t):
    return (r * math.cos(t), r * math.sin(t), a)


def cylinder_body():
    """Foot r 0.03 m, y = 0..0.04; tube r 0.045 m, y = 0.04..0.50; metres."""
    mesh = Mesh()
    profile = [(0.0, 0.0), (0.03, 0.0), (0.03, 0.04), (0.045, 0.04), (0.045, 0.50), (0.0, 0.50)]
    lathe(mesh, profile, along_y, along_y)
    return mesh


def piston_rod():
    """Rod r 22 mm, y = -760..-30; eye r 30 mm, y = -30..0; millimetres."""
    mesh = Mesh()
    profile = [(0.0, -760.0), (22.0, -760.0), (22.0, -30.0), (30.0, -30.0), (30.0, 0.0), (0.0, 0.0)]
    lathe(mesh, profile, along_y, along_y)
    return mesh


def servo_horn():
    """Hub r 5 mm, z = -2.5..2.5; arm z = -1.5..1.5, x = 0..25, 8 mm wide at x = 0, a tip
    of radius 2.5 mm centred at x = 22.5 with the arm's sides tangent to it; millimetres."""
    mesh = Mesh()
    lathe(mesh, [(0.0, -2.5), (5.0, -2.5), (5.0, 2.5), (0.0, 2.5)], along_z, along_z)
    half_root, tip_c, tip_r, half_t = 4.0, 22.5, 2.5, 1.5
    # the tangent from (0, -4) to the tip's circle touches it at angle phi (from +x)
    px, py = -tip_c, -half_root
    phi = math.atan2(py, px) + math.acos(tip_r / math.hypot(px, py))
    arc = 16
    outline = [(0.0, -half_root)]
    for i in range(arc + 1):
        t = phi - 2 * phi * i / arc  # from phi (about -86 degrees) round to -phi
        outline.append((tip_c + tip_r * math.cos(t), tip_r * math.sin(t)))
    outline.append((0.0, half_root))
    # convex, counter-clockwise seen from +z
    for i in range(len(outline)):
        a, b, c = outline[i - 1], outline[i], outline[(i + 1) % len(outline)]
        assert (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) > 0, "arm outline not convex"
    n = len(outline)
    for z, up in ((half_t, (0, 0, 1)), (-half_t, (0, 0, -1))):
        centre = mesh.vertex((10.0, 0.0, z), up)
        ring = [mesh.vertex((x, y, z), up) for x, y in outline]
        for i in range(n):
            mesh.triangle(centre, ring[i], ring[(i + 1) % n], up)
    for i in range(n):
        (ax, ay), (bx, by) = outline[i], outline[(i + 1) % n]
        out = unit((by - ay, -(bx - ax), 0.0))
        v = [mesh.vertex((ax, ay, -half_t), out), mesh.vertex((bx, by, -half_t), out),
             mesh.vertex((bx, by, half_t), out), mesh.vertex((ax, ay, half_t), out)]
        mesh.triangle(v[0], v[1], v[2], out)
        mesh.triangle(v[0], v[2], v[3], out)
    return mesh


# ---------------------------------------------------------------------------------------
# Writers.


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def facet_normal(mesh, tri):
    p = [mesh.positions[i] for i in tri]
    return unit(cross(sub(p[1], p[0]), sub(p[2], p[0])))


def write_binary_stl(path, mesh, header):
    head = header.encode("ascii")
    assert len(head) <= 80 and not head.lower().startswith(b"solid")
    out = [head.ljust(80, b" "), struct.pack("<I", len(mesh.triangles))]
    for tri in mesh.triangles:
        n = facet_normal(mesh, tri)
        coords = list(n) + [c for i in tri for c in mesh.positions[i]]
        out.append(struct.pack("<12fH", *[c + 0.0 for c in coords], 0))
    with open(path, "wb") as f:
        f.write(b"".join(out))


def write_ascii_stl(path, mesh, name):
    def e(x):
        return "%.6e" % (x + 0.0)

    lines = ["solid %s" % name]
    for tri in mesh.triangles:
        lines.append(" facet normal %s" % " ".join(e(c) for c in facet_normal(mesh, tri)))
        lines.append("  outer loop")
        for i in tri:
            lines.append("   vertex %s" % " ".join(e(c) for c in mesh.positions[i]))
        lines.append("  endloop")
        lines.append(" endfacet")
    lines.append("endsolid %s" % name)
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


def write_obj(path, mtl_name, mesh, materials, comment):
    def num(x, places):
        return "%.*f" % (places, round(x, places) + 0.0)

    # positions welded (each written once), flat normals per face, shared when equal
    vindex, vlines, nindex, nlines = {}, [], {}, []

    def key_index(table, lines, prefix, values):
        key = " ".join(num(c, 6 if prefix == "vn" else 4) for c in values)
        if key not in table:
            table[key] = len(table) + 1
            lines.append("%s %s" % (prefix, key))
        return table[key]

    faces = {name: [] for name in materials}
    for tri, mat in zip(mesh.triangles, mesh.materials):
        vn = key_index(nindex, nlines, "vn", facet_normal(mesh, tri))
        vs = [key_index(vindex, vlines, "v", mesh.positions[i]) for i in tri]
        faces[mat].append("f " + " ".join("%d//%d" % (v, vn) for v in vs))
    lines = ["# " + c for c in comment] + ["mtllib %s" % mtl_name, "o platform"] + vlines + nlines
    for name in materials:
        lines += ["g %s" % name, "usemtl %s" % name, "s off"] + faces[name]
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


def write_mtl(path, materials, comment):
    lines = ["# " + c for c in comment]
    for name, kd in materials.items():
        lines += ["", "newmtl %s" % name, "Ka 0 0 0", "Kd %g %g %g" % kd, "Ks 0.2 0.2 0.2",
                  "Ns 40", "d 1", "illum 2"]
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


def write_glb(path, mesh, material, nodes, generator="scripts/make-cad-examples.py"):
    """One mesh, one primitive (POSITION, NORMAL, indices), one material; `nodes` as glTF
    nodes (the scene's root is node 0)."""
    positions = [tuple(f32(c) for c in p) for p in mesh.positions]
    normals = [tuple(f32(c) for c in unit(n)) for n in mesh.normals]
    count = len(positions)
    index_type, index_fmt, index_size = (5123, "H", 2) if count < 65535 else (5125, "I", 4)
    indices = [i for tri in mesh.triangles for i in tri]
    blobs = [
        b"".join(struct.pack("<3f", *p) for p in positions),
        b"".join(struct.pack("<3f", *n) for n in normals),
        struct.pack("<%d%s" % (len(indices), index_fmt), *indices),
    ]
    views, binary = [], b""
    for blob, target in zip(blobs, (34962, 34962, 34963)):
        binary += b"\0" * (-len(binary) % 4)
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(blob), "target": target})
        binary += blob
    binary += b"\0" * (-len(binary) % 4)
    gltf = {
        "asset": {"version": "2.0", "generator": generator},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": nodes,
        "meshes": [{"name": mesh_name(nodes), "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0, "mode": 4}]}],
        "materials": [material],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
             "min": [min(p[k] for p in positions) for k in range(3)],
             "max": [max(p[k] for p in positions) for k in range(3)]},
            {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"},
            {"bufferView": 2, "componentType": index_type, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(binary)}],
    }
    text = json.dumps(gltf, separators=(",", ":")).encode("utf-8")
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(binary)
    with open(path, "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, total))
        f.write(struct.pack("<I4s", len(text), b"JSON") + text)
        f.write(struct.pack("<I4s", len(binary), b"BIN\0") + binary)


def mesh_name(nodes):
    return next(n["name"] for n in nodes if "mesh" in n)


def main():
    os.makedirs(OUT, exist_ok=True)
    write_binary_stl(os.path.join(OUT, "base.stl"), base_plate(),
                     "base plate, mm, top face z=0; scripts/make-cad-examples.py")
    comment = ["platform plate, millimetres, bottom face at z = 0, z up",
               "made by scripts/make-cad-examples.py"]
    materials = {"plate": (0.85, 0.45, 0.12), "boss": (0.2, 0.2, 0.22)}
    write_mtl(os.path.join(OUT, "platform.mtl"), materials, comment)
    write_obj(os.path.join(OUT, "platform.obj"), "platform.mtl", platform_plate(), materials, comment)
    write_glb(os.path.join(OUT, "cylinder.glb"), cylinder_body(),
              {"name": "steel", "pbrMetallicRoughness": {
                  "baseColorFactor": [0.55, 0.57, 0.6, 1.0], "metallicFactor": 0.6, "roughnessFactor": 0.4}},
              [{"name": "cylinder", "mesh": 0}])
    write_ascii_stl(os.path.join(OUT, "rod.stl"), piston_rod(), "rod")
    write_glb(os.path.join(OUT, "horn.glb"), servo_horn(),
              {"name": "white plastic", "pbrMetallicRoughness": {
                  "baseColorFactor": [0.92, 0.92, 0.9, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.6}},
              [{"name": "horn", "scale": [0.001, 0.001, 0.001], "children": [1]},
               {"name": "horn_mm", "mesh": 0}])


if __name__ == "__main__":
    main()
