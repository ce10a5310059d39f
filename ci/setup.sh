#!/usr/bin/env bash
# The first of README's two commands, for a fresh Debian 12 machine: install the
# dependencies from apt, configure and build, then run the main job (every case in
# cases/, with results.json, junit.xml and report.html under out/).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# Under sudo, hand build/ and out/ back to the user who asked, so README's second command
# (ctest, which writes into build/) runs without sudo; also when the main job fails.
if [ -n "${SUDO_USER:-}" ] && [ "$SUDO_USER" != root ]; then
  trap 'chown -R "$SUDO_USER": "$root/build" "$root/out" 2>/dev/null || true' EXIT
fi
if [ "$(id -u)" = 0 ]; then
  bash "$root/ci/install-deps.sh"
else
  sudo bash "$root/ci/install-deps.sh"
fi
# Extra configure arguments (CI passes -DTAA_WERROR=ON) come from $TAA_CMAKE_ARGS.
# shellcheck disable=SC2086
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo ${TAA_CMAKE_ARGS:-}
# One job more than cores: in CI's one-batch unity build the test batch alone takes about 90 s,
# and with one job a core it started last, alone with the other core idle (152 s against 166 s).
cmake --build "$root/build" -j "$(($(nproc) + 1))"
# Installs taa-harness and its SPIR-V (PREFIX/bin, PREFIX/share/taa-harness), so README's daily
# commands work as typed from any folder; $TAA_PREFIX picks another prefix than /usr/local.
prefix=${TAA_PREFIX:-/usr/local}
if [ "$(id -u)" = 0 ] || { mkdir -p "$prefix" 2>/dev/null && [ -w "$prefix" ]; }; then
  cmake --install "$root/build" --prefix "$prefix"
else
  sudo cmake --install "$root/build" --prefix "$prefix"
fi
"$prefix/bin/taa-harness" run "$root/cases" --out "$root/out"
