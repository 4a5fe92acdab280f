#include "engine/io/flatbuffer_builder.h"

#include <algorithm>

namespace hdprior::fb {

TableBuilder& TableBuilder::string(uint16_t id, const std::string& text) {
  Field f = field(id, Field::Kind::String);
  f.bytes.assign(text.begin(), text.end());
  fields.push_back(std::move(f));
  return *this;
}

TableBuilder& TableBuilder::table(uint16_t id, TableBuilder child) {
  Field f = field(id, Field::Kind::Table);
  f.tables.push_back(std::move(child));
  fields.push_back(std::move(f));
  return *this;
}

TableBuilder& TableBuilder::tables(uint16_t id, std::vector<TableBuilder> children) {
  Field f = field(id, Field::Kind::Tables);
  f.tables = std::move(children);
  fields.push_back(std::move(f));
  return *this;
}

TableBuilder& TableBuilder::structs(uint16_t id, std::vector<uint8_t> packed, size_t count, size_t align) {
  Field f = field(id, Field::Kind::Structs);
  f.bytes = std::move(packed);
  f.count = count;
  f.align = align;
  fields.push_back(std::move(f));
  return *this;
}

namespace {

using Kind = TableBuilder::Field::Kind;

size_t inlineSize(const TableBuilder::Field& f) { return f.kind == Kind::Scalar ? f.size : 4; }

class Serializer {
 public:
  std::vector<uint8_t> out;

  void pad(size_t align) {
    while (out.size() % align != 0) out.push_back(0);
  }
  template <class T>
  void put(T value) {
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &value, sizeof(T));
  }
  template <class T>
  void putAt(size_t at, T value) {
    std::memcpy(out.data() + at, &value, sizeof(T));
  }
  // Stores at `at` the uoffset to `target` (always forward).
  void link(size_t at, size_t target) { putAt<uint32_t>(at, uint32_t(target - at)); }

  // Writes vtable, table and then the table's children; returns the table's position.
  size_t table(const TableBuilder& t) {
    // Inline layout: widest fields first so that each is naturally aligned from an
    // 8-aligned table start (the 4-byte soffset comes first).
    std::vector<const TableBuilder::Field*> order;
    for (const auto& f : t.fields) order.push_back(&f);
    std::stable_sort(order.begin(), order.end(),
                     [](auto* a, auto* b) { return inlineSize(*a) > inlineSize(*b); });
    std::vector<uint16_t> slots;
    size_t end = 4;
    std::vector<size_t> offsetOf(t.fields.size());
    for (const auto* f : order) {
      const size_t size = inlineSize(*f);
      end = (end + size - 1) / size * size;
      offsetOf[size_t(f - t.fields.data())] = end;
      end += size;
      if (slots.size() <= f->id) slots.resize(f->id + 1u, 0);
      slots[f->id] = uint16_t(offsetOf[size_t(f - t.fields.data())]);
    }
    pad(2);
    const size_t vtable = out.size();
    put<uint16_t>(uint16_t(4 + 2 * slots.size()));
    put<uint16_t>(uint16_t(end));
    for (uint16_t s : slots) put<uint16_t>(s);
    pad(8);
    const size_t start = out.size();
    out.resize(start + end, 0);
    putAt<int32_t>(start, int32_t(start - vtable));
    for (size_t i = 0; i < t.fields.size(); ++i) {
      const auto& f = t.fields[i];
      if (f.kind == Kind::Scalar) std::memcpy(out.data() + start + offsetOf[i], &f.scalar, f.size);
    }
    for (size_t i = 0; i < t.fields.size(); ++i) child(t.fields[i], start + offsetOf[i]);
    return start;
  }

  void child(const TableBuilder::Field& f, size_t slot) {
    switch (f.kind) {
      case Kind::Scalar:
        return;
      case Kind::String:
        pad(4);
        link(slot, out.size());
        put<uint32_t>(uint32_t(f.bytes.size()));
        out.insert(out.end(), f.bytes.begin(), f.bytes.end());
        out.push_back(0);
        return;
      case Kind::Table:
        link(slot, table(f.tables.front()));
        return;
      case Kind::Tables: {
        pad(4);
        link(slot, out.size());
        put<uint32_t>(uint32_t(f.tables.size()));
        const size_t elements = out.size();
        out.resize(elements + 4 * f.tables.size(), 0);
        for (size_t i = 0; i < f.tables.size(); ++i) link(elements + 4 * i, table(f.tables[i]));
        return;
      }
      case Kind::Structs:
        pad(4);
        while ((out.size() + 4) % f.align != 0) out.push_back(0);  // elements follow the length
        link(slot, out.size());
        put<uint32_t>(uint32_t(f.count));
        out.insert(out.end(), f.bytes.begin(), f.bytes.end());
        return;
    }
  }
};

}  // namespace

std::vector<uint8_t> finish(const TableBuilder& root) {
  Serializer s;
  s.put<uint32_t>(0);
  s.link(0, s.table(root));
  s.pad(8);
  return std::move(s.out);
}

}  // namespace hdprior::fb
