#include "lcmtf/batch_numbering.hpp"

#include <map>
#include <mutex>
#include <utility>

namespace lcmtf {

namespace {

using Counter = std::atomic<std::int64_t>;

std::shared_ptr<Counter> sharedCounter(const std::string& channel, const std::string& authority) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, std::string>, std::weak_ptr<Counter>> counters;
  const std::lock_guard<std::mutex> guard(mutex);
  for (auto it = counters.begin(); it != counters.end();) {
    it = it->second.expired() ? counters.erase(it) : std::next(it);
  }
  std::weak_ptr<Counter>& slot = counters[{channel, authority}];
  std::shared_ptr<Counter> counter = slot.lock();
  if (!counter) {
    counter = std::make_shared<Counter>(0);
    slot = counter;
  }
  return counter;
}

}  // namespace

BatchNumbering::BatchNumbering(const std::string& channel, const std::string& authority)
    : last_(sharedCounter(channel, authority)) {}

}  // namespace lcmtf
