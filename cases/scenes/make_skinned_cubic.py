#!/usr/bin/env python3
"""Writes skinned_bend_cubic.gltf next to this script (run it to regenerate it).

A ribbon lying flat (y = 0, facing +Y) along x in [-1.2, 1.2], skinned to two joints at the
origin: the left part follows `root`, the right part `bend`, with a linear blend for |x| < 0.25.
`bend` turns about +Z, so the right half rises and its normals turn from +Y towards -X: under
the case's light (travelling down and towards -x) the raised half darkens as it bends, which
it would not if skinning moved the positions and left the normals as they were. One morph
target lifts a bump at x = -0.6.

Every animation is CUBICSPLINE with in-tangents that differ from out-tangents at every key
(rotation of `bend`, translation of `root`, the mesh's morph weight), so a spline that takes
the wrong tangent, or forgets to scale them by the key interval, moves the ribbon.
Only the standard library; the buffer is a data URI.
"""
import base64
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
COLUMNS = 13  # vertices along x
X0, X1, HALF_WIDTH = -1.2, 1.2, 0.35


def ribbon():
    positions, normals, joints, weights, bump = [], [], [], [], []
    for i in range(COLUMNS):
        x = X0 + (X1 - X0) * i / (COLUMNS - 1)
        w1 = min(1.0, max(0.0, (x + 0.25) / 0.5))  # weight of `bend`
        for z in (-HALF_WIDTH, HALF_WIDTH):
            positions.append((x, 0.0, z))
            normals.append((0.0, 1.0, 0.0))
            joints.append((0, 1, 0, 0))
            weights.append((1.0 - w1, w1, 0.0, 0.0))
            bump.append((0.0, 0.3 * max(0.0, 1.0 - abs(x + 0.6) / 0.4), 0.0))
    indices = []
    for i in range(COLUMNS - 1):
        a, b, c, d = 2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 3
        indices += [a, b, c, c, b, d]  # counter-clockwise seen from +Y
    return positions, normals, joints, weights, bump, indices


def quat_z(degrees):
    h = math.radians(degrees) / 2
    return (0.0, 0.0, math.sin(h), math.cos(h))


TIMES = [0.0, 0.25, 0.5]
# (in-tangent, value, out-tangent) per key, in the order glTF stores them.
ROTATION = [
    ((0.0, 0.0, -0.5, 0.0), quat_z(0.0), (0.0, 0.0, 2.0, -0.3)),
    ((0.0, 0.0, 1.6, -0.6), quat_z(55.0), (0.0, 0.0, -1.2, 0.4)),
    ((0.0, 0.0, -0.8, 0.2), quat_z(20.0), (0.0, 0.0, 0.9, 0.0)),
]
TRANSLATION = [
    ((0.1, 0.0, 0.0), (0.0, 0.0, 0.0), (1.2, 0.8, 0.0)),
    ((0.9, -0.6, 0.0), (0.15, 0.1, 0.0), (-0.4, 0.5, 0.3)),
    ((0.6, -0.3, 0.0), (0.3, 0.0, 0.0), (0.0, 0.0, 0.0)),
]
WEIGHTS = [((0.5,), (0.0,), (4.0,)), ((3.0,), (0.8,), (-2.5,)), ((-1.0,), (0.3,), (0.0,))]


class Buffer:
    def __init__(self):
        self.data, self.views, self.accessors = b"", [], []

    def add(self, fmt, rows, gltf_type, component, minmax=False):
        while len(self.data) % 4:
            self.data += b"\0"
        start = len(self.data)
        for row in rows:
            self.data += struct.pack("<" + fmt * len(row), *row)
        self.views.append({"buffer": 0, "byteOffset": start, "byteLength": len(self.data) - start})
        acc = {"bufferView": len(self.views) - 1, "componentType": component, "count": len(rows),
               "type": gltf_type}
        if minmax:
            acc["min"] = [min(r[k] for r in rows) for k in range(len(rows[0]))]
            acc["max"] = [max(r[k] for r in rows) for k in range(len(rows[0]))]
        self.accessors.append(acc)
        return len(self.accessors) - 1


def keyed(rows):
    return [part for key in rows for part in key]


def main():
    positions, normals, joints, weights, bump, indices = ribbon()
    b = Buffer()
    pos = b.add("f", positions, "VEC3", 5126, minmax=True)
    nrm = b.add("f", normals, "VEC3", 5126)
    jnt = b.add("B", joints, "VEC4", 5121)
    wgt = b.add("f", weights, "VEC4", 5126)
    bmp = b.add("f", bump, "VEC3", 5126, minmax=True)
    idx = b.add("H", [(i,) for i in indices], "SCALAR", 5123)
    ibm = b.add("f", [(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)] * 2, "MAT4", 5126)
    times = b.add("f", [(t,) for t in TIMES], "SCALAR", 5126, minmax=True)
    rot = b.add("f", keyed(ROTATION), "VEC4", 5126)
    tra = b.add("f", keyed(TRANSLATION), "VEC3", 5126)
    wts = b.add("f", keyed(WEIGHTS), "SCALAR", 5126)
    gltf = {
        "asset": {"version": "2.0", "generator": "cases/scenes/make_skinned_cubic.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"name": "ribbon", "mesh": 0, "skin": 0},
            {"name": "root", "children": [2]},
            {"name": "bend"},
        ],
        "skins": [{"joints": [1, 2], "inverseBindMatrices": ibm}],
        "materials": [{"name": "ribbon", "doubleSided": True,
                       "pbrMetallicRoughness": {"baseColorFactor": [0.55, 0.5, 0.4, 1.0]}}],
        "meshes": [{"name": "ribbon", "weights": [0.0], "primitives": [{
            "attributes": {"POSITION": pos, "NORMAL": nrm, "JOINTS_0": jnt, "WEIGHTS_0": wgt},
            "targets": [{"POSITION": bmp}], "indices": idx, "material": 0}]}],
        "animations": [{"name": "bend", "samplers": [
            {"input": times, "output": rot, "interpolation": "CUBICSPLINE"},
            {"input": times, "output": tra, "interpolation": "CUBICSPLINE"},
            {"input": times, "output": wts, "interpolation": "CUBICSPLINE"}],
            "channels": [
                {"sampler": 0, "target": {"node": 2, "path": "rotation"}},
                {"sampler": 1, "target": {"node": 1, "path": "translation"}},
                {"sampler": 2, "target": {"node": 0, "path": "weights"}}]}],
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": [{"byteLength": len(b.data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(b.data).decode()}],
    }
    with open(os.path.join(HERE, "skinned_bend_cubic.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
