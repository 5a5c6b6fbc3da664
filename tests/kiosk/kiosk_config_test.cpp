// The kiosk's frame settings are checked before anything starts, each refusal naming its flag:
// the per-stage profile's clock, the per-vertex passes' reuse, the label's settings.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "kiosk/kiosk_config.h"
#include "kiosk/kiosk_config_error.h"

using namespace weft;

namespace {
template <class Edit>
std::string error(Edit edit) {
  KioskConfig c;
  c.bundle = "x.weft";
  edit(c);
  try {
    check_kiosk_config(c);
  } catch (const KioskConfigError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(KioskConfig, ProfileAndVertexRefreshNameTheirFlag) {
  for (const char* clock : {"off", "auto", "gpu", "cpu"}) EXPECT_EQ(error([&](KioskConfig& c) { c.profile = clock; }), "") << clock;
  EXPECT_EQ(error([](KioskConfig& c) { c.profile = "fast"; }).rfind("--profile:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh = 1; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh = 64; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh = 0; }).rfind("--vertex-refresh:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh = 65; }).rfind("--vertex-refresh:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.broad_lobe_refresh_deg = 0; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.broad_lobe_refresh_deg = -1; }).rfind("--broad-lobe-refresh-deg:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.broad_lobe_refresh_deg = std::numeric_limits<double>::quiet_NaN(); }).rfind("--broad-lobe-refresh-deg:", 0), 0u);
}

TEST(KioskConfig, LabelSettingsNameTheirFlag) {
  EXPECT_EQ(error([](KioskConfig& c) { c.label = "on"; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.label_idle_s = 0; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.label = "yes"; }).rfind("--label:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.label_position = "middle"; }).rfind("--label-position:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.label_size = 4; }).rfind("--label-size:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.label_size = 1000; }).rfind("--label-size:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.label_idle_s = -1; }).rfind("--label-idle:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.label_idle_s = std::numeric_limits<double>::quiet_NaN(); }).rfind("--label-idle:", 0), 0u);
}
