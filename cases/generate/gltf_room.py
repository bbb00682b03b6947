#!/usr/bin/env python3
"""Writes the glTF dining room, cases/gltf-room.toml, and its furniture, a glTF 2.0 file
cases/gltf-room/furniture.gltf with its buffer furniture.bin and its texture wood.png.

    python3 cases/generate/gltf_room.py           # write every file
    python3 cases/generate/gltf_room.py --check   # compare the committed files; write nothing

A 5 x 4 x 2.8 m room lit by two batwing downlights (office-downlight.ies, 3,400 lm) holds
a dining table with four chairs and a round side table, all from one glTF file (metres, y
up): the chair is one mesh placed by four nodes (moved and turned about y); boxes are a
triangle list (the table top, the seats) or a triangle strip round their sides with two
triangle fans for their top and bottom (legs, backs), the round top a strip and two fans.
Materials: "oak" (base colour factor 1 times the 8 x 8 sRGB texture wood.png: ugo
averages it), "fabric" (a base colour), "steel" (mapped to the case's "metal"). Standard
library only (the PNG written with zlib and struct), deterministic.
"""

import argparse
import base64
import json
import math
import os
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.dirname(HERE)
FOLDER = "gltf-room"

LIST, STRIP, FAN = 4, 5, 6
OAK, FABRIC, STEEL = 0, 1, 2


# --- The texture -------------------------------------------------------------------------

def wood_texels():
    """8 x 8 sRGB texels: brown grain, darker every third row."""
    rows = []
    for y in range(8):
        shade = 0.8 if y % 3 == 0 else 1.0
        rows.append([tuple(round(c * shade * (1.0 - 0.05 * ((x + y) % 2))) for c in (168, 118, 72))
                     for x in range(8)])
    return rows


def png(rows):
    """An 8-bit RGB PNG of `rows` (filter 0 on every row)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    height, width = len(rows), len(rows[0])
    raw = b"".join(b"\0" + bytes(c for texel in row for c in texel) for row in rows)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9))
            + chunk(b"IEND", b""))


def linear(c):
    c /= 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def texture_reflectance(rows):
    """The luminance of the texels' mean linear colour (what ugo gives "oak")."""
    texels = [t for row in rows for t in row]
    mean = [sum(linear(t[c]) for t in texels) / len(texels) for c in range(3)]
    return 0.2126 * mean[0] + 0.7152 * mean[1] + 0.0722 * mean[2]


# --- Geometry: primitives as (material, mode, positions, indices) --------------------------

def corners(lo, hi):
    """The eight corners of the box lo..hi, corner x + 2y + 4z at (x, y, z)."""
    return [[(lo, hi)[(i >> a) & 1][a] for a in range(3)] for i in range(8)]


def box_list(material, lo, hi):
    """A box as one triangle list, counter-clockwise seen from outside."""
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3]]
    indices = [i for a, b, c, d in quads for i in (a, b, c, a, c, d)]
    return [(material, LIST, corners(lo, hi), indices)]


def prism(material, bottom, top):
    """A closed prism between the rings `bottom` and `top` (counter-clockwise seen from
    above, +y): a strip round its sides, a fan for its top and one for its bottom."""
    n = len(bottom)
    band = [i for k in list(range(n)) + [0] for i in (n + k, k)]
    return [(material, STRIP, bottom + top, band),
            (material, FAN, bottom + top, [n + k for k in range(n)]),
            (material, FAN, bottom + top, list(reversed(range(n))))]


def box_strip(material, lo, hi):
    """A box as a prism: its four sides one strip, its top and bottom two fans."""
    ring = [(lo[0], lo[2]), (lo[0], hi[2]), (hi[0], hi[2]), (hi[0], lo[2])]
    return prism(material, [[x, lo[1], z] for x, z in ring], [[x, hi[1], z] for x, z in ring])


def cylinder(material, radius, y0, y1, segments=24):
    ring = [(radius * math.cos(-2 * math.pi * k / segments), radius * math.sin(-2 * math.pi * k / segments))
            for k in range(segments)]
    return prism(material, [[x, y0, z] for x, z in ring], [[x, y1, z] for x, z in ring])


def legs(material, x, z, size, height):
    """Four square legs at (+-x, +-z)."""
    s = size / 2
    return [p for sx in (-x, x) for sz in (-z, z)
            for p in box_strip(material, [sx - s, 0, sz - s], [sx + s, height, sz + s])]


def table():
    return box_list(OAK, [-0.8, 0.72, -0.45], [0.8, 0.76, 0.45]) + legs(STEEL, 0.74, 0.39, 0.05, 0.72)


def chair():
    """Facing +z (its back at z = -0.2)."""
    return (box_list(FABRIC, [-0.22, 0.42, -0.22], [0.22, 0.46, 0.22])
            + box_strip(FABRIC, [-0.22, 0.46, -0.24], [0.22, 0.9, -0.2])
            + legs(STEEL, 0.19, 0.19, 0.03, 0.42))


