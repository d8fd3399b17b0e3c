# `cmake --install` gives a package that a CMake project and a pkg-config build can both use.
if(LCMTF_SANITIZE)
  return()
endif()

set(install_check "${CMAKE_CURRENT_SOURCE_DIR}/consumer/check_install.cmake")
set(install_work "${CMAKE_CURRENT_BINARY_DIR}/install_check")
set(install_args
  "-DPREFIX=${install_work}/prefix"
  "-DCXX=${CMAKE_CXX_COMPILER}"
  "-DLIBDIR=${CMAKE_INSTALL_LIBDIR}"
  "-DINCLUDEDIR=${CMAKE_INSTALL_INCLUDEDIR}"
  "-DDATADIR=${CMAKE_INSTALL_DATADIR}"
  "-DBINDIR=${CMAKE_INSTALL_BINDIR}")

add_test(NAME install_package_into_test_prefix
  COMMAND "${CMAKE_COMMAND}" ${install_args} -DSTEP=install
          "-DBUILD_DIR=${PROJECT_BINARY_DIR}" "-DCONFIG=$<CONFIG>"
          "-DLCMTYPES_SOURCE_DIR=${PROJECT_SOURCE_DIR}/lcmtypes"
          "-DHEADERS_SOURCE_DIR=${PROJECT_SOURCE_DIR}/lib/include/lcmtf"
          "-DWITH_JAVA=${LCMTF_BUILD_JAVA}" -P "${install_check}")
set_tests_properties(install_package_into_test_prefix PROPERTIES
  FIXTURES_SETUP lcmtf_installed TIMEOUT 120)

add_test(NAME install_consumer_builds_against_package
  COMMAND "${CMAKE_COMMAND}" ${install_args} -DSTEP=cmake
          "-DWORK_DIR=${install_work}/cmake_consumer" -P "${install_check}")
set(install_consumer_tests install_consumer_builds_against_package)

find_program(PKG_CONFIG_EXECUTABLE pkg-config)
if(PKG_CONFIG_EXECUTABLE)
  add_test(NAME install_pkgconfig_compiles_consumer
    COMMAND "${CMAKE_COMMAND}" ${install_args} -DSTEP=pkgconfig
            "-DPKG_CONFIG=${PKG_CONFIG_EXECUTABLE}"
            "-DWORK_DIR=${install_work}/pkgconfig_consumer" -P "${install_check}")
  list(APPEND install_consumer_tests install_pkgconfig_compiles_consumer)
else()
  message(STATUS "pkg-config not found: install_pkgconfig_compiles_consumer is not added")
endif()
set_tests_properties(${install_consumer_tests} PROPERTIES
  FIXTURES_REQUIRED lcmtf_installed TIMEOUT 300)
