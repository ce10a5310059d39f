#!/usr/bin/env bash
# Writes the tool-made variants of our own assets (Debian's gltfpack, from ci/install-deps.sh).
# Run from the repository root after make_assets.py; the output is deterministic, commit it.
#   skinned_quad_gltfpack.glb: skinned_quad.gltf quantised by gltfpack 0.18 (KHR_mesh_quantization:
#   integer positions, their dequantisation in the inverse bind matrices), which new-case must
#   frame by its posed vertices (tests/harness/new_case_test.cpp).
set -euo pipefail
cd "$(dirname "$0")"
gltfpack -i skinned_quad.gltf -o skinned_quad_gltfpack.glb
