# SPDX-License-Identifier: Apache-2.0
# `cmake --install`: the plugin's libraries and public headers, an exported CMake package
# (find_package(gazelod CONFIG) -> gazelod::plugin, gazelod::lod, gazelod::budget,
# gazelod::gaze), a pkg-config file, the simulated OpenXR runtime with an installed manifest,
# and the gazelod program. Layout (GNUInstallDirs; <libdir> is lib or lib/<multiarch>):
#
#   include/gazelod/gazelod.h              the C ABI (C99): #include <gazelod/gazelod.h>
#   include/gazelod/gazelod.hpp            a thin C++17 wrapper over it
#   <libdir>/libgazelod.so.1 (+ .so link)  exports only gzl_*; links no OpenXR loader
#   <libdir>/cmake/gazelod/                gazelodConfig.cmake, ConfigVersion, Targets
#   <libdir>/pkgconfig/gazelod.pc
#   <libdir>/gazelod/libgazelod_xr_runtime.so       the simulated OpenXR runtime
#   share/openxr/1/gazelod_xr_runtime.json          its manifest (XR_RUNTIME_JSON=<this file>)
#   <libdir>/gazelod/libXrApiLayer_gazelod_eye_gaze.so      the eye-gaze API layer, and its
#   share/openxr/1/api_layers/explicit.d/, share/gazelod/openxr/1/api_layers/implicit.d/ manifests
#   bin/gazelod
#   share/gazelod/shaders/cluster_select.comp    GPU cluster selection (GLSL, docs/gpu-selection.md)
#   share/gazelod/shaders/cluster_select_gpu.h   its bindings, buffer layouts, push constants (C99)
#
# Components: dev (libraries, headers, CMake and pkg-config files), xr_runtime, xr_layer, program,
# shaders.
# tests/install/ installs into a scratch prefix and builds a
# consumer against it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GAZELOD_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/gazelod)
set(GAZELOD_INSTALL_HEADERDIR ${CMAKE_INSTALL_INCLUDEDIR}/gazelod)
set(GAZELOD_XR_RUNTIME_INSTALL_LIBDIR ${CMAKE_INSTALL_LIBDIR}/gazelod)
set(GAZELOD_XR_RUNTIME_INSTALL_MANIFEST ${CMAKE_INSTALL_DATADIR}/openxr/1/gazelod_xr_runtime.json)

