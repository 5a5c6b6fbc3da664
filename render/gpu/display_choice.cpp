#include "gpu/display_choice.h"

#include <xf86drmMode.h>

#include <cstdlib>
#include <regex>

namespace weft::gpu {

std::string connector_name(std::uint32_t type, std::uint32_t type_id) {
  // The kernel's own spelling (drm_connector_enum_list), so a name from /sys/class/drm or
  // `modetest` works in --connector.
  const char* name = "Unknown";
  switch (type) {
    case DRM_MODE_CONNECTOR_VGA: name = "VGA"; break;
    case DRM_MODE_CONNECTOR_DVII: name = "DVI-I"; break;
    case DRM_MODE_CONNECTOR_DVID: name = "DVI-D"; break;
    case DRM_MODE_CONNECTOR_DVIA: name = "DVI-A"; break;
    case DRM_MODE_CONNECTOR_Composite: name = "Composite"; break;
    case DRM_MODE_CONNECTOR_SVIDEO: name = "SVIDEO"; break;
    case DRM_MODE_CONNECTOR_LVDS: name = "LVDS"; break;
    case DRM_MODE_CONNECTOR_Component: name = "Component"; break;
    case DRM_MODE_CONNECTOR_9PinDIN: name = "DIN"; break;
    case DRM_MODE_CONNECTOR_DisplayPort: name = "DP"; break;
    case DRM_MODE_CONNECTOR_HDMIA: name = "HDMI-A"; break;
    case DRM_MODE_CONNECTOR_HDMIB: name = "HDMI-B"; break;
    case DRM_MODE_CONNECTOR_TV: name = "TV"; break;
    case DRM_MODE_CONNECTOR_eDP: name = "eDP"; break;
    case DRM_MODE_CONNECTOR_VIRTUAL: name = "Virtual"; break;
    case DRM_MODE_CONNECTOR_DSI: name = "DSI"; break;
    case DRM_MODE_CONNECTOR_DPI: name = "DPI"; break;
    case DRM_MODE_CONNECTOR_WRITEBACK: name = "Writeback"; break;
    default: break;
  }
  return std::string(name) + "-" + std::to_string(type_id);
}

ModeRequest parse_mode_request(const std::string& text) {
  ModeRequest r;
  if (text.empty() || text == "preferred") return r;
  static const std::regex form(R"(([0-9]{1,5})x([0-9]{1,5})(@([0-9]{1,3}))?)");
  std::smatch m;
  if (!std::regex_match(text, m, form))
    throw std::invalid_argument("expected WIDTHxHEIGHT or WIDTHxHEIGHT@HZ (e.g. 1920x1080@60) or preferred, got '" + text + "'");
  r.width = std::atoi(m[1].str().c_str());
  r.height = std::atoi(m[2].str().c_str());
  r.refresh_hz = m[4].matched ? std::atoi(m[4].str().c_str()) : 0;
  if (r.width < 8 || r.height < 8 || r.width > 16384 || r.height > 16384)
    throw std::invalid_argument("mode size out of range [8, 16384]: '" + text + "'");
  if (m[4].matched && (r.refresh_hz < 1 || r.refresh_hz > 500))
    throw std::invalid_argument("refresh out of range [1, 500] Hz: '" + text + "'");
  return r;
}

std::string mode_text(const DrmMode& m) {
  return std::to_string(m.width) + "x" + std::to_string(m.height) + "@" + std::to_string(m.refresh_hz);
}

std::optional<std::size_t> choose_connector(const std::vector<DrmConnectorInfo>& connectors, const std::string& wanted) {
  for (std::size_t i = 0; i < connectors.size(); ++i) {
    const DrmConnectorInfo& c = connectors[i];
    if (!wanted.empty() && c.name != wanted) continue;
    if (c.connected && !c.modes.empty()) return i;
    if (!wanted.empty()) return std::nullopt;
  }
  return std::nullopt;
}

bool has_connector(const std::vector<DrmConnectorInfo>& connectors, const std::string& name) {
  for (const auto& c : connectors)
    if (c.name == name) return true;
  return false;
}

std::string connector_list(const std::vector<DrmConnectorInfo>& connectors) {
  std::string out;
  for (const auto& c : connectors)
    out += (out.empty() ? "" : ", ") + c.name + (c.connected ? " (connected)" : " (disconnected)");
  return out.empty() ? "none" : out;
}

ModeChoice choose_mode(const std::vector<DrmMode>& modes, const ModeRequest& request) {
  if (modes.empty()) throw std::invalid_argument("the connector lists no modes");
  std::size_t preferred = 0;
  for (std::size_t i = 0; i < modes.size(); ++i)
    if (modes[i].preferred) {
      preferred = i;
      break;
    }
  if (request.preferred()) return {preferred, ""};
  // Among the modes of the size asked for: the refresh asked for, else the preferred, else the fastest.
  std::optional<std::size_t> best;
  auto rank = [&](const DrmMode& m) {
    if (request.refresh_hz && m.refresh_hz == request.refresh_hz) return 3;
    return m.preferred ? 2 : 1;
  };
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const DrmMode& m = modes[i];
    if (m.width != request.width || m.height != request.height) continue;
    if (!best || rank(m) > rank(modes[*best]) || (rank(m) == rank(modes[*best]) && m.refresh_hz > modes[*best].refresh_hz))
      best = i;
  }
  const std::string asked = std::to_string(request.width) + "x" + std::to_string(request.height) +
                            (request.refresh_hz ? "@" + std::to_string(request.refresh_hz) : "");
  if (best) {
    if (request.refresh_hz && modes[*best].refresh_hz != request.refresh_hz)
      return {*best, asked + " is not offered; showing " + mode_text(modes[*best])};
    return {*best, ""};
  }
  std::string listed;
  for (const auto& m : modes) {
    const std::string t = mode_text(m);
    if (listed.find(t) == std::string::npos) listed += (listed.empty() ? "" : ", ") + t;
  }
  return {preferred, asked + " is not among the modes offered (" + listed + "); showing the preferred " + mode_text(modes[preferred])};
}

FrameSize rotated_size(int width, int height, int rotation_deg) {
  if (rotation_deg == 90 || rotation_deg == 270) return {height, width};
  return {width, height};
}

}  // namespace weft::gpu
