#include "engine/io/feather.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <random>

#include "engine/error.h"
#include "engine/io/byte_view.h"
#include "engine/io/file_bytes.h"
#include "engine/io/flatbuffer_builder.h"
#include "engine/io/flatbuffer_view.h"
#include "engine/io/float16.h"
#include "test_data.h"

namespace hdprior::arrow {
namespace {

namespace fs = std::filesystem;

const char* const kSweep = "sensors/lidar/315966265259836000.feather";
const char* const kSweep2 = "sensors/lidar/315966265360032000.feather";
const char* const kPoses = "city_SE3_egovehicle.feather";
const char* const kCalibration = "calibration/egovehicle_SE3_sensor.feather";

void expectSameTable(const Table& a, const Table& b, const std::string& what) {
  ASSERT_EQ(a.numRows, b.numRows) << what;
  ASSERT_EQ(a.columns.size(), b.columns.size()) << what;
  for (size_t i = 0; i < a.columns.size(); ++i) {
    const Column &x = a.columns[i], &y = b.columns[i];
    EXPECT_EQ(x.name, y.name) << what;
    EXPECT_EQ(x.type, y.type) << what << " " << x.name;
    EXPECT_EQ(x.nullable, y.nullable) << what << " " << x.name;
    EXPECT_EQ(x.length, y.length) << what << " " << x.name;
    EXPECT_EQ(x.validity, y.validity) << what << " " << x.name;
    EXPECT_EQ(x.values, y.values) << what << " " << x.name;
    EXPECT_EQ(x.offsets, y.offsets) << what << " " << x.name;
  }
}

template <class T>
Column numeric(const char* name, Type type, int64_t n, T (*value)(int64_t)) {
  std::vector<T> v(static_cast<size_t>(n));
  for (int64_t i = 0; i < n; ++i) v[size_t(i)] = value(i);
  return Column::fromValues<T>(name, type, std::span<const T>(v));
}

void setNulls(Column& c, int64_t every, int64_t phase) {
  c.nullable = true;
  c.validity.assign(size_t((c.length + 7) / 8), 0);
  for (int64_t i = 0; i < c.length; ++i) {
    if ((i + phase) % every != 0) c.validity[size_t(i / 8)] |= uint8_t(1u << (i % 8));
  }
}

// Every supported type, some with nulls, 29 rows (not a multiple of 8).
Table syntheticTable() {
  const int64_t n = 29;
  Table t;
  t.numRows = n;
  t.columns.push_back(numeric<int8_t>("i8", Type::Int8, n, [](int64_t i) { return int8_t(i * 9 - 128); }));
  t.columns.push_back(numeric<int16_t>("i16", Type::Int16, n, [](int64_t i) { return int16_t(i * -1111); }));
  t.columns.push_back(numeric<int32_t>("i32", Type::Int32, n, [](int64_t i) { return int32_t(i * 123456789); }));
  t.columns.push_back(numeric<int64_t>("i64", Type::Int64, n, [](int64_t i) { return (i - 14) << 50; }));
  t.columns.push_back(numeric<uint8_t>("u8", Type::UInt8, n, [](int64_t i) { return uint8_t(255 - i); }));
  t.columns.push_back(numeric<uint16_t>("u16", Type::UInt16, n, [](int64_t i) { return uint16_t(i * 2000); }));
  t.columns.push_back(numeric<uint32_t>("u32", Type::UInt32, n, [](int64_t i) { return uint32_t(i) * 0x9E3779B9u; }));
  t.columns.push_back(numeric<uint64_t>("u64", Type::UInt64, n, [](int64_t i) { return ~uint64_t(i); }));
  t.columns.push_back(numeric<uint16_t>("f16", Type::Float16, n, [](int64_t i) { return floatToHalf(float(i) * 0.1f - 1.f); }));
  t.columns.push_back(numeric<float>("f32", Type::Float32, n, [](int64_t i) { return float(i) / 3.f; }));
  t.columns.push_back(numeric<double>("f64", Type::Float64, n, [](int64_t i) { return std::sqrt(double(i)) * 1e10; }));
  std::vector<std::string> s;
  for (int64_t i = 0; i < n; ++i) s.push_back(i % 5 == 0 ? "" : "row " + std::to_string(i) + (i % 2 ? " ü" : ""));
  t.columns.push_back(Column::fromStrings("utf8", s));
  Column flags{.name = "flag", .type = Type::Bool, .length = n};
  for (int64_t i = 0; i < n; ++i) flags.values.push_back(uint8_t(i % 3 == 0 || i == n - 1));
  t.columns.push_back(flags);
  setNulls(t.columns[2], 3, 0);
  setNulls(t.columns[8], 7, 1);
  setNulls(t.columns[10], 2, 1);
  setNulls(t.columns[11], 4, 2);
  setNulls(t.columns[12], 5, 1);
  t.columns[5].nullable = true;  // nullable without nulls
  return t;
}

// --- real files -------------------------------------------------------------------------

TEST(FeatherReal, LidarSweepMatchesTheIndependentReader) {
  const Table t = readFeather(test::sharedLog() / kSweep);
  ASSERT_EQ(t.numRows, 99229);
  const char* names[] = {"x", "y", "z", "intensity", "laser_number", "offset_ns"};
  ASSERT_EQ(t.columns.size(), 6u);
  for (size_t i = 0; i < 6; ++i) EXPECT_EQ(t.columns[i].name, names[i]);
  const auto x = t.column("x", Type::Float16, kSweep).as<uint16_t>();
  const auto y = t.column("y", Type::Float16, kSweep).as<uint16_t>();
  const auto z = t.column("z", Type::Float16, kSweep).as<uint16_t>();
  EXPECT_EQ(halfToFloat(x[0]), -1.537109375f);
  EXPECT_EQ(halfToFloat(y[0]), 3.060546875f);
  EXPECT_EQ(halfToFloat(z[0]), -0.322509765625f);
  EXPECT_EQ(t.column("x").toDouble()[0], -1.537109375);
  EXPECT_EQ(t.column("intensity", Type::UInt8, kSweep).as<uint8_t>()[0], 10);
  EXPECT_EQ(t.column("laser_number", Type::UInt8, kSweep).as<uint8_t>()[0], 31);
  const auto offsets = t.column("offset_ns", Type::Int32, kSweep).as<int32_t>();
  EXPECT_EQ(offsets.front(), 2654000);
  EXPECT_EQ(offsets.back(), 106085816);
  for (const Column& c : t.columns) EXPECT_EQ(c.nullCount(), 0) << c.name;
  EXPECT_THROW(t.column("x", Type::Float32, kSweep), Error);

  EXPECT_EQ(readFeather(test::sharedLog() / kSweep2).numRows, 99466);
}

TEST(FeatherReal, PosesAndCalibration) {
  const Table poses = readFeather(test::sharedLog() / kPoses);
  ASSERT_EQ(poses.numRows, 2706);
  EXPECT_EQ(poses.column("timestamp_ns", Type::Int64, kPoses).as<int64_t>()[0], 315966253572412942);
  EXPECT_EQ(poses.column("timestamp_ns", Type::Int64, kPoses).as<int64_t>().back(), 315966269522412935);
  EXPECT_EQ(poses.column("tx_m", Type::Float64, kPoses).as<double>()[0], 5172.668216028519);
  for (const char* name : {"qw", "qx", "qy", "qz", "ty_m", "tz_m"}) EXPECT_TRUE(poses.has(name)) << name;

  const Table calib = readFeather(test::sharedLog() / kCalibration);
  const Column& names = calib.column("sensor_name", Type::Utf8, kCalibration);
  std::vector<std::string> sensors;
  for (int64_t i = 0; i < names.length; ++i) sensors.emplace_back(names.stringAt(i));
  EXPECT_NE(std::find(sensors.begin(), sensors.end(), "up_lidar"), sensors.end());
  EXPECT_NE(std::find(sensors.begin(), sensors.end(), "down_lidar"), sensors.end());
  EXPECT_EQ(calib.column("qw", Type::Float64, kCalibration).length, calib.numRows);
}

// The real ground labels beside the log (Argoverse 2 scene flow, pyarrow-written): bool columns are
// bit-packed in the file and read as one byte per row.
TEST(FeatherReal, GroundLabelsWithBoolColumns) {
  const std::filesystem::path file = test::sharedDataDir() / "labels/7fab2350-7eaf-3b7e-a39d-6937a4c1bede/flow_labels.feather";
  const Table t = readFeather(file);
  ASSERT_EQ(t.numRows, 99229);
  const std::span<const bool> ground = t.column("is_ground_0", Type::Bool, file.string()).as<bool>();
  EXPECT_EQ(std::count(ground.begin(), ground.end(), true), 17374);
  const std::span<const bool> dynamic = t.column("dynamic", Type::Bool, file.string()).as<bool>();
  EXPECT_EQ(std::count(dynamic.begin(), dynamic.end(), true), 2037);
  EXPECT_EQ(t.column("classes", Type::UInt8, file.string()).length, 99229);
  for (Compression c : {Compression::None, Compression::Lz4Frame}) {
    expectSameTable(t, parseFeather(serializeFeather(t, c, 1000), "labels"), "labels");
  }
}

TEST(FeatherReal, MissingFileIsAnError) {
  EXPECT_THROW(readFeather(test::sharedLog() / "no_such.feather"), Error);
}

// --- round trips --------------------------------------------------------------------------

TEST(FeatherRoundTrip, RealFilesAreBitIdenticalForEveryCompression) {
  for (const char* file : {kSweep, kPoses, kCalibration}) {
    const Table original = readFeather(test::sharedLog() / file);
    for (Compression c : {Compression::None, Compression::Lz4Frame, Compression::Zstd}) {
      for (int64_t rowsPerBatch : {0, 1000}) {
        const std::string what = std::string(file) + " codec " + std::to_string(int(c)) + " batch " +
                                 std::to_string(rowsPerBatch);
        expectSameTable(original, parseFeather(serializeFeather(original, c, rowsPerBatch), what), what);
      }
    }
  }
}

TEST(FeatherRoundTrip, TinyBatches) {
  for (const char* file : {kSweep, kPoses, kCalibration}) {
    const Table original = readFeather(test::sharedLog() / file);
    for (Compression c : {Compression::None, Compression::Lz4Frame, Compression::Zstd}) {
      if (file == kSweep && c != Compression::Lz4Frame) continue;  // 14176 batches: one codec is enough
      const std::string what = std::string(file) + " codec " + std::to_string(int(c));
      expectSameTable(original, parseFeather(serializeFeather(original, c, 7), what), what);
    }
  }
}

TEST(FeatherRoundTrip, SyntheticTableWithEveryTypeAndNulls) {
  const Table t = syntheticTable();
  for (Compression c : {Compression::None, Compression::Lz4Frame, Compression::Zstd}) {
    for (int64_t rowsPerBatch : {0, 1, 3, 7, 8, 13, 28, 29, 100}) {
      const std::string what = "codec " + std::to_string(int(c)) + " batch " + std::to_string(rowsPerBatch);
      const Table back = parseFeather(serializeFeather(t, c, rowsPerBatch), what);
      expectSameTable(t, back, what);
    }
  }
  const Table back = parseFeather(serializeFeather(t), "synthetic");
  EXPECT_EQ(back.column("i32").nullCount(), 10);
  EXPECT_FALSE(back.column("utf8").isValid(2));
  EXPECT_EQ(back.column("utf8").stringAt(3), "row 3 ü");
  EXPECT_TRUE(std::isnan(back.column("f16").toDouble()[6]));
}

TEST(FeatherRoundTrip, EmptyTables) {
  Table t = syntheticTable();
  for (Column& c : t.columns) c = c.slice(0, 0);
  t.numRows = 0;
  expectSameTable(t, parseFeather(serializeFeather(t, Compression::Zstd), "empty"), "empty");
  const Table none;
  expectSameTable(none, parseFeather(serializeFeather(none), "no columns"), "no columns");
}

TEST(FeatherRoundTrip, WriteFeatherIsAtomicAndReadable) {
  const fs::path dir = test::freshOutputDir("feather_write");
  const Table t = syntheticTable();
  writeFeather(dir / "t.feather", t, Compression::Zstd);
  expectSameTable(t, readFeather(dir / "t.feather"), "file");
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, 1u);  // no temporary left behind
  Table bad = t;
  bad.columns[0].values.pop_back();
  EXPECT_THROW(writeFeather(dir / "bad.feather", bad), Error);
  EXPECT_FALSE(fs::exists(dir / "bad.feather"));
}

// The writer's output has the layout the format prescribes and pyarrow produces.
TEST(FeatherWriter, LayoutFollowsTheSpecification) {
  const std::vector<uint8_t> f = serializeFeather(syntheticTable(), Compression::Lz4Frame, 10);
  ASSERT_GT(f.size(), 32u);
  EXPECT_EQ(std::memcmp(f.data(), "ARROW1\0\0", 8), 0);
  EXPECT_EQ(std::memcmp(f.data() + f.size() - 6, "ARROW1", 6), 0);
  const ByteView all(f, "t");
  EXPECT_EQ(all.read<uint32_t>(8), 0xFFFFFFFFu);  // continuation marker before the schema message
  const size_t footerStart = f.size() - 10 - size_t(all.read<int32_t>(f.size() - 10));
  EXPECT_EQ(all.read<uint64_t>(footerStart - 8), 0xFFFFFFFFull);  // end-of-stream marker
  const ByteView footerBytes = all.sub(footerStart, f.size() - 10 - footerStart, "footer");
  const fb::Table footer = fb::Table::root(footerBytes, "footer");
  EXPECT_EQ(footer.scalar<int16_t>(0, 0), 4);  // V5
  const fb::Vector blocks = footer.vector(3, 24);
  ASSERT_EQ(blocks.size(), 3u);
  for (size_t i = 0; i < blocks.size(); ++i) {
    const int64_t offset = blocks.read<int64_t>(i, 0);
    const int32_t meta = blocks.read<int32_t>(i, 8);
    EXPECT_EQ(offset % 8, 0);
    EXPECT_EQ(meta % 8, 0);
    EXPECT_EQ(blocks.read<int64_t>(i, 16) % 8, 0);
    const ByteView msgBytes = all.sub(size_t(offset) + 8, size_t(meta) - 8, "message");
    const fb::Table msg = fb::Table::root(msgBytes, "message");
    EXPECT_EQ(msg.scalar<uint8_t>(1, 0), 3);  // RecordBatch
    const fb::Table rb = *msg.table(2, "rb");
    const fb::Vector buffers = rb.vector(2, 16);
    for (size_t b = 0; b < buffers.size(); ++b) EXPECT_EQ(buffers.read<int64_t>(b, 0) % 8, 0);
    const std::optional<fb::Table> compression = rb.table(3, "compression");
    ASSERT_TRUE(compression);
    EXPECT_EQ(compression->scalar<int8_t>(0, -1), 0);  // LZ4_FRAME
  }
}

// --- the flatbuffer builder and view -------------------------------------------------------

TEST(FeatherFlatbuffer, BuilderOutputReadsBackThroughTheView) {
  fb::TableBuilder child;
  child.scalar<int64_t>(0, -7);
  std::vector<uint8_t> structs(32);
  for (size_t i = 0; i < 32; ++i) structs[i] = uint8_t(i);
  fb::TableBuilder root;
  root.scalar<uint8_t>(0, 200).scalar<int64_t>(3, 1ll << 40).string(1, "hello").table(2, child);
  root.tables(4, {child, fb::TableBuilder{}}).structs(6, structs, 2, 8).scalar<int16_t>(7, -3);
  const std::vector<uint8_t> bytes = fb::finish(root);
  EXPECT_EQ(bytes.size() % 8, 0u);
  const ByteView view(bytes, "fb");
  const fb::Table t = fb::Table::root(view, "root");
  EXPECT_EQ(t.scalar<uint8_t>(0, 0), 200);
  EXPECT_EQ(t.scalar<int64_t>(3, 0), 1ll << 40);
  EXPECT_EQ(t.scalar<int16_t>(7, 0), -3);
  EXPECT_EQ(t.scalar<int32_t>(5, 42), 42);  // absent: default
  EXPECT_FALSE(t.has(5));
  EXPECT_EQ(t.string(1).value(), "hello");
  EXPECT_EQ(t.table(2, "child")->scalar<int64_t>(0, 0), -7);
  const fb::Vector tables = t.vector(4, 4);
  ASSERT_EQ(tables.size(), 2u);
  EXPECT_EQ(t.tableAt(tables, 0, "e").scalar<int64_t>(0, 0), -7);
  EXPECT_FALSE(t.tableAt(tables, 1, "e").has(0));
  const fb::Vector s = t.vector(6, 16);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.elementPos(0) % 8, 0u);
  EXPECT_EQ(s.read<uint8_t>(1, 3), 19);
  EXPECT_THROW(s.read<uint8_t>(2, 0), Error);
  EXPECT_THROW(s.read<int64_t>(0, 9), Error);
}

