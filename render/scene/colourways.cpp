// The scene's colourways and product colours: kept apart from scene.cpp's generators and file
// loading so that the glTF importer (and its fuzz build) needs only this beside it.
#include <algorithm>
#include <cmath>

#include "scene/scene.h"

namespace weft {

std::vector<ClothLook> cloth_looks(const Scene& s) {
  std::vector<ClothLook> looks;
  for (const auto& o : s.cloth_objects()) looks.push_back({o.fabric, o.colour});
  return looks;
}

std::vector<ClothLook> colourway_looks(const Scene& s, const std::vector<ClothLook>& base, size_t k) {
  std::vector<ClothLook> looks = base;
  const Colourway& c = s.colourways.at(k);
  size_t i = 0;
  for (const auto& o : s.cloth_objects()) {
    if (const auto it = c.objects.find(o.name); it != c.objects.end() && i < looks.size()) looks[i] = it->second;
    ++i;
  }
  return looks;
}

void wear_looks(Scene& s, const std::vector<ClothLook>& looks) {
  size_t i = 0;
  for (auto& o : s.cloth_objects()) {
    if (i >= looks.size()) break;
    o.fabric = looks[i].fabric;
    o.colour = looks[i].colour;
    ++i;
  }
}

std::vector<std::string> worn_fabrics(const Scene& s) {
  std::vector<std::string> names;
  const auto add = [&](const std::string& f) {
    if (std::find(names.begin(), names.end(), f) == names.end()) names.push_back(f);
  };
  for (const auto& o : s.cloth_objects()) add(o.fabric);
  for (const auto& c : s.colourways)
    for (const auto& [object, look] : c.objects) add(look.fabric);
  return names;
}

void check_colourways(const Scene& s, const std::string& origin) {
  std::string cloth;
  for (const auto& o : s.cloth_objects()) cloth += (cloth.empty() ? "" : ", ") + o.name;
  for (size_t k = 0; k < s.colourways.size(); ++k) {
    const Colourway& c = s.colourways[k];
    const std::string where = origin + ": colourways[" + std::to_string(k) + "]";
    if (c.name.empty()) throw SceneError(where + ": has no name");
    for (size_t j = 0; j < k; ++j)
      if (s.colourways[j].name == c.name) throw SceneError(where + ": the name '" + c.name + "' is taken by colourways[" + std::to_string(j) + "]");
    if (c.objects.empty()) throw SceneError(where + " ('" + c.name + "'): dresses no object");
    for (const auto& entry : c.objects) {  // not a structured binding: the fuzz build's clang 14 cannot capture one
      const std::string& object = entry.first;
      const ClothLook& look = entry.second;
      const auto it = std::find_if(s.objects.begin(), s.objects.end(), [&](const SceneObject& o) { return o.name == object; });
      if (it == s.objects.end() || !it->is_cloth())
        throw SceneError(where + " ('" + c.name + "'): '" + object + "' is not a cloth object of the scene (cloth: " + cloth + ")");
      if (look.fabric.empty()) throw SceneError(where + " ('" + c.name + "'): object '" + object + "' has no fabric");
    }
  }
}

glm::dvec3 product_colour(const std::vector<double>& rgb, const std::string& where) {
  if (rgb.size() != 3) throw SceneError(where + ": expected a colour [r, g, b], got " + std::to_string(rgb.size()) + " numbers");
  for (int c = 0; c < 3; ++c)
    if (!(std::isfinite(rgb[c]) && rgb[c] >= 0.0 && rgb[c] <= 1.0))
      throw SceneError(where + ": colour components must be finite numbers in [0, 1], got " + std::to_string(rgb[c]));
  return {rgb[0], rgb[1], rgb[2]};
}

}  // namespace weft
