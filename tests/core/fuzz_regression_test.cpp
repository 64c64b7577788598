// Inputs the fuzz targets (tests/fuzz) found to break a property, kept as regression tests.
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"

namespace armmimic {
namespace {

// fuzz_profile: a profile with a joint speed of 1.03e117 did not read back from FormatProfile,
// because FormatNumber wrote the number into a 64-byte buffer, which to_chars could not fill
// and which was then returned as it was (uninitialised bytes).
TEST(FuzzRegression, FormatNumberWritesHugeValuesInFull) {
  const double big = 1.0333333333e117;
  const std::string s = FormatNumber(big, 1);
  ASSERT_EQ(s.size(), 118u + 2u);  // 118 digits, ".0"
  EXPECT_EQ(s.substr(s.size() - 2), ".0");
  EXPECT_EQ(std::strtod(s.c_str(), nullptr), big);
  EXPECT_EQ(FormatNumber(-1.7976931348623157e308, 3).size(), 1u + 309u + 4u);
}

}  // namespace
}  // namespace armmimic
