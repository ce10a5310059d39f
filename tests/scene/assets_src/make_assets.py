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


def bend_quad(rate):
    """A 2x2-cell quad in the XY plane whose right edge (x = +0.5) rises at `rate` units per
    second while the left edge (x = -0.5) stays: the displacement (x + 0.5) * rate * t is
    affine, so every surface point's motion is known exactly (tests/renderer/deform_velocity)."""
    pos = [(x / 2.0 - 0.5, y / 2.0 - 0.5, 0.0) for y in range(3) for x in range(3)]
    idx = []
    for y in range(2):
        for x in range(2):
            a = y * 3 + x
            idx += [a, a + 1, a + 4, a, a + 4, a + 3]
    return pos, [(0, 0, 1)] * len(pos), idx


def skinned_quad():
    """bend_quad by a skin: joint 0 stays, joint 1 translates up at 0.8 units/s; a vertex's
    joint-1 weight is x + 0.5 (a blend of both joints in the middle column)."""
    b = Builder()
    pos, nrm, idx = bend_quad(0.8)
    joints = [(0, 1, 0, 0)] * len(pos)
    weights = [(0.5 - p[0], p[0] + 0.5, 0.0, 0.0) for p in pos]
    view = b._view(struct.pack("<%dB" % (4 * len(pos)), *[c for j in joints for c in j]))
    b.accessors.append({"bufferView": view, "componentType": 5121, "count": len(pos),
                        "type": "VEC4"})
    j_acc = len(b.accessors) - 1
    attrs = {"POSITION": b.floats(pos, "VEC3", minmax=True), "NORMAL": b.floats(nrm, "VEC3"),
             "JOINTS_0": j_acc, "WEIGHTS_0": b.floats(weights, "VEC4")}
    ibm = b.floats([tuple(float(i % 5 == 0) for i in range(16))] * 2, "MAT4")
    t = b.floats([0.0, 10.0], "SCALAR")
    b.accessors[t]["min"], b.accessors[t]["max"] = [0.0], [10.0]
    v = b.floats([(0.0, 0.0, 0.0), (0.0, 8.0, 0.0)], "VEC3")
    write("skinned_quad.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"name": "skinned", "mesh": 0, "skin": 0},
                  {"name": "anchor"}, {"name": "lifter"}],
        "meshes": [{"name": "skinned_quad", "primitives": [
            {"attributes": attrs, "indices": b.indices(idx), "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.6, 0.2, 1]},
                       "doubleSided": True}],
        "skins": [{"joints": [1, 2], "inverseBindMatrices": ibm}],
        "animations": [{"name": "lift", "samplers": [{"input": t, "output": v}],
                        "channels": [{"sampler": 0, "target": {"node": 2, "path": "translation"}}]}],
        "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
        "bufferViews": b.views, "accessors": b.accessors,
    })


