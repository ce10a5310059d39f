#!/usr/bin/env python3
"""Writes alpha_cutoff_zero.gltf next to this script (run it to regenerate): two MASK quads
with alphaCutoff 0 over a grey floor (case gltf_alpha_cutoff_zero). The left one's texture
(alpha_leaf.png) is fully transparent in its corners, which glTF still draws (alpha >= cutoff
is opaque); the right one's float COLOR_0 alpha runs from -1 (left edge) to 1 (right edge),
so its left half falls below 0 and is cut.
Only the standard library: the buffers are data URIs.
"""
import json
import os
import struct

from gltf_buffers import Buffer

HERE = os.path.dirname(os.path.abspath(__file__))


def quad_xy(uvs, colors=None):
    """A 1x1 quad in the xy plane facing +z, centred on the origin; uvs and colors per corner
    (lower left, lower right, upper right, upper left)."""
    pos = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
    return pos, [(0, 0, 1)] * 4, uvs, colors, [0, 1, 2, 0, 2, 3]


def floor():
    pos = [(-3, 0, 3), (3, 0, 3), (3, 0, -3), (-3, 0, -3)]
    return pos, [(0, 1, 0)] * 4, [(0, 0), (1, 0), (1, 1), (0, 1)], None, [0, 1, 2, 0, 2, 3]


def write(name, meshes, nodes, materials, textures, images):
    buf = Buffer()
    add = buf.add
    gltf_meshes = []

    for (pos, normals, uvs, colors, idx), material in meshes:
        attrs = {
            "POSITION": add(b"".join(struct.pack("<3f", *v) for v in pos), 34962, 5126, 4, "VEC3",
                            {"min": [min(v[i] for v in pos) for i in range(3)],
                             "max": [max(v[i] for v in pos) for i in range(3)]}),
            "NORMAL": add(b"".join(struct.pack("<3f", *v) for v in normals), 34962, 5126, 4, "VEC3"),
            "TEXCOORD_0": add(b"".join(struct.pack("<2f", *v) for v in uvs), 34962, 5126, 4, "VEC2"),
        }
        if colors:
            attrs["COLOR_0"] = add(b"".join(struct.pack("<4f", *c) for c in colors), 34962, 5126, 4, "VEC4")
        i = add(struct.pack("<6H", *idx), 34963, 5123, 6, "SCALAR")
        gltf_meshes.append({"primitives": [{"attributes": attrs, "indices": i, "material": material}]})
    doc = {
        "asset": {"version": "2.0", "generator": "cases/scenes/make_alpha_cutoff_zero.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": gltf_meshes,
        "materials": materials,
        "textures": textures,
        "samplers": [{"magFilter": 9728, "minFilter": 9728}],
        "images": [{"uri": i} for i in images],
        "accessors": buf.accessors,
        "bufferViews": buf.views,
        "buffers": buf.buffers(),
    }
    with open(os.path.join(HERE, name), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


grey = {"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0]}}
ramp = [(1, 1, 1, -1), (1, 1, 1, 1), (1, 1, 1, 1), (1, 1, 1, -1)]
write("alpha_cutoff_zero.gltf",
      [(quad_xy([(0, 1), (1, 1), (1, 0), (0, 0)]), 0), (quad_xy([(0, 0)] * 4, ramp), 1), (floor(), 2)],
      [{"mesh": 0, "translation": [-0.7, 0.6, 0]}, {"mesh": 1, "translation": [0.7, 0.6, 0]}, {"mesh": 2}],
      [{"alphaMode": "MASK", "alphaCutoff": 0.0, "doubleSided": True,
        "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
       {"alphaMode": "MASK", "alphaCutoff": 0.0, "doubleSided": True,
        "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.5, 0.2, 1.0]}}, grey],
      [{"source": 0, "sampler": 0}], ["alpha_leaf.png"])
