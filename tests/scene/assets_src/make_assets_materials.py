"""Generators of the glTF assets for sidedness, samplers, sparse accessors, the second UV set,
emissive and occlusion textures, KHR_materials_unlit and EXT_mesh_gpu_instancing
(cases/scenes/); run through make_assets.py, which calls every one of them."""
import math
import struct

from make_assets import (ASSET, Builder, box_geometry, data_uri, embedded, png, quad_geometry,
                         write)

S = math.sqrt(0.5)
FLOOR = {"rotation": [-S, 0, 0, S], "scale": [8, 8, 1]}  # a quad facing +Y


def _doc(b, **rest):
    doc = {"asset": ASSET, "scene": 0,
           "buffers": [{"byteLength": len(b.data), "uri": embedded(b.data)}],
           "bufferViews": b.views, "accessors": b.accessors}
    doc.update(rest)
    return doc


def _image(rows):
    return {"uri": data_uri("image/png", png(len(rows[0]), len(rows), rows))}


def culling():
    """Four quads in a row over a floor: single-sided facing the camera (+Z), single-sided
    turned away, double-sided facing, double-sided turned away. glTF culls the second (its
    back faces the camera), draws the fourth lit by its flipped normal, as bright as the third."""
    b = Builder()
    meshes = [dict(b.mesh(quad_geometry(), m), name=n)
              for m, n in ((0, "single"), (1, "double"), (2, "floor"))]
    turned = [0, 1, 0, 0]  # 180 degrees about +Y
    write("culling.gltf", _doc(
        b, scenes=[{"nodes": [0, 1, 2, 3, 4]}], meshes=meshes,
        nodes=[{"name": "single_front", "mesh": 0, "translation": [-1.8, 0.9, 0]},
               {"name": "single_back", "mesh": 0, "translation": [-0.6, 0.9, 0], "rotation": turned},
               {"name": "double_front", "mesh": 1, "translation": [0.6, 0.9, 0]},
               {"name": "double_back", "mesh": 1, "translation": [1.8, 0.9, 0], "rotation": turned},
               dict(FLOOR, name="floor", mesh=2)],
        materials=[{"name": "red_single_sided",
                    "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.15, 0.1, 1]}},
                   {"name": "green_double_sided", "doubleSided": True,
                    "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.7, 0.2, 1]}},
                   {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1]}}]))


def _texel(i, j):
    """A colour of its own for each texel (i, j) of the 4x4 sampler texture."""
    return (30 + 70 * i, 30 + 70 * j, 230 - 30 * (i + j), 255)