def two_skins():
    """Two bend quads sharing one mesh, each bound to its own skin: skin 0's lifter rises at
    0.8 units/s (animation "up"), skin 1's sinks at 0.4 units/s (animation "down") and hangs
    under a parent joint that slides along x at 1 unit/s (an animated joint hierarchy)."""
    b = Builder()
    pos, nrm, idx = bend_quad(0.8)
    view = b._view(struct.pack("<%dB" % (4 * len(pos)), *[c for _ in pos for c in (0, 1, 0, 0)]))
    b.accessors.append({"bufferView": view, "componentType": 5121, "count": len(pos),
                        "type": "VEC4"})
    joints = len(b.accessors) - 1
    attrs = {"POSITION": b.floats(pos, "VEC3", minmax=True), "NORMAL": b.floats(nrm, "VEC3"),
             "JOINTS_0": joints,
             "WEIGHTS_0": b.floats([(0.5 - p[0], p[0] + 0.5, 0.0, 0.0) for p in pos], "VEC4")}
    ibm = b.floats([tuple(float(i % 5 == 0) for i in range(16))] * 2, "MAT4")
    t = b.floats([0.0, 10.0], "SCALAR")
    b.accessors[t]["min"], b.accessors[t]["max"] = [0.0], [10.0]
    up = b.floats([(0.0, 0.0, 0.0), (0.0, 8.0, 0.0)], "VEC3")
    down = b.floats([(0.0, 0.0, 0.0), (0.0, -4.0, 0.0)], "VEC3")
    slide = b.floats([(0.0, 0.0, 0.0), (10.0, 0.0, 0.0)], "VEC3")
    write("two_skins.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3, 4]}],
        "nodes": [{"name": "first", "mesh": 0, "skin": 0}, {"name": "second", "mesh": 0, "skin": 1},
                  {"name": "anchor"}, {"name": "lifter_up"},
                  {"name": "slider", "children": [5, 6]}, {"name": "anchor2"},
                  {"name": "lifter_down"}],
        "meshes": [{"name": "bend_quad", "primitives": [
            {"attributes": attrs, "indices": b.indices(idx), "material": 0}]}],
        "materials": [{"doubleSided": True}],
        "skins": [{"joints": [2, 3], "inverseBindMatrices": ibm},
                  {"joints": [5, 6], "inverseBindMatrices": ibm}],
        "animations": [
            {"name": "up", "samplers": [{"input": t, "output": up}],
             "channels": [{"sampler": 0, "target": {"node": 3, "path": "translation"}}]},
            {"name": "down", "samplers": [{"input": t, "output": down},
                                          {"input": t, "output": slide}],
             "channels": [{"sampler": 0, "target": {"node": 6, "path": "translation"}},
                          {"sampler": 1, "target": {"node": 4, "path": "translation"}}]}],
        "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
        "bufferViews": b.views, "accessors": b.accessors,
    })


def morphed_quad():
    """bend_quad by a morph target (offset (0, x + 0.5, 0)) whose weight grows at 0.8 per
    second, plus vertex colours (COLOR_0, normalised bytes: red left, blue right)."""
    b = Builder()
    pos, nrm, idx = bend_quad(0.8)
    delta = [(0.0, p[0] + 0.5, 0.0) for p in pos]
    colors = [(255, 0, 0, 255) if p[0] < 0 else (0, 0, 255, 255) if p[0] > 0 else (255, 255, 255, 255)
              for p in pos]
    view = b._view(struct.pack("<%dB" % (4 * len(pos)), *[c for col in colors for c in col]))
    b.accessors.append({"bufferView": view, "componentType": 5121, "normalized": True,
                        "count": len(pos), "type": "VEC4"})
    c_acc = len(b.accessors) - 1
    attrs = {"POSITION": b.floats(pos, "VEC3", minmax=True), "NORMAL": b.floats(nrm, "VEC3"),
             "COLOR_0": c_acc}
    target = {"POSITION": b.floats(delta, "VEC3", minmax=True)}
    t = b.floats([0.0, 10.0], "SCALAR")
    b.accessors[t]["min"], b.accessors[t]["max"] = [0.0], [10.0]
    w = b.floats([0.0, 8.0], "SCALAR")
    write("morphed_quad.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "morphed", "mesh": 0}],
        "meshes": [{"name": "morphed_quad", "weights": [0.0], "primitives": [
            {"attributes": attrs, "targets": [target], "indices": b.indices(idx),
             "material": 0}]}],
        "materials": [{"doubleSided": True}],
        "animations": [{"name": "grow", "samplers": [{"input": t, "output": w}],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}]}],
        "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
        "bufferViews": b.views, "accessors": b.accessors,
    })


def extensions():
    """Files listing extensions the loader does not implement (under refused/)."""
    b = Builder()
    mesh = b.mesh(quad_geometry(), 0)

    def doc(required, used):
        return {"asset": ASSET, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
                "meshes": [mesh], "materials": [{}], "extensionsRequired": required,
                "extensionsUsed": used,
                "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
                "bufferViews": b.views, "accessors": b.accessors}

    write("refused/requires_draco.gltf",
          doc(["KHR_draco_mesh_compression"], ["KHR_draco_mesh_compression"]))
    write("refused/requires_basisu.gltf", doc(["KHR_texture_basisu"], ["KHR_texture_basisu"]))
    write("refused/requires_specgloss.gltf", doc(["KHR_materials_pbrSpecularGlossiness"],
                                                 ["KHR_materials_pbrSpecularGlossiness"]))
    write("uses_unsupported.gltf", doc(["KHR_mesh_quantization"],
                                       ["KHR_mesh_quantization", "KHR_lights_punctual",
                                        "KHR_materials_clearcoat"]))


