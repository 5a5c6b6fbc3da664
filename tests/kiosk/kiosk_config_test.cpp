// The kiosk's frame settings are checked before anything starts, each refusal naming its flag:
// the per-stage profile's clock, the per-vertex passes' reuse, the label's settings, the screen.
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

TEST(KioskConfig, WeaveTermsAndBudgetNameTheirFlag) {
  for (const char* terms : {"auto", "pixel", "table"}) EXPECT_EQ(error([&](KioskConfig& c) { c.weave_terms = terms; }), "") << terms;
  EXPECT_EQ(error([](KioskConfig& c) { c.weave_terms = "vertex"; }).rfind("--weave-terms:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.weave_budget_ms = 16.7; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.weave_budget_ms = 0.0; }).rfind("--weave-budget:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.weave_budget_ms = std::numeric_limits<double>::quiet_NaN(); }).rfind("--weave-budget:", 0), 0u);
}

TEST(KioskConfig, ProfileAndVertexRefreshNameTheirFlag) {
  for (const char* clock : {"off", "auto", "gpu", "cpu"}) EXPECT_EQ(error([&](KioskConfig& c) { c.profile = clock; }), "") << clock;
  EXPECT_EQ(error([](KioskConfig& c) { c.profile = "fast"; }).rfind("--profile:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh = 1; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh = 64; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh = 0; }).rfind("--vertex-refresh:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh = 65; }).rfind("--vertex-refresh:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh_deg = 0; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh_deg = 91; }).rfind("--vertex-refresh-deg:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.vertex_refresh_deg = std::numeric_limits<double>::infinity(); }).rfind("--vertex-refresh-deg:", 0), 0u);
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

TEST(ScreenSettings, EachRefusalNamesItsFlag) {
  for (int deg : {0, 90, 180, 270}) EXPECT_EQ(error([&](KioskConfig& c) { c.rotation = deg; }), "") << deg;
  for (int deg : {-90, 45, 360}) EXPECT_EQ(error([&](KioskConfig& c) { c.rotation = deg; }).rfind("--rotation:", 0), 0u) << deg;
  for (const char* m : {"", "preferred", "1920x1080", "1080x1920@60"}) EXPECT_EQ(error([&](KioskConfig& c) { c.mode = m; }), "") << m;
  EXPECT_EQ(error([](KioskConfig& c) { c.mode = "1920x1080p"; }).rfind("--mode: expected WIDTHxHEIGHT", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.connector = "HDMI-A-1"; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.connector = "HDMI A 1"; }).rfind("--connector:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.display_wait_s = 0; }), "");
  EXPECT_EQ(error([](KioskConfig& c) { c.display_wait_s = -1; }).rfind("--display-wait:", 0), 0u);
  EXPECT_EQ(error([](KioskConfig& c) { c.display_wait_s = std::numeric_limits<double>::quiet_NaN(); }).rfind("--display-wait:", 0), 0u);
}
