# SPDX-License-Identifier: Apache-2.0
# Small helpers shared by the folders' CMakeLists. Each folder globs its own sources so that
# adding a file needs no edit elsewhere; a sub-folder with its own CMakeLists.txt is added
# when it exists.
include(GNUInstallDirs)

# Include directories of a gazelod library: the repository root in the build tree; once
# installed (cmake/GazelodInstall.cmake), both <prefix>/include (for <gazelod/gazelod.hpp>) and
# <prefix>/include/gazelod (headers include each other from the root: "lod/cone.hpp").
set(GAZELOD_INCLUDE_DIRS
  $<BUILD_INTERFACE:${GAZELOD_ROOT}>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/gazelod>)

# gazelod_library(NAME DIR [TYPE STATIC|SHARED|OBJECT] [LIBS ...]): all *.cpp directly in DIR.
function(gazelod_library name)
  cmake_parse_arguments(A "" "TYPE" "LIBS" ${ARGN})
  if(NOT A_TYPE)
    set(A_TYPE STATIC)
  endif()
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(NOT srcs)  # headers only (so far)
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${GAZELOD_INCLUDE_DIRS})
    target_link_libraries(${name} INTERFACE ${A_LIBS})
    return()
  endif()
  add_library(${name} ${A_TYPE} ${srcs})
  target_include_directories(${name} PUBLIC ${GAZELOD_INCLUDE_DIRS})
  target_link_libraries(${name} PUBLIC ${A_LIBS})
endfunction()

# Adds every direct sub-folder of the current folder that has a CMakeLists.txt.
function(gazelod_add_subfolders)
  file(GLOB children LIST_DIRECTORIES true ${CMAKE_CURRENT_SOURCE_DIR}/*)
  list(SORT children)
  foreach(child ${children})
    if(IS_DIRECTORY ${child} AND EXISTS ${child}/CMakeLists.txt)
      add_subdirectory(${child})
    endif()
  endforeach()
endfunction()

# gazelod_test(NAME SOURCES ... LIBS ... [LABELS unit|integration ...]):
# one GoogleTest executable whose cases are each a CTest test. Label "unit" marks tests that
# also run under the sanitizer build in CI; "integration" ones need the loader, lavapipe, etc.
function(gazelod_test name)
  cmake_parse_arguments(A "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${A_SOURCES})
  target_link_libraries(${name} PRIVATE ${A_LIBS} GTest::gtest GTest::gmock GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    GAZELOD_SOURCE_DIR="${GAZELOD_ROOT}" GAZELOD_BINARY_DIR="${CMAKE_BINARY_DIR}")
  if(NOT A_LABELS)
    set(A_LABELS unit)
  endif()
  gtest_discover_tests(${name} PROPERTIES LABELS "${A_LABELS}" DISCOVERY_TIMEOUT 60)
  # `cmake --build DIR --target gazelod_unit_tests` builds just what `ctest -L unit` runs (the
  # sanitizer pass in CI builds only these).
  if("unit" IN_LIST A_LABELS)
    if(NOT TARGET gazelod_unit_tests)
      add_custom_target(gazelod_unit_tests)
    endif()
    add_dependencies(gazelod_unit_tests ${name})
  endif()
endfunction()

# gazelod_bench(NAME SOURCES ... LIBS ...): a Google Benchmark program.
function(gazelod_bench name)
  cmake_parse_arguments(A "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${A_SOURCES})
  target_link_libraries(${name} PRIVATE ${A_LIBS} benchmark::benchmark)
endfunction()
