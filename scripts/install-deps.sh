#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian 12 packages gazelod needs to build, test and run. Idempotent; run as
# root (or with sudo available). Every dependency is a Debian package: nothing is downloaded
# from anywhere else.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  # OpenXR: loader + headers, Khronos's hello_xr, the core validation layer
  libopenxr-dev libopenxr-loader1 libopenxr-utils openxr-layer-corevalidation
  # Vulkan with Mesa's lavapipe (CPU) driver; glslang compiles our shaders
  libvulkan-dev mesa-vulkan-drivers vulkan-tools vulkan-validationlayers glslang-tools
  # Maths, devices, assets, formats, command line
  libglm-dev libhidapi-dev libtinygltf-dev libmeshoptimizer-dev nlohmann-json3-dev libcli11-dev
  libpng-dev
  # Tests and benchmarks; clang + its runtime for the libFuzzer targets (scripts/fuzz.sh)
  libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev ninja-build
  # The evaluation's peer (bench/peer): OpenSceneGraph's osg::LOD
  libopenscenegraph-dev
  assimp-testmodels  # real glTF 2.0 models (Khronos 2CylinderEngine, ...) for the bake --clusters test
  gltfpack  # meshoptimizer's own simplifier, the bake's peer (gazelod eval gltfpack)
  abigail-tools  # abidiff: the C ABI of libgazelod.so against its checked-in baseline
  # Bindings: the Python package (pybind11, numpy; pytest and matplotlib for its tests and the
  # worked example) and C# (mono's compiler and runtime, as Unity loads native plugins)
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib mono-mcs mono-runtime
)
# node + npm run Khronos's glTF-Validator (npm gltf-validator; scripts/install-gltf-validator.sh).
# Debian's packages only where no node / npm is installed (a NodeSource nodejs brings its own npm,
# and Debian's npm would conflict with it).
command -v node >/dev/null || packages+=(nodejs)
command -v npm >/dev/null || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
