#!/usr/bin/env python3
"""Writes the small glTF test assets under cases/scenes/ (standard library only).

Run from the repository root: python3 tests/scene/assets_src/make_assets.py
The output is deterministic; rerun after editing and commit the results.
"""
import base64
import json
import math
import os
import struct
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")
OUT = os.path.normpath(os.path.join(ROOT, "cases", "scenes"))


def png(width, height, rgba_rows):
    """Encodes 8-bit RGBA rows (lists of (r, g, b, a)) as a PNG."""
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rgba_rows)

    def chunk(tag, data):
        body = tag + data
        crc = struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
        return struct.pack(">I", len(data)) + body + crc

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) +
            chunk(b"IEND", b""))


def checker_png(w, h, a, b, cell):
    rows = [[a if ((x // cell) + (y // cell)) % 2 == 0 else b for x in range(w)] for y in range(h)]
    return png(w, h, rows)


def disc_png(size):
    """Opaque green disc on transparent texels: an alpha-mask leaf stand-in."""
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            dx, dy = x + 0.5 - size / 2, y + 0.5 - size / 2
            inside = dx * dx + dy * dy <= (size * 0.4) ** 2
            row.append((60, 140, 50, 255) if inside else (60, 140, 50, 0))
        rows.append(row)
    return png(size, size, rows)


def box_geometry(with_normals=True, with_uvs=True):
    """Unit cube (+-0.5): 24 vertices, outward counter-clockwise faces."""
    faces = [((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
             ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
             ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1))]
    pos, nrm, uv, idx = [], [], [], []
    for n, r, u in faces:
        base = len(pos)
        for sr, su, tc in ((-1, -1, (0, 1)), (1, -1, (1, 1)), (1, 1, (1, 0)), (-1, 1, (0, 0))):
            pos.append(tuple(0.5 * n[i] + 0.5 * sr * r[i] + 0.5 * su * u[i] for i in range(3)))
            nrm.append(n)
            uv.append(tc)
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, (nrm if with_normals else None), (uv if with_uvs else None), idx


class Builder:
    """Accumulates one binary buffer with buffer views and accessors."""

    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors = [], []

    def _view(self, blob, target=None):
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(blob)}
        if target:
            view["target"] = target
        self.data += blob
        self.views.append(view)
        return len(self.views) - 1

    def floats(self, rows, kind, minmax=False):
        comps = len(rows[0]) if isinstance(rows[0], tuple) else 1
        flat = [c for r in rows for c in (r if comps > 1 else (r,))]
        view = self._view(struct.pack("<%df" % len(flat), *flat))
        acc = {"bufferView": view, "componentType": 5126, "count": len(rows), "type": kind}
        if minmax:
            acc["min"] = [min(r[i] for r in rows) for i in range(comps)]
            acc["max"] = [max(r[i] for r in rows) for i in range(comps)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def indices(self, idx):
        view = self._view(struct.pack("<%dH" % len(idx), *idx), 34963)
        self.accessors.append(
            {"bufferView": view, "componentType": 5123, "count": len(idx), "type": "SCALAR"})
        return len(self.accessors) - 1

    def image_view(self, blob):
        return self._view(blob)

    def mesh(self, geometry, material):
        pos, nrm, uv, idx = geometry
        attrs = {"POSITION": self.floats(pos, "VEC3", minmax=True)}
        if nrm:
            attrs["NORMAL"] = self.floats(nrm, "VEC3")
        if uv:
            attrs["TEXCOORD_0"] = self.floats(uv, "VEC2")
        prim = {"attributes": attrs, "indices": self.indices(idx), "material": material}
        return {"primitives": [prim]}


def data_uri(mime, blob):
    return "data:%s;base64,%s" % (mime, base64.b64encode(blob).decode("ascii"))


def embedded(data):
    return data_uri("application/octet-stream", bytes(data))


def write(name, doc):
    path = os.path.join(OUT, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(doc, f, indent=1, sort_keys=True)
        f.write("\n")


def write_glb(name, doc, binary):
    while len(binary) % 4:
        binary.append(0)
    text = json.dumps(doc, sort_keys=True).encode()
    text += b" " * ((4 - len(text) % 4) % 4)
    body = (struct.pack("<II", len(text), 0x4E4F534A) + text +
            struct.pack("<II", len(binary), 0x004E4942) + binary)
    path = os.path.join(OUT, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)


ASSET = {"version": "2.0", "generator": "tests/scene/assets_src/make_assets.py"}


def textured_box():
    """Textured box in a small hierarchy: TRS parent, rotated child, matrix node."""
    b = Builder()
    mesh = b.mesh(box_geometry(), 0)
    tex = checker_png(16, 16, (240, 240, 240, 255), (30, 60, 200, 255), 4)
    s = math.sqrt(0.5)
    # Matrix node: translate (0, 3, 0) after rotating 90 degrees about +X (column-major).
    matrix = [1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 3, 0, 1]
    write("textured_box.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [
            {"name": "root", "translation": [1, 0, 0], "scale": [2, 2, 2], "children": [1, 2]},
            {"name": "box", "mesh": 0, "rotation": [0, s, 0, s]},
            {"name": "lifted", "matrix": matrix, "children": [3]},
            {"name": "box2", "mesh": 0, "translation": [0, 0, 1]},
        ],
        "meshes": [dict(mesh, name="box")],
        "materials": [{"name": "checker", "pbrMetallicRoughness": {
            "baseColorFactor": [1, 0.5, 0.5, 1], "baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"wrapS": 33071, "wrapT": 33071}],
        "images": [{"uri": data_uri("image/png", tex)}],
        "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
        "bufferViews": b.views, "accessors": b.accessors,
    })


def glb_box():
    """Binary box without normals or uvs (flat normals are generated) and a 5x3 image."""
    b = Builder()
    mesh = b.mesh(box_geometry(with_normals=False, with_uvs=False), 0)
    view = b.image_view(checker_png(5, 3, (255, 0, 0, 255), (0, 0, 255, 255), 1))
    while len(b.data) % 4:
        b.data.append(0)
    doc = {"asset": ASSET, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": [{"name": "glb_box", "mesh": 0}], "meshes": [dict(mesh, name="glb_box")],
           "materials": [{"name": "red",
                          "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
           "textures": [{"source": 0}], "images": [{"bufferView": view, "mimeType": "image/png"}],
           "buffers": [{"byteLength": len(b.data)}], "bufferViews": b.views,
           "accessors": b.accessors}
    write_glb("box.glb", doc, b.data)


def animated():
    """A spinning, sliding box with a bouncing child; the buffer is an external .bin file."""
    b = Builder()
    mesh = b.mesh(box_geometry(), 0)
    s = math.sqrt(0.5)
    t_lin = b.floats([0.0, 1.0, 2.0], "SCALAR", minmax=False)
    b.accessors[t_lin]["min"], b.accessors[t_lin]["max"] = [0.0], [2.0]
    v_tr = b.floats([(0, 0, 0), (2, 0, 0), (2, 2, 0)], "VEC3")
    t_rot = b.floats([0.0, 2.0], "SCALAR")
    b.accessors[t_rot]["min"], b.accessors[t_rot]["max"] = [0.0], [2.0]
    v_rot = b.floats([(0, 0, 0, 1), (0, s, 0, s)], "VEC4")
    t_step = b.floats([0.0, 1.0], "SCALAR")
    b.accessors[t_step]["min"], b.accessors[t_step]["max"] = [0.0], [1.0]
    v_scale = b.floats([(1, 1, 1), (2, 2, 2)], "VEC3")
    # Cubic spline: per key in-tangent, value, out-tangent.
    v_cubic = b.floats([(0, 0, 0), (0, 0, 0), (0, 1, 0), (0, 0, 0), (0, 2, 0), (0, 0, 0)], "VEC3")
    with open(os.path.join(OUT, "animated.bin"), "wb") as f:
        f.write(bytes(b.data))
    write("animated.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "spinner", "mesh": 0, "children": [1]},
                  {"name": "bouncer", "mesh": 0, "scale": [0.25, 0.25, 0.25]}],
        "meshes": [dict(mesh, name="anim_box")],
        "materials": [{"name": "orange",
                       "pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.1, 1]}}],
        "animations": [{"name": "move", "samplers": [
            {"input": t_lin, "output": v_tr, "interpolation": "LINEAR"},
            {"input": t_rot, "output": v_rot, "interpolation": "LINEAR"},
            {"input": t_step, "output": v_scale, "interpolation": "STEP"},
            {"input": t_rot, "output": v_cubic, "interpolation": "CUBICSPLINE"}],
            "channels": [
                {"sampler": 0, "target": {"node": 0, "path": "translation"}},
                {"sampler": 1, "target": {"node": 0, "path": "rotation"}},
                {"sampler": 2, "target": {"node": 0, "path": "scale"}},
                {"sampler": 3, "target": {"node": 1, "path": "translation"}}]}],
        "buffers": [{"byteLength": len(b.data), "uri": "animated.bin"}],
        "bufferViews": b.views, "accessors": b.accessors,
    })


def quad_geometry():
    pos = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
    return pos, [(0, 0, 1)] * 4, [(0, 1), (1, 1), (1, 0), (0, 0)], [0, 1, 2, 0, 2, 3]


def alpha_modes():
    """An alpha-tested leaf (external PNG next to the file), a blended pane, an opaque floor."""
    with open(os.path.join(OUT, "alpha_leaf.png"), "wb") as f:
        f.write(disc_png(8))
    b = Builder()
    meshes = [dict(b.mesh(quad_geometry(), m), name=n)
              for m, n in ((0, "leaf"), (1, "pane"), (2, "floor"))]
    write("alpha_modes.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"name": "leaf", "mesh": 0, "translation": [-1, 0.5, 0]},
                  {"name": "pane", "mesh": 1, "translation": [1, 0.5, 0]},
                  {"name": "floor", "mesh": 2, "rotation": [-math.sqrt(0.5), 0, 0, math.sqrt(0.5)],
                   "scale": [4, 4, 1]}],
        "meshes": meshes,
        "materials": [
            {"name": "leaf_mask", "alphaMode": "MASK", "alphaCutoff": 0.3, "doubleSided": True,
             "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
            {"name": "glass_blend", "alphaMode": "BLEND",
             "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.9, 0.5]}},
            {"name": "floor_opaque",
             "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1]}}],
        "textures": [{"source": 0}],
        "images": [{"uri": "alpha_leaf.png"}],
        "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
        "bufferViews": b.views, "accessors": b.accessors,
    })


def refused():
    """Files the loader must refuse, each with one bad uri (under refused/)."""
    b = Builder()
    mesh = b.mesh(quad_geometry(), 0)
    length = len(b.data)

    def doc(buffer_uri, image_uri=None):
        d = {"asset": ASSET, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
             "meshes": [mesh], "materials": [{}],
             "buffers": [{"byteLength": length, "uri": buffer_uri}],
             "bufferViews": b.views, "accessors": b.accessors}
        if image_uri:
            d["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
            d["textures"] = [{"source": 0}]
            d["images"] = [{"uri": image_uri}]
        return d

    inline = data_uri("application/octet-stream", bytes(b.data))
    write("refused/external_http.gltf", doc("http://example.com/quad.bin"))
    write("refused/file_scheme.gltf", doc("file:///etc/hostname"))
    write("refused/absolute_path.gltf", doc("/etc/hostname"))
    write("refused/parent_dir.gltf", doc(inline, "../alpha_leaf.png"))
    write("refused/encoded_parent.gltf", doc("sub/%2E%2E/%2e%2e/animated.bin"))
    write("refused/missing_image.gltf", doc(inline, "not_here.png"))
    glb = doc(inline)
    glb["buffers"] = [{"byteLength": 4, "uri": "https://example.com/payload.bin"}]
    write_glb("refused/external_buffer.glb", glb, bytearray(4))


if __name__ == "__main__":
    textured_box()
    glb_box()
    animated()
    alpha_modes()
    refused()
    import make_assets_gltf as more  # the generators of the second file, same helpers
    more.skinned_quad()
    more.two_skins()
    more.morphed_quad()
    more.extensions()
    more.texture_transform()
    more.quantized_quad()
    more.node_weights()
    more.emissive()
    import make_assets_materials as materials  # sidedness, samplers, sparse, UV sets, unlit, instancing
    materials.culling()
    materials.samplers()
    materials.sparse()
    materials.uv1_emissive()
    materials.unlit()
    materials.instancing()