def texture_transform():
    """A textured quad whose base colour uses KHR_texture_transform with the extension's own
    example (offset [0, 1], rotation pi/2, scale 0.5: the lower left quadrant, turned)."""
    b = Builder()
    mesh = b.mesh(quad_geometry(), 0)
    tex = checker_png(4, 4, (230, 230, 230, 255), (40, 40, 40, 255), 2)
    write("texture_transform.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [mesh], "extensionsUsed": ["KHR_texture_transform"],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {
            "index": 0, "extensions": {"KHR_texture_transform": {
                "offset": [0, 1], "rotation": 1.57079632679, "scale": [0.5, 0.5]}}}}}],
        "textures": [{"source": 0}],
        "images": [{"uri": data_uri("image/png", tex)}],
        "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
        "bufferViews": b.views, "accessors": b.accessors,
    })


def quantized_quad():
    """KHR_mesh_quantization: positions as unnormalised shorts (node scale 0.001), normals as
    normalised bytes, UVs as normalised unsigned shorts; each attribute padded to a 4-byte stride."""
    b = Builder()
    pos = [(-500, -500, 0), (500, -500, 0), (500, 500, 0), (-500, 500, 0)]
    uv = [(0, 65535), (65535, 65535), (65535, 0), (0, 0)]

    def padded(fmt, rows, stride, ctype, kind, normalized):
        blob = b"".join(struct.pack(fmt, *r).ljust(stride, b"\0") for r in rows)
        view = b._view(blob)
        b.views[view]["byteStride"] = stride
        acc = {"bufferView": view, "componentType": ctype, "count": len(rows), "type": kind}
        if normalized:
            acc["normalized"] = True
        b.accessors.append(acc)
        return len(b.accessors) - 1

    p_acc = padded("<3h", pos, 8, 5122, "VEC3", False)
    b.accessors[p_acc]["min"], b.accessors[p_acc]["max"] = [-500, -500, 0], [500, 500, 0]
    attrs = {"POSITION": p_acc,
             "NORMAL": padded("<3b", [(0, 0, 127)] * 4, 4, 5120, "VEC3", True),
             "TEXCOORD_0": padded("<2H", uv, 4, 5123, "VEC2", True)}
    write("quantized_quad.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "scale": [0.001, 0.001, 0.001]}],
        "meshes": [{"primitives": [{"attributes": attrs, "indices": b.indices([0, 1, 2, 0, 2, 3]),
                                    "material": 0}]}],
        "materials": [{}],
        "extensionsUsed": ["KHR_mesh_quantization"],
        "extensionsRequired": ["KHR_mesh_quantization"],
        "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
        "bufferViews": b.views, "accessors": b.accessors,
    })


def node_weights():
    """A morph target whose node weight (0.75) overrides the mesh's default (0.25)."""
    b = Builder()
    pos, nrm, idx = bend_quad(0.8)
    attrs = {"POSITION": b.floats(pos, "VEC3", minmax=True), "NORMAL": b.floats(nrm, "VEC3")}
    target = {"POSITION": b.floats([(0.0, 1.0, 0.0)] * len(pos), "VEC3", minmax=True)}
    write("node_weights.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"name": "node_weight", "mesh": 0, "weights": [0.75]},
                  {"name": "mesh_weight", "mesh": 0, "translation": [2, 0, 0]}],
        "meshes": [{"weights": [0.25], "primitives": [
            {"attributes": attrs, "targets": [target], "indices": b.indices(idx), "material": 0}]}],
        "materials": [{}],
        "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
        "bufferViews": b.views, "accessors": b.accessors,
    })


if __name__ == "__main__":
    textured_box()
    glb_box()
    animated()
    alpha_modes()
    refused()
    skinned_quad()
    two_skins()
    morphed_quad()
    extensions()
    texture_transform()
    quantized_quad()
    node_weights()
