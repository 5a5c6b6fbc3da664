#pragma once
// The kiosk (`weft run`): one baked scene bundle shown fullscreen (DRM/KMS) or on a headless
// offscreen target, its look turned by the knob panel, its light by an optional camera probe.
//
//   Kiosk kiosk(config);
//   return kiosk.run(stop);   // stop: set by SIGTERM/SIGINT
//
// run() boots, then loops until `stop` is set or `frames` ticks have run:
//   check_config      flag values, the state directory
//   load_bundle       the bundle, or the last good copy (bundle/bundle_fallback.h); the method
//   open_display      KMS, else (display auto) headless
//   start_knobs       knob controller (state restored from STATE_DIR/knobs.json), knob sources
//   start_renderer    scene renderer, offscreen target, tone mapper (KMS)
//   start_probe       the light probe, when asked for
//   show_first_frame  first frame, then READY=1 to systemd
//   listen_to_knobs   the knob sources' threads start
//   tick …            poll knobs and light, redraw if the view, knobs or light changed,
//                     WATCHDOG=1, a stats line every stats_every seconds
//   shut_down         sources stopped, knob state saved, screenshot, the exit line, STOPPING=1
//
// One tick per display refresh: vsync on KMS, a 60 Hz timer headless. Lighting changes after
// the first frame are prepared on a worker thread; the frame keeps its light until they are done.
//
// Test-only fault injection: WEFT_FAULT_HANG_AFTER_TICKS=N makes the loop hang after N ticks (no
// frames, no watchdog pings), as a stuck driver would; the watchdog test uses it.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/iwasaki_bundle.h"
#include "runtime/scene_bundle.h"
#include "bundle/bundle_fallback.h"
#include "core/fabric.h"
#include "gpu/scene_renderer.h"
#include "kiosk/frame_stats.h"
#include "kiosk/latest_request_worker.h"
#include "kiosk/service_notifier.h"
#include "panel/appearance_state.h"
#include "panel/knob_controller.h"
#include "panel/knob_source.h"

namespace weft {

namespace gpu {
class EglContext;
class KmsDisplay;
class OffscreenTarget;
}  // namespace gpu
class KioskLightProbe;

struct KioskConfig {
  std::string bundle;                     // scene bundle (weft bake)
  std::string state_dir = "/var/lib/weft";  // knob state and the last good bundle
  std::string display = "auto";           // auto (KMS, else headless), kms or headless
  long frames = 0;                        // ticks to run; 0 = until stop
  double turntable = 6.0;                 // camera turn, degrees per second about the target's +Z
  // Knob source: hid, gpio, keyboard, sim:SCRIPT or none (kiosk/knob_sources.h); empty: the
  // panel config's "sources" (default hid).
  std::string panel = "hid";
  std::string panel_config;               // JSON: hid ids, gpio lines, sources
  double sim_speed = 1.0;                 // sim: scripts play this many times faster
  std::string screenshot;                 // PNG of the last frame, tone-mapped; empty: none
  std::vector<int> size{640, 480};        // headless frame size
  // auto: iwasaki_vertex when the bundle has seed 000 tables (the same accuracy as per-pixel
  // iwasaki on the showroom meshes at a tenth to a twentieth of the cost; render/methods/iwasaki/IWASAKI.md),
  // or sheer_vertex when a cloth object is a sheer (seed 004's layer over it, see-through), else sgpoint.
  std::string method = "auto";
  double exposure = 1.0;                  // tone mapping
  double stats_every = 300;               // seconds between stats lines; 0: none
  std::string probe = "none";             // none, camera[:ID] or mock:MAP.exr[,MAP.exr...]
  double probe_switch_s = 0;              // mock probe with several maps: seconds between switches
};

class Kiosk {
public:
  explicit Kiosk(KioskConfig config);
  ~Kiosk();
  Kiosk(const Kiosk&) = delete;
  Kiosk& operator=(const Kiosk&) = delete;

  // Returns 0 after a clean stop, 1 when display kms finds no display. Throws KioskConfigError
  // for bad configuration (exit 2), bundle::BundleError when neither the bundle nor its last good
  // copy is usable.
  int run(const std::atomic<bool>& stop);

private:
  using Clock = std::chrono::steady_clock;

  void check_config();
  void load_bundle();
  bool open_display();  // false when display kms has none
  void start_knobs();
  void start_renderer();
  void start_probe();
  void show_first_frame();
  void listen_to_knobs();
  void arm_fault_injection();
  void tick();
  void shut_down();

  // Parts of a tick.
  bool poll_knobs();             // applies a new knob state; true when there was one
  void poll_light();             // the probe's newest fit, handed to the lighting worker
  bool take_prepared_lighting(); // true when the worker's lighting was uploaded
  void apply_knob_state(const input::AppearanceState& state);
  void relight(const SgLighting& sgs);
  void draw_frame(double turn_deg);
  void log_stats(Clock::time_point now);

  KioskConfig config_;
  ServiceNotifier notifier_;
  Clock::time_point boot_;
  bool state_dir_ok_ = true;

  // The bundle.
  std::optional<bundle::OpenedBundle> opened_;
  std::optional<SceneBundle> scene_;
  std::shared_ptr<const IwasakiBundleData> iwasaki_;
  const methods::RuntimeMethod* method_ = nullptr;  // from the registry: --method, or the bundle's best

  // The display.
  std::unique_ptr<gpu::KmsDisplay> kms_;
  std::unique_ptr<gpu::EglContext> headless_;
  int width_ = 0, height_ = 0;

  // The knobs: every fabric in the bundle is a preset the fabric knob selects.
  std::vector<Fabric> presets_;
  std::unique_ptr<input::KnobController> controller_;
  std::atomic<int64_t> last_report_ns_{0};  // the newest HID report's arrival (steady_clock ns)
  std::vector<std::unique_ptr<input::KnobSource>> sources_;
  input::AppearanceState knobs_;
  uint64_t knob_version_ = ~0ull;

  // The renderer and what it draws into.
  std::vector<Fabric> cloth_fabrics_;  // the fabric of each cloth object
  std::unique_ptr<gpu::SceneRenderer> renderer_;
  std::unique_ptr<gpu::OffscreenTarget> target_;
  std::unique_ptr<gpu::ToneMapper> tonemap_;  // KMS only

  // The light: the bundle's SGs or the probe's latest fit, turned by the environment knob.
  SgLighting room_light_;
  std::unique_ptr<KioskLightProbe> probe_;
  float light_rotation_ = -1;  // degrees; < 0 until the knobs first set it
  std::atomic<long> lighting_prepared_{0};
  std::atomic<double> last_prepare_ms_{0};
  std::unique_ptr<LatestRequestWorker<SgLighting, gpu::SceneRenderer::PreparedLighting>> lighting_;
  bool first_frame_shown_ = false;

  // The loop.
  long hang_after_ = -1;
  Clock::time_point loop_start_, last_stats_;
  double shown_turn_ = 0;
  long ticks_ = 0, drawn_ = 0;
  long rss_start_kib_ = 0;
  RecentSamples frame_ms_, since_stats_ms_, latency_ms_;
};

}  // namespace weft
