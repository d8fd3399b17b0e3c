#include <iostream>

#include "lcmtf/nodes/echo.hpp"
#include "lcmtf/nodes/stop_signal.hpp"

int main(int argc, char** argv) {
  const auto& stop = lcmtf::nodes::installStopSignalHandlers();
  return lcmtf::nodes::echoCommand({argv + 1, argv + argc}, std::cout, std::cerr, stop);
}
