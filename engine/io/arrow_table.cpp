#include "engine/io/arrow_table.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "engine/error.h"
#include "engine/io/arrow_ipc.h"
#include "engine/io/float16.h"

namespace hdprior::arrow {

namespace {

// Which Arrow types a C++ element type may view (float16 is exposed as its raw bits).
template <class T>
bool matches(Type type) {
  if constexpr (std::is_same_v<T, int8_t>) return type == Type::Int8;
  if constexpr (std::is_same_v<T, int16_t>) return type == Type::Int16;
  if constexpr (std::is_same_v<T, int32_t>) return type == Type::Int32;
  if constexpr (std::is_same_v<T, int64_t>) return type == Type::Int64;
  if constexpr (std::is_same_v<T, uint8_t>) return type == Type::UInt8;
  if constexpr (std::is_same_v<T, uint16_t>) return type == Type::UInt16 || type == Type::Float16;
  if constexpr (std::is_same_v<T, uint32_t>) return type == Type::UInt32;
  if constexpr (std::is_same_v<T, uint64_t>) return type == Type::UInt64;
  if constexpr (std::is_same_v<T, float>) return type == Type::Float32;
  if constexpr (std::is_same_v<T, double>) return type == Type::Float64;
  if constexpr (std::is_same_v<T, bool>) return type == Type::Bool;
  return false;
}

template <class T>
const char* cppName() {
  if constexpr (std::is_same_v<T, int8_t>) return "int8_t";
  if constexpr (std::is_same_v<T, int16_t>) return "int16_t";
  if constexpr (std::is_same_v<T, int32_t>) return "int32_t";
  if constexpr (std::is_same_v<T, int64_t>) return "int64_t";
  if constexpr (std::is_same_v<T, uint8_t>) return "uint8_t";
  if constexpr (std::is_same_v<T, uint16_t>) return "uint16_t";
  if constexpr (std::is_same_v<T, uint32_t>) return "uint32_t";
  if constexpr (std::is_same_v<T, uint64_t>) return "uint64_t";
  if constexpr (std::is_same_v<T, float>) return "float";
  if constexpr (std::is_same_v<T, double>) return "double";
  if constexpr (std::is_same_v<T, bool>) return "bool";
  return "?";
}

[[noreturn]] void fail(const Column& c, const std::string& reason) {
  throw Error("column '" + c.name + "'", reason);
}

bool getBit(const uint8_t* bits, int64_t i) { return (bits[i >> 3] >> (i & 7)) & 1; }

void setBit(uint8_t* bits, int64_t i, bool value) {
  if (value) bits[i >> 3] |= uint8_t(1u << (i & 7));
}

// Copies `count` bits from src (from bit srcBit) to dst (from bit dstBit); the target bits
// of dst must be zero. Byte-wise once dst is byte aligned.
void copyBits(const uint8_t* src, int64_t srcBit, uint8_t* dst, int64_t dstBit, int64_t count) {
  for (; count > 0 && (dstBit & 7) != 0; --count) setBit(dst, dstBit++, getBit(src, srcBit++));
  const int64_t bytes = count / 8;
  const int shift = int(srcBit & 7);
  const uint8_t* s = src + (srcBit >> 3);
  uint8_t* d = dst + (dstBit >> 3);
  if (shift == 0) {
    if (bytes > 0) std::memcpy(d, s, size_t(bytes));
  } else {
    for (int64_t j = 0; j < bytes; ++j) d[j] = uint8_t((s[j] >> shift) | (s[j + 1] << (8 - shift)));
  }
  srcBit += bytes * 8;
  dstBit += bytes * 8;
  for (count -= bytes * 8; count > 0; --count) setBit(dst, dstBit++, getBit(src, srcBit++));
}

// Makes `bits` a bitmap of exactly `length` bits with zero padding; empty means all valid.
void normaliseBitmap(std::vector<uint8_t>& bits, int64_t length) {
  if (bits.empty()) {
    bits.assign(size_t(bitmapBytes(length)), 0xff);
  } else {
    bits.resize(size_t(bitmapBytes(length)));
  }
  if (length % 8 != 0) bits.back() &= uint8_t((1u << (length % 8)) - 1);
}

void checkShape(const Column& c) {
  if (c.length < 0) fail(c, "negative length");
  if (!c.validity.empty() && int64_t(c.validity.size()) < bitmapBytes(c.length)) {
    fail(c, "validity bitmap has " + std::to_string(c.validity.size()) + " bytes for " + std::to_string(c.length) +
                " rows");
  }
  if (c.type == Type::Utf8) {
    if (int64_t(c.offsets.size()) != c.length + 1) fail(c, "offsets do not match the row count");
    if (c.offsets.front() < 0 || c.offsets.back() < c.offsets.front() || size_t(c.offsets.back()) > c.values.size()) {
      fail(c, "offsets outside the string data");
    }
  } else if (int64_t(c.values.size()) != c.length * int64_t(byteWidth(c.type))) {
    fail(c, "has " + std::to_string(c.values.size()) + " value bytes for " + std::to_string(c.length) + " rows of " +
                std::string(typeName(c.type)));
  }
}

// Offsets of rows [begin, end) must not decrease (checkShape already bounds the ends).
void checkOffsets(const Column& c, int64_t begin, int64_t end) {
  for (int64_t i = begin; i < end; ++i) {
    if (c.offsets[size_t(i) + 1] < c.offsets[size_t(i)]) fail(c, "offsets decrease at row " + std::to_string(i));
  }
}

void checkRow(const Column& c, int64_t row) {
  if (row < 0 || row >= c.length) {
    fail(c, "row " + std::to_string(row) + " out of range (length " + std::to_string(c.length) + ")");
  }
}

template <class T>
void widen(const Column& c, std::vector<double>& out) {
  const std::span<const T> v = c.as<T>();
  for (size_t i = 0; i < v.size(); ++i) out[i] = double(v[i]);
}

}  // namespace

std::string_view typeName(Type type) {
  switch (type) {
    case Type::Int8: return "int8";
    case Type::Int16: return "int16";
    case Type::Int32: return "int32";
    case Type::Int64: return "int64";
    case Type::UInt8: return "uint8";
    case Type::UInt16: return "uint16";
    case Type::UInt32: return "uint32";
    case Type::UInt64: return "uint64";
    case Type::Float16: return "float16";
    case Type::Float32: return "float32";
    case Type::Float64: return "float64";
    case Type::Utf8: return "utf8";
    case Type::Bool: return "bool";
  }
  return "unknown";
}

size_t byteWidth(Type type) {
  switch (type) {
    case Type::Int8:
    case Type::UInt8:
    case Type::Bool: return 1;
    case Type::Int16:
    case Type::UInt16:
    case Type::Float16: return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32: return 4;
    case Type::Int64:
    case Type::UInt64:
    case Type::Float64: return 8;
    case Type::Utf8: return 0;
  }
  return 0;
}

bool Column::isValid(int64_t row) const {
  checkRow(*this, row);
  if (validity.empty()) return true;
  if (size_t(row >> 3) >= validity.size()) fail(*this, "validity bitmap shorter than the column");
  return getBit(validity.data(), row);
}

int64_t Column::nullCount() const {
  if (validity.empty()) return 0;
  checkShape(*this);
  const int64_t full = length / 8;
  int64_t valid = 0;
  for (int64_t i = 0; i < full; ++i) valid += std::popcount(validity[size_t(i)]);
  for (int64_t i = full * 8; i < length; ++i) valid += getBit(validity.data(), i);
  return length - valid;
}

template <class T>
std::span<const T> Column::as() const {
  if (!matches<T>(type)) {
    fail(*this, "has type " + std::string(typeName(type)) + ", accessed as " + cppName<T>());
  }
  checkShape(*this);
  // std::vector storage is aligned for any fundamental type.
  return std::span<const T>(reinterpret_cast<const T*>(values.data()), size_t(length));
}

std::vector<double> Column::toDouble() const {
  std::vector<double> out(static_cast<size_t>(length));
  switch (type) {
    case Type::Int8: widen<int8_t>(*this, out); break;
    case Type::Int16: widen<int16_t>(*this, out); break;
    case Type::Int32: widen<int32_t>(*this, out); break;
    case Type::Int64: widen<int64_t>(*this, out); break;
    case Type::UInt8: widen<uint8_t>(*this, out); break;
    case Type::UInt16: widen<uint16_t>(*this, out); break;
    case Type::UInt32: widen<uint32_t>(*this, out); break;
    case Type::UInt64: widen<uint64_t>(*this, out); break;
    case Type::Float32: widen<float>(*this, out); break;
    case Type::Float64: widen<double>(*this, out); break;
    case Type::Bool: widen<bool>(*this, out); break;
    case Type::Float16: {
      const std::span<const uint16_t> v = as<uint16_t>();
      for (size_t i = 0; i < v.size(); ++i) out[i] = halfToFloat(v[i]);
      break;
    }
    case Type::Utf8: fail(*this, "is utf8, not numeric");
  }
  if (!validity.empty()) {
    for (int64_t i = 0; i < length; ++i) {
      if (!getBit(validity.data(), i)) out[size_t(i)] = std::numeric_limits<double>::quiet_NaN();
    }
  }
  return out;
}

std::string_view Column::stringAt(int64_t row) const {
  if (type != Type::Utf8) fail(*this, "has type " + std::string(typeName(type)) + ", not utf8");
  checkRow(*this, row);
  if (offsets.size() < size_t(row) + 2) fail(*this, "offsets shorter than the column");
  const int32_t begin = offsets[size_t(row)], end = offsets[size_t(row) + 1];
  if (begin < 0 || end < begin || size_t(end) > values.size()) fail(*this, "bad offsets at row " + std::to_string(row));
  return std::string_view(reinterpret_cast<const char*>(values.data()) + begin, size_t(end - begin));
}

void Column::append(const Column& other) {
  if (other.type != type) {
    fail(*this, "cannot append " + std::string(typeName(other.type)) + " rows to " + std::string(typeName(type)));
  }
  checkShape(*this);
  checkShape(other);
  if (!validity.empty() || !other.validity.empty()) {
    normaliseBitmap(validity, length);
    std::vector<uint8_t> tail = other.validity;
    normaliseBitmap(tail, other.length);
    validity.resize(size_t(bitmapBytes(length + other.length)), 0);
    copyBits(tail.data(), 0, validity.data(), length, other.length);
  }
  if (type == Type::Utf8) {
    checkOffsets(other, 0, other.length);
    const int64_t base = int64_t(values.size()) - other.offsets.front();
    if (int64_t(values.size()) + other.offsets.back() - other.offsets.front() > std::numeric_limits<int32_t>::max()) {
      fail(*this, "more than 2 GiB of string data");
    }
    for (size_t i = 1; i < other.offsets.size(); ++i) offsets.push_back(int32_t(base + other.offsets[i]));
    values.insert(values.end(), other.values.begin() + other.offsets.front(), other.values.begin() + other.offsets.back());
  } else {
    values.insert(values.end(), other.values.begin(), other.values.end());
  }
  length += other.length;
}

Column Column::slice(int64_t start, int64_t count) const {
  checkShape(*this);
  if (start < 0 || count < 0 || start > length || count > length - start) {
    fail(*this, "slice [" + std::to_string(start) + ", +" + std::to_string(count) + ") out of range");
  }
  Column out;
  out.name = name;
  out.type = type;
  out.nullable = nullable;
  out.length = count;
  if (type == Type::Utf8) {
    checkOffsets(*this, start, start + count);
    const int32_t base = offsets[size_t(start)];
    if (base < 0 || size_t(offsets[size_t(start + count)]) > values.size()) fail(*this, "offsets outside the string data");
    out.offsets.reserve(size_t(count) + 1);
    for (int64_t i = 0; i <= count; ++i) out.offsets.push_back(offsets[size_t(start + i)] - base);
    out.values.assign(values.begin() + base, values.begin() + offsets[size_t(start + count)]);
  } else {
    const size_t w = byteWidth(type);
    out.values.assign(values.begin() + ptrdiff_t(size_t(start) * w), values.begin() + ptrdiff_t(size_t(start + count) * w));
  }
  if (!validity.empty()) {
    out.validity.assign(size_t(bitmapBytes(count)), 0);
    copyBits(validity.data(), start, out.validity.data(), 0, count);
    if (out.nullCount() == 0) out.validity.clear();
  }
  return out;
}

template <class T>
Column Column::fromValues(std::string name, Type type, std::span<const T> values) {
  Column c;
  c.name = std::move(name);
  c.type = type;
  if (!matches<T>(type)) fail(c, std::string("cannot build ") + std::string(typeName(type)) + " from " + cppName<T>());
  c.length = int64_t(values.size());
  c.values.resize(values.size_bytes());
  if (!values.empty()) std::memcpy(c.values.data(), values.data(), values.size_bytes());
  return c;
}

Column Column::fromStrings(std::string name, std::span<const std::string> values) {
  Column c;
  c.name = std::move(name);
  c.type = Type::Utf8;
  c.length = int64_t(values.size());
  c.offsets.reserve(values.size() + 1);
  c.offsets.push_back(0);
  for (const std::string& s : values) {
    if (c.values.size() + s.size() > size_t(std::numeric_limits<int32_t>::max())) fail(c, "more than 2 GiB of string data");
    c.values.insert(c.values.end(), s.begin(), s.end());
    c.offsets.push_back(int32_t(c.values.size()));
  }
  return c;
}

const Column& Table::column(std::string_view name, std::string_view source) const {
  for (const Column& c : columns) {
    if (c.name == name) return c;
  }
  throw Error(source.empty() ? std::string("table") : std::string(source), "missing column '" + std::string(name) + "'");
}

const Column& Table::column(std::string_view name, Type expected, std::string_view source) const {
  const Column& c = column(name, source);
  if (c.type != expected) {
    throw Error(source.empty() ? std::string("table") : std::string(source),
                "column '" + std::string(name) + "' has type " + std::string(typeName(c.type)) + ", expected " +
                    std::string(typeName(expected)));
  }
  return c;
}

bool Table::has(std::string_view name) const {
  for (const Column& c : columns) {
    if (c.name == name) return true;
  }
  return false;
}

#define HDPRIOR_ARROW_INSTANTIATE(T)                            \
  template std::span<const T> Column::as<T>() const;           \
  template Column Column::fromValues<T>(std::string, Type, std::span<const T>);
HDPRIOR_ARROW_INSTANTIATE(int8_t)
HDPRIOR_ARROW_INSTANTIATE(int16_t)
HDPRIOR_ARROW_INSTANTIATE(int32_t)
HDPRIOR_ARROW_INSTANTIATE(int64_t)
HDPRIOR_ARROW_INSTANTIATE(uint8_t)
HDPRIOR_ARROW_INSTANTIATE(uint16_t)
HDPRIOR_ARROW_INSTANTIATE(uint32_t)
HDPRIOR_ARROW_INSTANTIATE(uint64_t)
HDPRIOR_ARROW_INSTANTIATE(float)
HDPRIOR_ARROW_INSTANTIATE(double)
HDPRIOR_ARROW_INSTANTIATE(bool)
#undef HDPRIOR_ARROW_INSTANTIATE

}  // namespace hdprior::arrow
