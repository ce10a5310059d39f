#!/usr/bin/env bash
# Fuzzes the case reader, the track readers, the glTF loader and the PNG/OpenEXR readers
# with libFuzzer under ASan
# and UBSan (ci/asan-build.sh), each for a bounded time: $TAA_FUZZ_SECONDS (default 60).
# Seeds: the checked-in corpus tests/fuzz/corpus/TARGET (replayed first: each must pass),
# cases/, the tracks and the glTF scenes. A crash, a sanitizer report, an input running
# over 10 s or needing over 2 GiB (one allocation over 512 MiB for the image readers, whose
# 64 KiB inputs can hold no more) fails the script; libFuzzer leaves the input as
# crash-*/timeout-*/oom-* in $TAA_FUZZ_OUT (default build-asan/fuzz): copy it into
# tests/fuzz/corpus/TARGET/ once fixed, so every build replays it (fuzz_regressions_test).
# TAA_ASAN_BUILT=1: the fuzz targets are built already (.ci/run builds the tree once).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${TAA_ASAN_BUILD:-build-asan}
seconds=${TAA_FUZZ_SECONDS:-60}
out=${TAA_FUZZ_OUT:-$build/fuzz}
[ -n "${TAA_ASAN_BUILT:-}" ] || bash ci/asan-build.sh fuzz_case fuzz_track fuzz_gltf fuzz_image
export ASAN_OPTIONS=abort_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in case track gltf image; do
  work="$out/$target"
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/artifacts"
  cp tests/fuzz/corpus/$target/* "$work/corpus/"
  case $target in
    case) cp cases/*.json cases/sweep/*.json "$work/corpus/" 2>/dev/null || true ;;
    track) cp cases/tracks/*.json cases/tracks/*.csv "$work/corpus/" 2>/dev/null || true ;;
    gltf) cp cases/scenes/*.gltf cases/scenes/*.glb cases/scenes/refused/* "$work/corpus/" 2>/dev/null || true ;;
    image) find cases/scenes -name '*.png' -size -64k -exec cp {} "$work/corpus/" \; ;;
  esac
  limits="-rss_limit_mb=2048 -timeout=10"
  [ $target = image ] && limits="$limits -malloc_limit_mb=512"
  echo "fuzz_$target: replaying tests/fuzz/corpus/$target"
  "$build/tests/fuzz/fuzz_$target" $limits tests/fuzz/corpus/$target/*
  echo "fuzz_$target: fuzzing for $seconds s"
  "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" $limits \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$work/artifacts/" "$work/corpus"
done
echo "fuzz: every target ran clean for $seconds s"
