#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Khronos's OpenXR Conformance Test Suite (CTS 1.1.41.0) on the simulated runtime: the
# non-interactive suites with Vulkan and headless, the scripted-input action tests
# (XR_EXT_conformance_automation) and the eye-gaze tests. Needs ../shared beside the checkout
# (../shared/tools/openxr-cts/run-cts.sh builds the CTS once, about 12 minutes on 2 cores,
# cached in ~/.cache/gazelod-cts). docs/runtime.md, "Conformance", lists what it runs.
# Khronos's Vulkan validation layer watches every run: a Vulkan call the runtime gets wrong is
# undefined behaviour that lavapipe survives most of the time, so a passing test case alone does
# not show it (one CI run crashed in SwapchainsRender; the layer then showed sRGB storage images
# the device cannot make).
#
#   bash scripts/cts.sh [OUT_DIR]     exit 0 when no test case failed and no Vulkan call was invalid
set -euo pipefail
cd "$(dirname "$0")/.."
cts=../shared/tools/openxr-cts/run-cts.sh
[ -f "$cts" ] || { echo "cts: $cts not found (the CTS ships in ../shared beside the checkout)" >&2; exit 2; }
out="${1:-build/cts}"
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc 2>/dev/null || echo 2)" --target gazelod_xr_runtime
echo "cts: running the conformance suite on build/sim/runtime (results in $out)" >&2
# Paced: frames on the wall clock, as a headset's are. Unpaced, only xrWaitFrame moves the
# simulated clock, so a predicted display time falls behind CLOCK_MONOTONIC whenever the
# application is slower than the display; XR_KHR_convert_timespec_time's "Matches frame timing"
# then failed in 2 of 3 runs on a loaded machine (session setup took 54-62 ms of wall clock
# against 44 ms of simulated frames).
export GAZELOD_SIM_PACED=1
# Without the layer the loader would ignore VK_INSTANCE_LAYERS and the check below see nothing.
layer=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
[ -f "$layer" ] || { echo "cts: $layer missing (Debian's vulkan-validationlayers)" >&2; exit 2; }
status=0
VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation bash "$cts" build/sim/runtime/gazelod_xr_runtime.json "$out" || status=$?
# The layer's messages, as the CTS prints them ("Validation Error: [ VUID-... ]").
pattern='Validation Error|VUID-|UNASSIGNED-'
invalid=$(cat "$out"/*.out "$out"/*.err 2>/dev/null | grep -cE "$pattern" || true)
if [ "$invalid" -gt 0 ]; then
  echo "cts: $invalid Vulkan validation errors (in $out/*.out), the first:" >&2
  { grep -hE -m 3 "$pattern" "$out"/*.out "$out"/*.err | cut -c1-400 >&2; } || true
  status=1
fi
exit "$status"