TEST(FeatherFlatbuffer, ViewRejectsEveryTruncationAndCorruptionWithoutCrashing) {
  fb::TableBuilder root;
  root.scalar<int32_t>(0, 5).string(1, "name").tables(2, {fb::TableBuilder{}.scalar<int64_t>(0, 1)});
  const std::vector<uint8_t> good = fb::finish(root);
  auto walk = [](const std::vector<uint8_t>& bytes) {
    const ByteView view(bytes, "fb");
    const fb::Table t = fb::Table::root(view, "root");
    (void)t.scalar<int32_t>(0, 0);
    (void)t.string(1);
    const fb::Vector v = t.vector(2, 4);
    for (size_t i = 0; i < v.size(); ++i) (void)t.tableAt(v, i, "e").scalar<int64_t>(0, 0);
  };
  walk(good);
  for (size_t n = 0; n < good.size(); ++n) {
    std::vector<uint8_t> cut(good.begin(), good.begin() + ptrdiff_t(n));
    try {
      walk(cut);
    } catch (const Error&) {
    }
  }
  for (size_t i = 0; i < good.size(); ++i) {
    for (uint8_t x : {0x01, 0x80, 0xFF}) {
      std::vector<uint8_t> bad = good;
      bad[i] ^= x;
      try {
        walk(bad);
      } catch (const Error&) {
      }
    }
  }
}

