// `weft run`: the kiosk. Loads the bundle (falling back to the last good one), opens the display
// (DRM/KMS fullscreen, or a headless offscreen target), shows the first frame, tells systemd it
// is ready, then loops: slow turntable, knob edits applied without blocking, redraw only when the
// view, the knobs or the light changed, a watchdog ping every tick.
//
// Test-only fault injection: WEFT_FAULT_HANG_AFTER_TICKS=N makes the frame loop hang (no more
// frames, no more watchdog pings) after N ticks, as a stuck driver would; the watchdog test uses it.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/knob_appearance.h"
#include "app/service_notifier.h"
#include "bake/iwasaki_bundle.h"
#include "bake/scene_bundle.h"
#include "bundle/bundle_fallback.h"
#include "gpu/egl_context.h"
#include "gpu/kms_display.h"
#include "gl/offscreen_target.h"
#include "gpu/scene_renderer.h"
#include "image/image.h"
#include "panel/gpio_knob_source.h"
#include "panel/hid_knob_source.h"
#include "panel/keyboard_knob_source.h"
#include "panel/knob_controller.h"
#include "panel/panel_config.h"
#include "panel/simulated_panel.h"
#include "app/kiosk_light_probe.h"
#include "app/latest_request_worker.h"

namespace weft {
namespace {

std::atomic<bool> g_stop{false};
using Clock = std::chrono::steady_clock;

struct RunArgs {
  std::string bundle;
  std::string state_dir = "/var/lib/weft";
  std::string display = "auto";
  long frames = 0;          // ticks to run; 0 = until SIGTERM
  double turntable = 6.0;   // degrees per second about the camera target's +Z
  std::string panel = "hid";
  std::string panel_config;
  double sim_speed = 1.0;
  std::string screenshot;
  std::vector<int> size{640, 480};
  // auto: iwasaki_vertex when the bundle has seed 000 tables (the same accuracy as per-pixel
  // iwasaki on the showroom meshes at a tenth to a twentieth of the cost; render/gpu/IWASAKI.md), else sgpoint.
  std::string method = "auto";
  double exposure = 1.0;
  double stats_every = 300;  // seconds between stats lines in the log
  std::string probe = "none";
  double probe_switch_s = 0;  // mock probe with several maps: seconds between switches
};

void log_line(const std::string& s) {
  std::fprintf(stderr, "weft run: %s\n", s.c_str());
  std::fflush(stderr);
}

// Wraps the HID byte source to note when the last report arrived: the start of report→photon.
class TimedTransport : public input::HidTransport {
public:
  TimedTransport(std::unique_ptr<input::HidTransport> inner, std::atomic<int64_t>* last_report_ns)
      : inner_(std::move(inner)), last_(last_report_ns) {}
  std::unique_ptr<input::HidDevice> open(uint16_t vid, uint16_t pid, std::string& why) override {
    auto d = inner_->open(vid, pid, why);
    if (!d) return nullptr;
    return std::make_unique<Device>(std::move(d), last_);
  }

private:
  struct Device : input::HidDevice {
    Device(std::unique_ptr<input::HidDevice> d, std::atomic<int64_t>* last) : d(std::move(d)), last(last) {}
    int read(uint8_t* b, size_t n, int timeout_ms) override {
      const int r = d->read(b, n, timeout_ms);
      if (r > 0) last->store(Clock::now().time_since_epoch().count());
      return r;
    }
    std::string last_error() const override { return d->last_error(); }
    std::unique_ptr<input::HidDevice> d;
    std::atomic<int64_t>* last;
  };
  std::unique_ptr<input::HidTransport> inner_;
  std::atomic<int64_t>* last_;
};

SgLighting rotated_about_z(const SgLighting& sgs, double deg) {
  const double a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
  SgLighting out = sgs;
  for (auto& g : out) g.axis = glm::dvec3(c * g.axis.x - s * g.axis.y, s * g.axis.x + c * g.axis.y, g.axis.z);
  return out;
}

Camera turned_about_z(const Camera& cam, double deg) {
  const double a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
  Camera out = cam;
  const glm::dvec3 d = cam.position - cam.target;
  out.position = cam.target + glm::dvec3(c * d.x - s * d.y, s * d.x + c * d.y, d.z);
  return out;
}

// Keeps the most recent samples only: the kiosk runs for months.
void push_recent(std::vector<double>& v, double x) {
  constexpr size_t kKeep = 4096;
  if (v.size() >= 2 * kKeep) v.erase(v.begin(), v.end() - kKeep);
  v.push_back(x);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

long rss_kib() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::atol(line.c_str() + 6);
  return 0;
}

int run_kiosk(const RunArgs& a) {
  const auto boot = Clock::now();
  // From the start: a SIGTERM while booting still ends in the loop's clean exit path.
  std::signal(SIGINT, [](int) { g_stop = true; });
  std::signal(SIGTERM, [](int) { g_stop = true; });
  ServiceNotifier notifier;
  if (a.display != "auto" && a.display != "kms" && a.display != "headless")
    throw UsageError("--display: expected auto, kms or headless, got '" + a.display + "'");
  if (a.size.size() != 2 || a.size[0] < 8 || a.size[1] < 8 || a.size[0] > 8192 || a.size[1] > 8192)
    throw UsageError("--size: expected WIDTH HEIGHT in [8, 8192]");
  if (!std::isfinite(a.turntable) || std::abs(a.turntable) > 360)
    throw UsageError("--turntable: degrees per second in [-360, 360]");
  if (a.method != "auto") try {
      gpu::parse_method(a.method);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--method: ") + e.what() + " or auto");
    }
  std::error_code ec;
  std::filesystem::create_directories(a.state_dir, ec);
  if (ec) log_line("cannot create state directory " + a.state_dir + ": " + ec.message() + " (no last-good copy, no knob state)");

  // 1. The bundle, or the last good one.
  notifier.status("loading bundle " + a.bundle);
  std::optional<SceneBundle> loaded;
  bundle::FallbackOptions fo;
  std::shared_ptr<const IwasakiBundleData> iwasaki;
  // Seed 000's tables are read in the accept step too: a bundle whose tables do not read (a
  // section missing, a shape that does not match the mesh) falls back like a corrupt one.
  fo.accept = [&](const bundle::BundleReader& r) {
    loaded = read_scene_bundle(r);
    iwasaki.reset();
    if (has_iwasaki_sections(r) && a.method != "sgpoint") {
      std::map<size_t, size_t> vertices;
      for (size_t i = 0; i < loaded->scene.objects.size(); ++i) vertices[i] = loaded->scene.objects[i].mesh.positions.size();
      iwasaki = std::make_shared<IwasakiBundleData>(read_iwasaki_sections(r, vertices));
    }
  };
  fo.log = [](std::string_view s) { log_line(std::string(s)); };
  bundle::OpenedBundle opened = [&] {
    try {
      return bundle::open_bundle_with_fallback(a.bundle, a.state_dir, fo);
    } catch (const bundle::BundleError& e) {
      log_line(std::string("no usable bundle: ") + e.what());
      notifier.status("no usable bundle (see journal)");
      throw;
    }
  }();
  if (!loaded) fo.accept(opened.bundle);
  SceneBundle& sb = *loaded;
  const std::string method_name = a.method != "auto" ? a.method : (iwasaki ? "iwasaki_vertex" : "sgpoint");
  const gpu::Method method = gpu::parse_method(method_name);
  if (gpu::uses_seed000_tables(method) && !iwasaki)
    throw UsageError("--method " + method_name + ": bundle " + opened.file.string() + " has no seed 000 tables (weft bake without --no-tables)");
  log_line("bundle " + opened.file.string() + (opened.is_last_good ? " (LAST GOOD COPY: " + opened.primary_error + ")" : "") +
           ": scene '" + sb.scene.name + "', " + std::to_string(sb.scene.objects.size()) + " objects, " +
           std::to_string(sb.sgs.size()) + " SGs");

  // 2. The display.
  std::unique_ptr<gpu::KmsDisplay> kms;
  std::optional<gpu::EglContext> headless;
  int width = a.size[0], height = a.size[1];
  if (a.display != "headless") {
    try {
      kms = std::make_unique<gpu::KmsDisplay>();
      width = kms->width();
      height = kms->height();
      log_line("display " + kms->description());
    } catch (const std::exception& e) {
      if (a.display == "kms") {
        log_line(std::string("no display: ") + e.what());
        notifier.status(std::string("no display: ") + e.what());
        return 1;
      }
      log_line(std::string("no KMS display (") + e.what() + "); running headless");
    }
  }
  if (!kms) {
    headless.emplace(gpu::EglContext::headless());
    log_line("headless " + std::to_string(width) + "x" + std::to_string(height) + " on " + headless->renderer());
  }

  // 3. Knobs: every fabric in the bundle is a preset the fabric knob can select.
  std::vector<std::string> preset_names;
  std::vector<Fabric> presets;
  for (const auto& [name, f] : sb.fabrics) {
    preset_names.push_back(name);
    presets.push_back(f);
  }
  uint32_t default_preset = 0;
  for (const auto& o : sb.scene.objects)
    if (o.material == Material::cloth)
      default_preset = uint32_t(std::find(preset_names.begin(), preset_names.end(), o.fabric) - preset_names.begin());
  input::PanelConfig config;
  if (!a.panel_config.empty()) {
    try {
      config = input::parse_panel_config(read_argument_file(a.panel_config, "--panel-config"), a.panel_config);
    } catch (const input::PanelConfigError& e) {
      throw UsageError(e.what());
    }
  }
  input::KnobControllerOptions ko;
  ko.state_file = ec ? std::filesystem::path() : std::filesystem::path(a.state_dir) / "knobs.json";
  ko.default_preset = default_preset;
  const input::LogSink log = [](const std::string& s) { log_line(s); };
  input::KnobController controller(input::KnobMapper(preset_looks(presets)), ko, log);
  controller.restore();
  std::atomic<int64_t> last_report_ns{0};
  std::vector<std::unique_ptr<input::KnobSource>> sources;
  if (a.panel.rfind("sim:", 0) == 0) {
    if (!(a.sim_speed > 0 && a.sim_speed <= 1000)) throw UsageError("--sim-speed: must be in (0, 1000]");
    input::SimulatedPanel panel;
    try {
      panel = input::make_simulated_panel(read_argument_file(a.panel.substr(4), "--panel sim:"), a.sim_speed);
    } catch (const input::PanelScriptError& e) {
      throw UsageError(std::string("--panel sim: ") + e.what());
    }
    sources.push_back(std::make_unique<input::HidKnobSource>(
        config.hid, std::make_unique<TimedTransport>(std::move(panel.transport), &last_report_ns), log));
  } else if (a.panel == "hid") {
    sources.push_back(std::make_unique<input::HidKnobSource>(
        config.hid, std::make_unique<TimedTransport>(input::make_hidapi_transport(), &last_report_ns), log));
  } else if (a.panel == "gpio") {
    sources.push_back(std::make_unique<input::GpioKnobSource>(config.gpio, nullptr, log));
  } else if (a.panel == "keyboard") {
    sources.push_back(std::make_unique<input::KeyboardKnobSource>(0, log));
  } else if (a.panel != "none") {
    throw UsageError("--panel: expected hid, gpio, keyboard, sim:SCRIPT or none, got '" + a.panel + "'");
  }

  // 4. Renderer and first frame.
  std::vector<size_t> cloth;
  std::vector<Fabric> cloth_fabrics;
  for (size_t i = 0; i < sb.scene.objects.size(); ++i)
    if (sb.scene.objects[i].material == Material::cloth) cloth_fabrics.push_back(sb.fabrics.at(sb.scene.objects[i].fabric));
  gpu::SceneRenderer renderer(sb.scene, cloth_fabrics, method, 16, iwasaki);
  gpu::OffscreenTarget target(width, height);
  std::optional<gpu::ToneMapper> tonemap;
  if (kms) tonemap.emplace();

  // The light: the bundle's SGs, or the probe's latest fit; the environment knob turns either.
  SgLighting room_light = sb.sgs;
  std::unique_ptr<KioskLightProbe> probe;
  if (a.probe != "none") {
    probe = std::make_unique<KioskLightProbe>(a.probe, a.probe_switch_s, sb.sgs,
                                              [](const std::string& s) { log_line("light probe: " + s); });
    log_line("light probe " + a.probe + " started; the bundle's SGs stay until its first fit");
  }
  input::AppearanceState knobs;
  uint64_t knob_version = ~0ull;
  float light_rotation = -1;
  // Lighting changes after the first frame are prepared off the render thread; the frame keeps
  // the light it has until the new one is ready (relight, then take() in the loop).
  std::atomic<long> lighting_prepared{0};
  std::atomic<double> last_prepare_ms{0};
  LatestRequestWorker<SgLighting, gpu::SceneRenderer::PreparedLighting> lighting([&](const SgLighting& sgs) {
    const auto t0 = Clock::now();
    auto prepared = renderer.prepare_lighting(sgs);
    last_prepare_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    ++lighting_prepared;
    return prepared;
  });
  bool first_frame_shown = false;
  auto relight = [&](const SgLighting& sgs) {
    if (first_frame_shown)
      lighting.request(sgs);
    else
      renderer.set_lighting(sgs);
  };
  auto apply_knob_state = [&](const input::AppearanceState& s) {
    const Fabric f = apply_knobs(presets.at(std::min<size_t>(s.preset_index, presets.size() - 1)), s);
    try {
      for (size_t c = 0; c < cloth_fabrics.size(); ++c) renderer.set_fabric(c, f);
    } catch (const gpu::GpuError& e) {  // e.g. a preset the bundle baked no tables for
      log_line(std::string("knobs: ") + e.what() + "; keeping the fabric shown");
    }
    if (s.env_rotation_deg != light_rotation) {
      relight(rotated_about_z(room_light, s.env_rotation_deg));
      light_rotation = s.env_rotation_deg;
    }
  };
  auto poll_light = [&]() -> bool {
    if (!probe || !probe->acquire()) return false;
    room_light = probe->lighting();
    relight(rotated_about_z(room_light, std::max(light_rotation, 0.0f)));
    return true;
  };
  auto poll_knobs = [&]() -> bool {
    if (controller.channel().version() == knob_version) return false;
    uint64_t v = 0;
    if (!controller.channel().read(knobs, &v)) return false;  // writer mid-update: next tick
    knob_version = v;
    apply_knob_state(knobs);
    return true;
  };
  poll_knobs();
  if (light_rotation < 0) renderer.set_lighting(sb.sgs);

  std::vector<double> frame_ms, latency_ms, since_stats;  // recent samples (bounded)
  auto draw = [&](double turn_deg) {
    const auto t0 = Clock::now();
    target.bind();
    renderer.draw(turned_about_z(sb.scene.camera, turn_deg), width, height);
    if (kms) {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, width, height);
      tonemap->draw(target.colour_texture(), float(a.exposure));
      kms->present();
    } else {
      glFinish();
    }
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    push_recent(frame_ms, ms);
    push_recent(since_stats, ms);
  };
  draw(0);
  first_frame_shown = true;
  const double boot_ms = std::chrono::duration<double, std::milli>(Clock::now() - boot).count();
  const std::string where = kms ? kms->description() : "headless";
  char line[256];
  std::snprintf(line, sizeof line, "first frame after %.0f ms (%dx%d, %s, %s)", boot_ms, width, height, where.c_str(),
                method_name.c_str());
  log_line(line);
  notifier.ready(std::string("showing '") + sb.scene.name + "'" + (opened.is_last_good ? " from the LAST GOOD bundle" : "") +
                 " on " + where);
  if (notifier.watchdog_enabled())
    log_line("watchdog every " + std::to_string(notifier.watchdog_interval().count() / 1000) + " ms");

