#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs Khronos's glTF-Validator (npm package gltf-validator, pinned) for the bake
# --clusters integration test (tests/bake/cluster_validator_test.cpp), which looks for it in
# BUILD_DIR/gltf-validator/node_modules (or $GAZELOD_GLTF_VALIDATOR_PATH):
#   bash scripts/install-gltf-validator.sh build/gltf-validator
# Needs node, npm and the npm registry; without them it says so and exits 0 (the test skips, and
# fails under CI=true: tests/skip_or_fail.hpp).
set -euo pipefail
prefix="${1:-build/gltf-validator}"
version="2.0.0-dev.3.10"
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  echo "install-gltf-validator: node/npm not installed; the validator test will skip"
  exit 0
fi
if grep -qs "\"version\": \"$version\"" "$prefix/node_modules/gltf-validator/package.json"; then
  echo "install-gltf-validator: gltf-validator $version already in $prefix"
  exit 0
fi
if ! timeout 30 npm ping >/dev/null 2>&1; then
  echo "install-gltf-validator: the npm registry is not reachable; the validator test will skip"
  exit 0
fi
mkdir -p "$prefix"
npm install --prefix "$prefix" --no-audit --no-fund --no-save "gltf-validator@$version"
echo "install-gltf-validator: gltf-validator $version in $prefix/node_modules"
