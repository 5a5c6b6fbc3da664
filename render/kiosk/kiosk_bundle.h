#pragma once
// A scene bundle as the kiosk shows it: what it reads from a verified bundle (the scene, every
// fabric preset, what the bake holds, and of its shading data the parts its method reads),
// the runtime method it draws with, and a fingerprint of the content. Read at boot (through the last-good fallback)
// and for each content update (kiosk/bundle_watcher.h), the same way both times.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "bundle/bundle_reader.h"
#include "methods/registry.h"
#include "runtime/shading_data.h"
#include "runtime/scene_bundle.h"

namespace weft {

struct KioskBundle {
  SceneBundle scene;
  ShadingContents baked;                       // what the bake holds (its indices)
  // The parts of it the method reads (gpu::frame_bake_reads); null: none baked, or none read.
  std::shared_ptr<const ShadingData> shading;
  std::uint64_t fingerprint = 0;                     // of the section table: equal content, equal value
  // The method `weft bake --target-error` or `--choose-rung` measured (bake/selection); empty: none.
  std::string baked_for;
};

// The "method" a bake/selection section records; empty when the text has none or is not JSON
// (readers may ignore that section).
std::string selected_method(std::string_view selection_json);

// Reads what the kiosk needs; `method` is --method (auto, or a registry name), whose reads decide
// which of the bake's parts are loaded. Throws bundle::BundleError naming the section when
// something is missing or invalid.
KioskBundle read_kiosk_bundle(const bundle::BundleReader& reader, const std::string& method);

// The method for a bundle: --method, or for auto the first of the registry's kiosk rungs
// (RuntimeMethod::kiosk_rung) whose traits fit the bundle: without weighting tables, one that needs
// none; with them, a see-through per-vertex rung if a cloth object is a sheer; else an opaque rung
// with the shading (per pixel or per vertex) of the one the bake's search chose (per vertex when
// none), which where the bundle's masks cover the occluded cloth is the mask-reading rung
// `weft bake --choose-rung` chose (baked_for), or the one taking the broad lobes by quadrature over
// the masks, and elsewhere the one reading no masks. Throws KioskConfigError when the method needs
// tables or visibility masks the bundle lacks: `weft bundle info` lists the methods a bundle can
// draw by asking this for each.
const methods::RuntimeMethod& kiosk_method(const std::string& method, const KioskBundle& bundle,
                                           const std::filesystem::path& file);

// A fingerprint of a verified bundle's content: its sections' names, sizes and checksums.
std::uint64_t bundle_fingerprint(const bundle::BundleReader& reader);

}  // namespace weft