  for (auto& s : sources) {
    log_line("listening to " + s->describe());
    s->start(controller.sink());
  }
  long hang_after = -1;
  if (const char* h = std::getenv("WEFT_FAULT_HANG_AFTER_TICKS")) {
    hang_after = std::atol(h);
    log_line("FAULT INJECTION: the frame loop hangs after " + std::to_string(hang_after) + " ticks");
  }

  // 5. The loop: one tick per display refresh (vsync on KMS; 60 Hz headless).
  const auto loop_start = Clock::now();
  const auto tick_period = std::chrono::microseconds(16667);
  double shown_turn = 0;
  long ticks = 0, drawn = 1;
  const long rss_start = rss_kib();
  auto last_stats = loop_start;
  while (!g_stop && (a.frames <= 0 || ticks < a.frames)) {
    ++ticks;
    if (ticks == hang_after)
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // a stuck loop: no frames, no pings
    const auto tick_start = Clock::now();
    const double turn = a.turntable * std::chrono::duration<double>(tick_start - loop_start).count();
    const int64_t report_ns = last_report_ns.load();
    const bool knobs_changed = poll_knobs();
    poll_light();
    bool light_changed = false;
    try {
      if (auto prepared = lighting.take()) {
        renderer.set_lighting(*prepared);
        light_changed = true;
      }
    } catch (const std::exception& e) {
      log_line(std::string("lighting: ") + e.what() + "; keeping the light shown");
    }
    const bool view_changed = std::abs(turn - shown_turn) > 1e-4;
    if (knobs_changed || light_changed || view_changed) {
      draw(turn);
      shown_turn = turn;
      ++drawn;
      if (knobs_changed && report_ns != 0)
        push_recent(latency_ms, double(Clock::now().time_since_epoch().count() - report_ns) / 1e6);
    }
    notifier.tick();
    if (a.stats_every > 0 && tick_start - last_stats >= std::chrono::duration<double>(a.stats_every)) {
      std::snprintf(line, sizeof line,
                    "stats: %ld ticks, %ld frames drawn, median %.2f ms/frame over the last %zu, RSS %ld KiB, "
                    "%llu light-probe updates, lighting prepared off-thread %ld times (last %.0f ms)",
                    ticks, drawn, median(since_stats), since_stats.size(), rss_kib(),
                    static_cast<unsigned long long>(probe ? probe->updates() : 0), lighting_prepared.load(),
                    last_prepare_ms.load());
      log_line(line);
      last_stats = tick_start;
      since_stats.clear();
    }
    if (!kms || !(knobs_changed || light_changed || view_changed)) std::this_thread::sleep_until(tick_start + tick_period);
  }

