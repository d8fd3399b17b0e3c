#include <iostream>

#include "lcmtf/nodes/stop_signal.hpp"
#include "lcmtf/nodes/view_frames.hpp"

int main(int argc, char** argv) {
  const auto& stop = lcmtf::nodes::installStopSignalHandlers();
  return lcmtf::nodes::viewFramesCommand({argv + 1, argv + argc}, std::cout, std::cerr, stop);
}
