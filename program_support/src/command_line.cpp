#include "lcmtf/programs/command_line.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ostream>

#include "lcmtf/printable.hpp"
#include "lcmtf/sendable_names.hpp"

namespace lcmtf::programs {

namespace {

constexpr const char* kExitStatusText =
    "Exit status: 0 on success, 1 when the tool could not do its job, 2 for a bad argument.";

}  // namespace

std::optional<double> strictNumber(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

const char* toolsVersion() { return LCMTF_TOOLS_VERSION; }

std::unique_ptr<CLI::App> makeToolApp(const std::string& program, const std::string& description,
                                      const std::string& examples) {
  auto app = std::make_unique<CLI::App>(description, program);
  app->set_version_flag("--version", program + " (lcmtf) " + toolsVersion(),
                        "Print the version and exit");
  app->footer(examples + "\n\n" + kExitStatusText);
  app->get_formatter()->column_width(34);
  return app;
}

std::optional<int> parseCommandLine(CLI::App& app, const std::vector<std::string>& args,
                                    std::ostream& out, std::ostream& err) {
  std::vector<std::string> reversed;
  for (auto arg = args.rbegin(); arg != args.rend(); ++arg) {
    // CLI11 reads "-.5" as a short option; "-0.5" is the same number and reads as a value.
    const bool bare_negative_fraction = arg->rfind("-.", 0) == 0 && strictNumber(*arg);
    reversed.push_back(bare_negative_fraction ? "-0" + arg->substr(1) : *arg);
  }
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    return reportBadArguments(app, e.what(), err);
  } catch (const CommandLineError& e) {
    return reportBadArguments(app, e.what(), err);
  }
  return std::nullopt;
}

int reportBadArguments(const CLI::App& app, const std::string& message, std::ostream& err) {
  err << app.get_name() << ": " << terminalSafe(message) << "\nRun '" << app.get_name()
      << " --help' for usage.\n"
      << std::flush;
  return kExitBadArguments;
}

double parseFiniteNumber(const std::string& text, const std::string& what) {
  const std::optional<double> value = strictNumber(text);
  if (!value) throw CommandLineError(what + ": '" + text + "' is not a finite number");
  return *value;
}

CLI::Validator finiteNumber() {
  return CLI::Validator(
      [](std::string& text) {
        return strictNumber(text) ? std::string() : "'" + text + "' is not a finite number";
      },
      "");
}

CLI::Validator nonEmptyName() {
  return CLI::Validator(
      [](std::string& text) { return text.empty() ? std::string("must not be empty") : ""; }, "");
}

CLI::Validator sendableName() {
  return CLI::Validator(
      [](std::string& text) {
        return text.empty() ? std::string("must not be empty") : whyUnsendable(text);
      },
      "");
}

CLI::Validator positiveFiniteNumber() {
  return CLI::Validator(
      [](std::string& text) {
        const std::optional<double> value = strictNumber(text);
        return value && *value > 0.0 ? std::string()
                                     : "'" + text + "' is not a number greater than zero";
      },
      "");
}

CLI::Validator positiveFiniteNumberUpTo(double most) {
  char shown[32];
  std::snprintf(shown, sizeof shown, "%g", most);
  const std::string range = std::string("(0, ") + shown + "]";
  return CLI::Validator(
      [most, range](std::string& text) {
        const std::optional<double> value = strictNumber(text);
        return value && *value > 0.0 && *value <= most
                   ? std::string()
                   : "'" + text + "' is not a number in " + range;
      },
      "in " + range);
}

CLI::Option* addChannelOption(CLI::App& app, const std::string& name, std::string& channel,
                              const std::string& help) {
  return app.add_option(name, channel, help)
      ->capture_default_str()
      ->check(nonEmptyName())
      ->type_name("NAME");
}

CLI::Option* addStampAheadOption(CLI::App& app, double& seconds) {
  return app
      .add_option("--max-stamp-ahead", seconds,
                  "Transforms stamped further than this ahead of this machine's clock are refused "
                  "(0: no limit), as one would shut its edge's publisher out until then")
      ->check(finiteNumberIn(0.0, 1e9))
      ->type_name("SECONDS")
      ->capture_default_str();
}

void addOldName(CLI::App& app, const std::string& name, std::string& value) {
  app.add_option(name, value)->check(nonEmptyName())->group("");
}

CLI::Validator finiteNumberIn(double lower, double upper) {
  char shown[64];
  std::snprintf(shown, sizeof shown, "[%g, %g]", lower, upper);
  const std::string range = shown;
  return CLI::Validator(
      [lower, upper, range](std::string& text) {
        const std::optional<double> value = strictNumber(text);
        return value && *value >= lower && *value <= upper
                   ? std::string()
                   : "'" + text + "' is not a number in " + range;
      },
      "in " + range);
}

}  // namespace lcmtf::programs
