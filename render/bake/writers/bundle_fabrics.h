#pragma once
// The fabric presets a bundle stores, as their JSON text (preset → text): each cloth object's
// preset and each colourway's (worn_fabrics), validated first so an unknown name fails naming the known presets, and unless
// `only_scene` every other preset in `dir` (a few hundred bytes each: the kiosk's fabric knob
// selects among them).
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>

#include "core/fabric.h"
#include "scene/scene.h"

namespace weft {

// Bad input: "--fabric: <why>" for an invalid cloth preset, "fabric: cannot open '<path>'".
class BundleFabricError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

std::map<std::string, std::string> bundle_fabric_texts(const Scene& scene, const std::filesystem::path& dir,
                                                       bool only_scene);

// The fabrics the cloth wears (worn_fabrics: its own and its colourways') parsed from such texts (preset → fabric), as the bakers take them.
std::map<std::string, Fabric> cloth_fabrics(const Scene& scene, const std::map<std::string, std::string>& fabric_texts);

}  // namespace weft
