// Which connector and mode the kiosk takes, from connector lists as a card reports them (no
// device here): --connector, --mode WxH[@R] and the monitor's preferred mode.
#include <gtest/gtest.h>

#include <xf86drmMode.h>

#include "gpu/display_choice.h"

using namespace weft::gpu;

namespace {

// A desktop card: HDMI with a 4K monitor (preferred 3840x2160@60), DP empty, a second HDMI
// with a 1080p panel that also offers 1080p at 50 and 30 Hz.
std::vector<DrmConnectorInfo> desk() {
  return {
      {31, "HDMI-A-1", true, {{3840, 2160, 60, true}, {1920, 1080, 60, false}, {1920, 1080, 50, false}, {1280, 720, 60, false}}},
      {40, "DP-1", false, {}},
      {47, "HDMI-A-2", true, {{1920, 1080, 30, false}, {1920, 1080, 60, true}, {1920, 1080, 50, false}}},
  };
}

}  // namespace

TEST(DisplayChoice, ConnectorNamesAreTheKernels) {
  EXPECT_EQ(connector_name(DRM_MODE_CONNECTOR_HDMIA, 1), "HDMI-A-1");
  EXPECT_EQ(connector_name(DRM_MODE_CONNECTOR_DisplayPort, 2), "DP-2");
  EXPECT_EQ(connector_name(DRM_MODE_CONNECTOR_eDP, 1), "eDP-1");
  EXPECT_EQ(connector_name(DRM_MODE_CONNECTOR_VIRTUAL, 1), "Virtual-1");
  EXPECT_EQ(connector_name(DRM_MODE_CONNECTOR_DSI, 1), "DSI-1");
}

TEST(DisplayChoice, ModeRequestsParseOrSayWhatAModeIs) {
  EXPECT_TRUE(parse_mode_request("").preferred());
  EXPECT_TRUE(parse_mode_request("preferred").preferred());
  const ModeRequest m = parse_mode_request("1920x1080@50");
  EXPECT_EQ(m.width, 1920);
  EXPECT_EQ(m.height, 1080);
  EXPECT_EQ(m.refresh_hz, 50);
  EXPECT_EQ(parse_mode_request("1080x1920").refresh_hz, 0);
  for (const char* bad : {"1920", "1920x", "x1080", "1920*1080", "1920x1080@", "1920x1080@0", "4x4", "1920x1080 ", "big"}) {
    try {
      parse_mode_request(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}

TEST(DisplayChoice, TheFirstConnectedConnectorUnlessOneIsNamed) {
  const auto list = desk();
  EXPECT_EQ(choose_connector(list, ""), 0u);
  EXPECT_EQ(choose_connector(list, "HDMI-A-2"), 2u);
  EXPECT_EQ(choose_connector(list, "DP-1"), std::nullopt);  // named, there, but nothing plugged in
  EXPECT_EQ(choose_connector(list, "DP-9"), std::nullopt);
  EXPECT_TRUE(has_connector(list, "DP-1"));
  EXPECT_FALSE(has_connector(list, "DP-9"));
  EXPECT_EQ(connector_list(list), "HDMI-A-1 (connected), DP-1 (disconnected), HDMI-A-2 (connected)");
  EXPECT_EQ(connector_list({}), "none");
  // Boot before the screen is powered: nothing connected, nothing chosen; then it is plugged in.
  auto dark = list;
  dark[0].connected = dark[2].connected = false;
  EXPECT_EQ(choose_connector(dark, ""), std::nullopt);
  dark[2].connected = true;
  EXPECT_EQ(choose_connector(dark, ""), 2u);
  // Connected but no mode yet (EDID unread): not a screen to show on.
  dark[2].modes.clear();
  EXPECT_EQ(choose_connector(dark, ""), std::nullopt);
}

TEST(DisplayChoice, ModeIsTheRequestElseThePreferred) {
  const auto list = desk();
  const auto& uhd = list[0].modes;
  const auto& fhd = list[2].modes;
  EXPECT_EQ(choose_mode(uhd, parse_mode_request("")).index, 0u);
  EXPECT_EQ(choose_mode(fhd, parse_mode_request("")).index, 1u);  // the preferred, not the first listed
  EXPECT_EQ(choose_mode(uhd, parse_mode_request("1920x1080@50")).index, 2u);
  EXPECT_EQ(choose_mode(uhd, parse_mode_request("1920x1080")).index, 1u);  // that size's fastest
  EXPECT_EQ(choose_mode(fhd, parse_mode_request("1920x1080")).index, 1u);  // that size's preferred
  EXPECT_EQ(choose_mode(fhd, parse_mode_request("1920x1080@30")).index, 0u);
  EXPECT_TRUE(choose_mode(fhd, parse_mode_request("1920x1080@30")).note.empty());
  // The size without the refresh asked for: the size kept, the refresh said.
  const ModeChoice near = choose_mode(uhd, parse_mode_request("1280x720@50"));
  EXPECT_EQ(near.index, 3u);
  EXPECT_NE(near.note.find("1280x720@50 is not offered; showing 1280x720@60"), std::string::npos) << near.note;
  // A size the monitor does not offer: its preferred mode, the modes there are listed once each.
  const ModeChoice other = choose_mode(fhd, parse_mode_request("1024x768"));
  EXPECT_EQ(other.index, 1u);
  EXPECT_EQ(other.note, "1024x768 is not among the modes offered (1920x1080@30, 1920x1080@60, 1920x1080@50); "
                        "showing the preferred 1920x1080@60");
  // No preferred flag at all: the first listed.
  EXPECT_EQ(choose_mode({{800, 600, 60, false}, {640, 480, 60, false}}, {}).index, 0u);
  EXPECT_THROW(choose_mode({}, {}), std::invalid_argument);
}

TEST(DisplayChoice, AQuarterTurnSwapsTheFramesSides) {
  EXPECT_EQ(rotated_size(1920, 1080, 0).width, 1920);
  EXPECT_EQ(rotated_size(1920, 1080, 90).width, 1080);
  EXPECT_EQ(rotated_size(1920, 1080, 90).height, 1920);
  EXPECT_EQ(rotated_size(1920, 1080, 180).height, 1080);
  EXPECT_EQ(rotated_size(1920, 1080, 270).width, 1080);
}
