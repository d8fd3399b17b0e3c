#pragma once

#include <algorithm>
#include <cstring>
#include <memory>
#include <string_view>
#include <vector>

namespace lcmtf::detail {

/// Stable storage for frame names, packed into large blocks so that the names a lookup
/// compares sit together in a few cache lines rather than one heap block each.
class NameArena {
 public:
  /// A copy of `name` that stays where it is for the arena's lifetime.
  std::string_view store(std::string_view name) {
    if (name.size() > room_) {
      const std::size_t size = std::max(kBlockSize, name.size());
      blocks_.push_back(std::make_unique<char[]>(size));
      next_ = blocks_.back().get();
      room_ = size;
    }
    if (!name.empty()) std::memcpy(next_, name.data(), name.size());
    const std::string_view stored(next_, name.size());
    next_ += name.size();
    room_ -= name.size();
    return stored;
  }

 private:
  static constexpr std::size_t kBlockSize = 4096;
  std::vector<std::unique_ptr<char[]>> blocks_;
  char* next_ = nullptr;
  std::size_t room_ = 0;
};

}  // namespace lcmtf::detail
