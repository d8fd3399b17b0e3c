#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <unordered_set>

#include "lcmtf/printable.hpp"

namespace lcmtf::programs {

/// Passes a problem to the sink the first time its key comes up and stays quiet after that,
/// remembering at most `max_keys` keys, so a flood of distinct bad names cannot grow memory.
class OnceReporter {
 public:
  using Sink = std::function<void(const std::string& message)>;

  explicit OnceReporter(Sink sink, std::size_t max_keys = 1000)
      : sink_(std::move(sink)), max_keys_(max_keys) {}

  void report(const std::string& key, const std::string& message) {
    if (!sink_ || reported_.count(key)) return;
    if (reported_.size() >= max_keys_) {
      if (!full_reported_)
        sink_("too many kinds of problems to report each; the rest are only counted");
      full_reported_ = true;
      return;
    }
    reported_.insert(key);
    sink_(printable(message));
  }

 private:
  Sink sink_;
  std::size_t max_keys_;
  std::unordered_set<std::string> reported_;
  bool full_reported_ = false;
};

}  // namespace lcmtf::programs
