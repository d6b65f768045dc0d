#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Soak run (docs/hardening.md): one simulated hour at 90 Hz (324,000 frames),
# unpaced and headless, through the plugin's frame loop against the simulated runtime, with
# resident memory sampled as it goes (tests/soak/soak_main.cpp fails on growth), then the same
# under AddressSanitizer + LeakSanitizer, and optionally a shorter valgrind memcheck run.
#
#   scripts/soak.sh                          # 324000 frames release + 324000 frames ASan/LSan
#   SOAK_FRAMES=32400 SOAK_ASAN_FRAMES=9000 SOAK_VALGRIND_FRAMES=900 scripts/soak.sh
#
# Env: SOAK_FRAMES (release run), SOAK_ASAN_FRAMES (0 skips), SOAK_VALGRIND_FRAMES (default 0:
# skipped), SOAK_MAX_GROWTH_KIB (default 1024), SOAK_JOBS (build jobs, default 2).
# Build folders: build-soak/ (RelWithDebInfo), build-soak-asan/. Exit 0 only if every stage passes.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
frames=${SOAK_FRAMES:-324000}
asan_frames=${SOAK_ASAN_FRAMES:-$frames}
vg_frames=${SOAK_VALGRIND_FRAMES:-0}
growth=${SOAK_MAX_GROWTH_KIB:-1024}
jobs=${SOAK_JOBS:-2}

build() {  # build DIR [cmake args...]
  local dir="$1"; shift
  echo "soak.sh: building gazelod_soak in $dir"
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGAZELOD_BUILD_BENCH=OFF "$@" >/dev/null
  cmake --build "$dir" --target gazelod_soak -j "$jobs" >/dev/null
}

build "$root/build-soak"
echo "soak.sh: release run, $frames frames"
"$root/build-soak/tests/soak/gazelod_soak" --frames "$frames" --max-growth-kib "$growth"

if [ "$asan_frames" -gt 0 ]; then
  build "$root/build-soak-asan" -DGAZELOD_SANITIZE=ON
  echo "soak.sh: AddressSanitizer + LeakSanitizer run, $asan_frames frames"
  # ASan's own bookkeeping (quarantine) grows RSS: only LSan's verdict counts here.
  # tests/soak/lsan.supp: one-time leaks outside gazelod (the OpenXR loader's), listed there.
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions="$root/tests/soak/lsan.supp":print_suppressions=1 \
    "$root/build-soak-asan/tests/soak/gazelod_soak" --frames "$asan_frames" --max-growth-kib $((1 << 30))
  echo "soak.sh: LeakSanitizer found no leak"
fi

if [ "$vg_frames" -gt 0 ]; then
  command -v valgrind >/dev/null || { echo "soak.sh: valgrind not installed" >&2; exit 2; }
  echo "soak.sh: valgrind memcheck run, $vg_frames frames"
  valgrind --quiet --leak-check=full --suppressions="$root/tests/soak/valgrind.supp" --errors-for-leak-kinds=definite,indirect --error-exitcode=3 \
    "$root/build-soak/tests/soak/gazelod_soak" --frames "$vg_frames" --max-growth-kib $((1 << 30))
  echo "soak.sh: valgrind found no definite or indirect leak"
fi
echo "soak.sh: PASS"
