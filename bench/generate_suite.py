#!/usr/bin/env python3
"""A generated suite of N cases, to measure how `taa-harness run` scales with the case count.

Writes N case files into OUT (not into cases/: they are a load, not claims about images) and,
with --run, runs each prefix size given by --sizes through `taa-harness run` under
/usr/bin/time, printing cases, wall seconds, CPU seconds and peak memory per size, so that
"time linear in the cases, memory flat" can be read off the table (docs/performance.md).

Each case is a function of its index alone: a built-in scene, a camera placement, a jitter
pattern and a resolve setting picked by index, 64x36 pixels, 4 frames, the finite invariant
(goldens off: a generated case claims nothing about its image).

  python3 bench/generate_suite.py --out /tmp/suite --count 1000 \\
      --run build/harness/taa-harness --sizes 125,250,500,1000
"""
import argparse
import json
import re
import subprocess
import sys
from pathlib import Path

SCENES = ["checkerboard", "wires", "fence", "foliage", "rough_floor", "open_area"]
JITTER = ["halton", "uniform4", "symmetric2", "legacy2"]
RECTIFY = ["clip", "clamp", "none"]
FILTERS = ["catmull_rom_5", "bilinear", "catmull_rom_9", "bspline"]


def case(i: int) -> dict:
    angle = (i * 37) % 360
    return {
        "description": f"generated load case {i} (bench/generate_suite.py)",
        "scene": {"builtin": SCENES[i % len(SCENES)]},
        "render": {"width": 64, "height": 36},
        "camera": {"position": [4.0 * ((angle % 90) / 90.0 - 0.5), 1.2 + (i % 5) * 0.2, 5.0 + (i % 7) * 0.5],
                   "target": [0.0, 0.5, 0.0]},
        "jitter": {"pattern": JITTER[(i // len(SCENES)) % len(JITTER)]},
        "taa": {"rectify": RECTIFY[i % len(RECTIFY)], "history_filter": FILTERS[(i // 3) % len(FILTERS)]},
        "script": {"frames": 4},
        "output": {"frames": [3]},
        "reference": {"samples": 4},
        "checks": {"golden": False, "invariants": ["finite"]},
    }


def write(out: Path, count: int) -> None:
    out.mkdir(parents=True, exist_ok=True)
    for old in out.glob("gen_*.json"):
        old.unlink()
    for i in range(count):
        (out / f"gen_{i:05d}.json").write_text(json.dumps(case(i), indent=1) + "\n")


def measure(harness: str, suite: Path, size: int) -> dict:
    folder = suite.parent / f"{suite.name}_{size}"
    folder.mkdir(exist_ok=True)
    for old in folder.glob("gen_*.json"):
        old.unlink()
    for f in sorted(suite.glob("gen_*.json"))[:size]:
        (folder / f.name).write_bytes(f.read_bytes())
    proc = subprocess.run(["/usr/bin/time", "-v", harness, "run", str(folder), "--out", str(folder / "out")],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"{harness} run {folder}: exit {proc.returncode}\n{proc.stdout[-2000:]}{proc.stderr[-2000:]}")

    def field(name: str) -> str:
        m = re.search(rf"{re.escape(name)}: (.+)", proc.stderr)
        return m.group(1).strip() if m else "?"
    wall = field("Elapsed (wall clock) time (h:mm:ss or m:ss)").split(":")
    seconds = sum(float(p) * 60 ** k for k, p in enumerate(reversed(wall)))
    cpu = float(field("User time (seconds)")) + float(field("System time (seconds)"))
    return {"cases": size, "wall_s": round(seconds, 1), "cpu_s": round(cpu, 1),
            "peak_mib": round(int(field("Maximum resident set size (kbytes)")) / 1024),
            "wall_ms_per_case": round(1000 * seconds / size, 1)}


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True, type=Path, help="folder the cases are written to")
    p.add_argument("--count", type=int, default=1000)
    p.add_argument("--run", metavar="TAA_HARNESS", help="run prefixes of the suite through this binary")
    p.add_argument("--sizes", default="125,250,500,1000", help="prefix sizes to run (with --run)")
    a = p.parse_args()
    if a.count < 1:
        p.error("--count must be at least 1")
    write(a.out, a.count)
    print(f"wrote {a.count} cases to {a.out}")
    if not a.run:
        return
    print("| cases | wall s | CPU s | peak MiB | wall ms per case |")
    print("|---:|---:|---:|---:|---:|")
    for size in (int(s) for s in a.sizes.split(",")):
        if size > a.count:
            p.error(f"--sizes {size} is more than --count {a.count}")
        r = measure(a.run, a.out, size)
        print(f"| {r['cases']} | {r['wall_s']} | {r['cpu_s']} | {r['peak_mib']} | {r['wall_ms_per_case']} |", flush=True)


if __name__ == "__main__":
    main()
