#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "name_hash.hpp"
#include "name_words.hpp"

namespace lcmtf::detail {

/// The names of the senders that set the buffer's edges, each kept only while some edge names
/// it as the one that set it last: a peer sending under a new name on every message costs at
/// most one name per edge. Ids start at 1; 0 means no authority.
class AuthorityTable {
 public:
  /// The id of `name`, added when new; it stays only once use() counts an edge for it.
  std::uint32_t idOf(const std::string& name) {
    // Most inserts come from the same sender as the one before.
    if (last_ != 0 && sameName(entries_[last_ - 1].name, name)) return last_;
    auto found = ids_.find(name);
    if (found == ids_.end()) found = ids_.emplace(name, add(name)).first;
    last_ = found->second;
    return last_;
  }
  /// The id of a known name, or 0.
  std::uint32_t find(const std::string& name) const {
    const auto found = ids_.find(name);
    return found == ids_.end() ? 0 : found->second;
  }
  const std::string& name(std::uint32_t id) const { return entries_[id - 1].name; }

  /// Moves an edge from authority `from` to `to` (either may be 0); a name no edge uses any more
  /// is forgotten.
  void moveEdge(std::uint32_t from, std::uint32_t to) {
    if (from == to) return;
    if (to != 0) ++entries_[to - 1].edges;
    if (from != 0 && --entries_[from - 1].edges == 0) forget(from);
  }
  /// Names known now: at most one per edge, and the last one asked for.
  std::size_t size() const { return ids_.size(); }

 private:
  struct Entry {
    std::string name;
    std::size_t edges = 0;
  };

  std::uint32_t add(const std::string& name) {
    // A name asked for but never used by an edge is dropped when the next one is added.
    if (last_ != 0 && entries_[last_ - 1].edges == 0) forget(last_);
    if (!free_.empty()) {
      const std::uint32_t id = free_.back();
      free_.pop_back();
      entries_[id - 1].name = name;
      return id;
    }
    entries_.push_back(Entry{name, 0});
    return static_cast<std::uint32_t>(entries_.size());
  }
  void forget(std::uint32_t id) {
    Entry& entry = entries_[id - 1];
    ids_.erase(entry.name);
    std::string().swap(entry.name);
    free_.push_back(id);
    if (last_ == id) last_ = 0;
  }

  std::vector<Entry> entries_;
  std::unordered_map<std::string, std::uint32_t, NameHash> ids_;
  std::vector<std::uint32_t> free_;
  std::uint32_t last_ = 0;
};

}  // namespace lcmtf::detail
