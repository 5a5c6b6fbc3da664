// InputHash against FNV-1a 64 of the length-prefixed bytes (the length as 8 little-endian
// bytes, then the bytes), the expected values computed independently (Python, from the FNV
// reference's offset basis and prime; its published vector: FNV-1a 64("a") = af63dc4c8601ec8c).
#include <gtest/gtest.h>

#include "core/input_hash.h"

using weft::InputHash;

TEST(InputHash, NothingAddedIsTheOffsetBasis) {
  EXPECT_EQ(InputHash().hex(), "cbf29ce484222325");
  EXPECT_EQ(InputHash().value(), 0xcbf29ce484222325ull);
}

TEST(InputHash, LengthPrefixedFnv1a) {
  EXPECT_EQ(InputHash().add("a").hex(), "529a4ddc8ff56bbf");
  EXPECT_EQ(InputHash().add_number(0.5).hex(), "6e5ca7d3d603be23");  // "0.5"
  EXPECT_EQ(InputHash().add_integer(7).hex(), "a32078ded8da480a");
}

TEST(InputHash, BoundariesCount) {
  EXPECT_EQ(InputHash().add("ab").add("c").hex(), "7e60470bf599cad6");
  EXPECT_EQ(InputHash().add("a").add("bc").hex(), "ba1e1f0e0704d8ea");
}