def samplers():
    """Unlit quads with UVs from -1 to 2 (three repeats) of a 4x4 texture whose texels all
    differ: clamp along S and repeat along T, mirrored repeat on both, and linear filtering
    (the others magnify with NEAREST, so each texel is a flat block); then two small quads of
    a 1-texel 64x64 checker, minified: minFilter NEAREST under magFilter LINEAR (level 0 alone,
    every pixel one texel, black or white: aliasing) and LINEAR_MIPMAP_LINEAR (the mips' grey)."""
    b = Builder()
    pos, nrm, _, idx = quad_geometry()
    wide = [(-1, 2), (2, 2), (2, -1), (-1, -1)]
    tiled = b.mesh((pos, nrm, wide, idx), 0)["primitives"][0]
    meshes = [{"name": n, "primitives": [dict(tiled, material=m)]}
              for m, n in ((0, "clamp_s_repeat_t"), (1, "mirror"), (2, "linear"))]
    for m, n in ((3, "min_nearest"), (4, "min_mipmapped")):
        meshes.append(dict(b.mesh(quad_geometry(), m), name=n))
    checker = [[(255, 255, 255, 255) if (x + y) % 2 == 0 else (0, 0, 0, 255) for x in range(64)]
               for y in range(64)]
    unlit = {"KHR_materials_unlit": {}}

    def material(name, texture):
        return {"name": name, "extensions": unlit,
                "pbrMetallicRoughness": {"baseColorTexture": {"index": texture}}}

    write("samplers.gltf", _doc(
        b, scenes=[{"nodes": [0, 1, 2, 3, 4]}], meshes=meshes,
        extensionsUsed=["KHR_materials_unlit"],
        nodes=[{"name": "clamp_s_repeat_t", "mesh": 0, "translation": [-1.2, 1.2, 0]},
               {"name": "mirror", "mesh": 1, "translation": [0, 1.2, 0]},
               {"name": "linear", "mesh": 2, "translation": [1.2, 1.2, 0]},
               {"name": "min_nearest", "mesh": 3, "translation": [-0.5, 0.35, 0],
                "scale": [0.4, 0.4, 1]},
               {"name": "min_mipmapped", "mesh": 4, "translation": [0.5, 0.35, 0],
                "scale": [0.4, 0.4, 1]}],
        materials=[material("clamp_s_repeat_t", 0), material("mirror", 1),
                   material("linear", 2), material("min_nearest", 3),
                   material("min_mipmapped", 4)],
        textures=[{"source": 0, "sampler": 0}, {"source": 0, "sampler": 1},
                  {"source": 0, "sampler": 2}, {"source": 1, "sampler": 3},
                  {"source": 1, "sampler": 4}],
        samplers=[{"wrapS": 33071, "wrapT": 10497, "magFilter": 9728, "minFilter": 9728},
                  {"wrapS": 33648, "wrapT": 33648, "magFilter": 9728, "minFilter": 9728},
                  {"magFilter": 9729, "minFilter": 9987},
                  {"magFilter": 9729, "minFilter": 9728},
                  {"magFilter": 9729, "minFilter": 9987}],
        images=[_image([[_texel(i, j) for i in range(4)] for j in range(4)]), _image(checker)]))


def sparse():
    """Sparse accessors three ways: a 3x3 grid whose POSITION is a flat buffer view with the
    centre and one corner replaced (uint8 indices), a triangle whose POSITION has no buffer
    view at all (zeros, every value sparse, uint16 indices), and a quad with a morph target
    that is sparse only (its top edge rises 0.4, uint32 indices, weight 1)."""
    b = Builder()

    def sparse_accessor(count, indices, fmt, ctype, values, base=None, minmax=None):
        ind = b._view(struct.pack("<%d%s" % (len(indices), fmt), *indices))
        val = b._view(struct.pack("<%df" % (3 * len(values)), *[c for v in values for c in v]))
        acc = {"componentType": 5126, "count": count, "type": "VEC3",
               "sparse": {"count": len(indices),
                          "indices": {"bufferView": ind, "componentType": ctype},
                          "values": {"bufferView": val}}}
        if base is not None:
            acc["bufferView"] = b._view(struct.pack("<%df" % (3 * len(base)),
                                                    *[c for v in base for c in v]))
        if minmax:
            acc["min"], acc["max"] = minmax
        b.accessors.append(acc)
        return len(b.accessors) - 1

    grid = [(x / 2.0 - 0.5, y / 2.0 - 0.5, 0.0) for y in range(3) for x in range(3)]
    grid_idx = []
    for y in range(2):
        for x in range(2):
            a = y * 3 + x
            grid_idx += [a, a + 1, a + 4, a, a + 4, a + 3]
    bumped = sparse_accessor(9, [4, 8], "B", 5121, [(0, 0, 0.35), (0.5, 0.5, 0.2)], base=grid,
                             minmax=([-0.5, -0.5, 0], [0.5, 0.5, 0.35]))
    tri = sparse_accessor(3, [0, 1, 2], "H", 5123, [(-0.4, -0.4, 0), (0.4, -0.4, 0), (0, 0.4, 0)],
                          minmax=([-0.4, -0.4, 0], [0.4, 0.4, 0]))
    qpos, qnrm, _, qidx = quad_geometry()
    rise = sparse_accessor(4, [2, 3], "I", 5125, [(0, 0.4, 0), (0, 0.4, 0)],
                           minmax=([0, 0, 0], [0, 0.4, 0]))
    quad = {"POSITION": b.floats(qpos, "VEC3", minmax=True), "NORMAL": b.floats(qnrm, "VEC3")}
    write("sparse.gltf", _doc(
        b, scenes=[{"nodes": [0, 1, 2]}],
        nodes=[{"name": "bumped_grid", "mesh": 0, "translation": [-1.2, 0.8, 0]},
               {"name": "sparse_triangle", "mesh": 1, "translation": [0, 0.8, 0]},
               {"name": "sparse_morph", "mesh": 2, "translation": [1.2, 0.6, 0]}],
        meshes=[{"name": "bumped_grid", "primitives": [
                    {"attributes": {"POSITION": bumped}, "indices": b.indices(grid_idx),
                     "material": 0}]},
                {"name": "sparse_triangle", "primitives": [
                    {"attributes": {"POSITION": tri}, "material": 0}]},
                {"name": "sparse_morph", "weights": [1.0], "primitives": [
                    {"attributes": quad, "targets": [{"POSITION": rise}],
                     "indices": b.indices(qidx), "material": 0}]}],
        materials=[{"name": "sand", "doubleSided": True,
                    "pbrMetallicRoughness": {"baseColorFactor": [0.85, 0.7, 0.45, 1]}}]))


