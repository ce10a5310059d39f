#!/usr/bin/env python3
"""A Sponza-class glTF, generated: a two-storey atrium of fluted columns, brick arches,
balustrades, tiled floors and plastered walls around an open courtyard with potted ferns
(alphaMode MASK cutouts) and hanging banners, and a case that walks a camera through it, to
measure loading and rendering a large textured scene (docs/performance.md).

About 300,000 triangles at --scale 1 (--scale 2 doubles the tessellation, so the triangle
count, not the node count), about 400 nodes, 19 materials and 22 PNG textures from 64 to
1024 texels a side with mipmapped samplers, an external .bin and external images. Every
mesh is unique (each column, arch and wall is weathered by its own noise), so the file's
data grows with the triangles as a modelled scene's does. Everything is a function of the
arguments; nothing generated is committed.

  python3 bench/generate_atrium.py --out /tmp/atrium
  /usr/bin/time -v build/harness/taa-harness render /tmp/atrium/atrium.json --out /tmp/o
"""
import argparse
import array
import json
import math
import sys
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ beside the script in the source tree
import atrium_textures  # noqa: E402

BAY = 3.0                # column spacing
BAYS_X, BAYS_Z = 10, 4   # courtyard bays along x and z
GALLERY = 3.0            # depth of the arcade between the columns and the outer wall
LEVEL = 5.6              # storey height; the slab is its top 0.2
SPRING = 3.9             # arch springing height above a storey's floor
X, Z = BAY * BAYS_X / 2, BAY * BAYS_Z / 2


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    n = math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) or 1.0
    return (a[0] / n, a[1] / n, a[2] / n)


