# cmake -DPREFIX=... -DBINDIR=... -DDATADIR=... -P check_installed_programs.cmake
# The installed programs start from the install prefix alone (they find liblcmtf next to
# them) and read the installed example robot.
set(robot "${PREFIX}/${DATADIR}/lcmtf/examples/mobile_manipulator.urdf")
if(NOT EXISTS "${robot}")
  message(FATAL_ERROR "not installed: ${robot}")
endif()
execute_process(COMMAND "${PREFIX}/${BINDIR}/lcmtf-urdf-publisher" --check "${robot}"
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT result EQUAL 0 OR NOT output MATCHES "robot 'mobile_manipulator' from ")
  message(FATAL_ERROR "lcmtf-urdf-publisher --check: ${result}\n${output}${errors}")
endif()
execute_process(COMMAND "${PREFIX}/${BINDIR}/lcmtf-joint-publisher" --help
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT result EQUAL 0 OR NOT output MATCHES "--sweep")
  message(FATAL_ERROR "lcmtf-joint-publisher --help: ${result}\n${output}${errors}")
endif()
