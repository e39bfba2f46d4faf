#pragma once
// Minimal binary writer/reader for checkpoints (FMU state serialization): plain values and vectors of
// trivially copyable types, length-prefixed, in host byte order.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "core/errors.hpp"

namespace peristep {

class ByteWriter {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  template <class T>
  void put(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    const auto* p = reinterpret_cast<const std::uint8_t*>(v.data());
    bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(T));
  }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    T v;
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  template <class T>
  std::vector<T> getVector(std::size_t expected) {
    const auto n = get<std::uint64_t>();
    require(n == expected, "checkpoint does not belong to this set-up (array of " + std::to_string(n) +
                               " entries where " + std::to_string(expected) + " were expected)");
    need(n * sizeof(T));
    std::vector<T> v(n);
    std::memcpy(v.data(), bytes_.data() + pos_, n * sizeof(T));
    pos_ += n * sizeof(T);
    return v;
  }
  std::vector<std::size_t> getIndexVector() {  // a vector whose length is not known in advance
    const auto n = get<std::uint64_t>();
    need(n * sizeof(std::size_t));
    std::vector<std::size_t> v(n);
    std::memcpy(v.data(), bytes_.data() + pos_, n * sizeof(std::size_t));
    pos_ += n * sizeof(std::size_t);
    return v;
  }
  void expectEnd() const { require(pos_ == bytes_.size(), "checkpoint has trailing bytes"); }

 private:
  void need(std::size_t n) const { require(pos_ + n <= bytes_.size(), "checkpoint is truncated"); }
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

}  // namespace peristep