// --- hand-made files: unsupported types and malformed batches ------------------------------

template <class T>
void put(std::vector<uint8_t>& out, T v) {
  const size_t at = out.size();
  out.resize(at + sizeof(T));
  std::memcpy(out.data() + at, &v, sizeof(T));
}

fb::TableBuilder field(const std::string& name, uint8_t typeTag, fb::TableBuilder type) {
  fb::TableBuilder f;
  f.string(0, name).scalar<uint8_t>(1, 1).scalar<uint8_t>(2, typeTag).table(3, std::move(type)).tables(5, {});
  return f;
}

fb::TableBuilder int32Field(const std::string& name) {
  return field(name, 2, fb::TableBuilder{}.scalar<int32_t>(0, 32).scalar<uint8_t>(1, 1));
}

struct Crafted {
  std::vector<fb::TableBuilder> fields = {int32Field("a")};
  int16_t endianness = 0;
  int64_t rows = 0;
  std::vector<int64_t> nodes;    // (length, null_count) pairs
  std::vector<int64_t> buffers;  // (offset, length) pairs
  std::vector<uint8_t> body;
  std::optional<int8_t> codec;
  bool legacyPrefix = false;

  std::vector<uint8_t> bytes() const {
    std::vector<uint8_t> out = {'A', 'R', 'R', 'O', 'W', '1', 0, 0};
    auto packed = [](const std::vector<int64_t>& v) {
      std::vector<uint8_t> b;
      for (int64_t x : v) put(b, x);
      return b;
    };
    fb::TableBuilder rb;
    rb.scalar<int64_t>(0, rows).structs(1, packed(nodes), nodes.size() / 2, 8).structs(2, packed(buffers), buffers.size() / 2, 8);
    if (codec) rb.table(3, fb::TableBuilder{}.scalar<int8_t>(0, *codec));
    fb::TableBuilder msg;
    msg.scalar<int16_t>(0, 4).scalar<uint8_t>(1, 3).table(2, rb).scalar<int64_t>(3, int64_t(body.size()));
    const std::vector<uint8_t> meta = fb::finish(msg);
    const int64_t offset = int64_t(out.size());
    if (legacyPrefix) {
      put<int32_t>(out, int32_t(meta.size() + 4));
      out.insert(out.end(), meta.begin(), meta.end());
      put<int32_t>(out, 0);
    } else {
      put<uint32_t>(out, 0xFFFFFFFFu);
      put<int32_t>(out, int32_t(meta.size()));
      out.insert(out.end(), meta.begin(), meta.end());
    }
    const int32_t metaLength = int32_t(out.size() - size_t(offset));
    out.insert(out.end(), body.begin(), body.end());
    std::vector<uint8_t> block;
    put(block, offset);
    put(block, metaLength);
    put<int32_t>(block, 0);
    put(block, int64_t(body.size()));
    fb::TableBuilder schema;
    schema.scalar<int16_t>(0, endianness).tables(1, fields);
    fb::TableBuilder footer;
    footer.scalar<int16_t>(0, 4).table(1, schema).structs(3, block, 1, 8);
    const std::vector<uint8_t> f = fb::finish(footer);
    out.insert(out.end(), f.begin(), f.end());
    put<int32_t>(out, int32_t(f.size()));
    out.insert(out.end(), {'A', 'R', 'R', 'O', 'W', '1'});
    return out;
  }
};

