#include "bench/filament_peer/filament_environment.h"

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include "image/image.h"

namespace weft::peer {

glm::dvec3 cmgen_direction(double x, double y, int width, int height) {
  const double theta = (2.0 * x / (width - 1) - 1.0) * std::numbers::pi;
  const double phi = (1.0 - 2.0 * y / (height - 1)) * 0.5 * std::numbers::pi;
  const glm::dvec3 s(std::cos(phi) * std::sin(theta), std::sin(phi), std::cos(phi) * std::cos(theta));
  return {-s.x, s.y, s.z};
}

void write_cmgen_equirect(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, int width, int height,
                          int supersample, const std::filesystem::path& exr) {
  Image map(width, height);
  const double step = 1.0 / supersample;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::dvec3 sum(0.0);
      for (int j = 0; j < supersample; ++j)
        for (int i = 0; i < supersample; ++i) {
          // Clamped to the poles: past y = H−1 the direction would wrap over the pole.
          const double sy = std::min(y + (j + 0.5) * step, double(height - 1));
          sum += radiance(cmgen_direction(x + (i + 0.5) * step, sy, width, height));
        }
      map.at(x, y) = sum / double(supersample * supersample);
    }
  write_exr(map, exr);
}

std::filesystem::path make_ibl_ktx(const SgLighting& sgs, const std::filesystem::path& dir, int cube_size,
                                   int map_width, const std::string& sh_window) {
  std::filesystem::create_directories(dir);
  const auto exr = dir / "lighting.exr";
  write_cmgen_equirect([&](const glm::dvec3& d) { return evaluate(sgs, d); }, map_width, map_width / 2, 3, exr);
  const std::string command = std::string(FILAMENT_CMGEN) + " -q --format=ktx --size=" + std::to_string(cube_size) +
                              " --sh-window=" + sh_window + " --deploy='" + dir.string() + "' '" + exr.string() + "'";
  const int status = std::system(command.c_str());
  const auto ktx = dir / (dir.filename().string() + "_ibl.ktx");
  if (status != 0 || !std::filesystem::exists(ktx))
    throw IblError("cmgen: `" + command + "` exited with status " + std::to_string(status) + " and wrote no " +
                   ktx.string());
  return ktx;
}

}  // namespace weft::peer
