// Reader of the Arrow IPC file format ("feather v2"), written from the Arrow columnar format
// specification: magic, footer (schema + record batch blocks), encapsulated messages and
// record batch bodies with optional LZ4_FRAME / ZSTD buffer compression.
#include "engine/io/feather.h"

#include <lz4frame.h>
#define ZSTD_STATIC_LINKING_ONLY  // ZSTD_decompressBound
#include <zstd.h>

#include <array>
#include <bit>
#include <cstring>
#include <memory>
#include <optional>

#include "engine/error.h"
#include "engine/io/arrow_ipc.h"
#include "engine/io/byte_view.h"
#include "engine/io/file_bytes.h"
#include "engine/io/flatbuffer_view.h"

namespace hdprior::arrow {

namespace {

constexpr std::string_view kMagic = "ARROW1";
constexpr uint32_t kContinuation = 0xFFFFFFFFu;
constexpr int8_t kCodecLz4Frame = 0, kCodecZstd = 1;
// Far above any real log, low enough that row counts times widths cannot overflow.
constexpr int64_t kMaxRows = int64_t(1) << 40;
// An LZ4 sequence never expands one input byte into more than 255 output bytes.
constexpr uint64_t kLz4MaxRatio = 255;

// Field ids in Arrow's flatbuffer schemas (File.fbs, Message.fbs, Schema.fbs).
namespace footer { enum : uint16_t { version = 0, schema = 1, dictionaries = 2, recordBatches = 3 }; }
namespace schema { enum : uint16_t { endianness = 0, fields = 1 }; }
namespace field { enum : uint16_t { name = 0, nullable = 1, typeType = 2, type = 3, dictionary = 4, children = 5 }; }
namespace message { enum : uint16_t { version = 0, headerType = 1, header = 2, bodyLength = 3 }; }
namespace batch { enum : uint16_t { length = 0, nodes = 1, buffers = 2, compression = 3, variadicCounts = 4 }; }

std::string unionTypeName(uint8_t tag) {
  static constexpr std::array<const char*, 27> names = {
      "NONE", "Null", "Int", "FloatingPoint", "Binary", "Utf8", "Bool", "Decimal", "Date", "Time",
      "Timestamp", "Interval", "List", "Struct", "Union", "FixedSizeBinary", "FixedSizeList", "Map", "Duration",
      "LargeBinary", "LargeUtf8", "LargeList", "RunEndEncoded", "BinaryView", "Utf8View", "ListView",
      "LargeListView"};
  return tag < names.size() ? names[tag] : "#" + std::to_string(tag);
}

struct FieldSpec {
  std::string name;
  Type type;
  bool nullable;
};

Type intType(const fb::Table& t, const ByteView& file, const std::string& column) {
  const int32_t bits = t.scalar<int32_t>(0, 0);
  const bool isSigned = t.scalar<uint8_t>(1, 0) != 0;
  switch (bits) {
    case 8: return isSigned ? Type::Int8 : Type::UInt8;
    case 16: return isSigned ? Type::Int16 : Type::UInt16;
    case 32: return isSigned ? Type::Int32 : Type::UInt32;
    case 64: return isSigned ? Type::Int64 : Type::UInt64;
    default: file.fail("unsupported Int bit width " + std::to_string(bits) + " in column '" + column + "'");
  }
}

Type floatType(const fb::Table& t, const ByteView& file, const std::string& column) {
  switch (t.scalar<int16_t>(0, 0)) {
    case 0: return Type::Float16;
    case 1: return Type::Float32;
    case 2: return Type::Float64;
    default: file.fail("unknown FloatingPoint precision in column '" + column + "'");
  }
}

FieldSpec parseField(const fb::Table& f, const ByteView& file) {
  FieldSpec spec;
  spec.name = std::string(f.string(field::name).value_or(""));
  spec.nullable = f.scalar<uint8_t>(field::nullable, 0) != 0;
  if (f.has(field::dictionary)) file.fail("dictionary-encoded column '" + spec.name + "' is not supported");
  const uint8_t tag = f.scalar<uint8_t>(field::typeType, 0);
  const std::optional<fb::Table> type = f.table(field::type, "field type");
  if (!type) file.fail("column '" + spec.name + "' has no type");
  if (tag == kTypeInt) {
    spec.type = intType(*type, file, spec.name);
  } else if (tag == kTypeFloatingPoint) {
    spec.type = floatType(*type, file, spec.name);
  } else if (tag == kTypeUtf8) {
    spec.type = Type::Utf8;
  } else if (tag == kTypeBool) {
    spec.type = Type::Bool;
  } else if (tag == kTypeDecimal) {
    file.fail("unsupported type Decimal" + std::to_string(type->scalar<int32_t>(2, 128)) + " in column '" + spec.name + "'");
  } else {
    file.fail("unsupported type " + unionTypeName(tag) + " in column '" + spec.name + "'");
  }
  if (!f.vector(field::children, 4).empty()) file.fail("column '" + spec.name + "' has child fields");
  return spec;
}

void checkVersion(int16_t version, const ByteView& file, const char* what) {
  if (version == kMetadataV4 || version == kMetadataV5) return;
  file.fail(std::string(what) + ": unsupported metadata version V" + std::to_string(int(version) + 1) +
            " (only V4 and V5 are read)");
}

std::vector<FieldSpec> parseSchema(const fb::Table& footerTable, const ByteView& file) {
  const std::optional<fb::Table> s = footerTable.table(footer::schema, "schema");
  if (!s) file.fail("footer has no schema");
  if (s->scalar<int16_t>(schema::endianness, 0) != 0) file.fail("big-endian Arrow data is not supported");
  const fb::Vector fields = s->vector(schema::fields, 4);
  std::vector<FieldSpec> specs;
  specs.reserve(fields.size());
  for (size_t i = 0; i < fields.size(); ++i) specs.push_back(parseField(s->tableAt(fields, i, "field"), file));
  return specs;
}

struct Block {
  int64_t offset;
  int32_t metaLength;
  int64_t bodyLength;
};

struct Region {
  uint64_t offset = 0;
  uint64_t length = 0;
};

template <class T, void (*Free)(T*)>
struct Deleter {
  void operator()(T* p) const { Free(p); }
};
void freeLz4(LZ4F_dctx* c) { LZ4F_freeDecompressionContext(c); }
void freeZstd(ZSTD_DCtx* c) { ZSTD_freeDCtx(c); }

// Decompression contexts, created on first use and shared by every buffer of one file.
class Decompressor {
 public:
  explicit Decompressor(const ByteView& file) : file_(file) {}

