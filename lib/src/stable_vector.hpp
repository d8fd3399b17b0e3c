#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <vector>

#include "large_arrays.hpp"

namespace lcmtf::detail {

/// A sequence indexed like a vector whose elements never move: it grows by chunks, each twice
/// the size of the one before, so adding an element copies none and pointers into the
/// elements (as the root paths keep) stay valid while it grows.
template <class T>
class StableVector {
 public:
  StableVector() = default;
  StableVector(const StableVector&) = delete;
  StableVector& operator=(const StableVector&) = delete;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t index) { return at(index); }
  const T& operator[](std::size_t index) const { return at(index); }
  T& back() { return at(size_ - 1); }

  template <class... Args>
  T& emplace_back(Args&&... args) {
    const std::size_t top = topBitOf(size_);
    if (top - kFirstChunkBits == chunks_.size()) {
      // Storage left uninitialized: each element is constructed as it is added.
      chunks_.reserve(chunks_.size() + 1);
      Storage* const chunk = allocator().allocate(kFirstChunk << chunks_.size());
      chunks_.push_back(chunk);
      origins_[top] = reinterpret_cast<std::uintptr_t>(chunk) -
                      (size_ * sizeof(Storage));  // wraps around for the elements before the chunk
    }
    T* element = ::new (addressOf(size_)) T(std::forward<Args>(args)...);
    ++size_;
    return *element;
  }

  ~StableVector() {
    for (std::size_t i = size_; i-- > 0;) at(i).~T();
    for (std::size_t chunk = 0; chunk < chunks_.size(); ++chunk) {
      allocator().deallocate(chunks_[chunk], kFirstChunk << chunk);
    }
  }

  template <class Table, class Element>
  class Iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = Element*;
    using reference = Element&;

    Iterator(Table* table, std::size_t index) : table_(table), index_(index) {}
    Element& operator*() const { return (*table_)[index_]; }
    Element* operator->() const { return &(*table_)[index_]; }
    Iterator& operator++() {
      ++index_;
      return *this;
    }
    bool operator==(const Iterator& other) const { return index_ == other.index_; }
    bool operator!=(const Iterator& other) const { return index_ != other.index_; }

   private:
    Table* table_;
    std::size_t index_;
  };
  using iterator = Iterator<StableVector, T>;
  using const_iterator = Iterator<const StableVector, const T>;
  iterator begin() { return {this, 0}; }
  iterator end() { return {this, size_}; }
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size_}; }

 private:
  static constexpr std::size_t kFirstChunk = 32;  // a power of two
  struct alignas(T) Storage {
    unsigned char bytes[sizeof(T)];
  };
  static LargeArrayAllocator<Storage> allocator() { return {}; }
  static constexpr std::size_t kFirstChunkBits = __builtin_ctzll(kFirstChunk);

  // Chunk c holds the elements from kFirstChunk * (2^c - 1) on: those whose index +
  // kFirstChunk has its highest bit at c + kFirstChunkBits.
  static std::size_t topBitOf(std::size_t index) {
    return static_cast<std::size_t>(63 - __builtin_clzll(index + kFirstChunk));
  }

  // An element's address is its chunk's origin plus its index times the size of one: one load
  // where the chunk's start and the offset in it took two loads and a few more instructions
  // (14 of an insert's 888 on deep_chain in buffer_core_bench).
  void* addressOf(std::size_t index) const {
    return reinterpret_cast<void*>(origins_[topBitOf(index)] + index * sizeof(Storage));
  }
  T& at(std::size_t index) const { return *std::launder(static_cast<T*>(addressOf(index))); }

  std::vector<Storage*> chunks_;
  // Indexed by the highest bit set in index + kFirstChunk, the same for all of one chunk's
  // elements: the chunk's address less its first element's index times the size of one.
  std::uintptr_t origins_[64] = {};
  std::size_t size_ = 0;
};

}  // namespace lcmtf::detail
