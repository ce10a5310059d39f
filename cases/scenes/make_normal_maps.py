#!/usr/bin/env python3
"""Writes the normal-mapped test scenes next to this script (run it to regenerate them):

normal_tilt.gltf: two 1x1 quads on the ground (y = 0, facing +Y), u along +x, v along +z.
  The left quad's normal map tilts every normal 30 degrees towards +u (normal_tilt_u.png),
  the right one's towards the image's top, i.e. -v (normal_tilt_v.png). Used by
  tests/renderer/normal_map_test.cpp to pin the tangent frame's signs.
normal_bumps.gltf: an 8x8 floor whose UVs repeat a 64x64 map of round bumps (normal_bumps.png)
  once per unit; the case normal_map_bumps shows their speculars under camera motion.
normal_half.gltf: a 2x2 floor whose map (normal_half.png) holds 127 in every channel of its left
  column and 128 in its right; u spans 0.5 +- 2^-12 across the floor, so pixels sample the map
  exactly half way between the two, where a float filter gives 0.5 and the tangent-space normal
  (2t - 1) is exactly 0. Its sampler mirrors (MIRRORED_REPEAT), which lavapipe filters in float
  (it filters 8-bit maps in fixed point only for repeat and clamp). Used by
  tests/renderer/normal_map_test.cpp: the zero normal keeps the surface's.
Only the standard library: PNGs are written with zlib, the buffers as data URIs.
"""
import json
import math
import os
import struct

from gltf_buffers import Buffer
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def png(path, size, texel):
    rows = b""
    for y in range(size):
        rows += b"\x00" + b"".join(bytes(texel(x, y, size)) for x in range(size))

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", size, size, 8, 6, 0, 0, 0)  # 8-bit RGBA
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def encode(n):
    return [max(0, min(255, round((c * 0.5 + 0.5) * 255))) for c in n] + [255]


def tilt(x, y):
    return lambda *_: encode((x, y, math.sqrt(1 - x * x - y * y)))


def bump(x, y, size):
    # A dome of radius 0.4 tile centred in each tile: the normal of a sphere cap, flat outside.
    cx, cy = (x + 0.5) / size - 0.5, (y + 0.5) / size - 0.5
    r2 = cx * cx + cy * cy
    if r2 >= 0.16:
        return encode((0.0, 0.0, 1.0))
    h = math.sqrt(0.16 - r2)
    n = (cx, -cy, h)  # image y grows down; tangent-space +Y is the image's top
    length = math.sqrt(sum(c * c for c in n))
    return encode(tuple(c / length for c in n))


def quad(x0, x1, z0, z1, u1, v1, u0=0):
    # CCW seen from +Y (glTF front face), normal +Y; u along +x, v along +z.
    pos = [(x0, 0, z0), (x0, 0, z1), (x1, 0, z1), (x1, 0, z0)]
    uv = [(u0, 0), (u0, v1), (u1, v1), (u1, 0)]
    return pos, uv, [0, 1, 2, 0, 2, 3]


def gltf(path, quads, materials, images, wrap=10497):
    buf = Buffer()
    add = buf.add
    primitives = []

    for (pos, uv, idx), material in zip(quads, range(len(quads))):
        p = add(b"".join(struct.pack("<3f", *v) for v in pos), 34962, 5126, 4, "VEC3",
                {"min": [min(v[i] for v in pos) for i in range(3)], "max": [max(v[i] for v in pos) for i in range(3)]})
        n = add(struct.pack("<3f", 0, 1, 0) * 4, 34962, 5126, 4, "VEC3")
        t = add(b"".join(struct.pack("<2f", *v) for v in uv), 34962, 5126, 4, "VEC2")
        i = add(struct.pack("<6H", *idx), 34963, 5123, 6, "SCALAR")
        primitives.append({"attributes": {"POSITION": p, "NORMAL": n, "TEXCOORD_0": t}, "indices": i,
                           "material": material})
    doc = {
        "asset": {"version": "2.0", "generator": "cases/scenes/make_normal_maps.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": primitives}],
        "materials": materials,
        "textures": [{"source": i, "sampler": 0} for i in range(len(images))],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": wrap, "wrapT": wrap}],
        "images": [{"uri": name} for name in images],
        "accessors": buf.accessors,
        "bufferViews": buf.views,
        "buffers": buf.buffers(),
    }
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def grey(texture, value=0.6):
    return {"pbrMetallicRoughness": {"baseColorFactor": [value, value, value, 1.0]},
            "normalTexture": {"index": texture}}


s30, c30 = math.sin(math.radians(30)), math.cos(math.radians(30))
png(os.path.join(HERE, "normal_tilt_u.png"), 4, tilt(s30, 0.0))
png(os.path.join(HERE, "normal_tilt_v.png"), 4, tilt(0.0, s30))
gltf(os.path.join(HERE, "normal_tilt.gltf"),
     [quad(-1.1, -0.1, -0.5, 0.5, 1, 1), quad(0.1, 1.1, -0.5, 0.5, 1, 1)],
     [grey(0), grey(1)], ["normal_tilt_u.png", "normal_tilt_v.png"])
png(os.path.join(HERE, "normal_bumps.png"), 64, bump)
gltf(os.path.join(HERE, "normal_bumps.gltf"), [quad(-4, 4, -4, 4, 8, 8)], [grey(0, 0.5)], ["normal_bumps.png"])
png(os.path.join(HERE, "normal_half.png"), 2, lambda x, y, size: [127 + x] * 3 + [255])
gltf(os.path.join(HERE, "normal_half.gltf"), [quad(-1, 1, -1, 1, 0.5 + 2 ** -12, 1, 0.5 - 2 ** -12)],
     [grey(0)], ["normal_half.png"], wrap=33648)
