#!/usr/bin/env bash
# The scorecard ranks the shipped example resolves plausibly, on measured numbers: the minimal
# clamp (no reprojection) ghosts more than the built-in default on every mover case, the
# variance clip (velocity reprojection) ghosts less than the minimal clamp, and neither writes
# a non-finite sample. Usage: score_check.sh TAA_HARNESS SOURCE_DIR WORK_DIR
set -euo pipefail
exe=$1 src=$2 work=$3
rm -rf "$work"
export TAA_SHADER_CACHE="$work/cache"
for ex in minimal_clamp variance_clip; do
  "$exe" score "$src/examples/user_taa/cases/$ex.comp" --cases "$src/examples/user_taa/cases" --out "$work/$ex" >"$work.$ex.log"
done
python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
m = json.load(open(f"{work}/minimal_clamp/score.json"))
v = json.load(open(f"{work}/variance_clip/score.json"))
movers = [c for c in m["cases"] if c["movers"]]
assert movers, "no mover case was scored"
failures = []
for c in movers:
    d, u = c["lanes"]["default"]["ghosting"], c["lanes"]["user"]["ghosting"]
    print(f"{c['name']}: ghosting default {d:.4f}, minimal_clamp {u:.4f}")
    if not u > d:
        failures.append(f"{c['name']}: minimal_clamp ghosting {u} is not above the default's {d}")
for cm, cv in zip(m["cases"], v["cases"]):
    if not cm["movers"]:
        continue
    gm, gv = cm["lanes"]["user"]["ghosting"], cv["lanes"]["user"]["ghosting"]
    print(f"{cm['name']}: ghosting variance_clip {gv:.4f}, minimal_clamp {gm:.4f}")
    if not gv < gm:
        failures.append(f"{cm['name']}: variance_clip ghosting {gv} is not below minimal_clamp's {gm}")
for s in (m, v):
    for c in s["cases"]:
        for lane, l in c["lanes"].items():
            if l["non_finite"]:
                failures.append(f"{s['shader']} {c['name']} {lane}: {l['non_finite']} non-finite samples")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("scorecard ranks the examples plausibly")
PY
