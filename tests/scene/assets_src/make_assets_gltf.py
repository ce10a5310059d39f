"""Generators of the glTF assets for skins, morph targets, vertex colours, extensions and
quantization (cases/scenes/); run through make_assets.py, which calls every one of them."""
import math
import struct

from make_assets import ASSET, Builder, checker_png, data_uri, embedded, quad_geometry, write


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



def emissive():
    """Three black panels over a grey floor: one glowing (1, 0.5, 0.125) at
    KHR_materials_emissive_strength 4, one glowing (0.25, 0.5, 1) by emissiveFactor alone,
    one without emission. Black and unlit, a panel shows exactly its emission."""
    b = Builder()
    meshes = [dict(b.mesh(quad_geometry(), m), name=n)
              for m, n in ((0, "strong"), (1, "factor_only"), (2, "dark"), (3, "floor"))]
    black = {"baseColorFactor": [0, 0, 0, 1]}
    write("emissive.gltf", {
        "asset": ASSET, "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3]}],
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "nodes": [{"name": "strong", "mesh": 0, "translation": [-0.8, 0.6, 0], "scale": [0.7, 0.7, 1]},
                  {"name": "factor_only", "mesh": 1, "translation": [0, 0.6, 0],
                   "scale": [0.7, 0.7, 1]},
                  {"name": "dark", "mesh": 2, "translation": [0.8, 0.6, 0], "scale": [0.7, 0.7, 1]},
                  {"name": "floor", "mesh": 3, "rotation": [-math.sqrt(0.5), 0, 0, math.sqrt(0.5)],
                   "scale": [4, 4, 1]}],
        "meshes": meshes,
        "materials": [
            {"name": "strong", "pbrMetallicRoughness": black, "emissiveFactor": [1, 0.5, 0.125],
             "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}},
            {"name": "factor_only", "pbrMetallicRoughness": black,
             "emissiveFactor": [0.25, 0.5, 1]},
            {"name": "dark", "pbrMetallicRoughness": black},
            {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1]}}],
        "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
        "bufferViews": b.views, "accessors": b.accessors,
    })
