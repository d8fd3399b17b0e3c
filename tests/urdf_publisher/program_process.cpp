#include "program_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

extern char** environ;

namespace lcmtf_test {

namespace {

std::string readFile(const std::string& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string outputPath(const char* kind) {
  static std::atomic<int> counter{0};
  return testing::TempDir() + "/program_" + std::to_string(getpid()) + "_" +
         std::to_string(counter++) + "." + kind;
}

// Whether `done` said so within `timeout`, asking every few milliseconds.
bool pollUntil(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

}  // namespace

ProgramProcess::ProgramProcess(const std::string& program,
                               const std::vector<std::string>& arguments)
    : output_path_(outputPath("out")), errors_path_(outputPath("err")) {
  std::vector<std::string> storage{program};
  storage.insert(storage.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& argument : storage) argv.push_back(argument.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, output_path_.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errors_path_.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int error = posix_spawn(&pid_, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error("cannot start " + program + ": " + std::strerror(error));
}

ProgramProcess::~ProgramProcess() {
  signal(SIGKILL);
  waitForExit(std::chrono::seconds(10));
  std::remove(output_path_.c_str());
  std::remove(errors_path_.c_str());
}

void ProgramProcess::signal(int signal_number) {
  if (!status_ && pid_ > 0) ::kill(pid_, signal_number);
}

std::optional<int> ProgramProcess::waitForExit(std::chrono::milliseconds timeout) {
  pollUntil([this] { return reaped(); }, timeout);
  return status_;
}

bool ProgramProcess::reaped() {
  if (status_ || pid_ <= 0) return true;
  int status = 0;
  const pid_t result = waitpid(pid_, &status, WNOHANG);
  if (result < 0 && errno != EINTR) {
    throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
  }
  if (result != pid_) return false;
  status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return true;
}

bool ProgramProcess::waitForOutput(const std::string& text,
                                   std::chrono::milliseconds timeout) const {
  return pollUntil([&] { return output().find(text) != std::string::npos; }, timeout);
}

bool ProgramProcess::waitForErrors(const std::string& text,
                                   std::chrono::milliseconds timeout) const {
  return pollUntil([&] { return errors().find(text) != std::string::npos; }, timeout);
}

std::string ProgramProcess::output() const { return readFile(output_path_); }

std::string ProgramProcess::errors() const { return readFile(errors_path_); }

}  // namespace lcmtf_test
