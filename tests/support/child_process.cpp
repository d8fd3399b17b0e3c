#include "support/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

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

// Whether `done` said so within `timeout`, asking every few milliseconds.
bool pollUntil(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (done()) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

std::size_t occurrencesOf(const std::string& text, const std::string& in) {
  std::size_t found = 0;
  for (std::size_t at = in.find(text); at != std::string::npos; at = in.find(text, at + 1)) {
    ++found;
  }
  return found;
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

ChildProcess::ChildProcess(const std::string& program, const std::vector<std::string>& arguments)
    : directory_(makeTemporaryDirectory("lcmtf-process")) {
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

ChildProcess::~ChildProcess() {
  kill();
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

bool ChildProcess::reaped() {
  if (status_) return true;
  int status = 0;
  const pid_t result = waitpid(pid_, &status, WNOHANG);
  if (result < 0 && errno != EINTR) {
    throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
  }
  if (result != pid_) return false;
  status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return true;
}

std::optional<int> ChildProcess::waitForExit(std::chrono::milliseconds timeout) {
  pollUntil([this] { return reaped(); }, timeout);
  return status_;
}

void ChildProcess::kill() {
  if (status_) return;
  ::kill(pid_, SIGKILL);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

bool ChildProcess::waitForStdout(const std::string& text, std::chrono::milliseconds timeout,
                                 std::size_t occurrences) const {
  return pollUntil([&] { return occurrencesOf(text, stdoutText()) >= occurrences; }, timeout);
}

bool ChildProcess::waitForStderr(const std::string& text, std::chrono::milliseconds timeout) const {
  return pollUntil([&] { return occurrencesOf(text, stderrText()) > 0; }, timeout);
}

void ChildProcess::signal(int signal_number) const {
  if (!status_) ::kill(pid_, signal_number);
}

void ChildProcess::interrupt() const { signal(SIGINT); }

std::string ChildProcess::stdoutText() const { return readWholeFile(directory_ / "stdout"); }
std::string ChildProcess::stderrText() const { return readWholeFile(directory_ / "stderr"); }

}  // namespace lcmtf_test
