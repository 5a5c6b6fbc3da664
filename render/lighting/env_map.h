#pragma once
// Equirectangular environment maps (docs/design.md §3): loading and writing OpenEXR, the
// direction <-> texel mapping, bilinear lookup, per-texel solid angle, area-weighted resampling.
//
// Orientation (Blender's, +Z up): for a unit direction d,
//   u = atan2(d.y, -d.x) / (2π) + 0.5,   v = atan2(d.z, hypot(d.x, d.y)) / π + 0.5,
// u grows to the right, v = 1 is the TOP row of the image (row 0 in memory).
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace weft {

// Any failure to read or write a map: missing, corrupt or truncated file, missing channels,
// non-finite texels under NonFinitePolicy::fail. The message names the file.
class EnvMapError : public std::runtime_error {
public:
  EnvMapError(const std::filesystem::path& path, const std::string& what);
  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
};

// What to do with NaN, ±Inf or negative texels (never accepted silently: they are counted).
enum class NonFinitePolicy {
  clamp,  // NaN -> 0, -Inf/negative -> 0, +Inf -> the largest finite value of the map
  fail,   // throw EnvMapError with the counts
};

// Per-channel-value counts of the texels the loader had to repair (all 0 for a clean map).
struct EnvMapRepairs {
  size_t nan = 0;
  size_t infinite = 0;
  size_t negative = 0;
  size_t total() const { return nan + infinite + negative; }
};

struct EnvMap {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> texels;  // linear RGB, row-major, row 0 = top (v = 1)

  EnvMap() = default;
  EnvMap(int w, int h);

  glm::vec3& at(int x, int y) { return texels[static_cast<size_t>(y) * width + x]; }
  const glm::vec3& at(int x, int y) const { return texels[static_cast<size_t>(y) * width + x]; }

  // Unit direction through the centre of texel (x, y).
  glm::dvec3 direction(int x, int y) const;
  // Exact solid angle of one texel of row y (all texels of a row are equal).
  double solid_angle(int y) const;
  // Bilinear lookup (wraps in u, clamps in v).
  glm::dvec3 lookup(const glm::dvec3& d) const;
};

// The mapping of docs/design.md §3. uv in [0,1]²; v = 1 is straight up (+Z).
glm::dvec2 direction_to_uv(const glm::dvec3& d);
glm::dvec3 uv_to_direction(const glm::dvec2& uv);
// Continuous pixel coordinates (x right, y down from the top row; texel (i, j) spans [i, i+1) ×
// [j, j+1), its centre at (i+0.5, j+0.5)) of direction d in a width × height map.
glm::dvec2 direction_to_pixel(const glm::dvec3& d, int width, int height);

// Loads an OpenEXR map: channels R,G,B (A ignored) or Y (grey), half/float/uint, any compression
// OpenEXR reads, scanline or tiled; the data window is the image. `repairs` receives the counts.
EnvMap load_env_map(const std::filesystem::path& path, NonFinitePolicy policy = NonFinitePolicy::fail,
                    EnvMapRepairs* repairs = nullptr);

// An environment map as the command line or a scene names it: a file path (a directory part or
// an .exr ending) as given, else `<dir>/<name>.exr`.
std::filesystem::path env_map_file(const std::string& name, const std::filesystem::path& dir);
// The map's short name for labels: the file's stem for a path, the name otherwise.
std::string env_map_label(const std::string& name);

enum class ExrPixel { half, full_float };
enum class ExrCompression { none, rle, zip, piz, dwab };
struct EnvMapWriteOptions {
  ExrPixel pixel = ExrPixel::full_float;
  ExrCompression compression = ExrCompression::zip;
  bool alpha = false;  // also write an A channel (= 1)
};
void write_env_map(const std::filesystem::path& path, const EnvMap& map, const EnvMapWriteOptions& options = {});

// Area-weighted resampling to width × height: every source texel goes to the target texel that
// contains its centre, weighted by its solid angle (radiant power is kept exactly when the sizes
// divide, to within the row-boundary misfit otherwise; a constant map stays constant); target texels no
// source centre falls in (upsampling) take the bilinear lookup at their centre.
EnvMap resample(const EnvMap& map, int width, int height);

// Radiant power-weighted mean radiance over the sphere: ∫L dω / 4π (per channel).
glm::dvec3 mean_radiance(const EnvMap& map);

}  // namespace weft