def side_table():
    return (cylinder(OAK, 0.3, 0.6, 0.63) + box_strip(STEEL, [-0.03, 0.03, -0.03], [0.03, 0.6, 0.03])
            + cylinder(STEEL, 0.2, 0.0, 0.03))


def triangles(mode, indices):
    """The glTF 2.0 specification's triangles of a list, strip or fan."""
    n = len(indices)
    if mode == LIST:
        return [indices[i:i + 3] for i in range(0, n, 3)]
    if mode == STRIP:
        return [[indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]] for i in range(n - 2)]
    return [[indices[i + 1], indices[i + 2], indices[0]] for i in range(n - 2)]


def check_outward(name, primitives):
    """Every triangle faces away from the centre of its primitive's vertices."""
    for _, mode, positions, indices in primitives:
        centre = [sum(p[a] for p in positions) / len(positions) for a in range(3)]
        for a, b, c in triangles(mode, indices):
            pa, pb, pc = positions[a], positions[b], positions[c]
            u = [pb[k] - pa[k] for k in range(3)]
            v = [pc[k] - pa[k] for k in range(3)]
            normal = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            out = [(pa[k] + pb[k] + pc[k]) / 3 - centre[k] for k in range(3)]
            assert sum(normal[k] * out[k] for k in range(3)) > 0, f"{name}: a triangle faces inwards"


# --- The glTF file -------------------------------------------------------------------------

def quaternion_y(degrees):
    half = math.radians(degrees) / 2
    return [0.0, round(math.sin(half), 9), 0.0, round(math.cos(half), 9)]


def gltf(meshes):
    """The JSON and the buffer of `meshes` (name, primitives)."""
    buffer, views, accessors, out = bytearray(), [], [], []

    def accessor(data, component, kind, count, extra):
        views.append({"buffer": 0, "byteOffset": len(buffer), "byteLength": len(data)})
        buffer.extend(data + b"\0" * (-len(data) % 4))
        accessors.append({"bufferView": len(views) - 1, "componentType": component, "count": count,
                          "type": kind, **extra})
        return len(accessors) - 1

    for name, primitives in meshes:
        check_outward(name, primitives)
        listed = []
        for material, mode, positions, indices in primitives:
            floats = struct.pack(f"<{3 * len(positions)}f", *[x for p in positions for x in p])
            bounds = {"min": [min(p[a] for p in positions) for a in range(3)],
                      "max": [max(p[a] for p in positions) for a in range(3)]}
            where = accessor(floats, 5126, "VEC3", len(positions), bounds)
            order = accessor(struct.pack(f"<{len(indices)}H", *indices), 5123, "SCALAR", len(indices), {})
            listed.append({"attributes": {"POSITION": where}, "indices": order, "material": material,
                           "mode": mode})
        out.append({"name": name, "primitives": listed})
    chairs = [("chair north", [2.5, 0, 1.2], 0), ("chair south", [2.5, 0, 2.8], 180),
              ("chair west", [1.45, 0, 2.0], 90), ("chair east", [3.55, 0, 2.0], -90)]
    nodes = [{"name": "dining", "children": [1, 2, 3, 4, 5]},
             {"name": "table", "mesh": 0, "translation": [2.5, 0, 2.0]}]
    nodes += [{"name": n, "mesh": 1, "translation": t, "rotation": quaternion_y(a)} for n, t, a in chairs]
    nodes.append({"name": "side table", "mesh": 2, "translation": [4.4, 0, 0.6]})
    document = {
        "asset": {"version": "2.0", "generator": "ugo cases/generate/gltf_room.py"},
        "scene": 0,
        "scenes": [{"name": "dining room", "nodes": [0, 6]}],
        "nodes": nodes,
        "meshes": out,
        "materials": [
            {"name": "oak", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1],
                                                     "baseColorTexture": {"index": 0}}},
            {"name": "fabric", "pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.35, 0.55, 1]}},
            {"name": "steel", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1],
                                                       "metallicFactor": 1}},
        ],
        "textures": [{"source": 0}],
        "images": [{"name": "wood", "uri": "wood.png"}],
        "buffers": [{"byteLength": len(buffer), "uri": "furniture.bin"}],
        "bufferViews": views,
        "accessors": accessors,
    }
    return json.dumps(document, indent=1) + "\n", bytes(buffer)


# --- The case ------------------------------------------------------------------------------

def vec(a):
    return "[" + ", ".join(f"{x:g}" for x in a) + "]"


