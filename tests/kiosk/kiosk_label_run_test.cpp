// `weft run --label` headless through the real GLES path (llvmpipe): the screenshot (what the
// screen shows) has white text at FreeType's coverage over the dark plate in the label's corner
// box, and is the unlabelled frame everywhere else; a label fully faded leaves the frame as it
// was, and once faded the loop draws nothing; a missing font is one warning and no label; bad
// label settings are bad usage naming the flag.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "label/label_overlay.h"
#include "label/label_text.h"
#include "support/file_text.h"
#include "support/png_pixels.h"

namespace fs = std::filesystem;

namespace weft {
namespace {

using test::read_all;
using test::read_png_rgb;

constexpr int kW = 320, kH = 240, kSize = 16;

class KioskLabelRun : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("weft_label_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    ASSERT_EQ(weft({"bake", "--scene", "pillow", "--fabric", "linen_plain", "--no-tables", "--out", (dir_ / "pillow.weft").string()}, "bake"), 0)
        << read_all(dir_ / "bake.log");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  // Runs the weft binary; stdout and stderr go to DIR/NAME.log. Returns the exit status.
  static int weft(const std::vector<std::string>& args, const std::string& name) {
    std::string cmd = WEFT_BINARY;
    for (const auto& a : args) cmd += " '" + a + "'";
    cmd += " >'" + (dir_ / (name + ".log")).string() + "' 2>&1";
    const int rc = std::system(cmd.c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  }
  // weft run headless, still, no panel, screenshot DIR/NAME.png.
  static int run(const std::string& name, const std::vector<std::string>& label_args, const std::string& frames = "2") {
    std::vector<std::string> args{"run", "--bundle", (dir_ / "pillow.weft").string(), "--state-dir", (dir_ / ("st_" + name)).string(),
                                  "--display", "headless", "--frames", frames, "--turntable", "0", "--panel", "none",
                                  "--width", std::to_string(kW), "--height", std::to_string(kH), "--stats-every", "0",
                                  "--screenshot", (dir_ / (name + ".png")).string(), "--label-size", std::to_string(kSize)};
    args.insert(args.end(), label_args.begin(), label_args.end());
    return weft(args, name);
  }
  static std::string log(const std::string& name) { return read_all(dir_ / (name + ".log")); }
  static long frames_drawn(const std::string& log) {
    const size_t at = log.find(" frames drawn");
    if (at == std::string::npos) return -1;
    const size_t from = log.rfind(", ", at);
    return std::stol(log.substr(from + 2, at - from - 2));
  }
  static fs::path dir_;
};
fs::path KioskLabelRun::dir_;

TEST_F(KioskLabelRun, TheFabricsNameInItsCornerOverTheFrameAndNothingElseChanges) {
  ASSERT_EQ(run("off", {"--label", "off"}), 0) << log("off");
  ASSERT_EQ(run("on", {"--label", "on", "--label-idle", "0"}), 0) << log("on");
  const test::PngPixels off = read_png_rgb(dir_ / "off.png"), on = read_png_rgb(dir_ / "on.png");
  ASSERT_EQ(off.width, kW);
  ASSERT_EQ(on.width, kW);
  // The label the kiosk draws for linen_plain, rasterised here by the same library.
  const label::LabelFont title(label::kDefaultFontFile, kSize), detail(label::kDefaultFontFile, 11);
  const label::CoverageImage img = label::rasterise_lines({{"Linen, plain weave", &title}, {"100 % linen", &detail}}, 5);
  const label::Box box = label::place_box(label::Corner::bottom_left, kSize, kW, kH, img.width, img.height);
  const int top = kH - box.y - box.height;  // the box's first row in the picture (row 0 at the top)
  int outside_changed = 0, inside_off = 0, white = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const int ix = x - box.x, iy = y - top;
      const bool inside = ix >= 0 && iy >= 0 && ix < box.width && iy < box.height;
      for (int c = 0; c < 3; ++c) {
        if (!inside) {
          outside_changed += on.at(x, y)[c] != off.at(x, y)[c];
          continue;
        }
        // Premultiplied white at coverage k over the plate (black, alpha 0.55), over the frame.
        const double k = img.at(ix, iy) / 255.0;
        const double want = 255.0 * k + off.at(x, y)[c] * (1.0 - (k + 0.55 * (1.0 - k)));
        inside_off += std::abs(on.at(x, y)[c] - want) > 2.0;
      }
      white += inside && on.at(x, y)[0] >= 250 && on.at(x, y)[1] >= 250 && on.at(x, y)[2] >= 250;
    }
  EXPECT_EQ(outside_changed, 0);
  EXPECT_EQ(inside_off, 0);
  EXPECT_GT(white, 60);  // the glyphs' cores: legible white text
}

TEST_F(KioskLabelRun, AFadedLabelLeavesTheFrameAsItWasAndDrawsNothingOnceFaded) {
  ASSERT_EQ(run("plain", {}), 0) << log("plain");  // off by default in `weft run`
  EXPECT_EQ(frames_drawn(log("plain")), 1) << log("plain");
  // Shown for 0.05 s, faded over the next second; 150 ticks are 2.5 s at 60 Hz.
  ASSERT_EQ(run("faded", {"--label", "on", "--label-idle", "0.05"}, "150"), 0) << log("faded");
  EXPECT_EQ(read_all(dir_ / "faded.png"), read_all(dir_ / "plain.png"));
  const long drawn = frames_drawn(log("faded"));
  EXPECT_GT(drawn, 10) << log("faded");   // the fade presented frame after frame
  EXPECT_LT(drawn, 150 - 40) << log("faded");  // and then nothing
}

TEST_F(KioskLabelRun, AMissingFontIsOneWarningAndNoLabel) {
  ASSERT_EQ(run("plain_nofont", {}), 0);
  ASSERT_EQ(run("nofont", {"--label", "on", "--label-font", "/nonexistent/Font.ttf"}), 0) << log("nofont");
  const std::string l = log("nofont");
  const std::string warning = "weft run: label off: font /nonexistent/Font.ttf: no such file";
  const size_t at = l.find(warning);
  ASSERT_NE(at, std::string::npos) << l;
  EXPECT_EQ(l.find("label off", at + warning.size()), std::string::npos) << l;  // once
  EXPECT_EQ(read_all(dir_ / "nofont.png"), read_all(dir_ / "plain_nofont.png"));
}

TEST_F(KioskLabelRun, BadLabelSettingsAreBadUsageNamingTheFlag) {
  for (const auto& [flag, value] : std::vector<std::pair<std::string, std::string>>{
           {"--label", "yes"}, {"--label-position", "middle"}, {"--label-size", "2"}, {"--label-idle", "-1"}}) {
    EXPECT_EQ(run("bad", {flag, value}), 2) << flag << " " << value << "\n" << log("bad");
    EXPECT_NE(log("bad").find(flag + ":"), std::string::npos) << log("bad");
  }
}

}  // namespace
}  // namespace weft
