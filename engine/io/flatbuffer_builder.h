#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace hdprior::fb {

// A flatbuffer table described as a value tree, serialised by finish(). Only what the Arrow
// IPC metadata needs: scalars, strings, sub-tables, vectors of tables and vectors of structs.
struct TableBuilder {
  struct Field {
    enum class Kind : uint8_t { Scalar, String, Table, Tables, Structs };
    uint16_t id = 0;
    Kind kind = Kind::Scalar;
    uint64_t scalar = 0;           // Scalar: the value's little-endian bytes
    uint8_t size = 0;              // Scalar: its width in bytes
    std::vector<uint8_t> bytes;    // String bytes, or the packed structs
    size_t count = 0;              // Structs: number of elements
    size_t align = 1;              // Structs: alignment of one element
    std::vector<TableBuilder> tables;  // Table (one) or Tables
  };
  std::vector<Field> fields;

  template <class T>
  TableBuilder& scalar(uint16_t id, T value) {
    static_assert(std::is_arithmetic_v<T> && sizeof(T) <= 8);
    Field f = field(id, Field::Kind::Scalar);
    f.size = uint8_t(sizeof(T));
    std::memcpy(&f.scalar, &value, sizeof(T));  // little-endian host assumed, as everywhere in hdprior
    fields.push_back(std::move(f));
    return *this;
  }
  TableBuilder& string(uint16_t id, const std::string& text);
  TableBuilder& table(uint16_t id, TableBuilder child);
  TableBuilder& tables(uint16_t id, std::vector<TableBuilder> children);
  TableBuilder& structs(uint16_t id, std::vector<uint8_t> packed, size_t count, size_t align);

 private:
  static Field field(uint16_t id, Field::Kind kind) {
    Field f;
    f.id = id;
    f.kind = kind;
    return f;
  }
};

// Serialises `root` as a complete flatbuffer (root uoffset first), padded to 8 bytes.
// Objects are written front to back, each child after its parent, so every uoffset points
// forward as the format requires; all scalars are naturally aligned.
std::vector<uint8_t> finish(const TableBuilder& root);

}  // namespace hdprior::fb