  // Decompresses `src` into dst[0, size); `context` prefixes error messages.
  void lz4(std::span<const uint8_t> src, uint8_t* dst, size_t size, const std::string& context) {
    if (!lz4_) {
      LZ4F_dctx* ctx = nullptr;
      if (LZ4F_isError(LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION))) file_.fail("out of memory for LZ4");
      lz4_.reset(ctx);
    }
    LZ4F_resetDecompressionContext(lz4_.get());
    size_t in = 0, out = 0, hint = 1;
    while (in < src.size()) {
      size_t inSize = src.size() - in, outSize = size - out;
      hint = LZ4F_decompress(lz4_.get(), dst + out, &outSize, src.data() + in, &inSize, nullptr);
      if (LZ4F_isError(hint)) file_.fail(context + ": corrupt LZ4 frame (" + LZ4F_getErrorName(hint) + ")");
      in += inSize;
      out += outSize;
      if (inSize == 0 && outSize == 0 && hint != 0) break;  // no progress: output full or input exhausted
    }
    if (hint != 0) {
      file_.fail(context + (out == size ? ": LZ4 frame decompresses to more than the " + std::to_string(size) +
                                              " bytes the header says"
                                        : ": truncated LZ4 frame"));
    }
    if (out != size) {
      file_.fail(context + ": LZ4 frame decompressed to " + std::to_string(out) + " bytes, header says " +
                 std::to_string(size));
    }
  }

