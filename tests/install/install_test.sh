#!/usr/bin/env bash
# What a user gets from `cmake --install`: installs into a fresh prefix, then, from a folder
# outside both trees, checks that the installed binary loads its own SPIR-V, renders a case
# copied there, and passes a case of the source tree against its goldens bit for bit.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work/elsewhere"
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
exe="$work/prefix/bin/taa-harness"
want="shaders: $work/prefix/share/taa-harness/shaders"
version=$(cd "$work/elsewhere" && "$exe" --version)
if ! grep -qxF "$want" <<<"$version"; then
  echo "installed binary does not load its installed shaders; --version says:"
  echo "$version"
  exit 1
fi
cp "$src/cases/checkerboard_static.json" "$work/elsewhere/mine.json"
cd "$work/elsewhere"
"$exe" render mine.json --out frames
for f in 0 23; do
  png=$(printf 'frames/mine/frame_%04d.png' "$f")
  [ -s "$png" ] || { echo "render wrote no $png:"; ls -R frames | head; exit 1; }
done
"$exe" run "$src/cases/checkerboard_static.json" --out run-out

# A user's own resolve outside both trees, against the installed taa_user.h: run (no goldens
# yet), bless, run again (bit-exact), a sweep with it as a preset, a scorecard, and a compile
# error that names the file and line with exit 2.
export TAA_SHADER_CACHE="$work/shader-cache"
mkdir -p mine/cases
cp "$src/examples/user_taa/cases/minimal_clamp.comp" mine/cases/my_resolve.comp
scene='"scene": {"builtin": "checkerboard"}, "render": {"width": 64, "height": 36}, "script": {"frames": 8},
  "movers": [{"shape": "cube", "start": [-2, 0.5, 2], "end": [2, 0.5, 2], "speed": 2.4}]'
echo "{$scene, \"taa\": {\"shader\": \"my_resolve.comp\", \"shader_clamps\": true},
  \"checks\": {\"invariants\": [\"finite\", \"history_bounded\"]}}" >mine/cases/my_case.json
echo "{$scene}" >mine/cases/plain.json
echo '{"builtin": {}, "mine": {"taa": {"shader": "my_resolve.comp"}}}' >mine/presets.json
env -u CI "$exe" run mine/cases/my_case.json --out user-run >user-run.log  # no goldens yet: a skip
"$exe" bless mine/cases/my_case.json --reason "install test" >/dev/null
[ -f mine/goldens/my_case/manifest.json ] || { echo "bless wrote no goldens for the user shader"; exit 1; }
"$exe" run mine/cases/my_case.json --out user-run2 | grep -q "^PASS my_case" || { echo "user shader case did not pass its goldens"; exit 1; }
"$exe" sweep mine/cases/plain.json --presets builtin,mine --presets-file mine/presets.json --out user-sweep >/dev/null
grep -q "^mine," user-sweep/sweep.csv || { echo "sweep has no row for the user shader preset"; exit 1; }
# The report's A/B split: the built-in resolve against the user shader on one replay.
mkdir -p mine/cases/presets
cp mine/presets.json mine/cases/presets/presets.json
echo "{$scene, \"output\": {\"frames\": [7]}, \"report\": {\"ab\": \"mine\"}}" >mine/cases/ab.json
env -u CI "$exe" run mine/cases/ab.json --out user-ab >/dev/null
[ -f user-ab/ab/frame_0007.ab.png ] || { echo "report.ab wrote no B frame for the user shader preset"; exit 1; }
if cmp -s user-ab/ab/frame_0007.png user-ab/ab/frame_0007.ab.png; then
  echo "report.ab's B frame (user shader) equals A (built-in resolve)"; exit 1
fi
grep -q "frame_0007.ab.png" user-ab/report.html || { echo "the report shows no A/B split"; exit 1; }
"$exe" score mine/cases/my_resolve.comp --cases mine/cases --out user-score >/dev/null
[ -s user-score/score.json ] || { echo "score wrote no score.json"; exit 1; }
printf '#version 450\n#include "taa_user.h"\nvoid main() {\n  nope();\n}\n' >mine/cases/broken.comp
echo "{$scene, \"taa\": {\"shader\": \"broken.comp\"}}" >mine/cases/broken.json
set +e
"$exe" validate mine/cases/broken.json 2>broken.err
rc=$?
set -e
[ "$rc" = 2 ] || { echo "a compile error exited $rc, not 2"; exit 1; }
grep -q "broken.comp:4:" broken.err || { echo "the compile error does not name file and line:"; cat broken.err; exit 1; }
echo "installed taa-harness rendered, passed and ran a user shader from $work/elsewhere"