  for (auto& s : sources) s->stop();
  probe.reset();
  controller.flush();
  if (!a.screenshot.empty()) {
    target.bind();
    try {
      write_png(gpu::read_linear_image(width, height), a.screenshot, a.exposure);
      log_line("screenshot " + a.screenshot);
    } catch (const std::exception& e) {
      log_line(std::string("screenshot failed: ") + e.what());
    }
  }
  std::vector<double> steady(frame_ms.begin() + std::min<size_t>(1, frame_ms.size()), frame_ms.end());
  std::snprintf(line, sizeof line,
                "stopping after %ld ticks, %ld frames drawn; median %.2f ms/frame; %zu knob changes shown, "
                "report->photon median %.1f ms max %.1f ms; RSS %ld -> %ld KiB",
                ticks, drawn, median(steady), latency_ms.size(), median(latency_ms),
                latency_ms.empty() ? 0.0 : *std::max_element(latency_ms.begin(), latency_ms.end()), rss_start, rss_kib());
  log_line(line);
  notifier.stopping("stopping");
  return 0;  // KmsDisplay's destructor puts the previous CRTC back
}

}  // namespace

CommandAction add_run_command(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  CLI::App* sub = app.add_subcommand("run", "The kiosk: show a baked bundle fullscreen (or headless) with the knob panel");
  sub->add_option("--bundle", a->bundle, "Scene bundle (weft bake)")->required();
  sub->add_option("--state-dir", a->state_dir, "Knob state and last good bundle")->capture_default_str();
  sub->add_option("--display", a->display, "auto (KMS, else headless), kms or headless")->capture_default_str();
  sub->add_option("--frames", a->frames, "Stop after this many ticks (display refreshes); 0: until SIGTERM")
      ->capture_default_str();
  sub->add_option("--turntable", a->turntable, "Camera turn, degrees per second (0: still)")->capture_default_str();
  sub->add_option("--panel", a->panel, "Knobs: hid, gpio, keyboard, sim:SCRIPT (simulated USB panel) or none")
      ->capture_default_str();
  sub->add_option("--panel-config", a->panel_config, "Panel configuration (JSON: hid ids, gpio lines)");
  sub->add_option("--sim-speed", a->sim_speed, "Play the sim: script this many times faster")->capture_default_str();
  sub->add_option("--screenshot", a->screenshot, "Write the last frame, tone-mapped, as PNG");
  sub->add_option("--size", a->size, "Headless frame size WIDTH HEIGHT")->expected(2)->capture_default_str();
  sub->add_option("--method", a->method, "Runtime method: auto (iwasaki_vertex when the bundle has seed 000 tables, else sgpoint), iwasaki (per pixel), iwasaki_vertex (per vertex: same tables, a fraction of the cost) or sgpoint")->capture_default_str();
  sub->add_option("--stats-every", a->stats_every, "Seconds between stats lines (frames, ms/frame, memory); 0: none")
      ->capture_default_str();
  sub->add_option("--exposure", a->exposure, "Tone-mapping exposure")->capture_default_str();
  sub->add_option("--probe", a->probe, "Light probe: none, camera[:ID] (libcamera) or mock:MAP.exr[,MAP.exr...]")
      ->capture_default_str();
  sub->add_option("--probe-switch", a->probe_switch_s, "Mock probe with several maps: seconds between switching them");
  return [a] { return run_kiosk(*a); };
}

}  // namespace weft