def case(oak, triangle_count, size):
    def rect(name, material, o, u, v):
        return (f'[[surface]]\nname = "{name}"\nshape = "rectangle"\nmaterial = "{material}"\n'
                f"origin = {vec(o)}\nedge_u = {vec(u)}\nedge_v = {vec(v)}\n\n")

    def probe(name, p, n):
        return f'[[probe]]\nname = "{name}"\nposition = {vec(p)}\nnormal = {vec(n)}\n\n'

    def material(name, rho):
        return f'[[material]]\nname = "{name}"\ntype = "lambert"\nreflectance = {rho}\n\n'

    def downlight(n, x):
        return (f'[[luminaire]]\nname = "downlight {n}"\ntype = "ies"\nfile = "office-downlight.ies"\n'
                f"position = [{x}, 2.79, 2]\n\n")

    head = f"""# A 5 x 4 x 2.8 m dining room whose furniture is one glTF 2.0 file (issue 38, point 4):
# a table with four chairs and a round side table in gltf-room/furniture.gltf (its
# buffer furniture.bin, its texture wood.png; {size:,} bytes in all), {triangle_count} triangles
# read from triangle lists, strips and fans; the chair is one mesh placed by four nodes.
# Its materials: "oak" has the 8 x 8 texture wood.png, averaged to one reflectance (the
# luminance of its mean linear colour, rho = {oak:.4f}, said in a warning); "fabric" is a
# Lambert material of its base colour's luminance; "steel" is mapped to "metal". Two
# batwing downlights (office-downlight.ies, 3,400 lm each) 1 cm below the ceiling.
# Probes on the table, a seat, the side table, the floor, the walls and the ceiling; one
# camera. Checked against `ugo trace` in docs/scene-format.md ("glTF 2.0 meshes").
#
# Generated by `python3 cases/generate/gltf_room.py` (do not edit: edit the script and rerun it).

[scene]
name = "gltf-room"
description = "5 x 4 x 2.8 m dining room, glTF furniture (strips, fans, a texture), 2 downlights"

[discretization]
patch_size = 0.15
kernel = "hierarchical"
root_size = 1
link_tolerance = 0.01

[solver]
tolerance = 1e-6

"""
    text = head + material("floor", 0.2) + material("ceiling", 0.8) + material("wall", 0.6)
    text += material("metal", 0.35)
    text += rect("floor", "floor", [0, 0, 0], [0, 0, 4], [5, 0, 0])
    text += rect("ceiling", "ceiling", [0, 2.8, 0], [5, 0, 0], [0, 0, 4])
    text += rect("wall x = 0", "wall", [0, 0, 0], [0, 2.8, 0], [0, 0, 4])
    text += rect("wall x = 5", "wall", [5, 0, 0], [0, 0, 4], [0, 2.8, 0])
    text += rect("wall z = 0", "wall", [0, 0, 0], [5, 0, 0], [0, 2.8, 0])
    text += rect("wall z = 4", "wall", [0, 0, 4], [0, 2.8, 0], [5, 0, 0])
    text += ('[[surface]]\nname = "furniture"\nshape = "mesh"\nfile = "gltf-room/furniture.gltf"\n'
             'material = "metal"\nmaterials = { steel = "metal" }\n\n')
    text += downlight(1, 1.75) + downlight(2, 3.25)
    text += probe("table, centre", [2.5, 0.76, 2], [0, 1, 0])
    text += probe("table, corner", [3.1, 0.76, 2.3], [0, 1, 0])
    text += probe("seat, chair south", [2.5, 0.46, 2.85], [0, 1, 0])
    text += probe("side table", [4.4, 0.63, 0.6], [0, 1, 0])
    text += probe("floor, open", [1, 0, 3.5], [0, 1, 0])
    text += probe("floor, under the table", [2.5, 0, 2], [0, 1, 0])
    text += probe("wall x = 0", [0, 1.5, 2], [1, 0, 0])
    text += probe("wall z = 4", [2.5, 1.5, 4], [0, 0, -1])
    text += probe("ceiling, centre", [2.5, 2.8, 2], [0, -1, 0])
    text += ('[[camera]]\nname = "room"\nposition = [4.7, 1.6, 3.7]\nlook_at = [2.2, 0.5, 1.6]\nfov_deg = 70\n'
             "resolution = [640, 480]\n")
    return text


def files():
    rows = wood_texels()
    picture = png(rows)
    meshes = [("table", table()), ("chair", chair()), ("side table", side_table())]
    text, buffer = gltf(meshes)
    placed = {"table": 1, "chair": 4, "side table": 1}
    count = sum(placed[name] * len(triangles(m, i)) for name, prims in meshes for _, m, _, i in prims)
    size = len(text) + len(buffer) + len(picture)
    return {
        f"{FOLDER}/wood.png": picture,
        f"{FOLDER}/furniture.bin": buffer,
        f"{FOLDER}/furniture.gltf": text.encode(),
        "gltf-room.toml": case(texture_reflectance(rows), count, size).encode(),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true", help="compare the committed files; write nothing")
    args = parser.parse_args()
    stale = []
    os.makedirs(os.path.join(OUT, FOLDER), exist_ok=True)
    for name, data in files().items():
        path = os.path.join(OUT, name)
        if args.check:
            with open(path, "rb") as f:
                if f.read() != data:
                    stale.append(name)
        else:
            with open(path, "wb") as f:
                f.write(data)
    if stale:
        sys.exit("stale: " + ", ".join(stale) + " (run python3 cases/generate/gltf_room.py)")


if __name__ == "__main__":
    main()
