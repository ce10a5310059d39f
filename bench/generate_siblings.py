#!/usr/bin/env python3
"""A glTF of N sibling nodes that share one mesh, and a case that renders it, to measure that
loading and rendering cost grows with the data and not with an overhead per node
(docs/performance.md, docs/trust.md).

The mesh is a unit box (24 vertices, 12 triangles, one material); node i sits on a square grid,
so the whole scene is in view of the case's camera. Everything is a function of N.

  python3 bench/generate_siblings.py --out /tmp/siblings --nodes 100000
  /usr/bin/time -v build/harness/taa-harness render /tmp/siblings/siblings.json --out /tmp/o
"""
import argparse
import base64
import json
import math
import struct
from pathlib import Path


def box() -> bytes:
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u, v = (axis + 1) % 3, (axis + 2) % 3
            base = len(positions)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = 0.5 * sign, 0.5 * a, 0.5 * b
                positions.append(p)
                normals.append(n)
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            indices += [base + k for k in quad]
    data = b"".join(struct.pack("<3f", *p) for p in positions)
    data += b"".join(struct.pack("<3f", *n) for n in normals)
    data += b"".join(struct.pack("<H", i) for i in indices)
    return data


def gltf(nodes: int) -> dict:
    data = box()
    side = math.ceil(math.sqrt(nodes))
    spacing = 1.5
    node_list = []
    for i in range(nodes):
        x, z = i % side, i // side
        node_list.append({"mesh": 0, "translation": [round((x - (side - 1) / 2) * spacing, 3), 0.5,
                                                      round((z - (side - 1) / 2) * spacing, 3)]})
    return {
        "asset": {"version": "2.0", "generator": "bench/generate_siblings.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(nodes))}],
        "nodes": node_list,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2,
                                    "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.5, 0.3, 1.0],
                                                "metallicFactor": 0.0}}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 24, "type": "VEC3",
             "min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
            {"bufferView": 1, "componentType": 5126, "count": 24, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": 36, "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 288},
            {"buffer": 0, "byteOffset": 288, "byteLength": 288},
            {"buffer": 0, "byteOffset": 576, "byteLength": 72},
        ],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    }


def case(nodes: int, frames: int) -> dict:
    extent = math.ceil(math.sqrt(nodes)) * 1.5
    return {
        "description": f"{nodes} sibling nodes sharing one box (bench/generate_siblings.py)",
        "scene": {"gltf": "siblings.gltf"},
        "render": {"width": 320, "height": 180},
        "camera": {"position": [0.0, extent * 0.6, extent * 0.8], "target": [0.0, 0.0, 0.0]},
        "script": {"frames": frames},
        "output": {"frames": [frames - 1]},
        "checks": {"golden": False, "invariants": ["finite"]},
    }


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True, help="folder for siblings.gltf and siblings.json")
    p.add_argument("--nodes", type=int, default=100000)
    p.add_argument("--frames", type=int, default=4)
    a = p.parse_args()
    if a.nodes < 1 or a.frames < 1:
        p.error("--nodes and --frames must be at least 1")
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "siblings.gltf").write_text(json.dumps(gltf(a.nodes), separators=(",", ":")))
    (out / "siblings.json").write_text(json.dumps(case(a.nodes, a.frames), indent=2) + "\n")


if __name__ == "__main__":
    main()
