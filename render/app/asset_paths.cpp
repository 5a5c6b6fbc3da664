#include "app/asset_paths.h"

#include <cstdlib>

namespace weft {
std::filesystem::path assets_dir() {
  if (const char* env = std::getenv("WEFT_ASSETS"); env && *env) return env;
  return WEFT_SOURCE_ASSETS;
}
}  // namespace weft
