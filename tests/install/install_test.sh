#!/usr/bin/env bash
# The install_consumer test (tests/install/CMakeLists.txt passes every argument):
#  1. cmake --install the build into <work>/prefix (a fresh one each run);
#  2. check the layout, that no installed CMake/pkg-config file names the source or build
#     tree, that the runtime manifest's library_path resolves to the installed library, and
#     that every installed header compiles on its own with only the prefix's include dirs;
#  3. configure, build and run tests/install/consumer/ out of tree with
#     -DCMAKE_PREFIX_PATH=<prefix> (find_package(gazelod CONFIG REQUIRED));
#  4. compile the same main.cpp with `pkg-config --cflags --libs gazelod` and run it;
#  5. run the installed gazelod program.
# Both consumers run on the installed simulated runtime (XR_RUNTIME_JSON = installed manifest).
set -euo pipefail

built=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --cmake) cmake=$2; shift 2 ;;
    --build-dir) build=$2; shift 2 ;;
    --config) config=$2; shift 2 ;;
    --consumer) consumer=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --cxx) cxx=$2; shift 2 ;;
    --pkg-config) pkgconfig=$2; shift 2 ;;
    --libdir) libdir=$2; shift 2 ;;
    --manifest) manifest_rel=$2; shift 2 ;;
    --runtime-lib) runtime_lib_rel=$2; shift 2 ;;
    --bindir) bindir=$2; shift 2 ;;
    --ldflags) ldflags=$2; shift 2 ;;
    --built) shift; built=("$@"); break ;;
    *) echo "install_test.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

fail() { echo "install_consumer: FAIL $*" >&2; exit 1; }
step() { echo "== $*"; }

for f in "${built[@]}"; do
  [[ -e $f ]] || fail "$f is not built; build what is installed first:
  $cmake --build $build --target gazelod_install_targets"
done

prefix=$work/prefix
rm -rf "$work"
mkdir -p "$work"

step "cmake --install $build --prefix $prefix"
cfg=()
[[ -n ${config:-} ]] && cfg=(--config "$config")
"$cmake" --install "$build" --prefix "$prefix" "${cfg[@]}" > "$work/install.log" ||
  { cat "$work/install.log"; fail "cmake --install"; }

step "layout"
expect=(
  include/gazelod/gazelod.hpp
  include/gazelod/plugin/frame_output.hpp include/gazelod/plugin/gaze_source_kind.hpp
  include/gazelod/plugin/plugin_config.hpp
  include/gazelod/lod/lod_chain.hpp include/gazelod/lod/cone.hpp include/gazelod/lod/criterion.hpp
  include/gazelod/lod/acuity.hpp include/gazelod/lod/select.hpp
  include/gazelod/budget/frame_budget_options.hpp include/gazelod/budget/cost_model.hpp
  include/gazelod/gaze/gaze_source.hpp include/gazelod/gaze/gaze_sample.hpp
  "$libdir/libgazelod_plugin.a" "$libdir/libgazelod_budget.a" "$libdir/libgazelod_gaze.a"
  "$libdir/libgazelod_lod.a"
  "$libdir/cmake/gazelod/gazelodConfig.cmake" "$libdir/cmake/gazelod/gazelodConfigVersion.cmake"
  "$libdir/cmake/gazelod/gazelodTargets.cmake"
  "$libdir/pkgconfig/gazelod.pc"
  "$runtime_lib_rel" "$manifest_rel" "$bindir/gazelod"
)
for f in "${expect[@]}"; do
  [[ -e $prefix/$f ]] || fail "not installed: $f"
