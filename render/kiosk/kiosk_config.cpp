#include "kiosk/kiosk_config.h"

#include <cctype>
#include <cmath>
#include <stdexcept>

#include "gpu/display_choice.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/screen_schedule.h"
#include "kiosk/weave_terms_governor.h"
#include "label/label_overlay.h"
#include "methods/registry.h"

namespace weft {

namespace {

void check_screen_config(const KioskConfig& c) {
  try {
    gpu::parse_mode_request(c.mode);
  } catch (const std::invalid_argument& e) {
    throw KioskConfigError(std::string("--mode: ") + e.what());
  }
  if (c.rotation != 0 && c.rotation != 90 && c.rotation != 180 && c.rotation != 270)
    throw KioskConfigError("--rotation: degrees clockwise, 0, 90, 180 or 270, got " + std::to_string(c.rotation));
  if (!(c.display_wait_s >= 0.0 && c.display_wait_s <= 86400.0))
    throw KioskConfigError("--display-wait: seconds in [0, 86400] (0: never report a missing screen)");
  for (const char ch : c.connector)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_')
      throw KioskConfigError("--connector: a connector name such as HDMI-A-1 or DP-2 (letters, digits, '-'), got '" +
                             c.connector + "'");
}

}  // namespace

void check_kiosk_config(const KioskConfig& c) {
  if (c.display != "auto" && c.display != "kms" && c.display != "headless")
    throw KioskConfigError("--display: expected auto, kms or headless, got '" + c.display + "'");
  if (c.size.size() != 2 || c.size[0] < 8 || c.size[1] < 8 || c.size[0] > 8192 || c.size[1] > 8192)
    throw KioskConfigError("--width/--height: expected a frame size in [8, 8192]");
  if (!std::isfinite(c.exposure_bias) || std::abs(c.exposure_bias) > 20)
    throw KioskConfigError("--exposure-bias: EV in [-20, 20]");
  if (!(c.exposure > 0.0) || !std::isfinite(c.exposure))
    throw KioskConfigError("--exposure: a multiplier > 0 on the metered exposure (1: none; --exposure-bias takes EV)");
  if (!std::isfinite(c.turntable) || std::abs(c.turntable) > 360)
    throw KioskConfigError("--turntable: degrees per second in [-360, 360]");
  if (!(c.zoom >= 0.0 && c.zoom <= 1.0)) throw KioskConfigError("--zoom: the way to the close-up, in [0, 1]");
  if (c.vertex_refresh < 1 || c.vertex_refresh > 64)
    throw KioskConfigError("--vertex-refresh: frames over which every vertex is recomputed once, in [1, 64]");
  if (!(c.idle_return_s >= 0.0 && c.idle_return_s <= 7.0 * 86400.0))
    throw KioskConfigError("--idle-return: seconds without a knob change before the look eases back, in [0, 604800] (0: never)");
  try {
    ScreenSchedule::parse(c.screen_off);
  } catch (const std::invalid_argument& e) {
    throw KioskConfigError(std::string("--screen-off: ") + e.what());
  }
  if (!(c.vertex_refresh_deg >= 0.0 && c.vertex_refresh_deg <= 90.0))
    throw KioskConfigError("--vertex-refresh-deg: degrees of turn over which every vertex is recomputed once, in [0, 90]");
  if (!(c.broad_lobe_refresh_deg >= 0.0 && c.broad_lobe_refresh_deg <= 90.0))
    throw KioskConfigError("--broad-lobe-refresh-deg: degrees of turn over which the broad lobes' quadrature is recomputed once, in [0, 90]");
  if (!WeaveTermsGovernor::parse(c.weave_terms))
    throw KioskConfigError("--weave-terms: expected auto, pixel or table, got '" + c.weave_terms + "'");
  if (!(c.weave_budget_ms >= 1.0 && c.weave_budget_ms <= 10000.0))
    throw KioskConfigError("--weave-budget: milliseconds a frame in [1, 10000]");
  if (c.profile != "off" && c.profile != "auto" && c.profile != "gpu" && c.profile != "cpu")
    throw KioskConfigError("--profile: expected off, auto, gpu or cpu, got '" + c.profile + "'");
  if (c.label != "on" && c.label != "off") throw KioskConfigError("--label: expected on or off, got '" + c.label + "'");
  if (!label::parse_corner(c.label_position))
    throw KioskConfigError(std::string("--label-position: expected ") + label::corner_names() + ", got '" + c.label_position + "'");
  if (c.label_size < 8 || c.label_size > 256) throw KioskConfigError("--label-size: pixels in [8, 256], got " + std::to_string(c.label_size));
  if (!(c.label_idle_s >= 0.0 && c.label_idle_s <= 86400.0))
    throw KioskConfigError("--label-idle: seconds in [0, 86400] (0: never fades)");
  check_screen_config(c);
  if (c.method != "auto") try {
      methods::method(c.method);
    } catch (const std::invalid_argument& e) {
      throw KioskConfigError(std::string("--method: ") + e.what() + " or auto");
    }
}

}  // namespace weft
