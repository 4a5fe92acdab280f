#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hdprior::arrow {

// The column types hdprior reads and writes (a strict subset of Arrow's). A Bool column holds one
// byte per row (0 or 1) here; the file packs it into bits.
enum class Type : uint8_t {
  Int8, Int16, Int32, Int64, UInt8, UInt16, UInt32, UInt64, Float16, Float32, Float64, Utf8, Bool,
};

std::string_view typeName(Type type);
size_t byteWidth(Type type);  // 0 for Utf8

// One column, all record batches concatenated. Values are stored as raw little-endian
// bytes exactly as Arrow lays them out, so reading and writing are bit-exact.
struct Column {
  std::string name;
  Type type = Type::Int32;
  bool nullable = false;
  int64_t length = 0;
  std::vector<uint8_t> validity;  // LSB-first bitmap of `length` bits; empty = all valid
  std::vector<uint8_t> values;    // fixed-width values, or UTF-8 bytes for Utf8
  std::vector<int32_t> offsets;   // Utf8 only: length + 1 offsets into `values`

  bool isValid(int64_t row) const;
  int64_t nullCount() const;

  // Typed access; throws Error if the column's type is not T's (float16 as uint16_t).
  template <class T>
  std::span<const T> as() const;
  // Any numeric column widened to double (float16 decoded); nulls become NaN.
  std::vector<double> toDouble() const;
  std::string_view stringAt(int64_t row) const;  // Utf8 only

  // Concatenation and slicing by rows (record batches); validity bits are re-packed. A
  // slice without nulls gets an empty bitmap. Both throw Error on mismatched or bad ranges.
  void append(const Column& other);
  Column slice(int64_t start, int64_t count) const;

  // Builders used by writers and tests.
  template <class T>
  static Column fromValues(std::string name, Type type, std::span<const T> values);
  static Column fromStrings(std::string name, std::span<const std::string> values);
};

struct Table {
  std::vector<Column> columns;
  int64_t numRows = 0;

  // Throws Error(source, "missing column 'name'") or a type mismatch naming the column.
  const Column& column(std::string_view name, std::string_view source = {}) const;
  const Column& column(std::string_view name, Type expected, std::string_view source) const;
  bool has(std::string_view name) const;
};

}  // namespace hdprior::arrow
