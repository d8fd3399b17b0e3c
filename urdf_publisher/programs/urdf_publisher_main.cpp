// lcmtf-urdf-publisher: a robot's URDF and its joint states in, its frames out on LCM.
#include "lcmtf_urdf/urdf_publisher_program.hpp"

int main(int argc, char** argv) { return lcmtf::urdf::urdfPublisherMain(argc, argv); }
