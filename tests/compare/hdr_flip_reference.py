#!/usr/bin/env python3
"""Independent HDR-FLIP in plain Python (no numpy), used to derive the values flip_hdr_test.cpp pins.

Written from Andersson, Nilsson, Shirley and Akenine-Moller, "Visualizing Errors in Rendered High
Dynamic Range Images" (Eurographics 2021 short paper) on top of LDR-FLIP (Andersson et al., HPG
2020): full 2D kernels, clamp-to-edge borders, float64 throughout. It shares no code with
harness/compare/flip_hdr.cpp or flip.cpp.

HDR-FLIP as the paper defines it:
  - tone mapper: the ACES fit of Narkowicz, (x (2.51 x + 0.03)) / (x (2.43 x + 0.59) + 0.14),
    applied to 0.6 x (the pre-exposure the paper cancels);
  - exposure range from the reference's luminance Y (Rec. 709 weights): start = log2(x85 / Ymax),
    stop = log2(x85 / Ymedian), x85 the input the tone curve maps to 0.85, Ymedian the element
    at index N/2 of the sorted luminances;
  - N = max(2, ceil(stop - start)) exposures evenly spaced from start to stop;
  - per exposure: both images times 2^c, tonemapped, clamped to [0, 1], compared with LDR-FLIP
    as linear RGB; HDR-FLIP is the per-pixel maximum.

Usage: python3 tests/compare/hdr_flip_reference.py
Prints, per case, the exposure range, the mean and a few pixels, as flip_hdr_test.cpp pins them.
"""
import math

PPD = 3840.0 * math.pi / 180.0
WHITE = (0.950428545, 1.0, 1.088900371)
RGB2XYZ = ((10135552 / 24577794, 8788810 / 24577794, 4435075 / 24577794),
           (2613072 / 12288897, 8788810 / 12288897, 887015 / 12288897),
           (1425312 / 73733382, 8788810 / 73733382, 70074185 / 73733382))


