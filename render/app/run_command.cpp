// `weft run`: the kiosk (render/kiosk/kiosk.h; usage and measurements in render/kiosk/README.md).
// This file turns the flags into a KioskConfig and runs the kiosk until SIGTERM or SIGINT.
#include <atomic>
#include <csignal>
#include <cstdlib>

#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/option_spelling.h"
#include "kiosk/kiosk.h"
#include "kiosk/kiosk_config_error.h"
#include "kiosk/kiosk_status_file.h"

namespace weft {
namespace {

std::atomic<bool> g_stop{false};

int run_kiosk(const KioskConfig& config) {
  // From the start: a SIGTERM while booting still ends in the loop's clean exit path.
  std::signal(SIGINT, [](int) { g_stop = true; });
  std::signal(SIGTERM, [](int) { g_stop = true; });
  try {
    Kiosk kiosk(config);
    return kiosk.run(g_stop);
  } catch (const KioskConfigError& e) {
    throw UsageError(e.what());
  }
}

}  // namespace

CommandAction add_run_command(CLI::App& app) {
  auto a = std::make_shared<KioskConfig>();
  CLI::App* sub = app.add_subcommand("run", "The kiosk: show a baked bundle fullscreen (or headless) with the knob panel");
  sub->add_option("--bundle", a->bundle, "Scene bundle (weft bake)")->required();
  sub->add_option("--state-dir", a->state_dir, "Knob state and last good bundle")->capture_default_str();
  sub->add_option("--display", a->display, "auto (KMS, taking screens as they are plugged; without a display card, headless), kms (as auto, but exit when there is no screen at start) or headless")->capture_default_str();
  sub->add_option("--frames", a->frames, "Stop after this many ticks (display refreshes); 0: until SIGTERM")
      ->capture_default_str();
  sub->add_option("--turntable", a->turntable, "Camera turn, degrees per second (0: still)")->capture_default_str();
  sub->add_option("--zoom", a->zoom, "Start the camera this share of the way to the scene's close-up (0: its view, 1: the close-up; the zoom knob adds to it)")->capture_default_str();
  CLI::Option* panel =
      sub->add_option("--panel", a->panel,
                      "Knobs: hid, gpio, keyboard, sim:SCRIPT (simulated USB panel) or none; default: the panel "
                      "config's sources, else hid")
          ->capture_default_str();
  sub->add_option("--panel-config", a->panel_config, "Panel configuration (JSON: hid ids, gpio lines, sources)");
  sub->add_option("--sim-speed", a->sim_speed, "Play the sim: script this many times faster")->capture_default_str();
  sub->add_option("--screenshot", a->screenshot, "Write the last frame, tone-mapped, as PNG");
  sub->add_option("--width", a->size[0], "Headless frame width")->check(CLI::Range(8, 8192))->capture_default_str();
  sub->add_option("--height", a->size[1], "Headless frame height")->check(CLI::Range(8, 8192))->capture_default_str();
  old_spelling(sub->add_option_function<std::vector<int>>("--size", [a](const std::vector<int>& wh) { a->size[0] = wh[0], a->size[1] = wh[1]; })
                   ->expected(2));
  sub->add_option("--method", a->method, "Runtime method: auto (with weighting tables: sheer_vertex if a cloth object is a sheer, else iwasaki_vertex_quadrature where masks cover the occluded cloth (weft bake writes them unless --no-masks) or none is occluded (iwasaki_vertex_mask_quadrature where weft bake --choose-rung measured it closer), else iwasaki_vertex; iwasaki or iwasaki_quadrature where the bake's --target-error search chose per pixel; sgpoint without tables), iwasaki (per pixel), iwasaki_vertex (per vertex: same tables, a fraction of the cost), iwasaki_mask or iwasaki_vertex_mask (visibility from the bundle's masks), iwasaki_quadrature or iwasaki_vertex_quadrature (the broad sky lobes by quadrature per vertex, visibility from the masks), iwasaki_mask_quadrature or iwasaki_vertex_mask_quadrature (the same, the sharper lobes with the masks' visibility too), sheer, sheer_vertex (a sheer over what lies behind) or sgpoint")->capture_default_str();
  sub->add_option("--stats-every", a->stats_every, "Seconds between stats lines (frames, ms/frame, memory); 0: none")
      ->capture_default_str();
  sub->add_option("--vertex-refresh", a->vertex_refresh,
                  "While only the turntable moves, recompute the cloth's per-vertex shading over at least this many frames "
                  "(each frame a share, kept values carried on to the frame's time; knob, light and zoom changes "
                  "recompute all at once); 1: as --vertex-refresh-deg says")
      ->capture_default_str();
  sub->add_option("--vertex-refresh-deg", a->vertex_refresh_deg,
                  "While only the turntable moves, recompute the cloth's per-vertex shading once per this many degrees of "
                  "turn, a share each frame (with --vertex-refresh 1 and this 0: every vertex every frame)")
      ->capture_default_str();
  sub->add_option("--broad-lobe-refresh-deg", a->broad_lobe_refresh_deg,
                  "While only the turntable moves, recompute the broad sky lobes' quadrature (the part of the per-vertex "
                  "shading that changes slowly with the view) once per this many degrees of turn, a share each frame; "
                  "the sharper lobes follow --vertex-refresh and --vertex-refresh-deg; 0: every frame")
      ->capture_default_str();
  sub->add_option("--weave-terms", a->weave_terms,
                  "Up close over a per-vertex rung, each float of the weave lit per pixel (pixel: close to the resolved "
                  "model), from a per-vertex table (table: a fraction of the cost, coarser), or auto: per pixel while the "
                  "frames that show threads stay within --weave-budget, else the table for the rest of the run")
      ->check(CLI::IsMember({"auto", "pixel", "table"}))
      ->capture_default_str();
  sub->add_option("--weave-budget", a->weave_budget_ms,
                  "Milliseconds a frame (median of 8 that show threads) the per-pixel weave may take under --weave-terms auto")
      ->check(CLI::Range(1.0, 10000.0))
      ->capture_default_str();
  sub->add_option("--profile", a->profile,
                  "Per-stage frame profile in the stats lines (backdrop, surfaces, vertex passes, cloth, weave, "
                  "metering, present): off, auto (GPU timer queries where a hardware driver has them, else CPU time), gpu or cpu")
      ->capture_default_str();
  sub->add_option("--exposure-bias", a->exposure_bias, "EV added to the exposure metered on the cloth (+1: twice as bright)")
      ->capture_default_str();
  sub->add_option("--exposure", a->exposure, "Multiplier on the metered exposure: the same as --exposure-bias log2(X)")
      ->capture_default_str();
  sub->add_option("--probe", a->probe, "Light probe: none, camera[:ID] (libcamera) or mock:MAP.exr[,MAP.exr...]")
      ->capture_default_str();
  sub->add_option("--probe-switch", a->probe_switch_s, "Mock probe with several maps: seconds between switching them");
  sub->add_option("--label", a->label,
                  "The fabric's name, colourway and composition in a corner of the screen, fading out while the knobs "
                  "are idle and back on any change: on or off (weft.service: on, WEFT_LABEL)")
      ->capture_default_str();
  sub->add_option("--label-position", a->label_position, "The label's corner: bottom-left, bottom-right, top-left or top-right")
      ->capture_default_str();
  sub->add_option("--label-size", a->label_size, "The label's name in pixels (8-256); its other lines are 0.7 of it")
      ->capture_default_str();
  sub->add_option("--label-idle", a->label_idle_s,
                  "Seconds the label stays after start or a knob change before it fades out over a second (0: never fades)")
      ->capture_default_str();
  sub->add_option("--idle-return", a->idle_return_s,
                  "Seconds without a knob change after which the look eases back to the bundle's fabric over 3 s "
                  "(the knob state file too); 0: it stays as the knobs left it")
      ->capture_default_str();
  sub->add_option("--screen-off", a->screen_off,
                  "Daily period in local time, HH:MM-HH:MM (e.g. 22:00-07:30), during which the screen is powered "
                  "down (DPMS) and nothing is drawn; empty: never");
  sub->add_option("--label-font", a->label_font, "The label's font file (TrueType or OpenType)")->capture_default_str();
  sub->add_option("--connector", a->connector,
                  "The screen's connector, as /sys/class/drm names it (HDMI-A-1, DP-2, ...); empty: the first connected "
                  "(weft.service: WEFT_CONNECTOR)");
  sub->add_option("--mode", a->mode, "The screen's mode: WIDTHxHEIGHT or WIDTHxHEIGHT@HZ; empty or preferred: the monitor's own "
                                     "(weft.service: WEFT_MODE)");
  sub->add_option("--rotation", a->rotation,
                  "The picture turned clockwise on the screen for one mounted turned: 0, 90, 180 or 270 degrees "
                  "(weft.service: WEFT_ROTATION)")
      ->capture_default_str();
  sub->add_option("--display-wait", a->display_wait_s,
                  "Seconds without a screen (from start, or since it was unplugged) before the kiosk reports it: a "
                  "journal warning, the service status, `weft status`; 0: never (weft.service: WEFT_DISPLAY_WAIT)")
      ->capture_default_str();
  // Under systemd the RuntimeDirectory holds it (weft status reads it there); elsewhere none unless asked for.
  if (std::getenv("RUNTIME_DIRECTORY")) a->status_file = default_status_path().string();
  sub->add_option("--status-file", a->status_file, "Health file for `weft status` and a fleet (JSON, rewritten every 2 s); empty: none")
      ->capture_default_str();
  return [a, panel] {
    KioskConfig config = *a;
    if (panel->count() == 0) config.panel.clear();  // the panel config's sources decide
    return run_kiosk(config);
  };
}

}  // namespace weft
