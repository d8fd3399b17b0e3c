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
# The viewer serves its page from the prefix's share folder, with the robot from the prefix.
if(EXISTS "${PREFIX}/${BINDIR}/lcmtf-viewer")
  if(NOT EXISTS "${PREFIX}/${DATADIR}/lcmtf/viewer/index.html"
     OR NOT EXISTS "${PREFIX}/${DATADIR}/lcmtf/viewer/js/main.js")
    message(FATAL_ERROR "not installed: the viewer's page in ${PREFIX}/${DATADIR}/lcmtf/viewer")
  endif()
  execute_process(COMMAND "${PREFIX}/${BINDIR}/lcmtf-viewer" --port 0 --duration 0.5
      --lcm-url "udpm://239.255.76.67:17689?ttl=0" --urdf "${robot}"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
  if(NOT result EQUAL 0 OR NOT output MATCHES "lcmtf-viewer: open http://127.0.0.1:[0-9]+/"
     OR NOT errors MATCHES "robot 'mobile_manipulator' from ")
    message(FATAL_ERROR "lcmtf-viewer: ${result}\n${output}${errors}")
  endif()
endif()
