#pragma once
// The camera light probe's backend is a plugin, libweft-probe-libcamera.so in the package
// weft-probe-camera, loaded (dlopen) only when a camera probe is configured: a kiosk without a
// camera needs neither the plugin nor libcamera. Without the plugin the camera probe is
// unavailable with an error that names the package to install; nothing else changes.
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera/libcamera_options.h"
#include "camera/light_probe_source.h"

namespace weft {

struct CameraProbePluginApi;

inline constexpr const char* kCameraProbePackage = "weft-probe-camera";
inline constexpr const char* kCameraProbePluginFile = "libweft-probe-libcamera.so";

// The plugin is missing, cannot be loaded (its libcamera missing) or is not this kiosk's build.
// what() says which, names the file, and ends with what to install.
class CameraPluginError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class CameraProbePlugin {
public:
  // Loads the plugin from `file`; throws CameraPluginError.
  explicit CameraProbePlugin(const std::filesystem::path& file);

  // The plugin where the running program's package puts it: <libdir>/weft beside the prefix of
  // this executable's folder (installed), else this executable's own folder (the build tree).
  // Loaded once per process; throws CameraPluginError.
  static const CameraProbePlugin& installed();

  // A libcamera light-probe source (LightProbeSource's failures: absent, busy, ...).
  std::unique_ptr<LightProbeSource> open(const LibcameraOptions& options) const;
  // The ids of the cameras libcamera sees now.
  std::vector<std::string> list_cameras() const;
  const std::filesystem::path& file() const { return file_; }

private:
  std::filesystem::path file_;
  const CameraProbePluginApi* api_ = nullptr;
};

}  // namespace weft
