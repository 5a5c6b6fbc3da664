#include "lighting/sg_set_io.h"

#include <cmath>
#include <fstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "files/atomic_file.h"

namespace weft {

SgSetError::SgSetError(const std::filesystem::path& path, const std::string& what)
    : std::runtime_error("SG set '" + path.string() + "': " + what) {}

nlohmann::ordered_json sg_set_to_json(const SgLighting& sgs) {
  nlohmann::ordered_json out;
  out["format"] = "weft-sg-set";
  out["version"] = 1;
  out["sgs"] = nlohmann::ordered_json::array();
  for (const auto& g : sgs) {
    nlohmann::ordered_json e;
    e["axis"] = {g.axis.x, g.axis.y, g.axis.z};
    e["sharpness"] = g.sharpness;
    e["amplitude"] = {g.amplitude.r, g.amplitude.g, g.amplitude.b};
    out["sgs"].push_back(e);
  }
  return out;
}

SgLighting sg_set_from_json(const nlohmann::json& j, const std::filesystem::path& where) {
  if (!j.is_object() || !j.contains("sgs") || !j["sgs"].is_array())
    throw SgSetError(where, "expected an object with an \"sgs\" array");
  if (j.contains("format") && j["format"] != "weft-sg-set")
    throw SgSetError(where, "format is not \"weft-sg-set\"");
  if (j.contains("version") && j["version"] != 1) throw SgSetError(where, "unsupported version (expected 1)");
  auto triple = [&](const nlohmann::json& e, const char* key, size_t index) {
    const std::string at = "sgs[" + std::to_string(index) + "]." + key;
    if (!e.contains(key) || !e[key].is_array() || e[key].size() != 3)
      throw SgSetError(where, at + ": expected 3 numbers");
    glm::dvec3 v;
    for (int c = 0; c < 3; ++c) {
      if (!e[key][c].is_number()) throw SgSetError(where, at + ": expected 3 numbers");
      v[c] = e[key][c].get<double>();
      if (!std::isfinite(v[c])) throw SgSetError(where, at + ": not finite");
    }
    return v;
  };
  SgLighting out;
  for (size_t i = 0; i < j["sgs"].size(); ++i) {
    const auto& e = j["sgs"][i];
    const std::string at = "sgs[" + std::to_string(i) + "]";
    if (!e.is_object()) throw SgSetError(where, at + ": expected an object");
    SphericalGaussian g;
    g.axis = triple(e, "axis", i);
    const double len = glm::length(g.axis);
    if (!(len > 1e-12)) throw SgSetError(where, at + ".axis: zero length");
    g.axis /= len;
    if (!e.contains("sharpness") || !e["sharpness"].is_number()) throw SgSetError(where, at + ".sharpness: expected a number");
    g.sharpness = e["sharpness"].get<double>();
    if (!(g.sharpness > 0.0) || !std::isfinite(g.sharpness)) throw SgSetError(where, at + ".sharpness: must be finite and > 0");
    g.amplitude = triple(e, "amplitude", i);
    if (g.amplitude.r < 0 || g.amplitude.g < 0 || g.amplitude.b < 0) throw SgSetError(where, at + ".amplitude: must be >= 0");
    out.push_back(g);
  }
  return out;
}

SgLighting load_sg_set(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw SgSetError(path, "cannot open");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw SgSetError(path, std::string("not valid JSON: ") + e.what());
  }
  return sg_set_from_json(j, path);
}

void save_sg_set(const std::filesystem::path& path, const SgLighting& sgs) {
  // A reader never sees half a file, nor a power cut a mix of two.
  try {
    write_file_atomically(path, sg_set_to_json(sgs).dump(2) + "\n");
  } catch (const std::system_error& e) {
    throw SgSetError(path, e.what());
  }
}

}  // namespace weft
