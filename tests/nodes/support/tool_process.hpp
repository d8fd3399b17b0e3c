#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lcmtf_test {

/// A program run by a test with its stdout and stderr captured in files, readable while it
/// runs. Killed and reaped when it goes out of scope.
class ToolProcess {
 public:
  /// Starts `program`; throws std::runtime_error if it cannot start.
  ToolProcess(const std::string& program, const std::vector<std::string>& arguments);
  ~ToolProcess();
  ToolProcess(const ToolProcess&) = delete;
  ToolProcess& operator=(const ToolProcess&) = delete;

  /// The exit status (128 + signal when killed) once it exits within `timeout`.
  std::optional<int> waitForExit(std::chrono::milliseconds timeout);
  /// Whether `text` shows up in stdout (`occurrences` times) or stderr within `timeout`.
  bool waitForStdout(const std::string& text, std::chrono::milliseconds timeout,
                     std::size_t occurrences = 1) const;
  bool waitForStderr(const std::string& text, std::chrono::milliseconds timeout) const;
  /// Sends SIGINT, as Ctrl-C does.
  void interrupt() const;

  std::string stdoutText() const;
  std::string stderrText() const;

 private:
  std::filesystem::path directory_;
  pid_t pid_ = -1;
  std::optional<int> status_;
};

/// The whole content of a file ("" when it cannot be read).
std::string readWholeFile(const std::filesystem::path& path);

/// A fresh empty directory under the system's temporary directory, removed by the caller.
std::filesystem::path makeTemporaryDirectory(const std::string& purpose);

}  // namespace lcmtf_test
