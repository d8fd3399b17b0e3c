#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lcmtf_test {

/// A program started by a test, its stdout and stderr kept in files that can be read while it
/// runs; killed and reaped when it goes out of scope, so no test leaves a process behind.
class ChildProcess {
 public:
  /// Starts `program` with `arguments`; throws std::runtime_error if it cannot start.
  ChildProcess(const std::string& program, const std::vector<std::string>& arguments);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// The exit status (128 + signal when killed) once it exits within `timeout`.
  std::optional<int> waitForExit(std::chrono::milliseconds timeout);
  /// Whether `text` shows up in stdout (`occurrences` times) or stderr within `timeout`.
  bool waitForStdout(const std::string& text, std::chrono::milliseconds timeout,
                     std::size_t occurrences = 1) const;
  bool waitForStderr(const std::string& text, std::chrono::milliseconds timeout) const;
  /// Sends `signal_number` if it still runs; interrupt() sends SIGINT, as Ctrl-C does.
  void signal(int signal_number) const;
  void interrupt() const;
  /// Kills and reaps it.
  void kill();

  std::string stdoutText() const;
  std::string stderrText() const;
  pid_t pid() const { return pid_; }

 private:
  bool reaped();

  std::filesystem::path directory_;
  pid_t pid_ = -1;
  std::optional<int> status_;
};

/// The whole content of a file ("" when it cannot be read).
std::string readWholeFile(const std::filesystem::path& path);

/// A fresh empty directory under the system's temporary directory, removed by the caller.
std::filesystem::path makeTemporaryDirectory(const std::string& purpose);

}  // namespace lcmtf_test