  void zstd(std::span<const uint8_t> src, uint8_t* dst, size_t size, const std::string& context) {
    if (!zstd_) {
      zstd_.reset(ZSTD_createDCtx());
      if (!zstd_) file_.fail("out of memory for ZSTD");
    }
    const size_t got = ZSTD_decompressDCtx(zstd_.get(), dst, size, src.data(), src.size());
    if (ZSTD_isError(got)) file_.fail(context + ": corrupt ZSTD frame (" + ZSTD_getErrorName(got) + ")");
    if (got != size) {
      file_.fail(context + ": ZSTD frame decompressed to " + std::to_string(got) + " bytes, header says " +
                 std::to_string(size));
    }
  }

 private:
  const ByteView& file_;
  std::unique_ptr<LZ4F_dctx, Deleter<LZ4F_dctx, freeLz4>> lz4_;
  std::unique_ptr<ZSTD_DCtx, Deleter<ZSTD_DCtx, freeZstd>> zstd_;
};

// The buffers of one record batch body, decompressed on demand.
class BodyReader {
 public:
  BodyReader(const ByteView& body, std::optional<int8_t> codec, std::vector<Region> regions, Decompressor& dec,
             std::string context)
      : body_(body), codec_(codec), regions_(std::move(regions)), dec_(dec), context_(std::move(context)) {}

  // At least `needed` bytes of buffer `index`; valid until the next call.
  std::span<const uint8_t> get(size_t index, uint64_t needed, const std::string& what) {
    const Region r = regions_[index];
    std::span<const uint8_t> raw = body_.bytes().subspan(size_t(r.offset), size_t(r.length));
    if (codec_ && !raw.empty()) raw = decompress(raw, needed, what);
    if (raw.size() < needed) {
      body_.fail(context_ + ": " + what + " has " + std::to_string(raw.size()) + " bytes, needs " +
                 std::to_string(needed));
    }
    return raw;
  }

 private:
  std::span<const uint8_t> decompress(std::span<const uint8_t> raw, uint64_t needed, const std::string& what) {
    const std::string where = context_ + ": " + what;
    if (raw.size() < 8) body_.fail(where + ": compressed buffer shorter than its 8-byte length prefix");
    int64_t declared;
    std::memcpy(&declared, raw.data(), 8);
    raw = raw.subspan(8);
    if (declared == -1) return raw;  // stored uncompressed
    if (declared < 0 || uint64_t(declared) < needed) {
      body_.fail(where + ": declared uncompressed length " + std::to_string(declared) + ", needs " +
                 std::to_string(needed));
    }
    // Never allocate more than the compressed bytes can possibly expand to.
    const uint64_t bound = *codec_ == kCodecLz4Frame ? raw.size() * kLz4MaxRatio + 64
                                                     : ZSTD_decompressBound(raw.data(), raw.size());
    if (bound == ZSTD_CONTENTSIZE_ERROR) body_.fail(where + ": corrupt ZSTD frame");
    if (uint64_t(declared) > bound) {
      body_.fail(where + ": declared uncompressed length " + std::to_string(declared) + " exceeds the " +
                 std::to_string(bound) + " bytes its " + (*codec_ == kCodecLz4Frame ? "LZ4" : "ZSTD") +
                 " frame can hold");
    }
    scratch_.resize(size_t(declared));
    if (*codec_ == kCodecLz4Frame) {
      dec_.lz4(raw, scratch_.data(), scratch_.size(), where);
    } else {
      dec_.zstd(raw, scratch_.data(), scratch_.size(), where);
    }
    return scratch_;
  }

