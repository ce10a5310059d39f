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
echo "installed taa-harness rendered and passed from $work/elsewhere"
