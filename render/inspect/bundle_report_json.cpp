#include "inspect/bundle_report_json.h"

#include "bundle/bundle_format.h"
#include "scene/object_schema.h"

namespace weft {

namespace {

nlohmann::json text_or_null(const std::string& s) { return s.empty() ? nlohmann::json() : nlohmann::json(s); }

nlohmann::json object_json(const ObjectReport& o, std::size_t index) {
  const bool cloth = o.material == material_name(Material::cloth);
  return {{"index", index},
          {"name", o.name},
          {"material", o.material},
          {"fabric", cloth ? nlohmann::json(o.fabric) : nlohmann::json()},
          {"optical_thickness", cloth ? nlohmann::json(o.optical_thickness) : nlohmann::json()},
          {"colour", o.colour ? nlohmann::json(*o.colour) : nlohmann::json()},
          {"vertices", o.vertices},
          {"triangles", o.triangles}};
}

nlohmann::json section_json(const bundle::SectionInfo& s) {
  return {{"name", s.name},
          {"type", std::string(bundle::element_type_name(s.type))},
          {"shape", s.shape},
          {"offset", s.offset},
          {"bytes", s.size},
          {"crc32c", s.crc}};
}

}  // namespace

nlohmann::json to_json(const BundleReport& r) {
  nlohmann::json objects = nlohmann::json::array(), methods = nlohmann::json::array(),
                 sections = nlohmann::json::array(), bake = nlohmann::json::object();
  for (std::size_t i = 0; i < r.objects.size(); ++i) objects.push_back(object_json(r.objects[i], i));
  for (const auto& m : r.methods)
    methods.push_back({{"name", m.name}, {"kiosk_rung", m.kiosk_rung}, {"drawable", m.drawable},
                       {"refusal", text_or_null(m.refusal)}});
  for (const auto& s : r.sections) sections.push_back(section_json(s));
  nlohmann::json colourways = nlohmann::json::array();
  for (const auto& c : r.colourways) {
    nlohmann::json looks = nlohmann::json::object();
    for (const auto& l : c.looks) looks[l.object] = {{"fabric", l.fabric}, {"colour", l.colour ? nlohmann::json(*l.colour) : nlohmann::json()}};
    colourways.push_back({{"name", c.name}, {"objects", looks}});
  }
  for (const auto& [stage, j] : r.bake) bake[stage] = j;
  return {{"file", r.file},
          {"bytes", r.bytes},
          {"format_version", r.format_version},
          {"scene", {{"name", r.scene}, {"description", r.description}, {"environment", r.environment}}},
          {"objects", objects},
          {"fabrics", r.fabrics},
          {"colourways", colourways},
          {"sgs", r.sgs},
          {"auto_method", r.auto_method},
          {"methods", methods},
          {"sections", sections},
          {"bake", bake}};
}

nlohmann::json to_json(const BundleVerdict& v) {
  return {{"file", v.file},
          {"ok", v.ok},
          {"method", text_or_null(v.method)},
          {"part", text_or_null(v.part)},
          {"section", text_or_null(v.section)},
          {"message", text_or_null(v.message)}};
}

}  // namespace weft
