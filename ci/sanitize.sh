#!/usr/bin/env bash
# The unit tests that need no Vulkan device, built with clang under ASan and UBSan
# (ci/asan-build.sh): an out-of-bounds read, a leak or undefined behaviour fails CI.
# Tests that render (they include support/gpu.h, effects.h or gpu_resolve.h, or run the
# taa-harness binary or chromium) are not built in that tree (ci/asan-build.sh says which):
# lavapipe's JIT under ASan is too slow for CI. TAA_ASAN_BUILT=1: the tree is built already.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${TAA_ASAN_BUILD:-build-asan}
[ -n "${TAA_ASAN_BUILT:-}" ] || bash ci/asan-build.sh taa_tests
export ASAN_OPTIONS=abort_on_error=1:detect_leaks=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$build/tests/taa_tests" --gtest_brief=1
