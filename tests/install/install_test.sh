#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
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
  include/gazelod/gazelod.h include/gazelod/gazelod.hpp
  "$libdir/libgazelod.so.1" "$libdir/libgazelod.so"
  "$libdir/cmake/gazelod/gazelodConfig.cmake" "$libdir/cmake/gazelod/gazelodConfigVersion.cmake"
  "$libdir/cmake/gazelod/gazelodTargets.cmake"
  "$libdir/pkgconfig/gazelod.pc"
  "$runtime_lib_rel" "$manifest_rel" "$bindir/gazelod"
  share/gazelod/shaders/cluster_select.comp share/gazelod/shaders/cluster_select_gpu.h
)
for f in "${expect[@]}"; do
  [[ -e $prefix/$f ]] || fail "not installed: $f"
done
src_root=$(cd "$consumer/../../.." && pwd)
# Headers only under include/gazelod/, and only the public ones.
extra=$(cd "$prefix/include" && find . -type f ! -path './gazelod/gazelod.h' ! -path './gazelod/gazelod.hpp')
[[ -z $extra ]] || fail "headers other than gazelod/gazelod.h and gazelod/gazelod.hpp installed: $extra"
(cd "$prefix" && find . -type f | sort) > "$work/installed.txt"
echo "$(wc -l < "$work/installed.txt") files installed (list: $work/installed.txt)"

step "libgazelod.so: exports only gzl_*, needs no OpenXR loader"
lib=$prefix/$libdir/libgazelod.so.1
# objdump's output read whole first: with pipefail, `objdump | grep -q` fails whenever grep's
# early exit makes objdump die of SIGPIPE, which happened under load.
headers=$(objdump -p "$lib")
grep -q 'SONAME *libgazelod.so.1' <<< "$headers" || fail "libgazelod.so.1 has no SONAME libgazelod.so.1"
! grep -qi 'NEEDED.*openxr' <<< "$headers" || fail "libgazelod.so.1 needs an OpenXR loader"
undefined_xr=$(nm -D --undefined-only "$lib" | awk '{print $2}' | grep '^xr' || true)
[[ -z $undefined_xr ]] || fail "libgazelod.so.1 has undefined xr* symbols: $undefined_xr"
others=$(nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBRVW]$/ {print $3}' | grep -v '^gzl_' || true)
[[ -z $others ]] || fail "libgazelod.so.1 exports symbols other than gzl_*: $(echo $others | head -c 300)"
echo "$(nm -D --defined-only "$lib" | grep -c ' gzl_') gzl_* symbols, nothing else"

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

step "the headers compile alone: gazelod.h as C99 and C++17, gazelod.hpp as C++17 (-Werror)"
echo '#include <gazelod/gazelod.h>' | cc -std=c99 -pedantic -Wall -Wextra -Werror -fsyntax-only -I"$prefix/include" -x c - ||
  fail "gazelod.h does not compile alone as C99"
for h in gazelod.h gazelod.hpp; do
  echo "#include <gazelod/$h>" | "$cxx" -std=c++17 -pedantic -Wall -Wextra -Werror -fsyntax-only -I"$prefix/include" -x c++ - ||
    fail "$h does not compile alone as C++17"
done

step "the GPU selection's interface header compiles alone (C99, C++17); its shader compiles"
shaders=$prefix/share/gazelod/shaders
cc -std=c99 -pedantic -Wall -Wextra -Werror -fsyntax-only -x c "$shaders/cluster_select_gpu.h" ||
  fail "cluster_select_gpu.h does not compile alone as C99"
"$cxx" -std=c++17 -pedantic -Wall -Wextra -Werror -fsyntax-only -x c++ "$shaders/cluster_select_gpu.h" ||
  fail "cluster_select_gpu.h does not compile alone as C++17"
if command -v glslangValidator > /dev/null; then
  glslangValidator -V --target-env vulkan1.1 -o "$work/cluster_select.spv" "$shaders/cluster_select.comp" > /dev/null ||
    fail "the installed cluster_select.comp does not compile"
fi

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
"$cxx" -std=c++17 -O1 -o "$work/gazelod_consumer_pc" "$consumer/main.cpp" $pc_flags $("$pkgconfig" --libs openxr) -Wl,-rpath,"$prefix/$libdir" $ldflags ||
  fail "compiling the consumer with pkg-config's flags"
"$work/gazelod_consumer_pc" "$scenario" || fail "the pkg-config-built consumer"

step "installed Python package (when the binding was built)"
pkg=$(ls -d "$prefix"/lib/python3*/dist-packages/gazelod 2>/dev/null | head -n1 || true)
if [[ -n $pkg && -x /usr/bin/python3 ]]; then
  # Found from the prefix alone: libgazelod.so.1 through the module's RUNPATH, the simulated
  # runtime through the package's own search (XR_RUNTIME_JSON unset).
  (cd "$work" && env -u XR_RUNTIME_JSON PYTHONPATH="$(dirname "$pkg")" /usr/bin/python3 -c "
import gazelod
assert gazelod.__file__.startswith('$prefix'), gazelod.__file__
r = gazelod.run(frames=10, out='$work/py-run')
assert r.decisions.shape[0] == 10, r.decisions.shape
print('python: gazelod', gazelod.__version__, 'from', gazelod.__file__, '->', r.decisions.shape)
") || fail "the installed Python package"
else
  echo "no Python package installed (binding not built): skipped"
fi

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
