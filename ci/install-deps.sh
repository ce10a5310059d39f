#!/usr/bin/env bash
# Installs every build and run dependency from Debian 12's packages (run as root).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
packages=(
  build-essential cmake ninja-build pkg-config git
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools
  libglm-dev nlohmann-json3-dev libopenimageio-dev libtinygltf-dev
  googletest libgtest-dev libbenchmark-dev
  chromium
)
if [ "${TAA_SKIP_APT_UPDATE:-0}" != 1 ]; then apt-get update; fi
apt-get install -y --no-install-recommends "${packages[@]}"
