#!/usr/bin/env bash
# The case suite at CPU feature levels other than the primary positive's (GALLIUM_OVERRIDE_CPU_CAPS):
# lavapipe generates other code there, so low bits differ. The goldens hold a positive of their
# own for sse4.1 (blessed with `bless --from RUN --add-environment` from a run at that level), so
# that level is compared bit for bit and run with --require-exact: a case without its positive
# fails. A level without a positive (avx below, or any level TAA_CPU_LEVELS names) takes the
# tolerance path: stored frames against each case's checks.tolerance, every other frame by its
# quality signature (tests/harness/positives_test.cpp keeps that path tested at ssse3).
#
#   ci/cpu-level.sh [BUILD_DIR]                  levels: sse4.1, and avx (AVX2 without AVX-512)
#                                                when the CPU has AVX-512, which the goldens used
#   TAA_EXACT_LEVELS="sse4.1"                    the levels whose positives the goldens hold: run with
#                                                TAA_REQUIRE_EXACT=1 (the others on the tolerance path)
#   TAA_CPU_LEVELS="sse4.1 ssse3" ci/cpu-level.sh  other levels Mesa's override knows; each listed
#                                                level runs the whole suite, no probe
#
# The avx level runs the whole suite only where it renders other bytes than this machine's
# own level. A few probe cases render at both levels first; when every one of their frames
# hashes the same, the full run would repeat ctest's exact verdicts on the same bytes (on the
# goldens' machine, lavapipe's 256-bit vectors: all 14,251 frames of the 117 cases were equal,
# docs/performance.md), and the level is left out with a line saying so.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
harness=$build/harness/taa-harness
[ -x "$harness" ] || { echo "cpu-level: $harness not built (ninja -C $build taa-harness)" >&2; exit 3; }
levels=${TAA_CPU_LEVELS:-sse4.1}
probe_avx=
if [ -z "${TAA_CPU_LEVELS:-}" ] && grep -qw avx512f /proc/cpuinfo; then levels="$levels avx" probe_avx=1; fi

# Whether the probe cases' frames at GALLIUM_OVERRIDE_CPU_CAPS=$1 hash as at the native level.
# Forward, deferred with shadows, glTF skinning, HDR, TSCMAA, MSAA, sharpening, motion blur and
# the adaptive tracer: at sse4.1, 183 of their 184 frames differ from the native level's.
probe_cases=(rough_floor_mover_ycocg_variance shadows_deferred_open_area gltf_animated_mover
  gltf_skinned_normals_cubic stress_hdr_highlights tscmaa_fence msaa_4x_fence sharpen_cas
  motion_blur_velocity_in_alpha adaptive_aniso)
same_as_native() {
  local out=out/cpu-probe files=() earlier=()
  for c in "${probe_cases[@]}"; do files+=("cases/$c.json"); done
  # The native frames come from the main job's results when this very build made them from the
  # same inputs (run --verdict-from checks that, and renders otherwise).
  [ -f out/results.json ] && earlier=(--verdict-from out/results.json)
  rm -rf "$out"
  "$harness" run "${files[@]}" "${earlier[@]}" --out "$out/native" >/dev/null || true
  GALLIUM_OVERRIDE_CPU_CAPS=$1 "$harness" run "${files[@]}" --out "$out/$1" >/dev/null || true
  python3 - "$out/native/results.json" "$out/$1/results.json" <<'EOF'
import json, sys
a, b = (json.load(open(p))["cases"] for p in sys.argv[1:])
hashes = lambda cs: {c["name"]: c["frame_sha256"] for c in cs}
ha, hb = hashes(a), hashes(b)
frames = sum(len(v) for v in ha.values())
if ha != hb or not frames:
    sys.exit(1)
print(f"{frames} frames of {len(ha)} probe cases")
EOF
}

status=0
for level in $levels; do
  if [ "$level" = avx ] && [ -n "$probe_avx" ] && probed=$(same_as_native avx); then
    echo "cpu-level: avx left out: its $probed hash as at this machine's level, so ctest's exact verdicts hold for it (TAA_CPU_LEVELS=\"sse4.1 avx\" runs it anyway)"
    continue
  fi
  exact=0
  for e in ${TAA_EXACT_LEVELS:-sse4.1}; do [ "$e" = "$level" ] && exact=1; done
  echo "cpu-level: GALLIUM_OVERRIDE_CPU_CAPS=$level (TAA_REQUIRE_EXACT=$exact)"
  if ! CI=true TAA_REQUIRE_EXACT=$exact GALLIUM_OVERRIDE_CPU_CAPS=$level "$harness" run cases --out "out/cpu-$level"; then
    echo "cpu-level: the suite fails at $level (report: out/cpu-$level/report.html)" >&2
    status=1
  fi
done
exit $status
