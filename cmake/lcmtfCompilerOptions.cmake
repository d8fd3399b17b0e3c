# Warnings as errors for the project's own targets, and the optional sanitizer build.
set(LCMTF_SANITIZE "" CACHE STRING "Sanitizers for every target, e.g. address,undefined or thread")

if(LCMTF_SANITIZE)
  add_compile_options(-fsanitize=${LCMTF_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${LCMTF_SANITIZE})
  if(LCMTF_SANITIZE MATCHES "undefined")
    # GCC 12's vptr check misreads the pointer-to-member call in LCM's subscription callback
    # (lcm-cpp-impl.hpp) and reports a bad object where there is none.
    add_compile_options(-fno-sanitize=vptr)
  endif()
endif()

option(LCMTF_BUILD_FUZZERS "Build the libFuzzer targets (needs clang)" OFF)
if(LCMTF_BUILD_FUZZERS AND NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "LCMTF_BUILD_FUZZERS needs clang: configure with CXX=clang++")
endif()

# Coverage for libFuzzer's guidance, in the code a fuzzer reaches (the tests built beside the
# fuzzers run without it, at full speed).
function(lcmtf_fuzz_coverage target)
  if(LCMTF_BUILD_FUZZERS)
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()

function(lcmtf_strict_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion -Wnon-virtual-dtor -Wold-style-cast -Werror)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # lcm-gen's inline decode() reads its fingerprint through a helper GCC cannot see into
    # once inlined at -O3, and warns about the generated header, not about this code.
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
  endif()
endfunction()
