# The unit tests of lookups, inserts and their arithmetic run again under Valgrind's memcheck, as
# users run their programs: it must know every instruction the library's clones use (the one
# built for AVX2 included, where the processor has it), and find no read outside the memory the
# program owns and no decision taken on bytes never written.
option(LCMTF_REQUIRE_MEMCHECK "Fail to configure unless the memcheck tests are built" OFF)
find_program(LCMTF_VALGRIND valgrind)
if(LCMTF_REQUIRE_MEMCHECK AND (NOT LCMTF_VALGRIND OR LCMTF_SANITIZE))
  message(FATAL_ERROR "LCMTF_REQUIRE_MEMCHECK is on, but valgrind was not found or the build is "
    "sanitized: scripts/install-deps.sh --tests installs valgrind")
endif()
if(LCMTF_VALGRIND AND NOT LCMTF_SANITIZE)
  foreach(test_program IN ITEMS batch_interpolation_test time_cache_test root_paths_test
      frame_name_index_test name_words_test transform_test buffer_core_lookup_test
      buffer_core_static_chain_test buffer_core_insert_test buffer_core_velocity_test
      buffer_core_errors_test wire_decode_test do_transform_test)
    add_test(NAME memcheck.${test_program}
      COMMAND "${LCMTF_VALGRIND}" --quiet --error-exitcode=1 --exit-on-first-error=yes
              $<TARGET_FILE:${test_program}>)
    set_tests_properties(memcheck.${test_program} PROPERTIES TIMEOUT 300)
  endforeach()
endif()
