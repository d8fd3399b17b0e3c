#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>

namespace lcmtf::detail {

/// A fixed-size array of plain values left unwritten until each is assigned, so that a large
/// one costs no page faults until it is used.
template <class T>
class UnfilledArray {
  static_assert(std::is_trivial_v<T>);

 public:
  UnfilledArray() = default;
  explicit UnfilledArray(std::size_t size) : values_(new T[size]), size_(size) {}

  std::size_t size() const { return size_; }
  T& operator[](std::size_t index) { return values_[index]; }
  const T& operator[](std::size_t index) const { return values_[index]; }
  void swap(UnfilledArray& other) noexcept {
    values_.swap(other.values_);
    std::swap(size_, other.size_);
  }
  void clear() {
    values_.reset();
    size_ = 0;
  }

 private:
  std::unique_ptr<T[]> values_;
  std::size_t size_ = 0;
};

}  // namespace lcmtf::detail
