#include "inspect/bundle_report.h"

#include "kiosk/kiosk_bundle.h"
#include "kiosk/kiosk_config_error.h"
#include "methods/registry.h"
#include "scene/object_schema.h"

namespace weft {

namespace {

// The `bake/<stage>` sections' JSON; a text that does not parse (readers may ignore
// bake/selection) is kept as a string.
std::map<std::string, nlohmann::json> bake_sections(const bundle::BundleReader& reader) {
  std::map<std::string, nlohmann::json> out;
  const std::string prefix = "bake/";
  for (const auto& s : reader.sections()) {
    if (s.name.rfind(prefix, 0) != 0 || s.type != bundle::ElementType::Json) continue;
    const std::string_view text = reader.json(s.name);
    auto j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    out[s.name.substr(prefix.size())] = j.is_discarded() ? nlohmann::json(std::string(text)) : std::move(j);
  }
  return out;
}

ObjectReport object_report(const SceneObject& o, const SceneBundle& scene) {
  ObjectReport r;
  r.name = o.name;
  r.material = material_name(o.material);
  if (o.is_cloth()) {
    r.fabric = o.fabric;
    r.optical_thickness = object_fabric(o, scene.fabrics.at(o.fabric)).optical_thickness;
    if (o.colour) r.colour = std::array<double, 3>{o.colour->r, o.colour->g, o.colour->b};
  }
  r.vertices = o.mesh.positions.size();
  r.triangles = o.mesh.triangles.size();
  return r;
}

}  // namespace

BundleVerdict verify_bundle(const std::filesystem::path& file, const std::string& method) {
  if (method != "auto") methods::method(method);  // an unknown name is the caller's mistake
  BundleVerdict v;
  v.file = file.string();
  try {
    const bundle::BundleReader reader = bundle::BundleReader::read(file);
    const KioskBundle b = read_kiosk_bundle(reader, method);
    v.method = kiosk_method(method, b, file).name;
    v.ok = true;
  } catch (const bundle::BundleError& e) {
    v.part = e.part();
    v.section = e.section();
    v.message = e.what();
  } catch (const KioskConfigError& e) {
    v.part = "method";
    v.message = e.what();
  }
  return v;
}

BundleReport bundle_report(const std::filesystem::path& file) {
  const bundle::BundleReader reader = bundle::BundleReader::read(file);
  const KioskBundle b = read_kiosk_bundle(reader, "auto");
  BundleReport r;
  r.file = file.string();
  r.bytes = reader.bytes().size();
  r.format_version = reader.format_version();
  const Scene& scene = b.scene.scene;
  r.scene = scene.name;
  r.description = scene.description;
  r.environment = scene.environment;
  for (const auto& o : scene.objects) r.objects.push_back(object_report(o, b.scene));
  for (const auto& [preset, fabric] : b.scene.fabrics) r.fabrics.push_back(preset);
  for (const Colourway& c : b.scene.scene.colourways) {
    ColourwayReport cr;
    cr.name = c.name;
    for (const auto& [object, look] : c.objects) {
      ColourwayReport::Look l{object, look.fabric, std::nullopt};
      if (look.colour) l.colour = std::array<double, 3>{look.colour->r, look.colour->g, look.colour->b};
      cr.looks.push_back(l);
    }
    r.colourways.push_back(std::move(cr));
  }
  r.sgs = b.scene.sgs.size();
  r.auto_method = kiosk_method("auto", b, file).name;
  for (const auto& m : methods::registry()) {
    MethodReport mr{m.name, m.kiosk_rung, true, {}};
    try {
      kiosk_method(m.name, b, file);
    } catch (const KioskConfigError& e) {
      mr.drawable = false;
      mr.refusal = e.what();
    }
    r.methods.push_back(std::move(mr));
  }
  r.sections = reader.sections();
  r.bake = bake_sections(reader);
  return r;
}

}  // namespace weft
