#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The install_layer test (tests/install/CMakeLists.txt passes every argument): the eye-gaze API
# layer as `cmake --install` lays it out, used from the install prefix only.
#  1. cmake --install the xr_runtime, xr_layer and program components into <work>/prefix;
#  2. both layer manifests' library_path resolve to the installed library (the explicit one's
#     relative to its folder, the implicit one's absolute, in the prefix), neither names the
#     build tree;
#  3. explicit layer: XR_API_LAYER_PATH=<prefix>/share/openxr/1/api_layers/explicit.d and
#     XR_ENABLE_API_LAYERS: the installed `gazelod layer check` finds it and would emulate, and
#     an eye-gaze-only client gets gaze from it on the installed runtime without eye gaze;
#  4. implicit layer: the installed implicit manifest copied into an implicit.d folder
#     (XDG_DATA_HOME): inactive without GAZELOD_EYE_GAZE_LAYER_ENABLE (the client cannot enable
#     the extension), active with it, inactive again with GAZELOD_EYE_GAZE_LAYER_DISABLE.
set -euo pipefail

while [[ $# -gt 0 ]]; do
  case "$1" in
    --cmake) cmake=$2; shift 2 ;;
    --build-dir) build=$2; shift 2 ;;
    --config) config=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --layer-lib) layer_lib_rel=$2; shift 2 ;;
    --explicit-dir) explicit_rel=$2; shift 2 ;;
    --implicit-dir) implicit_rel=$2; shift 2 ;;
    --manifest-name) manifest_name=$2; shift 2 ;;
    --runtime-manifest) runtime_rel=$2; shift 2 ;;
    --bindir) bindir=$2; shift 2 ;;
    --client) client=$2; shift 2 ;;
    *) echo "install_layer_test.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

fail() { echo "install_layer: FAIL $*" >&2; exit 1; }
step() { echo "== $*"; }

prefix=$work/prefix
rm -rf "$work"
mkdir -p "$work"
step "cmake --install $build --prefix $prefix (xr_runtime, xr_layer, program)"
cfg=()
[[ -n ${config:-} ]] && cfg=(--config "$config")
for component in xr_runtime xr_layer program; do
  "$cmake" --install "$build" --prefix "$prefix" --component "$component" "${cfg[@]}" >> "$work/install.log" ||
    { cat "$work/install.log"; fail "cmake --install --component $component"; }
done

step "layout and manifests"
for f in "$layer_lib_rel" "$explicit_rel/$manifest_name" "$implicit_rel/$manifest_name" "$runtime_rel" "$bindir/gazelod"; do
  [[ -e $prefix/$f ]] || fail "not installed: $f"
done
build_abs=$(cd "$build" && pwd)
for m in "$explicit_rel/$manifest_name" "$implicit_rel/$manifest_name"; do
  ! grep -qF "$build_abs/" "$prefix/$m" || [[ $prefix == "$build_abs"/* ]] || fail "$m names the build tree"
  ! grep -F '"library_path"' "$prefix/$m" | grep -qF "$build_abs/layer" || fail "$m names the build tree's library"
  lib_path=$(sed -n 's/.*"library_path": *"\([^"]*\)".*/\1/p' "$prefix/$m")
  [[ $lib_path == /* ]] || lib_path=$(dirname "$prefix/$m")/$lib_path
  [[ $(realpath "$lib_path") == $(realpath "$prefix/$layer_lib_rel") ]] ||
    fail "$m: library_path $lib_path is not the installed $layer_lib_rel"
  echo "$m -> $(realpath --relative-to="$prefix" "$lib_path")"
done
grep -q '"disable_environment": "GAZELOD_EYE_GAZE_LAYER_DISABLE"' "$prefix/$implicit_rel/$manifest_name" ||
  fail "the implicit manifest has no disable_environment"
grep -q '"enable_environment": "GAZELOD_EYE_GAZE_LAYER_ENABLE"' "$prefix/$implicit_rel/$manifest_name" ||
  fail "the implicit manifest has no enable_environment"

export XR_RUNTIME_JSON=$prefix/$runtime_rel
export GAZELOD_SIM_EYE_GAZE_EXTENSION=0 GAZELOD_SIM_PACED=0 GAZELOD_SIM_DURATION_S=1
unset XR_ENABLE_API_LAYERS XR_API_LAYER_PATH GAZELOD_LAYER_CONFIG GAZELOD_EYE_GAZE_LAYER_ENABLE GAZELOD_EYE_GAZE_LAYER_DISABLE

step "explicit layer: the client gets eye gaze, gazelod layer check says so"
XR_API_LAYER_PATH=$prefix/$explicit_rel XR_ENABLE_API_LAYERS=XR_APILAYER_GAZELOD_eye_gaze \
  "$client" --write-trace "$work/trace.csv" > "$work/explicit.log" 2>&1 || { cat "$work/explicit.log"; fail "client, explicit layer"; }
grep 'layer_gaze_client:' "$work/explicit.log"
XR_API_LAYER_PATH=$prefix/$explicit_rel XR_ENABLE_API_LAYERS=XR_APILAYER_GAZELOD_eye_gaze GAZELOD_LAYER_TRACE=$work/trace.csv \
  "$prefix/$bindir/gazelod" layer check > "$work/check.txt" 2>&1 || { cat "$work/check.txt"; fail "gazelod layer check"; }
cat "$work/check.txt"
grep -q 'found by the loader, enabled' "$work/check.txt" || fail "layer check: layer not found"
grep -q '^decision   emulating XR_EXT_eye_gaze_interaction with gaze from trace' "$work/check.txt" || fail "layer check: decision"

step "implicit layer: enable and disable variables"
export XDG_DATA_HOME=$work/xdg
mkdir -p "$XDG_DATA_HOME/openxr/1/api_layers/implicit.d"
cp "$prefix/$implicit_rel/$manifest_name" "$XDG_DATA_HOME/openxr/1/api_layers/implicit.d/$manifest_name"
if "$client" --write-trace "$work/trace.csv" > "$work/implicit-off.log" 2>&1; then
  fail "without GAZELOD_EYE_GAZE_LAYER_ENABLE the implicit layer must stay off"
fi
grep -q 'xrCreateInstance failed' "$work/implicit-off.log" || { cat "$work/implicit-off.log"; fail "implicit, off"; }
GAZELOD_EYE_GAZE_LAYER_ENABLE=1 "$client" --write-trace "$work/trace.csv" > "$work/implicit-on.log" 2>&1 ||
  { cat "$work/implicit-on.log"; fail "client, implicit layer enabled"; }
grep 'layer_gaze_client:' "$work/implicit-on.log"
if GAZELOD_EYE_GAZE_LAYER_ENABLE=1 GAZELOD_EYE_GAZE_LAYER_DISABLE=1 "$client" --write-trace "$work/trace.csv" \
     > "$work/implicit-disabled.log" 2>&1; then
  fail "GAZELOD_EYE_GAZE_LAYER_DISABLE must turn the implicit layer off"
fi
echo "install_layer: PASS"
