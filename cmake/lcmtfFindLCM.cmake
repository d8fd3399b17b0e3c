# Finds LCM (headers, library, and lcm-gen when present) and defines the imported target
# LCM::lcm. Debian's LCM ships no CMake package, so this looks for the files themselves.
if(TARGET LCM::lcm)
  return()
endif()

find_path(LCM_INCLUDE_DIR lcm/lcm-cpp.hpp)
find_library(LCM_LIBRARY NAMES lcm)
find_program(LCM_GEN_EXECUTABLE lcm-gen)

if(NOT LCM_INCLUDE_DIR OR NOT LCM_LIBRARY)
  set(_lcmtf_lcm_message "LCM not found (header: ${LCM_INCLUDE_DIR}, library: ${LCM_LIBRARY}); on Debian: apt-get install liblcm-dev")
  if(LCMTF_REQUIRE_LCM)
    message(FATAL_ERROR "${_lcmtf_lcm_message}")
  endif()
  return()
endif()

add_library(LCM::lcm UNKNOWN IMPORTED)
set_target_properties(LCM::lcm PROPERTIES
  IMPORTED_LOCATION "${LCM_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${LCM_INCLUDE_DIR}")
