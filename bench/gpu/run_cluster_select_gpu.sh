#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The GPU cluster-selection pass on 10 M clusters (bench_cluster_select_gpu.cpp): builds the
# benchmark (Release) if needed, prints the machine (date, CPU, Vulkan devices) and runs it; the
# figure is the dispatch's timestamp-query ms. Target on a real GPU: <= 0.3 ms per frame.
#   bench/gpu/run_cluster_select_gpu.sh [--build-dir DIR] [-- BENCH_ARGS...]
# BENCH_ARGS: --clusters N (10000000), --frames F (20), --triangles T (1000000, the baked
# terrain), --cpu (lavapipe even where a GPU exists). The benchmark prefers a discrete GPU.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$root/build
while [[ $# -gt 0 ]]; do
  case $1 in
    --build-dir) build=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "usage: $0 [--build-dir DIR] [-- BENCH_ARGS...]" >&2; exit 64 ;;
  esac
done
if [[ ! -f $build/CMakeCache.txt ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")
[[ $type == Release ]] || echo "note: $build is a '$type' build; figures are meant from Release" >&2
cmake --build "$build" --target bench_cluster_select_gpu -j"$(nproc)"

echo "date: $(date -u '+%Y-%m-%d %H:%M:%S UTC')"
echo "cpu: $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1) ($(nproc) cores)"
if command -v vulkaninfo > /dev/null; then
  echo "vulkan devices:"
  vulkaninfo --summary 2> /dev/null | sed -n 's/^[[:space:]]*deviceName[[:space:]]*= /  /p' || true
fi
exec "$build/bench/gpu/bench_cluster_select_gpu" "$@"
