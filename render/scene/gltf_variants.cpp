#include "scene/gltf_variants.h"

#include <cmath>

#include <tiny_gltf.h>

namespace weft {

namespace {

// A whole number in [0, n) from a glTF value, or −1.
long index_below(const tinygltf::Value& v, size_t n) {
  if (!v.IsNumber()) return -1;
  const double x = v.GetNumberAsDouble();
  return x >= 0.0 && x < double(n) && x == std::floor(x) ? long(x) : -1;
}

}  // namespace

GltfVariants::GltfVariants(const tinygltf::Model& model, std::string origin) : m_(model), origin_(std::move(origin)) {
  const auto it = m_.extensions.find(kVariants);
  if (it == m_.extensions.end()) return;
  const std::string where = std::string("extensions.") + kVariants + ".variants";
  const tinygltf::Value& list = it->second.IsObject() ? it->second.Get("variants") : tinygltf::Value();
  // tinygltf reads an empty list as no value: both are refused alike.
  if (!list.IsArray() || list.ArrayLen() == 0) fail(where + ": expected a non-empty list of variants ({\"name\": ...})");
  for (size_t k = 0; k < list.ArrayLen(); ++k) {
    const tinygltf::Value& v = list.Get(int(k));
    const bool named = v.IsObject() && v.Has("name") && v.Get("name").IsString() && !v.Get("name").Get<std::string>().empty();
    if (!named) fail(where + "[" + std::to_string(k) + "]: has no name");
    variants_.push_back(v.Get("name").Get<std::string>());
  }
  worn_.assign(variants_.size(), std::vector<std::set<size_t>>(m_.materials.size() + 1));
}

void GltfVariants::fail(const std::string& what) const { throw SceneError(origin_ + ": " + what); }

void GltfVariants::map(const tinygltf::Primitive& p, const std::string& where) {
  const auto it = p.extensions.find(kVariants);
  const std::string w = where + ".extensions." + kVariants + ".mappings";
  if (variants_.empty()) {
    if (it != p.extensions.end()) fail(w + ": the file lists no variants (extensions." + kVariants + ".variants)");
    return;
  }
  const size_t own = size_t(p.material + 1);
  std::vector<size_t> worn(variants_.size(), own);
  if (it != p.extensions.end()) {
    const tinygltf::Value& maps = it->second.IsObject() ? it->second.Get("mappings") : tinygltf::Value();
    if (!maps.IsArray()) fail(w + ": expected a list of {\"material\", \"variants\"}");
    for (size_t k = 0; k < maps.ArrayLen(); ++k) {
      const tinygltf::Value& m = maps.Get(int(k));
      const std::string mw = w + "[" + std::to_string(k) + "]";
      const tinygltf::Value& material = m.IsObject() ? m.Get("material") : tinygltf::Value();
      const long mi = index_below(material, m_.materials.size());
      if (mi < 0)
        fail(mw + ".material: " +
             (material.IsNumber() ? "material " + std::to_string(material.GetNumberAsDouble()) + " does not exist"
                                  : std::string("missing or not a number")) +
             " (" + std::to_string(m_.materials.size()) + " materials)");
      const tinygltf::Value& vs = m.Get("variants");
      if (!vs.IsArray() || vs.ArrayLen() == 0) fail(mw + ".variants: expected a non-empty list of variant indices");
      for (size_t j = 0; j < vs.ArrayLen(); ++j) {
        const long vi = index_below(vs.Get(int(j)), variants_.size());
        if (vi < 0)
          fail(mw + ".variants[" + std::to_string(j) + "]: not one of the file's " + std::to_string(variants_.size()) +
               " variants");
        worn[size_t(vi)] = size_t(mi + 1);
      }
    }
  }
  for (size_t v = 0; v < variants_.size(); ++v) worn_[v][own].insert(worn[v]);
}

std::vector<Colourway> GltfVariants::colourways(const std::vector<std::string>& object_names,
                                                const GltfMaterials& materials) const {
  std::vector<Colourway> out;
  for (size_t v = 0; v < variants_.size(); ++v) {
    Colourway c;
    c.name = variants_[v];
    const std::string in = "variant '" + c.name + "'";
    for (size_t i = 0; i < object_names.size(); ++i) {
      const std::set<size_t>& worn = worn_[v][i];
      if (object_names[i].empty() || worn.empty()) continue;
      if (worn.size() > 1)
        fail(in + ": the primitives of " + material_label(m_, i) +
             " wear different materials; Weft draws one look per material (give them one material in this variant)");
      const size_t t = *worn.begin();
      const bool cloth = materials.cloth(i), becomes_cloth = materials.cloth(t);
      if (cloth != becomes_cloth)
        fail(in + ": " + material_label(m_, i) + (cloth ? " is cloth and " : " is not cloth and ") + material_label(m_, t) +
             (cloth ? " is not" : " is") + "; a colourway changes a cloth object's fabric and colour only");
      if (cloth) c.objects[object_names[i]] = ClothLook{materials.fabric(t), materials.cloth_colour(t)};
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace weft
