// Writer of the Arrow IPC file format ("feather v2"): magic, schema message, record batches
// (8-byte aligned body buffers, optionally LZ4_FRAME / ZSTD compressed per buffer), footer.
#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <cstring>
#include <memory>

#include "engine/error.h"
#include "engine/io/arrow_ipc.h"
#include "engine/io/feather.h"
#include "engine/io/file_bytes.h"
#include "engine/io/flatbuffer_builder.h"

namespace hdprior::arrow {

namespace {

constexpr int kZstdLevel = 1;  // Arrow's default

template <class T>
void appendScalar(std::vector<uint8_t>& out, T value) {
  const size_t at = out.size();
  out.resize(at + sizeof(T));
  std::memcpy(out.data() + at, &value, sizeof(T));
}

void padTo8(std::vector<uint8_t>& out) { out.resize((out.size() + 7) / 8 * 8, 0); }

fb::TableBuilder fieldTable(const Column& c) {
  fb::TableBuilder type;
  uint8_t tag = kTypeUtf8;
  switch (c.type) {
    case Type::Float16:
    case Type::Float32:
    case Type::Float64:
      tag = kTypeFloatingPoint;
      type.scalar<int16_t>(0, c.type == Type::Float16 ? 0 : c.type == Type::Float32 ? 1 : 2);
      break;
    case Type::Utf8:
      break;
    case Type::Bool:
      tag = kTypeBool;
      break;
    default: {
      const bool isSigned = c.type == Type::Int8 || c.type == Type::Int16 || c.type == Type::Int32 || c.type == Type::Int64;
      tag = kTypeInt;
      type.scalar<int32_t>(0, int32_t(byteWidth(c.type) * 8)).scalar<uint8_t>(1, isSigned);
    }
  }
  fb::TableBuilder f;
  f.string(0, c.name).scalar<uint8_t>(1, c.nullable).scalar<uint8_t>(2, tag).table(3, std::move(type)).tables(5, {});
  return f;
}

fb::TableBuilder schemaTable(const Table& table) {
  std::vector<fb::TableBuilder> fields;
  for (const Column& c : table.columns) fields.push_back(fieldTable(c));
  fb::TableBuilder s;
  s.scalar<int16_t>(0, 0).tables(1, std::move(fields));  // little endian
  return s;
}

// Appends an encapsulated message (continuation marker, padded metadata length, flatbuffer)
// and returns its size; the body that follows starts 8-byte aligned.
int32_t appendMessage(std::vector<uint8_t>& out, uint8_t headerType, fb::TableBuilder header, int64_t bodyLength) {
  fb::TableBuilder message;
  message.scalar<int16_t>(0, kMetadataV5).scalar<uint8_t>(1, headerType).table(2, std::move(header));
  message.scalar<int64_t>(3, bodyLength);
  const std::vector<uint8_t> flatbuffer = fb::finish(message);  // already a multiple of 8 bytes
  appendScalar<uint32_t>(out, 0xFFFFFFFFu);
  appendScalar<int32_t>(out, int32_t(flatbuffer.size()));
  out.insert(out.end(), flatbuffer.begin(), flatbuffer.end());
  return int32_t(8 + flatbuffer.size());
}

struct ZstdFree {
  void operator()(ZSTD_CCtx* c) const { ZSTD_freeCCtx(c); }
};

// A record batch body: buffers appended one by one, each compressed if asked and padded
// to 8 bytes; remembers the (offset, length) of each.
class BodyBuilder {
 public:
  BodyBuilder(Compression compression, const std::string& source) : compression_(compression), source_(source) {}

  void add(std::span<const uint8_t> data) {
    const int64_t offset = int64_t(bytes_.size());
    if (!data.empty()) {  // empty buffers stay empty, without a length prefix
      if (compression_ == Compression::None) {
        bytes_.insert(bytes_.end(), data.begin(), data.end());
      } else {
        appendScalar<int64_t>(bytes_, int64_t(data.size()));
        compression_ == Compression::Lz4Frame ? lz4(data) : zstd(data);
      }
    }
    appendScalar<int64_t>(buffers_, offset);
    appendScalar<int64_t>(buffers_, int64_t(bytes_.size()) - offset);
    ++count_;
    padTo8(bytes_);
  }

