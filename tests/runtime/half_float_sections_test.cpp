// The bundle's binary16 float sections (runtime/half_float_sections.h): values come back within
// binary16's rounding (half a unit in the 11th significant bit: 2⁻¹¹ relative, 2⁻²⁵ absolute
// among the subnormals), the section is half the bytes of f32, a value beyond ±65504 or a
// non-finite one keeps the whole section f32 exactly, and an f32 section (older bundles) reads
// as it is.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "runtime/half_float_sections.h"

using namespace weft;

namespace {

bundle::BundleReader round_trip(const std::vector<float>& values, std::vector<std::byte>& bytes) {
  bundle::BundleWriter w;
  add_halves_or_floats(w, "t", values, {values.size()});
  w.add_array<float>("f", std::span<const float>(values));
  bytes = w.to_bytes();
  return bundle::BundleReader::view(bytes, "test");
}

}  // namespace

TEST(HalfFloatSections, ValuesComeBackWithinBinary16Rounding) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> mantissa(-1.0f, 1.0f);
  std::uniform_int_distribution<int> exponent(-30, 15);
  std::vector<float> v;
  for (int i = 0; i < 20000; ++i) v.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  v.push_back(0.0f), v.push_back(65504.0f), v.push_back(-65504.0f);
  std::vector<std::byte> bytes;
  const auto r = round_trip(v, bytes);
  EXPECT_EQ(r.section("t").type, bundle::ElementType::F16);
  EXPECT_EQ(r.section("t").size, 2 * v.size());
  const std::vector<float> got = read_halves_or_floats(r, "t");
  ASSERT_EQ(got.size(), v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    const double bound = std::max(std::abs(double(v[i])) * std::ldexp(1.0, -11), std::ldexp(1.0, -25));
    ASSERT_LE(std::abs(double(got[i]) - v[i]), bound * 1.0001) << "value " << v[i];
  }
}

TEST(HalfFloatSections, OutOfRangeOrNonFiniteKeepsFloats) {
  for (float odd : {70000.0f, -1e9f, std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
    const std::vector<float> v{0.25f, odd, 1.0f / 3.0f};
    std::vector<std::byte> bytes;
    const auto r = round_trip(v, bytes);
    EXPECT_EQ(r.section("t").type, bundle::ElementType::F32) << odd;
    const std::vector<float> got = read_halves_or_floats(r, "t");
    EXPECT_EQ(got[0], 0.25f);
    EXPECT_EQ(got[2], 1.0f / 3.0f);  // exactly: nothing rounded
  }
}

TEST(HalfFloatSections, FloatSectionsReadAsTheyAre) {
  const std::vector<float> v{1.0f / 3.0f, -7.5e-9f};
  std::vector<std::byte> bytes;
  const auto r = round_trip(v, bytes);
  EXPECT_EQ(read_halves_or_floats(r, "f"), v);
  EXPECT_THROW(read_halves_or_floats(r, "absent"), bundle::BundleError);
}
