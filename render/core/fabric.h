#pragma once
// A woven fabric: two threads with their scattering parameters and tangent curves (Table II).
// Presets are JSON files in assets/fabrics/ (format: assets/fabrics/README.md).
#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/microcylinder.h"

namespace weft {

// The weave's structure and physical size (core/weave_layout.h draws it). Counts are the yarns
// per centimetre: ends (warp yarns, counted along t) and picks (weft yarns, counted along s).
struct WeaveSpec {
  int rows = 0;   // warp yarns in one repeat; 0: chosen from the threads' coverages
  int shift = 0;  // rows a float's start moves by from one row to the next (with rows)
  double ends_per_cm = kDefaultThreadsPerCm, picks_per_cm = kDefaultThreadsPerCm;
  static constexpr double kDefaultThreadsPerCm = 30.0;
  static constexpr int kMaxRows = 64;
  static constexpr double kMaxThreadsPerCm = 1000.0;
};

struct Fabric {
  std::string name;
  // What a shopper reads on the kiosk's label (both optional, from the fabric file): the name to
  // show (empty: `name`) and the composition ("100 % linen").
  std::string display_name, composition;
  std::array<ThreadParams, 2> threads;  // [0] = warp (thread 1), [1] = weft (thread 2)
  // The optical thickness τ of the cloth as a thin layer (direct transmission e^{−τ/μ}):
  // > 0 marks a sheer (voile, net) that shows what lies behind it; 0 (the Table II presets) is a
  // fabric with no thickness of its own, which see-through methods draw at their default τ.
  double optical_thickness = 0.0;
  WeaveSpec weave;
  // Each thread's `albedo_scale` from the file: a product colour given in place of the file's
  // `albedo` (product_coloured) is scaled by it, so the fabric keeps its brightness per thread.
  std::array<double, 2> albedo_scale{1.0, 1.0};
  // The file's `pin_colour`: its threads keep their own colour whatever the product asks for.
  bool pin_colour = false;
};

// `fabric` with a product's colour (linear RGB in [0, 1], e.g. glTF's baseColorFactor) on both
// threads, each at its own albedo_scale: the fabric gives the weave, gloss and thread structure,
// the product the colour. A fabric that pins its colour is returned as it is.
Fabric product_coloured(Fabric fabric, const dvec3& colour);
// Longest display_name or composition a fabric file (or a glTF material) may give, in bytes: a
// label is a few words.
inline constexpr std::size_t kMaxFabricTextBytes = 120;
// Why `text` cannot be a display_name or composition (too long, a control character: one line),
// or empty when it can.
std::string fabric_text_problem(const std::string& text);

// Largest optical thickness a fabric file, scene or glTF may give: e^{−20} leaves nothing to see.
inline constexpr double kMaxOpticalThickness = 20.0;

// A fabric file that cannot be used. what() names the file, the field and the value.
class FabricError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Parses and validates a fabric from JSON text; `origin` names it in errors.
Fabric parse_fabric(const std::string& json_text, const std::string& origin);
Fabric load_fabric(const std::filesystem::path& file);
// Looks a preset up by name in `dir` (`<dir>/<name>.json`).
Fabric load_fabric_preset(const std::string& name, const std::filesystem::path& dir);
std::vector<std::string> list_fabric_presets(const std::filesystem::path& dir);
// True when `name` is a fabric file path rather than a preset name: it has a directory part or
// ends in .json.
bool names_fabric_file(const std::string& name);
// A fabric as the command line or a scene names it: a file path (names_fabric_file) or a preset in `dir`.
Fabric load_fabric_named(const std::string& name, const std::filesystem::path& dir);
// The fabric file's text as stored in a bundle: the file itself, or `<dir>/<name>.json`.
std::filesystem::path fabric_file(const std::string& name, const std::filesystem::path& dir);

}  // namespace weft
