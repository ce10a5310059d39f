#!/usr/bin/env bash
# Installs every build and run dependency from Debian 12's packages (run as root).
# One package a line, so that changes merge cleanly.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
packages=(
  build-essential
  clang
  # libFuzzer and the ASan/UBSan runtimes for ci/sanitize.sh and ci/fuzz.sh.
  libclang-rt-14-dev
  cmake
  ninja-build
  pkg-config
  git
  libvulkan-dev
  mesa-vulkan-drivers
  vulkan-validationlayers
  glslang-tools
  # glslang as a library, to compile a user's resolve shader (taa.shader) at run time.
  glslang-dev
  # SPIRV-Tools' optimizer: `taa-harness coverage` specializes the resolve per case (glslang-dev
  # depends on it too; named here because the harness links it itself).
  spirv-tools
  libglm-dev
  nlohmann-json3-dev
  # PNG reading and writing (core/png_codec.cpp).
  libpng-dev
  # OpenEXR reading and writing (core/exr_codec.cpp).
  libopenexr-dev
  # Only the tests link OpenImageIO, to cross-check our PNG and EXR code (tests/crosscheck).
  libopenimageio-dev
  # OpenImageIO's CMake package names /usr/bin/iconvert and the other tools as imported
  # targets and refuses to configure when they are absent.
  openimageio-tools
  libtinygltf-dev
  # glTF EXT_meshopt_compression decoding (and encoding in its tests).
  libmeshoptimizer-dev
  # glTF KHR_draco_mesh_compression decoding (and encoding in its tests).
  libdraco-dev
  # gltfpack and Draco's tools write the compressed and quantised variants of outside models
  # (cases/scenes/make_variants.sh); building and testing do not run them.
  gltfpack
  draco
  googletest
  libgtest-dev
  libbenchmark-dev
  # The report check renders out/report.html headless.
  chromium
  # ci/mutate.py (the mutation self-test) and its ctest check.
  python3
)
if [ "${TAA_SKIP_APT_UPDATE:-0}" != 1 ]; then apt-get update; fi
apt-get install -y --no-install-recommends "${packages[@]}"