  void clear() {
    bytes_.clear();
    buffers_.clear();
    count_ = 0;
  }
  const std::vector<uint8_t>& bytes() const { return bytes_; }
  const std::vector<uint8_t>& buffers() const { return buffers_; }
  size_t count() const { return count_; }

 private:
  void lz4(std::span<const uint8_t> data) {
    LZ4F_preferences_t prefs{};
    prefs.frameInfo.contentSize = data.size();
    const size_t at = bytes_.size(), bound = LZ4F_compressFrameBound(data.size(), &prefs);
    bytes_.resize(at + bound);
    const size_t got = LZ4F_compressFrame(bytes_.data() + at, bound, data.data(), data.size(), &prefs);
    if (LZ4F_isError(got)) throw Error(source_, std::string("LZ4 compression failed: ") + LZ4F_getErrorName(got));
    bytes_.resize(at + got);
  }

  void zstd(std::span<const uint8_t> data) {
    if (!zstd_) zstd_.reset(ZSTD_createCCtx());
    if (!zstd_) throw Error(source_, "out of memory for ZSTD");
    const size_t at = bytes_.size(), bound = ZSTD_compressBound(data.size());
    bytes_.resize(at + bound);
    const size_t got = ZSTD_compressCCtx(zstd_.get(), bytes_.data() + at, bound, data.data(), data.size(), kZstdLevel);
    if (ZSTD_isError(got)) throw Error(source_, std::string("ZSTD compression failed: ") + ZSTD_getErrorName(got));
    bytes_.resize(at + got);
  }

