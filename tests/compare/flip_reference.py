#!/usr/bin/env python3
"""Independent float64 LDR-FLIP used to derive the pinned values in flip_test.cpp.

Written from the paper (Andersson et al., HPG 2020) and the structure of the NVlabs/flip Python
reference: full 2D kernels (not separable passes), edge padding (clamp-to-edge), double
precision. It shares no code with harness/compare/flip.cpp, so agreement checks the separable
float implementation against a direct reading of the algorithm.

Usage: python3 tests/compare/flip_reference.py   (needs numpy; Debian: python3-numpy)
Prints, per case, the mean and a few pixels, in the form flip_test.cpp pins.
"""
import math

import numpy as np

PPD = 3840.0 * math.pi / 180.0
WHITE = np.array([0.950428545, 1.0, 1.088900371])
RGB2XYZ = np.array([[10135552 / 24577794, 8788810 / 24577794, 4435075 / 24577794],
                    [2613072 / 12288897, 8788810 / 12288897, 887015 / 12288897],
                    [1425312 / 73733382, 8788810 / 73733382, 70074185 / 73733382]])
XYZ2RGB = np.linalg.inv(RGB2XYZ)


def correlate2d(img, k):
    r = k.shape[0] // 2
    p = np.pad(img, r, mode="edge")
    h, w = img.shape
    out = np.zeros_like(img)
    for dy in range(k.shape[0]):
        for dx in range(k.shape[1]):
            out += k[dy, dx] * p[dy:dy + h, dx:dx + w]
    return out


def srgb2lin(c):
    return np.where(c > 0.04045, ((c + 0.055) / 1.055) ** 2.4, c / 12.92)


def hunt_lab(rgb):  # rgb: HxWx3 linear
    xyz = rgb @ RGB2XYZ.T / WHITE
    d = 6 / 29
    f = np.where(xyz > d ** 3, np.cbrt(xyz), xyz / (3 * d * d) + 4 / 29)
    L = 116 * f[..., 1] - 16
    a = 500 * (f[..., 0] - f[..., 1])
    b = 200 * (f[..., 1] - f[..., 2])
    return np.stack([L, 0.01 * L * a, 0.01 * L * b], -1)


def csf_kernel(a1, b1, a2, b2):
    r = int(math.ceil(3 * math.sqrt(0.04 / (2 * math.pi ** 2)) * PPD))
    x, y = np.meshgrid(np.arange(-r, r + 1), np.arange(-r, r + 1))
    z = (x / PPD) ** 2 + (y / PPD) ** 2
    s = a1 * np.sqrt(np.pi / b1) * np.exp(-np.pi ** 2 * z / b1)
    if a2:
        s = s + a2 * np.sqrt(np.pi / b2) * np.exp(-np.pi ** 2 * z / b2)
    return s / s.sum()


def feature_kernel(kind):
    sd = 0.5 * 0.082 * PPD
    r = int(math.ceil(3 * sd))
    x, y = np.meshgrid(np.arange(-r, r + 1), np.arange(-r, r + 1))
    g = np.exp(-(x ** 2 + y ** 2) / (2 * sd * sd))
    k = -x * g if kind == "edge" else (x ** 2 / (sd * sd) - 1) * g
    return np.where(k < 0, k / -k[k < 0].sum(), k / k[k > 0].sum())


def prepare(srgb):
    lin = srgb2lin(np.clip(srgb, 0, 1))
    xyz = lin @ RGB2XYZ.T / WHITE
    opp = [116 * xyz[..., 1] - 16, 500 * (xyz[..., 0] - xyz[..., 1]),
           200 * (xyz[..., 1] - xyz[..., 2])]
    ks = [csf_kernel(1, 0.0047, 0, 1), csf_kernel(1, 0.0053, 0, 1),
          csf_kernel(34.1, 0.04, 13.5, 0.025)]
    f = [correlate2d(o, k) for o, k in zip(opp, ks)]
    yy = (f[0] + 16) / 116
    xyz2 = np.stack([yy + f[1] / 500, yy, yy - f[2] / 200], -1) * WHITE
    rgb = np.clip(xyz2 @ XYZ2RGB.T, 0, 1)
    lum = (opp[0] + 16) / 116
    feats = []
    for kind in ("edge", "point"):
        k = feature_kernel(kind)
        feats.append(np.hypot(correlate2d(lum, k), correlate2d(lum, k.T)))
    return hunt_lab(rgb), feats[0], feats[1]


def flip(ref, test):
    lab_r, e_r, p_r = prepare(ref)
    lab_t, e_t, p_t = prepare(test)
    d = lab_r - lab_t
    hy = np.abs(d[..., 0]) + np.hypot(d[..., 1], d[..., 2])
    gb = hunt_lab(np.array([[[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]]))[0]
    dgb = gb[0] - gb[1]
    cmax = (abs(dgb[0]) + math.hypot(dgb[1], dgb[2])) ** 0.7
    pc, pt = 0.4, 0.95
    pw = hy ** 0.7
    dc = np.where(pw < pc * cmax, pt / (pc * cmax) * pw,
                  pt + (pw - pc * cmax) / (cmax - pc * cmax) * (1 - pt))
    df = (np.maximum(np.abs(e_r - e_t), np.abs(p_r - p_t)) / math.sqrt(2)) ** 0.5
    return dc ** (1 - df)


def noise(x, y, c):
    """Same integer hash as flip_test.cpp: a value in [-0.5, 0.5]."""
    m = 0xFFFFFFFF
    h = ((x * 73856093) & m) ^ ((y * 19349663) & m) ^ ((c * 83492791) & m)
    h ^= h >> 13
    h = (h * 0x5BD1E995) & m
    h ^= h >> 15
    return (h & 0xFFFF) / 65535.0 - 0.5


def cases(w=24, h=16):
    ys, xs = np.mgrid[0:h, 0:w]
    base = np.stack([xs / (w - 1), ys / (h - 1), 0.5 + 0.25 * ((xs // 4 + ys // 4) % 2)], -1)
    noisy = base.copy()
    for y in range(h):
        for x in range(w):
            for c in range(3):
                noisy[y, x, c] = min(1.0, max(0.0, base[y, x, c] + 0.2 * noise(x, y, c)))
    edge_a = np.where(xs < 10, 0.1, 0.9)[..., None].repeat(3, -1)
    edge_b = np.where(xs < 11, 0.1, 0.9)[..., None].repeat(3, -1)
    grey = np.full((h, w, 3), 0.5)
    patch = grey.copy()
    patch[4:12, 6:18] = [0.8, 0.2, 0.2]
    patch_g = grey.copy()
    patch_g[4:12, 6:18] = [0.2, 0.8, 0.2]
    return {"noise": (base, noisy), "edge_shift": (edge_a, edge_b), "red_vs_green": (patch, patch_g)}


if __name__ == "__main__":
    for name, (ref, test) in cases().items():
        e = flip(ref, test).astype(np.float32)
        px = [(0, 0), (5, 3), (10, 8), (12, 8), (23, 15)]
        vals = ", ".join("{%d, %d, %.6ff}" % (x, y, e[y, x]) for x, y in px)
        print("%s: mean %.7f  pixels %s" % (name, float(flip(ref, test).mean()), vals))
