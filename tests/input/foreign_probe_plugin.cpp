// Stand-ins for a plugin the kiosk must refuse (camera_probe_plugin_test.cpp): built with
// FOREIGN_VERSION, a camera probe plugin of another weft version; without it, a shared
// object that has no plugin entry point at all.
#include "camera/camera_probe_plugin_abi.h"

#ifdef FOREIGN_VERSION
namespace {
const weft::CameraProbePluginApi kApi{FOREIGN_VERSION, nullptr, nullptr};
}
extern "C" __attribute__((visibility("default"))) const weft::CameraProbePluginApi* weft_camera_probe_plugin() { return &kApi; }
#else
extern "C" __attribute__((visibility("default"))) int weft_not_a_plugin() { return 1; }
#endif
