#include "lcmtf/sendable_names.hpp"

#include <stdexcept>

#include "lcmtf/printable.hpp"
#include "lcmtf/wire_decode.hpp"

namespace lcmtf {

namespace {

// Enough of a long name to recognize it.
constexpr std::size_t kQuotedBytes = 60;

std::string quoted(std::string_view name) {
  if (name.size() <= kQuotedBytes) return "'" + printable(name) + "'";
  return "'" + printable(name.substr(0, kQuotedBytes)) + "...'";
}

void require(std::string_view name, std::string_view what) {
  const std::string problem = unsendableNameProblem(what, name);
  if (!problem.empty()) throw std::invalid_argument(problem);
}

}  // namespace

std::string whyUnsendable(std::string_view name) {
  const std::size_t limit = DecodeLimits{}.max_name_bytes;
  if (name.size() > limit) {
    return "is " + std::to_string(name.size()) +
           " bytes long: listeners refuse a batch with a name longer than " +
           std::to_string(limit) + " bytes";
  }
  if (name.find('\0') != std::string_view::npos) {
    return "holds a NUL byte: LCM would send only the name up to it";
  }
  return {};
}

std::string unsendableNameProblem(std::string_view what, std::string_view name) {
  const std::string why = whyUnsendable(name);
  if (why.empty()) return {};
  return std::string(what) + " " + quoted(name) + " " + why;
}

void requireSendable(const std::vector<TransformStamped>& transforms,
                     const std::string& authority) {
  require(authority, "sender name");
  for (const TransformStamped& transform : transforms) {
    require(transform.parent_frame, "parent frame name");
    require(transform.child_frame, "child frame name");
  }
}

}  // namespace lcmtf
