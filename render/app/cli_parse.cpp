#include "app/cli_parse.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace weft {

std::vector<double> parse_numbers(const std::string& text, size_t count, const std::string& arg) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    size_t used = 0;
    double v = 0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    while (used < item.size() && std::isspace(static_cast<unsigned char>(item[used]))) ++used;
    if (item.empty() || used != item.size()) throw UsageError(arg + ": '" + item + "' is not a number");
    if (!std::isfinite(v)) throw UsageError(arg + ": '" + item + "' is not finite");
    out.push_back(v);
  }
  if (out.size() != count)
    throw UsageError(arg + ": expected " + std::to_string(count) + " comma-separated numbers, got " +
                     std::to_string(out.size()) + " in '" + text + "'");
  return out;
}

glm::dvec3 parse_direction(const std::string& text, const std::string& arg) {
  const auto v = parse_numbers(text, 3, arg);
  const glm::dvec3 d(v[0], v[1], v[2]);
  const double len = glm::length(d);
  if (!(len > 1e-12)) throw UsageError(arg + ": direction '" + text + "' has zero length");
  return d / len;
}

SphericalGaussian parse_sg(const std::string& text, const std::string& arg) {
  const auto v = parse_numbers(text, 7, arg + " (axis_x,axis_y,axis_z,sharpness,r,g,b)");
  SphericalGaussian g;
  const glm::dvec3 axis(v[0], v[1], v[2]);
  if (!(glm::length(axis) > 1e-12)) throw UsageError(arg + ": axis of '" + text + "' has zero length");
  g.axis = glm::normalize(axis);
  if (!(v[3] > 0.0)) throw UsageError(arg + ": sharpness (lambda) must be > 0, got " + std::to_string(v[3]));
  if (v[3] > 1e6) throw UsageError(arg + ": sharpness (lambda) " + std::to_string(v[3]) + " is beyond 1e6");
  for (int c = 0; c < 3; ++c)
    if (v[4 + c] < 0.0) throw UsageError(arg + ": amplitude must be >= 0, got " + std::to_string(v[4 + c]));
  g.sharpness = v[3];
  g.amplitude = glm::dvec3(v[4], v[5], v[6]);
  return g;
}

std::string read_argument_file(const std::string& path, const std::string& arg) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(arg + ": cannot open '" + path + "'");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace weft
