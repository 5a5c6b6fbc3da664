#pragma once
// glTF 2.0 import (.gltf and .glb, through tinygltf): a showroom scene from a model file.
// Indexed or plain triangle primitives with POSITION, NORMAL, TEXCOORD_0 and TANGENT, node
// hierarchies (TRS or matrix), several meshes and materials; Draco, meshopt and quantized
// geometry (gltf_draco.h, gltf_meshopt.h, KHR_mesh_quantization). glTF's +Y-up metres become Weft's
// +Z-up frame: (x, y, z)_glTF → (x, −z, y). One scene object per material (its primitives merged).
// Format notes: assets/scenes/README.md ("glTF scenes").
#include <filesystem>
#include <map>
#include <string>

#include "scene/scene.h"

namespace weft {

struct GltfImportOptions {
  // Preset fabrics: a material whose name is a preset here is cloth with that preset.
  std::filesystem::path fabrics_dir;
  // Per material name: a preset name or a fabric file path (taken as given), overriding what
  // the glTF says; the material becomes cloth.
  std::map<std::string, std::string> fabric_overrides;
  // When no material is cloth (no override, no extras.weft.fabric, no preset name, no fabric in
  // its name, no sheen), every material becomes cloth with this fabric; empty: the scene stays
  // without cloth.
  std::string fallback_fabric;
};

// Caps on what one file may hold (hostile files are refused before they exhaust memory).
inline constexpr size_t kGltfMaxVertices = 10'000'000;
inline constexpr size_t kGltfMaxTriangles = 10'000'000;
inline constexpr size_t kGltfMaxFileBytes = size_t(1) << 30;

// True when `name` ends in .gltf or .glb (any case).
bool is_gltf_path(const std::string& name);

// Loads a glTF file as a scene: its first perspective camera (else a camera framed on the cloth,
// or on everything when nothing is cloth), the default environment ("studio"). A material is
// cloth when an override names it, when its extras.weft.fabric names a preset or a fabric file
// (relative to the glTF), when its name is a preset's, or when its name's words or its
// KHR_materials_sheen say cloth (docs/design.md §1, "glTF materials as cloth"; each such
// inference is in the scene's warnings). Throws SceneError naming the file and the reason for
// anything it cannot use.
Scene load_gltf_scene(const std::filesystem::path& file, const GltfImportOptions& options);
// The same from bytes in memory (`origin` names them in errors, `base_dir` resolves external
// buffers and fabric files).
Scene parse_gltf_scene(const std::string& bytes, const std::string& origin, const std::filesystem::path& base_dir,
                       const GltfImportOptions& options);

}  // namespace weft
