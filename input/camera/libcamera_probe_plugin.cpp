// The camera probe plugin's entry point (camera_probe_plugin_abi.h): the libcamera backend
// behind the table the kiosk looks up by name. Everything else in the plugin stays hidden
// (-fvisibility=hidden), so its copies of shared code cannot clash with the kiosk's.
#include "camera/camera_probe_plugin_abi.h"
#include "camera/libcamera_probe_source.h"

namespace {

std::unique_ptr<weft::LightProbeSource> open_source(const weft::LibcameraOptions& options) {
  return std::make_unique<weft::LibcameraProbeSource>(options);
}

const weft::CameraProbePluginApi kApi{WEFT_VERSION, open_source, weft::LibcameraProbeSource::list_cameras};

}  // namespace

extern "C" __attribute__((visibility("default"))) const weft::CameraProbePluginApi* weft_camera_probe_plugin() {
  return &kApi;
}
