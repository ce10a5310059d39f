#!/usr/bin/env python3
"""Writes still_zone_plate.png (320x180, 8-bit RGB) next to this script: the image the case
still_image_upsample.json temporally upsamples (debug.image). A zone plate, whose rings get
finer towards the edges (up to about 0.4 cycles per output pixel, below the output Nyquist
limit but far above that of the half-resolution render), over a colour ramp, so every
frequency band and all three channels are exercised. Standard library only."""
import math
import os
import struct
import zlib

W, H = 320, 180


def texel(x, y):
    cx, cy = x + 0.5 - W / 2, y + 0.5 - H / 2
    # Phase k r^2 / 2: local frequency k r / (2 pi) cycles per pixel, 0.4 at the corners.
    k = 0.4 * 2 * math.pi / math.hypot(W / 2, H / 2)
    ring = 0.5 + 0.5 * math.cos(0.5 * k * (cx * cx + cy * cy))
    return (0.15 + 0.7 * ring * (0.4 + 0.6 * x / W), 0.15 + 0.7 * ring, 0.15 + 0.7 * ring * (1.0 - 0.6 * y / H))


def chunk(tag, data):
    return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)


rows = b"".join(b"\x00" + bytes(round(255 * c) for x in range(W) for c in texel(x, y)) for y in range(H))
with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "still_zone_plate.png"), "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))
