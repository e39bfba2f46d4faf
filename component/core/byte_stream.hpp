#pragma once
// Minimal binary writer and bounds-checked reader for checkpoints (serialized FMU states). Values are
// stored in the machine's own representation: a serialized state is only read back by the same binary.
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
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&value, sizeof(T));
  }
  template <class T>
  void putArray(std::span<const T> values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(values.size());
    append(values.data(), values.size_bytes());
  }
  template <class T>
  void putArray(const std::vector<T>& values) {
    putArray(std::span<const T>(values));
  }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  void append(const void* p, std::size_t n) {
    if (n == 0) return;
    const std::size_t at = bytes_.size();
    bytes_.resize(at + n);
    std::memcpy(bytes_.data() + at, p, n);
  }
  std::vector<std::uint8_t> bytes_;
};

// Throws InvalidInput("serialized FMU state is corrupt: ...") instead of reading past the end.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> getArray() {
    const auto n = get<std::uint64_t>();
    if (n > remaining() / sizeof(T)) corrupt("an array of " + std::to_string(n) + " elements overruns the data");
    std::vector<T> values(static_cast<std::size_t>(n));
    if (n > 0) std::memcpy(values.data(), take(values.size() * sizeof(T)), values.size() * sizeof(T));
    return values;
  }
  // An array that must have exactly n elements (it belongs to this set-up).
  template <class T>
  std::vector<T> getArray(std::size_t n) {
    std::vector<T> v = getArray<T>();
    if (v.size() != n)
      corrupt("an array of " + std::to_string(v.size()) + " elements where this set-up has " + std::to_string(n));
    return v;
  }
  std::size_t remaining() const { return bytes_.size() - at_; }
  void expectEnd() const {
    if (remaining() != 0) corrupt(std::to_string(remaining()) + " bytes follow the state");
  }
  [[noreturn]] static void corrupt(const std::string& why) {
    throw InvalidInput("serialized FMU state is corrupt: " + why);
  }

 private:
  const std::uint8_t* take(std::size_t n) {
    if (n > remaining()) corrupt("it ends early");
    const std::uint8_t* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 0;
};

}  // namespace peristep