// One int32 column [1, 2, 3] in an uncompressed batch.
Crafted threeInts() {
  Crafted c;
  c.rows = 3;
  c.nodes = {3, 0};
  c.buffers = {0, 0, 0, 12};
  for (int32_t v : {1, 2, 3}) put(c.body, v);
  c.body.resize(16, 0);
  return c;
}

std::string featherErrorOf(const std::vector<uint8_t>& bytes) {
  try {
    parseFeather(bytes, "crafted.feather");
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "crafted.feather");
    return e.reason();
  }
  return "no error";
}

TEST(FeatherCrafted, ReadsAHandMadeFileWithEitherMessagePrefix) {
  Crafted c = threeInts();
  for (bool legacy : {false, true}) {
    c.legacyPrefix = legacy;
    const Table t = parseFeather(c.bytes(), "crafted");
    ASSERT_EQ(t.numRows, 3);
    EXPECT_EQ(t.column("a").as<int32_t>()[2], 3);
  }
}

TEST(FeatherCrafted, UnsupportedSchemasAreNamed) {
  Crafted c = threeInts();
  c.fields = {field("d", 7, fb::TableBuilder{}.scalar<int32_t>(0, 10).scalar<int32_t>(1, 2))};
  EXPECT_EQ(featherErrorOf(c.bytes()), "unsupported type Decimal128 in column 'd'");
  c.fields = {field("s", 13, fb::TableBuilder{})};
  EXPECT_EQ(featherErrorOf(c.bytes()), "unsupported type Struct in column 's'");
  c.fields = {field("b", 4, fb::TableBuilder{})};
  EXPECT_EQ(featherErrorOf(c.bytes()), "unsupported type Binary in column 'b'");
  c.fields = {field("i", 2, fb::TableBuilder{}.scalar<int32_t>(0, 12))};
  EXPECT_EQ(featherErrorOf(c.bytes()), "unsupported Int bit width 12 in column 'i'");
  c.fields = {int32Field("a").table(4, fb::TableBuilder{}.scalar<int64_t>(0, 0))};
  EXPECT_EQ(featherErrorOf(c.bytes()), "dictionary-encoded column 'a' is not supported");
  c.fields = {int32Field("a")};
  c.endianness = 1;
  EXPECT_EQ(featherErrorOf(c.bytes()), "big-endian Arrow data is not supported");
}

