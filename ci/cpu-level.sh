#!/usr/bin/env bash
# The case suite at CPU feature levels other than the goldens' (GALLIUM_OVERRIDE_CPU_CAPS):
# lavapipe generates other code there, so low bits differ and the harness takes its tolerance
# path: stored frames against each case's checks.tolerance, every other frame by its quality
# signature. Any failure here is either a real regression or a tolerance too tight for another
# machine; both must be fixed, never ignored.
#
#   ci/cpu-level.sh [BUILD_DIR]                  levels: sse4.1, and avx (AVX2 without AVX-512)
#                                                when the CPU has AVX-512, which the goldens used
#   TAA_CPU_LEVELS="sse4.1 ssse3" ci/cpu-level.sh  other levels Mesa's override knows
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
harness=$build/harness/taa-harness
[ -x "$harness" ] || { echo "cpu-level: $harness not built (ninja -C $build taa-harness)" >&2; exit 3; }
levels=${TAA_CPU_LEVELS:-sse4.1}
if [ -z "${TAA_CPU_LEVELS:-}" ] && grep -qw avx512f /proc/cpuinfo; then levels="$levels avx"; fi
status=0
for level in $levels; do
  echo "cpu-level: GALLIUM_OVERRIDE_CPU_CAPS=$level"
  if ! CI=true GALLIUM_OVERRIDE_CPU_CAPS=$level "$harness" run cases --out "out/cpu-$level"; then
    echo "cpu-level: the suite fails at $level (report: out/cpu-$level/report.html)" >&2
    status=1
  fi
done
exit $status
