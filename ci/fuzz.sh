#!/usr/bin/env bash
# Fuzzes the case reader, the track readers, the glTF loader, the PNG/OpenEXR readers, a
# user's HLSL resolve (compile, entry-point rules, spirv-val, interface check), the results-file
# readers (merge, coverage --results, run --verdict-from, bless --from), the lanes reader, and the
# entry readers of the reference cache and the SPIR-V cache with libFuzzer under ASan and UBSan
# (ci/asan-build.sh), each for a bounded time: $TAA_FUZZ_SECONDS (default 60).
# Seeds: the checked-in corpus tests/fuzz/corpus/TARGET (replayed first: each must pass),
# cases/, the tracks and the glTF scenes. A crash, a sanitizer report, an input running
# over 10 s or needing over 2 GiB (one allocation over 512 MiB for the image readers, whose
# 64 KiB inputs can hold no more) fails the script; libFuzzer leaves the input as
# crash-*/timeout-*/oom-* in $TAA_FUZZ_OUT (default build-asan/fuzz): copy it into
# tests/fuzz/corpus/TARGET/ once fixed, so every build replays it (fuzz_regressions_test).
# TAA_ASAN_BUILT=1: the fuzz targets are built already (.ci/run builds the tree once).
# `ci/fuzz.sh --targets` prints the targets' build names (.ci/run builds them with the tree).
set -euo pipefail
cd "$(dirname "$0")/.."
# The targets are the files tests/fuzz/fuzz_NAME.cpp, less the *_test.cpp that replays their
# corpus in taa_tests (tests/fuzz/CMakeLists.txt globs the same).
targets=()
for f in tests/fuzz/fuzz_*.cpp; do
  [[ $f == *_test.cpp ]] && continue
  f=${f#tests/fuzz/fuzz_}
  targets+=("${f%.cpp}")
done
if [ "${1:-}" = --targets ]; then
  echo "${targets[@]/#/fuzz_}"
  exit 0
fi
build=${TAA_ASAN_BUILD:-build-asan}
seconds=${TAA_FUZZ_SECONDS:-60}
out=${TAA_FUZZ_OUT:-$build/fuzz}
[ -n "${TAA_ASAN_BUILT:-}" ] || bash ci/asan-build.sh "${targets[@]/#/fuzz_}"
export ASAN_OPTIONS=abort_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Called where `set -e` does not reach (a lane's `||`): each step that can fail returns.
fuzz_one() {
  local target=$1 work limits
  work="$out/$target"
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/artifacts" || return 1
  cp tests/fuzz/corpus/$target/* "$work/corpus/" || return 1
  case $target in
    case) cp cases/*.json cases/sweep/*.json "$work/corpus/" 2>/dev/null || true ;;
    track) cp cases/tracks/*.json cases/tracks/*.csv "$work/corpus/" 2>/dev/null || true ;;
    gltf) cp cases/scenes/*.gltf cases/scenes/*.glb cases/scenes/refused/* "$work/corpus/" 2>/dev/null || true ;;
    image) find cases/scenes -name '*.png' -size -64k -exec cp {} "$work/corpus/" \; ;;
    shader) find examples/user_taa -name '*.hlsl' -size -2k -exec cp {} "$work/corpus/" \; ;;
  esac
  limits="-rss_limit_mb=2048 -timeout=10"
  [ $target = image ] && limits="$limits -malloc_limit_mb=512"
  # Each shader input is a glslang compile in a forked child (tens of ms): short inputs keep
  # the runs many; a resolve's interesting parts (semantics, attributes) fit in 2 KiB.
  local max_len=65536
  [ $target = shader ] && max_len=2048
  echo "fuzz_$target: replaying tests/fuzz/corpus/$target"
  "$build/tests/fuzz/fuzz_$target" $limits tests/fuzz/corpus/$target/* || return 1
  echo "fuzz_$target: fuzzing for $seconds s"
  "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" $limits \
    -max_len=$max_len -print_final_stats=1 -artifact_prefix="$work/artifacts/" "$work/corpus" || return 1
}
# TAA_FUZZ_JOBS=2 fuzzes two targets at a time (each still for $seconds s; .ci/run does, so the
# core the sanitized unit tests leave free is not idle); each target's output is printed whole,
# in target order, once all have ended.
jobs=${TAA_FUZZ_JOBS:-1}
logs=$(mktemp -d)
status=0
for ((lane = 0; lane < jobs; lane++)); do
  (
    for ((i = lane; i < ${#targets[@]}; i += jobs)); do
      fuzz_one "${targets[$i]}" >"$logs/${targets[$i]}" 2>&1 || { echo "fuzz_${targets[$i]} failed" >>"$logs/${targets[$i]}"; exit 1; }
    done
  ) &
done
for ((lane = 0; lane < jobs; lane++)); do wait -n || status=1; done
for target in "${targets[@]}"; do [ -f "$logs/$target" ] && cat "$logs/$target"; done
rm -rf "$logs"
[ $status = 0 ] || { echo "fuzz: a target failed (its output above; inputs in $out/TARGET/artifacts)" >&2; exit 1; }
echo "fuzz: every target ran clean for $seconds s"
