#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs an OpenXR program against the simulated runtime with the Khronos core validation layer
# and checks what it did:
#   exit 0 from the program, its log shows XR_SESSION_STATE_FOCUSED and later
#   XR_SESSION_STATE_EXITING, the runtime (GAZELOD_SIM_LOG=1) counted submitted frames, and the
#   validation layer reported nothing.
# Usage: check_xr_run.sh <runtime manifest> <work dir> -- <program> [args...]
# Exit codes: 0 ok, 1 program failed, 2 usage, 3 validation messages, 4 lifecycle or frames missing.
set -u
if [[ $# -lt 4 || $3 != "--" ]]; then
  echo "usage: $0 <runtime manifest> <work dir> -- <program> [args...]" >&2
  exit 2
fi
manifest=$1
work=$2
shift 3
mkdir -p "$work"
log=$work/program.log
vlog=$work/core_validation.txt
rm -f "$log" "$vlog"

export XR_RUNTIME_JSON=$manifest
export XR_ENABLE_API_LAYERS=XR_APILAYER_LUNARG_core_validation
export XR_CORE_VALIDATION_EXPORT_TYPE=text
export XR_CORE_VALIDATION_FILE_NAME=$vlog
export VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
export GAZELOD_SIM_DURATION_S=${GAZELOD_SIM_DURATION_S:-3}
export GAZELOD_SIM_LOG=1

echo "check_xr_run: running $* (scenario ${GAZELOD_SIM_DURATION_S} s), log in $log"
# hello_xr ends when its standard input reaches end of file: keep stdin open for the run
# (a sleeping writer whose only descriptor besides the pipe is /dev/null, killed afterwards,
# so CTest does not wait for it).
exec 3< <(exec sleep 60 2> /dev/null)
stdin_holder=$!
timeout 55 "$@" <&3 > "$log" 2>&1
rc=$?
exec 3<&-
kill "$stdin_holder" 2> /dev/null
if [[ $rc -ne 0 ]]; then
  echo "check_xr_run: program exited with $rc; last lines:"
  tail -n 30 "$log"
  exit 1
fi

# Validation: the layer must have been loaded (it announces its output type on stdout), and
# it writes its messages to the file; also look for any that reached the log.
if ! grep -q 'Core Validation output type' "$log"; then
  echo "check_xr_run: the core validation layer was not loaded"
  exit 4
fi
if [[ -s $vlog ]] && grep -qE 'VUID|ERROR|WARNING|Error|Warning' "$vlog"; then
  echo "check_xr_run: the core validation layer reported:"
  head -n 40 "$vlog"
  exit 3
fi
if grep -qE 'VUID-|OpenXR-Core-Validation|core_validation.*(ERROR|WARNING)' "$log"; then
  echo "check_xr_run: validation messages in the program log:"
  grep -E 'VUID-|OpenXR-Core-Validation' "$log" | head -n 40
  exit 3
fi

focused=$(grep -n 'XR_SESSION_STATE_FOCUSED' "$log" | head -n 1 | cut -d: -f1)
exiting=$(grep -n 'XR_SESSION_STATE_EXITING' "$log" | tail -n 1 | cut -d: -f1)
if [[ -z $focused || -z $exiting || $exiting -le $focused ]]; then
  echo "check_xr_run: the log does not show FOCUSED followed by EXITING"
  grep -n 'XR_SESSION_STATE' "$log" | head -n 20
  exit 4
fi
frames=$(sed -n 's/.*gazelod_xr_runtime: session destroyed: \([0-9]*\) frames submitted, \([0-9]*\) layers.*/\1 \2/p' "$log" | tail -n 1)
read -r nframes nlayers <<< "${frames:-0 0}"
if [[ ${nframes:-0} -lt 1 ]]; then
  echo "check_xr_run: the runtime saw no submitted frame"
  exit 4
fi
echo "check_xr_run: ok: FOCUSED (line $focused) then EXITING (line $exiting), $nframes frames and $nlayers layers submitted, no validation message"
exit 0
