#!/usr/bin/env bash
# For `git bisect run`: builds the commit under test and runs one case against a
# fixed set of goldens. Exit 0 good, 1 bad, 125 skip (the commit does not build or
# cannot run the case).
#
#   cp -r goldens /tmp/known-good-goldens           # goldens you trust, outside the tree
#   git bisect start BAD GOOD
#   git bisect run ci/bisect.sh cases/A.json --goldens /tmp/known-good-goldens
#   git bisect run ci/bisect.sh cases/A.json --goldens /tmp/known-good-goldens --metric flip_mean --above 0.05
#
# Everything after the case is passed to `taa-harness run`. When the goldens' environment is
# this machine's, every frame's hash is compared and the first differing frame is printed.
set -u
root=$(git rev-parse --show-toplevel) || exit 125
build=${TAA_BISECT_BUILD:-$root/build-bisect}
log=$build/bisect-build.log
mkdir -p "$build"
# Warnings are not errors here: an old commit must build with today's compiler.
if ! cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAA_WERROR=OFF \
     -DTAA_BUILD_TESTS=OFF -DTAA_BUILD_BENCH=OFF >"$log" 2>&1; then
  echo "bisect: configure failed (see $log): skip"; exit 125
fi
if ! cmake --build "$build" --target taa-harness >>"$log" 2>&1; then
  echo "bisect: build failed (see $log): skip"; exit 125
fi
run_log=$build/bisect-run.log
"$build/harness/taa-harness" run "$@" --out "$build/bisect-out" 2>&1 | tee "$run_log"
rc=${PIPESTATUS[0]}
# Where the sequence starts to go wrong (a commit older than per-frame hashes prints nothing here).
grep -E '^FAIL .* frame [0-9]+ sequence: ' "$run_log" | sed 's/^FAIL /bisect: first differing frame: /'
case $rc in
  0) exit 0 ;;
  1) exit 1 ;;
  *) echo "bisect: taa-harness exited $rc (bad input or environment): skip"; exit 125 ;;
esac
