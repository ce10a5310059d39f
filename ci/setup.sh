#!/usr/bin/env bash
# The first of README's two commands, for a fresh Debian 12 machine: install the
# dependencies from apt, configure and build, then run the main job (every case in
# cases/, with results.json, junit.xml and report.html under out/).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "$(id -u)" = 0 ]; then
  bash "$root/ci/install-deps.sh"
else
  sudo bash "$root/ci/install-deps.sh"
fi
# Extra configure arguments (CI passes -DTAA_WERROR=ON) come from $TAA_CMAKE_ARGS.
# shellcheck disable=SC2086
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo ${TAA_CMAKE_ARGS:-}
cmake --build "$root/build" -j "$(nproc)"
"$root/build/harness/taa-harness" run "$root/cases" --out "$root/out"
