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
# Everything after the case is passed to `taa-harness run`. Each step compares exactly, so any
# changed byte counts: when the goldens hold no positive for this machine's environment (another
# CPU level, driver or GPU than the blesser's), the first step makes one from the known-good
# commit before judging anything: it builds that commit beside the tree, renders the case there
# and adds the run's frames to the goldens copy (bless --from ... --add-environment), which
# refuses frames outside the case's tolerances of the trusted ones. The known-good commit is
# $TAA_BISECT_GOOD, else the newest of `git bisect good`'s refs (refs/bisect/good-*).
set -u
root=$(git rev-parse --show-toplevel) || exit 125
build=${TAA_BISECT_BUILD:-$root/build-bisect}
log=$build/bisect-build.log
mkdir -p "$build"

# build_at DIR SOURCE: configures and builds taa-harness from SOURCE into DIR; 1 when it fails.
build_at() {
  # Warnings are not errors here: an old commit must build with today's compiler.
  cmake -S "$2" -B "$1" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAA_WERROR=OFF \
    -DTAA_BUILD_TESTS=OFF -DTAA_BUILD_BENCH=OFF >"$1.log" 2>&1 &&
    cmake --build "$1" --target taa-harness >>"$1.log" 2>&1
}

# The goldens folder given after --goldens, if any.
goldens=
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  [ "${args[$i]}" = --goldens ] && goldens=${args[$((i + 1))]:-}
done

# golden_mode RESULTS: "tolerance" when the case was judged without a positive for this machine.
golden_mode() {
  python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["cases"][0].get("golden_mode",""))' "$1" 2>/dev/null
}

# Makes this environment's positive in $goldens from the known-good commit; 0 when it exists after.
make_positive() {
  local good=${TAA_BISECT_GOOD:-$(git for-each-ref --sort=-committerdate --format='%(objectname)' 'refs/bisect/good-*' | head -n1)}
  [ -n "$good" ] || { echo "bisect: no known-good commit (set TAA_BISECT_GOOD or run git bisect good)"; return 1; }
  local src=$build/good-src gb=$build/good-build
  goldens=$(cd "$goldens" && pwd) || return 1
  echo "bisect: the goldens hold no positive for this machine; making one from known-good ${good:0:12}"
  git worktree remove --force "$src" >/dev/null 2>&1 || rm -rf "$src"
  git worktree add --detach "$src" "$good" >/dev/null 2>&1 || { echo "bisect: cannot check out $good"; return 1; }
  build_at "$gb" "$src" || { echo "bisect: known-good commit does not build (see $gb.log)"; return 1; }
  local case_file=$1
  (cd "$src" && "$gb/harness/taa-harness" run "$case_file" --goldens "$goldens" --out "$build/good-out" >/dev/null)
  (cd "$src" && "$gb/harness/taa-harness" bless --from "$build/good-out" "$case_file" --add-environment \
    --goldens "$goldens" --reason "bisect: this machine's positive, rendered at known-good ${good:0:12}")
  local rc=$?
  git worktree remove --force "$src" >/dev/null 2>&1
  return $rc
}

if ! build_at "$build" "$root"; then
  echo "bisect: build failed (see $build.log): skip"; exit 125
fi
run_log=$build/bisect-run.log
run_step() {
  "$build/harness/taa-harness" run "$@" --out "$build/bisect-out" 2>&1 | tee "$run_log"
  return "${PIPESTATUS[0]}"
}
run_step "$@"
rc=$?
if [ -n "$goldens" ] && [ "$(golden_mode "$build/bisect-out/results.json")" = tolerance ]; then
  if make_positive "$1"; then
    echo "bisect: positive added; judging this commit exactly"
    run_step "$@"
    rc=$?
  else
    echo "bisect: no positive could be made; this step is judged within tolerances"
  fi
fi
# Where the sequence starts to go wrong (a commit older than per-frame hashes prints nothing here).
grep -E '^FAIL .* frame [0-9]+ sequence: ' "$run_log" | sed 's/^FAIL /bisect: first differing frame: /'
case $rc in
  0) exit 0 ;;
  1) exit 1 ;;
  *) echo "bisect: taa-harness exited $rc (bad input or environment): skip"; exit 125 ;;
esac
