#pragma once
// Content updates: a replaced bundle file shown without a restart, the scene shown kept until then.
//
//   BundleWatcher reports a settled change → a worker reads and verifies the file (kiosk_bundle.h;
//   content equal to what is shown is skipped) → poll() builds its SceneRenderer on the calling
//   (render) thread, whose GL context it needs → a thread prepares its lighting → poll() hands the
//   lit bundle over, and a thread saves it as the last good copy.
//
// A file that does not verify, or that cannot be drawn or lit, is refused with an error line naming
// the file and why; the scene shown stays.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/fabric.h"
#include "core/spherical_gaussian.h"
#include "gpu/scene_renderer.h"
#include "kiosk/bundle_watcher.h"
#include "kiosk/kiosk_bundle.h"
#include "kiosk/latest_request_worker.h"

namespace weft {

class BundleSwap {
public:
  using Clock = std::chrono::steady_clock;

  struct Options {
    std::string bundle;     // the file watched
    std::string method;     // --method: auto or a registry name
    std::string state_dir;  // where the bundle swapped in is saved as the last good copy; empty: not saved
  };

  // What the kiosk shows, for a poll: named in refusals, and how a new scene is lit.
  struct Shown {
    const std::string& scene;
    const std::filesystem::path& file;
    const SgLighting* room_light;  // the probe's fit, which outlives the bundle; null: the new bundle's own SGs
    float light_rotation_deg;      // the environment knob
    std::uint64_t light_version;   // changes whenever the kiosk relights
  };

  // A bundle verified, its renderer built and lit: ready to be swapped in.
  struct Ready {
    KioskBundle bundle;
    const methods::RuntimeMethod* method = nullptr;
    std::vector<Fabric> cloth_fabrics;  // the fabric of each cloth object
    SgLighting room_light;              // the light it was lit by, before the environment knob's turn
    std::uint64_t light_version = 0;    // Shown::light_version when its lighting was asked for
    std::unique_ptr<gpu::SceneRenderer> renderer;
  };

  struct Step {
    std::optional<Ready> ready;
    bool refused = false;  // a new file did not verify this step
  };

  // The latest update's outcome.
  struct Outcome {
    std::chrono::system_clock::time_point when{};  // epoch: no update yet
    std::string result;  // "shown", "unchanged" or "refused: REASON"
  };

  // Starts watching the bundle's directory (logged); throws std::system_error when it cannot.
  explicit BundleSwap(Options options);
  ~BundleSwap();
  BundleSwap(const BundleSwap&) = delete;
  BundleSwap& operator=(const BundleSwap&) = delete;

  // The content shown at boot (0: none, as for a last good copy, so the fixed primary is shown).
  void set_shown_fingerprint(std::uint64_t f) { shown_fingerprint_ = f; }

  // One step of the update under way, never blocking; call it every tick from the render thread.
  Step poll(const Shown& shown);

  // The bundle handed over by poll() has been drawn: logs how long after its change.
  void log_shown(const SceneBundle& scene, const std::string& method);

  const Outcome& last_outcome() const { return outcome_; }

private:
  struct Loaded;
  struct Pending;
  void start(Loaded loaded, const Shown& shown);
  std::optional<Ready> finish(const Shown& shown);
  void refuse(const std::string& why, const Shown& shown);

  Options options_;
  std::atomic<std::uint64_t> shown_fingerprint_{0};
  std::unique_ptr<BundleWatcher> watcher_;
  std::unique_ptr<LatestRequestWorker<BundleWatcher::Change, Loaded>> loader_;
  std::unique_ptr<Pending> pending_;
  std::optional<BundleWatcher::Change> swapped_;  // the change handed over, until its frame is drawn
  std::future<void> saving_;                      // the last good copy of the bundle swapped in
  double read_ms_ = 0, gpu_ms_ = 0, light_ms_ = 0;
  Outcome outcome_;
};

}  // namespace weft