# ---- the library: libgazelod.so.<major>, the C ABI only ----------------------------------
# The engine's static libraries are inside it and not installed: applications see gzl_* and
# nothing else (plugin/capi/exports.map), so no C++ standard library or compiler version leaks
# through the interface.
set(gazelod_installed_targets gazelod_shared)
install(TARGETS gazelod_shared EXPORT gazelodTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev NAMELINK_COMPONENT dev
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

# ---- public headers: include/gazelod/ (C99 gazelod.h, the C++17 wrapper gazelod.hpp) ---------
file(GLOB gazelod_public_headers CONFIGURE_DEPENDS ${GAZELOD_ROOT}/include/gazelod/*.h ${GAZELOD_ROOT}/include/gazelod/*.hpp)
install(FILES ${gazelod_public_headers} DESTINATION ${GAZELOD_INSTALL_HEADERDIR} COMPONENT dev)

# ---- CMake package -------------------------------------------------------------------------
install(EXPORT gazelodTargets NAMESPACE gazelod:: FILE gazelodTargets.cmake
  DESTINATION ${GAZELOD_INSTALL_CMAKEDIR} COMPONENT dev)
set(gazelod_pkg_dir ${CMAKE_BINARY_DIR}/gazelod-package)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/gazelodConfig.cmake.in
  ${gazelod_pkg_dir}/gazelodConfig.cmake
  INSTALL_DESTINATION ${GAZELOD_INSTALL_CMAKEDIR}
  PATH_VARS GAZELOD_XR_RUNTIME_INSTALL_MANIFEST)
# 0.x: a new minor version may break the API.
write_basic_package_version_file(${gazelod_pkg_dir}/gazelodConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${gazelod_pkg_dir}/gazelodConfig.cmake ${gazelod_pkg_dir}/gazelodConfigVersion.cmake
  DESTINATION ${GAZELOD_INSTALL_CMAKEDIR} COMPONENT dev)

# ---- pkg-config ------------------------------------------------------------------------------
# Relocatable: prefix is found from the .pc file's own folder (works with --prefix and DESTDIR).
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(GAZELOD_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH gazelod_pc_up /_prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /_prefix)
  string(REGEX REPLACE "/$" "" gazelod_pc_up "${gazelod_pc_up}")
  set(GAZELOD_PC_PREFIX "\${pcfiledir}/${gazelod_pc_up}")
endif()
foreach(var LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${var}}")
    set(GAZELOD_PC_${var} "${CMAKE_INSTALL_${var}}")
  else()
    set(GAZELOD_PC_${var} "\${prefix}/${CMAKE_INSTALL_${var}}")
  endif()
endforeach()
if(IS_ABSOLUTE "${GAZELOD_XR_RUNTIME_INSTALL_MANIFEST}")
  set(GAZELOD_PC_XR_RUNTIME_JSON "${GAZELOD_XR_RUNTIME_INSTALL_MANIFEST}")
else()
  set(GAZELOD_PC_XR_RUNTIME_JSON "\${prefix}/${GAZELOD_XR_RUNTIME_INSTALL_MANIFEST}")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/gazelod.pc.in ${gazelod_pkg_dir}/gazelod.pc @ONLY)
install(FILES ${gazelod_pkg_dir}/gazelod.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dev)

# ---- the simulated OpenXR runtime ------------------------------------------------------------
# The installed manifest's library_path is relative to the manifest's folder (the Khronos
# loader resolves it from there, also through a symlink such as active_runtime.json), so it
# points at the installed library whatever --prefix or DESTDIR says. The build tree keeps its
# own manifest (GAZELOD_XR_RUNTIME_JSON, sim/runtime/CMakeLists.txt).
if(TARGET gazelod_xr_runtime)
  install(TARGETS gazelod_xr_runtime
    LIBRARY DESTINATION ${GAZELOD_XR_RUNTIME_INSTALL_LIBDIR} COMPONENT xr_runtime)
  get_filename_component(manifest_dir ${GAZELOD_XR_RUNTIME_INSTALL_MANIFEST} DIRECTORY)
  if(IS_ABSOLUTE "${GAZELOD_XR_RUNTIME_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${manifest_dir}")
    set(lib_dir_from_manifest ${GAZELOD_XR_RUNTIME_INSTALL_LIBDIR})
    if(NOT IS_ABSOLUTE "${lib_dir_from_manifest}")
      set(lib_dir_from_manifest ${CMAKE_INSTALL_PREFIX}/${lib_dir_from_manifest})
    endif()
  else()
    file(RELATIVE_PATH lib_dir_from_manifest /_prefix/${manifest_dir} /_prefix/${GAZELOD_XR_RUNTIME_INSTALL_LIBDIR})
  endif()
  set(installed_manifest ${gazelod_pkg_dir}/gazelod_xr_runtime.json)
  file(GENERATE OUTPUT ${installed_manifest} CONTENT "{
    \"file_format_version\": \"1.0.0\",
    \"runtime\": {
        \"name\": \"gazelod simulated runtime\",
        \"library_path\": \"${lib_dir_from_manifest}/$<TARGET_FILE_NAME:gazelod_xr_runtime>\"
    }
}
")
  get_filename_component(manifest_name ${GAZELOD_XR_RUNTIME_INSTALL_MANIFEST} NAME)
  install(FILES ${installed_manifest} DESTINATION ${manifest_dir} RENAME ${manifest_name}
    COMPONENT xr_runtime)
endif()

# ---- the eye-gaze API layer (layer/, docs/layer.md) --------------------------------------------
#   <libdir>/gazelod/libXrApiLayer_gazelod_eye_gaze.so
#   share/openxr/1/api_layers/explicit.d/XrApiLayer_gazelod_eye_gaze.json
#     explicit manifest; library_path relative to its folder (relocatable, like the runtime's)
#   share/gazelod/openxr/1/api_layers/implicit.d/XrApiLayer_gazelod_eye_gaze.json
#     implicit manifest (enable_environment / disable_environment), inert where it is: copy or
#     symlink it into an implicit.d folder, or put <prefix>/share/gazelod on XDG_DATA_DIRS. Its
#     library_path is absolute, written at install time (--prefix, without DESTDIR), because the
#     Khronos loader 1.0.20 resolves a relative one from where it finds the manifest (a symlink's
#     folder), not from the file it points to.
# Component xr_layer.
set(GAZELOD_LAYER_INSTALL_LIBDIR ${CMAKE_INSTALL_LIBDIR}/gazelod)
set(GAZELOD_LAYER_INSTALL_EXPLICIT_DIR ${CMAKE_INSTALL_DATADIR}/openxr/1/api_layers/explicit.d)
set(GAZELOD_LAYER_INSTALL_IMPLICIT_DIR ${CMAKE_INSTALL_DATADIR}/gazelod/openxr/1/api_layers/implicit.d)
if(TARGET gazelod_eye_gaze_layer)
  install(TARGETS gazelod_eye_gaze_layer LIBRARY DESTINATION ${GAZELOD_LAYER_INSTALL_LIBDIR} COMPONENT xr_layer)
  set(layer_file $<TARGET_FILE_NAME:gazelod_eye_gaze_layer>)
  set(layer_manifest ${GAZELOD_LAYER_LIBRARY_NAME}.json)
  # Explicit: relative from its folder to the library (absolute when either path is).
  set(dir ${GAZELOD_LAYER_INSTALL_EXPLICIT_DIR})
  if(IS_ABSOLUTE "${GAZELOD_LAYER_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${dir}")
    set(lib_from_manifest ${GAZELOD_LAYER_INSTALL_LIBDIR})
    if(NOT IS_ABSOLUTE "${lib_from_manifest}")
      set(lib_from_manifest ${CMAKE_INSTALL_PREFIX}/${lib_from_manifest})
    endif()
  else()
    file(RELATIVE_PATH lib_from_manifest /_prefix/${dir} /_prefix/${GAZELOD_LAYER_INSTALL_LIBDIR})
  endif()
  gazelod_layer_manifest_text(text "${lib_from_manifest}/${layer_file}" OFF)
  file(GENERATE OUTPUT ${gazelod_pkg_dir}/layer-explicit/${layer_manifest} CONTENT "${text}")
  install(FILES ${gazelod_pkg_dir}/layer-explicit/${layer_manifest} DESTINATION ${dir} COMPONENT xr_layer)
  # Implicit: a template here, the install prefix put in when installing.
  gazelod_layer_manifest_text(text "@GAZELOD_LAYER_LIBRARY@" ON)
  set(template ${gazelod_pkg_dir}/layer-implicit/${layer_manifest}.in)
  file(GENERATE OUTPUT ${template} CONTENT "${text}")
  file(GENERATE OUTPUT ${gazelod_pkg_dir}/layer-implicit/library_name.txt CONTENT "${layer_file}")
  install(CODE "set(gazelod_layer_libdir [[${GAZELOD_LAYER_INSTALL_LIBDIR}]])
    set(gazelod_layer_dir [[${GAZELOD_LAYER_INSTALL_IMPLICIT_DIR}]])
    set(gazelod_layer_name_file [[${gazelod_pkg_dir}/layer-implicit/library_name.txt]])
    set(gazelod_layer_template [[${template}]])
    set(gazelod_layer_manifest [[${layer_manifest}]])" COMPONENT xr_layer)
  install(CODE [[
    foreach(v gazelod_layer_libdir gazelod_layer_dir)
      if(NOT IS_ABSOLUTE "${${v}}")
        set(${v} "${CMAKE_INSTALL_PREFIX}/${${v}}")
      endif()
    endforeach()
    file(READ "${gazelod_layer_name_file}" name)
    file(READ "${gazelod_layer_template}" text)
    string(REPLACE "@GAZELOD_LAYER_LIBRARY@" "${gazelod_layer_libdir}/${name}" text "${text}")
    message(STATUS "Installing: $ENV{DESTDIR}${gazelod_layer_dir}/${gazelod_layer_manifest}")
    file(WRITE "$ENV{DESTDIR}${gazelod_layer_dir}/${gazelod_layer_manifest}" "${text}")
    list(APPEND CMAKE_INSTALL_MANIFEST_FILES "${gazelod_layer_dir}/${gazelod_layer_manifest}")
  ]] COMPONENT xr_layer)
endif()

# ---- GPU cluster selection: the compute shader and the header describing its interface -------
# For an engine that runs the selection on its own buffers (docs/gpu-selection.md); gazelod's own
# host for it is render/cluster_select_pass.hpp, which is not installed. Sources, not SPIR-V: the
# engine compiles them with its own glslangValidator (-V, Vulkan 1.1 or later).
install(FILES ${GAZELOD_ROOT}/shaders/cluster_select.comp ${GAZELOD_ROOT}/shaders/cluster_select_gpu.h
  DESTINATION ${CMAKE_INSTALL_DATADIR}/gazelod/shaders COMPONENT shaders)

# ---- the gazelod program ---------------------------------------------------------------------
if(TARGET gazelod)
  install(TARGETS gazelod RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT program)
endif()

# Everything `cmake --install` copies, in one target:
#   cmake --build build --target gazelod_install_targets && cmake --install build --prefix P
add_custom_target(gazelod_install_targets)
add_dependencies(gazelod_install_targets ${gazelod_installed_targets})
foreach(t gazelod_xr_runtime gazelod_eye_gaze_layer gazelod)
  if(TARGET ${t})
    add_dependencies(gazelod_install_targets ${t})
  endif()
endforeach()
