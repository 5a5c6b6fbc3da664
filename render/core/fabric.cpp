#include "core/fabric.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/preset_names.h"

namespace weft {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& origin, const std::string& field, const std::string& what) {
  throw FabricError(origin + ": field '" + field + "': " + what);
}

std::string show(const json& v) { return v.dump(); }

const json& require(const json& obj, const std::string& key, const std::string& origin,
                    const std::string& path) {
  if (!obj.is_object() || !obj.contains(key)) fail(origin, path + key, "missing");
  return obj.at(key);
}

double number(const json& obj, const std::string& key, const std::string& origin, const std::string& path,
              double lo, double hi, bool lo_open = false) {
  const json& v = require(obj, key, origin, path);
  if (!v.is_number()) fail(origin, path + key, "value " + show(v) + " is not a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi || (lo_open && x == lo)) {
    std::ostringstream range;
    range << "value " << show(v) << " is outside " << (lo_open ? "(" : "[") << lo << ", " << hi << "]";
    fail(origin, path + key, range.str());
  }
  return x;
}

std::vector<double> number_list(const json& obj, const std::string& key, const std::string& origin,
                                const std::string& path, double lo, double hi) {
  const json& v = require(obj, key, origin, path);
  if (!v.is_array()) fail(origin, path + key, "value " + show(v) + " is not a list");
  std::vector<double> out;
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string f = path + key + "[" + std::to_string(i) + "]";
    if (!v[i].is_number()) fail(origin, f, "value " + show(v[i]) + " is not a number");
    const double x = v[i].get<double>();
    if (!std::isfinite(x) || x < lo || x > hi)
      fail(origin, f, "value " + show(v[i]) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    out.push_back(x);
  }
  return out;
}

ThreadParams parse_thread(const json& t, const std::string& origin, const std::string& path, double* albedo_scale) {
  ThreadParams p;
  p.eta = number(t, "eta", origin, path, 1.0, 4.0, true);
  const auto colour = number_list(t, "albedo", origin, path, 0.0, 1e6);
  if (colour.size() != 3) fail(origin, path + "albedo", "needs 3 values (r, g, b), got " + std::to_string(colour.size()));
  const double scale = number(t, "albedo_scale", origin, path, 0.0, 1e6);
  p.albedo = dvec3(colour[0], colour[1], colour[2]) * scale;
  *albedo_scale = scale;
  p.kd = number(t, "kd", origin, path, 0.0, 1.0);
  p.gamma_s = glm::radians(number(t, "gamma_s_deg", origin, path, 0.0, 90.0, true));
  p.gamma_v = glm::radians(number(t, "gamma_v_deg", origin, path, 0.0, 90.0, true));
  p.coverage = number(t, "coverage", origin, path, 0.0, 1.0);
  auto offsets = number_list(t, "tangent_offsets_deg", origin, path, -90.0, 90.0);
  auto lengths = number_list(t, "segment_lengths", origin, path, 0.0, 1e6);
  if (offsets.empty()) fail(origin, path + "tangent_offsets_deg", "is empty");
  if (offsets.size() > 1 && lengths.size() != offsets.size() - 1)
    fail(origin, path + "segment_lengths",
         "has " + std::to_string(lengths.size()) + " values but " + std::to_string(offsets.size()) +
             " offsets need " + std::to_string(offsets.size() - 1));
  try {
    p.curve = TangentCurve(std::move(offsets), std::move(lengths));
  } catch (const std::invalid_argument& e) {
    fail(origin, path + "segment_lengths", e.what());
  }
  return p;
}

WeaveSpec parse_weave(const json& w, const std::string& origin) {
  if (!w.is_object()) fail(origin, "weave", "value " + show(w).substr(0, 40) + " is not an object");
  WeaveSpec spec;
  for (const auto& [key, value] : w.items())
    if (key != "rows" && key != "shift" && key != "ends_per_cm" && key != "picks_per_cm")
      fail(origin, "weave." + key, "unknown (known: rows, shift, ends_per_cm, picks_per_cm)");
  auto whole = [&](const char* key, int lo, int hi) {
    const double x = number(w, key, origin, "weave.", lo, hi);
    if (x != std::floor(x)) fail(origin, std::string("weave.") + key, "value " + show(w.at(key)) + " is not a whole number");
    return int(x);
  };
  if (w.contains("rows")) {
    spec.rows = whole("rows", 1, WeaveSpec::kMaxRows);
    spec.shift = w.contains("shift") ? whole("shift", 0, spec.rows - 1) : (spec.rows == 5 ? 2 : 1) % spec.rows;
  } else if (w.contains("shift")) {
    fail(origin, "weave.shift", "needs weave.rows beside it");
  }
  if (w.contains("ends_per_cm")) spec.ends_per_cm = number(w, "ends_per_cm", origin, "weave.", 0.0, WeaveSpec::kMaxThreadsPerCm, true);
  if (w.contains("picks_per_cm")) spec.picks_per_cm = number(w, "picks_per_cm", origin, "weave.", 0.0, WeaveSpec::kMaxThreadsPerCm, true);
  return spec;
}

