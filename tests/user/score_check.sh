#!/usr/bin/env bash
# One scorecard of both shipped example resolves, two lanes next to the built-in default in
# one run, ranks them plausibly on measured numbers: the minimal clamp (no reprojection)
# ghosts more than the built-in default on every mover case, the variance clip (velocity
# reprojection) ghosts less than the minimal clamp; on the stress case the built-in resolve
# and the variance clip (NaN guard) write no non-finite sample while the minimal clamp (no
# guard) lets the injected NaNs through, and the table stays readable: its error columns are
# finite numbers over the finite samples, the NaNs counted in their own column.
# Usage: score_check.sh TAA_HARNESS SOURCE_DIR WORK_DIR
set -euo pipefail
exe=$1 src=$2 work=$3
rm -rf "$work"
export TAA_SHADER_CACHE="$work/cache"
ex="$src/examples/user_taa/cases"
"$exe" score "$ex/minimal_clamp.comp" --params alpha=0.1 "$ex/variance_clip.comp" --name variance \
  --cases "$src/examples/user_taa/score_cases" --out "$work/score" >"$work.log"
# The table's rows, not the prose above it (which names NaN to say how it is counted).
if grep -Eiq '^\|.*\b(nan|inf)\b' "$work/score/score.md"; then
  echo "score.md prints a non-finite figure:"; cat "$work/score/score.md"; exit 1
fi
python3 - "$work" <<'PY'
import json, math, sys
s = json.load(open(f"{sys.argv[1]}/score/score.json"))
assert [l["name"] for l in s["lanes"]] == ["default", "minimal_clamp", "variance"], s["lanes"]
movers = [c for c in s["cases"] if c["movers"]]
assert movers, "no mover case was scored"
failures = []
for c in movers:
    d, m, v = (c["lanes"][k]["ghosting"] for k in ("default", "minimal_clamp", "variance"))
    print(f"{c['name']}: ghosting default {d:.4f}, minimal_clamp {m:.4f}, variance_clip {v:.4f}")
    if not m > d:
        failures.append(f"{c['name']}: minimal_clamp ghosting {m} is not above the default's {d}")
    if not v < m:
        failures.append(f"{c['name']}: variance_clip ghosting {v} is not below minimal_clamp's {m}")
stress = [c for c in s["cases"] if c["stress"]]
assert stress, "no stress case was scored"
for c in stress:
    n = {k: c["lanes"][k]["non_finite"] for k in c["lanes"]}
    print(f"{c['name']}: non-finite samples {n}")
    if n["default"] or n["variance"] or not n["minimal_clamp"]:
        failures.append(f"{c['name']}: expected non-finite samples only from minimal_clamp")
    m = c["lanes"]["minimal_clamp"]
    if not all(math.isfinite(m[k]) for k in ("flip_mean", "rmse", "flicker")):
        failures.append(f"{c['name']}: minimal_clamp's error columns are not finite: {m}")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("scorecard ranks the examples plausibly")
PY