  const ByteView& body_;
  std::optional<int8_t> codec_;
  std::vector<Region> regions_;
  Decompressor& dec_;
  std::string context_;
  std::vector<uint8_t> scratch_;
};

int64_t countValid(const uint8_t* bits, int64_t length) {
  int64_t valid = 0;
  for (int64_t i = 0; i < length / 8; ++i) valid += std::popcount(bits[i]);
  for (int64_t i = length / 8 * 8; i < length; ++i) valid += (bits[i >> 3] >> (i & 7)) & 1;
  return valid;
}

// Decodes one column of one record batch into a Column of `length` rows.
Column decodeColumn(const FieldSpec& spec, int64_t length, int64_t nulls, BodyReader& body, size_t& buffer,
                    const ByteView& file, const std::string& context) {
  Column c;
  c.name = spec.name;
  c.type = spec.type;
  c.nullable = spec.nullable;
  c.length = length;
  const std::string col = "column '" + spec.name + "'";
  const uint64_t validityBytes = uint64_t(bitmapBytes(length));
  if (nulls > 0) {
    const std::span<const uint8_t> bits = body.get(buffer, validityBytes, col + " validity");
    if (length - countValid(bits.data(), length) != nulls) {
      file.fail(context + ": " + col + " validity bitmap disagrees with null count " + std::to_string(nulls));
    }
    c.validity.assign(bits.begin(), bits.begin() + ptrdiff_t(validityBytes));
    if (length % 8 != 0) c.validity.back() &= uint8_t((1u << (length % 8)) - 1);
  }
  ++buffer;
  if (spec.type == Type::Bool) {  // bit-packed in the file, a byte per row here
    const std::span<const uint8_t> bits = body.get(buffer++, validityBytes, col + " values");
    c.values.resize(size_t(length));
    for (int64_t i = 0; i < length; ++i) c.values[size_t(i)] = (bits[size_t(i >> 3)] >> (i & 7)) & 1;
    return c;
  }
  if (spec.type != Type::Utf8) {
    const uint64_t bytes = uint64_t(length) * byteWidth(spec.type);
    const std::span<const uint8_t> values = body.get(buffer++, bytes, col + " values");
    c.values.assign(values.begin(), values.begin() + ptrdiff_t(bytes));
    return c;
  }
  // Utf8: offsets, then data. An empty batch may omit its single offset.
  c.offsets.assign(size_t(length) + 1, 0);
  const uint64_t offsetBytes = length == 0 ? 0 : uint64_t(length + 1) * 4;
  const std::span<const uint8_t> offsets = body.get(buffer++, offsetBytes, col + " offsets");
  if (offsetBytes > 0) std::memcpy(c.offsets.data(), offsets.data(), size_t(offsetBytes));
  const int32_t first = c.offsets.front();
  if (first < 0) file.fail(context + ": " + col + " has a negative first offset");
  for (int64_t i = 0; i < length; ++i) {
    if (c.offsets[size_t(i) + 1] < c.offsets[size_t(i)]) {
      file.fail(context + ": " + col + " offsets decrease at row " + std::to_string(i));
    }
  }
  const std::span<const uint8_t> data = body.get(buffer++, uint64_t(c.offsets.back()), col + " string data");
  c.values.assign(data.begin() + first, data.begin() + c.offsets.back());
  for (int32_t& o : c.offsets) o -= first;
  return c;
}

class FileParser {
 public:
  FileParser(std::span<const uint8_t> bytes, const std::string& source) : file_(bytes, source), dec_(file_) {}

  Table parse() {
    const ByteView footerBytes = locateFooter();
    const fb::Table footerTable = fb::Table::root(footerBytes, "footer");
    checkVersion(footerTable.scalar<int16_t>(footer::version, 0), file_, "footer");
    fields_ = parseSchema(footerTable, file_);
    Table table;
    for (const FieldSpec& f : fields_) {
      Column c;
      c.name = f.name;
      c.type = f.type;
      c.nullable = f.nullable;
      if (f.type == Type::Utf8) c.offsets = {0};
      table.columns.push_back(std::move(c));
    }
    const fb::Vector blocks = footerTable.vector(footer::recordBatches, 24);
    uint64_t previousEnd = 8;
    for (size_t i = 0; i < blocks.size(); ++i) {
      const Block block{blocks.read<int64_t>(i, 0), blocks.read<int32_t>(i, 8), blocks.read<int64_t>(i, 16)};
      previousEnd = readBatch(block, i, previousEnd, table);
    }
    return table;
  }

