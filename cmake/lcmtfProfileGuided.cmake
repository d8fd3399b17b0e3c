# A profile-guided liblcmtf: where the project is built on its own, in Release with GCC, the
# build first makes an instrumented copy of the library in profile/build, runs
# bench/profile_training.cpp on it, and compiles the library with the counts it left in
# profile/data. GCC then lays out the lookups' and inserts' code for the paths they take. In
# buffer_core_bench (fastest of three runs each way, taking turns), lookups ran 3-19 % faster
# so (pr2's random ones 3 %, its time-travel ones 7 %, wide's deepest 10 %, deep_chain's
# latest-time ones 19 %), canTransform 11-14 %, inserts 4 %.
#
# The training runs once per build directory. After the library's code changes, the counts
# that no longer match are left unused (-Wno-coverage-mismatch); deleting profile/ retrains.

option(LCMTF_PROFILE_GUIDED "Release builds with GCC: optimize liblcmtf by a training run" ON)
set(LCMTF_PROFILE_STAGE "" CACHE STRING "'generate' in the build that trains the profile")
set(LCMTF_PROFILE_DATA "" CACHE PATH "Where the training build writes its counts")
mark_as_advanced(LCMTF_PROFILE_STAGE LCMTF_PROFILE_DATA)

# Options for the library's compile and link steps alike (link-time optimization reads them).
function(lcmtf_profile_options target)
  target_compile_options(${target} PRIVATE ${ARGN})
  target_link_options(${target} PRIVATE ${ARGN})
endfunction()

if(LCMTF_PROFILE_STAGE STREQUAL "generate")
  # Object files are named relative to the build directory, as in the build that reads them.
  lcmtf_profile_options(lcmtf -fprofile-generate=${LCMTF_PROFILE_DATA}
    -fprofile-update=prefer-atomic -fprofile-prefix-path=${PROJECT_BINARY_DIR})
  add_executable(lcmtf_profile_training "${PROJECT_SOURCE_DIR}/bench/profile_training.cpp")
  target_link_libraries(lcmtf_profile_training PRIVATE lcmtf::lcmtf)
  # A static library's counters need the profiling runtime linked into the program.
  target_link_options(lcmtf_profile_training PRIVATE -fprofile-generate=${LCMTF_PROFILE_DATA})
  lcmtf_strict_warnings(lcmtf_profile_training)
  return()
endif()

# -fprofile-prefix-path came with GCC 11.
if(NOT LCMTF_PROFILE_GUIDED OR NOT PROJECT_IS_TOP_LEVEL OR NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU"
   OR CMAKE_CXX_COMPILER_VERSION VERSION_LESS 11 OR NOT CMAKE_BUILD_TYPE STREQUAL "Release"
   OR LCMTF_SANITIZE OR LCMTF_BUILD_FUZZERS)
  return()
endif()

include(ExternalProject)
set(lcmtf_profile_data "${PROJECT_BINARY_DIR}/profile/data")
set(lcmtf_profile_build "${PROJECT_BINARY_DIR}/profile/build")
ExternalProject_Add(lcmtf_profile
  SOURCE_DIR "${PROJECT_SOURCE_DIR}"
  BINARY_DIR "${lcmtf_profile_build}"
  PREFIX "${PROJECT_BINARY_DIR}/profile"
  CMAKE_CACHE_ARGS
    -DCMAKE_BUILD_TYPE:STRING=Release
    -DCMAKE_CXX_COMPILER:FILEPATH=${CMAKE_CXX_COMPILER}
    -DCMAKE_CXX_FLAGS:STRING=${CMAKE_CXX_FLAGS}
    -DBUILD_SHARED_LIBS:BOOL=${BUILD_SHARED_LIBS}
    -DLCMTF_PROFILE_STAGE:STRING=generate
    -DLCMTF_PROFILE_DATA:PATH=${lcmtf_profile_data}
    -DLCMTF_BUILD_TESTS:BOOL=OFF
    -DLCMTF_BUILD_BENCHMARKS:BOOL=OFF
    -DLCMTF_BUILD_EXAMPLES:BOOL=OFF
    -DLCMTF_BUILD_JAVA:BOOL=OFF
    -DLCMTF_BUILD_PYTHON:BOOL=OFF
    -DLCMTF_BUILD_TOOLS:BOOL=OFF
    -DLCMTF_BUILD_URDF:BOOL=OFF
    -DLCMTF_BUILD_VIEWER:BOOL=OFF
  INSTALL_COMMAND ${CMAKE_COMMAND} -E rm -rf "${lcmtf_profile_data}"
    COMMAND "<BINARY_DIR>/bin/lcmtf_profile_training")
add_dependencies(lcmtf lcmtf_profile)
lcmtf_profile_options(lcmtf -fprofile-use=${lcmtf_profile_data} -fprofile-partial-training
  -fprofile-prefix-path=${PROJECT_BINARY_DIR} -Wno-missing-profile -Wno-coverage-mismatch)