def uv1_emissive():
    """Three quads whose TEXCOORD_1 is TEXCOORD_0 transposed (u1 = v0, v1 = u0), each with a
    2x1 texture (sampled NEAREST) on the second set: where TEXCOORD_1 is honoured the texture's
    left texel covers the quad's top half, where it is not, its left half. First an emissive
    texture (red, black) times emissiveFactor 1 on a dark base; then an occlusion texture
    (1, 0) on a white base: the ambient light reaches the top half only; then the base colour
    itself (white, blue)."""
    b = Builder()
    pos, nrm, uv, idx = quad_geometry()
    uv1 = [(v, u) for u, v in uv]
    attrs = {"POSITION": b.floats(pos, "VEC3", minmax=True), "NORMAL": b.floats(nrm, "VEC3"),
             "TEXCOORD_0": b.floats(uv, "VEC2"), "TEXCOORD_1": b.floats(uv1, "VEC2")}
    ind = b.indices(idx)
    meshes = [{"name": n, "primitives": [{"attributes": attrs, "indices": ind, "material": m}]}
              for m, n in ((0, "emissive_uv1"), (1, "occlusion_uv1"), (2, "base_uv1"))]
    uv1_ref = {"texCoord": 1}
    write("uv1_emissive.gltf", _doc(
        b, scenes=[{"nodes": [0, 1, 2, 3]}], meshes=meshes + [
            dict(b.mesh(quad_geometry(), 3), name="floor")],
        nodes=[{"name": "emissive_uv1", "mesh": 0, "translation": [-1.2, 0.9, 0]},
               {"name": "occlusion_uv1", "mesh": 1, "translation": [0, 0.9, 0]},
               {"name": "base_uv1", "mesh": 2, "translation": [1.2, 0.9, 0]},
               dict(FLOOR, name="floor", mesh=3)],
        materials=[{"name": "emissive_uv1",
                    "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.1, 0.1, 1]},
                    "emissiveFactor": [1, 1, 1], "emissiveTexture": dict(uv1_ref, index=0)},
                   {"name": "occlusion_uv1", "occlusionTexture": dict(uv1_ref, index=1)},
                   {"name": "base_uv1",
                    "pbrMetallicRoughness": {"baseColorTexture": dict(uv1_ref, index=2)}},
                   {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}}],
        textures=[{"source": i, "sampler": 0} for i in range(3)],
        samplers=[{"magFilter": 9728, "minFilter": 9728}],
        images=[_image([[(255, 0, 0, 255), (0, 0, 0, 255)]]),
                _image([[(255, 255, 255, 255), (0, 0, 0, 255)]]),
                _image([[(255, 255, 255, 255), (40, 80, 230, 255)]])]))


