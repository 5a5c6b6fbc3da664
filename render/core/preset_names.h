#pragma once
// Presets are JSON files in a folder, named by their stem: the fabrics' and the scenes' lists.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace weft {

// The stems of `dir`'s *.json files, sorted; none where the folder cannot be read.
inline std::vector<std::string> preset_names(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace weft
