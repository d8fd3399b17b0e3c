#include "lcmtf_urdf/urdfdom_parse.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <mutex>
#include <vector>

#include "joint_loops.hpp"
#include "lcmtf/programs/plain_text.hpp"
#include "lcmtf_urdf/description_limits.hpp"
#include "lcmtf_urdf/robot_model.hpp"
#include "xml_syntax.hpp"

namespace lcmtf::urdf {

namespace {

class CollectedErrors : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char* /*filename*/,
           int /*line*/) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors.push_back(text);
  }
  std::vector<std::string> errors;
};

// console_bridge's output handler is one global for the whole process.
std::mutex& consoleBridgeMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

::urdf::ModelInterfaceSharedPtr parseWithUrdfdom(const std::string& urdf,
                                                 const std::string& source) {
  if (urdf.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw UrdfError(source + ": the robot description is empty");
  }
  if (programs::isUtf16Or32(urdf)) {
    throw UrdfError(source + ": the text is UTF-16 or UTF-32, which TinyXML cannot read; " +
                    "save the URDF as UTF-8");
  }
  refuseOversizedDescription(urdf, source);
  TiXmlDocument document;
  parseXmlOrRefuse(urdf, source, document);
  refuseJointLoops(document, source);
  CollectedErrors collected;
  ::urdf::ModelInterfaceSharedPtr model;
  std::string exception;
  {
    std::lock_guard<std::mutex> guard(consoleBridgeMutex());
    console_bridge::useOutputHandler(&collected);
    try {
      model = ::urdf::parseURDF(urdf);
    } catch (const std::exception& e) {
      exception = e.what();
    }
    console_bridge::restorePreviousOutputHandler();
  }
  if (model && exception.empty()) return model;
  std::string problems;
  for (const std::string& error : collected.errors) {
    problems += (problems.empty() ? "" : "; ") + error;
  }
  if (!exception.empty()) problems += (problems.empty() ? "" : "; ") + exception;
  if (problems.empty()) problems = "urdfdom could not read it";
  throw UrdfError(source + ": invalid URDF: " + problems);
}

}  // namespace lcmtf::urdf
