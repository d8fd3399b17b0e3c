#pragma once

#include <iosfwd>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace lcmtf::programs {

/// Exit statuses shared by every tool.
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;       ///< the tool ran but could not do its job
inline constexpr int kExitBadArguments = 2;  ///< the command line (or a file it names) is wrong

/// A wrong command line found after parsing; what() names the argument and what is wrong.
class CommandLineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The lcmtf version the programs were built from ("0.1.0").
const char* toolsVersion();

/// A CLI11 app for `program` with --help, --version and a footer that explains exit statuses.
std::unique_ptr<CLI::App> makeToolApp(const std::string& program, const std::string& description,
                                      const std::string& examples);

/// Parses `args` (without the program name). Help and version go to `out`; errors go to `err`
/// as "program: message". Returns the exit status when the tool must not run.
std::optional<int> parseCommandLine(CLI::App& app, const std::vector<std::string>& args,
                                    std::ostream& out, std::ostream& err);

/// Reports a CommandLineError found after parsing, like parseCommandLine does; returns 2.
int reportBadArguments(const CLI::App& app, const std::string& message, std::ostream& err);

/// `text` as a finite number, all of it; nothing otherwise.
std::optional<double> strictNumber(const std::string& text);

/// `text` as a finite number; CommandLineError "what: 'text' is not a finite number" otherwise.
double parseFiniteNumber(const std::string& text, const std::string& what);

/// Validators for numbers typed by people: finite, and finite and above zero.
CLI::Validator finiteNumber();
CLI::Validator positiveFiniteNumber();
/// Above zero and at most `most`; the help shows the range as (0, most].
CLI::Validator positiveFiniteNumberUpTo(double most);
/// A finite number in [lower, upper]; the help shows the range.
CLI::Validator finiteNumberIn(double lower, double upper);
/// A validator refusing the empty string (channel and frame names).
CLI::Validator nonEmptyName();
/// A validator refusing a name that cannot be sent as a frame or sender name (empty, or as
/// whyUnsendable() says).
CLI::Validator sendableName();

/// An option naming an LCM channel: not empty, its default shown in the help.
CLI::Option* addChannelOption(CLI::App& app, const std::string& name, std::string& channel,
                              const std::string& help);
/// --max-stamp-ahead SECONDS, for the programs that keep a listener's buffer
/// (ListenerOptions::max_stamp_ahead): 0 to 1e9, its default shown in the help.
CLI::Option* addStampAheadOption(CLI::App& app, double& seconds);
/// An option under a name the programs once used: it still works, and --help leaves it out.
void addOldName(CLI::App& app, const std::string& name, std::string& value);

}  // namespace lcmtf::programs
