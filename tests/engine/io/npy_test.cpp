#include "engine/io/npy.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.h"
#include "engine/io/file_bytes.h"
#include "engine/io/float16.h"
#include "test_data.h"

namespace hdprior {
namespace {

std::filesystem::path groundHeightFile() {
  return test::sharedLog() / "map" / "7fab2350-7eaf-3b7e-a39d-6937a4c1bede_ground_height_surface____PIT.npy";
}

TEST(Npy, ReadsRealGroundHeightRaster) {
  const NpyArray a = readNpy(groundHeightFile());
  EXPECT_EQ(a.dtype, NpyDtype::Float16);
  ASSERT_EQ(a.shape, (std::vector<size_t>{785, 880}));
  ASSERT_EQ(a.values.size(), 785u * 880u);
  size_t finite = 0;
  for (float v : a.values) finite += std::isfinite(v);
  EXPECT_GT(finite, a.values.size() / 10);  // NaN outside the region of interest, heights inside
  EXPECT_LT(finite, a.values.size());
}

TEST(Npy, RoundTripIsBitIdenticalForFloat16) {
  const std::vector<uint8_t> original = readFileBytes(groundHeightFile());
  const NpyArray a = parseNpy(original, "ground height");
  EXPECT_EQ(serializeNpy(a), original);  // same header layout and padding as numpy
}

TEST(Npy, RoundTripFloat32AndFloat64AndOneDimension) {
  for (NpyDtype dtype : {NpyDtype::Float32, NpyDtype::Float64}) {
    const NpyArray a{dtype, {5}, {1.5f, -2.0f, NAN, 0.0f, 1e-3f}};
    const NpyArray b = parseNpy(serializeNpy(a), "mem");
    EXPECT_EQ(b.shape, a.shape);
    for (size_t i = 0; i < a.values.size(); ++i) {
      if (std::isnan(a.values[i])) EXPECT_TRUE(std::isnan(b.values[i]));
      else EXPECT_EQ(b.values[i], a.values[i]);
    }
  }
}

TEST(Npy, RejectsMalformedInputWithError) {
  const std::vector<uint8_t> good = readFileBytes(groundHeightFile());
  for (size_t len : {size_t(0), size_t(5), size_t(9), size_t(50), size_t(127), good.size() - 1}) {
    EXPECT_THROW(parseNpy(std::span(good).first(len), "t.npy"), Error) << "length " << len;
  }
  std::vector<uint8_t> bad = good;
  bad[0] = 'X';
  EXPECT_THROW(parseNpy(bad, "t.npy"), Error);
  const auto withHeaderEdit = [&](const std::string& from, const std::string& to) {
    std::string text(good.begin(), good.end());
    const size_t at = text.find(from);
    EXPECT_LT(at, 128u);
    text.replace(at, from.size(), to);
    return std::vector<uint8_t>(text.begin(), text.end());
  };
  EXPECT_THROW(parseNpy(withHeaderEdit("<f2", "<i2"), "t.npy"), Error);     // int16 is not supported
  EXPECT_THROW(parseNpy(withHeaderEdit("False", "True "), "t.npy"), Error);  // Fortran order
  EXPECT_THROW(parseNpy(withHeaderEdit("(785, 880)", "(785, 881)"), "t.npy"), Error);  // size mismatch
  EXPECT_THROW(parseNpy(withHeaderEdit("'shape'", "'shap_'"), "t.npy"), Error);
  // A shape that is no tuple (found by fuzz.npy: it threw std::out_of_range, not Error).
  EXPECT_THROW(parseNpy(withHeaderEdit("(785, 880)", ",785, 880)"), "t.npy"), Error);
  EXPECT_THROW(parseNpy(withHeaderEdit("(785, 880)", "7       ,  "), "t.npy"), Error);
  try {
    parseNpy(std::span(good).first(1000), "where.npy");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "where.npy");
    EXPECT_NE(e.reason().find("truncated"), std::string::npos) << e.reason();
  }
}

TEST(Float16, EveryHalfRoundTripsThroughFloat) {
  for (uint32_t h = 0; h < 0x10000; ++h) {
    const float f = halfToFloat(uint16_t(h));
    if (std::isnan(f)) {
      EXPECT_TRUE(std::isnan(halfToFloat(floatToHalf(f))));
    } else {
      EXPECT_EQ(floatToHalf(f), uint16_t(h)) << std::hex << h;
    }
  }
  EXPECT_EQ(halfToFloat(floatToHalf(-1.537109375f)), -1.537109375f);
  EXPECT_EQ(floatToHalf(65520.0f), 0x7c00);  // rounds to infinity
  EXPECT_EQ(halfToFloat(floatToHalf(1.0f + 1.0f / 4096)), 1.0f);  // ties to even
}

}  // namespace
}  // namespace hdprior
