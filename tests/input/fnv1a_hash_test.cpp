// FNV-1a 64 against independent values: the raw hash against the FNV reference's published
// vectors (FNV-1a 64 of "" = cbf29ce484222325, "a" = af63dc4c8601ec8c, "foobar" = 85944171f73967e8);
// InputHash against FNV-1a 64 of the length-prefixed bytes (the length as 8 little-endian bytes,
// then the bytes), computed in Python from the reference's offset basis and prime.
#include <gtest/gtest.h>

#include "hashing/fnv1a_hash.h"

using weft::fnv1a64_hex;
using weft::InputHash;

TEST(Fnv1a64, PublishedVectors) {
  EXPECT_EQ(fnv1a64_hex(""), "cbf29ce484222325");
  EXPECT_EQ(fnv1a64_hex("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(fnv1a64_hex("foobar"), "85944171f73967e8");
}

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
