#include "kiosk/kiosk_light_probe.h"

#include <sstream>

#include "kiosk/kiosk_config_error.h"
#include "camera/camera_probe_plugin.h"
#include "probe/mock_probe_source.h"

namespace weft {

KioskLightProbe::KioskLightProbe(const std::string& spec, double switch_s, SgLighting stored,
                                 LightProbeUpdater::Log log) {
  LightProbeConfig config;
  config.min_update_interval_s = 0.25;  // the room changes slowly; leave the CPU to the frames
  std::unique_ptr<LightProbeSource> source;
  if (spec.rfind("mock:", 0) == 0) {
    std::stringstream list(spec.substr(5));
    for (std::string file; std::getline(list, file, ',');) {
      try {
        maps_.push_back(load_env_map(file, NonFinitePolicy::clamp));
      } catch (const EnvMapError& e) {
        throw KioskConfigError(std::string("--probe mock: ") + e.what());
      }
    }
    if (maps_.empty()) throw KioskConfigError("--probe mock: needs at least one EXR map, e.g. mock:studio.exr");
    if (maps_.size() > 1 && !(switch_s > 0)) throw KioskConfigError("--probe-switch: must be > 0 seconds with several maps");
    MockCameraOptions mock;
    mock.ball = config.ball;
    mock.calibration = config.calibration;
    mock.name = spec.substr(5);
    auto m = std::make_unique<MockProbeSource>(maps_.front(), mock);
    mock_ = m.get();
    source = std::move(m);
  } else if (spec == "camera" || spec.rfind("camera:", 0) == 0) {
    LibcameraOptions lc;
    if (spec.size() > 7) lc.camera_id = spec.substr(7);
    config.ball = MirrorBall{lc.width / 2.0, lc.height / 2.0, 0.95 * lc.height / 2.0};
    source = CameraProbePlugin::installed().open(lc);  // CameraPluginError: the caller runs without a probe
  } else {
    throw KioskConfigError("--probe: expected none, camera[:ID] or mock:MAP.exr[,MAP.exr...], got '" + spec + "'");
  }
  probe_ = std::make_unique<LightProbe>(std::move(source), config, std::move(stored), std::move(log));
  probe_->start();
  if (maps_.size() > 1) switcher_ = std::thread([this, switch_s] { switch_scenes(switch_s); });
}

KioskLightProbe::~KioskLightProbe() {
  {
    std::lock_guard lock(m_);
    stopping_ = true;
  }
  cv_.notify_all();
  if (switcher_.joinable()) switcher_.join();
  probe_->stop();
}

void KioskLightProbe::switch_scenes(double switch_s) {
  std::unique_lock lock(m_);
  for (size_t next = 1;; next = (next + 1) % maps_.size()) {
    if (cv_.wait_for(lock, std::chrono::duration<double>(switch_s), [this] { return stopping_; })) return;
    mock_->set_map(maps_[next]);  // the mock is thread-safe; the worker sees it on its next capture
    ++switches_;
  }
}

}  // namespace weft
