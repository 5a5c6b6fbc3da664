#pragma once
// What `weft bundle info` and `weft bundle verify` say about a scene bundle file: the kiosk's own
// checks (a full verification, then the sections read as the kiosk reads them, kiosk/kiosk_bundle.h)
// and, for a bundle that passes them, what it holds: scene, objects, fabrics, the methods the kiosk
// can draw it with, sections and the bake's settings and measured errors. Presented as text or
// JSON by bundle_report_text.h and bundle_report_json.h.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bundle/bundle_reader.h"

namespace weft {

// The kiosk's verdict on a bundle file (kiosk/kiosk_bundle.h: read_kiosk_bundle, kiosk_method).
struct BundleVerdict {
  std::string file;
  bool ok = false;
  // When refused: the part at fault ("header", "section table", "file", "section 'NAME'", or
  // "method" when the bundle lacks what the asked method needs), that section's name or "", and
  // the whole message, which names the file.
  std::string part, section, message;
  std::string method;  // when accepted: the method the kiosk draws it with
};

struct ObjectReport {
  std::string name;
  std::string material;           // material_name (scene/object_schema.h): "cloth" or "lambertian"
  std::string fabric;             // cloth: its preset
  double optical_thickness = 0;   // cloth: > 0 when shown as a sheer (its own or its fabric's)
  std::optional<std::array<double, 3>> colour;  // cloth: the product's colour on its fabric, when it has one
  std::size_t vertices = 0, triangles = 0;
};

// One colourway: the look it gives each cloth object it names (object → fabric, colour).
struct ColourwayReport {
  std::string name;
  struct Look {
    std::string object, fabric;
    std::optional<std::array<double, 3>> colour;
  };
  std::vector<Look> looks;
};

// One runtime method of the registry and whether the kiosk can draw this bundle with it.
struct MethodReport {
  std::string name;
  bool kiosk_rung = false;  // --method auto may choose it
  bool drawable = false;
  std::string refusal;      // why not, when not drawable
};

struct BundleReport {
  std::string file;
  std::uint64_t bytes = 0;
  std::uint32_t format_version = 0;
  std::string scene, description, environment;
  std::vector<ObjectReport> objects;
  std::vector<std::string> fabrics;     // the presets the bundle stores (the fabric knob's choices)
  std::vector<ColourwayReport> colourways;  // in the bundle's order; the kiosk's colourway button cycles them
  std::size_t sgs = 0;                  // default lighting
  std::string auto_method;              // what `weft run --method auto` draws
  std::vector<MethodReport> methods;    // the registry's order
  std::vector<bundle::SectionInfo> sections;
  // Each `bake/<stage>` section's JSON by stage (T, vis, kappa, mask, selection, ...): the bake's
  // settings and the errors it measured (BUNDLE_FORMAT.md).
  std::map<std::string, nlohmann::json> bake;
};

// The kiosk's checks on `file` with `method` (auto or a registry name; an unknown name throws
// std::invalid_argument). Never throws for a bad bundle: the verdict says what is wrong.
BundleVerdict verify_bundle(const std::filesystem::path& file, const std::string& method = "auto");

// The report on a bundle the kiosk accepts; throws bundle::BundleError naming the file and the
// part at fault otherwise.
BundleReport bundle_report(const std::filesystem::path& file);

}  // namespace weft
