#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace lcmtf_test {

/// A program started by a test with its stdout and stderr kept in files, so the test can read
/// what it said; killed and reaped when it goes out of scope.
class ProgramProcess {
 public:
  /// Starts `program`; throws std::runtime_error if it cannot start.
  ProgramProcess(const std::string& program, const std::vector<std::string>& arguments);
  ~ProgramProcess();
  ProgramProcess(const ProgramProcess&) = delete;
  ProgramProcess& operator=(const ProgramProcess&) = delete;

  /// Sends `signal_number` (SIGINT, SIGTERM, ...) if the program still runs.
  void signal(int signal_number);
  /// The exit code (128 + signal when killed) once it has exited within `timeout`.
  std::optional<int> waitForExit(std::chrono::milliseconds timeout);
  /// Whether stdout has contained `text` within `timeout`.
  bool waitForOutput(const std::string& text, std::chrono::milliseconds timeout) const;
  /// Whether stderr has contained `text` within `timeout`.
  bool waitForErrors(const std::string& text, std::chrono::milliseconds timeout) const;

  std::string output() const;
  std::string errors() const;
  pid_t pid() const { return pid_; }

 private:
  bool reaped();

  pid_t pid_ = -1;
  std::optional<int> status_;
  std::string output_path_;
  std::string errors_path_;
};

}  // namespace lcmtf_test
