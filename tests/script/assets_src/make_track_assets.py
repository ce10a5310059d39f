#!/usr/bin/env python3
"""Writes the recorded-track test assets under cases/tracks/ (standard library only).

Run from the repository root: python3 tests/script/assets_src/make_track_assets.py
The output is deterministic; rerun after editing and commit the results.

  capture.csv        a camera captured at a variable frame rate (frame times jitter
                     between about 1/110 s and 1/40 s, as an engine's would), with one
                     cut and a slow zoom, printed with 7 significant digits
  capture_mover.csv  a spinning box circling the origin, captured at another variable rate
  camera_anim.gltf   an animated perspective camera node ("ShotCam") under a parent
                     node ("Rig", raised 1 unit), for the glTF camera import
"""
import base64
import json
import math
import os
import struct

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")
OUT = os.path.normpath(os.path.join(ROOT, "cases", "tracks"))


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def quat_from_basis(x, y, z):
    """Unit quaternion (x, y, z, w) of the rotation whose columns are x, y, z."""
    m = [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        q = [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s]
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2
        q = [0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s]
    elif m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2
        q = [(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s]
    else:
        s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2
        q = [(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s]
    return normalize(q)


def look_quat(position, target):
    """Camera looking from position at target with +Y up (right-handed, looks down -Z)."""
    f = normalize([t - p for t, p in zip(target, position)])
    right = normalize(cross(f, [0.0, 1.0, 0.0]))
    up = cross(right, f)
    return quat_from_basis(right, up, [-c for c in f])


def yaw_quat(radians):
    return [0.0, math.sin(radians / 2), 0.0, math.cos(radians / 2)]


def variable_times(duration, base, wobble, phase):
    """Deterministic jittery frame times from 0 past `duration`."""
    times, t, k = [0.0], 0.0, 0
    while t < duration:
        k += 1
        t += base * (1.0 + wobble * math.sin(1.7 * k + phase) * math.cos(0.31 * k))
        times.append(t)
    return times


def g7(v):
    return "%.7g" % v


def camera_capture():
    cut_time = 0.55  # the recorded shot changes here: a teleport
    rows = []
    for t in variable_times(1.2, 1.0 / 60.0, 0.45, 0.0):
        second = t >= cut_time
        angle = 0.35 * t + (1.9 if second else 0.0)
        radius = 6.0 if not second else 4.5
        pos = [radius * math.sin(angle), 1.6 + 0.2 * math.sin(2.0 * t), radius * math.cos(angle)]
        q = look_quat(pos, [0.0, 0.5, 0.0])
        fov = 60.0 - 8.0 * t
        cut = 1 if second and not any(r[-1] == 1 for r in rows) else 0
        rows.append([t] + pos + q + [fov, cut])
    lines = [
        "# Camera capture for cases/track_csv_capture.json, recorded at a variable frame rate",
        "# (written by tests/script/assets_src/make_track_assets.py). Position in world units,",
        "# orientation as a unit quaternion (x, y, z, w), vertical fov in degrees; cut marks",
        "# the first sample of a new shot.",
        "time,px,py,pz,qx,qy,qz,qw,fov_y_deg,cut",
    ]
    for r in rows:
        lines.append(",".join([g7(v) for v in r[:-1]] + [str(r[-1])]))
    return "\n".join(lines) + "\n"


def mover_capture():
    lines = [
        "# Mover capture for cases/track_csv_capture.json: a box circling the origin while it",
        "# spins, recorded at a variable frame rate (make_track_assets.py).",
        "time,px,py,pz,qx,qy,qz,qw,sx,sy,sz",
    ]
    for t in variable_times(1.2, 1.0 / 50.0, 0.35, 0.8):
        a = 1.4 * t
        pos = [1.8 * math.cos(a), 0.45, 1.8 * math.sin(a)]
        q = yaw_quat(2.5 * t)
        lines.append(",".join(g7(v) for v in [t] + pos + q + [0.7, 0.7, 0.7]))
    return "\n".join(lines) + "\n"


def camera_gltf():
    times = [0.0, 1.0, 2.0]
    translations = [[0.0, 0.6, 6.0], [2.0, 0.6, 5.0], [4.0, 1.0, 3.0]]
    rotations = [yaw_quat(math.radians(d)) for d in (0.0, 20.0, 40.0)]
    blob = b"".join(struct.pack("<f", v) for v in times)
    blob += b"".join(struct.pack("<3f", *v) for v in translations)
    blob += b"".join(struct.pack("<4f", *v) for v in rotations)
    uri = "data:application/octet-stream;base64," + base64.b64encode(blob).decode("ascii")
    doc = {
        "asset": {"version": "2.0", "generator": "make_track_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [
            {"name": "Rig", "translation": [0.0, 1.0, 0.0], "children": [1]},
            {"name": "ShotCam", "camera": 0, "translation": translations[0],
             "rotation": rotations[0]},
        ],
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.9, "znear": 0.05, "zfar": 200.0,
                                     "aspectRatio": 1.7777778}}],
        "buffers": [{"byteLength": len(blob), "uri": uri}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 12},
            {"buffer": 0, "byteOffset": 12, "byteLength": 36},
            {"buffer": 0, "byteOffset": 48, "byteLength": 48},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "SCALAR",
             "min": [0.0], "max": [2.0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC4"},
        ],
        "animations": [{
            "name": "dolly",
            "samplers": [{"input": 0, "output": 1, "interpolation": "LINEAR"},
                         {"input": 0, "output": 2, "interpolation": "LINEAR"}],
            "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}},
                         {"sampler": 1, "target": {"node": 1, "path": "rotation"}}],
        }],
    }
    return json.dumps(doc, indent=1) + "\n"


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, text in [("capture.csv", camera_capture()), ("capture_mover.csv", mover_capture()),
                       ("camera_anim.gltf", camera_gltf())]:
        with open(os.path.join(OUT, name), "w", newline="\n") as f:
            f.write(text)
        print("wrote", os.path.join(OUT, name))


if __name__ == "__main__":
    main()
