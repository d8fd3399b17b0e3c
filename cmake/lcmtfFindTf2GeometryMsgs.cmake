# Finds tf2_geometry_msgs (Debian: libtf2-geometry-msgs-dev), header-only over ROS tf2 and KDL,
# and defines the imported target lcmtf_ros_tf2_geometry_msgs when every part is present. Only
# the doTransform agreement test uses it; nothing requires it.
if(TARGET lcmtf_ros_tf2_geometry_msgs)
  return()
endif()

include(lcmtfFindRosTf2)
find_path(LCMTF_TF2_GEOMETRY_MSGS_INCLUDE_DIR tf2_geometry_msgs/tf2_geometry_msgs.h)
find_path(LCMTF_KDL_INCLUDE_DIR kdl/frames.hpp)
if(NOT (TARGET lcmtf_ros_tf2 AND LCMTF_TF2_GEOMETRY_MSGS_INCLUDE_DIR AND LCMTF_KDL_INCLUDE_DIR))
  return()
endif()

add_library(lcmtf_ros_tf2_geometry_msgs INTERFACE IMPORTED)
target_include_directories(lcmtf_ros_tf2_geometry_msgs SYSTEM INTERFACE
  "${LCMTF_TF2_GEOMETRY_MSGS_INCLUDE_DIR}" "${LCMTF_KDL_INCLUDE_DIR}")
target_link_libraries(lcmtf_ros_tf2_geometry_msgs INTERFACE lcmtf_ros_tf2)
