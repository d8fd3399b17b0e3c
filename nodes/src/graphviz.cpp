#include "lcmtf/nodes/graphviz.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>
#include <vector>

extern char** environ;

namespace lcmtf::nodes {

namespace {

// The exit status of `pid` once it ends within `timeout`; killed and nothing otherwise.
std::optional<int> awaitExit(pid_t pid, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  for (;;) {
    const pid_t ended = waitpid(pid, &status, WNOHANG);
    if (ended == pid) break;
    if (ended < 0 && errno != EINTR) return std::nullopt;
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return std::nullopt;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

std::optional<std::string> findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream directories(path ? path : "/usr/local/bin:/usr/bin:/bin");
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    const std::string candidate = (directory.empty() ? "." : directory) + "/" + program;
    struct stat info {};
    if (stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
        access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
  }
  return std::nullopt;
}

std::string renderDot(const std::string& dot_program, const std::string& dot_file,
                      const std::string& format, const std::string& output,
                      std::chrono::seconds timeout) {
  std::vector<std::string> arguments{dot_program, "-T" + format, "-o", output, dot_file};
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, dot_program.c_str(), nullptr, nullptr, argv.data(), environ);
  if (error != 0) return "cannot run " + dot_program + ": " + std::strerror(error);
  const std::optional<int> status = awaitExit(pid, timeout);
  if (!status) {
    return dot_program + " did not finish " + output + " within " +
           std::to_string(timeout.count()) + " s";
  }
  if (*status != 0) {
    return dot_program + " failed (exit status " + std::to_string(*status) + ") writing " + output;
  }
  return {};
}

}  // namespace lcmtf::nodes
