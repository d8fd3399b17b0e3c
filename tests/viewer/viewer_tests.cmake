# The viewer as a user meets it: lcmtf-viewer, lcmtf-urdf-publisher and lcmtf-joint-publisher as
# real processes over udpm (ttl=0, a port of each test's own), the page in headless Chromium
# driven over the DevTools protocol, and the server against hostile requests and messages.
# Debian's python3 runs them (python3-websocket); without Chromium or the websocket module they
# are skipped (77), and so is a case whose robot file in ../shared/urdf is missing.
find_program(LCMTF_SYSTEM_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT LCMTF_SYSTEM_PYTHON)
  find_program(LCMTF_SYSTEM_PYTHON python3)
endif()

if(LCMTF_SYSTEM_PYTHON AND TARGET lcmtf-viewer AND TARGET lcmtf-urdf-publisher
   AND TARGET lcmtf-joint-publisher)
  set(viewer_test_dir "${CMAKE_CURRENT_SOURCE_DIR}")
  set(viewer_test_args
    --bin-dir "$<TARGET_FILE_DIR:lcmtf-viewer>"
    --source-dir "${PROJECT_SOURCE_DIR}"
    --shared-urdf "${PROJECT_SOURCE_DIR}/../shared/urdf")

  set(viewer_lcm_port 17691)
  set(browser_cases demo joint_sliders reconnect panda_meshes panda_stl_meshes missing_meshes
                    broken_meshes)
  # The sanitizer builds test the server against hostile input only: the page's tests exercise
  # Chromium more than the server, and take a minute.
  if(LCMTF_SANITIZE)
    set(browser_cases)
  endif()
  set(viewer_browser_tests viewer_hostile_input)
  foreach(case IN LISTS browser_cases)
    list(APPEND viewer_browser_tests viewer_page_${case})
    set(case_args --case ${case})
    if(case STREQUAL "demo")
      # The picture of the demo robot that docs/viewer.png is taken from.
      list(APPEND case_args --screenshot "${CMAKE_CURRENT_BINARY_DIR}/viewer.png")
    endif()
    add_test(NAME viewer_page_${case}
      COMMAND "${LCMTF_SYSTEM_PYTHON}" "${viewer_test_dir}/browser_test.py" ${viewer_test_args}
              --lcm-port ${viewer_lcm_port} ${case_args})
    math(EXPR viewer_lcm_port "${viewer_lcm_port} + 1")
  endforeach()

  add_test(NAME viewer_hostile_input
    COMMAND "${LCMTF_SYSTEM_PYTHON}" "${viewer_test_dir}/hostile_input_test.py"
            ${viewer_test_args} --lcm-port ${viewer_lcm_port})

  set_tests_properties(${viewer_browser_tests} PROPERTIES
    TIMEOUT 180 SKIP_RETURN_CODE 77
    # One Chromium drawing with SwiftShader at a time keeps their timing honest.
    RESOURCE_LOCK lcmtf_viewer_browser
    # The scripts import each other from the source tree, which the tests leave as they found it.
    ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endif()
