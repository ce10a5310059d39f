#!/usr/bin/env bash
# Configures and builds the sanitizer tree shared by ci/sanitize.sh and ci/fuzz.sh: clang
# with AddressSanitizer and UndefinedBehaviorSanitizer (any UB report aborts), plus
# libFuzzer's coverage instrumentation so the fuzz targets are guided through the readers.
# Usage: ci/asan-build.sh TARGET...   (build folder: $TAA_ASAN_BUILD, default build-asan)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${TAA_ASAN_BUILD:-build-asan}
flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DTAA_BUILD_BENCH=OFF -DTAA_BUILD_FUZZ=ON -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j"${TAA_JOBS:-2}" --target "$@"