 private:
  // Checks both magics and returns the footer flatbuffer.
  ByteView locateFooter() {
    const std::span<const uint8_t> b = file_.bytes();
    auto magicAt = [&](size_t at) { return std::memcmp(b.data() + at, kMagic.data(), kMagic.size()) == 0; };
    if (b.size() < kMagic.size() || !magicAt(0)) {
      file_.fail(b.size() >= 4 && std::memcmp(b.data(), "FEA1", 4) == 0
                     ? "bad magic: feather v1 is not supported, only Arrow IPC files (feather v2)"
                     : "bad magic: not an Arrow IPC file");
    }
    constexpr size_t kHeader = 8, kTrailer = 4 + 6;
    if (b.size() < kHeader + kTrailer) file_.fail("truncated: " + std::to_string(b.size()) + " bytes");
    if (!magicAt(b.size() - kMagic.size())) file_.fail("truncated: no ARROW1 magic at the end of the file");
    const int32_t footerLength = file_.read<int32_t>(b.size() - kTrailer, "footer length");
    if (footerLength <= 0 || size_t(footerLength) > b.size() - kHeader - kTrailer) {
      file_.fail("truncated: footer length " + std::to_string(footerLength) + " exceeds file size " +
                 std::to_string(b.size()));
    }
    footerStart_ = b.size() - kTrailer - size_t(footerLength);
    return file_.sub(footerStart_, size_t(footerLength), "footer");
  }

  // Reads record batch `index`; blocks must follow each other without overlapping, which
  // bounds the decoded size by the file size. Returns the block's end.
  uint64_t readBatch(const Block& block, size_t index, uint64_t previousEnd, Table& table) {
    const std::string context = "record batch " + std::to_string(index);
    if (block.offset < 0 || block.metaLength <= 0 || block.bodyLength < 0 || uint64_t(block.offset) < previousEnd ||
        uint64_t(block.offset) > footerStart_ || uint64_t(block.metaLength) > footerStart_ - uint64_t(block.offset) ||
        uint64_t(block.bodyLength) > footerStart_ - uint64_t(block.offset) - uint64_t(block.metaLength)) {
      file_.fail(context + ": block (offset " + std::to_string(block.offset) + ", metadata " +
                 std::to_string(block.metaLength) + ", body " + std::to_string(block.bodyLength) +
                 " bytes) lies outside the data area or overlaps the previous one");
    }
    const ByteView meta = file_.sub(size_t(block.offset), size_t(block.metaLength), "message");
    const ByteView body = file_.sub(size_t(block.offset) + size_t(block.metaLength), size_t(block.bodyLength), "body");
    const ByteView flatbuffer = messageFlatbuffer(meta, context);
    const fb::Table msg = fb::Table::root(flatbuffer, "message");
    checkVersion(msg.scalar<int16_t>(message::version, 0), file_, context.c_str());
    if (msg.scalar<uint8_t>(message::headerType, 0) != kHeaderRecordBatch) {
      file_.fail(context + ": message is not a record batch");
    }
    if (msg.scalar<int64_t>(message::bodyLength, 0) != block.bodyLength) {
      file_.fail(context + ": message body length disagrees with the footer");
    }
    const std::optional<fb::Table> rb = msg.table(message::header, "record batch");
    if (!rb) file_.fail(context + ": record batch message without header");
    decodeBatch(*rb, body, context, table);
    return uint64_t(block.offset) + uint64_t(block.metaLength) + uint64_t(block.bodyLength);
  }

  // Strips the message prefix: continuation marker + length, or the legacy bare length.
  ByteView messageFlatbuffer(const ByteView& meta, const std::string& context) const {
    size_t prefix = 4;
    uint32_t length = meta.read<uint32_t>(0, "message length");
    if (length == kContinuation) {
      prefix = 8;
      length = meta.read<uint32_t>(4, "message length");
    }
    if (length == 0 || length > meta.size() - prefix) {
      file_.fail(context + ": message length " + std::to_string(length) + " exceeds its block");
    }
    return meta.sub(prefix, length, "message");
  }

