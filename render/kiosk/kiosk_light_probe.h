#pragma once
// The kiosk's optional light probe (`weft run --probe ...`): the room's light, fitted to SGs on
// the probe's own thread and picked up by the frame loop without waiting (docs/design.md §5).
//   none               the bundle's stored SGs only
//   camera[:ID]        libcamera (first camera, or the one with this id), through the plugin of
//                      package weft-probe-camera; camera absent: stored SGs stay
//   mock:A.exr[,B.exr] a simulated mirror-ball camera in map A; with several maps it switches to
//                      the next every `switch_s` seconds (a lamp going on and off), for soak tests
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "probe/light_probe_pipeline.h"

namespace weft {

class MockProbeSource;

class KioskLightProbe {
public:
  // Throws KioskConfigError for a malformed spec or an unreadable mock map, CameraPluginError
  // for a camera probe whose plugin (package weft-probe-camera) is not installed or not loadable.
  KioskLightProbe(const std::string& spec, double switch_s, SgLighting stored, LightProbeUpdater::Log log);
  ~KioskLightProbe();
  KioskLightProbe(const KioskLightProbe&) = delete;
  KioskLightProbe& operator=(const KioskLightProbe&) = delete;

  // Render thread, once per tick: never blocks. True when newer SGs arrived.
  bool acquire() { return probe_->acquire(); }
  const SgLighting& lighting() const { return probe_->lighting(); }
  uint64_t updates() const { return probe_->updates(); }
  uint64_t scene_switches() const { return switches_.load(); }

private:
  void switch_scenes(double switch_s);

  std::vector<EnvMap> maps_;
  MockProbeSource* mock_ = nullptr;  // owned by probe_
  std::unique_ptr<LightProbe> probe_;
  std::thread switcher_;
  std::mutex m_;
  std::condition_variable cv_;
  bool stopping_ = false;
  std::atomic<uint64_t> switches_{0};
};

}  // namespace weft
