#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fuzz campaigns (docs/hardening.md): builds the libFuzzer targets with clang
# (-DGAZELOD_FUZZ=ON, ASan+UBSan) in build-fuzz/ and runs each for FUZZ_SECONDS (default 120).
#
#   scripts/fuzz.sh                     # every target, 120 s each
#   FUZZ_SECONDS=600 scripts/fuzz.sh fuzz_scenario fuzz_gltf
#
# Seeds: fuzz/corpus/<target>/ (read only). New coverage goes to build-fuzz/corpus/<target>/,
# crashes to build-fuzz/artifacts/<target>/; fuzz/<name>.dict, where present, is the dictionary. A crash stops the script with exit 1: fix it, copy
# the input into fuzz/corpus/<target>/ (tests/faults replays every corpus file in ctest).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${FUZZ_SECONDS:-120}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_trace_reader fuzz_scenario fuzz_hid_reports fuzz_budget_instance fuzz_gltf fuzz_capi)

command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DGAZELOD_FUZZ=ON \
  -DGAZELOD_BUILD_TESTS=OFF -DGAZELOD_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --target "${targets[@]}" -j "${FUZZ_BUILD_JOBS:-2}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
for t in "${targets[@]}"; do
  name=${t#fuzz_}
  work="$build/corpus/$name"; art="$build/artifacts/$name"
  mkdir -p "$work" "$art"
  dict=(); [ -f "$root/fuzz/$name.dict" ] && dict=(-dict="$root/fuzz/$name.dict")
  echo "fuzz.sh: $t for ${seconds}s (seeds fuzz/corpus/$name, corpus $work)"
  if ! "$build/fuzz/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
       -print_final_stats=1 "${dict[@]}" -artifact_prefix="$art/" "$work" "$root/fuzz/corpus/$name" \
       > "$build/$t.log" 2>&1; then
    echo "fuzz.sh: $t FAILED: see $build/$t.log and $art/" >&2
    tail -n 40 "$build/$t.log" >&2
    status=1
  fi
  grep -E '^stat::(number_of_executed_units|peak_rss_mb)|cov: ' "$build/$t.log" | tail -n 3 || true
done
exit $status
