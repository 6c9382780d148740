#include <gtest/gtest.h>

#include "antumbra/gpu/hash.hpp"

namespace antumbra::gpu {
namespace {

TEST(Fnv1a64, MatchesReferenceVectors) {
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
  static_assert(fnv1a64("a") == 0xaf63dc4c8601ec8cull);
}

TEST(Fnv1a64, FieldsAreLengthPrefixed) {
  const auto ab_c = Fnv1a64{}.field("ab").field("c").value();
  const auto a_bc = Fnv1a64{}.field("a").field("bc").value();
  EXPECT_NE(ab_c, a_bc);
}

TEST(ToHex, SixteenDigits) {
  EXPECT_EQ(to_hex(0), "0000000000000000");
  EXPECT_EQ(to_hex(0xcbf29ce484222325ull), "cbf29ce484222325");
}

}  // namespace
}  // namespace antumbra::gpu
