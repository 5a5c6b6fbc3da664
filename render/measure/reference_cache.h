#pragma once
// Cached reference renders for the bench. A render is stored under a key that hashes
// everything that produced it (scene file and the mesh data it reads, fabric file, SGs,
// render settings and kReferenceCodeVersion), so changed inputs miss and stale files are
// never read; bump kReferenceCodeVersion when the reference or the model changes.
// File: "WEFTREF1", width, height (int32), then width·height RGB float64 and kind bytes.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hashing/fnv1a_hash.h"
#include "image/image.h"
#include "reference/scene_render.h"
#include "reference/tangent_convergence.h"
#include "scene/mesh.h"

namespace weft::bench {

inline constexpr const char* kReferenceCodeVersion = "weft-reference-2026-11-27";

// Adds a file's contents to `h`; throws std::runtime_error when it cannot be read.
InputHash& add_file(InputHash& h, const std::filesystem::path& file);
// Adds a mesh's positions, normals, warps and triangles to `h`, as the cache keys hash a scene's meshes.
InputHash& add_mesh(InputHash& h, const TriangleMesh& mesh);

struct CachedReference {
  Image image;
  std::vector<PixelKind> kinds;
  int tangent_samples = 0;  // N_j it was rendered with (the key holds it; the file does not)
};

std::optional<CachedReference> load_reference(const std::filesystem::path& file);
void store_reference(const std::filesystem::path& file, const CachedReference& r);  // atomic rename

// A tangent-sample choice (reference/tangent_convergence.h) as text: "WEFTNJ1", then
// "samples N converged 0|1 cloth_pixels P seconds S", then one "step N finer change" line per doubling.
std::optional<TangentConvergence> load_convergence(const std::filesystem::path& file);
void store_convergence(const std::filesystem::path& file, const TangentConvergence& c);  // atomic rename

}  // namespace weft::bench
