#include "kiosk/kiosk_bundle.h"

#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "hashing/fnv1a_hash.h"
#include "kiosk/kiosk_config_error.h"
#include "gpu/scene_renderer.h"
#include "methods/registry.h"
#include "scene/scene.h"

namespace weft {

namespace {

// The first of the kiosk's rungs (RuntimeMethod::kiosk_rung), in the registry's order, whose traits fit.
template <class Fits>
const methods::RuntimeMethod& kiosk_rung(Fits fits) {
  for (const auto& m : methods::registry())
    if (m.kiosk_rung && fits(m)) return m;
  throw std::logic_error("the method registry has no kiosk rung for this bundle");
}

// Opaque cloth shaded with the weighting tables.
bool opaque_with_tables(const methods::RuntimeMethod& m) { return m.needs_weighting_tables() && !m.see_through; }

// Drawn without the weighting tables: opaque, and nothing the bundle's bake adds.
const methods::RuntimeMethod& tableless_rung() {
  return kiosk_rung([](const methods::RuntimeMethod& m) {
    return !m.reads_weighting_tables() && !m.see_through && !m.reads_visibility_masks();
  });
}

// Every occluded cloth object has a visibility mask (weft bake writes them unless --no-masks), or
// none is occluded.
bool masks_cover_occluded_cloth(const KioskBundle& bundle) {
  if (!bundle.baked.tables) return false;
  for (size_t i : bundle.baked.visibility)
    if (i < bundle.scene.scene.objects.size() && bundle.scene.scene.objects[i].is_cloth() && !bundle.baked.masks.count(i))
      return false;
  return true;
}

// --method auto (header).
const methods::RuntimeMethod& auto_method(const KioskBundle& bundle) {
  using methods::RuntimeMethod, methods::Shading;
  if (!bundle.baked.tables) return tableless_rung();
  bool sheer = false;  // a cloth object shown as a sheer (an optical thickness of its fabric's or its own)
  for (const auto& o : bundle.scene.scene.cloth_objects())
    sheer = sheer || object_fabric(o, bundle.scene.fabrics.at(o.fabric)).optical_thickness > 0.0;
  if (sheer)
    return kiosk_rung([](const RuntimeMethod& m) {
      return m.see_through && m.needs_weighting_tables() && m.shading == Shading::per_vertex && !m.reads_visibility_masks();
    });
  // The bake's search chose an opaque rung without masks (per pixel or per vertex): its shading;
  // else per vertex.
  const RuntimeMethod* chosen = methods::find_method(bundle.baked_for);
  const Shading shading =
      chosen && opaque_with_tables(*chosen) && !chosen->reads_visibility_masks() ? chosen->shading : Shading::per_vertex;
  // The broad sky lobes by quadrature need a cell's visibility wherever the cloth is occluded: with a
  // mask for every occluded cloth object (weft bake writes them unless --no-masks), or none occluded,
  // take the quadrature rung, or the rung that reads the masks which `weft bake --choose-rung`
  // measured closer to the scene's reference.
  if (!masks_cover_occluded_cloth(bundle))
    return kiosk_rung([&](const RuntimeMethod& m) {
      return opaque_with_tables(m) && m.shading == shading && !m.reads_visibility_masks();
    });
  if (chosen && opaque_with_tables(*chosen) && chosen->reads_visibility_masks()) return *chosen;
  return kiosk_rung([&](const RuntimeMethod& m) {
    return opaque_with_tables(m) && m.shading == shading && m.masks.broad_lobes && !m.masks.open_share;
  });
}

}  // namespace

std::uint64_t bundle_fingerprint(const bundle::BundleReader& reader) {
  InputHash h;
  for (const auto& s : reader.sections()) h.add(s.name).add_integer(s.size).add_integer(s.crc);
  return h.value();
}

KioskBundle read_kiosk_bundle(const bundle::BundleReader& reader, const std::string& method) {
  KioskBundle b;
  b.scene = read_scene_bundle(reader);
  b.baked = read_shading_contents(reader);
  if (reader.has("bake/selection")) b.baked_for = selected_method(reader.json("bake/selection"));
  b.fingerprint = bundle_fingerprint(reader);
  // The payload the method draws with reads, nothing else (an unknown name: the caller's mistake,
  // reported by kiosk_method).
  const methods::RuntimeMethod* m = method == "auto" ? &auto_method(b) : methods::find_method(method);
  const ShadingParts parts = m ? gpu::frame_bake_reads(*m) : ShadingParts::none();
  if (b.baked.tables && parts.any())
    b.shading = std::make_shared<ShadingData>(read_scene_shading_data(reader, b.scene.scene, parts));
  return b;
}

std::string selected_method(std::string_view selection_json) {
  const auto j = nlohmann::json::parse(selection_json, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return {};
  const auto at = j.find("method");
  return at != j.end() && at->is_string() ? at->get<std::string>() : std::string();
}

const methods::RuntimeMethod& kiosk_method(const std::string& method, const KioskBundle& bundle,
                                           const std::filesystem::path& file) {
  const methods::RuntimeMethod& m = method != "auto" ? methods::method(method) : auto_method(bundle);
  if (m.needs_weighting_tables() && !bundle.baked.tables)
    throw KioskConfigError("--method " + m.name + ": bundle " + file.string() +
                           " has no weighting tables (weft bake without --no-tables)");
  // The masks' open share replaces the SDF's visibility: an occluded cloth object needs its mask.
  if (m.masks.open_share && bundle.baked.tables && !masks_cover_occluded_cloth(bundle))
    throw KioskConfigError("--method " + m.name + ": bundle " + file.string() +
                           " has no visibility mask for its occluded cloth (weft bake without --no-masks)");
  return m;
}

}  // namespace weft