class Mesh:
    """One glTF mesh: a primitive per material, each with positions, normals, UVs, indices."""

    def __init__(self, name: str):
        self.name = name
        self.prims = {}  # material -> [positions, normals, uvs, indices]

    def surface(self, material: int, nu: int, nv: int, f, closed_u: bool = False):
        """The grid f(u, v) -> (xyz, uv) for u, v in [0, 1]; its front face is cross(du, dv).
        Normals are central differences on the grid (wrapping in u when closed_u)."""
        pos, nrm, uvs, idx = self.prims.setdefault(material, [[], [], [], []])
        base = len(pos)
        grid = [[f(i / nu, j / nv) for i in range(nu + 1)] for j in range(nv + 1)]
        for j in range(nv + 1):
            for i in range(nu + 1):
                if closed_u:
                    left, right = grid[j][(i - 1) % nu if i > 0 else nu - 1][0], grid[j][(i + 1) % nu][0]
                else:
                    left, right = grid[j][max(i - 1, 0)][0], grid[j][min(i + 1, nu)][0]
                down, up = grid[max(j - 1, 0)][i][0], grid[min(j + 1, nv)][i][0]
                pos.append(grid[j][i][0])
                uvs.append(grid[j][i][1])
                nrm.append(unit(cross(sub(right, left), sub(up, down))))
        for j in range(nv):
            for i in range(nu):
                a = base + j * (nu + 1) + i
                idx += (a, a + 1, a + nu + 2, a, a + nu + 2, a + nu + 1)

    def lathe(self, material, profile, nu, nv, uv_scale=(1.0, 1.0), rough=None, x=0.0):
        """A surface of revolution of profile(v) -> (radius, y) about the vertical line at x,
        facing outward while y rises; rough(u, v) scales the radius (weathering)."""
        def f(u, v):
            r, y = profile(v)
            if rough:
                r *= rough(u, v)
            t = -2 * math.pi * u
            return (x + r * math.cos(t), y, r * math.sin(t)), (u * uv_scale[0], v * uv_scale[1])
        self.surface(material, nu, nv, f, closed_u=True)

    def box(self, material, centre, half, uv_per_m=1.0):
        """Six faces, two triangles each, UVs in metres times uv_per_m."""
        axes = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
        # (normal axis, sign, a axis, b axis) with cross(a, b) = sign * normal
        for n, s, a, b in ((0, 1, 1, 2), (0, -1, 2, 1), (1, 1, 2, 0), (1, -1, 0, 2),
                           (2, 1, 0, 1), (2, -1, 1, 0)):
            def f(u, v, n=n, s=s, a=a, b=b):
                p = [centre[k] + s * half[k] * axes[n][k] for k in range(3)]
                p[a] += (2 * u - 1) * half[a]
                p[b] += (2 * v - 1) * half[b]
                return tuple(p), (u * 2 * half[a] * uv_per_m, v * 2 * half[b] * uv_per_m)
            self.surface(material, 1, 1, f)

    def triangles(self) -> int:
        return sum(len(p[3]) // 3 for p in self.prims.values())


def weathering(seed: int, amount: float):
    n = atrium_textures.Noise(seed, 8)
    return lambda u, v: 1.0 + amount * (n.at(u, v) - 0.5)


def tess(n: int, scale: float) -> int:
    """A tessellation count for --scale: triangles grow with scale (both grid axes by sqrt)."""
    return max(2, round(n * math.sqrt(scale)))


def column_parts(seed: int, material: int, scale: float):
    """Base, fluted shaft and capital, each its own mesh (a node each, as a modeller splits them)."""
    base, shaft, capital = Mesh(f"base{seed}"), Mesh(f"shaft{seed}"), Mesh(f"capital{seed}")
    base.box(3, (0, 0.06, 0), (0.36, 0.06, 0.36))
    base.lathe(3, lambda v: (0.34 - 0.08 * v + 0.03 * math.sin(v * math.pi * 2), 0.12 + 0.18 * v),
               tess(32, scale), tess(8, scale), (2, 0.3), weathering(seed + 1, 0.04))
    flutes = weathering(seed, 0.03)
    shaft.lathe(material, lambda v: (0.26 - 0.04 * v, 0.3 + 3.2 * v), tess(32, scale), tess(24, scale),
                (2, 3), lambda u, v: (1 + 0.035 * math.cos(u * 16 * 2 * math.pi)) * flutes(u, v))
    capital.lathe(3, lambda v: (0.22 + 0.14 * v * v, 3.5 + 0.3 * v), tess(32, scale), tess(10, scale),
                  (2, 0.4), weathering(seed + 2, 0.05))
    capital.box(3, (0, 3.85, 0), (0.36, 0.05, 0.36))
    return base, shaft, capital


def arch(seed: int, plaster: int, scale: float) -> Mesh:
    """A bay's arch in its own frame (x along the arcade, y up from the springing line, z across):
    a brick intrados and two plastered spandrel faces up to the slab."""
    m = Mesh(f"arch{seed}")
    radius, half, top, depth = BAY / 2 - 0.3, BAY / 2, LEVEL - 0.2 - SPRING, 0.6
    rough = weathering(seed, 0.03)
    nt, nv = tess(32, scale), tess(6, scale)

    def face(z, theta_of_u):
        def f(u, v):
            t = theta_of_u(u)
            c, s = math.cos(t), math.sin(t)
            reach = min(half / abs(c) if abs(c) > 1e-9 else 1e9, top / s if s > 1e-9 else 1e9)
            r = radius + (reach - radius) * v
            p = (r * c, r * s, z * rough(u, v))
            return p, (p[0] / 2, p[1] / 2)
        return f

    m.surface(plaster, nt, nv, face(depth / 2, lambda u: math.pi * (1 - u)))
    m.surface(plaster, nt, nv, face(-depth / 2, lambda u: math.pi * u))

    def intrados(u, v):
        t = math.pi * u
        r = radius * rough(u, v)
        return (r * math.cos(t), r * math.sin(t), depth / 2 - v * depth), (u * 4, v)
    m.surface(4, nt, tess(4, scale), intrados)
    return m


def balustrade(seed: int, scale: float) -> Mesh:
    """Eight turned marble balusters between two columns, on a base, under a wooden rail."""
    m = Mesh(f"balustrade{seed}")
    span = BAY - 0.8
    for k in range(8):
        x = -span / 2 + span * (k + 0.5) / 8
        m.lathe(16, lambda v: (0.05 + 0.035 * math.sin(v * math.pi * 1.3) ** 2, 0.1 + 0.85 * v),
                tess(12, scale), tess(10, scale), (1, 2), weathering(seed * 8 + k, 0.04), x)
    m.box(16, (0, 0.05, 0), (span / 2, 0.05, 0.12))
    m.box(17, (0, 1.0, 0), (span / 2 + 0.05, 0.05, 0.1), 2.0)
    return m


def quad(m: Mesh, material: int, origin, a, b, nu=1, nv=1, uv_per_m=0.5, seed=0, bulge=0.0):
    """A plane from `origin` spanned by vectors a and b (front face cross(a, b)), displaced
    along its normal by up to `bulge` of noise."""
    n = unit(cross(a, b))
    la, lb = math.sqrt(sum(c * c for c in a)), math.sqrt(sum(c * c for c in b))
    rough = weathering(seed, 2.0)

    def f(u, v):
        d = bulge * (rough(u, v) - 1.0)
        p = tuple(origin[k] + u * a[k] + v * b[k] + d * n[k] for k in range(3))
        return p, (u * la * uv_per_m, v * lb * uv_per_m)
    m.surface(material, nu, nv, f)
    return m


def plant(seed: int, scale: float):
    """A terracotta pot with soil, and a crown of fern fronds (alpha-masked, double-sided)."""
    pot, crown = Mesh(f"pot{seed}"), Mesh(f"fronds{seed}")
    pot.lathe(14, lambda v: (0.25 + 0.2 * v - 0.05 * max(0.0, v - 0.9) * 10, 0.8 * v),
              tess(24, scale), tess(12, scale), (3, 1), weathering(seed, 0.03))
    pot.lathe(15, lambda v: (0.4 * (1 - v), 0.72), tess(24, scale), 2, (1, 1))
    fronds = 36
    for k in range(fronds):
        azimuth = 2 * math.pi * (k * 0.618034 + seed * 0.13)
        rise = 0.35 + 0.9 * ((k * 7 + seed) % 11) / 11
        length = 0.9 + 0.5 * ((k * 5 + seed * 3) % 7) / 7
        d, side = (math.cos(azimuth), 0.0, math.sin(azimuth)), (-math.sin(azimuth), 0.0, math.cos(azimuth))
        material = 12 if k % 3 else 13

        def f(u, v, d=d, side=side, rise=rise, length=length):
            t = 1 - v  # the frond's base is the image's bottom row
            w = (u - 0.5) * 0.55
            out = length * t * math.cos(rise)
            up = length * (t * math.sin(rise) - 0.45 * t * t)
            return ((d[0] * out + side[0] * w, 0.75 + up + 0.08 * abs(w), d[2] * out + side[2] * w),
                    (u, v))
        crown.surface(material, 2, tess(6, scale), f)
    return pot, crown


def banner(seed: int, scale: float) -> Mesh:
    """A cloth banner hanging from the upper balustrade, rippled."""
    m = Mesh(f"banner{seed}")

    def f(u, v):
        ripple = 0.06 * math.sin(2 * math.pi * (2 * u + 0.3 * v + seed * 0.17))
        return ((u - 0.5) * 1.2, -3.0 * v, ripple * v), (u, v)
    m.surface(9 + seed % 3, tess(16, scale), tess(32, scale), f)
    return m


# name, base colour image, normal map image (or None), extra material keys. Index = material.
MATERIALS = [
    ("column_sandstone", "column_sandstone", "column_normal", {}),
    ("column_marble", "column_marble", None, {}),
    ("column_red", "column_red", None, {}),
    ("capital", "capital", "column_normal", {}),
    ("arch_brick", "arch_brick", "arch_brick_normal", {}),
    ("plaster_warm", "plaster_warm", "plaster_normal", {}),
    ("plaster_cool", "plaster_cool", "plaster_normal", {}),
    ("floor_tiles", "floor_tiles", "floor_tiles_normal", {}),
    ("gallery_floor", "gallery_floor", None, {}),
    ("banner_red", "banner_red", None, {"doubleSided": True}),
    ("banner_green", "banner_green", None, {"doubleSided": True}),
    ("banner_blue", "banner_blue", None, {"doubleSided": True}),
    ("leaf_fern", "leaf_fern", None, {"alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True}),
    ("leaf_palm", "leaf_palm", None, {"alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True}),
    ("pot", "pot_terracotta", None, {}),
    ("soil", "soil", None, {}),
    ("baluster", "baluster_marble", None, {}),
    ("rail", "rail_wood", None, {}),
    ("wall", "plaster_warm", "plaster_normal", {"baseColorFactor": [0.85, 0.8, 0.74, 1.0]}),
]
WALL = 18

# glTF samplers, all mipmapped (LINEAR_MIPMAP_LINEAR but soil's LINEAR_MIPMAP_NEAREST), and
# which images use which: repeat, mirrored repeat, banners clamped across, leaves clamped.
SAMPLERS = [
    {"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497},
    {"magFilter": 9729, "minFilter": 9987, "wrapS": 33648, "wrapT": 33648},
    {"magFilter": 9729, "minFilter": 9987, "wrapS": 33071, "wrapT": 10497},
    {"magFilter": 9729, "minFilter": 9987, "wrapS": 33071, "wrapT": 33071},
    {"magFilter": 9729, "minFilter": 9985, "wrapS": 10497, "wrapT": 10497},
]


def sampler_of(image: str) -> int:
    for prefix, sampler in (("plaster", 1), ("column", 1), ("banner", 2), ("leaf", 3), ("soil", 4)):
        if image.startswith(prefix):
            return sampler
    return 0


class Scene:
    """glTF nodes over unique meshes: add() returns the node index."""

    def __init__(self):
        self.nodes, self.meshes = [], []

    def add(self, name, mesh=None, translation=None, yaw90=False, children=()):
        node = {"name": name}
        if mesh is not None:
            node["mesh"] = len(self.meshes)
            self.meshes.append(mesh)
        if translation and any(translation):
            node["translation"] = [round(c, 4) for c in translation]
        if yaw90:
            node["rotation"] = [0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5)]
        if children:
            node["children"] = list(children)
        self.nodes.append(node)
        return len(self.nodes) - 1


def column_sites():
    xs = [-X + BAY * i for i in range(BAYS_X + 1)]
    zs = [-Z + BAY * j for j in range(1, BAYS_Z)]
    return [(x, s * Z) for s in (-1, 1) for x in xs] + [(s * X, z) for s in (-1, 1) for z in zs]


def bays():
    """(x, z, turned a quarter about y) of each arch's centre."""
    return ([(-X + BAY * (i + 0.5), s * Z, False) for s in (-1, 1) for i in range(BAYS_X)] +
            [(s * X, -Z + BAY * (j + 0.5), True) for s in (-1, 1) for j in range(BAYS_Z)])


def slab(level: int, side: int) -> Mesh:
    """One side's gallery slab at the top of a storey: floor above, ceiling below, and its edge
    facing the courtyard."""
    m = Mesh(f"slab{level}_{side}")
    y0, y1, g, e = LEVEL - 0.2, LEVEL, GALLERY, 0.3
    ceiling = 5 + level
    if side < 2:  # along x, at z = -Z (side 0) or +Z (side 1)
        s = 1 if side else -1
        z0, z1 = (Z - e, Z + g) if s > 0 else (-Z - g, -Z + e)
        quad(m, 8, (-X - g, y1, z0), (0, 0, z1 - z0), (2 * (X + g), 0, 0))
        quad(m, ceiling, (-X - g, y0, z0), (2 * (X + g), 0, 0), (0, 0, z1 - z0))
        edge = z0 if s > 0 else z1
        a, b = ((0, 0.2, 0), (2 * (X + g), 0, 0)) if s > 0 else ((2 * (X + g), 0, 0), (0, 0.2, 0))
        quad(m, ceiling, (-X - g, y0, edge), a, b)
    else:  # along z, at x = -X (side 2) or +X (side 3)
        s = 1 if side == 3 else -1
        x0, x1 = (X - e, X + g) if s > 0 else (-X - g, -X + e)
        zs = Z - e
        quad(m, 8, (x0, y1, -zs), (0, 0, 2 * zs), (x1 - x0, 0, 0))
        quad(m, ceiling, (x0, y0, -zs), (x1 - x0, 0, 0), (0, 0, 2 * zs))
        edge = x0 if s > 0 else x1
        a, b = ((0, 0, 2 * zs), (0, 0.2, 0)) if s > 0 else ((0, 0.2, 0), (0, 0, 2 * zs))
        quad(m, ceiling, (edge, y0, -zs), a, b)
    return m


def walls(level: int, scale: float):
    """The four outer walls of a storey, facing in, gently uneven."""
    w, d, h = X + GALLERY, Z + GALLERY, LEVEL
    nu, nv = tess(64, scale), tess(16, scale)
    nz = tess(32, scale)
    sides = [((-w, 0, d), (0, h, 0), (2 * w, 0, 0), nv, nu), ((-w, 0, -d), (2 * w, 0, 0), (0, h, 0), nu, nv),
             ((w, 0, -d), (0, 0, 2 * d), (0, h, 0), nz, nv), ((-w, 0, -d), (0, h, 0), (0, 0, 2 * d), nv, nz)]
    return [quad(Mesh(f"wall{level}_{k}"), WALL, o, a, b, n1, n2, 0.5, 1000 + level * 4 + k, 0.04)
            for k, (o, a, b, n1, n2) in enumerate(sides)]


def build(scale: float) -> Scene:
    sc = Scene()
    levels = []
    for level in range(2):
        parts = []
        for k, (x, z) in enumerate(column_sites()):
            seed = level * 100 + k
            base, shaft, capital = column_parts(seed, (k + level) % 3, scale)
            kids = [sc.add(f"column{level}_{k}_{p.name}", p) for p in (base, shaft, capital)]
            parts.append(sc.add(f"column{level}_{k}", translation=(x, 0, z), children=kids))
        for k, (x, z, turned) in enumerate(bays()):
            parts.append(sc.add(f"arch{level}_{k}", arch(level * 100 + k, 5 + level, scale),
                                (x, SPRING, z), turned))
            if level == 1:
                parts.append(sc.add(f"balustrade{k}", balustrade(k, scale), (x, 0, z), turned))
        for side in range(4):
            parts.append(sc.add(f"slab{level}_{side}", slab(level, side)))
        for m in walls(level, scale):
            parts.append(sc.add(m.name, m))
        if level == 1:
            for k in range(10):
                x = -X + BAY * (2 * (k % 5) + 0.5 + k // 5)
                z = (Z - 0.22) * (1 if k % 2 else -1)
                parts.append(sc.add(f"banner{k}", banner(k, scale), (x, 1.0, z)))
        levels.append(sc.add(f"level{level}", translation=(0, level * LEVEL, 0), children=parts))
    ground = []
    floor = quad(Mesh("courtyard_floor"), 7, (-X, 0, -Z), (0, 0, 2 * Z), (2 * X, 0, 0),
                 tess(24, scale), tess(60, scale), 0.25)
    ground.append(sc.add("courtyard_floor", floor))
    g = GALLERY
    for k, (o, a, b) in enumerate([((-X - g, 0, Z), (0, 0, g), (2 * (X + g), 0, 0)),
                                   ((-X - g, 0, -Z - g), (0, 0, g), (2 * (X + g), 0, 0)),
                                   ((X, 0, -Z), (0, 0, 2 * Z), (g, 0, 0)),
                                   ((-X - g, 0, -Z), (0, 0, 2 * Z), (g, 0, 0))]):
        ground.append(sc.add(f"gallery_floor{k}", quad(Mesh(f"gallery_floor{k}"), 8, o, a, b, uv_per_m=0.5)))
    for k in range(16):
        pot, crown = plant(k, scale)
        kids = [sc.add(f"pot{k}", pot), sc.add(f"fronds{k}", crown)]
        x, z = -X + 1.5 + BAY * (k % 8) * 1.15, (2.4 if k // 8 else -2.4)
        ground.append(sc.add(f"plant{k}", translation=(x, 0, z), children=kids))
    courtyard = sc.add("courtyard", children=ground)
    sc.root = sc.add("atrium", children=levels + [courtyard])
    return sc


def pack(values, typecode: str) -> bytes:
    a = array.array(typecode, values)
    if sys.byteorder != "little":
        a.byteswap()
    return a.tobytes()


def gltf(sc: Scene, images) -> tuple:
    """The glTF document and its .bin."""
    blob = bytearray()
    views, accessors = [], []

    def add(data: bytes, count: int, component: int, kind: str, target: int, extra=None):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
        blob.extend(data)
        accessors.append({"bufferView": len(views) - 1, "componentType": component, "count": count,
                          "type": kind, **(extra or {})})
        return len(accessors) - 1

    meshes = []
    for m in sc.meshes:
        prims = []
        for material, (pos, nrm, uvs, idx) in sorted(m.prims.items()):
            lo = [min(p[k] for p in pos) for k in range(3)]
            hi = [max(p[k] for p in pos) for k in range(3)]
            flat = lambda rows: [c for r in rows for c in r]
            attributes = {
                "POSITION": add(pack(flat(pos), "f"), len(pos), 5126, "VEC3", 34962,
                                {"min": lo, "max": hi}),
                "NORMAL": add(pack(flat(nrm), "f"), len(nrm), 5126, "VEC3", 34962),
                "TEXCOORD_0": add(pack(flat(uvs), "f"), len(uvs), 5126, "VEC2", 34962),
            }
            wide = len(pos) > 65535
            indices = add(pack(idx, "I" if wide else "H"), len(idx), 5125 if wide else 5123,
                          "SCALAR", 34963)
            prims.append({"attributes": attributes, "indices": indices, "material": material})
        meshes.append({"name": m.name, "primitives": prims})
    names = list(images)
    materials = []
    for name, colour, normal, extra in MATERIALS:
        pbr = {"baseColorTexture": {"index": names.index(colour)}, "metallicFactor": 0.0,
               "roughnessFactor": 0.8}
        if "baseColorFactor" in extra:
            pbr["baseColorFactor"] = extra["baseColorFactor"]
        mat = {"name": name, "pbrMetallicRoughness": pbr}
        if normal:
            mat["normalTexture"] = {"index": names.index(normal)}
        mat.update({k: v for k, v in extra.items() if k != "baseColorFactor"})
        materials.append(mat)
    doc = {
        "asset": {"version": "2.0", "generator": "bench/generate_atrium.py"},
        "scene": 0,
        "scenes": [{"nodes": [sc.root]}],
        "nodes": sc.nodes,
        "meshes": meshes,
        "materials": materials,
        "textures": [{"source": i, "sampler": sampler_of(n)} for i, n in enumerate(names)],
        "images": [{"uri": f"textures/{n}.png"} for n in names],
        "samplers": SAMPLERS,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob), "uri": "atrium.bin"}],
    }
    return doc, bytes(blob)


def case(frames: int, fps: int, width: int, height: int) -> dict:
    """A walk down the courtyard at eye height, facing its far end, in sunlight with shadows."""
    return {
        "description": "A Sponza-class atrium walk (bench/generate_atrium.py)",
        "scene": {"gltf": "atrium.gltf"},
        "render": {"width": width, "height": height},
        "lighting": {"direction": [-0.35, -1.0, -0.3], "shadows": True},
        "camera": {"fov_y_deg": 70, "target": [X + GALLERY, 2.5, 1.5],
                   "path": {"type": "catmull_rom", "look": "target", "constant_speed": True,
                            "duration_s": (frames - 1) / fps,
                            "points": [[-13.5, 1.7, -1.0], [-7.0, 1.8, 1.2], [0.0, 1.7, -0.8],
                                       [6.0, 2.0, 1.0], [10.5, 2.2, 1.5]]}},
        "script": {"fps": fps, "frames": frames},
        "output": {"frames": sorted({0, frames // 2, frames - 1})},
        "checks": {"golden": False, "invariants": ["finite"]},
    }


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True, help="folder for atrium.gltf, atrium.bin, textures/, atrium.json")
    p.add_argument("--scale", type=float, default=1.0, help="tessellation: triangles grow about linearly")
    p.add_argument("--frames", type=int, default=24)
    p.add_argument("--fps", type=int, default=8)
    p.add_argument("--width", type=int, default=640)
    p.add_argument("--height", type=int, default=360)
    a = p.parse_args()
    if not 0.05 <= a.scale <= 64 or a.frames < 2 or a.fps < 1 or a.width < 1 or a.height < 1:
        p.error("--scale must be in [0.05, 64], --frames at least 2, --fps and the size at least 1")
    out = Path(a.out)
    (out / "textures").mkdir(parents=True, exist_ok=True)
    images = atrium_textures.textures()
    for name, (w, h, pattern, strength) in images.items():
        (out / "textures" / f"{name}.png").write_bytes(atrium_textures.render(w, h, pattern, strength))
    sc = build(a.scale)
    doc, blob = gltf(sc, images)
    (out / "atrium.bin").write_bytes(blob)
    (out / "atrium.gltf").write_text(json.dumps(doc, separators=(",", ":")))
    (out / "atrium.json").write_text(json.dumps(case(a.frames, a.fps, a.width, a.height), indent=2) + "\n")
    print(f"{len(sc.nodes)} nodes, {len(sc.meshes)} meshes, {sum(m.triangles() for m in sc.meshes)} "
          f"triangles, {len(MATERIALS)} materials, {len(images)} textures, {len(blob)} bytes of buffer")


if __name__ == "__main__":
    main()
