#include <iostream>

#include "lcmtf/nodes/echo.hpp"
#include "lcmtf/programs/stop_signal.hpp"

int main(int argc, char** argv) {
  const auto& stop = lcmtf::programs::installStopSignalHandlers();
  return lcmtf::nodes::echoCommand({argv + 1, argv + argc}, std::cout, std::cerr, stop);
}
