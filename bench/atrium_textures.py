"""Procedural PNG textures for bench/generate_atrium.py: stone, brick, tiles, plaster, cloth,
wood, terracotta, normal maps, and leaf cutouts with an alpha channel. Python stdlib only
(PNG through zlib); every texel is a function of the texture's name, size and seed, so the
files are byte-identical on every run.
"""
import math
import random
import struct
import zlib


def png(width: int, height: int, rgba: bytearray) -> bytes:
    """An 8-bit RGBA PNG of `rgba` (rows top to bottom, 4 bytes a texel)."""
    stride = width * 4
    raw = b"".join(b"\x00" + bytes(rgba[y * stride:(y + 1) * stride]) for y in range(height))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 6)) +
            chunk(b"IEND", b""))


class Noise:
    """Tileable value noise over [0, 1)^2: `period` lattice cells a side, smoothstep-blended."""

    def __init__(self, seed: int, period: int):
        r = random.Random(seed)
        self.period = period
        self.table = [r.random() for _ in range(period * period)]

    def at(self, u: float, v: float) -> float:
        p = self.period
        x, y = u * p, v * p
        xi, yi = math.floor(x), math.floor(y)
        fx, fy = x - xi, y - yi
        fx, fy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
        x0, y0 = xi % p, yi % p
        x1, y1 = (x0 + 1) % p, (y0 + 1) % p
        t = self.table
        a = t[y0 * p + x0] + (t[y0 * p + x1] - t[y0 * p + x0]) * fx
        b = t[y1 * p + x0] + (t[y1 * p + x1] - t[y1 * p + x0]) * fx
        return a + (b - a) * fy


def fbm(seed: int, base: int):
    """Two octaves of Noise, in [0, 1]."""
    lo, hi = Noise(seed, base), Noise(seed + 1, base * 4)
    return lambda u, v: 0.7 * lo.at(u, v) + 0.3 * hi.at(u, v)


def cell_hash(seed: int, i: int, j: int) -> float:
    """A per-cell value in [0, 1) (brick and tile tints), independent of Python's hash seed."""
    h = (i * 73856093 ^ j * 19349663 ^ seed * 83492791) & 0xFFFFFFFF
    h = (h ^ (h >> 13)) * 1274126177 & 0xFFFFFFFF
    return (h ^ (h >> 16)) / 2.0 ** 32


def clamp8(x: float) -> int:
    return 0 if x <= 0 else 255 if x >= 255 else int(x + 0.5)


def tint(colour, k: float):
    return tuple(clamp8(c * k) for c in colour)


# Height fields in [0, 1] (1 = raised) and their colour: each pattern is one function of (u, v).

def stone(seed, colour, veins):
    n = fbm(seed, 8)

    def f(u, v):
        h = n(u, v)
        k = 0.75 + 0.4 * h
        if veins:
            k *= 0.8 + 0.2 * min(1.0, abs(math.sin((u + 0.35 * h) * 2 * math.pi * 3)) * 4)
        return tint(colour, k), h
    return f


def brick(seed, colour, rows=8, cols=4):
    n = fbm(seed, 16)

    def f(u, v):
        row = int(v * rows)
        x = u * cols + (0.5 if row % 2 else 0.0)
        col = int(x) % cols
        fx, fy = x - math.floor(x), v * rows - row
        mortar = min(fx, 1 - fx) * 4 < 0.12 * rows / cols or min(fy, 1 - fy) < 0.07
        if mortar:
            return tint((170, 165, 150), 0.8 + 0.2 * n(u, v)), 0.0
        k = 0.75 + 0.35 * cell_hash(seed, row, col) + 0.15 * n(u, v)
        return tint(colour, k), 0.6 + 0.4 * n(u, v)
    return f


def tiles(seed, a, b, count=4):
    n = fbm(seed, 8)

    def f(u, v):
        i, j = int(u * count), int(v * count)
        fx, fy = u * count - i, v * count - j
        if min(fx, 1 - fx, fy, 1 - fy) < 0.03:
            return (90, 85, 80, 255), 0.0
        base = a if (i + j) % 2 == 0 else b
        return tint(base, 0.8 + 0.25 * n(u, v) + 0.1 * cell_hash(seed, i, j)), 1.0
    return f


def stripes(seed, colour, trim, bands=6):
    n = fbm(seed, 16)

    def f(u, v):
        border = min(u, 1 - u) < 0.08 or v > 0.93
        emblem = abs(u - 0.5) + abs(v - 0.4) * 0.7 < 0.18
        c = trim if border or emblem else colour if int(u * bands) % 2 == 0 else tint(colour, 0.75)
        return tint(c, 0.85 + 0.3 * n(u, v)), 0.5
    return f


def wood(seed, colour):
    n = fbm(seed, 8)

    def f(u, v):
        g = 0.5 + 0.5 * math.sin((v * 12 + 2.5 * n(u, v)) * 2 * math.pi)
        return tint(colour, 0.7 + 0.35 * g), g
    return f