  void decodeBatch(const fb::Table& rb, const ByteView& body, const std::string& context, Table& table) {
    const int64_t length = rb.scalar<int64_t>(batch::length, 0);
    if (length < 0 || length > kMaxRows || table.numRows > kMaxRows - length) {
      file_.fail(context + ": implausible length " + std::to_string(length));
    }
    const fb::Vector nodes = rb.vector(batch::nodes, 16);
    const fb::Vector buffers = rb.vector(batch::buffers, 16);
    if (nodes.size() != fields_.size()) {
      file_.fail(context + ": " + std::to_string(nodes.size()) + " field nodes for " + std::to_string(fields_.size()) +
                 " columns");
    }
    size_t expectedBuffers = 0;
    for (const FieldSpec& f : fields_) expectedBuffers += f.type == Type::Utf8 ? 3 : 2;
    if (buffers.size() != expectedBuffers) {
      file_.fail(context + ": " + std::to_string(buffers.size()) + " buffers, schema needs " +
                 std::to_string(expectedBuffers));
    }
    if (!rb.vector(batch::variadicCounts, 8).empty()) file_.fail(context + ": variadic buffers are not supported");
    BodyReader reader(body, codec(rb, context), regions(buffers, body, context), dec_, context);
    size_t buffer = 0;
    for (size_t i = 0; i < fields_.size(); ++i) {
      const int64_t nodeLength = nodes.read<int64_t>(i, 0), nulls = nodes.read<int64_t>(i, 8);
      if (nodeLength != length) file_.fail(context + ": column '" + fields_[i].name + "' length differs from the batch");
      if (nulls < 0 || nulls > length) file_.fail(context + ": column '" + fields_[i].name + "' has a bad null count");
      Column part = decodeColumn(fields_[i], length, nulls, reader, buffer, file_, context);
      if (table.columns[i].length == 0) {
        table.columns[i] = std::move(part);
      } else {
        table.columns[i].append(part);
      }
    }
    table.numRows += length;
  }

  std::optional<int8_t> codec(const fb::Table& rb, const std::string& context) const {
    const std::optional<fb::Table> c = rb.table(batch::compression, "body compression");
    if (!c) return std::nullopt;
    const int8_t codec = c->scalar<int8_t>(0, kCodecLz4Frame);
    if (codec != kCodecLz4Frame && codec != kCodecZstd) {
      file_.fail(context + ": unknown compression codec " + std::to_string(codec));
    }
    if (c->scalar<int8_t>(1, 0) != 0) file_.fail(context + ": unsupported body compression method");
    return codec;
  }

  // Buffer regions, each inside the body; non-empty ones in order without overlap.
  std::vector<Region> regions(const fb::Vector& buffers, const ByteView& body, const std::string& context) const {
    std::vector<Region> out(buffers.size());
    uint64_t end = 0;
    for (size_t i = 0; i < buffers.size(); ++i) {
      const int64_t offset = buffers.read<int64_t>(i, 0), length = buffers.read<int64_t>(i, 8);
      if (offset < 0 || length < 0 || uint64_t(offset) > body.size() || uint64_t(length) > body.size() - uint64_t(offset)) {
        file_.fail(context + ": buffer " + std::to_string(i) + " (offset " + std::to_string(offset) + ", length " +
                   std::to_string(length) + ") exceeds the body of " + std::to_string(body.size()) + " bytes");
      }
      if (length == 0) continue;
      if (uint64_t(offset) < end) file_.fail(context + ": buffer " + std::to_string(i) + " overlaps the previous one");
      out[i] = Region{uint64_t(offset), uint64_t(length)};
      end = uint64_t(offset) + uint64_t(length);
    }
    return out;
  }

  ByteView file_;
  Decompressor dec_;
  size_t footerStart_ = 0;
  std::vector<FieldSpec> fields_;
};

}  // namespace

Table parseFeather(std::span<const uint8_t> bytes, const std::string& source) {
  return FileParser(bytes, source).parse();
}

Table readFeather(const std::filesystem::path& path) {
  const std::vector<uint8_t> bytes = readFileBytes(path);
  return parseFeather(bytes, path.string());
}

}  // namespace hdprior::arrow
