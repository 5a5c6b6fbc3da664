#pragma once
// Parsing of what the command line takes: small value lists (`0.5,0.2,0.8`, SG descriptions).
// Errors are UsageError with a message that names the argument.
#include <stdexcept>
#include <string>
#include <vector>

#include "core/spherical_gaussian.h"
#include "scene/scene.h"

namespace weft {

class UsageError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Comma-separated finite numbers, exactly `count` of them.
std::vector<double> parse_numbers(const std::string& text, size_t count, const std::string& arg);
// A direction: 3 numbers, non-zero length; returned normalised.
glm::dvec3 parse_direction(const std::string& text, const std::string& arg);
// `axis_x,axis_y,axis_z,λ,μ_r,μ_g,μ_b`: axis normalised, λ > 0, μ ≥ 0.
SphericalGaussian parse_sg(const std::string& text, const std::string& arg);
// --camera's "ex,ey,ez:tx,ty,tz[:fov]": `base` moved to the eye, looking at the target, its up kept and its
// vertical field of view unless FOV (degrees) is given; checked as a scene's camera (check_camera).
Camera parse_camera(const std::string& text, const Camera& base, const std::string& arg);
// The whole of a file a command-line argument names; UsageError "<arg>: cannot open '<path>'".
std::string read_argument_file(const std::string& path, const std::string& arg);

// f(), with any other exception it throws turned into UsageError "<arg>: <what>": a file or name
// the command line gives that cannot be used is bad input (exit 2).
template <class F>
auto as_usage(const std::string& arg, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const UsageError&) {
    throw;
  } catch (const std::exception& e) {
    throw UsageError(arg + ": " + e.what());
  }
}

}  // namespace weft
