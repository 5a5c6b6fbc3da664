#include "scene/gltf_sheen_fabric.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace weft {

namespace {

// glTF keeps a satin's gloss in the base layer's roughness: the sheen lobe is a rim at grazing
// angles, which a satin's floats do not show, so the sheen roughness cannot tell a satin. GGX's
// α = r² spreads the highlight by about atan(α): r = 0.25 gives 3.6°, between the satin's 2.5°
// and the crêpe's 5° surface lobe (Table II), r = 0.4 gives 9°, between the crêpe's 5° and
// linen's 12°. Above it the base is matte.
constexpr double kSatinBelow = 0.25;
constexpr double kSilkBelow = 0.4;
// A strong, sharp sheen: the spec reads a low sheen roughness as fibres standing along the normal
// (a pile), its own velvet example being sheen 0.9 at roughness 0.
constexpr double kStrongSheen = 0.5;
constexpr double kSharpSheenBelow = 0.5;
// Where the sheen is this many times the base, the base is the dark ground under a pile and what
// a shopper sees as the velvet's colour is its sheen (Khronos' GlamVelvetSofa pairs a base of
// 0.01 with a navy sheen).
constexpr double kSheenOutshines = 2.0;

double brightest(const glm::dvec3& c) { return std::max({c.r, c.g, c.b}); }

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

// A factor as a number in [0, 1]: not finite throws, out of range is clamped with a note (an
// exporter's 1.0000001 should not refuse a product).
double unit_factor(double x, const std::string& where, std::vector<std::string>& notes) {
  if (!std::isfinite(x)) throw SceneError(where + ": not a finite number");
  const double clamped = std::clamp(x, 0.0, 1.0);
  if (clamped != x) notes.push_back(where + ": " + number(x) + " is outside [0, 1], clamped to " + number(clamped));
  return clamped;
}

double unit_factor(const tinygltf::Value& v, const std::string& where, std::vector<std::string>& notes) {
  if (!v.IsNumber()) throw SceneError(where + ": expected a number in [0, 1]");
  return unit_factor(v.GetNumberAsDouble(), where, notes);
}

glm::dvec3 unit_colour(const tinygltf::Value& v, const std::string& where, std::vector<std::string>& notes) {
  if (!v.IsArray() || v.ArrayLen() != 3) throw SceneError(where + ": expected three numbers in [0, 1] (linear RGB)");
  glm::dvec3 c;
  for (int k = 0; k < 3; ++k) c[k] = unit_factor(v.Get(k), where + "[" + std::to_string(k) + "]", notes);
  return c;
}

}  // namespace

bool sheen_is_on(const SheenFactors& f) { return brightest(f.sheen_colour) > 0.0; }

std::string sheen_preset(const SheenFactors& f) {
  if (f.base_roughness < kSatinBelow) return "polyester_satin_charmeuse";
  if (f.base_roughness < kSilkBelow) return "silk_crepe_de_chine";
  // A pile: its sheen outshines its base (the Khronos velvet samples), or is strong and sharp
  // (the spec's reading of a low sheen roughness).
  const double sheen = brightest(f.sheen_colour);
  if (sheen >= brightest(f.base_colour) || (sheen >= kStrongSheen && f.sheen_roughness < kSharpSheenBelow))
    return "velvet";
  // A soft or faint sheen over a matte base: the plain weave of matte yarn.
  return kDefaultClothPreset;
}

glm::dvec3 sheen_thread_colour(const SheenFactors& f, const std::string& preset) {
  if (preset == "velvet" && brightest(f.sheen_colour) >= kSheenOutshines * brightest(f.base_colour))
    return f.sheen_colour;
  return f.base_colour;
}

std::optional<SheenFactors> read_sheen_factors(const tinygltf::Material& m, const std::string& where,
                                               std::vector<std::string>& notes) {
  const auto ext = m.extensions.find(kSheenExtension);
  if (ext == m.extensions.end()) return std::nullopt;
  const std::string at = where + ".extensions." + kSheenExtension;
  const tinygltf::Value& sheen = ext->second;
  if (!sheen.IsObject()) throw SceneError(at + ": expected an object");
  SheenFactors f;
  if (sheen.Has("sheenColorFactor"))
    f.sheen_colour = unit_colour(sheen.Get("sheenColorFactor"), at + ".sheenColorFactor", notes);
  if (sheen.Has("sheenRoughnessFactor"))
    f.sheen_roughness = unit_factor(sheen.Get("sheenRoughnessFactor"), at + ".sheenRoughnessFactor", notes);
  const auto& pbr = m.pbrMetallicRoughness;
  const std::string base = where + ".pbrMetallicRoughness";
  if (pbr.baseColorFactor.size() >= 3)
    for (int k = 0; k < 3; ++k)
      f.base_colour[k] = unit_factor(pbr.baseColorFactor[k], base + ".baseColorFactor[" + std::to_string(k) + "]", notes);
  f.base_roughness = unit_factor(pbr.roughnessFactor, base + ".roughnessFactor", notes);
  return f;
}

std::string describe_sheen(const SheenFactors& f) {
  return "sheen " + number(brightest(f.sheen_colour)) + " at roughness " + number(f.sheen_roughness) + " over base " +
         number(brightest(f.base_colour)) + " at roughness " + number(f.base_roughness);
}

}  // namespace weft