// A short line of text for people (the kiosk's label): a string of printable characters (UTF-8
// welcome), at most kMaxFabricTextBytes; absent: empty.
std::string optional_text(const json& doc, const char* key, const std::string& origin) {
  if (!doc.contains(key)) return "";
  const json& v = doc.at(key);
  if (!v.is_string()) fail(origin, key, "value " + show(v).substr(0, 40) + " is not a string");
  const std::string s = v.get<std::string>();
  if (const std::string why = fabric_text_problem(s); !why.empty()) fail(origin, key, why);
  return s;
}

}  // namespace

std::string fabric_text_problem(const std::string& text) {
  if (text.size() > kMaxFabricTextBytes)
    return std::to_string(text.size()) + " bytes, more than " + std::to_string(kMaxFabricTextBytes);
  for (const char c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "holds a control character (one line of text)";
  return "";
}

Fabric parse_fabric(const std::string& text, const std::string& origin) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw FabricError(origin + ": not valid JSON: " + e.what());
  }
  Fabric f;
  const json& name = require(doc, "name", origin, "");
  if (!name.is_string() || name.get<std::string>().empty()) fail(origin, "name", "value " + show(name) + " is not a name");
  f.name = name.get<std::string>();
  const json& threads = require(doc, "threads", origin, "");
  if (!threads.is_array() || threads.size() != 2)
    fail(origin, "threads", "needs exactly 2 threads (warp, weft), got " + show(threads).substr(0, 40));
  for (int j = 0; j < 2; ++j)
    f.threads[j] = parse_thread(threads[j], origin, "threads[" + std::to_string(j) + "].", &f.albedo_scale[j]);
  const double a = f.threads[0].coverage + f.threads[1].coverage;
  if (a > 1.0 + 1e-9) {
    std::ostringstream s;
    s << "a_1 + a_2 = " << a << " exceeds 1";
    fail(origin, "threads[*].coverage", s.str());
  }
  f.display_name = optional_text(doc, "display_name", origin);
  f.composition = optional_text(doc, "composition", origin);
  if (doc.contains("optical_thickness"))
    f.optical_thickness = number(doc, "optical_thickness", origin, "", 0.0, kMaxOpticalThickness, true);
  if (doc.contains("weave")) f.weave = parse_weave(doc.at("weave"), origin);
  if (doc.contains("pin_colour")) {
    if (!doc.at("pin_colour").is_boolean()) fail(origin, "pin_colour", "value " + show(doc.at("pin_colour")) + " is not true or false");
    f.pin_colour = doc.at("pin_colour").get<bool>();
  }
  return f;
}

Fabric product_coloured(Fabric fabric, const dvec3& colour) {
  if (fabric.pin_colour) return fabric;
  for (int j = 0; j < 2; ++j) fabric.threads[j].albedo = colour * fabric.albedo_scale[j];
  return fabric;
}

Fabric load_fabric(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FabricError(file.string() + ": cannot open fabric file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_fabric(ss.str(), file.string());
}

Fabric load_fabric_preset(const std::string& name, const std::filesystem::path& dir) {
  const bool plain = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  const auto path = dir / (name + ".json");
  if (!plain || !std::filesystem::exists(path)) {
    std::string known;
    for (const auto& p : list_fabric_presets(dir)) known += (known.empty() ? "" : ", ") + p;
    throw FabricError("unknown fabric '" + name + "' (known: " + known + ")");
  }
  return load_fabric(path);
}

bool names_fabric_file(const std::string& name) {
  const std::filesystem::path p(name);
  return p.has_parent_path() || p.extension() == ".json";
}

Fabric load_fabric_named(const std::string& name, const std::filesystem::path& dir) {
  return names_fabric_file(name) ? load_fabric(name) : load_fabric_preset(name, dir);
}

std::filesystem::path fabric_file(const std::string& name, const std::filesystem::path& dir) {
  return names_fabric_file(name) ? std::filesystem::path(name) : dir / (name + ".json");
}

std::vector<std::string> list_fabric_presets(const std::filesystem::path& dir) {
  return preset_names(dir);
}

}  // namespace weft
