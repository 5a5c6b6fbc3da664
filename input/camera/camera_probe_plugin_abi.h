#pragma once
// The one entry point of the camera probe plugin (libweft-probe-libcamera.so): the kiosk
// dlopen()s the plugin and calls kCameraProbePluginEntry to get this table. C++ types cross
// the boundary, so kiosk and plugin must come from the same build: `version` is checked
// against the kiosk's before anything else is used (the packages also pin equal versions).
#include <memory>
#include <string>
#include <vector>

#include "camera/libcamera_options.h"
#include "camera/light_probe_source.h"

namespace weft {

struct CameraProbePluginApi {
  const char* version;  // the WEFT_VERSION the plugin was built with
  std::unique_ptr<LightProbeSource> (*open)(const LibcameraOptions& options);
  std::vector<std::string> (*list_cameras)();
};

inline constexpr const char* kCameraProbePluginEntry = "weft_camera_probe_plugin";
using CameraProbePluginEntry = const CameraProbePluginApi* (*)();

}  // namespace weft
