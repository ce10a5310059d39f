#!/usr/bin/env bash
# The unit tests that need no Vulkan device, built with clang under ASan and UBSan
# (ci/asan-build.sh): an out-of-bounds read, a leak or undefined behaviour fails CI.
# Tests that render (they include support/gpu.h, effects.h or gpu_resolve.h, or run the
# taa-harness binary or chromium) are left out: lavapipe's JIT under ASan is too slow for CI.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${TAA_ASAN_BUILD:-build-asan}
bash ci/asan-build.sh taa_tests
# Suites of test files that render or run the harness, by the helper headers they include.
gpu='support/(gpu|effects|gpu_resolve|process)\.h|post_test_util\.h|cli_fixture\.h|tscmaa_test_util\.h|TAA_HARNESS_BIN|chromium'
exclude=$(grep -rlE "$gpu" --include='*_test.cpp' tests |
  xargs grep -hoE '^TEST(_F|_P)?\(\s*[A-Za-z0-9_]+' | sed -E 's/^TEST(_F|_P)?\(\s*//' | sort -u |
  sed -E 's|(.*)|\1.*:*/\1.*|' | paste -sd: -)
export ASAN_OPTIONS=abort_on_error=1:detect_leaks=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$build/tests/taa_tests" --gtest_brief=1 --gtest_filter="-$exclude"
