#pragma once
// The real light-probe camera through libcamera (0.0.3, Debian 12): one still stream in 8-bit
// RGB (the ISP's output, its tone curve being the response the HDR merge inverts), auto
// exposure off, ExposureTime and AnalogueGain set per request, frames read from mmapped
// buffers when requestCompleted fires. libcamera headers stay inside the .cpp.
//
// Failures map onto ProbeError: no camera or not the configured one -> absent; acquire()
// answering EBUSY -> busy; a rejected configuration -> config; the camera's disconnected
// signal or a cancelled request -> disconnected; no completed request within `timeout` ->
// timeout. The exposure the frame really had comes from the request's metadata: sensors apply
// new controls a few frames late, so frames whose metadata differs from the request by more
// than 5 % are retaken (a few times) and the reported values are what the merge uses.
//
// Built only into the plugin libweft-probe-libcamera.so (package weft-probe-camera), which the
// kiosk loads when a camera probe is configured (camera_probe_plugin.h): the kiosk's own binary
// never links libcamera.
#include <memory>
#include <string>
#include <vector>

#include "camera/libcamera_options.h"
#include "camera/light_probe_source.h"

namespace weft {

class LibcameraProbeSource : public LightProbeSource {
public:
  explicit LibcameraProbeSource(LibcameraOptions options = {});
  ~LibcameraProbeSource() override;

  std::string name() const override;
  void open() override;
  void close() override;
  ProbeFrame capture(const ProbeExposure& exposure) override;

  // The ids of the cameras libcamera sees now (empty on a machine without one).
  static std::vector<std::string> list_cameras();

private:
  struct State;
  LibcameraOptions options_;
  std::unique_ptr<State> state_;
};

}  // namespace weft
