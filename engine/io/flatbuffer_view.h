#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "engine/io/byte_view.h"

namespace hdprior::fb {

// A vector inside a flatbuffer: `count` elements of `elementSize` bytes starting at `pos`.
// The whole extent was checked against the buffer when the vector was obtained.
class Vector {
 public:
  Vector(const ByteView* buf, size_t pos, size_t count, size_t elementSize)
      : buf_(buf), pos_(pos), count_(count), elementSize_(elementSize) {}

  size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }

  // Reads a scalar at `offset` bytes into element i (struct vectors and scalar vectors).
  template <class T>
  T read(size_t i, size_t offset = 0) const {
    check(i, offset + sizeof(T));
    return buf_->read<T>(pos_ + i * elementSize_ + offset, "flatbuffer vector element");
  }
  // Position of element i; used to follow offset elements (vectors of tables).
  size_t elementPos(size_t i) const {
    check(i, elementSize_);
    return pos_ + i * elementSize_;
  }

 private:
  void check(size_t i, size_t bytes) const {
    if (i >= count_ || bytes > elementSize_) {
      buf_->fail("flatbuffer vector index " + std::to_string(i) + " out of range");
    }
  }

  const ByteView* buf_;
  size_t pos_;
  size_t count_;
  size_t elementSize_;
};

// A table inside a flatbuffer. Construction checks the table's soffset, its vtable and its
// inline extent; each accessor checks that the field lies inside the table and that what it
// points to lies inside the buffer. The ByteView must outlive the Table.
class Table {
 public:
  Table(const ByteView& buf, size_t pos, const char* what) : buf_(&buf), pos_(pos), what_(what) {
    const int64_t soffset = buf.read<int32_t>(pos, what);
    const int64_t vtable = int64_t(pos) - soffset;
    if (vtable < 0 || size_t(vtable) > buf.size()) fail("vtable outside the buffer");
    vtable_ = size_t(vtable);
    vtableSize_ = buf.read<uint16_t>(vtable_, what);
    tableSize_ = buf.read<uint16_t>(vtable_ + 2, what);
    if (vtableSize_ < 4 || vtableSize_ % 2 != 0) fail("bad vtable size " + std::to_string(vtableSize_));
    if (tableSize_ < 4) fail("bad table size " + std::to_string(tableSize_));
    buf.require(vtable_, vtableSize_, what);
    buf.require(pos_, tableSize_, what);
  }

  // The root table: a uoffset at the start of the buffer.
  static Table root(const ByteView& buf, const char* what) { return Table(buf, deref(buf, 0, what), what); }

  bool has(uint16_t field) const { return slot(field) != 0; }

  template <class T>
  T scalar(uint16_t field, T fallback) const {
    const size_t at = fieldPos(field, sizeof(T));
    return at ? buf_->read<T>(at, what_) : fallback;
  }

  std::optional<Table> table(uint16_t field, const char* what) const {
    const size_t at = fieldPos(field, 4);
    if (!at) return std::nullopt;
    return Table(*buf_, deref(*buf_, at, what), what);
  }

  std::optional<std::string_view> string(uint16_t field) const {
    const Vector bytes = vector(field, 1);
    if (!has(field)) return std::nullopt;
    if (bytes.empty()) return std::string_view();
    return std::string_view(reinterpret_cast<const char*>(buf_->bytes().data()) + bytes.elementPos(0), bytes.size());
  }

  // An absent vector reads as empty.
  Vector vector(uint16_t field, size_t elementSize) const {
    const size_t at = fieldPos(field, 4);
    if (!at) return Vector(buf_, 0, 0, elementSize);
    const size_t pos = deref(*buf_, at, what_);
    const size_t count = buf_->read<uint32_t>(pos, what_);
    const size_t room = buf_->size() - pos - 4;  // read<> above proved pos + 4 <= size
    if (count > room / elementSize) fail("vector of " + std::to_string(count) + " elements exceeds the buffer");
    return Vector(buf_, pos + 4, count, elementSize);
  }

  // The table that element i of a vector of tables points to.
  Table tableAt(const Vector& tables, size_t i, const char* what) const {
    return Table(*buf_, deref(*buf_, tables.elementPos(i), what), what);
  }

 private:
  // The vtable entry of `field`: its offset inside the table, 0 when absent.
  uint16_t slot(uint16_t field) const {
    const size_t entry = 4 + 2 * size_t(field);
    if (entry + 2 > vtableSize_) return 0;
    return buf_->read<uint16_t>(vtable_ + entry, what_);
  }

  size_t fieldPos(uint16_t field, size_t size) const {
    const uint16_t offset = slot(field);
    if (offset == 0) return 0;
    if (offset < 4 || size_t(offset) + size > tableSize_) {
      fail("field " + std::to_string(field) + " lies outside its table");
    }
    return pos_ + offset;
  }

  // Follows the uoffset stored at `at`; the target must lie inside the buffer.
  static size_t deref(const ByteView& buf, size_t at, const char* what) {
    const size_t target = at + buf.read<uint32_t>(at, what);
    buf.require(target, 4, what);
    return target;
  }

  [[noreturn]] void fail(const std::string& reason) const { buf_->fail(std::string(what_) + ": " + reason); }

  const ByteView* buf_;
  size_t pos_;
  const char* what_;
  size_t vtable_ = 0;
  uint16_t vtableSize_ = 0;
  uint16_t tableSize_ = 0;
};

}  // namespace hdprior::fb