def unlit():
    """A lit and a KHR_materials_unlit quad side by side with one 2x2 texture (NEAREST) times
    one factor, and a box in front casting a shadow on both: the unlit quad shows its texels
    times the factor everywhere, shadow or not. The extension is only used (no fallback
    needed: unlit materials carry their colour in the core fields)."""
    b = Builder()
    meshes = [dict(b.mesh(quad_geometry(), m), name=n)
              for m, n in ((0, "lit"), (1, "unlit"), (2, "floor"))]
    meshes.append(dict(b.mesh(box_geometry(), 2), name="caster"))
    base = {"baseColorFactor": [1, 0.8, 0.6, 1], "baseColorTexture": {"index": 0}}
    write("unlit.gltf", _doc(
        b, scenes=[{"nodes": [0, 1, 2, 3]}], meshes=meshes,
        extensionsUsed=["KHR_materials_unlit"],
        nodes=[{"name": "lit", "mesh": 0, "translation": [-0.7, 0.9, 0]},
               {"name": "unlit", "mesh": 1, "translation": [0.7, 0.9, 0]},
               dict(FLOOR, name="floor", mesh=2),
               {"name": "caster", "mesh": 3, "translation": [0, 1.4, 0.8],
                "scale": [2.4, 0.2, 0.2]}],
        materials=[{"name": "lit", "pbrMetallicRoughness": base},
                   {"name": "unlit", "pbrMetallicRoughness": base,
                    "extensions": {"KHR_materials_unlit": {}}},
                   {"name": "grey", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1]}}],
        textures=[{"source": 0, "sampler": 0}],
        samplers=[{"magFilter": 9728, "minFilter": 9728}],
        images=[_image([[(200, 60, 40, 255), (60, 200, 90, 255)],
                        [(50, 90, 220, 255), (230, 230, 230, 255)]])]))


def instancing():
    """EXT_mesh_gpu_instancing: six single-sided boxes on a ring of radius 1.2 (TRANSLATION,
    ROTATION about +Y by 30 degrees a step, SCALE 0.3; the sixth mirrored, x scale -0.3, so
    its front faces wind clockwise) under a node that turns once about +Y in 4 s: every
    instance moves differently, and each needs its own previous transform for its velocity."""
    b = Builder()
    mesh = dict(b.mesh(box_geometry(), 0), name="box")
    angles = [k * math.pi / 3 for k in range(6)]
    t = b.floats([(1.2 * math.cos(a), 0.0, 1.2 * math.sin(a)) for a in angles], "VEC3")
    r = b.floats([(0.0, math.sin(k * math.pi / 12), 0.0, math.cos(k * math.pi / 12))
                  for k in range(6)], "VEC4")
    s = b.floats([(0.3, 0.3, 0.3)] * 5 + [(-0.3, 0.3, 0.3)], "VEC3")
    keys = b.floats([float(k) for k in range(5)], "SCALAR")
    b.accessors[keys]["min"], b.accessors[keys]["max"] = [0.0], [4.0]
    turn = b.floats([(0.0, math.sin(k * math.pi / 4), 0.0, math.cos(k * math.pi / 4))
                     for k in range(5)], "VEC4")
    write("instancing.gltf", _doc(
        b, scenes=[{"nodes": [0, 1]}],
        extensionsUsed=["EXT_mesh_gpu_instancing"],
        extensionsRequired=["EXT_mesh_gpu_instancing"],
        nodes=[{"name": "ring", "mesh": 0, "translation": [0, 0.6, 0],
                "extensions": {"EXT_mesh_gpu_instancing": {
                    "attributes": {"TRANSLATION": t, "ROTATION": r, "SCALE": s}}}},
               dict(FLOOR, name="floor", mesh=1)],
        meshes=[mesh, dict(b.mesh(quad_geometry(), 1), name="floor")],
        materials=[{"name": "orange", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.5, 0.15, 1]}},
                   {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}}],
        animations=[{"name": "turn", "samplers": [{"input": keys, "output": turn}],
                     "channels": [{"sampler": 0, "target": {"node": 0, "path": "rotation"}}]}]))
