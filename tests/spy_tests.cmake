# lcm-spy decodes every lcmtf channel by name: checked without a display, through lcmtf-spy's
# CLASSPATH and lcm-spy's own type lookup.
if(LCMTF_BUILD_JAVA AND LCMTF_TYPES_JAR)
  find_package(Java 1.8 REQUIRED COMPONENTS Runtime Development)
  set(spy_dir "${CMAKE_CURRENT_SOURCE_DIR}/spy")
  set(spy_build_dir "${CMAKE_CURRENT_BINARY_DIR}/spy")
  set(spy_launcher "${PROJECT_BINARY_DIR}/bin/lcmtf-spy")

  set(checker_classes "${spy_build_dir}/classes")
  add_custom_command(OUTPUT "${checker_classes}/SpyDecodesLcmtf.class"
    COMMAND "${Java_JAVAC_EXECUTABLE}" -Xlint:all -Werror --release 8 -cp "${LCM_JAR}"
            -d "${checker_classes}" "${spy_dir}/SpyDecodesLcmtf.java"
    DEPENDS "${spy_dir}/SpyDecodesLcmtf.java" "${LCM_JAR}"
    COMMENT "javac: SpyDecodesLcmtf"
    VERBATIM)
  add_custom_target(spy_decodes_lcmtf_classes ALL
    DEPENDS "${checker_classes}/SpyDecodesLcmtf.class")

  add_test(NAME spy_decodes_every_channel_type
    COMMAND sh "${spy_dir}/decode_like_spy.sh" "${spy_launcher}"
            "$<TARGET_FILE:write_sample_messages>" "${Java_JAVA_EXECUTABLE}" "${checker_classes}"
            "${spy_build_dir}/messages")
  add_test(NAME spy_launcher_command_line
    COMMAND sh "${spy_dir}/check_launcher.sh" "${spy_launcher}" "${LCM_JAR}" "${JCHART2D_JAR}")
  add_test(NAME spy_jar_lists_every_type
    COMMAND sh "${spy_dir}/check_jar_types.sh" "${Java_JAR_EXECUTABLE}" "${LCMTF_TYPES_JAR}"
            "${PROJECT_SOURCE_DIR}/lcmtypes")
  set_tests_properties(spy_decodes_every_channel_type spy_launcher_command_line
    spy_jar_lists_every_type PROPERTIES TIMEOUT 60)
endif()
