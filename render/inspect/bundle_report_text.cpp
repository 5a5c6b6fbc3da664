#include "inspect/bundle_report_text.h"

#include <cstdio>

#include "bundle/bundle_format.h"
#include "scene/object_schema.h"

namespace weft {

namespace {

std::string joined(const std::vector<std::string>& items) {
  if (items.empty()) return "none";
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

// A bake value in a few characters: floats to 4 significant digits, strings unquoted.
std::string brief(const nlohmann::json& j) {
  if (j.is_number_float()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", j.get<double>());
    return buf;
  }
  if (j.is_string()) return j.get<std::string>();
  if (j.is_array()) {
    std::string s;
    for (const auto& e : j) s += (s.empty() ? "" : " ") + brief(e);
    return "[" + s + "]";
  }
  if (j.is_object()) {
    std::string s;
    for (const auto& [k, v] : j.items()) s += (s.empty() ? "" : ", ") + k + " " + brief(v);
    return "{" + s + "}";
  }
  return j.dump();
}

// A key of bake/vis or bake/mask is an object index: name the object too.
std::string entry_name(const std::string& key, const BundleReport& r) {
  if (key.empty() || key.find_first_not_of("0123456789") != std::string::npos || key.size() > 6) return key;
  const std::size_t i = std::stoul(key);
  return i < r.objects.size() ? key + " (" + r.objects[i].name + ")" : key;
}

// One line per entry when a stage lists fabrics or objects (every value an object), else one line.
void write_bake_stage(const std::string& stage, const nlohmann::json& j, const BundleReport& r, std::ostream& out) {
  bool per_entry = j.is_object() && !j.empty();
  for (const auto& [k, v] : j.items()) per_entry = per_entry && v.is_object();
  if (!per_entry) {
    const std::string b = brief(j);
    out << "  " << stage << ": " << (j.is_object() ? b.substr(1, b.size() - 2) : b) << "\n";
    return;
  }
  out << "  " << stage << ":\n";
  for (const auto& [k, v] : j.items()) {
    const std::string b = brief(v);
    out << "    " << entry_name(k, r) << ": " << b.substr(1, b.size() - 2) << "\n";
  }
}

std::string colour_text(const std::array<double, 3>& c) {
  char s[64];
  std::snprintf(s, sizeof s, "[%.3g, %.3g, %.3g]", c[0], c[1], c[2]);
  return s;
}

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  std::string s;
  for (auto e : shape) s += (s.empty() ? "" : ", ") + std::to_string(e);
  return "[" + s + "]";
}

}  // namespace

void write_report_text(const BundleReport& r, std::ostream& out) {
  out << "bundle " << r.file << ": format version " << r.format_version << ", " << r.bytes << " bytes\n";
  out << "scene: " << r.scene << " (environment " << r.environment << ")"
      << (r.description.empty() ? "" : ": " + r.description) << "\n";
  out << "objects (" << r.objects.size() << "):\n";
  for (std::size_t i = 0; i < r.objects.size(); ++i) {
    const ObjectReport& o = r.objects[i];
    out << "  " << i << " " << o.name << ": " << o.material;
    if (o.material == material_name(Material::cloth)) out << " " << o.fabric;
    if (o.colour) out << " in " << colour_text(*o.colour);
    if (o.optical_thickness > 0) out << " (sheer, optical thickness " << o.optical_thickness << ")";
    out << ", " << o.vertices << " vertices, " << o.triangles << " triangles\n";
  }
  out << "fabrics (" << r.fabrics.size() << "): " << joined(r.fabrics) << "\n";
  out << "colourways (" << r.colourways.size() << ")" << (r.colourways.empty() ? ": none" : ":") << "\n";
  for (const auto& c : r.colourways) {
    out << "  " << c.name << ":";
    for (const auto& l : c.looks)
      out << " " << l.object << " " << l.fabric << (l.colour ? " in " + colour_text(*l.colour) : std::string()) << ";";
    out << "\n";
  }
  out << "lighting: " << r.sgs << " SGs\n";
  std::vector<std::string> drawable;
  for (const auto& m : r.methods)
    if (m.drawable) drawable.push_back(m.name);
  out << "methods: --method auto draws " << r.auto_method << "; it can draw " << joined(drawable) << "\n";
  for (const auto& m : r.methods)
    if (!m.drawable) out << "  cannot draw " << m.name << ": " << m.refusal << "\n";
  out << "sections (" << r.sections.size() << "):\n";
  for (const auto& s : r.sections)
    out << "  " << s.name << " " << bundle::element_type_name(s.type) << " " << shape_text(s.shape) << " " << s.size
        << " bytes\n";
  out << "bake (settings and measured errors):" << (r.bake.empty() ? " none" : "") << "\n";
  for (const auto& [stage, j] : r.bake) write_bake_stage(stage, j, r, out);
}

std::string verdict_line(const BundleVerdict& v) {
  if (!v.ok) return v.message;
  return "bundle " + v.file + ": ok, the kiosk accepts it and draws it with " + v.method;
}

}  // namespace weft
