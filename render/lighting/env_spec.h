#pragma once
// An environment as a command line or a scene names it, beyond a plain map file:
//   <name or .exr path>            a map (env_map.h's env_map_file)
//   <name or path>@<degrees>       that map rotated about +Z by the angle (a feature at azimuth
//                                  a, measured from +X toward +Y, moves to a + degrees)
//   sky[:key=value,...]            a procedural sky (procedural_sky.h); keys elev, azim, size,
//                                  haze, albedo, width (defaults in SkyParams)
// A rotation applies to a sky too (sky:elev=5@90 is sky:elev=5,azim=90).
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "lighting/env_map.h"
#include "lighting/procedural_sky.h"

namespace weft {

// A spec that names nothing usable (a bad key, a value out of range, a bad angle). Bad input.
class EnvSpecError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

struct EnvSpec {
  enum class Kind { file, sky } kind = Kind::file;
  std::string name;        // file: the map's name or path as given
  SkyParams sky;           // sky: its parameters
  double rotation_deg = 0; // about +Z, applied after loading or generating
};

// Parses `spec`; throws EnvSpecError with the spec and the reason.
EnvSpec parse_env_spec(const std::string& spec);

// True for a spec that is not a plain file name (a sky or a rotation).
bool is_env_spec(const std::string& spec);

// Loads or generates the environment. A file that cannot be read throws EnvMapError (its path
// in the message); a bad spec throws EnvSpecError.
EnvMap load_env(const std::string& spec, const std::filesystem::path& dir,
                NonFinitePolicy policy = NonFinitePolicy::clamp, EnvMapRepairs* repairs = nullptr);

// The file a map spec reads (empty for a sky), for existence checks and cache keys.
std::filesystem::path env_spec_file(const std::string& spec, const std::filesystem::path& dir);

// A label fit for a file name: the map's label (env_map_label), `_r<deg>` for a rotation,
// `sky_e<elev>_a<azim>_s<size>_h<haze>` for a sky (defaults left out except the elevation).
std::string env_spec_label(const std::string& spec);

// `map` rotated about +Z by `degrees`: each row shifted, linearly interpolated between columns
// (exact, and every row's power kept, when the shift is a whole number of texels).
EnvMap rotate_about_z(const EnvMap& map, double degrees);

// A list split at commas (as --maps is) put back together: items of the form key=value that
// follow a sky spec belong to it ("sky:elev=5", "size=1" → "sky:elev=5,size=1").
std::vector<std::string> join_env_specs(const std::vector<std::string>& items);

}  // namespace weft
