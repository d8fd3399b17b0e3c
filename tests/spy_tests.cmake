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

  # The TF and joint tables lcm-spy shows through the plugins in the types jar: their rows on
  # messages the C++ types encoded, and, under Xvfb where it is installed, a picture of each.
  set(table_classes "${spy_build_dir}/table_classes")
  set(table_tests SpyTablesShowDecodedMessages SpyTablesScreenshot)
  set(table_outputs "")
  foreach(test_class IN LISTS table_tests)
    list(APPEND table_outputs "${table_classes}/${test_class}.class")
  endforeach()
  add_custom_command(OUTPUT ${table_outputs}
    COMMAND "${Java_JAVAC_EXECUTABLE}" -Xlint:all -Werror -encoding UTF-8 --release 8
            -cp "${LCM_JAR}:${LCMTF_TYPES_JAR}" -d "${table_classes}"
            "${spy_dir}/SpyTablesShowDecodedMessages.java" "${spy_dir}/SpyTablesScreenshot.java"
    DEPENDS "${spy_dir}/SpyTablesShowDecodedMessages.java" "${spy_dir}/SpyTablesScreenshot.java"
            "${LCMTF_TYPES_JAR}" lcmtf_types_jar
    COMMENT "javac: the lcm-spy table tests"
    VERBATIM)
  add_custom_target(spy_table_test_classes ALL DEPENDS ${table_outputs})
  set(table_classpath "${LCM_JAR}:${LCMTF_TYPES_JAR}:${table_classes}")
  add_test(NAME spy_tables_show_decoded_messages
    COMMAND sh -c "mkdir -p \"$2\" && \"$1\" \"$2\" && \"$3\" -Djava.awt.headless=true -cp \"$4\" SpyTablesShowDecodedMessages \"$2\" \"$5\""
            sh "$<TARGET_FILE:write_sample_messages>" "${spy_build_dir}/table_messages"
            "${Java_JAVA_EXECUTABLE}" "${table_classpath}" "${LCMTF_TYPES_JAR}")
  add_test(NAME spy_tables_screenshot
    COMMAND sh "${spy_dir}/screenshot_tables.sh" "$<TARGET_FILE:write_sample_messages>"
            "${Java_JAVA_EXECUTABLE}" "${table_classpath}" "${spy_build_dir}/screenshots")
  set_tests_properties(spy_tables_show_decoded_messages spy_tables_screenshot PROPERTIES
    TIMEOUT 60)
  set_tests_properties(spy_tables_screenshot PROPERTIES SKIP_RETURN_CODE 77)
endif()
