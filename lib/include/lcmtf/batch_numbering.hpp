#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace lcmtf {

/// Numbers the batches one sender publishes on one channel: 1, 2, 3, ... (tf_message_t::sequence).
/// Every BatchNumbering in a process with the same channel and authority shares one count, so
/// two broadcasters under one name still send one unbroken stream.
class BatchNumbering {
 public:
  BatchNumbering(const std::string& channel, const std::string& authority);
  /// The number of the batch about to be published.
  std::int64_t next() { return ++*last_; }

 private:
  std::shared_ptr<std::atomic<std::int64_t>> last_;
};

}  // namespace lcmtf
