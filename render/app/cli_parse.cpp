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

Camera parse_camera(const std::string& text, const Camera& base, const std::string& arg) {
  const size_t c1 = text.find(':');
  if (c1 == std::string::npos) throw UsageError(arg + ": expected 'scene', 'closeup' or EYE:TARGET[:FOV], got '" + text + "'");
  const size_t c2 = text.find(':', c1 + 1);
  const std::vector<double> eye = parse_numbers(text.substr(0, c1), 3, arg + " (eye)");
  const std::vector<double> target =
      parse_numbers(text.substr(c1 + 1, c2 == std::string::npos ? std::string::npos : c2 - c1 - 1), 3, arg + " (target)");
  Camera c = base;
  c.position = {eye[0], eye[1], eye[2]};
  c.target = {target[0], target[1], target[2]};
  if (c2 != std::string::npos) c.fov_deg = parse_numbers(text.substr(c2 + 1), 1, arg + " (field of view)")[0];
  as_usage(arg, [&] { check_camera(c, "camera"); });
  return c;
}

std::string read_argument_file(const std::string& path, const std::string& arg) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(arg + ": cannot open '" + path + "'");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace weft
