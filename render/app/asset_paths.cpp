#include "app/asset_paths.h"

#include <cstdlib>

namespace weft {
std::filesystem::path assets_dir() {
  if (const char* env = std::getenv("WEFT_ASSETS"); env && *env) return env;
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    // WEFT_ASSETS_FROM_EXEDIR: share/weft relative to the folder this executable is installed in.
    const std::filesystem::path installed = (self.parent_path() / WEFT_ASSETS_FROM_EXEDIR).lexically_normal();
    if (std::filesystem::is_directory(installed / "fabrics", ec)) return installed;
  }
  return WEFT_SOURCE_ASSETS;
}
}  // namespace weft