def inverse3(m):
    a, b, c = m[0]
    d, e, f = m[1]
    g, h, i = m[2]
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return ((
        (e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det),
        ((f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det),
        ((d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det))


XYZ2RGB = inverse3(RGB2XYZ)


def mul(m, v):
    return tuple(m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2] for r in range(3))


def correlate(plane, kernel):
    """2D correlation of a list-of-rows plane with a square kernel, clamp-to-edge."""
    h, w, r = len(plane), len(plane[0]), len(kernel) // 2
    out = []
    for y in range(h):
        row = []
        for x in range(w):
            s = 0.0
            for dy in range(-r, r + 1):
                src = plane[min(max(y + dy, 0), h - 1)]
                krow = kernel[dy + r]
                for dx in range(-r, r + 1):
                    s += krow[dx + r] * src[min(max(x + dx, 0), w - 1)]
            row.append(s)
        out.append(row)
    return out


def csf_kernel(terms):
    r = int(math.ceil(3 * math.sqrt(0.04 / (2 * math.pi ** 2)) * PPD))
    k = [[sum(a * math.sqrt(math.pi / b) * math.exp(-math.pi ** 2 * ((x / PPD) ** 2 + (y / PPD) ** 2) / b)
              for a, b in terms) for x in range(-r, r + 1)] for y in range(-r, r + 1)]
    total = sum(map(sum, k))
    return [[v / total for v in row] for row in k]


def feature_kernel(kind, transpose):
    sd = 0.5 * 0.082 * PPD
    r = int(math.ceil(3 * sd))
    k = []
    for y in range(-r, r + 1):
        row = []
        for x in range(-r, r + 1):
            u = y if transpose else x
            g = math.exp(-(x * x + y * y) / (2 * sd * sd))
            row.append(-u * g if kind == "edge" else (u * u / (sd * sd) - 1) * g)
        k.append(row)
    pos = sum(v for row in k for v in row if v > 0)
    neg = -sum(v for row in k for v in row if v < 0)
    return [[v / pos if v > 0 else v / neg for v in row] for row in k]


KERNELS = None


def kernels():
    global KERNELS
    if KERNELS is None:
        KERNELS = ([csf_kernel([(1, 0.0047)]), csf_kernel([(1, 0.0053)]),
                    csf_kernel([(34.1, 0.04), (13.5, 0.025)])],
                   {(kind, t): feature_kernel(kind, t) for kind in ("edge", "point") for t in (0, 1)})
    return KERNELS


def hunt_lab(rgb):
    xyz = mul(RGB2XYZ, rgb)
    d = 6 / 29
    f = [t ** (1 / 3) if t > d ** 3 else t / (3 * d * d) + 4 / 29 for t in (xyz[i] / WHITE[i] for i in range(3))]
    L = 116 * f[1] - 16
    return (L, 0.01 * L * 500 * (f[0] - f[1]), 0.01 * L * 200 * (f[1] - f[2]))


def prepare(linear):
    """linear: rows of (r, g, b) in [0, 1]. Returns Lab rows, edge and point magnitudes."""
    h, w = len(linear), len(linear[0])
    opp = [[[0.0] * w for _ in range(h)] for _ in range(3)]
    lum = [[0.0] * w for _ in range(h)]
    for y in range(h):
        for x in range(w):
            X, Y, Z = mul(RGB2XYZ, linear[y][x])
            Y /= WHITE[1]
            opp[0][y][x] = 116 * Y - 16
            opp[1][y][x] = 500 * (X / WHITE[0] - Y)
            opp[2][y][x] = 200 * (Y - Z / WHITE[2])
            lum[y][x] = Y
    csf, feat = kernels()
    filt = [correlate(opp[c], csf[c]) for c in range(3)]
    lab = [[None] * w for _ in range(h)]
    for y in range(h):
        for x in range(w):
            yy = (filt[0][y][x] + 16) / 116
            xyz = ((yy + filt[1][y][x] / 500) * WHITE[0], yy, (yy - filt[2][y][x] / 200) * WHITE[2])
            rgb = tuple(min(max(v, 0.0), 1.0) for v in mul(XYZ2RGB, xyz))
            lab[y][x] = hunt_lab(rgb)
    mags = {}
    for kind in ("edge", "point"):
        gx, gy = correlate(lum, feat[(kind, 0)]), correlate(lum, feat[(kind, 1)])
        mags[kind] = [[math.hypot(gx[y][x], gy[y][x]) for x in range(w)] for y in range(h)]
    return lab, mags["edge"], mags["point"]


def hyab(a, b):
    return abs(a[0] - b[0]) + math.hypot(a[1] - b[1], a[2] - b[2])


def ldr_flip(ref, test):
    lr, er, pr = prepare(ref)
    lt, et, pt_ = prepare(test)
    cmax = hyab(hunt_lab((0, 1, 0)), hunt_lab((0, 0, 1))) ** 0.7
    pc, pt = 0.4, 0.95
    out = []
    for y in range(len(ref)):
        row = []
        for x in range(len(ref[0])):
            e = hyab(lr[y][x], lt[y][x]) ** 0.7
            dc = pt / (pc * cmax) * e if e < pc * cmax else pt + (e - pc * cmax) / (cmax - pc * cmax) * (1 - pt)
            df = (max(abs(er[y][x] - et[y][x]), abs(pr[y][x] - pt_[y][x])) / math.sqrt(2)) ** 0.5
            row.append(dc ** (1 - df))
        out.append(row)
    return out


def aces(x):
    x *= 0.6
    return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)


def x85():
    lo, hi = 0.0, 100.0  # bisection: the curve rises monotonically on [0, inf)
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if aces(mid) < 0.85 else (lo, mid)
    return (lo + hi) / 2


def hdr_flip(ref, test):
    lum = sorted(0.2126 * r + 0.7152 * g + 0.0722 * b for row in ref for r, g, b in row)
    start = math.log2(x85() / lum[-1])
    stop = math.log2(x85() / lum[len(lum) // 2])
    n = max(2, math.ceil(stop - start))
    result = None
    for i in range(n):
        scale = 2 ** (start + i * (stop - start) / (n - 1))
        expose = lambda img: [[tuple(min(max(aces(c * scale), 0.0), 1.0) for c in px) for px in row] for row in img]
        m = ldr_flip(expose(ref), expose(test))
        result = m if result is None else [[max(a, b) for a, b in zip(ra, rb)] for ra, rb in zip(result, m)]
    return start, stop, n, result


def cases(w=16, h=12):
    """Linear HDR frames: a lit ramp with a highlight, and variants (mirrored in the C++ test)."""
    def base(x, y):
        v = 0.02 + 0.5 * x / (w - 1) + 0.25 * y / (h - 1)
        return (v, 0.8 * v, 0.6 * v + 0.05)
    ref = [[base(x, y) for x in range(w)] for y in range(h)]
    for y in range(4, 7):
        for x in range(9, 12):
            ref[y][x] = (24.0, 20.0, 16.0)
    dim_highlight = [[(px[0] * 0.5, px[1] * 0.5, px[2] * 0.5) if 4 <= y < 7 and 9 <= x < 12 else px
                      for x, px in enumerate(row)] for y, row in enumerate(ref)]
    shadow_noise = [[(px[0] * (1.1 if (x + y) % 2 else 0.9), px[1], px[2]) if x < 6 else px
                     for x, px in enumerate(row)] for y, row in enumerate(ref)]
    return {"dim_highlight": (ref, dim_highlight), "shadow_noise": (ref, shadow_noise)}


if __name__ == "__main__":
    for name, (ref, test) in cases().items():
        start, stop, n, m = hdr_flip(ref, test)
        mean = sum(map(sum, m)) / (len(m) * len(m[0]))
        px = [(0, 0), (3, 5), (10, 5), (12, 8), (15, 11)]
        vals = ", ".join("{%d, %d, %.6ff}" % (x, y, m[y][x]) for x, y in px)
        print("%s: start %.7f stop %.7f n %d mean %.7f pixels %s" % (name, start, stop, n, mean, vals))
