#include "engine/io/arrow_table.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.h"
#include "engine/io/float16.h"

namespace hdprior::arrow {
namespace {

template <class T>
Column makeColumn(const char* name, Type type, std::vector<T> values) {
  return Column::fromValues<T>(name, type, std::span<const T>(values));
}

// A column of `n` int32 rows (value = row) where rows divisible by `nullEvery` are null.
Column withNulls(int64_t n, int64_t nullEvery) {
  std::vector<int32_t> v(static_cast<size_t>(n));
  for (int64_t i = 0; i < n; ++i) v[size_t(i)] = int32_t(i);
  Column c = makeColumn("a", Type::Int32, v);
  c.nullable = true;
  c.validity.assign(size_t((n + 7) / 8), 0);
  for (int64_t i = 0; i < n; ++i) {
    if (i % nullEvery != 0) c.validity[size_t(i / 8)] |= uint8_t(1u << (i % 8));
  }
  return c;
}

TEST(ArrowTable, TypedAccessChecksTheType) {
  const Column c = makeColumn<float>("f", Type::Float32, {1.5f, -2.f});
  ASSERT_EQ(c.as<float>().size(), 2u);
  EXPECT_EQ(c.as<float>()[1], -2.f);
  EXPECT_THROW(c.as<double>(), Error);
  EXPECT_THROW(c.as<int32_t>(), Error);
  EXPECT_THROW(makeColumn<double>("d", Type::Float32, {1.0}), Error);

  const Column h = makeColumn<uint16_t>("h", Type::Float16, {floatToHalf(0.5f), floatToHalf(-3.f)});
  EXPECT_EQ(h.as<uint16_t>().size(), 2u);  // float16 is exposed as raw bits
  EXPECT_EQ(h.toDouble(), (std::vector<double>{0.5, -3.0}));
}

TEST(ArrowTable, ToDoubleWidensEveryNumericTypeAndMapsNullsToNaN) {
  EXPECT_EQ(makeColumn<int8_t>("a", Type::Int8, {-128, 127}).toDouble(), (std::vector<double>{-128, 127}));
  EXPECT_EQ(makeColumn<uint64_t>("a", Type::UInt64, {1ull << 40}).toDouble(), (std::vector<double>{std::ldexp(1.0, 40)}));
  EXPECT_EQ(makeColumn<int64_t>("a", Type::Int64, {-5}).toDouble(), (std::vector<double>{-5}));
  const std::vector<double> d = withNulls(10, 3).toDouble();
  for (int i = 0; i < 10; ++i) {
    if (i % 3 == 0) {
      EXPECT_TRUE(std::isnan(d[size_t(i)])) << i;
    } else {
      EXPECT_EQ(d[size_t(i)], i);
    }
  }
  EXPECT_THROW(Column::fromStrings("s", std::vector<std::string>{"x"}).toDouble(), Error);
}

TEST(ArrowTable, ValidityAndNullCount) {
  const Column c = withNulls(19, 4);  // rows 0, 4, 8, 12, 16 are null
  EXPECT_EQ(c.nullCount(), 5);
  EXPECT_FALSE(c.isValid(0));
  EXPECT_TRUE(c.isValid(1));
  EXPECT_FALSE(c.isValid(16));
  EXPECT_THROW(c.isValid(19), Error);
  EXPECT_THROW(c.isValid(-1), Error);
  EXPECT_EQ(makeColumn<int32_t>("a", Type::Int32, {1, 2}).nullCount(), 0);
}

TEST(ArrowTable, StringsRoundTripThroughTheBuilder) {
  const std::vector<std::string> s = {"up_lidar", "", "down_lidar", "ü"};
  const Column c = Column::fromStrings("sensor_name", s);
  ASSERT_EQ(c.length, 4);
  for (size_t i = 0; i < s.size(); ++i) EXPECT_EQ(c.stringAt(int64_t(i)), s[i]);
  EXPECT_THROW(c.stringAt(4), Error);
  EXPECT_THROW(makeColumn<int32_t>("a", Type::Int32, {1}).stringAt(0), Error);
}

TEST(ArrowTable, ColumnLookupErrorsNameTheColumnAndTheSource) {
  Table t;
  t.columns.push_back(makeColumn<float>("x", Type::Float32, {1.f}));
  t.numRows = 1;
  EXPECT_TRUE(t.has("x"));
  EXPECT_FALSE(t.has("y"));
  EXPECT_EQ(&t.column("x"), &t.columns[0]);
  try {
    t.column("y", "poses.feather");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "poses.feather");
    EXPECT_EQ(e.reason(), "missing column 'y'");
  }
  try {
    t.column("x", Type::Float64, "poses.feather");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.reason(), "column 'x' has type float32, expected float64");
  }
}

TEST(ArrowTable, SliceAndAppendRepackValidityBits) {
  const Column full = withNulls(37, 3);
  for (int64_t step : {1, 3, 7, 8, 13, 37}) {
    Column joined;
    for (int64_t start = 0; start < full.length; start += step) {
      const Column part = full.slice(start, std::min(step, full.length - start));
      if (start == 0) {
        joined = part;
      } else {
        joined.append(part);
      }
    }
    EXPECT_EQ(joined.length, full.length) << step;
    EXPECT_EQ(joined.values, full.values) << step;
    EXPECT_EQ(joined.validity, full.validity) << step;
  }
  // A slice without nulls drops its bitmap; appending it back materialises ones.
  EXPECT_TRUE(full.slice(1, 2).validity.empty());
  Column a = full.slice(1, 2);
  a.append(full.slice(3, 1));
  EXPECT_EQ(a.nullCount(), 1);
  EXPECT_TRUE(a.isValid(0));
  EXPECT_FALSE(a.isValid(2));
  EXPECT_THROW(full.slice(30, 8), Error);
  EXPECT_THROW(a.append(makeColumn<float>("f", Type::Float32, {1.f})), Error);
}

TEST(ArrowTable, SliceAndAppendStrings) {
  const std::vector<std::string> s = {"a", "bb", "", "ccc", "d"};
  const Column c = Column::fromStrings("s", s);
  Column joined = c.slice(0, 2);
  joined.append(c.slice(2, 0));
  joined.append(c.slice(2, 3));
  EXPECT_EQ(joined.offsets, c.offsets);
  EXPECT_EQ(joined.values, c.values);
  const Column tail = c.slice(3, 2);
  EXPECT_EQ(tail.offsets, (std::vector<int32_t>{0, 3, 4}));
  EXPECT_EQ(tail.stringAt(0), "ccc");
}

}  // namespace
}  // namespace hdprior::arrow