TEST(FeatherCrafted, MalformedBatchesAreRejected) {
  Crafted c = threeInts();
  c.buffers = {0, 0, 0, 1ll << 62};
  EXPECT_NE(featherErrorOf(c.bytes()).find("buffer 1 (offset 0, length 4611686018427387904) exceeds the body"),
            std::string::npos);
  c = threeInts();
  c.buffers = {0, 0, 8, 8};  // the values buffer is too short for 3 rows
  EXPECT_EQ(featherErrorOf(c.bytes()), "record batch 0: column 'a' values has 8 bytes, needs 12");
  c = threeInts();
  c.nodes = {4, 0};
  EXPECT_EQ(featherErrorOf(c.bytes()), "record batch 0: column 'a' length differs from the batch");
  c = threeInts();
  c.nodes = {3, 1};  // a null count without a validity bitmap
  EXPECT_EQ(featherErrorOf(c.bytes()), "record batch 0: column 'a' validity has 0 bytes, needs 1");
  c = threeInts();
  c.nodes = {3, 1};
  c.body.insert(c.body.begin(), 8, 0);  // bitmap byte 0x00: three nulls, not one
  c.buffers = {0, 1, 8, 12};
  EXPECT_EQ(featherErrorOf(c.bytes()), "record batch 0: column 'a' validity bitmap disagrees with null count 1");
  c = threeInts();
  c.buffers = {0, 0, 0, 12, 0, 0};
  EXPECT_EQ(featherErrorOf(c.bytes()), "record batch 0: 3 buffers, schema needs 2");
  c = threeInts();
  c.rows = 1ll << 39;  // no allocation may follow from the row count alone
  c.nodes = {1ll << 39, 0};
  EXPECT_NE(featherErrorOf(c.bytes()).find("values has 12 bytes, needs 2199023255552"), std::string::npos);
  c.rows = c.nodes[0] = 1ll << 62;
  EXPECT_NE(featherErrorOf(c.bytes()).find("implausible length"), std::string::npos);
}

