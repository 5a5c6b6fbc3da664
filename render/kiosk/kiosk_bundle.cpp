#include "kiosk/kiosk_bundle.h"

#include <map>

#include <nlohmann/json.hpp>

#include "core/input_hash.h"
#include "gpu/scene_renderer.h"
#include "kiosk/kiosk_config_error.h"
#include "methods/registry.h"
#include "scene/scene.h"

namespace weft {

std::uint64_t bundle_fingerprint(const bundle::BundleReader& reader) {
  InputHash h;
  for (const auto& s : reader.sections()) h.add(s.name).add_integer(s.size).add_integer(s.crc);
  return h.value();
}

KioskBundle read_kiosk_bundle(const bundle::BundleReader& reader, const std::string& method) {
  KioskBundle b;
  b.scene = read_scene_bundle(reader);
  if (has_iwasaki_sections(reader) && method != "sgpoint") {
    std::map<size_t, size_t> vertices;
    for (size_t i = 0; i < b.scene.scene.objects.size(); ++i) vertices[i] = b.scene.scene.objects[i].mesh.positions.size();
    b.iwasaki = std::make_shared<IwasakiBundleData>(read_iwasaki_sections(reader, vertices));
  }
  if (reader.has("bake/selection")) b.baked_for = selected_method(reader.json("bake/selection"));
  b.fingerprint = bundle_fingerprint(reader);
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
  bool sheer = false;  // a cloth object shown as a sheer (an optical thickness of its fabric's or its own)
  for (const auto& o : bundle.scene.scene.objects)
    if (o.material == Material::cloth)
      sheer = sheer || object_fabric(o, bundle.scene.fabrics.at(o.fabric)).optical_thickness > 0.0;
  const bool searched = bundle.baked_for == "iwasaki" || bundle.baked_for == "iwasaki_vertex";
  std::string opaque = searched ? bundle.baked_for : "iwasaki_vertex";
  // The broad sky lobes by quadrature need a cell's visibility wherever the cloth is occluded: with a
  // mask for every occluded cloth object (weft bake writes them unless --no-masks), or none occluded,
  // take the quadrature rung, or the rung that reads the masks which `weft bake --choose-rung`
  // measured closer to the scene's reference.
  if (bundle.iwasaki) {
    bool masks_cover = true;
    for (const auto& [i, v] : bundle.iwasaki->visibility)
      if (i < bundle.scene.scene.objects.size() && bundle.scene.scene.objects[i].material == Material::cloth)
        masks_cover = masks_cover && bundle.iwasaki->masks.count(i);
    if (masks_cover) {
      const methods::RuntimeMethod* chosen = methods::find_method(bundle.baked_for);
      const bool measured = chosen && chosen->visibility_masks && chosen->seed000 == methods::Seed000Tables::required &&
                            !chosen->see_through;
      opaque = measured ? chosen->name : opaque == "iwasaki" ? "iwasaki_quadrature" : "iwasaki_vertex_quadrature";
    }
  }
  const methods::RuntimeMethod& m = gpu::parse_method(method != "auto" ? method
                                                      : bundle.iwasaki ? (sheer ? "sheer_vertex" : opaque)
                                                                       : "sgpoint");
  if (gpu::uses_seed000_tables(m) && !bundle.iwasaki)
    throw KioskConfigError("--method " + m.name + ": bundle " + file.string() +
                           " has no seed 000 tables (weft bake without --no-tables)");
  return m;
}

}  // namespace weft
