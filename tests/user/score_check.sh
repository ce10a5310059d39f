#!/usr/bin/env bash
# The scorecard ranks the shipped example resolves plausibly, on measured numbers: the minimal
# clamp (no reprojection) ghosts more than the built-in default on every mover case, the
# variance clip (velocity reprojection) ghosts less than the minimal clamp; on the stress case
# the built-in resolve and the variance clip (NaN guard) write no non-finite sample, the minimal
# clamp (no guard) lets the injected NaNs through. Usage: score_check.sh TAA_HARNESS SOURCE_DIR WORK_DIR
set -euo pipefail
exe=$1 src=$2 work=$3
rm -rf "$work"
export TAA_SHADER_CACHE="$work/cache"
for ex in minimal_clamp variance_clip; do
  "$exe" score "$src/examples/user_taa/cases/$ex.comp" --cases "$src/examples/user_taa/score_cases" --out "$work/$ex" >"$work.$ex.log"
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
stress = [i for i, c in enumerate(m["cases"]) if c["stress"]]
assert stress, "no stress case was scored"
for i in stress:
    nm, nv = m["cases"][i]["lanes"]["user"]["non_finite"], v["cases"][i]["lanes"]["user"]["non_finite"]
    nd = m["cases"][i]["lanes"]["default"]["non_finite"]
    print(f"{m['cases'][i]['name']}: non-finite samples default {nd}, minimal_clamp {nm}, variance_clip {nv}")
    if nd or nv or not nm:
        failures.append(f"{m['cases'][i]['name']}: expected non-finite samples only from minimal_clamp")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("scorecard ranks the examples plausibly")
PY
