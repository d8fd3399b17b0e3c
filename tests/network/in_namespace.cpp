#include "network/in_namespace.hpp"

#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <thread>

namespace lcmtf_test {

void runInNamespace(const std::string& name, const std::function<void()>& work) {
  const std::string path = "/var/run/netns/" + name;
  std::exception_ptr failure;
  // A network namespace belongs to a thread, so entering one here leaves the caller's alone.
  std::thread thread([&] {
    try {
      const int descriptor = open(path.c_str(), O_RDONLY | O_CLOEXEC);
      if (descriptor < 0) {
        throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno));
      }
      const int entered = setns(descriptor, CLONE_NEWNET);
      const int setns_error = errno;
      close(descriptor);
      if (entered != 0) {
        throw std::runtime_error("cannot enter " + path + ": " + std::strerror(setns_error));
      }
      work();
    } catch (...) {
      failure = std::current_exception();
    }
  });
  thread.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace lcmtf_test
