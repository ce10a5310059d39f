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
tests=$build/tests/taa_tests
# TAA_SANITIZE_JOBS=N runs the suites in N processes at once, whole suites to each (as ctest runs
# them: a suite's tests share its scratch folders, so two processes never split one). .ci/run
# asks for 2, so the sanitized tests do not finish alone on one core once the fuzzers have ended.
# Each process's output is printed whole, in order, once all have ended.
jobs=${TAA_SANITIZE_JOBS:-1}
if [ "$jobs" -le 1 ]; then
  exec "$tests" --gtest_brief=1
fi
# Suite lines start in column one ("Name." or "Prefix/Name/0.  # TypeParam = ..."); test lines
# are indented. Disabled tests are listed but do not run.
listing=$("$tests" --gtest_list_tests)
suite='/^[^ ]+\.( |$)/'
mapfile -t suites < <(awk "$suite"' {sub(/\.$/, "", $1); print $1}' <<<"$listing")
expected=$(awk "$suite"' {off = ($1 ~ /^DISABLED_|\/DISABLED_/)} /^  [^ ]/ {if (!off && $1 !~ /^DISABLED_/) n++} END {print n + 0}' <<<"$listing")
[ ${#suites[@]} -gt 0 ] || { echo "sanitize: $tests lists no suites" >&2; exit 1; }
# An empty --gtest_filter would run every test: never more processes than suites.
[ "$jobs" -le ${#suites[@]} ] || jobs=${#suites[@]}
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
pids=()
for ((lane = 0; lane < jobs; lane++)); do
  filter=
  for ((i = lane; i < ${#suites[@]}; i += jobs)); do filter+="${suites[$i]}.*:"; done
  "$tests" --gtest_brief=1 --gtest_filter="${filter%:}" >"$logs/$lane" 2>&1 &
  pids+=($!)
done
status=0
for ((lane = 0; lane < jobs; lane++)); do
  wait "${pids[$lane]}" || { status=1; echo "sanitize: process $lane of $jobs failed" >>"$logs/$lane"; }
done
for ((lane = 0; lane < jobs; lane++)); do cat "$logs/$lane"; done
# Every test ran in some process: a suite the split missed would otherwise drop out unseen.
ran=$(cat "$logs"/* | sed -n 's/^\[==========\] \([0-9]*\) tests\? from .* ran\..*/\1/p' | awk '{n += $1} END {print n + 0}')
if [ "$status" = 0 ] && [ "$ran" != "$expected" ]; then
  echo "sanitize: $ran tests ran in $jobs processes, but $tests lists $expected" >&2
  status=1
fi
[ "$status" = 0 ] && echo "sanitize: $ran tests in $jobs processes"
exit $status
