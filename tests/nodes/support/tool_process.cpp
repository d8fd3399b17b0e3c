#include "support/tool_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace lcmtf_test {

namespace {

bool poll(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (done()) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

std::string readWholeFile(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::filesystem::path makeTemporaryDirectory(const std::string& purpose) {
  std::string pattern = (std::filesystem::temp_directory_path() / (purpose + "-XXXXXX")).string();
  if (!mkdtemp(pattern.data())) {
    throw std::runtime_error("mkdtemp " + pattern + ": " + std::strerror(errno));
  }
  return pattern;
}

ToolProcess::ToolProcess(const std::string& program, const std::vector<std::string>& arguments)
    : directory_(makeTemporaryDirectory("lcmtf-tool")) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string out = (directory_ / "stdout").string();
  const std::string err = (directory_ / "stderr").string();
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  std::vector<std::string> words{program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const int error = posix_spawn(&pid_, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) {
    std::filesystem::remove_all(directory_);
    throw std::runtime_error("cannot start " + program + ": " + std::strerror(error));
  }
}

ToolProcess::~ToolProcess() {
  if (!status_) {
    ::kill(pid_, SIGKILL);
    while (waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

std::optional<int> ToolProcess::waitForExit(std::chrono::milliseconds timeout) {
  poll(
      [this] {
        int status = 0;
        if (status_ || waitpid(pid_, &status, WNOHANG) != pid_) return status_.has_value();
        status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        return true;
      },
      timeout);
  return status_;
}

bool ToolProcess::waitForStdout(const std::string& text, std::chrono::milliseconds timeout,
                                std::size_t occurrences) const {
  return poll(
      [&] {
        const std::string out = stdoutText();
        std::size_t found = 0;
        for (std::size_t at = out.find(text); at != std::string::npos;
             at = out.find(text, at + 1)) {
          ++found;
        }
        return found >= occurrences;
      },
      timeout);
}

bool ToolProcess::waitForStderr(const std::string& text, std::chrono::milliseconds timeout) const {
  return poll([&] { return stderrText().find(text) != std::string::npos; }, timeout);
}

void ToolProcess::interrupt() const {
  if (!status_) ::kill(pid_, SIGINT);
}

std::string ToolProcess::stdoutText() const { return readWholeFile(directory_ / "stdout"); }
std::string ToolProcess::stderrText() const { return readWholeFile(directory_ / "stderr"); }

}  // namespace lcmtf_test
