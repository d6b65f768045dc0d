#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The two set-up commands of the README:
#   bash scripts/setup.sh run    install, build, run the main job
#   bash scripts/setup.sh test   install, build, run every test (also under ASan + UBSan, TSan)
# Build folders: build/ (release), build-asan/ (ASan+UBSan, unit tests only), build-tsan/
# (ThreadSanitizer, the HID reader thread's tests and the cluster bake's and selection's thread
# pools).
set -euo pipefail
cd "$(dirname "$0")/.."
what="${1:-}"
[ $# -gt 0 ] && shift
jobs="$(nproc 2>/dev/null || echo 2)"
# Each step's header says how long the run has taken so far (CI has a time limit to keep under).
step() { echo "== $1 (at $((SECONDS / 60)) min $((SECONDS % 60)) s) =="; }

bash scripts/install-deps.sh

build() {  # build DIR [cmake args...] [-- target]
  local dir="$1"; shift
  local args=() target=()
  while [ $# -gt 0 ]; do
    if [ "$1" = "--" ]; then shift; target=(--target "$@"); break; fi
    args+=("$1"); shift
  done
  # Debian's interpreter, where its python3-numpy and python3-pytest are (not a pyenv or venv
  # one first on PATH).
  local py=()
  [ -x /usr/bin/python3 ] && py=(-DPython3_EXECUTABLE=/usr/bin/python3)
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "${py[@]}" "${args[@]}" >/dev/null
  cmake --build "$dir" -j"$jobs" "${target[@]}"
}

case "$what" in
  run)
    build build -DGAZELOD_BUILD_TESTS=OFF -DGAZELOD_BUILD_BENCH=OFF
    ./build/apps/gazelod/gazelod run "$@"
    ;;
  test)
    build build -DGAZELOD_BUILD_TESTS=ON -DGAZELOD_BUILD_BENCH=ON
    bash scripts/install-gltf-validator.sh build/gltf-validator
    step "tests (release)"
    ctest --test-dir build --output-on-failure -j"$jobs" --timeout 600
    step "unit tests under AddressSanitizer + UndefinedBehaviorSanitizer"
    # -O0 -g1: line numbers in reports, and half the compile time of -O1 (UBSan's checks are
    # what -O1 spends it on: 20 s against 10 s for run/scenario.cpp); the tests run about 3x
    # slower (76 s -> ~4 min), which the 10 min saved on the build pays for.
    # GAZELOD_NO_CLONES: the selection kernels' baseline x86-64 code, which the release
    # build's load-time dispatch never runs on a machine with AVX2 or AVX-512.
    build build-asan -DGAZELOD_SANITIZE=ON -DGAZELOD_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug \
      "-DCMAKE_CXX_FLAGS_DEBUG=-O0 -g1 -DGAZELOD_NO_CLONES" -- gazelod_unit_tests
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      ctest --test-dir build-asan --output-on-failure -j"$jobs" -L unit --timeout 600
    step "HID reader thread, the cluster bake's and selection's thread pools and the C ABI's threads under ThreadSanitizer"
    # GAZELOD_NO_CLONES here too: the selection kernels' ifunc resolvers would run inside
    # libgazelod.so before the ThreadSanitizer runtime is set up (test_capi crashed loading it).
    build build-tsan -DGAZELOD_TSAN=ON -DGAZELOD_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug \
      "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1 -DGAZELOD_NO_CLONES" -- test_hid test_faults test_bake_clusters test_capi \
      test_lod_cluster_bvh test_plugin_cluster_policy
    # Repeated: a test that reads what a thread publishes before it is published fails only
    # sometimes (issue #40 item 11; 50 repeats ran clean before this landed, bench/RESULTS.md).
    TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 ./build-tsan/tests/hid/test_hid --gtest_repeat=10 --gtest_brief=1
    TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 ./build-tsan/tests/faults/test_faults --gtest_filter='HidFaults.*' \
      --gtest_repeat=10 --gtest_brief=1
    # The C ABI: an application thread registering and reading beside the render thread.
    TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 ./build-tsan/tests/capi/test_capi --gtest_filter='CApiThreads.*'
    # The cluster selection's thread pool: the same cut on 1, 2 and 4 threads.
    TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 ./build-tsan/tests/lod/test_lod_cluster_bvh \
      --gtest_filter='ClusterSelectorThreads.*' --gtest_repeat=10 --gtest_brief=1
    # The plugin's cluster frame on those threads, its switch policy stepping what they evaluated.
    TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 ./build-tsan/tests/plugin/test_plugin_cluster_policy --gtest_brief=1
    TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 ./build-tsan/tests/bake/test_bake_clusters \
      --gtest_filter='ClusterBuild.SameHierarchyOnAnyThreadCount*:ClusterBuild.OpenGridSimplifiesItsRimWithoutCrack:SharedPositions.TiledTerrainKeepsTileSeamsAndSimplifiesTheRim:ClusterGltf.SideBySideBuildsWriteTheSameFile'
    step "every libFuzzer target builds (clang, ASan+UBSan) and runs 10 s from its seeds"
    FUZZ_SECONDS=10 bash scripts/fuzz.sh
    step "done"
    ;;
  *)
    echo "usage: bash scripts/setup.sh run|test" >&2
    exit 2
    ;;
esac
