#!/usr/bin/env bash
# The full settings audit (docs/settings-audit.md): every key of `taa-harness techniques --json`
# that can change pixels, set to another legal value on every path (each taa.mode, stereo
# TSCMAA, velocity off, upsampling, deferred lighting), must be refused with exit 2 or change
# the output. Prints the table (key | path | value | verdict | message) and fails on any key
# accepted and ignored. ctest runs only its fast subset (the resolve's keys on the full path).
#
#   ci/audit-settings.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
tests=$build/tests/taa_tests
[ -x "$tests" ] || { echo "audit-settings: $tests not built (ninja -C $build taa_tests)" >&2; exit 3; }
TAA_SETTINGS_AUDIT=full "$tests" --gtest_filter='SettingsAudit.*'
