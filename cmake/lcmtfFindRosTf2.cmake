# Finds ROS tf2's BufferCore (Debian: libtf2-dev), which ships no CMake package usable outside
# catkin, and defines the imported target lcmtf_ros_tf2 when every part is present. Only the
# benchmark's comparison and the agreement tests use it; nothing requires it.
if(TARGET lcmtf_ros_tf2)
  return()
endif()

find_path(LCMTF_TF2_INCLUDE_DIR tf2/buffer_core.h)
find_path(LCMTF_GEOMETRY_MSGS_INCLUDE_DIR geometry_msgs/TransformStamped.h)
find_library(LCMTF_TF2_LIBRARY tf2)
find_library(LCMTF_ROSTIME_LIBRARY rostime)
find_library(LCMTF_CPP_COMMON_LIBRARY cpp_common)
find_library(LCMTF_CONSOLE_BRIDGE_LIBRARY console_bridge)
if(NOT (LCMTF_TF2_INCLUDE_DIR AND LCMTF_GEOMETRY_MSGS_INCLUDE_DIR AND LCMTF_TF2_LIBRARY
        AND LCMTF_ROSTIME_LIBRARY AND LCMTF_CPP_COMMON_LIBRARY AND LCMTF_CONSOLE_BRIDGE_LIBRARY))
  return()
endif()

add_library(lcmtf_ros_tf2 INTERFACE IMPORTED)
target_include_directories(lcmtf_ros_tf2 SYSTEM INTERFACE
  "${LCMTF_TF2_INCLUDE_DIR}" "${LCMTF_GEOMETRY_MSGS_INCLUDE_DIR}")
target_link_libraries(lcmtf_ros_tf2 INTERFACE "${LCMTF_TF2_LIBRARY}" "${LCMTF_ROSTIME_LIBRARY}"
  "${LCMTF_CPP_COMMON_LIBRARY}" "${LCMTF_CONSOLE_BRIDGE_LIBRARY}")
