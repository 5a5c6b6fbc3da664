#pragma once
// SG sets on disk: a small JSON file that `weft fit --out` writes and later commands read.
//   {"format": "weft-sg-set", "version": 1,
//    "sgs": [{"axis": [x, y, z], "sharpness": λ, "amplitude": [r, g, b]}, ...]}
// Loading also accepts any object with such an "sgs" array (e.g. `weft fit --json` output).
// Axes are normalised on load; λ must be finite and > 0, amplitudes finite and ≥ 0.
#include <filesystem>
#include <stdexcept>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/spherical_gaussian.h"

namespace weft {

class SgSetError : public std::runtime_error {
public:
  SgSetError(const std::filesystem::path& path, const std::string& what);
};

nlohmann::ordered_json sg_set_to_json(const SgLighting& sgs);
// `where` names the source in error messages.
SgLighting sg_set_from_json(const nlohmann::json& j, const std::filesystem::path& where);

SgLighting load_sg_set(const std::filesystem::path& path);
void save_sg_set(const std::filesystem::path& path, const SgLighting& sgs);

}  // namespace weft
