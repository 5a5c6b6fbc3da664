// Kiosk boot: a bad bundle falls back to the last good one and says why; a good one becomes the
// last good copy, replaced atomically and only when it changed (docs/design.md §5).
#include <gtest/gtest.h>

#include <fstream>

#include "bundle/bundle_fallback.h"
#include "bundle/bundle_writer.h"

namespace wb = weft::bundle;
namespace fs = std::filesystem;

namespace {

class Fallback : public ::testing::Test {
protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("weft_fallback_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
    primary_ = root_ / "scene.weftbundle";
    state_ = root_ / "state";  // does not exist yet: created on the first good boot
    options_.log = [this](weft::LogPriority, const std::string& line) { log_.emplace_back(line); };
  }
  void TearDown() override { fs::remove_all(root_); }

  static std::vector<std::byte> scene(float marker) {
    wb::BundleWriter w;
    const std::vector<float> v{marker, 2.f, 3.f};
    w.add_array<float>("mesh.positions", v, {1, 3});
    w.add_json("fabric", R"({"name":"linen_plain"})");
    return w.to_bytes();
  }
  void write_primary(const std::vector<std::byte>& bytes) {
    std::ofstream(primary_, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  }
  float marker(const wb::OpenedBundle& b) { return b.bundle.array<float>("mesh.positions")[0]; }
  bool logged(const std::string& needle) const {
    for (const auto& l : log_)
      if (l.find(needle) != std::string::npos) return true;
    return false;
  }

  fs::path root_, primary_, state_;
  wb::FallbackOptions options_;
  std::vector<std::string> log_;
};

}  // namespace

TEST_F(Fallback, AGoodBundleIsUsedAndSavedAsLastGood) {
  write_primary(scene(1.f));
  const auto b = wb::open_bundle_with_fallback(primary_, state_, options_);
  EXPECT_FALSE(b.is_last_good);
  EXPECT_EQ(b.file, primary_);
  EXPECT_EQ(marker(b), 1.f);
  ASSERT_TRUE(fs::exists(wb::last_good_path(state_)));
  EXPECT_EQ(wb::BundleReader::open(wb::last_good_path(state_)).array<float>("mesh.positions")[0], 1.f);
  EXPECT_TRUE(logged("saved as the last good bundle"));
  // Nothing but the copy is left in the directory (no temporaries).
  EXPECT_EQ(std::distance(fs::directory_iterator(state_), fs::directory_iterator()), 1);

  // The same bundle on the next boot is not written again.
  log_.clear();
  const auto again = wb::open_bundle_with_fallback(primary_, state_, options_);
  EXPECT_FALSE(again.is_last_good);
  EXPECT_TRUE(log_.empty());
}

TEST_F(Fallback, CorruptTruncatedWrongVersionOrMissingBundlesFallBackAndSayWhy) {
  write_primary(scene(1.f));
  wb::open_bundle_with_fallback(primary_, state_, options_);  // boot 1 saves the last good copy

  const auto good2 = scene(2.f);
  auto corrupt = good2;
  const auto info = wb::BundleReader::view(good2, "x").section("fabric");
  corrupt[info.offset + 2] ^= std::byte{1};
  auto truncated = good2;
  truncated.resize(truncated.size() - 5);
  auto future = good2;
  wb::store_u32(&future[wb::header_at::format_version], 2);

  struct Case { std::string what; std::vector<std::byte> bytes; std::string reason; };
  const std::vector<Case> cases{{"corrupt", corrupt, "section 'fabric': checksum mismatch"},
                                {"truncated", truncated, "section 'fabric': truncated"},
                                {"future version", future, "format version 2"},
                                {"missing", {}, "cannot open"}};
  for (const Case& c : cases) {
    log_.clear();
    fs::remove(primary_);
    if (c.what != "missing") write_primary(c.bytes);
    const auto b = wb::open_bundle_with_fallback(primary_, state_, options_);
    EXPECT_TRUE(b.is_last_good) << c.what;
    EXPECT_EQ(b.file, wb::last_good_path(state_)) << c.what;
    EXPECT_EQ(marker(b), 1.f) << c.what;  // the old scene, not the broken new one
    EXPECT_NE(b.primary_error.find(c.reason), std::string::npos) << c.what << ": " << b.primary_error;
    EXPECT_TRUE(logged(c.reason)) << c.what;
    EXPECT_TRUE(logged("falling back to the last good bundle")) << c.what;
    // The broken bundle never replaces the last good copy.
    EXPECT_EQ(wb::BundleReader::open(wb::last_good_path(state_)).array<float>("mesh.positions")[0], 1.f);
  }
}

TEST_F(Fallback, ANewGoodBundleReplacesTheLastGoodCopy) {
  write_primary(scene(1.f));
  wb::open_bundle_with_fallback(primary_, state_, options_);
  write_primary(scene(7.f));
  const auto b = wb::open_bundle_with_fallback(primary_, state_, options_);
  EXPECT_FALSE(b.is_last_good);
  EXPECT_EQ(marker(b), 7.f);
  EXPECT_EQ(wb::BundleReader::open(wb::last_good_path(state_)).array<float>("mesh.positions")[0], 7.f);
}

TEST_F(Fallback, TheConsumersOwnChecksCanRejectABundle) {
  write_primary(scene(1.f));
  wb::open_bundle_with_fallback(primary_, state_, options_);
  wb::BundleWriter w;  // verifies as a bundle, but lacks what the runtime needs
  w.add_json("fabric", "{}");
  write_primary(w.to_bytes());
  options_.accept = [](const wb::BundleReader& r) { (void)r.section("mesh.positions"); };
  const auto b = wb::open_bundle_with_fallback(primary_, state_, options_);
  EXPECT_TRUE(b.is_last_good);
  EXPECT_NE(b.primary_error.find("section 'mesh.positions': missing"), std::string::npos) << b.primary_error;
  EXPECT_EQ(marker(b), 1.f);
}

TEST_F(Fallback, NoUsableBundleIsAnErrorWithBothReasons) {
  auto bad = scene(1.f);
  bad.resize(100);
  write_primary(bad);
  try {
    wb::open_bundle_with_fallback(primary_, state_, options_);
    FAIL() << "opened something";
  } catch (const wb::BundleError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no usable bundle"), std::string::npos) << what;
    EXPECT_NE(what.find("section table: truncated"), std::string::npos) << what;
    EXPECT_NE(what.find("last good copy"), std::string::npos) << what;
  }
}
