// The bench's ladder (render/bench/ladder.h), read off the registry: every runtime method once, in
// the registry's order, and the thin-layer reference and the see-through scene the see-through methods'.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "bench/ladder.h"
#include "methods/registry.h"

using namespace weft;

TEST(Ladder, ListsRuntimeMethodsOnce) {
  std::set<std::string> seen;
  for (const auto& e : bench::ladder()) {
    EXPECT_NE(methods::find_method(e.name), nullptr) << e.name;
    EXPECT_TRUE(seen.insert(e.name).second) << e.name;
  }
}

TEST(Ladder, IsTheRegistryInItsOrder) {
  const auto& l = bench::ladder();
  const auto& r = methods::registry();
  ASSERT_EQ(l.size(), r.size());
  for (size_t i = 0; i < l.size(); ++i) {
    EXPECT_EQ(l[i].name, r[i].name);
    EXPECT_EQ(l[i].scenes.empty(), !r[i].see_through) << r[i].name;
  }
}

TEST(Ladder, ThinReferenceIsTheSeeThroughMethods) {
  for (const auto& m : methods::registry()) EXPECT_EQ(bench::thin_reference(m.name), m.see_through) << m.name;
}

TEST(Ladder, UnlistedMethodsRunAfterTheLadder) {
  const bench::LadderRun r = bench::select_methods({"sgpoint", "new_rung"}, {});
  ASSERT_EQ(r.run.size(), 2u);
  EXPECT_EQ(r.run[0].name, "sgpoint");
  EXPECT_EQ(r.run[1].name, "new_rung");
  EXPECT_TRUE(r.run[1].scenes.empty());
  EXPECT_FALSE(r.run[1].thin_reference);
}
