#pragma once
// Cloth textures as scenes give them (scene/scene.h's ThreadMap): the image files they name, read
// with the importer's caps, and a scene file's "texture" / "weft_texture" / "normal_map" fields.
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "scene/scene.h"

namespace weft {

// The most bytes an image file may have (a 8192² RGBA PNG compresses below this).
inline constexpr size_t kMaxTextureFileBytes = size_t(256) << 20;

// Decodes the PNG or JPEG file `file`. Throws SceneError starting with `what` when the file is
// missing, not a regular file, too large, or not a usable image (texture_image.h's reasons).
std::shared_ptr<const TextureImage> load_texture_file(const std::filesystem::path& file, const std::string& what);

// Images already read, by their normalised path: a scene's objects share them.
using TextureFiles = std::map<std::string, std::shared_ptr<const TextureImage>>;

// A scene file's {"image": FILE, "offset": [u, v], "scale": [u, v], "rotation": RADIANS} (all but
// "image" optional), FILE relative to `base_dir`. Throws SceneError naming `where` and the field.
ThreadMap parse_thread_map(const nlohmann::json& j, const std::string& where, const std::filesystem::path& base_dir,
                           TextureFiles& files);

// A scene file's normal map: parse_thread_map's fields plus "normal_scale" (optional, default 1:
// glTF's normalTexture.scale, on the map's x and y), a finite number within ±10^6.
NormalMap parse_normal_map(const nlohmann::json& j, const std::string& where, const std::filesystem::path& base_dir,
                           TextureFiles& files);

// Checks a transform's numbers: finite, scales non-zero and within ±1e6, offsets within ±1e6.
// Returns the problem, or "" when it is fine.
std::string texture_transform_problem(const TextureTransform& t);

}  // namespace weft