done
# Every lod/*.hpp of the source tree.
src_root=$(cd "$consumer/../../.." && pwd)
for h in "$src_root"/lod/*.hpp; do
  [[ -e $prefix/include/gazelod/lod/$(basename "$h") ]] || fail "not installed: include/gazelod/lod/$(basename "$h")"
done
[[ ! -e $prefix/include/gazelod/plugin/gazelod.hpp ]] || fail "gazelod.hpp installed twice"
(cd "$prefix" && find . -type f | sort) > "$work/installed.txt"
echo "$(wc -l < "$work/installed.txt") files installed (list: $work/installed.txt)"

# Installed package files must not point back into the trees this was built from.
if grep -rlF -e "$src_root" -e "$(cd "$build" && pwd)" "$prefix/$libdir/cmake" "$prefix/$libdir/pkgconfig" \
     "$prefix/$manifest_rel"; then
  fail "the files above name the source or build tree"
fi

# library_path: relative to the manifest's folder (the loader's rule) or absolute.
lib_path=$(sed -n 's/.*"library_path": *"\([^"]*\)".*/\1/p' "$prefix/$manifest_rel")
[[ $lib_path == /* ]] || lib_path=$(dirname "$prefix/$manifest_rel")/$lib_path
[[ -e $lib_path ]] || fail "manifest library_path $lib_path does not exist"
[[ $(realpath "$lib_path") == $(realpath "$prefix/$runtime_lib_rel") ]] ||
  fail "manifest library_path $lib_path is not the installed $runtime_lib_rel"
echo "manifest $manifest_rel -> $(realpath --relative-to="$prefix" "$lib_path")"

step "every installed header compiles alone (-I prefix/include -I prefix/include/gazelod only)"
(cd "$prefix/include" && find gazelod -name '*.hpp' | sort) > "$work/headers.txt"
export cxx prefix work
xargs -P 2 -I{} bash -c 'echo "#include <{}>" | "$cxx" -std=c++20 -fsyntax-only \
    -I"$prefix/include" -I"$prefix/include/gazelod" -x c++ - 2> "$work/header-$(echo {} | tr / _).log" ||
  { echo "header {} does not compile alone:"; cat "$work/header-$(echo {} | tr / _).log"; exit 255; }' \
  < "$work/headers.txt" || fail "an installed header does not compile alone"
echo "$(wc -l < "$work/headers.txt") headers"

export XR_RUNTIME_JSON=$prefix/$manifest_rel
export GAZELOD_SIM_PACED=0
scenario=$consumer/still_gaze.json

step "find_package(gazelod CONFIG REQUIRED) consumer"
"$cmake" -S "$consumer" -B "$work/consumer-build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
  -DCMAKE_EXE_LINKER_FLAGS="$ldflags" > "$work/consumer-configure.log" 2>&1 ||
  { cat "$work/consumer-configure.log"; fail "configuring the consumer"; }
grep -- '-- gazelod' "$work/consumer-configure.log"
found_dir=$(sed -n 's/^gazelod_DIR:PATH=//p' "$work/consumer-build/CMakeCache.txt")
[[ $(realpath "$found_dir") == $(realpath "$prefix/$libdir/cmake/gazelod") ]] ||
  fail "find_package found gazelod in $found_dir, not in the install prefix"
"$cmake" --build "$work/consumer-build" -j 2 > "$work/consumer-build.log" 2>&1 ||
  { cat "$work/consumer-build.log"; fail "building the consumer"; }
"$work/consumer-build/gazelod_consumer" "$scenario" || fail "the CMake-built consumer"

step "pkg-config consumer"
export PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
pc_flags=$("$pkgconfig" --cflags --libs gazelod) || fail "pkg-config --cflags --libs gazelod"
echo "pkg-config --cflags --libs gazelod: $pc_flags"
pc_manifest=$("$pkgconfig" --variable=xr_runtime_json gazelod)
[[ $(realpath "$pc_manifest") == $(realpath "$XR_RUNTIME_JSON") ]] ||
  fail "gazelod.pc's xr_runtime_json is $pc_manifest, not the installed manifest"
# shellcheck disable=SC2086  # word splitting of the flags is intended
"$cxx" -std=c++20 -O1 -o "$work/gazelod_consumer_pc" "$consumer/main.cpp" $pc_flags $ldflags ||
  fail "compiling the consumer with pkg-config's flags"
"$work/gazelod_consumer_pc" "$scenario" || fail "the pkg-config-built consumer"

step "installed gazelod program"
"$prefix/$bindir/gazelod" hmds > "$work/hmds.txt" || fail "$bindir/gazelod hmds"
grep -q questpro "$work/hmds.txt" || fail "$bindir/gazelod hmds lists no questpro"
echo "$bindir/gazelod hmds: $(wc -l < "$work/hmds.txt") lines"
# Without XR_RUNTIME_JSON the installed program finds the installed runtime beside it.
env -u XR_RUNTIME_JSON XR_LOADER_DEBUG=info \
  "$prefix/$bindir/gazelod" run --frames 20 --no-render --out "$work/run" > "$work/run.txt" 2>&1 ||
  fail "$bindir/gazelod run --frames 20 --no-render (see $work/run.txt)"
grep -q "loading runtime defined in manifest file $prefix/share/openxr/1/gazelod_xr_runtime.json" "$work/run.txt" ||
  fail "$bindir/gazelod run did not load the installed runtime manifest"
echo "$bindir/gazelod run: used the installed runtime"

echo "install_consumer: PASS"
