#!/usr/bin/env bash
# cmake/copy_spirv.cmake (TAA_SPIRV_FROM): a copy newer than its shader and headers is made; a
# missing one, or one older than or as old as any of them, fails the build naming what to rebuild.
#   copy_spirv_selftest.sh CMAKE SCRIPT
set -u
cmake=$1 script=$2
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
status=0
check() {
  if [ "$2" = "$3" ]; then echo "ok   $1"; else echo "FAIL $1 (got '$2', want '$3')"; status=1; fi
}
copy() {
  "$cmake" "-DFROM=$t/$1" "-DTO=$t/out/to.spv" "-DSOURCES=$t/a.comp;$t/h.glsl" -P "$script" >"$t/log" 2>&1
  echo $?
}
echo source >"$t/a.comp"
echo header >"$t/h.glsl"
echo words >"$t/from.spv"
touch -d '2026-01-01 00:00' "$t/a.comp" "$t/h.glsl"
touch -d '2026-01-02 00:00' "$t/from.spv"
check "a copy newer than its sources is made" "$(copy from.spv)" 0
check "with the other tree's bytes" "$(cat "$t/out/to.spv" 2>&1)" words
rm -f "$t/out/to.spv"
touch -d '2026-01-03 00:00' "$t/h.glsl"
check "a header newer than the other tree's SPIR-V fails the copy" "$(copy from.spv)" 1
check "naming the header" "$(grep -c "older than $t/h.glsl" "$t/log")" 1
check "and writes nothing" "$(test -e "$t/out/to.spv" && echo written || echo none)" none
touch -d '2026-01-02 00:00' "$t/h.glsl"
check "as old as a source fails too" "$(copy from.spv)" 1
check "a missing file fails" "$(copy none.spv)" 1
check "saying it is missing" "$(grep -c "none.spv is missing" "$t/log")" 1
exit $status
