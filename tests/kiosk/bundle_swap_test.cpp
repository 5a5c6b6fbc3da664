// Content updates alone (kiosk/bundle_swap.h), on a headless GL context: a corrupt file renamed
// over the bundle is refused (nothing handed over, no last good copy written), the content shown
// is skipped, and another good bundle is handed over built and lit, then saved as the last good copy.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "bundle/bundle_fallback.h"
#include "bundle/bundle_reader.h"
#include "gpu/egl_context.h"
#include "kiosk/bundle_swap.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

fs::path bake(const fs::path& dir, const std::string& scene, const std::string& fabric) {
  const fs::path out = dir / (scene + ".weft");
  const std::string cmd = std::string(WEFT_BINARY) + " bake --scene " + scene + " --fabric " + fabric +
                          " --no-tables --out " + out.string() + " >" + (dir / "bake.log").string() + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return out;
}

std::vector<char> bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `bytes` written beside `target`, then renamed over it, as an update tool does.
void replace(const fs::path& target, const std::vector<char>& bytes) {
  const fs::path tmp = target.parent_path() / ".incoming";
  std::ofstream(tmp, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  fs::rename(tmp, target);
}

// Polls (as the frame loop does, every few ms) until `done` holds for a step or the outcome; at
// most a minute, so a swap that never comes fails the test instead of hanging it.
BundleSwap::Step poll_until(BundleSwap& swap, const BundleSwap::Shown& shown,
                            const std::function<bool(const BundleSwap::Step&)>& done) {
  for (int i = 0; i < 6000; ++i) {
    BundleSwap::Step step = swap.poll(shown);
    if (done(step)) return step;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ADD_FAILURE() << "no such step within a minute";
  return {};
}

TEST(BundleSwap, RefusesACorruptFileSkipsTheContentShownAndHandsOverAGoodOne) {
  const fs::path dir = fs::temp_directory_path() / ("weft_bundle_swap_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "live");
  const fs::path pillow = bake(dir, "pillow", "linen_plain"), swatch = bake(dir, "swatch", "silk_shot");
  const fs::path live = dir / "live" / "showroom.weft", state = dir / "state";
  fs::copy_file(pillow, live);

  gpu::EglContext ctx = gpu::EglContext::headless();
  {
    BundleSwap swap({live.string(), "auto", state.string()});
    swap.set_shown_fingerprint(bundle_fingerprint(bundle::BundleReader::read(live)));
    const std::string scene = "pillow";
    const BundleSwap::Shown shown{scene, live, nullptr, 0.0f, 7};

    std::vector<char> corrupt = bytes_of(pillow);
    corrupt[corrupt.size() / 2] ^= 0x5a;  // inside a section: its checksum fails
    replace(live, corrupt);
    BundleSwap::Step step = poll_until(swap, shown, [](const BundleSwap::Step& s) { return s.refused || s.ready; });
    EXPECT_TRUE(step.refused);
    EXPECT_FALSE(step.ready);
    EXPECT_EQ(swap.last_outcome().result.rfind("refused: ", 0), 0u) << swap.last_outcome().result;

    replace(live, bytes_of(pillow));  // the content shown
    poll_until(swap, shown, [&](const BundleSwap::Step& s) {
      EXPECT_FALSE(s.ready);
      return swap.last_outcome().result == "unchanged";
    });

    replace(live, bytes_of(swatch));
    step = poll_until(swap, shown, [](const BundleSwap::Step& s) { return s.ready.has_value(); });
    ASSERT_TRUE(step.ready);
    EXPECT_EQ(step.ready->bundle.scene.scene.name, "swatch");
    EXPECT_EQ(step.ready->method->name, "sgpoint");
    EXPECT_NE(step.ready->renderer, nullptr);
    EXPECT_EQ(step.ready->cloth_fabrics.size(), 1u);
    EXPECT_EQ(step.ready->light_version, 7u);
    EXPECT_EQ(step.ready->room_light.size(), step.ready->bundle.scene.sgs.size());  // no probe: its own SGs
    swap.log_shown(step.ready->bundle.scene, step.ready->method->name);
    EXPECT_EQ(swap.last_outcome().result, "shown");
  }  // waits for the last good copy to be written
  EXPECT_EQ(bundle_fingerprint(bundle::BundleReader::read(bundle::last_good_path(state))),
            bundle_fingerprint(bundle::BundleReader::read(swatch)));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace weft
