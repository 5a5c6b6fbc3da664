#include "kiosk/kiosk.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include <unistd.h>

#include "bundle/bundle_fallback.h"
#include "camera/camera_probe_plugin.h"
#include "gpu/egl_context.h"
#include "gl/offscreen_target.h"
#include "image/tone_map.h"
#include "kiosk/camera_zoom.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/kiosk_knobs.h"
#include "kiosk/kiosk_light_probe.h"
#include "kiosk/kiosk_log.h"
#include "kiosk/kiosk_renderer.h"
#include "kiosk/turntable.h"
#include "methods/registry.h"

namespace weft {
namespace {

constexpr auto kTickPeriod = std::chrono::microseconds(16667);
// Time constant of the exposure easing in after a lighting change (a probe update, the
// environment knob): quick enough to follow the room, slow enough not to flicker.
constexpr double kExposureAdaptSeconds = 0.7;
// The look's way home after --idle-return: slow enough to read as deliberate, not as a glitch.
constexpr double kIdleEaseSeconds = 3.0;

}  // namespace

Kiosk::Kiosk(KioskConfig config)
    : config_(std::move(config)),
      look_sink_([this](float degrees) {
        // Before the first frame a turned light is set at once: meter the first frame under it
        // (afterwards the worker's hand-over asks for metering: take_prepared_lighting).
        if (!first_frame_shown_ && degrees != 0) exposure_.request();
        relight(rotated_about_z(room_light_, degrees));
      }),
      look_applier_(look_sink_, config_.zoom,
                    [this](std::uint32_t colourway) -> const std::vector<Fabric>& { return knobs_->presets(colourway); }),
      exposure_(config_.exposure_bias + std::log2(config_.exposure), kExposureAdaptSeconds),
      idle_(config_.idle_return_s, kIdleEaseSeconds),
      screen_schedule_(ScreenSchedule::parse(config_.screen_off)),
      weave_terms_(WeaveTermsGovernor::parse(config_.weave_terms).value_or(WeaveTermsGovernor::Mode::automatic),
                   config_.weave_budget_ms) {}

Kiosk::~Kiosk() = default;

int Kiosk::run(const std::atomic<bool>& stop) {
  boot_ = Clock::now();
  Clock::time_point stage = boot_;
  check_config();
  watch_bundle();
  load_bundle();
  boot_stage("bundle", stage);
  if (!open_display()) return 1;
  boot_stage("display", stage);
  start_knobs();
  start_renderer();
  boot_stage("renderer", stage);
  start_probe();
  show_first_frame();
  knobs_->listen();
  arm_fault_injection();
  loop_start_ = last_stats_ = Clock::now();
  rss_start_kib_ = resident_set_kib();
  while (!stop && !restart_ && (config_.frames <= 0 || ticks_ < config_.frames)) tick();
  shut_down();
  return restart_ ? 3 : 0;  // KmsDisplay's destructor puts the previous CRTC back
}

void Kiosk::check_config() {
  check_kiosk_config(config_);
  const KioskConfig& c = config_;
  std::error_code ec;
  std::filesystem::create_directories(c.state_dir, ec);
  state_dir_ok_ = !ec;
  if (!c.status_file.empty()) status_ = std::make_unique<StatusFile>(c.status_file);
  if (ec)
    kiosk_log_warning("cannot create state directory " + c.state_dir + ": " + ec.message() + " (no last-good copy, no knob state)");
}

// Watched before it is read: a replacement made while the kiosk boots is seen (and read once
// the loop runs, unless it is the content already shown).
void Kiosk::watch_bundle() {
  try {
    swap_ = std::make_unique<BundleSwap>(BundleSwap::Options{config_.bundle, config_.method, state_dir_ok_ ? config_.state_dir : ""});
  } catch (const std::exception& e) {
    kiosk_log_warning(std::string("content updates are not watched (") + e.what() + "); a new bundle needs a restart");
  }
}

void Kiosk::load_bundle() {
  notifier_.status("loading bundle " + config_.bundle);
  bundle::FallbackOptions fo;
  // The weighting tables are read in the accept step too: a bundle whose tables do not read (a
  // section missing, a shape that does not match the mesh) falls back like a corrupt one.
  std::optional<KioskBundle> read;
  fo.accept = [&](const bundle::BundleReader& r) { read = read_kiosk_bundle(r, config_.method); };
  fo.log = stderr_sink("weft run");
  fo.read_into_memory = true;  // the file may be rewritten in place while the kiosk runs
  std::optional<bundle::OpenedBundle> opened;
  try {
    opened.emplace(bundle::open_bundle_with_fallback(config_.bundle, config_.state_dir, fo));
  } catch (const bundle::BundleError& e) {
    kiosk_log_error(std::string("no usable bundle: ") + e.what());
    notifier_.status("no usable bundle (see journal)");
    write_status("no usable bundle");
    throw;
  }
  if (!read) read = read_kiosk_bundle(opened->bundle, config_.method);
  shown_ = {opened->file, opened->is_last_good, opened->primary_error};
  // A last good copy shown does not count as the primary's content: the primary, once fixed, is.
  if (swap_) swap_->set_shown_fingerprint(opened->is_last_good ? 0 : read->fingerprint);
  method_ = &kiosk_method(config_.method, *read, opened->file);
  scene_ = std::move(read->scene);
  shading_ = read->shading;
  (shown_.is_last_good ? kiosk_log_warning : kiosk_log_info)("bundle " + shown_.file.string() +
           (shown_.is_last_good ? " (LAST GOOD COPY: " + shown_.primary_error + ")" : "") + ": scene '" +
           scene_->scene.name + "', " + std::to_string(scene_->scene.objects.size()) + " objects, " +
           std::to_string(scene_->sgs.size()) + " SGs" +
           (read->baked_for.empty() ? "" : "; the bake measured " + read->baked_for + " for it") + "; drawing " +
           method_->name);
}

bool Kiosk::open_display() {
  try {
    display_ = std::make_unique<KioskDisplay>(display_settings());
  } catch (const NoDisplayError& e) {
    kiosk_log_error(std::string("no display: ") + e.what());
    notifier_.status(std::string("no display: ") + e.what());
    write_status("no display");
    return false;
  }
  width_ = display_->width();
  height_ = display_->height();
  const auto since_boot = std::chrono::duration_cast<std::chrono::seconds>(Clock::now() - boot_).count();
  screen_wait_.emplace(config_.display_wait_s, boot_, std::time(nullptr) - since_boot);
  return true;
}

void Kiosk::start_knobs() {
  const std::filesystem::path state_file = state_dir_ok_ ? std::filesystem::path(config_.state_dir) / "knobs.json" : "";
  knobs_ = std::make_unique<KioskKnobs>(config_, state_file, *scene_);
}

void Kiosk::start_renderer() {
  const SceneBundle& sb = *scene_;
  cloth_fabrics_ = cloth_fabrics(sb);
  if (cloth_fabrics_.empty())
    kiosk_log_info("the bundle has no cloth: its surfaces are shown, the knobs change nothing (name a fabric for a "
                   "material in the scene file, or give it KHR_materials_sheen, and bake again)");
  closeup_ = closeup_of(sb.scene, cloth_fabrics_, height_);
  pivot_ = turntable_pivot(sb.scene);
  renderer_ = make_kiosk_renderer(sb, cloth_fabrics_, *method_, shading_);
  arm_weave_range(*renderer_, sb, closeup_, width_, height_);
  target_ = std::make_unique<gpu::OffscreenTarget>(width_, height_);
  if (config_.label == "on" && !label_) {
    label_ = std::make_unique<KioskLabel>(config_);
    if (!label_->usable()) label_.reset();  // warned: the kiosk runs without it
  }
  look_sink_.show(*scene_, *renderer_, cloth_fabrics_, label_.get());
  start_profile();
}

void Kiosk::start_probe() {
  room_light_ = scene_->sgs;
  if (config_.probe != "none") {
    try {
      probe_ = std::make_unique<KioskLightProbe>(config_.probe, config_.probe_switch_s, scene_->sgs,
                                                 [](LogPriority p, const std::string& s) { log_line("weft run", p, "light probe: " + s); });
      kiosk_log_info("light probe " + config_.probe + " started; the bundle's SGs stay until its first fit");
    } catch (const CameraPluginError& e) {
      // The showroom still shows, under the bundle's light, as with an unplugged camera.
      kiosk_log_error("light probe " + config_.probe + " unavailable: " + std::string(e.what()) +
                      "; showing the bundle's stored lighting");
    }
  }
  lighting_ = std::make_unique<KioskLighting>();
}

void Kiosk::boot_stage(const char* name, Clock::time_point& since) {
  const Clock::time_point now = Clock::now();
  const long ms = std::lround(std::chrono::duration<double, std::milli>(now - since).count());
  boot_stages_ += (boot_stages_.empty() ? "" : ", ") + std::string(name) + " " + std::to_string(ms);
  since = now;
}

void Kiosk::show_first_frame() {
  Clock::time_point stage = Clock::now();
  // The exposure is metered first on the bundle as baked (its own fabrics under its own light,
  // a quarter-size frame), so that a knob state restored at boot shows the picture it showed
  // when the knobs were turned (knob edits never re-meter).
  renderer_->set_lighting(scene_->sgs);
  boot_stage("lighting", stage);
  meter_as_baked();
  boot_stage("metering", stage);
  poll_knobs();
  // The light set above stands unless the look restored turns it (relight, at once before the
  // first frame): set again it would cost a dense mesh's whole lighting stage a second time.
  idle_.touched(Clock::now());  // a look restored at boot goes home after the idle time too
  zoom_shown_ = zoom_drawn_ = look_sink_.zoom_target();  // a kiosk started zoomed in (--zoom) shows it at once
  draw_frame(0);
  boot_stage("frame", stage);
  drawn_ = 1;
  first_frame_shown_ = true;
  const double boot_ms = std::chrono::duration<double, std::milli>(Clock::now() - boot_).count();
  const std::string where = display_->description();
  char line[512];
  std::snprintf(line, sizeof line, "first frame after %.0f ms (%dx%d, %s, %s; ms: %s)", boot_ms, width_, height_,
                where.c_str(), method_->name.c_str(), boot_stages_.c_str());
  kiosk_log_info(line);
  notifier_.ready(std::string("showing '") + scene_->scene.name + "'" +
                  (shown_.is_last_good ? " from the LAST GOOD bundle" : "") + " on " + where);
  if (notifier_.watchdog_enabled())
    kiosk_log_info("watchdog every " + std::to_string(notifier_.watchdog_interval().count() / 1000) + " ms");
  write_status("running");
}

void Kiosk::arm_fault_injection() {
  if (const char* h = std::getenv("WEFT_FAULT_HANG_AFTER_TICKS")) {
    hang_after_ = std::atol(h);
    kiosk_log_warning("FAULT INJECTION: the frame loop hangs after " + std::to_string(hang_after_) + " ticks");
  }
}

void Kiosk::tick() {
  ++ticks_;
  hang_if_injected();
  const auto tick_start = Clock::now();
  const double turn = config_.turntable * std::chrono::duration<double>(tick_start - loop_start_).count();
  const TickNews news = poll_inputs(tick_start, turn);
  const bool redraw = news.redraw() || (!news.asleep && exposure_.adapting());
  const bool label_changed = !news.asleep && !redraw && label_ && label_->changed(tick_start);
  if (label_changed) {
    present(tick_start);
    ++drawn_;
  }
  if (redraw) {
    draw_frame(turn);
    shown_turn_ = turn;
    zoom_drawn_ = zoom_shown_;
    ++drawn_;
    if (news.scene) {
      swap_->log_shown(*scene_, method_->name);
      notifier_.status("showing '" + scene_->scene.name + "' on " + display_->description());
    }
    if (news.knobs && news.knob_report_ns != 0)
      latency_ms_.push(double(Clock::now().time_since_epoch().count() - news.knob_report_ns) / 1e6);
  }
  knob_changes_ += news.knobs;
  notifier_.tick();
  if (status_) status_->update(status("running"), tick_start);
  if (config_.stats_every > 0 && tick_start - last_stats_ >= std::chrono::duration<double>(config_.stats_every))
    log_stats(tick_start);
  wait_for_next_tick(tick_start, redraw || label_changed);
}

Kiosk::TickNews Kiosk::poll_inputs(Clock::time_point now, double turn_deg) {
  TickNews news;
  follow_display(now);
  news.knob_report_ns = knobs_->last_report_ns();
  news.knobs = poll_knobs();
  if (news.knobs) idle_.touched(now);
  news.look_returning = return_when_idle(now);
  poll_light();
  news.light = take_prepared_lighting();
  news.scene = poll_bundle();
  news.view = move_view(now, turn_deg);
  news.woke = screen_off_;
  news.asleep = screen_asleep(now);
  return news;
}

void Kiosk::hang_if_injected() {
  if (ticks_ == hang_after_)
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // a stuck loop: no frames, no pings
}

bool Kiosk::move_view(Clock::time_point now, double turn_deg) {
  zoom_shown_ = ease_zoom(zoom_shown_, look_sink_.zoom_target(), std::chrono::duration<double>(now - zoom_step_).count());
  zoom_step_ = now;
  return std::abs(turn_deg - shown_turn_) > 1e-4 || zoom_shown_ != zoom_drawn_;
}

void Kiosk::wait_for_next_tick(Clock::time_point tick_start, bool drew) {
  // On KMS a drawn frame already waited for vsync.
  if (!display_->vsynced() || !drew) std::this_thread::sleep_until(tick_start + kTickPeriod);
}

void Kiosk::shut_down() {
  knobs_->stop();
  probe_.reset();
  if (!config_.screenshot.empty()) {
    try {
      display_->screenshot(*target_, exposure_.shown(), label_overlay(), config_.screenshot);
      kiosk_log_info("screenshot " + config_.screenshot);
    } catch (const std::exception& e) {
      kiosk_log_warning(std::string("screenshot failed: ") + e.what());
    }
  }
  char line[256];
  std::snprintf(line, sizeof line,
                "stopping after %ld ticks, %ld frames drawn; median %.2f ms/frame; %zu knob changes shown, "
                "report->photon median %.1f ms max %.1f ms; RSS %ld -> %ld KiB",
                ticks_, drawn_, frame_ms_.median(1), latency_ms_.size(), latency_ms_.median(), latency_ms_.max(),
                rss_start_kib_, resident_set_kib());
  kiosk_log_info(line);
  if (profile_ && profile_->frames() > 0) kiosk_log_info("frame profile: " + profile_->summary());
  write_status("stopping");
  notifier_.stopping("stopping");
}

bool Kiosk::poll_knobs() {
  if (!knobs_->poll()) return false;
  look_applier_.apply(knobs_->state());
  return true;
}

void Kiosk::poll_light() {
  if (!probe_ || !probe_->acquire()) return;
  room_light_ = probe_->lighting();
  relight(rotated_about_z(room_light_, look_applier_.light_turn_deg().value_or(0.0f)));
}

bool Kiosk::take_prepared_lighting() {
  try {
    auto prepared = lighting_->take(renderer_.get());
    if (!prepared) return false;
    renderer_->set_lighting(*prepared);
    exposure_.request();
    return true;
  } catch (const std::exception& e) {
    kiosk_log_warning(std::string("lighting: ") + e.what() + "; keeping the light shown");
    return false;
  }
}

// Before the first frame the lighting is set here and now; after it, on the worker.
void Kiosk::relight(const SgLighting& sgs) {
  ++light_version_;
  if (first_frame_shown_)
    lighting_->request(*renderer_, sgs);
  else
    renderer_->set_lighting(sgs);
}

void Kiosk::draw_frame(double turn_deg) {
  const auto t0 = Clock::now();
  if (profile_) profile_->begin_frame();
  if (zoom_shown_ != zoom_drawn_) renderer_->refresh_all();  // the dolly moves the eye far in a frame
  // The turn a frame, smoothed: a share count that follows each frame's time would jump between
  // neighbours and break the shares' turns.
  const double turn = std::abs(turn_deg - shown_turn_);
  turn_per_frame_ = turn_per_frame_ > 0.0 ? 0.9 * turn_per_frame_ + 0.1 * turn : turn;
  // By degrees only where kept values follow the camera (a rung that would hold them, sheer_vertex,
  // keeps --vertex-refresh alone).
  const int by_turn = renderer_->reuse_follows_camera() ? refresh_shares(config_.vertex_refresh_deg, turn_per_frame_) : 1;
  renderer_->set_vertex_refresh(std::max(config_.vertex_refresh, by_turn));
  renderer_->set_broad_lobe_refresh(refresh_shares(config_.broad_lobe_refresh_deg, turn_per_frame_));
  renderer_->set_clock(std::chrono::duration<double>(t0.time_since_epoch()).count());
  renderer_->set_weave_pixel_terms(weave_terms_.pixel_terms());
  target_->bind();
  // Far away the camera circles the product; all the way in, the point it looks at up close.
  const Camera camera = dolly(scene_->scene.camera, closeup_, zoom_shown_);
  renderer_->draw(turned_about_z(camera, turn_deg, glm::mix(pivot_, camera.target, zoom_shown_)), width_, height_);
  if (exposure_.requested()) {
    const gpu::StageScope stage(gpu::Stage::metering);
    meter_frame(width_, height_);
  }
  exposure_.ease(Clock::now());
  present(Clock::now());
  if (profile_) profile_->end_frame();
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  frame_ms_.push(ms);
  since_stats_ms_.push(ms);
  if (const auto line = weave_terms_.frame(ms, renderer_->weave_drawn())) kiosk_log_info(*line);
}

void Kiosk::present(Clock::time_point now) {
  const gpu::StageScope stage(gpu::Stage::present);
  if (label_) label_->present(now);
  display_->present(*target_, exposure_.shown(), label_overlay());
  if (label_) label_->presented(Clock::now());
}

KioskDisplay::Overlay Kiosk::label_overlay() const {
  if (!label_) return {};
  return [label = label_.get()](int width, int height) { label->draw(width, height); };
}

void Kiosk::meter_as_baked() {
  target_->bind();
  const int mw = std::max(8, width_ / 4), mh = std::max(8, height_ / 4);
  renderer_->set_vertex_refresh(1);
  renderer_->set_broad_lobe_refresh(1);
  renderer_->draw(scene_->scene.camera, mw, mh);
  renderer_->refresh_all();  // kept per-vertex values are for this camera, not the next frame's
  exposure_.restart();  // shown at once, not eased in from another scene's
  non_finite_logged_ = false;
  meter_frame(mw, mh);
}

void Kiosk::meter_frame(int width, int height) {
  exposure_.meter_bound_framebuffer(width, height);
  if (exposure_.non_finite_pixels() == 0 || non_finite_logged_) return;
  non_finite_logged_ = true;
  kiosk_log_warning(std::to_string(exposure_.non_finite_pixels()) + " of " + std::to_string(exposure_.cloth_pixels()) +
                    " cloth pixels are not finite (shown black): this GPU driver evaluates a shader unlike the one it "
                    "was tested on; tests/gpu/gpu_check.sh on this machine names it, `--method sheen` avoids it");
}

}  // namespace weft
