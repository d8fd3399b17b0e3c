#include <iostream>

#include "lcmtf/nodes/view_frames.hpp"
#include "lcmtf/programs/stop_signal.hpp"

int main(int argc, char** argv) {
  const auto& stop = lcmtf::programs::installStopSignalHandlers();
  return lcmtf::nodes::viewFramesCommand({argv + 1, argv + argc}, std::cout, std::cerr, stop);
}