TEST(FeatherCrafted, StringOffsetsAreChecked) {
  Crafted c;
  c.fields = {field("s", 5, fb::TableBuilder{})};
  c.rows = 2;
  c.nodes = {2, 0};
  c.buffers = {0, 0, 0, 12, 16, 3};
  auto withOffsets = [&](int32_t a, int32_t b, int32_t d) {
    c.body.clear();
    for (int32_t o : {a, b, d}) put(c.body, o);
    c.body.resize(16, 0);
    c.body.insert(c.body.end(), {'a', 'b', 'c', 0, 0, 0, 0, 0});
    return c.bytes();
  };
  const Table ok = parseFeather(withOffsets(0, 1, 3), "ok");
  EXPECT_EQ(ok.column("s").stringAt(1), "bc");
  EXPECT_EQ(parseFeather(withOffsets(1, 1, 3), "rebased").column("s").stringAt(1), "bc");
  EXPECT_EQ(featherErrorOf(withOffsets(0, 2, 1)), "record batch 0: column 's' offsets decrease at row 1");
  EXPECT_EQ(featherErrorOf(withOffsets(-1, 2, 3)), "record batch 0: column 's' has a negative first offset");
  EXPECT_EQ(featherErrorOf(withOffsets(0, 1, 4)), "record batch 0: column 's' string data has 3 bytes, needs 4");
}

