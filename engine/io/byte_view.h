#pragma once
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>

#include "engine/error.h"

namespace hdprior {

// A bounds-checked, little-endian view of bytes read from a named source.
// Every read checks the range first and throws Error naming the source.
class ByteView {
 public:
  ByteView(std::span<const uint8_t> bytes, std::string source)
      : bytes_(bytes), source_(std::move(source)) {}

  size_t size() const { return bytes_.size(); }
  const std::string& source() const { return source_; }
  std::span<const uint8_t> bytes() const { return bytes_; }

  void require(size_t offset, size_t count, const char* what) const {
    if (offset > bytes_.size() || count > bytes_.size() - offset) {
      fail(std::string("truncated: ") + what + " needs " + std::to_string(count) + " bytes at offset " +
           std::to_string(offset) + ", only " + std::to_string(bytes_.size()) + " available");
    }
  }

  template <class T>
  T read(size_t offset, const char* what = "value") const {
    static_assert(std::is_trivially_copyable_v<T>);
    require(offset, sizeof(T), what);
    T value;
    std::memcpy(&value, bytes_.data() + offset, sizeof(T));
    return value;
  }

  ByteView sub(size_t offset, size_t count, const char* what) const {
    require(offset, count, what);
    return ByteView(bytes_.subspan(offset, count), source_);
  }

  [[noreturn]] void fail(const std::string& reason) const { throw Error(source_, reason); }

 private:
  std::span<const uint8_t> bytes_;
  std::string source_;
};

}  // namespace hdprior