  Compression compression_;
  const std::string& source_;
  std::vector<uint8_t> bytes_;
  std::vector<uint8_t> buffers_;  // packed Buffer structs
  size_t count_ = 0;
  std::unique_ptr<ZSTD_CCtx, ZstdFree> zstd_;
};

template <class T>
std::span<const uint8_t> asBytes(const std::vector<T>& v, size_t count) {
  return {reinterpret_cast<const uint8_t*>(v.data()), count * sizeof(T)};
}

void checkColumn(const Column& c, int64_t rows, const std::string& source) {
  const std::string col = "column '" + c.name + "'";
  if (c.length != rows) throw Error(source, col + " has " + std::to_string(c.length) + " rows, table " + std::to_string(rows));
  if (!c.validity.empty() && int64_t(c.validity.size()) < bitmapBytes(rows)) {
    throw Error(source, col + " validity bitmap is too short");
  }
  if (c.type != Type::Utf8) {
    if (int64_t(c.values.size()) != rows * int64_t(byteWidth(c.type))) throw Error(source, col + " has the wrong value size");
    return;
  }
  if (int64_t(c.offsets.size()) != rows + 1 || c.offsets.front() < 0 || size_t(c.offsets.back()) > c.values.size()) {
    throw Error(source, col + " has bad offsets");
  }
  for (size_t i = 1; i < c.offsets.size(); ++i) {
    if (c.offsets[i] < c.offsets[i - 1]) throw Error(source, col + " offsets decrease at row " + std::to_string(i - 1));
  }
}

// A Bool column's bytes (0 or 1) packed LSB-first, as Arrow stores Bool values.
std::vector<uint8_t> packedBits(const std::vector<uint8_t>& bytes) {
  std::vector<uint8_t> bits(size_t(bitmapBytes(int64_t(bytes.size()))), 0);
  for (size_t i = 0; i < bytes.size(); ++i) {
    if (bytes[i]) bits[i >> 3] |= uint8_t(1u << (i & 7));
  }
  return bits;
}

// Appends one column's field node and buffers; `part` holds exactly this batch's rows.
void addColumn(const Column& part, std::vector<uint8_t>& nodes, BodyBuilder& body) {
  const int64_t nulls = part.nullCount();
  appendScalar<int64_t>(nodes, part.length);
  appendScalar<int64_t>(nodes, nulls);
  body.add(nulls > 0 ? asBytes(part.validity, size_t(bitmapBytes(part.length))) : std::span<const uint8_t>());
  if (part.type == Type::Utf8) {
    body.add(asBytes(part.offsets, part.offsets.size()));
    body.add(asBytes(part.values, size_t(part.offsets.back())));
  } else if (part.type == Type::Bool) {
    body.add(packedBits(part.values));
  } else {
    body.add(asBytes(part.values, part.values.size()));
  }
}

fb::TableBuilder recordBatchTable(int64_t rows, std::vector<uint8_t> nodes, size_t columns, const BodyBuilder& body,
                                  Compression compression) {
  fb::TableBuilder rb;
  rb.scalar<int64_t>(0, rows).structs(1, std::move(nodes), columns, 8).structs(2, body.buffers(), body.count(), 8);
  if (compression != Compression::None) {
    fb::TableBuilder c;
    c.scalar<int8_t>(0, compression == Compression::Lz4Frame ? 0 : 1).scalar<int8_t>(1, 0);  // codec, BUFFER
    rb.table(3, std::move(c));
  }
  return rb;
}

std::vector<uint8_t> serialize(const Table& table, Compression compression, int64_t rowsPerBatch,
                               const std::string& source) {
  if (rowsPerBatch < 0) throw Error(source, "negative rows per batch");
  for (const Column& c : table.columns) checkColumn(c, table.numRows, source);
  const int64_t step = rowsPerBatch == 0 ? std::max<int64_t>(table.numRows, 1) : rowsPerBatch;

  std::vector<uint8_t> out = {'A', 'R', 'R', 'O', 'W', '1', 0, 0};
  appendMessage(out, kHeaderSchema, schemaTable(table), 0);
  std::vector<uint8_t> blocks;  // packed Block structs
  size_t blockCount = 0;
  BodyBuilder body(compression, source);
  int64_t start = 0;
  do {
    const int64_t rows = std::min(step, table.numRows - start);
    body.clear();
    std::vector<uint8_t> nodes;
    for (const Column& c : table.columns) {
      if (rows == c.length && (c.type != Type::Utf8 || c.offsets.front() == 0)) {
        addColumn(c, nodes, body);  // the whole column: no copy
      } else {
        addColumn(c.slice(start, rows), nodes, body);
      }
    }
    const int64_t offset = int64_t(out.size());
    const int32_t metaLength = appendMessage(out, kHeaderRecordBatch,
                                             recordBatchTable(rows, std::move(nodes), table.columns.size(), body, compression),
                                             int64_t(body.bytes().size()));
    out.insert(out.end(), body.bytes().begin(), body.bytes().end());
    appendScalar<int64_t>(blocks, offset);
    appendScalar<int32_t>(blocks, metaLength);
    appendScalar<int32_t>(blocks, 0);  // struct padding
    appendScalar<int64_t>(blocks, int64_t(body.bytes().size()));
    ++blockCount;
    start += rows;
  } while (start < table.numRows);

  appendScalar<uint32_t>(out, 0xFFFFFFFFu);  // end-of-stream marker, as pyarrow writes it
  appendScalar<int32_t>(out, 0);
  fb::TableBuilder footer;
  footer.scalar<int16_t>(0, kMetadataV5).table(1, schemaTable(table)).structs(2, {}, 0, 8);
  footer.structs(3, std::move(blocks), blockCount, 8);
  const std::vector<uint8_t> footerBytes = fb::finish(footer);
  out.insert(out.end(), footerBytes.begin(), footerBytes.end());
  appendScalar<int32_t>(out, int32_t(footerBytes.size()));
  out.insert(out.end(), {'A', 'R', 'R', 'O', 'W', '1'});
  return out;
}

}  // namespace

std::vector<uint8_t> serializeFeather(const Table& table, Compression compression, int64_t rowsPerBatch) {
  return serialize(table, compression, rowsPerBatch, "feather output");
}

void writeFeather(const std::filesystem::path& path, const Table& table, Compression compression) {
  writeFileAtomically(path, serialize(table, compression, 0, path.string()));
}

}  // namespace hdprior::arrow