// A crafted batch whose single int32 buffer [1, 2, 3] is stored behind a compression prefix.
Crafted compressedInts(int8_t codec, int64_t declared, std::vector<uint8_t> payload) {
  Crafted c;
  c.codec = codec;
  c.rows = 3;
  c.nodes = {3, 0};
  put(c.body, declared);
  c.body.insert(c.body.end(), payload.begin(), payload.end());
  c.buffers = {0, 0, 0, int64_t(c.body.size())};
  c.body.resize((c.body.size() + 7) / 8 * 8, 0);
  return c;
}

std::vector<uint8_t> threeIntBytes() {
  std::vector<uint8_t> b;
  for (int32_t v : {1, 2, 3}) put(b, v);
  return b;
}

// The compressed payload for [1, 2, 3] as this library's writer produces it.
std::vector<uint8_t> compressedPayload(Compression compression) {
  Table t;
  t.numRows = 3;
  const std::vector<int32_t> v = {1, 2, 3};
  t.columns.push_back(Column::fromValues<int32_t>("a", Type::Int32, v));
  const std::vector<uint8_t> file = serializeFeather(t, compression);
  const ByteView all(file, "t");
  const size_t footerStart = file.size() - 10 - size_t(all.read<int32_t>(file.size() - 10));
  const ByteView footerBytes = all.sub(footerStart, file.size() - 10 - footerStart, "footer");
  const fb::Vector blocks = fb::Table::root(footerBytes, "footer").vector(3, 24);
  const size_t offset = size_t(blocks.read<int64_t>(0, 0)), meta = size_t(blocks.read<int32_t>(0, 8));
  const ByteView msgBytes = all.sub(offset + 8, meta - 8, "message");
  const fb::Vector buffers = fb::Table::root(msgBytes, "message").table(2, "rb")->vector(2, 16);
  const size_t start = offset + meta + size_t(buffers.read<int64_t>(1, 0));
  return std::vector<uint8_t>(file.begin() + ptrdiff_t(start) + 8,
                              file.begin() + ptrdiff_t(start + size_t(buffers.read<int64_t>(1, 8))));
}

TEST(FeatherCrafted, CompressedBuffersMustDecompressToTheirDeclaredLength) {
  for (auto [codec, compression] : {std::pair{int8_t(0), Compression::Lz4Frame}, {int8_t(1), Compression::Zstd}}) {
    const std::vector<uint8_t> payload = compressedPayload(compression);
    EXPECT_EQ(parseFeather(compressedInts(codec, 12, payload).bytes(), "ok").column("a").as<int32_t>()[2], 3);
    // LZ4 finds out while decompressing; ZSTD frames carry their content size, so the bound catches it.
    EXPECT_EQ(featherErrorOf(compressedInts(codec, 16, payload).bytes()),
              codec == 0 ? "record batch 0: column 'a' values: LZ4 frame decompressed to 12 bytes, header says 16"
                         : "record batch 0: column 'a' values: declared uncompressed length 16 exceeds the 12 bytes "
                           "its ZSTD frame can hold");
    EXPECT_NE(featherErrorOf(compressedInts(codec, 8, payload).bytes()).find("declared uncompressed length 8, needs 12"),
              std::string::npos);
    EXPECT_NE(featherErrorOf(compressedInts(codec, 1ll << 50, payload).bytes()).find("can hold"),
              std::string::npos);
    std::vector<uint8_t> cut(payload.begin(), payload.end() - 3);
    EXPECT_NE(featherErrorOf(compressedInts(codec, 12, cut).bytes()), "no error");
    std::vector<uint8_t> garbage = payload;
    for (size_t i = 4; i < garbage.size(); ++i) garbage[i] ^= 0x5A;
    EXPECT_NE(featherErrorOf(compressedInts(codec, 12, garbage).bytes()), "no error");
  }
  // -1: the data follows uncompressed.
  EXPECT_EQ(parseFeather(compressedInts(0, -1, threeIntBytes()).bytes(), "raw").column("a").as<int32_t>()[1], 2);
  Crafted shortPrefix = compressedInts(0, 12, {});
  shortPrefix.buffers = {0, 0, 0, 5};
  EXPECT_NE(featherErrorOf(shortPrefix.bytes()).find("shorter than its 8-byte length prefix"), std::string::npos);
}

// --- corruption of real and written files ------------------------------------------------------

