#include "future_deadlines.hpp"

#include <vector>

namespace lcmtf::detail {

FutureDeadlines::~FutureDeadlines() { stop("shut down"); }

std::uint64_t FutureDeadlines::add(std::chrono::steady_clock::time_point deadline, Expire expire) {
  std::lock_guard<std::mutex> guard(mutex_);
  const std::uint64_t ticket = next_ticket_++;
  entries_.emplace(ticket, Entry{deadline, std::move(expire), nullptr});
  if (!thread_.joinable() && !stopping_) thread_ = std::thread([this] { run(); });
  changed_.notify_all();
  return ticket;
}

void FutureDeadlines::attachCancel(std::uint64_t ticket, std::function<void()> cancel) {
  std::lock_guard<std::mutex> guard(mutex_);
  const auto entry = entries_.find(ticket);
  if (entry != entries_.end()) entry->second.cancel = std::move(cancel);
}

bool FutureDeadlines::claim(std::uint64_t ticket) {
  std::lock_guard<std::mutex> guard(mutex_);
  return entries_.erase(ticket) == 1;
}

void FutureDeadlines::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    auto earliest = entries_.end();
    for (auto entry = entries_.begin(); entry != entries_.end(); ++entry) {
      if (earliest == entries_.end() || entry->second.deadline < earliest->second.deadline) {
        earliest = entry;
      }
    }
    if (earliest == entries_.end()) {
      changed_.wait(lock);
      continue;
    }
    // A copy: the entry may be claimed, and erased, while this waits.
    const std::chrono::steady_clock::time_point deadline = earliest->second.deadline;
    if (std::chrono::steady_clock::now() < deadline) {
      changed_.wait_until(lock, deadline);
      continue;
    }
    Entry expired = std::move(earliest->second);
    entries_.erase(earliest);
    lock.unlock();
    if (expired.cancel) expired.cancel();
    expired.expire("");
    lock.lock();
  }
}

void FutureDeadlines::stop(const std::string& reason) {
  std::map<std::uint64_t, Entry> remaining;
  {
    std::lock_guard<std::mutex> guard(mutex_);
    stopping_ = true;
    remaining.swap(entries_);
    changed_.notify_all();
  }
  if (thread_.joinable()) thread_.join();
  for (auto& [ticket, entry] : remaining) {
    if (entry.cancel) entry.cancel();
    entry.expire(reason);
  }
}

}  // namespace lcmtf::detail
