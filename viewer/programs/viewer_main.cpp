// lcmtf-viewer: the robot and its frames, live in a web browser.
#include "lcmtf_viewer/viewer_program.hpp"

int main(int argc, char** argv) { return lcmtf::viewer::viewerMain(argc, argv); }
