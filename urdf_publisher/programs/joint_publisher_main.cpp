// lcmtf-joint-publisher: joint states for a robot at rest or sweeping, from its URDF.
#include "lcmtf_urdf/joint_publisher_program.hpp"

int main(int argc, char** argv) { return lcmtf::urdf::jointPublisherMain(argc, argv); }
