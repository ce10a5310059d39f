#!/usr/bin/env bash
# Configures and builds the sanitizer tree shared by ci/sanitize.sh and ci/fuzz.sh: clang
# with AddressSanitizer and UndefinedBehaviorSanitizer (any UB report aborts); with
# TAA_BUILD_FUZZ the libraries also get libFuzzer's coverage instrumentation, so the fuzz
# targets are guided through the readers.
# Usage: ci/asan-build.sh TARGET...   (build folder: $TAA_ASAN_BUILD, default build-asan;
#        more configure arguments: $TAA_ASAN_CMAKE_ARGS)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${TAA_ASAN_BUILD:-build-asan}
# _GLIBCXX_ASSERTIONS: libstdc++ checks its preconditions (an index within a vector's size, not
# only within its allocation as ASan sees it; a value in an optional before it is read).
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -D_GLIBCXX_ASSERTIONS"
# Test files that render or run the taa-harness binary or chromium (they include support/gpu.h,
# effects.h, gpu_resolve.h, process.h or a fixture built on them, such as settings_audit.h,
# which renders though its test need not include gpu.h): lavapipe's JIT under ASan is
# too slow for CI, so this tree does not compile them (tests/CMakeLists.txt, TAA_TESTS_LEAVE_OUT)
# and its taa_tests holds only the tests that need no Vulkan device.
# -gline-tables-only: the file:line a sanitizer report names, at about three quarters of
# full -g's compile CPU (case_loader.cpp: 23.5 s against 31.5 s). -O1, as the sanitizers'
# own documentation suggests: the libraries compile in 220 s of CPU against -O2's 272 (unity
# batches of 32), and the fuzz targets run about as many inputs in their 30 s (fuzz_gltf the
# same, fuzz_case 17% fewer). -O0 would halve the compile and the fuzzers' throughput; the test
# drivers, which render nothing here, are -O0 (one unity batch of them: 34 s of CPU at -O1, 15 s).
render_tests='support/(gpu|effects|gpu_resolve|process|settings_audit)\.h|post_test_util\.h|cli_fixture\.h|tscmaa_test_util\.h|TAA_HARNESS_BIN|chromium'
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DTAA_BUILD_BENCH=OFF -DTAA_BUILD_FUZZ=ON -DCMAKE_CXX_FLAGS="$flags" \
  -DTAA_TESTS_LEAVE_OUT="$render_tests" -DTAA_TEST_DRIVER_OPT=-O0 \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" ${TAA_ASAN_CMAKE_ARGS:-} >/dev/null
cmake --build "$build" -j"${TAA_JOBS:-2}" --target "$@"