def bands(seed, colour, count=5):
    n = fbm(seed, 8)

    def f(u, v):
        ring = 0.85 + 0.15 * math.cos(v * count * 2 * math.pi)
        return tint(colour, ring * (0.8 + 0.3 * n(u, v))), ring
    return f


def frond(seed, colour, leaflets):
    """A fern frond: a stem up the middle, `leaflets` pairs of ellipses; alpha 0 around them."""
    n = fbm(seed, 8)

    def f(u, v):
        x = u - 0.5
        if abs(x) < 0.012 + 0.01 * (1 - v):
            return tint((70, 90, 40), 1.0) + (255,), 1.0
        width = 0.46 * math.sin(math.pi * min(1.0, v * 1.1))  # widest mid-frond
        t = v * leaflets - 0.5 * abs(x) / max(width, 1e-3) * 1.4
        fy = t - math.floor(t) - 0.5
        inside = abs(x) < width and (fy * 2) ** 2 + (abs(x) / max(width, 1e-3) - 0.5) ** 2 * 3 < 0.8
        k = 0.7 + 0.5 * n(u, v) + 0.2 * (abs(x) / max(width, 1e-3))
        return tint(colour, k) + ((255,) if inside else (0,)), 1.0
    return f


def render(width: int, height: int, pattern, normal_strength: float = 0.0) -> bytes:
    """The PNG of `pattern` at width x height: its colour, or (normal_strength > 0) a tangent-
    space normal map of its height field."""
    texels = [[pattern((x + 0.5) / width, (y + 0.5) / height) for x in range(width)]
              for y in range(height)]
    out = bytearray(width * height * 4)
    for y in range(height):
        for x in range(width):
            colour, h = texels[y][x]
            if normal_strength > 0:
                dx = texels[y][(x + 1) % width][1] - texels[y][x - 1][1]
                dy = texels[(y + 1) % height][x][1] - texels[y - 1][x][1]
                nx, ny, nz = -dx * normal_strength, dy * normal_strength, 1.0
                s = 127.5 / math.sqrt(nx * nx + ny * ny + nz * nz)
                colour = (clamp8(127.5 + nx * s), clamp8(127.5 + ny * s), clamp8(127.5 + nz * s), 255)
            elif len(colour) == 3:
                colour = colour + (255,)
            out[(y * width + x) * 4:(y * width + x) * 4 + 4] = bytes(colour)
    return png(width, height, out)


# Every texture of the atrium: name -> (width, height, pattern, normal-map strength; 0: colour).
# Sizes vary from 64 to 1024 a side, square and not, as in an authored scene.
def textures():
    stone_a, stone_b = (200, 188, 160), (170, 172, 176)
    return {
        "column_sandstone": (512, 512, stone(11, stone_a, False), 0),
        "column_marble": (256, 512, stone(12, stone_b, True), 0),
        "column_red": (256, 256, stone(13, (170, 110, 90), True), 0),
        "column_normal": (256, 256, stone(14, stone_a, False), 3.0),
        "arch_brick": (1024, 512, brick(21, (160, 82, 60)), 0),
        "arch_brick_normal": (512, 256, brick(21, (160, 82, 60)), 4.0),
        "plaster_warm": (512, 512, stone(31, (214, 200, 176), False), 0),
        "plaster_cool": (256, 256, stone(32, (190, 196, 200), False), 0),
        "plaster_normal": (128, 128, stone(33, (200, 200, 200), False), 2.0),
        "floor_tiles": (1024, 1024, tiles(41, (200, 196, 186), (120, 60, 50)), 0),
        "floor_tiles_normal": (512, 512, tiles(41, (200, 196, 186), (120, 60, 50)), 3.0),
        "gallery_floor": (512, 512, tiles(42, (150, 140, 128), (180, 170, 150), 8), 0),
        "capital": (128, 128, stone(51, (220, 212, 196), True), 0),
        "banner_red": (256, 512, stripes(61, (150, 30, 30), (210, 170, 60)), 0),
        "banner_green": (256, 512, stripes(62, (30, 110, 50), (220, 210, 190)), 0),
        "banner_blue": (256, 512, stripes(63, (30, 50, 130), (200, 200, 200)), 0),
        "leaf_fern": (256, 256, frond(71, (60, 120, 40), 9), 0),
        "leaf_palm": (128, 256, frond(72, (80, 130, 50), 14), 0),
        "pot_terracotta": (256, 128, bands(81, (176, 96, 60)), 0),
        "baluster_marble": (128, 128, stone(91, (225, 222, 215), True), 0),
        "rail_wood": (256, 64, wood(92, (120, 80, 45)), 0),
        "soil": (64, 64, stone(93, (70, 50, 35), False), 0),
    }
