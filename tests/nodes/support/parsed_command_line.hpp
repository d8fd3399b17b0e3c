#pragma once

#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace lcmtf_test {

/// What a tool's parse function made of a command line, and what it printed.
template <class Options>
struct ParsedCommandLine {
  std::optional<int> status;  ///< set when the tool would not run
  Options options;
  std::string out;
  std::string err;
};

/// Runs `parse` (one of the tools' parse...CommandLine functions) on `args`.
template <class Options>
ParsedCommandLine<Options> parseWith(std::optional<int> (*parse)(const std::vector<std::string>&,
                                                                 Options&, std::ostream&,
                                                                 std::ostream&),
                                     const std::vector<std::string>& args) {
  ParsedCommandLine<Options> parsed;
  std::ostringstream out, err;
  parsed.status = parse(args, parsed.options, out, err);
  parsed.out = out.str();
  parsed.err = err.str();
  return parsed;
}

}  // namespace lcmtf_test
