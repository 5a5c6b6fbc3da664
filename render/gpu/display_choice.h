#pragma once
// Which screen the kiosk shows on, decided from what a DRM card lists: the connector (the one
// named by --connector, else the first connected one) and its mode (--mode WxH[@R], else the
// preferred one). Plain data in, a choice out: no device is touched here (kms_display.h lists
// the card's connectors and applies the choice).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace weft::gpu {

struct DrmMode {
  int width = 0, height = 0;
  int refresh_hz = 0;
  bool preferred = false;  // the monitor's own choice (its EDID)
};

struct DrmConnectorInfo {
  std::uint32_t id = 0;  // the KMS object id
  std::string name;      // "HDMI-A-1", as the kernel and xrandr spell it
  bool connected = false;
  std::vector<DrmMode> modes;  // empty while disconnected
};

// "HDMI-A-1" from a DRM connector type and its number on the card.
std::string connector_name(std::uint32_t type, std::uint32_t type_id);

// A --mode value: empty or "preferred" (the monitor's preferred mode), "WxH" or "WxH@R" (R in Hz).
struct ModeRequest {
  int width = 0, height = 0;  // 0: the preferred mode
  int refresh_hz = 0;         // 0: any
  bool preferred() const { return width == 0; }
};
// Throws std::invalid_argument saying what a mode looks like.
ModeRequest parse_mode_request(const std::string& text);
std::string mode_text(const DrmMode& m);  // "1920x1080@60"

// The connector to show on: `wanted` by name (empty: the first connected one with a mode).
// nullopt when that connector is not connected (or, unnamed, none is).
std::optional<std::size_t> choose_connector(const std::vector<DrmConnectorInfo>& connectors, const std::string& wanted);
bool has_connector(const std::vector<DrmConnectorInfo>& connectors, const std::string& name);
// "HDMI-A-1 (connected), DP-1 (disconnected)"; "none" for an empty list.
std::string connector_list(const std::vector<DrmConnectorInfo>& connectors);

struct ModeChoice {
  std::size_t index = 0;  // into the connector's modes
  std::string note;       // why the request was not followed to the letter; empty when it was
};
// The request's size at its refresh (else that size's preferred or fastest mode); a size the
// connector does not list falls back to the preferred mode with a note naming the modes there are.
// Throws std::invalid_argument for an empty mode list.
ModeChoice choose_mode(const std::vector<DrmMode>& modes, const ModeRequest& request);

// The frame the kiosk renders for a mode shown at `rotation_deg` (0, 90, 180, 270): the mode's
// size, its sides swapped for a quarter turn.
struct FrameSize {
  int width = 0, height = 0;
};
FrameSize rotated_size(int width, int height, int rotation_deg);

}  // namespace weft::gpu
