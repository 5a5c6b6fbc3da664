#pragma once
// The one interface every light-probe camera backend implements: open the camera,
// take one frame at a manual exposure, close. Backends: the real camera through libcamera
// (libcamera_probe_source.h, in a plugin: camera_probe_plugin.h) and a mock that photographs a
// known environment map (mock_probe_source.h). Nothing here blocks the renderer: the probe pipeline calls a source
// only from its own worker thread.
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace weft {

// Why a capture failed; each kind has its own operator-readable line in the log.
enum class ProbeFailure {
  absent,        // no camera (or not the configured one) is connected
  busy,          // another process holds the camera
  disconnected,  // the camera went away mid-capture (unplugged, driver reset)
  timeout,       // the camera did not deliver a frame in time
  bad_frame,     // a frame arrived but cannot be used (black, saturated, wrong size/format)
  config,        // the camera rejected the configuration (size, format, controls)
};
const char* to_string(ProbeFailure failure);

class ProbeError : public std::runtime_error {
public:
  ProbeError(ProbeFailure failure, const std::string& what) : std::runtime_error(what), failure_(failure) {}
  ProbeFailure failure() const { return failure_; }

private:
  ProbeFailure failure_;
};

// Manual exposure for one frame of a bracket (auto exposure off).
struct ProbeExposure {
  double exposure_s = 1.0 / 100.0;  // shutter time
  double analogue_gain = 1.0;
};

// One frame, 8-bit RGB after the camera's processing (its response curve applied), row-major,
// top row first, `stride` bytes per row, channels R,G,B in that order. The exposure fields are
// what the camera reports it actually used (metadata), which the HDR merge trusts over the
// request.
struct ProbeFrame {
  int width = 0;
  int height = 0;
  int stride = 0;
  std::vector<uint8_t> rgb;
  ProbeExposure exposure;
  uint64_t sequence = 0;
  std::chrono::steady_clock::time_point captured;

  const uint8_t* pixel(int x, int y) const { return rgb.data() + static_cast<size_t>(y) * stride + 3 * x; }
};

class LightProbeSource {
public:
  virtual ~LightProbeSource() = default;
  // What the log calls this camera ("libcamera /base/soc/i2c0mux/...", "mock studio.exr").
  virtual std::string name() const = 0;
  // Opens and configures the camera; throws ProbeError (absent, busy, config). Idempotent.
  virtual void open() = 0;
  // Releases the camera; never throws. Safe when not open.
  virtual void close() = 0;
  // One frame at `exposure`; throws ProbeError (disconnected, timeout, bad_frame).
  virtual ProbeFrame capture(const ProbeExposure& exposure) = 0;
};

}  // namespace weft
