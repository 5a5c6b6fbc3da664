#include "camera/camera_probe_plugin.h"

#include <dlfcn.h>

#include <mutex>
#include <optional>

#include "camera/camera_probe_plugin_abi.h"

namespace weft {

namespace {

std::string install_hint() { return std::string("; install the ") + kCameraProbePackage + " package"; }

std::vector<std::filesystem::path> plugin_candidates() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const std::filesystem::path dir = self.parent_path();
  return {(dir / WEFT_PLUGIN_FROM_BINDIR / kCameraProbePluginFile).lexically_normal(), dir / kCameraProbePluginFile};
}

}  // namespace

CameraProbePlugin::CameraProbePlugin(const std::filesystem::path& file) : file_(file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw CameraPluginError("the camera light probe's plugin " + file.string() + " is not installed" + install_hint());
  // RTLD_LOCAL: the plugin's symbols (its libcamera, its copies of shared code) stay its own.
  // Never dlclose()d: sources it made may live until the process ends.
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    throw CameraPluginError("cannot load the camera light probe's plugin " + file.string() + ": " + (why ? why : "unknown error") +
                            "; reinstall the " + kCameraProbePackage + " package (it brings libcamera)");
  }
  auto entry = reinterpret_cast<CameraProbePluginEntry>(::dlsym(handle, kCameraProbePluginEntry));
  const CameraProbePluginApi* api = entry ? entry() : nullptr;
  if (!api) throw CameraPluginError(file.string() + " is not a weft camera probe plugin (no " + kCameraProbePluginEntry + ")" + install_hint());
  if (std::string(api->version) != WEFT_VERSION)
    throw CameraPluginError("the camera light probe's plugin " + file.string() + " is version " + api->version + ", this weft is " +
                            WEFT_VERSION + install_hint() + " of the same version as weft");
  api_ = api;
}

const CameraProbePlugin& CameraProbePlugin::installed() {
  // Loaded once; a failure is remembered too (the files do not change under a running kiosk).
  static std::once_flag once;
  static std::optional<CameraProbePlugin> plugin;
  static std::string failure;
  std::call_once(once, [] {
    const auto candidates = plugin_candidates();
    if (candidates.empty()) {
      failure = std::string("cannot find the camera light probe's plugin: /proc/self/exe unreadable") + install_hint();
      return;
    }
    std::error_code ec;
    for (const auto& c : candidates)
      if (std::filesystem::exists(c, ec)) {
        try {
          plugin.emplace(c);
        } catch (const CameraPluginError& e) {
          failure = e.what();
        }
        return;
      }
    failure = "the camera light probe's plugin " + candidates.front().string() + " is not installed" + install_hint();
  });
  if (!plugin) throw CameraPluginError(failure);
  return *plugin;
}

std::unique_ptr<LightProbeSource> CameraProbePlugin::open(const LibcameraOptions& options) const { return api_->open(options); }

std::vector<std::string> CameraProbePlugin::list_cameras() const { return api_->list_cameras(); }

}  // namespace weft
