#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace lcmtf_test {

/// A program started by a test; killed and reaped when it goes out of scope, so no test
/// leaves a process behind.
class ChildProcess {
 public:
  /// Starts `program` with `arguments`; throws std::runtime_error if it cannot start.
  ChildProcess(const std::string& program, const std::vector<std::string>& arguments);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// The exit status once the process has exited within `timeout`; nothing if it is still running.
  std::optional<int> waitForExit(std::chrono::milliseconds timeout);
  void kill();

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
};

}  // namespace lcmtf_test