// Parses `bytes`: an Error is fine, success is fine (then the table must be usable);
// anything else (another exception, a crash, a sanitizer report) fails.
bool parsesOrThrowsError(const std::vector<uint8_t>& bytes) {
  try {
    const Table t = parseFeather(bytes, "corrupt.feather");
    for (const Column& c : t.columns) {
      EXPECT_EQ(c.length, t.numRows);
      (void)c.nullCount();
      if (c.type == Type::Utf8) {
        for (int64_t i = 0; i < c.length; ++i) (void)c.stringAt(i);
      } else {
        (void)c.toDouble();
      }
    }
    return true;
  } catch (const Error&) {
    return false;
  }
}

std::vector<std::vector<uint8_t>> corruptionInputs() {
  std::vector<std::vector<uint8_t>> files;
  const Table t = syntheticTable();
  for (Compression c : {Compression::None, Compression::Lz4Frame, Compression::Zstd}) {
    files.push_back(serializeFeather(t, c, 10));
  }
  files.push_back(readFileBytes(test::sharedLog() / kCalibration));
  return files;
}

TEST(FeatherCorrupt, BadMagic) {
  std::vector<uint8_t> f = serializeFeather(syntheticTable());
  std::vector<uint8_t> bad = f;
  bad[0] = 'X';
  EXPECT_EQ(featherErrorOf(bad), "bad magic: not an Arrow IPC file");
  EXPECT_EQ(featherErrorOf({}), "bad magic: not an Arrow IPC file");
  std::memcpy(bad.data(), "FEA1", 4);
  EXPECT_NE(featherErrorOf(bad).find("feather v1"), std::string::npos);
  bad = f;
  bad.back() = 'X';
  EXPECT_EQ(featherErrorOf(bad), "truncated: no ARROW1 magic at the end of the file");
}

TEST(FeatherCorrupt, EveryTruncationThrows) {
  for (const std::vector<uint8_t>& f : corruptionInputs()) {
    for (size_t n = 0; n < f.size(); ++n) {
      std::vector<uint8_t> cut(f.begin(), f.begin() + ptrdiff_t(n));
      EXPECT_FALSE(parsesOrThrowsError(cut)) << n;
      // Keep a valid-looking trailer so that the footer parser sees shifted garbage.
      if (n >= 10) {
        cut.insert(cut.end(), f.end() - 10, f.end());
        parsesOrThrowsError(cut);
      }
    }
  }
}

TEST(FeatherCorrupt, FooterLengthFlips) {
  const std::vector<uint8_t> f = serializeFeather(syntheticTable());
  const size_t at = f.size() - 10;
  for (int bit = 0; bit < 32; ++bit) {
    std::vector<uint8_t> bad = f;
    bad[at + size_t(bit / 8)] ^= uint8_t(1u << (bit % 8));
    EXPECT_FALSE(parsesOrThrowsError(bad)) << bit;
  }
  std::vector<uint8_t> huge = f;
  const int32_t big = 1 << 30;
  std::memcpy(huge.data() + at, &big, 4);
  EXPECT_EQ(featherErrorOf(huge), "truncated: footer length 1073741824 exceeds file size " + std::to_string(f.size()));
}

TEST(FeatherCorrupt, EverySingleByteChangeIsHandled) {
  for (const std::vector<uint8_t>& f : corruptionInputs()) {
    for (size_t i = 0; i < f.size(); ++i) {
      for (uint8_t x : {uint8_t(0x01), uint8_t(0xFF)}) {
        std::vector<uint8_t> bad = f;
        bad[i] ^= x;
        parsesOrThrowsError(bad);
      }
    }
  }
}

TEST(FeatherCorrupt, RandomMultiByteMutationsAreHandled) {
  std::mt19937 rng(12345);
  const std::vector<std::vector<uint8_t>> files = corruptionInputs();
  for (int iteration = 0; iteration < 4000; ++iteration) {
    std::vector<uint8_t> bad = files[size_t(iteration) % files.size()];
    const int edits = 1 + int(rng() % 6);
    for (int e = 0; e < edits; ++e) {
      const size_t at = rng() % bad.size();
      switch (rng() % 3) {
        case 0: bad[at] = uint8_t(rng()); break;
        case 1: bad[at] = 0xFF; break;
        default: {  // an interesting 32-bit value (offsets, lengths)
          const uint32_t values[] = {0, 1, 0x7FFFFFFF, 0x80000000u, 0xFFFFFFFFu, 8, 24};
          const uint32_t v = values[rng() % 7];
          if (at + 4 <= bad.size()) std::memcpy(bad.data() + at, &v, 4);
        }
      }
    }
    parsesOrThrowsError(bad);
  }
}

}  // namespace
}  // namespace hdprior::arrow
