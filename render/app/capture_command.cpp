// `weft capture`: the printed card (--card), simulated photos of a known fabric (--simulate), and
// a fabric file fitted to photos of the card (DIR --out F); docs/capture.md.
#include <iostream>
#include <memory>
#include <optional>

#include "app/asset_paths.h"
#include "app/cli_parse.h"
#include "app/commands.h"
#include "app/progress_bar.h"
#include "capture/appearance_check.h"
#include "capture/capture_card.h"
#include "capture/capture_fit.h"
#include "capture/capture_rejection.h"
#include "capture/capture_report.h"
#include "capture/capture_simulation.h"
#include "journal/journal_log.h"
#include "lighting/env_map.h"

namespace weft {

namespace {

struct CaptureArgs {
  std::string photos_dir, card_out, simulate, map, out, truth_out, report, check_map, truth;
  int dpi = 600, photos = 4, width = 1024, height = 768;
  unsigned seed = 1;
  int jpeg_quality = CaptureSimulationOptions{}.jpeg_quality;
};

EnvMap load_named_map(const std::string& name) {
  try {
    return load_env_map(env_map_file(name, assets_dir() / "envmaps"), NonFinitePolicy::clamp);
  } catch (const EnvMapError& e) {
    throw UsageError(e.what());
  }
}

int run_card(const CaptureArgs& a) {
  if (a.dpi < 50 || a.dpi > 1200) throw UsageError("--dpi: must be in [50, 1200], got " + std::to_string(a.dpi));
  write_card_png(a.card_out, a.dpi);
  std::cout << "wrote " << a.card_out << " (print at " << a.dpi << " dpi, 100 % scale)\n";
  return 0;
}

int run_simulate(const CaptureArgs& a) {
  if (a.map.empty()) throw UsageError("--simulate needs --map MAP (a name in assets/envmaps or an .exr)");
  if (a.out.empty()) throw UsageError("--simulate needs --out DIR");
  if (a.photos < 1 || a.photos > 64) throw UsageError("--photos: must be in [1, 64], got " + std::to_string(a.photos));
  if (a.width < 320 || a.height < 240 || a.width > 8192 || a.height > 8192)
    throw UsageError("--width/--height: from 320×240 to 8192×8192");
  const Fabric fabric = load_fabric_named(a.simulate, assets_dir() / "fabrics");
  const EnvMap map = load_named_map(a.map);
  CaptureSimulationOptions o;
  o.photos = a.photos;
  o.seed = a.seed;
  o.jpeg_quality = a.jpeg_quality;
  o.width = a.width;
  o.height = a.height;
  o.progress = open_progress_bar("simulate");
  simulate_capture(fabric, map, o, a.out, a.truth_out.empty() ? std::nullopt : std::optional<std::filesystem::path>(a.truth_out));
  std::cout << "wrote " << a.photos << " photos and capture.json to " << a.out << "\n";
  return 0;
}

int run_fit(const CaptureArgs& a) {
  if (a.out.empty()) throw UsageError("a fit needs --out FITTED.json");
  if (a.check_map.empty() != a.truth.empty()) throw UsageError("--check-map and --truth go together");
  // Loaded before the fit so that a bad name fails at once.
  std::optional<Fabric> truth;
  EnvMap check_map;
  if (!a.check_map.empty()) {
    truth = load_fabric_named(a.truth, assets_dir() / "fabrics");
    check_map = load_named_map(a.check_map);
  }
  const std::filesystem::path out(a.out);
  const std::filesystem::path report = a.report.empty() ? out.parent_path() / (out.stem().string() + "_side_by_side.png")
                                                        : std::filesystem::path(a.report);
  CaptureFitOptions o;
  o.open_progress = [](const std::string& stage) { return open_progress_bar(stage); };
  CaptureFitResult r;
  try {
    r = fit_capture(a.photos_dir, assets_dir() / "fabrics", o);
  } catch (const CaptureRejection& e) {
    log_line("weft capture", LogPriority::error, std::string("rejected: ") + e.what());
    return 2;
  }
  std::optional<AppearanceCheck> check;
  if (truth) check = check_appearance(*truth, r.fit.fabric, check_map, a.check_map);
  write_fitted_fabric(r, assets_dir() / "fabrics", out, check);
  write_side_by_side(r, report);
  std::cout << fit_summary(r, check);
  std::cout << "wrote " << out.string() << " and " << report.string() << "\n";
  return 0;
}

int run_capture(const CaptureArgs& a) {
  const int modes = !a.card_out.empty() + !a.simulate.empty() + !a.photos_dir.empty();
  if (modes != 1) throw UsageError("give exactly one of --card OUT.png, --simulate FABRIC or a photo folder DIR");
  if (!a.card_out.empty()) return run_card(a);
  if (!a.simulate.empty()) return run_simulate(a);
  return run_fit(a);
}

}  // namespace

CommandAction add_capture_command(CLI::App& app) {
  auto a = std::make_shared<CaptureArgs>();
  CLI::App* sub = app.add_subcommand(
      "capture", "Fit a fabric file to photos of a swatch on the printed capture card beside a mirror ball");
  sub->footer(
      "Examples:\n"
      "  weft capture --card card.png\n"
      "  weft capture --simulate linen_plain --map interior --out shots/ --photos 4\n"
      "  weft capture shots/ --out fitted.json\n"
      "  weft capture shots/ --out fitted.json --truth linen_plain --check-map courtyard\n"
      "Exit codes: 0 ok, 1 runtime failure, 2 bad usage or unusable photos (no card, saturated or\n"
      "blurred, too few swatch turns).");
  sub->add_option("dir", a->photos_dir,
                  "Folder of photos (JPEG or PNG), capture.json and, optionally, closeup.jpg (the swatch from straight above, "
                  "its threads resolved; with the card's scale tag, id 5, in a corner it also gives the ends and picks per cm and "
                  "each thread's colour where the weave puts it) to fit");
  sub->add_option("--card", a->card_out, "Write the capture card to this PNG, for printing");
  sub->add_option("--dpi", a->dpi, "The card's print resolution")->capture_default_str();
  sub->add_option("--simulate", a->simulate, "Photograph this fabric (a preset name or a .json file) on a simulated card");
  sub->add_option("--map", a->map, "--simulate: the environment map that lights it (a name in assets/envmaps or an .exr)");
  sub->add_option("--out", a->out, "--simulate: the folder for the photos; a fit: the fabric file to write");
  sub->add_option("--photos", a->photos, "--simulate: how many photos (the swatch turned by 180°/N between them)")->capture_default_str();
  sub->add_option("--seed", a->seed, "--simulate: the random seed (poses, noise)")->capture_default_str();
  sub->add_option("--jpeg-quality", a->jpeg_quality, "--simulate: the photos' JPEG quality (a camera's finest setting by default)")->check(CLI::Range(50, 100))->capture_default_str();
  sub->add_option("--width", a->width, "--simulate: photo width")->capture_default_str();
  sub->add_option("--height", a->height, "--simulate: photo height")->capture_default_str();
  sub->add_option("--report", a->report, "A fit: the side-by-side PNG (photo, fitted render, difference ×4); default OUT_side_by_side.png");
  sub->add_option("--check-map", a->check_map,
                  "A fit, with --truth: render the fitted fabric and the truth under this map (a name in "
                  "assets/envmaps or an .exr) and report their relative RMSE; a check for simulated captures only");
  sub->add_option("--truth", a->truth,
                  "A fit, with --check-map: the fabric the photos were simulated from (a preset name or a .json file)");
  sub->add_option("--truth-out", a->truth_out, "--simulate: also write what was simulated (fabric, turns, poses, response) as JSON");
  return [a] { return run_capture(*a); };
}

}  // namespace weft
